!> Pull-off force of an adhesive sphere against the Maugis parameter lambda:
!> DMT (lambda -> 0), Maugis-Dugdale, JKR (lambda -> infinity), under load
!> and displacement control, in units of pi w R; then one Maugis-Dugdale
!> force-approach curve at lambda = 1 (examples/c/pull_off_table.c in
!> Fortran).
!>
!> For each lambda the Dugdale cohesive stress is
!>     sigma0 = (lambda / 2) (pi w K^2 / R)^(1/3),  K = 4 E* / 3,
!> checked against asperity_maugis_parameter.
!>
!> The calls pass `status=`: a law that fails is reported and shown as "n/a",
!> the program goes on with the others and stops with a non-zero code at the
!> end. Lines "CHECK <name> <value>" and the curve rows ("approach",
!> "retract") are read by tests/fortran_bindings.rs.
program pull_off_table
  use asperity
  implicit none
  integer, parameter :: n_lambda = 13
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double), parameter :: radius = 1e-6_c_double, work = 0.05_c_double, e_star = 1e9_c_double
  real(c_double), parameter :: third = 1.0_c_double/3
  real(c_double) :: k, piwr, sigma_unit, delta_unit, a_unit
  real(c_double) :: lambda(n_lambda), sigma0(n_lambda), md_load(n_lambda), md_disp(n_lambda)
  logical :: md_ok(n_lambda), dmt_ok, jkr_ok
  real(c_double) :: dmt_load, dmt_disp, jkr_load, jkr_disp, lambda_err, check_lambda
  type(asperity_normal_law) :: dmt, jkr, md
  integer(c_int32_t) :: last
  integer :: failures, i
  character(len=200) :: line

  k = 4*e_star/3
  piwr = pi*work*radius
  sigma_unit = (pi*work*k*k/radius)**third
  delta_unit = (pi*pi*work*work*radius/(k*k))**third
  a_unit = (pi*work*radius*radius/k)**third
  failures = 0
  lambda_err = 0
  dmt_load = 0
  dmt_disp = 0
  jkr_load = 0
  jkr_disp = 0

  write (*, '(a)') 'Pull-off force of an adhesive sphere, P_c / (pi w R)'
  write (*, '(a)') 'theory: DMT -2 (both controls); JKR -3/2 (load), -5/6 (displacement)'

  call asperity_law_dmt(radius, e_star, work, dmt, status=last)
  dmt_ok = ok('asperity_law_dmt')
  if (dmt_ok) then
    call asperity_pull_off_force(dmt, ASPERITY_CONTROL_LOAD, dmt_load, status=last)
    dmt_ok = ok('asperity_pull_off_force (DMT, load)')
  end if
  if (dmt_ok) then
    call asperity_pull_off_force(dmt, ASPERITY_CONTROL_DISPLACEMENT, dmt_disp, status=last)
    dmt_ok = ok('asperity_pull_off_force (DMT, displacement)')
  end if
  call asperity_law_jkr(radius, e_star, work, jkr, status=last)
  jkr_ok = ok('asperity_law_jkr')
  if (jkr_ok) then
    call asperity_pull_off_force(jkr, ASPERITY_CONTROL_LOAD, jkr_load, status=last)
    jkr_ok = ok('asperity_pull_off_force (JKR, load)')
  end if
  if (jkr_ok) then
    call asperity_pull_off_force(jkr, ASPERITY_CONTROL_DISPLACEMENT, jkr_disp, status=last)
    jkr_ok = ok('asperity_pull_off_force (JKR, displacement)')
  end if

  do i = 1, n_lambda
    lambda(i) = 10.0_c_double**(-2 + (i - 1)/3.0_c_double)
    sigma0(i) = 0.5_c_double*lambda(i)*sigma_unit
    md_load(i) = 0
    md_disp(i) = 0
    call asperity_maugis_parameter(radius, work, e_star, sigma0(i), check_lambda, status=last)
    if (ok('asperity_maugis_parameter')) then
      lambda_err = max(lambda_err, abs(check_lambda/lambda(i) - 1))
    else
      lambda_err = huge(lambda_err)
    end if
    call asperity_law_maugis_dugdale(radius, e_star, work, sigma0(i), md, status=last)
    md_ok(i) = ok('asperity_law_maugis_dugdale')
    if (md_ok(i)) then
      call asperity_pull_off_force(md, ASPERITY_CONTROL_LOAD, md_load(i), status=last)
      md_ok(i) = ok('asperity_pull_off_force (M-D, load)')
    end if
    if (md_ok(i)) then
      call asperity_pull_off_force(md, ASPERITY_CONTROL_DISPLACEMENT, md_disp(i), status=last)
      md_ok(i) = ok('asperity_pull_off_force (M-D, displacement)')
    end if
  end do

  write (*, '(/, a9, 1x, a11, " | ", a29, " | ", a29)') '', '', 'load control', &
      'displacement control'
  write (*, '(a9, 1x, a11, " | ", 3a10, " | ", 3a10)') 'lambda', 'sigma0 (Pa)', 'DMT', 'M-D', &
      'JKR', 'DMT', 'M-D', 'JKR'
  do i = 1, n_lambda
    write (line, '(es9.3, 1x, es11.4, " |")') lambda(i), sigma0(i)
    line = trim(line)//cell(dmt_load/piwr, dmt_ok)//cell(md_load(i)/piwr, md_ok(i)) &
        //cell(jkr_load/piwr, jkr_ok)//' |'//cell(dmt_disp/piwr, dmt_ok) &
        //cell(md_disp(i)/piwr, md_ok(i))//cell(jkr_disp/piwr, jkr_ok)
    write (*, '(a)') trim(line)
  end do

  call md_curve()

  write (*, '(a)') ''
  call check('maugis_parameter_max_rel_err', lambda_err)
  if (dmt_ok) then
    call check('dmt_pull_off_load_over_piwR', dmt_load/piwr)
    call check('dmt_pull_off_displacement_over_piwR', dmt_disp/piwr)
  end if
  if (jkr_ok) then
    call check('jkr_pull_off_load_over_piwR', jkr_load/piwr)
    call check('jkr_pull_off_displacement_over_piwR', jkr_disp/piwr)
  end if
  do i = 1, n_lambda
    if (md_ok(i)) then
      call check('md_pull_off_load_over_piwR@'//num(lambda(i)), md_load(i)/piwr)
      call check('md_pull_off_displacement_over_piwR@'//num(lambda(i)), md_disp(i)/piwr)
    end if
  end do
  if (failures > 0) then
    write (*, '(a, i0, a)') 'pull_off_table: ', failures, ' call(s) failed'
    error stop 1
  end if

contains

  !> One Maugis-Dugdale force-approach curve at lambda = 1, displacement
  !> control: 31 steps in (Delta = -1.5 .. 1.5), 31 out (1.45 .. -1.55).
  subroutine md_curve()
    type(asperity_normal_law) :: law
    type(asperity_contact_state) :: state
    type(asperity_normal_response) :: r
    real(c_double) :: big_delta, min_force
    logical :: approach
    character(len=8) :: label
    integer :: j
    write (*, '(/, a)') 'Maugis-Dugdale, lambda = 1: force-approach curve under displacement control'
    write (*, '(a)') '(reduced units: Delta = delta (K^2/(pi^2 w^2 R))^(1/3), P/(pi w R), '// &
        'A = a (K/(pi w R^2))^(1/3), C = c likewise)'
    call asperity_law_maugis_dugdale(radius, e_star, work, 0.5_c_double*sigma_unit, law, &
        status=last)
    if (.not. ok('asperity_law_maugis_dugdale (curve)')) return
    min_force = 0
    write (*, '(a8, 4a10, a)') 'phase', 'Delta', 'P/(piwR)', 'A', 'C', ' in_contact'
    do j = 0, 61
      approach = j < 31
      if (approach) then
        big_delta = -1.5_c_double + 0.1_c_double*j
        label = 'approach'
      else
        big_delta = 1.45_c_double - 0.1_c_double*(j - 31)
        label = 'retract'
      end if
      ! `state=`: the history is stepped in place.
      call asperity_normal_eval(law, big_delta*delta_unit, r, state=state, status=last)
      if (.not. ok('asperity_normal_eval (curve)')) return
      write (*, '(a8, f10.4, 3f10.5, i3)') label, big_delta, r%force/piwr, &
          r%contact_radius/a_unit, state%cohesive_radius/a_unit, r%in_contact
      if (.not. approach) min_force = min(min_force, r%force)
    end do
    call check('md_curve_min_force_over_piwR', min_force/piwr)
  end subroutine md_curve

  !> Report the last call when it failed; true when it succeeded.
  logical function ok(what)
    character(len=*), intent(in) :: what
    ok = last == ASPERITY_OK
    if (.not. ok) then
      failures = failures + 1
      write (*, '(a)') 'pull_off_table: '//what//' failed: '//asperity_status_string(last)// &
          ': '//asperity_last_error_message()
    end if
  end function ok

  function cell(value, good) result(text)
    real(c_double), intent(in) :: value
    logical, intent(in) :: good
    character(len=10) :: text
    if (good) then
      write (text, '(f10.4)') value
    else
      text = '       n/a'
    end if
  end function cell

  function num(x) result(text)
    real(c_double), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(es25.17e3)') x
    text = trim(adjustl(buf))
  end function num

  subroutine check(name, value)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    write (*, '(a)') 'CHECK '//name//' '//num(value)
  end subroutine check

end program pull_off_table
