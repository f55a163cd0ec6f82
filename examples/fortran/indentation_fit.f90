!> Fit a measured nanoindentation curve through the Fortran module: Borodich
!> rescaling (kappa, d), Oliver-Pharr reduced modulus and hardness, validity
!> flags (examples/c/indentation_fit.c in Fortran).
!>
!>   indentation_fit [FILE.csv]
!>
!> FILE is in the format of ../shared/data/indentation (`#` comments, header
!> time_s,depth_m,load_N,segment). Without an argument the fused-silica
!> calibration curve is read from ../shared/data/indentation/; when it is
!> not there the program says so, runs only the closed-form checks, and
!> exits 0. Output: a readable report and `CHECK name value` lines.
program indentation_fit
  use asperity
  implicit none
  character(len=*), parameter :: default_file = &
      '../shared/data/indentation/fused_silica_berkovich_agilent_calibration_test001.csv'
  character(len=1024) :: path
  real(c_double) :: value
  real(c_double), allocatable :: depth(:), load(:)
  integer(c_int32_t), allocatable :: seg(:)
  integer(c_int32_t) :: st, bit
  type(asperity_indentation_options) :: opt
  type(asperity_indentation_result) :: res, res_unlabelled
  logical :: have_argument, found
  character(len=:), allocatable :: flags

  have_argument = command_argument_count() > 0
  path = default_file
  if (have_argument) call get_command_argument(1, path)

  ! Closed-form checks (REFERENCE.md sections 2 and 8).
  call asperity_rescaling_load(0.112_c_double, 2.0_c_double, 1.0_c_double, 0.1e-3_c_double, &
      2310.0_c_double, 0.224e-3_c_double, value)
  write (*, '(a, f8.2, a)') 'Taljat A533-B, kappa = 0.112: P(0.1 mm) = ', value, ' N'
  call check('taljat_load_at_0.1mm', value)
  call asperity_rescaling_kappa_from_slope(1.056_c_double, 2.0_c_double, value)
  call check('taljat_kappa', value)
  call asperity_galanov_medium_radius(0.788e-3_c_double, 62.8824e-3_c_double, value)
  call check('taljat_medium_radius_mm', value*1e3_c_double)
  call asperity_rescaling_kappa_from_slope(2.0_c_double, 1.0_c_double, value, status=st)
  call check('cone_kappa_status', real(st, c_double))

  ! Too few points: a clear error, not a NaN.
  call asperity_indentation_fit([1e-7_c_double, 2e-7_c_double], [1e-3_c_double, 2e-3_c_double], &
      res, status=st)
  call check('two_points_status', real(st, c_double))

  call read_curve(trim(path), depth, load, seg, found)
  if (.not. found) then
    write (*, '(a)') 'SKIPPED: '//trim(path)//' is not present (measured data live outside '// &
        'the project); closed-form checks only'
    call check('data_present', 0.0_c_double)
    stop
  end if
  call check('data_present', 1.0_c_double)
  write (*, '(a, i0, a)') trim(path)//': ', size(depth), ' points'

  call asperity_indentation_default_options(opt)
  opt%indenter = ASPERITY_INDENTER_BERKOVICH
  if (.not. have_argument) then
    ! Tip Berk40_20210907_MarilaineSP, area coefficients from the README;
    ! fused silica, nu = 0.18.
    opt%n_area_coefficients = 3
    opt%area_coefficients(0:2) = [27.3136_c_double, 152.6988585_c_double, -494.1823171_c_double]
    opt%nu_sample = 0.18_c_double
  end if
  call asperity_indentation_fit(depth, load, res, segments=seg, options=opt)

  write (*, '(a, 4(f8.3, a))') 'kappa = ', res%kappa, ' +- ', res%kappa_stderr, ', d = ', &
      res%d, ' +- ', res%d_stderr, ''
  write (*, '(a, 3(f8.2, a))') 'E_r = ', res%reduced_modulus/1e9_c_double, ' GPa, E = ', &
      res%sample_modulus/1e9_c_double, ' GPa, H = ', res%hardness/1e9_c_double, ' GPa'
  flags = ''
  do bit = 0, 31
    if (btest(res%flags, bit)) flags = flags//' '//asperity_indentation_flag_name(bit)
  end do
  write (*, '(a)') 'flags:'//flags
  call check('kappa', res%kappa)
  call check('kappa_stderr', res%kappa_stderr)
  call check('d', res%d)
  call check('d_stderr', res%d_stderr)
  call check('reduced_modulus_GPa', res%reduced_modulus/1e9_c_double)
  call check('sample_modulus_GPa', res%sample_modulus/1e9_c_double)
  call check('hardness_GPa', res%hardness/1e9_c_double)
  call check('has_unloading', real(res%has_unloading, c_double))
  call check('flag_kappa_above_one', merge(1.0_c_double, 0.0_c_double, &
      iand(res%flags, ASPERITY_INDENT_FLAG_KAPPA_ABOVE_ONE) /= 0))
  call check('flag_sharp_indenter', merge(1.0_c_double, 0.0_c_double, &
      iand(res%flags, ASPERITY_INDENT_FLAG_SHARP_INDENTER) /= 0))

  ! The same curve without labels: segments detected.
  call asperity_indentation_fit(depth, load, res_unlabelled, options=opt)
  write (*, '(a, 2(f8.3, a))') 'unlabelled: E_r = ', res_unlabelled%reduced_modulus/1e9_c_double, &
      ' GPa, H = ', res_unlabelled%hardness/1e9_c_double, ' GPa'
  call check('unlabelled_reduced_modulus_GPa', res_unlabelled%reduced_modulus/1e9_c_double)
  call check('unlabelled_hardness_GPa', res_unlabelled%hardness/1e9_c_double)
  ! Main-program allocatables outlive END PROGRAM unless released: release
  ! them, so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(depth)) deallocate (depth)
  if (allocated(load)) deallocate (load)
  if (allocated(seg)) deallocate (seg)
  if (allocated(flags)) deallocate (flags)

