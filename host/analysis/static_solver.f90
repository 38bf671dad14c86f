!> Static (NLGEOM) steps: prescribed displacements, automatic increments (step_control), full Newton with the
!> Abaqus convergence criteria (convergence_check), commit on convergence, output per increment, closing summary.
module static_solver
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t, amplitude_value, etype_user, etype_c3d8, etype_cpe4
  use analysis_core, only: analysis_t, analysis_init, analysis_number_equations, analysis_assemble, analysis_commit, &
    analysis_restore, pnewdt_large
  use step_control, only: step_control_t, step_control_init, step_control_cutback, step_control_converged, &
    step_control_done, step_control_dt
  use convergence_check, only: newton_converged, typical_force
  use sparse_system, only: sparse_factorize, sparse_solve, sparse_time_analysis, sparse_time_factor, &
    sparse_time_solve, sparse_factor_count, sparse_destroy, sparse_is_factored, sparse_solve_krylov, &
    sparse_krylov_count
  use output_files, only: output_t, output_log, output_csv_header, output_csv_row, output_sta, output_progress, &
    output_vtu_frame, output_vtu_t, output_csv_resume, output_frames_resume, output_sta_note
  use restart_file, only: restart_state_t, restart_write, restart_read, restart_checksum
  use user_routines, only: user_routines_t
  use abaqus_host_state, only: abaqus_stop_requested, abaqus_stop_message, abaqus_clear_stop
  implicit none
  private
  public :: run_analysis, run_summary_t, exit_ok, exit_input, exit_no_convergence
  public :: solver_options_t, newton_full, newton_modified, newton_krylov, newton_auto, newton_mode_code

  integer, parameter :: exit_ok = 0, exit_input = 2, exit_no_convergence = 3
  integer, parameter :: max_cutbacks = 5        !< Abaqus I_A: attempts per increment
  integer, parameter :: n_sdv_out = 3           !< state variables written to the VTU frames
  !> Newton variants (docs/performance.md): full = fresh tangent and factorization every iteration; modified =
  !> factors kept across iterations and increments, elements called for the residual only (UEL LFLAGS(3) = 5),
  !> a fresh tangent when the residual contracts poorly; krylov = fresh tangent every iteration, solved by GMRES
  !> preconditioned with the last factorization, refactorized when GMRES does not converge quickly; auto = krylov
  !> with the GMRES budget set from the measured cost of a factorization against a solve.
  integer, parameter :: newton_full = 1, newton_modified = 2, newton_krylov = 3, newton_auto = 4
  real(dp), parameter :: modified_contraction = 0.5_dp  !< modified Newton: r_k/r_(k-1) above this -> new tangent
  integer, parameter :: modified_max_reuse = 8          !< modified Newton: new tangent after this many reuses
  real(dp), parameter :: krylov_rel_tol = 1.0e-8_dp     !< GMRES relative residual (an exact Newton step)
  integer, parameter :: krylov_max_iter = 30            !< GMRES budget of mode krylov (restart = budget)
  real(dp), parameter :: opening_target = 0.8_dp        !< next increment aims at this fraction of the bound

  !> Run-time choices of the solver (command line; defaults: Abaqus-like full Newton, no accuracy control).
  type :: solver_options_t
    integer :: newton = newton_full             !< newton_full, newton_modified, newton_krylov, newton_auto
    real(dp) :: max_opening = 0.0_dp            !< > 0: largest cohesive opening increment / delta per increment
    integer :: plastic_statev = -1              !< STATEV whose largest increment is reported (-1: by the UMAT, 0 none)
    real(dp) :: max_plastic = 0.0_dp            !< > 0: next increment aims at this STATEV(plastic_statev) increment
    integer :: restart_write = -1               !< JOB.rst every n increments (-1: as *RESTART in the deck; 0 never)
    character(len=:), allocatable :: restart_from  !< continue from this restart file (docs/host.md, "Restart")
    integer :: stop_after = 0                   !< > 0: stop after so many converged increments (restart tests)
  end type solver_options_t

  !> Counters and measures of a run (printed in the closing summary).
  type :: run_summary_t
    integer :: increments = 0, attempts = 0, cutbacks = 0, iterations = 0, factorizations = 0
    integer :: neq = 0, ndof = 0
    real(dp) :: t_assembly = 0, t_factor = 0, t_solve = 0, t_output = 0, t_analysis = 0, wall = 0, cpu = 0
    real(dp) :: w_ext = 0                       !< external work of the reactions (trapezoidal)
    real(dp) :: e_int = 0                       !< stored + dissipated energy of elements and materials
    real(dp) :: max_open_ratio = 0              !< largest cohesive |Delta| increment / delta
    real(dp) :: max_statev_inc = 0              !< largest increment of STATEV(plastic_statev)
    integer :: plastic_statev = 0               !< the STATEV reported (0: none)
    integer :: krylov_solves = 0, krylov_iterations = 0, krylov_failures = 0, reused_solves = 0
    integer :: accuracy_cutbacks = 0            !< increments redone for the opening bound
    integer :: newton = newton_full
    integer :: peak_kb = 0                      !< VmHWM
  end type run_summary_t

