!> *ORIENTATION of the deck reader: local material axes for *SOLID SECTION, ORIENTATION= (docs/host.md).
!> SYSTEM=RECTANGULAR (default) or CYLINDRICAL; DEFINITION=COORDINATES (default: points a, b[, c] on the first data
!> line) or NODES (node labels a, b[, c]); an optional second data line: local axis 1..3 and an additional rotation
!> angle about it in degrees. Inside a part read for an instance the points are placed with the instance.
!> *TRANSFORM (local node systems for boundary conditions, concentrated loads and nodal output) shares the axes.
module deck_orientation
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_normalize
  use model_types, only: orientation_t, transform_t, model_find_orientation
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_allow_params, ctx_required, ctx_split, ctx_get_real, &
    ctx_get_int, ctx_get_label, ctx_def_name, ctx_pos, ctx_find_nset
  implicit none
  private
  public :: read_orientation, read_transform

contains

  !> *ORIENTATION, NAME=[, SYSTEM=][, DEFINITION=].
  subroutine read_orientation(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(orientation_t) :: o
    type(orientation_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: n, k, nline
    real(dp) :: p(9)
    call ctx_allow_params(ctx, [character(len=12) :: 'NAME', 'SYSTEM', 'DEFINITION'])
    if (ctx%stat /= 0) return
    o%name = ctx_def_name(ctx, ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    o%pos = ctx_pos(ctx, ctx%ir)
    v = deck_normalize(deck_param_value(ctx%params, 'SYSTEM'))
    select case (v)
    case ('', 'RECTANGULAR')
      o%system = 1
    case ('CYLINDRICAL')
      o%system = 2
    case default
      call ctx_fail(ctx, ctx%ir, 'SYSTEM='//v//' is not supported (RECTANGULAR, CYLINDRICAL)')
      return
    end select
    v = deck_normalize(deck_param_value(ctx%params, 'DEFINITION'))
    select case (v)
    case ('', 'COORDINATES')
      o%by_nodes = .false.
    case ('NODES')
      o%by_nodes = .true.
    case default
      call ctx_fail(ctx, ctx%ir, 'DEFINITION='//v//' is not supported (COORDINATES, NODES)')
      return
    end select
    nline = ctx%ir_next - ctx%ir - 1
    if (nline < 1 .or. nline > 2) then
      call ctx_fail(ctx, ctx%ir, 'one or two data lines expected (the points; an additional rotation)')
      return
    end if
    call ctx_split(ctx, ctx%ir + 1, f, n)
    if (o%by_nodes) then
      if (n < 2 .or. n > 3) then
        call ctx_fail(ctx, ctx%ir + 1, 'expected: node a, node b[, node c]')
        return
      end if
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_label(ctx, ctx%ir + 1, f(k), .true., o%nodes(k))) return
      end do
      if (o%system == 2 .and. o%nodes(3) /= 0) then
        call ctx_fail(ctx, ctx%ir + 1, 'CYLINDRICAL takes two nodes on the axis')
        return
      end if
    else
      if (n < 6 .or. n > 9) then
        call ctx_fail(ctx, ctx%ir + 1, 'expected: a1, a2, a3, b1, b2, b3[, c1, c2, c3]')
        return
      end if
      p = 0.0_dp
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_real(ctx, ctx%ir + 1, f(k), p(k))) return
      end do
      o%a = p(1:3)
      o%b = p(4:6)
      o%c = p(7:9)
      if (ctx%placed) then
        o%a = matmul(ctx%place_r, o%a) + ctx%place_c
        o%b = matmul(ctx%place_r, o%b) + ctx%place_c
        o%c = matmul(ctx%place_r, o%c) + ctx%place_c
      end if
    end if
    if (nline == 2) then
      call ctx_split(ctx, ctx%ir + 2, f, n)
      if (n > 2) then
        call ctx_fail(ctx, ctx%ir + 2, 'expected: local axis (1, 2 or 3), additional rotation angle (degrees)')
        return
      end if
      if (len_trim(f(1)) > 0) then
        if (.not. ctx_get_int(ctx, ctx%ir + 2, f(1), o%extra_axis)) return
      end if
      if (n == 2) then
        if (len_trim(f(2)) > 0) then
          if (.not. ctx_get_real(ctx, ctx%ir + 2, f(2), o%extra_angle)) return
        end if
      end if
      if (o%extra_axis < 0 .or. o%extra_axis > 3) then
        call ctx_fail(ctx, ctx%ir + 2, 'the local axis of the additional rotation must be 1, 2 or 3')
        return
      end if
      if (o%extra_axis == 0 .and. o%extra_angle /= 0.0_dp) o%extra_axis = 1
    end if
    associate (model => ctx%model)
      if (model_find_orientation(model, o%name) > 0) then
        call ctx_fail(ctx, ctx%ir, 'orientation '//trim(o%name)//' defined twice')
        return
      end if
      if (.not. allocated(model%orientations)) allocate (model%orientations(2))
      if (model%norient == size(model%orientations)) then
        allocate (tmp(2 * model%norient))
        tmp(1:model%norient) = model%orientations(1:model%norient)
        call move_alloc(tmp, model%orientations)
      end if
      model%norient = model%norient + 1
      model%orientations(model%norient) = o
    end associate
  end subroutine read_orientation

  !> *TRANSFORM, NSET=[, TYPE=R|C|S]: one data line with the global coordinates of the points a and b. TYPE=R
  !> (default): local x along a, local y in the plane of a and b (the origin being the third point); TYPE=C: a and
  !> b on the axis (local 1 radial, 2 tangential, 3 axial a -> b); TYPE=S: a the centre, b on the polar axis
  !> (1 radial, 2 polar angle, 3 azimuth). The directions are those of the node's reference position and stay fixed
  !> in space (also under NLGEOM). Inside a part read for an instance they are placed with the instance.
  subroutine read_transform(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(transform_t) :: t
    type(transform_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: n, k
    real(dp) :: p(6)
    call ctx_allow_params(ctx, [character(len=12) :: 'NSET', 'TYPE'])
    if (ctx%stat /= 0) return
    t%pos = ctx_pos(ctx, ctx%ir)
    v = ctx_required(ctx, 'NSET')
    if (ctx%stat /= 0) return
    t%nset = ctx_find_nset(ctx, v)
    if (t%nset == 0) then
      call ctx_fail(ctx, ctx%ir, 'undefined node set '//deck_normalize(v))
      return
    end if
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    select case (v)
    case ('', 'R')
      t%kind = 'R'
      t%axes%system = 1
    case ('C')
      t%kind = 'C'
      t%axes%system = 2
    case ('S')
      t%kind = 'S'
      t%axes%system = 3
    case default
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (R, C, S)')
      return
    end select
    if (ctx%ir_next - ctx%ir - 1 /= 1) then
      call ctx_fail(ctx, ctx%ir, 'one data line expected: a1, a2, a3, b1, b2, b3')
      return
    end if
    call ctx_split(ctx, ctx%ir + 1, f, n)
    if (n /= 6) then
      call ctx_fail(ctx, ctx%ir + 1, 'expected six coordinates: a1, a2, a3, b1, b2, b3')
      return
    end if
    p = 0.0_dp
    do k = 1, 6
      if (len_trim(f(k)) == 0) cycle
      if (.not. ctx_get_real(ctx, ctx%ir + 1, f(k), p(k))) return
    end do
    t%axes%a = p(1:3)
    t%axes%b = p(4:6)
    t%axes%c = 0.0_dp
    if (t%axes%system == 1) then
      if (norm2(cross(t%axes%a, t%axes%b)) <= 1.0e-12_dp * max(1.0_dp, norm2(t%axes%a) * norm2(t%axes%b))) then
        call ctx_fail(ctx, ctx%ir + 1, 'TYPE=R: a and b must not be zero nor parallel (a is local x, b in the '// &
          'local x-y plane)')
        return
      end if
    else if (norm2(t%axes%b - t%axes%a) <= 1.0e-12_dp * max(1.0_dp, norm2(t%axes%a))) then
      call ctx_fail(ctx, ctx%ir + 1, 'TYPE='//t%kind//': the points a and b coincide')
      return
    end if
    if (ctx%placed) then
      t%axes%a = matmul(ctx%place_r, t%axes%a) + ctx%place_c
      t%axes%b = matmul(ctx%place_r, t%axes%b) + ctx%place_c
      t%axes%c = matmul(ctx%place_r, t%axes%c) + ctx%place_c
    end if
    associate (model => ctx%model)
      if (.not. allocated(model%transforms)) allocate (model%transforms(2))
      if (model%ntransform == size(model%transforms)) then
        allocate (tmp(2 * model%ntransform))
        tmp(1:model%ntransform) = model%transforms(1:model%ntransform)
        call move_alloc(tmp, model%transforms)
      end if
      model%ntransform = model%ntransform + 1
      model%transforms(model%ntransform) = t
    end associate
  contains
    pure function cross(p1, q1) result(w)
      real(dp), intent(in) :: p1(3), q1(3)
      real(dp) :: w(3)
      w = [p1(2) * q1(3) - p1(3) * q1(2), p1(3) * q1(1) - p1(1) * q1(3), p1(1) * q1(2) - p1(2) * q1(1)]
    end function cross
  end subroutine read_transform

end module deck_orientation
