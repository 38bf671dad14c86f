!> Calls the installed UEL and UMAT as Abaqus would and checks one closed form each (test package_find_ldfcz):
!> a unit-area LDF element opened in mode I by d = delta carries RF = T_max A = phi/(e delta) (paper Eqs. 5, 20);
!> one UMAT call with a small uniaxial strain increment 1e-7 returns sigma_11 = (K + 4/3 (G + G_r)) eps
!> (the Leonov model's small-strain moduli: K = E/(3(1-2 nu)), G = E/(2(1+nu)), hardening G_r; to 1e-5).
program consumer
  implicit none
  interface
    subroutine uel(rhs, amatrx, svars, energy, ndofel, nrhs, nsvars, props, nprops, coords, mcrd, nnode, u, du, v, a, &
                   jtype, time, dtime, kstep, kinc, jelem, params, ndload, jdltyp, adlmag, predef, npredf, lflags, &
                   mlvarx, ddlmag, mdload, pnewdt, jprops, njprop, period)
      integer :: ndofel, nrhs, nsvars, nprops, mcrd, nnode, jtype, kstep, kinc, jelem, ndload, npredf
      integer :: mlvarx, mdload, njprop, jdltyp(mdload, *), lflags(*), jprops(*)
      double precision :: rhs(mlvarx, *), amatrx(ndofel, ndofel), svars(*), energy(8), pnewdt
      double precision :: props(*), coords(mcrd, nnode), u(ndofel), du(mlvarx, *), v(ndofel), a(ndofel)
      double precision :: time(2), dtime, params(*), adlmag(mdload, *), predef(2, npredf, nnode)
      double precision :: ddlmag(mdload, *), period
    end subroutine uel
  end interface
  integer, parameter :: dp = kind(1.0d0)
  real(dp), parameter :: phi = 0.2_dp, delta = 3.679e-3_dp
  real(dp) :: coords(3, 8), rhs(24, 1), amatrx(24, 24), svars(16), energy(8), props(3), u(24), du(24, 1)
  real(dp) :: v(24), acc(24), time(2), params(3), adlmag(1, 1), ddlmag(1, 1), predef(2, 1, 8), pnewdt, rf, want
  integer :: lflags(5), jprops(2), jdltyp(1, 1), k
  real(dp) :: stress(6), statev(11), ddsdde(6, 6), sse, spd, scd, rpl, ddsddt(6), drplde(6), drpldt, stran(6)
  real(dp) :: dstran(6), temp, dtemp, predef_m(1), dpred(1), mprops(10), coords_m(3), drot(3, 3), celent
  real(dp) :: dfgrd0(3, 3), dfgrd1(3, 3), eps, kmod, gmod
  integer :: jstep(4)
  character(len=80) :: cmname

  coords = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [3, 8]) * 1.0_dp
  props = [phi, delta, 0.0_dp]
  jprops = [1, 1]
  u = 0.0_dp
  do k = 5, 8
    u(3 * k) = delta
  end do
  du(:, 1) = u
  svars = 0.0_dp
  energy = 0.0_dp
  v = 0.0_dp
  acc = 0.0_dp
  time = 0.0_dp
  params = 0.0_dp
  adlmag = 0.0_dp
  ddlmag = 0.0_dp
  predef = 0.0_dp
  jdltyp = 0
  lflags = [1, 1, 1, 0, 0]
  pnewdt = 1.0e36_dp
  call uel(rhs, amatrx, svars, energy, 24, 1, 16, props, 3, coords, 3, 8, u, du, v, acc, 1, time, 1.0_dp, 1, 1, 1, &
           params, 0, jdltyp, adlmag, predef, 1, lflags, 24, ddlmag, 1, pnewdt, jprops, 2, 1.0_dp)
  rf = -sum(rhs(3:24:3, 1) * [0, 0, 0, 0, 1, 1, 1, 1])
  want = phi / (exp(1.0_dp) * delta)
  write (*, '(a,es16.9,a,es16.9)') 'UEL: top force ', rf, ', T_max A = ', want
  if (abs(rf - want) > 1.0e-9_dp * want) error stop 'UEL force differs from T_max A'

  mprops = [1250.0_dp, 0.4_dp, 28.4_dp, 0.486_dp, 0.95_dp, 0.047_dp, 28.2_dp, 0.990_dp, 200.0_dp, -4.0_dp]
  eps = 1.0e-7_dp
  stress = 0.0_dp
  statev = 0.0_dp
  stran = 0.0_dp
  dstran = 0.0_dp
  dstran(1) = eps
  dfgrd0 = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3]) * 1.0_dp
  dfgrd1 = dfgrd0
  dfgrd1(1, 1) = exp(eps)
  drot = dfgrd0
  jstep = [1, 1, 1, 0]
  cmname = 'PET'
  pnewdt = 1.0e36_dp
  sse = 0
  spd = 0
  scd = 0
  temp = 0
  dtemp = 0
  coords_m = 0
  celent = 1
  call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, time, 1.0_dp, temp, &
            dtemp, predef_m, dpred, cmname, 3, 3, 6, 11, mprops, 10, coords_m, drot, pnewdt, celent, dfgrd0, dfgrd1, &
            1, 1, 1, 1, jstep, 1)
  kmod = mprops(1) / (3 * (1 - 2 * mprops(2)))
  gmod = mprops(1) / (2 * (1 + mprops(2)))
  want = (kmod + 4.0_dp / 3.0_dp * (gmod + mprops(7))) * eps
  write (*, '(a,es16.9,a,es16.9)') 'UMAT: sigma_11 ', stress(1), ', (K + 4/3 (G + G_r)) eps = ', want
  if (abs(stress(1) - want) > 1.0e-5_dp * want) error stop 'UMAT stress differs from the small-strain modulus'
  write (*, '(a)') 'consumer: ok'
end program consumer
