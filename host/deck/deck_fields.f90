!> Initial-state keywords of the deck reader: *INITIAL CONDITIONS, TYPE=STRESS (continuum elements: the stress
!> components in Abaqus order, constant over the element) and TYPE=SOLUTION (UMAT state variables, all NSTATV
!> values of an element on one logical data line). Temperatures and fields are not supported (errors).
module deck_fields
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_normalize
  use model_types, only: initial_condition_t, init_stress, init_solution, model_find_elset
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_pos, ctx_allow_params, ctx_split, ctx_get_real, &
    ctx_get_int
  implicit none
  private
  public :: read_initial_conditions

contains

  !> *INITIAL CONDITIONS, TYPE=STRESS|SOLUTION: element or element set, then the values.
  subroutine read_initial_conditions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(initial_condition_t) :: ic, empty
    type(initial_condition_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n, k, kind, id, last
    call ctx_allow_params(ctx, [character(len=8) :: 'TYPE'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    select case (v)
    case ('STRESS')
      kind = init_stress
    case ('SOLUTION')
      kind = init_solution
    case default
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (STRESS, SOLUTION)')
      return
    end select
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      ic = empty
      ic%kind = kind
      ic%pos = ctx_pos(ctx, i)
      last = n
      do while (last > 1)
        if (len_trim(f(last)) > 0) exit
        last = last - 1
      end do
      if (last < 2) then
        call ctx_fail(ctx, i, 'expected: element or element set, then the values')
        return
      end if
      if (kind == init_stress .and. last > 7) then
        call ctx_fail(ctx, i, 'at most 6 stress components (S11, S22, S33, S12, S13, S23)')
        return
      end if
      if (verify(trim(f(1)), '0123456789+-') == 0) then
        if (.not. ctx_get_int(ctx, i, f(1), id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'element ids must be positive, got '//itoa(id))
          return
        end if
        ic%elems = [-id]
      else
        ic%elset = model_find_elset(ctx%model, deck_normalize(f(1)))
        if (ic%elset == 0) then
          call ctx_fail(ctx, i, 'undefined element set '//deck_normalize(f(1)))
          return
        end if
        allocate (ic%elems(0))
      end if
      allocate (ic%values(last - 1))
      ic%values = 0.0_dp
      do k = 2, last
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_real(ctx, i, f(k), ic%values(k - 1))) return
      end do
      if (.not. allocated(ctx%model%inits)) allocate (ctx%model%inits(4))
      if (ctx%model%ninit == size(ctx%model%inits)) then
        allocate (tmp(2 * ctx%model%ninit))
        tmp(1:ctx%model%ninit) = ctx%model%inits(1:ctx%model%ninit)
        call move_alloc(tmp, ctx%model%inits)
      end if
      ctx%model%ninit = ctx%model%ninit + 1
      ctx%model%inits(ctx%model%ninit) = ic
    end do
  end subroutine read_initial_conditions

end module deck_fields
