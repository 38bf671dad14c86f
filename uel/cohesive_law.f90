!> Traction-separation laws of the LDF cohesive zone (van den Bosch, Schreurs, Geers 2007), pure and host-free.
!>
!> * LDF law (Eqs. 20-21): T = (phi/delta) (Delta/delta) exp(-Delta/delta) along m = Delta_vec/|Delta_vec|, with its
!>   analytic tangent (Eq. 26) written as M = dT/dDelta m m^T + (T/Delta) (I - m m^T), T/Delta = (phi/delta^2) exp(-Delta/delta),
!>   finite everywhere (isotropic phi/delta^2 I at Delta = 0); Eq. 28's form (division by Delta (delta - Delta)) is not used.
!> * Unloading (Fig. 6) with a scalar history Delta_max per point: reversible, elastic damage (secant to the origin),
!>   plastic (unloading with the initial stiffness K0 = phi/delta^2 to a permanent opening magnitude Delta_p).
!> * Contact penalty (Eqs. 19, 22, 29) on the normal opening Delta_c = Delta_vec . n.
!> * The classical small-displacement law (Eqs. 1-2) in a given local normal n, for comparison.
!> All vectors are 3-component (plane problems carry zero z components).
module cohesive_law
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: cohesive_props, law_ldf, law_classical
  public :: ldf_envelope, ldf_potential, ldf_traction, contact_traction, classical_traction

  integer, parameter, public :: unload_reversible = 1  !< Fig. 6 (i): reversible, along the law
  integer, parameter, public :: unload_damage = 2      !< Fig. 6 (ii): elastic damage, secant to the origin
  integer, parameter, public :: unload_plastic = 3     !< Fig. 6 (iii): plastic, initial stiffness K0
  integer, parameter :: law_ldf = 1                    !< large displacement formulation (Eqs. 20-23)
  integer, parameter :: law_classical = 2              !< small displacement formulation (Eqs. 1-2)

  !> Parameters of one cohesive zone (already validated and defaulted by the caller).
  type :: cohesive_props
    real(dp) :: phi = 0.0_dp      !< work of separation phi (N/mm)
    real(dp) :: delta = 0.0_dp    !< characteristic opening delta (mm); T_max = phi/(e delta), Eq. 5
    real(dp) :: kc = 0.0_dp       !< contact stiffness k_c (MPa), Eq. 22
    real(dp) :: phi_t = 0.0_dp    !< tangential work of separation of the classical law (Eq. 1)
    real(dp) :: delta_t = 0.0_dp  !< tangential characteristic length of the classical law (Eq. 1)
    real(dp) :: eta_v = 0.0_dp    !< optional viscous regularisation (N s/mm^3): T_vec += eta_v dDelta_vec/dt; 0 = none
    integer :: unloading = unload_reversible  !< unload_reversible, unload_damage or unload_plastic
    integer :: law = law_ldf                  !< law_ldf or law_classical
  end type cohesive_props

