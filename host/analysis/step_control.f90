!> Automatic time incrementation of a static step with Abaqus/Standard semantics (one small routine per event):
!> - cutback after a failed attempt: dt <- 0.25 dt (non-convergence, divergence, element failure) or
!>   dt <- min(PNEWDT) dt when a UEL/UMAT asked for PNEWDT < 1; below the minimum increment the step stops;
!> - after a converged increment: dt grows by 1.5 once two consecutive increments converged in at most
!>   `easy_iterations` Newton iterations, capped by min(PNEWDT) > 1 of the user routines and by the maximum increment;
!> - the last increment is cut to end exactly at the step period. DIRECT: fixed increments, no cutback;
!> - at most max_cutbacks cutbacks per increment (Abaqus I_A = 5 attempts after the first);
!> - accuracy bounds of the host (--max-opening-increment: the cohesive opening increment, paper section 7;
!>   --max-plastic-increment: a material's plastic strain increment): a converged increment whose bounded quantity
!>   grew by more than its bound is redone with dt * max(0.1, 0.8 bound / measured) (step_control_accuracy), and
!>   the next increment aims at 0.8 of each bound (step_control_converged). Every increment-size rule is here.
module step_control
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: step_control_t, step_control_init, step_control_cutback, step_control_converged, step_control_done
  public :: step_control_dt, step_control_accuracy, step_control_exhausted, max_cutbacks

  real(dp), parameter :: cutback_factor = 0.25_dp  !< Abaqus D_f
  real(dp), parameter :: growth_factor = 1.5_dp    !< Abaqus D_G
  real(dp), parameter :: time_tol = 1.0e-12_dp     !< relative tolerance on reaching the period
  integer, parameter :: max_cutbacks = 5            !< Abaqus I_A: cutbacks per increment at most
  real(dp), parameter :: bound_target = 0.8_dp      !< the next increment aims at this fraction of a bound
  real(dp), parameter :: accuracy_cut_min = 0.1_dp  !< smallest cutback factor of an accuracy redo
  real(dp), parameter :: plastic_cut_min = 0.25_dp  !< smallest factor of the plastic-increment prediction

  type :: step_control_t
    real(dp) :: period = 1.0_dp       !< step period
    real(dp) :: dt_min = 1.0e-5_dp    !< minimum increment
    real(dp) :: dt_max = 1.0_dp       !< maximum increment
    logical :: direct = .false.       !< fixed increments
    integer :: easy_iterations = 5    !< "easy" increment: at most this many iterations
    real(dp) :: t = 0.0_dp            !< step time reached (converged)
    real(dp) :: dt = 1.0_dp           !< size of the next attempt (before clipping to the period)
    integer :: easy_count = 0         !< consecutive easy increments
    integer :: cutbacks = 0           !< cutbacks of the current increment
    integer :: total_cutbacks = 0     !< cutbacks in the step
  end type step_control_t

contains

  !> Start a step.
  pure subroutine step_control_init(sc, dt_initial, period, dt_min, dt_max, direct)
    type(step_control_t), intent(out) :: sc  !< controller
    real(dp), intent(in) :: dt_initial       !< initial increment
    real(dp), intent(in) :: period           !< step period
    real(dp), intent(in) :: dt_min           !< minimum increment
    real(dp), intent(in) :: dt_max           !< maximum increment
    logical, intent(in) :: direct            !< fixed increments
    sc%period = period
    sc%dt_min = dt_min
    sc%dt_max = dt_max
    sc%direct = direct
    sc%dt = min(dt_initial, period)
    if (.not. direct) sc%dt = min(sc%dt, dt_max)
    sc%t = 0.0_dp
  end subroutine step_control_init

  !> Size of the next attempt: the current dt, cut so that the step ends exactly at its period and, with points
  !> (step times, ascending: *OUTPUT, TIME POINTS=), so that the increment ends exactly on the next point it would
  !> pass or reach (as Abaqus/Standard adjusts its increments to the time points).
  pure real(dp) function step_control_dt(sc, points) result(dt)
    type(step_control_t), intent(in) :: sc      !< controller
    real(dp), intent(in), optional :: points(:) !< time points of the step
    integer :: k
    dt = sc%dt
    if (sc%t + dt >= sc%period * (1.0_dp - time_tol)) dt = sc%period - sc%t
    if (.not. present(points)) return
    do k = 1, size(points)
      if (points(k) <= sc%t + time_tol * sc%period) cycle
      if (sc%t + dt >= points(k) - time_tol * sc%period) dt = points(k) - sc%t
      exit
    end do
  end function step_control_dt

  !> The attempt of size dt_attempt failed. pnewdt < 1: the user routines' request; otherwise pass pnewdt >= 1
  !> (the standard factor 0.25 is used). ok = .false. when the new increment would be below the minimum (or DIRECT).
  pure subroutine step_control_cutback(sc, dt_attempt, pnewdt, ok)
    type(step_control_t), intent(inout) :: sc  !< controller
    real(dp), intent(in) :: dt_attempt         !< size of the failed attempt
    real(dp), intent(in) :: pnewdt             !< min PNEWDT of the attempt (>= 1: none requested)
    logical, intent(out) :: ok                 !< a retry is possible
    real(dp) :: f
    sc%easy_count = 0
    sc%cutbacks = sc%cutbacks + 1
    sc%total_cutbacks = sc%total_cutbacks + 1
    if (pnewdt < 1.0_dp .and. pnewdt > 0.0_dp) then
      f = pnewdt
    else
      f = cutback_factor
    end if
    sc%dt = f * dt_attempt
    ok = (.not. sc%direct) .and. sc%dt >= sc%dt_min * (1.0_dp - time_tol)
  end subroutine step_control_cutback

  !> True when the current increment has had its max_cutbacks cutbacks: no further attempt.
  pure logical function step_control_exhausted(sc)
    type(step_control_t), intent(in) :: sc  !< controller
    step_control_exhausted = sc%cutbacks > max_cutbacks
  end function step_control_exhausted

  !> Accuracy check of a converged attempt of size dt_attempt: redo when the bounded quantity's increment
  !> (measured) exceeds its bound, unless the increment is already at the minimum or fixed (DIRECT); pnewdt is then
  !> the cutback factor of the redo, max(0.1, 0.8 bound / measured).
  pure subroutine step_control_accuracy(sc, dt_attempt, measured, bound, redo, pnewdt)
    type(step_control_t), intent(in) :: sc     !< controller
    real(dp), intent(in) :: dt_attempt         !< size of the converged attempt
    real(dp), intent(in) :: measured           !< largest increment of the bounded quantity
    real(dp), intent(in) :: bound              !< its bound (<= 0: none)
    logical, intent(out) :: redo               !< the attempt must be redone smaller
    real(dp), intent(inout) :: pnewdt          !< cutback factor when redo
    redo = .false.
    if (bound <= 0.0_dp .or. sc%direct) return
    redo = measured > bound .and. dt_attempt > sc%dt_min * (1.0_dp + 1.0e-9_dp)
    if (redo) pnewdt = max(accuracy_cut_min, bound_target * bound / measured)
  end subroutine step_control_accuracy

  !> The attempt of size dt_attempt converged in `iterations` iterations; pnewdt = min over the user routines
  !> (a large value when none asked for anything). Advances the time and chooses the next increment: the automatic
  !> growth, then the host's accuracy bounds when given (opening: the next increment aims at 0.8 of the bound,
  !> growing at most x1.5 after an easy increment and honouring PNEWDT > 1; plastic: a prediction from the
  !> material's plastic strain increment, at least a quarter of the increment just converged).
  pure subroutine step_control_converged(sc, dt_attempt, iterations, pnewdt, opening, opening_bound, plastic, &
      plastic_bound, clipped)
    type(step_control_t), intent(inout) :: sc  !< controller
    real(dp), intent(in) :: dt_attempt         !< converged increment
    integer, intent(in) :: iterations          !< Newton iterations it needed
    real(dp), intent(in) :: pnewdt             !< min PNEWDT over the user routines (>= 1)
    real(dp), intent(in), optional :: opening        !< largest cohesive opening increment (delta units; 0: none)
    real(dp), intent(in), optional :: opening_bound  !< its bound (<= 0: none)
    real(dp), intent(in), optional :: plastic        !< largest plastic strain increment (0: none)
    real(dp), intent(in), optional :: plastic_bound  !< its bound (<= 0: none)
    !> the attempt was shortened to end on a time point: the next one grows from the size before that cut
    logical, intent(in), optional :: clipped
    real(dp) :: f, dt_base
    sc%t = sc%t + dt_attempt
    if (sc%t >= sc%period * (1.0_dp - time_tol)) sc%t = sc%period
    sc%cutbacks = 0
    if (sc%direct) return
    ! growth from the increment just converged
    dt_base = dt_attempt
    if (present(clipped)) then
      if (clipped) dt_base = max(dt_attempt, sc%dt)
    end if
    if (iterations <= sc%easy_iterations) then
      sc%easy_count = sc%easy_count + 1
    else
      sc%easy_count = 0
    end if
    f = 1.0_dp
    if (sc%easy_count >= 2) then
      f = growth_factor
      sc%easy_count = 0
    end if
    if (pnewdt >= 1.0_dp) f = min(f, pnewdt)
    sc%dt = min(f * dt_base, sc%dt_max)
    if (present(opening) .and. present(opening_bound)) then
      if (opening > 0.0_dp .and. opening_bound > 0.0_dp) then
        f = merge(growth_factor, 1.0_dp, iterations <= sc%easy_iterations)
        if (pnewdt >= 1.0_dp) f = min(f, pnewdt)
        sc%dt = min(sc%dt_max, dt_attempt * min(f, bound_target * opening_bound / opening))
      end if
    end if
    if (present(plastic) .and. present(plastic_bound)) then
      if (plastic > 0.0_dp .and. plastic_bound > 0.0_dp) sc%dt = min(sc%dt, max(dt_attempt, sc%dt_min) * &
        max(plastic_cut_min, bound_target * plastic_bound / plastic))
    end if
  end subroutine step_control_converged

  !> True when the step period is reached.
  pure logical function step_control_done(sc)
    type(step_control_t), intent(in) :: sc  !< controller
    step_control_done = sc%t >= sc%period
  end function step_control_done

end module step_control
