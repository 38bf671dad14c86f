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
    ctx_param_int, ctx_def_name, ctx_find_nset, ctx_get_real, ctx_set_member
  use deck_mesh, only: get_nset, get_elset, grow_nodes, grow_elems
  use deck_assembly, only: read_shift
  implicit none
  private
  public :: read_ngen, read_nfill, read_ncopy, read_elgen

contains

  !> *NGEN[, NSET=][, LINE=L|C|P][, SYSTEM=RC]: first end node, second end node[, label increment (default 1)[,
  !> extra node[, x, y, z of the extra point[, normal n1, n2, n3]]]] per data line (both end nodes defined before).
  !> LINE=L: evenly spaced on the straight line. LINE=C: on the circular arc about the extra point (the centre),
  !> evenly spaced in angle, the radius and the component along the normal varying linearly from one end to the
  !> other (equal for a true circle); the arc is the one below 180 degrees unless a normal is given, which makes it
  !> the arc turning right-handed about the normal (up to 360 degrees). LINE=P: on the parabola through the first
  !> end, the extra point (the midpoint) and the second end, evenly spaced in its parameter. The extra point is the
  !> extra node when one is given, else the coordinates (in the scope's coordinates, placed with an instance).
  subroutine read_ngen(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, a, b, inc, k, nstep, iset, ia, ib, iextra, ic
    real(dp) :: xa(3), xb(3), xc(3), nrm(3), x(3), v(9)
    character(len=:), allocatable :: line, emsg
    logical :: has_point, has_normal
    call ctx_allow_params(ctx, [character(len=8) :: 'NSET', 'LINE', 'SYSTEM'])
    if (ctx%stat /= 0) return
    line = deck_normalize(deck_param_value(ctx%params, 'LINE'))
    if (line == '') line = 'L'
    if (line /= 'L' .and. line /= 'C' .and. line /= 'P') then
      call ctx_fail(ctx, ctx%ir, 'LINE='//line//' is not supported (L, C, P)')
      return
    end if
    if (deck_normalize(deck_param_value(ctx%params, 'SYSTEM')) /= '' .and. &
        deck_normalize(deck_param_value(ctx%params, 'SYSTEM')) /= 'RC') then
      call ctx_fail(ctx, ctx%ir, 'only SYSTEM=RC (the extra point in rectangular coordinates) is supported')
      return
    end if
    iset = 0
    if (deck_has_param(ctx%params, 'NSET')) iset = get_nset(ctx, ctx_def_name(ctx, ctx_required(ctx, 'NSET')))
    if (ctx%stat /= 0) return
    call node_map(ctx, map)
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      if (n < 2 .or. n > 10 .or. (line == 'L' .and. n > 3)) then
        if (line == 'L') then
          call ctx_fail(ctx, i, 'expected: first end node, second end node[, increment] (LINE=L)')
        else
          call ctx_fail(ctx, i, 'expected: first end node, second end node, increment, extra node or blank, '// &
            'x, y, z of the extra point[, normal n1, n2, n3] (LINE='//line//')')
        end if
        return
      end if
      if (.not. ctx_get_int(ctx, i, f(1), a)) return
      if (.not. ctx_get_int(ctx, i, f(2), b)) return
      inc = 1
      if (n >= 3) then
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
      has_normal = .false.
      if (line /= 'L') then
        ! the extra point: a node (field 4) or coordinates (fields 5-7); a normal (fields 8-10)
        v = 0.0_dp
        iextra = 0
        if (n >= 4) then
          if (len_trim(f(4)) > 0) then
            if (.not. ctx_get_int(ctx, i, f(4), iextra)) return
          end if
        end if
        has_point = .false.
        do k = 5, n
          if (len_trim(f(k)) == 0) cycle
          if (.not. ctx_get_real(ctx, i, f(k), v(k - 4))) return
          if (k <= 7) has_point = .true.
          if (k >= 8) has_normal = .true.
        end do
        if (iextra /= 0) then
          ic = node_at(ctx, map, iextra)
          if (ic == 0) then
            call ctx_fail(ctx, i, 'extra node '//itoa(iextra)//' is not defined before')
            return
          end if
          xc = ctx%model%x(:, ic)
        else if (has_point) then
          xc = v(1:3)
          if (ctx%placed) xc = matmul(ctx%place_r, xc) + ctx%place_c
        else
          call ctx_fail(ctx, i, 'LINE='//line//' needs an extra point ('//trim(merge('the centre  ', &
            'the midpoint', line == 'C'))//'): a node in field 4 or its coordinates in fields 5-7')
          return
        end if
        nrm = v(4:6)
        if (has_normal .and. ctx%placed) nrm = matmul(ctx%place_r, nrm)
        if (has_normal .and. norm2(nrm) == 0.0_dp) has_normal = .false.
      end if
      do k = 1, nstep - 1
        select case (line)
        case ('C')
          call arc_point(xa, xb, xc, nrm, has_normal, real(k, dp) / real(nstep, dp), x, emsg)
          if (len(emsg) > 0) then
            call ctx_fail(ctx, i, emsg)
            return
          end if
        case ('P')
          x = parabola_point(xa, xc, xb, real(k, dp) / real(nstep, dp))
        case default
          x = xa + real(k, dp) / real(nstep, dp) * (xb - xa)
        end select
        call add_node(ctx, i, a + k * inc, x, map)
        if (ctx%stat /= 0) return
      end do
      if (iset > 0) then
        do k = 0, nstep
          call ctx_set_member(ctx, .true., iset, -(a + k * inc + ctx%node_off), i)
        end do
      end if
    end do
  end subroutine read_ngen

  !> Point at fraction s of the arc from xa to xb about the centre xc (read_ngen, LINE=C). errmsg non-empty when
  !> the arc is undefined (an end at the centre, or ends opposite each other without a normal).
  pure subroutine arc_point(xa, xb, xc, normal, has_normal, s, x, errmsg)
    real(dp), intent(in) :: xa(3), xb(3), xc(3), normal(3), s
    logical, intent(in) :: has_normal
    real(dp), intent(out) :: x(3)
    character(len=:), allocatable, intent(out) :: errmsg
    real(dp) :: v1(3), v2(3), n(3), p1(3), p2(3), h1, h2, r1, r2, u1(3), w(3), th, phi, tol
    errmsg = ''
    x = xa
    v1 = xa - xc
    v2 = xb - xc
    tol = 1.0e-10_dp * max(norm2(v1), norm2(v2), tiny(1.0_dp))
    if (has_normal) then
      n = normal / norm2(normal)
    else
      n = cross3(v1, v2)
      if (norm2(n) <= tol * max(norm2(v1), norm2(v2))) then
        errmsg = 'the arc plane is undefined (ends at 0 or 180 degrees about the centre): give a normal in '// &
          'fields 8-10'
        return
      end if
      n = n / norm2(n)
    end if
    h1 = dot_product(v1, n)
    h2 = dot_product(v2, n)
    p1 = v1 - h1 * n
    p2 = v2 - h2 * n
    r1 = norm2(p1)
    r2 = norm2(p2)
    if (r1 <= tol .or. r2 <= tol) then
      errmsg = 'an end node lies at the centre (on the normal through it): no arc'
      return
    end if
    th = atan2(dot_product(n, cross3(p1, p2)), dot_product(p1, p2))
    if (th <= 0.0_dp) th = th + 2.0_dp * acos(-1.0_dp)
    u1 = p1 / r1
    w = cross3(n, u1)
    phi = s * th
    x = xc + (h1 + s * (h2 - h1)) * n + (r1 + s * (r2 - r1)) * (cos(phi) * u1 + sin(phi) * w)
  end subroutine arc_point

  !> Fraction of the way from the first set to the second of node k of n intervals, each interval 1/bias times the
  !> one before it (the ratio of adjacent intervals, the one nearer the first set over the next, is bias; inferred
  !> from the keyword reference's "bias ratio", which concentrates nodes at the first set when below 1).
  pure real(dp) function bias_fraction(bias, k, n) result(f)
    real(dp), intent(in) :: bias  !< ratio of adjacent intervals
    integer, intent(in) :: k, n   !< node, intervals
    real(dp) :: q
    q = 1.0_dp / bias
    if (abs(q - 1.0_dp) < 1.0e-12_dp) then
      f = real(k, dp) / real(n, dp)
    else if (q < 1.0_dp) then
      f = (1.0_dp - q**k) / (1.0_dp - q**n)
    else
      ! (q^k - 1) / (q^n - 1) without overflow: powers of 1/q only
      f = ((1.0_dp / q)**(n - k) - (1.0_dp / q)**n) / (1.0_dp - (1.0_dp / q)**n)
    end if
  end function bias_fraction

  !> Point at parameter s of the parabola through xa (s = 0), xm (s = 1/2) and xb (s = 1) (read_ngen, LINE=P).
  pure function parabola_point(xa, xm, xb, s) result(x)
    real(dp), intent(in) :: xa(3), xm(3), xb(3), s
    real(dp) :: x(3)
    x = (1.0_dp - s) * (1.0_dp - 2.0_dp * s) * xa + 4.0_dp * s * (1.0_dp - s) * xm + s * (2.0_dp * s - 1.0_dp) * xb
  end function parabola_point

  pure function cross3(p, q) result(w)
    real(dp), intent(in) :: p(3), q(3)
    real(dp) :: w(3)
    w = [p(2) * q(3) - p(3) * q(2), p(3) * q(1) - p(1) * q(3), p(1) * q(2) - p(2) * q(1)]
  end function cross3

  !> *NFILL[, NSET=][, BIAS=b]: first node set, second node set, number of intervals[, label increment (default
  !> 1)]. The sets' nodes, in ascending labels, are paired; between each pair the nodes first + k * increment
  !> (k = 1 .. intervals - 1) lie on the straight line, evenly spaced, or with BIAS=b each interval 1/b times the
  !> one before it counting from the first set (b < 1 concentrates the nodes at the first set; bias_fraction).
  subroutine read_nfill(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:), s1(:), s2(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, j, k, nintv, inc, iset, i1, i2, ia, ib
    real(dp) :: bias
    character(len=:), allocatable :: v
    call ctx_allow_params(ctx, [character(len=8) :: 'NSET', 'BIAS'])
    if (ctx%stat /= 0) return
    bias = 1.0_dp
    if (deck_has_param(ctx%params, 'BIAS')) then
      v = deck_param_value(ctx%params, 'BIAS')
      if (.not. ctx_get_real(ctx, ctx%ir, v, bias)) return
      if (.not. (bias > 0.0_dp .and. bias <= 1.0e6_dp)) then
        call ctx_fail(ctx, ctx%ir, 'BIAS must be a positive ratio')
        return
      end if
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
          call add_node(ctx, i, s1(j) - ctx%node_off + k * inc, ctx%model%x(:, ia) + bias_fraction(bias, k, nintv) * &
            (ctx%model%x(:, ib) - ctx%model%x(:, ia)), map)
          if (ctx%stat /= 0) return
          if (iset > 0) call ctx_set_member(ctx, .true., iset, -(s1(j) + k * inc), i)
        end do
        if (iset > 0) then
          call ctx_set_member(ctx, .true., iset, -s1(j), i)
          call ctx_set_member(ctx, .true., iset, -s2(j), i)
        end if
      end do
    end do
  end subroutine read_nfill

  !> *NCOPY, CHANGE NUMBER=, OLD SET=, SHIFT | REFLECT=LINE|MIRROR|POINT[, NEW SET=]: the nodes of OLD SET copied
  !> with labels + CHANGE NUMBER, translated and then rotated as the two data lines say (SHIFT: the convention of
  !> *INSTANCE), or reflected (read_reflection). POLE and MULTIPLE are not supported.
  subroutine read_ncopy(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, allocatable :: map(:), old(:)
    integer :: iold, inew, dn, j, ia, nline
    real(dp) :: r(3, 3), c(3), x(3)
    character(len=:), allocatable :: reflect
    call ctx_allow_params(ctx, [character(len=16) :: 'CHANGE NUMBER', 'OLD SET', 'NEW SET', 'SHIFT', 'REFLECT', &
      'POLE', 'MULTIPLE'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'POLE') .or. deck_has_param(ctx%params, 'MULTIPLE')) then
      call ctx_fail(ctx, ctx%ir, 'POLE and MULTIPLE are not supported (SHIFT, REFLECT=LINE|MIRROR|POINT are)')
      return
    end if
    if (deck_has_param(ctx%params, 'SHIFT') .eqv. deck_has_param(ctx%params, 'REFLECT')) then
      call ctx_fail(ctx, ctx%ir, 'give either SHIFT or REFLECT=LINE|MIRROR|POINT')
      return
    end if
    reflect = deck_normalize(deck_param_value(ctx%params, 'REFLECT'))
    if (deck_has_param(ctx%params, 'REFLECT') .and. reflect /= 'LINE' .and. reflect /= 'MIRROR' .and. &
        reflect /= 'POINT') then
      call ctx_fail(ctx, ctx%ir, 'REFLECT='//reflect//' is not supported (LINE, MIRROR, POINT)')
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
    if (len(reflect) > 0) then
      call read_reflection(ctx, reflect, nline, r, c)
    else
      if (nline > 2) then
        call ctx_fail(ctx, ctx%ir + 3, 'at most two data lines (translation; rotation axis points and angle)')
        return
      end if
      call read_shift(ctx, ctx%ir + 1, nline, r, c)
    end if
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
      if (inew > 0) call ctx_set_member(ctx, .true., inew, -(old(j) + dn), ctx%ir)
    end do
  end subroutine read_ncopy

  !> The reflection x' = r x + c of *NCOPY, REFLECT= (points in the scope's coordinates, one data line): LINE
  !> through the points a, b (x' = 2 p - x, p the foot of x on the line: a half turn about it); MIRROR, the plane
  !> through a, b, c; POINT, through a.
  subroutine read_reflection(ctx, kind, nline, r, c)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: kind        !< LINE, MIRROR or POINT
    integer, intent(in) :: nline                !< data lines
    real(dp), intent(out) :: r(3, 3), c(3)      !< the map
    character(len=flen), allocatable :: f(:)
    real(dp) :: v(9), e(3)
    integer :: n, k, need, i
    r = 0.0_dp
    c = 0.0_dp
    need = merge(6, merge(9, 3, kind == 'MIRROR'), kind == 'LINE')
    if (nline /= 1) then
      call ctx_fail(ctx, ctx%ir, 'REFLECT='//kind//': one data line with '//itoa(need)//' coordinates expected')
      return
    end if
    call ctx_split(ctx, ctx%ir + 1, f, n)
    if (n /= need) then
      call ctx_fail(ctx, ctx%ir + 1, 'REFLECT='//kind//': expected '//itoa(need)//' coordinates ('// &
        trim(merge('a, b     ', merge('a, b, c  ', 'the point', kind == 'MIRROR'), kind == 'LINE'))//')')
      return
    end if
    v = 0.0_dp
    do k = 1, n
      if (len_trim(f(k)) == 0) cycle
      if (.not. ctx_get_real(ctx, ctx%ir + 1, f(k), v(k))) return
    end do
    select case (kind)
    case ('POINT')
      do i = 1, 3
        r(i, i) = -1.0_dp
      end do
      c = 2.0_dp * v(1:3)
      return
    case ('LINE')
      e = v(4:6) - v(1:3)
    case default
      e = cross3(v(4:6) - v(1:3), v(7:9) - v(1:3))
    end select
    if (norm2(e) <= 1.0e-12_dp * max(1.0_dp, norm2(v))) then
      call ctx_fail(ctx, ctx%ir + 1, 'REFLECT='//kind//': the points do not define a '// &
        trim(merge('line ', 'plane', kind == 'LINE')))
      return
    end if
    e = e / norm2(e)
    do i = 1, 3
      r(:, i) = 2.0_dp * e * e(i)
      r(i, i) = r(i, i) - 1.0_dp
    end do
    if (kind == 'MIRROR') r = -r                 ! I - 2 e e^T
    c = v(1:3) - matmul(r, v(1:3))               ! a is fixed
  end subroutine read_reflection

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
              if (iset > 0) call ctx_set_member(ctx, .false., iset, -id, i)
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
