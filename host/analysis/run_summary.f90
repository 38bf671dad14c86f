!> Counters and measures of a run, the closing summary of the log (with the energy balance) and the accuracy
!> indicators measured per increment: the cohesive opening increment (paper section 7) and a material STATEV increment.
module run_summary
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t, etype_user
  use analysis_core, only: analysis_t, n_cost_class
  use sparse_system, only: sparse_time_analysis, sparse_time_factor, sparse_time_solve, sparse_factor_count, &
    sparse_time_comm, sparse_factor_entries, sparse_factor_flops, sparse_time_factor_beside, sparse_time_factor_wait
  use output_files, only: output_t, output_log
  use parallel_context, only: parallel_t, parallel_max, parallel_sum
  use solver_options, only: newton_full, newton_mode_name
  implicit none
  private
  public :: run_summary_t, run_summary_collect, run_summary_write, run_summary_continue, peak_memory_kb
  public :: cohesive_ratio, statev_increment, element_costs, cutback_cause, n_cutback_cause, cutback_cause_name
  public :: max_summary_steps, n_cost_class, energy_balance

  !> steps whose increments, cutbacks, time and work the summary keeps one by one (later steps: counted only)
  integer, parameter :: max_summary_steps = 500
  !> causes of a cutback (cutback_cause): the outcomes of newton_iteration and the opening bound, and any other
  integer, parameter :: n_cutback_cause = 8
  character(len=*), parameter :: cutback_names(n_cutback_cause) = [character(len=17) :: 'diverging', &
    'iteration_limit', 'pnewdt', 'element_failure', 'singular_tangent', 'solve_failed', 'opening_increment', 'other']

  !> Counters and measures of a run (printed in the closing summary).
  type :: run_summary_t
    integer :: increments = 0, attempts = 0, cutbacks = 0, iterations = 0, factorizations = 0
    integer :: neq = 0, ndof = 0
    real(dp) :: t_assembly = 0, t_factor = 0, t_solve = 0, t_output = 0, t_analysis = 0, wall = 0, cpu = 0
    real(dp) :: t_factor_beside = 0             !< of t_factor: factorizations on their own thread (pipelined)
    real(dp) :: t_factor_wait = 0               !< of t_solve: waits for them
    real(dp) :: w_ext = 0                       !< external work of the reactions (trapezoidal)
    real(dp) :: e_int = 0                       !< stored + dissipated energy of elements and materials
    real(dp) :: max_open_ratio = 0              !< largest cohesive |Delta| increment / delta
    real(dp) :: max_statev_inc = 0              !< largest increment of STATEV(plastic_statev)
    integer :: plastic_statev = 0               !< the STATEV reported (0: none)
    integer :: krylov_solves = 0, krylov_iterations = 0, krylov_failures = 0, reused_solves = 0
    integer :: accuracy_cutbacks = 0            !< increments redone for the opening bound
    integer :: newton = newton_full
    integer :: peak_kb = 0                      !< VmHWM
    integer :: nranks = 1                       !< processes of the run (MPI)
    real(dp) :: t_comm = 0                      !< wall seconds in the host's reductions and broadcasts (MPI)
    integer :: peak_kb_max = 0                  !< largest VmHWM over the processes (MPI)
    real(dp) :: t_assembly_max = 0              !< element loops up to their first reduction: the largest total (MPI)
    real(dp) :: t_assembly_mean = 0             !< element loops up to their first reduction: the processes' mean (MPI)
    real(dp) :: t_assembly_slowest = 0          !< element loop: the slowest process's time of each loop, summed
    real(dp) :: t_loop_wait = 0                 !< rank 0's wait at the end of its element loops (in t_comm)
    real(dp) :: class_time(n_cost_class) = 0    !< seconds in the element routines per cost class, all processes
    real(dp) :: class_calls(n_cost_class) = 0   !< element calls per cost class, all processes
    integer :: class_weight(n_cost_class) = 0   !< the partition's weights (MPI)
    integer(i8) :: factor_entries = 0           !< entries in the last factors (MUMPS INFOG(29); 0: none)
    real(dp) :: factor_flops = 0.0_dp           !< operations of the last factorization (MUMPS RINFOG(3); 0: none)
    integer :: cutbacks_by_cause(n_cutback_cause) = 0  !< cutbacks per cause (cutback_cause)
    integer :: last_step = 0                    !< the last step with a converged increment or a cutback
    integer :: step_increments(max_summary_steps) = 0   !< converged increments of each step (its last KINC)
    integer :: step_cutbacks(max_summary_steps) = 0     !< cutbacks in each step
    logical :: step_completed(max_summary_steps) = .false.  !< the step reached its end
    real(dp) :: step_total_time(max_summary_steps) = 0  !< total time at the step's last converged increment
    real(dp) :: step_work(max_summary_steps) = 0        !< w_ext at the step's last converged increment
    integer :: increments_resumed = 0           !< increments of the run before the restart point (a restarted run)
    logical :: collected = .false.              !< run_summary_collect done (times, energy, costs are known)
    logical :: routine_stop = .false.           !< a user routine asked to end the analysis (XIT, STDB_ABQERR)
  contains
    procedure :: add_increment => run_summary_add_increment
    procedure :: add_cutback => run_summary_add_cutback
  end type run_summary_t

