!> Static (NLGEOM) steps: prescribed displacements, automatic increments (step_control) with cutbacks and growth,
!> an accuracy bound on the cohesive opening increment (paper section 7), commit on convergence, output per
!> increment (CSV, VTU frames, status) and the restart hooks (continue from a restart file, write one).
module static_step
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t, amplitude_factor
  use step_loads, only: load_state_t, load_state_init, load_step_begin, load_vector
  use distributed_loads, only: dload_step_begin
  use linear_constraints, only: constraints_apply
  use node_rotations, only: node_vector_global
  use analysis_core, only: analysis_t, analysis_number_equations, analysis_commit, analysis_restore
  use step_control, only: step_control_t, step_control_init, step_control_cutback, step_control_converged, &
    step_control_done, step_control_dt, step_control_accuracy, step_control_exhausted, max_cutbacks
  use analysis_state, only: analysis_state_t, analysis_state_init
  use sparse_system, only: sparse_factor_count
  use output_files, only: output_t, output_log, output_csv_header, output_csv_row, output_sta, output_progress, &
    output_csv_resume, output_frames_resume, output_sta_note
  use restart_file, only: restart_state_t, restart_write, restart_read, restart_checksum
  use user_routines, only: user_routines_t
  use solver_options, only: solver_options_t, exit_input, exit_no_convergence, newton_mode_name
  use run_summary, only: run_summary_t, run_summary_continue, cohesive_ratio, statev_increment
  use newton_iteration, only: newton_state_t, newton_solve, newton_forget_factors
  use field_frame, only: write_field_frame
  use history_columns, only: history_columns_t, history_columns_build, history_columns_values
  use print_tables, only: print_tables_any, print_tables_write, print_tables_elements
  use state_gather, only: gather_converged_states, release_converged_states
  use stop_report, only: stop_message
  use plane_stress_notice, only: plane_stress_umat_warnings
  use solver_text, only: itoa, rtoa
  use parallel_context, only: parallel_file, parallel_max, parallel_distributed
  use stop_signal, only: stop_signal_install, stop_signal_received, stop_signal_name
  implicit none
  private
  public :: run_steps

  integer, parameter :: extrapolated_attempts = 2       !< attempts of an increment that start extrapolated

