!> The state of one element between increments: integration-point arrays of a continuum element (stress, strain,
!> STATEV, energy densities), SVARS and ENERGY of a user element. The converged states are part of the analysis
!> state (analysis_state, written by restart_file), the trial states of the last element loop working data.
module element_state
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: elem_state_t, element_state_free, element_state_copy

  !> State of one element (integration-point arrays of continuum elements, SVARS and ENERGY of user elements).
  type :: elem_state_t
    real(dp), allocatable :: stress(:, :)  !< (ntens, nip) Cauchy stress
    real(dp), allocatable :: stran(:, :)   !< (ntens, nip) strain
    real(dp), allocatable :: statev(:, :)  !< (nstatv, nip)
    real(dp), allocatable :: eip(:, :)     !< (3, nip) SSE, SPD, SCD per unit volume
    real(dp), allocatable :: svars(:)      !< user element SVARS
    real(dp) :: energy(8) = 0.0_dp         !< user element ENERGY; continuum: (2) SSE and (4) SPD integrals
  end type elem_state_t

contains

  !> An element state without arrays (another process's element in a distributed run), its energies zero.
  pure subroutine element_state_free(state)
    type(elem_state_t), intent(inout) :: state      !< the state
    if (allocated(state%stress)) deallocate (state%stress)
    if (allocated(state%stran)) deallocate (state%stran)
    if (allocated(state%statev)) deallocate (state%statev)
    if (allocated(state%eip)) deallocate (state%eip)
    if (allocated(state%svars)) deallocate (state%svars)
    state%energy = 0.0_dp
  end subroutine element_state_free

  !> to takes the values of from (the arrays from holds; to's others are left as they are).
  pure subroutine element_state_copy(from, to)
    type(elem_state_t), intent(in) :: from     !< source
    type(elem_state_t), intent(inout) :: to    !< destination
    if (allocated(from%stress)) to%stress = from%stress
    if (allocated(from%stran)) to%stran = from%stran
    if (allocated(from%statev)) to%statev = from%statev
    if (allocated(from%eip)) to%eip = from%eip
    if (allocated(from%svars)) to%svars = from%svars
    to%energy = from%energy
  end subroutine element_state_copy

end module element_state
