!> Quick start (README): a JKR sphere from Fortran, one loading step and the pull-off.
program quick_start
  use asperity
  implicit none
  type(asperity_normal_law) :: law
  type(asperity_contact_state) :: old_state, new_state   ! all-zero: never touched
  type(asperity_normal_response) :: r
  real(c_double) :: pull_off
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  integer(c_int32_t) :: status

  ! R = 1 um, E* = 1 GPa, w = 0.05 J/m^2 (SI units throughout).
  call asperity_law_jkr(1e-6_c_double, 1e9_c_double, 0.05_c_double, law)
  call asperity_normal_eval(law, 2e-9_c_double, r, old_state=old_state, new_state=new_state)
  print '(a, 1x, es11.4, a, 1x, es11.4, a)', 'delta = 2 nm: force', r%force, ' N, contact radius', &
      r%contact_radius, ' m'
  call asperity_pull_off_force(law, ASPERITY_CONTROL_LOAD, pull_off)
  print '(a, 1x, es13.6, a, 1x, f9.6, a)', 'pull-off (load control)', pull_off, ' N =', &
      pull_off/(pi*0.05_c_double*1e-6_c_double), ' pi w R'
  ! A bad argument is refused; with `status` present the call returns it
  ! (without, the program stops with the message).
  call asperity_law_jkr(-1e-6_c_double, 1e9_c_double, 0.05_c_double, law, status)
  print '(a)', 'negative radius: '//asperity_last_error_message()
  if (status == ASPERITY_OK) error stop 1
  if (abs(pull_off/(pi*0.05_c_double*1e-6_c_double) + 1.5_c_double) > 1e-9_c_double) error stop 1
end program quick_start
