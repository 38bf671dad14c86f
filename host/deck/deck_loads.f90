!> Load keywords of the deck reader: *CLOAD (concentrated nodal forces of fixed direction), *DLOAD (body forces
!> BX/BY/BZ/GRAV, face pressure P1..P6, user element loads Un), *SURFACE (TYPE=ELEMENT) and *DSLOAD (pressure P on a
!> surface). Element ids stay negative user ids, element sets set indices, until finish_model.
module deck_loads
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: cload_t, dload_t, surface_t, model_find_amplitude, &
    model_find_surface, dload_bx, dload_grav, dload_pressure, dload_user, dload_centrif, dload_rota
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_elset, &
    ctx_find_surface, ctx_def_name, ctx_enter_instance, ctx_fail, ctx_pos, ctx_allow_params, ctx_need_step, &
    ctx_split, ctx_get_real, ctx_get_int, ctx_required
  implicit none
  private
  public :: read_cload, read_dload, read_dsload, read_surface

contains

  !> *CLOAD[, AMPLITUDE=][, OP=MOD|NEW]: node or node set, dof, magnitude. Node ids stay negative user ids until
  !> finish_model. FOLLOWER (rotational dofs only in Abaqus) and the file/cyclic variants are errors.
  subroutine read_cload(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(cload_t) :: cl, empty_cl
    character(len=flen), allocatable :: f(:)
    integer :: i, n, id, iset, iamp, ir, istep
    character(len=:), allocatable :: v
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    istep = ctx%istep
    v = deck_normalize(deck_param_value(ctx%params, 'OP'))
    if (len(v) > 0 .and. v /= 'MOD' .and. v /= 'NEW') then
      call ctx_fail(ctx, ir, 'OP must be MOD or NEW')
      return
    end if
    if (v == 'NEW') ctx%model%steps(istep)%cload_op_new = .true.
    iamp = 0
    if (deck_has_param(ctx%params, 'AMPLITUDE')) then
      iamp = model_find_amplitude(ctx%model, deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
      if (iamp == 0) then
        call ctx_fail(ctx, ir, 'undefined amplitude '//deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
        return
      end if
    end if
    do i = ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      cl = empty_cl
      cl%amplitude = iamp
      cl%pos = ctx_pos(ctx, i)
      if (n < 3) then
        call ctx_fail(ctx, i, 'expected: node or node set, dof, magnitude')
        return
      end if
      if (n > 3) then
        if (any(len_trim(f(4:n)) > 0)) then
          call ctx_fail(ctx, i, 'too many fields (node or node set, dof, magnitude)')
          return
        end if
      end if
      if (ctx_is_label(ctx, f(1))) then
        if (.not. ctx_get_label(ctx, i, f(1), .true., id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
          return
        end if
        allocate (cl%nodes(1))
        cl%nodes(1) = -id  ! resolved in finish_model
      else
        iset = ctx_find_nset(ctx, f(1))
        if (iset == 0) then
          call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(1)))
          return
        end if
        cl%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
      end if
      if (.not. ctx_get_int(ctx, i, f(2), cl%dof)) return
      if (cl%dof < 1 .or. cl%dof > 6) then
        call ctx_fail(ctx, i, 'dof '//itoa(cl%dof)//' invalid (1..6)')
        return
      end if
      ! moments (dofs 4..6) exist at the reference node of a *COUPLING only: checked when the model is complete
      if (len_trim(f(3)) > 0) then
        if (.not. ctx_get_real(ctx, i, f(3), cl%value)) return
      end if
      call push_cload(ctx%model%steps(istep)%cloads, ctx%model%steps(istep)%ncload, cl)
    end do
  end subroutine read_cload

  !> OP= and AMPLITUDE= of a *DLOAD/*DSLOAD (history data): iamp the amplitude (0: the step's default).
  subroutine dload_params(ctx, iamp)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(out) :: iamp                !< amplitude index
    character(len=:), allocatable :: v
    iamp = 0
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'OP'))
    if (len(v) > 0 .and. v /= 'MOD' .and. v /= 'NEW') then
      call ctx_fail(ctx, ctx%ir, 'OP must be MOD or NEW')
      return
    end if
    if (v == 'NEW') ctx%model%steps(ctx%istep)%dload_op_new = .true.
    if (deck_has_param(ctx%params, 'AMPLITUDE')) then
      iamp = model_find_amplitude(ctx%model, deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
      if (iamp == 0) call ctx_fail(ctx, ctx%ir, 'undefined amplitude '// &
        deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
    end if
  end subroutine dload_params

  !> Element or element set of field f on record i: dl%elset (set index) or dl%elems = [-id].
  logical function element_target(ctx, i, f, dl) result(ok)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: i                    !< record
    character(len=*), intent(in) :: f           !< field
    type(dload_t), intent(inout) :: dl          !< load being read
    integer :: id
    ok = .false.
    if (ctx_is_label(ctx, f)) then
      if (.not. ctx_get_label(ctx, i, f, .false., id)) return
      if (id < 1) then
        call ctx_fail(ctx, i, 'element ids must be positive, got '//itoa(id))
        return
      end if
      dl%elems = [-id]
      dl%elset = 0
    else
      dl%elset = ctx_find_elset(ctx, f)
      if (dl%elset == 0) then
        call ctx_fail(ctx, i, 'undefined element set '//deck_normalize(f))
        return
      end if
      dl%elems = [integer ::]   ! (re)set: the caller reuses dl line after line
    end if
    ok = .true.
  end function element_target

  !> *DLOAD[, AMPLITUDE=][, OP=]: element or element set, load label, magnitude[, direction for GRAV].
  !> Labels: BX, BY, BZ (force per unit reference volume), GRAV (magnitude g, then the direction components),
  !> CENTRIF (omega^2) and ROTA (alpha), then a point on the axis and the axis direction, P1..P6 (pressure on face
  !> Sn), Un (user element load type n, passed to the UEL). Others are errors.
  subroutine read_dload(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(dload_t) :: dl, empty
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: lab
    integer :: i, n, iamp, k, ios
    real(dp) :: d(3)
    call dload_params(ctx, iamp)
    if (ctx%stat /= 0) return
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      dl = empty
      dl%amplitude = iamp
      dl%pos = ctx_pos(ctx, i)
      if (n < 3) then
        call ctx_fail(ctx, i, 'expected: element or element set, load label, magnitude')
        return
      end if
      if (.not. element_target(ctx, i, f(1), dl)) return
      lab = deck_normalize(f(2))
      if (len_trim(f(3)) > 0) then
        if (.not. ctx_get_real(ctx, i, f(3), dl%value)) return
      end if
      d = 0.0_dp
      select case (lab)
      case ('BX', 'BY', 'BZ')
        dl%kind = dload_bx
        dl%dir(iachar(lab(2:2)) - iachar('X') + 1) = 1.0_dp
      case ('GRAV')
        dl%kind = dload_grav
        do k = 1, 3
          if (n >= 3 + k) then
            if (len_trim(f(3 + k)) > 0) then
              if (.not. ctx_get_real(ctx, i, f(3 + k), d(k))) return
            end if
          end if
        end do
        if (norm2(d) <= 0.0_dp) then
          call ctx_fail(ctx, i, 'GRAV needs a nonzero direction (magnitude, then its components)')
          return
        end if
        dl%dir = d / norm2(d)
      case ('CENTRIF', 'ROTA')
        dl%kind = merge(dload_centrif, dload_rota, lab == 'CENTRIF')
        if (.not. rotation_axis(ctx, i, f, n, dl)) return
      case default
        k = 0
        ios = 1
        if (len(lab) >= 2) read (lab(2:), *, iostat=ios) k
        if (lab(1:1) == 'P' .and. ios == 0 .and. verify(lab(2:), '0123456789') == 0 .and. k >= 1 .and. k <= 6) then
          dl%kind = dload_pressure
          dl%label = k
        else if (lab(1:1) == 'U' .and. ios == 0 .and. verify(lab(2:), '0123456789') == 0 .and. k >= 1) then
          dl%kind = dload_user
          dl%label = k
        else
          call ctx_fail(ctx, i, 'unsupported load label '//lab//' (BX, BY, BZ, GRAV, CENTRIF, ROTA, P1..P6, Un)')
          return
        end if
      end select
      if (dl%kind /= dload_grav .and. dl%kind /= dload_centrif .and. dl%kind /= dload_rota .and. n > 3) then
        if (any(len_trim(f(4:n)) > 0)) then
          call ctx_fail(ctx, i, 'too many fields for load '//lab)
          return
        end if
      end if
      call push_dload(ctx%model%steps(ctx%istep)%dloads, ctx%model%steps(ctx%istep)%ndload, dl)
    end do
  end subroutine read_dload

  !> CENTRIF/ROTA data fields 4..9 of record i: a point on the axis (blank: 0) and the axis direction (unit; zero
  !> when not given: the model's dimension decides, deck_finish_extras). More than 9 fields is an error.
  logical function rotation_axis(ctx, i, f, n, dl) result(ok)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: i                    !< record
    character(len=*), intent(in) :: f(:)        !< its fields
    integer, intent(in) :: n                    !< fields in use
    type(dload_t), intent(inout) :: dl          !< the load
    integer :: k
    real(dp) :: v(6)
    ok = .false.
    if (n > 9) then
      if (any(len_trim(f(10:n)) > 0)) then
        call ctx_fail(ctx, i, 'too many fields (element, label, magnitude, point on the axis, axis direction)')
        return
      end if
    end if
    v = 0.0_dp
    do k = 1, min(n - 3, 6)
      if (len_trim(f(3 + k)) == 0) cycle
      if (.not. ctx_get_real(ctx, i, f(3 + k), v(k))) return
    end do
    dl%point = v(1:3)
    dl%dir = 0.0_dp
    if (norm2(v(4:6)) > 0.0_dp) dl%dir = v(4:6) / norm2(v(4:6))
    ok = .true.
  end function rotation_axis

  !> *DSLOAD[, AMPLITUDE=][, OP=]: surface, P, magnitude (pressure on every face of the surface).
  subroutine read_dsload(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(dload_t) :: dl, empty
    character(len=flen), allocatable :: f(:)
    integer :: i, n, iamp, isurf
    call dload_params(ctx, iamp)
    if (ctx%stat /= 0) return
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      dl = empty
      dl%amplitude = iamp
      dl%pos = ctx_pos(ctx, i)
      if (n < 3) then
        call ctx_fail(ctx, i, 'expected: surface, P, magnitude')
        return
      end if
      if (n > 3) then
        if (any(len_trim(f(4:n)) > 0)) then
          call ctx_fail(ctx, i, 'too many fields (surface, P, magnitude)')
          return
        end if
      end if
      isurf = ctx_find_surface(ctx, f(1))
      if (isurf == 0) then
        call ctx_fail(ctx, i, 'undefined surface '//deck_normalize(f(1)))
        return
      end if
      if (deck_normalize(f(2)) /= 'P') then
        call ctx_fail(ctx, i, 'unsupported load label '//deck_normalize(f(2))//' (only P, pressure)')
        return
      end if
      if (len_trim(f(3)) > 0) then
        if (.not. ctx_get_real(ctx, i, f(3), dl%value)) return
      end if
      dl%kind = dload_pressure
      dl%label = 0
      dl%elset = -isurf  ! a surface: expanded in finish_model
      dl%elems = [integer ::]   ! (re)set: the caller reuses dl line after line
      call push_dload(ctx%model%steps(ctx%istep)%dloads, ctx%model%steps(ctx%istep)%ndload, dl)
    end do
  end subroutine read_dsload

  !> *SURFACE, NAME=[, TYPE=ELEMENT]: element or element set, face label S1..S6 per data line.
  subroutine read_surface(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(surface_t), allocatable :: tmp(:)
    type(dload_t) :: dl
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v, lab
    integer :: i, n, k, is
    character(len=96) :: ref_prefix
    integer :: node_off, elem_off
    call ctx_allow_params(ctx, [character(len=12) :: 'NAME', 'TYPE', 'INTERNAL', 'INSTANCE'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    if (v /= '' .and. v /= 'ELEMENT') then
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (ELEMENT: element faces S1..S6)')
      return
    end if
    if (.not. allocated(ctx%model%surfaces)) allocate (ctx%model%surfaces(2))
    if (ctx%model%nsurf == size(ctx%model%surfaces)) then
      allocate (tmp(2 * size(ctx%model%surfaces)))
      tmp(1:ctx%model%nsurf) = ctx%model%surfaces(1:ctx%model%nsurf)
      call move_alloc(tmp, ctx%model%surfaces)
    end if
    v = ctx_def_name(ctx, ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    if (model_find_surface(ctx%model, v) > 0) then
      call ctx_fail(ctx, ctx%ir, 'surface '//v//' defined twice')
      return
    end if
    is = ctx%model%nsurf + 1
    ! INSTANCE= (assembly level): the element labels and sets of the data lines are the instance's
    ref_prefix = ctx%ref_prefix
    node_off = ctx%node_off
    elem_off = ctx%elem_off
    call ctx_enter_instance(ctx)
    if (ctx%stat /= 0) return
    associate (sf => ctx%model%surfaces(is))
      sf%name = v
      sf%pos = ctx_pos(ctx, ctx%ir)
      n = ctx%ir_next - ctx%ir - 1
      allocate (sf%elems(n), sf%faces(n), sf%elsets(n))
      sf%n = 0
      do i = ctx%ir + 1, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        if (n < 2) then
          call ctx_fail(ctx, i, 'expected: element or element set, face label S1..S6 (free-surface generation '// &
            'without a label is not supported)')
          return
        end if
        if (n > 2) then
          if (any(len_trim(f(3:n)) > 0)) then
            call ctx_fail(ctx, i, 'too many fields (element or element set, face label)')
            return
          end if
        end if
        if (.not. element_target(ctx, i, f(1), dl)) return
        lab = deck_normalize(f(2))
        k = 0
        if (len(lab) == 2 .and. lab(1:1) == 'S') k = index('123456', lab(2:2))
        if (k == 0) then
          call ctx_fail(ctx, i, 'unsupported face label '//lab//' (S1..S6)')
          return
        end if
        sf%n = sf%n + 1
        sf%faces(sf%n) = k
        sf%elsets(sf%n) = dl%elset
        sf%elems(sf%n) = 0
        if (dl%elset == 0) sf%elems(sf%n) = dl%elems(1)
      end do
      if (sf%n == 0) then
        call ctx_fail(ctx, ctx%ir, 'a surface needs at least one data line')
        return
      end if
    end associate
    ctx%model%nsurf = is
    ctx%ref_prefix = ref_prefix
    ctx%node_off = node_off
    ctx%elem_off = elem_off
  end subroutine read_surface

  !> Append a distributed load to a list with n entries, doubling the capacity when full.
  pure subroutine push_dload(list, n, dl)
    type(dload_t), allocatable, intent(inout) :: list(:) !< load list
    integer, intent(inout) :: n                          !< entries in use
    type(dload_t), intent(in) :: dl                      !< load to append
    type(dload_t), allocatable :: t(:)
    if (.not. allocated(list)) allocate (list(4))
    if (n == size(list)) then
      allocate (t(2 * n))
      t(1:n) = list(1:n)
      call move_alloc(t, list)
    end if
    n = n + 1
    list(n) = dl
  end subroutine push_dload

  !> Append a load to a list with n entries, doubling the capacity when full.
  pure subroutine push_cload(list, n, cl)
    type(cload_t), allocatable, intent(inout) :: list(:) !< load list
    integer, intent(inout) :: n                          !< entries in use
    type(cload_t), intent(in) :: cl                      !< load to append
    type(cload_t), allocatable :: t(:)
    if (.not. allocated(list)) allocate (list(4))
    if (n == size(list)) then
      allocate (t(2 * n))
      t(1:n) = list(1:n)
      call move_alloc(t, list)
    end if
    n = n + 1
    list(n) = cl
  end subroutine push_cload

end module deck_loads
