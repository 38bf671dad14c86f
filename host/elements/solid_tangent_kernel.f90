!> Tangent kernel of the C3D8 element (solid_element.f90): the contribution of one integration point to the
!> element matrix, K_(a i)(b k) += int [dN_a/dx_j A_ijkl dN_b/dx_l + dN_a/dx_j q_ij (dN_b/dx_k|centre - dN_b/dx_k)] dv.
!> In a file of its own so that it is compiled with -O3 (host/elements/CMakeLists.txt) and not inlined into the
!> large element routine, where gfortran 12 does not vectorise it: the node loop then runs on packed doubles
!> (no reassociation: -O3 does not imply -ffast-math).
module solid_tangent_kernel
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: k_point_c3d8

contains

  !> Tangent contribution of one C3D8 integration point: kl(i, a, k, b) += sum_j dN_a/dx_j t_ij with
  !> t_ij = [sum_l A_ijkl dN_b/dx_l + q_ij bc_bk] dv (fixed sizes, so the compiler unrolls and vectorises it).
  pure subroutine k_point_c3d8(a4, q, dndx, bc, bcr, dv, kl)
    real(dp), intent(in) :: a4(3, 3, 3, 3), q(3, 3), dndx(8, 3), bc(8, 3), dv
    !> row-side dilatation operator / m: K_(a i)(b k) += bcr_ai tr(t) (small-strain B-bar virtual strain; 0 under NLGEOM)
    real(dp), intent(in) :: bcr(8, 3)
    real(dp), intent(inout) :: kl(8, 3, 3, 8)    !< kl(a, i, k, b): node a fastest (contiguous 8-vectors)
    real(dp) :: t(3, 3), d1(8), d2(8), d3(8), t1, t2, t3, tr
    integer :: a, b, k, i
    d1 = dndx(1:8, 1)
    d2 = dndx(1:8, 2)
    d3 = dndx(1:8, 3)
    do b = 1, 8
      do k = 1, 3
        t = (q * bc(b, k) + a4(:, :, k, 1) * d1(b) + a4(:, :, k, 2) * d2(b) + a4(:, :, k, 3) * d3(b)) * dv
        tr = t(1, 1) + t(2, 2) + t(3, 3)
        do i = 1, 3
          t1 = t(i, 1)
          t2 = t(i, 2)
          t3 = t(i, 3)
          do a = 1, 8
            kl(a, i, k, b) = kl(a, i, k, b) + t1 * d1(a) + t2 * d2(a) + t3 * d3(a) + tr * bcr(a, i)
          end do
        end do
      end do
    end do
  end subroutine k_point_c3d8

end module solid_tangent_kernel
