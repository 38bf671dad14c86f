!> Abaqus utility routines for an open host that runs Abaqus user subroutines but does not define these (EN234_FEA,
!> a test driver, your own code): the one-file drop-ins call XIT and STDB_ABQERR on bad input; the other routines are
!> the environment queries user code commonly calls. Interfaces as the Abaqus User Subroutines Guide documents them
!> ("Terminating an analysis", "Printing messages to the message or status file", "Obtaining Abaqus environment
!> information", "Obtaining parallel processes information"). Not for ldfcz or Abaqus, which define their own.
!>
!> Meaning here (an open host has no message file, no job and no process model of its own):
!> * XIT: writes a line to standard error and ends the program with ERROR STOP 1: an open host has no other way to
!>   stop the analysis that the routine asked to stop (this file is the one place where a routine stops the program).
!> * STDB_ABQERR(LOP, STRING, INTV, REALV, CHARV): writes STRING to standard error with %I, %R and %S replaced in order
!>   by INTV, REALV and CHARV; LOP = 1 information, -1 warning, -2 error, -3 error that ends the analysis (then XIT).
!> * GETJOBNAME, GETOUTDIR: the environment variables LDFCZ_JOB_NAME and LDFCZ_OUTDIR where set, otherwise "job" and
!>   the current directory ($PWD, or "." where that is not set); the length is that of the returned text.
!> * GETNUMCPUS = 1, GETRANK = 0, GETNUMTHREADS() = 1, GET_THREAD_ID() = 0: one process, one thread. A host that runs
!>   user routines in several threads or processes must provide these itself.

!> XIT: end the analysis (here: the program) with a message.
subroutine xit()
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  write (error_unit, '(a)') 'XIT: a user subroutine ended the analysis (ldfcz open-host utilities)'
  error stop 1
end subroutine xit

!> STDB_ABQERR: a message with %I, %R, %S replaced from INTV, REALV, CHARV; LOP = -3 then ends the analysis.
subroutine stdb_abqerr(lop, string, intv, realv, charv)
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  integer, intent(in) :: lop                 !< 1 information, -1 warning, -2 error, -3 error and end
  character(len=*), intent(in) :: string     !< message text with %I, %R, %S placeholders
  integer, intent(in) :: intv(*)             !< integers for the %I in order
  double precision, intent(in) :: realv(*)   !< reals for the %R in order
  character(len=8), intent(in) :: charv(*)   !< 8-character strings for the %S in order
  character(len=1024) :: text
  character(len=32) :: item
  integer :: i, k, n, ni, nr, ns
  interface
    subroutine xit()
    end subroutine xit
  end interface

  text = ''
  n = 0
  ni = 0
  nr = 0
  ns = 0
  i = 1
  do while (i <= len_trim(string))
    if (string(i:i) == '%' .and. i < len_trim(string)) then
      select case (string(i + 1:i + 1))
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
        item = string(i:i + 1)
      end select
      item = adjustl(item)
      k = min(len_trim(item), len(text) - n)
      if (k > 0) text(n + 1:n + k) = item(1:k)
      n = n + max(k, 0)
      i = i + 2
    else
      if (n < len(text)) then
        n = n + 1
        text(n:n) = string(i:i)
      end if
      i = i + 1
    end if
  end do
  if (lop == 1) then
    write (error_unit, '(a)') '***NOTE: ' // trim(text)
  else if (lop == -1) then
    write (error_unit, '(a)') '***WARNING: ' // trim(text)
  else
    write (error_unit, '(a)') '***ERROR: ' // trim(text)
  end if
  if (lop == -3) call xit()
end subroutine stdb_abqerr

!> GETJOBNAME: the job name ($LDFCZ_JOB_NAME, otherwise "job") and its length.
subroutine getjobname(jobname, lenjobname)
  implicit none
  character(len=*), intent(out) :: jobname   !< job name, blank-filled
  integer, intent(out) :: lenjobname         !< length of the name
  integer :: stat
  call get_environment_variable('LDFCZ_JOB_NAME', jobname, lenjobname, stat)
  if (stat /= 0 .or. lenjobname == 0) jobname = 'job'
  lenjobname = len_trim(jobname)
end subroutine getjobname

!> GETOUTDIR: the output directory ($LDFCZ_OUTDIR, otherwise $PWD, otherwise ".") and its length.
subroutine getoutdir(outdir, lenoutdir)
  implicit none
  character(len=*), intent(out) :: outdir    !< output directory, blank-filled
  integer, intent(out) :: lenoutdir          !< length of the directory name
  integer :: stat
  call get_environment_variable('LDFCZ_OUTDIR', outdir, lenoutdir, stat)
  if (stat /= 0 .or. lenoutdir == 0) call get_environment_variable('PWD', outdir, lenoutdir, stat)
  if (stat /= 0 .or. lenoutdir == 0) outdir = '.'
  lenoutdir = len_trim(outdir)
end subroutine getoutdir

!> GETNUMCPUS: number of processes of the analysis (one).
subroutine getnumcpus(numprocesses)
  implicit none
  integer, intent(out) :: numprocesses  !< number of processes
  numprocesses = 1
end subroutine getnumcpus

!> GETRANK: rank of the calling process (0).
subroutine getrank(rank)
  implicit none
  integer, intent(out) :: rank  !< process rank
  rank = 0
end subroutine getrank

!> GETNUMTHREADS: number of threads running user routines (one).
integer function getnumthreads()
  implicit none
  getnumthreads = 1
end function getnumthreads

!> GET_THREAD_ID: number of the calling thread (0).
integer function get_thread_id()
  implicit none
  get_thread_id = 0
end function get_thread_id
