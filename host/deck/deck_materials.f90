!> Material keywords of the deck reader: *MATERIAL with its options *USER MATERIAL, *DEPVAR and *DENSITY (*ELASTIC and
!> *EXPANSION: deck_elastic), and
!> *SOLID SECTION (element set -> material, thickness).
module deck_materials
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: material_t, section_t, model_find_material
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_def_name, ctx_fail, ctx_warn, ctx_pos, ctx_allow_params, ctx_required, &
    ctx_param_int, ctx_block_fields, ctx_split, ctx_get_real, ctx_get_int
  implicit none
  private
  public :: read_material, read_density, read_user_material, read_depvar, read_solid_section

contains

  !> *SOLID SECTION, ELSET=, MATERIAL=: optional data line with the thickness (plane strain).
  subroutine read_solid_section(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(section_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: n, k, ir, ir_next
    real(dp) :: t
    ! CONTROLS=: *SECTION CONTROLS of the one-point elements (read without effect, deck_section_controls);
    ! OFFSET= (CalculiX decks: the offset of plane elements expanded to solids) only as 0, which changes nothing
    call ctx_allow_params(ctx, [character(len=12) :: 'ELSET', 'MATERIAL', 'ORIENTATION', 'CONTROLS', 'OFFSET'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'OFFSET')) then
      if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'OFFSET'), t)) return
      if (t /= 0.0_dp) then
        call ctx_fail(ctx, ctx%ir, 'OFFSET other than 0 is not supported')
        return
      end if
    end if
    ir = ctx%ir
    ir_next = ctx%ir_next
    if (ctx%model%nsection == size(ctx%model%sections)) then
      allocate (tmp(2 * size(ctx%model%sections)))
      tmp(1:ctx%model%nsection) = ctx%model%sections(1:ctx%model%nsection)
      call move_alloc(tmp, ctx%model%sections)
    end if
    k = ctx%model%nsection + 1
    v = ctx_def_name(ctx, ctx_required(ctx, 'ELSET'))
    ctx%model%sections(k)%elset = v
    if (ctx%stat /= 0) return
    v = deck_normalize(ctx_required(ctx, 'MATERIAL'))
    ctx%model%sections(k)%material = v
    if (ctx%stat /= 0) return
    ctx%model%sections(k)%pos = ctx_pos(ctx, ir)
    ctx%model%sections(k)%orientation = ''
    ctx%model%sections(k)%iorient = 0
    if (deck_has_param(ctx%params, 'ORIENTATION')) then
      ctx%model%sections(k)%orientation = ctx_def_name(ctx, ctx_required(ctx, 'ORIENTATION'))
      if (ctx%stat /= 0) return
    end if
    ctx%model%sections(k)%thickness = 1.0_dp
    if (ir_next > ir + 2) then
      call ctx_fail(ctx, ir + 2, 'more than one data line (only the thickness line is read)')
      return
    end if
    if (ir_next == ir + 2) then
      call ctx_split(ctx, ir + 1, f, n)
      if (n > 1) then
        do k = 2, n
          if (len_trim(f(k)) > 0) then
            call ctx_fail(ctx, ir + 1, 'only the first field (thickness) of the data line is supported')
            return
          end if
        end do
      end if
      if (len_trim(f(1)) > 0) then
        if (.not. ctx_get_real(ctx, ir + 1, f(1), t)) return
        if (t <= 0.0_dp) then
          call ctx_fail(ctx, ir + 1, 'thickness must be positive')
          return
        end if
        ctx%model%sections(ctx%model%nsection + 1)%thickness = t
      end if
    end if
    ctx%model%nsection = ctx%model%nsection + 1
  end subroutine read_solid_section

  !> *MATERIAL, NAME=: starts a material definition (options follow as keywords).
  subroutine read_material(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(material_t), allocatable :: tmp(:)
    character(len=:), allocatable :: name
    integer :: imat
    call ctx_allow_params(ctx, [character(len=8) :: 'NAME'])
    if (ctx%stat /= 0) return
    name = ctx_required(ctx, 'NAME')
    if (ctx%stat /= 0) return
    associate (model => ctx%model)
      if (model_find_material(model, deck_normalize(name)) > 0) then
        call ctx_fail(ctx, ctx%ir, 'material '//name//' defined twice')
        return
      end if
      if (model%nmat == size(model%materials)) then
        allocate (tmp(2 * size(model%materials)))
        tmp(1:model%nmat) = model%materials(1:model%nmat)
        call move_alloc(tmp, model%materials)
      end if
      model%nmat = model%nmat + 1
      imat = model%nmat
      ctx%imat = imat
      model%materials(imat)%name = deck_normalize(name)
      model%materials(imat)%given_name = name
      model%materials(imat)%pos = ctx_pos(ctx, ctx%ir)
    end associate
    if (ctx%ir_next > ctx%ir + 1) call ctx_fail(ctx, ctx%ir + 1, 'no data lines expected')
  end subroutine read_material

  !> Error when a material option comes outside a *MATERIAL definition.
  subroutine need_material(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (ctx%imat == 0) call ctx_fail(ctx, ctx%ir, 'material option outside a *MATERIAL definition')
  end subroutine need_material

  !> *DENSITY: the mass density, one data line (rho[, temperature]) or one per temperature. Used by GRAV loads only
  !> (no effect otherwise in a static step); GRAV with a temperature-dependent density is refused (deck_finish).
  subroutine read_density(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    integer :: n, ir, i
    real(dp) :: rho
    call need_material(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=8) ::])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    if (ctx%ir_next == ir + 1) then
      call ctx_fail(ctx, ir, 'a data line with the density is required')
      return
    end if
    do i = ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      if (n > 2) then
        call ctx_fail(ctx, i, 'expected: density[, temperature] (field-variable dependence is not supported)')
        return
      end if
      if (.not. ctx_get_real(ctx, i, f(1), rho)) return
      if (rho < 0.0_dp) then
        call ctx_fail(ctx, i, 'the density must not be negative')
        return
      end if
      if (i == ir + 1) ctx%model%materials(ctx%imat)%density = rho
    end do
    ctx%model%materials(ctx%imat)%has_density = .true.
    ctx%model%materials(ctx%imat)%density_varies = ctx%ir_next > ir + 2
  end subroutine read_density

  !> *USER MATERIAL, CONSTANTS=n: the n UMAT properties.
  subroutine read_user_material(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    integer :: n, nc, k, ir, ir_next, imat
    real(dp) :: r
    call need_material(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=18) :: 'CONSTANTS', 'UNSYMM', 'TYPE', 'HYBRID FORMULATION'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    imat = ctx%imat
    ! HYBRID FORMULATION: how Abaqus' hybrid elements treat the routine's volumetric response. INCREMENTAL (the
    ! default) is what ldfcz's reading of the hybrid names does (docs/elements.md, Hybrid names); TOTAL and
    ! INCOMPRESSIBLE need an independent pressure the elements here do not have
    if (deck_has_param(ctx%params, 'HYBRID FORMULATION')) then
      if (deck_normalize(deck_param_value(ctx%params, 'HYBRID FORMULATION')) /= 'INCREMENTAL') then
        call ctx_fail(ctx, ir, 'HYBRID FORMULATION='//deck_param_value(ctx%params, 'HYBRID FORMULATION')// &
          ' is not supported (only INCREMENTAL, the default: the hybrid names are read as the constant-dilatation '// &
          'types, without an independent pressure; docs/elements.md)')
        return
      end if
    end if
    if (deck_has_param(ctx%params, 'TYPE')) then
      if (deck_normalize(deck_param_value(ctx%params, 'TYPE')) /= 'MECHANICAL') then
        call ctx_fail(ctx, ir, 'only TYPE=MECHANICAL is supported')
        return
      end if
    end if
    nc = ctx_param_int(ctx, 'CONSTANTS', 0)
    if (ctx%stat /= 0) return
    call ctx_block_fields(ctx, ir + 1, ir_next - 1, f, n)
    if (nc < 0) then
      call ctx_fail(ctx, ir, 'CONSTANTS must not be negative')
      return
    end if
    ! more values than CONSTANTS: NPROPS = CONSTANTS, the rest not passed (a published deck with CONSTANTS=5 and 6
    ! values completed in Abaqus; which values Abaqus keeps is inferred: the first CONSTANTS); warned, since the
    ! UMAT may have expected them
    if (n > nc) then
      call ctx_warn(ctx, ir, 'CONSTANTS='//itoa(nc)//' but '//itoa(n)//' values given: values '//itoa(nc + 1)// &
        ' to '//itoa(n)//' are not passed to the UMAT (NPROPS = '//itoa(nc)//')')
      n = nc
    end if
    ! fewer values than CONSTANTS: NPROPS = CONSTANTS, the values not given (and empty fields) are 0, as Abaqus
    ! takes omitted numeric data (decks that ran in Abaqus do this); said, since a constant may be missing
    if (n < nc) call ctx_warn(ctx, ir, 'CONSTANTS='//itoa(nc)//' but '//itoa(n)//' values given: PROPS('// &
      itoa(n + 1)//':'//itoa(nc)//') = 0 (NPROPS = '//itoa(nc)//')')
    if (allocated(ctx%model%materials(imat)%props)) then
      call ctx_fail(ctx, ir, 'a second *USER MATERIAL in material '//trim(ctx%model%materials(imat)%given_name))
      return
    end if
    allocate (ctx%model%materials(imat)%props(nc))
    ctx%model%materials(imat)%props = 0.0_dp
    do k = 1, n
      if (len_trim(f(k)) == 0) cycle
      if (.not. ctx_get_real(ctx, field_record(ctx, ir + 1, ir_next - 1, k), f(k), r)) return
      ctx%model%materials(imat)%props(k) = r
    end do
    ctx%model%materials(imat)%has_user = .true.
    ctx%model%materials(imat)%unsymm = deck_has_param(ctx%params, 'UNSYMM')
    ctx%model%materials(imat)%user_pos = ctx_pos(ctx, min(ir + 1, ir_next - 1))
  end subroutine read_user_material

  !> *DEPVAR[, DELETE=k]: number of state variables of the user material; optional lines 'n, key, description' name
  !> state variable n (the form Abaqus/CAE writes; Abaqus Keywords Guide, *DEPVAR): its field output is SDV_key.
  !> DELETE=k: state variable k controls element deletion (model_change: element_deletion).
  subroutine read_depvar(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    integer :: n, ir, i, nstatv, k
    call need_material(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=8) :: 'DELETE'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    if (ctx%ir_next == ir + 1) then
      call ctx_fail(ctx, ir, 'a data line with the number of state variables is required')
      return
    end if
    call ctx_split(ctx, ir + 1, f, n)
    if (n > 1) then
      call ctx_fail(ctx, ir + 1, 'the first data line holds the number of state variables only')
      return
    end if
    if (.not. ctx_get_int(ctx, ir + 1, f(1), nstatv)) return
    if (nstatv < 0) then
      call ctx_fail(ctx, ir + 1, 'negative number of state variables')
      return
    end if
    associate (m => ctx%model%materials(ctx%imat))
      m%nstatv = nstatv
      m%delete_sdv = depvar_delete(ctx, nstatv)
      if (ctx%stat /= 0) return
      m%delete_pos = ctx_pos(ctx, ir)
      if (allocated(m%sdv_key)) deallocate (m%sdv_key, m%sdv_desc)
      allocate (m%sdv_key(nstatv), m%sdv_desc(nstatv))
      m%sdv_key = ''
      m%sdv_desc = ''
      do i = ir + 2, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        if (n < 2 .or. n > 3) then
          call ctx_fail(ctx, i, 'expected: state variable number, output key[, description]')
          return
        end if
        if (.not. ctx_get_int(ctx, i, f(1), k)) return
        if (k < 1 .or. k > nstatv) then
          call ctx_fail(ctx, i, 'state variable '//itoa(k)//' outside 1..'//itoa(nstatv))
          return
        end if
        if (len_trim(m%sdv_key(k)) > 0) then
          call ctx_fail(ctx, i, 'state variable '//itoa(k)//' named twice')
          return
        end if
        m%sdv_key(k) = unquoted(f(2))
        if (len_trim(m%sdv_key(k)) == 0) then
          call ctx_fail(ctx, i, 'empty output key')
          return
        end if
        if (n == 3) m%sdv_desc(k) = unquoted(f(3))
      end do
    end associate
  end subroutine read_depvar

  !> *DEPVAR, DELETE=k: the state variable whose value 0 deletes the material point (1 active; Analysis User's Guide
  !> "User-defined mechanical material behavior"), 1..nstatv; 0 without DELETE.
  integer function depvar_delete(ctx, nstatv) result(k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state (the *DEPVAR line)
    integer, intent(in) :: nstatv               !< the number of state variables
    character(len=:), allocatable :: v
    integer :: ios
    k = 0
    if (.not. deck_has_param(ctx%params, 'DELETE')) return
    v = trim(deck_param_value(ctx%params, 'DELETE'))
    read (v, *, iostat=ios) k
    if (ios /= 0 .or. len(v) == 0 .or. verify(v, '0123456789') /= 0) then
      call ctx_fail(ctx, ctx%ir, 'DELETE='//v//' is not a state variable number')
      k = 0
    else if (k < 1 .or. k > nstatv) then
      call ctx_fail(ctx, ctx%ir, 'DELETE='//v//' outside the state variables 1..'//itoa(nstatv))
      k = 0
    end if
  end function depvar_delete

  !> A label as written, without enclosing double quotes (case preserved, as *DEPVAR keys are).
  pure function unquoted(field) result(t)
    character(len=*), intent(in) :: field  !< data field
    character(len=:), allocatable :: t
    t = trim(adjustl(field))
    if (len(t) >= 2) then
      if (t(1:1) == '"' .and. t(len(t):len(t)) == '"') t = t(2:len(t) - 1)
    end if
  end function unquoted

  !> Record of the k-th data field of records i1..i2 (messages about one value of a multi-line block).
  integer function field_record(ctx, i1, i2, k) result(irec)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: i1, i2            !< the block's data records
    integer, intent(in) :: k                 !< field number (1-based, over the block)
    character(len=flen), allocatable :: f(:)
    integer :: n, seen
    seen = 0
    do irec = i1, i2
      call ctx_split(ctx, irec, f, n)
      seen = seen + n
      if (seen >= k) return
    end do
    irec = i2
  end function field_record

end module deck_materials
