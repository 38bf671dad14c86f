!> The prescribed conditions in force, per dof (*BOUNDARY): which dofs are prescribed, their magnitude, amplitude,
!> kind (displacement, TYPE=VELOCITY, USER), and the values a step's ramps start from; their propagation from step
!> to step (inherited boundaries hold the value reached, OP=NEW removes all but the model-data ones, Abaqus) and
!> their values at the end of an increment (amplitude, ramp, velocity x DTIME, the user subroutine DISP).
module boundary_table
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t, boundary_t, amplitude_factor, model_dof
  use increment, only: increment_t, increment_end
  use node_rotations, only: node_rotation_t, node_vector_global
  use user_routines, only: user_routines_t
  implicit none
  private
  public :: boundary_table_t, boundary_table_init, boundary_apply, boundary_step_begin, boundary_prescribe
  public :: boundary_rates_update

  !> Per dof (ndof): the prescribed condition in force.
  type :: boundary_table_t
    logical, allocatable :: on(:)         !< the dof is prescribed
    logical, allocatable :: init(:)       !< prescribed by an initial *BOUNDARY (model data)
    logical, allocatable :: vel(:)        !< the value is a velocity (*BOUNDARY, TYPE=VELOCITY)
    logical, allocatable :: user(:)       !< the value comes from the user subroutine DISP (*BOUNDARY, USER)
    real(dp), allocatable :: val(:)       !< magnitude of the prescribed value
    integer, allocatable :: amp(:)        !< its amplitude (0: the step's ramp)
    real(dp), allocatable :: rate(:)      !< a velocity's value in the last converged increment (the next step's)
    real(dp), allocatable :: u_start(:)   !< displacement at the start of the step (start of the ramps)
  end type boundary_table_t

