! The helper of umat_fixed.f, in a second file (free form): isotropic elasticity matrix, Abaqus component order.
subroutine elastic_matrix(e, anu, ndi, ntens, d)
  implicit none
  double precision, intent(in) :: e, anu
  integer, intent(in) :: ndi, ntens
  double precision, intent(out) :: d(ntens, ntens)
  double precision :: alam, amu
  integer :: i
  alam = e * anu / ((1.0d0 + anu) * (1.0d0 - 2.0d0 * anu))
  amu = 0.5d0 * e / (1.0d0 + anu)
  d = 0.0d0
  do i = 1, ndi
    d(1:ndi, i) = alam
    d(i, i) = alam + 2.0d0 * amu
  end do
  do i = ndi + 1, ntens
    d(i, i) = amu
  end do
end subroutine elastic_matrix
