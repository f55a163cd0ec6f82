!> Batch evaluation and error handling through the Fortran module
!> (examples/c/batch_and_errors.c in Fortran).
!>
!> 1. asperity_normal_eval_batch over arrays of contacts (a Hertz and a DMT
!>    sphere), compared with the scalar call and the closed forms; the same
!>    batch in place through the raw layer.
!> 2. A bad call (negative radius) with `status=`: its status,
!>    asperity_status_string and asperity_last_error_message; the raw
!>    message call with a buffer that is too small.
!> 3. A batch with a bad element: the message names the element, earlier
!>    outputs are written. An array that is too short: the friendly layer's
!>    own error, naming the argument.
!>
!> Lines "CHECK <name> <value>" are read by tests/fortran_bindings.rs.
program batch_and_errors
  use asperity
  use, intrinsic :: iso_c_binding, only: c_char, c_loc, c_null_ptr
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  integer, parameter :: n = 8
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double), parameter :: radius = 1e-6_c_double, e_star = 1e9_c_double, work = 0.05_c_double
  real(c_double), parameter :: delta(n) = [-2e-9_c_double, -1e-10_c_double, 0.0_c_double, &
      1e-10_c_double, 5e-10_c_double, 1e-9_c_double, 5e-9_c_double, 2e-8_c_double]
  real(c_double) :: force(n), a(n), k(n), diff, err_f, err_a, err_k, d, a_ref, want
  real(c_double), target :: inout(n)
  type(asperity_normal_law) :: hertz, dmt, bad
  type(asperity_contact_state) :: states(n)
  integer(c_int32_t) :: status
  integer(c_size_t) :: msg_len, got
  character(len=:), allocatable :: msg
  character(kind=c_char), target :: small(16)
  character(len=32) :: version
  integer :: i, written

  write (version, '(i0, ".", i0, ".", i0)') ASPERITY_VERSION_MAJOR, ASPERITY_VERSION_MINOR, &
      ASPERITY_VERSION_PATCH
  write (*, '(a)') 'asperity '//asperity_version()//' (module '//trim(version)//')'
  call check('version_matches_header', flag(asperity_version() == trim(version)))

  ! 1. Batches (no status argument: a failure would stop the program).
  call asperity_law_hertz(radius, e_star, hertz)
  call asperity_law_dmt(radius, e_star, work, dmt)

  call batch_vs_scalar(hertz, force, a, k, diff)
  write (*, '(/, a, es10.3, a, es10.3, a)') 'Hertz sphere R = ', radius, ' m, E* = ', e_star, ' Pa'
  err_f = 0
  err_a = 0
  err_k = 0
  do i = 1, n
    d = max(delta(i), 0.0_c_double)
    a_ref = sqrt(radius*d)
    write (*, '(4es15.6)') delta(i), force(i), a(i), k(i)
    err_f = max(err_f, rel_err(force(i), 4.0_c_double/3*e_star*sqrt(radius)*d**1.5_c_double))
    err_a = max(err_a, rel_err(a(i), a_ref))
    err_k = max(err_k, rel_err(k(i), 2*e_star*a_ref))
  end do
  call check('hertz_batch_vs_scalar_max_abs_diff', diff)
  call check('hertz_batch_force_max_rel_err', err_f)
  call check('hertz_batch_radius_max_rel_err', err_a)
  call check('hertz_batch_stiffness_max_rel_err', err_k)

  call batch_vs_scalar(dmt, force, a, k, diff)
  write (*, '(/, a, es13.6, a)') 'DMT sphere (pull-off -2 pi w R = ', -2*pi*work*radius, ' N)'
  err_f = 0
  do i = 1, n
    want = 0
    if (delta(i) >= 0) want = 4.0_c_double/3*e_star*sqrt(radius)*delta(i)**1.5_c_double &
        - 2*pi*work*radius
    write (*, '(3es15.6)') delta(i), force(i), a(i)
    err_f = max(err_f, rel_err(force(i), want))
  end do
  call check('dmt_batch_vs_scalar_max_abs_diff', diff)
  call check('dmt_batch_force_max_rel_err', err_f)

  ! In place: the C API lets the force array be the delta array; Fortran
  ! forbids that aliasing in a call, so it goes through the raw layer.
  inout = delta
  status = c_asperity_normal_eval_batch(hertz, int(n, c_size_t), inout, c_null_ptr, c_null_ptr, &
      inout, c_null_ptr, c_null_ptr)
  if (status /= ASPERITY_OK) error stop 'in-place batch failed'
  diff = 0
  do i = 1, n
    d = max(delta(i), 0.0_c_double)
    diff = max(diff, rel_err(inout(i), 4.0_c_double/3*e_star*sqrt(radius)*d**1.5_c_double))
  end do
  call check('hertz_in_place_force_max_rel_err', diff)

  ! 2. A bad call: negative radius.
  write (*, '(/, a)') 'error handling'
  call asperity_law_hertz(-1e-6_c_double, e_star, bad, status=status)
  write (*, '(a, i0, a)') 'asperity_law_hertz(-1e-6, ...) -> ', status, &
      ' ('//asperity_status_string(status)//')'
  call check('bad_radius_status', real(status, c_double))
  call check('bad_radius_status_is_invalid_argument', flag(status == ASPERITY_ERR_INVALID_ARGUMENT))
  msg = asperity_last_error_message()
  write (*, '(a)') 'message: '//msg
  msg_len = c_asperity_last_error_message(c_null_ptr, 0_c_size_t)
  call check('message_length', real(msg_len, c_double))
  call check('message_length_consistent', flag(msg_len == size_of(msg)))
  call check('message_names_radius', flag(index(msg, '`radius`') > 0))
  ! A buffer that is too small: truncated, NUL-terminated, full length returned.
  got = c_asperity_last_error_message(c_loc(small), int(size(small), c_size_t))
  call check('truncated_strlen', real(strlen(small), c_double))
  call check('truncated_returns_full_length', flag(got == msg_len))
  call check('truncated_is_prefix', flag(prefix_of(small, msg)))

  ! Every status code has a description.
  do i = ASPERITY_OK, ASPERITY_ERR_INTERNAL, -1
    write (*, '(a, i2, a)') 'status ', i, ': '//asperity_status_string(int(i, c_int32_t))
  end do
  write (*, '(a, i2, a)') 'status ', 42, ': '//asperity_status_string(42_c_int32_t)

  ! 3. A batch with a bad element: NaN at element 5 (0-based, as the C ABI counts).
  inout = delta
  inout(6) = ieee_value(inout(6), ieee_quiet_nan)
  force = -1 ! sentinel
  call asperity_normal_eval_batch(hertz, inout, force, status=status)
  msg = asperity_last_error_message()
  write (*, '(a, i0, a)') 'batch with NaN at element 5 -> ', status, ': '//msg
  call check('batch_error_status', real(status, c_double))
  call check('batch_error_names_element', flag(index(msg, 'element 5') > 0))
  written = count(force(1:5) >= 0)
  call check('batch_error_outputs_written_before', real(written, c_double))
  call check('batch_error_sentinel_after', flag(all(force(7:8) < -0.5_c_double)))

  ! The friendly layer's own check: an output array shorter than the input.
  call asperity_normal_eval_batch(hertz, delta, force(1:3), status=status)
  msg = asperity_last_error_message()
  write (*, '(a, i0, a)') 'batch with a short force array -> ', status, ': '//msg
  call check('short_array_status', real(status, c_double))
  call check('short_array_names_force', flag(index(msg, '`force`') > 0))
  ! ... and in-place states given twice are refused.
  call asperity_normal_eval_batch(hertz, delta, force, old_state=states, states=states, &
      status=status)
  call check('state_clash_status', real(status, c_double))
  ! A later library failure brings the library's message back.
  call asperity_law_hertz(radius, -1.0_c_double, bad, status=status)
  msg = asperity_last_error_message()
  call check('library_message_after_local_error', flag(index(msg, '`e_star`') > 0))
  ! Main-program allocatables outlive END PROGRAM unless released: release
  ! them, so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(msg)) deallocate (msg)

