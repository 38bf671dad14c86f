!> Finiteness test of real(dp) values by their bit pattern (exponent field not all ones): the same answer as
!> ieee_is_finite of the intrinsic module ieee_arithmetic, without that module. gfortran saves and restores the
!> floating-point environment around every call of a procedure that uses ieee_arithmetic, directly or through a
!> module it uses (_gfortran_ieee_procedure_entry/exit): through the UMAT and UEL adapters that cost about 4 % of
!> the element loop of a peel run (docs/performance.md). The physics cores and their adapters use this one.
module ldfcz_finite
  use ldfcz_kinds, only: dp, i8
  implicit none
  private
  public :: is_finite

contains

  !> .true. unless x is an infinity or a NaN (integer operations only: raises no floating-point exception).
  elemental logical function is_finite(x)
    real(dp), intent(in) :: x   !< value to test
    is_finite = iand(shiftr(transfer(x, 0_i8), 52), 2047_i8) /= 2047_i8
  end function is_finite

end module ldfcz_finite
