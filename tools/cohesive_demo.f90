!> Demo of the LDF cohesive UEL: one unit-area 3D element (8 nodes) driven as Abaqus/Standard would drive it
!> (fresh copy of the converged SVARS on each call, U the total displacement), opened in mode I to 6 delta, unloaded to 0,
!> reloaded to 30 delta, for the three unloading types of Fig. 6. Prints T/T_max against Delta/delta at selected openings
!> and the work of the nodal forces over the path, W/(phi A0) (the tail beyond 30 delta is (1+30) exp(-30) ~ 3e-12).
program cohesive_demo
  use ldfcz_kinds, only: dp
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

  real(dp), parameter :: phi = 0.2_dp, tmax = 20.0_dp          ! N/mm, MPa (the paper's values)
  real(dp), parameter :: delta = phi / (exp(1.0_dp) * tmax)    ! Eq. 5: 3.679e-3 mm
  integer, parameter :: nsteps = 50                            ! increments per delta of opening
  real(dp), parameter :: marks_load(7) = [0.0_dp, 0.5_dp, 1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 6.0_dp]
  real(dp), parameter :: marks_unload(5) = [4.0_dp, 2.0_dp, 1.0_dp, 0.5_dp, 0.0_dp]
  real(dp), parameter :: marks_reload(6) = [1.0_dp, 2.0_dp, 4.0_dp, 6.0_dp, 8.0_dp, 30.0_dp]
  character(len=*), parameter :: names(3) = ['reversible  ', 'elast damage', 'plastic     ']
  real(dp) :: coords(3, 8), table(3, 18), tabd(18), work(3), etot(3)
  integer :: iv, nrow

  coords = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [3, 8])
  do iv = 1, 3
    call run_path(iv, table(iv, :), tabd, nrow, work(iv), etot(iv))
  end do

  write (*, '(a)') 'LDF cohesive UEL demo: one 8-node element, A0 = 1 mm^2, mode I'
  write (*, '(a, es10.3, a, es10.3, a, f6.2, a)') 'phi = ', phi, ' N/mm, delta = ', delta, ' mm, T_max = ', tmax, ' MPa'
  write (*, '(a)') 'path: load 0 -> 6 delta, unload -> 0, reload -> 30 delta, increments delta/50'
  write (*, '(a12, 3a14)') 'Delta/delta', (trim(names(iv)), iv = 1, 3)
  do iv = 1, nrow
    if (iv == 1) write (*, '(a)') '  loading'
    if (iv == size(marks_load) + 1) write (*, '(a)') '  unloading'
    if (iv == size(marks_load) + size(marks_unload) + 1) write (*, '(a)') '  reloading'
    write (*, '(f12.2, 3f14.5)') tabd(iv), table(:, iv)
  end do
  write (*, '(a, 3f14.8)') 'W/(phi A0)  ', work / phi
  write (*, '(a, 3f14.8)') '(E2+E4)/phi ', etot
  write (*, '(a)') 'T/T_max from the summed top-face nodal forces; W the trapezoidal work of the nodal forces'
  write (*, '(a)') '(trapezoid error (h/delta)^2/12 = 3.3e-5 with h = delta/50);'
  write (*, '(a)') 'E2 + E4 = ENERGY(2) + ENERGY(4) at the end (recoverable + dissipated).'

contains

  !> Drive one variant along the path; tab(i) = T/T_max at the opening tabd(i).
  subroutine run_path(unloading, tab, tabd, nrow, w, esum)
    integer, intent(in) :: unloading
    real(dp), intent(out) :: tab(:), tabd(:), w, esum
    integer, intent(out) :: nrow
    real(dp) :: path(0:42 * nsteps), marks(18), dnow, dold, t
    real(dp) :: fold(24), fnew(24), uold(24), unew(24), svars(16), energy(8), sv(16), en(8)
    real(dp) :: rhs(24, 1), amatrx(24, 24), props(3), du(24, 1), v(24), acc(24), time(2), params(1)
    real(dp) :: adlmag(1, 1), ddlmag(1, 1), predef(2, 1, 8), pnewdt
    integer :: lflags(5), jprops(2), jdltyp(1, 1), k, n, np, ilast(3)

    ! the opening path in units of delta: 0 -> 6 -> 0 -> 30 in steps 1/nsteps
    np = 0
    path(0) = 0.0_dp
    do k = 1, 6 * nsteps
      np = np + 1
      path(np) = real(k, dp) / nsteps
    end do
    do k = 6 * nsteps - 1, 0, -1
      np = np + 1
      path(np) = real(k, dp) / nsteps
    end do
    do k = 1, 30 * nsteps
      np = np + 1
      path(np) = real(k, dp) / nsteps
    end do
    marks = [marks_load, marks_unload, marks_reload]
    ilast = [size(marks_load), size(marks_load) + size(marks_unload), size(marks)]

    props = [phi, delta, 0.0_dp]
    jprops = [unloading, 1]
    lflags = [1, 1, 1, 0, 0]
    v = 0.0_dp
    acc = 0.0_dp
    time = 0.0_dp
    params = 0.0_dp
    adlmag = 0.0_dp
    ddlmag = 0.0_dp
    predef = 0.0_dp
    jdltyp = 0
    svars = 0.0_dp
    energy = 0.0_dp
    uold = 0.0_dp
    fold = 0.0_dp
    w = 0.0_dp
    nrow = 1
    tab(1) = 0.0_dp
    tabd(1) = 0.0_dp
    dold = 0.0_dp
    do k = 1, np
      dnow = path(k)
      unew = 0.0_dp
      do n = 5, 8
        unew(3 * n) = dnow * delta                 ! top face moves along +z
      end do
      du(:, 1) = unew - uold
      pnewdt = 1.0e36_dp
      sv = svars                                   ! the host's fresh copy of the converged state
      en = energy
      call uel(rhs, amatrx, sv, en, 24, 1, 16, props, 3, coords, 3, 8, unew, du, v, acc, 1, time, 1.0_dp, 1, k, 1, &
               params, 0, jdltyp, adlmag, predef, 0, lflags, 24, ddlmag, 1, pnewdt, jprops, 2, 1.0_dp)
      fnew = -rhs(:, 1)                            ! f_int
      w = w + 0.5_dp * dot_product(fold + fnew, unew - uold)
      svars = sv                                   ! converged: commit
      energy = en
      ! record at the next mark of the current branch (loading, unloading, reloading)
      if (nrow < size(marks)) then
        if (abs(dnow - marks(nrow + 1)) < 1.0e-9_dp .and. ((nrow + 1 <= ilast(1) .and. dnow > dold) .or. &
            (nrow + 1 > ilast(1) .and. nrow + 1 <= ilast(2) .and. dnow < dold) .or. &
            (nrow + 1 > ilast(2) .and. dnow > dold))) then
          t = (fnew(15) + fnew(18) + fnew(21) + fnew(24)) / tmax   ! top-face z forces / (A0 T_max)
          nrow = nrow + 1
          tab(nrow) = t
          tabd(nrow) = dnow
        end if
      end if
      uold = unew
      fold = fnew
      dold = dnow
    end do
    esum = (energy(2) + energy(4)) / phi
  end subroutine run_path

end program cohesive_demo
