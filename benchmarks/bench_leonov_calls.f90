!> Time per call of the Leonov update (umat/leonov.f90, `leonov_update` with the consistent tangent) at an elastic
!> increment (the fast path) and at plastic ones (the full return), Table 1 properties:
!>   bench_leonov_calls [N]      (N elastic calls, N/5 calls of each plastic case; default 10^6)
!> Elastic: simple shear 1e-4 from a slightly pre-stretched Be~, dt = 0.5 s; plastic: shear 0.1 and stretch 1.02
!> from Be~_12 = 0.05, dt = 0.5 s (dgamma ~0.12); relaxing: the most frequent plastic state late in the
!> application scene, a low stress (tau_bar = 0.02 tau_0) of softened material (gamma_p = 2) held at fixed F for
!> dt = 100 eta/G (99 % of it relaxes in the increment). Prints microseconds per call (CPU time), a checksum of
!> the stresses and tangents (two builds compare for speed and results), and for the relaxing case the
!> evaluations of g in the scalar predictor of the return (docs/performance.md).
program bench_leonov_calls
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp
  use leonov_parameters, only: leonov_props, leonov_props_from_array, leonov_props_table1
  use leonov, only: leonov_state, leonov_update, leonov_predictor_evaluations, leonov_log_r_gamma
  implicit none
  type(leonov_props) :: p
  type(leonov_state) :: old, new
  real(dp) :: f0(3, 3), f1(3, 3), sig(3, 3), c(6, 6), fac, t0, t1, sum_el, sum_pl, us_el, us_pl, sum_rx, us_rx
  real(dp) :: dt_rx, u
  integer :: i, n, st, n_rx
  character(len=200) :: msg
  character(len=32) :: arg

  n = 1000000
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read (arg, *, iostat=st) n
    if (st /= 0 .or. n < 1) then
      write (error_unit, '(a)') 'bench_leonov_calls: the argument is the number of calls, a positive integer: '// &
        trim(arg)
      call exit(2)
    end if
  end if
  call leonov_props_from_array(leonov_props_table1(), p, st, msg)
  f0 = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])

  f1 = f0
  f1(1, 2) = 1.0e-4_dp
  f1(1, 1) = 1.00002_dp
  old%be(1, 2) = 2.0e-4_dp
  old%be(2, 1) = 2.0e-4_dp
  sum_el = 0.0_dp
  call cpu_time(t0)
  do i = 1, n
    f1(2, 2) = 1.0_dp + 1.0e-9_dp * mod(i, 7)
    call leonov_update(p, f0, f1, 0.5_dp, old, new, sig, st, fac, c)
    sum_el = sum_el + sig(1, 2) + c(1, 1)
  end do
  call cpu_time(t1)
  us_el = 1.0e6_dp * (t1 - t0) / n
  if (new%dgamma /= 0.0_dp) stop 'bench_leonov_calls: the elastic case flowed'

  f1 = f0
  f1(1, 2) = 0.1_dp
  f1(1, 1) = 1.02_dp
  old%be(1, 2) = 0.05_dp
  old%be(2, 1) = 0.05_dp
  sum_pl = 0.0_dp
  call cpu_time(t0)
  do i = 1, max(1, n / 5)
    f1(2, 2) = 1.0_dp + 1.0e-9_dp * mod(i, 7)
    call leonov_update(p, f0, f1, 0.5_dp, old, new, sig, st, fac, c)
    sum_pl = sum_pl + sig(1, 2) + c(1, 1)
  end do
  call cpu_time(t1)
  us_pl = 1.0e6_dp * (t1 - t0) / max(1, n / 5)
  if (.not. (new%dgamma > 0.0_dp)) stop 'bench_leonov_calls: the plastic case did not flow'

  ! relaxing: Be~_12 = 0.02 tau_0/G (tau_bar = 0.02 tau_0), gamma_p = 2, F held, dt = 100 eta/G with
  ! eta = exp(ln eta_0r + S(gamma_p)) (Eq. 37 at low stress)
  old = leonov_state()
  old%gamma_p = 2.0_dp
  old%be(1, 2) = 0.02_dp * p%tau_0 / p%g
  old%be(2, 1) = old%be(1, 2)
  dt_rx = 100.0_dp * exp(p%ln_eta_0r + p%s_a * exp(leonov_log_r_gamma(p, 2.0_dp))) / p%g
  sum_rx = 0.0_dp
  call cpu_time(t0)
  do i = 1, max(1, n / 5)
    f1 = f0
    f1(2, 2) = 1.0_dp + 1.0e-12_dp * mod(i, 7)
    call leonov_update(p, f0, f1, dt_rx, old, new, sig, st, fac, c)
    sum_rx = sum_rx + sig(1, 2) + c(1, 1)
  end do
  call cpu_time(t1)
  us_rx = 1.0e6_dp * (t1 - t0) / max(1, n / 5)
  if (.not. (new%tau_bar < 0.02_dp * p%tau_0)) stop 'bench_leonov_calls: the relaxing case did not relax'
  call leonov_predictor_evaluations(p, 0.02_dp * p%tau_0, 0.0_dp, dt_rx, 2.0_dp, u, n_rx)

  print '(a,f8.3,a,es23.15)', 'elastic increment (fast path): ', us_el, ' us per call, checksum ', sum_el
  print '(a,f8.3,a,es23.15)', 'plastic increment (return):    ', us_pl, ' us per call, checksum ', sum_pl
  print '(a,f8.3,a,es23.15,a,i0,a)', 'relaxing low stress (return):  ', us_rx, ' us per call, checksum ', sum_rx, &
    ' (predictor: ', n_rx, ' evaluations)'
end program bench_leonov_calls
