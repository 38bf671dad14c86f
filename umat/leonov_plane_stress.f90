!> Plane-stress branch of the compressible Leonov model (paper section 6, Eqs. 31-42) for Abaqus' plane-stress
!> elements (NDI = 2, NSHR = 1, NTENS = 3): the 3D core (module leonov) unchanged, driven with the deformation
!> gradient F = [F_2D 0; 0 lambda_3] whose thickness stretch lambda_3 is found by a local Newton iteration on
!> sigma_33(lambda_3) = 0 (the plane-stress condition; sigma_13 = sigma_23 = 0 by symmetry of this F and of the
!> isotropic model). The tangent returned is the in-plane block condensed with d sigma_33 = 0.
!>
!> Newton step: a perturbation d(ln lambda_3) is the Miehe perturbation dF = d(ln lambda_3) e3 (x) e3 F without
!> spin, so with the core's tangent c = (1/J) d(tau)/d(eps) (Jaumann rate of Kirchhoff stress over J, Voigt
!> 11,22,33,12,13,23) and tau = J sigma, dJ/J = d(ln lambda_3):
!>     d sigma_33 / d(ln lambda_3) = c_33 - sigma_33   (> 0 for every admissible state of the model)
!> Condensation: at sigma_33 = 0, d tau_33 = J c_3b d eps_b = 0 gives d eps_33 = -c_3b d eps_b / c_33 and
!>     c_ps(a, b) = c_ab - c_a3 c_3b / c_33,   a, b in (11, 22, 12).
module leonov_plane_stress
  use ldfcz_finite, only: is_finite
  use ldfcz_kinds, only: dp
  use leonov_parameters, only: leonov_props
  use leonov, only: leonov_state, leonov_update, leonov_ok, leonov_step_too_large, leonov_no_convergence, &
                    leonov_bad_input, leonov_elastic_tangent
  implicit none
  private
  public :: leonov_plane_stress_update, leonov_plane_stress_tangent

  integer, parameter :: max_iter = 30
  !> |sigma_33| accepted: 1e-12 of the larger of the in-plane stress and 1e-6 E (round-off of the 3D core's stress
  !> is ~1e-15 relative, so the tolerance is reached in 2-4 quadratic steps)
  real(dp), parameter :: tol_rel = 1.0e-12_dp
  real(dp), parameter :: max_step = 0.5_dp   !< largest change of ln lambda_3 per Newton step
  integer, parameter :: ip(3) = [1, 2, 4]    !< in-plane components in the 6-vector order (11, 22, 12)

