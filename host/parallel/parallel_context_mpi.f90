!> The parallel context of a run, MPI implementation (LDFCZ_MPI=ON; the serial build compiles
!> parallel_context_serial.f90, same interface). Every process holds the whole model and the whole dof vectors;
!> each computes its own elements (analysis_core), and the sums of their contributions come through parallel_sum:
!> a reduction to rank 0 followed by a broadcast, so that every process holds the same bits and takes the same
!> Newton, increment and cutback decisions (MPI_Allreduce does not promise identical results on every process).
module parallel_context
  use mpi
  use ldfcz_kinds, only: dp, i8
  implicit none
  private
  public :: parallel_t, parallel_init, parallel_finalize, parallel_writer, parallel_distributed
  public :: parallel_sum, parallel_max, parallel_min, parallel_any, parallel_lowest, parallel_bcast
  public :: parallel_file, parallel_barrier, parallel_first_error, parallel_gather_pieces, parallel_build_is_mpi
  public :: parallel_concat_first, parallel_comm_self

  !> The processes' lists one after the other (rank order) on rank 0: MPI_Gatherv, the same order on every run.
  interface parallel_concat_first
    module procedure concat_first_int, concat_first_real
  end interface parallel_concat_first

  !> Where this process stands among the processes of the run.
  type :: parallel_t
    integer :: rank = 0                 !< this process (0 .. nranks-1)
    integer :: nranks = 1               !< processes of the run
    integer :: comm = MPI_COMM_WORLD    !< communicator
    real(dp) :: t_comm = 0.0_dp         !< wall seconds spent in reductions and broadcasts
  end type parallel_t

  logical, parameter :: parallel_build_is_mpi = .true.  !< this build's implementation

