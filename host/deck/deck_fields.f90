!> Initial-state keywords of the deck reader: *INITIAL CONDITIONS, TYPE=STRESS (continuum elements: the stress
!> components in Abaqus order, constant over the element) and TYPE=SOLUTION (UMAT state variables, all NSTATV
!> values of an element on one logical data line), TYPE=TEMPERATURE and TYPE=FIELD, VARIABLE=n (nodal values); the
!> history keywords *TEMPERATURE and *FIELD, VARIABLE=n (one reader: node or node set, value).
module deck_fields
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_normalize, deck_has_param
  use model_types, only: initial_condition_t, init_stress, init_solution, cload_t, &
    model_find_amplitude
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_continued, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_elset, &
    ctx_fail, ctx_pos, ctx_allow_params, ctx_split, ctx_get_real, ctx_need_step, ctx_param_int, ctx_warn
  implicit none
  private
  public :: read_initial_conditions, read_temperature, read_field

contains

  !> *INITIAL CONDITIONS, TYPE=STRESS|SOLUTION: element or element set, then the values.
  subroutine read_initial_conditions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(initial_condition_t) :: ic, empty
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n, k, kind, id, last, m
    character(len=flen), allocatable :: g(:)
    call ctx_allow_params(ctx, [character(len=8) :: 'TYPE', 'VARIABLE', 'USER'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    if (deck_has_param(ctx%params, 'USER')) then
      ! Abaqus calls SIGINI (STRESS) and SDVINI (SOLUTION) at every material point; HARDINI (HARDENING), ... need
      ! materials ldfcz does not have
      call read_user_initial_conditions(ctx, v)
      return
    end if
    if (v == 'PLASTIC STRAIN') then
      ! Abaqus applies initial plastic strains to its built-in elastic-plastic materials; ldfcz has none: *ELASTIC is
      ! linear elastic, and Abaqus passes no plastic strain to a UMAT (its plastic state lives in STATEV)
      call ctx_fail(ctx, ctx%ir, 'TYPE=PLASTIC STRAIN needs an elastic-plastic material, which ldfcz does not '// &
        'have (*ELASTIC is linear elastic; a UMAT receives no initial plastic strain from Abaqus: give its '// &
        'plastic state in its state variables with TYPE=SOLUTION)')
      return
    end if
    if (v /= 'FIELD' .and. deck_has_param(ctx%params, 'VARIABLE')) then
      call ctx_fail(ctx, ctx%ir, 'VARIABLE= only with TYPE=FIELD')
      return
    end if
    select case (v)
    case ('TEMPERATURE')
      call read_node_values(ctx, ctx%model%temp_inits, ctx%model%ntemp_init, 0, 1)
      return
    case ('FIELD')
      k = field_variable(ctx)
      if (ctx%stat /= 0) return
      call read_node_values(ctx, ctx%model%field_inits, ctx%model%nfield_init, 0, k)
      return
    case ('STRESS')
      kind = init_stress
    case ('SOLUTION')
      kind = init_solution
    case default
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (TEMPERATURE, FIELD, STRESS, SOLUTION; PLASTIC '// &
        'STRAIN needs a plastic material)')
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
      call push_initial_condition(ctx, ic)
    end do
  end subroutine read_initial_conditions

  !> *INITIAL CONDITIONS, TYPE=STRESS or SOLUTION, USER (no data lines): the user library's SIGINI or SDVINI gives
  !> the values at every point of every continuum element (analysis_core, apply_initial_conditions).
  subroutine read_user_initial_conditions(ctx, v)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: v           !< TYPE=
    type(initial_condition_t) :: ic
    select case (v)
    case ('STRESS')
      ic%kind = init_stress
    case ('SOLUTION')
      ic%kind = init_solution
    case default
      call ctx_fail(ctx, ctx%ir, 'USER with TYPE='//v//' is not supported (TYPE=STRESS: SIGINI, TYPE=SOLUTION: '// &
        'SDVINI)')
      return
    end select
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, 'no data lines with USER (the routine gives the values at every point)')
      return
    end if
    ic%user = .true.
    ic%pos = ctx_pos(ctx, ctx%ir)
    allocate (ic%elems(0), ic%values(0))
    call push_initial_condition(ctx, ic)
  end subroutine read_user_initial_conditions

  !> Appends an initial condition to the model's list, doubling its capacity when full.
  subroutine push_initial_condition(ctx, ic)
    type(deck_context_t), intent(inout) :: ctx      !< reader state
    type(initial_condition_t), intent(in) :: ic     !< the condition
    type(initial_condition_t), allocatable :: tmp(:)
    if (.not. allocated(ctx%model%inits)) allocate (ctx%model%inits(4))
    if (ctx%model%ninit == size(ctx%model%inits)) then
      allocate (tmp(2 * ctx%model%ninit))
      tmp(1:ctx%model%ninit) = ctx%model%inits(1:ctx%model%ninit)
      call move_alloc(tmp, ctx%model%inits)
    end if
    ctx%model%ninit = ctx%model%ninit + 1
    ctx%model%inits(ctx%model%ninit) = ic
  end subroutine push_initial_condition

  !> *TEMPERATURE[, AMPLITUDE=][, OP=MOD|NEW] (history data): node or node set, temperature.
  subroutine read_temperature(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical :: op_new
    integer :: iamp
    call read_predefined_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP'], iamp, op_new)
    if (ctx%stat /= 0) return
    if (op_new) ctx%model%steps(ctx%istep)%field_new = [ctx%model%steps(ctx%istep)%field_new, 0]
    call read_node_values(ctx, ctx%model%steps(ctx%istep)%temps, ctx%model%steps(ctx%istep)%ntemp, iamp, 1)
  end subroutine read_temperature

  !> *FIELD, VARIABLE=n[, AMPLITUDE=][, OP=MOD|NEW] (history data): node or node set, value of field variable n.
  !> OP=NEW is recorded per variable (step%field_new; 0 stands for the temperature).
  subroutine read_field(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical :: op_new
    integer :: iamp, k
    call read_predefined_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP', 'VARIABLE'], iamp, op_new)
    if (ctx%stat /= 0) return
    k = field_variable(ctx)
    if (ctx%stat /= 0) return
    if (op_new) ctx%model%steps(ctx%istep)%field_new = [ctx%model%steps(ctx%istep)%field_new, k]
    call read_node_values(ctx, ctx%model%steps(ctx%istep)%fields, ctx%model%steps(ctx%istep)%nfielddef, iamp, k)
  end subroutine read_field

  !> The parameters *TEMPERATURE and *FIELD share: inside a step, AMPLITUDE= (an amplitude defined before), OP=MOD
  !> (default) or NEW.
  subroutine read_predefined_params(ctx, allowed, iamp, op_new)
    type(deck_context_t), intent(inout) :: ctx      !< reader state
    character(len=*), intent(in) :: allowed(:)      !< parameters the keyword accepts
    integer, intent(out) :: iamp                    !< amplitude index (0: the step's default)
    logical, intent(out) :: op_new                  !< OP=NEW
    character(len=:), allocatable :: v
    iamp = 0
    op_new = .false.
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, allowed)
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'OP'))
    if (len(v) > 0 .and. v /= 'MOD' .and. v /= 'NEW') then
      call ctx_fail(ctx, ctx%ir, 'OP must be MOD or NEW')
      return
    end if
    op_new = v == 'NEW'
    if (.not. allocated(ctx%model%steps(ctx%istep)%field_new)) allocate (ctx%model%steps(ctx%istep)%field_new(0))
    if (deck_has_param(ctx%params, 'AMPLITUDE')) then
      iamp = model_find_amplitude(ctx%model, deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
      if (iamp == 0) then
        call ctx_fail(ctx, ctx%ir, 'undefined amplitude '//deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
        return
      end if
    end if
  end subroutine read_predefined_params

  !> VARIABLE=n (n >= 1, default 1) of TYPE=FIELD and *FIELD; the model's field count grows to n.
  integer function field_variable(ctx) result(k)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    ! VARIABLE= defaults to 1 (the Keywords Reference gives *FIELD's default so; for *INITIAL CONDITIONS,
    ! TYPE=FIELD the same default is inferred: a published deck without it completed in Abaqus)
    k = ctx_param_int(ctx, 'VARIABLE', 1)
    if (ctx%stat /= 0) return
    if (k < 1) then
      call ctx_fail(ctx, ctx%ir, 'VARIABLE must be 1 or more, got '//itoa(k))
      return
    end if
    ctx%model%nfield = max(ctx%model%nfield, k)
  end function field_variable

  !> Data lines "node or node set, value" appended to list (node ids negative until finish_model; dof = the
  !> temperature's 1 or the field variable number).
  subroutine read_node_values(ctx, list, nlist, iamp, dof)
    type(deck_context_t), intent(inout) :: ctx        !< reader state
    type(cload_t), allocatable, intent(inout) :: list(:) !< list
    integer, intent(inout) :: nlist                   !< entries in use
    integer, intent(in) :: iamp                       !< amplitude
    integer, intent(in) :: dof                        !< 1 (temperature) or the field variable
    type(cload_t) :: cl, empty
    type(cload_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, id, iset
    if (ctx%ir_next == ctx%ir + 1) call ctx_warn(ctx, ctx%ir, 'no data lines: no node gets a value here')
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      cl = empty
      cl%dof = dof
      cl%amplitude = iamp
      cl%pos = ctx_pos(ctx, i)
      if (n < 2) then
        call ctx_fail(ctx, i, 'expected: node or node set, value')
        return
      end if
      if (n > 2) then
        if (any(len_trim(f(3:n)) > 0)) then
          call ctx_fail(ctx, i, 'too many fields (node or node set, value)')
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