contains

  !> One increment in plane stress. f0, f1: deformation gradients at t_n and t_n+1 of which only the in-plane
  !> block (1:2, 1:2) is used; ln_l3_old: converged ln(lambda_3) at t_n. Out: the 3D state, the Cauchy stress
  !> (sigma_33 = 0 to tol_rel), ln_l3 at t_n+1, the condensed 3x3 tangent (11, 22, 12; engineering shear) and the
  !> 3D deformation gradient used (for the energies). stat as leonov_update's; on failure new = old, sigma = 0,
  !> ln_l3 = ln_l3_old, the condensed elastic tangent and step_factor 0.25.
  pure subroutine leonov_plane_stress_update(p, f0, f1, ln_l3_old, dt, old, new, sigma, ln_l3, stat, step_factor, &
                                             ddsdde, f0_3d, f1_3d)
    type(leonov_props), intent(in) :: p
    real(dp), intent(in) :: f0(3, 3), f1(3, 3), ln_l3_old, dt
    type(leonov_state), intent(in) :: old
    type(leonov_state), intent(out) :: new
    real(dp), intent(out) :: sigma(3, 3), ln_l3, step_factor, ddsdde(3, 3), f0_3d(3, 3), f1_3d(3, 3)
    integer, intent(out) :: stat
    real(dp) :: c6(6, 6), j0, j1, x, dx, denom, scale, nu_ratio
    integer :: it, st

    f0_3d = 0.0_dp
    f1_3d = 0.0_dp
    f0_3d(1:2, 1:2) = f0(1:2, 1:2)
    f1_3d(1:2, 1:2) = f1(1:2, 1:2)
    j0 = f0(1, 1) * f0(2, 2) - f0(1, 2) * f0(2, 1)
    j1 = f1(1, 1) * f1(2, 2) - f1(1, 2) * f1(2, 1)
    call fail_state(p, old, ln_l3_old, leonov_bad_input, stat, new, sigma, ln_l3, step_factor, ddsdde)
    if (.not. (is_finite(ln_l3_old) .and. abs(ln_l3_old) < 10.0_dp .and. j0 > 0.0_dp .and. j1 > 0.0_dp &
               .and. is_finite(j0) .and. is_finite(j1))) return
    f0_3d(3, 3) = exp(ln_l3_old)
    ! start: the elastic thickness strain increment -nu/(1 - nu) times the in-plane log volume change
    nu_ratio = p%nu / (1.0_dp - p%nu)
    x = ln_l3_old - nu_ratio * log(j1 / j0)
    do it = 1, max_iter
      f1_3d(3, 3) = exp(x)
      call leonov_update(p, f0_3d, f1_3d, dt, old, new, sigma, stat, step_factor, c6)
      if (stat /= leonov_ok .and. stat /= leonov_step_too_large) then
        st = stat
        call fail_state(p, old, ln_l3_old, st, stat, new, sigma, ln_l3, step_factor, ddsdde)
        return
      end if
      scale = max(maxval(abs(sigma)), 1.0e-6_dp * p%e)
      if (abs(sigma(3, 3)) <= tol_rel * scale) then
        ln_l3 = x
        sigma(3, 3) = 0.0_dp
        ddsdde = leonov_plane_stress_tangent(c6)
        return
      end if
      denom = c6(3, 3) - sigma(3, 3)
      if (.not. (denom > 0.0_dp .and. is_finite(denom))) exit
      dx = -sigma(3, 3) / denom
      x = x + sign(min(abs(dx), max_step), dx)
    end do
    call fail_state(p, old, ln_l3_old, leonov_no_convergence, stat, new, sigma, ln_l3, step_factor, ddsdde)
  end subroutine leonov_plane_stress_update

  !> The failure outputs: old state kept, zero stress, condensed elastic tangent, cutback to a quarter.
  pure subroutine fail_state(p, old, ln_l3_old, code, stat, new, sigma, ln_l3, step_factor, ddsdde)
    type(leonov_props), intent(in) :: p
    type(leonov_state), intent(in) :: old
    real(dp), intent(in) :: ln_l3_old
    integer, intent(in) :: code
    integer, intent(out) :: stat
    type(leonov_state), intent(out) :: new
    real(dp), intent(out) :: sigma(3, 3), ln_l3, step_factor, ddsdde(3, 3)
    real(dp) :: c6(6, 6)
    stat = code
    new = old
    sigma = 0.0_dp
    ln_l3 = ln_l3_old
    step_factor = 0.25_dp
    ! (a temporary: flang-new-16 crashes on the nested call leonov_plane_stress_tangent(leonov_elastic_tangent(p)))
    c6 = leonov_elastic_tangent(p)
    ddsdde = leonov_plane_stress_tangent(c6)
  end subroutine fail_state

  !> Static condensation of a 6x6 tangent (11,22,33,12,13,23) to plane stress (11,22,12) with d sigma_33 = 0.
  !> c_33 > 0 for the Leonov tangent (it is kappa + 4/3 G at the virgin state and stays positive); a
  !> non-positive c_33 would mean a material without plane-stress stiffness: the in-plane block is returned as is.
  pure function leonov_plane_stress_tangent(c6) result(c)
    real(dp), intent(in) :: c6(6, 6)
    real(dp) :: c(3, 3)
    integer :: a, b
    do b = 1, 3
      do a = 1, 3
        c(a, b) = c6(ip(a), ip(b))
        if (c6(3, 3) > 0.0_dp) c(a, b) = c(a, b) - c6(ip(a), 3) * c6(3, ip(b)) / c6(3, 3)
      end do
    end do
  end function leonov_plane_stress_tangent

end module leonov_plane_stress
