!> The last pass of the deck reader for the couplings, rotational dofs, equations over node sets, element removal
!> and reactivation, time points and rotational body loads (called by deck_finish once ids and sets are resolved):
!> each definition resolved to indices and checked against what Abaqus defines (docs/host.md), errors naming the
!> line that defines the offending item.
module deck_finish_extras
  use ldfcz_kinds, only: dp
  use ldfcz_sorting, only: sort_real
  use model_types, only: model_t, coupling_t, boundary_t, source_pos_t, model_dof, model_label_text, &
    dload_centrif, dload_rota, init_stress, orientation_axes, model_find_orientation
  use element_catalog, only: element_is_axisymmetric
  use deck_lists, only: itoa, unique
  use deck_surface_nodes, only: surface_face_nodes
  use deck_context, only: deck_context_t, ctx_fail_pos, ctx_warn_pos
  implicit none
  private
  public :: finish_extras

  real(dp), parameter :: time_tol = 1.0e-12_dp  !< relative tolerance of a time point against the step's period

contains

  !> Resolve and check the definitions of this module's keywords (ctx%stat = 2 with a message on error).
  subroutine finish_extras(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    call resolve_couplings(ctx)
    if (ctx%stat == 0) call number_rotations(ctx)
    if (ctx%stat == 0) call check_rotation_dofs(ctx)
    if (ctx%stat == 0) call pair_equation_sets(ctx)
    if (ctx%stat == 0) call resolve_model_changes(ctx)
    if (ctx%stat == 0) call resolve_time_points(ctx%model)
    if (ctx%stat == 0) call check_rotational_loads(ctx)
  end subroutine finish_extras

  !> Every coupling: its type given, the reference node (a node, or a node set of one node), the coupling nodes (the
  !> nodes of the surface's faces within the influence radius of the reference node), none of them with a
  !> *TRANSFORM.
  subroutine resolve_couplings(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, id
    integer, allocatable :: nodes(:)
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do k = 1, model%ncoupling
        associate (c => model%couplings(k))
          pos = c%pos
          if (c%kind_pos%line == 0) then
            call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': *KINEMATIC or *DISTRIBUTING must follow')
            return
          end if
          if (c%ref_set > 0) then
            nodes = model%nsets(c%ref_set)%nodes
            if (size(nodes) /= 1) then
              call ctx_fail_pos(ctx, pos, 'REF NODE: node set '//trim(model%nsets(c%ref_set)%name)//' holds '// &
                itoa(size(nodes))//' nodes; one reference node is required')
              return
            end if
            c%ref = nodes(1)
          else
            id = -c%ref
            c%ref = 0
            if (id <= size(model%node_index)) c%ref = model%node_index(id)
            if (c%ref == 0) then
              call ctx_fail_pos(ctx, pos, 'REF NODE: undefined node '//model_label_text(model, id, .true.))
              return
            end if
          end if
          call coupling_nodes(ctx, c)
          if (ctx%stat /= 0) return
          if (len_trim(c%orientation) > 0) call coupling_orientation(ctx, c)
          if (ctx%stat /= 0) return
          if (allocated(model%node_transform)) then
            if (model%node_transform(c%ref) /= 0 .or. any(model%node_transform(c%nodes) /= 0)) then
              call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': a node with a *TRANSFORM (the coupling '// &
                'constrains global components)')
              return
            end if
          end if
        end associate
      end do
    end associate
  end subroutine resolve_couplings

  !> The ORIENTATION of coupling c (Keywords Reference *COUPLING: the local system of the constrained dofs):
  !> resolved to its index; 3D only. Kinematic: the local directions are taken at each coupling node (Analysis
  !> User's Guide "Kinematic coupling constraints": local systems "at the constrained nodes"); a node on the axis of
  !> a cylindrical system keeps its axial dof only (a warning; inferred). Distributing: every translation is
  !> constrained whatever the system; constrained rotations about some local axes only (the others released) are
  !> supported where those axes are global ones (taken at the reference node), and become the global rotational
  !> dofs.
  subroutine coupling_orientation(ctx, c)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(coupling_t), intent(inout) :: c        !< the coupling (an element of ctx%model%couplings)
    type(source_pos_t) :: pos
    real(dp) :: t(3, 3)
    logical :: ok, rot(3)
    integer :: k, j
    pos = c%pos
    associate (model => ctx%model)
      c%iorient = model_find_orientation(model, c%orientation)
      if (c%iorient == 0) then
        call ctx_fail_pos(ctx, pos, 'ORIENTATION: undefined orientation '//trim(c%orientation))
        return
      end if
      if (model%ndim /= 3) then
        call ctx_fail_pos(ctx, pos, 'ORIENTATION (constrained dofs in local directions) is supported in 3D '// &
          'models only')
        return
      end if
      if (c%kinematic) then
        do k = 1, size(c%nodes)
          call orientation_axes(model%orientations(c%iorient), model%x(:, c%nodes(k)), t, ok)
          if (ok) cycle
          if (model%orientations(c%iorient)%system /= 2) then
            call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': orientation '//trim(c%orientation)// &
              ' defines no local directions (coinciding points)')
            return
          end if
          ! on the axis of a cylindrical system: local 1 and 2 undefined, the node keeps the axial dof 3 only
          if (any(c%dofs(1:2))) call ctx_warn_pos(ctx, pos, 'coupling '//trim(c%name)//': coupling node '// &
            model_label_text(model, model%node_id(c%nodes(k)), .true.)//' lies on the axis of cylindrical '// &
            'orientation '//trim(c%orientation)//', which defines no radial or tangential direction there: its '// &
            'local dofs 1, 2 are not constrained')
        end do
        return
      end if
      if (all(c%dofs(4:6)) .or. .not. any(c%dofs(4:6))) return
      call orientation_axes(model%orientations(c%iorient), model%x(:, c%ref), t, ok)
      rot = .false.
      do k = 1, 3
        if (.not. c%dofs(3 + k)) cycle
        j = maxloc(abs(t(:, k)), 1)
        if (.not. ok .or. abs(t(j, k)) < 1.0_dp - 1.0e-9_dp) then
          pos = c%kind_pos
          call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': the rotation about local axis '//itoa(k)// &
            ' of orientation '//trim(c%orientation)//' is constrained and others released, but that axis is '// &
            'not a global axis (not supported: constrain all rotations, or give the axes globally)')
          return
        end if
        rot(j) = .true.
      end do
      c%dofs(4:6) = rot
    end associate
  end subroutine coupling_orientation

  !> The coupling nodes of coupling c: the nodes of its surface's faces within its influence radius.
  subroutine coupling_nodes(ctx, c)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(coupling_t), intent(inout) :: c        !< the coupling (an element of ctx%model%couplings)
    integer :: j
    integer, allocatable :: nodes(:)
    type(source_pos_t) :: pos
    pos = c%pos
    call surface_face_nodes(ctx, c%surface, pos, 'couplings need continuum element faces', nodes)
    if (ctx%stat /= 0) return
    associate (model => ctx%model)
      if (c%radius > 0.0_dp) nodes = pack(nodes, [(norm2(model%x(:, nodes(j)) - model%x(:, c%ref)) <= c%radius, &
        j = 1, size(nodes))])
      if (size(nodes) == 0) then
        call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': no coupling node (no surface node within the '// &
          'influence radius)')
        return
      end if
      if (any(nodes == c%ref)) then
        call ctx_fail_pos(ctx, pos, 'coupling '//trim(c%name)//': the reference node is a node of the surface')
        return
      end if
      c%nodes = nodes
    end associate
  end subroutine coupling_nodes

  !> The rotational dofs of the reference nodes (model%node_rot, model%nrot): a kinematic coupling always moves its
  !> coupling nodes with the reference node's rotation; a distributing one couples the rotations when its dofs
  !> include them (3D: any of 4..6, the others released; 2D: 6).
  subroutine number_rotations(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, nr
    associate (model => ctx%model)
      allocate (model%node_rot(model%nnode))
      model%node_rot = 0
      model%nrot = 0
      nr = merge(3, 1, model%ndim == 3)
      do k = 1, model%ncoupling
        associate (c => model%couplings(k))
          if (.not. c%kinematic) then
            if (model%ndim == 2 .and. .not. c%dofs(6)) cycle
            if (model%ndim == 3 .and. .not. any(c%dofs(4:6))) cycle
          end if
          if (model%node_rot(c%ref) /= 0) cycle
          model%node_rot(c%ref) = model%nrot + 1
          model%nrot = model%nrot + nr
        end associate
      end do
    end associate
  end subroutine number_rotations

  !> Boundaries and concentrated loads on rotational dofs (4..6): they exist only at the reference node of a
  !> coupling that has rotations. A boundary on them elsewhere constrains nothing (a warning, as Abaqus warns for
  !> inactive dofs; the rotations of a type such as ENCASTRE silently); a moment elsewhere would be lost: an error.
  subroutine check_rotation_dofs(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: is, k, j
    associate (model => ctx%model)
      do k = 1, model%n_initial_bc
        call check_bc(model%initial_bcs(k))
      end do
      do is = 1, model%nstep
        do k = 1, model%steps(is)%nbc
          call check_bc(model%steps(is)%bcs(k))
        end do
        do k = 1, model%steps(is)%ncload
          associate (cl => model%steps(is)%cloads(k))
            if (cl%dof < 4) cycle
            if (any([(model_dof(model, cl%nodes(j), cl%dof) == 0, j = 1, size(cl%nodes))])) then
              call ctx_fail_pos(ctx, cl%pos, 'dof '//itoa(cl%dof)//' (a moment) exists only at the reference node '// &
                'of a *COUPLING that couples rotations (ldfcz''s continuum nodes have translations only)')
              return
            end if
          end associate
        end do
      end do
    end associate

  contains

    subroutine check_bc(bc)
      type(boundary_t), intent(in) :: bc
      integer :: a, d
      if (bc%last_dof < 4) return
      do a = 1, size(bc%nodes)
        do d = max(4, bc%first_dof), bc%last_dof
          if (model_dof(ctx%model, bc%nodes(a), d) /= 0) cycle
          if (ctx%model%ndim == 2 .and. d < 6) cycle
          call ctx_warn_pos(ctx, bc%pos, 'dof '//itoa(d)//' (a rotation) does not exist at node '// &
            model_label_text(ctx%model, ctx%model%node_id(bc%nodes(a)), .true.)//' (rotations exist only at the '// &
            'reference node of a *COUPLING that couples them): ignored there')
          return
        end do
      end do
    end subroutine check_bc

  end subroutine check_rotation_dofs

  !> *EQUATION over node sets, as Abaqus pairs them: the members of sets in the set's order (sorted by label, or as
  !> given for an UNSORTED set), one equation per member; a single node (or a set of one node) in a later term is
  !> used in every equation; sets of other sizes, or a set after a single first node, are errors.
  subroutine pair_equation_sets(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, t, n1, j
    integer, allocatable :: lab(:)
    associate (model => ctx%model)
      do k = 1, model%nequation
        associate (eqn => model%equations(k))
          if (allocated(eqn%term_set)) then
            do t = 1, size(eqn%terms)
              if (eqn%term_set(t) == 0) cycle
              if (model%nsets(eqn%term_set(t))%unsorted) then
                eqn%terms(t)%nodes = first_occurrences(eqn%terms(t)%nodes)
              else
                lab = model%node_id(model%nsets(eqn%term_set(t))%nodes)
                call unique(lab)
                eqn%terms(t)%nodes = model%node_index(lab)
              end if
            end do
          end if
          n1 = size(eqn%terms(1)%nodes)
          do t = 2, size(eqn%terms)
            if (size(eqn%terms(t)%nodes) == n1) cycle
            if (size(eqn%terms(t)%nodes) == 1) then
              eqn%terms(t)%nodes = [(eqn%terms(t)%nodes(1), j = 1, n1)]
              cycle
            end if
            if (n1 == 1) then
              call ctx_fail_pos(ctx, eqn%terms(t)%pos, 'term '//itoa(t)//' is a node set of '// &
                itoa(size(eqn%terms(t)%nodes))//' nodes after a single first node (Abaqus: when the first term is '// &
                'a single node, the others must be single nodes)')
            else
              call ctx_fail_pos(ctx, eqn%terms(t)%pos, 'term '//itoa(t)//' is a node set of '// &
                itoa(size(eqn%terms(t)%nodes))//' nodes, the first term''s has '//itoa(n1)//' (sets are paired '// &
                'member by member: equal sizes, or a single node used in every equation)')
            end if
            return
          end do
        end associate
      end do
    end associate
  end subroutine pair_equation_sets

  !> The list without the repetitions of a member (the first occurrence kept).
  pure function first_occurrences(a) result(b)
    integer, intent(in) :: a(:)
    integer, allocatable :: b(:)
    integer :: i
    allocate (b(0))
    do i = 1, size(a)
      if (.not. any(b == a(i))) b = [b, a(i)]
    end do
  end function first_occurrences

  !> *MODEL CHANGE: element labels and sets to indices; followed through the steps, so that an element removed twice
  !> or added while active is a warning and dropped. An element removed in the first step may not carry an initial
  !> stress (the forces it would leave behind are those of the previous step's end, which the first step has not).
  subroutine resolve_model_changes(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: is, k, j, id, ie
    logical, allocatable :: active(:), keep(:)
    integer, allocatable :: el(:)
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      allocate (active(model%nelem))
      active = .true.
      do is = 1, model%nstep
        do k = 1, model%steps(is)%nchange
          associate (mc => model%steps(is)%changes(k))
            pos = mc%pos
            allocate (el(0))
            do j = 1, size(mc%elems)
              id = -mc%elems(j)
              ie = 0
              if (id <= size(model%elem_index)) ie = model%elem_index(id)
              if (ie == 0) then
                call ctx_fail_pos(ctx, pos, 'undefined element '//model_label_text(model, id, .false.))
                return
              end if
              el = [el, ie]
            end do
            do j = 1, size(mc%elsets)
              el = [el, model%elsets(mc%elsets(j))%elems]
            end do
            call unique(el)
            keep = active(el) .eqv. mc%remove
            if (.not. all(keep)) call ctx_warn_pos(ctx, pos, itoa(count(.not. keep))//' element(s) '// &
              trim(merge('removed already', 'active already ', mc%remove))//' (e.g. '// &
              model_label_text(model, model%elem_id(el(findloc(keep, .false., 1))), .false.)// &
              '): nothing to do for them')
            el = pack(el, keep)
            active(el) = .not. mc%remove
            if (is == 1 .and. mc%remove) then
              if (initial_stress_on(model, el)) then
                call ctx_fail_pos(ctx, pos, 'an element with an initial stress removed in the first step (the '// &
                  'forces it leaves behind are not computed)')
                return
              end if
            end if
            call move_alloc(el, mc%elems)
          end associate
        end do
      end do
    end associate
  end subroutine resolve_model_changes

  !> True when an element of el has *INITIAL CONDITIONS, TYPE=STRESS.
  pure logical function initial_stress_on(model, el) result(yes)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: el(:)        !< element indices
    integer :: k, j
    yes = .false.
    do k = 1, model%ninit
      if (model%inits(k)%kind /= init_stress) cycle
      do j = 1, size(model%inits(k)%elems)
        if (any(el == model%inits(k)%elems(j))) yes = .true.
      end do
    end do
  end function initial_stress_on

  !> The time points in effect in each step: a field request's (carried to the next steps with the request, as
  !> Abaqus carries output requests) and a history request's (likewise); the increments end on their union within
  !> the step (cut_points).
  pure subroutine resolve_time_points(model)
    type(model_t), intent(inout) :: model  !< the model
    integer :: is
    real(dp), allocatable :: t(:)
    do is = 1, model%nstep
      associate (st => model%steps(is))
        if (is > 1) then
          associate (prev => model%steps(is - 1))
            if (.not. st%field_given .and. prev%field_output .and. allocated(prev%field_points)) &
              st%field_points = prev%field_points
            if (.not. st%history_given .and. allocated(prev%history_points)) st%history_points = prev%history_points
          end associate
        end if
        allocate (t(0))
        if (allocated(st%field_points)) t = [t, st%field_points]
        if (allocated(st%history_points)) t = [t, st%history_points]
        t = pack(t, t > time_tol * st%period .and. t < st%period * (1.0_dp - time_tol))
        call sort_unique(t)
        if (size(t) > 0) then
          st%cut_points = t
        else if (allocated(st%cut_points)) then
          deallocate (st%cut_points)
        end if
        deallocate (t)
      end associate
    end do
  end subroutine resolve_time_points

  !> Sort ascending and drop repeated values.
  pure subroutine sort_unique(t)
    real(dp), allocatable, intent(inout) :: t(:)
    integer :: i, j
    call sort_real(t)
    j = 0
    do i = 1, size(t)
      if (j > 0) then
        if (t(i) == t(j)) cycle
      end if
      j = j + 1
      t(j) = t(i)
    end do
    t = t(1:j)
  end subroutine sort_unique

  !> CENTRIF and ROTA: the axis. 3D: a direction is required; plane elements: the axis is normal to the plane
  !> (through the point); axisymmetric elements: the symmetry axis (CENTRIF only: a rotary acceleration about it
  !> would leave the plane of the model).
  subroutine check_rotational_loads(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: is, k, j
    logical :: axi
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do is = 1, model%nstep
        do k = 1, model%steps(is)%ndload
          associate (dl => model%steps(is)%dloads(k))
            if (dl%kind /= dload_centrif .and. dl%kind /= dload_rota) cycle
            pos = dl%pos
            if (model%ndim == 3) then
              if (norm2(dl%dir) == 0.0_dp) call ctx_fail_pos(ctx, pos, 'the axis direction is required (fields '// &
                '7-9: after the magnitude, a point on the axis and the direction)')
              if (ctx%stat /= 0) return
              cycle
            end if
            if (size(dl%elems) == 0) cycle
            axi = element_is_axisymmetric(model%elem_kind(dl%elems(1)))
            if (.not. all([(element_is_axisymmetric(model%elem_kind(dl%elems(j))) .eqv. axi, j = 1, size(dl%elems))])) &
                then
              call ctx_fail_pos(ctx, pos, 'axisymmetric and plane elements in one CENTRIF/ROTA load')
              return
            end if
            if (axi) then
              if (dl%kind == dload_rota) then
                call ctx_fail_pos(ctx, pos, 'ROTA on axisymmetric elements (a rotary acceleration about the '// &
                  'symmetry axis acts out of the plane of the model)')
                return
              end if
              if (abs(dl%dir(1)) + abs(dl%dir(3)) > 1.0e-12_dp .or. dl%point(1) /= 0.0_dp) then
                call ctx_fail_pos(ctx, pos, 'axisymmetric elements turn about their symmetry axis (the global 2 '// &
                  'axis through the origin): give that axis or none')
                return
              end if
              dl%dir = [0.0_dp, 1.0_dp, 0.0_dp]
              dl%point = 0.0_dp
            else
              if (abs(dl%dir(1)) + abs(dl%dir(2)) > 1.0e-12_dp) then
                call ctx_fail_pos(ctx, pos, 'in a plane model the axis is normal to the plane (direction 0, 0, 1, '// &
                  'or none)')
                return
              end if
              if (norm2(dl%dir) == 0.0_dp) dl%dir = [0.0_dp, 0.0_dp, 1.0_dp]
            end if
          end associate
        end do
      end do
    end associate

  end subroutine check_rotational_loads

end module deck_finish_extras
