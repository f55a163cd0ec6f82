!> JKR sphere under displacement control: approach, then retraction
!> (examples/c/jkr_hysteresis.c in Fortran).
!>
!> The host owns the per-contact history (`type(asperity_contact_state)`,
!> all-zero when declared) and keeps the state at the start of the step
!> ("old") apart from the state at its end ("new"); it accepts a step by
!> copying new to old. On approach the contact forms at delta = 0 with a jump
!> to a finite radius (jump-in); on retraction it holds down to the negative
!> critical approach delta_c and then snaps off (jump-out).
!>
!> Numbers: the worked example of REFERENCE.md section 8, R = 1 um,
!> w = 0.05 J/m^2, E* = 1 GPa. The law's inputs are read back through the
!> `asperity_jkr_params` mirror of the law's parameter union, its critical
!> approach through `asperity_normal_reach`.
!>
!> Lines "CHECK <name> <value>" and the rows starting with "approach" or
!> "retract" are read by tests/fortran_bindings.rs.
program jkr_hysteresis
  use asperity
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
  implicit none
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double), parameter :: radius = 1e-6_c_double, work = 0.05_c_double, e_star = 1e9_c_double
  integer, parameter :: n_approach_lo = -20, n_approach_hi = 40, n_retract = 62
  real(c_double) :: piwr, delta_c, abs_dc, a_jump, h, delta, p_load, p_disp, min_force
  real(c_double) :: jump_in_delta, last_contact, first_free, reach
  type(asperity_normal_law) :: law
  type(asperity_jkr_params) :: jkr
  type(asperity_contact_state) :: old_state, new_state, saved, fresh
  type(asperity_normal_response) :: r, r2
  logical :: old_unchanged, reeval_identical
  character(len=16) :: mark
  integer :: i

  piwr = pi*work*radius
  delta_c = -0.75_c_double*(pi*pi*work*work*radius/(e_star*e_star))**(1.0_c_double/3)
  abs_dc = abs(delta_c)
  a_jump = (2*pi*work*radius*radius/e_star)**(1.0_c_double/3)
  h = abs_dc/20
  jump_in_delta = ieee_value(h, ieee_quiet_nan)
  last_contact = jump_in_delta
  first_free = jump_in_delta
  min_force = 0
  old_unchanged = .true.
  reeval_identical = .true.

  call asperity_law_jkr(radius, e_star, work, law)
  write (*, '(a, 3es10.2, a)') 'JKR sphere: R, w, E* =', radius, work, e_star, &
      ', library '//asperity_version()

  ! The law is a plain value: its inputs are the JKR member of the C union.
  jkr = transfer(law%params, jkr)
  call check('law_kind_is_jkr', flag(law%kind == ASPERITY_LAW_KIND_JKR))
  call check('jkr_params_radius', jkr%radius)
  call check('jkr_params_e_star', jkr%e_star)
  call check('jkr_params_work_of_adhesion', jkr%work_of_adhesion)
  call asperity_normal_reach(law, ASPERITY_CONTROL_DISPLACEMENT, 0.5_c_double, reach)
  call check('jkr_reach_displacement', reach)

  call asperity_pull_off_force(law, ASPERITY_CONTROL_LOAD, p_load)
  call asperity_pull_off_force(law, ASPERITY_CONTROL_DISPLACEMENT, p_disp)
  write (*, '(a, es14.6, a, f9.6, a)') 'pull-off, load control:         ', p_load, ' N = ', &
      p_load/piwr, ' pi w R (theory -3/2)'
  write (*, '(a, es14.6, a, f9.6, a)') 'pull-off, displacement control: ', p_disp, ' N = ', &
      p_disp/piwr, ' pi w R (theory -5/6)'

  ! Approach from out of range, accepting every step.
  do i = n_approach_lo, n_approach_hi
    delta = i*h
    mark = ''
    saved = old_state
    call asperity_normal_eval(law, delta, r, old_state=old_state, new_state=new_state)
    if (.not. same_state(saved, old_state)) old_unchanged = .false.
    if (old_state%in_contact == 0 .and. new_state%in_contact == 1) then
      mark = '   <- jump-in'
      if (ieee_is_nan(jump_in_delta)) jump_in_delta = delta
    end if
    call row('approach', delta, r, mark)
    old_state = new_state
  end do

  ! Retraction, on a grid offset by h/2 so that delta_c falls between points.
  do i = 0, n_retract - 1
    delta = (n_approach_hi - 0.5_c_double - i)*h
    mark = ''
    saved = old_state
    call asperity_normal_eval(law, delta, r, old_state=old_state, new_state=new_state)
    if (.not. same_state(saved, old_state)) old_unchanged = .false.
    ! A host may re-evaluate (cut back) a step: same old state, same answer.
    call asperity_normal_eval(law, delta, r2, old_state=old_state, new_state=saved)
    if (.not. (same_response(r, r2) .and. same_state(saved, new_state))) &
        reeval_identical = .false.
    if (old_state%in_contact == 1 .and. new_state%in_contact == 0) then
      mark = '   <- jump-out'
      if (ieee_is_nan(first_free)) first_free = delta
    end if
    if (new_state%in_contact == 1) last_contact = delta
    min_force = min(min_force, r%force)
    call row('retract', delta, r, mark)
    old_state = new_state
  end do

  ! Jump-in from a fresh state just past delta = 0; `state=` steps in place.
  call asperity_normal_eval(law, -1e-9_c_double*abs_dc, r, old_state=fresh)
  call check('jkr_fresh_just_outside_in_contact', real(r%in_contact, c_double))
  old_state = fresh
  call asperity_normal_eval(law, 1e-9_c_double*abs_dc, r, state=old_state)
  call check('jkr_in_place_state_in_contact', real(old_state%in_contact, c_double))
  call check('jkr_in_place_state_radius_over_response', old_state%contact_radius/r%contact_radius)

  call check('jkr_delta_c_m', delta_c)
  call check('jkr_pull_off_load_N', p_load)
  call check('jkr_pull_off_load_over_piwR', p_load/piwr)
  call check('jkr_pull_off_displacement_over_piwR', p_disp/piwr)
  call check('jkr_jump_in_delta_over_abs_delta_c', jump_in_delta/abs_dc)
  call check('jkr_jump_in_radius_over_theory', r%contact_radius/a_jump)
  call check('jkr_jump_in_force_over_piwR', r%force/piwr)
  call check('jkr_jump_in_in_contact', real(r%in_contact, c_double))
  call check('jkr_last_contact_delta_over_abs_delta_c', last_contact/abs_dc)
  call check('jkr_first_free_delta_over_abs_delta_c', first_free/abs_dc)
  call check('jkr_min_force_retraction_over_piwR', min_force/piwr)
  call check('jkr_old_state_unchanged', flag(old_unchanged))
  call check('jkr_reeval_identical', flag(reeval_identical))

contains

  subroutine row(phase, delta, r, mark)
    character(len=*), intent(in) :: phase, mark
    real(c_double), intent(in) :: delta
    type(asperity_normal_response), intent(in) :: r
    character(len=8) :: label
    label = phase
    write (*, '(a8, es14.6, f9.4, es14.6, f9.4, es14.6, i2, a)') label, delta, delta/abs_dc, &
        r%force, r%force/piwr, r%contact_radius, r%in_contact, trim(mark)
  end subroutine row

  !> Bitwise equality of two states (as the C example's memcmp).
  pure logical function same_state(a, b)
    type(asperity_contact_state), intent(in) :: a, b
    same_state = all(transfer(a, [0_c_int64_t]) == transfer(b, [0_c_int64_t]))
  end function same_state

  pure logical function same_response(a, b)
    type(asperity_normal_response), intent(in) :: a, b
    same_response = all(transfer(a, [0_c_int64_t]) == transfer(b, [0_c_int64_t]))
  end function same_response

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

end program jkr_hysteresis
