!> The homogenised friction law behind an Abaqus/Explicit VFRIC user
!> subroutine, and a small driver that calls it as Abaqus would.
!>
!> `vfric` has the argument list of VFRIC (Abaqus User Subroutines
!> Reference, "VFRIC"; the 2024 names, older releases say Slv/Mst for
!> Sec/Main): it writes `fTangential(nFricDir, nContact)`, reads and
!> updates the per-node state `statev(nStateVar, nSecNod)`, and reads the
!> rest. Per contact point k on secondary node `jConSecid(k)` it passes the
!> normal force `fNormal(k)`, the node's area `areaSec(node)` and the slip
!> increment `dSlipFric(1:nFricDir, k)` (local basis: t1 along the slip) to
!> one `asperity_friction_step_block_in_place` call for the whole block. The
!> law's history (its friction state, `asperity_friction_state_size` = 9
!> doubles: dissipation, slip path, stick force x and y, plastic slip path,
!> dissipation by mechanism) lives in `statev(1:9, node)`, so nStateVar >= 9.
!> Abaqus wants `fTangential(1, k)` between minus the stick force
!> `fStickForce(k)` and zero; the law's force is clamped to that range (its
!> own history is kept).
!>
!> The law comes from the properties of *FRICTION, USER (built on the first
!> call and kept: the homogenised table with its stick stiffness, one
!> `asperity_friction` handle): props(1) = stick stiffness k (N/m); props(2) = number of
!> table rows m; then m rows of 7 values: nominal pressure (Pa), coefficient
!> of friction, adhesion pressure (Pa), contact fraction, and the chemical,
!> van der Waals and elastic shares of the dissipation (the plastic share is
!> the rest). nProps = 2 + 7 m.
!>
!> In Abaqus: run Abaqus/Explicit in double precision (the reals here are
!> c_double), replace the explicit declarations by `include 'vaba_param.inc'`
!> where your site requires it, build the table in VEXTERNALDB when the
!> analysis runs in several threads, and rotate the stored force with
!> `dirCosSl` when the slip direction turns (left out here: the driver slides
!> one way along x).
!>
!> The driver: four contact points on secondary nodes 2..5 of six, under
!> 10, 50, 100 and 100 N on 1 mm^2 each (10, 50, 100, 100 MPa: table rows, so
!> mu(p) and the adhesion pressure are the tabulated values), slide by
!> 1e-8 m per increment for 100 increments with a stick stiffness of 1e8 N/m;
!> point 4 has a stick force of 20 N, below its slip limit. Rows
!> "friction <increment> <slip> <fTangential(1,1..4)>" and lines
!> "CHECK <name> <value>" are read by tests/fortran_bindings.rs.
module vfric_law
  use asperity
  implicit none
  private
  !> The law, built from props on the first call of vfric.
  type(asperity_friction), save, public :: law
  !> Doubles per point state in statev (`asperity_friction_state_size` of
  !> the homogenised law).
  integer, parameter, public :: state_words = 9
end module vfric_law

