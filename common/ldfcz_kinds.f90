!> Kind parameters shared by every module of ldfcz (physics cores, adapters, host).
module ldfcz_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int32, int64
  implicit none
  private
  public :: dp, i4, i8

  integer, parameter :: dp = real64  !< double precision, as Abaqus' REAL*8
  integer, parameter :: i4 = int32   !< default integer width of the Abaqus interfaces
  integer, parameter :: i8 = int64   !< wide integers (sparse pattern sizes, MUMPS 64-bit counts)
end module ldfcz_kinds
