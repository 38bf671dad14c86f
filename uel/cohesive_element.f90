!> Kinematics and integration of the LDF cohesive element (van den Bosch, Schreurs, Geers 2007, Eqs. 10-19, 26-30):
!> the 8-node 3D element (nodes 1-4 bottom face, 5-8 top face, node k+4 initially on node k, counter-clockwise seen
!> from the top; 2x2 Gauss points) and its 4-node plane-strain twin (Abaqus COH2D4 order: nodes 1-2 bottom, 3-4 top,
!> node 3 on node 2 and node 4 on node 1; 2 Gauss points; per unit out-of-plane thickness).
!>
!> Internal force f = sum_ip w J0 P^T N^T T (Eq. 14, P = [-I I], Eq. 11; N from Eq. 13), with the first Piola-Kirchhoff
!> traction T integrated over the INITIAL mid-surface: J0 = |dX/dxi x dX/deta| of the initial mid-surface at the Gauss
!> point (exact for any planar quadrilateral, where Eq. 10 uses A0/4). Stiffness K = df/du (Eq. 15) with the tangent M of
!> Eqs. 26, 29-30 plus, in contact, the linearisation of the normal n w.r.t. the nodal positions, which Eq. 29 omits:
!> the contact stiffness is then unsymmetric.
!>
!> Section of the 2D element (optional arguments; Abaqus gives a user element its section data only through PROPS):
!> planar with an out-of-plane thickness t (plane strain or plane stress; default 1: per unit thickness), w = t J0;
!> or axisymmetric about the x2 axis (x1 = r), w = 2 pi R J0 with R = sum_k psi_k X_m,1(k) the radius of the
!> INITIAL mid-line at the Gauss point: the tractions are first Piola-Kirchhoff tractions per unit initial area
!> (Eq. 9), and the initial area element of the surface of revolution is dA0 = 2 pi R J0 dxi, so f (Eq. 14) and K
!> (Eq. 15) keep their form with this weight, which does not depend on u (no extra stiffness term). Forces are
!> totals over the circumference (2 pi radians), as the axisymmetric continuum elements and Abaqus report them.
!> The thickness of a plane-stress section is the initial one (the interface does not follow the bulk's thickness
!> change; the host refuses plane stress under NLGEOM anyway).
!> Pure and host-free: no SAVE, no module state.
module cohesive_element
  use ldfcz_finite, only: is_finite
  use ldfcz_kinds, only: dp
  use cohesive_law, only: cohesive_props, law_ldf, law_classical, ldf_traction, contact_traction, classical_traction
  implicit none
  private
  public :: cohesive_element_compute, nsv_per_ip, element_nip

  !> State variables per integration point (ip-major): 1 Delta_max (history, the only value read back),
  !> 2 opening magnitude |Delta_vec|, 3 traction magnitude |T| (with contact), 4 normal opening Delta_c = Delta_vec . n
  !> (all end-of-increment values; 2-4 are output only).
  integer, parameter :: nsv_per_ip = 4

  integer, parameter, public :: stat_ok = 0             !< success
  integer, parameter, public :: stat_bad_input = 1      !< invalid element geometry or sizes (user error)
  integer, parameter, public :: stat_bad_state = 2      !< current configuration unusable (e.g. collapsed mid-surface)

  character(len=*), parameter :: proc = 'cohesive_element_compute'

