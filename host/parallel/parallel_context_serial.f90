!> The parallel context of a run: every global reduction, the stop flag, output ownership and restart naming of the
!> host go through this module (docs/host.md, "Running on several processes"). This is the serial implementation
!> (the default build): one process, every reduction the identity. The MPI build (LDFCZ_MPI=ON) compiles
!> parallel_context_mpi.f90 instead, with the same interface.
module parallel_context
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: parallel_t, parallel_init, parallel_finalize, parallel_writer, parallel_distributed
  public :: parallel_sum, parallel_max, parallel_min, parallel_any, parallel_lowest, parallel_bcast
  public :: parallel_file, parallel_barrier, parallel_first_error, parallel_gather_pieces, parallel_build_is_mpi
  public :: parallel_concat_first, parallel_comm_self

  !> The processes' lists one after the other (rank order) on rank 0.
  interface parallel_concat_first
    module procedure concat_first_int, concat_first_real
  end interface parallel_concat_first

  !> Where this process stands among the processes of the run.
  type :: parallel_t
    integer :: rank = 0                 !< this process (0 .. nranks-1)
    integer :: nranks = 1               !< processes of the run
    integer :: comm = 0                 !< MPI communicator (MPI_COMM_WORLD); unused in the serial build
    real(dp) :: t_comm = 0.0_dp         !< wall seconds spent in reductions and broadcasts
  end type parallel_t

  logical, parameter :: parallel_build_is_mpi = .false.  !< this build's implementation

contains

  !> Start the parallel context (MPI_Init in the MPI build).
  subroutine parallel_init(par)
    type(parallel_t), intent(out) :: par  !< context
    par%rank = 0
    par%nranks = 1
  end subroutine parallel_init

  !> End it (MPI_Finalize in the MPI build).
  subroutine parallel_finalize(par)
    type(parallel_t), intent(inout) :: par  !< context
    par%nranks = 1
  end subroutine parallel_finalize

  !> True on the process that writes the run's shared output (log, CSV, status, PVD): rank 0.
  pure logical function parallel_writer(par)
    type(parallel_t), intent(in) :: par  !< context
    parallel_writer = par%rank == 0
  end function parallel_writer

  !> True when the run has more than one process.
  pure logical function parallel_distributed(par)
    type(parallel_t), intent(in) :: par  !< context
    parallel_distributed = par%nranks > 1
  end function parallel_distributed

  !> v <- sum of v over the processes, the same bits on every process.
  subroutine parallel_sum(par, v)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(inout) :: v(:)         !< summed in place
    if (.false.) v = v + par%t_comm
  end subroutine parallel_sum

  !> Largest x over the processes.
  real(dp) function parallel_max(par, x) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(in) :: x               !< this process's value
    y = x
    if (.false.) y = par%t_comm
  end function parallel_max

  !> Smallest x over the processes.
  real(dp) function parallel_min(par, x) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(in) :: x               !< this process's value
    y = x
    if (.false.) y = par%t_comm
  end function parallel_min

  !> True when l is true on any process (the stop flag of a signal, a user routine's XIT).
  logical function parallel_any(par, l) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    logical, intent(in) :: l                !< this process's flag
    y = l
    if (.false.) y = par%t_comm > 0.0_dp
  end function parallel_any

  !> The lowest positive key over the processes (0 where none has one) and the text of the process that holds it:
  !> the element that failed or asked to stop, with its message, the same on every process.
  subroutine parallel_lowest(par, key, text, owner)
    type(parallel_t), intent(inout) :: par                 !< context
    integer, intent(inout) :: key                          !< this process's key in, the lowest out
    character(len=:), allocatable, intent(inout) :: text   !< its text in, the lowest key's out
    integer, intent(out), optional :: owner                !< the process that holds it
    if (.not. allocated(text)) text = ''
    if (present(owner)) owner = par%rank
    if (.false.) key = int(par%t_comm)
  end subroutine parallel_lowest

  !> v <- v of rank 0.
  subroutine parallel_bcast(par, v)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(inout) :: v(:)         !< broadcast in place
    if (.false.) v = v + par%t_comm
  end subroutine parallel_bcast

  !> Name of a per-process file: path itself in a one-process run, path.RANKofN with several (restart files, VTU
  !> pieces keep their own naming).
  pure function parallel_file(par, path) result(name)
    type(parallel_t), intent(in) :: par   !< context
    character(len=*), intent(in) :: path  !< the one-process name
    character(len=:), allocatable :: name
    character(len=32) :: b
    if (par%nranks <= 1) then
      name = path
    else
      write (b, '(i0,a,i0)') par%rank, 'of', par%nranks
      name = path//'.'//trim(b)
    end if
  end function parallel_file

  !> The pieces of the processes gathered on every process (MPI build): here the one process holds them all.
  subroutine parallel_gather_pieces(par, rows, v)
    type(parallel_t), intent(inout) :: par  !< context
    integer, intent(in) :: rows(:)          !< this process's entries of v
    real(dp), intent(inout) :: v(:)         !< unchanged
    if (.false.) par%t_comm = real(size(rows) + size(v), dp)
  end subroutine parallel_gather_pieces

  !> Wait for every process.
  subroutine parallel_barrier(par)
    type(parallel_t), intent(inout) :: par  !< context
    if (.false.) par%t_comm = 0.0_dp
  end subroutine parallel_barrier

  !> The first error of the processes (MPI build: collective, the lowest failing rank's status and message on
  !> every process): here this process's own.
  subroutine parallel_first_error(par, code, text)
    type(parallel_t), intent(inout) :: par                 !< context
    integer, intent(inout) :: code                         !< this process's status (unchanged)
    character(len=:), allocatable, intent(inout) :: text   !< this process's message (unchanged)
    if (.not. allocated(text)) text = ''
    if (.false.) par%t_comm = real(code, dp)   ! par and code unused: one process
  end subroutine parallel_first_error

  !> all <- mine (one process).
  subroutine concat_first_int(par, mine, all)
    type(parallel_t), intent(inout) :: par               !< context
    integer, intent(in) :: mine(:)                       !< this process's list
    integer, allocatable, intent(inout) :: all(:)        !< the lists of every process, in rank order
    all = mine
    if (.false.) par%t_comm = 0.0_dp   ! par unused: one process
  end subroutine concat_first_int

  !> all <- mine (one process).
  subroutine concat_first_real(par, mine, all)
    type(parallel_t), intent(inout) :: par               !< context
    real(dp), intent(in) :: mine(:)                      !< this process's list
    real(dp), allocatable, intent(inout) :: all(:)       !< the lists of every process, in rank order
    all = mine
    if (.false.) par%t_comm = 0.0_dp   ! par unused: one process
  end subroutine concat_first_real

  !> The communicator of this process alone (MPI_COMM_SELF in the MPI build).
  integer function parallel_comm_self() result(comm)
    comm = 0
  end function parallel_comm_self

end module parallel_context
