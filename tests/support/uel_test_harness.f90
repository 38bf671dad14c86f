!> The UEL test harness of the cohesive element's suites (tests/test_uel*.pf): SUBROUTINE UEL called with the
!> argument list Abaqus/Standard passes (NRHS = 1, MLVARX = NDOFEL, U the total displacement, DU(:,1) its increment,
!> SVARS and ENERGY at the start of the increment on entry and at its end on exit, LFLAGS = (1 static, 1 NLGEOM,
!> LFLAGS(3), 0, 0), PNEWDT as the host passes it), the element geometries the suites use, and AMATRX against
!> central differences of RHS. One place for the argument list: a change of the adapter's interface is one change
!> here, not one per suite.
module uel_test_harness
  use ldfcz_kinds, only: dp
  use test_geometry, only: rotation
  implicit none
  private
  public :: call_uel, eval_uel, uel_increment, uel_fd_error, square_coords, distorted_coords

  real(dp), parameter :: pnewdt_unset = 1.0e36_dp   !< PNEWDT as the host passes it (no smaller increment asked)

contains

  !> One UEL call with Abaqus' argument list. RHS and AMATRX are added to (Abaqus passes them zeroed; the callers
  !> do so), SVARS, ENERGY and PNEWDT updated in place. DU = 0 and DTIME = 1 unless given.
  subroutine call_uel(coords, u, props, jprops, svars, rhs, amatrx, energy, lflag3, pnewdt, du, dtime)
    real(dp), intent(in) :: coords(:,:)             !< node coordinates (MCRD x NNODE)
    real(dp), intent(in) :: u(:)                    !< total displacement (NDOFEL)
    real(dp), intent(in) :: props(:)                !< PROPS
    integer, intent(in) :: jprops(:)                !< JPROPS
    real(dp), intent(inout) :: svars(:)             !< SVARS: start of the increment in, end out
    real(dp), intent(inout) :: rhs(:)               !< RHS(:, 1)
    real(dp), intent(inout) :: amatrx(:,:)          !< AMATRX
    real(dp), intent(inout) :: energy(8)            !< ENERGY
    integer, intent(in) :: lflag3                   !< LFLAGS(3): 1 RHS and AMATRX, 2 AMATRX only, 5 RHS only
    real(dp), intent(inout) :: pnewdt               !< PNEWDT
    real(dp), intent(in), optional :: du(:)         !< DU(:, 1), the displacement increment (default 0)
    real(dp), intent(in), optional :: dtime         !< DTIME (default 1)
    real(dp) :: rhs2(size(u), 1), du2(size(u), 1), v(size(u)), acc(size(u)), time(2), params(3), adlmag(1, 1)
    real(dp) :: ddlmag(1, 1), predef(2, 1, size(coords, 2)), dt
    integer :: lflags(5), jdltyp(1, 1), ndofel
    external :: uel
    ndofel = size(u)
    rhs2(:, 1) = rhs
    du2(:, 1) = 0.0_dp
    if (present(du)) du2(:, 1) = du
    dt = 1.0_dp
    if (present(dtime)) dt = dtime
    v = 0.0_dp
    acc = 0.0_dp
    time = [0.0_dp, 0.0_dp]
    params = 0.0_dp
    adlmag = 0.0_dp
    ddlmag = 0.0_dp
    predef = 0.0_dp
    jdltyp = 0
    lflags = [1, 1, lflag3, 0, 0]
    call uel(rhs2, amatrx, svars, energy, ndofel, 1, size(svars), props, size(props), coords, size(coords, 1), &
             size(coords, 2), u, du2, v, acc, 1, time, dt, 1, 1, 7, params, 0, jdltyp, adlmag, predef, 0, lflags, &
             ndofel, ddlmag, 1, pnewdt, jprops, size(jprops), 1.0_dp)
    rhs = rhs2(:, 1)
  end subroutine call_uel

  !> RHS and AMATRX of one call with LFLAGS(3) = 1 from a copy of the given start-of-increment SVARS (as every
  !> Newton iteration of the host calls it): SVARS at the end in svars1, ENERGY from zero.
  subroutine eval_uel(coords, u, props, jprops, svars0, rhs, amatrx, svars1, energy, du, dtime)
    real(dp), intent(in) :: coords(:,:), u(:), props(:), svars0(:)   !< as call_uel; SVARS at the start
    integer, intent(in) :: jprops(:)                                 !< JPROPS
    real(dp), intent(out) :: rhs(:), amatrx(:,:), svars1(:), energy(8) !< RHS, AMATRX, SVARS at the end, ENERGY
    real(dp), intent(in), optional :: du(:), dtime                   !< as call_uel
    real(dp) :: pnewdt
    svars1 = svars0
    rhs = 0.0_dp
    amatrx = 0.0_dp
    energy = 0.0_dp
    pnewdt = pnewdt_unset
    call call_uel(coords, u, props, jprops, svars1, rhs, amatrx, energy, 1, pnewdt, du, dtime)
  end subroutine eval_uel

  !> One increment as the host runs it: U, DU and DTIME given, SVARS and ENERGY carried over (updated in place),
  !> RHS and AMATRX computed afresh (LFLAGS(3) = 1), PNEWDT from its unset value.
  subroutine uel_increment(coords, u, du, dtime, props, jprops, svars, energy, rhs, amatrx, pnewdt)
    real(dp), intent(in) :: coords(:,:), u(:), du(:), dtime, props(:)   !< as call_uel
    integer, intent(in) :: jprops(:)                                    !< JPROPS
    real(dp), intent(inout) :: svars(:), energy(8)                      !< SVARS, ENERGY: start in, end out
    real(dp), intent(out) :: rhs(:), amatrx(:,:), pnewdt                !< RHS, AMATRX, PNEWDT
    rhs = 0.0_dp
    amatrx = 0.0_dp
    pnewdt = pnewdt_unset
    call call_uel(coords, u, props, jprops, svars, rhs, amatrx, energy, 1, pnewdt, du, dtime)
  end subroutine uel_increment

  !> max |AMATRX - K_fd| / max(|AMATRX|_max, tiny), K_fd(:, j) = -(RHS(u + h e_j) - RHS(u - h e_j)) / 2h, every call
  !> from the same start-of-increment SVARS (as in a Newton iteration). With ustart: DU = U - ustart and DTIME =
  !> dtime in every call (DU changes with U, as in a Newton iteration of a rate-dependent law); without: DU = 0.
  !> Prints the error; AMATRX at u in kmat when asked.
  function uel_fd_error(coords, u, props, jprops, svars0, h, kmat, ustart, dtime) result(err)
    real(dp), intent(in) :: coords(:,:), u(:), props(:), svars0(:)  !< as eval_uel
    integer, intent(in) :: jprops(:)                                !< JPROPS
    real(dp), intent(in) :: h                                       !< difference step
    real(dp), intent(out), optional :: kmat(:,:)                    !< AMATRX at u
    real(dp), intent(in), optional :: ustart(:)                     !< displacement at the start of the increment
    real(dp), intent(in), optional :: dtime                         !< DTIME (with ustart)
    real(dp) :: err, r(size(u)), rp(size(u)), rm(size(u)), k(size(u), size(u)), kfd(size(u), size(u))
    real(dp) :: kd(size(u), size(u)), up(size(u)), s1(size(svars0)), e(8)
    integer :: j
    call eval_at(u, r, k)
    do j = 1, size(u)
      up = u
      up(j) = u(j) + h
      call eval_at(up, rp, kd)
      up(j) = u(j) - h
      call eval_at(up, rm, kd)
      kfd(:, j) = -(rp - rm) / (2.0_dp * h)
    end do
    err = maxval(abs(k - kfd)) / max(maxval(abs(k)), tiny(1.0_dp))
    write (*, '(a, es9.2)') '  |K - K_fd|_max / |K|_max = ', err
    if (present(kmat)) kmat = k
  contains
    subroutine eval_at(x, rx, kx)
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: rx(:), kx(:,:)
      if (present(ustart)) then
        call eval_uel(coords, x, props, jprops, svars0, rx, kx, s1, e, du=x - ustart, dtime=dtime)
      else
        call eval_uel(coords, x, props, jprops, svars0, rx, kx, s1, e)
      end if
    end subroutine eval_at
  end function uel_fd_error

  !> Unit-square 3D element (A0 = 1) or unit-length 2D element, both faces at z = 0 (y = 0 in 2D).
  function square_coords(ndim) result(c)
    integer, intent(in) :: ndim   !< 3: the 8-node 3D element; 2: the 4-node 2D element
    real(dp), allocatable :: c(:,:)
    if (ndim == 3) then
      c = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [3, 8]) * 1.0_dp
    else
      c = reshape([0, 0, 1, 0, 1, 0, 0, 0], [2, 4]) * 1.0_dp
    end if
  end function square_coords

  !> A distorted planar quadrilateral, tilted out of the xy plane (both faces coincide): 3D element coordinates.
  function distorted_coords() result(c)
    real(dp) :: c(3, 8), q(2, 4), r(3, 3)
    integer :: k
    q = reshape([0.1_dp, -0.2_dp, 1.4_dp, 0.1_dp, 1.1_dp, 0.9_dp, -0.3_dp, 1.2_dp], [2, 4])
    r = rotation([1.0_dp, 2.0_dp, 0.5_dp], 0.7_dp)
    do k = 1, 4
      c(:, k) = matmul(r, [q(1, k), q(2, k), 0.0_dp]) + [0.3_dp, -0.1_dp, 0.2_dp]
      c(:, k + 4) = c(:, k)
    end do
  end function distorted_coords

end module uel_test_harness
