!> Converged element states of other processes, brought to every process for output that rank 0 writes alone
!> (the JOB.dat *EL PRINT tables): in a distributed run each process holds the states of its own elements only
!> (analysis_init), so the printed ones are gathered before the tables and released after them.
module state_gather
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, etype_user
  use analysis_core, only: analysis_t, element_state_allocate, element_state_free, continuum_state_dims
  use parallel_context, only: parallel_distributed, parallel_gather_pieces
  implicit none
  private
  public :: gather_converged_states, release_converged_states

contains

  !> Collective (every process, the same elems): the converged stress, strain (STRAN) and state variables of the
  !> continuum elements elems, as their owners hold them, on every process (another process's element gets its
  !> arrays here; release_converged_states frees them). User elements in elems are skipped alike everywhere. A
  !> one-process run returns at once.
  subroutine gather_converged_states(an, model, elems)
    type(analysis_t), intent(inout) :: an   !< analysis data: an%state%conv of elems filled from their owners
    type(model_t), intent(in) :: model      !< the model (the states' shapes)
    integer, intent(in) :: elems(:)         !< elements, the same list on every process
    integer, allocatable :: first(:), rows(:)
    real(dp), allocatable :: v(:)
    integer :: k, ie, n, pos, nown, d(3)

    if (.not. parallel_distributed(an%par)) return
    ! layout: element k's stress, stran, statev, one after the other, at first(k); the shapes come from the model,
    ! the same on every process
    allocate (first(size(elems) + 1))
    first(1) = 1
    do k = 1, size(elems)
      n = 0
      if (model%elem_kind(elems(k)) /= etype_user) then
        d = continuum_state_dims(an, model, elems(k))
        n = d(2) * (2 * d(1) + d(3))
      end if
      first(k + 1) = first(k) + n
    end do
    allocate (v(max(1, first(size(elems) + 1) - 1)))
    v = 0.0_dp
    nown = 0
    do k = 1, size(elems)
      if (an%owned(elems(k))) nown = nown + first(k + 1) - first(k)
    end do
    allocate (rows(nown))
    nown = 0
    do k = 1, size(elems)
      ie = elems(k)
      if (.not. an%owned(ie) .or. first(k + 1) == first(k)) cycle
      pos = first(k)
      associate (cv => an%state%conv(ie))
        n = size(cv%stress)
        v(pos:pos + n - 1) = reshape(cv%stress, [n])
        pos = pos + n
        n = size(cv%stran)
        v(pos:pos + n - 1) = reshape(cv%stran, [n])
        pos = pos + n
        n = size(cv%statev)
        v(pos:pos + n - 1) = reshape(cv%statev, [n])
      end associate
      rows(nown + 1:nown + first(k + 1) - first(k)) = [(pos, pos = first(k), first(k + 1) - 1)]
      nown = nown + first(k + 1) - first(k)
    end do
    call parallel_gather_pieces(an%par, rows, v)
    do k = 1, size(elems)
      ie = elems(k)
      if (an%owned(ie) .or. first(k + 1) == first(k)) cycle
      call element_state_allocate(an, model, ie, an%state%conv(ie))
      pos = first(k)
      associate (cv => an%state%conv(ie))
        n = size(cv%stress)
        cv%stress = reshape(v(pos:pos + n - 1), shape(cv%stress))
        pos = pos + n
        n = size(cv%stran)
        cv%stran = reshape(v(pos:pos + n - 1), shape(cv%stran))
        pos = pos + n
        n = size(cv%statev)
        cv%statev = reshape(v(pos:pos + n - 1), shape(cv%statev))
      end associate
    end do
  end subroutine gather_converged_states

  !> Frees what gather_converged_states gave this process of other processes' elements (a process holds its own
  !> elements' states only: restart files and memory stay as the partition says).
  subroutine release_converged_states(an, elems)
    type(analysis_t), intent(inout) :: an   !< analysis data
    integer, intent(in) :: elems(:)         !< the elements gathered
    integer :: k, ie
    if (.not. parallel_distributed(an%par)) return
    do k = 1, size(elems)
      ie = elems(k)
      if (.not. an%owned(ie)) call element_state_free(an%state%conv(ie))
    end do
  end subroutine release_converged_states

end module state_gather
