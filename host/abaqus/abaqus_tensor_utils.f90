!> Abaqus/Standard tensor utility routines for user code: SINV, SPRINC, SPRIND, ROTSIG.
!>
!> Semantics as in the Abaqus User Subroutines Reference Guide, "Obtaining stress invariants, principal
!> stress/strain values and directions, and rotating tensors" (v6.5 usb 26.2.9 and the 3DEXPERIENCE page
!> simasub-c-tensor, read through the search tool):
!>  - SINV(STRESS,SINV1,SINV2,NDI,NSHR): SINV1 = trace(sigma)/3 (so it is the MEAN stress, not the trace),
!>    SINV2 = sqrt(3/2 S:S), S = sigma - SINV1 I (the Mises stress).
!>  - SPRINC(S,PS,LSTR,NDI,NSHR): PS(1:3) the three principal values, "in an unsorted order"; LSTR = 1 for a
!>    stress, 2 for a strain tensor (whose shear components are engineering shears, halved before use).
!>  - SPRIND(S,PS,AN,LSTR,NDI,NSHR): as SPRINC plus AN(K1,I), I = 1..3, the direction cosines of the principal
!>    direction of PS(K1): the ROWS of AN are the unit principal directions.
!>  - ROTSIG(S,R,SPRIME,LSTR,NDI,NSHR): SPRIME = R S R^T with R the rotation matrix (e.g. DROT of a UMAT),
!>    LSTR as above (engineering shears halved on the way in, doubled on the way out). Open hosts' imitations of
!>    ROTSIG (found with the search tool) all use R S R^T; some of them use LSTR = 0 for strains, so every
!>    LSTR other than 1 is treated as a strain here.
!> Component order (Abaqus conventions): the NDI direct components 11, 22, 33 first, then the NSHR shear
!> components 12, 13, 23 (3D: NDI = 3, NSHR = 3; plane strain and axisymmetry: 3, 1; plane stress: 2, 1).
!> Components not stored are zero (e.g. sigma_33 in plane stress).
!>
!> The module holds the pure helpers; the Abaqus entry points are external subroutines after it, callable from
!> fixed-form user code with implicit REAL*8 typing (ABA_PARAM.INC).
module abaqus_tensor_utils
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: voigt_to_tensor, tensor_to_voigt, symmetric_eigen

contains

  !> Full 3x3 symmetric tensor from Abaqus component storage; shear components multiplied by shear_factor
  !> (1 for stresses, 1/2 for engineering strains).
  pure function voigt_to_tensor(s, ndi, nshr, shear_factor) result(t)
    integer, intent(in) :: ndi                 !< number of direct components (1..3)
    integer, intent(in) :: nshr                !< number of shear components (0..3)
    real(dp), intent(in) :: s(ndi + nshr)      !< components: direct, then 12, 13, 23
    real(dp), intent(in) :: shear_factor       !< tensor shear = shear_factor * stored shear
    real(dp) :: t(3, 3)
    integer, parameter :: si(3) = [1, 1, 2], sj(3) = [2, 3, 3]
    integer :: k

    t = 0.0_dp
    do k = 1, min(ndi, 3)
      t(k, k) = s(k)
    end do
    do k = 1, min(nshr, 3)
      t(si(k), sj(k)) = shear_factor * s(ndi + k)
      t(sj(k), si(k)) = t(si(k), sj(k))
    end do
  end function voigt_to_tensor

  !> Abaqus component storage of a symmetric tensor; shears divided by shear_factor.
  pure function tensor_to_voigt(t, ndi, nshr, shear_factor) result(s)
    real(dp), intent(in) :: t(3, 3)            !< symmetric tensor
    integer, intent(in) :: ndi                 !< number of direct components
    integer, intent(in) :: nshr                !< number of shear components
    real(dp), intent(in) :: shear_factor       !< as in voigt_to_tensor
    real(dp) :: s(ndi + nshr)
    integer, parameter :: si(3) = [1, 1, 2], sj(3) = [2, 3, 3]
    integer :: k

    do k = 1, min(ndi, 3)
      s(k) = t(k, k)
    end do
    do k = 1, min(nshr, 3)
      s(ndi + k) = 0.5_dp * (t(si(k), sj(k)) + t(sj(k), si(k))) / shear_factor
    end do
  end function tensor_to_voigt

  !> Eigenvalues w and orthonormal eigenvectors (columns of v) of a symmetric 3x3 matrix by cyclic Jacobi
  !> rotations (Golub & Van Loan, Matrix Computations, sec. 8.5): unconditionally convergent, accurate for
  !> repeated eigenvalues, no library needed.
  pure subroutine symmetric_eigen(a, w, v)
    real(dp), intent(in) :: a(3, 3)            !< symmetric matrix
    real(dp), intent(out) :: w(3)              !< eigenvalues (unsorted: the diagonal after convergence)
    real(dp), intent(out) :: v(3, 3)           !< eigenvectors in columns, v(:, k) for w(k)
    real(dp) :: b(3, 3), off, scale, theta, t, c, s, bpq
    real(dp) :: row_p(3), row_q(3)
    integer :: sweep, p, q, k
    integer, parameter :: ip(3) = [1, 1, 2], iq(3) = [2, 3, 3]

    b = 0.5_dp * (a + transpose(a))
    v = 0.0_dp
    do k = 1, 3
      v(k, k) = 1.0_dp
    end do
    scale = sqrt(sum(b**2))
    do sweep = 1, 50
      off = b(1, 2)**2 + b(1, 3)**2 + b(2, 3)**2
      if (off <= (epsilon(1.0_dp) * scale)**2 .or. scale == 0.0_dp) exit
      do k = 1, 3
        p = ip(k)
        q = iq(k)
        bpq = b(p, q)
        if (bpq == 0.0_dp) cycle
        ! Rotation annihilating b(p, q): t = tan(phi) is the smaller root of t^2 + 2 theta t - 1 = 0.
        theta = (b(q, q) - b(p, p)) / (2.0_dp * bpq)
        t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta**2 + 1.0_dp))
        c = 1.0_dp / sqrt(t**2 + 1.0_dp)
        s = t * c
        ! B <- J^T B J with J the rotation in the (p, q) plane.
        row_p = b(p, :)
        row_q = b(q, :)
        b(p, :) = c * row_p - s * row_q
        b(q, :) = s * row_p + c * row_q
        row_p = b(:, p)
        row_q = b(:, q)
        b(:, p) = c * row_p - s * row_q
        b(:, q) = s * row_p + c * row_q
        b(p, q) = 0.0_dp
        b(q, p) = 0.0_dp
        row_p = v(:, p)
        row_q = v(:, q)
        v(:, p) = c * row_p - s * row_q
        v(:, q) = s * row_p + c * row_q
      end do
    end do
    do k = 1, 3
      w(k) = b(k, k)
    end do
  end subroutine symmetric_eigen