contains

  !> Every step of the model from the initial state of an (analysis_init done), or from opt%restart_from.
  !> summarize is false when the run ended before its first step (input error: no closing summary).
  subroutine run_steps(model, routines, out, verbose, opt, an, summary, exit_code, fact_offset, summarize)
    type(model_t), intent(in) :: model             !< the model
    type(user_routines_t), intent(in) :: routines  !< UEL and UMAT
    type(output_t), intent(inout) :: out           !< output files
    logical, intent(in) :: verbose                 !< per-iteration residual lines in the log
    type(solver_options_t), intent(in) :: opt      !< solver choices
    type(analysis_t), intent(inout) :: an          !< analysis data
    type(run_summary_t), intent(inout) :: summary  !< counters and measures
    integer, intent(inout) :: exit_code            !< exit status (solver_options)
    integer, intent(out) :: fact_offset            !< factorizations of the run before the restart point
    logical, intent(out) :: summarize              !< the closing summary is due
    integer :: stat, is, attempt, iter, i, k
    character(len=:), allocatable :: errmsg, msg
    type(history_columns_t) :: cols    !< the columns of JOB.csv
    character(len=512), allocatable :: notes(:)
    integer, allocatable :: printed(:)        !< elements of the *EL PRINT tables due (gathered, then released)
    real(dp), allocatable :: r(:), ratios(:), colv(:)
    logical, allocatable :: bc_was_on(:)
    type(analysis_state_t) :: s        !< the increment loop's state (what a restart file holds)
    type(load_state_t) :: ls, ls_temp, ls_field
    real(dp), allocatable :: temp_init(:), field_init(:)
    logical :: field_comp(max(1, model%nfield))
    real(dp), allocatable :: zero_nodes(:)
    real(dp), allocatable :: u_carry(:)  !< (ndof) the prescribed change the first iteration carries (newton_iteration)
    real(dp) :: time(2), dt, pnewdt_min, q_now, t_end
    real(dp) :: open_inc, plastic_inc
    integer(i8) :: c1, rate, cs0
    type(newton_state_t) :: ns
    logical :: converged, ok, stopped, redo
    integer :: lrestart       !< UEXTERNALDB's LRESTART: 1 when restart data were written after the increment
    real(dp) :: t_reached(2)  !< step and total time of the last converged increment (UEXTERNALDB)
    character(len=64) :: outcome
    type(restart_state_t) :: rs, fp
    logical :: restarting, resumed, fresh_csv
    integer :: is_first, run_increments, sig
    integer :: dat                      !< JOB.dat unit (-1: no printed output requested)

    call system_clock(count_rate=rate)
    summarize = .false.
    restarting = .false.
    if (allocated(opt%restart_from)) restarting = len(opt%restart_from) > 0
    run_increments = 0
    fact_offset = 0
    if (restarting) then
      ! the converged state of the increment the restart file was written after (element states straight into conv)
      fp%nnode = model%nnode
      fp%nelem = model%nelem
      fp%ndof = an%ndof
      ! a distributed run: the partition too (a restart needs the same, else elements' states are elsewhere)
      fp%checksum = ieor(restart_checksum(model), an%partition_sig)
      call restart_read(parallel_file(an%par, opt%restart_from), fp, rs, an%conv, stat, errmsg)
      if (nint(parallel_max(an%par, real(stat, dp))) /= 0 .and. stat == 0) then
        ! another process could not read its restart file (distributed run): all stop alike
        stat = 2
        errmsg = parallel_file(an%par, opt%restart_from)//': another process could not read its restart file'
      end if
      if (stat == 0 .and. rs%state%step > model%nstep) then
        stat = 2
        errmsg = opt%restart_from//': the restart file is of step '//itoa(rs%state%step)//' but the deck has '// &
          itoa(model%nstep)//' steps'
      end if
      if (stat /= 0) then
        call output_log(out, 'ldfcz: error: '//errmsg)
        if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
        exit_code = exit_input
        return
      end if
    end if
    if (restarting .and. (any(model%steps(1:model%nstep)%ncload > 0) .or. &
        any(model%steps(1:model%nstep)%ndload > 0) .or. any(model%steps(1:model%nstep)%op_new) .or. &
        any(model%steps(1:model%nstep)%ntemp > 0) .or. any(model%steps(1:model%nstep)%nfielddef > 0) .or. &
        any_velocity())) then
      ! the load state (step_loads) is not in the restart file
      errmsg = opt%restart_from//': a restart of a deck with *CLOAD, *DLOAD, *DSLOAD, *TEMPERATURE, *FIELD, '// &
        '*BOUNDARY, TYPE=VELOCITY or *BOUNDARY, OP=NEW is not supported'
      call output_log(out, 'ldfcz: error: '//errmsg)
      if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    if (.not. associated(routines%disp)) then
      ! *BOUNDARY, USER needs the user subroutine DISP
      do i = 1, model%nstep
        do k = 1, model%steps(i)%nbc
          if (.not. model%steps(i)%bcs(k)%user) cycle
          errmsg = model%steps(i)%bcs(k)%pos%file//':'//itoa(model%steps(i)%bcs(k)%pos%line)//': *BOUNDARY: '// &
            'USER needs the user subroutine DISP: give a file defining it with --user FILE'
          call output_log(out, 'ldfcz: error: '//errmsg)
          if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
          exit_code = exit_input
          return
        end do
      end do
    end if
    msg = ''
    if (an%sym_factors .and. .not. an%symmetric) msg = ' (LDL^T factors of (K+K^T)/2 precondition GMRES)'
    if (an%single_factors) msg = msg//' (single-precision factors precondition GMRES)'
    call output_log(out, 'ldfcz: '//itoa(model%nnode)//' nodes, '//itoa(model%nelem)//' elements, '// &
      itoa(summary%ndof)//' dofs, '//merge('symmetric  ', 'unsymmetric', an%symmetric)//' solver'//msg// &
      '; UEL: '//routines%uel_origin//'; UMAT: '//routines%umat_origin)
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
      errmsg = '--max-plastic-increment needs a UMAT material that declares its equivalent plastic strain '// &
        '(**LDFCZ STATEV, PLASTIC STRAIN=n; docs/umat.md) or --plastic-statev N'
      call output_log(out, 'ldfcz: error: '//errmsg)
      if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    if (opt%max_opening > 0.0_dp .and. .not. any(model%utypes(1:model%nutype)%sv_opening > 0 .and. &
        model%utypes(1:model%nutype)%sv_length_prop > 0)) then
      errmsg = '--max-opening-increment needs a user element type that declares its opening and length scale '// &
        '(**LDFCZ SVARS, ..., OPENING=, LENGTH PROPERTY=; docs/uel.md)'
      call output_log(out, 'ldfcz: error: '//errmsg)
      if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    if (opt%max_opening > 0.0_dp) then
      call output_log(out, 'ldfcz: Newton '//trim(newton_mode_name(opt%newton))//'; increments limited to a '// &
        'cohesive opening increment <= '//rtoa(opt%max_opening)//' delta')
    else
      call output_log(out, 'ldfcz: Newton '//trim(newton_mode_name(opt%newton)))
    end if

    ! CSV columns: every (set, variable) requested by *NODE PRINT in any step
    call history_columns_build(model, cols)
    allocate (colv(cols%n))
    if (restarting) then
      call output_csv_resume(out, cols%names(1:cols%n), rs%state%csv_rows, fresh_csv, stat, errmsg)
      if (stat /= 0) then
        call output_log(out, 'ldfcz: error: '//errmsg)
        if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
        exit_code = exit_input
        return
      end if
      if (fresh_csv) call output_log(out, 'ldfcz: warning: no '//out%job//'.csv in '//out%dir//': the new one '// &
        'holds the increments after the restart point only')
    else
      call output_csv_header(out, cols%names(1:cols%n))
    end if
    ! JOB.dat: the *NODE PRINT / *EL PRINT tables, on unit 6, which output_open has pointed at JOB.dat (continued
    ! after a restart): what user routines write there interleaves with the tables as in Abaqus
    dat = -1
    if (print_tables_any(model) .and. .not. out%silent) dat = output_unit  ! once: by the writing process
    summarize = .true.
    call stop_signal_install()

    call analysis_state_init(s, an%ndof)
    allocate (bc_was_on(an%ndof))
    call load_state_init(ls, an%ndof)
    ! nodal temperatures: every node holds its initial temperature until a *TEMPERATURE changes it
    call load_state_init(ls_temp, model%nnode)
    ls_temp%on = .true.
    ls_temp%base = an%temp_start
    ls_temp%target = an%temp_start
    allocate (zero_nodes(model%nnode))
    zero_nodes = 0.0_dp
    temp_init = an%temp_start
    ! field variables likewise (*INITIAL CONDITIONS, TYPE=FIELD until a *FIELD changes them), nfield per node
    call load_state_init(ls_field, size(an%field_start))
    ls_field%on = .true.
    ls_field%base = an%field_start
    ls_field%target = an%field_start
    field_init = an%field_start
    call apply_bc_list(model%initial_bcs, model%n_initial_bc, .true.)
    t_reached = 0.0_dp
    is_first = 1
    ! a user library's UEXTERNALDB: start of the analysis (LOP 0) or of a restarted one (4, below)
    if (.not. restarting) call external_db(0, 0, [0.0_dp, 0.0_dp], 0.0_dp, 0, 0)
    if (restarting) then
      call resume_state()
      call external_db(4, 0, [rs%state%sc%t, rs%state%t_total0 + rs%state%sc%t], 0.0_dp, rs%state%step, &
        rs%state%kinc)
    else if (any(model%steps(1:model%nstep)%field_output)) then
      call write_frame(0.0_dp, findloc(model%steps(1:model%nstep)%field_output, .true., 1))
    end if

    steps: do is = is_first, model%nstep
      associate (st => model%steps(is))
        resumed = .false.
        if (restarting) resumed = is == rs%state%step
        if (.not. resumed) then
          ! boundaries of this step: inherited ones keep the value reached (OP=NEW drops them)
          s%u_start = an%u_conv
          where (s%bc_on .and. .not. s%bc_init .and. .not. s%bc_vel)
            s%bc_val = an%u_conv
            s%bc_amp = 0
          end where
          ! an inherited velocity keeps the velocity reached (constant in this step)
          where (s%bc_on .and. s%bc_vel)
            s%bc_val = s%bc_rate
            s%bc_amp = 0
          end where
          if (st%op_new) where (.not. s%bc_init) s%bc_vel = .false.
          bc_was_on = s%bc_on
          if (st%op_new) where (.not. s%bc_init) s%bc_on = .false.
          call apply_bc_list(st%bcs, st%nbc, .false.)
          ! loads of this step; a boundary removed by OP=NEW leaves its reaction as a force that decays over the step
          where (bc_was_on .and. .not. s%bc_on)
            bc_was_on = .true.
          elsewhere
            bc_was_on = .false.
          end where
          call load_step_begin(ls, s%fcl_old, merge(s%rf_old, 0.0_dp, bc_was_on), st%cloads, st%ncload, &
            st%cload_op_new, model%ndim)
          ! predefined fields: OP=NEW (per variable, 0 the temperature) returns them to their initial values
          field_comp = .false.
          if (allocated(st%field_new)) then
            do k = 1, model%nfield
              field_comp(k) = any(st%field_new == k)
            end do
            call load_step_begin(ls_temp, an%temp_start, zero_nodes, st%temps, st%ntemp, any(st%field_new == 0), 1, &
              rest=temp_init)
          else
            call load_step_begin(ls_temp, an%temp_start, zero_nodes, st%temps, st%ntemp, .false., 1)
          end if
          if (model%nfield > 0) call load_step_begin(ls_field, an%field_start, 0.0_dp * field_init, st%fields, &
            st%nfielddef, any(field_comp), model%nfield, rest=field_init, new_comp=field_comp)
          call dload_step_begin(an%dl, model, is, s%t_total0, stat, errmsg)
          if (stat /= 0) then
            call output_log(out, 'ldfcz: error: '//errmsg)
            if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
            exit_code = exit_input
            exit steps
          end if
        end if
        an%prescribed = s%bc_on .and. an%used
        call analysis_number_equations(an, model, stat, errmsg)
        if (stat /= 0) then
          call output_log(out, 'ldfcz: error: step '//itoa(is)//': '//errmsg)
          exit_code = exit_input
          exit steps
        end if
        summary%neq = an%neq
        if (allocated(r)) deallocate (r)
        allocate (r(max(an%neq, 1)))
        if (resumed) then
          ! restart within this step: increment control, q_avg history and output marks as they were (s)
          call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': resumed from '//opt%restart_from// &
            ' after increment '//itoa(s%kinc)//' at step time '//rtoa(s%sc%t)//' of '//rtoa(st%period)//', '// &
            itoa(an%neq)//' equations')
        else
          call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': period '//rtoa(st%period)// &
            ', NLGEOM '//merge('YES', 'NO ', st%nlgeom)//', '//itoa(an%neq)//' equations')
          call step_control_init(s%sc, st%dt_initial, st%period, st%dt_min, st%dt_max, st%direct)
          s%step = is
          s%kinc = 0
          s%dt_prev = 0.0_dp  ! Abaqus: no extrapolation into the first increment of a step
          s%q_sum = 0.0_dp
          s%next_mark = st%period / max(1, st%field_intervals)
          s%last_frame_inc = -1
        end if
        call system_clock(cs0)
        increments: do while (.not. step_control_done(s%sc))
          s%kinc = s%kinc + 1
          if (s%kinc > st%max_inc) then
            call output_log(out, 'ldfcz: step '//itoa(is)//': the maximum number of increments (INC='// &
              itoa(st%max_inc)//') is reached before the end of the step')
            exit_code = exit_no_convergence
            exit steps
          end if
          attempt = 0
          attempts: do
            attempt = attempt + 1
            summary%attempts = summary%attempts + 1
            dt = step_control_dt(s%sc)
            time = [s%sc%t, s%t_total0 + s%sc%t]
            t_end = s%sc%t + dt
            call external_db(1, 0, time, dt, is, s%kinc)
            ! the start of the increment: the converged state, or extrapolated
            an%u = an%u_conv
            an%extrapolated = st%extrapolate .and. s%dt_prev > 0.0_dp .and. attempt <= extrapolated_attempts
            if (an%extrapolated) then
              ! *STEP, EXTRAPOLATION=LINEAR (Abaqus' default): every dof starts from the last converged increment's
              ! change scaled to this increment; a failed start is retried once, then from u_conv
              an%u = an%u_conv + (dt / s%dt_prev) * s%du_prev
            end if
            if (an%cs%n > 0) call constraints_apply(an%cs, an%u)
            ! the prescribed values at the end of the increment; what they add to the start (all of the prescribed
            ! increment, or what the extrapolation missed) the first Newton iteration carries through the tangent
            u_carry = an%u
            do i = 1, an%ndof
              if (an%prescribed(i)) an%u(i) = prescribed_value(i, t_end)
            end do
            if (an%cs%n > 0) call constraints_apply(an%cs, an%u)
            u_carry = an%u - u_carry
            call load_vector(ls, model, is, t_end, s%t_total0, an%fext)
            call load_vector(ls_temp, model, is, t_end, s%t_total0, an%temp_end)
            call load_vector(ls_field, model, is, t_end, s%t_total0, an%field_end)
            call newton_solve(an, model, is, s%kinc, time, dt, opt%newton, verbose, out, ns, summary, r, ratios, s%q_sum, &
              converged, stopped, iter, q_now, pnewdt_min, outcome, u_carry)
            if (stopped) then
              call output_sta(out, is, s%kinc, attempt, iter, t_end, dt, 'stopped: XIT/STDB_ABQERR in a user routine')
              msg = 'ldfcz: error: '//stop_message(model, an%stop_elem, an%stop_text, is, s%kinc)
              call output_log(out, msg)
              if (out%quiet .and. .not. out%silent) write (error_unit, '(a)') msg
              if (parallel_distributed(an%par)) call output_log(out, 'ldfcz: the element is computed by process '// &
                itoa(an%stop_rank)//' of '//itoa(an%par%nranks)//'; every process stopped')
              exit_code = exit_input
              exit steps
            end if
            summary%iterations = summary%iterations + iter
            open_inc = 0.0_dp
            if (converged .and. opt%max_opening > 0.0_dp .and. .not. st%direct) then
              ! accuracy: the cohesive opening increment bound (paper section 7); redo the increment if exceeded
              call cohesive_ratio(model, an, open_inc)
              call step_control_accuracy(s%sc, dt, open_inc, opt%max_opening, redo, pnewdt_min)
              if (redo) then
                converged = .false.
                s%q_sum = s%q_sum - q_now
                outcome = 'cutback: opening increment '//rtoa(open_inc)//' delta'
                summary%accuracy_cutbacks = summary%accuracy_cutbacks + 1
              end if
            end if
            if (converged) then
              if (model%monitor_node > 0) then
                ! *MONITOR: the dof's displacement at the end of the increment, on the converged line
                call output_sta(out, is, s%kinc, attempt, iter, t_end, dt, 'converged  monitor U'// &
                  itoa(model%monitor_dof)//' '//rtoa(an%u((model%monitor_node - 1) * model%ndim + model%monitor_dof)), &
                  ratios(1:iter + 1))
              else
                call output_sta(out, is, s%kinc, attempt, iter, t_end, dt, 'converged', ratios(1:iter + 1))
              end if
              exit attempts
            end if
            call newton_forget_factors(ns)
            ! failed attempt
            call output_sta(out, is, s%kinc, attempt, iter, s%sc%t + dt, dt, trim(outcome), ratios(1:min(iter + 1, size(ratios))))
            call analysis_restore(an)
            call step_control_cutback(s%sc, dt, pnewdt_min, ok)
            call summary%add_cutback(is, outcome)
            if (.not. ok .or. step_control_exhausted(s%sc)) then
              if (st%direct) then
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(s%kinc)//': no convergence '// &
                  'with DIRECT (fixed) increments ('//trim(outcome)//')')
              else if (.not. ok) then
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(s%kinc)//': no convergence; '// &
                  'the increment '//rtoa(s%sc%dt)//' would be below the minimum '//rtoa(st%dt_min)//' ('// &
                  trim(outcome)//')')
              else
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(s%kinc)//': no convergence '// &
                  'after '//itoa(max_cutbacks)//' cutbacks ('//trim(outcome)//')')
              end if
              call output_log(out, 'ldfcz: the analysis stopped at step time '//rtoa(s%sc%t)//' of '// &
                rtoa(st%period)//'; the output of the converged increments is complete')
              exit_code = exit_no_convergence
              exit steps
            end if
          end do attempts
          ! converged increment: energy, commit, output
          call cohesive_ratio(model, an, summary%max_open_ratio)
          plastic_inc = 0.0_dp
          if (summary%plastic_statev > 0) then
            call statev_increment(model, an, summary%plastic_statev, plastic_inc)
            summary%max_statev_inc = max(summary%max_statev_inc, plastic_inc)
          end if
          ! work of the reactions (trapezoidal) and of the external forces on the free dofs
          do i = 1, an%ndof
            if (an%prescribed(i)) then
              summary%w_ext = summary%w_ext + 0.5_dp * (s%rf_old(i) + an%fint(i) - an%fext(i) - an%fdl(i)) * &
                (an%u(i) - an%u_conv(i))
            else
              summary%w_ext = summary%w_ext + 0.5_dp * (s%fext_old(i) + an%fext(i) + an%fdl(i)) * &
                (an%u(i) - an%u_conv(i))
            end if
          end do
          where (an%prescribed)
            s%rf_old = an%fint - an%fext - an%fdl
          elsewhere
            s%rf_old = 0.0_dp
          end where
          s%fext_old = an%fext + an%fdl
          s%fcl_old = an%fext
          s%du_prev = an%u - an%u_conv
          s%dt_prev = dt
          call analysis_commit(an)
          an%temp_start = an%temp_end
          an%field_start = an%field_end
          do i = 1, an%ndof
            if (s%bc_vel(i)) s%bc_rate(i) = velocity_value(i, t_end)
          end do
          call step_control_converged(s%sc, dt, iter, pnewdt_min, open_inc, opt%max_opening, plastic_inc, &
            opt%max_plastic)
          call summary%add_increment(is, s%kinc, s%t_total0 + s%sc%t, step_control_done(s%sc))
          s%kinc_total = s%kinc_total + 1
          run_increments = run_increments + 1
          call history_columns_values(cols, model, an%u, an%fint, an%fext, an%fdl, an%prescribed, colv)
          call output_csv_row(out, is, s%kinc, s%sc%t, s%t_total0 + s%sc%t, colv)
          s%csv_rows = s%csv_rows + 1
          ! rank 0 prints: the states of the other processes' printed elements first (every process takes part),
          ! released after the tables
          if (print_tables_any(model)) then
            printed = print_tables_elements(model, st, s%kinc, step_control_done(s%sc))
            call gather_converged_states(an, model, printed)
          end if
          if (dat /= -1) call print_tables_write(dat, model, an, st, is, s%kinc, s%sc%t, s%t_total0 + s%sc%t, dt, &
            step_control_done(s%sc))
          if (print_tables_any(model)) call release_converged_states(an, printed)
          if (st%field_output) then
            if (st%field_intervals > 0) then
              if (s%sc%t >= s%next_mark * (1.0_dp - 1.0e-9_dp) .or. step_control_done(s%sc)) then
                call write_frame(s%t_total0 + s%sc%t, is)
                do while (s%next_mark <= s%sc%t * (1.0_dp + 1.0e-9_dp))
                  s%next_mark = s%next_mark + st%period / st%field_intervals
                end do
              end if
            else if (st%field_frequency > 0) then
              if (mod(s%kinc, st%field_frequency) == 0 .or. step_control_done(s%sc)) call write_frame(s%t_total0 + s%sc%t, is)
            end if
          end if
          call system_clock(c1)
          call output_progress(out, is, model%nstep, s%kinc, s%sc%t, st%period, real(c1 - cs0, dp) / real(rate, dp))
          ! restart data after every n-th increment and at the end of the step (Abaqus *RESTART, WRITE, FREQUENCY=n)
          k = st%restart_frequency
          if (opt%restart_write >= 0) k = opt%restart_write
          lrestart = 0
          if (k > 0) then
            if (mod(s%kinc, k) == 0 .or. step_control_done(s%sc)) then
              call save_restart()
              lrestart = 1
            end if
          end if
          t_reached = [s%sc%t, s%t_total0 + s%sc%t]
          call external_db(2, lrestart, t_reached, dt, is, s%kinc)
          if (opt%stop_after > 0 .and. run_increments >= opt%stop_after) then
            call output_log(out, 'ldfcz: stopped after '//itoa(run_increments)//' increments as asked '// &
              '(--stop-after-increments), at step '//itoa(is)//' time '//rtoa(s%sc%t)//' of '//rtoa(st%period))
            exit_code = exit_no_convergence
            exit steps
          end if
          ! a signal to any process stops every one after this increment
          sig = nint(parallel_max(an%par, real(stop_signal_received(), dp)))
          if (sig /= 0 .and. .not. (is == model%nstep .and. step_control_done(s%sc))) then
            ! SIGTERM/SIGINT (stop_signal): end here as a complete run ends; the restart data first, so that a
            ! restart from them replaces the extra frame below with the uninterrupted run's frames
            call output_log(out, 'ldfcz: '//stop_signal_name(sig)//' received: stopped after increment '// &
              itoa(s%kinc)//' of step '//itoa(is)//' at step time '//rtoa(s%sc%t)//' of '//rtoa(st%period)// &
              '; the output of every converged increment is complete')
            call output_sta_note(out, 'stopped by '//stop_signal_name(sig)//' after step '//itoa(is)// &
              ' increment '//itoa(s%kinc))
            if (k > 0) then
              if (mod(s%kinc, k) /= 0) call save_restart()
            end if
            if (st%field_output) call write_frame(s%t_total0 + s%sc%t, is)
            exit_code = 128 + sig
            exit steps
          end if
        end do increments
        s%t_total0 = s%t_total0 + st%period
        call output_log(out, 'ldfcz: step '//itoa(is)//' completed in '//itoa(s%kinc)//' increments')
      end associate
    end do steps
    call external_db(3, 0, t_reached, 0.0_dp, min(is, model%nstep), s%kinc)
    if (dat /= -1) flush (dat)
    if (ns%tangents_skipped > 0) call output_log(out, 'ldfcz: Newton auto: '//itoa(ns%tangents_skipped)// &
      ' iterations expected to converge assembled without a tangent, '//itoa(ns%stale_solves)// &
      ' of them not converged and solved with the previous iterate''s tangent (this run)')

  contains

    !> Restart: the solver state of the restart file (read above) replaces the initial one; is_first is the step
    !> to continue (the next one when the restart point ended its step).
    subroutine resume_state()
      an%u_conv = rs%u_conv
      an%u = rs%u_conv
      an%fint = rs%fint
      an%trial = an%conv
      s = rs%state
      ns%reuse_count = s%reuse_count
      fact_offset = rs%summary%factorizations
      call run_summary_continue(summary, rs%summary)
      call output_frames_resume(out, rs%frame_times)
      is_first = s%step
      if (s%sc%t >= s%sc%period) then
        ! the restart point ended step s%step: the next step starts as in the uninterrupted run
        is_first = s%step + 1
        s%t_total0 = s%t_total0 + model%steps(s%step)%period
        restarting = .false.
      end if
      call output_sta_note(out, 'restart from '//opt%restart_from//' after step '//itoa(s%step)//' increment '// &
        itoa(s%kinc))
      call output_log(out, 'ldfcz: restart from '//opt%restart_from//': step '//itoa(s%step)//', increment '// &
        itoa(s%kinc)//', total time '//rtoa(rs%state%t_total0 + s%sc%t)//'; '//itoa(s%csv_rows)//' CSV rows and '// &
        itoa(size(rs%frame_times))//' VTU frames kept; summary counters continue, times are of this run only')
    end subroutine resume_state

    !> JOB.rst with the state after the increment just converged and written (restart_file).
    subroutine save_restart()
      type(restart_state_t) :: w
      integer :: st2
      character(len=:), allocatable :: em
      integer(i8) :: r0, r1
      call system_clock(r0)
      w%nnode = model%nnode
      w%nelem = model%nelem
      w%ndof = an%ndof
      if (fp%checksum == 0) fp%checksum = ieor(restart_checksum(model), an%partition_sig)
      w%checksum = fp%checksum
      s%reuse_count = ns%reuse_count
      w%state = s
      w%u_conv = an%u_conv
      w%fint = an%fint
      w%summary = summary
      w%summary%factorizations = fact_offset + an%n_factor_done
      if (an%sys_ready) w%summary%factorizations = w%summary%factorizations + sparse_factor_count(an%sys)
      if (allocated(out%frame_times)) then
        w%frame_times = out%frame_times(1:out%nframe)
      else
        allocate (w%frame_times(0))
      end if
      call restart_write(parallel_file(an%par, out%dir//'/'//out%job//'.rst'), w, an%conv, st2, em)
      if (st2 /= 0) call output_log(out, 'ldfcz: warning: restart file not written: '//em)
      call system_clock(r1)
      out%t_output = out%t_output + real(r1 - r0, dp) / real(rate, dp)
    end subroutine save_restart

    subroutine apply_bc_list(list, n, initial)
      use model_types, only: boundary_t
      type(boundary_t), intent(in) :: list(:)
      integer, intent(in) :: n
      logical, intent(in) :: initial
      integer :: k, a, d, dof
      do k = 1, n
        do a = 1, size(list(k)%nodes)
          do d = list(k)%first_dof, min(list(k)%last_dof, model%ndim)
            dof = (list(k)%nodes(a) - 1) * model%ndim + d
            s%bc_on(dof) = .true.
            s%bc_val(dof) = list(k)%value
            s%bc_amp(dof) = list(k)%amplitude
            s%bc_vel(dof) = list(k)%velocity
            s%bc_user(dof) = list(k)%user
            if (initial) s%bc_init(dof) = .true.
          end do
        end do
      end do
    end subroutine apply_bc_list

    !> Prescribed value at step time t: amplitude * value, or a linear ramp from the step-start value (Abaqus).
    real(dp) function prescribed_value(dof, t) result(v)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t
      if (s%bc_vel(dof)) then
        ! TYPE=VELOCITY: u = u of the last converged increment + v(t) dt, v a STEP unless an amplitude is given
        v = an%u_conv(dof) + velocity_value(dof, t) * dt
        return
      end if
      if (s%bc_amp(dof) > 0) then
        v = amplitude_factor(model%amplitudes(s%bc_amp(dof)), t, s%t_total0) * s%bc_val(dof)
      else if (model%steps(is)%amp_step) then
        v = s%bc_val(dof)
      else
        v = s%u_start(dof) + (t / model%steps(is)%period) * (s%bc_val(dof) - s%u_start(dof))
      end if
      if (s%bc_user(dof)) v = user_disp(dof, t, v)
    end function prescribed_value

    !> *BOUNDARY, USER: the value of DISP for dof at step time t (the end of the increment), U(1) passed in as v;
    !> COORDS the node's coordinates at the start of the increment (current ones under NLGEOM); JDOF in the node's
    !> *TRANSFORM system where it has one. NOEL = 0 (a node's boundary).
    real(dp) function user_disp(dof, t, v) result(w)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t, v
      real(dp) :: c_u(3), c_time(3), c_coords(3)
      integer :: c_kstep, c_kinc, c_node, c_noel, c_jdof, nd
      nd = (dof - 1) / model%ndim + 1
      c_u = [v, 0.0_dp, 0.0_dp]
      c_time = [t, s%t_total0 + t, dt]
      c_coords = model%x(:, nd)
      if (model%steps(is)%nlgeom) c_coords(1:model%ndim) = c_coords(1:model%ndim) + &
        node_vector_global(an%nr, an%u_conv, nd)
      c_kstep = is
      c_kinc = s%kinc
      c_node = model%node_id(nd)
      c_noel = 0
      c_jdof = dof - (nd - 1) * model%ndim
      call routines%disp(c_u, c_kstep, c_kinc, c_time, c_node, c_noel, c_jdof, c_coords)
      w = c_u(1)
    end function user_disp

    !> Prescribed velocity of dof at step time t: amplitude * value, else the value (Abaqus' default for velocity
    !> boundaries in a static step is a STEP function whatever *STEP, AMPLITUDE says).
    real(dp) function velocity_value(dof, t) result(v)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t
      v = s%bc_val(dof)
      if (s%bc_amp(dof) > 0) v = amplitude_factor(model%amplitudes(s%bc_amp(dof)), t, s%t_total0) * s%bc_val(dof)
    end function velocity_value

    !> A step of the model has a velocity boundary.
    logical function any_velocity()
      integer :: js, kb
      any_velocity = .false.
      do js = 1, model%nstep
        do kb = 1, model%steps(js)%nbc
          if (model%steps(js)%bcs(kb)%velocity) any_velocity = .true.
        end do
      end do
    end function any_velocity

    !> Calls the user library's UEXTERNALDB, if it has one, with copies of the arguments (a routine may write to
    !> them).
    subroutine external_db(lop, lrestart_, tm, dtm, kstep, kinc_)
      integer, intent(in) :: lop, lrestart_, kstep, kinc_  !< Abaqus' LOP, LRESTART, KSTEP, KINC
      real(dp), intent(in) :: tm(2), dtm                    !< TIME (step, total), DTIME
      integer :: c_lop, c_lrestart, c_kstep, c_kinc
      real(dp) :: c_time(2), c_dtime
      if (.not. associated(routines%uexternaldb)) return
      c_lop = lop
      c_lrestart = lrestart_
      c_kstep = kstep
      c_kinc = kinc_
      c_time = tm
      c_dtime = dtm
      call routines%uexternaldb(c_lop, c_lrestart, c_time, c_dtime, c_kstep, c_kinc)
    end subroutine external_db

    !> A VTU frame of the converged state, once per converged increment.
    subroutine write_frame(ttot, istep)
      real(dp), intent(in) :: ttot  !< total time of the frame
      integer, intent(in) :: istep  !< step whose field request applies
      if (s%kinc_total == s%last_frame_inc) return
      s%last_frame_inc = s%kinc_total
      call write_field_frame(out, model, an, ttot, model%steps(istep))
    end subroutine write_frame

  end subroutine run_steps

end module static_step
