!> Integer lists of the deck reader: append, grow, sort-unique, and integer-to-text for messages.
module deck_lists
  implicit none
  private
  public :: itoa, add_member, grow_int, unique

contains

  !> Integer as text without blanks (messages).
  pure function itoa(i) result(s)
    integer, intent(in) :: i               !< value
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

  !> Append v to a(1:n), doubling the capacity when full.
  pure subroutine add_member(a, n, v)
    integer, allocatable, intent(inout) :: a(:) !< list storage
    integer, intent(inout) :: n                 !< entries in use
    integer, intent(in) :: v                    !< value to append
    integer, allocatable :: t(:)
    if (.not. allocated(a)) allocate (a(0))
    if (n == size(a)) then
      allocate (t(max(16, 2 * n)))
      t(1:n) = a(1:n)
      call move_alloc(t, a)
    end if
    n = n + 1
    a(n) = v
  end subroutine add_member

  !> Resize a to nnew entries (default: twice its size), new entries zero.
  pure subroutine grow_int(a, nnew)
    integer, allocatable, intent(inout) :: a(:) !< array to resize
    integer, intent(in), optional :: nnew       !< new size
    integer, allocatable :: t(:)
    integer :: n, m
    n = size(a)
    m = 2 * n
    if (present(nnew)) m = nnew
    allocate (t(m))
    t = 0
    t(1:min(n, m)) = a(1:min(n, m))
    call move_alloc(t, a)
  end subroutine grow_int

  !> Sort (heap sort, O(n log n)) and remove duplicates (insertion order is not meaningful for sets).
  pure subroutine unique(a)
    integer, allocatable, intent(inout) :: a(:) !< list, sorted and without duplicates on return
    integer :: i, j, n, t
    n = size(a)
    do i = n / 2, 1, -1
      call sift_down(a, i, n)
    end do
    do i = n, 2, -1
      t = a(1)
      a(1) = a(i)
      a(i) = t
      call sift_down(a, 1, i - 1)
    end do
    j = 0
    do i = 1, n
      if (j > 0) then
        if (a(i) == a(j)) cycle
      end if
      j = j + 1
      a(j) = a(i)
    end do
    a = a(1:j)
  end subroutine unique

  !> Restore the max-heap property of a(start:last) below start.
  pure subroutine sift_down(a, start, last)
    integer, intent(inout) :: a(:)   !< heap
    integer, intent(in) :: start     !< root to sift
    integer, intent(in) :: last      !< last heap entry
    integer :: root, child, tmp
    root = start
    do while (2 * root <= last)
      child = 2 * root
      if (child < last) then
        if (a(child + 1) > a(child)) child = child + 1
      end if
      if (a(root) >= a(child)) return
      tmp = a(root)
      a(root) = a(child)
      a(child) = tmp
      root = child
    end do
  end subroutine sift_down

end module deck_lists