subroutine vfric( &
    ! Write only -
    fTangential, &
    ! Read/Write -
    statev, &
    ! Read only -
    kStep, kInc, nContact, nFacNod, nSecNod, nMainNod, &
    nFricDir, nDir, nStateVar, nProps, nTemp, nPred, numDefTfv, &
    jSecUid, jMainUid, jConSecid, jConMainid, timStep, timGlb, &
    dTimCur, surfInt, surfSec, surfMain, lContType, &
    dSlipFric, fStickForce, fTangPrev, fNormal, frictionWork, &
    shape, coordSec, coordMain, dirCosSl, dircosN, props, &
    areaSec, tempSec, preDefSec, tempMain, preDefMain)
  use asperity
  use vfric_law
  implicit none
  integer, intent(in) :: kStep, kInc, nContact, nFacNod, nSecNod, nMainNod, nFricDir, nDir, &
      nStateVar, nProps, nTemp, nPred, numDefTfv, lContType
  real(c_double), intent(out) :: fTangential(nFricDir, nContact)
  real(c_double), intent(inout) :: statev(nStateVar, nSecNod)
  integer, intent(in) :: jSecUid(nSecNod), jMainUid(nMainNod), jConSecid(nContact), &
      jConMainid(nFacNod, nContact)
  real(c_double), intent(in) :: timStep, timGlb, dTimCur, frictionWork
  character(len=80), intent(in) :: surfInt, surfSec, surfMain
  real(c_double), intent(in) :: dSlipFric(nDir, nContact), fStickForce(nContact), &
      fTangPrev(nDir, nContact), fNormal(nContact), shape(nFacNod, nContact), &
      coordSec(nDir, nSecNod), coordMain(nDir, nMainNod), dirCosSl(nDir, nContact), &
      dircosN(nDir, nContact), props(nProps), areaSec(nSecNod), tempSec(nContact), &
      preDefSec(nContact, nPred), tempMain(numDefTfv), preDefMain(numDefTfv, nPred)
  real(c_double) :: states(state_words, nContact)
  real(c_double) :: normal(nContact), area(nContact), slip(2, nContact), force(2, nContact)
  integer(c_int32_t) :: status
  integer :: k, node

  if (.not. c_associated_law()) call build_law(props, nProps)
  if (nStateVar < state_words) then
    write (*, '(a, i0)') 'vfric: nStateVar must be at least ', state_words
    error stop 'vfric: too few state variables'
  end if
  ! Gather the block: one point per contact, its history from its node.
  do k = 1, nContact
    node = jConSecid(k)
    normal(k) = fNormal(k)
    area(k) = areaSec(node)
    slip(1, k) = dSlipFric(1, k)
    slip(2, k) = 0
    if (nFricDir == 2) slip(2, k) = dSlipFric(2, k)
    states(:, k) = statev(1:state_words, node)
  end do
  call asperity_friction_step_block_in_place(law, normal, slip, dTimCur, states, force, &
      areas=area, status=status)
  if (status /= ASPERITY_OK) then
    ! In Abaqus: call XPLB_ABQERR with the message.
    write (*, '(a)') 'vfric: '//asperity_last_error_message()
    error stop 'vfric: the friction step failed'
  end if
  ! Scatter: forces within Abaqus's bounds, histories back to the nodes.
  do k = 1, nContact
    node = jConSecid(k)
    fTangential(:, k) = force(1:nFricDir, k)
    fTangential(1, k) = min(0.0_c_double, max(fTangential(1, k), -fStickForce(k)))
    statev(1:state_words, node) = states(:, k)
  end do

contains

  logical function c_associated_law()
    use, intrinsic :: iso_c_binding, only: c_associated
    c_associated_law = c_associated(law%ptr)
  end function c_associated_law

  subroutine build_law(props, n_props)
    integer, intent(in) :: n_props
    real(c_double), intent(in) :: props(n_props)
    type(asperity_homogenised_sample), allocatable :: samples(:)
    type(asperity_homogenised_friction) :: table
    integer :: m, i, j, words
    m = nint(props(2))
    if (n_props /= 2 + 7*m) error stop 'vfric: nProps must be 2 + 7 * props(2)'
    allocate (samples(m))
    do i = 1, m
      j = 2 + 7*(i - 1)
      samples(i)%pressure = props(j + 1)
      samples(i)%cof = props(j + 2)
      samples(i)%adhesion_pressure = props(j + 3)
      samples(i)%contact_fraction = props(j + 4)
      samples(i)%shares = asperity_dissipation(props(j + 5), props(j + 6), props(j + 7), &
          1 - props(j + 5) - props(j + 6) - props(j + 7))
    end do
    call asperity_homogenised_friction_new(samples, table)
    ! The law: the table with the stick stiffness props(1) (the law keeps a
    ! copy of the table).
    call asperity_friction_from_homogenised(table, props(1), law)
    call table%free()
    call asperity_friction_state_size(law, words)
    if (words /= state_words) error stop 'vfric: unexpected friction state size'
  end subroutine build_law

end subroutine vfric

