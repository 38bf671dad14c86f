!> The Abaqus/Standard UMAT calling sequence as a Fortran abstract interface.
!>
!> A procedure pointer of this interface lets the continuum elements call the built-in ldfcz UMAT or a user's own
!> UMAT (compiled from an Abaqus user file, loaded at run time) exactly as Abaqus/Standard calls it
!> (docs/conventions.md, "Abaqus UMAT"). The 37 arguments are in Abaqus order with the types that
!> INCLUDE 'ABA_PARAM.INC' gives them (REAL*8 for A-H and O-Z, default INTEGER for I-N, CHARACTER*80 CMNAME).
!> A C caller would add the hidden length of CMNAME as a 38th argument; Fortran callers do not see it.
!>
!> The dummies deliberately carry no INTENT: Abaqus user routines are written without it (implicit typing from
!> ABA_PARAM.INC), and INTENT is a characteristic of a procedure, so an interface with INTENT could not be
!> associated with them. What each argument carries is documented in docs/elements.md.
module solid_umat_interface
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: umat_interface

  abstract interface
    !> Abaqus UMAT: update STRESS, STATEV, energies and return DDSDDE for one integration point.
    subroutine umat_interface(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
        time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
        pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
      import :: dp
      integer :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
      integer :: jstep(4)
      character(len=80) :: cmname
      real(dp) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens), sse, spd, scd, rpl
      real(dp) :: ddsddt(ntens), drplde(ntens), drpldt, stran(ntens), dstran(ntens), time(2), dtime
      real(dp) :: temp, dtemp, predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), pnewdt, celent
      real(dp) :: dfgrd0(3, 3), dfgrd1(3, 3)
    end subroutine umat_interface
  end interface

end module solid_umat_interface
