!> One increment of a static step, in the words of Abaqus/Standard's description of a nonlinear step: a step is
!> broken into increments; each increment is found by Newton iterations from the converged state at its start, and
!> an attempt that does not converge (or whose result a routine or an accuracy bound rejects) is abandoned and the
!> increment attempted again with a smaller time increment (a cutback). The increment is passed explicitly to every
!> phase of the increment loop (static_step), to the Newton iteration (newton_iteration), to the element loop
!> (analysis_core: KSTEP, KINC, TIME, DTIME, PERIOD, LFLAGS of UEL and UMAT) and to the prescribed values
!> (boundary_table), so that nothing reaches them by host association.
module increment
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: increment_t, increment_time, increment_end

  !> The increment under way and its current attempt.
  type :: increment_t
    integer :: step = 0                 !< step number (KSTEP)
    integer :: kinc = 0                 !< increment number in the step (KINC)
    integer :: attempt = 0              !< attempt of the increment (1, then 1 more after each cutback)
    real(dp) :: t_step = 0.0_dp         !< step time at the start of the increment
    real(dp) :: t_total0 = 0.0_dp       !< total time at the start of the step
    real(dp) :: dt = 0.0_dp             !< time increment of the attempt (DTIME)
    real(dp) :: period = 1.0_dp         !< time period of the step (PERIOD)
    logical :: nlgeom = .false.         !< the step is geometrically nonlinear (NLGEOM)
    logical :: extrapolated = .false.   !< the attempt starts from an extrapolated state (UEL LFLAGS(5) = 1; the
                                        !< first element loop of the attempt only)
    integer :: iter = 0                 !< Newton iterations of the attempt
    real(dp) :: pnewdt = 1.0_dp         !< smallest PNEWDT the user routines asked for in the attempt
    real(dp) :: opening = 0.0_dp        !< largest cohesive opening increment / delta of the attempt (accuracy bound)
    character(len=64) :: cause = ''     !< why the attempt was cut back ('' when it converged)
  end type increment_t

contains

  !> TIME(1:2) of the user routines: step and total time at the start of the increment.
  pure function increment_time(inc) result(time)
    type(increment_t), intent(in) :: inc  !< the increment
    real(dp) :: time(2)
    time = [inc%t_step, inc%t_total0 + inc%t_step]
  end function increment_time

  !> Step time at the end of the increment (where prescribed values and loads are evaluated).
  pure real(dp) function increment_end(inc) result(t)
    type(increment_t), intent(in) :: inc  !< the increment
    t = inc%t_step + inc%dt
  end function increment_end

end module increment
