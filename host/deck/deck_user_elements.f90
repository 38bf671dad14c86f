!> User-element keywords of the deck reader: *USER ELEMENT (type Un: nodes, coordinates, property and state counts,
!> active dofs) and *UEL PROPERTY (the real and integer properties of an element set of one user type).
module deck_user_elements
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_has_param, deck_normalize
  use model_types, only: user_element_type_t, uel_property_t, etype_user, model_find_user_type
  use deck_lists, only: itoa, grow_int
  use deck_context, only: deck_context_t, flen, ctx_find_elset, ctx_fail, ctx_pos, ctx_allow_params, ctx_required, &
    ctx_param_int, ctx_block_fields, ctx_split, ctx_get_real, ctx_get_int
  implicit none
  private
  public :: read_user_element, read_uel_property

contains

  !> *USER ELEMENT, TYPE=Un, NODES=, COORDINATES=, PROPERTIES=, I PROPERTIES=, VARIABLES=, UNSYMM: one data line
  !> with the active displacement dofs of every node.
  subroutine read_user_element(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(user_element_type_t) :: ut
    type(user_element_type_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: n, k, ir, ir_next
    call ctx_allow_params(ctx, [character(len=12) :: 'TYPE', 'NODES', 'COORDINATES', 'PROPERTIES', 'I PROPERTIES', &
      'VARIABLES', 'UNSYMM', 'INTEGRATION', 'TENSOR'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    if (deck_has_param(ctx%params, 'INTEGRATION') .or. deck_has_param(ctx%params, 'TENSOR')) then
      call ctx_fail(ctx, ir, 'INTEGRATION/TENSOR (UMAT inside UEL) are not supported')
      return
    end if
    ut%name = deck_normalize(ctx_required(ctx, 'TYPE'))
    if (ctx%stat /= 0) return
    if (ut%name(1:1) /= 'U' .or. verify(trim(ut%name(2:)), '0123456789') /= 0 .or. len_trim(ut%name) < 2) then
      call ctx_fail(ctx, ir, 'TYPE must be Un with n a number, got '//trim(ut%name))
      return
    end if
    read (ut%name(2:), *) ut%jtype
    k = model_find_user_type(ctx%model, ut%name)
    if (k > 0) then
      ! a part's *USER ELEMENT read again for its next instance: the one type it defines
      if (ctx%model%utypes(k)%pos%line == ctx%src%rec(ir)%line .and. &
          ctx%model%utypes(k)%pos%file == ctx%src%files(ctx%src%rec(ir)%file_id)%name) return
      call ctx_fail(ctx, ir, 'user element '//trim(ut%name)//' defined twice')
      return
    end if
    ut%nnode = ctx_param_int(ctx, 'NODES', 0)
    ut%mcrd = ctx_param_int(ctx, 'COORDINATES', 3)
    ut%nprops = ctx_param_int(ctx, 'PROPERTIES', 0)
    ut%njprops = ctx_param_int(ctx, 'I PROPERTIES', 0)
    ut%nsvars = ctx_param_int(ctx, 'VARIABLES', 1)
    if (ctx%stat /= 0) return
    if (ut%nnode <= 0) then
      call ctx_fail(ctx, ir, 'NODES= must be given and positive')
      return
    end if
    if (ut%mcrd < 2 .or. ut%mcrd > 3) then
      call ctx_fail(ctx, ir, 'COORDINATES must be 2 or 3')
      return
    end if
    if (ut%nprops < 0 .or. ut%njprops < 0 .or. ut%nsvars < 0) then
      call ctx_fail(ctx, ir, 'negative PROPERTIES, I PROPERTIES or VARIABLES')
      return
    end if
    ut%unsymm = deck_has_param(ctx%params, 'UNSYMM')
    if (ir_next == ir + 1) then
      call ctx_fail(ctx, ir, 'the active-dof data line is missing')
      return
    end if
    if (ir_next > ir + 2) then
      call ctx_fail(ctx, ir + 2, 'node-dependent active-dof lines are not supported (one line for all nodes)')
      return
    end if
    call ctx_split(ctx, ir + 1, f, n)
    allocate (ut%active(n))
    do k = 1, n
      if (.not. ctx_get_int(ctx, ir + 1, f(k), ut%active(k))) return
      if (ut%active(k) < 1 .or. ut%active(k) > ut%mcrd) then
        call ctx_fail(ctx, ir + 1, 'active dof '//itoa(ut%active(k))//' not a displacement dof 1..COORDINATES')
        return
      end if
    end do
    ut%pos = ctx_pos(ctx, ir)
    associate (model => ctx%model)
      if (model%nutype == size(model%utypes)) then
        allocate (tmp(2 * size(model%utypes)))
        tmp(1:model%nutype) = model%utypes(1:model%nutype)
        call move_alloc(tmp, model%utypes)
      end if
      model%nutype = model%nutype + 1
      model%utypes(model%nutype) = ut
    end associate
  end subroutine read_user_element

  !> *UEL PROPERTY, ELSET=: PROPERTIES reals then I PROPERTIES integers of the set's (single) user type.
  subroutine read_uel_property(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: setname
    integer :: iset, iu, k, n, e, ie, ip, np, nj, ir, ir_next, jv
    real(dp) :: r
    character(len=flen), allocatable :: f(:)
    type(uel_property_t), allocatable :: tmp(:)
    call ctx_allow_params(ctx, [character(len=8) :: 'ELSET'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    setname = deck_normalize(ctx_required(ctx, 'ELSET'))
    if (ctx%stat /= 0) return
    iset = ctx_find_elset(ctx, setname)
    if (iset == 0) then
      call ctx_fail(ctx, ir, 'undefined element set '//setname)
      return
    end if
    ! the user type of the set's elements
    iu = 0
    do k = 1, ctx%model%elsets(iset)%n
      e = -ctx%model%elsets(iset)%elems(k)
      ie = find_elem_raw(ctx, e)
      if (ie == 0) then
        call ctx_fail(ctx, ir, 'element '//itoa(e)//' of set '//setname//' is not defined')
        return
      end if
      if (ctx%model%elem_kind(ie) /= etype_user) then
        call ctx_fail(ctx, ir, 'element '//itoa(e)//' of set '//setname//' is not a user element')
        return
      end if
      if (iu == 0) iu = ctx%model%elem_utype(ie)
      if (ctx%model%elem_utype(ie) /= iu) then
        call ctx_fail(ctx, ir, 'set '//setname//' mixes user element types')
        return
      end if
    end do
    if (iu == 0) then
      call ctx_fail(ctx, ir, 'element set '//setname//' is empty')
      return
    end if
    np = ctx%model%utypes(iu)%nprops
    nj = ctx%model%utypes(iu)%njprops
    call ctx_block_fields(ctx, ir + 1, ir_next - 1, f, n)
    if (n /= np + nj) then
      call ctx_fail(ctx, ir, 'type '//trim(ctx%model%utypes(iu)%name)//' needs PROPERTIES='//itoa(np)// &
        ' reals and '//'I PROPERTIES='//itoa(nj)//' integers, '//itoa(n)//' values given')
      return
    end if
    if (ctx%model%n_uelprop == size(ctx%model%uelprops)) then
      allocate (tmp(2 * size(ctx%model%uelprops)))
      tmp(1:ctx%model%n_uelprop) = ctx%model%uelprops(1:ctx%model%n_uelprop)
      call move_alloc(tmp, ctx%model%uelprops)
    end if
    ip = ctx%model%n_uelprop + 1
    allocate (ctx%model%uelprops(ip)%props(np), ctx%model%uelprops(ip)%jprops(nj))
    do k = 1, np
      if (.not. ctx_get_real(ctx, ir + 1, f(k), r)) return
      ctx%model%uelprops(ip)%props(k) = r
    end do
    do k = 1, nj
      if (.not. ctx_get_int(ctx, ir + 1, f(np + k), jv)) then
        ctx%errmsg = ctx%errmsg//' (integer property '//itoa(k)//')'
        return
      end if
      ctx%model%uelprops(ip)%jprops(k) = jv
    end do
    associate (model => ctx%model)
      model%n_uelprop = ip
      model%uelprops(ip)%pos = ctx_pos(ctx, min(ir + 1, ir_next - 1))
      if (.not. allocated(model%elem_uelprop)) then
        allocate (model%elem_uelprop(size(model%elem_id)))
        model%elem_uelprop = 0
      end if
      if (size(model%elem_uelprop) < model%nelem) call grow_int(model%elem_uelprop, model%nelem)
      do k = 1, model%elsets(iset)%n
        ie = find_elem_raw(ctx, -model%elsets(iset)%elems(k))
        model%elem_uelprop(ie) = ip
      end do
    end associate
  end subroutine read_uel_property

  !> Element index of a user element id while reading (linear search only in *UEL PROPERTY).
  integer function find_elem_raw(ctx, id) result(ie)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: id                !< user element id
    do ie = 1, ctx%model%nelem
      if (ctx%model%elem_id(ie) == id) return
    end do
    ie = 0
  end function find_elem_raw

end module deck_user_elements
