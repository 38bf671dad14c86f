!> Mesh generation keywords of the deck reader: *NGEN (nodes on a straight line between two nodes), *NFILL (nodes
!> between two node sets), *NCOPY (a node set copied with a label offset and a SHIFT), *ELGEN (elements repeated
!> in up to three directions by node and element label increments). Labels are those of the current scope (part
!> labels inside a part read for an instance); coordinates are the placed ones (an instance's placement is affine,
!> so interpolating placed nodes equals placing interpolated ones).
module deck_generate
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_has_param, deck_param_value, deck_normalize
  use deck_lists, only: itoa, add_member, grow_int, unique
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_allow_params, ctx_required, ctx_split, ctx_get_int, &
    ctx_param_int, ctx_def_name, ctx_find_nset
  use deck_mesh, only: get_nset, get_elset, grow_nodes, grow_elems
  use deck_assembly, only: read_shift
  implicit none
  private
  public :: read_ngen, read_nfill, read_ncopy, read_elgen

contains

  !> *NGEN[, NSET=][, LINE=L]: first end node, second end node[, label increment (default 1)] per data line; the
  !> nodes between are spaced evenly on the straight line. Both end nodes must be defined before.
  subroutine read_ngen(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, a, b, inc, k, nstep, iset, ia, ib
    real(dp) :: xa(3), xb(3)
    call ctx_allow_params(ctx, [character(len=8) :: 'NSET', 'LINE'])
    if (ctx%stat /= 0) return
    if (deck_normalize(deck_param_value(ctx%params, 'LINE')) /= '' .and. &
        deck_normalize(deck_param_value(ctx%params, 'LINE')) /= 'L') then
      call ctx_fail(ctx, ctx%ir, 'only LINE=L (straight line) is supported')
      return
    end if
    iset = 0
    if (deck_has_param(ctx%params, 'NSET')) iset = get_nset(ctx, ctx_def_name(ctx, ctx_required(ctx, 'NSET')))
    if (ctx%stat /= 0) return
    call node_map(ctx, map)
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      if (n < 2 .or. n > 3) then
        call ctx_fail(ctx, i, 'expected: first end node, second end node[, increment] (LINE=L)')
        return
      end if
      if (.not. ctx_get_int(ctx, i, f(1), a)) return
      if (.not. ctx_get_int(ctx, i, f(2), b)) return
      inc = 1
      if (n == 3) then
        if (len_trim(f(3)) > 0) then
          if (.not. ctx_get_int(ctx, i, f(3), inc)) return
        end if
      end if
      ia = node_at(ctx, map, a)
      ib = node_at(ctx, map, b)
      if (ia == 0 .or. ib == 0) then
        call ctx_fail(ctx, i, 'end node '//itoa(merge(a, b, ia == 0))//' is not defined before')
        return
      end if
      if (inc == 0 .or. mod(b - a, inc) /= 0 .or. (b - a) / inc < 1) then
        call ctx_fail(ctx, i, 'the increment must step from the first end node to the second')
        return
      end if
      nstep = (b - a) / inc
      xa = ctx%model%x(:, ia)
      xb = ctx%model%x(:, ib)
      do k = 1, nstep - 1
        call add_node(ctx, i, a + k * inc, xa + real(k, dp) / real(nstep, dp) * (xb - xa), map)
        if (ctx%stat /= 0) return
      end do
      if (iset > 0) then
        do k = 0, nstep
          call add_member(ctx%model%nsets(iset)%nodes, ctx%model%nsets(iset)%n, -(a + k * inc + ctx%node_off))
        end do
      end if
    end do
  end subroutine read_ngen

  !> *NFILL[, NSET=]: first node set, second node set, number of intervals[, label increment (default 1)]. The
  !> sets' nodes, in ascending labels, are paired; between each pair the nodes first + k * increment
  !> (k = 1 .. intervals - 1) are spaced evenly on the straight line.
  subroutine read_nfill(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:), s1(:), s2(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, j, k, nintv, inc, iset, i1, i2, ia, ib
    call ctx_allow_params(ctx, [character(len=8) :: 'NSET', 'BIAS'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'BIAS')) then
      call ctx_fail(ctx, ctx%ir, 'BIAS is not supported (evenly spaced nodes only)')
      return
    end if
    iset = 0
    if (deck_has_param(ctx%params, 'NSET')) iset = get_nset(ctx, ctx_def_name(ctx, ctx_required(ctx, 'NSET')))
    if (ctx%stat /= 0) return
    call node_map(ctx, map)
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      if (n < 3 .or. n > 4) then
        call ctx_fail(ctx, i, 'expected: first node set, second node set, intervals[, increment]')
        return
      end if
      i1 = ctx_find_nset(ctx, f(1))
      i2 = ctx_find_nset(ctx, f(2))
      if (i1 == 0 .or. i2 == 0) then
        call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(merge(1, 2, i1 == 0))))
        return
      end if
      if (.not. ctx_get_int(ctx, i, f(3), nintv)) return
      inc = 1
      if (n == 4) then
        if (len_trim(f(4)) > 0) then
          if (.not. ctx_get_int(ctx, i, f(4), inc)) return
        end if
      end if
      if (nintv < 1 .or. inc < 1) then
        call ctx_fail(ctx, i, 'intervals and increment must be positive')
        return
      end if
      s1 = -ctx%model%nsets(i1)%nodes(1:ctx%model%nsets(i1)%n)
      s2 = -ctx%model%nsets(i2)%nodes(1:ctx%model%nsets(i2)%n)
      call unique(s1)
      call unique(s2)
      if (size(s1) /= size(s2) .or. size(s1) == 0) then
        call ctx_fail(ctx, i, 'the two node sets must have the same number of nodes')
        return
      end if
      do j = 1, size(s1)
        ia = node_at(ctx, map, s1(j) - ctx%node_off)
        ib = node_at(ctx, map, s2(j) - ctx%node_off)
        if (ia == 0 .or. ib == 0) then
          call ctx_fail(ctx, i, 'node '//itoa(merge(s1(j), s2(j), ia == 0) - ctx%node_off)//' of the sets is not '// &
            'defined before')
          return
        end if
        do k = 1, nintv - 1
          call add_node(ctx, i, s1(j) - ctx%node_off + k * inc, ctx%model%x(:, ia) + real(k, dp) / real(nintv, dp) * &
            (ctx%model%x(:, ib) - ctx%model%x(:, ia)), map)
          if (ctx%stat /= 0) return
          if (iset > 0) call add_member(ctx%model%nsets(iset)%nodes, ctx%model%nsets(iset)%n, -(s1(j) + k * inc))
        end do
        if (iset > 0) then
          call add_member(ctx%model%nsets(iset)%nodes, ctx%model%nsets(iset)%n, -s1(j))
          call add_member(ctx%model%nsets(iset)%nodes, ctx%model%nsets(iset)%n, -s2(j))
        end if
      end do
    end do
  end subroutine read_nfill

  !> *NCOPY, CHANGE NUMBER=, OLD SET=, SHIFT[, NEW SET=]: the nodes of OLD SET copied with labels + CHANGE NUMBER,
  !> translated and then rotated as the two data lines say (the convention of *INSTANCE). REFLECT and POLE are
  !> not supported.
  subroutine read_ncopy(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:), old(:)
    integer :: iold, inew, dn, j, ia, nline
    real(dp) :: r(3, 3), c(3), x(3)
    call ctx_allow_params(ctx, [character(len=16) :: 'CHANGE NUMBER', 'OLD SET', 'NEW SET', 'SHIFT', 'REFLECT', &
      'POLE', 'MULTIPLE'])
    if (ctx%stat /= 0) return
    if (.not. deck_has_param(ctx%params, 'SHIFT') .or. deck_has_param(ctx%params, 'REFLECT') .or. &
        deck_has_param(ctx%params, 'POLE') .or. deck_has_param(ctx%params, 'MULTIPLE')) then
      call ctx_fail(ctx, ctx%ir, 'only SHIFT is supported (REFLECT, POLE, MULTIPLE are not)')
      return
    end if
    dn = ctx_param_int(ctx, 'CHANGE NUMBER', -1)
    if (ctx%stat /= 0) return
    if (dn < 1) then
      call ctx_fail(ctx, ctx%ir, 'CHANGE NUMBER= (a positive label offset) is required')
      return
    end if
    iold = ctx_find_nset(ctx, ctx_required(ctx, 'OLD SET'))
    if (ctx%stat /= 0) return
    if (iold == 0) then
      call ctx_fail(ctx, ctx%ir, 'undefined node set '//deck_normalize(deck_param_value(ctx%params, 'OLD SET')))
      return
    end if
    inew = 0
    if (deck_has_param(ctx%params, 'NEW SET')) inew = get_nset(ctx, ctx_def_name(ctx, ctx_required(ctx, 'NEW SET')))
    if (ctx%stat /= 0) return
    nline = ctx%ir_next - ctx%ir - 1
    if (nline > 2) then
      call ctx_fail(ctx, ctx%ir + 3, 'at most two data lines (translation; rotation axis points and angle)')
      return
    end if
    call read_shift(ctx, ctx%ir + 1, nline, r, c)
    if (ctx%stat /= 0) return
    call node_map(ctx, map)
    old = -ctx%model%nsets(iold)%nodes(1:ctx%model%nsets(iold)%n)
    call unique(old)
    do j = 1, size(old)
      ia = node_at(ctx, map, old(j) - ctx%node_off)
      if (ia == 0) then
        call ctx_fail(ctx, ctx%ir, 'node '//itoa(old(j) - ctx%node_off)//' of OLD SET is not defined before')
        return
      end if
      x = ctx%model%x(:, ia)
      ! the shift acts in the scope's own coordinates: undo and redo an instance's placement around it
      if (ctx%placed) x = matmul(transpose(ctx%place_r), x - ctx%place_c)
      x = matmul(r, x) + c
      if (ctx%placed) x = matmul(ctx%place_r, x) + ctx%place_c
      call add_node(ctx, ctx%ir, old(j) - ctx%node_off + dn, x, map)
      if (ctx%stat /= 0) return
      if (inew > 0) call add_member(ctx%model%nsets(inew)%nodes, ctx%model%nsets(inew)%n, -(old(j) + dn))
    end do
  end subroutine read_ncopy

  !> *ELGEN[, ELSET=]: master element, number in the first direction (master included), node label increment,
  !> element label increment[, the same three for the second and third directions]. Each generated element has
  !> the master's type and nodes shifted by the increments.
  subroutine read_elgen(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: emap(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, k, master, im, num(3), dnode(3), delem(3), a, b, c, iset, nn, id, p0, j
    call ctx_allow_params(ctx, [character(len=8) :: 'ELSET'])
    if (ctx%stat /= 0) return
    iset = 0
    if (deck_has_param(ctx%params, 'ELSET')) iset = get_elset(ctx, ctx_def_name(ctx, ctx_required(ctx, 'ELSET')))
    if (ctx%stat /= 0) return
    associate (model => ctx%model)
      do i = ctx%ir + 1, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        if (n < 2 .or. n > 10) then
          call ctx_fail(ctx, i, 'expected: master element, then number, node increment, element increment for up '// &
            'to three directions')
          return
        end if
        if (.not. ctx_get_int(ctx, i, f(1), master)) return
        num = 1
        dnode = 1
        delem = 1
        do k = 2, n
          if (len_trim(f(k)) == 0) cycle
          select case (mod(k - 2, 3))
          case (0)
            if (.not. ctx_get_int(ctx, i, f(k), num((k + 1) / 3))) return
          case (1)
            if (.not. ctx_get_int(ctx, i, f(k), dnode((k + 1) / 3))) return
          case (2)
            if (.not. ctx_get_int(ctx, i, f(k), delem((k + 1) / 3))) return
          end select
        end do
        if (any(num < 1)) then
          call ctx_fail(ctx, i, 'the numbers of elements must be positive')
          return
        end if
        call elem_map(ctx, emap)
        im = 0
        if (master + ctx%elem_off <= size(emap) .and. master > 0) im = emap(master + ctx%elem_off)
        if (im == 0) then
          call ctx_fail(ctx, i, 'master element '//itoa(master)//' is not defined before')
          return
        end if
        p0 = model%conn_ptr(im)
        nn = model%conn_ptr(im + 1) - p0
        do c = 0, num(3) - 1
          do b = 0, num(2) - 1
            do a = 0, num(1) - 1
              id = master + ctx%elem_off + a * delem(1) + b * delem(2) + c * delem(3)
              if (a + b + c > 0) then
                if (model%nelem == size(model%elem_id)) call grow_elems(ctx)
                model%nelem = model%nelem + 1
                model%elem_id(model%nelem) = id
                model%elem_kind(model%nelem) = model%elem_kind(im)
                model%elem_utype(model%nelem) = model%elem_utype(im)
                ctx%elem_rec(model%nelem) = i
                ctx%top_elem = max(ctx%top_elem, id)
                do while (model%conn_ptr(model%nelem) + nn > size(ctx%conn_raw))
                  call grow_int(ctx%conn_raw)
                end do
                do j = 0, nn - 1
                  ctx%conn_raw(model%conn_ptr(model%nelem) + j) = ctx%conn_raw(p0 + j) + a * dnode(1) + &
                    b * dnode(2) + c * dnode(3)
                end do
                model%conn_ptr(model%nelem + 1) = model%conn_ptr(model%nelem) + nn
              end if
              if (iset > 0) call add_member(model%elsets(iset)%elems, model%elsets(iset)%n, -id)
            end do
          end do
        end do
      end do
    end associate
  end subroutine read_elgen

  !> Add a node of scope label id (offset added here) at model coordinates x (already placed); the label map is
  !> kept current (a label defined twice is reported by finish_model with both places).
  subroutine add_node(ctx, irec, id, x, map)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record that generates it
    integer, intent(in) :: id                   !< label in the scope
    real(dp), intent(in) :: x(3)                !< coordinates
    integer, allocatable, intent(inout) :: map(:) !< model label -> node index (node_map)
    if (id < 1) then
      call ctx_fail(ctx, irec, 'generated node label '//itoa(id)//' is not positive')
      return
    end if
    associate (model => ctx%model)
      if (model%nnode == size(model%node_id)) call grow_nodes(ctx)
      model%nnode = model%nnode + 1
      model%node_id(model%nnode) = id + ctx%node_off
      ctx%node_rec(model%nnode) = irec
      model%x(:, model%nnode) = x
      ctx%top_node = max(ctx%top_node, id + ctx%node_off)
      if (id + ctx%node_off > size(map)) call grow_int(map, max(2 * size(map), id + ctx%node_off))
      if (map(id + ctx%node_off) == 0) map(id + ctx%node_off) = model%nnode
    end associate
  end subroutine add_node

  !> Model label -> node index of the nodes read so far (0: none).
  subroutine node_map(ctx, map)
    type(deck_context_t), intent(in) :: ctx      !< reader state
    integer, allocatable, intent(out) :: map(:)  !< index by model label
    integer :: k
    if (ctx%model%nnode == 0) then
      allocate (map(1))
      map = 0
      return
    end if
    allocate (map(maxval(ctx%model%node_id(1:ctx%model%nnode))))
    map = 0
    do k = 1, ctx%model%nnode
      map(ctx%model%node_id(k)) = k
    end do
  end subroutine node_map

  !> Model label -> element index of the elements read so far (0: none).
  subroutine elem_map(ctx, map)
    type(deck_context_t), intent(in) :: ctx      !< reader state
    integer, allocatable, intent(out) :: map(:)  !< index by model label
    integer :: k
    allocate (map(1))
    map = 0
    if (ctx%model%nelem == 0) return
    deallocate (map)
    allocate (map(maxval(ctx%model%elem_id(1:ctx%model%nelem))))
    map = 0
    do k = 1, ctx%model%nelem
      map(ctx%model%elem_id(k)) = k
    end do
  end subroutine elem_map

  !> Node index of scope label id (0 when not defined yet).
  integer function node_at(ctx, map, id) result(k)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: map(:)            !< from node_map
    integer, intent(in) :: id                !< label in the scope
    k = 0
    if (id + ctx%node_off >= 1 .and. id + ctx%node_off <= size(map)) k = map(id + ctx%node_off)
  end function node_at

end module deck_generate