end module abaqus_tensor_utils

!> SINV: SINV1 = trace(sigma)/3, SINV2 = Mises stress sqrt(3/2 S:S) (Abaqus utility routine).
subroutine sinv(stress, sinv1, sinv2, ndi, nshr)
  use ldfcz_kinds, only: dp
  use abaqus_tensor_utils, only: voigt_to_tensor
  implicit none
  integer, intent(in) :: ndi                   !< number of direct components
  integer, intent(in) :: nshr                  !< number of shear components
  real(dp), intent(in) :: stress(ndi + nshr)   !< stress components
  real(dp), intent(out) :: sinv1               !< first invariant: trace/3
  real(dp), intent(out) :: sinv2               !< second invariant: Mises stress
  real(dp) :: t(3, 3)
  integer :: k

  t = voigt_to_tensor(stress, ndi, nshr, 1.0_dp)
  sinv1 = (t(1, 1) + t(2, 2) + t(3, 3)) / 3.0_dp
  do k = 1, 3
    t(k, k) = t(k, k) - sinv1
  end do
  sinv2 = sqrt(1.5_dp * sum(t**2))
end subroutine sinv

!> SPRINC: the three principal values PS (unsorted) of a stress (LSTR = 1) or strain (LSTR = 2) tensor.
subroutine sprinc(s, ps, lstr, ndi, nshr)
  use ldfcz_kinds, only: dp
  use abaqus_tensor_utils, only: voigt_to_tensor, symmetric_eigen
  implicit none
  integer, intent(in) :: ndi                   !< number of direct components
  integer, intent(in) :: nshr                  !< number of shear components
  real(dp), intent(in) :: s(ndi + nshr)        !< tensor components
  real(dp), intent(out) :: ps(3)               !< principal values
  integer, intent(in) :: lstr                  !< 1 stress, 2 strain (engineering shears)
  real(dp) :: t(3, 3), v(3, 3)

  t = voigt_to_tensor(s, ndi, nshr, merge(1.0_dp, 0.5_dp, lstr == 1))
  call symmetric_eigen(t, ps, v)
end subroutine sprinc

!> SPRIND: principal values PS and directions AN (row K1 = unit direction of PS(K1)).
subroutine sprind(s, ps, an, lstr, ndi, nshr)
  use ldfcz_kinds, only: dp
  use abaqus_tensor_utils, only: voigt_to_tensor, symmetric_eigen
  implicit none
  integer, intent(in) :: ndi                   !< number of direct components
  integer, intent(in) :: nshr                  !< number of shear components
  real(dp), intent(in) :: s(ndi + nshr)        !< tensor components
  real(dp), intent(out) :: ps(3)               !< principal values
  real(dp), intent(out) :: an(3, 3)            !< an(k, :) direction cosines of principal direction k
  integer, intent(in) :: lstr                  !< 1 stress, 2 strain (engineering shears)
  real(dp) :: t(3, 3), v(3, 3)

  t = voigt_to_tensor(s, ndi, nshr, merge(1.0_dp, 0.5_dp, lstr == 1))
  call symmetric_eigen(t, ps, v)
  an = transpose(v)
end subroutine sprind

!> ROTSIG: SPRIME = R S R^T for a stress (LSTR = 1) or strain (LSTR = 2, engineering shears) tensor.
subroutine rotsig(s, r, sprime, lstr, ndi, nshr)
  use ldfcz_kinds, only: dp
  use abaqus_tensor_utils, only: voigt_to_tensor, tensor_to_voigt
  implicit none
  integer, intent(in) :: ndi                   !< number of direct components
  integer, intent(in) :: nshr                  !< number of shear components
  real(dp), intent(in) :: s(ndi + nshr)        !< tensor components
  real(dp), intent(in) :: r(3, 3)              !< rotation matrix
  real(dp), intent(out) :: sprime(ndi + nshr)  !< rotated components
  integer, intent(in) :: lstr                  !< 1 stress, 2 strain (engineering shears)
  real(dp) :: f, t(3, 3), tr(3, 3)

  f = merge(1.0_dp, 0.5_dp, lstr == 1)
  ! R T R^T in steps (nested MATMULs of function results: gfortran 12 warns about its own temporaries)
  t = voigt_to_tensor(s, ndi, nshr, f)
  tr = matmul(t, transpose(r))
  sprime = tensor_to_voigt(matmul(r, tr), ndi, nshr, f)
end subroutine rotsig
