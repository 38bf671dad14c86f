!> The increment engine of a static (NLGEOM) analysis, in the phases of Abaqus/Standard's description of a
!> nonlinear step (steps are broken into increments; an increment is found by Newton iterations; an attempt that
!> fails is abandoned and retried with a smaller increment, a cutback):
!>   begin the analysis (or resume it from a restart file), begin each step (its prescribed conditions, loads and
!>   equations), and for each increment: begin it; then attempts, each one predict (the start: the converged
!>   state or its linear extrapolation; the prescribed values and loads at the end of the increment), iterate
!>   (Newton, then the accuracy bound on the cohesive opening increment of paper section 7) and, unless it
!>   converged, cut back; accept the converged one (commit, energy balance, the next increment's size), write its
!>   output, checkpoint it (restart file, UEXTERNALDB) and stop there when asked.
!> The loops are run_steps; every phase is one procedure taking the model, the options, the analysis (whose state
!> is what a continuation needs: analysis_state), the run's working data and the increment (increment) explicitly.
module static_step
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t, model_label_text
  use analysis_core, only: analysis_t, analysis_number_equations, analysis_commit, analysis_restore
  use analysis_state, only: analysis_state_step_begin, last_increment_t
  use increment, only: increment_t, increment_time, increment_end
  use boundary_table, only: boundary_prescribe, boundary_rates_update
  use step_loads, only: loads_at_end
  use linear_constraints, only: constraints_apply, constraints_reactions
  use coupling_constraints, only: coupling_check_step
  use model_change, only: model_change_release, model_change_step_begin, model_change_resume, &
    model_change_prescribable, model_change_deletion
  use step_control, only: step_control_init, step_control_cutback, step_control_converged, step_control_done, &
    step_control_dt, step_control_accuracy, step_control_exhausted, max_cutbacks
  use sparse_system, only: sparse_factor_count
  use output_files, only: output_t, output_log, output_sta, output_progress, output_frames_resume, output_sta_note
  use step_output, only: output_state_t, output_state_open, output_step_begin, write_increment_output, write_frame
  use restart_file, only: checkpoint_t, restart_write, restart_read, restart_checksum
  use user_routines, only: user_routines_t
  use solver_options, only: solver_options_t, exit_input, exit_no_convergence, newton_mode_name
  use run_summary, only: run_summary_t, run_summary_continue, cohesive_ratio, statev_increment
  use newton_iteration, only: newton_state_t, newton_solve, newton_forget_factors
  use stop_report, only: stop_message
  use cutback_log, only: cutback_log_t, cutback_log_add, cutback_log_flush
  use plane_stress_notice, only: plane_stress_umat_warnings
  use solver_text, only: itoa, rtoa
  use parallel_context, only: parallel_file, parallel_max, parallel_distributed
  use stop_signal, only: stop_signal_install, stop_signal_received, stop_signal_name
  implicit none
  private
  public :: run_steps

  integer, parameter :: extrapolated_attempts = 2       !< attempts of an increment that start extrapolated

  !> The run's working data shared by the phases (OpenFAST's "misc" variables): never checkpointed.
  type :: run_t
    logical :: verbose = .false.          !< per-iteration residual lines in the log
    type(newton_state_t) :: ns            !< Newton's state across iterations, attempts and increments
    type(output_state_t) :: os            !< output state (step_output)
    real(dp), allocatable :: r(:)         !< (max(neq, 1)) residual and correction
    real(dp), allocatable :: ratios(:)    !< r_max / q_avg of the attempt's iterations (status file)
    real(dp), allocatable :: u_carry(:)   !< (ndof) prescribed change the first iteration carries (newton_iteration)
    integer :: increments = 0             !< converged increments of this run (--stop-after-increments)
    integer :: fact_offset = 0            !< factorizations of the run before the restart point
    integer :: resume_step = 0            !< step a restart continues within (0: none)
    integer(i8) :: checksum = 0           !< restart fingerprint of the model and partition (0: not computed yet)
    real(dp) :: t_reached(2) = 0.0_dp     !< step and total time of the last converged increment (UEXTERNALDB)
    integer(i8) :: step_clock = 0         !< clock count at the start of the step (progress line)
    type(cutback_log_t) :: cutbacks       !< repeated cutbacks not yet named in JOB.log
    logical :: halt = .false.             !< the analysis ends (exit_code says why)
    integer :: exit_code = 0              !< exit status (solver_options)
  end type run_t

