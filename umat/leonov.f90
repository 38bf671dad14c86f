!> Compressible Leonov model (van den Bosch, Schreurs, Geers 2007, section 6, Eqs. 31-42): the host-free core.
!>
!> Stress (Eqs. 31-33), Cauchy:  sigma = G dev(Be~) + kappa (J - 1) I + G_r dev(B~),  B~ = J^(-2/3) F F^T.
!> Flow (Eqs. 35-37): Dp = G dev(Be~) / (2 eta),
!>   eta = eta_0r exp(mu p / tau_0) exp(S) (tau_bar/tau_0) / sinh(tau_bar/tau_0),  p = -tr(sigma)/3 = -kappa (J - 1),
!>   tau_bar = sqrt(tr(Ss^d Ss^d)/2) (Eq. 40), S = S_a R_gamma(gamma_p) (Eqs. 41-42).
!> Equivalent plastic strain: gamma_p_dot = sqrt(2 Dp:Dp) = tau_bar/eta, so Dp = (gamma_p_dot / (2 tau_bar)) Ss^d.
!>
!> Time integration (one increment t_n -> t_n+1, F_n -> F_n+1):
!>  1. elastic predictor, exact for the elastic part of Eq. 35 (the Jaumann form with D equals the upper-convected
!>     form with L): Be~_trial = F~_rel Be~_n F~_rel^T, F_rel = F_n+1 F_n^-1, F~_rel = det(F_rel)^(-1/3) F_rel;
!>  2. exponential-map return, backward Euler in Dp: Be~_n+1 = exp(-2 dt Dp_n+1) Be~_trial. Dp is coaxial with Be~
!>     (isotropic flow), so trial and final Be~ share eigenvectors and the return acts on the principal logarithmic
!>     elastic stretches e_a = ln(lambda_a):  e_a = e_a^trial - (dgamma/2) N_a(e),  N = G dev(b)/tau_bar, b_a = exp(2 e_a),
!>     together with the flow rule in logarithmic form (overflow-free):
!>        ln sinh(tau_bar/tau_0) = ln(dgamma) + ln(eta_0r/tau_0) + mu p/tau_0 + S(gamma_p,n + dgamma) - ln(dt),
!>     i.e. dgamma = dt tau_bar/eta at the end of the increment (fully implicit, softening included).
!>     Unknowns (e_1, e_2, e_3, ln dgamma), local Newton with line search, started from a bracketed scalar
!>     small-strain radial-return predictor. sum(e_a) = 0 is kept exactly, so det(Be~) = 1 to round-off.
!> Consistent tangent (Abaqus DDSDDE, Jaumann rate of Kirchhoff stress over J): analytic, the limit of the
!> perturbation dF = eps/2 (e_i e_j^T + e_j e_i^T) F_n+1 (Miehe 1996): implicit function theorem at the converged
!> return for the principal values, spectral derivative of the isotropic map Be~_trial -> Be~_n+1 for the
!> eigenvectors (subroutine consistent_tangent). The central perturbation (13 local solves) is kept as an option.
!> Elastic fast path: no return when the Eyring increment at the trial stress is below 1e-10 (docs/umat.md), worked in
!> Cartesian form on Be~_trial (no eigen-decomposition; subroutine elastic_tangent for its tangent).
module leonov
  use ldfcz_finite, only: is_finite
  use ldfcz_kinds, only: dp
  use leonov_parameters, only: leonov_props
  implicit none
  private
  public :: leonov_state, leonov_update, leonov_elastic_tangent
  public :: leonov_state_from_statev, leonov_state_to_statev
  public :: leonov_log_r_gamma, leonov_log_x_over_sinh, leonov_ln_sinh, leonov_ln_sinh_coth
  public :: leonov_ok, leonov_step_too_large, leonov_no_convergence, leonov_bad_input
  public :: voigt_i, voigt_j, leonov_predictor_evaluations

  integer, parameter :: leonov_ok = 0              !< converged, increment accurate
  integer, parameter :: leonov_step_too_large = 1  !< converged and valid, but dgamma > p%dgamma_max
  integer, parameter :: leonov_no_convergence = 2  !< local Newton failed: outputs are the old state
  integer, parameter :: leonov_bad_input = 3       !< det F <= 0, non-finite or absurd F or state: old state kept

  !> Abaqus Voigt order 11, 22, 33, 12, 13, 23.
  integer, parameter :: voigt_i(6) = [1, 2, 3, 1, 1, 2]
  integer, parameter :: voigt_j(6) = [1, 2, 3, 2, 3, 3]

  real(dp), parameter :: identity(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                                   0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
  real(dp), parameter :: third = 1.0_dp / 3.0_dp
  real(dp), parameter :: q_elastic = 1.0e-13_dp    !< below this |dev Be~| the increment is treated as elastic
  real(dp), parameter :: eps_tangent = 1.0e-6_dp   !< perturbation of the (optional) perturbation tangent
  !> elastic fast path: ln of the Eyring increment dt sinh(tau_tr/tau_0)/A(gamma_n) at the trial stress below which
  !> the return is skipped: dgamma < 1e-10 changes tau_bar by < G 1e-10 (4.5e-8 MPa for Table 1) per increment, so
  !> at most 4.5e-5 MPa over 10^3 increments at a point held just below it: 1e-6 of the yield stress, far below
  !> the Newton tolerance and the plastic accuracy bound PROPS(11). Measured on a window of the application scene:
  !> element loop 42.4 -> 37.7 s against 1e-12 (within the run-to-run noise), reaction force equal to 4e-11.
  real(dp), parameter :: log_dgamma_elastic = -23.025850929940457_dp   ! ln(1e-10)
  real(dp), parameter :: tol_local = 1.0e-14_dp    !< local Newton tolerance (log-strain units)
  real(dp), parameter :: tol_stall = 1.0e-10_dp    !< accepted when the line search stalls at round-off
  integer, parameter :: max_newton = 60

  !> State of one material point (spatial frame of the current configuration).
  type :: leonov_state
    real(dp) :: be(3, 3) = identity   !< isochoric elastic left Cauchy-Green tensor Be~ (det = 1)
    real(dp) :: gamma_p = 0.0_dp      !< equivalent plastic strain gamma_p (Eq. 41)
    real(dp) :: tau_bar = 0.0_dp      !< output: equivalent stress tau_bar (MPa), Eq. 40
    real(dp) :: eta = 0.0_dp          !< output: viscosity eta (MPa s), Eq. 37
    real(dp) :: s_soft = 0.0_dp       !< output: state parameter S = S_a R_gamma (Eq. 41)
    real(dp) :: gamma_dot = 0.0_dp    !< output: equivalent plastic rate dgamma/dt (1/s)
    real(dp) :: dgamma = 0.0_dp       !< increment of gamma_p in the last update (not stored in STATEV)
  end type leonov_state

contains

  ! ------------------------------------------------------------------------------------------------------------
  ! State vector layout (docs/umat.md): 1-6 Be~ - I (11,22,33,12,13,23), 7 gamma_p, 8 tau_bar, 9 eta, 10 S,
  ! 11 plastic rate. All zero = virgin state (Be~ = I, gamma_p = 0).
  ! ------------------------------------------------------------------------------------------------------------

  !> State from a STATEV array (at least 11 entries).
  pure function leonov_state_from_statev(statev) result(st)
    real(dp), intent(in) :: statev(:)   !< state variables, layout above
    type(leonov_state) :: st
    integer :: k
    st%be = identity
    do k = 1, 6
      st%be(voigt_i(k), voigt_j(k)) = st%be(voigt_i(k), voigt_j(k)) + statev(k)
      st%be(voigt_j(k), voigt_i(k)) = st%be(voigt_i(k), voigt_j(k))
    end do
    st%gamma_p = statev(7)
    st%tau_bar = statev(8)
    st%eta = statev(9)
    st%s_soft = statev(10)
    st%gamma_dot = statev(11)
  end function leonov_state_from_statev

  !> Write a state into STATEV(1:11).
  pure subroutine leonov_state_to_statev(st, statev)
    type(leonov_state), intent(in) :: st    !< state
    real(dp), intent(inout) :: statev(:)    !< state variables, layout above
    integer :: k
    do k = 1, 6
      statev(k) = st%be(voigt_i(k), voigt_j(k)) - identity(voigt_i(k), voigt_j(k))
    end do
    statev(7) = st%gamma_p
    statev(8) = st%tau_bar
    statev(9) = st%eta
    statev(10) = st%s_soft
    statev(11) = st%gamma_dot
  end subroutine leonov_state_to_statev

  ! ------------------------------------------------------------------------------------------------------------
  ! Overflow-safe scalar functions
  ! ------------------------------------------------------------------------------------------------------------

  !> softplus(x) = ln(1 + exp(x)) without overflow.
  elemental real(dp) function softplus(x)
    real(dp), intent(in) :: x
    softplus = max(x, 0.0_dp) + log1p_exp_neg(abs(x))
  end function softplus

  !> ln(1 + exp(-y)) for y >= 0.
  elemental real(dp) function log1p_exp_neg(y)
    real(dp), intent(in) :: y
    if (y > 745.0_dp) then
      log1p_exp_neg = 0.0_dp
    else
      log1p_exp_neg = log(1.0_dp + exp(-y))
      if (y > 30.0_dp) log1p_exp_neg = exp(-y)
    end if
  end function log1p_exp_neg

  !> ln R_gamma(gamma_p) of Eq. 42 in log space:
  !> ln R = ((r2 - 1)/r1) [softplus(r1 (ln r0 + gamma_p)) - softplus(r1 ln r0)]; finite for every finite gamma_p
  !> (the printed form overflows for gamma_p > ~3.5 with r1 = 200).
  elemental real(dp) function leonov_log_r_gamma(p, gamma_p)
    type(leonov_props), intent(in) :: p   !< properties (r0, r1, r2)
    real(dp), intent(in) :: gamma_p       !< equivalent plastic strain
    leonov_log_r_gamma = ((p%r2 - 1.0_dp) / p%r1) * (softplus(p%r1 * (p%ln_r0 + gamma_p)) - p%softplus_0)
  end function leonov_log_r_gamma

  !> S(gamma_p) = S_a R_gamma (Eq. 41) and dS/dgamma_p = S (r2 - 1) logistic(z), z = r1 (ln r0 + gamma_p): the
  !> softplus of leonov_log_r_gamma and the logistic share e = exp(-|z|) (softplus(z) = max(z, 0) + ln(1 + e),
  !> logistic(z) = 1/(1 + e) for z >= 0, e/(1 + e) otherwise): three transcendental calls in all.
  elemental subroutine softening(p, gamma_p, s, ds)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: gamma_p
    real(dp), intent(out) :: s, ds
    real(dp) :: z, y, e, l1, lg
    z = p%r1 * (p%ln_r0 + gamma_p)
    y = abs(z)
    e = exp(-min(y, 745.0_dp))
    if (y > 30.0_dp) then
      l1 = e                     ! ln(1 + e) = e to round-off
    else
      l1 = log(1.0_dp + e)
    end if
    if (z >= 0.0_dp) then
      lg = 1.0_dp / (1.0_dp + e)
    else
      lg = e / (1.0_dp + e)
    end if
    s = p%s_a * exp(max(((p%r2 - 1.0_dp) / p%r1) * (max(z, 0.0_dp) + l1 - p%softplus_0), -700.0_dp))
    ds = s * (p%r2 - 1.0_dp) * lg
  end subroutine softening

  !> ln sinh(x) for x > 0 without overflow.
  elemental real(dp) function leonov_ln_sinh(x)
    real(dp), intent(in) :: x   !< argument, > 0
    real(dp) :: cth
    call leonov_ln_sinh_coth(x, leonov_ln_sinh, cth)
  end function leonov_ln_sinh

  !> ln sinh(x) and coth(x) for x > 0 together, one or two transcendental calls instead of three:
  !>   x < 1/2:    sinh(x)/x and cosh(x) from their Taylor series (8 terms: truncation < 1e-21 at x = 1/2),
  !>               ls = ln(x sinh(x)/x), coth = cosh/(x sinh(x)/x);
  !>   x <= 20:    e = exp(-2x) <= 1/e, ls = x - ln 2 + ln(1 - e), coth = (1 + e)/(1 - e);
  !>   x > 20:     ls = x - ln 2 (ln(1 - e) < 5e-18 rounds away against x - ln 2 > 19.3), coth = 1.
  elemental subroutine leonov_ln_sinh_coth(x, ls, cth)
    real(dp), intent(in) :: x     !< argument, > 0
    real(dp), intent(out) :: ls   !< ln sinh(x)
    real(dp), intent(out) :: cth  !< coth(x)
    real(dp) :: x2, sh, ch, e
    if (x <= tiny(1.0_dp)) then
      ls = log(tiny(1.0_dp))
      cth = 1.0_dp / tiny(1.0_dp)
    else if (x > 20.0_dp) then
      ls = x - log(2.0_dp)
      cth = 1.0_dp
    else if (x >= 0.5_dp) then
      e = exp(-2.0_dp * x)
      ls = x - log(2.0_dp) + log(1.0_dp - e)
      cth = (1.0_dp + e) / (1.0_dp - e)
    else
      x2 = x * x
      sh = 1.0_dp + x2 / 6.0_dp * (1.0_dp + x2 / 20.0_dp * (1.0_dp + x2 / 42.0_dp * (1.0_dp + x2 / 72.0_dp * &
           (1.0_dp + x2 / 110.0_dp * (1.0_dp + x2 / 156.0_dp * (1.0_dp + x2 / 210.0_dp * (1.0_dp + x2 / 272.0_dp)))))))
      ch = 1.0_dp + x2 / 2.0_dp * (1.0_dp + x2 / 12.0_dp * (1.0_dp + x2 / 30.0_dp * (1.0_dp + x2 / 56.0_dp * &
           (1.0_dp + x2 / 90.0_dp * (1.0_dp + x2 / 132.0_dp * (1.0_dp + x2 / 182.0_dp * (1.0_dp + x2 / 240.0_dp)))))))
      ls = log(x * sh)
      cth = ch / (x * sh)
    end if
  end subroutine leonov_ln_sinh_coth

  !> ln(x / sinh(x)) for x >= 0 (the Eyring factor of Eq. 37), overflow-free.
  elemental real(dp) function leonov_log_x_over_sinh(x)
    real(dp), intent(in) :: x   !< argument tau_bar/tau_0 >= 0
    if (x < 1.0e-4_dp) then
      leonov_log_x_over_sinh = -x * x / 6.0_dp
    else if (x <= 20.0_dp) then
      leonov_log_x_over_sinh = log(x / sinh(x))
    else
      leonov_log_x_over_sinh = log(x) - leonov_ln_sinh(x)
    end if
  end function leonov_log_x_over_sinh

  ! ------------------------------------------------------------------------------------------------------------
  ! Small tensor algebra
  ! ------------------------------------------------------------------------------------------------------------

  pure real(dp) function det3(a)
    real(dp), intent(in) :: a(3, 3)
    det3 = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
         + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function det3

  !> Inverse of a 3x3 matrix with known nonzero determinant.
  pure function inv3(a, det) result(b)
    real(dp), intent(in) :: a(3, 3), det
    real(dp) :: b(3, 3)
    b(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
    b(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
    b(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
    b(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
    b(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
    b(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
    b(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
    b(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
    b(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
    b = b / det
  end function inv3

  pure function dev3(a) result(b)
    real(dp), intent(in) :: a(3, 3)
    real(dp) :: b(3, 3)
    b = a - (third * (a(1, 1) + a(2, 2) + a(3, 3))) * identity
  end function dev3

  !> Eigenvalues and orthonormal eigenvectors (columns of v) of a symmetric 3x3 matrix, cyclic Jacobi.
  pure subroutine sym3_eigen(a, lam, v)
    real(dp), intent(in) :: a(3, 3)
    real(dp), intent(out) :: lam(3), v(3, 3)
    real(dp) :: b(3, 3), colp(3), colq(3), theta, t, c, s, scale
    integer :: sweep, ip, iq
    b = 0.5_dp * (a + transpose(a))
    v = identity
    scale = maxval(abs(b))
    if (scale > 0.0_dp) then
      do sweep = 1, 50
        if (abs(b(1, 2)) + abs(b(1, 3)) + abs(b(2, 3)) <= 1.0e-18_dp * scale) exit
        do ip = 1, 2
          do iq = ip + 1, 3
            if (abs(b(ip, iq)) <= 1.0e-19_dp * scale) cycle
            theta = (b(iq, iq) - b(ip, ip)) / (2.0_dp * b(ip, iq))
            if (abs(theta) > 1.0e150_dp) then
              t = 0.5_dp / theta
            else
              t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta * theta + 1.0_dp))
            end if
            c = 1.0_dp / sqrt(t * t + 1.0_dp)
            s = t * c
            ! b <- R^T b R and v <- v R with the plane rotation R (R_pp = R_qq = c, R_pq = -R_qp = s):
            ! only rows and columns p, q change
            colp = c * b(:, ip) - s * b(:, iq)
            colq = s * b(:, ip) + c * b(:, iq)
            b(:, ip) = colp
            b(:, iq) = colq
            colp = c * b(ip, :) - s * b(iq, :)
            colq = s * b(ip, :) + c * b(iq, :)
            b(ip, :) = colp
            b(iq, :) = colq
            b(ip, iq) = 0.0_dp
            b(iq, ip) = 0.0_dp
            colp = c * v(:, ip) - s * v(:, iq)
            colq = s * v(:, ip) + c * v(:, iq)
            v(:, ip) = colp
            v(:, iq) = colq
          end do
        end do
      end do
    end if
    lam = [b(1, 1), b(2, 2), b(3, 3)]
  end subroutine sym3_eigen

  !> Solve the 4x4 system a x = rhs by Gaussian elimination with partial pivoting; ok = .false. if singular.
  pure subroutine solve4(a, rhs, x, ok)
    real(dp), intent(in) :: a(4, 4), rhs(4)
    real(dp), intent(out) :: x(4)
    logical, intent(out) :: ok
    real(dp) :: b(4, 1), xm(4, 1)
    b(:, 1) = rhs
    call solve4m(a, b, xm, ok)
    x = xm(:, 1)
  end subroutine solve4

  !> Solve a x = rhs for the right-hand sides in the columns of rhs, Gaussian elimination with partial pivoting.
  !> ok = .false. when a is singular in floating point: a zero pivot, or a back-substitution quotient beyond 1e150
  !> (the unknowns of the local problems are increments of log stretches and of ln dgamma and their sensitivities,
  !> O(1) to O(1e3)); the quotient is not formed then, so nothing overflows (e.g. the local Jacobian at
  !> phi = dt G/(2 eta) ~ 1e25, where the identity next to phi times the deviatoric projection is lost in round-off
  !> and the last pivot is 3e-300: test_singular_local_jacobian_requests_cutback).
  pure subroutine solve4m(a, rhs, x, ok)
    real(dp), intent(in) :: a(4, 4), rhs(:, :)   !< rhs(4, nrhs)
    real(dp), intent(out) :: x(:, :)             !< x(4, nrhs)
    logical, intent(out) :: ok
    real(dp), parameter :: x_max = 1.0e150_dp
    real(dp) :: m(4, 4 + size(rhs, 2)), row(4 + size(rhs, 2)), f, num
    integer :: k, i, piv, nc
    nc = 4 + size(rhs, 2)
    m(:, 1:4) = a
    m(:, 5:nc) = rhs(1:4, :)
    ok = .false.
    x = 0.0_dp
    if (.not. all(is_finite(a))) return
    do k = 1, 4
      piv = k - 1 + maxloc(abs(m(k:4, k)), dim=1)
      if (.not. (abs(m(piv, k)) > 0.0_dp)) return
      if (piv /= k) then
        row = m(k, :)
        m(k, :) = m(piv, :)
        m(piv, :) = row
      end if
      do i = k + 1, 4
        f = m(i, k) / m(k, k)
        m(i, k:nc) = m(i, k:nc) - f * m(k, k:nc)
      end do
    end do
    do k = 4, 1, -1
      do i = 1, nc - 4
        num = m(k, 4 + i) - dot_product(m(k, k + 1:4), x(k + 1:4, i))
        if (.not. (abs(num) <= x_max * abs(m(k, k)))) return
        x(k, i) = num / m(k, k)
      end do
    end do
    ok = all(is_finite(x))
  end subroutine solve4m

  ! ------------------------------------------------------------------------------------------------------------
  ! Return map on the principal logarithmic elastic stretches
  ! ------------------------------------------------------------------------------------------------------------

  !> expm1(x) = exp(x) - 1 without cancellation (exp(x) - 1 = 2 t/(1 - t), t = tanh(x/2)).
  elemental real(dp) function expm1(x)
    real(dp), intent(in) :: x
    real(dp) :: t
    if (abs(x) < 1.0_dp) then
      t = tanh(0.5_dp * x)
      expm1 = 2.0_dp * t / (1.0_dp - t)
    else
      expm1 = exp(x) - 1.0_dp
    end if
  end function expm1

  !> b = exp(2e), d = dev(b) (from differences b_a - b_c = b_c expm1(2(e_a - e_c)), accurate when the e_a are
  !> close), q = sqrt(d.d/2) (tau_bar = G q, Eq. 40).
  pure subroutine principal_measures(e, b, d, q)
    real(dp), intent(in) :: e(3)
    real(dp), intent(out) :: b(3), d(3), q
    real(dp) :: d12, d13, d23
    b = exp(2.0_dp * e)
    ! b_a - b_c = b_c expm1(2 (e_a - e_c)) for the three pairs; d_a = (1/3) sum_c (b_a - b_c)
    d12 = b(2) * expm1(2.0_dp * (e(1) - e(2)))
    d13 = b(3) * expm1(2.0_dp * (e(1) - e(3)))
    d23 = b(3) * expm1(2.0_dp * (e(2) - e(3)))
    d(1) = third * (d12 + d13)
    d(2) = third * (d23 - d12)
    d(3) = -third * (d13 + d23)
    q = sqrt(0.5_dp * sum(d * d))
  end subroutine principal_measures

  !> ln A(gamma) with A = eta_0r exp(mu p/tau_0) exp(S)/tau_0 (s): the Eyring flow rule is gamma_p_dot = sinh(x)/A.
  elemental subroutine log_a(p, press, gamma_p, la, dla)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: press, gamma_p
    real(dp), intent(out) :: la, dla    !< ln A and d ln A / d gamma_p
    real(dp) :: s, ds
    call softening(p, gamma_p, s, ds)
    la = p%ln_eta_0r - p%ln_tau_0 + p%mu * press / p%tau_0 + s
    dla = ds
  end subroutine log_a

  !> Scalar radial-return predictor (small elastic strain): tau = tau_tr - G dgamma with the log flow rule;
  !> g(u) = ln sinh(x) - u - ln A(gamma_n + e^u) + ln dt = 0, u = ln dgamma, x = tau/tau_0 = x_tr - v, v = G e^u/tau_0
  !> the stress drop (u < ln(tau_tr/G): tau > 0). Safeguarded Newton from the Eyring increment at the trial stress
  !> (at most half the trial stress relaxed), each step taken in the variable in which g is nearly linear:
  !>   v > x and x < 1 (a low stress, mostly relaxed: g ~ ln x - u): in ln x;
  !>   otherwise v > 1 (g ~ x - u with x = x_tr - v, a large drop): in v, u_new = u + ln(1 + du);
  !>   otherwise (a small drop, g ~ -u): in u, du = -g/g'.
  !> A step that leaves the bracket is replaced by bisection, or by a step down of 5 while no lower bound is known
  !> (g need not be monotone under strong softening). Newton steps in u alone needed 23 evaluations of g per call
  !> on a late state of the application scene (a singularity at tau -> 0 and a bracket test that failed on a step
  !> below round-off); this form needs about 5 there (docs/umat.md "Integration").
  pure subroutine predictor(p, tau_tr, press, dt, gamma_n, la, u, n_eval)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: tau_tr, press, dt, gamma_n
    real(dp), intent(in) :: la       !< ln A(gamma_n) (log_a)
    real(dp), intent(out) :: u
    integer, intent(out) :: n_eval   !< evaluations of g
    real(dp) :: u_lo, u_hi, g, dg, v, x, x_tr, du, t, xn, un, ldt
    logical :: have_lo
    integer :: k
    ldt = log(dt)
    x_tr = tau_tr / p%tau_0
    u_hi = log(tau_tr / p%g)
    u = min(ldt + leonov_ln_sinh(x_tr) - la, u_hi - log(2.0_dp))
    u_lo = u
    have_lo = .false.
    n_eval = 0
    do k = 1, 200
      call g_of(u, g, dg, v)
      n_eval = k
      if (g > 0.0_dp) then
        u_lo = u
        have_lo = .true.
      else
        u_hi = u
      end if
      x = x_tr - v
      if (g <= -huge(1.0_dp)) then
        ! G dgamma >= tau_tr (round-off at the upper bracket, g_of's flag): no Newton step (it would be -huge and
        ! overflow below); bisect when bracketed, else step down
        if (have_lo) then
          du = 0.5_dp * (u_lo + u_hi) - u
        else
          du = -5.0_dp
        end if
      else
        du = -g / dg
        if (v > x .and. x < 1.0_dp) then
          ! step in ln x: d(ln x)/du = -v/x, dy = -du v/x; new drop v' = x_tr - x exp(dy) must stay in (0, x_tr).
          ! dy is formed only where it is finite: t = dy x is compared with 30 x and -700 x. At x <= 0 (tau <= 0
          ! in floating point) the step in ln x is that of its limit x -> 0+, dy -> +inf, i.e. the case dy >= 30:
          ! no step in ln x; the bracket test below takes over.
          if (x > 0.0_dp) then
            t = -du * v
            if (t < 30.0_dp * x) then
              xn = 0.0_dp                    ! dy < -700: exp(dy) x is below the smallest normal number
              if (t > -700.0_dp * x) xn = x * exp(t / x)
              if (xn < x_tr) du = log((x_tr - xn) / v)
            end if
          end if
        else if (v > 1.0_dp .and. du > -1.0_dp) then
          du = log(1.0_dp + du)
        end if
      end if
      un = u + du
      if (abs(du) <= 1.0e-12_dp * max(1.0_dp, abs(u))) then
        u = un
        exit
      end if
      if (.not. (un < u_hi .and. (un > u_lo .or. .not. have_lo) .and. un > u - 50.0_dp)) then
        if (have_lo) then
          un = 0.5_dp * (u_lo + u_hi)
        else
          un = u - 5.0_dp
        end if
      end if
      if (have_lo .and. u_hi - u_lo <= 1.0e-12_dp * max(1.0_dp, abs(u))) then
        u = un
        exit
      end if
      u = un
    end do

  contains

    pure subroutine g_of(uu, gg, dgg, vv)
      real(dp), intent(in) :: uu
      real(dp), intent(out) :: gg, dgg, vv
      real(dp) :: dgam, tau, lau, dlau, ls, cth
      dgam = exp(min(uu, 50.0_dp))
      tau = tau_tr - p%g * dgam
      vv = p%g * dgam / p%tau_0
      call log_a(p, press, gamma_n + dgam, lau, dlau)
      if (tau <= 0.0_dp) then
        gg = -huge(1.0_dp)
        dgg = -1.0_dp
        return
      end if
      call leonov_ln_sinh_coth(tau / p%tau_0, ls, cth)
      gg = ls - uu - lau + ldt
      dgg = -cth * vv - 1.0_dp - dgam * dlau
    end subroutine g_of
  end subroutine predictor

  !> The scalar predictor alone (diagnostics for tests and tools/bench_leonov_calls.f90): its root u = ln dgamma
  !> for the trial equivalent stress tau_tr (MPa), pressure press, time increment dt and gamma_n, and the
  !> evaluations of g it took.
  pure subroutine leonov_predictor_evaluations(p, tau_tr, press, dt, gamma_n, u, n_eval)
    type(leonov_props), intent(in) :: p   !< properties
    real(dp), intent(in) :: tau_tr        !< trial tau_bar (MPa), > 0
    real(dp), intent(in) :: press         !< pressure (MPa)
    real(dp), intent(in) :: dt            !< time increment (s), > 0
    real(dp), intent(in) :: gamma_n       !< equivalent plastic strain at the start
    real(dp), intent(out) :: u            !< ln dgamma
    integer, intent(out) :: n_eval        !< evaluations of g
    real(dp) :: la, dla
    call log_a(p, press, gamma_n, la, dla)
    call predictor(p, tau_tr, press, dt, gamma_n, la, u, n_eval)
  end subroutine leonov_predictor_evaluations

  !> Residual and Jacobian of the local problem in x = (e_1, e_2, e_3, u = ln dgamma):
  !>   r_a = e_a - e_a^tr + phi d_a,  phi = dt G/(2 eta) = (dt G/(2 tau_0)) exp(-ln A) sinh(x)/x,  x = tau_bar/tau_0
  !>   (dgamma/2 N_a = dt Dp_a: the viscosity form stays smooth when tau_bar -> 0),
  !>   r_4 = ln sinh(x) - u - ln A(gamma_n + e^u) + ln dt  (Eq. 37 with dgamma = dt tau_bar/eta).
  pure subroutine local_residual(p, etr, press, ldt, lphi0, gamma_n, x, r, jac, norm, ok, phi, s)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: etr(3), press
    real(dp), intent(in) :: ldt         !< ln dt
    real(dp), intent(in) :: lphi0       !< ln(dt G/(2 tau_0))
    real(dp), intent(in) :: gamma_n, x(4)
    real(dp), intent(out) :: r(4), jac(4, 4), norm
    logical, intent(out) :: ok
    real(dp), intent(out) :: phi       !< dt G/(2 eta) at x
    real(dp), intent(out) :: s         !< S(gamma_n + dgamma) at x (Eq. 41)
    real(dp) :: b(3), d(3), q, dgam, xs, la, dla, dxs(3), lphi, dlx, ls, cth
    integer :: a, c
    ok = .false.
    r = 0.0_dp
    jac = 0.0_dp
    phi = 0.0_dp
    s = 0.0_dp
    norm = huge(1.0_dp)
    if (any(abs(x(1:3)) > 50.0_dp) .or. x(4) > 50.0_dp) return
    call principal_measures(x(1:3), b, d, q)
    if (q <= tiny(1.0_dp) * 1.0e10_dp) return
    dgam = exp(x(4))
    xs = p%g * q / p%tau_0
    ! ln A as log_a computes it, keeping S for the state's output (finish_update)
    call softening(p, gamma_n + dgam, s, dla)
    la = p%ln_eta_0r - p%ln_tau_0 + p%mu * press / p%tau_0 + s
    ! ln sinh(x), ln(x/sinh x) and coth x once each (shared by r, phi and the Jacobian)
    call leonov_ln_sinh_coth(xs, ls, cth)
    if (xs < 1.0e-4_dp) then
      lphi = lphi0 - la + xs * xs / 6.0_dp
    else
      lphi = lphi0 - la - (log(xs) - ls)
    end if
    if (lphi > 600.0_dp) return
    phi = exp(lphi)
    if (xs < 1.0e-3_dp) then
      dlx = xs / 3.0_dp - xs**3 / 45.0_dp
    else
      dlx = cth - 1.0_dp / xs
    end if
    dxs = (p%g / p%tau_0) * b * d / q
    r(1:3) = x(1:3) - etr + phi * d
    r(4) = ls - x(4) - la + ldt
    do a = 1, 3
      do c = 1, 3
        jac(a, c) = phi * (2.0_dp * b(c) * (merge(1.0_dp, 0.0_dp, a == c) - third) + d(a) * dlx * dxs(c))
      end do
      jac(a, a) = jac(a, a) + 1.0_dp
      jac(a, 4) = -phi * d(a) * dla * dgam
    end do
    jac(4, 1:3) = cth * dxs
    jac(4, 4) = -1.0_dp - dgam * dla
    ! norm in log-strain units: r4 times the larger of d tau/d r4 / (2 G) and d(dgamma)/d u / 2
    norm = max(maxval(abs(r(1:3))), abs(r(4)) * max(p%tau_0 * tanh(xs) / (2.0_dp * p%g), 0.5_dp * dgam))
    ok = is_finite(norm) .and. all(is_finite(jac))
  end subroutine local_residual

  !> Elastic fast path: .true. when the increment is treated as elastic (no return), from the trial q = tau_bar/G.
  !> The Eyring increment at the trial stress, dt sinh(tau_tr/tau_0)/A(gamma_n), bounds dgamma (the return lowers
  !> tau_bar; the softening of A over dgamma is a factor 1 + O(dgamma)); below dgamma_elastic the increment is
  !> elastic. Also elastic: dt <= 0 and a deviator below q_elastic.
  pure logical function elastic_increment(p, dt, q_tr, la)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: dt, q_tr
    real(dp), intent(in) :: la     !< ln A(gamma_n) (log_a)
    elastic_increment = .true.
    if (.not. (dt > 0.0_dp) .or. q_tr <= q_elastic) return
    elastic_increment = log(dt) + leonov_ln_sinh(p%g * q_tr / p%tau_0) - la < log_dgamma_elastic
  end function elastic_increment

  !> Implicit exponential-map return on the principal log elastic stretches (see the module header).
  !> Also returns what the consistent tangent needs (implicit function theorem at the converged root of
  !> R(x; e_tr, p) = 0: dx = -(dR/dx)^-1 (dR/de_tr de_tr + dR/dp dp), dR/dx = the local Newton Jacobian):
  !> dedetr(a, c) = de_a/de_tr,c, dedp(a) = de_a/dp, phi = dt G/(2 eta) at the solution (identity, 0, 0 when the
  !> increment is elastic).
  pure subroutine return_map(p, etr, press, dt, gamma_n, la_n, s_n, e, dgamma, stat, dedetr, dedp, phi, s_new)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: etr(3), press, dt, gamma_n
    real(dp), intent(in) :: la_n, s_n   !< ln A(gamma_n) and S(gamma_n) (log_a, softening)
    real(dp), intent(out) :: e(3), dgamma
    integer, intent(out) :: stat
    real(dp), intent(out) :: dedetr(3, 3), dedp(3), phi
    real(dp), intent(out) :: s_new      !< S(gamma_n + dgamma)
    real(dp) :: b(3), d(3), q_tr, tau_tr, u, tau, x(4), xt(4), r(4), jac(4, 4), dx(4), norm, norm_t, alpha, sc
    real(dp) :: rhs(4, 4), sens(4, 4), ldt, lphi0
    logical :: ok, accepted
    integer :: it, ls, n_eval

    stat = leonov_ok
    e = etr
    dgamma = 0.0_dp
    dedetr = identity
    dedp = 0.0_dp
    phi = 0.0_dp
    s_new = s_n
    call principal_measures(etr, b, d, q_tr)
    if (elastic_increment(p, dt, q_tr, la_n)) return
    tau_tr = p%g * q_tr
    call predictor(p, tau_tr, press, dt, gamma_n, la_n, u, n_eval)
    ldt = log(dt)
    lphi0 = ldt + log(p%g / (2.0_dp * p%tau_0))
    tau = max(tau_tr - p%g * exp(u), 1.0e-12_dp * tau_tr)
    x(1:3) = etr * (tau / tau_tr)
    x(4) = u
    call local_residual(p, etr, press, ldt, lphi0, gamma_n, x, r, jac, norm, ok, phi, s_new)
    if (.not. ok) then
      x(1:3) = etr
      x(4) = u
      call local_residual(p, etr, press, ldt, lphi0, gamma_n, x, r, jac, norm, ok, phi, s_new)
      if (.not. ok) then
        stat = leonov_no_convergence
        return
      end if
    end if
    do it = 1, max_newton
      if (norm <= tol_local * max(1.0_dp, maxval(abs(etr)))) exit
      call solve4(jac, -r, dx, ok)
      if (.not. ok) then
        stat = leonov_no_convergence
        return
      end if
      sc = max(maxval(abs(dx(1:3))) / 0.5_dp, abs(dx(4)) / 5.0_dp, 1.0_dp)
      dx = dx / sc
      alpha = 1.0_dp
      accepted = .false.
      do ls = 1, merge(3, 30, norm <= tol_stall)
        xt = x + alpha * dx
        call local_residual(p, etr, press, ldt, lphi0, gamma_n, xt, r, jac, norm_t, ok, phi, s_new)
        if (ok .and. norm_t < (1.0_dp - 1.0e-4_dp * alpha) * norm) then
          accepted = .true.
          exit
        end if
        alpha = 0.5_dp * alpha
      end do
      if (.not. accepted) then
        ! round-off floor: accept if already tight, otherwise fail
        call local_residual(p, etr, press, ldt, lphi0, gamma_n, x, r, jac, norm, ok, phi, s_new)
        if (ok .and. norm <= tol_stall) exit
        stat = leonov_no_convergence
        return
      end if
      x = xt
      norm = norm_t
      if (it == max_newton .and. norm > tol_stall) then
        stat = leonov_no_convergence
        return
      end if
    end do
    e = x(1:3) - third * sum(x(1:3))
    dgamma = exp(x(4))
    ! sensitivities: jac and phi belong to the converged x (last accepted evaluation). dR_a/de_tr,c = -delta_ac;
    ! dR/dp from ln A = ... + mu p/tau_0: dR_a/dp = -phi d_a mu/tau_0, dR_4/dp = -mu/tau_0.
    call principal_measures(x(1:3), b, d, q_tr)
    rhs = 0.0_dp
    rhs(1, 1) = 1.0_dp
    rhs(2, 2) = 1.0_dp
    rhs(3, 3) = 1.0_dp
    rhs(1:3, 4) = phi * d * (p%mu / p%tau_0)
    rhs(4, 4) = p%mu / p%tau_0
    call solve4m(jac, rhs, sens, ok)
    if (.not. ok) then
      stat = leonov_no_convergence
      return
    end if
    dedetr = sens(1:3, 1:3)
    dedp = sens(1:3, 4)
  end subroutine return_map

  ! ------------------------------------------------------------------------------------------------------------
  ! Update of one material point
  ! ------------------------------------------------------------------------------------------------------------

  !> State update and Kirchhoff stress for F_n -> F_n+1 in time dt; with c present also the consistent tangent.
  pure subroutine kirchhoff_update(p, f0, f1, dt, old, new, tau_k, stat, c)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: f0(3, 3), f1(3, 3), dt
    type(leonov_state), intent(in) :: old
    type(leonov_state), intent(out) :: new
    real(dp), intent(out) :: tau_k(3, 3)
    integer, intent(out) :: stat
    real(dp), intent(inout), optional :: c(6, 6)   !< consistent tangent (set only when stat = leonov_ok)
    real(dp) :: j0, j1, frel(3, 3), betr(3, 3), lam(3), v(3, 3), etr(3), e(3), press, dgamma, detb
    real(dp) :: be(3, 3), bt(3, 3), sigma(3, 3), dedetr(3, 3), dedp(3), phi, dbe(3, 3), q_tr
    real(dp) :: s_n, ds_n, la_n, s_new
    real(dp) :: bv(3)
    integer :: i, j

    new = old
    tau_k = 0.0_dp
    stat = leonov_bad_input
    if (.not. (all(is_finite(f0)) .and. all(is_finite(f1)) .and. all(is_finite(old%be)))) return
    if (maxval(abs(f0)) > 1.0e50_dp .or. maxval(abs(f1)) > 1.0e50_dp .or. maxval(abs(old%be)) > 1.0e50_dp) return
    if (.not. is_finite(old%gamma_p) .or. .not. is_finite(dt)) return
    j0 = det3(f0)
    j1 = det3(f1)
    if (.not. (j0 > 1.0e-50_dp .and. j1 > 1.0e-50_dp)) return
    detb = det3(old%be)
    if (.not. (detb > 1.0e-50_dp)) return
    ! elastic predictor (exact for the elastic part of Eq. 35)
    frel = matmul(f1, inv3(f0, j0))
    ! Be~_trial = F~_rel (Be~_n / det(Be~_n)^(1/3)) F~_rel^T, F~_rel = (J/J_n)^(-1/3) F_rel: one power for both
    ! factors ((J/J_n) sqrt(det Be~_n))^(-2/3), in range for every accepted input (|F|, |Be~_n| <= 1e50)
    betr = matmul(frel, matmul(old%be, transpose(frel))) * ((j1 / j0) * sqrt(detb))**(-2.0_dp * third)
    if (.not. all(is_finite(betr))) return
    ! p = -tr(sigma)/3 = -kappa (J - 1) (Eq. 38; the hardening and driving deviators are traceless)
    press = -p%kappa * (j1 - 1.0_dp)
    ! ln A(gamma_n) as log_a computes it, S(gamma_n) kept for an elastic increment's outputs
    call softening(p, old%gamma_p, s_n, ds_n)
    la_n = p%ln_eta_0r - p%ln_tau_0 + p%mu * press / p%tau_0 + s_n
    bt = j1**(-2.0_dp * third) * matmul(f1, transpose(f1))
    ! elastic fast path in Cartesian form (most points of a peel run: the bonded coating ahead of the front):
    ! Be~_n+1 = Be~_trial, no eigen-decomposition. tau_bar/G = |dev Be~_trial|/sqrt(2) as in principal_measures
    ! (det Be~_trial = 1 to round-off: det F~_rel = 1 and Be~_n is rescaled to det 1 above). Only for moderate
    ! elastic strains (q < 1); larger trial deviators take the spectral route with its range checks.
    dbe = dev3(betr)
    q_tr = sqrt(0.5_dp * sum(dbe * dbe))
    if (q_tr < 1.0_dp) then
      if (elastic_increment(p, dt, q_tr, la_n)) then
        be = betr
        sigma = p%g * dbe + p%kappa * (j1 - 1.0_dp) * identity + p%g_r * dev3(bt)
        dgamma = 0.0_dp
        call finish_update(p, old, be, sigma, dgamma, press, j1, dt, s_n, new, tau_k)
        if (present(c)) call elastic_tangent(p, j1, sigma, be, bt, c)
        stat = leonov_ok
        return
      end if
    end if
    call sym3_eigen(betr, lam, v)
    if (.not. all(lam > 0.0_dp)) return
    etr = 0.5_dp * log(lam)
    etr = etr - third * sum(etr)
    if (maxval(abs(etr)) > 25.0_dp) return
    call return_map(p, etr, press, dt, old%gamma_p, la_n, s_n, e, dgamma, stat, dedetr, dedp, phi, s_new)
    if (stat /= leonov_ok) return
    ! Be~_n+1 = sum_a exp(2 e_a) v_a v_a^T in the trial eigenbasis
    bv = exp(2.0_dp * e)
    do j = 1, 3
      do i = 1, 3
        be(i, j) = bv(1) * v(i, 1) * v(j, 1) + bv(2) * v(i, 2) * v(j, 2) + bv(3) * v(i, 3) * v(j, 3)
      end do
    end do
    ! Eqs. 31-33
    sigma = p%g * dev3(be) + p%kappa * (j1 - 1.0_dp) * identity + p%g_r * dev3(bt)
    call finish_update(p, old, be, sigma, dgamma, press, j1, dt, s_new, new, tau_k)
    if (present(c)) call consistent_tangent(p, j1, sigma, bt, v, etr, e, dedetr, dedp, phi, c)
    stat = leonov_ok
  end subroutine kirchhoff_update

  !> Kirchhoff stress and the new state (with its outputs tau_bar, S, eta, rate) from Be~_n+1, sigma, dgamma and
  !> s = S(gamma_n + dgamma) (from the return or, for an elastic increment, S(gamma_n): the softening is not
  !> evaluated a second time).
  pure subroutine finish_update(p, old, be, sigma, dgamma, press, j1, dt, s, new, tau_k)
    type(leonov_props), intent(in) :: p
    type(leonov_state), intent(in) :: old
    real(dp), intent(in) :: be(3, 3), sigma(3, 3), dgamma, press, j1, dt, s
    type(leonov_state), intent(inout) :: new
    real(dp), intent(out) :: tau_k(3, 3)
    real(dp) :: x
    tau_k = j1 * sigma
    new%be = be
    new%gamma_p = old%gamma_p + dgamma
    new%dgamma = dgamma
    new%tau_bar = p%g * sqrt(0.5_dp * sum(dev3(be)**2))
    new%s_soft = s
    ! eta = tau_0 A x/sinh(x) (Eq. 37), ln(tau_0 A) = ln eta_0r + mu p/tau_0 + S (log_a)
    x = new%tau_bar / p%tau_0
    new%eta = exp(min(p%ln_eta_0r + p%mu * press / p%tau_0 + s + leonov_log_x_over_sinh(x), 700.0_dp))
    if (dt > 0.0_dp) then
      new%gamma_dot = dgamma / dt
    else
      new%gamma_dot = 0.0_dp
    end if
  end subroutine finish_update

  !> Tangent of an elastic increment (Be~_n+1 = Be~_trial), Cartesian: the elastic limit of consistent_tangent
  !> (phi = 0, de/de_tr = identity, de/dp = 0, c_ab = b_a + b_b), i.e. dBe~ = dE' Be~ + Be~ dE' for dF = dE F:
  !>   dtau/J = dev(dE' M + M dE') + tr(dE) (sigma + kappa J I),  M = G Be~ + G_r B~,  dE' = dev(dE)  (Eqs. 31-33).
  pure subroutine elastic_tangent(p, j1, sigma, be, bt, c)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: j1, sigma(3, 3), be(3, 3), bt(3, 3)
    real(dp), intent(out) :: c(6, 6)
    real(dp) :: mm(3, 3), trm, tr, trx, x
    integer :: i, j, k, kk, a, b
    ! column k: dE = (e_i e_j^T + e_j e_i^T)/2, tr = delta_ij; X = dE' M + M dE' = dE M + M dE - (2 tr/3) M,
    ! (dE M + M dE)_ab = (delta_ai M_jb + delta_aj M_ib + M_ai delta_bj + M_aj delta_bi)/2,
    ! tr X = 2 M_ij - (2 tr/3) tr M
    mm = p%g * be + p%g_r * bt
    trm = mm(1, 1) + mm(2, 2) + mm(3, 3)
    do k = 1, 6
      i = voigt_i(k)
      j = voigt_j(k)
      tr = merge(1.0_dp, 0.0_dp, i == j)
      trx = 2.0_dp * mm(i, j) - 2.0_dp * third * tr * trm
      do kk = 1, 6
        a = voigt_i(kk)
        b = voigt_j(kk)
        x = -2.0_dp * third * tr * mm(a, b)
        if (a == i) x = x + 0.5_dp * mm(j, b)
        if (a == j) x = x + 0.5_dp * mm(i, b)
        if (b == j) x = x + 0.5_dp * mm(a, i)
        if (b == i) x = x + 0.5_dp * mm(a, j)
        if (a == b) x = x - third * trx + p%kappa * j1 * tr
        c(kk, k) = x + tr * sigma(a, b)
      end do
    end do
  end subroutine elastic_tangent

  !> x/tanh(x), smooth at 0.
  elemental real(dp) function x_over_tanh(x)
    real(dp), intent(in) :: x
    if (abs(x) < 1.0e-4_dp) then
      x_over_tanh = 1.0_dp + x * x / 3.0_dp
    else if (abs(x) > 20.0_dp) then
      x_over_tanh = abs(x)
    else
      x_over_tanh = x / tanh(x)
    end if
  end function x_over_tanh

  !> sinh(x)/x, smooth at 0.
  elemental real(dp) function sinh_over_x(x)
    real(dp), intent(in) :: x
    if (abs(x) < 1.0e-4_dp) then
      sinh_over_x = 1.0_dp + x * x / 6.0_dp
    else
      sinh_over_x = sinh(x) / x
    end if
  end function sinh_over_x

  !> expm1(2x)/x, smooth at 0 (= 2 + 2x + 4x^2/3 + ...).
  elemental real(dp) function expm1_2x_over_x(x)
    real(dp), intent(in) :: x
    if (abs(x) < 1.0e-5_dp) then
      expm1_2x_over_x = 2.0_dp + x * (2.0_dp + x * (4.0_dp / 3.0_dp))
    else
      expm1_2x_over_x = expm1(2.0_dp * x) / x
    end if
  end function expm1_2x_over_x

  !> Consistent tangent of the converged update (Abaqus DDSDDE: Jaumann rate of Kirchhoff stress over J,
  !> engineering shear), analytic. Column k is the response to dF = dE_k F with dE_k the symmetric Voigt unit
  !> (e_i e_j^T + e_j e_i^T)/2 (the same F-perturbation as Miehe 1996, taken to its limit): a spin-free
  !> perturbation, so the Jaumann rate is the plain change, dtau/J = tr(dE) sigma + dsigma with (Eqs. 31-33)
  !>   dsigma = G dev(dBe~) + kappa J tr(dE) I + G_r dev(dE' B~ + B~ dE'),  dE' = dev(dE);
  !>   dBe~_trial = dE' Be~_trial + Be~_trial dE' (the trial sees F only through its isochoric part);
  !>   in the trial eigenbasis v (also that of Be~_n+1): de_tr,a = dE'_aa, dp = -kappa J tr(dE) (Eq. 38),
  !>     dBe~_aa = 2 b_a (dedetr de_tr + dedp dp)_a  (b_a = exp(2 e_a), sensitivities from the return map),
  !>     dBe~_ab = c_ab dE'_ab (a /= b),  c_ab = (b_a - b_b)(l_a + l_b)/(l_a - l_b) (l = trial eigenvalues)
  !>             = 2 exp(e_a + e_b) [sinh(D)/D] [D/D_tr] [D_tr/tanh(D_tr)],  D = e_a - e_b, D_tr = e_tr,a - e_tr,b,
  !>   and D/D_tr = 1/(1 + phi b_b expm1(2D)/D) from r_a - r_b = 0 of the return (D = D_tr when elastic): no
  !>   division by D_tr, so repeated trial eigenvalues (uniaxial states) need no special case.
  pure subroutine consistent_tangent(p, j1, sigma, bt, v, etr, e, dedetr, dedp, phi, c)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: j1, sigma(3, 3), bt(3, 3), v(3, 3), etr(3), e(3), dedetr(3, 3), dedp(3), phi
    real(dp), intent(out) :: c(6, 6)
    real(dp) :: coef(3, 3), dd(3, 3), dq(3, 3), dbe(3, 3), dsig(3, 3), de(3), tr, dpress, dlt, dltr, ratio, b(3)
    integer :: a, bb, i, j, k, kk
    b = exp(2.0_dp * e)
    ! coef is symmetric (b_b expm1(2 D)/D = (b_a - b_b)/D; sinh(D)/D and D/tanh(D) are even): three pairs
    coef = 0.0_dp
    do a = 1, 2
      do bb = a + 1, 3
        dlt = e(a) - e(bb)
        dltr = etr(a) - etr(bb)
        ratio = 1.0_dp / (1.0_dp + phi * b(bb) * expm1_2x_over_x(dlt))
        coef(a, bb) = 2.0_dp * sqrt(b(a) * b(bb)) * sinh_over_x(dlt) * ratio * x_over_tanh(dltr)
        coef(bb, a) = coef(a, bb)
      end do
    end do
    do k = 1, 6
      i = voigt_i(k)
      j = voigt_j(k)
      dd = 0.0_dp
      dd(i, j) = 0.5_dp
      dd(j, i) = dd(j, i) + 0.5_dp
      tr = dd(1, 1) + dd(2, 2) + dd(3, 3)
      dd = dev3(dd)
      dpress = -p%kappa * j1 * tr
      ! dq = v^T dE' v = sym(v_i. x v_j.) - tr/3 I (v^T I v = I)
      do bb = 1, 3
        do a = 1, 3
          dq(a, bb) = 0.5_dp * (v(i, a) * v(j, bb) + v(j, a) * v(i, bb))
        end do
        dq(bb, bb) = dq(bb, bb) - third * tr
      end do
      de = matmul(dedetr, [dq(1, 1), dq(2, 2), dq(3, 3)]) + dedp * dpress
      dq = coef * dq
      do a = 1, 3
        dq(a, a) = 2.0_dp * b(a) * de(a)
      end do
      dbe = matmul(v, matmul(dq, transpose(v)))
      dsig = p%g * dev3(dbe) + p%g_r * dev3(matmul(dd, bt) + matmul(bt, dd)) + tr * sigma
      do a = 1, 3
        dsig(a, a) = dsig(a, a) + p%kappa * j1 * tr
      end do
      do kk = 1, 6
        c(kk, k) = dsig(voigt_i(kk), voigt_j(kk))
      end do
    end do
  end subroutine consistent_tangent

  !> Isotropic small-strain tangent kappa I x I + 2 (G + G_r) I_dev in Abaqus Voigt form (engineering shear).
  pure function leonov_elastic_tangent(p) result(c)
    type(leonov_props), intent(in) :: p   !< properties
    real(dp) :: c(6, 6)
    real(dp) :: gt
    integer :: k
    gt = p%g + p%g_r
    c = 0.0_dp
    c(1:3, 1:3) = p%kappa - 2.0_dp * third * gt
    do k = 1, 3
      c(k, k) = p%kappa + 4.0_dp * third * gt
      c(k + 3, k + 3) = gt
    end do
  end function leonov_elastic_tangent

  !> One increment of the compressible Leonov model.
  !> stat: leonov_ok; leonov_step_too_large (results valid, dgamma > p%dgamma_max: ask for a smaller step);
  !> leonov_no_convergence or leonov_bad_input (new = old, sigma = 0, ddsdde elastic: the caller must cut back).
  !> step_factor: suggested ratio of the next to the present time increment (< 1 on any trouble).
  pure subroutine leonov_update(p, f0, f1, dt, old, new, sigma, stat, step_factor, ddsdde, perturbation_tangent)
    type(leonov_props), intent(in) :: p              !< validated properties
    real(dp), intent(in) :: f0(3, 3)                 !< deformation gradient at t_n
    real(dp), intent(in) :: f1(3, 3)                 !< deformation gradient at t_n+1
    real(dp), intent(in) :: dt                       !< time increment (s)
    type(leonov_state), intent(in) :: old            !< state at t_n
    type(leonov_state), intent(out) :: new           !< state at t_n+1
    real(dp), intent(out) :: sigma(3, 3)             !< Cauchy stress at t_n+1 (MPa)
    integer, intent(out) :: stat                     !< status, see above
    real(dp), intent(out) :: step_factor             !< suggested time step ratio
    real(dp), intent(out), optional :: ddsdde(6, 6)  !< Abaqus tangent, order 11,22,33,12,13,23, engineering shear
    !> .true.: DDSDDE by central perturbation of F (13 local solves; the former method, kept for comparison)
    logical, intent(in), optional :: perturbation_tangent
    real(dp) :: tau_k(3, 3), tp(3, 3), tm(3, 3), fp(3, 3), fm(3, 3), dlt(3, 3), j1
    type(leonov_state) :: scratch
    integer :: k, kk, stp, stm
    logical :: perturb

    perturb = .false.
    if (present(perturbation_tangent)) perturb = perturbation_tangent
    sigma = 0.0_dp
    if (present(ddsdde)) ddsdde = leonov_elastic_tangent(p)
    if (present(ddsdde) .and. .not. perturb) then
      call kirchhoff_update(p, f0, f1, dt, old, new, tau_k, stat, ddsdde)
    else
      call kirchhoff_update(p, f0, f1, dt, old, new, tau_k, stat)
    end if
    if (stat /= leonov_ok) then
      if (present(ddsdde)) ddsdde = leonov_elastic_tangent(p)
      new = old
      step_factor = 0.25_dp
      return
    end if
    j1 = det3(f1)
    sigma = tau_k / j1
    if (new%dgamma > p%dgamma_max) then
      stat = leonov_step_too_large
      step_factor = max(0.1_dp, 0.9_dp * p%dgamma_max / new%dgamma)
    else
      step_factor = min(1.5_dp, max(1.0_dp, 0.9_dp * p%dgamma_max / max(new%dgamma, tiny(1.0_dp))))
    end if
    if (.not. (present(ddsdde) .and. perturb)) return
    do k = 1, 6
      dlt = 0.0_dp
      dlt(voigt_i(k), voigt_j(k)) = 0.5_dp * eps_tangent
      dlt(voigt_j(k), voigt_i(k)) = dlt(voigt_j(k), voigt_i(k)) + 0.5_dp * eps_tangent
      fp = f1 + matmul(dlt, f1)
      fm = f1 - matmul(dlt, f1)
      call kirchhoff_update(p, f0, fp, dt, old, scratch, tp, stp)
      call kirchhoff_update(p, f0, fm, dt, old, scratch, tm, stm)
      if (stp /= leonov_ok .or. stm /= leonov_ok) then
        ddsdde = leonov_elastic_tangent(p)
        new = old
        sigma = 0.0_dp
        stat = leonov_no_convergence
        step_factor = 0.25_dp
        return
      end if
      do kk = 1, 6
        ddsdde(kk, k) = (tp(voigt_i(kk), voigt_j(kk)) - tm(voigt_i(kk), voigt_j(kk))) / (2.0_dp * j1 * eps_tangent)
      end do
    end do
  end subroutine leonov_update

end module leonov
