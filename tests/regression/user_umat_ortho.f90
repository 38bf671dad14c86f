! A user UMAT for the *ORIENTATION tests (run with ldfcz --user): linear orthotropic elasticity in the material
! axes, hypoelastic (STRESS = STRESS + C DSTRAN, DDSDDE = C). PROPS = E1, E2, E3, nu12, nu13, nu23, G12, G13, G23
! (nu_ij: contraction along j under stress along i, nu_ji / E_j = nu_ij / E_i); engineering shears in Abaqus order
! 11, 22, 33, 12, 13, 23 (plane elements: 11, 22, 33, 12).
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
    time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
    pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
  include 'ABA_PARAM.INC'
  character(len=80) :: cmname
  dimension stress(ntens), statev(*), ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), stran(ntens), &
    dstran(ntens), time(2), predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), dfgrd0(3, 3), &
    dfgrd1(3, 3), jstep(4)
  dimension s(3, 3), c(3, 3)
  if (nprops < 9) then
    write (*, *) 'UMAT ortho: needs 9 constants (E1, E2, E3, nu12, nu13, nu23, G12, G13, G23)'
    call xit()
    return
  end if
  ! direct compliance block and its inverse (cofactors)
  s(1, 1) = 1.0d0 / props(1)
  s(2, 2) = 1.0d0 / props(2)
  s(3, 3) = 1.0d0 / props(3)
  s(1, 2) = -props(4) / props(1)
  s(1, 3) = -props(5) / props(1)
  s(2, 3) = -props(6) / props(2)
  s(2, 1) = s(1, 2)
  s(3, 1) = s(1, 3)
  s(3, 2) = s(2, 3)
  det = s(1, 1) * (s(2, 2) * s(3, 3) - s(2, 3) * s(3, 2)) - s(1, 2) * (s(2, 1) * s(3, 3) - s(2, 3) * s(3, 1)) &
    + s(1, 3) * (s(2, 1) * s(3, 2) - s(2, 2) * s(3, 1))
  c(1, 1) = (s(2, 2) * s(3, 3) - s(2, 3) * s(3, 2)) / det
  c(1, 2) = -(s(1, 2) * s(3, 3) - s(1, 3) * s(3, 2)) / det
  c(1, 3) = (s(1, 2) * s(2, 3) - s(1, 3) * s(2, 2)) / det
  c(2, 2) = (s(1, 1) * s(3, 3) - s(1, 3) * s(3, 1)) / det
  c(2, 3) = -(s(1, 1) * s(2, 3) - s(1, 3) * s(2, 1)) / det
  c(3, 3) = (s(1, 1) * s(2, 2) - s(1, 2) * s(2, 1)) / det
  c(2, 1) = c(1, 2)
  c(3, 1) = c(1, 3)
  c(3, 2) = c(2, 3)
  ddsdde = 0.0d0
  ddsdde(1:3, 1:3) = c
  ddsdde(4, 4) = props(7)
  if (ntens == 6) then
    ddsdde(5, 5) = props(8)
    ddsdde(6, 6) = props(9)
  end if
  stress = stress + matmul(ddsdde, dstran)
end subroutine umat
