! A user's own free-form Abaqus UMAT that deletes its failed points (test deck_element_deletion, restart
! restart_element_deletion; docs/host.md, *DEPVAR, DELETE=): small-strain isotropic elasticity (PROPS(1) = E,
! PROPS(2) = nu), incremental STRESS = STRESS + DDSDDE DSTRAN, and state variable 1 the deletion flag of
! *DEPVAR, DELETE=1: 1 while the largest direct total strain STRAN + DSTRAN is at most PROPS(3), else 0, the
! stress zeroed in the increment that crosses the limit (Abaqus: a deleted point carries no stress).
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
    time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
    pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
  include 'ABA_PARAM.INC'
  character(len=80) :: cmname
  dimension stress(ntens), statev(nstatv), ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), stran(ntens), &
    dstran(ntens), time(2), predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), dfgrd0(3, 3), &
    dfgrd1(3, 3), jstep(4)

  if (nprops < 3 .or. nstatv < 1) then
    write (*, *) 'UMAT delete: needs 3 constants (E, nu, strain limit) and 1 state variable'
    call xit()
    return
  end if
  e = props(1)
  anu = props(2)
  alam = e * anu / ((1.0d0 + anu) * (1.0d0 - 2.0d0 * anu))
  amu = 0.5d0 * e / (1.0d0 + anu)
  ddsdde = 0.0d0
  do i = 1, ndi
    do j = 1, ndi
      ddsdde(i, j) = alam
    end do
    ddsdde(i, i) = alam + 2.0d0 * amu
  end do
  do i = ndi + 1, ntens
    ddsdde(i, i) = amu
  end do
  stress = stress + matmul(ddsdde, dstran)
  statev(1) = 1.0d0
  if (maxval(stran(1:ndi) + dstran(1:ndi)) > props(3)) statev(1) = 0.0d0
  ! the increment that crosses the limit zeroes the stress; a later call (the host not deleting the element) would
  ! load it again from zero, so that the test sees whether the host removed it
  if (maxval(stran(1:ndi)) <= props(3) .and. statev(1) == 0.0d0) stress = 0.0d0
end subroutine umat
