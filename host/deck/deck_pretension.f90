!> *PRE-TENSION SECTION of the deck reader (Abaqus Keywords Reference "*PRE-TENSION SECTION"; Analysis User's
!> Guide "Prescribed assembly loads"): an element-based surface that cuts a fastener of continuum elements, and the
!> pre-tension node whose dof 1 is the relative displacement of the two sides of the cut along the section's normal
!> (its conjugate force the force across the section). finish_pretensions resolves each section after the
!> surfaces: the pre-tension node (free: no element holds it), the section's nodes, the normal (the data line's, or
!> the mean outward normal of the surface's faces) and the elements on the surface's side that move with the
!> relative displacement (docs/host.md, "Pre-tension sections"; the analysis side: host/analysis/pretension_sections).
module deck_pretension
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: pretension_t, model_t, boundary_t, model_label_text
  use element_catalog, only: element_face_nodes
  use deck_lists, only: itoa
  use deck_surface_nodes, only: surface_face_nodes
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_surface, &
    ctx_fail, ctx_fail_pos, ctx_pos, ctx_allow_params, ctx_required, ctx_split, ctx_get_real, ctx_note_pos, ctx_warn_pos
  implicit none
  private
  public :: read_pretension_section, finish_pretensions

contains

  !> *PRE-TENSION SECTION, SURFACE=, NODE= (a node, or a node set of one node)[, FOLLOWER=NO]; an optional data
  !> line: the normal's components. ELEMENT= (a truss or beam fastener) and FOLLOWER=YES are refused.
  subroutine read_pretension_section(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t) :: p
    type(pretension_t), allocatable :: tmp(:)
    character(len=:), allocatable :: v
    call ctx_allow_params(ctx, [character(len=8) :: 'SURFACE', 'NODE', 'ELEMENT', 'FOLLOWER'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'ELEMENT')) then
      call ctx_fail(ctx, ctx%ir, 'ELEMENT= (a fastener of truss or beam elements) is not supported: ldfcz has no '// &
        'truss or beam elements (SURFACE= cuts a fastener of continuum elements)')
      return
    end if
    if (deck_has_param(ctx%params, 'FOLLOWER')) then
      if (deck_normalize(deck_param_value(ctx%params, 'FOLLOWER')) /= 'NO') then
        call ctx_fail(ctx, ctx%ir, 'FOLLOWER=YES (a normal that turns with the fastener) is not supported: the '// &
          'normal is fixed (FOLLOWER=NO, Abaqus'' default)')
        return
      end if
    end if
    v = ctx_required(ctx, 'SURFACE')
    if (ctx%stat /= 0) return
    p%surface = ctx_find_surface(ctx, v)
    if (p%surface == 0) then
      call ctx_fail(ctx, ctx%ir, 'SURFACE: undefined surface '//deck_normalize(v)//' (an element-based *SURFACE '// &
        'defined before)')
      return
    end if
    call read_node_parameter(ctx, p)
    if (ctx%stat /= 0) return
    call read_normal(ctx, p)
    if (ctx%stat /= 0) return
    p%pos = ctx_pos(ctx, ctx%ir)
    associate (m => ctx%model)
      if (.not. allocated(m%pretensions)) allocate (m%pretensions(2))
      if (m%npretension == size(m%pretensions)) then
        allocate (tmp(2 * m%npretension))
        tmp(1:m%npretension) = m%pretensions(1:m%npretension)
        call move_alloc(tmp, m%pretensions)
      end if
      m%npretension = m%npretension + 1
      m%pretensions(m%npretension) = p
    end associate
  end subroutine read_pretension_section

  !> NODE=: a node label (kept negative until finish_pretensions) or a node set.
  subroutine read_node_parameter(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(inout) :: p      !< the section
    character(len=:), allocatable :: v
    integer :: id
    v = ctx_required(ctx, 'NODE')
    if (ctx%stat /= 0) return
    if (ctx_is_label(ctx, v)) then
      if (.not. ctx_get_label(ctx, ctx%ir, v, .true., id)) return
      if (id < 1) then
        call ctx_fail(ctx, ctx%ir, 'NODE: node ids must be positive, got '//itoa(id))
        return
      end if
      p%node = -id
    else
      p%node_set = ctx_find_nset(ctx, v)
      if (p%node_set == 0) call ctx_fail(ctx, ctx%ir, 'NODE: undefined node set '//deck_normalize(v))
    end if
  end subroutine read_node_parameter

  !> The optional data line: the normal's first, second (and third) component; a zero vector is an error.
  subroutine read_normal(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(inout) :: p      !< the section
    character(len=flen), allocatable :: f(:)
    integer :: n, j
    if (ctx%ir_next == ctx%ir + 1) return
    if (ctx%ir_next > ctx%ir + 2) then
      call ctx_fail(ctx, ctx%ir + 2, 'one data line at most (the normal''s components)')
      return
    end if
    call ctx_split(ctx, ctx%ir + 1, f, n)
    if (n > 3) then
      if (any(len_trim(f(4:n)) > 0)) then
        call ctx_fail(ctx, ctx%ir + 1, 'expected: the normal''s components n1, n2[, n3]')
        return
      end if
    end if
    do j = 1, min(n, 3)
      if (len_trim(f(j)) == 0) cycle
      if (.not. ctx_get_real(ctx, ctx%ir + 1, f(j), p%normal(j))) return
    end do
    if (.not. norm2(p%normal) > 0.0_dp) then
      call ctx_fail(ctx, ctx%ir + 1, 'the normal is the zero vector')
      return
    end if
    p%normal_given = .true.
  end subroutine read_normal

  !> Every section: its pre-tension node (free, one section each), its nodes (in no other section, without a
  !> *TRANSFORM), its normal, the elements on its side, and a check that it cuts the mesh; then the extra dofs.
  subroutine finish_pretensions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, ndof, is
    ndof = 0
    do k = 1, ctx%model%npretension
      call resolve_node(ctx, k)
      if (ctx%stat == 0) call section_nodes(ctx, ctx%model%pretensions(k))
      if (ctx%stat == 0) call check_overlap(ctx, k)
      if (ctx%stat == 0) call section_normal(ctx, ctx%model%pretensions(k))
      if (ctx%stat == 0) call section_side(ctx, ctx%model%pretensions(k))
      if (ctx%stat /= 0) return
      ctx%model%pretensions(k)%dof0 = ndof
      ndof = ndof + ctx%model%ndim * size(ctx%model%pretensions(k)%nodes)
      call note_section(ctx, ctx%model%pretensions(k))
      call warn_inactive(ctx, ctx%model%pretensions(k)%node, ctx%model%initial_bcs, ctx%model%n_initial_bc)
      do is = 1, ctx%model%nstep
        call warn_inactive(ctx, ctx%model%pretensions(k)%node, ctx%model%steps(is)%bcs, ctx%model%steps(is)%nbc)
      end do
    end do
    ctx%model%npret_dof = ndof
  end subroutine finish_pretensions

  !> A boundary on dofs 2.. of a pre-tension node (it has dof 1 only) constrains nothing: warned, as Abaqus warns
  !> for inactive dofs.
  subroutine warn_inactive(ctx, node, bcs, nbc)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: node                 !< the pre-tension node
    type(boundary_t), intent(in) :: bcs(:)      !< boundaries
    integer, intent(in) :: nbc                  !< in use
    integer :: j
    do j = 1, nbc
      if (bcs(j)%last_dof < 2 .or. all(bcs(j)%nodes /= node)) cycle
      call ctx_warn_pos(ctx, bcs(j)%pos, 'dofs 2.. of pre-tension node '//model_label_text(ctx%model, &
        ctx%model%node_id(node), .true.)//' are not active (it has dof 1 only): constrained nothing there')
    end do
  end subroutine warn_inactive

  !> JOB.log's note of a section: its nodes, normal and moving elements.
  subroutine note_section(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(in) :: p         !< the section
    character(len=16) :: b
    character(len=:), allocatable :: n
    integer :: d
    n = ''
    do d = 1, ctx%model%ndim
      write (b, '(es12.5)') p%normal(d)
      n = n//trim(adjustl(b))//merge(', ', ') ', d < ctx%model%ndim)
    end do
    call ctx_note_pos(ctx, p%pos, 'surface '//trim(ctx%model%surfaces(p%surface)%name)//': '// &
      itoa(size(p%nodes))//' nodes, normal ('//trim(n)//trim(merge(' given   ', ' computed', p%normal_given))// &
      ', '//itoa(size(p%elems))//' elements on the surface''s side; pre-tension node '// &
      model_label_text(ctx%model, ctx%model%node_id(p%node), .true.))
  end subroutine note_section

  !> Section k's pre-tension node: a node, or a node set of one node; no element may hold it ("The pre-tension
  !> node should not be attached to any element", Analysis User's Guide), and one section only.
  subroutine resolve_node(ctx, k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: k                    !< the section
    integer :: id, ie, j
    associate (model => ctx%model, p => ctx%model%pretensions(k))
      if (p%node_set > 0) then
        if (size(model%nsets(p%node_set)%nodes) /= 1) then
          call ctx_fail_pos(ctx, p%pos, 'NODE: node set '//trim(model%nsets(p%node_set)%name)//' holds '// &
            itoa(size(model%nsets(p%node_set)%nodes))//' nodes; the pre-tension node is one node')
          return
        end if
        p%node = model%nsets(p%node_set)%nodes(1)
      else
        id = -p%node
        p%node = 0
        if (id <= size(model%node_index)) p%node = model%node_index(id)
        if (p%node == 0) then
          call ctx_fail_pos(ctx, p%pos, 'NODE: undefined node '//model_label_text(model, id, .true.))
          return
        end if
      end if
      do ie = 1, model%nelem
        if (all(model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1) /= p%node)) cycle
        call ctx_fail_pos(ctx, p%pos, 'the pre-tension node '//model_label_text(model, model%node_id(p%node), &
          .true.)//' belongs to element '//model_label_text(model, model%elem_id(ie), .false.)//': it must be a '// &
          'node of no element (its dof 1 is the relative displacement of the section''s two sides)')
        return
      end do
      do j = 1, k - 1
        if (model%pretensions(j)%node /= p%node) cycle
        call ctx_fail_pos(ctx, p%pos, 'node '//model_label_text(model, model%node_id(p%node), .true.)// &
          ' is the pre-tension node of the section at '//model%pretensions(j)%pos%file//':'// &
          itoa(model%pretensions(j)%pos%line)//' already: one section per pre-tension node')
        return
      end do
    end associate
  end subroutine resolve_node

  !> The section's nodes: those of its surface's faces (continuum element faces), without repetition.
  subroutine section_nodes(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(inout) :: p      !< the section (an element of ctx%model%pretensions)
    integer, allocatable :: nodes(:)
    call surface_face_nodes(ctx, p%surface, p%pos, 'a pre-tension section is made of continuum element faces', nodes)
    if (ctx%stat /= 0) return
    if (size(nodes) == 0) then
      call ctx_fail_pos(ctx, p%pos, 'surface '//trim(ctx%model%surfaces(p%surface)%name)//' has no face')
      return
    end if
    p%nodes = nodes
  end subroutine section_nodes

  !> A node of section k in an earlier section, or with a *TRANSFORM (the constraint ties global components), is
  !> refused.
  subroutine check_overlap(ctx, k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: k                    !< the section
    integer :: j, a
    associate (model => ctx%model, p => ctx%model%pretensions(k))
      do a = 1, size(p%nodes)
        do j = 1, k - 1
          if (all(model%pretensions(j)%nodes /= p%nodes(a)) .and. model%pretensions(j)%node /= p%nodes(a)) cycle
          call ctx_fail_pos(ctx, p%pos, 'node '//model_label_text(model, model%node_id(p%nodes(a)), .true.)// &
            ' belongs to the section at '//model%pretensions(j)%pos%file//':'//itoa(model%pretensions(j)%pos%line)// &
            ' too: a node may be in one pre-tension section only')
          return
        end do
        if (.not. allocated(model%node_transform)) cycle
        if (model%node_transform(p%nodes(a)) == 0 .and. model%node_transform(p%node) == 0) cycle
        call ctx_fail_pos(ctx, p%pos, 'a node of the section or the pre-tension node has a *TRANSFORM: the '// &
          'section ties global components')
        return
      end do
    end associate
  end subroutine check_overlap

  !> The unit normal: the data line's (its in-plane part in 2D), or the mean of the faces' outward normals
  !> weighted by their areas ("Abaqus/Standard will compute an average normal", Keywords Reference).
  subroutine section_normal(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(inout) :: p      !< the section
    integer :: j
    real(dp) :: n(3)
    associate (model => ctx%model, sf => ctx%model%surfaces(p%surface))
      if (p%normal_given) then
        n = p%normal
        if (model%ndim == 2) n(3) = 0.0_dp
      else
        n = 0.0_dp
        do j = 1, size(sf%relems)
          n = n + face_area_vector(model, sf%relems(j), sf%rfaces(j))
        end do
      end if
      if (.not. norm2(n) > 1.0e-12_dp * max(1.0_dp, norm2(p%normal))) then
        call ctx_fail_pos(ctx, p%pos, 'the normal of the section is undefined (zero in the model''s plane, or the '// &
          'faces'' outward normals cancel): give it on the data line')
        return
      end if
      p%normal = n / norm2(n)
    end associate
  end subroutine section_normal

  !> Area-weighted outward normal of face f of element ie (corners only: the edge in 2D, the triangle or
  !> quadrilateral of the first 3 or 4 face nodes in 3D), turned away from the element's centre.
  function face_area_vector(model, ie, f) result(a)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie           !< element
    integer, intent(in) :: f            !< face
    real(dp) :: a(3), xf(3, 8), xc(3)
    integer :: loc(8), nfn, nc
    call element_face_nodes(model%elem_kind(ie), f, loc, nfn)
    xf(:, 1:nfn) = model%x(:, model%conn(model%conn_ptr(ie) + loc(1:nfn) - 1))
    xc = element_centre(model, ie)
    if (model%ndim == 2) then
      nc = 2
      a = [xf(2, 2) - xf(2, 1), xf(1, 1) - xf(1, 2), 0.0_dp]
    else if (nfn == 3 .or. nfn == 6) then
      nc = 3
      a = 0.5_dp * cross(xf(:, 2) - xf(:, 1), xf(:, 3) - xf(:, 1))
    else
      nc = 4
      a = 0.5_dp * cross(xf(:, 3) - xf(:, 1), xf(:, 4) - xf(:, 2))
    end if
    if (dot_product(a, sum(xf(:, 1:nc), dim=2) / nc - xc) < 0.0_dp) a = -a
  end function face_area_vector

  !> The elements that move with the relative displacement: those of the surface's faces, and every other element
  !> holding a section node whose centre lies on the same side (behind the faces' mean outward normal); each section
  !> node must also be held by an element on the other side (the surface cuts the mesh).
  subroutine section_side(ctx, p)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(pretension_t), intent(inout) :: p      !< the section
    logical :: on_node(ctx%model%nnode), moves(ctx%model%nelem), other(ctx%model%nnode)
    real(dp) :: nout(3)
    integer :: ie, a
    associate (model => ctx%model, sf => ctx%model%surfaces(p%surface))
      ! the side is the faces' outward one, whichever way a given normal points
      nout = 0.0_dp
      do a = 1, size(sf%relems)
        nout = nout + face_area_vector(model, sf%relems(a), sf%rfaces(a))
      end do
      if (.not. norm2(nout) > 0.0_dp) nout = p%normal
      do a = 1, size(sf%relems)
        if (dot_product(face_area_vector(model, sf%relems(a), sf%rfaces(a)), nout) > 0.0_dp) cycle
        call ctx_fail_pos(ctx, p%pos, 'surface '//trim(sf%name)//': face S'//itoa(sf%rfaces(a))//' of element '// &
          model_label_text(model, model%elem_id(sf%relems(a)), .false.)//' faces the other way: a pre-tension '// &
          'section is made of the faces of the elements on one side of the cut')
        return
      end do
      on_node = .false.
      on_node(p%nodes) = .true.
      moves = .false.
      moves(model%surfaces(p%surface)%relems) = .true.
      other = .false.
      do ie = 1, model%nelem
        associate (c => model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1))
          if (.not. any(on_node(c))) cycle
          a = findloc(on_node(c), .true., 1)
          if (.not. moves(ie)) moves(ie) = dot_product(nout, element_centre(model, ie) - model%x(:, c(a))) < 0.0_dp
          if (.not. moves(ie)) other(c) = .true.
        end associate
      end do
      do a = 1, size(p%nodes)
        if (other(p%nodes(a))) cycle
        call ctx_fail_pos(ctx, p%pos, 'surface '//trim(model%surfaces(p%surface)%name)//' does not cut the mesh: '// &
          'node '//model_label_text(model, model%node_id(p%nodes(a)), .true.)//' has no element on the other side '// &
          'of the section (the section cuts the fastener into two parts)')
        return
      end do
      p%elems = pack([(ie, ie = 1, model%nelem)], moves)
    end associate
  end subroutine section_side

  !> Mean of an element's node positions.
  pure function element_centre(model, ie) result(xc)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie           !< element
    real(dp) :: xc(3)
    integer :: n
    n = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
    xc = sum(model%x(:, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)), dim=2) / n
  end function element_centre

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

end module deck_pretension
