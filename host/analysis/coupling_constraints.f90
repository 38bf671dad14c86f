!> *COUPLING constraints on continuum nodes as linear constraint rows for linear_constraints (docs/host.md,
!> "Coupling constraints"), in the linearized (small-rotation) form of the Abaqus Theory Manual:
!> - kinematic: each constrained translation of a coupling node s follows the reference node R's rigid-body
!>   motion, u_s = u_R + theta_R x (X_s - X_R), with an ORIENTATION in its local directions at s; the coupling nodes'
!>   dofs are eliminated (as Abaqus eliminates them), the reference node's translations and rotations (its
!>   rotational dofs, model_dof) are the masters;
!> - distributing: the reference node moves with the coupling nodes' weighted mean, u_R = sum w_n u_n +
!>   theta x (X_R - X_bar), the constrained components of theta_R = theta = T^-1 sum w_n r_n x u_n (the weighted
!>   least-squares rotation; a released rotation has no row,
!>   r_n = X_n - X_bar, T = sum w_n (r_n.r_n I - r_n r_n)), w_n the tributary area of node n on the surface times
!>   the weighting function, normalized; a force and moment at R are then distributed as the Theory Manual's
!>   "Distributing coupling constraints" gives them. The rows are solved for as many coupling-node dofs as the
!>   constraint has rows (chosen by complete pivoting among dofs no boundary or other constraint uses), so that the
!>   reference node's dofs stay ordinary unknowns (loaded or prescribed like any other).
!> Exact without NLGEOM; under NLGEOM only where the rotation cannot enter (coupling_check_step).
module coupling_constraints
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, coupling_t, model_dof, model_label_text, orientation_axes
  use element_catalog, only: element_face_nodes, element_is_axisymmetric
  use distributed_loads, only: surface_shape, line_shape
  use boundary_table, only: boundary_table_t
  use step_loads, only: loads_t
  use solver_text, only: itoa
  implicit none
  private
  public :: coupling_rows_t, coupling_rows, coupling_mark_used, coupling_check_step

  real(dp), parameter :: pivot_tol = 1.0e-10_dp  !< smallest pivot relative to the largest entry of a row set

  !> Constraint rows u(slave(i)) = sum_j w(j) u(mdof(j)), j = ptr(i) .. ptr(i+1)-1.
  type :: coupling_rows_t
    integer :: n = 0                      !< rows
    integer, allocatable :: slave(:)      !< (n) eliminated dof
    integer, allocatable :: ptr(:)        !< (n+1) into mdof, w
    integer, allocatable :: mdof(:)       !< master dofs
    real(dp), allocatable :: w(:)         !< their weights
  end type coupling_rows_t

