!> Small geometry helpers the unit suites share (tests/*.pf): rotations, the 3 x 3 identity and determinant, the
!> cross product.
module test_geometry
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: rotation, eye3, det3, cross3

contains

  !> Rotation by angle (rad) about axis (any length; normalised here), Rodrigues' formula
  !> R = I + sin(angle) W + (1 - cos(angle)) W^2, W the cross-product matrix of the unit axis.
  pure function rotation(axis, angle) result(r)
    real(dp), intent(in) :: axis(3)   !< rotation axis (not zero)
    real(dp), intent(in) :: angle     !< angle, rad
    real(dp) :: r(3, 3), e(3), w(3, 3)
    integer :: i
    e = axis / norm2(axis)
    w = reshape([0.0_dp, e(3), -e(2), -e(3), 0.0_dp, e(1), e(2), -e(1), 0.0_dp], [3, 3])
    r = sin(angle) * w + (1.0_dp - cos(angle)) * matmul(w, w)
    do i = 1, 3
      r(i, i) = r(i, i) + 1.0_dp
    end do
  end function rotation

  !> The 3 x 3 identity.
  pure function eye3() result(e)
    real(dp) :: e(3, 3)
    e = 0.0_dp
    e(1, 1) = 1.0_dp
    e(2, 2) = 1.0_dp
    e(3, 3) = 1.0_dp
  end function eye3

  !> Determinant of a 3 x 3 matrix (cofactors of the first row).
  pure real(dp) function det3(a)
    real(dp), intent(in) :: a(3, 3)   !< matrix
    det3 = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
         + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function det3

  !> Cross product p x q.
  pure function cross3(p, q) result(r)
    real(dp), intent(in) :: p(3), q(3)   !< vectors
    real(dp) :: r(3)
    r = [p(2) * q(3) - p(3) * q(2), p(3) * q(1) - p(1) * q(3), p(1) * q(2) - p(2) * q(1)]
  end function cross3

end module test_geometry
