!> The Newton iteration of one attempt of an increment, in the variants of solver_options (full, modified,
!> krylov, auto), with the Abaqus convergence criteria (convergence_check) and the cutback reasons of Abaqus.
module newton_iteration
  use ldfcz_kinds, only: dp
  use model_types, only: model_t
  use analysis_core, only: analysis_t, analysis_assemble
  use increment, only: increment_t
  use linear_constraints, only: constraints_residual, constraints_apply
  use convergence_check, only: newton_converged, typical_force
  use sparse_system, only: sparse_system_t, sparse_factorize, sparse_solve, sparse_is_factored, &
    sparse_solve_krylov, sparse_factors_exact, sparse_factor_flops, sparse_iteration_flops, sparse_pipelined, &
    sparse_factor_install
  use output_files, only: output_t, output_log
  use solver_options, only: newton_modified, newton_krylov, newton_auto
  use run_summary, only: run_summary_t
  use solver_text, only: itoa, rtoa
  implicit none
  private
  public :: newton_state_t, newton_solve, newton_forget_factors

  real(dp), parameter :: modified_contraction = 0.5_dp  !< modified Newton: r_k/r_(k-1) above this -> new tangent
  integer, parameter :: modified_max_reuse = 8          !< modified Newton: new tangent after this many reuses
  real(dp), parameter :: krylov_rel_tol = 1.0e-8_dp     !< GMRES relative residual (an exact Newton step)
  integer, parameter :: krylov_max_iter = 30            !< GMRES budget of mode krylov (restart = budget)
  ! Mode auto's GMRES budget with older factors (krylov_budget below): the iterations that take about
  ! krylov_budget_share of a factorization's time. Counted in operations, so that the same deck takes the same path
  ! on every run (the budget once came from measured times: the application scene took 55-64 increments for the
  ! same 30 um), and converted to time by krylov_speed, a GMRES iteration's operations per second relative to a
  ! factorization's, measured on the application scene (89 595 DOFs, its options, SkylakeX kernels, the idle 2-core
  ! machine; docs/performance.md "OpenBLAS kernels"): 0.345 s per factorization of 3.50e9 operations, 28.3 ms per
  ! iteration of 6.74e7, i.e. 1.01e10 and 2.38e9 per second. The budget there is int(0.5 x 0.235 x 52.0) = 6, what
  ! half the measured time ratio gave on that machine (0.345 / 0.0283 / 2 = 6.1).
  real(dp), parameter :: krylov_budget_share = 0.5_dp   !< GMRES time with older factors, of a factorization's
  real(dp), parameter :: krylov_speed = 0.235_dp        !< operations per second: GMRES iteration / factorization
  ! Mode auto pipelines its refactorizations (two factor instances, sparse_system): when GMRES with the last factors
  ! has not converged within its budget, the factorization of the current tangent begins (on a thread of its own
  ! when the run has two) while GMRES goes on with the older factors for krylov_overlap iterations, about one
  ! factorization's time (counted in operations, as the budget); then the new factors are installed (waited for if
  ! late) and GMRES restarts from its iterate with them. The iterates depend on those counts only, never on when
  ! the factorization ends: one thread runs the same schedule in sequence (docs/performance.md, "Pipelined
  ! refactorization"). The older factors' iterations are no longer discarded either: GMRES continues from them.
  ! Mode auto is an inexact Newton-Krylov method: GMRES is stopped at the relative residual eta_k of
  ! Eisenstat & Walker (1996, SIAM J. Sci. Comput. 17:16-32, "choice 2": eta_k = gamma (|r_k| / |r_(k-1)|)^2,
  ! safeguarded by gamma eta_(k-1)^2 when that exceeds 0.1, capped by eta_max), and never solved more accurately
  ! than the Newton criterion needs: eta_k |r_k| >= 0.1 R_n q_avg, a linear residual that small (in 2-norm, so in
  ! every dof) cannot keep the force criterion r_max <= R_n q_avg from being met. Convergence is still decided by
  ! the true residual, so the converged results are those of full Newton within its tolerance (deck_newton_modes);
  ! the early iterations, far from the solution, no longer pay for exact linear solves (docs/performance.md).
  real(dp), parameter :: ew_gamma = 0.9_dp              !< Eisenstat-Walker gamma
  real(dp), parameter :: ew_eta_max = 0.1_dp            !< largest forcing term (also the first iteration's)
  ! Mode auto also skips the tangent of an iteration that is likely to be the last, since a converged iteration's
  ! tangent is never used. Both criteria of that iteration are tested beforehand: the correction criterion
  ! exactly (the last correction and the displacement increment are known before its element loop), the force
  ! criterion on the residual expected at quadratic convergence, r_k = r_(k-1) (r_(k-1) / r_(k-2))^2, within
  ! skip_margin of R_n q_avg. Then the elements compute forces only (UEL LFLAGS(3) = 5). If the iteration does
  ! not converge after all, GMRES solves with the tangent still assembled, that of the previous iterate (a Newton
  ! step with a one-iteration-old Jacobian, close to the solution), and the next iteration assembles it anew. The
  ! estimate at the last rate, r_(k-1)^2 / r_(k-2) within 10 R_n q_avg, skipped as often but failed twice as
  ! often, half of its failures on the correction criterion (docs/performance.md, "A sharper last-iteration test").
  real(dp), parameter :: skip_margin = 1.0_dp           !< skip when the expected r_k < skip_margin R_n q_avg
  ! The first iteration of an increment evaluates the elements at the start of the increment, the prescribed dofs
  ! at their start values, and carries the prescribed increment du_p through that tangent: it solves
  ! K_ff du_f = r_f - K_fp du_p (r = f_ext - f_int), then sets u_p to its end value (as CalculiX does; that Abaqus
  ! does so is inferred, docs/host.md "Analysis"; the alternative, u_p at its end value before the first element
  ! loop, strains the layer beside a loaded face by the whole increment and costs Newton iterations:
  ! docs/performance.md). A change below carry_negligible of the largest displacement (round-off of an extrapolated
  ! start on a linear ramp) is applied directly instead. Modified Newton reusing its factors in the first iteration
  ! has no tangent to carry with: it applies u_p before the element loop.
  real(dp), parameter :: carry_negligible = 1.0e-10_dp

  !> What the variants carry from one iteration, attempt and increment to the next.
  type :: newton_state_t
    integer :: reuse_count = 0          !< modified Newton: solves with the current factors (saved in restarts)
    integer :: tangents_skipped = 0     !< mode auto: iterations assembled without a tangent (this run)
    integer :: stale_solves = 0         !< of those, not converged: solved with the previous iterate's tangent
    character(len=:), allocatable :: last_reason  !< the last cutback reason logged at default verbosity
    integer :: reason_repeats = 0       !< cutbacks for that same reason since it was logged
  end type newton_state_t

contains

  !> Mode auto's GMRES budget with the last factors (a fresh tangent preconditioned by an older factorization): as
  !> many iterations as cost krylov_budget_share of a factorization, the work counted in floating-point
  !> operations from the sizes of the factors and the matrix (sparse_system), so that the same deck takes the same
  !> path on every run, thread count and process count; between 2 and krylov_max_iter.
  integer function krylov_budget(sys) result(kbudget)
    type(sparse_system_t), intent(in) :: sys  !< factored system
    real(dp) :: f_fact, f_iter
    kbudget = krylov_max_iter
    f_fact = sparse_factor_flops(sys)
    f_iter = sparse_iteration_flops(sys)
    if (f_fact > 0.0_dp .and. f_iter > 0.0_dp) &
      kbudget = max(2, min(krylov_max_iter, int(krylov_budget_share * krylov_speed * f_fact / f_iter)))
  end function krylov_budget

  !> Mode auto's GMRES iterations with the older factors while a pipelined factorization runs (see above): as many
  !> as cost one factorization, counted in operations; between 2 and krylov_max_iter.
  integer function krylov_overlap(sys) result(koverlap)
    type(sparse_system_t), intent(in) :: sys  !< factored system
    real(dp) :: f_fact, f_iter
    koverlap = krylov_max_iter
    f_fact = sparse_factor_flops(sys)
    f_iter = sparse_iteration_flops(sys)
    if (f_fact > 0.0_dp .and. f_iter > 0.0_dp) &
      koverlap = max(2, min(krylov_max_iter, int(krylov_speed * f_fact / f_iter)))
  end function krylov_overlap

  !> After a failed attempt: modified Newton starts the next one with a fresh tangent.
  pure subroutine newton_forget_factors(ns)
    type(newton_state_t), intent(inout) :: ns  !< Newton state
    ns%reuse_count = modified_max_reuse
  end subroutine newton_forget_factors

  !> Newton iterations of an attempt of increment inc from its start an%work%u (prescribed dofs at their end values)
  !> until convergence, a cutback reason (inc%cause) or a stop asked by a user routine (stopped; nothing else is set
  !> then but inc%iter). carry: the part of an%work%u's change that the first iteration carries through the tangent
  !> (the prescribed increment, see carry_negligible above). ratios(1:inc%iter + 1) are r_max / q_avg of the
  !> iterations, for the status file. inc%pnewdt: the smallest PNEWDT the user routines asked for.
  subroutine newton_solve(an, model, inc, newton, verbose, out, ns, summary, r, ratios, q_sum, converged, stopped, &
      q_now, carry)
    type(analysis_t), intent(inout) :: an                !< analysis data, an%work%u updated
    type(model_t), intent(in) :: model                   !< the model
    type(increment_t), intent(inout) :: inc              !< the increment (iter, pnewdt, cause set)
    integer, intent(in) :: newton                        !< Newton variant (solver_options)
    logical, intent(in) :: verbose                       !< per-iteration residual lines in the log
    type(output_t), intent(inout) :: out                 !< output files
    type(newton_state_t), intent(inout) :: ns            !< Newton state
    type(run_summary_t), intent(inout) :: summary        !< solve counters
    real(dp), intent(inout) :: r(:)                      !< work array, size max(neq, 1)
    real(dp), allocatable, intent(inout) :: ratios(:)    !< r_max / q_avg per iteration (grown as needed)
    real(dp), intent(inout) :: q_sum                     !< sum of q of the converged increments of the step
    logical, intent(out) :: converged                    !< the iteration converged
    logical, intent(out) :: stopped                      !< a user routine asked to stop (XIT)
    real(dp), intent(out) :: q_now                       !< typical force of the last residual
    real(dp), intent(in) :: carry(:)                     !< (ndof) change of an%work%u carried through the first tangent
    integer :: i, stat, kit, kbudget, koverlap
    character(len=:), allocatable :: errmsg, pnewdt_who
    character(len=256) :: smsg
    real(dp) :: r_max, r_prev, r_prev2, c_max, du_max, q_avg, r_norm, r_norm_prev, eta, eta_prev, tol
    real(dp) :: pnewdt_min   ! smallest PNEWDT of the user routines (inc%pnewdt at the end)
    real(dp), allocatable :: r_copy(:), k_carry(:)
    logical :: want_k, k_fresh, k_skip, k_stale, carrying, failed

    associate (st => model%steps(inc%step), is => inc%step, kinc => inc%kinc, iter => inc%iter, outcome => inc%cause)
      converged = .false.
      stopped = .false.
      pnewdt_min = 1.0_dp
      outcome = ''
      iter = 0
      q_now = 0.0_dp
      c_max = 0.0_dp
      r_prev = huge(1.0_dp)
      r_prev2 = huge(1.0_dp)
      r_norm_prev = 0.0_dp
      eta_prev = ew_eta_max
      k_stale = .false.
      if (.not. allocated(ratios)) allocate (ratios(st%max_iter + 1))
      if (size(ratios) < st%max_iter + 1) then
        deallocate (ratios)
        allocate (ratios(st%max_iter + 1))
      end if
      newton_loop: do
        call decide_tangent()
        ! the first iteration carries the prescribed increment through the tangent, when it assembles one
        carrying = .false.
        if (iter == 0 .and. want_k .and. an%eqs%neq > 0) &
          carrying = maxval(abs(carry)) > carry_negligible * maxval(abs(an%work%u))
        if (carrying) then
          an%work%u = an%work%u - carry
          if (.not. allocated(k_carry)) allocate (k_carry(an%ndof))
          call analysis_assemble(an, model, inc, want_k, pnewdt_min, stat, errmsg, pnewdt_who, carry=carry, &
            k_carry=k_carry)
        else
          call analysis_assemble(an, model, inc, want_k, pnewdt_min, stat, errmsg, pnewdt_who)
        end if
        inc%extrapolated = .false.  ! only the first call of an increment sees the extrapolated start
        if (an%work%stop%asked) then
          stopped = .true.
          exit newton_loop
        end if
        if (stat /= 0) then
          outcome = 'cutback: element failure'
          call log_reason(errmsg)
          pnewdt_min = min(pnewdt_min, 0.25_dp)
          exit newton_loop
        end if
        if (pnewdt_min < 1.0_dp) then
          outcome = 'cutback: PNEWDT '//rtoa(pnewdt_min)
          call log_reason(pnewdt_who)
          exit newton_loop
        end if
        call form_residual()
        ! (a carried increment is not applied yet: never converged before it is)
        if (an%eqs%neq == 0 .or. (.not. carrying .and. newton_converged(r_max, q_avg, c_max, du_max, st%r_n, st%c_n, &
            iter))) then
          converged = .true.
          q_sum = q_sum + q_now
          exit newton_loop
        end if
        ! divergence: the residual grew in two consecutive iterations (after the fourth, Abaqus I_0 = 4)
        if (iter >= 4 .and. r_max > r_prev .and. r_prev > r_prev2) then
          outcome = 'cutback: diverging'
          exit newton_loop
        end if
        if (iter >= st%max_iter) then
          outcome = 'cutback: '//itoa(iter)//' iterations'
          exit newton_loop
        end if
        if (iter == 0) then
          r_prev = huge(1.0_dp)
          r_prev2 = huge(1.0_dp)
        end if
        call linear_step(failed)
        if (failed) exit newton_loop
        iter = iter + 1
        r_norm_prev = r_norm
        c_max = maxval(abs(r(1:max(an%eqs%neq, 1))))
        if (carrying) an%work%u = an%work%u + carry
        do i = 1, an%ndof
          if (an%eqs%eq(i) > 0) an%work%u(i) = an%work%u(i) + r(an%eqs%eq(i))
        end do
        if (an%eqs%cs%n > 0) call constraints_apply(an%eqs%cs, an%work%u)
      end do newton_loop
    end associate
    inc%pnewdt = pnewdt_min
  contains
    !> Whether this iteration assembles a tangent (want_k): modified Newton reuses the factors while they contract
    !> (docs/performance.md); mode auto skips it for an iteration likely to converge (see skip_margin above), never
    !> twice running (k_skip, k_stale). Keeps r_prev, r_prev2.
    subroutine decide_tangent()
      want_k = .true.
      if (newton == newton_modified .and. an%eqs%sys_ready) then
        if (sparse_is_factored(an%eqs%sys)) then
          want_k = ns%reuse_count >= modified_max_reuse
          if (inc%iter >= 1 .and. r_prev < huge(1.0_dp)) then
            if (r_max > modified_contraction * r_prev) want_k = .true.
          end if
        end if
      end if
      ! mode auto: no tangent for an iteration likely to converge (see skip_margin above); never twice running
      k_skip = newton == newton_auto .and. inc%iter >= 2 .and. .not. k_stale .and. an%eqs%sys_ready
      if (k_skip) k_skip = sparse_is_factored(an%eqs%sys) .and. r_max < r_prev   ! (contracting: no overflow below)
      if (k_skip) k_skip = c_max <= model%steps(inc%step)%c_n * maxval(abs(an%work%u - an%state%u_conv))
      if (k_skip) k_skip = r_max * (r_max / r_prev)**2 < skip_margin * model%steps(inc%step)%r_n * q_avg
      k_stale = k_skip
      if (k_skip) then
        want_k = .false.
        ns%tangents_skipped = ns%tangents_skipped + 1
      end if
      if (inc%iter >= 1) then
        r_prev2 = r_prev
        r_prev = r_max
      end if
    end subroutine decide_tangent

    !> The residual r of the free equations (with a carried increment: predicted at its end, r - K carry; *EQUATION:
    !> an eliminated dof's on its masters), its largest entry and norm, the typical force q_now and q_avg, du_max and
    !> the iteration's ratio r_max / q_avg; the verbose line.
    subroutine form_residual()
      do i = 1, an%ndof
        if (an%eqs%eq(i) > 0) r(an%eqs%eq(i)) = an%work%fext(i) + an%work%fdl(i) - an%work%fint(i)
      end do
      if (carrying) then
        ! the residual predicted at the end values of the prescribed dofs: r - K carry
        do i = 1, an%ndof
          if (an%eqs%eq(i) > 0) r(an%eqs%eq(i)) = r(an%eqs%eq(i)) - k_carry(i)
        end do
      end if
      ! *EQUATION: the residual of an eliminated dof acts on its masters
      if (an%eqs%cs%n > 0 .and. an%eqs%neq > 0) then
        if (carrying) then
          call constraints_residual(an%eqs%cs, an%eqs%eq, an%work%fext + an%work%fdl - an%work%fint - k_carry, r)
        else
          call constraints_residual(an%eqs%cs, an%eqs%eq, an%work%fext + an%work%fdl - an%work%fint, r)
        end if
      end if
      r_max = 0.0_dp
      if (an%eqs%neq > 0) r_max = maxval(abs(r(1:an%eqs%neq)))
      r_norm = 0.0_dp
      if (an%eqs%neq > 0) r_norm = norm2(r(1:an%eqs%neq))
      ! typical force: of the internal forces, or of the applied loads where they are larger (the first iteration
      ! of a load-controlled increment starts from zero internal force; Abaqus counts the applied loads in q)
      ! (a carried increment: of the internal forces predicted at its end, f_int + K carry)
      if (carrying) then
        q_now = max(typical_force(an%work%fint + k_carry), typical_force(an%work%fext + an%work%fdl))
      else
        q_now = max(typical_force(an%work%fint), typical_force(an%work%fext + an%work%fdl))
      end if
      q_avg = (q_sum + q_now) / real(inc%kinc, dp)
      du_max = maxval(abs(an%work%u - an%state%u_conv))
      if (carrying) du_max = maxval(abs(an%work%u + carry - an%state%u_conv))
      ratios(inc%iter + 1) = 0.0_dp
      if (q_avg > 1.0e-300_dp * r_max) ratios(inc%iter + 1) = r_max / q_avg   ! (no overflow when q_avg ~ 0)
      if (verbose) call output_log(out, '    step '//itoa(inc%step)//' inc '//itoa(inc%kinc)//' inc%iter '//itoa(inc%iter)// &
        ': r_max '//rtoa(r_max)//' q_avg '//rtoa(q_avg)//' c_max '//rtoa(c_max)//' du_max '//rtoa(du_max)// &
        merge(' (tangent)      ', ' (reused LU/LDL)', want_k))
    end subroutine form_residual

    !> The linear solve of the iteration into r (the Newton correction): the forcing term of mode auto, then the
    !> factors reused (modified Newton), GMRES beside a pipelined refactorization, GMRES with the last factors, or a
    !> fresh factorization. failed: a cutback (inc%cause set).
    subroutine linear_step(failed)
      logical, intent(out) :: failed  !< the step failed: a cutback
      failed = .false.
      tol = krylov_rel_tol
      if (newton == newton_auto) then
        ! inexact Newton: the forcing term eta_k (see ew_gamma above)
        eta = ew_eta_max
        if (inc%iter >= 1 .and. r_norm_prev > 0.0_dp) then
          eta = ew_gamma * (r_norm / r_norm_prev)**2
          if (ew_gamma * eta_prev**2 > 0.1_dp) eta = max(eta, ew_gamma * eta_prev**2)
        end if
        eta = min(ew_eta_max, max(eta, 0.1_dp * model%steps(inc%step)%r_n * q_avg / max(r_norm, tiny(1.0_dp))))
        eta_prev = eta
        tol = max(krylov_rel_tol, eta)
      end if
      k_fresh = .true.
      if (k_skip) then
        ! the expected convergence did not come: GMRES with the previous iterate's tangent (still assembled)
        want_k = .true.
        ns%stale_solves = ns%stale_solves + 1
      end if
      if (.not. want_k) then
        ! modified Newton: the last factors, a residual-only element loop
        call sparse_solve(an%eqs%sys, r, stat, smsg)
        ns%reuse_count = ns%reuse_count + 1
        summary%reused_solves = summary%reused_solves + 1
        k_fresh = stat /= 0
      else if (newton == newton_auto .and. sparse_pipelined(an%eqs%sys) .and. sparse_is_factored(an%eqs%sys)) then
        ! fresh tangent, GMRES preconditioned by the last factors, refactorized on the way (pipelined, see above)
        call sparse_factor_install(an%eqs%sys, stat, smsg)
        if (stat /= 0) then
          inc%cause = 'cutback: singular tangent'
          if (verbose) call output_log(out, '  '//trim(smsg))
          failed = .true.
          return
        end if
        kbudget = krylov_budget(an%eqs%sys)
        koverlap = krylov_overlap(an%eqs%sys)
        call sparse_solve_krylov(an%eqs%sys, r(1:an%eqs%neq), tol, kbudget + koverlap + krylov_max_iter, &
          krylov_max_iter, kit, stat, smsg, refactor_at=kbudget, switch_at=kbudget + koverlap)
        summary%krylov_iterations = summary%krylov_iterations + kit
        summary%krylov_solves = summary%krylov_solves + 1
        if (kit > kbudget) summary%krylov_failures = summary%krylov_failures + 1
        if (stat == 1) then
          ! still short of the forcing term after the refactorization: the best iterate, an inexact Newton step
          if (verbose) call output_log(out, '    GMRES short of its tolerance after '//itoa(kit)// &
            ' iterations (a refactorization on the way): best iterate used (an inexact Newton step)')
          stat = 0
        end if
        if (stat /= 0) then
          inc%cause = 'cutback: solve failed'
          if (stat == -10) inc%cause = 'cutback: singular tangent'
          if (verbose) call output_log(out, '  '//trim(smsg))
          failed = .true.
          return
        end if
        k_fresh = .false.
      else if ((newton == newton_krylov .or. newton == newton_auto) .and. sparse_is_factored(an%eqs%sys)) then
        ! fresh tangent, GMRES preconditioned by the last factorization
        kbudget = krylov_max_iter
        if (newton == newton_auto) kbudget = krylov_budget(an%eqs%sys)
        r_copy = r(1:an%eqs%neq)
        call sparse_solve_krylov(an%eqs%sys, r(1:an%eqs%neq), tol, kbudget, kbudget, kit, stat, smsg)
        summary%krylov_iterations = summary%krylov_iterations + kit
        if (stat == 0) then
          summary%krylov_solves = summary%krylov_solves + 1
          k_fresh = .false.
        else
          summary%krylov_failures = summary%krylov_failures + 1
          r(1:an%eqs%neq) = r_copy
        end if
      end if
      if (k_fresh) then
        if (.not. want_k) then
          inc%cause = 'cutback: solve failed'
          failed = .true.
          return
        end if
        call sparse_factorize(an%eqs%sys, stat, smsg)
        ns%reuse_count = 0
        if (stat /= 0) then
          inc%cause = 'cutback: singular tangent'
          if (verbose) call output_log(out, '  '//trim(smsg))
          failed = .true.
          return
        end if
        if (sparse_factors_exact(an%eqs%sys)) then
          call sparse_solve(an%eqs%sys, r, stat, smsg)
        else
          ! preconditioning factors only (--factors symmetric/single): GMRES with them, the whole budget; when
          ! it does not reach tol, its best iterate (the residual only decreases in GMRES) is an inexact step
          call sparse_solve_krylov(an%eqs%sys, r(1:an%eqs%neq), tol, krylov_max_iter, krylov_max_iter, kit, stat, smsg)
          summary%krylov_iterations = summary%krylov_iterations + kit
          summary%krylov_solves = summary%krylov_solves + 1
          if (stat == 1) then
            if (verbose) call output_log(out, '    GMRES with fresh preconditioning factors short of its tolerance '// &
              'after '//itoa(kit)//' iterations: best iterate used (an inexact Newton step)')
            stat = 0
          end if
        end if
        if (stat /= 0) then
          inc%cause = 'cutback: solve failed'
          failed = .true.
          return
        end if
      end if
    end subroutine linear_step

    !> A cutback's cause (element, point, routine, reason) in the log at default verbosity, once: the same reason
    !> again is only counted, and the count is logged when another reason comes.
    subroutine log_reason(reason)
      character(len=*), intent(in) :: reason  !< what the element or routine reported
      character(len=:), allocatable :: where
      if (len_trim(reason) == 0) return
      where = '  step '//itoa(inc%step)//' increment '//itoa(inc%kinc)//': cutback: '
      if (verbose) then
        call output_log(out, where//trim(reason))
        return
      end if
      if (allocated(ns%last_reason)) then
        if (ns%last_reason == trim(reason)) then
          ns%reason_repeats = ns%reason_repeats + 1
          return
        end if
        if (ns%reason_repeats > 0) call output_log(out, '  (the cutback reason before repeated '// &
          itoa(ns%reason_repeats)//' more times)')
      end if
      ns%last_reason = trim(reason)
      ns%reason_repeats = 0
      call output_log(out, where//trim(reason))
    end subroutine log_reason
  end subroutine newton_solve

end module newton_iteration