contains

  !> Start the parallel context: MPI_Init (threads funnelled: only the thread outside OpenMP regions calls MPI).
  subroutine parallel_init(par)
    type(parallel_t), intent(out) :: par  !< context
    integer :: ierr, provided
    logical :: started
    call MPI_Initialized(started, ierr)
    if (.not. started) call MPI_Init_thread(MPI_THREAD_FUNNELED, provided, ierr)
    par%comm = MPI_COMM_WORLD
    call MPI_Comm_rank(par%comm, par%rank, ierr)
    call MPI_Comm_size(par%comm, par%nranks, ierr)
  end subroutine parallel_init

  !> End it: MPI_Finalize.
  subroutine parallel_finalize(par)
    type(parallel_t), intent(inout) :: par  !< context
    integer :: ierr
    logical :: done
    call MPI_Finalized(done, ierr)
    if (.not. done) call MPI_Finalize(ierr)
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

  !> v <- sum of v over the processes, the same bits on every process (reduce to rank 0, then broadcast).
  subroutine parallel_sum(par, v)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(inout) :: v(:)         !< summed in place
    real(dp), allocatable :: w(:)
    integer :: ierr
    integer(i8) :: c0
    if (par%nranks <= 1 .or. size(v) == 0) return
    c0 = clock()
    allocate (w(size(v)))
    call MPI_Reduce(v, w, size(v), MPI_DOUBLE_PRECISION, MPI_SUM, 0, par%comm, ierr)
    if (par%rank == 0) v = w
    call MPI_Bcast(v, size(v), MPI_DOUBLE_PRECISION, 0, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end subroutine parallel_sum

  !> Largest x over the processes.
  real(dp) function parallel_max(par, x) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(in) :: x               !< this process's value
    integer :: ierr
    integer(i8) :: c0
    y = x
    if (par%nranks <= 1) return
    c0 = clock()
    call MPI_Allreduce(x, y, 1, MPI_DOUBLE_PRECISION, MPI_MAX, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end function parallel_max

  !> Smallest x over the processes.
  real(dp) function parallel_min(par, x) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(in) :: x               !< this process's value
    integer :: ierr
    integer(i8) :: c0
    y = x
    if (par%nranks <= 1) return
    c0 = clock()
    call MPI_Allreduce(x, y, 1, MPI_DOUBLE_PRECISION, MPI_MIN, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end function parallel_min

  !> True when l is true on any process (the stop flag of a signal, a user routine's XIT).
  logical function parallel_any(par, l) result(y)
    type(parallel_t), intent(inout) :: par  !< context
    logical, intent(in) :: l                !< this process's flag
    integer :: ierr
    integer(i8) :: c0
    y = l
    if (par%nranks <= 1) return
    c0 = clock()
    call MPI_Allreduce(l, y, 1, MPI_LOGICAL, MPI_LOR, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end function parallel_any

  !> The lowest positive key over the processes (0 where none has one) and the text of the process that holds it:
  !> the element that failed or asked to stop, with its message, the same on every process.
  subroutine parallel_lowest(par, key, text, owner)
    type(parallel_t), intent(inout) :: par                 !< context
    integer, intent(inout) :: key                          !< this process's key in, the lowest out
    character(len=:), allocatable, intent(inout) :: text   !< its text in, the lowest key's out
    integer, intent(out), optional :: owner                !< the process that holds it
    integer :: ierr, pair(2), best(2), n
    integer(i8) :: c0
    if (.not. allocated(text)) text = ''
    if (present(owner)) owner = par%rank
    if (par%nranks <= 1) return
    c0 = clock()
    pair = [huge(1), par%rank]
    if (key > 0) pair(1) = key
    call MPI_Allreduce(pair, best, 1, MPI_2INTEGER, MPI_MINLOC, par%comm, ierr)
    if (best(1) == huge(1)) then
      key = 0
      text = ''
    else
      key = best(1)
      if (present(owner)) owner = best(2)
      n = len(text)
      call MPI_Bcast(n, 1, MPI_INTEGER, best(2), par%comm, ierr)
      if (par%rank /= best(2)) then
        deallocate (text)
        allocate (character(len=n) :: text)
      end if
      if (n > 0) call MPI_Bcast(text, n, MPI_CHARACTER, best(2), par%comm, ierr)
    end if
    par%t_comm = par%t_comm + since(c0)
  end subroutine parallel_lowest

  !> v <- the pieces of the processes: each process holds v(rows) of its own (disjoint pieces that together
  !> cover what it needs); on return every process holds every piece (the same bits: copies, no sums).
  !> One MPI_Allgatherv of the rows and one of the values, no process in between.
  subroutine parallel_gather_pieces(par, rows, v)
    type(parallel_t), intent(inout) :: par  !< context
    integer, intent(in) :: rows(:)          !< this process's entries of v
    real(dp), intent(inout) :: v(:)         !< v(rows) in, every process's pieces out (other entries kept)
    integer, allocatable :: counts(:), displs(:), all_rows(:)
    real(dp), allocatable :: mine(:), all_vals(:)
    integer :: ierr, p, total
    integer(i8) :: c0
    if (par%nranks <= 1) return
    c0 = clock()
    allocate (counts(par%nranks), displs(par%nranks))
    call MPI_Allgather(size(rows), 1, MPI_INTEGER, counts, 1, MPI_INTEGER, par%comm, ierr)
    displs(1) = 0
    do p = 2, par%nranks
      displs(p) = displs(p - 1) + counts(p - 1)
    end do
    total = displs(par%nranks) + counts(par%nranks)
    allocate (all_rows(max(1, total)), all_vals(max(1, total)), mine(max(1, size(rows))))
    mine(1:size(rows)) = v(rows)
    call MPI_Allgatherv(rows, size(rows), MPI_INTEGER, all_rows, counts, displs, MPI_INTEGER, par%comm, ierr)
    call MPI_Allgatherv(mine, size(rows), MPI_DOUBLE_PRECISION, all_vals, counts, displs, MPI_DOUBLE_PRECISION, &
      par%comm, ierr)
    v(all_rows(1:total)) = all_vals(1:total)
    par%t_comm = par%t_comm + since(c0)
  end subroutine parallel_gather_pieces

  !> v <- v of rank 0.
  subroutine parallel_bcast(par, v)
    type(parallel_t), intent(inout) :: par  !< context
    real(dp), intent(inout) :: v(:)         !< broadcast in place
    integer :: ierr
    integer(i8) :: c0
    if (par%nranks <= 1 .or. size(v) == 0) return
    c0 = clock()
    call MPI_Bcast(v, size(v), MPI_DOUBLE_PRECISION, 0, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end subroutine parallel_bcast

  !> Name of a per-process file: path itself in a one-process run, path.RANKofN with several.
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

  !> Wait for every process.
  subroutine parallel_barrier(par)
    type(parallel_t), intent(inout) :: par  !< context
    integer :: ierr
    if (par%nranks > 1) call MPI_Barrier(par%comm, ierr)
  end subroutine parallel_barrier

  !> The first error of the processes: every process calls it at the same point of the start-up (a checkpoint),
  !> or in place of the next checkpoint when it has found an error itself (its one collective call then matches
  !> the others' checkpoint, so no process waits for one that has given up). In: this process's exit status (0:
  !> no error) and message. Out: the status and message of the lowest rank that reported an error, the same on
  !> every process (0 and '' when none did). No MPI_Abort: the caller ends every process alike.
  subroutine parallel_first_error(par, code, text)
    type(parallel_t), intent(inout) :: par                 !< context
    integer, intent(inout) :: code                         !< this process's status in, the first error's out
    character(len=:), allocatable, intent(inout) :: text   !< this process's message in, the first error's out
    integer :: ierr, mine, first, n
    integer(i8) :: c0
    if (.not. allocated(text)) text = ''
    if (par%nranks <= 1) return
    c0 = clock()
    mine = huge(1)
    if (code /= 0) mine = par%rank
    call MPI_Allreduce(mine, first, 1, MPI_INTEGER, MPI_MIN, par%comm, ierr)
    if (first == huge(1)) then
      code = 0
      text = ''
    else
      call MPI_Bcast(code, 1, MPI_INTEGER, first, par%comm, ierr)
      n = len(text)
      call MPI_Bcast(n, 1, MPI_INTEGER, first, par%comm, ierr)
      if (par%rank /= first) then
        deallocate (text)
        allocate (character(len=n) :: text)
      end if
      if (n > 0) call MPI_Bcast(text, n, MPI_CHARACTER, first, par%comm, ierr)
    end if
    par%t_comm = par%t_comm + since(c0)
  end subroutine parallel_first_error

  !> all <- on rank 0 the lists of every process in rank order (size 0 elsewhere).
  subroutine concat_first_int(par, mine, all)
    type(parallel_t), intent(inout) :: par               !< context
    integer, intent(in) :: mine(:)                       !< this process's list
    integer, allocatable, intent(inout) :: all(:)        !< rank 0: the lists of every process, in rank order
    integer, allocatable :: counts(:), displs(:)
    integer :: ierr
    integer(i8) :: c0
    c0 = clock()
    call gather_layout(par, size(mine), counts, displs)
    if (allocated(all)) deallocate (all)
    allocate (all(merge(sum(counts), 0, par%rank == 0)))
    call MPI_Gatherv(mine, size(mine), MPI_INTEGER, all, counts, displs, MPI_INTEGER, 0, par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end subroutine concat_first_int

  !> all <- on rank 0 the lists of every process in rank order (size 0 elsewhere).
  subroutine concat_first_real(par, mine, all)
    type(parallel_t), intent(inout) :: par               !< context
    real(dp), intent(in) :: mine(:)                      !< this process's list
    real(dp), allocatable, intent(inout) :: all(:)       !< rank 0: the lists of every process, in rank order
    integer, allocatable :: counts(:), displs(:)
    integer :: ierr
    integer(i8) :: c0
    c0 = clock()
    call gather_layout(par, size(mine), counts, displs)
    if (allocated(all)) deallocate (all)
    allocate (all(merge(sum(counts), 0, par%rank == 0)))
    call MPI_Gatherv(mine, size(mine), MPI_DOUBLE_PRECISION, all, counts, displs, MPI_DOUBLE_PRECISION, 0, &
      par%comm, ierr)
    par%t_comm = par%t_comm + since(c0)
  end subroutine concat_first_real

  !> The processes' list sizes and their offsets in the concatenation (on rank 0; zeros elsewhere).
  subroutine gather_layout(par, n, counts, displs)
    type(parallel_t), intent(in) :: par                  !< context
    integer, intent(in) :: n                             !< this process's list size
    integer, allocatable, intent(out) :: counts(:), displs(:)
    integer :: ierr, p
    allocate (counts(par%nranks), displs(par%nranks))
    counts = 0
    call MPI_Gather(n, 1, MPI_INTEGER, counts, 1, MPI_INTEGER, 0, par%comm, ierr)
    displs(1) = 0
    do p = 2, par%nranks
      displs(p) = displs(p - 1) + counts(p - 1)
    end do
  end subroutine gather_layout

  !> The communicator of this process alone.
  integer function parallel_comm_self() result(comm)
    comm = MPI_COMM_SELF
  end function parallel_comm_self

  integer(i8) function clock() result(c)
    call system_clock(c)
  end function clock

  real(dp) function since(c0) result(s)
    integer(i8), intent(in) :: c0
    integer(i8) :: c1, rate
    call system_clock(c1, rate)
    s = real(c1 - c0, dp) / real(rate, dp)
  end function since

end module parallel_context