contains

  !> Run a batch with fresh states and the scalar calls; the largest difference.
  subroutine batch_vs_scalar(law, force, radius_out, stiffness, max_diff)
    type(asperity_normal_law), intent(in) :: law
    real(c_double), intent(out) :: force(n), radius_out(n), stiffness(n), max_diff
    type(asperity_contact_state) :: old_state(n), new_state(n)
    type(asperity_normal_response) :: r
    integer :: j
    call asperity_normal_eval_batch(law, delta, force, old_state=old_state, new_state=new_state, &
        contact_radius=radius_out, stiffness=stiffness)
    max_diff = 0
    do j = 1, n
      call asperity_normal_eval(law, delta(j), r, old_state=old_state(j))
      max_diff = max(max_diff, abs(r%force - force(j)), abs(r%contact_radius - radius_out(j)), &
          abs(r%stiffness - stiffness(j)))
      if (new_state(j)%in_contact /= r%in_contact) max_diff = huge(max_diff)
    end do
  end subroutine batch_vs_scalar

  pure real(c_double) function rel_err(got, want)
    real(c_double), intent(in) :: got, want
    rel_err = abs(got - want)/merge(abs(want), 1.0_c_double, abs(want) > 0)
  end function rel_err

  pure real(c_double) function flag(condition)
    logical, intent(in) :: condition
    flag = merge(1.0_c_double, 0.0_c_double, condition)
  end function flag

  pure integer(c_size_t) function size_of(text)
    character(len=*), intent(in) :: text
    size_of = int(len(text), c_size_t)
  end function size_of

  !> Length of the NUL-terminated text in `buf`.
  pure integer function strlen(buf)
    character(kind=c_char), intent(in) :: buf(:)
    do strlen = 0, size(buf) - 1
      if (buf(strlen + 1) == achar(0)) return
    end do
  end function strlen

  pure logical function prefix_of(buf, text)
    character(kind=c_char), intent(in) :: buf(:)
    character(len=*), intent(in) :: text
    integer :: j
    prefix_of = .true.
    do j = 1, strlen(buf)
      if (buf(j) /= text(j:j)) prefix_of = .false.
    end do
  end function prefix_of

  subroutine check(name, value)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    character(len=32) :: buf
    write (buf, '(es25.17e3)') value
    write (*, '(a)') 'CHECK '//name//' '//trim(adjustl(buf))
  end subroutine check

end program batch_and_errors
