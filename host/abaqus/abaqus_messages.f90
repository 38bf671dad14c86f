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
  public :: abaqus_set_job, abaqus_job_name, abaqus_output_dir, abaqus_set_processes, abaqus_processes
  public :: abaqus_request_stop, abaqus_stop_requested, abaqus_clear_stop, abaqus_stop_message
  public :: abaqus_message_is_new, abaqus_flush_repeats
  public :: abaqus_set_caller, abaqus_stop_element

  character(len=:), allocatable :: job_name      !< job name (the deck's base name)
  character(len=:), allocatable :: output_dir    !< directory of the job's output files
  integer :: process_rank = 0                    !< MPI rank of this process (GETRANK)
  integer :: process_count = 1                   !< processes of the analysis (GETNUMCPUS)
  integer :: process_comm = 0                    !< MPI communicator (GETCOMMUNICATOR; 0 without MPI)
  logical :: stop_flag = .false.                 !< a user routine asked to end the analysis
  character(len=:), allocatable :: stop_text     !< the message that came with the first request
  character(len=:), allocatable :: last_message  !< the last STDB_ABQERR message printed, numbers masked
  integer :: message_repeats = 0                 !< times it came again since (not printed)
  integer :: caller = 0                          !< element whose routine this thread is calling (0: none)
  !$omp threadprivate(caller)
  integer :: stop_elem = 0                       !< the lowest element that asked to stop (0: none known)

contains

  !> Set the job name and output directory that GETJOBNAME and GETOUTDIR report.
  subroutine abaqus_set_job(name, outdir)
    character(len=*), intent(in) :: name    !< job name
    character(len=*), intent(in) :: outdir  !< output directory
    job_name = trim(name)
    output_dir = trim(outdir)
  end subroutine abaqus_set_job

  !> The job name ('ldfcz' before abaqus_set_job).
  !> The processes of the analysis, as GETRANK, GETNUMCPUS and GETCOMMUNICATOR report them.
  subroutine abaqus_set_processes(rank, count, comm)
    integer, intent(in) :: rank   !< this process
    integer, intent(in) :: count  !< processes of the run
    integer, intent(in) :: comm   !< MPI communicator (0 without MPI)
    process_rank = rank
    process_count = count
    process_comm = comm
  end subroutine abaqus_set_processes

  !> Rank, count and communicator set by abaqus_set_processes (0, 1, 0 by default).
  subroutine abaqus_processes(rank, count, comm)
    integer, intent(out) :: rank, count, comm  !< as set
    rank = process_rank
    count = process_count
    comm = process_comm
  end subroutine abaqus_processes

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

  !> Whether a user routine's message should be printed: a text that differs from the last one only in its numbers
  !> (element labels, values) is only counted (element loops call a routine on every element, and a routine that
  !> complains about its properties does so each time); when another text comes, the count of the repeats is
  !> printed first. Safe to call from several threads.
  logical function abaqus_message_is_new(text, unit) result(is_new)
    character(len=*), intent(in) :: text  !< the message as it would be printed
    integer, intent(in) :: unit           !< where messages go
    character(len=:), allocatable :: key
    integer :: k
    key = trim(text)
    do k = 1, len(key)
      if (index('0123456789', key(k:k)) > 0) key(k:k) = '#'
    end do
    !$omp critical (abaqus_message_log)
    if (.not. allocated(last_message)) last_message = ''
    if (key == last_message) then
      message_repeats = message_repeats + 1
      is_new = .false.
    else
      if (message_repeats > 0) write (unit, '(a,i0,a)') '***NOTE: the message above was repeated ', &
        message_repeats, ' more times (other elements or values)'
      last_message = key
      message_repeats = 0
      is_new = .true.
    end if
    !$omp end critical (abaqus_message_log)
  end function abaqus_message_is_new

  !> Print the count of repeats of the last message, if any (at the end of a run).
  subroutine abaqus_flush_repeats(unit)
    integer, intent(in) :: unit  !< where messages go
    if (message_repeats > 0) write (unit, '(a,i0,a)') '***NOTE: the message above was repeated ', &
      message_repeats, ' more times (other elements or values)'
    message_repeats = 0
  end subroutine abaqus_flush_repeats

  !> The host is about to call a user routine for element ie (0: no element) on this thread: a stop request made
  !> during the call is recorded with the element (abaqus_stop_element).
  subroutine abaqus_set_caller(ie)
    integer, intent(in) :: ie  !< element index of the host (0: none)
    caller = ie
  end subroutine abaqus_set_caller

  !> The element whose routine asked to stop (the lowest index when several did; 0: not known).
  integer function abaqus_stop_element() result(ie)
    !$omp critical (abaqus_host_state_lock)
    ie = stop_elem
    !$omp end critical (abaqus_host_state_lock)
  end function abaqus_stop_element

  !> Record a request to end the analysis with the element of the call it comes from: the message kept is that of
  !> the lowest element that asked (so it does not depend on the thread schedule), else the first one.
  subroutine abaqus_request_stop(text)
    character(len=*), intent(in) :: text  !< why (may be empty)
    !$omp critical (abaqus_host_state_lock)
    if (.not. allocated(stop_text)) stop_text = ''
    if (.not. stop_flag) then
      stop_text = text
      stop_elem = caller
    else if (caller > 0 .and. (stop_elem == 0 .or. caller < stop_elem)) then
      stop_text = text
      stop_elem = caller
    else if (len_trim(stop_text) == 0 .and. caller == stop_elem) then
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
    text = ''
    if (allocated(stop_text)) text = trim(stop_text)
  end function abaqus_stop_message

  !> Forget a stop request (used by tests and by drivers that call routines more than once).
  subroutine abaqus_clear_stop()
    !$omp critical (abaqus_host_state_lock)
    stop_flag = .false.
    stop_text = ''
    stop_elem = 0
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
  use abaqus_host_state, only: abaqus_request_stop, abaqus_message_is_new
  implicit none
  integer, intent(in) :: lop                 !< message level
  character(len=*), intent(in) :: string     !< text with %I, %R, %S placeholders
  integer, intent(in) :: intv(*)             !< integers for %I
  double precision, intent(in) :: realv(*)   !< reals for %R
  character(len=8), intent(in) :: charv(*)   !< 8-character strings for %S
  character(len=:), allocatable :: text, body
  character(len=32) :: item
  integer :: i, ni, nr, ns
  body = ''
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
      body = trim(body // trim(adjustl(item)))
      i = i + 2
    else
      body = body // string(i:i)
      i = i + 1
    end if
  end do
  ! the whole message, however long: the level's prefix and the text after substitution
  select case (lop)
  case (1)
    text = '***NOTE: ' // body
  case (-1)
    text = '***WARNING: ' // body
  case default
    text = '***ERROR: ' // body
  end select
  if (abaqus_message_is_new(text, error_unit)) write (error_unit, '(a)') text
  if (lop == -3) call abaqus_request_stop(body)
end subroutine stdb_abqerr
