!> Test doubles of the Abaqus utility routines XIT and STDB_ABQERR.
!> Abaqus terminates the analysis in XIT; a unit test must observe that a routine asked to stop, so these
!> stubs only record the request (and the last message) and return. The adapters return right after XIT.
module abaqus_test_record
  implicit none
  private
  public :: abaqus_record_reset, abaqus_xit_count, abaqus_last_message, record_xit, record_message

  integer :: xit_calls = 0                !< number of XIT calls since the last reset
  character(len=512) :: last_message = '' !< last message passed to STDB_ABQERR

contains

  !> Forget earlier XIT calls and messages.
  subroutine abaqus_record_reset()
    xit_calls = 0
    last_message = ''
  end subroutine abaqus_record_reset

  !> Number of XIT calls since the last reset.
  integer function abaqus_xit_count()
    abaqus_xit_count = xit_calls
  end function abaqus_xit_count

  !> The last message passed to STDB_ABQERR.
  function abaqus_last_message() result(msg)
    character(len=:), allocatable :: msg
    msg = trim(last_message)
  end function abaqus_last_message

  subroutine record_xit()
    xit_calls = xit_calls + 1
  end subroutine record_xit

  subroutine record_message(text)
    character(len=*), intent(in) :: text
    last_message = text
  end subroutine record_message
end module abaqus_test_record

!> Stub of the Abaqus XIT: records the stop request instead of terminating.
subroutine xit()
  use abaqus_test_record, only: record_xit
  implicit none
  call record_xit()
end subroutine xit

!> Stub of the Abaqus STDB_ABQERR(LOP, STRING, INTV, REALV, CHARV): records the message text.
subroutine stdb_abqerr(lop, string, intv, realv, charv)
  use abaqus_test_record, only: record_message
  implicit none
  integer, intent(in) :: lop                 !< 1 info, -1 warning, -2 error, -3 error and stop
  character(len=*), intent(in) :: string     !< message with %I, %R, %S placeholders
  integer, intent(in) :: intv(*)             !< integers substituted for %I
  double precision, intent(in) :: realv(*)   !< reals substituted for %R
  character(len=8), intent(in) :: charv(*)   !< strings substituted for %S
  if (.false.) print *, lop, intv(1), realv(1), charv(1)
  call record_message(string)
end subroutine stdb_abqerr
