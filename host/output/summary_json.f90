!> JOB.summary.json: the closing summary of a run for programs (docs/summary.md lists every key with its unit): how
!> the run ended, the job and the build, threads and processes, the model's size, the counters (cutbacks by cause,
!> increments per step), wall times by phase, memory, the energy balance, element costs, the balance of a
!> distributed run and the accuracy indicators. The program writes it last, after JOB.log is closed, for every run
!> that got as far as its analysis; a run removes the file of an earlier run when it starts. JOB.log keeps the same
!> figures as text for people.
module summary_json
  use ldfcz_kinds, only: dp, i8
  use json_writer, only: json_t, json_begin, json_end, json_open, json_close, json_put, json_put_null, &
    json_put_real_or_null, json_write_file, json_remove_file
  use run_summary, only: run_summary_t, element_costs, energy_balance, n_cutback_cause, cutback_cause_name, &
    max_summary_steps, n_cost_class
  use solver_options, only: newton_mode_name, exit_ok, exit_input, exit_no_convergence
  use stop_signal, only: stop_signal_name
  implicit none
  private
  public :: run_facts_t, summary_json_document, summary_json_write, summary_json_clear, run_status
  public :: summary_schema_version

  !> version of the document's layout: raised when a key changes meaning or goes; new keys may come without it
  integer, parameter :: summary_schema_version = 1
  character(len=*), parameter :: class_names(n_cost_class) = [character(len=17) :: 'umat_continuum', &
    'elastic_continuum', 'user_element']

  !> What the program knows of the run beyond the summary counters.
  type :: run_facts_t
    character(len=:), allocatable :: job           !< job name
    character(len=:), allocatable :: deck          !< the deck as given
    character(len=:), allocatable :: output_dir    !< output directory as given
    character(len=:), allocatable :: version       !< ldfcz version
    character(len=:), allocatable :: commit        !< git commit of the build ('' or 'unknown': not known)
    character(len=:), allocatable :: restart_from  !< the restart file continued ('': a fresh run)
    integer :: exit_code = 0                       !< the program's exit status
    integer :: threads = 1                         !< OpenMP threads per process
    integer :: processes = 1                       !< MPI processes
    integer :: nodes = 0, elements = 0, steps = 0  !< the model's size
    integer :: stop_after = 0                      !< --stop-after-increments (0: not given)
  end type run_facts_t

