!> External nodal forces of the steps: the *CLOAD definitions in force per dof, their propagation from step to step
!> (OP=MOD keeps and modifies, OP=NEW removes), the step's default amplitude (*STEP, AMPLITUDE=RAMP|STEP) and the
!> forces released from removed loads and from boundaries removed by *BOUNDARY, OP=NEW, which go to zero over the
!> step (linearly with RAMP, at once with STEP), as Abaqus/Standard documents for prescribed conditions. The same
!> machinery carries the predefined fields (*TEMPERATURE, *FIELD); loads_t gathers every load of the analysis state
!> (with the distributed loads of distributed_loads) and evaluates them at the end of an increment.
module step_loads
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, amplitude_factor, cload_t, model_dof
  use distributed_loads, only: dload_state_t, dload_step_begin
  use increment, only: increment_t, increment_end
  implicit none
  private
  public :: load_state_t, load_state_init, load_step_begin, load_vector
  public :: loads_t, loads_init, loads_step_begin, loads_at_end, initial_temperatures, initial_fields

  !> Per dof: the load defined in the current step and the released force that decays over it.
  type :: load_state_t
    logical, allocatable :: on(:)        !< a concentrated load is defined on the dof
    real(dp), allocatable :: base(:)     !< its value at the start of the step (start of a RAMP)
    real(dp), allocatable :: target(:)   !< its magnitude in this step
    integer, allocatable :: amp(:)       !< its amplitude (0: the step's default)
    real(dp), allocatable :: released(:) !< force at the start of the step of removed loads and boundaries
  end type load_state_t

  !> Every load of the analysis in the current step (part of the analysis state: a restart continues them).
  type :: loads_t
    type(load_state_t) :: cload        !< (ndof) concentrated loads (*CLOAD) and released reactions
    type(load_state_t) :: temperature  !< (nnode) nodal temperatures (*TEMPERATURE)
    type(load_state_t) :: field        !< (nfield*nnode) field variables (*FIELD)
    type(dload_state_t) :: dload       !< distributed loads (*DLOAD, *DSLOAD)
  end type loads_t

contains

  !> No loads (before the first step).
  pure subroutine load_state_init(ls, ndof)
    type(load_state_t), intent(out) :: ls  !< load state
    integer, intent(in) :: ndof            !< dofs of the model
    allocate (ls%on(ndof), ls%base(ndof), ls%target(ndof), ls%amp(ndof), ls%released(ndof))
    ls%on = .false.
    ls%base = 0.0_dp
    ls%target = 0.0_dp
    ls%amp = 0
    ls%released = 0.0_dp
  end subroutine load_state_init

  !> Start of step is: f_now is the external force at the end of the previous step (zero before the first),
  !> reaction the reaction force (internal minus external force) of the dofs whose boundary this step removes
  !> (zero elsewhere). Loads not re-specified keep their value (OP=MOD) or are released (OP=NEW); the step's
  !> *CLOAD lines are applied in deck order (the last line for a node and dof wins).
  !> The same machinery carries the predefined fields: the nodal temperatures (*TEMPERATURE, stride 1) and the
  !> field variables (*FIELD, stride = the number of field variables, entry (node-1)*stride + n for variable n).
  !> Every node is on from the start with its initial value; OP=NEW returns the values of the components in
  !> new_comp to rest (their initial values) over the step, like any change (RAMP or STEP), instead of releasing them.
  pure subroutine load_step_begin(ls, f_now, reaction, list, n, op_new, stride, rest, new_comp, model)
    type(load_state_t), intent(inout) :: ls  !< load state
    real(dp), intent(in) :: f_now(:)         !< external force at the end of the previous step
    real(dp), intent(in) :: reaction(:)      !< reactions of the boundaries removed at this step's start
    type(cload_t), intent(in) :: list(:)     !< the step's definitions (*CLOAD lines)
    integer, intent(in) :: n                 !< definitions in use
    logical, intent(in) :: op_new            !< OP=NEW in this step
    integer, intent(in) :: stride            !< entries per node (the model dimension for forces)
    real(dp), intent(in), optional :: rest(:)    !< values removed entries return to (predefined fields)
    logical, intent(in), optional :: new_comp(:) !< (stride) the components OP=NEW applies to (all when absent)
    type(model_t), intent(in), optional :: model !< concentrated loads: the model's dofs (model_dof: moments at the
                                                 !< rotational dofs of a coupling's reference node)
    integer :: k, a, i
    logical :: removed(size(ls%on))
    ! inherited loads hold the value reached
    where (ls%on)
      ls%base = f_now
      ls%target = f_now
    end where
    ls%amp = 0
    ls%released = reaction
    if (op_new) then
      removed = ls%on
      if (present(new_comp)) then
        do i = 1, size(removed)
          removed(i) = removed(i) .and. new_comp(mod(i - 1, stride) + 1)
        end do
      end if
      if (present(rest)) then
        where (removed) ls%target = rest
      else
        where (removed)
          ls%released = ls%released + f_now
          ls%on = .false.
          ls%base = 0.0_dp
          ls%target = 0.0_dp
        end where
      end if
    end if
    do k = 1, n
      do a = 1, size(list(k)%nodes)
        i = (list(k)%nodes(a) - 1) * stride + list(k)%dof
        if (present(model)) i = model_dof(model, list(k)%nodes(a), list(k)%dof)
        if (.not. ls%on(i)) ls%base(i) = 0.0_dp
        ls%on(i) = .true.
        ls%target(i) = list(k)%value
        ls%amp(i) = list(k)%amplitude
      end do
    end do
  end subroutine load_step_begin

  !> External nodal forces at step time t of step is (which began at total time t_total0).
  pure subroutine load_vector(ls, model, is, t, t_total0, fext)
    type(load_state_t), intent(in) :: ls  !< load state of the step
    type(model_t), intent(in) :: model    !< the model
    integer, intent(in) :: is             !< step number
    real(dp), intent(in) :: t             !< step time
    real(dp), intent(in) :: t_total0      !< total time at the start of the step
    real(dp), intent(out) :: fext(:)      !< (ndof) external forces
    real(dp) :: s
    integer :: i
    associate (st => model%steps(is))
      s = min(1.0_dp, max(0.0_dp, t / st%period))
      if (st%amp_step) s = 1.0_dp
      do i = 1, size(fext)
        fext(i) = (1.0_dp - s) * ls%released(i)
        if (.not. ls%on(i)) cycle
        if (ls%amp(i) > 0) then
          fext(i) = fext(i) + amplitude_factor(model%amplitudes(ls%amp(i)), t, t_total0) * ls%target(i)
        else
          fext(i) = fext(i) + ls%base(i) + s * (ls%target(i) - ls%base(i))
        end if
      end do
    end associate
  end subroutine load_vector

  !> Nodal temperatures before the first step (*INITIAL CONDITIONS, TYPE=TEMPERATURE in deck order; 0 elsewhere).
  pure function initial_temperatures(model) result(temp)
    type(model_t), intent(in) :: model  !< the model
    real(dp) :: temp(model%nnode)
    integer :: k
    temp = 0.0_dp
    do k = 1, model%ntemp_init
      temp(model%temp_inits(k)%nodes) = model%temp_inits(k)%value
    end do
  end function initial_temperatures

  !> Field variables before the first step (*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=n in deck order; 0
  !> elsewhere), variable n of node a at (a-1)*nfield+n.
  pure function initial_fields(model) result(field)
    type(model_t), intent(in) :: model  !< the model
    real(dp) :: field(model%nfield * model%nnode)
    integer :: k
    field = 0.0_dp
    do k = 1, model%nfield_init
      associate (fi => model%field_inits(k))
        field((fi%nodes - 1) * model%nfield + fi%dof) = fi%value
      end associate
    end do
  end function initial_fields

  !> No loads; every node at its initial temperature and field values until a *TEMPERATURE or *FIELD changes them.
  pure subroutine loads_init(loads, model, ndof)
    type(loads_t), intent(out) :: loads  !< the loads
    type(model_t), intent(in) :: model   !< the model
    integer, intent(in) :: ndof          !< dofs of the model
    call load_state_init(loads%cload, ndof)
    call load_state_init(loads%temperature, model%nnode)
    loads%temperature%on = .true.
    loads%temperature%base = initial_temperatures(model)
    loads%temperature%target = loads%temperature%base
    call load_state_init(loads%field, model%nfield * model%nnode)
    loads%field%on = .true.
    loads%field%base = initial_fields(model)
    loads%field%target = loads%field%base
  end subroutine loads_init

  !> Start of step is (at total time t_total0) for every load: f_cload the concentrated loads at the end of the
  !> previous step, reaction the reactions of the boundaries this step removes (they decay over the step), temp and
  !> field the predefined fields reached. *TEMPERATURE/*FIELD, OP=NEW (per variable, 0 the temperature) return
  !> them to their initial values. stat /= 0 (errmsg): a distributed load on a face the element lacks.
  subroutine loads_step_begin(loads, model, is, t_total0, f_cload, reaction, temp, field, stat, errmsg)
    type(loads_t), intent(inout) :: loads                !< the loads
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: is                            !< the step beginning
    real(dp), intent(in) :: t_total0                     !< total time at its start
    real(dp), intent(in) :: f_cload(:)                   !< (ndof) concentrated loads reached
    real(dp), intent(in) :: reaction(:)                  !< (ndof) reactions of removed boundaries (0 elsewhere)
    real(dp), intent(in) :: temp(:)                      !< (nnode) temperatures reached
    real(dp), intent(in) :: field(:)                     !< (nfield*nnode) field variables reached
    integer, intent(out) :: stat                         !< 0 ok, 2 input error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    logical :: field_comp(max(1, model%nfield))
    real(dp) :: no_release(size(temp))
    integer :: k
    no_release = 0.0_dp
    associate (st => model%steps(is))
      call load_step_begin(loads%cload, f_cload, reaction, st%cloads, st%ncload, st%cload_op_new, model%ndim, &
        model=model)
      field_comp = .false.
      if (allocated(st%field_new)) then
        do k = 1, model%nfield
          field_comp(k) = any(st%field_new == k)
        end do
        call load_step_begin(loads%temperature, temp, no_release, st%temps, st%ntemp, any(st%field_new == 0), &
          1, rest=initial_temperatures(model))
      else
        call load_step_begin(loads%temperature, temp, no_release, st%temps, st%ntemp, .false., 1)
      end if
      ! (predefined fields release nothing: OP=NEW returns them to rest)
      if (model%nfield > 0) call load_step_begin(loads%field, field, 0.0_dp * initial_fields(model), st%fields, &
        st%nfielddef, any(field_comp), model%nfield, rest=initial_fields(model), new_comp=field_comp)
    end associate
    call dload_step_begin(loads%dload, model, is, t_total0, stat, errmsg)
  end subroutine loads_step_begin

  !> The concentrated loads, temperatures and field variables at the end of increment inc (the distributed loads
  !> are evaluated by the elements: distributed_loads).
  pure subroutine loads_at_end(loads, model, inc, fext, temp, field)
    type(loads_t), intent(in) :: loads    !< the loads
    type(model_t), intent(in) :: model    !< the model
    type(increment_t), intent(in) :: inc  !< the increment
    real(dp), intent(out) :: fext(:)      !< (ndof) concentrated loads
    real(dp), intent(out) :: temp(:)      !< (nnode) temperatures
    real(dp), intent(out) :: field(:)     !< (nfield*nnode) field variables
    call load_vector(loads%cload, model, inc%step, increment_end(inc), inc%t_total0, fext)
    call load_vector(loads%temperature, model, inc%step, increment_end(inc), inc%t_total0, temp)
    call load_vector(loads%field, model, inc%step, increment_end(inc), inc%t_total0, field)
  end subroutine loads_at_end

end module step_loads
