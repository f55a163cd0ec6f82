!> A toy explicit FE loop over a one-dimensional strip of contact points
!> with the homogenised friction law as the interface law
!> (examples/c/fe_strip_friction.c in Fortran).
!>
!> Each of the 64 points is a mass m on a spring k_s (with a dashpot c) to a
!> base driven at constant speed v along x; the point rests on a rigid
!> counter-surface under a normal force N_i rising along the strip
!> (10 .. 200 MPa on 1 mm^2). Every increment:
!>
!>   a_i = (k_s (x_base - x_i) + c (v - u_i) + F_i) / m    (forces at t_n)
!>   u_i += dt a_i;  dx_i = dt u_i;  x_i += dx_i            (symplectic Euler)
!>   asperity_friction_step_block_in_place(dx)  ->  F_i at t_{n+1}
!>
!> with the per-point states, the columns of `state(m, np)` (m =
!> asperity_friction_state_size), stepped in place. The slip increments and
!> forces are Fortran arrays (2, n): column i is point i's (x, y), the C
!> ABI's interleaved layout. The friction law is the homogenised law of a
!> table built from five copper-like samples (mu 1.10 .. 0.90 over
!> 10 .. 200 MPa) with a stick stiffness, one `asperity_friction` handle.
!> The strip sticks while the springs load, then slides; in steady sliding
!> the total friction force is sum mu(p_i)(N_i + A_i).
!>
!> Prints the friction force history every 1000 increments and lines
!> "CHECK <name> <value>" read by tests/fortran_bindings.rs.
program fe_strip_friction
  use asperity
  implicit none
  integer, parameter :: np = 64, steps = 30000, print_every = 1000
  real(c_double), parameter :: area_per_point = 1e-6_c_double ! m^2
  real(c_double), parameter :: mass = 1e-3_c_double           ! kg
  real(c_double), parameter :: k_spring = 1e6_c_double        ! N/m
  real(c_double), parameter :: k_stick = 1e8_c_double         ! regularised stick (N/m)
  real(c_double), parameter :: speed = 0.01_c_double          ! base speed (m/s)
  real(c_double), parameter :: dt = 1e-6_c_double             ! s
  type(asperity_homogenised_sample) :: samples(5)
  type(asperity_homogenised_friction) :: table, copy
  type(asperity_friction) :: law, copy_law
  type(asperity_friction_work) :: work
  real(c_double), allocatable :: state(:, :), fresh(:), scratch(:), next(:, :)
  type(asperity_friction_increment) :: inc
  type(asperity_friction_response) :: r, r1, r2, responses(np)
  real(c_double) :: normal(np), area(np), slip(2, np), force(2, np), diss(np)
  real(c_double) :: x(np), u(np), limit(np)
  real(c_double) :: expected, steady, d_steps, d_states, d_limit_path, min_diss, stick_balance
  real(c_double) :: c, base_old, total, d, sum_spring, p, path1
  integer :: first_slip, all_sliding_from, sliding, i, n, m, mech, plastic_path
  logical :: stick_below_limit, same_responses
  integer(c_int32_t) :: st
  character(len=:), allocatable :: json, msg

  samples(1) = sample(10.0_c_double, 1.10_c_double, 0.90_c_double, 0.010_c_double, &
      0.930_c_double, 0.067_c_double, 0.002_c_double)
  samples(2) = sample(50.0_c_double, 1.02_c_double, 4.50_c_double, 0.050_c_double, &
      0.925_c_double, 0.066_c_double, 0.006_c_double)
  samples(3) = sample(100.0_c_double, 0.97_c_double, 9.00_c_double, 0.100_c_double, &
      0.920_c_double, 0.064_c_double, 0.010_c_double)
  samples(4) = sample(150.0_c_double, 0.93_c_double, 13.5_c_double, 0.150_c_double, &
      0.910_c_double, 0.062_c_double, 0.018_c_double)
  samples(5) = sample(200.0_c_double, 0.90_c_double, 18.0_c_double, 0.200_c_double, &
      0.900_c_double, 0.060_c_double, 0.025_c_double)
  call asperity_homogenised_friction_new(samples, table)
  ! The friction law: the table with the stick stiffness.
  call asperity_friction_from_homogenised(table, k_stick, law)
  call asperity_friction_work_new(law, work)
  call asperity_friction_state_size(law, m)
  ! The state: dissipation, slip path, stick force (x, y), plastic slip path,
  ! dissipation by mechanism (4); C's indices, from 0.
  mech = ASPERITY_HOMOGENISED_STATE_MECHANISMS + 1
  plastic_path = ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH + 1
  call check('state_size_matches', flag(m == ASPERITY_HOMOGENISED_STATE_MECHANISMS + 4))
  allocate (state(m, np), fresh(m), scratch(m))
  state = 0 ! all-zero: fresh
  fresh = 0

  ! The strip, and each point's slip limit from a scalar step (a large slip
  ! from a fresh state slides: |F| = mu (N + A)).
  expected = 0
  do i = 1, np
    p = 10e6_c_double + 190e6_c_double*(i - 1)/(np - 1)
    normal(i) = p*area_per_point
    area(i) = area_per_point
    inc = asperity_friction_increment(normal_force=normal(i), area=area_per_point, &
        slip=[1.0_c_double, 0.0_c_double], dt=dt)
    call asperity_friction_step(law, inc, fresh, scratch, r, work)
    limit(i) = r%cof*(r%normal_force + r%adhesion)
    expected = expected + limit(i)
  end do
  x = 0
  u = 0
  force = 0
  write (*, '(a, i0, a, f6.1, a, f6.1, a, f12.6, a)') '# strip of ', np, ' points, N = ', &
      normal(1), ' .. ', normal(np), ' N, sum mu (N + A) = ', expected, ' N'
  write (*, '(a)') '# increment  time_s  base_m  friction_force_N  sliding_points  dissipation_J'

  c = 2*0.5_c_double*sqrt(k_spring*mass) ! damping ratio 0.5
  d_steps = 0
  min_diss = 0
  stick_balance = 0
  steady = 0
  first_slip = -1
  all_sliding_from = -1
  stick_below_limit = .true.
  path1 = 0
  do n = 1, steps
    base_old = speed*dt*(n - 1)
    do i = 1, np
      u(i) = u(i) + dt*(k_spring*(base_old - x(i)) + c*(speed - u(i)) + force(1, i))/mass
      slip(1, i) = dt*u(i)
      slip(2, i) = 0
      x(i) = x(i) + slip(1, i)
    end do
    path1 = path1 + abs(slip(1, 1))
    call asperity_friction_step_block_in_place(law, normal, slip, dt, state, force, areas=area, &
        dissipation=diss, work=work)
    total = sum(force(1, :))
    d = sum(diss)
    min_diss = min(min_diss, minval(diss))
    sliding = count(diss > 0)
    if (first_slip < 0 .and. any(abs(force(1, :)) >= limit*(1 + 1e-12_c_double))) &
        stick_below_limit = .false.
    sum_spring = sum(k_spring*(speed*dt*n - x) + c*(speed - u))
    d_steps = d_steps + d
    if (sliding > 0 .and. first_slip < 0) first_slip = n
    if (sliding == np .and. all_sliding_from < 0) then
      all_sliding_from = n
    else if (sliding < np) then
      all_sliding_from = -1
    end if
    ! Quasi-static stick: friction balances spring and dashpot.
    if (n == 5000) stick_balance = rel_diff(-total, sum_spring)
    if (mod(n, print_every) == 0) write (*, '(a, i7, 3es14.6, i4, es17.9)') 'history', n, &
        dt*n, speed*dt*n, total, sliding, d_steps
    if (n == steps) steady = -total
  end do

  d_states = 0
  d_limit_path = 0
  do i = 1, np
    d_states = d_states + sum(state(mech:mech + 3, i))
    d_limit_path = d_limit_path + limit(i)*state(plastic_path, i)
  end do

  call check('points', real(np, c_double))
  call check('expected_steady_force', expected)
  call check('steady_force', steady)
  call check('steady_force_rel_diff', rel_diff(steady, expected))
  call check('first_slip_increment', real(first_slip, c_double))
  call check('all_sliding_from', real(all_sliding_from, c_double))
  call check('stick_below_limit', flag(stick_below_limit))
  call check('stick_balance_rel_diff', stick_balance)
  call check('total_dissipation', d_steps)
  call check('min_increment_dissipation', min_diss)
  call check('dissipation_states_rel_diff', rel_diff(d_states, d_steps))
  call check('dissipation_limit_path_rel_diff', rel_diff(d_limit_path, d_steps))
  call check('chemical_share', state(mech, np/2 + 1)/sum(state(mech:mech + 3, np/2 + 1)))
  ! Every increment is booked: point 1's slip path is the sum of |dx|.
  call check('slip_path_booked_rel_diff', &
      rel_diff(state(ASPERITY_FRICTION_STATE_SLIP_PATH + 1, 1), path1))

  ! JSON round trip: the law of the reloaded table steps bit-identically.
  call asperity_homogenised_friction_to_json(table, json)
  call asperity_homogenised_friction_from_json(json, copy)
  call asperity_friction_from_homogenised(copy, k_stick, copy_law)
  inc = asperity_friction_increment(normal_force=77.7_c_double, area=area_per_point, &
      slip=[3e-7_c_double, -1e-7_c_double], dt=dt)
  call asperity_friction_step(law, inc, state(:, 4), scratch, r1, work)
  call asperity_friction_step(copy_law, inc, state(:, 4), scratch, r2, work)
  call check('json_bytes', real(len(json), c_double))
  call check('json_roundtrip_identical', &
      flag(all(transfer(r1, [0_c_int64_t]) == transfer(r2, [0_c_int64_t]))))
  call copy_law%free()
  call copy%free()

  ! An implicit host's call: every point's full response with both
  ! tangents, bit-identical to the scalar steps of the same increments.
  allocate (next(m, np))
  call asperity_friction_step_block_responses(law, normal, slip, dt, &
      ASPERITY_FRICTION_TANGENT_NORMAL + ASPERITY_FRICTION_TANGENT_SLIP, state, next, &
      responses, areas=area, work=work)
  same_responses = .true.
  do i = 1, np
    inc = asperity_friction_increment(normal_force=normal(i), area=area(i), slip=slip(:, i), &
        dt=dt, tangents=ASPERITY_FRICTION_TANGENT_NORMAL + ASPERITY_FRICTION_TANGENT_SLIP)
    call asperity_friction_step(law, inc, state(:, i), scratch, r, work)
    if (any(transfer(r, [0_c_int64_t]) /= transfer(responses(i), [0_c_int64_t])) .or. &
        any(transfer(scratch, [0_c_int64_t]) /= transfer(next(:, i), [0_c_int64_t]))) &
        same_responses = .false.
  end do
  call check('block_responses_identical', flag(same_responses))
  call check('block_responses_regime', real(responses(np)%regime, c_double))
  call check('block_responses_tangents', real(responses(np)%tangents, c_double))

  ! Errors: a negative area in the block names the element (0-based, as the
  ! C ABI counts); an empty handle is a NULL pointer.
  area(10) = -1
  call asperity_friction_step_block_in_place(law, normal, slip, dt, state, force, areas=area, &
      dissipation=diss, work=work, status=st)
  msg = asperity_last_error_message()
  write (*, '(a)') 'bad area: '//msg
  call check('bad_area_status', real(st, c_double))
  call check('bad_area_names_element', flag(index(msg, 'element 9') > 0))
  call check('bad_area_names_area', flag(index(msg, '`area`') > 0))
  area(10) = area_per_point
  call asperity_friction_step_block_in_place(copy_law, normal, slip, dt, state, force, &
      areas=area, status=st)
  call check('null_handle_status', real(st, c_double))

  call work%free()
  call law%free()
  call asperity_free(law) ! an empty handle is accepted
  call table%free()
  ! Main-program allocatables outlive END PROGRAM unless released: release
  ! them, so leak checkers (scripts/memcheck.sh) see a clean exit.
  if (allocated(json)) deallocate (json)
  if (allocated(msg)) deallocate (msg)
  if (allocated(state)) deallocate (state)
  if (allocated(fresh)) deallocate (fresh)
  if (allocated(scratch)) deallocate (scratch)
  if (allocated(next)) deallocate (next)

contains

  function sample(p_mpa, mu, adh_mpa, fraction, chemical, vdw, elastic) result(s)
    real(c_double), intent(in) :: p_mpa, mu, adh_mpa, fraction, chemical, vdw, elastic
    type(asperity_homogenised_sample) :: s
    s%pressure = p_mpa*1e6_c_double
    s%cof = mu
    s%adhesion_pressure = adh_mpa*1e6_c_double
    s%contact_fraction = fraction
    s%shares = asperity_dissipation(chemical, vdw, elastic, 1 - chemical - vdw - elastic)
  end function sample

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

end program fe_strip_friction
