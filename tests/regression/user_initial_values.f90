! SIGINI, SDVINI and a linear elastic UMAT for the test deck_user_initial_values (decks/single/user_initial_values.inp):
! SIGINI gives every point the uniform stress sigma11 = -100 MPa, SDVINI sets the point's first state variable to
! its z coordinate and the second to its number NPT, the UMAT (PROPS: E, nu; isotropic, small strain) carries both.
subroutine sigini(sigma, coords, ntens, ncrds, noel, npt, layer, kspt, lrebar, names)
  implicit none
  integer :: ntens, ncrds, noel, npt, layer, kspt, lrebar
  double precision :: sigma(ntens), coords(ncrds)
  character(len=80) :: names(2)
  sigma = 0.0d0
  sigma(1) = -100.0d0
end subroutine sigini

subroutine sdvini(statev, coords, nstatv, ncrds, noel, npt, layer, kspt)
  implicit none
  integer :: nstatv, ncrds, noel, npt, layer, kspt
  double precision :: statev(nstatv), coords(ncrds)
  statev = 0.0d0
  statev(1) = coords(3)
  ! the next line is longer than 132 characters on purpose: free-form sources compile as Intel Fortran takes them
  statev(2) = dble(npt) + 0.0d0 * dble(noel + layer + kspt + ncrds + nstatv) + 0.0d0 * dble(noel + layer + kspt + ncrds + nstatv) + 0.0d0 * dble(npt)
end subroutine sdvini

subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, time, dtime, &
                temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, pnewdt, &
                celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
  implicit none
  character(len=80) :: cmname
  integer :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kstep, kinc
  double precision :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens), sse, spd, scd, rpl, ddsddt(ntens), &
    drplde(ntens), drpldt, stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp, predef(1), dpred(1), &
    props(nprops), coords(3), drot(3, 3), pnewdt, celent, dfgrd0(3, 3), dfgrd1(3, 3)
  double precision :: e, nu, lam, g
  integer :: i
  e = props(1)
  nu = props(2)
  g = e / (2.0d0 * (1.0d0 + nu))
  lam = e * nu / ((1.0d0 + nu) * (1.0d0 - 2.0d0 * nu))
  ddsdde = 0.0d0
  ddsdde(1:ndi, 1:ndi) = lam
  do i = 1, ndi
    ddsdde(i, i) = lam + 2.0d0 * g
  end do
  do i = ndi + 1, ntens
    ddsdde(i, i) = g
  end do
  stress = stress + matmul(ddsdde, dstran)
end subroutine umat
