!> Load keywords of the deck reader (history data): *CLOAD, concentrated nodal forces of fixed direction.
!> Distributed loads (*DLOAD, *DSLOAD) are not read yet: the dispatcher reports them as unsupported.
module deck_loads
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: cload_t, model_find_nset, model_find_amplitude
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_pos, ctx_allow_params, ctx_need_step, ctx_split, &
    ctx_get_real, ctx_get_int
  implicit none
  private
  public :: read_cload

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
      if (verify(trim(f(1)), '0123456789+-') == 0) then
        if (.not. ctx_get_int(ctx, i, f(1), id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
          return
        end if
        allocate (cl%nodes(1))
        cl%nodes(1) = -id  ! resolved in finish_model
      else
        iset = model_find_nset(ctx%model, deck_normalize(f(1)))
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
      if (cl%dof > 3) then
        call ctx_fail(ctx, i, 'dof '//itoa(cl%dof)//' (a moment) does not exist in ldfcz models: only the '// &
          'displacement dofs 1..3 carry forces')
        return
      end if
      if (len_trim(f(3)) > 0) then
        if (.not. ctx_get_real(ctx, i, f(3), cl%value)) return
      end if
      call push_cload(ctx%model%steps(istep)%cloads, ctx%model%steps(istep)%ncload, cl)
    end do
  end subroutine read_cload

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