contains

  !> No prescribed dofs (before the model data's boundaries).
  pure subroutine boundary_table_init(bc, ndof)
    type(boundary_table_t), intent(out) :: bc  !< the table
    integer, intent(in) :: ndof                !< dofs of the model
    allocate (bc%on(ndof), bc%init(ndof), bc%vel(ndof), bc%user(ndof), bc%val(ndof), bc%amp(ndof), bc%rate(ndof), &
      bc%u_start(ndof))
    bc%on = .false.
    bc%init = .false.
    bc%vel = .false.
    bc%user = .false.
    bc%val = 0.0_dp
    bc%amp = 0
    bc%rate = 0.0_dp
    bc%u_start = 0.0_dp
  end subroutine boundary_table_init

  !> The *BOUNDARY definitions list(1:n) in deck order (the last one for a dof wins; dofs a node does not have are
  !> skipped: model_dof); initial: model data.
  pure subroutine boundary_apply(bc, list, n, model, initial)
    type(boundary_table_t), intent(inout) :: bc  !< the table
    type(boundary_t), intent(in) :: list(:)      !< definitions
    integer, intent(in) :: n                     !< definitions in use
    type(model_t), intent(in) :: model           !< the model (its dofs)
    logical, intent(in) :: initial               !< model data (kept by OP=NEW)
    integer :: k, a, d, dof, j
    do k = 1, n
      do a = 1, size(list(k)%nodes)
        do j = list(k)%first_dof, list(k)%last_dof + 3
          ! the dof range, then the rotations of a type (ENCASTRE, XSYMM, ...)
          d = j
          if (j > list(k)%last_dof) d = list(k)%rot_dofs(j - list(k)%last_dof)
          dof = 0
          if (d > 0) dof = model_dof(model, list(k)%nodes(a), d)
          if (dof == 0) cycle
          bc%on(dof) = .true.
          bc%val(dof) = list(k)%value
          ! FIXED: the value at the start of the step (u_start, set before a step's boundaries are applied)
          if (list(k)%fixed) bc%val(dof) = bc%u_start(dof)
          bc%amp(dof) = list(k)%amplitude
          bc%vel(dof) = list(k)%velocity
          bc%user(dof) = list(k)%user
          if (initial) bc%init(dof) = .true.
        end do
      end do
    end do
  end subroutine boundary_apply

  !> Start of step st from the converged displacement u_conv: inherited boundaries keep the value reached (a
  !> velocity the velocity reached, constant in this step), OP=NEW removes those of earlier steps, then the step's
  !> own. released: the dofs whose boundary this step removed (their reactions become decaying loads, step_loads).
  pure subroutine boundary_step_begin(bc, st, model, u_conv, released)
    type(boundary_table_t), intent(inout) :: bc  !< the table
    type(step_t), intent(in) :: st               !< the step beginning
    type(model_t), intent(in) :: model           !< the model (its dofs)
    real(dp), intent(in) :: u_conv(:)            !< converged displacement (end of the previous step)
    logical, intent(out) :: released(:)          !< (ndof) boundary removed by this step
    logical :: was_on(size(bc%on))
    bc%u_start = u_conv
    where (bc%on .and. .not. bc%init .and. .not. bc%vel)
      bc%val = u_conv
      bc%amp = 0
    end where
    where (bc%on .and. bc%vel)
      bc%val = bc%rate
      bc%amp = 0
    end where
    if (st%op_new) where (.not. bc%init) bc%vel = .false.
    was_on = bc%on
    if (st%op_new) where (.not. bc%init) bc%on = .false.
    call boundary_apply(bc, st%bcs, st%nbc, model, .false.)
    released = was_on .and. .not. bc%on
  end subroutine boundary_step_begin

  !> The prescribed dofs of u at their values at the end of increment inc (the other dofs untouched). u_conv: the
  !> converged displacement (velocity boundaries; DISP's COORDS under NLGEOM), nr the *TRANSFORM systems.
  subroutine boundary_prescribe(bc, model, inc, u_conv, nr, routines, prescribed, u)
    type(boundary_table_t), intent(in) :: bc       !< the table
    type(model_t), intent(in) :: model             !< the model
    type(increment_t), intent(in) :: inc           !< the increment
    real(dp), intent(in) :: u_conv(:)              !< converged displacement
    type(node_rotation_t), intent(in) :: nr        !< local node systems
    type(user_routines_t), intent(in) :: routines  !< DISP
    logical, intent(in) :: prescribed(:)           !< (ndof) dofs to set
    real(dp), intent(inout) :: u(:)                !< (ndof) displacement
    integer :: i
    real(dp) :: t
    t = increment_end(inc)
    do i = 1, size(u)
      if (.not. prescribed(i)) cycle
      if (bc%vel(i)) then
        ! TYPE=VELOCITY: u = u of the last converged increment + v(t) dt, v a STEP unless an amplitude is given
        u(i) = u_conv(i) + velocity_value(bc, model, i, t, inc%t_total0) * inc%dt
        cycle
      end if
      if (bc%amp(i) > 0) then
        u(i) = amplitude_factor(model%amplitudes(bc%amp(i)), t, inc%t_total0) * bc%val(i)
      else if (model%steps(inc%step)%amp_step) then
        u(i) = bc%val(i)
      else
        ! a linear ramp from the step-start value (Abaqus)
        u(i) = bc%u_start(i) + (t / inc%period) * (bc%val(i) - bc%u_start(i))
      end if
      if (bc%user(i)) u(i) = user_disp(model, inc, u_conv, nr, routines, i, t, u(i))
    end do
  end subroutine boundary_prescribe

  !> After a converged increment: the velocity each velocity boundary has at its end (a later step keeps it).
  pure subroutine boundary_rates_update(bc, model, inc)
    type(boundary_table_t), intent(inout) :: bc  !< the table
    type(model_t), intent(in) :: model           !< the model
    type(increment_t), intent(in) :: inc         !< the converged increment
    integer :: i
    do i = 1, size(bc%vel)
      if (bc%vel(i)) bc%rate(i) = velocity_value(bc, model, i, increment_end(inc), inc%t_total0)
    end do
  end subroutine boundary_rates_update

  !> Prescribed velocity of dof at step time t: amplitude * value, else the value (Abaqus' default for velocity
  !> boundaries in a static step is a STEP function whatever *STEP, AMPLITUDE says).
  pure real(dp) function velocity_value(bc, model, dof, t, t_total0) result(v)
    type(boundary_table_t), intent(in) :: bc  !< the table
    type(model_t), intent(in) :: model        !< the model (amplitudes)
    integer, intent(in) :: dof                !< the dof
    real(dp), intent(in) :: t                 !< step time
    real(dp), intent(in) :: t_total0          !< total time at the start of the step
    v = bc%val(dof)
    if (bc%amp(dof) > 0) v = amplitude_factor(model%amplitudes(bc%amp(dof)), t, t_total0) * bc%val(dof)
  end function velocity_value

  !> *BOUNDARY, USER: the value of DISP for dof at step time t (the end of the increment), U(1) passed in as v;
  !> COORDS the node's coordinates at the start of the increment (current ones under NLGEOM); JDOF in the node's
  !> *TRANSFORM system where it has one. NOEL = 0 (a node's boundary).
  real(dp) function user_disp(model, inc, u_conv, nr, routines, dof, t, v) result(w)
    type(model_t), intent(in) :: model             !< the model
    type(increment_t), intent(in) :: inc           !< the increment (KSTEP, KINC, DTIME)
    real(dp), intent(in) :: u_conv(:)              !< converged displacement
    type(node_rotation_t), intent(in) :: nr        !< local node systems
    type(user_routines_t), intent(in) :: routines  !< DISP
    integer, intent(in) :: dof                     !< the dof
    real(dp), intent(in) :: t, v                   !< step time, the value before DISP
    real(dp) :: c_u(3), c_time(3), c_coords(3)
    integer :: c_kstep, c_kinc, c_node, c_noel, c_jdof, nd
    nd = (dof - 1) / model%ndim + 1
    c_u = [v, 0.0_dp, 0.0_dp]
    c_time = [t, inc%t_total0 + t, inc%dt]
    c_coords = model%x(:, nd)
    if (inc%nlgeom) c_coords(1:model%ndim) = c_coords(1:model%ndim) + node_vector_global(nr, u_conv, nd)
    c_kstep = inc%step
    c_kinc = inc%kinc
    c_node = model%node_id(nd)
    c_noel = 0
    c_jdof = dof - (nd - 1) * model%ndim
    call routines%disp(c_u, c_kstep, c_kinc, c_time, c_node, c_noel, c_jdof, c_coords)
    w = c_u(1)
  end function user_disp

end module boundary_table
