! A user element that reads its distributed loads (run with ldfcz --user): a 2-node spring of stiffness PROPS(1)
! along each of the 3 dofs, node 1 to node 2, loaded at node 2 by its *DLOAD types: U1 a force ADLMAG along x,
! U2 a force along y equal to the sum of the DDLMAG increments over the converged increments (SVARS(1)) plus the
! current one. Abaqus passes NDLOAD active loads with JDLTYP(K,1) = n of type Un, ADLMAG(K,1) the magnitude at the
! end of the increment and DDLMAG(K,1) its increment, so with node 1 fixed both give u = magnitude / PROPS(1).
! Along z node 2 carries PREDEF(1,1,2), the temperature at the end of the increment, plus 1e6 times the mismatch of
! PREDEF(2,1,2) (its increment) with the change since the last converged temperature kept in SVARS(2): u3 = T/k.
subroutine uel(rhs, amatrx, svars, energy, ndofel, nrhs, nsvars, props, nprops, coords, mcrd, nnode, u, du, v, a, &
    jtype, time, dtime, kstep, kinc, jelem, params, ndload, jdltyp, adlmag, predef, npredf, lflags, mlvarx, ddlmag, &
    mdload, pnewdt, jprops, njprop, period)
  include 'ABA_PARAM.INC'
  dimension rhs(mlvarx, *), amatrx(ndofel, ndofel), props(*), svars(*), energy(8), coords(mcrd, nnode), u(ndofel), &
    du(mlvarx, *), v(ndofel), a(ndofel), time(2), params(*), jdltyp(mdload, *), adlmag(mdload, *), &
    ddlmag(mdload, *), predef(2, npredf, nnode), lflags(*), jprops(*)
  if (nnode /= 2 .or. ndofel /= 6 .or. nsvars < 2) then
    write (*, *) 'UEL dload: needs 2 nodes, 6 dofs, 2 state variables'
    call xit()
    return
  end if
  sk = props(1)
  amatrx(1:6, 1:6) = 0.0d0
  do i = 1, 3
    amatrx(i, i) = sk
    amatrx(i + 3, i + 3) = sk
    amatrx(i, i + 3) = -sk
    amatrx(i + 3, i) = -sk
  end do
  rhs(1:6, 1) = -matmul(amatrx, u(1:6))
  rhs(6, 1) = rhs(6, 1) + predef(1, 1, 2) + 1.0d6 * (predef(2, 1, 2) - (predef(1, 1, 2) - svars(2)))
  svars(2) = predef(1, 1, 2)
  do k = 1, ndload
    if (jdltyp(k, 1) == 1) then
      rhs(4, 1) = rhs(4, 1) + adlmag(k, 1)
    else if (jdltyp(k, 1) == 2) then
      rhs(5, 1) = rhs(5, 1) + svars(1) + ddlmag(k, 1)
      svars(1) = svars(1) + ddlmag(k, 1)
    end if
  end do
end subroutine uel
