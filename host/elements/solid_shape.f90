!> Shape functions and Gauss rules of the continuum elements, with Abaqus node and integration-point orderings.
!>
!> C3D8: nodes 1-4 on the face zeta = -1 counter-clockwise seen from +zeta, nodes 5-8 above them on zeta = +1;
!> 2x2x2 Gauss points numbered with xi fastest, then eta, then zeta (Abaqus order).
!> CPE4: nodes counter-clockwise (-1,-1), (1,-1), (1,1), (-1,1); 2x2 Gauss points, xi fastest.
module solid_shape
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: solid_shape_eval, solid_gauss_point, SHAPE_C3D8, SHAPE_CPE4

  integer, parameter :: SHAPE_C3D8 = 1  !< 8-node hexahedron
  integer, parameter :: SHAPE_CPE4 = 2  !< 4-node quadrilateral

  real(dp), parameter :: hex_nodes(3, 8) = reshape([ &
    -1.0_dp, -1.0_dp, -1.0_dp,   1.0_dp, -1.0_dp, -1.0_dp,   1.0_dp, 1.0_dp, -1.0_dp,   -1.0_dp, 1.0_dp, -1.0_dp, &
    -1.0_dp, -1.0_dp,  1.0_dp,   1.0_dp, -1.0_dp,  1.0_dp,   1.0_dp, 1.0_dp,  1.0_dp,   -1.0_dp, 1.0_dp,  1.0_dp], [3, 8])
  real(dp), parameter :: quad_nodes(2, 4) = reshape([ &
    -1.0_dp, -1.0_dp,   1.0_dp, -1.0_dp,   1.0_dp, 1.0_dp,   -1.0_dp, 1.0_dp], [2, 4])

contains

  !> Shape functions n(a) and their derivatives dndxi(a, k) = dN_a / dxi_k at the parent point xi.
  pure subroutine solid_shape_eval(shape, xi, n, dndxi)
    integer, intent(in) :: shape          !< SHAPE_C3D8 or SHAPE_CPE4
    real(dp), intent(in) :: xi(:)         !< parent coordinates (3 or 2)
    real(dp), intent(out) :: n(:)         !< shape functions (8 or 4)
    real(dp), intent(out) :: dndxi(:, :)  !< derivatives (8x3 or 4x2)
    integer :: a

    select case (shape)
    case (SHAPE_C3D8)
      do a = 1, 8
        n(a) = 0.125_dp * (1 + hex_nodes(1, a) * xi(1)) * (1 + hex_nodes(2, a) * xi(2)) * (1 + hex_nodes(3, a) * xi(3))
        dndxi(a, 1) = 0.125_dp * hex_nodes(1, a) * (1 + hex_nodes(2, a) * xi(2)) * (1 + hex_nodes(3, a) * xi(3))
        dndxi(a, 2) = 0.125_dp * hex_nodes(2, a) * (1 + hex_nodes(1, a) * xi(1)) * (1 + hex_nodes(3, a) * xi(3))
        dndxi(a, 3) = 0.125_dp * hex_nodes(3, a) * (1 + hex_nodes(1, a) * xi(1)) * (1 + hex_nodes(2, a) * xi(2))
      end do
    case default
      do a = 1, 4
        n(a) = 0.25_dp * (1 + quad_nodes(1, a) * xi(1)) * (1 + quad_nodes(2, a) * xi(2))
        dndxi(a, 1) = 0.25_dp * quad_nodes(1, a) * (1 + quad_nodes(2, a) * xi(2))
        dndxi(a, 2) = 0.25_dp * quad_nodes(2, a) * (1 + quad_nodes(1, a) * xi(1))
      end do
    end select
  end subroutine solid_shape_eval

  !> Parent coordinates xi and weight w of Gauss point ip (2 points per direction at +-1/sqrt(3), weights 1).
  pure subroutine solid_gauss_point(shape, ip, xi, w)
    integer, intent(in) :: shape   !< SHAPE_C3D8 or SHAPE_CPE4
    integer, intent(in) :: ip      !< integration point, Abaqus numbering
    real(dp), intent(out) :: xi(:) !< parent coordinates
    real(dp), intent(out) :: w     !< weight
    real(dp), parameter :: g = 0.577350269189625764509148780502_dp  ! 1/sqrt(3)
    integer :: k

    k = ip - 1
    xi(1) = merge(g, -g, mod(k, 2) == 1)
    xi(2) = merge(g, -g, mod(k / 2, 2) == 1)
    if (shape == SHAPE_C3D8) xi(3) = merge(g, -g, mod(k / 4, 2) == 1)
    w = 1.0_dp
  end subroutine solid_gauss_point

end module solid_shape
