!> Thin wrapper of one sequential MUMPS 5.5 instance (double precision, or single precision factors of the
!> double-precision values for use as a preconditioner; centralized assembled COO input).
!>
!> Phases (MUMPS 5.5 user guide): JOB = -1 initialise, 1 analyse (with the host's METIS ordering passed as a user
!> ordering, ICNTL(7) = 1 and PERM_IN), 2 factorize, 3 solve, -2 terminate. SYM = 2 is the general symmetric
!> LDL^T factorization (indefinite matrices allowed: a softening cohesive zone makes the tangent indefinite);
!> SYM = 0 the unsymmetric LU. All state lives in the mumps_solver_t instance: no module variables.
!>
!> Single precision (mumps_analyse, single = .true.; SMUMPS): the values are rounded to real32 for the
!> factorization and the right-hand side of a solve to real32 and back, so a solve is accurate only to about
!> cond(A) * 6e-8: half the factor storage and memory traffic, for GMRES preconditioning (sparse_system).
!>
!> Debian's sequential MUMPS (libdmumps_seq + libmpiseq_seq) ships a stub MPI: MPI_INIT is a no-op there and
!> the communicator is only passed through to the stub, so COMM is set to MPI_COMM_WORLD of the stub mpif.h
!> (/usr/include/mumps_seq/mpif.h). The parallel MUMPS (the LDFCZ_MPI build) needs MPI started: ldfcz starts it
!> (parallel_init) before any MUMPS call; a program that calls this module without doing so (the unit tests, a
!> user's own driver of the host library) has it started at its first analysis (mpi_start_if_needed).
!>
!> Distributed (the LDFCZ_MPI build, several processes; mumps_analyse with comm): the parallel MUMPS on that
!> communicator, PAR = 1 (the host works too), the matrix in distributed assembled form (ICNTL(18) = 3: each
!> process gives IRN_loc, JCN_loc, A_loc of the entries its own elements touch; MUMPS sums the entries given on
!> several processes), the user ordering (PERM_IN), and the right-hand side and solution distributed, in both
!> precisions (ICNTL(20) = 10: each process gives a block of rows, IRHS_loc, of the right-hand side that every
!> process holds; ICNTL(21) = 1: each process receives the solution entries MUMPS leaves on it, ISOL_loc, known
!> after the factorization): after a solve a process's rhs holds its own solution entries, zero elsewhere, and
!> mumps_solution_rows names them (sparse_system gathers the pieces on every process). Nothing goes through the
!> host. Every call is collective: all processes call the same phases in the same order.
!>
!> Output of MUMPS is silenced (ICNTL(1:4)) unless the environment variable LDFCZ_MUMPS_VERBOSE is set to a value
!> other than '' or '0'. Two switches for measurements only (benchmarks/bench_mpi.py, docs/performance.md):
!> LDFCZ_MUMPS_ORDERING = pord, amd, amf or qamd replaces the host's METIS ordering by that built-in ordering of
!> MUMPS (ICNTL(7) = 4, 0, 2, 6); LDFCZ_MUMPS_CENTRAL_RHS = 1 keeps a distributed run's right-hand side and
!> solution on the host (ICNTL(20) = 0, ICNTL(21) = 0, the solution broadcast: the path before the distributed
!> one). Neither changes the solution beyond rounding.
module mumps_solver
  use ldfcz_kinds, only: dp, i8
  use, intrinsic :: iso_fortran_env, only: sp => real32
  implicit none
  private
  public :: mumps_solver_t, mumps_analyse, mumps_factorize, mumps_solve, mumps_destroy
  public :: mumps_set_values, mumps_factorize_values, mumps_forget_factors, mumps_factor_flops_estimate
  public :: mumps_factor_entries, mumps_pivot_order, mumps_is_analysed, mumps_is_factored
  public :: mumps_solution_rows, mumps_solution_distributed, mumps_factor_flops

  include 'mpif.h'
  include 'dmumps_struc.h'
  include 'smumps_struc.h'

  integer, parameter :: job_init = -1, job_end = -2, job_analyse = 1, job_factorize = 2, job_solve = 3
  integer, parameter :: max_workspace_retries = 6   !< ICNTL(14) doublings tried before giving up
  integer, parameter :: icntl14_start = 30          !< initial workspace relaxation in percent (default 20)

  !> One MUMPS instance and what the wrapper knows about it.
  type :: mumps_solver_t
    private
    type(dmumps_struc) :: id                         !< the MUMPS instance (double precision)
    type(smumps_struc) :: sid                        !< the MUMPS instance when single
    logical :: single = .false.                      !< single-precision factors (SMUMPS)
    logical :: initialised = .false.                 !< JOB = -1 done
    logical :: analysed = .false.                    !< JOB = 1 done
    logical :: factored = .false.                    !< JOB = 2 done with the current values
    integer :: n = 0                                 !< order of the matrix
    logical :: distributed = .false.                 !< ICNTL(18) = 3 on a communicator of several processes
    logical :: host = .true.                         !< this process is MUMPS' host (rank 0 of the communicator)
    logical :: dist_vectors = .false.                !< distributed right-hand side and solution (ICNTL(20/21))
  end type mumps_solver_t

contains

  !> MPI started if it is not yet, with threads funnelled as parallel_init starts it (only the thread outside
  !> OpenMP regions calls MPI): without it the parallel MUMPS stops at its initialisation ("MPI is not running")
  !> and the instance is unusable. A no-op with the sequential MUMPS' stub MPI.
  subroutine mpi_start_if_needed()
    logical :: started
    integer :: ierr, provided
    call MPI_Initialized(started, ierr)
    if (.not. started) call MPI_Init_thread(MPI_THREAD_FUNNELED, provided, ierr)
  end subroutine mpi_start_if_needed

  !> Initialise the instance and run the analysis of the pattern (irn, jcn) with the user pivot order.
  subroutine mumps_analyse(ms, symmetric, n, irn, jcn, pivot_position, stat, errmsg, single, comm, rank)
    type(mumps_solver_t), intent(inout) :: ms        !< instance (must be fresh or destroyed)
    logical, intent(in) :: symmetric                 !< SYM = 2 (LDL^T, upper triangle given) or SYM = 0
    integer, intent(in) :: n                         !< order
    integer, intent(in) :: irn(:)                    !< row index of each entry
    integer, intent(in) :: jcn(:)                    !< column index of each entry
    integer, intent(in) :: pivot_position(:)         !< position of each variable in the pivot order (PERM_IN)
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFO(1)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    logical, intent(in), optional :: single          !< single-precision factors (default false)
    !> distributed: the communicator of the processes (irn, jcn: this process's entries only) and this rank
    integer, intent(in), optional :: comm, rank
    character(len=*), parameter :: here = 'mumps_analyse'

    stat = 0
    errmsg = ''
    call mpi_start_if_needed()
    if (ms%initialised) call mumps_destroy(ms)
    ms%single = .false.
    if (present(single)) ms%single = single
    ms%distributed = present(comm) .and. present(rank)
    ms%host = .true.
    if (ms%distributed) ms%host = rank == 0
    ms%dist_vectors = .false.
    if (ms%distributed) ms%dist_vectors = .not. env_set('LDFCZ_MUMPS_CENTRAL_RHS')
    if (ms%single) then
      call analyse_single(ms, symmetric, n, irn, jcn, pivot_position, stat, errmsg, comm)
      return
    end if
    ms%id%COMM = MPI_COMM_WORLD
    if (present(comm)) ms%id%COMM = comm
    ms%id%PAR = 1
    ms%id%SYM = merge(2, 0, symmetric)
    ms%id%JOB = job_init
    call dmumps(ms%id)
    if (ms%id%INFOG(1) < 0) then
      stat = ms%id%INFOG(1)
      call describe(here//' (initialisation)', ms%id%INFOG(1), ms%id%INFOG(2), errmsg)
      return
    end if
    ms%initialised = .true.
    call set_controls(ms%id%ICNTL, ms%distributed, ms%dist_vectors)
    ms%n = n
    ms%id%N = n
    if (ms%distributed) then
      if (ms%dist_vectors) then
        call rhs_row_block(n, ms%id%MYID, ms%id%NPROCS, ms%id%Nloc_RHS, ms%id%IRHS_loc)
        ms%id%LRHS_loc = size(ms%id%IRHS_loc)
        allocate (ms%id%RHS_loc(size(ms%id%IRHS_loc)))
        ms%id%RHS_loc = 0.0_dp
      end if
      ms%id%NNZ_loc = int(size(irn), i8)
      allocate(ms%id%IRN_loc(size(irn)), ms%id%JCN_loc(size(jcn)), ms%id%A_loc(size(irn)))
      ms%id%IRN_loc = irn
      ms%id%JCN_loc = jcn
      ms%id%A_loc = 0.0_dp
      if (ms%host) then
        allocate(ms%id%PERM_IN(n))
        ms%id%PERM_IN = pivot_position
        if (.not. ms%dist_vectors) then
          allocate(ms%id%RHS(n))
          ms%id%RHS = 0.0_dp
        end if
      end if
    else
      ms%id%NNZ = int(size(irn), i8)
      allocate(ms%id%IRN(size(irn)), ms%id%JCN(size(jcn)), ms%id%A(size(irn)), ms%id%PERM_IN(n), ms%id%RHS(n))
      ms%id%IRN = irn
      ms%id%JCN = jcn
      ms%id%A = 0.0_dp
      ms%id%PERM_IN = pivot_position
      ms%id%RHS = 0.0_dp
    end if
    ms%id%JOB = job_analyse
    call dmumps(ms%id)
    if (ms%id%INFOG(1) < 0) then
      stat = ms%id%INFOG(1)
      call describe(here, ms%id%INFOG(1), ms%id%INFOG(2), errmsg)
      return
    end if
    ms%analysed = .true.
    ms%factored = .false.
  end subroutine mumps_analyse

  !> Numeric factorization of the given values (same order as irn/jcn at the analysis): mumps_set_values, then
  !> mumps_factorize_values.
  subroutine mumps_factorize(ms, values, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< analysed instance
    real(dp), intent(in) :: values(:)                !< matrix entries
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1) (-10: singular)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    call mumps_set_values(ms, values, stat, errmsg)
    if (stat == 0) call mumps_factorize_values(ms, stat, errmsg)
  end subroutine mumps_factorize

  !> The values of the next factorization, copied into the instance (rounded to real32 when single): after this
  !> call the caller's array may change while mumps_factorize_values runs (on another thread: sparse_system).
  !> The instance's factors are no longer valid.
  subroutine mumps_set_values(ms, values, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< analysed instance
    real(dp), intent(in) :: values(:)                !< matrix entries
    integer, intent(out) :: stat                     !< 0 on success; -1000 not analysed, -1001 wrong size,
                                                     !< -1004 an entry beyond the single-precision range
    character(len=*), intent(out) :: errmsg          !< reason on failure
    character(len=*), parameter :: here = 'mumps_factorize'
    integer :: n_given

    stat = 0
    errmsg = ''
    ms%factored = .false.
    if (.not. ms%analysed) then
      stat = -1000
      errmsg = here//': called before a successful analysis'
      return
    end if
    if (ms%single .and. ms%distributed) then
      n_given = size(ms%sid%A_loc)
    else if (ms%single) then
      n_given = size(ms%sid%A)
    else if (ms%distributed) then
      n_given = size(ms%id%A_loc)
    else
      n_given = size(ms%id%A)
    end if
    if (size(values) /= n_given) then
      stat = -1001
      errmsg = here//': value array size differs from the analysed pattern'
      return
    end if
    if (ms%single) then
      if (any(abs(values) > real(huge(1.0_sp), dp))) then
        stat = -1004
        errmsg = here//' (single precision): a matrix entry exceeds the single-precision range'
        return
      end if
      if (ms%distributed) then
        ms%sid%A_loc = real(values, sp)
      else
        ms%sid%A = real(values, sp)
      end if
    else if (ms%distributed) then
      ms%id%A_loc = values
    else
      ms%id%A = values
    end if
  end subroutine mumps_set_values

  !> Numeric factorization (JOB = 2) of the values given by mumps_set_values. Workspace shortage (INFO(1) = -8,
  !> -9, -14, -15, -17, -20: "increase ICNTL(14)") is retried with a doubled ICNTL(14). Touches this instance
  !> only: another instance may solve meanwhile on another thread (sequential MUMPS; sparse_system).
  subroutine mumps_factorize_values(ms, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< instance with its values set
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1) (-10: singular)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    character(len=*), parameter :: here = 'mumps_factorize'
    integer :: attempt

    stat = 0
    errmsg = ''
    ms%factored = .false.
    if (ms%single) then
      call factorize_single(ms, stat, errmsg)
      return
    end if
    do attempt = 0, max_workspace_retries
      ms%id%JOB = job_factorize
      call dmumps(ms%id)
      select case (ms%id%INFOG(1))
      case (-8, -9, -14, -15, -17, -20)
        ms%id%ICNTL(14) = 2 * ms%id%ICNTL(14)
      case default
        exit
      end select
    end do
    if (ms%id%INFOG(1) < 0) then
      stat = ms%id%INFOG(1)
      call describe(here, ms%id%INFOG(1), ms%id%INFOG(2), errmsg)
      return
    end if
    if (ms%dist_vectors) then
      ! the solution entries MUMPS leaves on this process: INFO(23) of them (ISOL_loc filled by the solve)
      if (associated(ms%id%SOL_loc)) then
        if (size(ms%id%SOL_loc) /= max(1, ms%id%INFO(23))) deallocate (ms%id%SOL_loc)
      end if
      if (.not. associated(ms%id%SOL_loc)) allocate (ms%id%SOL_loc(max(1, ms%id%INFO(23))))
      call size_solution_rows(ms%id%INFO(23), ms%id%ISOL_loc, ms%id%LSOL_loc)
    end if
    ms%factored = .true.
  end subroutine mumps_factorize_values

  !> Solve with the last factors: rhs in, solution out. Distributed (mumps_solution_distributed): every process
  !> gives the same rhs; out, its rhs holds its own solution entries (mumps_solution_rows), zero elsewhere.
  !> Distributed with central vectors (LDFCZ_MUMPS_CENTRAL_RHS): rank 0's rhs only holds the solution (the
  !> others' is untouched).
  subroutine mumps_solve(ms, rhs, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< factored instance
    real(dp), intent(inout) :: rhs(:)                !< right-hand side in, solution out (size n)
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    character(len=*), parameter :: here = 'mumps_solve'

    stat = 0
    errmsg = ''
    if (.not. ms%factored) then
      stat = -1002
      errmsg = here//': no valid factorization (factorize first)'
      return
    end if
    if (size(rhs) /= ms%n) then
      stat = -1003
      errmsg = here//': right-hand side size differs from the matrix order'
      return
    end if
    if (ms%single) then
      call solve_single(ms, rhs, stat, errmsg)
      return
    end if
    ms%id%NRHS = 1
    if (ms%dist_vectors) then
      if (ms%id%Nloc_RHS > 0) ms%id%RHS_loc(1:ms%id%Nloc_RHS) = rhs(ms%id%IRHS_loc(1:ms%id%Nloc_RHS))
    else
      if (ms%host) ms%id%RHS = rhs
      ms%id%LRHS = ms%n
    end if
    ms%id%JOB = job_solve
    call dmumps(ms%id)
    if (ms%id%INFOG(1) < 0) then
      stat = ms%id%INFOG(1)
      call describe(here, ms%id%INFOG(1), ms%id%INFOG(2), errmsg)
      return
    end if
    if (ms%dist_vectors) then
      rhs = 0.0_dp
      rhs(ms%id%ISOL_loc(1:ms%id%INFO(23))) = ms%id%SOL_loc(1:ms%id%INFO(23))
    else if (ms%host) then
      rhs = ms%id%RHS
    end if
  end subroutine mumps_solve

  !> The factors are no longer to be used (a failed refactorization of the matrix they precondition): solves
  !> refuse until the next factorization.
  pure subroutine mumps_forget_factors(ms)
    type(mumps_solver_t), intent(inout) :: ms        !< instance
    ms%factored = .false.
  end subroutine mumps_forget_factors

  !> Terminate the instance (JOB = -2) and free the arrays given to it.
  subroutine mumps_destroy(ms)
    type(mumps_solver_t), intent(inout) :: ms        !< instance
    if (ms%initialised .and. ms%single) then
      ms%sid%JOB = job_end
      call smumps(ms%sid)
      if (associated(ms%sid%IRN)) deallocate(ms%sid%IRN)
      if (associated(ms%sid%JCN)) deallocate(ms%sid%JCN)
      if (associated(ms%sid%A)) deallocate(ms%sid%A)
      if (associated(ms%sid%PERM_IN)) deallocate(ms%sid%PERM_IN)
      if (associated(ms%sid%RHS)) deallocate(ms%sid%RHS)
      if (associated(ms%sid%IRN_loc)) deallocate(ms%sid%IRN_loc)
      if (associated(ms%sid%JCN_loc)) deallocate(ms%sid%JCN_loc)
      if (associated(ms%sid%A_loc)) deallocate(ms%sid%A_loc)
      if (associated(ms%sid%IRHS_loc)) deallocate(ms%sid%IRHS_loc)
      if (associated(ms%sid%RHS_loc)) deallocate(ms%sid%RHS_loc)
      if (associated(ms%sid%ISOL_loc)) deallocate(ms%sid%ISOL_loc)
      if (associated(ms%sid%SOL_loc)) deallocate(ms%sid%SOL_loc)
    else if (ms%initialised) then
      ms%id%JOB = job_end
      call dmumps(ms%id)
      if (associated(ms%id%IRN)) deallocate(ms%id%IRN)
      if (associated(ms%id%JCN)) deallocate(ms%id%JCN)
      if (associated(ms%id%A)) deallocate(ms%id%A)
      if (associated(ms%id%PERM_IN)) deallocate(ms%id%PERM_IN)
      if (associated(ms%id%RHS)) deallocate(ms%id%RHS)
      if (associated(ms%id%IRN_loc)) deallocate(ms%id%IRN_loc)
      if (associated(ms%id%JCN_loc)) deallocate(ms%id%JCN_loc)
      if (associated(ms%id%A_loc)) deallocate(ms%id%A_loc)
      if (associated(ms%id%IRHS_loc)) deallocate(ms%id%IRHS_loc)
      if (associated(ms%id%RHS_loc)) deallocate(ms%id%RHS_loc)
      if (associated(ms%id%ISOL_loc)) deallocate(ms%id%ISOL_loc)
      if (associated(ms%id%SOL_loc)) deallocate(ms%id%SOL_loc)
    end if
    ms%single = .false.
    ms%dist_vectors = .false.
    ms%initialised = .false.
    ms%analysed = .false.
    ms%factored = .false.
    ms%n = 0
  end subroutine mumps_destroy

  !> Entries in the factors: after a factorization INFOG(29) (effective), before it INFOG(20) (estimate);
  !> MUMPS stores values above 2**31 as minus millions.
  integer(i8) function mumps_factor_entries(ms) result(nf)
    type(mumps_solver_t), intent(in) :: ms           !< instance
    integer :: v

    nf = 0
    if (.not. ms%analysed) return
    if (ms%single) then
      v = merge(ms%sid%INFOG(29), ms%sid%INFOG(20), ms%factored)
    else
      v = merge(ms%id%INFOG(29), ms%id%INFOG(20), ms%factored)
    end if
    if (v >= 0) then
      nf = int(v, i8)
    else
      nf = -int(v, i8) * 1000000_i8
    end if
  end function mumps_factor_entries

  !> Floating-point operations of one factorization: after a factorization RINFOG(3) (effective), before it
  !> RINFOG(1) (the analysis' estimate); 0 before the analysis.
  real(dp) function mumps_factor_flops(ms) result(flops)
    type(mumps_solver_t), intent(in) :: ms           !< instance

    flops = 0.0_dp
    if (.not. ms%analysed) return
    if (ms%single) then
      flops = real(merge(ms%sid%RINFOG(3), ms%sid%RINFOG(1), ms%factored), dp)
    else
      flops = merge(ms%id%RINFOG(3), ms%id%RINFOG(1), ms%factored)
    end if
  end function mumps_factor_flops

  !> The analysis' estimate of a factorization's operations (RINFOG(1)), the same for every instance analysed
  !> alike; 0 before the analysis.
  real(dp) function mumps_factor_flops_estimate(ms) result(flops)
    type(mumps_solver_t), intent(in) :: ms           !< instance
    flops = 0.0_dp
    if (.not. ms%analysed) return
    if (ms%single) then
      flops = real(ms%sid%RINFOG(1), dp)
    else
      flops = ms%id%RINFOG(1)
    end if
  end function mumps_factor_flops_estimate

  !> The pivot order MUMPS used (SYM_PERM after the analysis: position of each variable), for checks.
  subroutine mumps_pivot_order(ms, position)
    type(mumps_solver_t), intent(in) :: ms           !< analysed instance
    integer, allocatable, intent(out) :: position(:) !< position of each variable (empty if not analysed)
    if (ms%analysed .and. ms%single) then
      allocate(position(ms%n))
      position = ms%sid%SYM_PERM(1:ms%n)
    else if (ms%analysed .and. associated(ms%id%SYM_PERM)) then
      allocate(position(ms%n))
      position = ms%id%SYM_PERM(1:ms%n)
    else
      allocate(position(0))
    end if
  end subroutine mumps_pivot_order

  !> True when a solve leaves each process its own solution entries (distributed instance).
  logical function mumps_solution_distributed(ms)
    type(mumps_solver_t), intent(in) :: ms           !< instance
    mumps_solution_distributed = ms%dist_vectors
  end function mumps_solution_distributed

  !> The solution entries a solve leaves on this process (ISOL_loc; empty unless mumps_solution_distributed and
  !> solved once with the current factors).
  subroutine mumps_solution_rows(ms, rows)
    type(mumps_solver_t), intent(in) :: ms           !< factored and solved instance
    integer, allocatable, intent(out) :: rows(:)     !< equation numbers
    if (ms%dist_vectors .and. ms%factored .and. ms%single) then
      rows = ms%sid%ISOL_loc(1:ms%sid%INFO(23))
    else if (ms%dist_vectors .and. ms%factored) then
      rows = ms%id%ISOL_loc(1:ms%id%INFO(23))
    else
      allocate (rows(0))
    end if
  end subroutine mumps_solution_rows

  logical function mumps_is_analysed(ms)
    type(mumps_solver_t), intent(in) :: ms           !< instance
    mumps_is_analysed = ms%analysed
  end function mumps_is_analysed

  logical function mumps_is_factored(ms)
    type(mumps_solver_t), intent(in) :: ms           !< instance
    mumps_is_factored = ms%factored
  end function mumps_is_factored

  !> Controls: streams and print level, centralized assembled input, user ordering, workspace relaxation.
  subroutine set_controls(icntl, distributed, dist_vectors)
    integer, intent(inout) :: icntl(:)               !< ICNTL of an instance after JOB = -1
    logical, intent(in) :: distributed               !< distributed assembled input (ICNTL(18) = 3)
    logical, intent(in) :: dist_vectors              !< distributed right-hand side and solution
    character(len=16) :: val
    integer :: length, status

    call get_environment_variable('LDFCZ_MUMPS_VERBOSE', val, length, status)
    if (status == 0 .and. length > 0 .and. trim(val) /= '0') then
      icntl(1) = 6
      icntl(2) = 0
      icntl(3) = 6
      icntl(4) = 2
    else
      icntl(1) = -1     ! error messages suppressed: the wrapper reports INFOG(1) through stat/errmsg
      icntl(2) = -1     ! diagnostics suppressed
      icntl(3) = -1     ! global information suppressed
      icntl(4) = 0      ! print level: none
    end if
    icntl(5) = 0        ! assembled input
    icntl(18) = 0       ! centralized on the host
    if (distributed) icntl(18) = 3  ! distributed assembled entries, summed by MUMPS
    icntl(7) = 1        ! user ordering in PERM_IN (the host's METIS nested dissection)
    call get_environment_variable('LDFCZ_MUMPS_ORDERING', val, length, status)
    if (status == 0 .and. length > 0) then
      select case (trim(val))   ! measurements only: a built-in ordering of MUMPS instead (PERM_IN ignored)
      case ('amd')
        icntl(7) = 0
      case ('amf')
        icntl(7) = 2
      case ('pord')
        icntl(7) = 4
      case ('qamd')
        icntl(7) = 6
      end select
    end if
    icntl(14) = icntl14_start
    icntl(20) = 0       ! dense right-hand side on the host
    icntl(21) = 0       ! centralized solution (overwrites RHS)
    if (dist_vectors) then
      icntl(20) = 10    ! dense right-hand side distributed by rows (IRHS_loc, RHS_loc)
      icntl(21) = 1     ! solution distributed as MUMPS holds it (ISOL_loc, SOL_loc)
    end if
  end subroutine set_controls

  !> True when the environment variable name is set to a value other than '' or '0'.
  logical function env_set(name)
    character(len=*), intent(in) :: name             !< variable
    character(len=16) :: val
    integer :: length, status
    call get_environment_variable(name, val, length, status)
    env_set = status == 0 .and. length > 0 .and. trim(val) /= '0'
  end function env_set

  !> mumps_analyse for single-precision factors (SMUMPS): same pattern, ordering and controls.
  subroutine analyse_single(ms, symmetric, n, irn, jcn, pivot_position, stat, errmsg, comm)
    type(mumps_solver_t), intent(inout) :: ms        !< fresh instance
    logical, intent(in) :: symmetric                 !< SYM = 2 or 0
    integer, intent(in) :: n                         !< order
    integer, intent(in) :: irn(:)                    !< row index of each entry
    integer, intent(in) :: jcn(:)                    !< column index of each entry
    integer, intent(in) :: pivot_position(:)         !< PERM_IN
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    integer, intent(in), optional :: comm            !< distributed: the communicator
    character(len=*), parameter :: here = 'mumps_analyse (single precision)'

    ms%sid%COMM = MPI_COMM_WORLD
    if (present(comm)) ms%sid%COMM = comm
    ms%sid%PAR = 1
    ms%sid%SYM = merge(2, 0, symmetric)
    ms%sid%JOB = job_init
    call smumps(ms%sid)
    if (ms%sid%INFOG(1) < 0) then
      stat = ms%sid%INFOG(1)
      call describe(here//' (initialisation)', ms%sid%INFOG(1), ms%sid%INFOG(2), errmsg)
      return
    end if
    ms%initialised = .true.
    call set_controls(ms%sid%ICNTL, ms%distributed, ms%dist_vectors)
    ms%n = n
    ms%sid%N = n
    if (ms%distributed) then
      if (ms%dist_vectors) then
        call rhs_row_block(n, ms%sid%MYID, ms%sid%NPROCS, ms%sid%Nloc_RHS, ms%sid%IRHS_loc)
        ms%sid%LRHS_loc = size(ms%sid%IRHS_loc)
        allocate (ms%sid%RHS_loc(size(ms%sid%IRHS_loc)))
        ms%sid%RHS_loc = 0.0_sp
      end if
      ms%sid%NNZ_loc = int(size(irn), i8)
      allocate(ms%sid%IRN_loc(size(irn)), ms%sid%JCN_loc(size(jcn)), ms%sid%A_loc(size(irn)))
      ms%sid%IRN_loc = irn
      ms%sid%JCN_loc = jcn
      ms%sid%A_loc = 0.0_sp
      if (ms%host) then
        allocate(ms%sid%PERM_IN(n))
        ms%sid%PERM_IN = pivot_position
        if (.not. ms%dist_vectors) then
          allocate(ms%sid%RHS(n))
          ms%sid%RHS = 0.0_sp
        end if
      end if
    else
      ms%sid%NNZ = int(size(irn), i8)
      allocate(ms%sid%IRN(size(irn)), ms%sid%JCN(size(jcn)), ms%sid%A(size(irn)), ms%sid%PERM_IN(n), ms%sid%RHS(n))
      ms%sid%IRN = irn
      ms%sid%JCN = jcn
      ms%sid%A = 0.0_sp
      ms%sid%PERM_IN = pivot_position
      ms%sid%RHS = 0.0_sp
    end if
    ms%sid%JOB = job_analyse
    call smumps(ms%sid)
    if (ms%sid%INFOG(1) < 0) then
      stat = ms%sid%INFOG(1)
      call describe(here, ms%sid%INFOG(1), ms%sid%INFOG(2), errmsg)
      return
    end if
    ms%analysed = .true.
    ms%factored = .false.
  end subroutine analyse_single

  !> mumps_factorize_values for single-precision factors (the values rounded to real32 by mumps_set_values).
  subroutine factorize_single(ms, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< instance with its values set
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    character(len=*), parameter :: here = 'mumps_factorize (single precision)'
    integer :: attempt

    stat = 0
    errmsg = ''
    do attempt = 0, max_workspace_retries
      ms%sid%JOB = job_factorize
      call smumps(ms%sid)
      select case (ms%sid%INFOG(1))
      case (-8, -9, -14, -15, -17, -20)
        ms%sid%ICNTL(14) = 2 * ms%sid%ICNTL(14)
      case default
        exit
      end select
    end do
    if (ms%sid%INFOG(1) < 0) then
      stat = ms%sid%INFOG(1)
      call describe(here, ms%sid%INFOG(1), ms%sid%INFOG(2), errmsg)
      return
    end if
    if (ms%dist_vectors) then
      if (associated(ms%sid%SOL_loc)) then
        if (size(ms%sid%SOL_loc) /= max(1, ms%sid%INFO(23))) deallocate (ms%sid%SOL_loc)
      end if
      if (.not. associated(ms%sid%SOL_loc)) allocate (ms%sid%SOL_loc(max(1, ms%sid%INFO(23))))
      call size_solution_rows(ms%sid%INFO(23), ms%sid%ISOL_loc, ms%sid%LSOL_loc)
    end if
    ms%factored = .true.
  end subroutine factorize_single

  !> mumps_solve with single-precision factors: the right-hand side scaled by its largest entry (so that it
  !> neither overflows nor underflows in real32), rounded, solved, and the solution scaled back in double.
  subroutine solve_single(ms, rhs, stat, errmsg)
    type(mumps_solver_t), intent(inout) :: ms        !< factored instance
    real(dp), intent(inout) :: rhs(:)                !< right-hand side in, solution out
    integer, intent(out) :: stat                     !< 0 on success, else MUMPS INFOG(1)
    character(len=*), intent(out) :: errmsg          !< reason on failure
    real(dp) :: scale

    scale = maxval(abs(rhs))   ! the same on every process: each holds the whole right-hand side
    if (scale == 0.0_dp .or. .not. (scale < huge(1.0_dp))) scale = 1.0_dp
    ms%sid%NRHS = 1
    if (ms%dist_vectors) then
      if (ms%sid%Nloc_RHS > 0) ms%sid%RHS_loc(1:ms%sid%Nloc_RHS) = &
        real(rhs(ms%sid%IRHS_loc(1:ms%sid%Nloc_RHS)) / scale, sp)
    else
      if (ms%host) ms%sid%RHS = real(rhs / scale, sp)
      ms%sid%LRHS = ms%n
    end if
    ms%sid%JOB = job_solve
    call smumps(ms%sid)
    if (ms%sid%INFOG(1) < 0) then
      stat = ms%sid%INFOG(1)
      call describe('mumps_solve (single precision)', ms%sid%INFOG(1), ms%sid%INFOG(2), errmsg)
      return
    end if
    if (ms%dist_vectors) then
      rhs = 0.0_dp
      rhs(ms%sid%ISOL_loc(1:ms%sid%INFO(23))) = real(ms%sid%SOL_loc(1:ms%sid%INFO(23)), dp) * scale
    else if (ms%host) then
      rhs = real(ms%sid%RHS, dp) * scale
    end if
  end subroutine solve_single

  !> This process's block of right-hand side rows for ICNTL(20) = 10: a contiguous share of 1..n (any disjoint
  !> cover serves, every process holds the whole right-hand side); an empty block still gets an array of one.
  pure subroutine rhs_row_block(n, myid, nprocs, count, rows)
    integer, intent(in) :: n                         !< order
    integer, intent(in) :: myid, nprocs              !< this process's MUMPS rank and the number of processes
    integer, intent(out) :: count                    !< rows in the block (Nloc_RHS)
    integer, pointer, intent(out) :: rows(:)         !< IRHS_loc (allocated here, size max(1, count))
    integer :: lo, hi, i
    lo = int(int(n, i8) * myid / nprocs) + 1
    hi = int(int(n, i8) * (myid + 1) / nprocs)
    count = hi - lo + 1
    allocate (rows(max(1, count)))
    rows = [(lo + i - 1, i = 1, size(rows))]
    if (count == 0) rows = 1   ! not read by MUMPS (Nloc_RHS = 0), but a valid row
  end subroutine rhs_row_block

  !> ISOL_loc of the size a factorization's INFO(23) asks for (kept when it already has it), and LSOL_loc.
  subroutine size_solution_rows(nsol, rows, lsol)
    integer, intent(in) :: nsol                      !< INFO(23): solution entries left on this process
    integer, pointer, intent(inout) :: rows(:)       !< ISOL_loc
    integer, intent(out) :: lsol                     !< LSOL_loc
    if (associated(rows)) then
      if (size(rows) /= max(1, nsol)) deallocate (rows)
    end if
    if (.not. associated(rows)) allocate (rows(max(1, nsol)))
    lsol = max(1, nsol)
  end subroutine size_solution_rows

  !> Message for a MUMPS error code (MUMPS 5.5 user guide, section "Error diagnostics").
  subroutine describe(where, info1, info2, errmsg)
    character(len=*), intent(in) :: where            !< calling routine
    integer, intent(in) :: info1                      !< INFOG(1)
    integer, intent(in) :: info2                      !< INFOG(2)
    character(len=*), intent(out) :: errmsg           !< message
    character(len=96) :: what

    select case (info1)
    case (-10)
      what = 'numerically singular matrix'
    case (-5, -13)
      what = 'memory allocation failed'
    case (-6)
      what = 'structurally singular matrix'
    case (-7)
      what = 'invalid PERM_IN (user ordering)'
    case (-8, -9, -14, -15, -17, -20)
      what = 'workspace too small even after increasing ICNTL(14)'
    case (-16)
      what = 'N out of range'
    case (-22)
      what = 'an array pointer was not associated'
    case default
      what = 'see the MUMPS user guide'
    end select
    write(errmsg, '(a,a,i0,a,i0,a,a)') where, ': MUMPS INFOG(1) = ', info1, ', INFOG(2) = ', info2, ': ', trim(what)
  end subroutine describe

end module mumps_solver
