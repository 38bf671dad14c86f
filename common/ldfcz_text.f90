!> ASCII case conversion of text (deck words, file names, command-line words), one implementation for the project.
module ldfcz_text
  implicit none
  private
  public :: lower_case, upper_case

contains

  !> s with its ASCII letters in lower case (same length).
  pure function lower_case(s) result(t)
    character(len=*), intent(in) :: s  !< text
    character(len=len(s)) :: t
    integer :: i
    t = s
    do i = 1, len(s)
      if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
    end do
  end function lower_case

  !> s with its ASCII letters in upper case (same length).
  pure function upper_case(s) result(t)
    character(len=*), intent(in) :: s  !< text
    character(len=len(s)) :: t
    integer :: i
    t = s
    do i = 1, len(s)
      if (s(i:i) >= 'a' .and. s(i:i) <= 'z') t(i:i) = achar(iachar(s(i:i)) - 32)
    end do
  end function upper_case

end module ldfcz_text