contains

  !> Every step of the model from the initial state of an (analysis_init done), or from opt%restart_from.
  !> summarize is false when the run ended before its first step (input error: no closing summary).
  subroutine run_steps(model, out, verbose, opt, an, summary, exit_code, fact_offset, summarize)
    type(model_t), intent(in) :: model             !< the model
    type(output_t), intent(inout) :: out           !< output files
    logical, intent(in) :: verbose                 !< per-iteration residual lines in the log
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(inout) :: exit_code            !< exit status (solver_options)
    integer, intent(out) :: fact_offset            !< factorizations of the run before the restart point
    logical, intent(out) :: summarize              !< the closing summary is due
    type(run_t) :: run
    type(increment_t) :: inc
    integer :: is
    logical :: converged
    run%verbose = verbose
    run%exit_code = exit_code
    call begin_analysis(model, opt, an, run, out, summary, is)
    summarize = .not. run%halt
    if (summarize) then
      steps: do while (is <= model%nstep)
        call begin_step(model, opt, an, run, out, summary, is)
        if (run%halt) exit steps
        increments: do while (.not. step_control_done(an%state%progress%sc))
          call begin_increment(model, an, run, out, inc)
          if (run%halt) exit steps
          attempts: do
            call predict(model, an, run, inc)
            call iterate(model, opt, an, run, out, summary, inc, converged)
            if (converged .or. run%halt) exit attempts
            call cut_back(model, an, run, out, summary, inc)
            if (run%halt) exit attempts
          end do attempts
          if (run%halt) exit steps
          call accept(model, opt, an, run, summary, inc)
          call delete_failed_elements(model, an, run, out, inc)
          if (run%halt) exit steps
          call write_output(model, an, run, out, inc)
          call checkpoint(model, opt, an, run, out, summary, inc)
          call stop_if_asked(model, opt, an, run, out, summary, inc)
          if (run%halt) exit steps
        end do increments
        call cutback_log_flush(run%cutbacks, out)
        call end_step(model, an, out, is)
        is = is + 1
      end do steps
      call cutback_log_flush(run%cutbacks, out)
      call end_analysis(model, an, run, out, is)
    end if
    exit_code = run%exit_code
    fact_offset = run%fact_offset
  end subroutine run_steps

  !> Begin the analysis: the restart file read when continuing one (everything else of the restart is resume),
  !> the requests checked, the model's lines in the log, JOB.csv and JOB.dat opened, the signal handler installed,
  !> UEXTERNALDB called (LOP 0, or 4 when continuing) and the initial frame written. is_first: the step to begin.
  subroutine begin_analysis(model, opt, an, run, out, summary, is_first)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(out) :: is_first               !< the step to begin (past the last: none)
    type(checkpoint_t) :: ck
    logical :: restarting
    integer :: stat
    character(len=:), allocatable :: errmsg
    is_first = 1
    restarting = .false.
    if (allocated(opt%restart_from)) restarting = len(opt%restart_from) > 0
    if (restarting) then
      call read_checkpoint(model, opt, an, run, ck, stat, errmsg)
      if (stat /= 0) then
        call halt_on_error(out, run, errmsg, exit_input)
        return
      end if
      run%os%marks = ck%marks
    end if
    call check_requests(model, an, run, out)
    if (run%halt) return
    call log_model(model, an, out, summary)
    call check_bounds(model, opt, run, out, summary)
    if (run%halt) return
    call output_state_open(run%os, model, out, restarting, stat, errmsg)
    if (stat /= 0) then
      call halt_on_error(out, run, errmsg, exit_input)
      return
    end if
    call stop_signal_install()
    if (restarting) then
      call resume(model, opt, an, run, out, summary, ck, is_first)
    else
      ! a user library's UEXTERNALDB: start of the analysis
      call external_db(an%routines, 0, 0, [0.0_dp, 0.0_dp], 0.0_dp, 0, 0)
      if (any(model%steps(1:model%nstep)%field_output)) call write_frame(run%os, out, model, an, 0.0_dp, &
        findloc(model%steps(1:model%nstep)%field_output, .true., 1))
    end if
  end subroutine begin_analysis

  !> The restart file of this process into the checkpoint record ck and the analysis state, for the model and
  !> partition of this run; every process fails alike when one cannot read its file (distributed run).
  subroutine read_checkpoint(model, opt, an, run, ck, stat, errmsg)
    type(model_t), intent(in) :: model                   !< the model
    type(solver_options_t), intent(in) :: opt            !< solver choices (the restart file)
    type(analysis_t), intent(inout) :: an                !< the analysis (its state replaced)
    type(run_t), intent(inout) :: run                    !< the run's working data
    type(checkpoint_t), intent(out) :: ck                !< the checkpoint's record
    integer, intent(out) :: stat                         !< 0 ok, 2 refused
    character(len=:), allocatable, intent(out) :: errmsg !< message
    ck%nnode = model%nnode
    ck%nelem = model%nelem
    ck%ndof = an%ndof
    ! a distributed run: the partition too (a restart needs the same, else elements' states are elsewhere)
    run%checksum = ieor(restart_checksum(model), an%partition_sig)
    ck%checksum = run%checksum
    call restart_read(parallel_file(an%par, opt%restart_from), ck, an%state, stat, errmsg)
    if (nint(parallel_max(an%par, real(stat, dp))) /= 0 .and. stat == 0) then
      stat = 2
      errmsg = parallel_file(an%par, opt%restart_from)//': another process could not read its restart file'
    end if
    if (stat == 0 .and. an%state%progress%step > model%nstep) then
      stat = 2
      errmsg = opt%restart_from//': the restart file is of step '//itoa(an%state%progress%step)//' but the deck has '// &
        itoa(model%nstep)//' steps'
    end if
  end subroutine read_checkpoint

  !> Continue from the checkpoint read: the working data from the analysis state, the summary counters, the VTU
  !> frames, the step to continue (the next one when the restart point ended its step), UEXTERNALDB's LOP 4.
  subroutine resume(model, opt, an, run, out, summary, ck, is_first)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices (the restart file)
    type(analysis_t), intent(inout) :: an          !< the analysis (state read)
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    type(checkpoint_t), intent(in) :: ck           !< the checkpoint's record
    integer, intent(out) :: is_first               !< the step to continue
    real(dp) :: t_point(2)
    associate (p => an%state%progress)
      t_point = [p%sc%t, p%t_total0 + p%sc%t]
      an%work%u = an%state%u_conv
      an%work%trial = an%state%conv
      call model_change_resume(an, model)
      run%ns%reuse_count = p%reuse_count
      run%fact_offset = ck%summary%factorizations
      call run_summary_continue(summary, ck%summary)
      call output_frames_resume(out, ck%frame_times)
      is_first = p%step
      run%resume_step = p%step
      if (p%sc%t >= p%sc%period) then
        ! the restart point ended step p%step: the next step starts as in the uninterrupted run
        is_first = p%step + 1
        p%t_total0 = p%t_total0 + model%steps(p%step)%period
        run%resume_step = 0
      end if
      call output_sta_note(out, 'restart from '//opt%restart_from//' after step '//itoa(p%step)//' increment '// &
        itoa(p%kinc))
      call output_log(out, 'ldfcz: restart from '//opt%restart_from//': step '//itoa(p%step)//', increment '// &
        itoa(p%kinc)//', total time '//rtoa(t_point(2))//'; '//itoa(run%os%marks%csv_rows)//' CSV rows and '// &
        itoa(size(ck%frame_times))//' VTU frames kept; summary counters continue, times are of this run only')
      call external_db(an%routines, 4, 0, t_point, 0.0_dp, p%step, p%kinc)
    end associate
  end subroutine resume

  !> What the deck asks that needs a user routine: *BOUNDARY, USER needs DISP.
  subroutine check_requests(model, an, run, out)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    integer :: i, k
    if (associated(an%routines%disp)) return
    do i = 1, model%nstep
      do k = 1, model%steps(i)%nbc
        if (.not. model%steps(i)%bcs(k)%user) cycle
        call halt_on_error(out, run, model%steps(i)%bcs(k)%pos%file//':'//itoa(model%steps(i)%bcs(k)%pos%line)// &
          ': *BOUNDARY: USER needs the user subroutine DISP: give a file defining it with --user FILE', exit_input)
        return
      end do
    end do
  end subroutine check_requests

  !> The model's lines in the log: size and solver, plane-stress notices, the part instances' label offsets.
  subroutine log_model(model, an, out, summary)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< the analysis
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures (dofs)
    character(len=:), allocatable :: msg
    character(len=512), allocatable :: notes(:)
    integer :: k
    msg = ''
    if (an%eqs%factoring%symmetric_part .and. .not. an%symmetric) &
      msg = ' (LDL^T factors of (K+K^T)/2 precondition GMRES)'
    if (an%eqs%factoring%single) msg = msg//' (single-precision factors precondition GMRES)'
    call output_log(out, 'ldfcz: '//itoa(model%nnode)//' nodes, '//itoa(model%nelem)//' elements, '// &
      itoa(summary%ndof)//' dofs, '//merge('symmetric  ', 'unsymmetric', an%symmetric)//' solver'//msg// &
      '; UEL: '//an%routines%uel_origin//'; UMAT: '//an%routines%umat_origin)
    ! plane-stress elements with a UMAT under NLGEOM: the inferred thickness, said loudly (log and standard error)
    call plane_stress_umat_warnings(model, an, notes)
    do k = 1, size(notes)
      call output_log(out, trim(notes(k)))
      if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') trim(notes(k))
    end do
    ! the label map of flattened part instances (output and messages use the model labels)
    do k = 1, model%ninstance
      associate (in => model%instances(k))
        call output_log(out, 'ldfcz: instance '//trim(in%name)//' of part '//trim(in%part)//': model label = '// &
          'part label + '//itoa(in%node_offset)//' (nodes, up to '//itoa(in%node_last)//'), + '// &
          itoa(in%elem_offset)//' (elements, up to '//itoa(in%elem_last)//')')
      end associate
    end do
  end subroutine log_model

  !> The accuracy bounds and the plastic-strain report need what they read declared (docs/umat.md, docs/uel.md).
  subroutine check_bounds(model, opt, run, out, summary)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures (Newton variant, STATEV reported)
    summary%newton = opt%newton
    summary%plastic_statev = opt%plastic_statev
    if (summary%plastic_statev < 0) then
      ! the STATEV a material declares as its equivalent plastic strain ('**LDFCZ STATEV', docs/umat.md), if any
      summary%plastic_statev = 0
      if (model%nmat > 0) summary%plastic_statev = maxval(model%materials(1:model%nmat)%plastic_statev)
    end if
    if (model%nmat > 0) then
      if (all(model%materials(1:model%nmat)%has_elastic)) summary%plastic_statev = 0
    else
      summary%plastic_statev = 0
    end if
    if (opt%max_plastic > 0.0_dp .and. summary%plastic_statev == 0) then
      call halt_on_error(out, run, '--max-plastic-increment needs a UMAT material that declares its equivalent '// &
        'plastic strain (**LDFCZ STATEV, PLASTIC STRAIN=n; docs/umat.md) or --plastic-statev N', exit_input)
      return
    end if
    if (opt%max_opening > 0.0_dp .and. .not. any(model%utypes(1:model%nutype)%sv_opening > 0 .and. &
        model%utypes(1:model%nutype)%sv_length_prop > 0)) then
      call halt_on_error(out, run, '--max-opening-increment needs a user element type that declares its '// &
        'opening and length scale (**LDFCZ SVARS, ..., OPENING=, LENGTH PROPERTY=; docs/uel.md)', exit_input)
      return
    end if
    if (opt%max_opening > 0.0_dp) then
      call output_log(out, 'ldfcz: Newton '//trim(newton_mode_name(opt%newton))//'; increments limited to a '// &
        'cohesive opening increment <= '//rtoa(opt%max_opening)//' delta')
    else
      call output_log(out, 'ldfcz: Newton '//trim(newton_mode_name(opt%newton)))
    end if
  end subroutine check_bounds

  !> Begin step is (unless a restart continues within it): its prescribed conditions and loads (analysis_state),
  !> the equations of its free dofs, the increment control and output marks; the step's line in the log.
  subroutine begin_step(model, opt, an, run, out, summary, is)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(in) :: is                      !< the step
    logical :: resumed
    integer :: stat
    character(len=:), allocatable :: errmsg
    associate (st => model%steps(is), p => an%state%progress)
      resumed = is == run%resume_step
      if (.not. resumed) then
        call analysis_state_step_begin(an%state, model, is, stat, errmsg)
        if (stat /= 0) then
          call halt_on_error(out, run, errmsg, exit_input)
          return
        end if
        call model_change_step_begin(an, model, is)
      end if
      call coupling_check_step(model, is, an%state%bc, an%state%loads, stat, errmsg)
      if (stat /= 0) then
        call halt_on_error(out, run, errmsg, exit_input)
        return
      end if
      an%eqs%prescribed = an%state%bc%on .and. model_change_prescribable(an, model)
      call analysis_number_equations(an, model, stat, errmsg)
      if (stat /= 0) then
        call halt_on_error(out, run, 'step '//itoa(is)//': '//errmsg, exit_input, echo=.false.)
        return
      end if
      summary%neq = an%eqs%neq
      if (allocated(run%r)) deallocate (run%r)
      allocate (run%r(max(an%eqs%neq, 1)))
      if (resumed) then
        ! restart within this step: increment control, q_avg history and output marks as they were
        call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': resumed from '//opt%restart_from// &
          ' after increment '//itoa(p%kinc)//' at step time '//rtoa(p%sc%t)//' of '//rtoa(st%period)//', '// &
          itoa(an%eqs%neq)//' equations')
      else
        call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': period '//rtoa(st%period)// &
          ', NLGEOM '//merge('YES', 'NO ', st%nlgeom)//', '//itoa(an%eqs%neq)//' equations')
        call step_control_init(p%sc, st%dt_initial, st%period, st%dt_min, st%dt_max, st%direct)
        p%step = is
        p%kinc = 0
        p%q_sum = 0.0_dp
        an%state%last%dt = 0.0_dp  ! Abaqus: no extrapolation into the first increment of a step
        an%state%last%dt_before = 0.0_dp
        call output_step_begin(run%os, st)
      end if
    end associate
    call system_clock(run%step_clock)
  end subroutine begin_step

  !> Begin the next increment of the step (INC= of *STEP bounds their number).
  subroutine begin_increment(model, an, run, out, inc)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(increment_t), intent(out) :: inc          !< the increment
    associate (p => an%state%progress, st => model%steps(an%state%progress%step))
      p%kinc = p%kinc + 1
      if (p%kinc > st%max_inc) then
        call output_log(out, 'ldfcz: step '//itoa(p%step)//': the maximum number of increments (INC='// &
          itoa(st%max_inc)//') is reached before the end of the step')
        run%exit_code = exit_no_convergence
        run%halt = .true.
        return
      end if
      inc = increment_t(step=p%step, kinc=p%kinc, t_total0=p%t_total0, period=st%period, nlgeom=st%nlgeom)
    end associate
  end subroutine begin_increment

  !> Predict the next attempt: its size (step_control), UEXTERNALDB's LOP 1, the start (the converged state, or
  !> with *STEP, EXTRAPOLATION=LINEAR, Abaqus' default, the last converged increment's change scaled to this one, or
  !> PARABOLIC, the quadratic through the last two: extrapolate); a failed extrapolated start is retried once, then from the converged state), the prescribed values at the end
  !> of the increment (what they add to the start, the first Newton iteration carries through the tangent) and the
  !> loads and predefined fields there.
  subroutine predict(model, an, run, inc)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(increment_t), intent(inout) :: inc        !< the increment
    associate (s => an%state, st => model%steps(inc%step))
      inc%attempt = inc%attempt + 1
      inc%t_step = s%progress%sc%t
      if (allocated(st%cut_points)) then
        inc%dt = step_control_dt(s%progress%sc, st%cut_points)
      else
        inc%dt = step_control_dt(s%progress%sc)
      end if
      inc%iter = 0
      inc%cause = ''
      call external_db(an%routines, 1, 0, increment_time(inc), inc%dt, inc%step, inc%kinc)
      an%work%u = s%u_conv
      inc%extrapolated = st%extrapolate .and. s%last%dt > 0.0_dp .and. inc%attempt <= extrapolated_attempts
      if (inc%extrapolated) call extrapolate(s%last, st%parabolic, inc%dt, s%u_conv, an%work%u)
      if (an%eqs%cs%n > 0) call constraints_apply(an%eqs%cs, an%work%u)
      run%u_carry = an%work%u
      call boundary_prescribe(s%bc, model, inc, s%u_conv, an%nr, an%routines, an%eqs%prescribed, an%work%u)
      if (an%eqs%cs%n > 0) call constraints_apply(an%eqs%cs, an%work%u)
      run%u_carry = an%work%u - run%u_carry
      call loads_at_end(s%loads, model, inc, an%work%fext, an%work%temp_end, an%work%field_end)
    end associate
  end subroutine predict

  !> The extrapolated start u of an increment of size dt from the converged u_conv (*STEP, EXTRAPOLATION): the last
  !> increment's change scaled to dt (LINEAR); with PARABOLIC and an increment before it in the step, the quadratic
  !> in time through the last three converged states, u_conv + h d1/h1 + h (h + h1) (d1/h1 - d0/h0) / (h1 + h0) (d1,
  !> h1: the last change and size, d0, h0: the one before; Newton's divided differences), else linear.
  pure subroutine extrapolate(last, parabolic, dt, u_conv, u)
    type(last_increment_t), intent(in) :: last     !< the last converged increments
    logical, intent(in) :: parabolic               !< EXTRAPOLATION=PARABOLIC
    real(dp), intent(in) :: dt                     !< size of the increment
    real(dp), intent(in) :: u_conv(:)              !< converged displacement
    real(dp), intent(out) :: u(:)                  !< the start
    u = u_conv + (dt / last%dt) * last%du
    if (parabolic .and. last%dt_before > 0.0_dp) u = u + dt * (dt + last%dt) / (last%dt + last%dt_before) * &
      (last%du / last%dt - last%du_before / last%dt_before)
  end subroutine extrapolate

  !> Iterate: Newton from the predicted start (newton_iteration); a converged attempt whose cohesive opening
  !> increment exceeds --max-opening-increment (paper section 7) is rejected; a stop asked by a user routine ends
  !> the analysis. The status line of a converged attempt.
  subroutine iterate(model, opt, an, run, out, summary, inc, converged)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    type(increment_t), intent(inout) :: inc        !< the increment
    logical, intent(out) :: converged              !< the attempt converged and is accepted
    real(dp) :: q_now
    logical :: stopped, redo
    associate (p => an%state%progress, st => model%steps(inc%step))
      summary%attempts = summary%attempts + 1
      call newton_solve(an, model, inc, opt%newton, run%verbose, out, run%ns, summary, run%r, run%ratios, p%q_sum, &
        converged, stopped, q_now, run%u_carry)
      if (stopped) then
        call output_sta(out, inc%step, inc%kinc, inc%attempt, inc%iter, increment_end(inc), inc%dt, &
          'stopped: XIT/STDB_ABQERR in a user routine')
        call halt_on_error(out, run, stop_message(model, an%work%stop%elem, an%work%stop%text, inc%step, inc%kinc), &
          exit_input, status_line=.false.)
        if (parallel_distributed(an%par)) call output_log(out, 'ldfcz: the element is computed by process '// &
          itoa(an%work%stop%rank)//' of '//itoa(an%par%nranks)//'; every process stopped')
        converged = .false.
        return
      end if
      summary%iterations = summary%iterations + inc%iter
      inc%opening = 0.0_dp
      if (converged .and. opt%max_opening > 0.0_dp .and. .not. st%direct) then
        ! accuracy: the cohesive opening increment bound (paper section 7); redo the increment if exceeded
        call cohesive_ratio(model, an, inc%opening)
        call step_control_accuracy(p%sc, inc%dt, inc%opening, opt%max_opening, redo, inc%pnewdt)
        if (redo) then
          converged = .false.
          p%q_sum = p%q_sum - q_now
          inc%cause = 'cutback: opening increment '//rtoa(inc%opening)//' delta'
          summary%accuracy_cutbacks = summary%accuracy_cutbacks + 1
        end if
      end if
      if (.not. converged) return
      if (model%monitor_node > 0) then
        ! *MONITOR: the dof's displacement at the end of the increment, on the converged line
        call output_sta(out, inc%step, inc%kinc, inc%attempt, inc%iter, increment_end(inc), inc%dt, &
          'converged  monitor U'//itoa(model%monitor_dof)//' '// &
          rtoa(an%work%u((model%monitor_node - 1) * model%ndim + model%monitor_dof)), run%ratios(1:inc%iter + 1))
      else
        call output_sta(out, inc%step, inc%kinc, inc%attempt, inc%iter, increment_end(inc), inc%dt, 'converged', &
          run%ratios(1:inc%iter + 1))
      end if
    end associate
  end subroutine iterate

  !> Cut back after a failed attempt: its status line, back to the converged state, the smaller increment
  !> (step_control: 0.25, or the PNEWDT asked for); the analysis ends below the minimum increment, after
  !> max_cutbacks cutbacks of one increment or with DIRECT (fixed) increments.
  subroutine cut_back(model, an, run, out, summary, inc)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    type(increment_t), intent(in) :: inc           !< the failed attempt
    logical :: ok
    character(len=:), allocatable :: head
    call newton_forget_factors(run%ns)
    call output_sta(out, inc%step, inc%kinc, inc%attempt, inc%iter, increment_end(inc), inc%dt, trim(inc%cause), &
      run%ratios(1:min(inc%iter + 1, size(run%ratios))))
    call analysis_restore(an)
    associate (p => an%state%progress, st => model%steps(inc%step))
      call step_control_cutback(p%sc, inc%dt, inc%pnewdt, ok)
      call summary%add_cutback(inc%step, inc%cause)
      call cutback_log_add(run%cutbacks, out, inc%step, inc%kinc, inc%attempt, inc%cause, inc%dt, p%sc%dt, run%verbose)
      if (ok .and. .not. step_control_exhausted(p%sc)) return
      call cutback_log_flush(run%cutbacks, out)
      head = 'ldfcz: step '//itoa(inc%step)//' increment '//itoa(inc%kinc)//': no convergence'
      if (st%direct) then
        call output_log(out, head//' with DIRECT (fixed) increments ('//trim(inc%cause)//')')
      else if (.not. ok) then
        call output_log(out, head//'; the increment '//rtoa(p%sc%dt)//' would be below the minimum '// &
          rtoa(st%dt_min)//' ('//trim(inc%cause)//')')
      else
        call output_log(out, head//' after '//itoa(max_cutbacks)//' cutbacks ('//trim(inc%cause)//')')
      end if
      call output_log(out, 'ldfcz: the analysis stopped at step time '//rtoa(p%sc%t)//' of '//rtoa(st%period)// &
        '; the output of the converged increments is complete')
    end associate
    run%exit_code = exit_no_convergence
    run%halt = .true.
  end subroutine cut_back

  !> Accept the converged increment: the largest opening and plastic increments, the work of the external forces
  !> and reactions, the trial state committed, the predefined fields and velocities reached, the next increment's
  !> size (step_control: growth, PNEWDT, accuracy bounds).
  subroutine accept(model, opt, an, run, summary, inc)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    type(increment_t), intent(in) :: inc           !< the converged increment
    real(dp) :: plastic_inc
    call cohesive_ratio(model, an, summary%max_open_ratio)
    plastic_inc = 0.0_dp
    if (summary%plastic_statev > 0) then
      call statev_increment(model, an, summary%plastic_statev, plastic_inc)
      summary%max_statev_inc = max(summary%max_statev_inc, plastic_inc)
    end if
    ! the reactions at prescribed masters of constraints include what their slaves carry
    if (an%eqs%cs%n > 0) call constraints_reactions(an%eqs%cs, an%eqs%prescribed, an%work%fext, an%work%fdl, &
      an%work%fint)
    call work_of_increment(an, inc, summary%w_ext)
    call analysis_commit(an)
    an%state%temp_start = an%work%temp_end
    an%state%field_start = an%work%field_end
    call boundary_rates_update(an%state%bc, model, inc)
    ! (an increment shortened to end on a time point: sc%dt is still the size before that cut)
    call step_control_converged(an%state%progress%sc, inc%dt, inc%iter, inc%pnewdt, inc%opening, opt%max_opening, &
      plastic_inc, opt%max_plastic, clipped=allocated(model%steps(inc%step)%cut_points) .and. &
      inc%dt < an%state%progress%sc%dt)
    ! the forces of the elements the next step removes (*MODEL CHANGE), from this last increment's element forces
    if (step_control_done(an%state%progress%sc)) call model_change_release(an, model, inc%step)
    call summary%add_increment(inc%step, inc%kinc, an%state%progress%t_total0 + an%state%progress%sc%t, &
      step_control_done(an%state%progress%sc))
    an%state%progress%kinc_total = an%state%progress%kinc_total + 1
    run%increments = run%increments + 1
  end subroutine accept

  !> After the converged increment: the elements whose material's deletion variable (*DEPVAR, DELETE=) is 0 at
  !> every point leave the model (model_change_deletion), said in the log; the equations follow.
  subroutine delete_failed_elements(model, an, run, out, inc)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(increment_t), intent(in) :: inc           !< the converged increment
    integer :: ndel, first, stat
    character(len=:), allocatable :: errmsg
    call model_change_deletion(an, model, ndel, first)
    if (ndel == 0) return
    call output_log(out, 'ldfcz: step '//itoa(inc%step)//' increment '//itoa(inc%kinc)//': '//itoa(ndel)// &
      ' element(s) deleted, their *DEPVAR, DELETE= state variable 0 at every point (element '// &
      model_label_text(model, first, .false.)//trim(merge(' and others', '           ', ndel > 1))//')')
    an%eqs%prescribed = an%state%bc%on .and. model_change_prescribable(an, model)
    call analysis_number_equations(an, model, stat, errmsg)
    if (stat /= 0) then
      call halt_on_error(out, run, 'step '//itoa(inc%step)//': '//errmsg, exit_input, echo=.false.)
      return
    end if
    if (allocated(run%r)) deallocate (run%r)
    allocate (run%r(max(an%eqs%neq, 1)))
    call newton_forget_factors(run%ns)   ! the tangent lost the deleted elements' stiffness
  end subroutine delete_failed_elements

  !> The work of the reactions (trapezoidal) and of the external forces on the free dofs over the converged
  !> increment, and what the next increment takes from it (an%state%last), before the commit.
  subroutine work_of_increment(an, inc, w_ext)
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(increment_t), intent(in) :: inc           !< the converged increment
    real(dp), intent(inout) :: w_ext               !< external work so far
    integer :: i
    associate (last => an%state%last, w => an%work, u_conv => an%state%u_conv, prescribed => an%eqs%prescribed)
      do i = 1, an%ndof
        if (prescribed(i)) then
          w_ext = w_ext + 0.5_dp * (last%rf(i) + w%fint(i) - w%fext(i) - w%fdl(i)) * (w%u(i) - u_conv(i))
        else
          w_ext = w_ext + 0.5_dp * (last%fext(i) + w%fext(i) + w%fdl(i)) * (w%u(i) - u_conv(i))
        end if
      end do
      where (prescribed)
        last%rf = w%fint - w%fext - w%fdl
      elsewhere
        last%rf = 0.0_dp
      end where
      last%fext = w%fext + w%fdl
      last%fcl = w%fext
      last%du_before = last%du
      last%dt_before = last%dt
      last%du = w%u - u_conv
      last%dt = inc%dt
    end associate
  end subroutine work_of_increment

  !> Write the output of the converged increment (step_output) and the progress line.
  subroutine write_output(model, an, run, out, inc)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(increment_t), intent(in) :: inc           !< the converged increment
    integer(i8) :: c1, rate
    call write_increment_output(run%os, out, model, an, inc)
    call system_clock(c1, rate)
    call output_progress(out, inc%step, model%nstep, inc%kinc, an%state%progress%sc%t, model%steps(inc%step)%period, &
      real(c1 - run%step_clock, dp) / real(rate, dp))
  end subroutine write_output

  !> Checkpoint: the restart file after every n-th increment of the step and its last (Abaqus *RESTART, WRITE,
  !> FREQUENCY=n; --restart-write), then UEXTERNALDB's LOP 2 (LRESTART 1 when the file was written).
  subroutine checkpoint(model, opt, an, run, out, summary, inc)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    type(increment_t), intent(in) :: inc           !< the converged increment
    integer :: k, lrestart
    k = restart_frequency(model, opt, inc%step)
    lrestart = 0
    if (k > 0) then
      if (mod(inc%kinc, k) == 0 .or. step_control_done(an%state%progress%sc)) then
        call save_checkpoint(model, an, run, out, summary)
        lrestart = 1
      end if
    end if
    run%t_reached = [an%state%progress%sc%t, an%state%progress%t_total0 + an%state%progress%sc%t]
    call external_db(an%routines, 2, lrestart, run%t_reached, inc%dt, inc%step, inc%kinc)
  end subroutine checkpoint

  !> Write the restart file (restart_file) of the state after the increment just converged and written: the
  !> analysis state whole and the record of the output marks, summary and frames.
  subroutine save_checkpoint(model, an, run, out, summary)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    type(checkpoint_t) :: ck
    integer :: stat
    character(len=:), allocatable :: errmsg
    integer(i8) :: r0, r1, rate
    call system_clock(r0, rate)
    ck%nnode = model%nnode
    ck%nelem = model%nelem
    ck%ndof = an%ndof
    if (run%checksum == 0) run%checksum = ieor(restart_checksum(model), an%partition_sig)
    ck%checksum = run%checksum
    an%state%progress%reuse_count = run%ns%reuse_count
    ck%marks = run%os%marks
    ck%summary = summary
    ck%summary%factorizations = run%fact_offset + an%timing%n_factor_done
    if (an%eqs%sys_ready) ck%summary%factorizations = ck%summary%factorizations + sparse_factor_count(an%eqs%sys)
    if (allocated(out%frame_times)) then
      ck%frame_times = out%frame_times(1:out%nframe)
    else
      allocate (ck%frame_times(0))
    end if
    call restart_write(parallel_file(an%par, out%dir//'/'//out%job//'.rst'), ck, an%state, stat, errmsg)
    if (stat /= 0) call output_log(out, 'ldfcz: warning: restart file not written: '//errmsg)
    call system_clock(r1)
    out%t_output = out%t_output + real(r1 - r0, dp) / real(rate, dp)
  end subroutine save_checkpoint

  !> Stop after the increment when asked: --stop-after-increments (exit 3), or a signal to any process (SIGTERM,
  !> SIGINT, SIGUSR1: stop_signal), which ends the run as a complete one ends, the restart file first (when restart
  !> data are written at all), so that a restart replaces the extra frame with the uninterrupted run's frames.
  subroutine stop_if_asked(model, opt, an, run, out, summary, inc)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    type(run_summary_t), intent(in) :: summary     !< counters and measures
    type(increment_t), intent(in) :: inc           !< the converged increment
    integer :: sig, k
    associate (p => an%state%progress, st => model%steps(inc%step))
      if (opt%stop_after > 0 .and. run%increments >= opt%stop_after) then
        call output_log(out, 'ldfcz: stopped after '//itoa(run%increments)//' increments as asked '// &
          '(--stop-after-increments), at step '//itoa(inc%step)//' time '//rtoa(p%sc%t)//' of '//rtoa(st%period))
        run%exit_code = exit_no_convergence
        run%halt = .true.
        return
      end if
      sig = nint(parallel_max(an%par, real(stop_signal_received(), dp)))
      if (sig == 0 .or. (inc%step == model%nstep .and. step_control_done(p%sc))) return
      call output_log(out, 'ldfcz: '//stop_signal_name(sig)//' received: stopped after increment '// &
        itoa(inc%kinc)//' of step '//itoa(inc%step)//' at step time '//rtoa(p%sc%t)//' of '//rtoa(st%period)// &
        '; the output of every converged increment is complete')
      call output_sta_note(out, 'stopped by '//stop_signal_name(sig)//' after step '//itoa(inc%step)// &
        ' increment '//itoa(inc%kinc))
      k = restart_frequency(model, opt, inc%step)
      if (k > 0) then
        if (mod(inc%kinc, k) /= 0) call save_checkpoint(model, an, run, out, summary)
      end if
      if (st%field_output) call write_frame(run%os, out, model, an, p%t_total0 + p%sc%t, inc%step)
      run%exit_code = 128 + sig
      run%halt = .true.
    end associate
  end subroutine stop_if_asked

  !> End of step is: the total time moves on by its period.
  subroutine end_step(model, an, out, is)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(inout) :: an          !< the analysis
    type(output_t), intent(inout) :: out           !< output files
    integer, intent(in) :: is                      !< the step
    an%state%progress%t_total0 = an%state%progress%t_total0 + model%steps(is)%period
    call output_log(out, 'ldfcz: step '//itoa(is)//' completed in '//itoa(an%state%progress%kinc)//' increments')
  end subroutine end_step

  !> End of the analysis (also after an error or a stop within it): UEXTERNALDB's LOP 3, JOB.dat flushed, the
  !> Newton auto counts.
  subroutine end_analysis(model, an, run, out, is)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< the analysis
    type(run_t), intent(inout) :: run              !< the run's working data
    type(output_t), intent(inout) :: out           !< output files
    integer, intent(in) :: is                      !< the step where the analysis ended (nstep + 1: completed)
    call external_db(an%routines, 3, 0, run%t_reached, 0.0_dp, min(is, model%nstep), an%state%progress%kinc)
    if (run%os%dat /= -1) flush (run%os%dat)
    if (run%ns%tangents_skipped > 0) call output_log(out, 'ldfcz: Newton auto: '//itoa(run%ns%tangents_skipped)// &
      ' iterations expected to converge assembled without a tangent, '//itoa(run%ns%stale_solves)// &
      ' of them not converged and solved with the previous iterate''s tangent (this run)')
  end subroutine end_analysis

  !> The restart frequency in effect in step is: --restart-write, else the deck's *RESTART, WRITE (0: none).
  pure integer function restart_frequency(model, opt, is) result(k)
    type(model_t), intent(in) :: model             !< the model
    type(solver_options_t), intent(in) :: opt      !< solver choices
    integer, intent(in) :: is                      !< the step
    k = model%steps(is)%restart_frequency
    if (opt%restart_write >= 0) k = opt%restart_write
  end function restart_frequency

  !> An error that ends the analysis: in the log and, when the log is not echoed (echo), on standard error.
  subroutine halt_on_error(out, run, text, code, echo, status_line)
    type(output_t), intent(inout) :: out           !< output files
    type(run_t), intent(inout) :: run              !< the run's working data
    character(len=*), intent(in) :: text           !< the message
    integer, intent(in) :: code                    !< exit status
    logical, intent(in), optional :: echo          !< also on standard error when quiet (default yes)
    !> an input error's line in JOB.sta (default yes; a user routine's stop has its own status line)
    logical, intent(in), optional :: status_line
    logical :: to_stderr, sta
    to_stderr = out%quiet .and. .not. out%silent
    if (present(echo)) to_stderr = to_stderr .and. echo
    sta = code == exit_input
    if (present(status_line)) sta = sta .and. status_line
    call output_log(out, 'ldfcz: error: '//text)
    if (sta) call output_sta_note(out, 'input error (exit status 2): '//text)
    if (to_stderr) write (error_unit, '(a)') 'ldfcz: error: '//text
    run%exit_code = code
    run%halt = .true.
  end subroutine halt_on_error

  !> Calls the user library's UEXTERNALDB, if it has one, with copies of the arguments (a routine may write to
  !> them).
  subroutine external_db(routines, lop, lrestart, tm, dtm, kstep, kinc)
    type(user_routines_t), intent(in) :: routines         !< the user library's routines
    integer, intent(in) :: lop, lrestart, kstep, kinc     !< Abaqus' LOP, LRESTART, KSTEP, KINC
    real(dp), intent(in) :: tm(2), dtm                    !< TIME (step, total), DTIME
    integer :: c_lop, c_lrestart, c_kstep, c_kinc
    real(dp) :: c_time(2), c_dtime
    if (.not. associated(routines%uexternaldb)) return
    c_lop = lop
    c_lrestart = lrestart
    c_kstep = kstep
    c_kinc = kinc
    c_time = tm
    c_dtime = dtm
    call routines%uexternaldb(c_lop, c_lrestart, c_time, c_dtime, c_kstep, c_kinc)
  end subroutine external_db

end module static_step
