!> What the friendly layer does without a `status` argument: a failed call
!> prints the library's message to standard error and stops the program
!> (`error stop`); so does copying a live handle with `=`.
!>
!>   stops_on_error call   a call that fails (negative radius), no status
!>   stops_on_error copy   a live table handle assigned to another handle
!>   stops_on_error        neither: says so and exits normally
!>
!> tests/fortran_bindings.rs runs both and checks the exit status and the
!> message.
program stops_on_error
  use asperity
  implicit none
  character(len=16) :: what
  type(asperity_normal_law) :: law
  type(asperity_table) :: a, b

  what = ''
  if (command_argument_count() > 0) call get_command_argument(1, what)
  select case (trim(what))
  case ('call')
    write (*, '(a)') 'calling asperity_law_hertz with a negative radius and no status'
    call asperity_law_hertz(-1e-6_c_double, 1e9_c_double, law)
    write (*, '(a)') 'NOT REACHED'
  case ('copy')
    call asperity_table_new_maugis_dugdale(1e-6_c_double, 1e9_c_double, 0.05_c_double, &
        3e7_c_double, 1e-3_c_double, a)
    write (*, '(a)') 'copying a live handle'
    b = a
    write (*, '(a)') 'NOT REACHED'
  case default
    write (*, '(a)') 'usage: stops_on_error call|copy (nothing to do)'
  end select
end program stops_on_error
