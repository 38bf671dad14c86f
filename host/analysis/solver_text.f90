!> Numbers as text for the log and status lines of the static solver.
module solver_text
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: itoa, rtoa

contains

  !> Integer without padding.
  pure function itoa(i) result(s)
    integer, intent(in) :: i  !< the number
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

  !> Real in the es12.5 format, without padding.
  pure function rtoa(x) result(s)
    real(dp), intent(in) :: x  !< the number
    character(len=:), allocatable :: s
    character(len=24) :: b
    write (b, '(es12.5)') x
    s = trim(adjustl(b))
  end function rtoa

end module solver_text
