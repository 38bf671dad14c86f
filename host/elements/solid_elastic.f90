!> Built-in *ELASTIC (isotropic) with Abaqus/Standard semantics.
!>
!> Under NLGEOM Abaqus integrates linear elasticity as a hypoelastic law in the co-rotational (Jaumann) frame:
!> the host has already rotated the stress by DROT (Hughes-Winget), then
!>     sigma_new = DROT sigma_old DROT^T + C : DSTRAN,        DDSDDE = C,
!> which is exactly what a linear-elastic UMAT does. Without NLGEOM it is ordinary small-strain elasticity.
!> Voigt order of docs/conventions.md (11,22,33,12,13,23 or 11,22,33,12), engineering shear strains.
module solid_elastic
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: elastic_isotropic_ddsdde, elastic_update, elastic_check

contains

  !> Isotropic elasticity matrix in Abaqus Voigt order (engineering shears): lambda, mu from E, nu. NDI = 2 is
  !> plane stress (Abaqus CPS elements: NDI = 2, NSHR = 1): E/(1 - nu^2) [1 nu; nu 1] and G, sigma33 = 0.
  pure subroutine elastic_isotropic_ddsdde(e, nu, ndi, nshr, ddsdde)
    real(dp), intent(in) :: e, nu            !< Young's modulus (MPa), Poisson's ratio
    integer, intent(in) :: ndi, nshr         !< direct and shear component counts
    real(dp), intent(out) :: ddsdde(:, :)    !< (ndi+nshr)^2 elasticity matrix
    real(dp) :: lam, mu
    integer :: i

    lam = e * nu / ((1 + nu) * (1 - 2 * nu))
    mu = e / (2 * (1 + nu))
    ddsdde = 0.0_dp
    if (ndi == 2) lam = 2 * mu * lam / (lam + 2 * mu)   ! plane stress: lambda* = 2 mu lambda / (lambda + 2 mu)
    ddsdde(1:ndi, 1:ndi) = lam
    do i = 1, ndi
      ddsdde(i, i) = lam + 2 * mu
    end do
    do i = ndi + 1, ndi + nshr
      ddsdde(i, i) = mu
    end do
  end subroutine elastic_isotropic_ddsdde

  !> Stress update: stress (already rotated by DROT) += C : dstran; sse += (sigma_old + sigma_new)/2 : dstran
  !> (trapezoidal elastic energy density, exact for linear elasticity without rotation).
  pure subroutine elastic_update(e, nu, ndi, nshr, stress, dstran, ddsdde, sse)
    real(dp), intent(in) :: e, nu            !< Young's modulus, Poisson's ratio
    integer, intent(in) :: ndi, nshr         !< direct and shear component counts
    real(dp), intent(inout) :: stress(:)     !< in: rotated start-of-increment Cauchy stress; out: end of increment
    real(dp), intent(in) :: dstran(:)        !< strain increment (engineering shears)
    real(dp), intent(out) :: ddsdde(:, :)    !< tangent C
    real(dp), intent(inout) :: sse           !< elastic energy density
    real(dp) :: s0(size(stress))

    call elastic_isotropic_ddsdde(e, nu, ndi, nshr, ddsdde)
    s0 = stress
    stress = stress + matmul(ddsdde, dstran)
    sse = sse + 0.5_dp * dot_product(s0 + stress, dstran)
  end subroutine elastic_update

  !> Validate the constants: E > 0 and -1 < nu < 0.5. stat = 0 when valid.
  pure subroutine elastic_check(e, nu, stat, errmsg)
    real(dp), intent(in) :: e, nu            !< Young's modulus, Poisson's ratio
    integer, intent(out) :: stat             !< 0 valid, 1 invalid
    character(len=*), intent(out) :: errmsg  !< reason when invalid
    stat = 0
    errmsg = ''
    if (.not. (e > 0.0_dp)) then
      stat = 1
      errmsg = '*ELASTIC: Young''s modulus must be > 0'
    else if (.not. (nu > -1.0_dp .and. nu < 0.5_dp)) then
      stat = 1
      errmsg = '*ELASTIC: Poisson''s ratio must lie in (-1, 0.5)'
    end if
  end subroutine elastic_check

end module solid_elastic
