!> Newton convergence test with Abaqus/Standard's criteria (Abaqus Analysis User's Guide, "Convergence criteria for
!> nonlinear problems"): the largest residual force r_max must not exceed R_n * q_avg, q_avg being the time-averaged
!> typical force of the step, and the largest displacement correction c_max must not exceed C_n * du_max, du_max the
!> largest displacement increment of the increment. A residual below 1e-8 q_avg is accepted alone (linear increment);
!> a model without forces (q_avg ~ 0) converges when r_max is negligible.
module convergence_check
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: newton_converged, typical_force

  real(dp), parameter :: linear_ratio = 1.0e-8_dp   !< Abaqus epsilon^l: residual small enough without a correction
  real(dp), parameter :: zero_force = 1.0e-10_dp    !< forces (N) below this count as zero

contains

  !> Convergence of the Newton iteration.
  pure logical function newton_converged(r_max, q_avg, c_max, du_max, r_n, c_n, iteration) result(ok)
    real(dp), intent(in) :: r_max    !< largest residual force component on the free dofs
    real(dp), intent(in) :: q_avg    !< time-averaged typical force
    real(dp), intent(in) :: c_max    !< largest component of the last correction
    real(dp), intent(in) :: du_max   !< largest component of the displacement increment
    real(dp), intent(in) :: r_n      !< residual tolerance R_n (0.005)
    real(dp), intent(in) :: c_n      !< correction tolerance C_n (0.01)
    integer, intent(in) :: iteration !< corrections solved so far in this increment (0 = none)
    if (q_avg <= zero_force) then
      ok = r_max <= zero_force
      return
    end if
    if (r_max <= linear_ratio * q_avg) then
      ok = .true.
      return
    end if
    ok = iteration >= 1 .and. r_max <= r_n * q_avg .and. c_max <= c_n * du_max
  end function newton_converged

  !> Typical force magnitude of one state: the mean of |f_i| over the non-zero components (internal forces and
  !> reactions alike), as Abaqus' spatial average of the flux over the model.
  pure real(dp) function typical_force(f) result(q)
    real(dp), intent(in) :: f(:)  !< internal force vector (all dofs)
    real(dp) :: fmax
    integer :: n
    fmax = maxval(abs(f), mask=.true.)
    if (size(f) == 0 .or. fmax <= 0.0_dp) then
      q = 0.0_dp
      return
    end if
    n = count(abs(f) > 1.0e-12_dp * fmax)
    q = sum(abs(f), mask=abs(f) > 1.0e-12_dp * fmax) / real(max(n, 1), dp)
  end function typical_force

end module convergence_check
