!> Mesh keywords of the deck reader: *NODE, *ELEMENT, *NSET, *ELSET. Node and element ids and set members are kept
!> as user ids (set members negative) until deck_finish resolves them to indices.
module deck_mesh
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_upper, deck_param_value, deck_has_param, deck_normalize
  use model_types, only: node_set_t, elem_set_t, etype_user, model_find_nset, model_find_elset, model_find_user_type
  use element_catalog, only: element_kind_of, element_nnode, element_ndim, element_names_text, element_hybrid_twin, &
    element_name
  use deck_lists, only: itoa, add_member, grow_int
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_warn, ctx_allow_params, ctx_required, ctx_split, ctx_get_real, &
    ctx_get_int, ctx_def_name, ctx_find_nset, ctx_find_elset, ctx_is_label, ctx_get_label, ctx_enter_instance, ctx_continued, &
    ctx_set_member
  implicit none
  private
  public :: read_node, read_element, read_set, read_system
  public :: get_nset, get_elset, grow_nodes, grow_elems

contains

  !> *NODE, NSET=: node number, x, y[, z].
  subroutine read_node(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: i, n, id, k, iset, nomit, i_omit
    character(len=flen), allocatable :: f(:)
    real(dp) :: c
    character(len=:), allocatable :: setname
    call ctx_allow_params(ctx, [character(len=8) :: 'NSET', 'SYSTEM', 'INPUT'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'SYSTEM')) then
      if (deck_upper(deck_param_value(ctx%params, 'SYSTEM')) /= 'R') then
        call ctx_fail(ctx, ctx%ir, 'only SYSTEM=R (rectangular) is supported')
        return
      end if
    end if
    if (deck_has_param(ctx%params, 'INPUT')) then
      call ctx_fail(ctx, ctx%ir, 'INPUT= on *NODE is not supported: use *INCLUDE')
      return
    end if
    iset = 0
    if (deck_has_param(ctx%params, 'NSET')) then
      setname = ctx_def_name(ctx, ctx_required(ctx, 'NSET'))
      iset = get_nset(ctx, setname)
    end if
    associate (model => ctx%model)
      nomit = 0
      do i = ctx%ir + 1, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        ! node number, up to 3 coordinates (omitted ones are 0), up to 3 direction cosines of a normal (used by
        ! elements with rotational dofs only, which ldfcz does not have: read and checked, without effect)
        if (n > 7) then
          call ctx_fail(ctx, i, 'expected: node number[, x[, y[, z[, normal n1, n2, n3]]]]')
          return
        end if
        if (n == 1 .or. any(len_trim(f(2:min(n, 4))) == 0)) then
          nomit = nomit + 1
          if (nomit == 1) i_omit = i
        end if
        if (.not. ctx_get_int(ctx, i, f(1), id)) return
        if (id <= 0) then
          call ctx_fail(ctx, i, 'node numbers must be positive')
          return
        end if
        if (id > huge(id) - ctx%node_off) then
          call ctx_fail(ctx, i, 'node number too large')
          return
        end if
        id = id + ctx%node_off
        ctx%top_node = max(ctx%top_node, id)
        if (model%nnode == size(model%node_id)) call grow_nodes(ctx)
        model%nnode = model%nnode + 1
        model%node_id(model%nnode) = id
        ctx%node_rec(model%nnode) = i
        model%x(:, model%nnode) = 0.0_dp
        do k = 2, n
          if (len_trim(f(k)) == 0) cycle
          if (.not. ctx_get_real(ctx, i, f(k), c)) return
          if (k <= 4) model%x(k - 1, model%nnode) = c
        end do
        ! *SYSTEM: local coordinates to the scope's
        if (ctx%system_on) model%x(:, model%nnode) = matmul(ctx%system_r, model%x(:, model%nnode)) + ctx%system_c
        ! a part's node placed by its instance (translation, then rotation)
        if (ctx%placed) model%x(:, model%nnode) = matmul(ctx%place_r, model%x(:, model%nnode)) + ctx%place_c
        if (iset > 0) call ctx_set_member(ctx, .true., iset, -id, i)
      end do
    end associate
    if (nomit > 0) call ctx_warn(ctx, i_omit, itoa(nomit)//' node line(s) of this block omit coordinates '// &
      '(an empty field, or the node number alone): taken as 0, as Abaqus takes omitted numeric data')
  end subroutine read_node

  !> *SYSTEM: the coordinates of the following *NODE data lines (of this part or of the model) are given in a local
  !> rectangular system: one data line with its origin a[, a point b on local x and a point c in the local x-y
  !> plane]. Only a: a translation. No data line: back to the global system.
  subroutine read_system(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    real(dp) :: v(9), e1(3), e2(3), e3(3)
    integer :: n, k
    call ctx_allow_params(ctx, [character(len=1) :: ' '])  ! no parameters
    if (ctx%stat /= 0) return
    if (ctx%ir_next == ctx%ir + 1) then
      ctx%system_on = .false.
      return
    end if
    if (ctx%ir_next - ctx%ir - 1 > 1) then
      call ctx_fail(ctx, ctx%ir, 'one data line expected: a1, a2, a3[, b1, b2, b3, c1, c2, c3]')
      return
    end if
    call ctx_split(ctx, ctx%ir + 1, f, n)
    if (n /= 3 .and. n /= 9) then
      call ctx_fail(ctx, ctx%ir + 1, 'expected the origin a (3 coordinates) or a, b, c (9): a point b on local x '// &
        'without c is not supported')
      return
    end if
    v = 0.0_dp
    do k = 1, n
      if (len_trim(f(k)) == 0) cycle
      if (.not. ctx_get_real(ctx, ctx%ir + 1, f(k), v(k))) return
    end do
    ctx%system_r = 0.0_dp
    do k = 1, 3
      ctx%system_r(k, k) = 1.0_dp
    end do
    ctx%system_c = v(1:3)
    if (n == 9) then
      e1 = v(4:6) - v(1:3)
      e3 = [e1(2) * (v(9) - v(3)) - e1(3) * (v(8) - v(2)), e1(3) * (v(7) - v(1)) - e1(1) * (v(9) - v(3)), &
        e1(1) * (v(8) - v(2)) - e1(2) * (v(7) - v(1))]
      if (norm2(e1) <= 1.0e-12_dp * max(1.0_dp, norm2(v)) .or. &
          norm2(e3) <= 1.0e-12_dp * max(1.0_dp, norm2(v))**2) then
        call ctx_fail(ctx, ctx%ir + 1, 'the points a, b, c do not define a system (coinciding or on one line)')
        return
      end if
      e1 = e1 / norm2(e1)
      e3 = e3 / norm2(e3)
      e2 = [e3(2) * e1(3) - e3(3) * e1(2), e3(3) * e1(1) - e3(1) * e1(3), e3(1) * e1(2) - e3(2) * e1(1)]
      ctx%system_r(:, 1) = e1
      ctx%system_r(:, 2) = e2
      ctx%system_r(:, 3) = e3
    end if
    ctx%system_on = .true.
  end subroutine read_system

  !> *ELEMENT, TYPE=, ELSET=: element number and its nodes (a continuum type of the element catalogue or a user
  !> type Un defined before).
  subroutine read_element(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: tname, setname
    integer :: kind, nn, iu, i, n, k, id, iset, node, m
    character(len=flen), allocatable :: f(:), g(:)
    call ctx_allow_params(ctx, [character(len=8) :: 'TYPE', 'ELSET'])
    if (ctx%stat /= 0) return
    tname = deck_normalize(ctx_required(ctx, 'TYPE'))
    if (ctx%stat /= 0) return
    iu = 0
    kind = element_kind_of(tname)
    if (kind == 0 .and. is_hybrid_name(tname)) then
      ! a hybrid name whose type has a constant element dilatation: read as that type (element_hybrid_twin)
      kind = element_hybrid_twin(tname)
      if (kind > 0) call ctx_warn(ctx, ctx%ir, 'hybrid type '//tname//' read as '//trim(element_name(kind))// &
        ', whose volumetric strain is constant over the element: the same equations as a constant-pressure hybrid '// &
        'element for a linear elastic material, nearly the same otherwise (no independent pressure: an exactly '// &
        'incompressible material is not possible; docs/elements.md)')
    end if
    if (kind > 0) then
      nn = element_nnode(kind)
      call set_dim(ctx, element_ndim(kind))
    else
      iu = model_find_user_type(ctx%model, tname)
      if (iu == 0) then
        if (tname(1:1) == 'U') then
          call ctx_fail(ctx, ctx%ir, 'user element type '//tname//' not defined by an earlier *USER ELEMENT')
        else if (tname == 'COH3D8') then
          ! Abaqus' cohesive elements need its built-in traction-separation laws: the LDF cohesive zone is the
          ! user element with the same connectivity (docs/uel.md)
          call ctx_fail(ctx, ctx%ir, 'element type COH3D8 (*COHESIVE SECTION, Abaqus traction-separation laws) '// &
            'is not supported: use the LDF cohesive user element, same 8 nodes: '// &
            '"*USER ELEMENT, TYPE=U1, NODES=8, COORDINATES=3, PROPERTIES=3, I PROPERTIES=2, VARIABLES=16, UNSYMM" '// &
            'and "*ELEMENT, TYPE=U1, ELSET=..." with *UEL PROPERTY (docs/uel.md)')
        else if (tname == 'COH2D4') then
          call ctx_fail(ctx, ctx%ir, 'element type COH2D4 (*COHESIVE SECTION, Abaqus traction-separation laws) '// &
            'is not supported: use the LDF cohesive user element, same 4 nodes: '// &
            '"*USER ELEMENT, TYPE=U2, NODES=4, COORDINATES=2, PROPERTIES=3, I PROPERTIES=2, VARIABLES=8, UNSYMM" '// &
            'and "*ELEMENT, TYPE=U2, ELSET=..." with *UEL PROPERTY (docs/uel.md)')
        else if (is_hybrid_name(tname)) then
          ! hybrid (mixed u-p) types are not implemented: the F-bar / B-bar elements are the route for nearly
          ! incompressible materials (docs/elements.md)
          call ctx_fail(ctx, ctx%ir, 'hybrid element type '//tname//' is not supported (the hybrid names read '// &
            'are those of the constant-dilatation types: C3D8H, C3D8RH, CPE4H, CPE4RH, CAX4H, CAX4RH): for nearly '// &
            'incompressible materials use C3D8, CPE4 or CAX4 (F-bar under NLGEOM, B-bar without: no volumetric '// &
            'locking; docs/elements.md)')
        else
          call ctx_fail(ctx, ctx%ir, 'element type '//tname//' not supported ('//element_names_text()// &
            ' and user types Un; docs/elements.md)')
        end if
        return
      end if
      kind = etype_user
      nn = ctx%model%utypes(iu)%nnode
      call set_dim(ctx, ctx%model%utypes(iu)%mcrd)
    end if
    if (ctx%stat /= 0) return
    iset = 0
    if (deck_has_param(ctx%params, 'ELSET')) then
      setname = ctx_def_name(ctx, ctx_required(ctx, 'ELSET'))
      iset = get_elset(ctx, setname)
    end if
    associate (model => ctx%model)
      i = ctx%ir
      do while (i < ctx%ir_next - 1)
        i = i + 1
        call ctx_split(ctx, i, f, n)
        ! a line ending with a comma before the element's nodes are complete continues on the next line (Abaqus:
        ! more than 15 nodes, C3D20); the empty field after that comma is not a node
        do while (n < nn + 1 .and. ctx_continued(ctx, i))
          if (n > 0) then
            if (len_trim(f(n)) == 0) n = n - 1
          end if
          i = i + 1
          call ctx_split(ctx, i, g, m)
          f = [f(1:n), g(1:m)]
          n = n + m
        end do
        if (n /= nn + 1) then
          call ctx_fail(ctx, i, 'element type '//tname//' needs '//itoa(nn)//' nodes, '//itoa(n - 1)//' given')
          return
        end if
        if (.not. ctx_get_int(ctx, i, f(1), id)) return
        if (id <= 0) then
          call ctx_fail(ctx, i, 'element numbers must be positive')
          return
        end if
        if (id > huge(id) - ctx%elem_off) then
          call ctx_fail(ctx, i, 'element number too large')
          return
        end if
        id = id + ctx%elem_off
        ctx%top_elem = max(ctx%top_elem, id)
        if (model%nelem == size(model%elem_id)) call grow_elems(ctx)
        model%nelem = model%nelem + 1
        model%elem_id(model%nelem) = id
        model%elem_kind(model%nelem) = kind
        model%elem_utype(model%nelem) = iu
        ctx%elem_rec(model%nelem) = i
        do while (model%conn_ptr(model%nelem) + nn > size(ctx%conn_raw))
          call grow_int(ctx%conn_raw)
        end do
        do k = 1, nn
          if (.not. ctx_get_label(ctx, i, f(k + 1), .true., node)) return
          ctx%conn_raw(model%conn_ptr(model%nelem) + k - 1) = node
        end do
        model%conn_ptr(model%nelem + 1) = model%conn_ptr(model%nelem) + nn
        if (iset > 0) call ctx_set_member(ctx, .false., iset, -id, i)
      end do
    end associate
  end subroutine read_element

  !> Model dimension from an element type: 2 (plane strain) or 3, the same for all elements.
  subroutine set_dim(ctx, nd)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: nd                   !< dimension of the element type
    if (nd /= 2 .and. nd /= 3) then
      call ctx_fail(ctx, ctx%ir, 'only 2D (plane strain) and 3D models are supported')
    else if (ctx%model%ndim == 0) then
      ctx%model%ndim = nd
    else if (ctx%model%ndim /= nd) then
      call ctx_fail(ctx, ctx%ir, 'mixing 2D and 3D element types in one model is not supported')
    end if
  end subroutine set_dim

  !> *NSET / *ELSET. Members are stored as negative user ids until finish_model resolves them; set names in data
  !> lines are expanded at once (they must be defined before).
  subroutine read_set(ctx, is_node)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: is_node              !< .true. for *NSET, .false. for *ELSET
    character(len=:), allocatable :: setname
    character(len=96) :: ref_prefix
    integer :: node_off, elem_off
    if (is_node) then
      call ctx_allow_params(ctx, [character(len=12) :: 'NSET', 'GENERATE', 'INTERNAL', 'UNSORTED', 'ELSET', &
        'INSTANCE'])
      if (ctx%stat /= 0) return
      setname = ctx_def_name(ctx, ctx_required(ctx, 'NSET'))
    else
      call ctx_allow_params(ctx, [character(len=12) :: 'ELSET', 'GENERATE', 'INTERNAL', 'UNSORTED', 'INSTANCE'])
      if (ctx%stat /= 0) return
      setname = ctx_def_name(ctx, ctx_required(ctx, 'ELSET'))
    end if
    if (ctx%stat /= 0) return
    ! INSTANCE= (assembly level): the labels and set names of the data lines are the instance's
    ref_prefix = ctx%ref_prefix
    node_off = ctx%node_off
    elem_off = ctx%elem_off
    call ctx_enter_instance(ctx)
    if (ctx%stat /= 0) return
    call read_set_members(ctx, is_node, setname)
    ctx%ref_prefix = ref_prefix
    ctx%node_off = node_off
    ctx%elem_off = elem_off
  end subroutine read_set

  !> Data lines of *NSET / *ELSET: labels, set names, or first, last[, increment] with GENERATE.
  subroutine read_set_members(ctx, is_node, setname)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: is_node              !< .true. for *NSET, .false. for *ELSET
    character(len=*), intent(in) :: setname     !< the set defined (scoped name)
    integer :: iset, i, n, k, a, b, s, other, j, off
    character(len=flen), allocatable :: f(:)
    logical :: gen
    if (is_node .and. deck_has_param(ctx%params, 'ELSET')) then
      call ctx_fail(ctx, ctx%ir, 'NSET from ELSET= is not supported: list the nodes')
      return
    end if
    gen = deck_has_param(ctx%params, 'GENERATE')
    if (is_node) then
      iset = get_nset(ctx, setname)
      if (deck_has_param(ctx%params, 'UNSORTED')) ctx%model%nsets(iset)%unsorted = .true.
    else
      iset = get_elset(ctx, setname)
    end if
    associate (model => ctx%model)
      do i = ctx%ir + 1, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        if (gen) then
          if (n < 2 .or. n > 3) then
            call ctx_fail(ctx, i, 'GENERATE expects: first, last[, increment]')
            return
          end if
          if (.not. ctx_get_int(ctx, i, f(1), a)) return
          if (.not. ctx_get_int(ctx, i, f(2), b)) return
          s = 1
          if (n == 3) then
            if (len_trim(f(3)) > 0) then
              if (.not. ctx_get_int(ctx, i, f(3), s)) return
            end if
          end if
          if (s <= 0 .or. b < a) then
            call ctx_fail(ctx, i, 'GENERATE needs first <= last and a positive increment')
            return
          end if
          if (a < 1) then
            call ctx_fail(ctx, i, 'ids must be positive, got '//itoa(a))
            return
          end if
          off = merge(ctx%node_off, ctx%elem_off, is_node)
          if (b > huge(b) - off - s) then
            call ctx_fail(ctx, i, 'ids too large')
            return
          end if
          do k = a + off, b + off, s
            call ctx_set_member(ctx, is_node, iset, -k, -i)
          end do
        else
          do k = 1, n
            if (len_trim(f(k)) == 0) cycle
            if (ctx_is_label(ctx, f(k))) then
              if (.not. ctx_get_label(ctx, i, f(k), is_node, a)) return
              if (a < 1) then
                call ctx_fail(ctx, i, 'ids must be positive, got '//itoa(a))
                return
              end if
              call ctx_set_member(ctx, is_node, iset, -a, i)
            else
              if (is_node) then
                other = ctx_find_nset(ctx, f(k))
              else
                other = ctx_find_elset(ctx, f(k))
              end if
              if (other == 0 .or. other == iset) then
                call ctx_fail(ctx, i, 'undefined set '//trim(deck_normalize(f(k))))
                return
              end if
              ! the members of the other set keep the lines that defined them
              if (is_node) then
                do j = 1, model%nsets(other)%n
                  call ctx_set_member(ctx, .true., iset, model%nsets(other)%nodes(j), ctx%nset_src(other)%rec(j))
                end do
              else
                do j = 1, model%elsets(other)%n
                  call ctx_set_member(ctx, .false., iset, model%elsets(other)%elems(j), ctx%elset_src(other)%rec(j))
                end do
              end if
            end if
          end do
        end if
      end do
    end associate
  end subroutine read_set_members

  !> Index of node set name, created empty when new.
  integer function get_nset(ctx, name) result(k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: name        !< upper-case set name
    type(node_set_t), allocatable :: tmp(:)
    associate (model => ctx%model)
      k = model_find_nset(model, name)
      if (k > 0) return
      if (model%n_nset == size(model%nsets)) then
        allocate (tmp(2 * size(model%nsets)))
        tmp(1:model%n_nset) = model%nsets(1:model%n_nset)
        call move_alloc(tmp, model%nsets)
      end if
      model%n_nset = model%n_nset + 1
      k = model%n_nset
      model%nsets(k)%name = name
      allocate (model%nsets(k)%nodes(0))
    end associate
  end function get_nset

  !> Index of element set name, created empty when new.
  integer function get_elset(ctx, name) result(k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: name        !< upper-case set name
    type(elem_set_t), allocatable :: tmp(:)
    associate (model => ctx%model)
      k = model_find_elset(model, name)
      if (k > 0) return
      if (model%n_elset == size(model%elsets)) then
        allocate (tmp(2 * size(model%elsets)))
        tmp(1:model%n_elset) = model%elsets(1:model%n_elset)
        call move_alloc(tmp, model%elsets)
      end if
      model%n_elset = model%n_elset + 1
      k = model%n_elset
      model%elsets(k)%name = name
      allocate (model%elsets(k)%elems(0))
    end associate
  end function get_elset

  !> Double the node storage.
  subroutine grow_nodes(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: t1(:), t3(:)
    real(dp), allocatable :: t2(:, :)
    integer :: n
    n = size(ctx%model%node_id)
    allocate (t1(2 * n), t2(3, 2 * n), t3(2 * n))
    t1(1:n) = ctx%model%node_id
    t2(:, 1:n) = ctx%model%x
    t3(1:n) = ctx%node_rec
    call move_alloc(t1, ctx%model%node_id)
    call move_alloc(t2, ctx%model%x)
    call move_alloc(t3, ctx%node_rec)
  end subroutine grow_nodes

  !> Double the element storage.
  subroutine grow_elems(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: n
    n = size(ctx%model%elem_id)
    call grow_int(ctx%model%elem_id, 2 * n)
    call grow_int(ctx%model%elem_kind, 2 * n)
    call grow_int(ctx%model%elem_utype, 2 * n)
    call grow_int(ctx%model%conn_ptr, 2 * n + 1)
    call grow_int(ctx%elem_rec, 2 * n)
    if (allocated(ctx%model%elem_uelprop)) call grow_int(ctx%model%elem_uelprop, 2 * n)
  end subroutine grow_elems

  !> An Abaqus hybrid (mixed displacement-pressure) continuum name: C3D*, CPE*, CAX* ending in H (C3D8H, C3D20RH,
  !> CPE4H, CAX8RH, ...).
  pure logical function is_hybrid_name(tname)
    character(len=*), intent(in) :: tname
    integer :: n
    n = len_trim(tname)
    is_hybrid_name = .false.
    if (n < 5) return
    is_hybrid_name = tname(n:n) == 'H' .and. (tname(1:3) == 'C3D' .or. tname(1:3) == 'CPE' .or. tname(1:3) == 'CAX')
  end function is_hybrid_name

end module deck_mesh
