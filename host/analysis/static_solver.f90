!> Entry point of the static analysis: set up the analysis data, run the steps (static_step: increments, cutbacks,
!> Newton in newton_iteration, output, restart), then the closing summary with the energy balance (run_summary).
!> The options, exit codes and summary type are those of solver_options and run_summary, re-exported here.
module static_solver
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t
  use analysis_core, only: analysis_t, analysis_init, close_loop_trace
  use sparse_system, only: sparse_destroy
  use output_files, only: output_t, output_log, output_sta_note
  use user_routines, only: user_routines_t
  use abaqus_host_state, only: abaqus_clear_stop
  use solver_options, only: solver_options_t, exit_ok, exit_input, exit_no_convergence, &
    newton_full, newton_modified, newton_krylov, newton_auto, newton_mode_code
  use run_summary, only: run_summary_t, run_summary_collect, run_summary_write, peak_memory_kb
  use static_step, only: run_steps
  use parallel_context, only: parallel_t, parallel_max
  implicit none
  private
  public :: run_analysis, run_summary_t, exit_ok, exit_input, exit_no_convergence
  public :: solver_options_t, newton_full, newton_modified, newton_krylov, newton_auto, newton_mode_code

contains

  !> Run every step of the model. exit_code: 0 all steps done, 2 input/model error, 3 no convergence.
  subroutine run_analysis(model, routines, out, verbose, summary, exit_code, options, par)
    type(model_t), intent(in) :: model             !< the model
    type(user_routines_t), intent(in) :: routines  !< UEL and UMAT
    type(output_t), intent(inout) :: out           !< output files
    logical, intent(in) :: verbose                 !< per-iteration residual lines in the log
    type(run_summary_t), intent(out) :: summary    !< counters and measures
    integer, intent(out) :: exit_code              !< exit status
    type(solver_options_t), intent(in), optional :: options  !< solver choices (default: full Newton)
    type(parallel_t), intent(in), optional :: par  !< processes of the run (default: this one alone)
    type(solver_options_t) :: opt
    type(analysis_t) :: an
    integer :: stat, fact_offset
    character(len=:), allocatable :: errmsg
    real(dp) :: cpu0, cpu1
    integer(i8) :: c0, c1, rate
    logical :: summarize

    call system_clock(c0, rate)
    call cpu_time(cpu0)
    if (present(options)) opt = options
    exit_code = exit_ok
    call abaqus_clear_stop()
    if (present(par)) an%par = par
    call analysis_init(an, model, routines, stat, errmsg, opt)
    if (stat /= 0) then
      call close_loop_trace(an)
      call output_log(out, 'ldfcz: error: '//errmsg)
      call output_sta_note(out, 'input error (exit status 2): '//errmsg)
      if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    summary%ndof = count(an%used)
    call run_steps(model, out, verbose, opt, an, summary, exit_code, fact_offset, summarize)
    call close_loop_trace(an)
    if (.not. summarize) return

    call run_summary_collect(summary, model, an, out%t_output, fact_offset)
    if (an%eqs%sys_ready) call sparse_destroy(an%eqs%sys)
    call system_clock(c1)
    call cpu_time(cpu1)
    summary%wall = real(c1 - c0, dp) / real(rate, dp)
    summary%cpu = cpu1 - cpu0
    summary%peak_kb = peak_memory_kb()
    summary%peak_kb_max = nint(parallel_max(an%par, real(summary%peak_kb, dp)))   ! every process (MPI)
    call run_summary_write(out, summary)
  end subroutine run_analysis

end module static_solver
