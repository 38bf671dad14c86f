!> Linear multi-point constraints (*EQUATION) by elimination: each equation sum_i A_i u_i = 0 makes its first dof a
!> dependent (slave) dof, u_s = sum_(i>1) (-A_i / A_1) u_i, as Abaqus eliminates the first term. The slave gets no
!> equation; an element holding slave dofs is assembled through its transformation T (u_e = T u_x), K_x = T^T K T,
!> on an extended dof list (its own free dofs, then the masters of its slaves), and the residual of a slave is
!> added to its masters with the same weights. The dofs of a node with a *TRANSFORM are its local components
!> (node_rotations), so an *EQUATION term there acts in the local system, as in Abaqus.
module linear_constraints
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, boundary_t, model_dof, model_label_text
  use element_catalog, only: element_face_nodes
  use coupling_constraints, only: coupling_rows_t, coupling_rows
  use pretension_sections, only: pretension_rows
  implicit none
  private
  public :: constraint_set_t, constraints_build, constraints_extend, constraints_transform, constraints_residual, &
    constraints_apply, constraints_reactions, constraints_mark_masters

  type :: constraint_set_t
    integer :: n = 0                      !< constraints (equations after set expansion)
    integer, allocatable :: slave(:)      !< (n) dependent dof
    integer, allocatable :: ptr(:)        !< (n+1) into mdof, w
    integer, allocatable :: mdof(:)       !< independent (master) dofs
    real(dp), allocatable :: w(:)         !< their weights -A_i / A_1
    integer, allocatable :: of_dof(:)     !< (ndof) constraint of a slave dof, 0 otherwise
    ! extended element lists (constraints_extend)
    integer, allocatable :: xptr(:)       !< (nelem+1) into xeq, xdof
    integer, allocatable :: xeq(:)        !< equations of the extended element dofs (0: none)
    integer, allocatable :: xdof(:)       !< global dofs of the extended element dofs
    integer, allocatable :: tptr(:)       !< (nelem+1) into trow, tcol, tw: the slave rows of T
    integer, allocatable :: trow(:), tcol(:)
    real(dp), allocatable :: tw(:)
    integer :: max_x = 0                  !< longest extended list
  end type constraint_set_t

