!> The state of the increment loop of a static analysis (static_step) between two converged increments: where the
!> analysis stands (step, increment, counters, times, increment control), the boundary tables and the dof vectors
!> the next increment starts from (its prescribed ramp, the reactions and loads for the energy balance, the
!> extrapolation of the last converged change). One type, so that the restart file (restart_file) writes and reads
!> it whole and a continuation starts from exactly the state the uninterrupted run had; the element states and the
!> converged displacement live in analysis_t (analysis_core) and are written beside it.
module analysis_state
  use ldfcz_kinds, only: dp
  use step_control, only: step_control_t
  implicit none
  private
  public :: analysis_state_t, analysis_state_init, analysis_state_write, analysis_state_read

  type :: analysis_state_t
    integer :: step = 0                   !< step of the last converged increment (0: none yet)
    integer :: kinc = 0                   !< increment number in the step
    integer :: kinc_total = 0             !< converged increments of the analysis
    integer :: csv_rows = 0               !< data rows of JOB.csv
    integer :: last_frame_inc = -1        !< kinc_total of the last VTU frame
    integer :: reuse_count = 0            !< modified Newton: solves with the current factors
    real(dp) :: t_total0 = 0.0_dp         !< total time at the start of the step
    real(dp) :: q_sum = 0.0_dp            !< sum of the converged increments' typical forces (q_avg)
    real(dp) :: next_mark = 0.0_dp        !< NUMBER INTERVAL: next output time
    real(dp) :: dt_prev = 0.0_dp          !< size of the last converged increment (0: no extrapolation)
    type(step_control_t) :: sc            !< increment control (time, next increment, growth state)
    real(dp), allocatable :: u_start(:)   !< (ndof) displacement at the start of the step (boundary ramps)
    real(dp), allocatable :: rf_old(:)    !< (ndof) reactions of the last converged increment
    real(dp), allocatable :: du_prev(:)   !< (ndof) displacement change of the last converged increment
    real(dp), allocatable :: fext_old(:)  !< (ndof) external and distributed-load forces of the last increment
    real(dp), allocatable :: fcl_old(:)   !< (ndof) concentrated loads of the last increment
    real(dp), allocatable :: bc_val(:)    !< (ndof) prescribed value of each dof
    logical, allocatable :: bc_on(:)      !< (ndof) the dof is prescribed
    logical, allocatable :: bc_init(:)    !< (ndof) prescribed by an initial *BOUNDARY (model data)
    integer, allocatable :: bc_amp(:)     !< (ndof) amplitude of the prescribed value (0: step ramp)
    logical, allocatable :: bc_vel(:)     !< (ndof) the prescribed value is a velocity (*BOUNDARY, TYPE=VELOCITY)
    real(dp), allocatable :: bc_rate(:)   !< (ndof) that velocity in the last converged increment (next step's)
    logical, allocatable :: bc_user(:)    !< (ndof) the value comes from the user subroutine DISP (*BOUNDARY, USER)
  end type analysis_state_t

contains

  !> The state before the first increment of an analysis with ndof dofs.
  pure subroutine analysis_state_init(s, ndof)
    type(analysis_state_t), intent(out) :: s  !< state
    integer, intent(in) :: ndof               !< dofs of the model
    allocate (s%u_start(ndof), s%rf_old(ndof), s%du_prev(ndof), s%fext_old(ndof), s%fcl_old(ndof), &
      s%bc_val(ndof), s%bc_on(ndof), s%bc_init(ndof), s%bc_amp(ndof), s%bc_vel(ndof), s%bc_rate(ndof), &
      s%bc_user(ndof))
    s%bc_vel = .false.
    s%bc_user = .false.
    s%bc_rate = 0.0_dp
    s%u_start = 0.0_dp
    s%rf_old = 0.0_dp
    s%du_prev = 0.0_dp
    s%fext_old = 0.0_dp
    s%fcl_old = 0.0_dp
    s%bc_val = 0.0_dp
    s%bc_on = .false.
    s%bc_init = .false.
    s%bc_amp = 0
  end subroutine analysis_state_init

  !> Write the whole state to the open unformatted stream unit u.
  subroutine analysis_state_write(u, s, ios, iomsg)
    integer, intent(in) :: u                    !< unit (stream, unformatted)
    type(analysis_state_t), intent(in) :: s     !< state
    integer, intent(out) :: ios                 !< iostat
    character(len=*), intent(inout) :: iomsg   !< iomsg
    write (u, iostat=ios, iomsg=iomsg) s%step, s%kinc, s%kinc_total, s%csv_rows, s%last_frame_inc, s%reuse_count, &
      s%t_total0, s%q_sum, s%next_mark, s%dt_prev
    if (ios == 0) write (u, iostat=ios, iomsg=iomsg) s%sc%period, s%sc%dt_min, s%sc%dt_max, &
      merge(1, 0, s%sc%direct), s%sc%easy_iterations, s%sc%t, s%sc%dt, s%sc%easy_count, s%sc%cutbacks, &
      s%sc%total_cutbacks
    if (ios == 0) write (u, iostat=ios, iomsg=iomsg) size(s%u_start)
    if (ios == 0) write (u, iostat=ios, iomsg=iomsg) s%u_start, s%rf_old, s%du_prev, s%fext_old, s%fcl_old, &
      s%bc_val, merge(1, 0, s%bc_on), merge(1, 0, s%bc_init), s%bc_amp, merge(1, 0, s%bc_vel), s%bc_rate, &
      merge(1, 0, s%bc_user)
  end subroutine analysis_state_write

  !> Read a state written by analysis_state_write for ndof dofs (ios = -2: another number of dofs).
  subroutine analysis_state_read(u, ndof, s, ios)
    integer, intent(in) :: u                    !< unit (stream, unformatted)
    integer, intent(in) :: ndof                 !< dofs of this model
    type(analysis_state_t), intent(out) :: s    !< state read
    integer, intent(out) :: ios                 !< iostat (-2: the dofs differ)
    integer :: idirect, n
    integer, allocatable :: ion(:), iinit(:), ivel(:), iuser(:)
    read (u, iostat=ios) s%step, s%kinc, s%kinc_total, s%csv_rows, s%last_frame_inc, s%reuse_count, &
      s%t_total0, s%q_sum, s%next_mark, s%dt_prev
    if (ios == 0) read (u, iostat=ios) s%sc%period, s%sc%dt_min, s%sc%dt_max, idirect, s%sc%easy_iterations, &
      s%sc%t, s%sc%dt, s%sc%easy_count, s%sc%cutbacks, s%sc%total_cutbacks
    if (ios /= 0) return
    s%sc%direct = idirect == 1
    read (u, iostat=ios) n
    if (ios /= 0) return
    if (n /= ndof) then
      ios = -2
      return
    end if
    allocate (s%u_start(ndof), s%rf_old(ndof), s%du_prev(ndof), s%fext_old(ndof), s%fcl_old(ndof), &
      s%bc_val(ndof), s%bc_on(ndof), s%bc_init(ndof), s%bc_amp(ndof), s%bc_vel(ndof), s%bc_rate(ndof), ion(ndof), &
      iinit(ndof), ivel(ndof), s%bc_user(ndof), iuser(ndof))
    read (u, iostat=ios) s%u_start, s%rf_old, s%du_prev, s%fext_old, s%fcl_old, s%bc_val, ion, iinit, s%bc_amp, &
      ivel, s%bc_rate, iuser
    s%bc_on = ion == 1
    s%bc_init = iinit == 1
    s%bc_vel = ivel == 1
    s%bc_user = iuser == 1
  end subroutine analysis_state_read

end module analysis_state
