!> Model structure of the deck reader: *PART ... *END PART, *ASSEMBLY ... *END ASSEMBLY, *INSTANCE ... *END INSTANCE.
!> The reader flattens them into the one model it builds: a part's blocks are read once per instance of it, with
!> the instance's node and element label offsets, its placement (translation, then rotation about an axis through
!> two points, as the Abaqus keyword reference defines the *INSTANCE data lines) and 'INSTANCE.' before the names
!> it defines. The offsets are kept in model%instances (model_label_text writes 'INSTANCE.label' for messages).
module deck_assembly
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_keyword_parse, deck_normalize, deck_param_t
  use model_types, only: instance_t
  use deck_context, only: deck_context_t, flen, part_def_t, ctx_fail, ctx_fail_kw, ctx_warn, ctx_allow_params, ctx_required, &
    ctx_split, ctx_get_real, scope_model, scope_part, scope_assembly
  implicit none
  private
  public :: prescan_assembly, read_part_def, begin_assembly, end_assembly, begin_instance, end_instance
  public :: allowed_in_part, allowed_in_assembly, mesh_keyword, read_shift

contains

  !> Keywords a part may hold (checked where the part is defined, so that a part without instance is checked too).
  pure logical function allowed_in_part(kw)
    character(len=*), intent(in) :: kw  !< keyword, upper case
    select case (kw)
    case ('*NODE', '*ELEMENT', '*NSET', '*ELSET', '*SURFACE', '*SOLID SECTION', '*UEL PROPERTY', '*NGEN', &
          '*NFILL', '*NCOPY', '*ELGEN', '*PARAMETER', '*ORIENTATION', '*TRANSFORM', '*SYSTEM', '*USER ELEMENT', &
          '*LDFCZ SVARS', '*LDFCZ BUILTIN')
      allowed_in_part = .true.
    case default
      allowed_in_part = .false.
    end select
  end function allowed_in_part

  !> Keywords of the assembly level (between *ASSEMBLY and *END ASSEMBLY, outside instances).
  pure logical function allowed_in_assembly(kw)
    character(len=*), intent(in) :: kw  !< keyword, upper case
    select case (kw)
    case ('*INSTANCE', '*END INSTANCE', '*END ASSEMBLY', '*NODE', '*ELEMENT', '*NSET', '*ELSET', '*SURFACE', &
          '*EQUATION', '*TIE', '*MPC', '*NGEN', '*NFILL', '*NCOPY', '*ELGEN', '*PARAMETER', '*TRANSFORM', '*SYSTEM', &
          '*COUPLING', '*KINEMATIC', '*DISTRIBUTING', '*PRE-TENSION SECTION', '*ORIENTATION')
      allowed_in_assembly = .true.
    case default
      allowed_in_assembly = .false.
    end select
  end function allowed_in_assembly

  !> Keywords that define mesh and sets: in a deck with an *ASSEMBLY they belong in a part or in the assembly.
  pure logical function mesh_keyword(kw)
    character(len=*), intent(in) :: kw  !< keyword, upper case
    select case (kw)
    case ('*NODE', '*ELEMENT', '*NSET', '*ELSET', '*SURFACE', '*SOLID SECTION', '*NGEN', '*NFILL', '*NCOPY', &
          '*ELGEN', '*UEL PROPERTY', '*ORIENTATION', '*TRANSFORM', '*SYSTEM')
      mesh_keyword = .true.
    case default
      mesh_keyword = .false.
    end select
  end function mesh_keyword

  !> Before reading: does the deck have an *ASSEMBLY (then all mesh is in parts or in the assembly)?
  subroutine prescan_assembly(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: i
    character(len=:), allocatable :: kw
    type(deck_param_t), allocatable :: params(:)
    do i = 1, ctx%src%nrec
      if (.not. ctx%src%rec(i)%keyword) cycle
      call deck_keyword_parse(ctx%src%rec(i)%text, kw, params)
      if (kw == '*ASSEMBLY') ctx%has_assembly = .true.
    end do
  end subroutine prescan_assembly

  !> *PART, NAME=: the records up to *END PART are kept (read for each instance); ctx%ir_next moves past
  !> *END PART.
  subroutine read_part_def(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: name, kw
    type(deck_param_t), allocatable :: params(:)
    type(part_def_t), allocatable :: tmp(:)
    integer :: i, k
    call ctx_allow_params(ctx, [character(len=8) :: 'NAME'])
    if (ctx%stat /= 0) return
    if (ctx%scope /= scope_model .or. ctx%in_step) then
      call ctx_fail(ctx, ctx%ir, '*PART only at model level (not inside *ASSEMBLY, another *PART or a step)')
      return
    end if
    name = deck_normalize(ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    do k = 1, ctx%npart
      if (ctx%parts(k)%name == name) then
        call ctx_fail(ctx, ctx%ir, 'part '//name//' defined twice')
        return
      end if
    end do
    do i = ctx%ir + 1, ctx%src%nrec
      if (.not. ctx%src%rec(i)%keyword) cycle
      call deck_keyword_parse(ctx%src%rec(i)%text, kw, params)
      if (kw == '*END PART') exit
      if (.not. allowed_in_part(kw)) then
        if (kw == '*PART' .or. kw == '*ASSEMBLY' .or. kw == '*STEP') then
          call ctx_fail(ctx, ctx%ir, 'part '//name//' has no *END PART before '//kw)
        else
          call ctx_fail_kw(ctx, i, kw, 'not supported inside *PART '//trim(name)//' (ldfcz reads *NODE, *ELEMENT, '// &
            '*NSET, *ELSET, *SURFACE, *SOLID SECTION, *ORIENTATION, *TRANSFORM, *SYSTEM, *UEL PROPERTY, *NGEN, *NFILL, '// &
            '*NCOPY, *ELGEN '// &
            'in a part), '// &
            'or *END PART missing before it')
        end if
        return
      end if
    end do
    if (i > ctx%src%nrec) then
      call ctx_fail(ctx, ctx%ir, 'part '//name//' has no *END PART')
      return
    end if
    if (.not. allocated(ctx%parts)) allocate (ctx%parts(4))
    if (ctx%npart == size(ctx%parts)) then
      allocate (tmp(2 * ctx%npart))
      tmp(1:ctx%npart) = ctx%parts(1:ctx%npart)
      call move_alloc(tmp, ctx%parts)
    end if
    ctx%npart = ctx%npart + 1
    ctx%parts(ctx%npart)%name = name
    ctx%parts(ctx%npart)%ir1 = ctx%ir + 1
    ctx%parts(ctx%npart)%ir2 = i
    ctx%ir_next = i + 1
  end subroutine read_part_def

  !> *ASSEMBLY, NAME=: assembly-level labels keep their numbers; instances are numbered above the largest of them
  !> (found here, before any instance is read).
  subroutine begin_assembly(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: kw
    type(deck_param_t), allocatable :: params(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, id, what
    logical :: ok, inside
    call ctx_allow_params(ctx, [character(len=8) :: 'NAME'])
    if (ctx%stat /= 0) return
    if (ctx%scope /= scope_model .or. ctx%in_step) then
      call ctx_fail(ctx, ctx%ir, '*ASSEMBLY only at model level, once')
      return
    end if
    if (ctx%model%nnode > 0 .or. ctx%model%nelem > 0 .or. ctx%model%ninstance > 0) then
      call ctx_fail(ctx, ctx%ir, 'a second *ASSEMBLY, or one after nodes or elements outside parts')
      return
    end if
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, 'no data lines expected')
      return
    end if
    ctx%scope = scope_assembly
    what = 0      ! 1: in an assembly-level *NODE block, 2: *ELEMENT
    inside = .false.
    do i = ctx%ir + 1, ctx%src%nrec
      if (ctx%src%rec(i)%keyword) then
        call deck_keyword_parse(ctx%src%rec(i)%text, kw, params)
        if (kw == '*END ASSEMBLY') return
        if (kw == '*INSTANCE') inside = .true.
        if (kw == '*END INSTANCE') inside = .false.
        what = 0
        if (.not. inside .and. kw == '*NODE') what = 1
        if (.not. inside .and. kw == '*ELEMENT') what = 2
        cycle
      end if
      if (what == 0) cycle
      call ctx_split(ctx, i, f, n)
      call parse_quiet(f(1), id, ok)
      if (.not. ok) cycle  ! reported when the block is read
      if (what == 1) ctx%top_node = max(ctx%top_node, id)
      if (what == 2) ctx%top_elem = max(ctx%top_elem, id)
    end do
    call ctx_fail(ctx, ctx%ir, 'no *END ASSEMBLY')
  end subroutine begin_assembly

  !> *END ASSEMBLY.
  subroutine end_assembly(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (ctx%scope /= scope_assembly .and. .not. ctx%has_assembly .and. ctx%scope == scope_model) then
      ! a lone *END ASSEMBLY in a deck without *ASSEMBLY closes nothing (decks that ran in Abaqus have it; Abaqus'
      ! manuals say nothing of it): without effect on the model, so accepted with a warning
      call ctx_warn(ctx, ctx%ir, 'no *ASSEMBLY before it in this deck: ignored (it closes nothing)')
      return
    end if
    if (ctx%scope /= scope_assembly) then
      call ctx_fail(ctx, ctx%ir, '*END ASSEMBLY without *ASSEMBLY')
      return
    end if
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, 'no data lines expected')
      return
    end if
    ctx%scope = scope_model
  end subroutine end_assembly

  !> *INSTANCE, NAME=, PART=: registers the instance (label offsets above every label read so far), reads its
  !> placement and enters the part scope. ip: the part; ir_end: the *END INSTANCE record; ir1..ir2: the records
  !> to read for the instance, the part's blocks, or the instance's own blocks when its part is empty (an
  !> independent instance as Abaqus/CAE writes it: *Part ... *End Part without data, the mesh between *Instance and
  !> *End Instance; Abaqus Analysis User's Guide, "Assembly definition").
  subroutine begin_instance(ctx, ip, ir_end, ir1, ir2)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(out) :: ip                  !< part index
    integer, intent(out) :: ir_end              !< record of *END INSTANCE
    integer, intent(out) :: ir1, ir2            !< records of the blocks to read for the instance
    character(len=:), allocatable :: name, part, kw
    type(deck_param_t), allocatable :: params(:)
    type(instance_t), allocatable :: tmp(:)
    integer :: i, k
    ip = 0
    ir_end = 0
    call ctx_allow_params(ctx, [character(len=8) :: 'NAME', 'PART'])
    if (ctx%stat /= 0) return
    if (ctx%scope /= scope_assembly) then
      call ctx_fail(ctx, ctx%ir, '*INSTANCE only inside *ASSEMBLY')
      return
    end if
    name = deck_normalize(ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    part = deck_normalize(ctx_required(ctx, 'PART'))
    if (ctx%stat /= 0) return
    do k = 1, ctx%npart
      if (ctx%parts(k)%name == part) ip = k
    end do
    if (ip == 0) then
      call ctx_fail(ctx, ctx%ir, 'undefined part '//part//' (a *PART defined before the *ASSEMBLY)')
      return
    end if
    do k = 1, ctx%model%ninstance
      if (ctx%model%instances(k)%name == name) then
        call ctx_fail(ctx, ctx%ir, 'instance '//name//' defined twice')
        return
      end if
    end do
    ir1 = ctx%parts(ip)%ir1
    ir2 = ctx%parts(ip)%ir2 - 1
    do i = ctx%ir_next, ctx%src%nrec
      if (.not. ctx%src%rec(i)%keyword) cycle
      call deck_keyword_parse(ctx%src%rec(i)%text, kw, params)
      if (kw == '*END INSTANCE') then
        ir_end = i
        exit
      end if
      if (ctx%parts(ip)%ir2 > ctx%parts(ip)%ir1) then
        call ctx_fail(ctx, ctx%ir, 'instance '//name//': *END INSTANCE expected before '//kw// &
          ' (the mesh of an instance comes from its *PART; only an instance of an empty part holds its own)')
        return
      end if
      if (.not. allowed_in_part(kw)) then
        call ctx_fail_kw(ctx, i, kw, 'not supported inside *INSTANCE '//name//' (the keywords of a *PART)')
        return
      end if
      ! an independent instance: its own blocks from the first keyword after the placement lines
      if (ir1 == ctx%parts(ip)%ir1) ir1 = i
    end do
    if (ir_end == 0) then
      call ctx_fail(ctx, ctx%ir, 'instance '//name//' has no *END INSTANCE')
      return
    end if
    if (ir1 /= ctx%parts(ip)%ir1) then
      ir2 = ir_end - 1
      if (ctx%parts(ip)%ninst > 0) then
        call ctx_fail(ctx, ctx%ir, 'part '//part//' has an independent instance (its mesh in the *INSTANCE) '// &
          'and another instance')
        return
      end if
    end if
    call read_placement(ctx)
    if (ctx%stat /= 0) return
    if (.not. allocated(ctx%model%instances)) allocate (ctx%model%instances(4))
    if (ctx%model%ninstance == size(ctx%model%instances)) then
      allocate (tmp(2 * ctx%model%ninstance))
      tmp(1:ctx%model%ninstance) = ctx%model%instances(1:ctx%model%ninstance)
      call move_alloc(tmp, ctx%model%instances)
    end if
    ctx%model%ninstance = ctx%model%ninstance + 1
    associate (in => ctx%model%instances(ctx%model%ninstance))
      in%name = name
      in%part = part
      in%node_offset = ctx%top_node
      in%elem_offset = ctx%top_elem
      in%node_last = ctx%top_node
      in%elem_last = ctx%top_elem
      ctx%node_off = in%node_offset
      ctx%elem_off = in%elem_offset
    end associate
    ctx%parts(ip)%ninst = ctx%parts(ip)%ninst + 1
    ctx%scope = scope_part
    ctx%def_prefix = name//'.'
    ctx%ref_prefix = name//'.'
    ctx%system_on = .false.   ! a part's *SYSTEM is its own (set within the part)
  end subroutine begin_instance

  !> After a part was read for the current instance: its label range recorded, the assembly scope restored.
  subroutine end_instance(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (ctx%placed .and. ctx%model%ndim == 2) then
      if (abs(ctx%place_r(3, 3) - 1.0_dp) > 1.0e-12_dp .or. abs(ctx%place_c(3)) > 0.0_dp) then
        call ctx_fail(ctx, ctx%ir, 'instance '//trim(ctx%model%instances(ctx%model%ninstance)%name)// &
          ' of a plane model is moved out of the x-y plane (translate in x, y; rotate about an axis along z)')
        return
      end if
    end if
    associate (in => ctx%model%instances(ctx%model%ninstance))
      in%node_last = max(in%node_offset, ctx%top_node)
      in%elem_last = max(in%elem_offset, ctx%top_elem)
    end associate
    ctx%scope = scope_assembly
    ctx%def_prefix = ''
    ctx%ref_prefix = ''
    ctx%node_off = 0
    ctx%elem_off = 0
    ctx%placed = .false.
    ctx%system_on = .false.
  end subroutine end_instance

  !> Data lines of *INSTANCE: the placement of the part's nodes.
  subroutine read_placement(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: nline
    nline = ctx%ir_next - ctx%ir - 1
    if (nline > 2) then
      call ctx_fail(ctx, ctx%ir + 3, 'at most two data lines (translation; rotation axis points and angle)')
      return
    end if
    call read_shift(ctx, ctx%ir + 1, nline, ctx%place_r, ctx%place_c)
    ctx%placed = nline > 0
  end subroutine read_placement

  !> Translation line (tx, ty, tz) and optional rotation line (point a, point b, angle in degrees about the axis
  !> a->b, right-handed) at records ir1, ir1 + 1 (nline of them, 0..2), as *INSTANCE and *NCOPY, SHIFT write
  !> them. Translation is applied first: x_new = a + R (x + t - a) = r x + c.
  subroutine read_shift(ctx, ir1, nline, r, c)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: ir1                  !< record of the translation line
    integer, intent(in) :: nline                !< data lines present (0, 1 or 2)
    real(dp), intent(out) :: r(3, 3)            !< rotation
    real(dp), intent(out) :: c(3)               !< shift
    character(len=flen), allocatable :: f(:)
    real(dp) :: t(3), a(3), b(3), v(7), axis(3), th, co, si
    integer :: n, k
    real(dp), parameter :: pi = acos(-1.0_dp)
    t = 0.0_dp
    r = 0.0_dp
    r(1, 1) = 1.0_dp
    r(2, 2) = 1.0_dp
    r(3, 3) = 1.0_dp
    a = 0.0_dp
    c = 0.0_dp
    if (nline >= 1) then
      call ctx_split(ctx, ir1, f, n)
      if (n > 3) then
        call ctx_fail(ctx, ir1, 'translation line: tx, ty, tz')
        return
      end if
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_real(ctx, ir1, f(k), t(k))) return
      end do
    end if
    if (nline >= 2) then
      call ctx_split(ctx, ir1 + 1, f, n)
      if (n /= 7) then
        call ctx_fail(ctx, ir1 + 1, 'rotation line: ax, ay, az, bx, by, bz, angle (degrees)')
        return
      end if
      v = 0.0_dp
      do k = 1, 7
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_real(ctx, ir1 + 1, f(k), v(k))) return
      end do
      a = v(1:3)
      b = v(4:6)
      axis = b - a
      if (norm2(axis) <= 1.0e-12_dp * max(1.0_dp, norm2(a), norm2(b))) then
        call ctx_fail(ctx, ir1 + 1, 'rotation axis: points a and b coincide')
        return
      end if
      axis = axis / norm2(axis)
      th = v(7) * pi / 180.0_dp
      co = cos(th)
      si = sin(th)
      ! Rodrigues: R = cos I + sin [axis]x + (1 - cos) axis axis^T
      do k = 1, 3
        r(:, k) = (1.0_dp - co) * axis * axis(k)
        r(k, k) = r(k, k) + co
      end do
      r(1, 2) = r(1, 2) - si * axis(3)
      r(2, 1) = r(2, 1) + si * axis(3)
      r(1, 3) = r(1, 3) + si * axis(2)
      r(3, 1) = r(3, 1) - si * axis(2)
      r(2, 3) = r(2, 3) - si * axis(1)
      r(3, 2) = r(3, 2) + si * axis(1)
    end if
    c = a + matmul(r, t - a)
  end subroutine read_shift

  !> Integer of a field without messages (pre-scan).
  pure subroutine parse_quiet(field, v, ok)
    character(len=*), intent(in) :: field  !< text
    integer, intent(out) :: v              !< value
    logical, intent(out) :: ok             !< an integer
    integer :: ios
    v = 0
    ok = len_trim(field) > 0 .and. verify(trim(adjustl(field)), '0123456789+') == 0 .and. len_trim(field) < 10
    if (.not. ok) return
    read (field, *, iostat=ios) v
    ok = ios == 0
  end subroutine parse_quiet

end module deck_assembly
