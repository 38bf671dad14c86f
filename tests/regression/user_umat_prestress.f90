! A user UMAT whose state variables hold a residual (eigen) stress (run with ldfcz --user): small-strain isotropic
! elasticity plus STATEV(1:NTENS), kept constant, STRESS = C : (STRAN + DSTRAN) + STATEV. PROPS(1) = E, PROPS(2) =
! nu; NSTATV >= NTENS. Set by *INITIAL CONDITIONS, TYPE=SOLUTION, the state stress relaxes like an initial stress.
! With a third constant c, S11 gets c (TEMP + DTEMP) in addition: a check that the temperature reaches the UMAT.
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
    time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
    pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
  include 'ABA_PARAM.INC'
  character(len=80) :: cmname
  dimension stress(ntens), statev(*), ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), stran(ntens), &
    dstran(ntens), time(2), predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), dfgrd0(3, 3), &
    dfgrd1(3, 3), jstep(4)
  if (nprops < 2 .or. nstatv < ntens) then
    write (*, *) 'UMAT prestress: needs 2 constants (E, nu) and NSTATV >= NTENS'
    call xit()
    return
  end if
  e = props(1)
  anu = props(2)
  alam = e * anu / ((1.0d0 + anu) * (1.0d0 - 2.0d0 * anu))
  g = 0.5d0 * e / (1.0d0 + anu)
  ddsdde = 0.0d0
  do i = 1, ndi
    do j = 1, ndi
      ddsdde(i, j) = alam
    end do
    ddsdde(i, i) = alam + 2.0d0 * g
  end do
  do i = ndi + 1, ntens
    ddsdde(i, i) = g
  end do
  stress = matmul(ddsdde, stran + dstran) + statev(1:ntens)
  if (nprops >= 3) stress(1) = stress(1) + props(3) * (temp + dtemp)
end subroutine umat