contains

  !> A run continued from a restart file: the counters and accumulators of the earlier run go on (the
  !> factorization count is carried separately by the caller); times, sizes and options stay this run's.
  pure subroutine run_summary_continue(summary, saved)
    type(run_summary_t), intent(inout) :: summary  !< this run's summary
    type(run_summary_t), intent(in) :: saved       !< the summary stored with the restart point
    summary%increments = saved%increments
    summary%attempts = saved%attempts
    summary%cutbacks = saved%cutbacks
    summary%iterations = saved%iterations
    summary%krylov_solves = saved%krylov_solves
    summary%krylov_iterations = saved%krylov_iterations
    summary%krylov_failures = saved%krylov_failures
    summary%reused_solves = saved%reused_solves
    summary%accuracy_cutbacks = saved%accuracy_cutbacks
    summary%w_ext = saved%w_ext
    summary%max_open_ratio = saved%max_open_ratio
    summary%max_statev_inc = saved%max_statev_inc
    summary%cutbacks_by_cause = saved%cutbacks_by_cause
    summary%last_step = saved%last_step
    summary%step_increments = saved%step_increments
    summary%step_cutbacks = saved%step_cutbacks
    summary%step_completed = saved%step_completed
    summary%step_total_time = saved%step_total_time
    summary%step_work = saved%step_work
    summary%increments_resumed = saved%increments
  end subroutine run_summary_continue

  !> A converged increment: counted, and the step's record (increments, total time and the external work reached;
  !> the step completed when the increment ended it). Called after the increment's work is added to w_ext.
  pure subroutine run_summary_add_increment(summary, step, kinc, total_time, step_done)
    class(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(in) :: step, kinc               !< the step and the increment's number in it (KINC)
    real(dp), intent(in) :: total_time              !< total time at the end of the increment
    logical, intent(in) :: step_done                !< the increment ended the step
    summary%increments = summary%increments + 1
    summary%last_step = max(summary%last_step, step)
    if (step < 1 .or. step > max_summary_steps) return
    summary%step_increments(step) = kinc
    summary%step_total_time(step) = total_time
    summary%step_work(step) = summary%w_ext
    summary%step_completed(step) = step_done
  end subroutine run_summary_add_increment

  !> A failed attempt (an increment cut back or redone), counted with its cause (the outcome JOB.sta shows).
  pure subroutine run_summary_add_cutback(summary, step, outcome)
    class(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(in) :: step                     !< the step
    character(len=*), intent(in) :: outcome         !< the attempt's outcome ('cutback: diverging', ...)
    integer :: k
    summary%cutbacks = summary%cutbacks + 1
    k = cutback_cause(outcome)
    summary%cutbacks_by_cause(k) = summary%cutbacks_by_cause(k) + 1
    summary%last_step = max(summary%last_step, step)
    if (step >= 1 .and. step <= max_summary_steps) summary%step_cutbacks(step) = summary%step_cutbacks(step) + 1
  end subroutine run_summary_add_cutback

  !> The cause of a cutback from the outcome of the attempt (newton_iteration's 'cutback: diverging', 'cutback: N
  !> iterations', 'cutback: PNEWDT x', 'cutback: element failure', 'cutback: singular tangent', 'cutback: solve
  !> failed'; static_step's 'cutback: opening increment x delta'), as an index of cutback_cause_name; 'other' else.
  pure integer function cutback_cause(outcome) result(k)
    character(len=*), intent(in) :: outcome  !< the outcome
    character(len=:), allocatable :: what
    integer :: c
    what = adjustl(outcome)
    c = index(what, 'cutback:')
    if (c > 0) what = adjustl(what(c + 8:))
    what = trim(what)
    if (starts(what, 'diverging')) then
      k = 1
    else if (ends(what, ' iterations')) then
      k = 2
    else if (starts(what, 'PNEWDT')) then
      k = 3
    else if (starts(what, 'element failure')) then
      k = 4
    else if (starts(what, 'singular tangent')) then
      k = 5
    else if (starts(what, 'solve failed')) then
      k = 6
    else if (starts(what, 'opening increment')) then
      k = 7
    else
      k = n_cutback_cause
    end if
  contains
    pure logical function starts(text, head)
      character(len=*), intent(in) :: text, head
      starts = len(text) >= len(head)
      if (starts) starts = text(1:len(head)) == head
    end function starts
    pure logical function ends(text, tail)
      character(len=*), intent(in) :: text, tail
      ends = len(text) >= len(tail)
      if (ends) ends = text(len(text) - len(tail) + 1:) == tail
    end function ends
  end function cutback_cause

  !> The name of cutback cause k (JOB.summary.json's keys of cutbacks_by_cause).
  pure function cutback_cause_name(k) result(name)
    integer, intent(in) :: k  !< 1..n_cutback_cause
    character(len=:), allocatable :: name
    name = trim(cutback_names(max(1, min(k, n_cutback_cause))))
  end function cutback_cause_name

  !> End of the run: internal energy of the converged states and the solver's times and factorization count
  !> (those of an earlier run continued by restart in fact_offset; the times are of this run only).
  subroutine run_summary_collect(summary, model, an, t_output, fact_offset)
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< analysis data (its sparse system is read)
    real(dp), intent(in) :: t_output               !< wall time spent writing output
    integer, intent(in) :: fact_offset             !< factorizations of the run before the restart point
    integer :: i
    real(dp) :: e(1)
    summary%e_int = 0.0_dp
    do i = 1, model%nelem
      if (an%owned(i)) summary%e_int = summary%e_int + an%state%conv(i)%energy(2) + an%state%conv(i)%energy(4)
    end do
    e(1) = summary%e_int
    call parallel_sum(an%par, e)   ! over the processes' elements (distributed run)
    summary%e_int = e(1)
    summary%t_factor = an%timing%t_factor_done
    summary%t_solve = an%timing%t_solve_done
    summary%t_factor_beside = an%timing%t_beside_done
    summary%t_factor_wait = an%timing%t_wait_done
    summary%t_analysis = an%timing%t_setup_done
    summary%factorizations = an%timing%n_factor_done + fact_offset
    if (an%eqs%sys_ready) then
      summary%t_factor = summary%t_factor + sparse_time_factor(an%eqs%sys)
      summary%t_solve = summary%t_solve + sparse_time_solve(an%eqs%sys)
      summary%t_factor_beside = summary%t_factor_beside + sparse_time_factor_beside(an%eqs%sys)
      summary%t_factor_wait = summary%t_factor_wait + sparse_time_factor_wait(an%eqs%sys)
      summary%t_analysis = summary%t_analysis + sparse_time_analysis(an%eqs%sys)
      summary%factorizations = summary%factorizations + sparse_factor_count(an%eqs%sys)
      summary%factor_entries = sparse_factor_entries(an%eqs%sys)
      summary%factor_flops = sparse_factor_flops(an%eqs%sys)
    end if
    summary%t_assembly = an%timing%t_assembly
    summary%t_output = t_output
    summary%nranks = an%par%nranks
    ! load balance of the element loop and the measured cost of each element class (sums over the processes)
    summary%t_assembly_max = parallel_max(an%par, an%timing%t_loop_own)
    e(1) = an%timing%t_loop_own
    call parallel_sum(an%par, e)
    summary%t_assembly_mean = e(1) / real(an%par%nranks, dp)
    summary%t_assembly_slowest = an%timing%t_assembly_slowest
    summary%t_loop_wait = an%timing%t_loop_wait
    summary%class_time = an%timing%class_time
    call parallel_sum(an%par, summary%class_time)
    summary%class_calls = real(an%timing%class_calls, dp)
    call parallel_sum(an%par, summary%class_calls)
    summary%class_weight = an%cost_weight
    summary%t_comm = an%par%t_comm
    if (an%eqs%sys_ready) summary%t_comm = summary%t_comm + sparse_time_comm(an%eqs%sys)
    summary%routine_stop = an%work%stop%asked
    summary%collected = .true.
  end subroutine run_summary_collect

  !> The measured cost of an element call per class (UMAT continuum, *ELASTIC continuum, user element: wall
  !> microseconds per call, summed over the processes' calls; 0 for a class without calls) and the weights they give
  !> for the partition of a distributed run (relative to the cheapest class present, at least 1; a class without
  !> elements keeps the weight of the run), to pass as --element-weights.
  pure subroutine element_costs(summary, us, w)
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    real(dp), intent(out) :: us(n_cost_class)      !< microseconds per call
    integer, intent(out) :: w(n_cost_class)        !< the partition weights they give
    real(dp) :: cheapest
    integer :: k
    us = 0.0_dp
    where (summary%class_calls > 0.0_dp) us = 1.0e6_dp * summary%class_time / summary%class_calls
    cheapest = minval(us, mask=summary%class_calls > 0.0_dp .and. us > 0.0_dp)
    w = summary%class_weight
    where (w <= 0) w = [6, 5, 1]
    do k = 1, n_cost_class
      if (summary%class_calls(k) > 0.0_dp .and. us(k) > 0.0_dp .and. cheapest > 0.0_dp .and. &
          cheapest < huge(1.0_dp)) w(k) = max(1, nint(us(k) / cheapest))
    end do
  end subroutine element_costs

  !> The log line of the element costs (element_costs), when any element was called.
  subroutine cost_line(out, summary)
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    character(len=300) :: line
    real(dp) :: us(n_cost_class)
    integer :: w(n_cost_class)
    if (all(summary%class_calls <= 0.0_dp)) return
    call element_costs(summary, us, w)
    write (line, '(a,3(f10.2,a,es9.2,a),3(i0,a))') 'element cost measured (us per call, calls): UMAT continuum ', &
      us(1), ' (', summary%class_calls(1), '), elastic continuum ', us(2), ' (', summary%class_calls(2), &
      '), user element ', us(3), ' (', summary%class_calls(3), '); as partition weights: --element-weights ', &
      w(1), ',', w(2), ',', w(3), ''
    call output_log(out, trim(line))
  end subroutine cost_line

  !> The energy balance: |W_ext - (stored + dissipated)| relative to the larger of the two; not available when the
  !> routines returned no energy (stored + dissipated 0 against a nonzero work).
  pure subroutine energy_balance(summary, rel, available)
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    real(dp), intent(out) :: rel                   !< the relative difference (0 when not available)
    logical, intent(out) :: available              !< the routines returned energies
    available = .not. (summary%e_int == 0.0_dp .and. summary%w_ext /= 0.0_dp)
    rel = 0.0_dp
    if (available) rel = abs(summary%w_ext - summary%e_int) / &
      max(abs(summary%w_ext), abs(summary%e_int), tiny(1.0_dp))
  end subroutine energy_balance

  !> The closing summary of the log: counters, times, memory, energy balance and accuracy indicators.
  subroutine run_summary_write(out, summary)
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    character(len=200) :: line
    real(dp) :: err
    logical :: available
    call output_log(out, '')
    call output_log(out, '=== ldfcz summary ===')
    write (line, '(a,i0,a,i0,a,i0,a,i0,a,i0)') 'increments ', summary%increments, ', attempts ', &
      summary%attempts, ', cutbacks ', summary%cutbacks, ', Newton iterations ', summary%iterations, &
      ', factorizations ', summary%factorizations
    call output_log(out, trim(line))
    write (line, '(a,i0,a,i0)') 'DOFs ', summary%ndof, ', free equations ', summary%neq
    call output_log(out, trim(line))
    write (line, '(3a,i0,a,i0,a,i0,a,i0,a,i0)') 'Newton ', trim(newton_mode_name(summary%newton)), &
      ': solves with reused factors ', summary%reused_solves, ', GMRES solves ', summary%krylov_solves, &
      ' (', summary%krylov_iterations, ' GMRES iterations, ', summary%krylov_failures, &
      ' refactorized), accuracy cutbacks ', summary%accuracy_cutbacks
    call output_log(out, trim(line))
    write (line, '(a,f10.3,a,f10.3,a)') 'wall time ', summary%wall, ' s, CPU time ', summary%cpu, ' s'
    call output_log(out, trim(line))
    write (line, '(a,4(f10.3,a))') 'wall time split: assembly ', summary%t_assembly, ' s, factorization ', &
      summary%t_factor, ' s, solve ', summary%t_solve, ' s, output ', summary%t_output, ' s'
    call output_log(out, trim(line))
    if (summary%t_factor_beside > 0.0_dp) then
      write (line, '(a,f10.3,a,f10.3,a)') 'pipelined factorizations: ', summary%t_factor_beside, &
        ' s of the factorization time on a thread of their own beside GMRES and the element loop, ', &
        summary%t_factor_wait, ' s of the solve time waited for them'
      call output_log(out, trim(line))
    end if
    write (line, '(a,f10.3,a,i0,a,es10.3)') 'solver setup (pattern, METIS ordering, MUMPS analysis) ', &
      summary%t_analysis, ' s, entries in the last factors ', summary%factor_entries, ', flops of the last ', &
      summary%factor_flops
    call output_log(out, trim(line))
    if (summary%nranks > 1) then
      write (line, '(a,i0,a,f10.3,a,i0,a)') 'MPI processes ', summary%nranks, ', communication of the host ', &
        summary%t_comm, ' s (rank 0; MUMPS'' own is in factorization and solve), peak memory of a process ', &
        summary%peak_kb_max, ' kB'
      call output_log(out, trim(line))
    end if
    if (summary%nranks > 1) then
      write (line, '(a,f10.3,a,f10.3,a,f6.3,a,3(i0,a))') 'element loop per process: max ', &
        summary%t_assembly_max, ' s, mean ', summary%t_assembly_mean, ' s, max/mean ', &
        summary%t_assembly_max / max(summary%t_assembly_mean, tiny(1.0_dp)), ' (partition weights ', &
        summary%class_weight(1), ',', summary%class_weight(2), ',', summary%class_weight(3), ')'
      call output_log(out, trim(line))
      write (line, '(a,f10.3,a,f6.3,a)') 'element loop, slowest process of each loop summed: ', &
        summary%t_assembly_slowest, ' s, against the mean ', &
        summary%t_assembly_slowest / max(summary%t_assembly_mean, tiny(1.0_dp)), &
        ' (the imbalance loop by loop: what the processes wait for at the force reduction)'
      call output_log(out, trim(line))
      write (line, '(a,f10.3,a,f10.3,a)') 'host communication of rank 0: waiting for the slowest process at the '// &
        'end of element loops ', summary%t_loop_wait, ' s, reductions, gathers and broadcasts ', &
        max(summary%t_comm - summary%t_loop_wait, 0.0_dp), ' s'
      call output_log(out, trim(line))
    end if
    call cost_line(out, summary)
    write (line, '(a,i0,a)') 'peak memory (VmHWM) ', summary%peak_kb, ' kB'
    call output_log(out, trim(line))
    ! energy balance: external work of the reactions against stored + dissipated energy, relative difference
    call energy_balance(summary, err, available)
    if (.not. available) then
      ! no routine filled SSE/SPD (UMAT) or ENERGY (UEL): there is nothing to balance, not a 100 % imbalance
      write (line, '(a,es12.4,a)') 'energy balance: external work ', summary%w_ext, &
        ' N mm; stored + dissipated energy not available (the user routines returned no SSE/SPD or ENERGY)'
    else
      write (line, '(a,es12.4,a,es12.4,a,es10.2)') 'energy balance: external work ', summary%w_ext, &
        ' N mm, stored + dissipated ', summary%e_int, ' N mm, relative difference ', err
    end if
    call output_log(out, trim(line))
    if (summary%max_open_ratio > 0.0_dp) then
      write (line, '(a,es10.3,a)') 'largest cohesive opening increment / delta ', summary%max_open_ratio, &
        merge(' (<= 1/3: >= 99% of phi dissipated, paper section 7)  ', &
              ' (> 1/3: may dissipate < 99% of phi, paper section 7) ', summary%max_open_ratio <= 1.0_dp / 3.0_dp)
      call output_log(out, trim(line))
    end if
    if (summary%plastic_statev > 0) then
      write (line, '(a,i0,a,es10.3)') 'largest plastic strain increment of the material (STATEV ', &
        summary%plastic_statev, ') ', summary%max_statev_inc
      call output_log(out, trim(line))
    end if
  end subroutine run_summary_write

  !> Largest change of the cohesive opening |Delta| over its length scale, for the user element types that declare
  !> both in their SVARS layout ('**LDFCZ SVARS, ..., OPENING=, LENGTH PROPERTY=', docs/uel.md).
  subroutine cohesive_ratio(model, an, worst)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< trial and converged element states
    real(dp), intent(inout) :: worst               !< raised to the largest ratio found
    integer :: ie, iu, ip, ipr, j
    real(dp) :: delta
    type(parallel_t) :: par
    do ie = 1, model%nelem
      if (model%elem_kind(ie) /= etype_user .or. .not. an%owned(ie)) cycle
      iu = model%elem_utype(ie)
      associate (ut => model%utypes(iu))
        if (ut%sv_points == 0 .or. ut%sv_opening == 0 .or. ut%sv_length_prop == 0) cycle
        if (size(an%work%trial(ie)%svars) < ut%sv_points * ut%sv_per_point) cycle
        ipr = model%elem_uelprop(ie)
        if (ipr == 0) cycle
        if (size(model%uelprops(ipr)%props) < ut%sv_length_prop) cycle
        delta = model%uelprops(ipr)%props(ut%sv_length_prop)
        if (delta <= 0.0_dp) cycle
        do ip = 1, ut%sv_points
          j = ut%sv_per_point * (ip - 1) + ut%sv_opening
          worst = max(worst, abs(an%work%trial(ie)%svars(j) - an%state%conv(ie)%svars(j)) / delta)
        end do
      end associate
    end do
    par = an%par
    worst = parallel_max(par, worst)   ! over the processes' elements (distributed run)
  end subroutine cohesive_ratio

  !> Largest increment of STATEV(k) over the integration points of the continuum elements (a documented
  !> convention: STATEV(7) is gamma_p of the built-in UMAT, docs/umat.md; --plastic-statev chooses another).
  subroutine statev_increment(model, an, k, worst)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< trial and converged element states
    integer, intent(in) :: k                       !< the STATEV
    real(dp), intent(inout) :: worst               !< raised to the largest increment found
    integer :: ie
    type(parallel_t) :: par
    do ie = 1, model%nelem
      if (model%elem_kind(ie) == etype_user .or. .not. an%owned(ie)) cycle
      if (.not. allocated(an%work%trial(ie)%statev)) cycle
      if (size(an%work%trial(ie)%statev, 1) < k .or. size(an%state%conv(ie)%statev, 1) < k) cycle
      worst = max(worst, maxval(abs(an%work%trial(ie)%statev(k, :) - an%state%conv(ie)%statev(k, :))))
    end do
    par = an%par
    worst = parallel_max(par, worst)   ! over the processes' elements (distributed run)
  end subroutine statev_increment

  !> Peak resident memory (VmHWM of /proc/self/status) in kB, 0 when unknown.
  integer function peak_memory_kb() result(kb)
    integer :: u, ios, k
    character(len=256) :: line
    kb = 0
    open (newunit=u, file='/proc/self/status', status='old', action='read', iostat=ios)
    if (ios /= 0) return
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:6) == 'VmHWM:') then
        k = index(line, 'kB')
        if (k > 0) read (line(7:k - 1), *, iostat=ios) kb
        exit
      end if
    end do
    close (u)
  end function peak_memory_kb

end module run_summary
