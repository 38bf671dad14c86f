!> External nodal forces of the steps: the *CLOAD definitions in force per dof, their propagation from step to step
!> (OP=MOD keeps and modifies, OP=NEW removes), the step's default amplitude (*STEP, AMPLITUDE=RAMP|STEP) and the
!> forces released from removed loads and from boundaries removed by *BOUNDARY, OP=NEW, which go to zero over the
!> step (linearly with RAMP, at once with STEP), as Abaqus/Standard documents for prescribed conditions.
module step_loads
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, amplitude_factor, cload_t
  implicit none
  private
  public :: load_state_t, load_state_init, load_step_begin, load_vector

  !> Per dof: the load defined in the current step and the released force that decays over it.
  type :: load_state_t
    logical, allocatable :: on(:)        !< a concentrated load is defined on the dof
    real(dp), allocatable :: base(:)     !< its value at the start of the step (start of a RAMP)
    real(dp), allocatable :: target(:)   !< its magnitude in this step
    integer, allocatable :: amp(:)       !< its amplitude (0: the step's default)
    real(dp), allocatable :: released(:) !< force at the start of the step of removed loads and boundaries
  end type load_state_t

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
  pure subroutine load_step_begin(ls, f_now, reaction, list, n, op_new, stride, rest, new_comp)
    type(load_state_t), intent(inout) :: ls  !< load state
    real(dp), intent(in) :: f_now(:)         !< external force at the end of the previous step
    real(dp), intent(in) :: reaction(:)      !< reactions of the boundaries removed at this step's start
    type(cload_t), intent(in) :: list(:)     !< the step's definitions (*CLOAD lines)
    integer, intent(in) :: n                 !< definitions in use
    logical, intent(in) :: op_new            !< OP=NEW in this step
    integer, intent(in) :: stride            !< entries per node (the model dimension for forces)
    real(dp), intent(in), optional :: rest(:)    !< values removed entries return to (predefined fields)
    logical, intent(in), optional :: new_comp(:) !< (stride) the components OP=NEW applies to (all when absent)
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

end module step_loads
