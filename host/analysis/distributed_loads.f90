!> Distributed loads of the steps (*DLOAD, *DSLOAD): per element and load (BX/BY/BZ, GRAV, face pressure Pn, user
!> load Un) the magnitude in force, its propagation across steps (OP=MOD modifies the load of the same element and
!> label, OP=NEW removes every inherited one, which then decays over the step like a removed concentrated load), the
!> nodal forces of body loads (per unit reference volume; GRAV: density x g, exact for the conserved mass) and of
!> face pressure (on the current face under NLGEOM: a follower load, with its load stiffness), and the NDLOAD,
!> JDLTYP, ADLMAG, DDLMAG arrays of a user element.
module distributed_loads
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, amplitude_factor, dload_bx, dload_grav, dload_pressure, dload_user, etype_user, &
    dload_centrif, dload_rota
  use element_catalog, only: element_face_nodes, element_is_axisymmetric
  use solver_text, only: itoa
  implicit none
  private
  public :: dload_state_t, dload_step_begin, dload_element, dload_uel_arrays, dload_has, dload_reindex
  public :: surface_shape, line_shape

  !> The distributed loads in force in the current step, one record per element and label.
  type :: dload_state_t
    integer :: n = 0                         !< records
    integer, allocatable :: elem(:)          !< element index
    integer, allocatable :: kind(:)          !< dload_bx, dload_grav, dload_pressure, dload_user
    integer, allocatable :: label(:)         !< direction (BX..BZ: 1..3), face (Pn), n (Un); 0 for GRAV
    integer, allocatable :: amp(:)           !< amplitude (0: the step's default)
    logical, allocatable :: removed(:)       !< removed by OP=NEW in this step (decays to zero)
    real(dp), allocatable :: base(:, :)      !< (3, n) value at the start of the step (vector for body loads)
    real(dp), allocatable :: target(:, :)    !< (3, n) magnitude in this step
    real(dp), allocatable :: axis(:, :)      !< (6, n) CENTRIF/ROTA: a point on the axis, its unit direction
    integer, allocatable :: ptr(:)           !< (nelem+1) records of element ie: idx(ptr(ie):ptr(ie+1)-1)
    integer, allocatable :: idx(:)
    integer :: step = 0                      !< step the records belong to
    real(dp) :: t_total0 = 0.0_dp            !< total time at the start of that step
  end type dload_state_t

contains

  !> Element ie carries a distributed load in the current step.
  pure logical function dload_has(ds, ie)
    type(dload_state_t), intent(in) :: ds  !< load state
    integer, intent(in) :: ie              !< element index
    dload_has = .false.
    if (.not. allocated(ds%ptr)) return
    dload_has = ds%ptr(ie + 1) > ds%ptr(ie)
  end function dload_has

  !> Value (3-vector) of record k at step time t of the step of the records.
  pure function record_value(ds, model, k, t) result(v)
    type(dload_state_t), intent(in) :: ds  !< load state
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: k               !< record
    real(dp), intent(in) :: t              !< step time
    real(dp) :: v(3), s
    associate (st => model%steps(ds%step))
      s = min(1.0_dp, max(0.0_dp, t / st%period))
      if (st%amp_step) s = 1.0_dp
      if (ds%amp(k) > 0) then
        v = amplitude_factor(model%amplitudes(ds%amp(k)), t, ds%t_total0) * ds%target(:, k)
      else
        v = ds%base(:, k) + s * (ds%target(:, k) - ds%base(:, k))
      end if
    end associate
  end function record_value

  !> Start of step is (at total time t_total0): inherited loads hold the value reached, OP=NEW removes them, the
  !> step's *DLOAD/*DSLOAD lines modify or add records in deck order. stat /= 0 (errmsg) for a face that the
  !> element does not have.
  subroutine dload_step_begin(ds, model, is, t_total0, stat, errmsg)
    type(dload_state_t), intent(inout) :: ds             !< load state
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: is                            !< step number
    real(dp), intent(in) :: t_total0                     !< total time at the start of step is
    integer, intent(out) :: stat                         !< 0 ok, 2 input error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: k, j, m, ie, lab, found, loc(8), nfn, keep
    real(dp) :: vec(3)
    character(len=16) :: b
    stat = 0
    errmsg = ''
    if (.not. allocated(ds%elem)) then
      allocate (ds%elem(0), ds%kind(0), ds%label(0), ds%amp(0), ds%removed(0), ds%base(3, 0), ds%target(3, 0), &
        ds%axis(6, 0))
    end if
    ! values reached at the end of the previous step; records that decayed to zero are dropped
    keep = 0
    do k = 1, ds%n
      if (ds%removed(k)) cycle
      vec = record_value(ds, model, k, model%steps(ds%step)%period)
      keep = keep + 1
      ds%elem(keep) = ds%elem(k)
      ds%kind(keep) = ds%kind(k)
      ds%label(keep) = ds%label(k)
      ds%base(:, keep) = vec
      ds%target(:, keep) = vec
      ds%axis(:, keep) = ds%axis(:, k)
    end do
    ds%n = keep
    ds%amp(1:keep) = 0
    ds%removed(1:keep) = .false.
    ds%step = is
    ds%t_total0 = t_total0
    associate (st => model%steps(is))
      if (st%dload_op_new) then
        ds%removed(1:ds%n) = .true.
        ds%target(:, 1:ds%n) = 0.0_dp
      end if
      do k = 1, st%ndload
        associate (dl => st%dloads(k))
          do j = 1, size(dl%elems)
            ie = dl%elems(j)
            select case (dl%kind)
            case (dload_bx)
              lab = maxloc(dl%dir, 1)
              vec = dl%value * dl%dir
            case (dload_grav, dload_centrif, dload_rota)
              ! one record per element: a later GRAV (CENTRIF, ROTA) line for it replaces the load (OP=MOD)
              lab = 0
              vec = dl%value * dl%dir
              if (dl%kind /= dload_grav) vec = [dl%value, 0.0_dp, 0.0_dp]
            case default
              lab = dl%faces(j)
              if (dl%kind == dload_user) lab = dl%label
              vec = [dl%value, 0.0_dp, 0.0_dp]
            end select
            if (dl%kind == dload_pressure) then
              call element_face_nodes(model%elem_kind(ie), lab, loc, nfn)
              if (nfn == 0) then
                write (b, '(i0)') model%elem_id(ie)
                stat = 2
                errmsg = dl%pos%file//':'//itoa(dl%pos%line)//': '//trim(dl%pos%keyword)//': element '// &
                  trim(b)//' has no face S'//itoa(lab)
                return
              end if
            end if
            found = 0
            do m = 1, ds%n
              if (ds%removed(m)) cycle
              if (ds%elem(m) == ie .and. ds%kind(m) == dl%kind .and. ds%label(m) == lab) then
                found = m
                exit
              end if
            end do
            if (found == 0) then
              call grow(ds)
              found = ds%n
              ds%elem(found) = ie
              ds%kind(found) = dl%kind
              ds%label(found) = lab
              ds%base(:, found) = 0.0_dp
              ds%removed(found) = .false.
            end if
            ds%target(:, found) = vec
            ds%amp(found) = dl%amplitude
            ds%axis(:, found) = [dl%point, dl%dir]
          end do
        end associate
      end do
    end associate
    call dload_reindex(ds, model%nelem)
  end subroutine dload_step_begin

  !> The records by element (ptr, idx) from the records' elements: after a step's begin and a restart's read.
  pure subroutine dload_reindex(ds, nelem)
    type(dload_state_t), intent(inout) :: ds  !< load state (n records)
    integer, intent(in) :: nelem              !< elements of the model
    integer :: k, ie
    integer, allocatable :: fill(:)
    if (allocated(ds%ptr)) deallocate (ds%ptr)
    if (allocated(ds%idx)) deallocate (ds%idx)
    allocate (ds%ptr(nelem + 1), ds%idx(ds%n))
    ds%ptr = 0
    do k = 1, ds%n
      ds%ptr(ds%elem(k) + 1) = ds%ptr(ds%elem(k) + 1) + 1
    end do
    ds%ptr(1) = 1
    do ie = 1, nelem
      ds%ptr(ie + 1) = ds%ptr(ie + 1) + ds%ptr(ie)
    end do
    fill = ds%ptr(1:nelem)
    do k = 1, ds%n
      ds%idx(fill(ds%elem(k))) = k
      fill(ds%elem(k)) = fill(ds%elem(k)) + 1
    end do
  end subroutine dload_reindex

  !> External nodal forces f (element dof layout, node-major) of the continuum element ie at step time t, and
  !> when want_k the load stiffness k_l = -df/du of follower pressure under NLGEOM (unsymmetric in general).
  !> x0 (ndim, nn) reference coordinates, u the element displacements, nfun/wdet the reference integration data,
  !> thickness of plane elements, density of the material.
  pure subroutine dload_element(ds, model, ie, t, x0, u, nlgeom, nfun, wdet, thickness, density, want_k, f, k_l)
    type(dload_state_t), intent(in) :: ds   !< load state
    type(model_t), intent(in) :: model      !< the model
    integer, intent(in) :: ie               !< element
    real(dp), intent(in) :: t               !< step time (end of the increment)
    real(dp), intent(in) :: x0(:, :)        !< (ndim, nn) reference coordinates
    real(dp), intent(in) :: u(:)            !< (ndim*nn) displacements
    logical, intent(in) :: nlgeom           !< follower pressure on the current face
    real(dp), intent(in) :: nfun(:, :)      !< (>= nn, nip) shape functions at the integration points
    real(dp), intent(in) :: wdet(:)         !< (nip) weight x reference Jacobian
    real(dp), intent(in) :: thickness       !< plane-strain thickness (2D)
    real(dp), intent(in) :: density         !< mass density (GRAV)
    logical, intent(in) :: want_k           !< load stiffness wanted
    real(dp), intent(out) :: f(:)           !< external forces
    real(dp), intent(out) :: k_l(:, :)      !< load stiffness
    integer :: j, k, ndim, nn, a, ip
    real(dp) :: v(3), x(size(x0, 1), size(x0, 2)), w
    ndim = size(x0, 1)
    nn = size(x0, 2)
    f = 0.0_dp
    k_l = 0.0_dp
    x = x0
    if (nlgeom) x = x0 + reshape(u, [ndim, nn])
    do j = ds%ptr(ie), ds%ptr(ie + 1) - 1
      k = ds%idx(j)
      v = record_value(ds, model, k, t)
      select case (ds%kind(k))
      case (dload_bx, dload_grav)
        w = 1.0_dp
        ! (axisymmetric elements: wdet is already the volume weight around 2 pi radians)
        if (ndim == 2 .and. .not. element_is_axisymmetric(model%elem_kind(ie))) w = thickness
        if (ds%kind(k) == dload_grav) w = w * density
        do ip = 1, size(wdet)
          do a = 1, nn
            f((a - 1) * ndim + 1:a * ndim) = f((a - 1) * ndim + 1:a * ndim) + w * wdet(ip) * nfun(a, ip) * v(1:ndim)
          end do
        end do
      case (dload_pressure)
        call face_pressure(model%elem_kind(ie), ds%label(k), v(1), x, ndim, thickness, nlgeom .and. want_k, f, k_l)
      case (dload_centrif, dload_rota)
        w = density
        if (ndim == 2 .and. .not. element_is_axisymmetric(model%elem_kind(ie))) w = w * thickness
        call rotational_load(ds%kind(k), v(1) * w, ds%axis(:, k), x, nfun, wdet, nlgeom .and. want_k, f, k_l)
      end select
    end do
  end subroutine dload_element

  !> The rotational body forces of the Abaqus Theory Manual ("Rotational body forces") per unit reference volume,
  !> at the points x (current ones under NLGEOM, where the forces follow the body, with their load stiffness):
  !> CENTRIF b = rho omega^2 (x - p)_perp, the centrifugal force about the axis (p, n), r_perp = (I - n n)(x - p);
  !> ROTA b = -rho alpha n x (x - p), the d'Alembert force of a rotary acceleration alpha about it. c = rho omega^2
  !> or rho alpha (times the thickness of plane elements; an axisymmetric element's wdet holds the 2 pi r). The load
  !> stiffness k_l = -df/du: CENTRIF -c N_a N_b (I - n n) (symmetric), ROTA c N_a N_b [n]x (skew).
  pure subroutine rotational_load(kind, c, axis, x, nfun, wdet, follower, f, k_l)
    integer, intent(in) :: kind               !< dload_centrif or dload_rota
    real(dp), intent(in) :: c                 !< rho omega^2 or rho alpha (x thickness)
    real(dp), intent(in) :: axis(6)           !< point on the axis, unit direction
    real(dp), intent(in) :: x(:, :)           !< (ndim, nn) coordinates
    real(dp), intent(in) :: nfun(:, :)        !< (>= nn, nip) shape functions at the integration points
    real(dp), intent(in) :: wdet(:)           !< (nip) weight x reference Jacobian
    logical, intent(in) :: follower           !< with the load stiffness
    real(dp), intent(inout) :: f(:)           !< element forces
    real(dp), intent(inout) :: k_l(:, :)      !< element load stiffness
    real(dp) :: xp(3), r(3), b(3), p(3, 3), g(3, 3), n(3)
    integer :: ip, a, bb, nd, nn, i
    nd = size(x, 1)
    nn = size(x, 2)
    n = axis(4:6)
    p = 0.0_dp
    do i = 1, 3
      p(i, i) = 1.0_dp
    end do
    p = p - spread(n, 2, 3) * spread(n, 1, 3)
    g = skew(n)
    do ip = 1, size(wdet)
      xp = 0.0_dp
      xp(1:nd) = matmul(x, nfun(1:nn, ip))
      r = xp - axis(1:3)
      if (kind == dload_centrif) then
        b = c * matmul(p, r)
      else
        b = -c * matmul(g, r)
      end if
      do a = 1, nn
        f((a - 1) * nd + 1:a * nd) = f((a - 1) * nd + 1:a * nd) + wdet(ip) * nfun(a, ip) * b(1:nd)
        if (.not. follower) cycle
        do bb = 1, nn
          if (kind == dload_centrif) then
            k_l((a - 1) * nd + 1:a * nd, (bb - 1) * nd + 1:bb * nd) = k_l((a - 1) * nd + 1:a * nd, &
              (bb - 1) * nd + 1:bb * nd) - c * wdet(ip) * nfun(a, ip) * nfun(bb, ip) * p(1:nd, 1:nd)
          else
            k_l((a - 1) * nd + 1:a * nd, (bb - 1) * nd + 1:bb * nd) = k_l((a - 1) * nd + 1:a * nd, &
              (bb - 1) * nd + 1:bb * nd) + c * wdet(ip) * nfun(a, ip) * nfun(bb, ip) * g(1:nd, 1:nd)
          end if
        end do
      end do
    end do
  end subroutine rotational_load

  !> Pressure p on face `face` of an element with current coordinates x: f -= p N_a n dA (n outward, element_catalog),
  !> and with follower the stiffness -df/du. Face interpolation by the number of face nodes: 2 or 3 (2D line, linear
  !> or quadratic, 3-point Gauss), 4 or 8 (quadrilateral, bilinear or serendipity, 3x3 Gauss), 3 or 6 (triangle,
  !> linear or quadratic, 3-point rule of degree 2). Exact for the nodal forces of a flat face.
  pure subroutine face_pressure(kind, face, p, x, ndim, thickness, follower, f, k_l)
    integer, intent(in) :: kind, face, ndim
    real(dp), intent(in) :: p, x(:, :), thickness
    logical, intent(in) :: follower
    real(dp), intent(inout) :: f(:), k_l(:, :)
    real(dp), parameter :: g3(3) = [-0.774596669241483377035853079956_dp, 0.0_dp, 0.774596669241483377035853079956_dp]
    real(dp), parameter :: w3(3) = [5.0_dp / 9, 8.0_dp / 9, 5.0_dp / 9]
    real(dp), parameter :: tri_pts(2, 3) = reshape([1.0_dp / 6, 1.0_dp / 6, 2.0_dp / 3, 1.0_dp / 6, 1.0_dp / 6, &
      2.0_dp / 3], [2, 3])
    integer :: loc(8), nfn, g, h, a, b, ia, ib, npt
    real(dp) :: s, t, w, nf(8), ds(8), dt(8), xs(3), xe(3), na(3), sx(3, 3), se(3, 3), c, wr
    logical :: axi
    call element_face_nodes(kind, face, loc, nfn)
    axi = element_is_axisymmetric(kind)
    if (ndim == 2) then
      ! plane elements: per section thickness; axisymmetric: per 2 pi r (totals around the circumference)
      do g = 1, 3
        call line_shape(nfn, g3(g), nf, ds)
        xs(1:2) = matmul(x(:, loc(1:nfn)), ds(1:nfn))
        wr = thickness
        if (axi) wr = 2 * acos(-1.0_dp) * dot_product(nf(1:nfn), x(1, loc(1:nfn)))
        do a = 1, nfn
          ia = (loc(a) - 1) * 2
          f(ia + 1) = f(ia + 1) - p * wr * w3(g) * nf(a) * xs(2)
          f(ia + 2) = f(ia + 2) + p * wr * w3(g) * nf(a) * xs(1)
          if (.not. follower) cycle
          do b = 1, nfn
            ib = (loc(b) - 1) * 2
            c = p * wr * w3(g) * nf(a) * ds(b)
            k_l(ia + 1, ib + 2) = k_l(ia + 1, ib + 2) + c
            k_l(ia + 2, ib + 1) = k_l(ia + 2, ib + 1) - c
            if (axi) then
              ! d(2 pi r)/du_(b r) = 2 pi N_b
              c = p * 2 * acos(-1.0_dp) * w3(g) * nf(a) * nf(b)
              k_l(ia + 1, ib + 1) = k_l(ia + 1, ib + 1) + c * xs(2)
              k_l(ia + 2, ib + 1) = k_l(ia + 2, ib + 1) - c * xs(1)
            end if
          end do
        end do
      end do
    else
      npt = merge(3, 9, nfn == 3 .or. nfn == 6)
      do g = 1, npt
        if (npt == 3) then
          s = tri_pts(1, g)
          t = tri_pts(2, g)
          w = 1.0_dp / 6
        else
          h = (g - 1) / 3 + 1
          s = g3(g - 3 * (h - 1))
          t = g3(h)
          w = w3(g - 3 * (h - 1)) * w3(h)
        end if
        call surface_shape(nfn, s, t, nf, ds, dt)
        xs = matmul(x(:, loc(1:nfn)), ds(1:nfn))
        xe = matmul(x(:, loc(1:nfn)), dt(1:nfn))
        na = [xs(2) * xe(3) - xs(3) * xe(2), xs(3) * xe(1) - xs(1) * xe(3), xs(1) * xe(2) - xs(2) * xe(1)]
        sx = skew(xs)
        se = skew(xe)
        do a = 1, nfn
          ia = (loc(a) - 1) * 3
          f(ia + 1:ia + 3) = f(ia + 1:ia + 3) - p * w * nf(a) * na
          if (.not. follower) cycle
          ! d(xs x xe)/du_b = dt_b [xs]x - ds_b [xe]x
          do b = 1, nfn
            ib = (loc(b) - 1) * 3
            k_l(ia + 1:ia + 3, ib + 1:ib + 3) = k_l(ia + 1:ia + 3, ib + 1:ib + 3) + p * w * nf(a) * &
              (dt(b) * sx - ds(b) * se)
          end do
        end do
      end do
    end if
  end subroutine face_pressure

  !> Line shape functions on [-1, 1]: 2 nodes (ends) or 3 (ends, then the middle).
  pure subroutine line_shape(nfn, s, nf, ds)
    integer, intent(in) :: nfn
    real(dp), intent(in) :: s
    real(dp), intent(out) :: nf(8), ds(8)
    nf = 0.0_dp
    ds = 0.0_dp
    if (nfn == 2) then
      nf(1:2) = [0.5_dp * (1 - s), 0.5_dp * (1 + s)]
      ds(1:2) = [-0.5_dp, 0.5_dp]
    else
      nf(1:3) = [0.5_dp * s * (s - 1), 0.5_dp * s * (s + 1), 1 - s * s]
      ds(1:3) = [s - 0.5_dp, s + 0.5_dp, -2 * s]
    end if
  end subroutine line_shape

  !> Face shape functions and derivatives in the face's node order (element_catalog): quadrilateral on [-1, 1]^2 with
  !> 4 or 8 nodes (corners, then mid-sides of edges 1-2, 2-3, 3-4, 4-1), triangle in area coordinates (s, t) with
  !> 3 or 6 nodes (corners at (0,0), (1,0), (0,1), then mid-sides of edges 1-2, 2-3, 3-1).
  pure subroutine surface_shape(nfn, s, t, nf, ds, dt)
    integer, intent(in) :: nfn
    real(dp), intent(in) :: s, t
    real(dp), intent(out) :: nf(8), ds(8), dt(8)
    real(dp), parameter :: cs(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp], ct(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
    real(dp) :: l(3), dls(3), dlt(3)
    integer :: a, i, j
    integer, parameter :: te(2, 3) = reshape([1, 2, 2, 3, 3, 1], [2, 3])
    nf = 0.0_dp
    ds = 0.0_dp
    dt = 0.0_dp
    select case (nfn)
    case (4)
      do a = 1, 4
        nf(a) = 0.25_dp * (1 + cs(a) * s) * (1 + ct(a) * t)
        ds(a) = 0.25_dp * cs(a) * (1 + ct(a) * t)
        dt(a) = 0.25_dp * ct(a) * (1 + cs(a) * s)
      end do
    case (8)
      do a = 1, 4
        nf(a) = 0.25_dp * (1 + cs(a) * s) * (1 + ct(a) * t) * (cs(a) * s + ct(a) * t - 1)
        ds(a) = 0.25_dp * cs(a) * (1 + ct(a) * t) * (2 * cs(a) * s + ct(a) * t)
        dt(a) = 0.25_dp * ct(a) * (1 + cs(a) * s) * (cs(a) * s + 2 * ct(a) * t)
      end do
      ! mid-sides 5 (t = -1), 6 (s = 1), 7 (t = 1), 8 (s = -1)
      nf(5) = 0.5_dp * (1 - s * s) * (1 - t); ds(5) = -s * (1 - t); dt(5) = -0.5_dp * (1 - s * s)
      nf(6) = 0.5_dp * (1 + s) * (1 - t * t); ds(6) = 0.5_dp * (1 - t * t); dt(6) = -t * (1 + s)
      nf(7) = 0.5_dp * (1 - s * s) * (1 + t); ds(7) = -s * (1 + t); dt(7) = 0.5_dp * (1 - s * s)
      nf(8) = 0.5_dp * (1 - s) * (1 - t * t); ds(8) = -0.5_dp * (1 - t * t); dt(8) = -t * (1 - s)
    case (3, 6)
      l = [1 - s - t, s, t]
      dls = [-1.0_dp, 1.0_dp, 0.0_dp]
      dlt = [-1.0_dp, 0.0_dp, 1.0_dp]
      if (nfn == 3) then
        nf(1:3) = l
        ds(1:3) = dls
        dt(1:3) = dlt
      else
        do a = 1, 3
          nf(a) = l(a) * (2 * l(a) - 1)
          ds(a) = (4 * l(a) - 1) * dls(a)
          dt(a) = (4 * l(a) - 1) * dlt(a)
        end do
        do a = 4, 6
          i = te(1, a - 3)
          j = te(2, a - 3)
          nf(a) = 4 * l(i) * l(j)
          ds(a) = 4 * (dls(i) * l(j) + l(i) * dls(j))
          dt(a) = 4 * (dlt(i) * l(j) + l(i) * dlt(j))
        end do
      end if
    end select
  end subroutine surface_shape

  !> [v]x: the matrix of the cross product v x (.).
  pure function skew(v) result(s)
    real(dp), intent(in) :: v(3)
    real(dp) :: s(3, 3)
    s = reshape([0.0_dp, v(3), -v(2), -v(3), 0.0_dp, v(1), v(2), -v(1), 0.0_dp], [3, 3])
  end function skew

  !> The Un loads of user element ie as Abaqus passes them: ndload active loads, jdltyp(k) = n, adlmag(k) the
  !> magnitude at the end of the increment (step time t_end), ddlmag(k) its increment over dt.
  pure subroutine dload_uel_arrays(ds, model, ie, t_end, dt, ndload, jdltyp, adlmag, ddlmag)
    type(dload_state_t), intent(in) :: ds  !< load state
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: ie              !< element
    real(dp), intent(in) :: t_end, dt      !< step time at the end of the increment, increment
    integer, intent(out) :: ndload         !< loads on the element
    integer, intent(out) :: jdltyp(:)      !< (mdload) load type numbers
    real(dp), intent(out) :: adlmag(:)     !< (mdload) magnitudes
    real(dp), intent(out) :: ddlmag(:)     !< (mdload) increments
    integer :: j, k
    real(dp) :: v1(3), v0(3)
    ndload = 0
    jdltyp = 0
    adlmag = 0.0_dp
    ddlmag = 0.0_dp
    if (.not. allocated(ds%ptr)) return
    do j = ds%ptr(ie), ds%ptr(ie + 1) - 1
      k = ds%idx(j)
      if (ds%kind(k) /= dload_user .or. ndload >= size(jdltyp)) cycle
      if (model%elem_kind(ie) /= etype_user) cycle
      ndload = ndload + 1
      v1 = record_value(ds, model, k, t_end)
      v0 = record_value(ds, model, k, max(0.0_dp, t_end - dt))
      jdltyp(ndload) = ds%label(k)
      adlmag(ndload) = v1(1)
      ddlmag(ndload) = v1(1) - v0(1)
    end do
  end subroutine dload_uel_arrays

  pure subroutine grow(ds)
    type(dload_state_t), intent(inout) :: ds
    integer :: c
    integer, allocatable :: ti(:)
    logical, allocatable :: tl(:)
    real(dp), allocatable :: tr(:, :)
    c = size(ds%elem)
    if (ds%n == c) then
      c = max(8, 2 * c)
      allocate (ti(c)); ti(1:ds%n) = ds%elem(1:ds%n); call move_alloc(ti, ds%elem)
      allocate (ti(c)); ti(1:ds%n) = ds%kind(1:ds%n); call move_alloc(ti, ds%kind)
      allocate (ti(c)); ti(1:ds%n) = ds%label(1:ds%n); call move_alloc(ti, ds%label)
      allocate (ti(c)); ti(1:ds%n) = ds%amp(1:ds%n); call move_alloc(ti, ds%amp)
      allocate (tl(c)); tl(1:ds%n) = ds%removed(1:ds%n); call move_alloc(tl, ds%removed)
      allocate (tr(3, c)); tr(:, 1:ds%n) = ds%base(:, 1:ds%n); call move_alloc(tr, ds%base)
      allocate (tr(3, c)); tr(:, 1:ds%n) = ds%target(:, 1:ds%n); call move_alloc(tr, ds%target)
      allocate (tr(6, c)); tr(:, 1:ds%n) = ds%axis(:, 1:ds%n); call move_alloc(tr, ds%axis)
    end if
    ds%n = ds%n + 1
  end subroutine grow

end module distributed_loads
