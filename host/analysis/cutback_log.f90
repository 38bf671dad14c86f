!> Every cutback named in JOB.log: one line per cutback with its cause and the increment size it leads to; a run of
!> cutbacks of the same cause in one step is summarised honestly when it ends ("cutback: PNEWDT ... repeated 27 more
!> times in step 1, increments 5-97; JOB.sta lists each"). JOB.sta keeps one line per attempt; the element, point
!> and routine behind an element-reported cause are logged by newton_iteration.
module cutback_log
  use ldfcz_kinds, only: dp
  use output_files, only: output_t, output_log
  use run_summary, only: cutback_cause
  use solver_text, only: itoa, rtoa
  implicit none
  private
  public :: cutback_log_t, cutback_log_add, cutback_log_flush

  !> The run of repeated cutbacks not yet logged.
  type :: cutback_log_t
    integer :: kind = 0                  !< cause class of the last logged cutback (run_summary's cutback_cause)
    character(len=64) :: cause = ''      !< its cause as logged
    integer :: step = 0                  !< its step
    integer :: repeats = 0               !< cutbacks of the same class since, not logged
    integer :: first_inc = 0, last_inc = 0  !< increments of those repeats
  end type cutback_log_t

contains

  !> A cutback of increment kinc (attempt) in step with its cause; dt: the increment cut back, dt_next: the next
  !> attempt's. every: log each (verbose) instead of summarising repeats.
  subroutine cutback_log_add(cl, out, step, kinc, attempt, cause, dt, dt_next, every)
    type(cutback_log_t), intent(inout) :: cl   !< repeats not yet logged
    type(output_t), intent(inout) :: out       !< JOB.log
    integer, intent(in) :: step, kinc, attempt !< where
    character(len=*), intent(in) :: cause      !< 'cutback: diverging', ...
    real(dp), intent(in) :: dt, dt_next        !< increment sizes
    logical, intent(in) :: every               !< log each cutback
    integer :: k
    k = cutback_cause(cause)
    if (.not. every .and. k == cl%kind .and. step == cl%step) then
      if (cl%repeats == 0) cl%first_inc = kinc
      cl%repeats = cl%repeats + 1
      cl%last_inc = kinc
      return
    end if
    call cutback_log_flush(cl, out)
    call output_log(out, '  step '//itoa(step)//' increment '//itoa(kinc)//' attempt '//itoa(attempt)//': '// &
      trim(cause)//' (increment '//rtoa(dt)//' -> '//rtoa(dt_next)//')')
    cl%kind = k
    cl%cause = cause
    cl%step = step
  end subroutine cutback_log_add

  !> The repeats not yet logged, as one line; the next cutback is logged in full.
  subroutine cutback_log_flush(cl, out)
    type(cutback_log_t), intent(inout) :: cl  !< repeats not yet logged
    type(output_t), intent(inout) :: out      !< JOB.log
    character(len=:), allocatable :: incs
    if (cl%repeats > 0) then
      incs = 'increment '//itoa(cl%first_inc)
      if (cl%last_inc /= cl%first_inc) incs = 'increments '//itoa(cl%first_inc)//'-'//itoa(cl%last_inc)
      call output_log(out, '  '//trim(cause_class(cl%cause))//' repeated '//itoa(cl%repeats)//' more time'// &
        trim(merge('s', ' ', cl%repeats > 1))//' in step '//itoa(cl%step)//', '//incs//' ('//out%job// &
        '.sta lists each)')
    end if
    cl = cutback_log_t()
  end subroutine cutback_log_flush

  !> The cause without its figures ('cutback: PNEWDT 2.5E-01' -> 'cutback: PNEWDT'; 'cutback: 8 iterations' ->
  !> 'cutback: iteration limit'), for the summary of repeats whose figures differ.
  pure function cause_class(cause) result(c)
    character(len=*), intent(in) :: cause
    character(len=:), allocatable :: c
    integer :: k
    c = trim(cause)
    if (index(c, ' iterations') > 0) then
      c = 'cutback: iteration limit'
      return
    end if
    k = scan(c, '0123456789')
    if (k > 1) c = trim(c(1:k - 1))
    if (c(len(c):len(c)) == '.' .or. c(len(c):len(c)) == '-') c = trim(c(1:len(c) - 1))
  end function cause_class

end module cutback_log
