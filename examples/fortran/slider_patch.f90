!> The full hierarchical slider as the friction law of a few FE surface
!> patches (examples/c/slider_patch.c in Fortran): each patch is one slider
!> of the chapter-6 scene (90 micro-rods of 1.5 um x 13.5 um carrying
!> nano-asperities) against the counter-surface profile, with its own
!> caller-owned state, normal force and slip direction.
!>
!> The program reads examples/scenes/chapter6_copper.json (or the scene given
!> as the first argument; without an argument and run from elsewhere than the
!> crate root it uses an inline copy of that scene), builds the slider, its
!> friction law (`asperity_friction_from_slider`) and one work handle, and
!> steps four patches with asperity_friction_step_block_in_place (the call
!> shape of an Abaqus/Explicit VFRIC user subroutine) for 60 increments of
!> |slip| = 1.5 um:
!>
!>   patch  normal force           slip direction   start on the track
!>   1      0.05 x capacity        +x               0
!>   2      0.10 x capacity        30 degrees       45 um
!>   3      0.20 x capacity        +y               0
!>   4      0.35 x capacity        -x               0
!>
!> States are the columns of `states(m, 4)` (m = asperity_friction_state_size),
!> all-zero at first (fresh: the first call seats each patch), stepped in
!> place; slips and forces are (2, 4) arrays, column i patch i's (x, y).
!> Copies of the states are stepped alongside, one patch at a time with
!> asperity_friction_step_in_place, and must agree bit for bit. After each
!> block, asperity_slider_get_record gives the full record of its last
!> patch's step (positions, counts of contacts, whether the step seated a
!> fresh state), checked against the state. Then one scalar step with
!> tangents (its record printed for tests/fortran_bindings.rs to compare
!> with the Rust API), a re-evaluation of an increment from the same old
!> state, a zero-slip increment and errors returned through `status=`.
!>
!> The program checks itself: it prints "CHECK <name> <value>" lines, and
!> every failed expectation on error_unit, and stops with `error stop` when
!> one failed.
program slider_patch
  use asperity
  use, intrinsic :: iso_fortran_env, only: error_unit
  use, intrinsic :: iso_c_binding, only: c_associated
  implicit none
  integer, parameter :: np = 4, steps = 60
  real(c_double), parameter :: step = 1.5e-6_c_double ! slip per increment (m)
  real(c_double), parameter :: dt = 1e-5_c_double     ! s, unused by the law
  character(len=*), parameter :: default_path = 'examples/scenes/chapter6_copper.json'
  ! examples/scenes/chapter6_copper.json, for runs outside the crate root.
  character(len=*), parameter :: inline_scene = &
      '{"material": {"preset": "copper"},' // &
      ' "surfaces": {' // &
      '  "slider": {"self_affine": {"hurst": 0.8, "rq": 5e-7, "roll_off_wavelength": 1e-4,' // &
      '   "points": 91, "dx": 1.5e-6, "seed": 6}},' // &
      '  "counter": {"self_affine": {"hurst": 0.8, "rq": 5e-7, "roll_off_wavelength": 1e-4,' // &
      '   "points": 241, "dx": 1.5e-6, "seed": 7}},' // &
      '  "nano": {"asperities": {"h_vdw": 6e-9, "w_vdw": 4.3e-7, "h_chem": 2.2e-9,' // &
      '   "w_chem": 1.61e-7, "spacing": 1.35e-6}}},' // &
      ' "rods": {"widths": [1.5e-6], "depth": 1.35e-5},' // &
      ' "mechanisms": {"chemical": true, "van_der_waals": true, "elastic": true,' // &
      '  "plastic": true},' // &
      ' "cof_form": "Derjaguin",' // &
      ' "loading": {"fixed_load": {"load": 0.18}},' // &
      ' "sliding": {"distance": 1.5e-4, "step": 1.5e-6},' // &
      ' "outputs": {"csv": true, "svg": true}}'
  real(c_double), parameter :: fraction(np) = [0.05_c_double, 0.10_c_double, 0.20_c_double, &
      0.35_c_double]
  real(c_double), parameter :: start(np) = [0.0_c_double, 45e-6_c_double, 0.0_c_double, &
      0.0_c_double]
  type(asperity_slider) :: slider, empty
  type(asperity_friction) :: law, empty_law
  type(asperity_friction_work) :: work, other_work
  type(asperity_slider_record) :: rec, rec2
  type(asperity_lugre_params) :: lugre
  type(asperity_slider_info) :: info, info2
  type(asperity_friction_increment) :: inc
  type(asperity_friction_response) :: r, r2
  real(c_double), allocatable :: states(:, :), scalar(:, :), copy(:, :), a(:), b(:)
  real(c_double) :: direction(2, np), normal(np), slip(2, np), force(2, np), diss(np)
  real(c_double) :: work_done(np), dissipated(np), force_sum(np)
  real(c_double) :: min_diss, max_misalignment, fx, fy, sx, sy, fm, dot, acc, mean
  logical :: opposes, block_equals_scalar, identical, ok
  logical :: record_seated, record_matches_state, record_counts
  real(c_double) :: before, record_max_advance_diff
  integer :: failures, i, n, m
  integer(c_int32_t) :: st
  character(len=:), allocatable :: json, path, msg
  character(len=2) :: p

  failures = 0
  call scene_text(json)

  ! The scene names no files; a scene that does would pass its directory as
  ! `base_dir=`.
  call asperity_slider_from_scene_json(json, slider)
  ! The slider as the friction law of a patch: the increment's normal force
  ! is the fixed load.
  call asperity_friction_from_slider(slider, law)
  call asperity_friction_work_new(law, work)
  call asperity_slider_get_info(slider, info)
  call asperity_friction_state_size(law, m)
  call check('state_size', real(m, c_double))
  call check('rods', real(info%rods, c_double))
  call check('capacity', info%capacity)
  call expect('state_size', m == info%state_size .and. &
      m == ASPERITY_SLIDER_STATE_HEIGHTS + 2*info%rods, 'the state size disagrees with the info')
  call expect('capacity', info%capacity > 0, 'no load capacity')
  write (*, '(a, i0, a, f5.2, a, f6.2, a, es11.4, a, f9.6, a)') '# slider: ', info%rods, &
      ' rods of ', info%rod_width*1e6_c_double, ' um x ', info%depth*1e6_c_double, &
      ' um, nominal area ', info%nominal_area, ' m^2, capacity ', info%capacity, ' N'

  allocate (states(m, np), a(m), b(m))
  states = 0 ! all-zero: fresh
  direction(:, 1) = [1.0_c_double, 0.0_c_double]
  direction(:, 2) = [sqrt(3.0_c_double)/2, 0.5_c_double]
  direction(:, 3) = [0.0_c_double, 1.0_c_double]
  direction(:, 4) = [-1.0_c_double, 0.0_c_double]
  do i = 1, np
    normal(i) = fraction(i)*info%capacity
    slip(:, i) = step*direction(:, i)
    ! A fresh state starts at its position: stagger the patches.
    states(ASPERITY_SLIDER_STATE_POSITION + 1, i) = start(i)
  end do
  ! The same patches stepped one at a time with asperity_friction_step_in_place.
  scalar = states
  work_done = 0
  dissipated = 0
  force_sum = 0
  min_diss = 0
  max_misalignment = 0
  opposes = .true.
  block_equals_scalar = .true.
  record_seated = .true.
  record_matches_state = .true.
  record_counts = .true.
  record_max_advance_diff = 0

  do n = 1, steps
    before = states(ASPERITY_SLIDER_STATE_POSITION + 1, np)
    call asperity_friction_step_block_in_place(law, normal, slip, dt, states, force, &
        dissipation=diss, work=work)
    ! The record of the block's last patch, read before the scalar steps
    ! below reuse the work: seated (fresh state) on the first block only; the
    ! slider advanced along its track by |slip|, to the state's position; the
    ! counts nest.
    call asperity_slider_get_record(work, rec)
    if (n <= 2) then
      write (p, '(i0)') n - 1
      call check('record_block'//trim(p)//'_seated', real(rec%seated, c_double))
      call check('record_block'//trim(p)//'_position', rec%position)
    end if
    record_seated = record_seated .and. rec%seated == merge(1, 0, n == 1)
    record_matches_state = record_matches_state .and. &
        same([rec%position, rec%rod_position], &
        states(ASPERITY_SLIDER_STATE_POSITION + 1:ASPERITY_SLIDER_STATE_ROD_POSITION + 1, np))
    record_max_advance_diff = max(record_max_advance_diff, abs(rec%position - before - step))
    record_counts = record_counts .and. counts_nest(rec)
    do i = 1, np
      inc = asperity_friction_increment(normal_force=normal(i), slip=slip(:, i), dt=dt)
      call asperity_friction_step_in_place(law, inc, scalar(:, i), r, work)
      block_equals_scalar = block_equals_scalar .and. &
          same(r%force, force(:, i)) .and. same([r%dissipated], [diss(i)])
      fx = force(1, i)
      fy = force(2, i)
      sx = slip(1, i)
      sy = slip(2, i)
      fm = hypot(fx, fy)
      dot = fx*sx + fy*sy
      work_done(i) = work_done(i) - dot
      dissipated(i) = dissipated(i) + diss(i)
      force_sum(i) = force_sum(i) + fm
      min_diss = min(min_diss, diss(i))
      opposes = opposes .and. dot < 0
      if (fm > 0) max_misalignment = max(max_misalignment, abs(fx*sy - fy*sx)/(fm*step))
    end do
  end do
  block_equals_scalar = block_equals_scalar .and. same(reshape(states, [m*np]), &
      reshape(scalar, [m*np]))
  call check('block_equals_scalar', flag(block_equals_scalar))
  call expect('block_equals_scalar', block_equals_scalar, &
      'asperity_friction_step_block_in_place and asperity_friction_step_in_place differ on '// &
      'the same increments')

  write (*, '(a)') '# patch  normal_N  mean_friction_N  friction_over_load  dissipation_J  '// &
      'slip_path_m'
  do i = 1, np
    write (p, '(i0)') i - 1
    acc = sum(states(ASPERITY_SLIDER_STATE_MECHANISMS + 1:ASPERITY_SLIDER_STATE_MECHANISMS + 4, &
        i))
    mean = force_sum(i)/steps
    write (*, '(a, i0, es13.6, es16.9, f9.6, es16.9, es13.6)') 'patch ', i - 1, normal(i), &
        mean, mean/normal(i), dissipated(i), states(ASPERITY_FRICTION_STATE_SLIP_PATH + 1, i)
    call check('patch'//trim(p)//'_mean_friction_force', mean)
    call check('patch'//trim(p)//'_dissipation', dissipated(i))
    call expect('patch'//trim(p)//'_dissipation', dissipated(i) > 0, 'nothing dissipated')
    ! The work of the friction force is the dissipated energy.
    call within('patch'//trim(p)//'_work_dissipation_rel_diff', &
        rel_diff(work_done(i), dissipated(i)), 0.0_c_double, 1e-12_c_double)
    ! The state's ledgers sum the increments: by mechanism, and the total.
    call within('patch'//trim(p)//'_state_dissipation_rel_diff', rel_diff(acc, dissipated(i)), &
        0.0_c_double, 1e-12_c_double)
    call within('patch'//trim(p)//'_state_total_dissipation_rel_diff', &
        rel_diff(states(ASPERITY_FRICTION_STATE_DISSIPATION + 1, i), dissipated(i)), &
        0.0_c_double, 1e-12_c_double)
    ! The slider advances along its track by |slip| per increment.
    call within('patch'//trim(p)//'_slip_path_rel_diff', &
        rel_diff(states(ASPERITY_FRICTION_STATE_SLIP_PATH + 1, i), steps*step), 0.0_c_double, &
        1e-12_c_double)
    call within('patch'//trim(p)//'_position_rel_diff', &
        rel_diff(states(ASPERITY_SLIDER_STATE_POSITION + 1, i), start(i) + steps*step), &
        0.0_c_double, 1e-12_c_double)
    ! Chemical bonds dominate (thesis 6.5.2).
    call within('patch'//trim(p)//'_chemical_share', &
        states(ASPERITY_SLIDER_STATE_MECHANISMS + 1, i)/acc, 0.5_c_double, 1.0_c_double)
  end do
  ! One more increment with the old and new states apart equals it in place.
  copy = states
  scalar = states
  call asperity_friction_step_block(law, normal, slip, dt, states, copy, force, &
      dissipation=diss, work=work)
  call asperity_friction_step_block_in_place(law, normal, slip, dt, scalar, force, work=work)
  ok = same(reshape(copy, [m*np]), reshape(scalar, [m*np]))
  call check('block_apart_equals_in_place', flag(ok))
  call expect('block_apart_equals_in_place', ok, &
      'asperity_friction_step_block and asperity_friction_step_block_in_place differ')
  call within('min_increment_dissipation', min_diss, 0.0_c_double, 0.0_c_double)
  call within('max_misalignment', max_misalignment, 0.0_c_double, 1e-15_c_double)
  call check('opposes_slip', flag(opposes))
  call expect('opposes_slip', opposes, 'a tangential force did not oppose the slip')
  call check('record_seated_ok', flag(record_seated))
  call expect('record_seated_ok', record_seated, &
      'the record says seated other than on the first step of a fresh state')
  call check('record_position_matches_state', flag(record_matches_state))
  call expect('record_position_matches_state', record_matches_state, &
      "the record's positions differ from the state's")
  call within('record_max_advance_diff', record_max_advance_diff, 0.0_c_double, 1e-18_c_double)
  call check('record_counts_consistent', flag(record_counts))
  call expect('record_counts_consistent', record_counts, &
      'adhesive > nano contacts, yielded > rods in contact, or no contact')
  write (*, '(a, es13.6, a, es13.6, 4(a, i0), a)') "# record of patch 3's last step: X =", &
      rec%position, ' m, b =', rec%rod_position, ' m, ', rec%nano_contacts, &
      ' nano contacts (', rec%adhesive_contacts, ' adhesive), ', rec%rods_in_contact, &
      ' rods in contact (', rec%yielded_rods, ' yielded)'

  ! One scalar step of patch 1 with both tangents, from its state.
  inc = asperity_friction_increment(normal_force=normal(1), slip=[step, 0.0_c_double], dt=dt, &
      tangents=ASPERITY_FRICTION_TANGENT_NORMAL + ASPERITY_FRICTION_TANGENT_SLIP)
  call asperity_friction_step(law, inc, states(:, 1), a, r, work)
  call check('tangent_friction_force', r%force_magnitude)
  ! dforce_dnormal(1) and dforce_dslip(1, 1) are C's [0] and [0][0].
  call check('tangent_dfdn', r%dforce_dnormal(1))
  call check('tangent_dfds_along', r%dforce_dslip(1, 1))
  call within('tangents_flag', real(r%tangents, c_double), 3.0_c_double, 3.0_c_double)
  ! Across the slip the force turns with it: -F_t/|slip|.
  call within('tangent_transverse_rel_diff', &
      rel_diff(r%dforce_dslip(2, 2), -r%force_magnitude/step), 0.0_c_double, 1e-12_c_double)
  ! Force along -x for slip along +x; F_t |slip| is the dissipation.
  call within('tangent_force_rel_diff', rel_diff(r%force(1), -r%force_magnitude), &
      0.0_c_double, 0.0_c_double)
  call within('tangent_work_rel_diff', rel_diff(r%force_magnitude*step, r%dissipated), &
      0.0_c_double, 1e-12_c_double)
  ! The step's own record, not a tangent evaluation's: one |slip| further
  ! than the old state, at the new state's position.
  call asperity_slider_get_record(work, rec)
  call check('tangent_record_position', rec%position)
  call within('tangent_record_advance_diff', &
      abs(rec%position - states(ASPERITY_SLIDER_STATE_POSITION + 1, 1) - step), 0.0_c_double, &
      1e-18_c_double)
  ok = same([rec%position, rec%rod_position], &
      a(ASPERITY_SLIDER_STATE_POSITION + 1:ASPERITY_SLIDER_STATE_ROD_POSITION + 1))
  call check('tangent_record_matches_state', flag(ok))
  call expect('tangent_record_matches_state', ok, "the record's positions differ from the "// &
      "new state's")
  call check('tangent_record_rod_position', rec%rod_position)
  call check('tangent_record_adhesion_area_share', rec%adhesion_area_share)
  call check('tangent_record_nano_contacts', real(rec%nano_contacts, c_double))
  call check('tangent_record_adhesive_contacts', real(rec%adhesive_contacts, c_double))
  call check('tangent_record_rods_in_contact', real(rec%rods_in_contact, c_double))
  call check('tangent_record_yielded_rods', real(rec%yielded_rods, c_double))
  call within('tangent_record_seated', real(rec%seated, c_double), 0.0_c_double, 0.0_c_double)
  call expect('tangent_record_counts', counts_nest(rec), 'the counts do not nest')
  ! Re-evaluating the increment from the same old state (a cut-back) gives
  ! identical results; the old state is untouched.
  copy = states
  call asperity_friction_step(law, inc, states(:, 1), b, r2, work)
  call asperity_slider_get_record(work, rec2)
  identical = all(transfer(r, [0_c_int64_t]) == transfer(r2, [0_c_int64_t])) .and. same(a, b) &
      .and. same(copy(:, 1), states(:, 1)) .and. &
      all(transfer(rec, [0_c_int64_t]) == transfer(rec2, [0_c_int64_t]))
  call check('reevaluation_identical', flag(identical))
  call expect('reevaluation_identical', identical, 're-evaluating an increment differed')
  ! A zero slip increment: stick, no force, nothing dissipated.
  inc%slip = 0
  inc%tangents = 0
  call asperity_friction_step(law, inc, states(:, 1), a, r, work)
  call within('zero_slip_force', abs(r%force(1)) + abs(r%force(2)), 0.0_c_double, 0.0_c_double)
  call within('zero_slip_dissipated', r%dissipated, 0.0_c_double, 0.0_c_double)
  call within('zero_slip_regime', real(r%regime, c_double), real(ASPERITY_FRICTION_STICK, &
      c_double), real(ASPERITY_FRICTION_STICK, c_double))
  ! The rods re-seated where the slider stands: no advance.
  call asperity_slider_get_record(work, rec)
  call within('zero_slip_record_advance', &
      rec%position - states(ASPERITY_SLIDER_STATE_POSITION + 1, 1), 0.0_c_double, 0.0_c_double)
  call within('zero_slip_record_seated', real(rec%seated, c_double), 0.0_c_double, &
      0.0_c_double)

  ! Errors. A normal force above the capacity at patch 3 (C's element 2)
  ! names the element and the argument; patches before are written, the
  ! rest untouched.
  copy = states
  normal(3) = 2*info%capacity
  call asperity_friction_step_block_in_place(law, normal, slip, dt, states, force, &
      dissipation=diss, work=work, status=st)
  call expect_error('bad_load', st, ASPERITY_ERR_OUT_OF_DOMAIN, 'element 2', '`normal_force`')
  ok = .not. same(reshape(copy(:, 1:2), [2*m]), reshape(states(:, 1:2), [2*m]))
  call check('bad_load_before_written', flag(ok))
  call expect('bad_load_before_written', ok, 'patches 1 and 2 not stepped')
  ok = same(reshape(copy(:, 3:4), [2*m]), reshape(states(:, 3:4), [2*m]))
  call check('bad_load_rest_untouched', flag(ok))
  call expect('bad_load_rest_untouched', ok, 'patches 3 and 4 changed')
  normal(3) = fraction(3)*info%capacity
  ! States whose columns are not the state size: the module names the
  ! argument before calling the library.
  deallocate (copy)
  allocate (copy(m - 1, np))
  copy = 0
  call asperity_friction_step_block_in_place(law, normal, slip, dt, copy, force, work=work, &
      status=st)
  call expect_error('short_states', st, ASPERITY_ERR_INVALID_ARGUMENT, '`states`', &
      'state size')
  ! An unknown tangents bit names `tangents`.
  inc = asperity_friction_increment(tangents=8)
  a = 0
  call asperity_friction_step_in_place(law, inc, a, r, work, status=st)
  call expect_error('bad_tangents', st, ASPERITY_ERR_INVALID_ARGUMENT, '`tangents`', '8')
  ! An empty handle is a NULL pointer named `slider` (`law` for the friction
  ! law).
  call asperity_slider_get_info(empty, info2, status=st)
  call expect_error('null_handle', st, ASPERITY_ERR_NULL_POINTER, '`slider`', 'NULL')
  call asperity_friction_state_size(empty_law, n, status=st)
  call expect_error('null_law', st, ASPERITY_ERR_NULL_POINTER, '`law`', 'NULL')
  ! A work with no slider step has no record, named `work`: an empty one
  ! (NULL), or a LuGre law's.
  call asperity_slider_get_record(other_work, rec, status=st)
  call expect_error('record_null_work', st, ASPERITY_ERR_NULL_POINTER, '`work`', 'NULL')
  lugre = asperity_lugre_params(mu_coulomb=0.3_c_double, mu_static=0.5_c_double, &
      stribeck_velocity=1e-3_c_double, stribeck_exponent=2.0_c_double, sigma0=1e5_c_double, &
      sigma1=1000.0_c_double, damping_velocity=1e-3_c_double)
  call asperity_friction_lugre_new(lugre, empty_law)
  call asperity_friction_work_new(empty_law, other_work)
  call asperity_slider_get_record(other_work, rec, status=st)
  call expect_error('record_lugre_work', st, ASPERITY_ERR_INVALID_ARGUMENT, '`work`', 'slider')
  call other_work%free()
  call empty_law%free()
  ! A scene with a wrong field type is a parse error; the handle stays empty.
  call asperity_slider_from_scene_json('{ "material": 3 }', empty, status=st)
  call expect_error('bad_scene', st, ASPERITY_ERR_PARSE, '`json`', 'line 1')
  call expect('bad_scene_empty', .not. c_associated_handle(empty), 'a handle after a failure')
  ! With a base directory for the files a scene names (this one names none):
  ! the same slider.
  call asperity_slider_from_scene_json(json, empty, base_dir='.')
  call asperity_slider_get_info(empty, info2)
  ok = all(transfer(info, [0_c_int64_t]) == transfer(info2, [0_c_int64_t]))
  call check('base_dir_same_slider', flag(ok))
  call expect('base_dir_same_slider', ok, 'a slider built with base_dir differs')
  call empty%free()

  call work%free()
  call law%free()
  call slider%free()
  call asperity_free(slider) ! an empty handle is accepted

  if (failures > 0) then
    write (error_unit, '(a, i0, a)') 'slider_patch: ', failures, ' check(s) failed'
    error stop 1
  end if
  write (*, '(a)') '# all checks passed'
  ! Main-program allocatables outlive END PROGRAM unless released: release
  ! them, so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(states)) deallocate (states)
  if (allocated(scalar)) deallocate (scalar)
  if (allocated(copy)) deallocate (copy)
  if (allocated(a)) deallocate (a)
  if (allocated(b)) deallocate (b)
  if (allocated(json)) deallocate (json)
  if (allocated(path)) deallocate (path)
  if (allocated(msg)) deallocate (msg)

contains

  !> The scene: the file named by the first argument, else the default path,
  !> else (no argument, file not found from here) the inline copy.
  subroutine scene_text(text)
    character(len=:), allocatable, intent(out) :: text
    integer :: length, u, ios
    integer(c_int64_t) :: bytes
    if (command_argument_count() >= 1) then
      call get_command_argument(1, length=length)
      allocate (character(len=length) :: path)
      call get_command_argument(1, path)
    else
      path = default_path
    end if
    open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
        action='read', iostat=ios)
    if (ios /= 0) then
      if (command_argument_count() >= 1) then
        write (error_unit, '(a)') 'slider_patch: cannot read '//path
        error stop 1
      end if
      write (*, '(a)') '# '//path//' not found from here: the inline copy of the scene'
      text = inline_scene
      return
    end if
    inquire (unit=u, size=bytes)
    allocate (character(len=int(bytes)) :: text)
    read (u, iostat=ios) text
    close (u)
    if (ios /= 0) then
      write (error_unit, '(a)') 'slider_patch: cannot read '//path
      error stop 1
    end if
  end subroutine scene_text

  !> Adhesive contacts among the nano contacts, yielded rods among the rods
  !> in contact, among the slider's rods; the slider in contact.
  logical function counts_nest(x)
    type(asperity_slider_record), intent(in) :: x
    counts_nest = x%nano_contacts > 0 .and. x%adhesive_contacts <= x%nano_contacts .and. &
        x%rods_in_contact > 0 .and. x%rods_in_contact <= info%rods .and. &
        x%yielded_rods <= x%rods_in_contact .and. x%adhesion_area_share >= 0 .and. &
        x%adhesion_area_share <= 1 .and. x%reserved == 0
  end function counts_nest

  logical function c_associated_handle(h)
    type(asperity_slider), intent(in) :: h
    c_associated_handle = c_associated(h%ptr)
  end function c_associated_handle

  !> The same bits.
  logical function same(x, y)
    real(c_double), intent(in) :: x(:), y(:)
    same = size(x) == size(y)
    if (same) same = all(transfer(x, [0_c_int64_t]) == transfer(y, [0_c_int64_t]))
  end function same

  pure real(c_double) function rel_diff(got, want)
    real(c_double), intent(in) :: got, want
    rel_diff = abs(got - want)/merge(abs(want), 1.0_c_double, abs(want) > 0)
  end function rel_diff

  pure real(c_double) function flag(condition)
    logical, intent(in) :: condition
    flag = merge(1.0_c_double, 0.0_c_double, condition)
  end function flag

  subroutine check(name, value)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    character(len=32) :: buf
    write (buf, '(es25.17e3)') value
    write (*, '(a)') 'CHECK '//name//' '//trim(adjustl(buf))
  end subroutine check

  !> Record an expectation; a failure is reported on error_unit and counted.
  subroutine expect(name, condition, detail)
    character(len=*), intent(in) :: name, detail
    logical, intent(in) :: condition
    if (.not. condition) then
      failures = failures + 1
      write (error_unit, '(a)') 'slider_patch: FAILED '//name//': '//detail
    end if
  end subroutine expect

  !> Print `value`, which must lie in [lo, hi].
  subroutine within(name, value, lo, hi)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value, lo, hi
    character(len=80) :: buf
    call check(name, value)
    write (buf, '(es12.4, a, es12.4, a, es12.4, a)') value, ' outside [', lo, ', ', hi, ']'
    call expect(name, value >= lo .and. value <= hi, trim(buf))
  end subroutine within

  !> The status `got` must be `want`, and the message name both `word1` and
  !> `word2`.
  subroutine expect_error(name, got, want, word1, word2)
    character(len=*), intent(in) :: name, word1, word2
    integer(c_int32_t), intent(in) :: got, want
    character(len=16) :: buf
    msg = asperity_last_error_message()
    write (*, '(a)') '# '//name//': '//msg
    call check(name//'_status', real(got, c_double))
    write (buf, '(i0)') got
    call expect(name, got == want, 'status '//trim(buf)//' ('//msg//')')
    call expect(name, index(msg, word1) > 0, 'the message lacks '//word1//': '//msg)
    call expect(name, index(msg, word2) > 0, 'the message lacks '//word2//': '//msg)
  end subroutine expect_error

end program slider_patch