contains

  !> Run every step of the model. exit_code: 0 all steps done, 2 input/model error, 3 no convergence.
  subroutine run_analysis(model, routines, out, verbose, summary, exit_code, options)
    type(model_t), intent(in) :: model             !< the model
    type(user_routines_t), intent(in) :: routines  !< UEL and UMAT
    type(output_t), intent(inout) :: out           !< output files
    logical, intent(in) :: verbose                 !< per-iteration residual lines in the log
    type(run_summary_t), intent(out) :: summary    !< counters and measures
    integer, intent(out) :: exit_code              !< exit status
    type(solver_options_t), intent(in), optional :: options  !< solver choices (default: full Newton)
    type(solver_options_t) :: opt
    type(analysis_t) :: an
    integer :: stat, is, kinc, attempt, iter, i, j, k, ncol, ic, kinc_total, last_frame_inc
    character(len=:), allocatable :: errmsg, msg
    character(len=96), allocatable :: colnames(:)
    integer, allocatable :: col_set(:), col_var(:), bc_amp(:)
    logical, allocatable :: bc_on(:), bc_init(:)
    real(dp), allocatable :: bc_val(:), u_start(:), r(:), rf_old(:), ratios(:), colv(:)
    real(dp) :: t_total0, time(2), dt, pnewdt_min, q_sum, q_avg, q_now, r_max, c_max, du_max, t_end, next_mark
    real(dp) :: cpu0, cpu1, r_prev, r_prev2, open_inc, plastic_inc, t_fact_last, t_solve_last, t0s
    real(dp), allocatable :: r_copy(:)
    integer :: reuse_count, kit, kbudget
    logical :: want_k, k_fresh
    integer(i8) :: c0, c1, rate, cs0
    type(step_control_t) :: sc
    logical :: converged, ok, diverging
    character(len=256) :: smsg
    character(len=64) :: outcome
    type(restart_state_t) :: rs, fp
    logical :: restarting, resumed, fresh_csv
    integer :: is_first, csv_rows, run_increments, fact_offset

    call system_clock(c0, rate)
    call cpu_time(cpu0)
    if (present(options)) opt = options
    exit_code = exit_ok
    restarting = .false.
    if (allocated(opt%restart_from)) restarting = len(opt%restart_from) > 0
    csv_rows = 0
    run_increments = 0
    fact_offset = 0
    t_fact_last = 0.0_dp
    t_solve_last = 0.0_dp
    reuse_count = 0
    call abaqus_clear_stop()
    call analysis_init(an, model, routines, stat, errmsg)
    if (stat /= 0) then
      call output_log(out, 'ldfcz: error: '//errmsg)
      exit_code = exit_input
      return
    end if
    summary%ndof = count(an%used)
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
    call output_log(out, 'ldfcz: '//itoa(model%nnode)//' nodes, '//itoa(model%nelem)//' elements, '// &
      itoa(summary%ndof)//' dofs, '//merge('symmetric  ', 'unsymmetric', an%symmetric)//' solver; UEL: '// &
      routines%uel_origin//'; UMAT: '//routines%umat_origin)
    summary%newton = opt%newton
    summary%plastic_statev = opt%plastic_statev
    if (summary%plastic_statev < 0) summary%plastic_statev = merge(7, 0, routines%umat_origin == 'built-in ldfcz UMAT')
    if (model%nmat > 0) then
      if (all(model%materials(1:model%nmat)%has_elastic)) summary%plastic_statev = 0
    else
      summary%plastic_statev = 0
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

    allocate (bc_on(an%ndof), bc_init(an%ndof), bc_val(an%ndof), bc_amp(an%ndof), u_start(an%ndof))
    allocate (rf_old(an%ndof))
    bc_on = .false.
    bc_init = .false.
    bc_val = 0.0_dp
    bc_amp = 0
    rf_old = 0.0_dp
    t_total0 = 0.0_dp
    kinc_total = 0
    last_frame_inc = -1
    call apply_bc_list(model%initial_bcs, model%n_initial_bc, .true.)
    is_first = 1
    if (restarting) then
      call resume_state()
    else if (any(model%steps(1:model%nstep)%field_output)) then
      call write_frame(0.0_dp)
    end if

    steps: do is = is_first, model%nstep
      associate (st => model%steps(is))
        resumed = .false.
        if (restarting) resumed = is == rs%step
        if (.not. resumed) then
          ! boundaries of this step: inherited ones keep the value reached (OP=NEW drops them)
          u_start = an%u_conv
          where (bc_on .and. .not. bc_init)
            bc_val = an%u_conv
            bc_amp = 0
          end where
          if (st%op_new) where (.not. bc_init) bc_on = .false.
          call apply_bc_list(st%bcs, st%nbc, .false.)
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
            ! prescribed displacements at the end of the increment, applied at its start
            an%u = an%u_conv
            do i = 1, an%ndof
              if (an%prescribed(i)) an%u(i) = prescribed_value(i, t_end)
            end do
            converged = .false.
            diverging = .false.
            outcome = ''
            iter = 0
            c_max = 0.0_dp
            r_prev = huge(1.0_dp)
            r_prev2 = huge(1.0_dp)
            if (.not. allocated(ratios)) allocate (ratios(st%max_iter + 1))
            if (size(ratios) < st%max_iter + 1) then
              deallocate (ratios)
              allocate (ratios(st%max_iter + 1))
            end if
            newton: do
              ! a tangent is needed unless modified Newton can reuse the factors (docs/performance.md)
              want_k = .true.
              if (opt%newton == newton_modified .and. an%sys_ready) then
                if (sparse_is_factored(an%sys)) then
                  want_k = reuse_count >= modified_max_reuse
                  if (iter >= 1 .and. r_prev < huge(1.0_dp)) then
                    if (r_max > modified_contraction * r_prev) want_k = .true.
                  end if
                end if
              end if
              if (iter >= 1) then
                r_prev2 = r_prev
                r_prev = r_max
              end if
              call analysis_assemble(an, model, is, kinc, time, dt, st%period, st%nlgeom, an%neq > 0 .and. want_k, &
                pnewdt_min, stat, errmsg)
              if (abaqus_stop_requested()) then
                call output_sta(out, is, kinc, attempt, iter, t_end, dt, 'stopped: XIT/STDB_ABQERR in a user routine')
                msg = 'ldfcz: error: '//stop_message(time, dt, st%period, st%nlgeom)
                call output_log(out, msg)
                if (out%quiet) write (error_unit, '(a)') msg
                exit_code = exit_input
                exit steps
              end if
              if (stat /= 0) then
                outcome = 'cutback: element failure'
                if (verbose) call output_log(out, '  '//errmsg)
                pnewdt_min = min(pnewdt_min, 0.25_dp)
                exit newton
              end if
              if (pnewdt_min < 1.0_dp) then
                outcome = 'cutback: PNEWDT '//rtoa(pnewdt_min)
                exit newton
              end if
              do i = 1, an%ndof
                if (an%eq(i) > 0) r(an%eq(i)) = -an%fint(i)
              end do
              r_max = 0.0_dp
              if (an%neq > 0) r_max = maxval(abs(r(1:an%neq)))
              q_now = typical_force(an%fint)
              q_avg = (q_sum + q_now) / real(kinc, dp)
              du_max = maxval(abs(an%u - an%u_conv))
              ratios(iter + 1) = r_max / max(q_avg, tiny(1.0_dp))
              if (verbose) call output_log(out, '    step '//itoa(is)//' inc '//itoa(kinc)//' iter '//itoa(iter)// &
                ': r_max '//rtoa(r_max)//' q_avg '//rtoa(q_avg)//' c_max '//rtoa(c_max)//' du_max '//rtoa(du_max)// &
                merge(' (tangent)      ', ' (reused LU/LDL)', want_k))
              if (an%neq == 0 .or. newton_converged(r_max, q_avg, c_max, du_max, st%r_n, st%c_n, iter)) then
                converged = .true.
                q_sum = q_sum + q_now
                exit newton
              end if
              ! divergence: the residual grew in two consecutive iterations (after the fourth, Abaqus I_0 = 4)
              if (iter >= 4 .and. r_max > r_prev .and. r_prev > r_prev2) then
                outcome = 'cutback: diverging'
                diverging = .true.
                exit newton
              end if
              if (iter >= st%max_iter) then
                outcome = 'cutback: '//itoa(iter)//' iterations'
                exit newton
              end if
              if (iter == 0) then
                r_prev = huge(1.0_dp)
                r_prev2 = huge(1.0_dp)
              end if
              k_fresh = .true.
              if (.not. want_k) then
                ! modified Newton: the last factors, a residual-only element loop
                call sparse_solve(an%sys, r, stat, smsg)
                reuse_count = reuse_count + 1
                summary%reused_solves = summary%reused_solves + 1
                k_fresh = stat /= 0
              else if ((opt%newton == newton_krylov .or. opt%newton == newton_auto) .and. &
                  sparse_is_factored(an%sys)) then
                ! fresh tangent, GMRES preconditioned by the last factorization
                kbudget = krylov_max_iter
                if (opt%newton == newton_auto .and. t_solve_last > 0.0_dp) &
                  kbudget = max(2, min(krylov_max_iter, int(0.5_dp * t_fact_last / t_solve_last)))
                r_copy = r(1:an%neq)
                t0s = sparse_time_solve(an%sys)
                call sparse_solve_krylov(an%sys, r(1:an%neq), krylov_rel_tol, kbudget, kbudget, kit, stat, smsg)
                if (kit > 0) t_solve_last = (sparse_time_solve(an%sys) - t0s) / real(kit, dp)
                summary%krylov_iterations = summary%krylov_iterations + kit
                if (stat == 0) then
                  summary%krylov_solves = summary%krylov_solves + 1
                  k_fresh = .false.
                else
                  summary%krylov_failures = summary%krylov_failures + 1
                  r(1:an%neq) = r_copy
                end if
              end if
              if (k_fresh) then
                if (.not. want_k) then
                  outcome = 'cutback: solve failed'
                  exit newton
                end if
                t0s = sparse_time_factor(an%sys)
                call sparse_factorize(an%sys, stat, smsg)
                t_fact_last = sparse_time_factor(an%sys) - t0s
                reuse_count = 0
                if (stat /= 0) then
                  outcome = 'cutback: singular tangent'
                  if (verbose) call output_log(out, '  '//trim(smsg))
                  exit newton
                end if
                t0s = sparse_time_solve(an%sys)
                call sparse_solve(an%sys, r, stat, smsg)
                if (t_solve_last <= 0.0_dp) t_solve_last = sparse_time_solve(an%sys) - t0s
                if (stat /= 0) then
                  outcome = 'cutback: solve failed'
                  exit newton
                end if
              end if
              iter = iter + 1
              c_max = maxval(abs(r(1:max(an%neq, 1))))
              do i = 1, an%ndof
                if (an%eq(i) > 0) an%u(i) = an%u(i) + r(an%eq(i))
              end do
            end do newton
            summary%iterations = summary%iterations + iter
            open_inc = 0.0_dp
            if (converged .and. opt%max_opening > 0.0_dp .and. .not. st%direct) then
              ! accuracy: the cohesive opening increment bound (paper section 7); redo the increment if exceeded
              call cohesive_ratio(open_inc)
              if (open_inc > opt%max_opening .and. dt > st%dt_min * (1.0_dp + 1.0e-9_dp)) then
                converged = .false.
                q_sum = q_sum - q_now
                outcome = 'cutback: opening increment '//rtoa(open_inc)//' delta'
                pnewdt_min = max(0.1_dp, opening_target * opt%max_opening / open_inc)
                summary%accuracy_cutbacks = summary%accuracy_cutbacks + 1
              end if
            end if
            if (converged) then
              call output_sta(out, is, kinc, attempt, iter, t_end, dt, 'converged', ratios(1:iter + 1))
              exit attempts
            end if
            reuse_count = modified_max_reuse
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
          call cohesive_ratio(summary%max_open_ratio)
          plastic_inc = 0.0_dp
          if (summary%plastic_statev > 0) then
            call statev_increment(summary%plastic_statev, plastic_inc)
            summary%max_statev_inc = max(summary%max_statev_inc, plastic_inc)
          end if
          do i = 1, an%ndof
            if (an%prescribed(i)) summary%w_ext = summary%w_ext + 0.5_dp * (rf_old(i) + an%fint(i)) * &
              (an%u(i) - an%u_conv(i))
          end do
          where (an%prescribed)
            rf_old = an%fint
          elsewhere
            rf_old = 0.0_dp
          end where
          call analysis_commit(an)
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
          if (st%field_output) then
            if (st%field_intervals > 0) then
              if (sc%t >= next_mark * (1.0_dp - 1.0e-9_dp) .or. step_control_done(sc)) then
                call write_frame(t_total0 + sc%t)
                do while (next_mark <= sc%t * (1.0_dp + 1.0e-9_dp))
                  next_mark = next_mark + st%period / st%field_intervals
                end do
              end if
            else if (st%field_frequency > 0) then
              if (mod(kinc, st%field_frequency) == 0 .or. step_control_done(sc)) call write_frame(t_total0 + sc%t)
            end if
          end if
          call system_clock(c1)
          call output_progress(out, is, model%nstep, kinc, sc%t, st%period, real(c1 - cs0, dp) / real(rate, dp))
          ! restart data after every n-th increment and at the end of the step (Abaqus *RESTART, WRITE, FREQUENCY=n)
          k = st%restart_frequency
          if (opt%restart_write >= 0) k = opt%restart_write
          if (k > 0) then
            if (mod(kinc, k) == 0 .or. step_control_done(sc)) call save_restart()
          end if
          if (opt%stop_after > 0 .and. run_increments >= opt%stop_after) then
            call output_log(out, 'ldfcz: stopped after '//itoa(run_increments)//' increments as asked '// &
              '(--stop-after-increments), at step '//itoa(is)//' time '//rtoa(sc%t)//' of '//rtoa(st%period))
            exit_code = exit_no_convergence
            exit steps
          end if
        end do increments
        t_total0 = t_total0 + st%period
        call output_log(out, 'ldfcz: step '//itoa(is)//' completed in '//itoa(kinc)//' increments')
      end associate
    end do steps

    ! summary
    summary%e_int = 0.0_dp
    do i = 1, model%nelem
      summary%e_int = summary%e_int + an%conv(i)%energy(2) + an%conv(i)%energy(4)
    end do
    summary%t_factor = an%t_factor_done
    summary%t_solve = an%t_solve_done
    summary%t_analysis = an%t_setup_done
    summary%factorizations = an%n_factor_done + fact_offset
    if (an%sys_ready) then
      summary%t_factor = summary%t_factor + sparse_time_factor(an%sys)
      summary%t_solve = summary%t_solve + sparse_time_solve(an%sys)
      summary%t_analysis = summary%t_analysis + sparse_time_analysis(an%sys)
      summary%factorizations = summary%factorizations + sparse_factor_count(an%sys)
      call sparse_destroy(an%sys)
    end if
    summary%t_assembly = an%t_assembly
    summary%t_output = out%t_output
    call system_clock(c1)
    call cpu_time(cpu1)
    summary%wall = real(c1 - c0, dp) / real(rate, dp)
    summary%cpu = cpu1 - cpu0
    summary%peak_kb = peak_memory_kb()
    call write_summary()

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
      bc_val = rs%bc_val
      bc_on = rs%bc_on
      bc_init = rs%bc_init
      bc_amp = rs%bc_amp
      t_total0 = rs%t_total0
      kinc_total = rs%kinc_total
      last_frame_inc = rs%last_frame_inc
      reuse_count = rs%reuse_count
      csv_rows = rs%csv_rows
      summary%increments = rs%increments
      summary%attempts = rs%attempts
      summary%cutbacks = rs%cutbacks
      summary%iterations = rs%iterations
      fact_offset = rs%factorizations
      summary%krylov_solves = rs%krylov_solves
      summary%krylov_iterations = rs%krylov_iterations
      summary%krylov_failures = rs%krylov_failures
      summary%reused_solves = rs%reused_solves
      summary%accuracy_cutbacks = rs%accuracy_cutbacks
      summary%w_ext = rs%w_ext
      summary%max_open_ratio = rs%max_open_ratio
      summary%max_statev_inc = rs%max_statev_inc
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
      w%reuse_count = reuse_count
      w%t_total0 = t_total0
      w%q_sum = q_sum
      w%next_mark = next_mark
      w%sc = sc
      w%u_conv = an%u_conv
      w%u_start = u_start
      w%fint = an%fint
      w%rf_old = rf_old
      w%bc_val = bc_val
      w%bc_on = bc_on
      w%bc_init = bc_init
      w%bc_amp = bc_amp
      w%increments = summary%increments
      w%attempts = summary%attempts
      w%cutbacks = summary%cutbacks
      w%iterations = summary%iterations
      w%factorizations = fact_offset + an%n_factor_done
      if (an%sys_ready) w%factorizations = w%factorizations + sparse_factor_count(an%sys)
      w%krylov_solves = summary%krylov_solves
      w%krylov_iterations = summary%krylov_iterations
      w%krylov_failures = summary%krylov_failures
      w%reused_solves = summary%reused_solves
      w%accuracy_cutbacks = summary%accuracy_cutbacks
      w%w_ext = summary%w_ext
      w%max_open_ratio = summary%max_open_ratio
      w%max_statev_inc = summary%max_statev_inc
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

    !> Message of a stop requested by a user routine (XIT, STDB_ABQERR with LOP = -3): the deck position of the
    !> properties of the first element whose call asks to stop (*UEL PROPERTY or *USER MATERIAL data line), found by
    !> element loops over growing prefixes of the element list (residual only), then the routine's message.
    function stop_message(time, dt, period, nlgeom) result(text)
      real(dp), intent(in) :: time(2), dt, period
      logical, intent(in) :: nlgeom
      character(len=:), allocatable :: text, what
      type(model_t), allocatable :: sub
      integer :: lo, hi, mid, ie, ip, im
      text = abaqus_stop_message()
      if (len_trim(text) == 0) text = 'XIT called without a message'
      allocate (sub, source=model)
      ! smallest prefix length whose element loop asks to stop: doubling, then bisection
      lo = 0
      hi = 1
      do
        hi = min(hi, model%nelem)
        if (prefix_stops(sub, hi, time, dt, period, nlgeom)) exit
        if (hi == model%nelem) then
          hi = 0
          exit
        end if
        lo = hi
        hi = 2 * hi
      end do
      if (hi > 0) then
        do while (hi - lo > 1)
          mid = (lo + hi) / 2
          if (prefix_stops(sub, mid, time, dt, period, nlgeom)) then
            hi = mid
          else
            lo = mid
          end if
        end do
      end if
      call abaqus_clear_stop()
      ie = hi
      what = ''
      if (ie > 0) then
        if (model%elem_kind(ie) == etype_user) then
          ip = 0
          if (allocated(model%elem_uelprop)) ip = model%elem_uelprop(ie)
          if (ip > 0) what = model%uelprops(ip)%pos%file//':'//itoa(model%uelprops(ip)%pos%line)// &
            ': *UEL PROPERTY: rejected by UEL: '
        else
          im = model_find_material_of(ie)
          if (im > 0) then
            if (model%materials(im)%has_user .and. allocated(model%materials(im)%user_pos%file)) what = &
              model%materials(im)%user_pos%file//':'//itoa(model%materials(im)%user_pos%line)// &
              ': *USER MATERIAL: rejected by UMAT: '
          end if
        end if
        if (len(what) == 0) what = 'a user routine asked to end the analysis (XIT): '
        text = what//text//' (element '//itoa(model%elem_id(ie))//', step '//itoa(is)//', increment '// &
          itoa(kinc)//')'
      else
        text = 'a user routine asked to end the analysis (XIT): '//text
      end if
    end function stop_message

    !> True when the element loop over the first n elements (residual only) has a user routine ask to stop.
    logical function prefix_stops(sub, n, time, dt, period, nlgeom)
      type(model_t), intent(inout) :: sub
      integer, intent(in) :: n
      real(dp), intent(in) :: time(2), dt, period
      logical, intent(in) :: nlgeom
      character(len=:), allocatable :: em
      integer :: st2
      real(dp) :: pn
      sub%nelem = n
      call abaqus_clear_stop()
      call analysis_assemble(an, sub, is, kinc, time, dt, period, nlgeom, .false., pn, st2, em)
      prefix_stops = abaqus_stop_requested()
    end function prefix_stops

    !> Material index of continuum element ie (0: none).
    integer function model_find_material_of(ie) result(im)
      integer, intent(in) :: ie
      integer :: isec
      im = 0
      if (.not. allocated(model%elem_section)) return
      isec = model%elem_section(ie)
      if (isec < 1 .or. isec > model%nsection) return
      do im = 1, model%nmat
        if (model%materials(im)%name == model%sections(isec)%material) return
      end do
      im = 0
    end function model_find_material_of

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
            if (initial) bc_init(dof) = .true.
          end do
        end do
      end do
    end subroutine apply_bc_list

    !> Prescribed value at step time t: amplitude * value, or a linear ramp from the step-start value (Abaqus).
    real(dp) function prescribed_value(dof, t) result(v)
      integer, intent(in) :: dof
      real(dp), intent(in) :: t
      if (bc_amp(dof) > 0) then
        v = amplitude_value(model%amplitudes(bc_amp(dof)), t) * bc_val(dof)
      else
        v = u_start(dof) + (t / model%steps(is)%period) * (bc_val(dof) - u_start(dof))
      end if
    end function prescribed_value

    real(dp) function column_value(iset, ivar) result(v)
      integer, intent(in) :: iset, ivar
      integer :: k, dof, nn
      v = 0.0_dp
      nn = size(model%nsets(iset)%nodes)
      do k = 1, nn
        if (mod(ivar, 10) > model%ndim) cycle
        dof = (model%nsets(iset)%nodes(k) - 1) * model%ndim + mod(ivar, 10)
        if (ivar > 10) then
          if (an%prescribed(dof)) v = v + an%fint(dof)
        else
          v = v + an%u(dof)
        end if
      end do
      if (ivar < 10 .and. nn > 0) v = v / real(nn, dp)
    end function column_value

    !> Largest change of the cohesive opening |Delta| (SVARS layout of the built-in UEL, docs/uel.md) over delta.
    subroutine cohesive_ratio(worst)
      real(dp), intent(inout) :: worst
      integer :: ie, iu, nip, ip, ipr
      real(dp) :: delta
      if (.not. routines%uel_origin == 'built-in ldfcz UEL') return
      do ie = 1, model%nelem
        if (model%elem_kind(ie) /= etype_user) cycle
        iu = model%elem_utype(ie)
        nip = merge(4, 2, model%utypes(iu)%nnode == 8)
        if (size(an%trial(ie)%svars) < 4 * nip) cycle
        ipr = model%elem_uelprop(ie)
        if (ipr == 0) cycle
        if (size(model%uelprops(ipr)%props) < 2) cycle
        delta = model%uelprops(ipr)%props(2)
        if (delta <= 0.0_dp) cycle
        do ip = 1, nip
          worst = max(worst, abs(an%trial(ie)%svars(4 * (ip - 1) + 2) - an%conv(ie)%svars(4 * (ip - 1) + 2)) / delta)
        end do
      end do
    end subroutine cohesive_ratio

    !> Largest increment of STATEV(k) over the integration points of the continuum elements (a documented
    !> convention: STATEV(7) is gamma_p of the built-in UMAT, docs/umat.md; --plastic-statev chooses another).
    subroutine statev_increment(k, worst)
      integer, intent(in) :: k
      real(dp), intent(inout) :: worst
      integer :: ie
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user) cycle
        if (.not. allocated(an%trial(ie)%statev)) cycle
        if (size(an%trial(ie)%statev, 1) < k .or. size(an%conv(ie)%statev, 1) < k) cycle
        worst = max(worst, maxval(abs(an%trial(ie)%statev(k, :) - an%conv(ie)%statev(k, :))))
      end do
    end subroutine statev_increment

    subroutine write_frame(ttot)
      real(dp), intent(in) :: ttot
      type(output_vtu_t) :: fr
      integer :: ie, nn, k, ncell, nip, ip, nsv, iu, h
      real(dp) :: s(6), p
      if (kinc_total == last_frame_inc) return
      last_frame_inc = kinc_total
      ncell = model%nelem
      allocate (fr%x(3, model%nnode), fr%u(3, model%nnode), fr%rf(3, model%nnode))
      fr%x = model%x
      fr%u = 0.0_dp
      fr%rf = 0.0_dp
      do k = 1, model%nnode
        fr%u(1:model%ndim, k) = an%u_conv((k - 1) * model%ndim + 1:k * model%ndim)
        do h = 1, model%ndim
          if (an%prescribed((k - 1) * model%ndim + h)) fr%rf(h, k) = an%fint((k - 1) * model%ndim + h)
        end do
      end do
      allocate (fr%cell_type(ncell), fr%cell_ptr(ncell + 1), fr%cell_conn(size(model%conn)), fr%cell_id(ncell))
      allocate (fr%stress(6, ncell), fr%mises(ncell), fr%sdv(n_sdv_out, ncell), fr%opening(3, ncell))
      allocate (fr%traction(ncell), fr%delta_max(ncell), fr%cohesive(ncell))
      fr%cell_ptr = model%conn_ptr
      fr%cell_conn = model%conn - 1
      fr%cell_id = model%elem_id
      fr%stress = 0.0_dp
      fr%mises = 0.0_dp
      fr%sdv = 0.0_dp
      fr%opening = 0.0_dp
      fr%traction = 0.0_dp
      fr%delta_max = 0.0_dp
      fr%cohesive = 0
      do ie = 1, ncell
        nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
        select case (model%elem_kind(ie))
        case (etype_c3d8)
          fr%cell_type(ie) = 12
        case (etype_cpe4)
          fr%cell_type(ie) = 9
        case default
          if (nn == 8) then
            fr%cell_type(ie) = 12
          else if (nn == 4) then
            fr%cell_type(ie) = 9
          else
            fr%cell_type(ie) = 2  ! poly-vertex for other user elements
          end if
        end select
        if (model%elem_kind(ie) == etype_user) then
          fr%cohesive(ie) = 1
          iu = model%elem_utype(ie)
          ! opening = top - bottom (COH3D8: node k+4 over k; COH2D4: 4 over 1, 3 over 2)
          if (nn == 8 .or. nn == 4) call cell_opening(ie, nn, fr%opening(:, ie))
          nip = merge(4, 2, nn == 8)
          nsv = size(an%conv(ie)%svars)
          if (nsv >= 4 * nip .and. routines%uel_origin == 'built-in ldfcz UEL') then
            do ip = 1, nip
              fr%delta_max(ie) = fr%delta_max(ie) + an%conv(ie)%svars(4 * (ip - 1) + 1) / nip
              fr%traction(ie) = fr%traction(ie) + an%conv(ie)%svars(4 * (ip - 1) + 3) / nip
            end do
          end if
        else
          nip = size(an%conv(ie)%stress, 2)
          s = 0.0_dp
          do ip = 1, nip
            if (size(an%conv(ie)%stress, 1) == 6) then
              s = s + an%conv(ie)%stress(:, ip) / nip
            else
              s(1:4) = s(1:4) + an%conv(ie)%stress(:, ip) / nip
            end if
          end do
          fr%stress(:, ie) = s
          p = (s(1) + s(2) + s(3)) / 3.0_dp
          fr%mises(ie) = sqrt(1.5_dp * ((s(1) - p)**2 + (s(2) - p)**2 + (s(3) - p)**2 + &
            2.0_dp * (s(4)**2 + s(5)**2 + s(6)**2)))
          k = min(n_sdv_out, size(an%conv(ie)%statev, 1))
          do ip = 1, nip
            fr%sdv(1:k, ie) = fr%sdv(1:k, ie) + an%conv(ie)%statev(1:k, ip) / nip
          end do
        end if
      end do
      call output_vtu_frame(out, fr, ttot)
    end subroutine write_frame

    subroutine cell_opening(ie, nn, op)
      integer, intent(in) :: ie, nn
      real(dp), intent(out) :: op(3)
      integer :: k, nb, nt, d
      op = 0.0_dp
      do k = 1, nn / 2
        nb = model%conn(model%conn_ptr(ie) + k - 1)
        if (nn == 8) then
          nt = model%conn(model%conn_ptr(ie) + k + 3)
        else
          nt = model%conn(model%conn_ptr(ie) + 4 - k)
        end if
        do d = 1, model%ndim
          op(d) = op(d) + (an%u_conv((nt - 1) * model%ndim + d) - an%u_conv((nb - 1) * model%ndim + d)) / (nn / 2)
        end do
      end do
    end subroutine cell_opening

    subroutine write_summary()
      character(len=160) :: line
      real(dp) :: err
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
      write (line, '(a,f10.3,a)') 'solver setup (pattern, METIS ordering, MUMPS analysis) ', summary%t_analysis, ' s'
      call output_log(out, trim(line))
      write (line, '(a,i0,a)') 'peak memory (VmHWM) ', summary%peak_kb, ' kB'
      call output_log(out, trim(line))
      err = abs(summary%w_ext - summary%e_int) / max(abs(summary%w_ext), abs(summary%e_int), tiny(1.0_dp))
      write (line, '(a,es12.4,a,es12.4,a,es10.2)') 'energy balance: external work ', summary%w_ext, &
        ' N mm, stored + dissipated ', summary%e_int, ' N mm, relative difference ', err
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
    end subroutine write_summary

  end subroutine run_analysis

  !> Name of a Newton variant.
  pure function newton_mode_name(code) result(name)
    integer, intent(in) :: code
    character(len=8) :: name
    select case (code)
    case (newton_modified)
      name = 'modified'
    case (newton_krylov)
      name = 'krylov'
    case (newton_auto)
      name = 'auto'
    case default
      name = 'full'
    end select
  end function newton_mode_name

  !> Code of a Newton variant name (full, modified, krylov, auto); 0 when unknown.
  pure integer function newton_mode_code(name) result(code)
    character(len=*), intent(in) :: name
    select case (name)
    case ('full')
      code = newton_full
    case ('modified')
      code = newton_modified
    case ('krylov')
      code = newton_krylov
    case ('auto')
      code = newton_auto
    case default
      code = 0
    end select
  end function newton_mode_code

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

  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

  pure function rtoa(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=24) :: b
    write (b, '(es12.5)') x
    s = trim(adjustl(b))
  end function rtoa

end module static_solver