contains

  !> Number of integration points of the element of dimension ndim (4 in 3D, 2 in 2D).
  pure integer function element_nip(ndim)
    integer, intent(in) :: ndim  !< 2 or 3
    element_nip = merge(4, 2, ndim == 3)
  end function element_nip

  !> Internal force, stiffness, new history and energies of one cohesive element.
  !> For the LDF law the stiffness is analytic. For the classical law (comparison only) it is the central difference
  !> of the element internal force w.r.t. each nodal displacement, step h = 1e-6 min(delta, delta_t) (so that the
  !> rotation of the local basis is linearised as well); relative accuracy about (h/delta)^2 + eps |x|/h.
  !>
  !> Optional viscous regularisation (not in the paper; props%eta_v > 0 with u_start and dtime > 0 present):
  !> T_vec += eta_v (Delta_vec - Delta_vec_start)/dtime at each Gauss point (backward Euler rate of the opening), tangent
  !> += (eta_v/dtime) I; its dissipation over the increment, sum w eta_v |Delta_vec - Delta_vec_start|^2/dtime, is
  !> returned in e_visc (zero otherwise).
  pure subroutine cohesive_element_compute(ndim, coords0, u, props, hist_old, want_stiffness, fint, kmat, hist_new, &
                                           e_stored, e_diss, stat, errmsg, ip_traction, ip_opening, u_start, dtime, &
                                           e_visc, e_diss_start, thickness, axisymmetric)
    integer, intent(in) :: ndim                    !< 3 (8 nodes) or 2 (4 nodes, plane strain)
    real(dp), intent(in) :: coords0(:,:)           !< initial coordinates (>= ndim rows, nnode columns)
    real(dp), intent(in) :: u(:)                   !< current total displacements, node by node (ndim per node)
    type(cohesive_props), intent(in) :: props      !< validated law parameters
    real(dp), intent(in) :: hist_old(:)            !< state variables at the start of the increment (nsv_per_ip*nip)
    logical, intent(in) :: want_stiffness          !< compute kmat
    real(dp), intent(out) :: fint(:)               !< internal force f_int (RHS = -f_int)
    real(dp), intent(out) :: kmat(:,:)             !< stiffness df_int/du (unsymmetric in contact)
    real(dp), intent(out) :: hist_new(:)           !< state variables at the end of the increment
    real(dp), intent(out) :: e_stored              !< recoverable energy of the element (incl. contact penalty)
    real(dp), intent(out) :: e_diss                !< dissipated energy of the element
    integer, intent(out) :: stat                   !< stat_ok, stat_bad_input or stat_bad_state
    character(len=*), intent(out) :: errmsg        !< message when stat /= stat_ok
    real(dp), intent(out), optional :: ip_traction(:,:)  !< (3, nip) traction vector at each Gauss point
    real(dp), intent(out), optional :: ip_opening(:,:)   !< (3, nip) opening vector at each Gauss point
    real(dp), intent(in), optional :: u_start(:)         !< total displacements at the start of the increment (viscous)
    real(dp), intent(in), optional :: dtime              !< time increment (viscous; <= 0: no viscous term)
    real(dp), intent(out), optional :: e_visc            !< viscous dissipation of this increment
    real(dp), intent(out), optional :: e_diss_start      !< dissipated energy of the law at the start of the increment
    real(dp), intent(in), optional :: thickness          !< 2D planar section: out-of-plane thickness (> 0; default 1)
    logical, intent(in), optional :: axisymmetric        !< 2D: axisymmetric about x2, x1 = r (default .false.)
    real(dp) :: tr(3,4), op(3,4), up(size(u)), fp(size(u)), fm(size(u)), hdum(size(hist_new)), kdum(1,1), h, ed, es
    real(dp) :: u0(size(u)), rate_c, ev, eds, evd, edsd, sec_t
    integer :: ndof, j, nnode
    logical :: axi

    fint = 0.0_dp
    hist_new = 0.0_dp
    e_stored = 0.0_dp
    e_diss = 0.0_dp
    if (want_stiffness) kmat = 0.0_dp
    if (present(e_visc)) e_visc = 0.0_dp
    if (present(e_diss_start)) e_diss_start = 0.0_dp
    errmsg = ''
    stat = stat_ok
    nnode = merge(8, 4, ndim == 3)
    ndof = ndim * nnode
    if ((ndim /= 2 .and. ndim /= 3) .or. size(coords0, 1) < ndim .or. size(coords0, 2) /= nnode .or. &
        size(u) /= ndof .or. size(fint) /= ndof .or. size(hist_old) < nsv_per_ip * element_nip(ndim) .or. &
        size(hist_new) /= size(hist_old)) then
      stat = stat_bad_input
      errmsg = proc // ': inconsistent array sizes'
      return
    end if
    sec_t = 1.0_dp
    if (present(thickness)) sec_t = thickness
    axi = .false.
    if (present(axisymmetric)) axi = axisymmetric
    if (.not. (sec_t > 0.0_dp .and. is_finite(sec_t)) .or. (ndim == 3 .and. (axi .or. sec_t /= 1.0_dp))) then
      stat = stat_bad_input
      errmsg = proc // ': the section (thickness > 0, axisymmetric) applies to the 2D element only'
      return
    end if
    if (want_stiffness) then
      if (size(kmat, 1) /= ndof .or. size(kmat, 2) /= ndof) then
        stat = stat_bad_input
        errmsg = proc // ': kmat must be ndof x ndof'
        return
      end if
    end if

    ! viscous coefficient eta_v/dtime (0: the rate-independent law exactly)
    rate_c = 0.0_dp
    u0 = u
    if (present(u_start) .and. present(dtime)) then
      if (props%eta_v > 0.0_dp .and. dtime > 0.0_dp .and. size(u_start) == ndof) then
        rate_c = props%eta_v / dtime
        u0 = u_start
      end if
    end if

    call element_forces(ndim, coords0, u, props, hist_old, want_stiffness .and. props%law == law_ldf, fint, kmat, &
                        hist_new, e_stored, e_diss, tr, op, stat, errmsg, u0, rate_c, ev, eds, sec_t, axi)
    if (stat /= stat_ok) return
    if (present(ip_traction)) ip_traction = tr(:, 1:element_nip(ndim))
    if (present(ip_opening)) ip_opening = op(:, 1:element_nip(ndim))
    if (present(e_visc)) e_visc = ev
    if (present(e_diss_start)) e_diss_start = eds

    if (want_stiffness .and. props%law == law_classical) then
      h = 1.0e-6_dp * min(props%delta, props%delta_t)
      do j = 1, ndof
        up = u
        up(j) = u(j) + h
        call element_forces(ndim, coords0, up, props, hist_old, .false., fp, kdum, hdum, es, ed, tr, op, stat, errmsg, &
                            u0, rate_c, evd, edsd, sec_t, axi)
        if (stat /= stat_ok) return
        up(j) = u(j) - h
        call element_forces(ndim, coords0, up, props, hist_old, .false., fm, kdum, hdum, es, ed, tr, op, stat, errmsg, &
                            u0, rate_c, evd, edsd, sec_t, axi)
        if (stat /= stat_ok) return
        kmat(:, j) = (fp - fm) / (2.0_dp * h)
      end do
    end if
  end subroutine cohesive_element_compute

  !> Forces (and for the LDF law the analytic stiffness) of one element; see cohesive_element_compute.
  pure subroutine element_forces(ndim, coords0, u, props, hist_old, want_k, fint, kmat, hist_new, e_stored, e_diss, &
                                 tr_ip, op_ip, stat, errmsg, u_start, rate_c, e_visc, e_diss_start, sec_t, axi)
    integer, intent(in) :: ndim
    real(dp), intent(in) :: coords0(:,:), u(:)
    type(cohesive_props), intent(in) :: props
    real(dp), intent(in) :: hist_old(:)
    logical, intent(in) :: want_k
    real(dp), intent(out) :: fint(:)
    real(dp), intent(inout) :: kmat(:,:)
    real(dp), intent(out) :: hist_new(:), e_stored, e_diss, tr_ip(3,4), op_ip(3,4)
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    real(dp), intent(in) :: u_start(:)      !< displacements at the start of the increment (viscous term)
    real(dp), intent(in) :: rate_c          !< eta_v/dtime, 0 = no viscous term
    real(dp), intent(out) :: e_visc         !< viscous dissipation of the increment
    real(dp), intent(out) :: e_diss_start   !< dissipated energy of the law at the start of the increment
    real(dp), intent(in) :: sec_t           !< planar section thickness (1 in 3D)
    logical, intent(in) :: axi              !< 2D axisymmetric: weight 2 pi R at the point (R of the initial mid-line)

    integer :: nf, nip, nnode, k, l, ip, bot(4), top(4), nodes(2,4), sa, sb, ka, kb
    real(dp) :: x0(3,8), x(3,8), xm0(3,4), xm(3,4), psi(4), dpsi_xi(4), dpsi_eta(4), dxi_c(4), deta_c(4)
    real(dp) :: gxi(4), geta(4), g, txi(3), teta(3), a(3), anorm, n(3), j0, w
    real(dp) :: dvec(3), tvec(3), mmat(3,3), tcv(3), mc(3,3), tc, dtc, wc, ws, wd, dmax_new, dn, dt
    real(dp) :: proj(3,3), dndx(3,3,4), gmat(3,3), fblk(3,2,4), kblk(3,3,2,2,4,4), rot2(3,3)
    real(dp) :: dt_top(3,3), dt_bot(3,3), xs(3,8), ddel(3), tdum(3), mdum(3,3), hdum, wsd, wdd
    real(dp), parameter :: two_pi = 2.0_dp * acos(-1.0_dp)
    real(dp) :: r0
    real(dp), parameter :: eye(3,3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], &
                                              [3, 3])

    stat = stat_ok
    errmsg = ''
    fint = 0.0_dp
    hist_new = hist_old
    e_stored = 0.0_dp
    e_diss = 0.0_dp
    e_visc = 0.0_dp
    e_diss_start = 0.0_dp
    tr_ip = 0.0_dp
    op_ip = 0.0_dp
    fblk = 0.0_dp
    kblk = 0.0_dp
    dndx = 0.0_dp

    ! Node sets of the two faces, paired by face position k (Eqs. 11-13)
    if (ndim == 3) then
      nf = 4
      nnode = 8
      bot = [1, 2, 3, 4]
      top = [5, 6, 7, 8]
    else
      nf = 2
      nnode = 4
      bot = [1, 2, 0, 0]
      top = [4, 3, 0, 0]
    end if
    nip = nf

    ! Initial and current positions, padded to 3 components (plane problems: z = 0)
    x0 = 0.0_dp
    x = 0.0_dp
    xs = 0.0_dp
    do k = 1, nnode
      x0(1:ndim, k) = coords0(1:ndim, k)
      x(1:ndim, k) = coords0(1:ndim, k) + u(ndim * (k - 1) + 1:ndim * k)
      xs(1:ndim, k) = u(ndim * (k - 1) + 1:ndim * k) - u_start(ndim * (k - 1) + 1:ndim * k)
    end do
    if (.not. all(is_finite(x))) then
      stat = stat_bad_state
      errmsg = proc // ': non-finite nodal position'
      return
    end if
    do k = 1, nf
      xm0(:, k) = 0.5_dp * (x0(:, bot(k)) + x0(:, top(k)))
      xm(:, k) = 0.5_dp * (x(:, bot(k)) + x(:, top(k)))
    end do

    ! Gauss points: 2x2 in 3D (counter-clockwise), 2 in 2D
    g = 1.0_dp / sqrt(3.0_dp)
    gxi = [-g, g, g, -g]
    geta = [-g, -g, g, g]
    if (ndim == 2) then
      gxi(1:2) = [-g, g]
      geta = 0.0_dp
    end if

    ! Normal of the current mid-surface at its centre xi = eta = 0 (Eqs. 17-18); in 2D n = e_z x t / |t|
    call shape(ndim, 0.0_dp, 0.0_dp, psi, dxi_c, deta_c)
    txi = matmul(xm(:, 1:nf), dxi_c(1:nf))
    rot2 = 0.0_dp
    if (ndim == 3) then
      teta = matmul(xm(:, 1:nf), deta_c(1:nf))
      a = cross(txi, teta)
    else
      teta = 0.0_dp
      rot2(1, 2) = -1.0_dp
      rot2(2, 1) = 1.0_dp
      a = matmul(rot2, txi)
    end if
    anorm = norm2(a)
    if (.not. (anorm > 0.0_dp)) then
      stat = stat_bad_state
      errmsg = proc // ': the current mid-surface is degenerate (no normal)'
      return
    end if
    n = a / anorm
    ! dn/dx_node for face position l (same for the bottom and the top node: x_m = (x_bot + x_top)/2):
    ! dn = (I - n n^T)/|a| da, da = -[t_eta]x dt_xi + [t_xi]x dt_eta (3D), da = R dt (2D)
    if (want_k .and. props%law == law_ldf) then
      proj = (eye - outer(n, n)) / anorm
      do l = 1, nf
        if (ndim == 3) then
          dndx(:, :, l) = 0.5_dp * matmul(proj, -dxi_c(l) * skew(teta) + deta_c(l) * skew(txi))
        else
          dndx(:, :, l) = 0.5_dp * matmul(proj, dxi_c(l) * rot2)
        end if
      end do
    end if

    do ip = 1, nip
      call shape(ndim, gxi(ip), geta(ip), psi, dpsi_xi, dpsi_eta)
      ! Exact Jacobian of the initial mid-surface (first Piola-Kirchhoff tractions, Eq. 9)
      if (ndim == 3) then
        j0 = norm2(cross(matmul(xm0(:, 1:nf), dpsi_xi(1:nf)), matmul(xm0(:, 1:nf), dpsi_eta(1:nf))))
      else
        j0 = norm2(matmul(xm0(:, 1:nf), dpsi_xi(1:nf)))
      end if
      if (.not. (j0 > 0.0_dp)) then
        stat = stat_bad_input
        errmsg = proc // ': degenerate initial element (zero mid-surface Jacobian; check the node numbering)'
        return
      end if
      w = j0          ! Gauss weights are 1 for both rules
      if (axi) then
        ! initial area element of the surface of revolution: 2 pi R J0 dxi (totals over 2 pi)
        r0 = dot_product(psi(1:nf), xm0(1, 1:nf))
        if (.not. (r0 > 0.0_dp)) then
          stat = stat_bad_input
          errmsg = proc // ': axisymmetric element with r <= 0 at an integration point (x1 is the radius)'
          return
        end if
        w = two_pi * r0 * j0
      else
        w = sec_t * j0
      end if

      ! Opening between associated points (Eq. 10 with P of Eq. 11)
      dvec = 0.0_dp
      do k = 1, nf
        dvec = dvec + psi(k) * (x(:, top(k)) - x(:, bot(k)))
      end do

      if (props%law == law_ldf) then
        call ldf_traction(props, dvec, hist_old(nsv_per_ip * (ip - 1) + 1), tvec, mmat, dmax_new, ws, wd)
        dn = dot_product(dvec, n)
        call contact_traction(props%kc, props%delta, dn, n, tcv, mc, tc, dtc, wc)
        tvec = tvec + tcv        ! Eq. 23
        mmat = mmat + mc         ! Eq. 30
        ws = ws + wc
        ! dT/dn at fixed opening: T_c I + dT_c/dDelta_c n Delta^T (the term Eq. 29 omits)
        gmat = tc * eye + dtc * outer(n, dvec)
        ! dissipated energy of the law at the start of the increment (zero opening keeps Delta_max_old)
        call ldf_traction(props, [0.0_dp, 0.0_dp, 0.0_dp], hist_old(nsv_per_ip * (ip - 1) + 1), tdum, mdum, hdum, &
                          wsd, wdd)
        e_diss_start = e_diss_start + w * wdd
      else
        call classical_traction(props, dvec, n, tvec, dn, dt, ws)
        dmax_new = max(hist_old(nsv_per_ip * (ip - 1) + 1), norm2(dvec))
        wd = 0.0_dp
        mmat = 0.0_dp
        gmat = 0.0_dp
      end if

      ! optional viscous regularisation: T_vec += eta_v dDelta_vec/dt, M += eta_v/dt I, dissipation eta_v |dDelta|^2/dt
      if (rate_c > 0.0_dp) then
        ddel = 0.0_dp
        do k = 1, nf
          ddel = ddel + psi(k) * (xs(:, top(k)) - xs(:, bot(k)))   ! xs: displacement increments
        end do
        tvec = tvec + rate_c * ddel
        mmat = mmat + rate_c * eye
        e_visc = e_visc + w * rate_c * dot_product(ddel, ddel)
      end if

      hist_new(nsv_per_ip * (ip - 1) + 1) = dmax_new
      hist_new(nsv_per_ip * (ip - 1) + 2) = norm2(dvec)
      hist_new(nsv_per_ip * (ip - 1) + 3) = norm2(tvec)
      hist_new(nsv_per_ip * (ip - 1) + 4) = dn
      tr_ip(:, ip) = tvec
      op_ip(:, ip) = dvec
      e_stored = e_stored + w * ws
      e_diss = e_diss + w * wd

      ! Eq. 14: bottom nodes -psi T, top nodes +psi T
      do k = 1, nf
        fblk(:, 1, k) = fblk(:, 1, k) - w * psi(k) * tvec
        fblk(:, 2, k) = fblk(:, 2, k) + w * psi(k) * tvec
      end do

      ! Eq. 15 plus the normal linearisation: dT/du_top,l = psi_l M + G dn/dx_l, dT/du_bot,l = -psi_l M + G dn/dx_l
      if (want_k .and. props%law == law_ldf) then
        do l = 1, nf
          dt_top = psi(l) * mmat + matmul(gmat, dndx(:, :, l))
          dt_bot = -psi(l) * mmat + matmul(gmat, dndx(:, :, l))
          do k = 1, nf
            kblk(:, :, 1, 1, k, l) = kblk(:, :, 1, 1, k, l) - w * psi(k) * dt_bot
            kblk(:, :, 1, 2, k, l) = kblk(:, :, 1, 2, k, l) - w * psi(k) * dt_top
            kblk(:, :, 2, 1, k, l) = kblk(:, :, 2, 1, k, l) + w * psi(k) * dt_bot
            kblk(:, :, 2, 2, k, l) = kblk(:, :, 2, 2, k, l) + w * psi(k) * dt_top
          end do
        end do
      end if
    end do

    ! Scatter to the element dof order (node by node, ndim per node); face 1 = bottom, face 2 = top
    nodes(1, :) = bot
    nodes(2, :) = top
    do k = 1, nf
      do sa = 1, 2
        ka = ndim * (nodes(sa, k) - 1)
        fint(ka + 1:ka + ndim) = fblk(1:ndim, sa, k)
        if (.not. (want_k .and. props%law == law_ldf)) cycle
        do l = 1, nf
          do sb = 1, 2
            kb = ndim * (nodes(sb, l) - 1)
            kmat(ka + 1:ka + ndim, kb + 1:kb + ndim) = kblk(1:ndim, 1:ndim, sa, sb, k, l)
          end do
        end do
      end do
    end do

  end subroutine element_forces

  !> Bilinear shape functions of the quadrilateral (Eq. 13) in 3D, linear ones of the line in 2D, and their derivatives.
  pure subroutine shape(ndim, xi, eta, psi, dpsi_xi, dpsi_eta)
    integer, intent(in) :: ndim
    real(dp), intent(in) :: xi, eta
    real(dp), intent(out) :: psi(4), dpsi_xi(4), dpsi_eta(4)
    if (ndim == 3) then
      psi = 0.25_dp * [(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)]
      dpsi_xi = 0.25_dp * [-(1 - eta), (1 - eta), (1 + eta), -(1 + eta)]
      dpsi_eta = 0.25_dp * [-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]
    else
      psi = [0.5_dp * (1 - xi), 0.5_dp * (1 + xi), 0.0_dp, 0.0_dp]
      dpsi_xi = [-0.5_dp, 0.5_dp, 0.0_dp, 0.0_dp]
      dpsi_eta = 0.0_dp
    end if
  end subroutine shape

  pure function cross(p, q) result(r)
    real(dp), intent(in) :: p(3), q(3)
    real(dp) :: r(3)
    r = [p(2) * q(3) - p(3) * q(2), p(3) * q(1) - p(1) * q(3), p(1) * q(2) - p(2) * q(1)]
  end function cross

  !> [v]x, the matrix with [v]x w = v x w.
  pure function skew(v) result(s)
    real(dp), intent(in) :: v(3)
    real(dp) :: s(3,3)
    s = reshape([0.0_dp, v(3), -v(2), -v(3), 0.0_dp, v(1), v(2), -v(1), 0.0_dp], [3, 3])
  end function skew

  pure function outer(p, q) result(r)
    real(dp), intent(in) :: p(3), q(3)
    real(dp) :: r(3,3)
    r = spread(p, 2, 3) * spread(q, 1, 3)
  end function outer

end module cohesive_element
