! A user's own free-form Abaqus UMAT (run with ldfcz --user): compressible neo-Hookean solid,
!   tau = mu (B - I) + lam ln(J) I,  STRESS = tau / J (Cauchy),
!   DDSDDE = (1/J) [lam I(x)I + 2 (mu - lam ln J) II + (d_ik tau_jl + d_il tau_jk + tau_ik d_jl + tau_il d_jk)/2],
! the Jaumann-rate tangent of the Kirchhoff stress over J that Abaqus expects. The stress depends on DFGRD1 alone,
! so with this tangent the host's Newton iteration converges quadratically. PROPS(1) = mu, PROPS(2) = lambda (MPa).
! Plane stress (NDI = 2, NTENS = 3): the UMAT finds its thickness stretch l3 itself from sigma_33 = 0 on the
! in-plane block of DFGRD1 (DFGRD1(3,3) is not used: Abaqus is reported to pass 1/det F_2D there), Newton on
! x = ln l3 for g(x) = mu (e^(2x) - 1) + lambda (ln det F_2D + x) = 0, and returns the in-plane stress with the
! condensed tangent (tau_33^J = 0): (1/J) [mu/2 (d b + b d terms) + lambda beta I(x)I], beta = 2 mu l3^2 /
! (2 mu l3^2 + lambda), J = det F_2D l3 (the same convention as in 3D, with the material's own J).
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
    time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, coords, drot, &
    pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)
  include 'ABA_PARAM.INC'
  character(len=80) :: cmname
  dimension stress(ntens), statev(*), ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), stran(ntens), &
    dstran(ntens), time(2), predef(1), dpred(1), props(nprops), coords(3), drot(3, 3), dfgrd0(3, 3), &
    dfgrd1(3, 3), jstep(4)
  dimension bm(3, 3), tau(3, 3), eye(3, 3), ii(6), jj(6)
  integer ii, jj
  data ii /1, 2, 3, 1, 1, 2/, jj /1, 2, 3, 2, 3, 3/

  if (nprops < 2) then
    write (*, *) 'UMAT neo-Hooke: needs 2 constants (mu, lambda)'
    call xit()
    return
  end if
  amu = props(1)
  alam = props(2)
  eye = 0.0d0
  do i = 1, 3
    eye(i, i) = 1.0d0
  end do
  cj = dfgrd1(1, 1) * (dfgrd1(2, 2) * dfgrd1(3, 3) - dfgrd1(2, 3) * dfgrd1(3, 2)) &
     - dfgrd1(1, 2) * (dfgrd1(2, 1) * dfgrd1(3, 3) - dfgrd1(2, 3) * dfgrd1(3, 1)) &
     + dfgrd1(1, 3) * (dfgrd1(2, 1) * dfgrd1(3, 2) - dfgrd1(2, 2) * dfgrd1(3, 1))
  if (cj <= 0.0d0) then
    pnewdt = 0.25d0
    return
  end if
  if (ntens == 3) then
    cj2 = dfgrd1(1, 1) * dfgrd1(2, 2) - dfgrd1(1, 2) * dfgrd1(2, 1)
    if (cj2 <= 0.0d0) then
      pnewdt = 0.25d0
      return
    end if
    x = -alam * log(cj2) / (2.0d0 * amu + alam)
    do it = 1, 60
      dx = -(amu * (exp(2.0d0 * x) - 1.0d0) + alam * (log(cj2) + x)) / (2.0d0 * amu * exp(2.0d0 * x) + alam)
      x = x + dx
      if (abs(dx) <= 1.0d-15) exit
    end do
    bm = 0.0d0
    bm(1:2, 1:2) = matmul(dfgrd1(1:2, 1:2), transpose(dfgrd1(1:2, 1:2)))
    bm(3, 3) = exp(2.0d0 * x)
    cj = cj2 * exp(x)
    alnj = log(cj)
    beta = 2.0d0 * amu * bm(3, 3) / (2.0d0 * amu * bm(3, 3) + alam)
    tau = amu * (bm - eye) + alam * alnj * eye
    do np = 1, 3
      i = ii(np)
      j = jj(np)
      if (np == 3) then
        i = 1
        j = 2
      end if
      stress(np) = tau(i, j) / cj
      do nq = 1, 3
        k = ii(nq)
        l = jj(nq)
        if (nq == 3) then
          k = 1
          l = 2
        end if
        ddsdde(np, nq) = (alam * beta * eye(i, j) * eye(k, l) &
          + 0.5d0 * amu * (eye(i, k) * bm(j, l) + eye(i, l) * bm(j, k) + bm(i, k) * eye(j, l) + bm(i, l) * eye(j, k))) &
          / cj
      end do
    end do
    sse = 0.5d0 * amu * (bm(1, 1) + bm(2, 2) + bm(3, 3) - 3.0d0) - amu * alnj + 0.5d0 * alam * alnj**2
    return
  end if
  alnj = log(cj)
  bm = matmul(dfgrd1, transpose(dfgrd1))
  tau = amu * (bm - eye) + alam * alnj * eye
  do np = 1, ntens
    i = ii(np)
    j = jj(np)
    stress(np) = tau(i, j) / cj
    do nq = 1, ntens
      k = ii(nq)
      l = jj(nq)
      ddsdde(np, nq) = (alam * eye(i, j) * eye(k, l) &
        + (amu - alam * alnj) * (eye(i, k) * eye(j, l) + eye(i, l) * eye(j, k)) &
        + 0.5d0 * (eye(i, k) * tau(j, l) + eye(i, l) * tau(j, k) + tau(i, k) * eye(j, l) + tau(i, l) * eye(j, k))) / cj
    end do
  end do
  ! stored energy density per reference volume (neo-Hooke): mu/2 (tr B - 3) - mu ln J + lam/2 (ln J)^2
  sse = 0.5d0 * amu * (bm(1, 1) + bm(2, 2) + bm(3, 3) - 3.0d0) - amu * alnj + 0.5d0 * alam * alnj**2
end subroutine umat