contains

  !> The constraints of the model's *EQUATION definitions (dofs of an ndim model). stat 2 with errmsg for a slave
  !> used twice, a master that is itself a slave, a zero first coefficient or a dof without an element.
  subroutine constraints_build(cs, model, used, stat, errmsg)
    type(constraint_set_t), intent(out) :: cs            !< constraints
    type(model_t), intent(in) :: model                   !< the model
    logical, intent(in) :: used(:)                       !< (ndof) dof attached to an element
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: k, c, t, ncopy, nc, nm, i
    character(len=16) :: b
    stat = 0
    errmsg = ''
    allocate (cs%of_dof(size(used)))
    cs%of_dof = 0
    nc = 0
    nm = 0
    do k = 1, model%nequation
      ncopy = size(model%equations(k)%terms(1)%nodes)
      nc = nc + ncopy
      nm = nm + ncopy * (size(model%equations(k)%terms) - 1)
    end do
    cs%n = nc
    allocate (cs%slave(nc), cs%ptr(nc + 1), cs%mdof(nm), cs%w(nm))
    cs%ptr(1) = 1
    nc = 0
    do k = 1, model%nequation
      associate (eqn => model%equations(k))
        write (b, '(i0)') eqn%pos%line
        ncopy = size(eqn%terms(1)%nodes)
        do c = 1, ncopy
          nc = nc + 1
          cs%slave(nc) = dof_of(eqn%terms(1)%nodes(c), eqn%terms(1)%dof)
          cs%ptr(nc + 1) = cs%ptr(nc)
          if (eqn%terms(1)%value == 0.0_dp) then
            call fail('the first coefficient (of the eliminated dof) is zero')
            return
          end if
          if (eqn%mpc .and. allocated(model%node_transform)) then
            ! an MPC ties global components; with a node's *TRANSFORM its dofs would be local ones
            if (any([(model%node_transform(eqn%terms(t)%nodes(c)) /= 0, t = 1, size(eqn%terms))])) then
              stat = 2
              errmsg = eqn%pos%file//':'//trim(b)//': *MPC: a node of the constraint has a *TRANSFORM: MPCs on '// &
                'transformed nodes are not supported'
              return
            end if
          end if
          do t = 2, size(eqn%terms)
            i = cs%ptr(nc + 1)
            cs%mdof(i) = dof_of(eqn%terms(t)%nodes(c), eqn%terms(t)%dof)
            cs%w(i) = -eqn%terms(t)%value / eqn%terms(1)%value
            cs%ptr(nc + 1) = i + 1
          end do
          if (cs%of_dof(cs%slave(nc)) /= 0) then
            call fail('a dof is the first (eliminated) term of two equations')
            return
          end if
          ! an eliminated dof of a node without an element (a node whose motion the equation defines, e.g. for
          ! output) is accepted when every retained term belongs to an element (constraints_mark_masters then
          ! counts it as used: a load there reaches the retained terms)
          if (.not. used(cs%slave(nc))) then
            if (.not. all(used(cs%mdof(cs%ptr(nc):cs%ptr(nc + 1) - 1)))) then
              call fail('the eliminated dof belongs to no element, nor do all of its retained terms')
              return
            end if
          end if
          cs%of_dof(cs%slave(nc)) = nc
        end do
      end associate
    end do
    if (model%npretension > 0) call add_pretensions(cs, model)
    do k = 1, model%ntie
      call add_tie(cs, model, k, used, stat, errmsg)
      if (stat /= 0) return
    end do
    if (model%ncoupling > 0) call add_couplings(cs, model, stat, errmsg)
    if (stat /= 0) return
    call resolve_chains(cs, stat)
    if (stat /= 0) errmsg = '*EQUATION/*TIE/*COUPLING: the constraints are dependent (a dof eliminated by one constraint '// &
      'depends on itself through others with weight 1): no dof can be eliminated'

  contains

    integer function dof_of(node, d)
      integer, intent(in) :: node, d
      dof_of = (node - 1) * model%ndim + d
    end function dof_of

    subroutine fail(msg)
      character(len=*), intent(in) :: msg
      stat = 2
      errmsg = model%equations(k)%pos%file//':'//trim(b)//': *EQUATION: '//msg
    end subroutine fail

  end subroutine constraints_build

  !> The rows of the pre-tension sections (pretension_sections): each extra dof of a section node is eliminated.
  pure subroutine add_pretensions(cs, model)
    type(constraint_set_t), intent(inout) :: cs  !< constraints
    type(model_t), intent(in) :: model           !< the model
    integer, allocatable :: slave(:), ptr(:), mdof(:)
    real(dp), allocatable :: w(:)
    integer :: r
    call pretension_rows(model, slave, ptr, mdof, w)
    do r = 1, size(slave)
      call append_exact(cs, slave(r), mdof(ptr(r):ptr(r + 1) - 1), w(ptr(r):ptr(r + 1) - 1))
    end do
  end subroutine add_pretensions

  !> *TIE k: every node of the slave surface that is not a node of the master surface is tied to the master face
  !> it projects onto (within the position tolerance), u_s = sum_a N_a(xi) u_a for each displacement dof.
  subroutine add_tie(cs, model, k, used, stat, errmsg)
    type(constraint_set_t), intent(inout) :: cs          !< constraints
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: k                             !< tie
    logical, intent(in) :: used(:)                       !< dofs attached to elements
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: j, a, nfn, loc(8), ie, nd, best, d, s, c
    integer, allocatable :: snodes(:), mnodes(:, :), mn(:)
    real(dp) :: xi(2), dist, bestd, bestxi(2), tol, nf(4), size_f
    character(len=16) :: b1, b2
    stat = 0
    errmsg = ''
    nd = model%ndim
    associate (t => model%ties(k), sm => model%surfaces(model%ties(k)%slave), &
        ms => model%surfaces(model%ties(k)%master))
      allocate (mnodes(4, size(ms%relems)), mn(size(ms%relems)))
      mnodes = 0
      do j = 1, size(ms%relems)
        ie = ms%relems(j)
        call element_face_nodes(model%elem_kind(ie), ms%rfaces(j), loc, nfn)
        if (.not. ((nd == 3 .and. nfn == 4) .or. (nd == 2 .and. nfn == 2))) then
          call fail('master surface '//trim(ms%name)//': a face that is not a 4-node (3D) or 2-node (2D) face')
          return
        end if
        mn(j) = nfn
        mnodes(1:nfn, j) = model%conn(model%conn_ptr(ie) + loc(1:nfn) - 1)
      end do
      allocate (snodes(0))
      do j = 1, size(sm%relems)
        ie = sm%relems(j)
        call element_face_nodes(model%elem_kind(ie), sm%rfaces(j), loc, nfn)
        do a = 1, nfn
          s = model%conn(model%conn_ptr(ie) + loc(a) - 1)
          if (any(snodes == s) .or. any(mnodes == s)) cycle
          snodes = [snodes, s]
        end do
      end do
      if (allocated(model%node_transform)) then
        ! the tie's u_s = sum N_a u_a holds between global components
        do j = 1, size(snodes)
          if (model%node_transform(snodes(j)) /= 0) then
            write (b1, '(i0)') model%node_id(snodes(j))
            call fail('slave node '//trim(b1)//' has a *TRANSFORM: ties between transformed nodes are not supported')
            return
          end if
        end do
        do j = 1, size(mn)
          do a = 1, mn(j)
            if (model%node_transform(mnodes(a, j)) /= 0) then
              write (b1, '(i0)') model%node_id(mnodes(a, j))
              call fail('master node '//trim(b1)//' has a *TRANSFORM: ties between transformed nodes are not '// &
                'supported')
              return
            end if
          end do
        end do
      end if
      do j = 1, size(snodes)
        s = snodes(j)
        best = 0
        bestd = huge(1.0_dp)
        do a = 1, size(mn)
          call project(model%x(1:nd, mnodes(1:mn(a), a)), model%x(1:nd, s), xi, dist, size_f)
          tol = t%tolerance
          if (tol < 0.0_dp) tol = 0.05_dp * size_f
          if (any(abs(xi(1:nd - 1)) > 1.0_dp + 1.0e-6_dp) .or. dist > tol) cycle
          if (dist < bestd) then
            bestd = dist
            best = a
            bestxi = xi
          end if
        end do
        if (best == 0) then
          write (b1, '(i0)') model%node_id(s)
          call fail('slave node '//trim(b1)//' of surface '//trim(sm%name)//' projects onto no face of '// &
            trim(ms%name)//' within the position tolerance')
          return
        end if
        if (bestd > 1.0e-6_dp * max(1.0_dp, size_f)) then
          write (b1, '(i0)') model%node_id(s)
          write (b2, '(es10.3)') bestd
          call fail('slave node '//trim(b1)//' is '//trim(adjustl(b2))//' away from the master surface: ldfcz '// &
            'does not move slave nodes onto it (ADJUST); mesh the tied surfaces to coincide')
          return
        end if
        if (nd == 3) then
          nf = 0.25_dp * [(1 - bestxi(1)) * (1 - bestxi(2)), (1 + bestxi(1)) * (1 - bestxi(2)), &
            (1 + bestxi(1)) * (1 + bestxi(2)), (1 - bestxi(1)) * (1 + bestxi(2))]
        else
          nf(1:2) = [0.5_dp * (1 - bestxi(1)), 0.5_dp * (1 + bestxi(1))]
        end if
        do d = 1, nd
          c = (s - 1) * nd + d
          if (.not. used(c)) cycle
          if (cs%of_dof(c) /= 0) then
            write (b1, '(i0)') model%node_id(s)
            call fail('slave node '//trim(b1)//' is already constrained by another equation or tie')
            return
          end if
          call append(cs, c, (mnodes(1:mn(best), best) - 1) * nd + d, nf(1:mn(best)))
        end do
      end do
    end associate

  contains

    subroutine fail(msg)
      character(len=*), intent(in) :: msg
      character(len=16) :: bl
      write (bl, '(i0)') model%ties(k)%pos%line
      stat = 2
      errmsg = model%ties(k)%pos%file//':'//trim(bl)//': *TIE: '//msg
    end subroutine fail

  end subroutine add_tie

  !> The *COUPLING constraints (coupling_constraints): a distributing coupling eliminates dofs that no boundary of
  !> any step prescribes and no earlier constraint uses; a kinematic coupling's nodes may not be constrained
  !> otherwise (Abaqus eliminates them too).
  subroutine add_couplings(cs, model, stat, errmsg)
    type(constraint_set_t), intent(inout) :: cs          !< constraints
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    logical, allocatable :: excluded(:)
    type(coupling_rows_t) :: rows
    integer :: k, i, is, nd
    character(len=16) :: b
    stat = 0
    errmsg = ''
    allocate (excluded(size(cs%of_dof)), source=.false.)
    call exclude_prescribed(model%initial_bcs, model%n_initial_bc)
    do is = 1, model%nstep
      call exclude_prescribed(model%steps(is)%bcs, model%steps(is)%nbc)
    end do
    do k = 1, model%ncoupling
      excluded = excluded .or. cs%of_dof /= 0
      excluded(cs%mdof) = .true.
      call coupling_rows(model, k, excluded, rows, stat, errmsg)
      if (stat /= 0) return
      do i = 1, rows%n
        if (cs%of_dof(rows%slave(i)) /= 0) then
          nd = (rows%slave(i) - 1) / model%ndim + 1
          write (b, '(i0)') model%couplings(k)%pos%line
          stat = 2
          errmsg = model%couplings(k)%pos%file//':'//trim(b)//': *COUPLING: coupling '// &
            trim(model%couplings(k)%name)//': node '//model_label_text(model, model%node_id(nd), .true.)// &
            ' is already constrained by another equation, tie or coupling'
          return
        end if
        call append_exact(cs, rows%slave(i), rows%mdof(rows%ptr(i):rows%ptr(i + 1) - 1), &
          rows%w(rows%ptr(i):rows%ptr(i + 1) - 1))
      end do
    end do

  contains

    subroutine exclude_prescribed(list, n)
      type(boundary_t), intent(in) :: list(:)
      integer, intent(in) :: n
      integer :: j, a, d, dof
      do j = 1, n
        do a = 1, size(list(j)%nodes)
          do d = list(j)%first_dof, list(j)%last_dof
            dof = model_dof(model, list(j)%nodes(a), d)
            if (dof > 0) excluded(dof) = .true.
          end do
          do d = 1, 3
            if (list(j)%rot_dofs(d) == 0) cycle
            dof = model_dof(model, list(j)%nodes(a), list(j)%rot_dofs(d))
            if (dof > 0) excluded(dof) = .true.
          end do
        end do
      end do
    end subroutine exclude_prescribed

  end subroutine add_couplings

  !> Chains of constraints (a dof that one constraint eliminates is a retained term of another, as Abaqus allows
  !> when the eliminating equation comes later: Analysis User's Guide "Linear constraint equations") resolved by
  !> substitution, so that every row's masters are independent dofs; repeated masters are merged, zero weights
  !> dropped. A row that comes back to its own slave (u_s = a u_s + ..., two equations that eliminate each other's
  !> retained dofs) is solved for it, u_s = (...) / (1 - a); stat 2 where 1 - a vanishes (the equations are
  !> dependent: no dof can be eliminated).
  pure subroutine resolve_chains(cs, stat)
    type(constraint_set_t), intent(inout) :: cs  !< constraints
    integer, intent(out) :: stat                 !< 0 ok, 2 dependent constraints
    integer, allocatable :: ptr(:), mdof(:)
    real(dp), allocatable :: w(:)
    real(dp) :: self
    integer :: pass, c, i, j, r
    logical :: changed
    stat = 0
    if (cs%n == 0) return
    if (all(cs%of_dof(cs%mdof) == 0)) return
    do pass = 1, 2 * cs%n + 2
      changed = .false.
      allocate (ptr(cs%n + 1), mdof(0), w(0))
      ptr(1) = 1
      do c = 1, cs%n
        self = 0.0_dp
        do i = cs%ptr(c), cs%ptr(c + 1) - 1
          r = cs%of_dof(cs%mdof(i))
          if (cs%mdof(i) == cs%slave(c)) then
            self = self + cs%w(i)
          else if (r == 0) then
            call add_term(mdof, w, ptr(c), cs%mdof(i), cs%w(i))
          else
            changed = .true.
            do j = cs%ptr(r), cs%ptr(r + 1) - 1
              if (cs%mdof(j) == cs%slave(c)) then
                self = self + cs%w(i) * cs%w(j)
              else
                call add_term(mdof, w, ptr(c), cs%mdof(j), cs%w(i) * cs%w(j))
              end if
            end do
          end if
        end do
        if (self /= 0.0_dp) then
          if (abs(1.0_dp - self) <= 1.0e-12_dp) then
            stat = 2
            return
          end if
          w(ptr(c):) = w(ptr(c):) / (1.0_dp - self)
          changed = .true.
        end if
        ptr(c + 1) = size(mdof) + 1
      end do
      call move_alloc(ptr, cs%ptr)
      call move_alloc(mdof, cs%mdof)
      call move_alloc(w, cs%w)
      if (.not. changed) return
    end do
    stat = 2
  end subroutine resolve_chains

  !> Term (dof, weight) added to the row that starts at mdof(start) (merged with the same dof already there).
  pure subroutine add_term(mdof, w, start, dof, wt)
    integer, allocatable, intent(inout) :: mdof(:)   !< masters of the rows built so far
    real(dp), allocatable, intent(inout) :: w(:)     !< their weights
    integer, intent(in) :: start                     !< first term of the row being built
    integer, intent(in) :: dof                       !< master dof
    real(dp), intent(in) :: wt                       !< its weight
    integer :: n
    if (wt == 0.0_dp) return
    do n = start, size(mdof)
      if (mdof(n) == dof) then
        w(n) = w(n) + wt
        return
      end if
    end do
    mdof = [mdof, dof]
    w = [w, wt]
  end subroutine add_term

  !> used(master) for the masters of every constraint whose slave is used: such a dof carries the slave's stiffness
  !> (a coupling's reference node, a node that ties nodes of elements) even when no element of its own holds it;
  !> first used(slave) for a slave of no element whose masters all belong to elements (its motion is defined).
  pure subroutine constraints_mark_masters(cs, used)
    type(constraint_set_t), intent(in) :: cs  !< constraints
    logical, intent(inout) :: used(:)         !< (ndof) dofs of the analysis
    integer :: c
    ! a slave of no element whose masters all belong to elements: held by its constraint
    do c = 1, cs%n
      if (cs%ptr(c + 1) > cs%ptr(c) .and. .not. used(cs%slave(c))) then
        if (all(used(cs%mdof(cs%ptr(c):cs%ptr(c + 1) - 1)))) used(cs%slave(c)) = .true.
      end if
    end do
    do c = 1, cs%n
      if (used(cs%slave(c))) used(cs%mdof(cs%ptr(c):cs%ptr(c + 1) - 1)) = .true.
    end do
  end subroutine constraints_mark_masters

  !> Append constraint u(slave) = sum w u(mdof) as given.
  pure subroutine append_exact(cs, slave, mdof, w)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: slave, mdof(:)
    real(dp), intent(in) :: w(:)
    cs%slave = [cs%slave, slave]
    cs%mdof = [cs%mdof, mdof]
    cs%w = [cs%w, w]
    cs%ptr = [cs%ptr, size(cs%mdof) + 1]
    cs%n = cs%n + 1
    cs%of_dof(slave) = cs%n
  end subroutine append_exact

  !> The reactions at prescribed masters include what their slaves carry: f(master) += w (f(slave) - fext(slave) -
  !> fdl(slave)) for every prescribed master of a constraint (a prescribed reference node of a coupling, a
  !> prescribed node a tie or equation carries), applied to the converged internal force before the reactions
  !> fint - fext - fdl are taken (the free dofs' equations already hold these terms: constraints_residual).
  pure subroutine constraints_reactions(cs, prescribed, fext, fdl, fint)
    type(constraint_set_t), intent(in) :: cs  !< constraints
    logical, intent(in) :: prescribed(:)      !< (ndof) prescribed dofs
    real(dp), intent(in) :: fext(:)           !< (ndof) concentrated loads
    real(dp), intent(in) :: fdl(:)            !< (ndof) distributed-load forces
    real(dp), intent(inout) :: fint(:)        !< (ndof) internal force
    integer :: c, i
    do c = 1, cs%n
      do i = cs%ptr(c), cs%ptr(c + 1) - 1
        if (prescribed(cs%mdof(i))) fint(cs%mdof(i)) = fint(cs%mdof(i)) + cs%w(i) * (fint(cs%slave(c)) - &
          fext(cs%slave(c)) - fdl(cs%slave(c)))
      end do
    end do
  end subroutine constraints_reactions

  !> Closest point of a face (2 nodes in 2D, 4 in 3D, bilinear) to point p: parent coordinates xi, distance, and
  !> the face size (largest node distance from the first node).
  pure subroutine project(xf, p, xi, dist, size_f)
    real(dp), intent(in) :: xf(:, :), p(:)
    real(dp), intent(out) :: xi(2), dist, size_f
    real(dp) :: x(size(p)), g1(size(p)), g2(size(p)), r(size(p)), a11, a12, a22, b1, b2, det, nf(4)
    integer :: it, nd, a
    nd = size(p)
    xi = 0.0_dp
    size_f = 0.0_dp
    do a = 2, size(xf, 2)
      size_f = max(size_f, norm2(xf(:, a) - xf(:, 1)))
    end do
    do it = 1, 20
      if (nd == 2) then
        x = 0.5_dp * (1 - xi(1)) * xf(:, 1) + 0.5_dp * (1 + xi(1)) * xf(:, 2)
        g1 = 0.5_dp * (xf(:, 2) - xf(:, 1))
        r = p - x
        xi(1) = xi(1) + dot_product(g1, r) / max(dot_product(g1, g1), tiny(1.0_dp))
      else
        nf = 0.25_dp * [(1 - xi(1)) * (1 - xi(2)), (1 + xi(1)) * (1 - xi(2)), (1 + xi(1)) * (1 + xi(2)), &
          (1 - xi(1)) * (1 + xi(2))]
        x = matmul(xf(:, 1:4), nf)
        g1 = 0.25_dp * (-(1 - xi(2)) * xf(:, 1) + (1 - xi(2)) * xf(:, 2) + (1 + xi(2)) * xf(:, 3) - (1 + xi(2)) * xf(:, 4))
        g2 = 0.25_dp * (-(1 - xi(1)) * xf(:, 1) - (1 + xi(1)) * xf(:, 2) + (1 + xi(1)) * xf(:, 3) + (1 - xi(1)) * xf(:, 4))
        r = p - x
        a11 = dot_product(g1, g1)
        a12 = dot_product(g1, g2)
        a22 = dot_product(g2, g2)
        b1 = dot_product(g1, r)
        b2 = dot_product(g2, r)
        det = a11 * a22 - a12 * a12
        if (abs(det) <= tiny(1.0_dp)) exit
        xi = xi + [a22 * b1 - a12 * b2, a11 * b2 - a12 * b1] / det
      end if
      xi = max(-2.0_dp, min(2.0_dp, xi))
    end do
    if (nd == 2) then
      x = 0.5_dp * (1 - xi(1)) * xf(:, 1) + 0.5_dp * (1 + xi(1)) * xf(:, 2)
    else
      nf = 0.25_dp * [(1 - xi(1)) * (1 - xi(2)), (1 + xi(1)) * (1 - xi(2)), (1 + xi(1)) * (1 + xi(2)), &
        (1 - xi(1)) * (1 + xi(2))]
      x = matmul(xf(:, 1:4), nf)
    end if
    dist = norm2(p - x)
  end subroutine project

  !> Append constraint u(slave) = sum w u(mdof) (weights below 1e-12 dropped).
  pure subroutine append(cs, slave, mdof, w)
    type(constraint_set_t), intent(inout) :: cs
    integer, intent(in) :: slave, mdof(:)
    real(dp), intent(in) :: w(:)
    integer :: i
    cs%slave = [cs%slave, slave]
    do i = 1, size(mdof)
      if (abs(w(i)) < 1.0e-12_dp) cycle
      cs%mdof = [cs%mdof, mdof(i)]
      cs%w = [cs%w, w(i)]
    end do
    cs%ptr = [cs%ptr, size(cs%mdof) + 1]
    cs%n = cs%n + 1
    cs%of_dof(slave) = cs%n
  end subroutine append

  !> Extended element lists for the equation numbers eq (0: prescribed, unused or slave): every element dof keeps
  !> its position (a slave's equation is 0), the masters of its slaves are appended (or found among its dofs).
  pure subroutine constraints_extend(cs, elem_ptr, elem_dof, eq)
    type(constraint_set_t), intent(inout) :: cs  !< constraints
    integer, intent(in) :: elem_ptr(:)           !< (nelem+1) element dof pointers
    integer, intent(in) :: elem_dof(:)           !< global dof of each element dof
    integer, intent(in) :: eq(:)                 !< (ndof) equation numbers
    integer :: nelem, ie, k, c, i, p, nx, nt, m
    integer, allocatable :: xdof(:), trow(:), tcol(:)
    real(dp), allocatable :: tw(:)
    nelem = size(elem_ptr) - 1
    allocate (cs%xptr(nelem + 1), cs%tptr(nelem + 1))
    allocate (xdof(size(elem_dof) + 8 * cs%n + 8), trow(8 * cs%n + 8), tcol(8 * cs%n + 8), tw(8 * cs%n + 8))
    cs%xptr(1) = 1
    cs%tptr(1) = 1
    nx = 0
    nt = 0
    cs%max_x = 0
    do ie = 1, nelem
      m = 0
      do k = elem_ptr(ie), elem_ptr(ie + 1) - 1
        call grow_i(xdof, nx + 1)
        nx = nx + 1
        m = m + 1
        xdof(nx) = elem_dof(k)
      end do
      do k = elem_ptr(ie), elem_ptr(ie + 1) - 1
        c = cs%of_dof(elem_dof(k))
        if (c == 0) cycle
        do i = cs%ptr(c), cs%ptr(c + 1) - 1
          p = 0
          do p = cs%xptr(ie), nx
            if (xdof(p) == cs%mdof(i)) exit
          end do
          if (p > nx) then
            call grow_i(xdof, nx + 1)
            nx = nx + 1
            m = m + 1
            xdof(nx) = cs%mdof(i)
            p = nx
          end if
          nt = nt + 1
          call grow_i(trow, nt)
          call grow_i(tcol, nt)
          call grow_r(tw, nt)
          trow(nt) = k - elem_ptr(ie) + 1
          tcol(nt) = p - cs%xptr(ie) + 1
          tw(nt) = cs%w(i)
        end do
      end do
      cs%xptr(ie + 1) = nx + 1
      cs%tptr(ie + 1) = nt + 1
      cs%max_x = max(cs%max_x, m)
    end do
    cs%xdof = xdof(1:nx)
    cs%xeq = eq(cs%xdof)
    cs%trow = trow(1:nt)
    cs%tcol = tcol(1:nt)
    cs%tw = tw(1:nt)
  end subroutine constraints_extend

  !> K_x = T^T K T of element ie (n element dofs, m = its extended dofs); the slave rows of T from cs%t*, the others
  !> the identity.
  pure subroutine constraints_transform(cs, ie, ke, m, kx)
    type(constraint_set_t), intent(in) :: cs  !< constraints
    integer, intent(in) :: ie                 !< element
    real(dp), intent(in) :: ke(:, :)          !< (n, n) element matrix
    integer, intent(out) :: m                 !< extended size
    real(dp), intent(out) :: kx(:, :)         !< (>= m, >= m) transformed matrix
    real(dp), allocatable :: t(:, :)
    integer :: n, k, j
    n = size(ke, 1)
    m = cs%xptr(ie + 1) - cs%xptr(ie)
    allocate (t(n, m))
    t = 0.0_dp
    do k = 1, n
      t(k, k) = 1.0_dp
    end do
    do j = cs%tptr(ie), cs%tptr(ie + 1) - 1
      t(cs%trow(j), cs%trow(j)) = 0.0_dp
    end do
    do j = cs%tptr(ie), cs%tptr(ie + 1) - 1
      t(cs%trow(j), cs%tcol(j)) = t(cs%trow(j), cs%tcol(j)) + cs%tw(j)
    end do
    kx(1:m, 1:m) = matmul(transpose(t), matmul(ke, t))
  end subroutine constraints_transform

  !> r(eq(master)) += w R(slave): the residual R (all dofs) of each slave goes to its free masters.
  pure subroutine constraints_residual(cs, eq, res, r)
    type(constraint_set_t), intent(in) :: cs  !< constraints
    integer, intent(in) :: eq(:)              !< equation numbers
    real(dp), intent(in) :: res(:)            !< (ndof) residual forces
    real(dp), intent(inout) :: r(:)           !< (neq) reduced residual
    integer :: c, i
    do c = 1, cs%n
      do i = cs%ptr(c), cs%ptr(c + 1) - 1
        if (eq(cs%mdof(i)) > 0) r(eq(cs%mdof(i))) = r(eq(cs%mdof(i))) + cs%w(i) * res(cs%slave(c))
      end do
    end do
  end subroutine constraints_residual

  !> u(slave) = sum w u(master).
  pure subroutine constraints_apply(cs, u)
    type(constraint_set_t), intent(in) :: cs  !< constraints
    real(dp), intent(inout) :: u(:)           !< displacements
    integer :: c
    do c = 1, cs%n
      u(cs%slave(c)) = dot_product(cs%w(cs%ptr(c):cs%ptr(c + 1) - 1), u(cs%mdof(cs%ptr(c):cs%ptr(c + 1) - 1)))
    end do
  end subroutine constraints_apply

  pure subroutine grow_i(a, n)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    integer, allocatable :: t(:)
    if (n <= size(a)) return
    allocate (t(2 * n))
    t(1:size(a)) = a
    call move_alloc(t, a)
  end subroutine grow_i

  pure subroutine grow_r(a, n)
    real(dp), allocatable, intent(inout) :: a(:)
    integer, intent(in) :: n
    real(dp), allocatable :: t(:)
    if (n <= size(a)) return
    allocate (t(2 * n))
    t(1:size(a)) = a
    call move_alloc(t, a)
  end subroutine grow_r

end module linear_constraints
