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
  use analysis_core, only: analysis_t, analysis_number_equations, analysis_commit, analysis_restore
  use step_control, only: step_control_t, step_control_init, step_control_cutback, step_control_converged, &
    step_control_done, step_control_dt
  use sparse_system, only: sparse_factor_count
  use output_files, only: output_t, output_log, output_csv_header, output_csv_row, output_sta, output_progress, &
    output_csv_resume, output_frames_resume, output_sta_note
  use restart_file, only: restart_state_t, restart_write, restart_read, restart_checksum
  use user_routines, only: user_routines_t
  use solver_options, only: solver_options_t, exit_input, exit_no_convergence, newton_mode_name
  use run_summary, only: run_summary_t, run_summary_continue, cohesive_ratio, statev_increment
  use newton_iteration, only: newton_state_t, newton_solve, newton_forget_factors
  use field_frame, only: write_field_frame
  use print_tables, only: print_tables_any, print_tables_write
  use stop_report, only: stop_message
  use solver_text, only: itoa, rtoa
  use stop_signal, only: stop_signal_install, stop_signal_received, stop_signal_name
  implicit none
  private
  public :: run_steps

  integer, parameter :: max_cutbacks = 5        !< Abaqus I_A: attempts per increment
  real(dp), parameter :: opening_target = 0.8_dp        !< next increment aims at this fraction of the bound
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
    integer :: stat, is, kinc, attempt, iter, i, j, k, ncol, ic, kinc_total, last_frame_inc
    character(len=:), allocatable :: errmsg, msg
    character(len=96), allocatable :: colnames(:)
    integer, allocatable :: col_set(:), col_var(:), bc_amp(:)
    logical, allocatable :: bc_on(:), bc_init(:)
    logical, allocatable :: bc_vel(:)   !< the dof's boundary is a velocity (TYPE=VELOCITY)
    real(dp), allocatable :: bc_rate(:) !< the velocity of the last converged increment (inherited by the next step)
    real(dp), allocatable :: bc_val(:), u_start(:), r(:), rf_old(:), ratios(:), colv(:), du_prev(:)
    real(dp), allocatable :: fext_old(:), fcl_old(:)
    logical, allocatable :: bc_was_on(:)
    type(load_state_t) :: ls, ls_temp, ls_field
    real(dp), allocatable :: temp_init(:), field_init(:)
    logical :: field_comp(max(1, model%nfield))
    real(dp), allocatable :: zero_nodes(:)
    real(dp) :: t_total0, time(2), dt, pnewdt_min, q_sum, q_now, t_end, next_mark, dt_prev
    real(dp) :: open_inc, plastic_inc
    integer(i8) :: c1, rate, cs0
    type(step_control_t) :: sc
    type(newton_state_t) :: ns
    logical :: converged, ok, stopped
    integer :: lrestart       !< UEXTERNALDB's LRESTART: 1 when restart data were written after the increment
    real(dp) :: t_reached(2)  !< step and total time of the last converged increment (UEXTERNALDB)
    character(len=64) :: outcome
    type(restart_state_t) :: rs, fp
    logical :: restarting, resumed, fresh_csv
    integer :: is_first, csv_rows, run_increments, sig
    integer :: dat                      !< JOB.dat unit (-1: no printed output requested)

    call system_clock(count_rate=rate)
    summarize = .false.
    restarting = .false.
    if (allocated(opt%restart_from)) restarting = len(opt%restart_from) > 0
    csv_rows = 0
    run_increments = 0
    fact_offset = 0
    if (restarting) then
      ! the converged state of the increment the restart file was written after (element states straight into conv)
      fp%nnode = model%nnode
      fp%nelem = model%nelem
      fp%ndof = an%ndof
      fp%checksum = restart_checksum(model)
      call restart_read(opt%restart_from, fp, rs, an%conv, stat, errmsg)
      if (stat == 0 .and. rs%step > model%nstep) then
        stat = 2
        errmsg = opt%restart_from//': the restart file is of step '//itoa(rs%step)//' but the deck has '// &
          itoa(model%nstep)//' steps'
      end if
      if (stat /= 0) then
        call output_log(out, 'ldfcz: error: '//errmsg)
        if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
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
      if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    msg = ''
    if (an%sym_factors .and. .not. an%symmetric) msg = ' (LDL^T factors of (K+K^T)/2 precondition GMRES)'
    if (an%single_factors) msg = msg//' (single-precision factors precondition GMRES)'
    call output_log(out, 'ldfcz: '//itoa(model%nnode)//' nodes, '//itoa(model%nelem)//' elements, '// &
      itoa(summary%ndof)//' dofs, '//merge('symmetric  ', 'unsymmetric', an%symmetric)//' solver'//msg// &
      '; UEL: '//routines%uel_origin//'; UMAT: '//routines%umat_origin)
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
      if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      exit_code = exit_input
      return
    end if
    if (opt%max_opening > 0.0_dp .and. .not. any(model%utypes(1:model%nutype)%sv_opening > 0 .and. &
        model%utypes(1:model%nutype)%sv_length_prop > 0)) then
      errmsg = '--max-opening-increment needs a user element type that declares its opening and length scale '// &
        '(**LDFCZ SVARS, ..., OPENING=, LENGTH PROPERTY=; docs/uel.md)'
      call output_log(out, 'ldfcz: error: '//errmsg)
      if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
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
    ncol = 0
    k = 0
    do is = 1, model%nstep
      do i = 1, model%steps(is)%nprint
        k = k + size(model%steps(is)%prints(i)%vars)
      end do
    end do
    allocate (colnames(k), col_set(k), col_var(k))
    do is = 1, model%nstep
      do i = 1, model%steps(is)%nprint
        if (model%steps(is)%prints(i)%set_index == 0) cycle  ! every node: the JOB.dat table only
        do j = 1, size(model%steps(is)%prints(i)%vars)
          msg = trim(model%steps(is)%prints(i)%nset)//'.'//trim(model%steps(is)%prints(i)%vars(j))
          if (any(colnames(1:ncol) == msg)) cycle
          ncol = ncol + 1
          colnames(ncol) = msg
          col_set(ncol) = model%steps(is)%prints(i)%set_index
          col_var(ncol) = var_code(model%steps(is)%prints(i)%vars(j))
        end do
      end do
    end do
    allocate (colv(ncol))
    if (restarting) then
      call output_csv_resume(out, colnames(1:ncol), rs%csv_rows, fresh_csv, stat, errmsg)
      if (stat /= 0) then
        call output_log(out, 'ldfcz: error: '//errmsg)
        if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
        exit_code = exit_input
        return
      end if
      if (fresh_csv) call output_log(out, 'ldfcz: warning: no '//out%job//'.csv in '//out%dir//': the new one '// &
        'holds the increments after the restart point only')
    else
      call output_csv_header(out, colnames(1:ncol))
    end if
    ! JOB.dat: the *NODE PRINT / *EL PRINT tables, on unit 6, which output_open has pointed at JOB.dat (continued
    ! after a restart): what user routines write there interleaves with the tables as in Abaqus
    dat = -1
    if (print_tables_any(model)) dat = output_unit
    summarize = .true.
    call stop_signal_install()

    allocate (bc_on(an%ndof), bc_init(an%ndof), bc_val(an%ndof), bc_amp(an%ndof), u_start(an%ndof))
    allocate (bc_vel(an%ndof), bc_rate(an%ndof))
    bc_vel = .false.
    bc_rate = 0.0_dp
    allocate (rf_old(an%ndof), du_prev(an%ndof), fext_old(an%ndof), bc_was_on(an%ndof), fcl_old(an%ndof))
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
    fext_old = 0.0_dp
    fcl_old = 0.0_dp
    du_prev = 0.0_dp
    dt_prev = 0.0_dp
    bc_on = .false.
    bc_init = .false.
    bc_val = 0.0_dp
    bc_amp = 0
    rf_old = 0.0_dp
    t_total0 = 0.0_dp
    kinc_total = 0
    last_frame_inc = -1
    call apply_bc_list(model%initial_bcs, model%n_initial_bc, .true.)
    t_reached = 0.0_dp
    kinc = 0
    is_first = 1
    ! a user library's UEXTERNALDB: start of the analysis (LOP 0) or of a restarted one (4, below)
    if (.not. restarting) call external_db(0, 0, [0.0_dp, 0.0_dp], 0.0_dp, 0, 0)
    if (restarting) then
      call resume_state()
      call external_db(4, 0, [rs%sc%t, rs%t_total0 + rs%sc%t], 0.0_dp, rs%step, rs%kinc)
    else if (any(model%steps(1:model%nstep)%field_output)) then
      call write_frame(0.0_dp, findloc(model%steps(1:model%nstep)%field_output, .true., 1))
    end if

    steps: do is = is_first, model%nstep
      associate (st => model%steps(is))
        resumed = .false.
        if (restarting) resumed = is == rs%step
        if (.not. resumed) then
          ! boundaries of this step: inherited ones keep the value reached (OP=NEW drops them)
          u_start = an%u_conv
          where (bc_on .and. .not. bc_init .and. .not. bc_vel)
            bc_val = an%u_conv
            bc_amp = 0
          end where
          ! an inherited velocity keeps the velocity reached (constant in this step)
          where (bc_on .and. bc_vel)
            bc_val = bc_rate
            bc_amp = 0
          end where
          if (st%op_new) where (.not. bc_init) bc_vel = .false.
          bc_was_on = bc_on
          if (st%op_new) where (.not. bc_init) bc_on = .false.
          call apply_bc_list(st%bcs, st%nbc, .false.)
          ! loads of this step; a boundary removed by OP=NEW leaves its reaction as a force that decays over the step
          where (bc_was_on .and. .not. bc_on)
            bc_was_on = .true.
          elsewhere
            bc_was_on = .false.
          end where
          call load_step_begin(ls, fcl_old, merge(rf_old, 0.0_dp, bc_was_on), st%cloads, st%ncload, &
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
          call dload_step_begin(an%dl, model, is, t_total0, stat, errmsg)
          if (stat /= 0) then
            call output_log(out, 'ldfcz: error: '//errmsg)
            if (out%quiet) write (error_unit, '(a)') 'ldfcz: error: '//errmsg
            exit_code = exit_input
            exit steps
          end if
        end if
        an%prescribed = bc_on .and. an%used
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
          ! restart within this step: increment control, q_avg history and output marks as they were
          sc = rs%sc
          kinc = rs%kinc
          q_sum = rs%q_sum
          next_mark = rs%next_mark
          last_frame_inc = rs%last_frame_inc
          call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': resumed from '//opt%restart_from// &
            ' after increment '//itoa(kinc)//' at step time '//rtoa(sc%t)//' of '//rtoa(st%period)//', '// &
            itoa(an%neq)//' equations')
        else
          call output_log(out, 'ldfcz: step '//itoa(is)//trim(' '//st%name)//': period '//rtoa(st%period)// &
            ', NLGEOM '//merge('YES', 'NO ', st%nlgeom)//', '//itoa(an%neq)//' equations')
          call step_control_init(sc, st%dt_initial, st%period, st%dt_min, st%dt_max, st%direct)
          kinc = 0
          dt_prev = 0.0_dp  ! Abaqus: no extrapolation into the first increment of a step
          q_sum = 0.0_dp
          next_mark = st%period / max(1, st%field_intervals)
          last_frame_inc = -1
        end if
        call system_clock(cs0)
        increments: do while (.not. step_control_done(sc))
          kinc = kinc + 1
          if (kinc > st%max_inc) then
            call output_log(out, 'ldfcz: step '//itoa(is)//': the maximum number of increments (INC='// &
              itoa(st%max_inc)//') is reached before the end of the step')
            exit_code = exit_no_convergence
            exit steps
          end if
          attempt = 0
          attempts: do
            attempt = attempt + 1
            summary%attempts = summary%attempts + 1
            dt = step_control_dt(sc)
            time = [sc%t, t_total0 + sc%t]
            t_end = sc%t + dt
            call external_db(1, 0, time, dt, is, kinc)
            ! prescribed displacements at the end of the increment, applied at its start
            an%u = an%u_conv
            an%extrapolated = st%extrapolate .and. dt_prev > 0.0_dp .and. attempt <= extrapolated_attempts
            if (an%extrapolated) then
              ! *STEP, EXTRAPOLATION=LINEAR (Abaqus' default): the free dofs start from the last converged
              ! increment's change scaled to this increment; a failed start is retried once, then from u_conv
              where (.not. an%prescribed) an%u = an%u_conv + (dt / dt_prev) * du_prev
            end if
            do i = 1, an%ndof
              if (an%prescribed(i)) an%u(i) = prescribed_value(i, t_end)
            end do
            if (an%cs%n > 0) call constraints_apply(an%cs, an%u)
            call load_vector(ls, model, is, t_end, t_total0, an%fext)
            call load_vector(ls_temp, model, is, t_end, t_total0, an%temp_end)
            call load_vector(ls_field, model, is, t_end, t_total0, an%field_end)
            call newton_solve(an, model, is, kinc, time, dt, opt%newton, verbose, out, ns, summary, r, ratios, q_sum, &
              converged, stopped, iter, q_now, pnewdt_min, outcome)
            if (stopped) then
              call output_sta(out, is, kinc, attempt, iter, t_end, dt, 'stopped: XIT/STDB_ABQERR in a user routine')
              msg = 'ldfcz: error: '//stop_message(an, model, is, kinc, time, dt, st%period, st%nlgeom)
              call output_log(out, msg)
              if (out%quiet) write (error_unit, '(a)') msg
              exit_code = exit_input
              exit steps
            end if
            summary%iterations = summary%iterations + iter
            open_inc = 0.0_dp
            if (converged .and. opt%max_opening > 0.0_dp .and. .not. st%direct) then
              ! accuracy: the cohesive opening increment bound (paper section 7); redo the increment if exceeded
              call cohesive_ratio(model, an, open_inc)
              if (open_inc > opt%max_opening .and. dt > st%dt_min * (1.0_dp + 1.0e-9_dp)) then
                converged = .false.
                q_sum = q_sum - q_now
                outcome = 'cutback: opening increment '//rtoa(open_inc)//' delta'
                pnewdt_min = max(0.1_dp, opening_target * opt%max_opening / open_inc)
                summary%accuracy_cutbacks = summary%accuracy_cutbacks + 1
              end if
            end if
            if (converged) then
              if (model%monitor_node > 0) then
                ! *MONITOR: the dof's displacement at the end of the increment, on the converged line
                call output_sta(out, is, kinc, attempt, iter, t_end, dt, 'converged  monitor U'// &
                  itoa(model%monitor_dof)//' '//rtoa(an%u((model%monitor_node - 1) * model%ndim + model%monitor_dof)), &
                  ratios(1:iter + 1))
              else
                call output_sta(out, is, kinc, attempt, iter, t_end, dt, 'converged', ratios(1:iter + 1))
              end if
              exit attempts
            end if
            call newton_forget_factors(ns)
            ! failed attempt
            call output_sta(out, is, kinc, attempt, iter, sc%t + dt, dt, trim(outcome), ratios(1:min(iter + 1, size(ratios))))
            call analysis_restore(an)
            if (pnewdt_min >= 1.0_dp) pnewdt_min = 0.25_dp
            call step_control_cutback(sc, dt, pnewdt_min, ok)
            summary%cutbacks = summary%cutbacks + 1
            if (.not. ok .or. attempt >= max_cutbacks + 1) then
              if (st%direct) then
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(kinc)//': no convergence '// &
                  'with DIRECT (fixed) increments ('//trim(outcome)//')')
              else if (.not. ok) then
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(kinc)//': no convergence; '// &
                  'the increment '//rtoa(sc%dt)//' would be below the minimum '//rtoa(st%dt_min)//' ('// &
                  trim(outcome)//')')
              else
                call output_log(out, 'ldfcz: step '//itoa(is)//' increment '//itoa(kinc)//': no convergence '// &
                  'after '//itoa(max_cutbacks)//' cutbacks ('//trim(outcome)//')')
              end if
              call output_log(out, 'ldfcz: the analysis stopped at step time '//rtoa(sc%t)//' of '// &
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
              summary%w_ext = summary%w_ext + 0.5_dp * (rf_old(i) + an%fint(i) - an%fext(i) - an%fdl(i)) * &
                (an%u(i) - an%u_conv(i))
            else
              summary%w_ext = summary%w_ext + 0.5_dp * (fext_old(i) + an%fext(i) + an%fdl(i)) * &
                (an%u(i) - an%u_conv(i))
            end if
          end do
          where (an%prescribed)
            rf_old = an%fint - an%fext - an%fdl
          elsewhere
            rf_old = 0.0_dp
          end where
          fext_old = an%fext + an%fdl
          fcl_old = an%fext
          du_prev = an%u - an%u_conv
          dt_prev = dt
          call analysis_commit(an)
          an%temp_start = an%temp_end
          an%field_start = an%field_end
          do i = 1, an%ndof
            if (bc_vel(i)) bc_rate(i) = velocity_value(i, t_end)
          end do
          call step_control_converged(sc, dt, iter, pnewdt_min)
          if (open_inc > 0.0_dp .and. .not. st%direct) then
            ! next increment from the opening bound: at most x1.5 after an easy increment, PNEWDT > 1 honoured
            q_now = merge(1.5_dp, 1.0_dp, iter <= sc%easy_iterations)
            if (pnewdt_min >= 1.0_dp) q_now = min(q_now, pnewdt_min)
            sc%dt = min(st%dt_max, dt * min(q_now, opening_target * opt%max_opening / open_inc))
          end if
          if (opt%max_plastic > 0.0_dp .and. plastic_inc > 0.0_dp .and. .not. st%direct) then
            ! next increment from the material's plastic strain increment (prediction only: the UMAT's own PNEWDT
            ! rejects); keeps the automatic growth from overshooting into PNEWDT cutbacks
            sc%dt = min(sc%dt, max(dt, sc%dt_min) * max(0.25_dp, opening_target * opt%max_plastic / plastic_inc))
          end if
          summary%increments = summary%increments + 1
          kinc_total = kinc_total + 1
          run_increments = run_increments + 1
          do ic = 1, ncol
            colv(ic) = column_value(col_set(ic), col_var(ic))
          end do
          call output_csv_row(out, is, kinc, sc%t, t_total0 + sc%t, colv)
          csv_rows = csv_rows + 1
          if (dat /= -1) call print_tables_write(dat, model, an, st, is, kinc, sc%t, t_total0 + sc%t, dt, &
            step_control_done(sc))
          if (st%field_output) then
            if (st%field_intervals > 0) then
              if (sc%t >= next_mark * (1.0_dp - 1.0e-9_dp) .or. step_control_done(sc)) then
                call write_frame(t_total0 + sc%t, is)
                do while (next_mark <= sc%t * (1.0_dp + 1.0e-9_dp))
                  next_mark = next_mark + st%period / st%field_intervals
                end do
              end if
            else if (st%field_frequency > 0) then
              if (mod(kinc, st%field_frequency) == 0 .or. step_control_done(sc)) call write_frame(t_total0 + sc%t, is)
            end if
          end if
          call system_clock(c1)
          call output_progress(out, is, model%nstep, kinc, sc%t, st%period, real(c1 - cs0, dp) / real(rate, dp))
          ! restart data after every n-th increment and at the end of the step (Abaqus *RESTART, WRITE, FREQUENCY=n)
          k = st%restart_frequency
          if (opt%restart_write >= 0) k = opt%restart_write
          lrestart = 0
          if (k > 0) then
            if (mod(kinc, k) == 0 .or. step_control_done(sc)) then
              call save_restart()
              lrestart = 1
            end if
          end if
          t_reached = [sc%t, t_total0 + sc%t]
          call external_db(2, lrestart, t_reached, dt, is, kinc)
          if (opt%stop_after > 0 .and. run_increments >= opt%stop_after) then
            call output_log(out, 'ldfcz: stopped after '//itoa(run_increments)//' increments as asked '// &
              '(--stop-after-increments), at step '//itoa(is)//' time '//rtoa(sc%t)//' of '//rtoa(st%period))
            exit_code = exit_no_convergence
            exit steps
          end if
          sig = stop_signal_received()
          if (sig /= 0 .and. .not. (is == model%nstep .and. step_control_done(sc))) then
            ! SIGTERM/SIGINT (stop_signal): end here as a complete run ends; the restart data first, so that a
            ! restart from them replaces the extra frame below with the uninterrupted run's frames
            call output_log(out, 'ldfcz: '//stop_signal_name(sig)//' received: stopped after increment '// &
              itoa(kinc)//' of step '//itoa(is)//' at step time '//rtoa(sc%t)//' of '//rtoa(st%period)// &
              '; the output of every converged increment is complete')
            call output_sta_note(out, 'stopped by '//stop_signal_name(sig)//' after step '//itoa(is)// &
              ' increment '//itoa(kinc))
            if (k > 0) then
              if (mod(kinc, k) /= 0) call save_restart()
            end if
            if (st%field_output) call write_frame(t_total0 + sc%t, is)
            exit_code = 128 + sig
            exit steps
          end if
        end do increments
        t_total0 = t_total0 + st%period
        call output_log(out, 'ldfcz: step '//itoa(is)//' completed in '//itoa(kinc)//' increments')
      end associate
    end do steps
    call external_db(3, 0, t_reached, 0.0_dp, min(is, model%nstep), kinc)
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
      u_start = rs%u_start
      rf_old = rs%rf_old
      du_prev = rs%du_prev
      dt_prev = rs%dt_prev
      bc_val = rs%bc_val
      bc_on = rs%bc_on
      bc_init = rs%bc_init
      bc_amp = rs%bc_amp
      t_total0 = rs%t_total0
      kinc_total = rs%kinc_total
      last_frame_inc = rs%last_frame_inc
      ns%reuse_count = rs%reuse_count
      csv_rows = rs%csv_rows
      fact_offset = rs%summary%factorizations
      call run_summary_continue(summary, rs%summary)
      call output_frames_resume(out, rs%frame_times)
      is_first = rs%step
      if (rs%sc%t >= rs%sc%period) then
        ! the restart point ended step rs%step: the next step starts as in the uninterrupted run
        is_first = rs%step + 1
        t_total0 = t_total0 + model%steps(rs%step)%period
        restarting = .false.
      end if
      call output_sta_note(out, 'restart from '//opt%restart_from//' after step '//itoa(rs%step)//' increment '// &
        itoa(rs%kinc))
      call output_log(out, 'ldfcz: restart from '//opt%restart_from//': step '//itoa(rs%step)//', increment '// &
        itoa(rs%kinc)//', total time '//rtoa(rs%t_total0 + rs%sc%t)//'; '//itoa(rs%csv_rows)//' CSV rows and '// &
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
      if (fp%checksum == 0) fp%checksum = restart_checksum(model)
      w%checksum = fp%checksum
      w%step = is
      w%kinc = kinc
      w%kinc_total = kinc_total
      w%csv_rows = csv_rows
      w%last_frame_inc = last_frame_inc
      w%reuse_count = ns%reuse_count
      w%t_total0 = t_total0
      w%q_sum = q_sum
      w%next_mark = next_mark
      w%sc = sc
      w%u_conv = an%u_conv
      w%u_start = u_start
      w%fint = an%fint
      w%rf_old = rf_old
      w%du_prev = du_prev
      w%dt_prev = dt_prev
      w%bc_val = bc_val
      w%bc_on = bc_on
      w%bc_init = bc_init
      w%bc_amp = bc_amp
      w%summary = summary
      w%summary%factorizations = fact_offset + an%n_factor_done
      if (an%sys_ready) w%summary%factorizations = w%summary%factorizations + sparse_factor_count(an%sys)
      if (allocated(out%frame_times)) then
        w%frame_times = out%frame_times(1:out%nframe)
      else
        allocate (w%frame_times(0))
      end if
      call restart_write(out%dir//'/'//out%job//'.rst', w, an%conv, st2, em)
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
            bc_on(dof) = .true.
            bc_val(dof) = list(k)%value
            bc_amp(dof) = list(k)%amplitude
            bc_vel(dof) = list(k)%velocity
            if (initial) bc_init(dof) = .true.
          end do
        end do
      end do
    end subroutine apply_bc_list

    !> Prescribed value at step time t: amplitude * value, or a linear ramp from the step-start value (Abaqus).
    real(dp) function prescribed_value(dof, t) result(v)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t
      if (bc_vel(dof)) then
        ! TYPE=VELOCITY: u = u of the last converged increment + v(t) dt, v a STEP unless an amplitude is given
        v = an%u_conv(dof) + velocity_value(dof, t) * dt
        return
      end if
      if (bc_amp(dof) > 0) then
        v = amplitude_factor(model%amplitudes(bc_amp(dof)), t, t_total0) * bc_val(dof)
      else if (model%steps(is)%amp_step) then
        v = bc_val(dof)
      else
        v = u_start(dof) + (t / model%steps(is)%period) * (bc_val(dof) - u_start(dof))
      end if
    end function prescribed_value

    !> Prescribed velocity of dof at step time t: amplitude * value, else the value (Abaqus' default for velocity
    !> boundaries in a static step is a STEP function whatever *STEP, AMPLITUDE says).
    real(dp) function velocity_value(dof, t) result(v)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t
      v = bc_val(dof)
      if (bc_amp(dof) > 0) v = amplitude_factor(model%amplitudes(bc_amp(dof)), t, t_total0) * bc_val(dof)
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

    real(dp) function column_value(iset, ivar) result(v)
      integer, intent(in) :: iset, ivar
      integer :: k, dof, nn
      v = 0.0_dp
      nn = size(model%nsets(iset)%nodes)
      do k = 1, nn
        if (mod(ivar, 10) > model%ndim) cycle
        dof = (model%nsets(iset)%nodes(k) - 1) * model%ndim + mod(ivar, 10)
        if (ivar > 10) then
          if (an%prescribed(dof)) v = v + an%fint(dof) - an%fext(dof) - an%fdl(dof)
        else
          v = v + an%u(dof)
        end if
      end do
      if (ivar < 10 .and. nn > 0) v = v / real(nn, dp)
    end function column_value

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
      if (kinc_total == last_frame_inc) return
      last_frame_inc = kinc_total
      call write_field_frame(out, model, an, ttot, model%steps(istep))
    end subroutine write_frame

  end subroutine run_steps

  !> Column code: 1..3 U1..U3 (mean), 11..13 RF1..RF3 (sum).
  pure integer function var_code(v)
    character(len=*), intent(in) :: v
    select case (trim(v))
    case ('U1')
      var_code = 1
    case ('U2')
      var_code = 2
    case ('U3')
      var_code = 3
    case ('RF1')
      var_code = 11
    case ('RF2')
      var_code = 12
    case default
      var_code = 13
    end select
  end function var_code

end module static_step