contains

  integer(c_int32_t) function segment_code(s)
    character(len=*), intent(in) :: s
    select case (s)
    case ('approach')
      segment_code = ASPERITY_SEGMENT_APPROACH
    case ('loading')
      segment_code = ASPERITY_SEGMENT_LOADING
    case ('hold_at_peak')
      segment_code = ASPERITY_SEGMENT_HOLD
    case ('unloading')
      segment_code = ASPERITY_SEGMENT_UNLOADING
    case ('thermal_drift_hold')
      segment_code = ASPERITY_SEGMENT_DRIFT_HOLD
    case ('final_unloading')
      segment_code = ASPERITY_SEGMENT_FINAL_UNLOADING
    case default
      segment_code = ASPERITY_SEGMENT_UNKNOWN
    end select
  end function segment_code

  !> Read the CSV (time_s,depth_m,load_N,segment); `found` is false when
  !> the file cannot be opened. A malformed line stops the program.
  subroutine read_curve(file, depth, load, seg, found)
    character(len=*), intent(in) :: file
    real(c_double), allocatable, intent(out) :: depth(:), load(:)
    integer(c_int32_t), allocatable, intent(out) :: seg(:)
    logical, intent(out) :: found
    character(len=512) :: line
    integer :: unit, ios, n, c1, c2, c3
    logical :: header_seen
    allocate (depth(1024), load(1024), seg(1024))
    n = 0
    header_seen = .false.
    open (newunit=unit, file=file, status='old', action='read', iostat=ios)
    found = ios == 0
    if (.not. found) return
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (len_trim(line) == 0 .or. line(1:1) == '#') cycle
      if (.not. header_seen) then
        header_seen = .true. ! time_s,depth_m,load_N,segment
        cycle
      end if
      c1 = index(line, ',')
      c2 = c1 + index(line(c1 + 1:), ',')
      c3 = c2 + index(line(c2 + 1:), ',')
      if (c1 == 0 .or. c2 == c1 .or. c3 == c2) error stop 'indentation_fit: malformed line'
      if (n == size(depth)) call grow(depth, load, seg)
      n = n + 1
      read (line(c1 + 1:c2 - 1), *) depth(n)
      read (line(c2 + 1:c3 - 1), *) load(n)
      seg(n) = segment_code(trim(adjustl(line(c3 + 1:))))
    end do
    close (unit)
    depth = depth(1:n)
    load = load(1:n)
    seg = seg(1:n)
  end subroutine read_curve

  subroutine grow(depth, load, seg)
    real(c_double), allocatable, intent(inout) :: depth(:), load(:)
    integer(c_int32_t), allocatable, intent(inout) :: seg(:)
    real(c_double), allocatable :: t(:)
    integer(c_int32_t), allocatable :: ti(:)
    integer :: n
    n = size(depth)
    allocate (t(2*n))
    t(1:n) = depth
    call move_alloc(t, depth)
    allocate (t(2*n))
    t(1:n) = load
    call move_alloc(t, load)
    allocate (ti(2*n))
    ti(1:n) = seg
    call move_alloc(ti, seg)
  end subroutine grow

  subroutine check(name, value)
    character(len=*), intent(in) :: name
    real(c_double), intent(in) :: value
    character(len=32) :: buf
    write (buf, '(es25.17e3)') value
    write (*, '(a)') 'CHECK '//name//' '//trim(adjustl(buf))
  end subroutine check

end program indentation_fit
