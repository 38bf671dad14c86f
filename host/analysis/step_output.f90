!> The output phase of the increment loop: per converged increment a JOB.csv row (history_columns), the JOB.dat
!> tables due (print_tables) and the VTU frame due (field_frame), and the output state: what the files hold (CSV
!> rows, the increment of the last frame) and when the next frame is due. The marks are part of a checkpoint
!> (restart_file); the CSV columns and the JOB.dat unit are set up by every run.
module step_output
  use, intrinsic :: iso_fortran_env, only: output_unit
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t
  use analysis_core, only: analysis_t
  use increment, only: increment_t
  use step_control, only: step_control_done
  use output_files, only: output_t, output_csv_header, output_csv_row, output_csv_resume, output_log
  use history_columns, only: history_columns_t, history_columns_build, history_columns_values
  use print_tables, only: print_tables_any, print_tables_write, print_tables_elements
  use state_gather, only: gather_converged_states, release_converged_states
  use field_frame, only: write_field_frame, field_frame_blocks
  implicit none
  private
  public :: output_marks_t, output_state_t, output_state_open, output_step_begin, write_increment_output
  public :: write_frame

  !> What the output files hold and when the next frame is due (checkpointed).
  type :: output_marks_t
    integer :: csv_rows = 0               !< data rows of JOB.csv
    integer :: last_frame_inc = -1        !< converged increment (of the analysis) of the last VTU frame
    real(dp) :: next_mark = 0.0_dp        !< NUMBER INTERVAL: step time of the next frame
  end type output_marks_t

  !> The output state of a run.
  type :: output_state_t
    type(output_marks_t) :: marks            !< what the files hold
    type(history_columns_t) :: cols          !< the columns of JOB.csv
    real(dp), allocatable :: values(:)       !< a row's values
    integer :: dat = -1                      !< JOB.dat unit (-1: no printed output requested)
  end type output_state_t

contains

  !> JOB.csv's header, or after a restart (resume) the file kept up to os%marks%csv_rows rows; JOB.dat's tables on
  !> unit 6, which output_open has pointed at JOB.dat (continued after a restart): what user routines write there
  !> interleaves with the tables as in Abaqus. stat /= 0 (errmsg): the CSV cannot be continued.
  subroutine output_state_open(os, model, out, resume, stat, errmsg)
    type(output_state_t), intent(inout) :: os            !< output state (marks set)
    type(model_t), intent(in) :: model                   !< the model
    type(output_t), intent(inout) :: out                 !< output files
    logical, intent(in) :: resume                        !< a restart: continue the files
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    logical :: fresh
    stat = 0
    errmsg = ''
    ! the frames' blocks (JOB.pvd of a restart lists the kept frames with their extension)
    out%nblocks = field_frame_blocks(model)
    ! CSV columns: every (set, variable) requested by *NODE PRINT in any step
    call history_columns_build(model, os%cols)
    allocate (os%values(os%cols%n))
    if (resume) then
      call output_csv_resume(out, os%cols%names(1:os%cols%n), os%marks%csv_rows, fresh, stat, errmsg)
      if (stat /= 0) return
      if (fresh) call output_log(out, 'ldfcz: warning: no '//out%job//'.csv in '//out%dir//': the new one '// &
        'holds the increments after the restart point only')
    else
      call output_csv_header(out, os%cols%names(1:os%cols%n))
    end if
    os%dat = -1
    if (print_tables_any(model) .and. .not. out%silent) os%dat = output_unit  ! once: by the writing process
  end subroutine output_state_open

  !> Start of step st: its first NUMBER INTERVAL mark.
  pure subroutine output_step_begin(os, st)
    type(output_state_t), intent(inout) :: os  !< output state
    type(step_t), intent(in) :: st             !< the step beginning
    os%marks%next_mark = st%period / max(1, st%field_intervals)
    os%marks%last_frame_inc = -1
  end subroutine output_step_begin

  !> The output of converged increment inc (the analysis state committed): the CSV row, the JOB.dat tables due
  !> (rank 0 prints: the states of the other processes' printed elements first, every process taking part,
  !> released after the tables) and the VTU frame due.
  subroutine write_increment_output(os, out, model, an, inc)
    type(output_state_t), intent(inout) :: os  !< output state
    type(output_t), intent(inout) :: out       !< output files
    type(model_t), intent(in) :: model         !< the model
    type(analysis_t), intent(inout) :: an      !< the analysis (converged states gathered for the tables)
    type(increment_t), intent(in) :: inc       !< the converged increment
    integer, allocatable :: printed(:)         ! elements of the *EL PRINT tables due
    logical :: done
    associate (p => an%state%progress, st => model%steps(inc%step))
      done = step_control_done(p%sc)
      call history_columns_values(os%cols, model, an%work%u, an%work%fint, an%work%fext, an%work%fdl, &
        an%eqs%prescribed, os%values, an%nr)
      call output_csv_row(out, inc%step, inc%kinc, p%sc%t, p%t_total0 + p%sc%t, os%values)
      os%marks%csv_rows = os%marks%csv_rows + 1
      if (print_tables_any(model)) then
        printed = print_tables_elements(model, st, inc%kinc, done)
        call gather_converged_states(an, model, printed)
      end if
      if (os%dat /= -1) call print_tables_write(os%dat, model, an, st, inc%step, inc%kinc, p%sc%t, &
        p%t_total0 + p%sc%t, inc%dt, done)
      if (print_tables_any(model)) call release_converged_states(an, printed)
      if (.not. st%field_output) return
      if (allocated(st%field_points)) then
        ! TIME POINTS: a frame at each increment ending on a point (the increments end on them) and the last
        if (any(abs(st%field_points - p%sc%t) <= 1.0e-9_dp * st%period) .or. done) call write_frame(os, out, model, &
          an, p%t_total0 + p%sc%t, inc%step)
      else if (st%field_intervals > 0) then
        if (p%sc%t >= os%marks%next_mark * (1.0_dp - 1.0e-9_dp) .or. done) then
          call write_frame(os, out, model, an, p%t_total0 + p%sc%t, inc%step)
          do while (os%marks%next_mark <= p%sc%t * (1.0_dp + 1.0e-9_dp))
            os%marks%next_mark = os%marks%next_mark + st%period / st%field_intervals
          end do
        end if
      else if (st%field_frequency > 0) then
        if (mod(inc%kinc, st%field_frequency) == 0 .or. done) call write_frame(os, out, model, an, &
          p%t_total0 + p%sc%t, inc%step)
      end if
    end associate
  end subroutine write_increment_output

  !> A VTU frame of the converged state at total time ttot with the field request of step istep, once per
  !> converged increment.
  subroutine write_frame(os, out, model, an, ttot, istep)
    type(output_state_t), intent(inout) :: os  !< output state
    type(output_t), intent(inout) :: out       !< output files
    type(model_t), intent(in) :: model         !< the model
    type(analysis_t), intent(in) :: an         !< the analysis
    real(dp), intent(in) :: ttot               !< total time of the frame
    integer, intent(in) :: istep               !< step whose field request applies
    if (an%state%progress%kinc_total == os%marks%last_frame_inc) return
    os%marks%last_frame_inc = an%state%progress%kinc_total
    call write_field_frame(out, model, an, ttot, model%steps(istep))
  end subroutine write_frame

end module step_output