contains

  !> How the run ended, from its exit status: completed (0), no_convergence (3), stopped_after_increments (3 after
  !> --stop-after-increments K converged increments of this run), input_error (2), stopped_by_user_routine (2: XIT
  !> or STDB_ABQERR), stopped_by_signal (128 + the signal, named in signal; '' otherwise), else error.
  pure subroutine run_status(exit_code, summary, stop_after, status, signal)
    integer, intent(in) :: exit_code                       !< the exit status
    type(run_summary_t), intent(in) :: summary             !< counters of the run
    integer, intent(in) :: stop_after                      !< --stop-after-increments (0: none)
    character(len=:), allocatable, intent(out) :: status   !< the status
    character(len=:), allocatable, intent(out) :: signal   !< the signal's name when stopped by one
    signal = ''
    select case (exit_code)
    case (exit_ok)
      status = 'completed'
    case (exit_no_convergence)
      status = 'no_convergence'
      if (stop_after > 0 .and. summary%increments - summary%increments_resumed >= stop_after) &
        status = 'stopped_after_increments'
    case (exit_input)
      status = 'input_error'
      if (summary%routine_stop) status = 'stopped_by_user_routine'
    case (129:160)
      status = 'stopped_by_signal'
      signal = stop_signal_name(exit_code - 128)
    case default
      status = 'error'
    end select
  end subroutine run_status

  !> The document of a run (docs/summary.md).
  subroutine summary_json_document(facts, summary, w)
    type(run_facts_t), intent(in) :: facts         !< the run
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    type(json_t), intent(out) :: w                 !< the document
    character(len=:), allocatable :: status, signal
    call run_status(facts%exit_code, summary, facts%stop_after, status, signal)
    call json_begin(w)
    call json_put(w, 'schema', 'ldfcz run summary')
    call json_put(w, 'schema_version', summary_schema_version)
    call json_put(w, 'status', status)
    call json_put(w, 'exit_code', facts%exit_code)
    call string_or_null(w, 'signal', signal)
    if (facts%stop_after > 0) then
      call json_put(w, 'stop_after_increments', facts%stop_after)
    else
      call json_put_null(w, 'stop_after_increments')
    end if
    call json_put(w, 'job', facts%job)
    call json_put(w, 'deck', facts%deck)
    call json_put(w, 'output_dir', facts%output_dir)
    call json_open(w, 'program', '{')
    call json_put(w, 'version', facts%version)
    if (facts%commit == 'unknown') then
      call json_put_null(w, 'commit')
    else
      call string_or_null(w, 'commit', facts%commit)
    end if
    call json_close(w)
    if (len(facts%restart_from) > 0) then
      call json_open(w, 'restart', '{')
      call json_put(w, 'from', facts%restart_from)
      call json_put(w, 'increments_before', summary%increments_resumed)
      call json_close(w)
    else
      call json_put_null(w, 'restart')
    end if
    call json_put(w, 'threads', facts%threads)
    call json_put(w, 'processes', facts%processes)
    call json_open(w, 'model', '{')
    call json_put(w, 'nodes', facts%nodes)
    call json_put(w, 'elements', facts%elements)
    call json_put(w, 'dofs', summary%ndof)
    call json_put(w, 'equations', summary%neq)
    call json_put(w, 'steps', facts%steps)
    call json_close(w)
    call json_put(w, 'newton', trim(newton_mode_name(summary%newton)))
    call counters(w, summary)
    call steps(w, summary)
    call measures(w, summary)
    call json_end(w)
  end subroutine summary_json_document

  !> Counters of the whole run (continued over a restart) and the cutbacks by cause.
  subroutine counters(w, summary)
    type(json_t), intent(inout) :: w               !< the document
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    integer :: k
    call json_open(w, 'counters', '{')
    call json_put(w, 'increments', summary%increments)
    call json_put(w, 'attempts', summary%attempts)
    call json_put(w, 'cutbacks', summary%cutbacks)
    call json_put(w, 'iterations', summary%iterations)
    call json_put(w, 'factorizations', summary%factorizations)
    call json_put(w, 'solves_with_reused_factors', summary%reused_solves)
    call json_put(w, 'gmres_solves', summary%krylov_solves)
    call json_put(w, 'gmres_iterations', summary%krylov_iterations)
    call json_put(w, 'gmres_refactorized', summary%krylov_failures)
    call json_put(w, 'accuracy_cutbacks', summary%accuracy_cutbacks)
    call json_close(w)
    call json_open(w, 'cutbacks_by_cause', '{')
    do k = 1, n_cutback_cause
      call json_put(w, cutback_cause_name(k), summary%cutbacks_by_cause(k))
    end do
    call json_close(w)
  end subroutine counters

  !> One record per step reached (up to max_summary_steps; the rest counted in steps_not_listed).
  subroutine steps(w, summary)
    type(json_t), intent(inout) :: w               !< the document
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    integer :: k
    call json_open(w, 'steps', '[')
    do k = 1, min(summary%last_step, max_summary_steps)
      call json_open(w, '', '{')
      call json_put(w, 'step', k)
      call json_put(w, 'increments', summary%step_increments(k))
      call json_put(w, 'cutbacks', summary%step_cutbacks(k))
      call json_put(w, 'completed', summary%step_completed(k))
      call json_put_real_or_null(w, 'total_time', summary%step_total_time(k), summary%step_increments(k) > 0)
      call json_put_real_or_null(w, 'external_work', summary%step_work(k), summary%step_increments(k) > 0)
      call json_close(w)
    end do
    call json_close(w)
    call json_put(w, 'steps_not_listed', max(summary%last_step - max_summary_steps, 0))
  end subroutine steps

  !> Times, memory, factors, energy, element costs, the balance of the processes and the accuracy indicators (null
  !> when the run ended before they were measured: an input error before the first step).
  subroutine measures(w, summary)
    type(json_t), intent(inout) :: w               !< the document
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    logical :: known, available
    real(dp) :: rel
    known = summary%collected
    call json_open(w, 'times', '{')
    call json_put_real_or_null(w, 'wall_s', summary%wall, known)
    call json_put_real_or_null(w, 'cpu_s', summary%cpu, known)
    call json_put_real_or_null(w, 'element_loop_s', summary%t_assembly, known)
    call json_put_real_or_null(w, 'factorization_s', summary%t_factor, known)
    call json_put_real_or_null(w, 'solve_s', summary%t_solve, known)
    call json_put_real_or_null(w, 'factorization_beside_s', summary%t_factor_beside, known)
    call json_put_real_or_null(w, 'factorization_wait_s', summary%t_factor_wait, known)
    call json_put_real_or_null(w, 'output_s', summary%t_output, known)
    call json_put_real_or_null(w, 'solver_setup_s', summary%t_analysis, known)
    call json_put_real_or_null(w, 'communication_s', summary%t_comm, known)
    call json_close(w)
    call json_open(w, 'memory', '{')
    call int_or_null(w, 'peak_kb', summary%peak_kb, known)
    call int_or_null(w, 'peak_kb_largest_process', summary%peak_kb_max, known)
    call json_close(w)
    call json_open(w, 'factors', '{')
    if (known .and. summary%factor_entries > 0) then
      call json_put(w, 'entries', summary%factor_entries)
    else
      call json_put_null(w, 'entries')
    end if
    call json_put_real_or_null(w, 'flops', summary%factor_flops, known .and. summary%factor_flops > 0.0_dp)
    call json_close(w)
    call energy_balance(summary, rel, available)
    call json_open(w, 'energy', '{')
    call json_put_real_or_null(w, 'external_work', summary%w_ext, known)
    call json_put_real_or_null(w, 'stored_dissipated', summary%e_int, known .and. available)
    call json_put_real_or_null(w, 'relative_difference', rel, known .and. available)
    call json_close(w)
    call costs(w, summary)
    call balance(w, summary)
    call json_open(w, 'accuracy', '{')
    call json_put(w, 'max_opening_ratio', summary%max_open_ratio)
    call int_or_null(w, 'plastic_statev', summary%plastic_statev, summary%plastic_statev > 0)
    call json_put_real_or_null(w, 'max_plastic_increment', summary%max_statev_inc, summary%plastic_statev > 0)
    call json_close(w)
  end subroutine measures

  !> The measured cost per element call of each class and the partition weights they give (run_summary).
  subroutine costs(w, summary)
    type(json_t), intent(inout) :: w               !< the document
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    real(dp) :: us(n_cost_class)
    integer :: wt(n_cost_class), k
    call element_costs(summary, us, wt)
    call json_open(w, 'element_cost', '{')
    do k = 1, n_cost_class
      call json_open(w, trim(class_names(k)), '{')
      call json_put(w, 'calls', nint(summary%class_calls(k), i8))
      call json_put_real_or_null(w, 'us_per_call', us(k), summary%collected .and. summary%class_calls(k) > 0.0_dp)
      call json_put(w, 'weight', wt(k))
      call json_close(w)
    end do
    call json_close(w)
  end subroutine costs

  !> A distributed run: the element loop's balance over the processes and rank 0's communication (null: one process).
  subroutine balance(w, summary)
    type(json_t), intent(inout) :: w               !< the document
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    real(dp) :: mean
    if (summary%nranks <= 1 .or. .not. summary%collected) then
      call json_put_null(w, 'mpi')
      return
    end if
    mean = max(summary%t_assembly_mean, tiny(1.0_dp))
    call json_open(w, 'mpi', '{')
    call json_put(w, 'processes', summary%nranks)
    call json_put(w, 'element_loop_max_s', summary%t_assembly_max)
    call json_put(w, 'element_loop_mean_s', summary%t_assembly_mean)
    call json_put(w, 'element_loop_max_over_mean', summary%t_assembly_max / mean)
    call json_put(w, 'element_loop_slowest_summed_s', summary%t_assembly_slowest)
    call json_put(w, 'element_loop_slowest_over_mean', summary%t_assembly_slowest / mean)
    call json_put(w, 'communication_s', summary%t_comm)
    call json_put(w, 'loop_end_wait_s', summary%t_loop_wait)
    call json_put(w, 'reductions_s', max(summary%t_comm - summary%t_loop_wait, 0.0_dp))
    call json_put(w, 'partition_weights', summary%class_weight)
    call json_close(w)
  end subroutine balance

  subroutine string_or_null(w, key, value)
    type(json_t), intent(inout) :: w       !< the document
    character(len=*), intent(in) :: key    !< member name
    character(len=*), intent(in) :: value  !< the value ('': null)
    if (len(value) > 0) then
      call json_put(w, key, value)
    else
      call json_put_null(w, key)
    end if
  end subroutine string_or_null

  subroutine int_or_null(w, key, value, known)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name
    integer, intent(in) :: value         !< the value
    logical, intent(in) :: known         !< false: null
    if (known) then
      call json_put(w, key, value)
    else
      call json_put_null(w, key)
    end if
  end subroutine int_or_null

  !> The file's path: DIR/JOB.summary.json.
  pure function summary_path(dir, job) result(path)
    character(len=*), intent(in) :: dir, job  !< output directory and job name
    character(len=:), allocatable :: path
    path = dir//'/'//job//'.summary.json'
  end function summary_path

  !> Write DIR/JOB.summary.json whole (a temporary file renamed over it).
  subroutine summary_json_write(dir, job, facts, summary, stat, errmsg)
    character(len=*), intent(in) :: dir, job              !< output directory and job name
    type(run_facts_t), intent(in) :: facts                !< the run
    type(run_summary_t), intent(in) :: summary            !< counters and measures
    integer, intent(out) :: stat                          !< 0: written
    character(len=:), allocatable, intent(out) :: errmsg  !< why not
    type(json_t) :: w
    call summary_json_document(facts, summary, w)
    call json_write_file(w, summary_path(dir, job), stat, errmsg)
  end subroutine summary_json_write

  !> Remove the summary of an earlier run from DIR (at the start of a run: a summary present is this run's).
  subroutine summary_json_clear(dir, job)
    character(len=*), intent(in) :: dir, job  !< output directory and job name
    call json_remove_file(summary_path(dir, job))
  end subroutine summary_json_clear

end module summary_json
