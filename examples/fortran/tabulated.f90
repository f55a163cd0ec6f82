!> A tabulated Maugis-Dugdale law in an MD-style loop through the handle
!> type `asperity_table` (examples/c/tabulated_threads.c in Fortran, with a
!> batch call where the C program uses threads).
!>
!> One table is built once and shared, read-only. Each of N_PAIRS sphere
!> pairs follows its own sinusoidal approach history for N_STEPS steps,
!> through jump-in, deep contact and jump-out; the host owns one
!> `asperity_contact_state` per pair.
!>
!> The loop runs twice: with scalar calls (asperity_table_eval, old and new
!> states apart), then with one batch call per step and the states stepped
!> in place (`states=`). The results must be bitwise identical. A subset of
!> pairs is also run with the closed-form Maugis-Dugdale law: same branches,
!> same in-contact sequence, forces within the table's stated tolerance.
!> Then the table goes to JSON text and back.
!>
!> Lines "CHECK <name> <value>" are read by tests/fortran_bindings.rs.
program tabulated
  use asperity
  use, intrinsic :: iso_c_binding, only: c_associated
  implicit none
  integer, parameter :: n_pairs = 2000, n_steps = 100, md_every = 20
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  ! Sphere: R = 1 um, E* = 1 GPa, w = 0.05 J/m^2, Maugis parameter 2.
  real(c_double), parameter :: radius = 1e-6_c_double, e_star = 1e9_c_double, &
      work = 0.05_c_double, lambda = 2.0_c_double
  type(asperity_table) :: table, loaded
  type(asperity_table), allocatable :: scratch
  type(asperity_normal_law) :: md
  type(asperity_normal_response) :: r, rc
  type(asperity_contact_state) :: st1(n_pairs), st2(n_pairs), new_s, old_s, sm, stt
  real(c_double), allocatable :: f1(:, :), a1(:, :), f2(:, :), a2(:, :)
  real(c_double) :: delta(n_pairs)
  real(c_double) :: k, sigma0, unit, tol, measured, pc_table, pc_md, pd_table, pd_md
  real(c_double) :: f_floor, a_floor, max_err, max_rad_err, d
  integer :: i, s, jumps_in, jumps_out, branch_mismatch, contact_mismatch, compared
  integer(c_int32_t) :: st
  logical :: identical
  character(len=:), allocatable :: json

  k = 4*e_star/3
  sigma0 = 0.5_c_double*lambda*(pi*work*k*k/radius)**(1.0_c_double/3)
  allocate (f1(n_pairs, n_steps), a1(n_pairs, n_steps), f2(n_pairs, n_steps), &
      a2(n_pairs, n_steps))

  call asperity_table_new_maugis_dugdale(radius, e_star, work, sigma0, 1e-4_c_double, table)
  call asperity_law_maugis_dugdale(radius, e_star, work, sigma0, md)
  call asperity_law_length_scale(md, unit)
  call asperity_table_max_error(table, tol, measured=measured)
  call check('table_tolerance', tol)
  call check('table_measured_error', measured)

  ! Pull-off forces: exact from the curve.
  call asperity_table_pull_off_force(table, ASPERITY_CONTROL_LOAD, pc_table)
  call asperity_pull_off_force(md, ASPERITY_CONTROL_LOAD, pc_md)
  call asperity_table_pull_off_force(table, ASPERITY_CONTROL_DISPLACEMENT, pd_table)
  call asperity_pull_off_force(md, ASPERITY_CONTROL_DISPLACEMENT, pd_md)
  call check('pull_off_load_rel_diff', abs(pc_table - pc_md)/abs(pc_md))
  call check('pull_off_displacement_rel_diff', abs(pd_table - pd_md)/abs(pd_md))
  call asperity_normal_eval_at_load(md, pc_md, r)
  f_floor = 1e-3_c_double*abs(pc_md)
  a_floor = 1e-3_c_double*r%contact_radius

  ! 1. Scalar calls, old and new states apart.
  jumps_in = 0
  jumps_out = 0
  do s = 1, n_steps
    do i = 1, n_pairs
      call asperity_table_eval(table, approach(i, s), r, old_state=st1(i), new_state=new_s)
      if (new_s%branch > st1(i)%branch) jumps_in = jumps_in + 1
      if (new_s%branch < st1(i)%branch) jumps_out = jumps_out + 1
      st1(i) = new_s
      f1(i, s) = r%force
      a1(i, s) = r%contact_radius
    end do
  end do

  ! 2. One batch call per step, states in place.
  do s = 1, n_steps
    do i = 1, n_pairs
      delta(i) = approach(i, s)
    end do
    call asperity_table_eval_batch(table, delta, f2(:, s), contact_radius=a2(:, s), states=st2)
  end do
  identical = all(transfer(f1, [0_c_int64_t]) == transfer(f2, [0_c_int64_t])) .and. &
      all(transfer(a1, [0_c_int64_t]) == transfer(a2, [0_c_int64_t])) .and. &
      all(transfer(st1, [0_c_int64_t]) == transfer(st2, [0_c_int64_t]))
  call check('batch_identical', flag(identical))
  call check('jumps_in', real(jumps_in, c_double))
  call check('jumps_out', real(jumps_out, c_double))

  ! 3. Every md_every-th pair with the closed-form law.
  branch_mismatch = 0
  contact_mismatch = 0
  compared = 0
  max_err = 0
  max_rad_err = 0
  do i = 1, n_pairs, md_every
    sm = asperity_contact_state()
    stt = asperity_contact_state()
    do s = 1, n_steps
      d = approach(i, s)
      call asperity_normal_eval(md, d, rc, old_state=sm, new_state=old_s)
      call asperity_table_eval(table, d, r, old_state=stt, new_state=new_s)
      if (old_s%branch /= new_s%branch) branch_mismatch = branch_mismatch + 1
      if (rc%in_contact /= r%in_contact .or. old_s%in_contact /= new_s%in_contact) &
          contact_mismatch = contact_mismatch + 1
      max_err = max(max_err, abs(r%force - rc%force)/max(abs(rc%force), f_floor))
      max_rad_err = max(max_rad_err, abs(r%contact_radius - rc%contact_radius)/ &
          max(rc%contact_radius, a_floor))
      sm = old_s
      stt = new_s
      compared = compared + 1
    end do
  end do
  call check('md_compared', real(compared, c_double))
  call check('md_branch_mismatches', real(branch_mismatch, c_double))
  call check('md_in_contact_mismatches', real(contact_mismatch, c_double))
  call check('md_max_rel_force_error', max_err)
  call check('md_max_rel_radius_error', max_rad_err)

  ! 4. Store and load: the loaded table evaluates bit-identically.
  call asperity_table_to_json(table, json)
  call asperity_table_from_json(json, loaded)
  identical = .true.
  do i = 1, n_pairs, 7
    old_s = asperity_contact_state()
    new_s = asperity_contact_state()
    do s = 1, n_steps
      d = approach(i, s)
      call asperity_table_eval(table, d, r, state=old_s)
      call asperity_table_eval(loaded, d, rc, state=new_s)
      identical = identical .and. all(transfer(r, [0_c_int64_t]) == transfer(rc, [0_c_int64_t])) &
          .and. all(transfer(old_s, [0_c_int64_t]) == transfer(new_s, [0_c_int64_t]))
    end do
  end do
  call check('json_bytes', real(len(json), c_double))
  call check('json_roundtrip_identical', flag(identical))
  call loaded%free()
  ! A damaged text is refused with a message, not loaded.
  json(len(json)/2:len(json)/2) = '}'
  call asperity_table_from_json(json, loaded, status=st)
  call check('json_corrupt_status', real(st, c_double))
  call check('json_corrupt_out_is_null', flag(.not. c_associated(loaded%ptr)))
  write (*, '(a)') 'corrupt JSON: '//asperity_last_error_message()

  ! A handle in an allocatable is freed when it is deallocated (finalised).
  allocate (scratch)
  call asperity_table_new_maugis_dugdale(radius, e_star, work, sigma0, 1e-3_c_double, scratch)
  call check('scratch_built', flag(c_associated(scratch%ptr)))
  deallocate (scratch)
  ! Assigning an empty handle empties a handle (copying a live one would stop).
  loaded = asperity_table()
  call asperity_free(table)
  call check('freed_is_null', flag(.not. c_associated(table%ptr)))
  write (*, '(a, i0, a, i0, a)') 'tabulated: ', n_pairs, ' pairs x ', n_steps, ' steps'
  ! Main-program allocatables outlive END PROGRAM unless released: release
  ! them, so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(f1)) deallocate (f1)
  if (allocated(a1)) deallocate (a1)
  if (allocated(f2)) deallocate (f2)
  if (allocated(a2)) deallocate (a2)
  if (allocated(json)) deallocate (json)

contains

  !> Approach of pair i at step s (m): a sinusoid around a pair-dependent
  !> mean, spanning far separation to a few overlap units of compression.
  pure real(c_double) function approach(i, s)
    integer, intent(in) :: i, s
    real(c_double) :: mean, amp, phase, period
    mean = (0.5_c_double + 1.5_c_double*mod(i - 1, 97)/97.0_c_double)*unit
    amp = (2.5_c_double + 2.0_c_double*mod(i - 1, 89)/89.0_c_double)*unit
    phase = 2*pi*mod(i - 1, 101)/101.0_c_double
    period = 25.0_c_double + mod(i - 1, 13)
    approach = mean + amp*sin(2*pi*(s - 1)/period + phase)
  end function approach

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

end program tabulated
