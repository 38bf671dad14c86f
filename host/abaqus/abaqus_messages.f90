!> Host side of the Abaqus messaging utilities: the job identity and the "stop requested" flag.
!>
!> In Abaqus, XIT ends the analysis. ldfcz's host never stops from inside an element call: XIT and
!> STDB_ABQERR(LOP = -3) record the request here and return; the host checks abaqus_stop_requested() after each
!> element loop and ends the run cleanly (message, exit status 2, the converged increments' output kept).
!> The ldfcz adapters return right after XIT; a third-party routine that relies on XIT never returning runs on
!> for the rest of that element call, whose results the host then discards.
module abaqus_host_state
  implicit none
  private
  public :: abaqus_set_job, abaqus_job_name, abaqus_output_dir
  public :: abaqus_request_stop, abaqus_stop_requested, abaqus_clear_stop, abaqus_stop_message

  character(len=:), allocatable :: job_name      !< job name (the deck's base name)
  character(len=:), allocatable :: output_dir    !< directory of the job's output files
  logical :: stop_flag = .false.                 !< a user routine asked to end the analysis
  character(len=1024) :: stop_text = ''          !< the message that came with the first request

contains

  !> Set the job name and output directory that GETJOBNAME and GETOUTDIR report.
  subroutine abaqus_set_job(name, outdir)
    character(len=*), intent(in) :: name    !< job name
    character(len=*), intent(in) :: outdir  !< output directory
    job_name = trim(name)
    output_dir = trim(outdir)
  end subroutine abaqus_set_job

  !> The job name ('ldfcz' before abaqus_set_job).
  function abaqus_job_name() result(name)
    character(len=:), allocatable :: name
    if (allocated(job_name)) then
      name = job_name
    else
      name = 'ldfcz'
    end if
  end function abaqus_job_name

  !> The output directory ('.' before abaqus_set_job).
  function abaqus_output_dir() result(dir)
    character(len=:), allocatable :: dir
    if (allocated(output_dir)) then
      dir = output_dir
    else
      dir = '.'
    end if
  end function abaqus_output_dir

  !> Record a request to end the analysis; the first message is kept.
  subroutine abaqus_request_stop(text)
    character(len=*), intent(in) :: text  !< why (may be empty)
    !$omp critical (abaqus_host_state_lock)
    if (.not. stop_flag) then
      stop_text = text
    else if (len_trim(stop_text) == 0) then
      stop_text = text
    end if
    stop_flag = .true.
    !$omp end critical (abaqus_host_state_lock)
  end subroutine abaqus_request_stop

  !> True once a user routine called XIT or STDB_ABQERR with LOP = -3.
  logical function abaqus_stop_requested()
    !$omp critical (abaqus_host_state_lock)
    abaqus_stop_requested = stop_flag
    !$omp end critical (abaqus_host_state_lock)
  end function abaqus_stop_requested

  !> The message recorded with the stop request.
  function abaqus_stop_message() result(text)
    character(len=:), allocatable :: text
    text = trim(stop_text)
  end function abaqus_stop_message

  !> Forget a stop request (used by tests and by drivers that call routines more than once).
  subroutine abaqus_clear_stop()
    !$omp critical (abaqus_host_state_lock)
    stop_flag = .false.
    stop_text = ''
    !$omp end critical (abaqus_host_state_lock)
  end subroutine abaqus_clear_stop
end module abaqus_host_state

!> Abaqus XIT: end the analysis. Here: record the request; the host ends the run after the element loop.
subroutine xit()
  use abaqus_host_state, only: abaqus_request_stop
  implicit none
  call abaqus_request_stop('')
end subroutine xit

!> Abaqus STDB_ABQERR(LOP, STRING, INTV, REALV, CHARV): print a message, substituting %I, %R and %S in order
!> from INTV, REALV and CHARV. LOP = 1 information, -1 warning, -2 error (analysis goes on), -3 error and stop.
subroutine stdb_abqerr(lop, string, intv, realv, charv)
  use, intrinsic :: iso_fortran_env, only: error_unit
  use abaqus_host_state, only: abaqus_request_stop
  implicit none
  integer, intent(in) :: lop                 !< message level
  character(len=*), intent(in) :: string     !< text with %I, %R, %S placeholders
  integer, intent(in) :: intv(*)             !< integers for %I
  double precision, intent(in) :: realv(*)   !< reals for %R
  character(len=8), intent(in) :: charv(*)   !< 8-character strings for %S
  character(len=2048) :: text
  character(len=32) :: item
  integer :: i, n, ni, nr, ns
  text = ''
  n = 0
  ni = 0
  nr = 0
  ns = 0
  i = 1
  do while (i <= len_trim(string))
    if (string(i:i) == '%' .and. i < len_trim(string)) then
      select case (string(i+1:i+1))
      case ('I', 'i')
        ni = ni + 1
        write (item, '(i0)') intv(ni)
      case ('R', 'r')
        nr = nr + 1
        write (item, '(es14.6)') realv(nr)
      case ('S', 's')
        ns = ns + 1
        item = charv(ns)
      case default
        item = string(i:i+1)
      end select
      text = text(1:n) // trim(adjustl(item))
      n = len_trim(text)
      i = i + 2
    else
      n = n + 1
      if (n <= len(text)) text(n:n) = string(i:i)
      i = i + 1
    end if
  end do
  select case (lop)
  case (1)
    write (error_unit, '(a)') '***NOTE: ' // trim(text)
  case (-1)
    write (error_unit, '(a)') '***WARNING: ' // trim(text)
  case (-2)
    write (error_unit, '(a)') '***ERROR: ' // trim(text)
  case default
    write (error_unit, '(a)') '***ERROR: ' // trim(text)
    call abaqus_request_stop(trim(text))
  end select
end subroutine stdb_abqerr
