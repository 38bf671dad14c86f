!> The analysis state: everything a continuation of the analysis needs, between two converged increments (the
!> "states" of OpenFAST's split by role, against the model's parameters and the solver's working data). Where the
!> analysis stands (step, increment, times, increment control), the prescribed conditions in force (boundary_table),
!> every load and predefined field with its propagation state (step_loads, distributed_loads), the converged
!> solution (displacement, element states, temperatures and field variables) and what the next increment takes
!> from the last one (its change for the extrapolation, its reactions and forces for the energy balance and the
!> released reactions). One type, held by the analysis (analysis_core) and written and read whole by the restart
!> file (restart_file): a continuation starts from exactly the state the uninterrupted run had. A distributed run's
!> process holds its own elements' states only.
module analysis_state
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, model_elements_leave
  use step_control, only: step_control_t
  use boundary_table, only: boundary_table_t, boundary_table_init, boundary_apply, boundary_step_begin
  use step_loads, only: loads_t, loads_init, loads_step_begin, initial_temperatures, initial_fields
  use element_state, only: elem_state_t
  implicit none
  private
  public :: analysis_state_t, progress_t, last_increment_t, analysis_state_init, analysis_state_step_begin

  !> Where the analysis stands after its last converged increment.
  type :: progress_t
    integer :: step = 0                   !< step of the last converged increment (0: none yet)
    integer :: kinc = 0                   !< its increment number in the step
    integer :: kinc_total = 0             !< converged increments of the analysis
    real(dp) :: t_total0 = 0.0_dp         !< total time at the start of the step
    type(step_control_t) :: sc            !< increment control (step time, next increment, growth state)
    real(dp) :: q_sum = 0.0_dp            !< sum of the step's converged increments' typical forces (q_avg)
    integer :: reuse_count = 0            !< modified Newton: solves with the current factors
  end type progress_t

  !> The last converged increment, as the next one uses it (and the one before it, for EXTRAPOLATION=PARABOLIC).
  type :: last_increment_t
    real(dp) :: dt = 0.0_dp               !< its size (0: no extrapolation, as at the start of a step)
    real(dp), allocatable :: du(:)        !< (ndof) its displacement change (extrapolation)
    real(dp) :: dt_before = 0.0_dp        !< the size of the increment before it (0: none in this step)
    real(dp), allocatable :: du_before(:) !< (ndof) that increment's displacement change
    real(dp), allocatable :: rf(:)        !< (ndof) its reactions (energy balance; released by OP=NEW)
    real(dp), allocatable :: fext(:)      !< (ndof) its external and distributed-load forces (energy balance)
    real(dp), allocatable :: fcl(:)       !< (ndof) its concentrated loads (the next step's inherited loads)
    !> (ndof) the forces the elements the next step removes exert on the rest at the end of this step, which that
    !> step ramps down (*MODEL CHANGE, REMOVE; model_change); 0 elsewhere
    real(dp), allocatable :: fremove(:)
  end type last_increment_t

  !> Everything a continuation needs (restart_file writes and reads it whole).
  type :: analysis_state_t
    type(progress_t) :: progress              !< step, increment, times, increment control
    type(boundary_table_t) :: bc              !< prescribed conditions in force
    type(loads_t) :: loads                    !< loads and predefined fields of the step
    type(last_increment_t) :: last            !< the last converged increment
    real(dp), allocatable :: u_conv(:)        !< (ndof) converged displacement
    !> (nelem) converged element states; a distributed process allocates its own elements' only (state_gather
    !> brings another's where output needs it)
    type(elem_state_t), allocatable :: conv(:)
    real(dp), allocatable :: temp_start(:)    !< (nnode) temperatures at the start of the increment
    real(dp), allocatable :: field_start(:)   !< (nfield*nnode) field variables at its start (n of node a at
                                              !< (a-1)*nfield+n)
    ! *MODEL CHANGE and *DEPVAR, DELETE= (model_change; size 0 in a model without either)
    logical, allocatable :: active(:)         !< (nelem) the element is in the model (not removed, not deleted)
    logical, allocatable :: shifted(:)        !< (nelem) reactivated strain-free: its reference is X + u_ref
    real(dp), allocatable :: u_ref(:)         !< (element dofs, elem_ptr layout) the displacement at reactivation
  end type analysis_state_t

contains

  !> The state before the first increment of an analysis with ndof dofs: the model data's boundaries, no loads,
  !> the initial temperatures and field variables, zero displacement. The element states (conv) are allocated by
  !> the analysis (analysis_core), which knows their shapes and owners.
  pure subroutine analysis_state_init(s, model, ndof)
    type(analysis_state_t), intent(inout) :: s  !< state (conv left as it is)
    type(model_t), intent(in) :: model          !< the model
    integer, intent(in) :: ndof                 !< dofs of the model
    s%progress = progress_t()
    call boundary_table_init(s%bc, ndof)
    call boundary_apply(s%bc, model%initial_bcs, model%n_initial_bc, model, .true.)
    call loads_init(s%loads, model, ndof)
    s%last%dt = 0.0_dp
    s%last%du = spread(0.0_dp, 1, ndof)
    s%last%dt_before = 0.0_dp
    s%last%du_before = s%last%du
    s%last%rf = s%last%du
    s%last%fext = s%last%du
    s%last%fcl = s%last%du
    s%last%fremove = s%last%du
    s%u_conv = s%last%du
    allocate (s%active(merge(model%nelem, 0, model_elements_leave(model))))
    s%active = .true.
    allocate (s%shifted(size(s%active)))
    s%shifted = .false.
    s%temp_start = initial_temperatures(model)
    s%field_start = initial_fields(model)
  end subroutine analysis_state_init

  !> Start of step is: the boundaries (inherited ones hold the value reached, OP=NEW removes them), the loads and
  !> predefined fields (inherited at the values reached; a removed boundary's reaction becomes a load that decays
  !> over the step). stat /= 0 (errmsg): a distributed load on a face the element lacks.
  subroutine analysis_state_step_begin(s, model, is, stat, errmsg)
    type(analysis_state_t), intent(inout) :: s           !< state
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: is                            !< the step beginning
    integer, intent(out) :: stat                         !< 0 ok, 2 input error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    logical :: released(size(s%u_conv))
    call boundary_step_begin(s%bc, model%steps(is), model, s%u_conv, released)
    call loads_step_begin(s%loads, model, is, s%progress%t_total0, s%last%fcl, merge(s%last%rf, 0.0_dp, released), &
      s%temp_start, s%field_start, stat, errmsg)
  end subroutine analysis_state_step_begin

end module analysis_state