!> Calls `vfric` as Abaqus/Explicit would, for one block of four contact
!> points, and prints the friction history.
program vfric_driver
  use asperity
  use vfric_law, only: law, state_words
  implicit none
  integer, parameter :: n_contact = 4, n_sec = 6, n_main = 4, n_fac = 4, n_dir = 3, &
      n_fric_dir = 2, n_state = 9, n_rows = 3, n_props = 2 + 7*n_rows, n_temp = 0, &
      n_pred = 1, num_def_tfv = 1, increments = 100
  real(c_double), parameter :: ds = 1e-8_c_double, dt = 1e-6_c_double
  real(c_double) :: props(n_props), f_tangential(n_fric_dir, n_contact)
  real(c_double) :: statev(n_state, n_sec), d_slip(n_dir, n_contact), f_stick(n_contact)
  real(c_double) :: f_tang_prev(n_dir, n_contact), f_normal(n_contact), shape(n_fac, n_contact)
  real(c_double) :: coord_sec(n_dir, n_sec), coord_main(n_dir, n_main), dir_sl(n_dir, n_contact)
  real(c_double) :: dir_n(n_dir, n_contact), area_sec(n_sec), temp_sec(n_contact)
  real(c_double) :: predef_sec(n_contact, n_pred), temp_main(num_def_tfv)
  real(c_double) :: predef_main(num_def_tfv, n_pred)
  integer :: j_sec_uid(n_sec), j_main_uid(n_main), j_con_sec(n_contact)
  integer :: j_con_main(n_fac, n_contact)
  character(len=80) :: surf_int, surf_sec, surf_main
  real(c_double) :: state(state_words)
  real(c_double) :: ledger
  character(len=200) :: line
  integer :: inc, k

  ! *FRICTION, USER: stick stiffness, three table rows.
  props(1) = 1e8_c_double
  props(2) = n_rows
  props(3:9) = [1e7_c_double, 0.8_c_double, 1.0e6_c_double, 0.01_c_double, 0.90_c_double, &
      0.07_c_double, 0.02_c_double]
  props(10:16) = [5e7_c_double, 0.6_c_double, 3.0e6_c_double, 0.05_c_double, 0.90_c_double, &
      0.07_c_double, 0.02_c_double]
  props(17:23) = [1e8_c_double, 0.5_c_double, 4.4e6_c_double, 0.10_c_double, 0.90_c_double, &
      0.07_c_double, 0.02_c_double]

  ! The mesh: secondary nodes 1..6 (user numbers 101..106), contact points on 2..5.
  j_sec_uid = [(100 + k, k = 1, n_sec)]
  j_main_uid = [(200 + k, k = 1, n_main)]
  j_con_sec = [2, 3, 4, 5]
  j_con_main = 1
  area_sec = 1e-6_c_double
  f_normal = [10.0_c_double, 50.0_c_double, 100.0_c_double, 100.0_c_double]
  f_stick = [1e30_c_double, 1e30_c_double, 1e30_c_double, 20.0_c_double]
  statev = 0 ! fresh points
  surf_int = 'ASPERITY'
  surf_sec = 'SECONDARY'
  surf_main = 'MAIN'
  shape = 0.25_c_double
  coord_sec = 0
  coord_main = 0
  dir_sl = 0
  dir_sl(1, :) = 1
  dir_n = 0
  dir_n(3, :) = 1
  temp_sec = 293
  temp_main = 293
  predef_sec = 0
  predef_main = 0
  f_tang_prev = 0

  write (*, '(a)') '# increment  slip_m  fTangential(1, k) for the four points (N)'
  do inc = 1, increments
    d_slip = 0
    d_slip(1, :) = ds ! local 1-direction: along the slip
    call vfric(f_tangential, statev, 1, inc, n_contact, n_fac, n_sec, n_main, n_fric_dir, &
        n_dir, n_state, n_props, n_temp, n_pred, num_def_tfv, j_sec_uid, j_main_uid, &
        j_con_sec, j_con_main, dt, dt*inc, dt, surf_int, surf_sec, surf_main, 2, d_slip, &
        f_stick, f_tang_prev, f_normal, 0.0_c_double, shape, coord_sec, coord_main, dir_sl, &
        dir_n, props, area_sec, temp_sec, predef_sec, temp_main, predef_main)
    write (line, '(a, i5, es14.6, 4es24.16)') 'friction', inc, ds*inc, f_tangential(1, :)
    write (*, '(a)') trim(line)
    f_tang_prev(1:n_fric_dir, :) = f_tangential
  end do

  ! The histories in statev (C's indices, from 0): dissipation by mechanism,
  ! plastic slip path, slip path, stick force.
  do k = 1, n_contact
    state = statev(1:state_words, j_con_sec(k))
    ledger = sum(state(ASPERITY_HOMOGENISED_STATE_MECHANISMS + 1: &
        ASPERITY_HOMOGENISED_STATE_MECHANISMS + 4))
    call check('dissipation_'//digit(k), ledger)
    call check('chemical_share_'//digit(k), state(ASPERITY_HOMOGENISED_STATE_MECHANISMS + 1)/ &
        ledger)
    call check('slip_path_'//digit(k), state(ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH + 1))
    call check('total_slip_path_'//digit(k), state(ASPERITY_FRICTION_STATE_SLIP_PATH + 1))
    call check('state_force_'//digit(k), state(ASPERITY_HOMOGENISED_STATE_FORCE + 1))
  end do
  call check('untouched_nodes_zero', merge(1.0_c_double, 0.0_c_double, &
      maxval(abs(statev(:, [1, n_sec]))) <= 0))
  call law%free()

contains

  function digit(k) result(s)
    integer, intent(in) :: k
    character(len=1) :: s
    write (s, '(i1)') k
  end function digit

  subroutine check(name, value)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    character(len=32) :: buf
    write (buf, '(es25.17e3)') value
    write (*, '(a)') 'CHECK '//name//' '//trim(adjustl(buf))
  end subroutine check

end program vfric_driver
