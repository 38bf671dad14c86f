!> Scalar stress measures for output: von Mises stress and principal stresses of a Voigt stress vector
!> (Abaqus order 11,22,33,12[,13,23]; ntens = 4 for plane strain, where 13 = 23 = 0).
module stress_measures
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: mises_stress, principal_stresses

contains

  !> Von Mises equivalent stress sqrt(3/2 s:s), s the deviator.
  pure function mises_stress(s) result(q)
    real(dp), intent(in) :: s(:)  !< Voigt stress, size 4 or 6
    real(dp) :: q
    real(dp) :: t(3, 3)

    call voigt_tensor(s, t)
    q = sqrt(max(0.0_dp, 1.5_dp * sum(dev(t)**2)))
  end function mises_stress

  !> Principal stresses in descending order (closed-form eigenvalues of the symmetric 3x3 tensor,
  !> trigonometric solution of the characteristic cubic).
  pure subroutine principal_stresses(s, p)
    real(dp), intent(in) :: s(:)    !< Voigt stress, size 4 or 6
    real(dp), intent(out) :: p(3)   !< principal values, p(1) >= p(2) >= p(3)
    real(dp), parameter :: pi = 3.14159265358979323846264338327950288_dp
    real(dp) :: t(3, 3), d(3, 3), mean, j2, j3, r, phi

    call voigt_tensor(s, t)
    mean = (t(1, 1) + t(2, 2) + t(3, 3)) / 3
    d = dev(t)
    j2 = 0.5_dp * sum(d**2)
    if (j2 <= 1.0e-30_dp * max(1.0_dp, mean**2)) then
      p = mean
      return
    end if
    j3 = d(1, 1) * (d(2, 2) * d(3, 3) - d(2, 3) * d(3, 2)) - d(1, 2) * (d(2, 1) * d(3, 3) - d(2, 3) * d(3, 1)) &
       + d(1, 3) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1))
    r = sqrt(j2 / 3)
    ! cos(3 phi) = J3 / (2 r^3), clipped to [-1, 1] against round-off
    phi = acos(max(-1.0_dp, min(1.0_dp, j3 / (2 * r**3)))) / 3
    p(1) = mean + 2 * r * cos(phi)
    p(3) = mean + 2 * r * cos(phi + 2 * pi / 3)
    p(2) = 3 * mean - p(1) - p(3)
  end subroutine principal_stresses

  pure subroutine voigt_tensor(s, t)
    real(dp), intent(in) :: s(:)
    real(dp), intent(out) :: t(3, 3)
    t = 0.0_dp
    t(1, 1) = s(1)
    t(2, 2) = s(2)
    t(3, 3) = s(3)
    t(1, 2) = s(4)
    t(2, 1) = s(4)
    if (size(s) >= 6) then
      t(1, 3) = s(5)
      t(3, 1) = s(5)
      t(2, 3) = s(6)
      t(3, 2) = s(6)
    end if
  end subroutine voigt_tensor

  pure function dev(t) result(d)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: d(3, 3)
    integer :: i
    d = t
    do i = 1, 3
      d(i, i) = d(i, i) - (t(1, 1) + t(2, 2) + t(3, 3)) / 3
    end do
  end function dev

end module stress_measures