contains

  !> used(dof) for the dofs of every coupling's reference node that its constraint holds (translations and rotational
  !> dofs): they belong to no element, yet are unknowns of the analysis.
  pure subroutine coupling_mark_used(model, used)
    type(model_t), intent(in) :: model  !< the model
    logical, intent(inout) :: used(:)   !< (ndof) dof of the analysis
    integer :: k, d, i, stat
    type(coupling_rows_t) :: rows
    logical, allocatable :: none(:)
    if (model%ncoupling == 0) return
    allocate (none(size(used)), source=.false.)
    do k = 1, model%ncoupling
      if (model%couplings(k)%kinematic) then
        ! only the reference dofs its rows hold (a coupling of dof 3 alone moves no coupling node with u_R1, u_R2 or
        ! theta_R3: those stay outside the analysis, like the dofs of a node without an element)
        call kinematic_rows(model, model%couplings(k), none, rows, stat)
        used(rows%mdof) = .true.
        cycle
      end if
      ! a distributing coupling: its translations and the rotations it constrains (released ones hold nothing)
      do d = 1, 6
        if (d > 3 .and. .not. model%couplings(k)%dofs(d)) cycle
        i = model_dof(model, model%couplings(k)%ref, d)
        if (i > 0) used(i) = .true.
      end do
    end do
  end subroutine coupling_mark_used

  !> The rows of coupling k. excluded(dof): dofs a distributing coupling may not eliminate (prescribed somewhere,
  !> eliminated or used as masters by other constraints). stat 2 (errmsg naming the *COUPLING line): no rotation is
  !> defined by the coupling nodes, or no independent set of eliminable dofs exists.
  subroutine coupling_rows(model, k, excluded, rows, stat, errmsg)
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: k                             !< coupling
    logical, intent(in) :: excluded(:)                   !< (ndof) dofs not to eliminate
    type(coupling_rows_t), intent(out) :: rows           !< its constraint rows
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    stat = 0
    errmsg = ''
    if (model%couplings(k)%kinematic) then
      call kinematic_rows(model, model%couplings(k), excluded, rows, stat)
      if (stat /= 0) then
        stat = 2
        errmsg = position(model%couplings(k))//': coupling '//trim(model%couplings(k)%name)//': a coupling node '// &
          'has no free global components for its local constraints (boundaries or other constraints hold them)'
      end if
    else
      call distributing_rows(model, model%couplings(k), excluded, rows, stat, errmsg)
    end if
  end subroutine coupling_rows

  !> Kinematic coupling c: u_s,d = u_R,d + (theta_R x (X_s - X_R))_d for every coupling node s and constrained
  !> translation d; with an ORIENTATION, d a local direction at s (kinematic_rows_local). stat 1: a node's local
  !> constraints find no free global components (excluded).
  pure subroutine kinematic_rows(model, c, excluded, rows, stat)
    type(model_t), intent(in) :: model         !< the model
    type(coupling_t), intent(in) :: c          !< the coupling
    logical, intent(in) :: excluded(:)         !< (ndof) dofs not to eliminate (ORIENTATION only)
    type(coupling_rows_t), intent(out) :: rows !< its rows
    integer, intent(out) :: stat               !< 0 ok, 1 no free components
    integer :: a, d, nd
    real(dp) :: r(3), g(3)
    nd = model%ndim
    stat = 0
    if (c%iorient > 0) then
      call kinematic_rows_local(model, c, excluded, rows, stat)
      return
    end if
    call rows_init(rows)
    do a = 1, size(c%nodes)
      r = model%x(:, c%nodes(a)) - model%x(:, c%ref)
      do d = 1, nd
        if (.not. c%dofs(d)) cycle
        if (nd == 3) then
          ! (theta x r)_d = sum_j g_j theta_j
          g = [0.0_dp, r(3), -r(2)]
          if (d == 2) g = [-r(3), 0.0_dp, r(1)]
          if (d == 3) g = [r(2), -r(1), 0.0_dp]
          call rows_add(rows, model_dof(model, c%nodes(a), d), [model_dof(model, c%ref, d), &
            model_dof(model, c%ref, 4), model_dof(model, c%ref, 5), model_dof(model, c%ref, 6)], [1.0_dp, g])
        else
          g(1) = merge(-r(2), r(1), d == 1)
          call rows_add(rows, model_dof(model, c%nodes(a), d), [model_dof(model, c%ref, d), &
            model_dof(model, c%ref, 6)], [1.0_dp, g(1)])
        end if
      end do
    end do
  end subroutine kinematic_rows

  !> Kinematic coupling c with an ORIENTATION (3D): at each coupling node s the local directions e_k of the
  !> orientation at X_s (columns of orientation_axes), and for each constrained local dof k the row
  !> e_k . u_s = e_k . (u_R + theta_R x r_s), r_s = X_s - X_R. The m rows of a node are solved for m of its global
  !> components, chosen by complete pivoting among those not excluded: u_S = E_S^-1 (E G [u_R; theta_R] - E_M u_M),
  !> G = [I, -[r_s]x]. A node on a cylindrical system's axis (no local directions 1, 2 there) gets the row of the
  !> axial dof 3 only, when constrained (inferred: CalculiX takes an arbitrary normal to the axis instead).
  pure subroutine kinematic_rows_local(model, c, excluded, rows, stat)
    type(model_t), intent(in) :: model         !< the model
    type(coupling_t), intent(in) :: c          !< the coupling
    logical, intent(in) :: excluded(:)         !< (ndof) dofs not to eliminate
    type(coupling_rows_t), intent(out) :: rows !< its rows
    integer, intent(out) :: stat               !< 0 ok, 1 no free components
    real(dp) :: t(3, 3), e(3, 3), g(3, 6), x(3, 9)
    real(dp), allocatable :: es(:, :), xs(:, :)
    integer :: a, i, j, m, ref_dof(6), node_dof(3)
    integer, allocatable :: piv(:)
    logical :: ok, is_slave(3)
    stat = 0
    call rows_init(rows)
    ref_dof = [(model_dof(model, c%ref, j), j = 1, 6)]
    do a = 1, size(c%nodes)
      call orientation_axes(model%orientations(c%iorient), model%x(:, c%nodes(a)), t, ok)
      m = count(c%dofs(1:3))
      if (.not. ok) then
        ! on a cylindrical system's axis: no radial or tangential direction, the axial one only (a warning at
        ! finish_model; inferred)
        m = 0
        if (c%dofs(3) .and. model%orientations(c%iorient)%system == 2) then
          m = 1
          t(:, 3) = model%orientations(c%iorient)%b - model%orientations(c%iorient)%a
          t(:, 3) = t(:, 3) / norm2(t(:, 3))
        end if
        if (m == 0) cycle
        e(1, :) = t(:, 3)
      else
        e(1:m, :) = transpose(t(:, pack([1, 2, 3], c%dofs(1:3))))
      end if
      g(:, 1:3) = identity3()
      g(:, 4:6) = -skew(model%x(:, c%nodes(a)) - model%x(:, c%ref))
      node_dof = [(model_dof(model, c%nodes(a), j), j = 1, 3)]
      call choose_pivots(e(1:m, :), excluded(node_dof), piv)
      if (size(piv) < m) then
        stat = 1
        return
      end if
      ! x = E_S^-1 [E G, -E] : the weights of the reference dofs, then of the node's components
      xs = reshape([matmul(e(1:m, :), g), -e(1:m, :)], [m, 9])
      es = e(1:m, piv)
      call solve_dense(es, xs, stat)
      if (stat /= 0) return
      x(1:m, :) = xs
      is_slave = .false.
      is_slave(piv) = .true.
      do i = 1, m
        call rows_add(rows, node_dof(piv(i)), [ref_dof, pack(node_dof, .not. is_slave)], &
          [x(i, 1:6), pack(x(i, 7:9), .not. is_slave)])
      end do
    end do
  end subroutine kinematic_rows_local

  !> Distributing coupling c: [u_R; theta_R] = B u_c solved for m coupling-node dofs S (complete pivoting over the
  !> dofs not excluded): u_S = B_S^-1 ([u_R; theta_R] - B_M u_M).
  subroutine distributing_rows(model, c, excluded, rows, stat, errmsg)
    type(model_t), intent(in) :: model                   !< the model
    type(coupling_t), intent(in) :: c                    !< the coupling
    logical, intent(in) :: excluded(:)                   !< (ndof) dofs not to eliminate
    type(coupling_rows_t), intent(out) :: rows           !< its rows
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    real(dp), allocatable :: b(:, :), bs(:, :), x(:, :)
    integer, allocatable :: col_dof(:), ref_dof(:), piv(:)
    integer :: m, nc, nd, i, j
    logical, allocatable :: is_slave(:)
    stat = 0
    errmsg = ''
    nd = model%ndim
    nc = size(c%nodes)
    call distributing_matrix(model, c, b, ref_dof, stat, errmsg)
    if (stat /= 0) return
    m = size(b, 1)
    allocate (col_dof(nd * nc))
    do i = 1, nc
      do j = 1, nd
        col_dof((i - 1) * nd + j) = model_dof(model, c%nodes(i), j)
      end do
    end do
    call choose_pivots(b, excluded(col_dof), piv)
    if (size(piv) < m) then
      stat = 2
      errmsg = position(c)//': coupling '//trim(c%name)//': the coupling nodes leave no '//itoa(m)// &
        ' independent dofs free of boundaries and other constraints to carry the constraint'
      return
    end if
    bs = b(:, piv)
    ! x = B_S^-1 [I, -B] : the weights of the reference dofs, then of every coupling dof
    allocate (x(m, m + size(b, 2)))
    x = 0.0_dp
    do i = 1, m
      x(i, i) = 1.0_dp
    end do
    x(:, m + 1:) = -b
    call solve_dense(bs, x, stat)
    if (stat /= 0) then
      stat = 2
      errmsg = position(c)//': coupling '//trim(c%name)//': singular constraint (coupling nodes on a line?)'
      return
    end if
    allocate (is_slave(size(b, 2)))
    is_slave = .false.
    is_slave(piv) = .true.
    call rows_init(rows)
    do i = 1, m
      call rows_add(rows, col_dof(piv(i)), [ref_dof, pack(col_dof, .not. is_slave)], &
        [x(i, 1:m), pack(x(i, m + 1:), .not. is_slave)])
    end do
  end subroutine distributing_rows

  !> B (m x ndim*nc) of coupling c, [u_R; theta_R] = B u_c, and the reference dofs of its rows (translations, then
  !> the rotational dofs when the coupling couples them).
  subroutine distributing_matrix(model, c, b, ref_dof, stat, errmsg)
    type(model_t), intent(in) :: model                   !< the model
    type(coupling_t), intent(in) :: c                    !< the coupling
    real(dp), allocatable, intent(out) :: b(:, :)        !< the matrix
    integer, allocatable, intent(out) :: ref_dof(:)      !< (m) reference dofs of the rows
    integer, intent(out) :: stat                         !< 0 ok, 2 no rotation defined
    character(len=:), allocatable, intent(out) :: errmsg !< message
    real(dp), allocatable :: w(:)
    real(dp) :: xbar(3), rr(3), r(3), t(3, 3), ti(3, 3), gn(3, 3), tt
    integer :: nd, nc, n, m, nrot, d
    logical :: rot_needed, rot(3)
    stat = 0
    errmsg = ''
    nd = model%ndim
    nc = size(c%nodes)
    call coupling_weights(model, c, w, xbar)
    rr = model%x(:, c%ref) - xbar
    ! the rotations the coupling constrains (the others released: no row, their moment transmits nothing)
    rot = [(c%dofs(d) .and. model_dof(model, c%ref, d) > 0, d = 4, 6)]
    if (nd == 2) rot(1:2) = .false.
    nrot = count(rot)
    m = nd + nrot
    allocate (b(m, nd * nc), ref_dof(m))
    ref_dof(1:nd) = [(model_dof(model, c%ref, d), d = 1, nd)]
    ref_dof(nd + 1:) = pack([(model_dof(model, c%ref, d), d = 4, 6)], rot)
    b = 0.0_dp
    rot_needed = nrot > 0 .or. norm2(rr) > 1.0e-12_dp * max(1.0_dp, maxval(abs(model%x(:, c%nodes))))
    t = 0.0_dp
    do n = 1, nc
      r = model%x(:, c%nodes(n)) - xbar
      if (nd == 3) then
        t = t + w(n) * (dot_product(r, r) * identity3() - spread(r, 2, 3) * spread(r, 1, 3))
      else
        t(1, 1) = t(1, 1) + w(n) * (r(1)**2 + r(2)**2)
      end if
    end do
    if (rot_needed) then
      call invert_inertia(t, nd, ti, stat)
      if (stat /= 0) then
        stat = 2
        errmsg = position(c)//': coupling '//trim(c%name)//': the coupling nodes define no rotation (on one line '// &
          'or one node), which the reference node''s rotation or its offset from their weighted centre needs'
        return
      end if
    end if
    do n = 1, nc
      r = model%x(:, c%nodes(n)) - xbar
      do d = 1, nd
        b(d, (n - 1) * nd + d) = w(n)
      end do
      if (.not. rot_needed) cycle
      if (nd == 3) then
        ! theta = sum G_n u_n, G_n = w_n T^-1 [r_n]x ; u_R += theta x r_R = -[r_R]x theta
        ! (full inertia T: a constrained rotation is the component of the group's least-squares rotation; inferred)
        gn = w(n) * matmul(ti, skew(r))
        b(1:3, (n - 1) * 3 + 1:n * 3) = b(1:3, (n - 1) * 3 + 1:n * 3) - matmul(skew(rr), gn)
        if (nrot > 0) b(4:m, (n - 1) * 3 + 1:n * 3) = gn(pack([1, 2, 3], rot), :)
      else
        tt = w(n) * ti(1, 1)
        ! theta = sum tt (r_x u_y - r_y u_x); u_R += theta (-r_Ry, r_Rx)
        b(1, (n - 1) * 2 + 1:n * 2) = b(1, (n - 1) * 2 + 1:n * 2) - rr(2) * tt * [-r(2), r(1)]
        b(2, (n - 1) * 2 + 1:n * 2) = b(2, (n - 1) * 2 + 1:n * 2) + rr(1) * tt * [-r(2), r(1)]
        if (nrot == 1) b(3, (n - 1) * 2 + 1:n * 2) = tt * [-r(2), r(1)]
      end if
    end do
  end subroutine distributing_matrix

  !> The normalized weights of coupling c's nodes and their weighted centre: the tributary area of each node on the
  !> surface (the integral of its face shape function over the faces; quadratic faces: the diagonal of the face
  !> mass matrix scaled to the face's area, which keeps every weight positive) times the weighting function of
  !> its distance r from the reference node (UNIFORM 1, LINEAR 1 - r/r0, QUADRATIC 1 - (r/r0)^2, CUBIC
  !> 1 - 3 (r/r0)^2 + 2 (r/r0)^3; r0 the influence radius, or the farthest coupling node's distance).
  pure subroutine coupling_weights(model, c, w, xbar)
    type(model_t), intent(in) :: model            !< the model
    type(coupling_t), intent(in) :: c             !< the coupling
    real(dp), allocatable, intent(out) :: w(:)    !< (nc) weights, sum 1
    real(dp), intent(out) :: xbar(3)              !< their weighted centre
    real(dp), allocatable :: area(:), dist(:)
    real(dp) :: r0, q
    integer :: n
    call tributary_areas(model, c, area)
    allocate (dist(size(c%nodes)))
    do n = 1, size(c%nodes)
      dist(n) = norm2(model%x(:, c%nodes(n)) - model%x(:, c%ref))
    end do
    r0 = c%radius
    if (r0 <= 0.0_dp) r0 = maxval(dist)
    w = area
    do n = 1, size(w)
      q = min(1.0_dp, dist(n) / max(r0, tiny(1.0_dp)))
      select case (c%weighting)
      case (2)
        w(n) = w(n) * (1.0_dp - q)
      case (3)
        w(n) = w(n) * (1.0_dp - q**2)
      case (4)
        w(n) = w(n) * (1.0_dp - 3.0_dp * q**2 + 2.0_dp * q**3)
      end select
    end do
    if (sum(w) <= 0.0_dp) w = area
    w = w / sum(w)
    do n = 1, 3
      xbar(n) = dot_product(w, model%x(n, c%nodes))
    end do
  end subroutine coupling_weights

  !> The tributary area of each coupling node of c on c's surface (a face node outside the influence radius adds
  !> nothing): linear faces the integral of N_a, quadratic faces the face mass diagonal scaled to the area (2D:
  !> per unit thickness; axisymmetric: the integral of N_a 2 pi r).
  pure subroutine tributary_areas(model, c, area)
    type(model_t), intent(in) :: model            !< the model
    type(coupling_t), intent(in) :: c             !< the coupling
    real(dp), allocatable, intent(out) :: area(:) !< (nc) areas
    real(dp), parameter :: g3(3) = [-0.774596669241483377035853079956_dp, 0.0_dp, 0.774596669241483377035853079956_dp]
    real(dp), parameter :: w3(3) = [5.0_dp / 9, 8.0_dp / 9, 5.0_dp / 9]
    real(dp) :: xf(3, 8), nf(8), ds(8), dt(8), da, fa(8), fm(8), s, t, wq
    integer :: j, ie, loc(8), nfn, g, h, a, npt, k
    logical :: axi
    allocate (area(size(c%nodes)))
    area = 0.0_dp
    associate (sf => model%surfaces(c%surface))
      do j = 1, size(sf%relems)
        ie = sf%relems(j)
        call element_face_nodes(model%elem_kind(ie), sf%rfaces(j), loc, nfn)
        axi = element_is_axisymmetric(model%elem_kind(ie))
        xf(:, 1:nfn) = model%x(:, model%conn(model%conn_ptr(ie) + loc(1:nfn) - 1))
        fa = 0.0_dp
        fm = 0.0_dp
        npt = 3
        if (model%ndim == 3) npt = merge(3, 9, nfn == 3 .or. nfn == 6)
        do g = 1, npt
          if (model%ndim == 2) then
            call line_shape(nfn, g3(g), nf, ds)
            da = w3(g) * norm2(matmul(xf(1:2, 1:nfn), ds(1:nfn)))
            if (axi) da = da * 2.0_dp * acos(-1.0_dp) * dot_product(nf(1:nfn), xf(1, 1:nfn))
          else
            if (npt == 3) then
              s = merge(2.0_dp / 3, 1.0_dp / 6, g == 2)
              t = merge(2.0_dp / 3, 1.0_dp / 6, g == 3)
              wq = 1.0_dp / 6
            else
              h = (g - 1) / 3 + 1
              s = g3(g - 3 * (h - 1))
              t = g3(h)
              wq = w3(g - 3 * (h - 1)) * w3(h)
            end if
            call surface_shape(nfn, s, t, nf, ds, dt)
            da = wq * norm2(cross(matmul(xf(:, 1:nfn), ds(1:nfn)), matmul(xf(:, 1:nfn), dt(1:nfn))))
          end if
          fa(1:nfn) = fa(1:nfn) + da * nf(1:nfn)
          fm(1:nfn) = fm(1:nfn) + da * nf(1:nfn)**2
        end do
        ! quadratic faces: the diagonal of the face mass, scaled to the face's area (all positive)
        if (any(nfn == [3, 6, 8]) .and. .not. (model%ndim == 3 .and. nfn == 3)) fa(1:nfn) = fm(1:nfn) * sum(fa(1:nfn)) / &
          sum(fm(1:nfn))
        do a = 1, nfn
          k = findloc(c%nodes, model%conn(model%conn_ptr(ie) + loc(a) - 1), 1)
          if (k > 0) area(k) = area(k) + fa(a)
        end do
      end do
    end associate
  end subroutine tributary_areas

  !> NLGEOM step is: the coupling is exact only where its rotation cannot enter: a kinematic coupling's reference
  !> rotations held at zero (prescribed 0, and 0 at the step's start); a distributing coupling with its reference
  !> node at the coupling nodes' weighted centre and its rotational dofs (if any) neither prescribed nor loaded.
  !> stat 2 (errmsg naming the *COUPLING line) otherwise.
  subroutine coupling_check_step(model, is, bc, loads, stat, errmsg)
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: is                            !< the step beginning
    type(boundary_table_t), intent(in) :: bc             !< its prescribed conditions
    type(loads_t), intent(in) :: loads                   !< its loads
    integer, intent(out) :: stat                         !< 0 ok, 2 not exact under NLGEOM
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: k, d, i
    real(dp), allocatable :: w(:)
    real(dp) :: xbar(3), size_c
    logical :: ok
    stat = 0
    errmsg = ''
    if (.not. model%steps(is)%nlgeom) return
    do k = 1, model%ncoupling
      associate (c => model%couplings(k))
        ok = .true.
        if (c%kinematic) then
          do d = 4, 6
            i = model_dof(model, c%ref, d)
            if (i == 0) cycle
            ok = ok .and. bc%on(i) .and. .not. bc%vel(i) .and. bc%val(i) == 0.0_dp .and. bc%u_start(i) == 0.0_dp
          end do
        else
          call coupling_weights(model, c, w, xbar)
          size_c = maxval([(norm2(model%x(:, c%nodes(d)) - xbar), d = 1, size(c%nodes))])
          ok = norm2(model%x(:, c%ref) - xbar) <= 1.0e-9_dp * max(size_c, tiny(1.0_dp))
          do d = 4, 6
            i = model_dof(model, c%ref, d)
            if (i == 0) cycle
            ok = ok .and. .not. bc%on(i) .and. .not. loads%cload%on(i) .and. loads%cload%released(i) == 0.0_dp
          end do
        end if
        if (ok) cycle
        stat = 2
        if (c%kinematic) then
          errmsg = position(c)//': coupling '//trim(c%name)//': step '//itoa(is)//' has NLGEOM, but ldfcz''s '// &
            'kinematic coupling is the small-rotation one: exact under NLGEOM only with the reference node''s '// &
            'rotations held at 0 (*BOUNDARY on dofs 4..6, or 6 in 2D); otherwise use NLGEOM=NO'
        else
          errmsg = position(c)//': coupling '//trim(c%name)//': step '//itoa(is)//' has NLGEOM, but ldfcz''s '// &
            'distributing coupling is the small-rotation one: exact under NLGEOM only with the reference node at '// &
            'the coupling nodes'' weighted centre and its rotations neither prescribed nor loaded; otherwise use '// &
            'NLGEOM=NO'
        end if
        return
      end associate
    end do
  end subroutine coupling_check_step

  ! ---------------------------------------------------------------------------------------------------- helpers

  pure function position(c) result(s)
    type(coupling_t), intent(in) :: c
    character(len=:), allocatable :: s
    s = c%pos%file//':'//itoa(c%pos%line)//': *COUPLING'
  end function position

  pure subroutine rows_init(rows)
    type(coupling_rows_t), intent(out) :: rows
    allocate (rows%slave(0), rows%mdof(0), rows%w(0), rows%ptr(1))
    rows%ptr(1) = 1
  end subroutine rows_init

  !> Append the row u(slave) = sum w u(mdof) (masters 0, the dofs a node lacks, and weights of 0 dropped).
  pure subroutine rows_add(rows, slave, mdof, w)
    type(coupling_rows_t), intent(inout) :: rows
    integer, intent(in) :: slave, mdof(:)
    real(dp), intent(in) :: w(:)
    integer :: i
    rows%n = rows%n + 1
    rows%slave = [rows%slave, slave]
    do i = 1, size(mdof)
      if (mdof(i) == 0 .or. w(i) == 0.0_dp) cycle
      rows%mdof = [rows%mdof, mdof(i)]
      rows%w = [rows%w, w(i)]
    end do
    rows%ptr = [rows%ptr, size(rows%mdof) + 1]
  end subroutine rows_add

  !> Columns of b for its rows by complete pivoting (largest remaining entry), among the columns not excluded;
  !> fewer than size(b, 1) when the rest fall below pivot_tol of the largest entry.
  pure subroutine choose_pivots(b, excluded, piv)
    real(dp), intent(in) :: b(:, :)
    logical, intent(in) :: excluded(:)
    integer, allocatable, intent(out) :: piv(:)
    real(dp) :: a(size(b, 1), size(b, 2)), big, f
    logical :: used_row(size(b, 1)), used_col(size(b, 2))
    integer :: k, i, j, r, q
    a = b
    used_row = .false.
    used_col = excluded
    allocate (piv(0))
    big = maxval(abs(b))
    do k = 1, size(b, 1)
      r = 0
      q = 0
      f = pivot_tol * big
      do j = 1, size(a, 2)
        if (used_col(j)) cycle
        do i = 1, size(a, 1)
          if (used_row(i)) cycle
          if (abs(a(i, j)) > f) then
            f = abs(a(i, j))
            r = i
            q = j
          end if
        end do
      end do
      if (r == 0) return
      piv = [piv, q]
      used_row(r) = .true.
      used_col(q) = .true.
      do i = 1, size(a, 1)
        if (used_row(i)) cycle
        a(i, :) = a(i, :) - a(i, q) / a(r, q) * a(r, :)
      end do
    end do
  end subroutine choose_pivots

  !> x <- a^-1 x by Gaussian elimination with partial pivoting; stat 1 when a is singular.
  pure subroutine solve_dense(a, x, stat)
    real(dp), intent(inout) :: a(:, :)
    real(dp), intent(inout) :: x(:, :)
    integer, intent(out) :: stat
    integer :: n, k, p, i
    real(dp) :: t(size(x, 2)), ta(size(a, 2))
    stat = 0
    n = size(a, 1)
    do k = 1, n
      p = k - 1 + maxloc(abs(a(k:n, k)), 1)
      if (abs(a(p, k)) <= pivot_tol * maxval(abs(a))) then
        stat = 1
        return
      end if
      if (p /= k) then
        ta = a(k, :); a(k, :) = a(p, :); a(p, :) = ta
        t = x(k, :); x(k, :) = x(p, :); x(p, :) = t
      end if
      do i = 1, n
        if (i == k) cycle
        x(i, :) = x(i, :) - a(i, k) / a(k, k) * x(k, :)
        a(i, :) = a(i, :) - a(i, k) / a(k, k) * a(k, :)
      end do
    end do
    do k = 1, n
      x(k, :) = x(k, :) / a(k, k)
    end do
  end subroutine solve_dense

  !> The inverse of the coupling nodes' inertia T (3D), or of its scalar (2D: ti(1,1) = 1 / T(1,1)).
  pure subroutine invert_inertia(t, nd, ti, stat)
    real(dp), intent(in) :: t(3, 3)
    integer, intent(in) :: nd
    real(dp), intent(out) :: ti(3, 3)
    integer, intent(out) :: stat
    real(dp) :: a(3, 3)
    integer :: i
    stat = 0
    ti = 0.0_dp
    if (nd == 2) then
      if (t(1, 1) <= 0.0_dp) then
        stat = 1
        return
      end if
      ti(1, 1) = 1.0_dp / t(1, 1)
      return
    end if
    a = t
    do i = 1, 3
      ti(i, i) = 1.0_dp
    end do
    call solve_dense(a, ti, stat)
  end subroutine invert_inertia

  pure function identity3() result(e)
    real(dp) :: e(3, 3)
    integer :: i
    e = 0.0_dp
    do i = 1, 3
      e(i, i) = 1.0_dp
    end do
  end function identity3

  !> [v]x: the matrix of v x (.).
  pure function skew(v) result(s)
    real(dp), intent(in) :: v(3)
    real(dp) :: s(3, 3)
    s = reshape([0.0_dp, v(3), -v(2), -v(3), 0.0_dp, v(1), v(2), -v(1), 0.0_dp], [3, 3])
  end function skew

  pure function cross(p, q) result(w)
    real(dp), intent(in) :: p(3), q(3)
    real(dp) :: w(3)
    w = [p(2) * q(3) - p(3) * q(2), p(3) * q(1) - p(1) * q(3), p(1) * q(2) - p(2) * q(1)]
  end function cross

end module coupling_constraints
