!> Converged element states of other processes, brought to every process for output that rank 0 writes alone
!> (the JOB.dat *EL PRINT tables): in a distributed run each process keeps the converged state of its own elements
!> only (analysis_core: every process allocates every element's state, but computes and commits its own).
module state_gather
  use ldfcz_kinds, only: dp
  use analysis_core, only: analysis_t
  use parallel_context, only: parallel_distributed, parallel_gather_pieces
  implicit none
  private
  public :: gather_converged_states

contains

  !> Collective (every process, the same elems): the converged stress, strain (STRAN) and state variables of the
  !> continuum elements elems, as their owners hold them, on every process. Elements without these arrays (user
  !> elements) are skipped alike everywhere. A one-process run returns at once.
  subroutine gather_converged_states(an, elems)
    type(analysis_t), intent(inout) :: an   !< analysis data: an%conv of elems filled from their owners
    integer, intent(in) :: elems(:)         !< elements, the same list on every process
    integer, allocatable :: first(:), rows(:)
    real(dp), allocatable :: v(:)
    integer :: k, ie, n, pos, nown

    if (.not. parallel_distributed(an%par)) return
    ! layout: element k's stress, stran, statev, one after the other, at first(k) (sizes are the same on every
    ! process: analysis_init allocates every element's state from the model)
    allocate (first(size(elems) + 1))
    first(1) = 1
    do k = 1, size(elems)
      first(k + 1) = first(k) + state_size(elems(k))
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
      associate (cv => an%conv(ie))
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
      pos = first(k)
      associate (cv => an%conv(ie))
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

  contains

    !> Reals of element ie's stress, stran and statev (0 when it has none of them: a user element).
    integer function state_size(ie) result(m)
      integer, intent(in) :: ie
      m = 0
      if (.not. (allocated(an%conv(ie)%stress) .and. allocated(an%conv(ie)%stran) .and. &
        allocated(an%conv(ie)%statev))) return
      m = size(an%conv(ie)%stress) + size(an%conv(ie)%stran) + size(an%conv(ie)%statev)
    end function state_size

  end subroutine gather_converged_states

end module state_gather
