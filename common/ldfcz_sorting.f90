!> Ascending insertion sorts of short lists (a matrix row's columns, a section's nodes, a step's time points): one
!> implementation for the host's libraries.
module ldfcz_sorting
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: sort_int, sort_real

contains

  !> Sort an integer list ascending in place (insertion sort: the lists are short).
  pure subroutine sort_int(a)
    integer, intent(inout) :: a(:)  !< list to sort ascending
    integer :: i, j, v
    do i = 2, size(a)
      v = a(i)
      j = i - 1
      do while (j >= 1)
        if (a(j) <= v) exit
        a(j + 1) = a(j)
        j = j - 1
      end do
      a(j + 1) = v
    end do
  end subroutine sort_int

  !> Sort a real list ascending in place (insertion sort: the lists are short).
  pure subroutine sort_real(a)
    real(dp), intent(inout) :: a(:)  !< list to sort ascending
    integer :: i, j
    real(dp) :: v
    do i = 2, size(a)
      v = a(i)
      j = i - 1
      do while (j >= 1)
        if (a(j) <= v) exit
        a(j + 1) = a(j)
        j = j - 1
      end do
      a(j + 1) = v
    end do
  end subroutine sort_real

end module ldfcz_sorting
