!> Initial-state keywords of the deck reader: *INITIAL CONDITIONS, TYPE=STRESS (continuum elements: the stress
!> components in Abaqus order, constant over the element) and TYPE=SOLUTION (UMAT state variables, all NSTATV
!> values of an element on one logical data line). Temperatures and fields are not supported (errors).
module deck_fields
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_normalize, deck_has_param
  use model_types, only: initial_condition_t, init_stress, init_solution, cload_t, &
    model_find_amplitude
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_continued, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_elset, &
    ctx_fail, ctx_pos, ctx_allow_params, ctx_split, ctx_get_real, ctx_need_step
  implicit none
  private
  public :: read_initial_conditions, read_temperature

contains

  !> *INITIAL CONDITIONS, TYPE=STRESS|SOLUTION: element or element set, then the values.
  subroutine read_initial_conditions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(initial_condition_t) :: ic, empty
    type(initial_condition_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n, k, kind, id, last, m
    character(len=flen), allocatable :: g(:)
    call ctx_allow_params(ctx, [character(len=8) :: 'TYPE'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    select case (v)
    case ('TEMPERATURE')
      call read_node_values(ctx, ctx%model%temp_inits, ctx%model%ntemp_init, 0)
      return
    case ('STRESS')
      kind = init_stress
    case ('SOLUTION')
      kind = init_solution
    case default
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (TEMPERATURE, STRESS, SOLUTION)')
      return
    end select
    i = ctx%ir
    do while (i < ctx%ir_next - 1)
      i = i + 1
      call ctx_split(ctx, i, f, n)
      ic = empty
      ic%kind = kind
      ic%pos = ctx_pos(ctx, i)
      if (kind == init_solution) then
        ! one logical line per element or set: a line ending with a comma continues on the next
        do while (ctx_continued(ctx, i))
          i = i + 1
          call ctx_split(ctx, i, g, m)
          f = [f(1:n), g(1:m)]
          n = n + m
        end do
      end if
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
      if (ctx_is_label(ctx, f(1))) then
        if (.not. ctx_get_label(ctx, i, f(1), .false., id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'element ids must be positive, got '//itoa(id))
          return
        end if
        ic%elems = [-id]
      else
        ic%elset = ctx_find_elset(ctx, f(1))
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

  !> *TEMPERATURE[, AMPLITUDE=][, OP=MOD] (history data): node or node set, temperature.
  subroutine read_temperature(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: iamp
    character(len=:), allocatable :: v
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'OP'))
    if (len(v) > 0 .and. v /= 'MOD') then
      call ctx_fail(ctx, ctx%ir, 'only OP=MOD is supported (temperatures stay until re-specified)')
      return
    end if
    iamp = 0
    if (deck_has_param(ctx%params, 'AMPLITUDE')) then
      iamp = model_find_amplitude(ctx%model, deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
      if (iamp == 0) then
        call ctx_fail(ctx, ctx%ir, 'undefined amplitude '//deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
        return
      end if
    end if
    call read_node_values(ctx, ctx%model%steps(ctx%istep)%temps, ctx%model%steps(ctx%istep)%ntemp, iamp)
  end subroutine read_temperature

  !> Data lines "node or node set, value" appended to list (node ids negative until finish_model; dof = 1).
  subroutine read_node_values(ctx, list, nlist, iamp)
    type(deck_context_t), intent(inout) :: ctx        !< reader state
    type(cload_t), allocatable, intent(inout) :: list(:) !< list
    integer, intent(inout) :: nlist                   !< entries in use
    integer, intent(in) :: iamp                       !< amplitude
    type(cload_t) :: cl, empty
    type(cload_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, id, iset
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      cl = empty
      cl%dof = 1
      cl%amplitude = iamp
      cl%pos = ctx_pos(ctx, i)
      if (n < 2) then
        call ctx_fail(ctx, i, 'expected: node or node set, temperature')
        return
      end if
      if (n > 2) then
        if (any(len_trim(f(3:n)) > 0)) then
          call ctx_fail(ctx, i, 'too many fields (node or node set, temperature; no field variables)')
          return
        end if
      end if
      if (ctx_is_label(ctx, f(1))) then
        if (.not. ctx_get_label(ctx, i, f(1), .true., id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
          return
        end if
        cl%nodes = [-id]
      else
        iset = ctx_find_nset(ctx, f(1))
        if (iset == 0) then
          call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(1)))
          return
        end if
        cl%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
      end if
      if (.not. ctx_get_real(ctx, i, f(2), cl%value)) return
      if (.not. allocated(list)) allocate (list(4))
      if (nlist == size(list)) then
        allocate (tmp(2 * nlist))
        tmp(1:nlist) = list(1:nlist)
        call move_alloc(tmp, list)
      end if
      nlist = nlist + 1
      list(nlist) = cl
    end do
  end subroutine read_node_values

end module deck_fields