contains

  !> The LDF envelope, Eq. 20: traction T, slope dT/dDelta and secant T/Delta at the opening magnitude d >= 0.
  !> T/Delta = (phi/delta^2) exp(-d/delta) is evaluated directly, so it is finite at d = 0.
  pure subroutine ldf_envelope(phi, delta, d, t, dtdd, t_over_d)
    real(dp), intent(in) :: phi       !< work of separation
    real(dp), intent(in) :: delta     !< characteristic opening
    real(dp), intent(in) :: d         !< opening magnitude (>= 0)
    real(dp), intent(out) :: t        !< traction magnitude, Eq. 20
    real(dp), intent(out) :: dtdd     !< dT/dDelta = (phi/delta^2) (1 - d/delta) exp(-d/delta)
    real(dp), intent(out) :: t_over_d !< T/Delta = (phi/delta^2) exp(-d/delta)
    real(dp) :: k0, e
    k0 = phi / delta**2
    e = exp(-d / delta)
    t_over_d = k0 * e
    t = t_over_d * d
    dtdd = k0 * (1.0_dp - d / delta) * e
  end subroutine ldf_envelope

  !> Potential of the LDF law, psi(d) = int_0^d T = phi [1 - (1 + d/delta) exp(-d/delta)]; psi(inf) = phi.
  elemental function ldf_potential(phi, delta, d) result(psi)
    real(dp), intent(in) :: phi    !< work of separation
    real(dp), intent(in) :: delta  !< characteristic opening
    real(dp), intent(in) :: d      !< opening magnitude
    real(dp) :: psi
    psi = phi * (1.0_dp - (1.0_dp + d / delta) * exp(-d / delta))
  end function ldf_potential

  !> LDF traction vector (Eq. 21), tangent (Eq. 26) and history update for the three unloading types (Fig. 6).
  !>
  !> The history is Delta_max, the largest opening magnitude reached. With the end-of-increment opening d:
  !> loading (d >= Delta_max_old) follows the envelope and Delta_max_new = d. Below Delta_max:
  !> (1) reversible: the envelope; (2) damage: T = T(Delta_max) d / Delta_max; (3) plastic: T = K0 (d - Delta_p) for
  !> d > Delta_p and 0 below, K0 = phi/delta^2, Delta_p = Delta_max - T(Delta_max)/K0 = Delta_max (1 - exp(-Delta_max/delta)).
  !> Every branch gives T_vec = s d_vec with the secant s = T/d, so no division by d is ever needed:
  !> M = s I + (dT/dd - s) m m^T, and at d = 0 dT/dd = s (M isotropic).
  !> Energies per unit initial area: w_stored the recoverable energy, w_diss the dissipated one (reversible: psi(d), 0;
  !> damage: s d^2/2, psi(Dmax) - T(Dmax) Dmax/2; plastic: T^2/(2 K0), psi(Dmax) - T(Dmax)^2/(2 K0)).
  pure subroutine ldf_traction(props, dvec, dmax_old, tvec, mmat, dmax_new, w_stored, w_diss)
    type(cohesive_props), intent(in) :: props  !< law parameters and unloading type
    real(dp), intent(in) :: dvec(3)            !< opening vector Delta_vec (global basis)
    real(dp), intent(in) :: dmax_old           !< Delta_max at the start of the increment
    real(dp), intent(out) :: tvec(3)           !< first Piola-Kirchhoff traction vector, Eq. 21
    real(dp), intent(out) :: mmat(3,3)         !< tangent dT_vec/dDelta_vec, Eq. 26
    real(dp), intent(out) :: dmax_new          !< Delta_max at the end of the increment
    real(dp), intent(out) :: w_stored          !< recoverable energy per unit initial area
    real(dp), intent(out) :: w_diss            !< dissipated energy per unit initial area
    real(dp) :: d, t, dtdd, sec, k0, tm, dtm, secm, dperm, m(3)
    integer :: i

    d = norm2(dvec)
    k0 = props%phi / props%delta**2
    dmax_new = max(dmax_old, d)
    if (d >= dmax_old .or. props%unloading == unload_reversible) then
      call ldf_envelope(props%phi, props%delta, d, t, dtdd, sec)
      select case (props%unloading)
      case (unload_damage)
        w_stored = 0.5_dp * t * d
      case (unload_plastic)
        w_stored = 0.5_dp * t**2 / k0
      case default
        w_stored = ldf_potential(props%phi, props%delta, d)
      end select
      w_diss = ldf_potential(props%phi, props%delta, dmax_new) - w_stored
      if (props%unloading == unload_reversible) w_diss = 0.0_dp
    else
      call ldf_envelope(props%phi, props%delta, dmax_old, tm, dtm, secm)
      if (props%unloading == unload_damage) then
        sec = secm                     ! secant to the origin, Fig. 6 (ii)
        dtdd = secm
        t = sec * d
        w_stored = 0.5_dp * sec * d**2
        w_diss = ldf_potential(props%phi, props%delta, dmax_old) - 0.5_dp * tm * dmax_old
      else
        dperm = dmax_old - tm / k0     ! permanent opening, Fig. 6 (iii)
        if (d > dperm) then
          t = k0 * (d - dperm)
          dtdd = k0
          sec = t / d                  ! d > dperm > 0 here
        else
          t = 0.0_dp
          dtdd = 0.0_dp
          sec = 0.0_dp
        end if
        w_stored = 0.5_dp * t**2 / k0
        w_diss = ldf_potential(props%phi, props%delta, dmax_old) - 0.5_dp * tm**2 / k0
      end if
    end if

    tvec = sec * dvec
    mmat = 0.0_dp
    do i = 1, 3
      mmat(i, i) = sec
    end do
    if (d > 0.0_dp) then
      m = dvec / d
      mmat = mmat + (dtdd - sec) * spread(m, 2, 3) * spread(m, 1, 3)
    end if
  end subroutine ldf_traction

  !> Contact penalty, Eqs. 19 and 22: for Delta_c = Delta_vec . n < 0, T_c = -k_c (Delta_c/delta)^2 along n.
  !> Returns T_c, dT_c/dDelta_c, the tangent w.r.t. the opening at fixed n (Eq. 29) and the penalty energy
  !> k_c |Delta_c|^3 / (3 delta^2). All zero when Delta_c >= 0.
  pure subroutine contact_traction(kc, delta, dc, n, tvec, mmat, tc, dtc, w_stored)
    real(dp), intent(in) :: kc          !< contact stiffness k_c
    real(dp), intent(in) :: delta       !< characteristic opening
    real(dp), intent(in) :: dc          !< normal opening Delta_c, Eq. 19
    real(dp), intent(in) :: n(3)        !< unit normal of the mid-surface, Eq. 18
    real(dp), intent(out) :: tvec(3)    !< T_c n, Eq. 22
    real(dp), intent(out) :: mmat(3,3)  !< dT_c/dDelta_c n n^T, Eq. 29
    real(dp), intent(out) :: tc         !< T_c
    real(dp), intent(out) :: dtc        !< dT_c/dDelta_c
    real(dp), intent(out) :: w_stored   !< penalty energy per unit initial area
    if (dc < 0.0_dp) then
      tc = -kc * (dc / delta)**2
      dtc = -2.0_dp * kc * dc / delta**2
      w_stored = kc * abs(dc)**3 / (3.0_dp * delta**2)
    else
      tc = 0.0_dp
      dtc = 0.0_dp
      w_stored = 0.0_dp
    end if
    tvec = tc * n
    mmat = dtc * spread(n, 2, 3) * spread(n, 1, 3)
  end subroutine contact_traction

  !> Classical small-displacement law, Eqs. 1-2 (exponential law of Xu and Needleman), in the local basis with normal n:
  !> Delta_n = Delta_vec . n, tangential part Delta_t_vec = Delta_vec - Delta_n n, Delta_t = |Delta_t_vec|;
  !> T = T_n n + T_t e_t with T_t e_t = 2 (phi_t/delta_t^2) (1 + Delta_n/delta) exp(-Delta_n/delta) exp(-Delta_t^2/delta_t^2) Delta_t_vec
  !> (Eq. 1, written without dividing by Delta_t). Energy: the Xu-Needleman potential with q = 1,
  !> phi [1 - (1 + Delta_n/delta) exp(-Delta_n/delta) exp(-Delta_t^2/delta_t^2)], exact when phi_t = phi.
  pure subroutine classical_traction(props, dvec, n, tvec, dn, dt, w_stored)
    type(cohesive_props), intent(in) :: props  !< phi, delta (normal) and phi_t, delta_t (tangential)
    real(dp), intent(in) :: dvec(3)            !< opening vector
    real(dp), intent(in) :: n(3)               !< unit normal of the local basis
    real(dp), intent(out) :: tvec(3)           !< traction vector
    real(dp), intent(out) :: dn                !< normal opening Delta_n
    real(dp), intent(out) :: dt                !< tangential opening magnitude Delta_t
    real(dp), intent(out) :: w_stored          !< potential (see above)
    real(dp) :: dtv(3), xn, e
    dn = dot_product(dvec, n)
    dtv = dvec - dn * n
    dt = norm2(dtv)
    xn = dn / props%delta
    e = exp(-xn) * exp(-(dt / props%delta_t)**2)
    tvec = (props%phi / props%delta) * xn * e * n &                                   ! Eq. 2
         + 2.0_dp * (props%phi_t / props%delta_t**2) * (1.0_dp + xn) * e * dtv         ! Eq. 1
    w_stored = props%phi * (1.0_dp - (1.0_dp + xn) * e)
  end subroutine classical_traction

end module cohesive_law
