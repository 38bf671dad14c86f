! A deliberately broken user UMAT (run with ldfcz --user; test deck_broken_umat): small-strain isotropic elasticity,
! PROPS(1) = E, PROPS(2) = nu, except that at integration point 3 of element 2 it returns a NaN stress, the way a
! user's routine goes wrong (0/0, log of a negative number in a build that does not trap). The host must say which element, point and routine.
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
    time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
    pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
  include 'ABA_PARAM.INC'
  character(len=80) :: cmname
  dimension stress(ntens), statev(*), ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), stran(ntens), &
    dstran(ntens), time(2), predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), dfgrd0(3, 3), &
    dfgrd1(3, 3), jstep(4)
  integer :: i
  e = props(1)
  anu = props(2)
  alam = e * anu / ((1.0d0 + anu) * (1.0d0 - 2.0d0 * anu))
  amu = 0.5d0 * e / (1.0d0 + anu)
  ddsdde = 0.0d0
  do i = 1, ndi
    ddsdde(1:ndi, i) = alam
    ddsdde(i, i) = alam + 2.0d0 * amu
  end do
  do i = ndi + 1, ntens
    ddsdde(i, i) = amu
  end do
  stress = stress + matmul(ddsdde, dstran)
  if (noel == 2 .and. npt == 3) then
    ! a quiet NaN by its bit pattern (0/0 would trap in the host's Debug build, which traps invalid operations)
    stress(1) = transfer(int(z'7FF8000000000000', 8), 1.0d0)
  end if
end subroutine umat
