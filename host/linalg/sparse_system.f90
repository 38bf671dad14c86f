!> The host's sparse linear system: fixed pattern, element -> slot maps, METIS node ordering, MUMPS solver.
!>
!> Life cycle: sparse_setup once per pattern (pattern, slot maps, METIS ordering, MUMPS analysis); then per Newton
!> iteration sparse_zero, sparse_add_element for every element (thread-safe), sparse_factorize, sparse_solve (as often
!> as wanted with the same factors); sparse_destroy at the end. The analysis is never repeated for the same pattern.
!>
!> Thread safety of the assembly: sparse_add_element adds each entry with `!$omp atomic update`, so the element loop
!> may run in any OpenMP schedule without colouring. Atomic adds make the sum order (and so the last bits of a
!> value shared by several elements) depend on the schedule; the tests compare threaded and serial assembly to a
!> relative tolerance for that reason. The library must be compiled with OpenMP for the directive to act (the
!> CMake target links OpenMP::OpenMP_Fortran when found). With exclusive=.true. the caller guarantees that no other
!> thread adds to the element's entries meanwhile (the host's coloured element loop, host/analysis/element_colors):
!> plain additions in a fixed order, so the assembled matrix does not depend on the thread count.
!>
!> Symmetric systems store the upper triangle (row <= column) and are factorized by MUMPS as LDL^T (SYM = 2);
!> the caller passes a symmetric ke and only its entries that map to the upper triangle are added.
!>
!> Unsymmetric systems may ask for symmetric factors (sparse_setup, symmetric_factors): all entries are stored
!> (products and GMRES use the true matrix), and MUMPS factorizes the symmetric part (A + A^T)/2 as LDL^T: half
!> the factor storage and roughly half the factorization work of LU. Those factors are a preconditioner, not a
!> solver: sparse_factors_exact is then false and the caller must solve with sparse_solve_krylov.
!> Single-precision factors (sparse_setup, single_factors; alone or with symmetric_factors) are a preconditioner
!> in the same way: half the factor storage and memory traffic of the double-precision ones.
!>
!> Distributed (sparse_setup with a parallel context of several processes and the elements this process owns):
!> every process builds the pattern of its own elements only, adds its own elements into it, and hands MUMPS
!> (distributed assembled input, mumps_solver) those entries; MUMPS sums what several processes give. Each process
!> gives MUMPS a block of the right-hand side's rows and receives its piece of the solution, and the pieces are
!> gathered on every process (one all-gather; the solution comes back on rank 0 and is broadcast only when
!> LDFCZ_MUMPS_CENTRAL_RHS asks for MUMPS' central vectors); products A x sum the processes' parts
!> (parallel_context), so every process holds the same vectors and the Newton decisions built on them agree.
!> MUMPS' parallel factorization and solve add the contributions of the processes in the order its messages arrive,
!> so two identical distributed runs differ in the last bits (1e-14 to 1e-11 relative, then possibly in the path).
!> With one_process (ldfcz --reproducible) a distributed system is factorized and solved on rank 0
!> alone instead (solo): the processes' entries gathered there in rank order (MPI_Gatherv), one MUMPS instance of
!> rank 0 alone (MPI_COMM_SELF, centralized input, duplicates summed in input order), the solution broadcast:
!> identical runs give identical bits, at the price of a sequential factorization (docs/host.md).
module sparse_system
  use ldfcz_kinds, only: dp, i8
  use sparse_pattern, only: build_pattern, build_slot_map, find_in_row
  use metis_ordering, only: node_graph_from_elements, metis_node_order, equation_order_from_nodes, is_permutation
  use parallel_context, only: parallel_t, parallel_distributed, parallel_sum, parallel_bcast, parallel_gather_pieces, &
    parallel_concat_first, parallel_comm_self, parallel_first_error
  use mumps_solver, only: mumps_solver_t, mumps_analyse, mumps_factorize, mumps_solve, mumps_destroy, &
                          mumps_factor_entries, mumps_pivot_order, mumps_is_factored, mumps_solution_rows, &
                          mumps_solution_distributed, mumps_factor_flops, mumps_set_values, mumps_factorize_values, &
                          mumps_forget_factors, mumps_factor_flops_estimate
  use blas_threads, only: blas_threads_set
  use background_task, only: task_start, task_join
  use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_null_ptr, c_associated, c_loc, c_f_pointer, c_funloc
  implicit none
  private
  public :: sparse_system_t
  public :: sparse_setup, sparse_zero, sparse_add_element, sparse_factorize, sparse_solve, sparse_matvec
  public :: sparse_destroy
  public :: sparse_nnz, sparse_neq, sparse_factor_entries, sparse_time_analysis, sparse_time_factor
  public :: sparse_time_solve, sparse_factor_count, sparse_analysis_count, sparse_solve_count
  public :: sparse_ordering, sparse_pivot_order, sparse_to_dense, sparse_is_symmetric
  public :: sparse_is_factored, sparse_solve_krylov, sparse_krylov_count, sparse_factors_exact, sparse_time_comm
  public :: sparse_set_factor_threads, sparse_factor_flops, sparse_iteration_flops
  public :: sparse_pipelined, sparse_factor_begin, sparse_factor_install, sparse_factor_pending
  public :: sparse_time_factor_wait, sparse_time_factor_beside

  !> A factorization begun by sparse_factor_begin and not installed yet: the instance it factorizes and its outcome
  !> (written by the thread that runs it, read after the join), or deferred: to be run on the one instance of a
  !> sequential system when its factors are no longer used (sparse_factor_begin).
  type :: factor_job_t
    type(mumps_solver_t), pointer :: ms => null()   !< the instance being factorized
    logical :: deferred = .false.                   !< not run yet (sequential system)
    logical :: beside = .false.                     !< run on a thread of its own
    integer :: stat = 0                             !< 0 ok, else the MUMPS error (mumps_factorize_values)
    character(len=256) :: errmsg = ''               !< its message
    real(dp) :: seconds = 0.0_dp                    !< wall seconds of the factorization itself
  end type factor_job_t

  !> A sparse system with its pattern, values, ordering and MUMPS instance (components private).
  type :: sparse_system_t
    private
    integer :: neq = 0                              !< number of equations
    logical :: symmetric = .true.                   !< upper triangle stored, LDL^T
    logical :: ready = .false.                      !< setup completed
    integer, allocatable :: row_ptr(:)              !< CSR row pointers (size neq+1)
    integer, allocatable :: irn(:)                  !< row of each entry
    integer, allocatable :: jcn(:)                  !< column of each entry
    real(dp), allocatable :: val(:)                 !< values
    integer, allocatable :: elem_size(:)            !< dofs of each element
    integer(i8), allocatable :: slot_ptr(:)         !< start of each element's slot map
    integer, allocatable :: slot(:)                 !< element entry -> value index (0 = skipped)
    integer, allocatable :: eq_position(:)          !< pivot position of each equation (METIS, expanded)
    logical :: sym_factors = .false.                !< unsymmetric values, LDL^T factors of (A + A^T)/2
    logical :: single_factors = .false.             !< factors in single precision (preconditioner only)
    integer, allocatable :: up_entry(:)             !< sym_factors: entry (i, j), i <= j, of each factor value
    integer, allocatable :: lo_entry(:)             !< sym_factors: entry (j, i) of each factor value
    real(dp), allocatable :: val_sym(:)             !< sym_factors: values given to MUMPS
    !> the MUMPS instances: one, or two when factorizations are pipelined on a thread of their own
    !> (sparse_factor_begin: the one not in use is factorized while GMRES goes on with the other; a pointer, so
    !> that the thread may work on it)
    type(mumps_solver_t), pointer :: solvers(:) => null()
    integer :: cur = 1                              !< the instance whose factors are in use
    logical :: pipelined = .false.                  !< refactorizations may be begun before they are used
    logical :: background = .false.                 !< they run on a thread of their own (two instances)
    type(factor_job_t), pointer :: job => null()    !< the pipelined factorization begun, not installed yet
    type(c_ptr) :: task = c_null_ptr                !< the thread running it (null: none, or run already)
    real(dp) :: t_factor_wait = 0.0_dp              !< wall seconds waited at installations for a running one
    real(dp) :: t_factor_beside = 0.0_dp            !< wall seconds of the factorizations run on their own thread
    real(dp) :: t_factor_here = 0.0_dp              !< wall seconds of pipelined ones run on the caller's thread
    integer :: factor_threads = 0                   !< > 1: BLAS threads of a large factorization (see sparse_factorize)
    real(dp) :: factor_min_flops = huge(1.0_dp)     !< operations from which a factorization is large
    type(parallel_t) :: par                         !< processes of the run (distributed: several)
    logical :: distributed = .false.                !< this process adds its own elements only
    real(dp) :: product_entries = 0.0_dp            !< stored entries of every process's part (the product's work)
    logical :: solo = .false.                       !< distributed, factorized and solved on rank 0 alone (above)
    logical :: solo_factored = .false.              !< solo: the last factorization succeeded (on every process)
    real(dp) :: solo_flops = 0.0_dp                 !< solo: rank 0's factorization operations, on every process
    integer(i8) :: solo_entries = 0                 !< solo: rank 0's factor entries, on every process
    real(dp) :: t_analysis = 0.0_dp                 !< wall seconds in setup (pattern, ordering, analysis)
    real(dp) :: t_factor = 0.0_dp                   !< wall seconds in factorizations
    real(dp) :: t_solve = 0.0_dp                    !< wall seconds in solves
    integer :: n_analysis = 0                       !< analyses done
    integer :: n_factor = 0                         !< successful factorizations
    integer :: n_solve = 0                          !< solves done
    integer :: n_krylov = 0                         !< GMRES iterations done (each: one solve with the factors)
  end type sparse_system_t

contains

  !> Build the pattern, the element -> slot maps, the METIS ordering and the MUMPS analysis, once.
  subroutine sparse_setup(sys, neq, elem_ptr, elem_eq, eq_node, symmetric, stat, errmsg, use_metis, &
      symmetric_factors, single_factors, par, owned, one_process, pipelined, background)
    type(sparse_system_t), intent(inout) :: sys     !< system (any previous content is destroyed)
    integer, intent(in) :: neq                      !< number of free equations (1..neq)
    integer, intent(in) :: elem_ptr(:)              !< size nelem+1, CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)               !< equation of each element dof in element order; 0 = constrained
    integer, intent(in) :: eq_node(:)               !< size neq: node (1..nnodes) of each equation
    logical, intent(in) :: symmetric                !< true: upper triangle, LDL^T (SYM = 2); false: LU (SYM = 0)
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    logical, intent(in), optional :: use_metis      !< false: natural order (for comparisons); default true
    logical, intent(in), optional :: symmetric_factors !< unsymmetric only: LDL^T factors of (A + A^T)/2
    logical, intent(in), optional :: single_factors !< single-precision factors (a preconditioner only)
    type(parallel_t), intent(in), optional :: par   !< processes of the run (default: this one alone)
    logical, intent(in), optional :: owned(:)       !< (nelem) the elements this process adds (with par)
    !> distributed: factorize and solve on rank 0 alone (identical runs give identical bits; default false)
    logical, intent(in), optional :: one_process
    !> refactorizations begun before they are used (sparse_factor_begin; not with solo), on a thread of their own
    !> (background, with two MUMPS instances; not distributed) or in sequence when the factors in use are no longer
    !> needed (one instance): the same factors at the same points either way
    logical, intent(in), optional :: pipelined, background
    integer(i8) :: c0
    logical :: metis
    real(dp) :: entries(1)

    stat = 0
    errmsg = ''
    c0 = clock_count()
    call sparse_destroy(sys)
    metis = .true.
    if (present(use_metis)) metis = use_metis
    call setup_check_input(neq, elem_ptr, elem_eq, eq_node, stat, errmsg)
    if (stat /= 0) return
    sys%neq = neq
    sys%symmetric = symmetric
    sys%distributed = .false.
    if (present(par)) then
      sys%par = par
      sys%distributed = parallel_distributed(par) .and. present(owned)
    end if
    sys%solo = .false.
    if (sys%distributed .and. present(one_process)) sys%solo = one_process
    sys%pipelined = .false.
    if (present(pipelined)) sys%pipelined = pipelined .and. .not. sys%solo
    sys%background = .false.
    if (present(background)) sys%background = background .and. sys%pipelined .and. .not. sys%distributed
    allocate (sys%solvers(merge(2, 1, sys%background)))
    sys%cur = 1

    call setup_pattern(sys, elem_ptr, elem_eq, owned, stat, errmsg)
    if (stat /= 0) return
    call setup_ordering(sys, elem_ptr, elem_eq, eq_node, metis, stat, errmsg)
    if (stat /= 0) return

    sys%sym_factors = .false.
    if (present(symmetric_factors)) sys%sym_factors = symmetric_factors .and. .not. symmetric
    sys%single_factors = .false.
    if (present(single_factors)) sys%single_factors = single_factors
    if (sys%sym_factors) then
      call setup_mirror(sys, stat, errmsg)
      if (stat /= 0) return
      call analyse_instances(sys, .true., sys%irn(sys%up_entry), sys%jcn(sys%up_entry), stat, errmsg)
    else
      call analyse_instances(sys, symmetric, sys%irn, sys%jcn, stat, errmsg)
    end if
    sys%n_analysis = sys%n_analysis + 1
    if (stat /= 0) then
      sys%t_analysis = sys%t_analysis + seconds_since(c0)
      return
    end if
    ! the work of a product counts every process's entries: the same number on every process (collective, after
    ! the analysis, whose failure every process sees alike)
    entries = real(size(sys%jcn), dp)
    if (sys%distributed) call parallel_sum(sys%par, entries)
    sys%product_entries = entries(1)
    sys%t_analysis = sys%t_analysis + seconds_since(c0)
    sys%ready = .true.
  end subroutine sparse_setup

  !> sparse_setup's arguments checked: at least one equation, a node for each, a valid element CSR.
  subroutine setup_check_input(neq, elem_ptr, elem_eq, eq_node, stat, errmsg)
    integer, intent(in) :: neq                      !< number of free equations
    integer, intent(in) :: elem_ptr(:)              !< size nelem+1, CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)               !< equation of each element dof; 0 = constrained
    integer, intent(in) :: eq_node(:)               !< node of each equation
    integer, intent(out) :: stat                    !< 0 when valid
    character(len=*), intent(out) :: errmsg         !< reason otherwise
    character(len=*), parameter :: here = 'sparse_setup'
    integer :: nelem
    stat = 1
    nelem = size(elem_ptr) - 1
    if (neq < 1) then
      write(errmsg, '(a,a,i0)') here, ': no equations, neq = ', neq
    else if (size(eq_node) /= neq) then
      errmsg = here//': eq_node must have neq entries'
    else if (nelem < 1) then
      errmsg = here//': elem_ptr is not a valid CSR pointer array into elem_eq'
    else if (elem_ptr(1) /= 1 .or. elem_ptr(nelem + 1) - 1 > size(elem_eq)) then
      errmsg = here//': elem_ptr is not a valid CSR pointer array into elem_eq'
    else if (any(elem_ptr(2:) < elem_ptr(:nelem))) then
      errmsg = here//': elem_ptr decreases'
    else if (any(eq_node < 1)) then
      errmsg = here//': eq_node holds a node index < 1'
    else
      stat = 0
      errmsg = ''
    end if
  end subroutine setup_check_input

  !> The host's pattern (row pointers, columns, rows, values) and the element -> slot maps. A process of a
  !> distributed run builds its part of the matrix only: the pattern of its own elements (the others as if all
  !> their dofs were constrained). Its entries are its MUMPS input (MUMPS sums the entries that several processes
  !> give) and its part of every product; the whole pattern is never built (docs/performance.md, "Memory of a
  !> process"), and it maps only its own elements (the maps of all elements are 2.3 kB a C3D8: 50 MB on the paper's
  !> application mesh).
  subroutine setup_pattern(sys, elem_ptr, elem_eq, owned, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system being set up (neq, symmetric, distributed set)
    integer, intent(in) :: elem_ptr(:)              !< size nelem+1, CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)               !< equation of each element dof; 0 = constrained
    logical, intent(in), optional :: owned(:)       !< (nelem) this process's elements (distributed)
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, allocatable :: own_eq(:)
    integer :: nelem, i, k
    nelem = size(elem_ptr) - 1
    if (sys%distributed) then
      own_eq = elem_eq(1:elem_ptr(nelem + 1) - 1)
      do k = 1, nelem
        if (.not. owned(k)) own_eq(elem_ptr(k):elem_ptr(k + 1) - 1) = 0
      end do
      call build_pattern(sys%neq, elem_ptr, own_eq, sys%symmetric, sys%row_ptr, sys%jcn, stat, errmsg, &
                         empty_rows=.true.)
      deallocate (own_eq)
    else
      call build_pattern(sys%neq, elem_ptr, elem_eq(1:elem_ptr(nelem + 1) - 1), sys%symmetric, sys%row_ptr, &
                         sys%jcn, stat, errmsg)
    end if
    if (stat /= 0) return
    allocate(sys%irn(size(sys%jcn)), sys%val(size(sys%jcn)))
    do i = 1, sys%neq
      sys%irn(sys%row_ptr(i):sys%row_ptr(i + 1) - 1) = i
    end do
    sys%val = 0.0_dp
    if (sys%distributed) then
      call build_slot_map(elem_ptr, elem_eq, sys%symmetric, sys%row_ptr, sys%jcn, sys%slot_ptr, sys%slot, &
                          keep=owned)
    else
      call build_slot_map(elem_ptr, elem_eq, sys%symmetric, sys%row_ptr, sys%jcn, sys%slot_ptr, sys%slot)
    end if
    allocate(sys%elem_size(nelem))
    sys%elem_size = elem_ptr(2:) - elem_ptr(:nelem)
  end subroutine setup_pattern

  !> Fill-reducing order: METIS nested dissection of the node graph (of every element: the same order on every
  !> process), expanded to equations (sys%eq_position); the natural order without metis.
  subroutine setup_ordering(sys, elem_ptr, elem_eq, eq_node, metis, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system being set up
    integer, intent(in) :: elem_ptr(:)              !< size nelem+1, CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)               !< equation of each element dof; 0 = constrained
    integer, intent(in) :: eq_node(:)               !< node of each equation
    logical, intent(in) :: metis                    !< METIS (else the natural order)
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, allocatable :: xadj(:), adjncy(:), node_position(:)
    integer :: nnode, i
    stat = 0
    errmsg = ''
    nnode = maxval(eq_node)
    allocate(sys%eq_position(sys%neq))
    if (metis) then
      call node_graph_from_elements(nnode, elem_ptr, elem_eq, eq_node, xadj, adjncy)
      call metis_node_order(nnode, xadj, adjncy, node_position, stat, errmsg)
      if (stat /= 0) return
    else
      node_position = [(i, i = 1, nnode)]
    end if
    call equation_order_from_nodes(nnode, node_position, eq_node, sys%eq_position)
    if (.not. is_permutation(sys%eq_position)) then
      stat = 2
      errmsg = 'sparse_setup: the expanded equation order is not a permutation'
    end if
  end subroutine setup_ordering

  !> Symmetric factors of an unsymmetric system: the upper triangle of the (structurally symmetric: element
  !> pattern) full pattern (sys%up_entry) and each entry's mirror (sys%lo_entry).
  subroutine setup_mirror(sys, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system being set up (pattern built)
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer :: m, k, i, j
    stat = 0
    errmsg = ''
    m = count(sys%irn <= sys%jcn)
    allocate(sys%up_entry(m), sys%lo_entry(m), sys%val_sym(m))
    m = 0
    do k = 1, size(sys%jcn)
      i = sys%irn(k)
      j = sys%jcn(k)
      if (i > j) cycle
      m = m + 1
      sys%up_entry(m) = k
      sys%lo_entry(m) = find_in_row(sys%jcn, sys%row_ptr(j), sys%row_ptr(j + 1) - 1, i)
      if (sys%lo_entry(m) == 0) then
        stat = 2
        errmsg = 'sparse_setup: the pattern is not structurally symmetric; symmetric factors impossible'
        return
      end if
    end do
    sys%val_sym = 0.0_dp
  end subroutine setup_mirror

  !> The MUMPS analysis of the pattern (irn, jcn) with the host's ordering, for every instance of the system (solo:
  !> on rank 0 alone; distributed: collective).
  subroutine analyse_instances(sys, symmetric, irn, jcn, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system being set up (instances allocated)
    logical, intent(in) :: symmetric                !< LDL^T of the upper triangle (else LU)
    integer, intent(in) :: irn(:), jcn(:)           !< the entries given to MUMPS
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer :: k
    stat = 0
    errmsg = ''
    if (sys%solo) then
      call solo_analyse(sys, symmetric, irn, jcn, stat, errmsg)
      return
    end if
    do k = 1, size(sys%solvers)
      if (sys%distributed) then
        call mumps_analyse(sys%solvers(k), symmetric, sys%neq, irn, jcn, sys%eq_position, stat, errmsg, &
          single=sys%single_factors, comm=sys%par%comm, rank=sys%par%rank)
      else
        call mumps_analyse(sys%solvers(k), symmetric, sys%neq, irn, jcn, sys%eq_position, stat, errmsg, &
          single=sys%single_factors)
      end if
      if (stat /= 0) return
    end do
  end subroutine analyse_instances

  !> Set all matrix values to zero (pattern kept).
  subroutine sparse_zero(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    if (allocated(sys%val)) sys%val = 0.0_dp
  end subroutine sparse_zero

  !> Add the element matrix ke (n_e x n_e, element dof order) of element ielem into its slots.
  !> Safe when called concurrently from OpenMP threads for different (or the same) elements: atomic adds.
  subroutine sparse_add_element(sys, ielem, ke, exclusive)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer, intent(in) :: ielem                    !< element number (1..nelem)
    real(dp), intent(in) :: ke(:, :)                !< element matrix, full (symmetric when the system is)
    !> .true.: no other thread adds to this element's entries meanwhile (coloured assembly): plain additions
    logical, intent(in), optional :: exclusive
    integer :: a, b, n, s
    integer(i8) :: p
    logical :: excl

    excl = .false.
    if (present(exclusive)) excl = exclusive
    n = sys%elem_size(ielem)
    p = sys%slot_ptr(ielem)
    ! another process's element has no map here (sparse_setup with owned): a caller's error, never data to drop
    if (sys%slot_ptr(ielem + 1) - p /= int(n, i8)**2) error stop 'sparse_add_element: the element is not mapped on &
      &this process (another process adds it)'
    if (excl) then
      do b = 1, n
        do a = 1, n
          s = sys%slot(p)
          p = p + 1
          if (s /= 0) sys%val(s) = sys%val(s) + ke(a, b)
        end do
      end do
      return
    end if
    do b = 1, n
      do a = 1, n
        s = sys%slot(p)
        p = p + 1
        if (s == 0) cycle
        !$omp atomic update
        sys%val(s) = sys%val(s) + ke(a, b)
      end do
    end do
  end subroutine sparse_add_element

  !> Numeric factorization of the current values (MUMPS JOB = 2, workspace retries inside).
  subroutine sparse_factorize(sys, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system after sparse_setup
    integer, intent(out) :: stat                    !< 0 on success; MUMPS INFOG(1) otherwise (-10: singular)
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer(i8) :: c0
    logical :: wide

    if (.not. sys%ready) then
      stat = -1000
      errmsg = 'sparse_factorize: system not set up'
      return
    end if
    ! a pipelined factorization still pending is dropped (these factors replace it): one thread on the instances
    call discard_job(sys)
    c0 = clock_count()
    ! A factorization with large dense fronts runs its BLAS on the process' threads (the OpenMP element loop is not
    ! running meanwhile); a small one stays on one thread, whose BLAS calls are too small to gain from a second
    ! (docs/performance.md, "BLAS threads")
    wide = wide_factorization(sys)
    if (wide) wide = blas_threads_set(sys%factor_threads)
    ! (distributed: a process's values, of its own elements' pattern, are its MUMPS input)
    if (sys%solo) then
      if (sys%sym_factors) then
        sys%val_sym = 0.5_dp * (sys%val(sys%up_entry) + sys%val(sys%lo_entry))
        call solo_factorize(sys, sys%val_sym, stat, errmsg)
      else
        call solo_factorize(sys, sys%val, stat, errmsg)
      end if
    else if (sys%sym_factors) then
      sys%val_sym = 0.5_dp * (sys%val(sys%up_entry) + sys%val(sys%lo_entry))
      call mumps_factorize(sys%solvers(sys%cur), sys%val_sym, stat, errmsg)
    else
      call mumps_factorize(sys%solvers(sys%cur), sys%val, stat, errmsg)
    end if
    if (wide) wide = blas_threads_set(1)
    sys%t_factor = sys%t_factor + seconds_since(c0)
    if (stat == 0) sys%n_factor = sys%n_factor + 1
  end subroutine sparse_factorize

  !> A factorization large enough to run its BLAS on the element loop's threads (sparse_set_factor_threads).
  logical function wide_factorization(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    wide_factorization = sys%factor_threads > 1 .and. mumps_factor_flops(sys%solvers(sys%cur)) >= sys%factor_min_flops
  end function wide_factorization

  !> True when refactorizations may be begun before they are used (sparse_factor_begin).
  logical function sparse_pipelined(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_pipelined = sys%ready .and. sys%pipelined
  end function sparse_pipelined

  !> Begin a factorization of the current values (pipelined systems), to be used from sparse_factor_install on.
  !> With two instances (background) the values are copied into the one not in use now, so that the matrix may be
  !> reassembled meanwhile, and it is factorized on a thread of its own when small enough to keep its BLAS on one
  !> thread (else here and now); the instance in use keeps serving solves until the installation. With one
  !> instance the factorization is deferred until its factors are no longer used: at the installation, or at the
  !> end of the GMRES solve that began it (sparse_solve_krylov), before the matrix changes. Its outcome (stat) is
  !> reported at the installation. stat /= 0 here: nothing begun (not pipelined, or one pending already).
  subroutine sparse_factor_begin(sys, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< pipelined system
    integer, intent(out) :: stat                    !< 0: begun
    character(len=*), intent(out) :: errmsg         !< reason when not begun
    type(c_funptr) :: fn
    stat = 0
    errmsg = ''
    if (.not. sparse_pipelined(sys) .or. associated(sys%job)) then
      stat = -1005
      errmsg = 'sparse_factor_begin: not pipelined, or a factorization pending already'
      return
    end if
    allocate (sys%job)
    sys%job%ms => sys%solvers(size(sys%solvers) + 1 - sys%cur)
    sys%job%deferred = .true.
    if (sys%background) then
      call set_job_values(sys)
      if (sys%job%stat /= 0) return
      if (.not. wide_pipelined(sys)) then
        fn = c_funloc(factor_task)   ! (through a variable: gfortran 12 would place the address in .rodata)
        sys%task = task_start(fn, c_loc(sys%job))
        sys%job%beside = c_associated(sys%task)
      end if
      if (.not. c_associated(sys%task)) call run_job_here(sys)
    end if
  end subroutine sparse_factor_begin

  !> A pipelined factorization large enough for the BLAS threads of a wide one (sparse_factorize), judged by the
  !> analysis' operation estimate, the same for both instances: it runs on the caller's thread, in either mode.
  logical function wide_pipelined(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    wide_pipelined = sys%factor_threads > 1 .and. mumps_factor_flops_estimate(sys%solvers(1)) >= sys%factor_min_flops
  end function wide_pipelined

  !> The job's factorization on this thread (with the BLAS threads of a wide one).
  subroutine run_job_here(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system with a job whose values are set
    logical :: wide
    wide = wide_pipelined(sys)
    if (wide) wide = blas_threads_set(sys%factor_threads)
    call factor_task(c_loc(sys%job))
    if (wide) wide = blas_threads_set(1)
    sys%t_factor_here = sys%t_factor_here + sys%job%seconds
  end subroutine run_job_here

  !> A pending pipelined factorization dropped (its thread waited for): its factors are never used.
  subroutine discard_job(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer :: stat
    if (.not. associated(sys%job)) return
    if (c_associated(sys%task)) stat = task_join(sys%task)
    sys%task = c_null_ptr
    if (.not. sys%job%deferred) sys%t_factor = sys%t_factor + sys%job%seconds
    if (sys%job%beside) sys%t_factor_beside = sys%t_factor_beside + sys%job%seconds
    deallocate (sys%job)
  end subroutine discard_job

  !> The values of the job's factorization into its instance (the symmetric part for symmetric factors).
  subroutine set_job_values(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system with a job
    sys%job%deferred = .false.
    if (sys%sym_factors) then
      sys%val_sym = 0.5_dp * (sys%val(sys%up_entry) + sys%val(sys%lo_entry))
      call mumps_set_values(sys%job%ms, sys%val_sym, sys%job%stat, sys%job%errmsg)
    else
      call mumps_set_values(sys%job%ms, sys%val, sys%job%stat, sys%job%errmsg)
    end if
  end subroutine set_job_values

  !> A deferred factorization (one instance) run now, from the values it was begun with (still the matrix's: the
  !> caller runs it before the matrix changes); nothing otherwise.
  subroutine run_deferred(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    if (.not. associated(sys%job)) return
    if (.not. sys%job%deferred) return
    call set_job_values(sys)
    if (sys%job%stat == 0) call run_job_here(sys)
  end subroutine run_deferred

  !> Install the factorization begun by sparse_factor_begin (running a deferred one, or waiting for its thread):
  !> its factors are used from now on. stat: its outcome; when it failed no factors are left to use (as one
  !> instance would have none), so that the next solve factorizes anew. 0 with nothing pending.
  subroutine sparse_factor_install(sys, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer, intent(out) :: stat                    !< 0 ok, else the factorization's MUMPS error
    character(len=*), intent(out) :: errmsg         !< its message
    integer(i8) :: c0
    stat = 0
    errmsg = ''
    if (.not. associated(sys%job)) return
    call run_deferred(sys)
    if (c_associated(sys%task)) then
      c0 = clock_count()
      stat = task_join(sys%task)
      sys%task = c_null_ptr
      sys%t_factor_wait = sys%t_factor_wait + seconds_since(c0)
    end if
    stat = sys%job%stat
    errmsg = sys%job%errmsg
    sys%t_factor = sys%t_factor + sys%job%seconds
    if (sys%job%beside) sys%t_factor_beside = sys%t_factor_beside + sys%job%seconds
    sys%cur = size(sys%solvers) + 1 - sys%cur
    if (stat == 0) then
      sys%n_factor = sys%n_factor + 1
    else
      call mumps_forget_factors(sys%solvers(sys%cur))
    end if
    deallocate (sys%job)
  end subroutine sparse_factor_install

  !> True while a factorization begun by sparse_factor_begin is not installed.
  logical function sparse_factor_pending(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_factor_pending = associated(sys%job)
  end function sparse_factor_pending

  !> Wall seconds the caller waited at sparse_factor_install for factorizations still running (part of the solve
  !> time when the installation is GMRES's, sparse_solve_krylov).
  real(dp) function sparse_time_factor_wait(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_factor_wait = sys%t_factor_wait
  end function sparse_time_factor_wait

  !> Wall seconds of the factorizations run on their own thread (part of sparse_time_factor, beside the caller's
  !> work).
  real(dp) function sparse_time_factor_beside(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_factor_beside = sys%t_factor_beside
  end function sparse_time_factor_beside

  !> The factorization of a pipelined job (factor_job_t), on the thread of background_task or on the caller's:
  !> it touches its own instance only.
  subroutine factor_task(arg) bind(C, name='ldfcz_sparse_factor_task')
    type(c_ptr), value :: arg                       !< the job (factor_job_t)
    type(factor_job_t), pointer :: job
    integer(i8) :: c0
    call c_f_pointer(arg, job)
    c0 = clock_count()
    call mumps_factorize_values(job%ms, job%stat, job%errmsg)
    job%seconds = seconds_since(c0)
  end subroutine factor_task

  !> BLAS threads for the factorizations of at least min_flops operations (n = 0 or 1: leave the BLAS alone). The
  !> caller passes the threads of its element loop when the host controls the BLAS (blas_threads_default).
  subroutine sparse_set_factor_threads(sys, n, min_flops)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer, intent(in) :: n                        !< threads
    real(dp), intent(in) :: min_flops               !< operations of one factorization from which they are used
    sys%factor_threads = n
    sys%factor_min_flops = min_flops
  end subroutine sparse_set_factor_threads

  !> Floating-point operations of one factorization (MUMPS' estimate before the first, then the effective count
  !> of the last); 0 before the setup.
  real(dp) function sparse_factor_flops(sys) result(flops)
    type(sparse_system_t), intent(in) :: sys        !< system
    if (sys%solo) then
      flops = sys%solo_flops
    else
      flops = mumps_factor_flops(sys%solvers(sys%cur))
    end if
  end function sparse_factor_flops

  !> Solo (--reproducible, distributed): the processes' MUMPS input (row and column of each of their entries)
  !> gathered on rank 0 in rank order and analysed there by an instance of rank 0 alone; the outcome on every
  !> process.
  subroutine solo_analyse(sys, symmetric, irn, jcn, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system being set up
    logical, intent(in) :: symmetric                !< LDL^T of the upper triangle (else LU)
    integer, intent(in) :: irn(:), jcn(:)           !< this process's entries
    integer, intent(out) :: stat                    !< 0 on success (the same on every process)
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, allocatable :: all_irn(:), all_jcn(:)
    call parallel_concat_first(sys%par, irn, all_irn)
    call parallel_concat_first(sys%par, jcn, all_jcn)
    stat = 0
    errmsg = ''
    if (sys%par%rank == 0) call mumps_analyse(sys%solvers(sys%cur), symmetric, sys%neq, all_irn, all_jcn, &
      sys%eq_position, &
      stat, errmsg, single=sys%single_factors, comm=parallel_comm_self())
    call agree(sys, stat, errmsg)
    sys%solo_factored = .false.
    call share_counts(sys)
  end subroutine solo_analyse

  !> Solo: the processes' values gathered on rank 0 (the order of solo_analyse) and factorized there.
  subroutine solo_factorize(sys, values, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< analysed system
    real(dp), intent(in) :: values(:)               !< this process's entries
    integer, intent(out) :: stat                    !< 0 on success (the same on every process)
    character(len=*), intent(out) :: errmsg         !< reason on failure
    real(dp), allocatable :: all_values(:)
    call parallel_concat_first(sys%par, values, all_values)
    stat = 0
    errmsg = ''
    if (sys%par%rank == 0) call mumps_factorize(sys%solvers(sys%cur), all_values, stat, errmsg)
    call agree(sys, stat, errmsg)
    sys%solo_factored = stat == 0
    call share_counts(sys)
  end subroutine solo_factorize

  !> Solo: rank 0's status and message on every process (collective).
  subroutine agree(sys, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer, intent(inout) :: stat                  !< rank 0's status out
    character(len=*), intent(inout) :: errmsg       !< rank 0's message out
    character(len=:), allocatable :: text
    text = trim(errmsg)
    call parallel_first_error(sys%par, stat, text)
    errmsg = text
  end subroutine agree

  !> Solo: rank 0's operation count and factor entries on every process (the GMRES budget and the summary use
  !> them).
  subroutine share_counts(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    real(dp) :: v(2)
    v = [mumps_factor_flops(sys%solvers(sys%cur)), real(mumps_factor_entries(sys%solvers(sys%cur)), dp)]
    call parallel_bcast(sys%par, v)
    sys%solo_flops = v(1)
    sys%solo_entries = nint(v(2), i8)
  end subroutine share_counts

  !> Floating-point operations of one GMRES iteration of sparse_solve_krylov with the last factors, counted from the
  !> sizes of the factors and the matrix: the two triangular sweeps (2 per factor entry and sweep: LU uses each
  !> entry of L or U in one sweep, LDL^T each entry of L in both) and the product (2 per stored entry, 4 for the
  !> upper triangle of a symmetric matrix, whose off-diagonal entries act twice). The orthogonalisation (4 n j at
  !> iteration j) is left out. The same number on every run, thread count and process (MUMPS' global entry count,
  !> the processes' entries summed at set-up): a measure of work that decisions may use (newton_iteration);
  !> 0 before a factorization.
  real(dp) function sparse_iteration_flops(sys) result(flops)
    type(sparse_system_t), intent(in) :: sys        !< system
    real(dp) :: sweeps, product
    flops = 0.0_dp
    if (.not. sparse_is_factored(sys)) return
    sweeps = merge(4.0_dp, 2.0_dp, sys%symmetric .or. sys%sym_factors)
    product = merge(4.0_dp, 2.0_dp, sys%symmetric)
    flops = sweeps * real(sparse_factor_entries(sys), dp) + product * sys%product_entries
  end function sparse_iteration_flops

  !> True when the factors are those of the stored matrix (sparse_solve solves it), false when they are the
  !> symmetric part's or in single precision (a preconditioner for sparse_solve_krylov only).
  logical function sparse_factors_exact(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_factors_exact = .not. (sys%sym_factors .or. sys%single_factors)
  end function sparse_factors_exact

  !> Solve with the last factors (MUMPS JOB = 3): rhs in, x out; x = A^-1 rhs only when sparse_factors_exact
  !> (otherwise an approximation: factors of the symmetric part, or in single precision).
  subroutine sparse_solve(sys, rhs, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< factored system
    real(dp), intent(inout) :: rhs(:)               !< right-hand side (size neq) in, solution out
    integer, intent(out) :: stat                    !< 0 on success
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer(i8) :: c0

    if (.not. sys%ready) then
      stat = -1000
      errmsg = 'sparse_solve: system not set up'
      return
    end if
    c0 = clock_count()
    call factor_solve(sys, rhs, stat, errmsg)
    sys%t_solve = sys%t_solve + seconds_since(c0)
    if (stat == 0) sys%n_solve = sys%n_solve + 1
  end subroutine sparse_solve

  !> Solve with the factors; distributed: each process's piece of the solution (MUMPS' distributed solution)
  !> gathered on every process, or with central vectors (LDFCZ_MUMPS_CENTRAL_RHS) rank 0's solution broadcast.
  subroutine factor_solve(sys, rhs, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< factored system
    real(dp), intent(inout) :: rhs(:)               !< right-hand side in, solution out
    integer, intent(out) :: stat                    !< 0 on success (the same on every process: MUMPS INFOG)
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, allocatable :: rows(:)
    if (sys%solo) then
      stat = 0
      errmsg = ''
      if (sys%par%rank == 0) call mumps_solve(sys%solvers(sys%cur), rhs, stat, errmsg)
      call agree(sys, stat, errmsg)
      if (stat == 0) call parallel_bcast(sys%par, rhs)
      return
    end if
    call mumps_solve(sys%solvers(sys%cur), rhs, stat, errmsg)
    if (.not. sys%distributed .or. stat /= 0) return
    if (mumps_solution_distributed(sys%solvers(sys%cur))) then
      call mumps_solution_rows(sys%solvers(sys%cur), rows)
      call parallel_gather_pieces(sys%par, rows, rhs)
    else
      call parallel_bcast(sys%par, rhs)
    end if
  end subroutine factor_solve

  !> y = A x with the current values (the stored triangle mirrored when symmetric; distributed: the processes'
  !> parts summed).
  subroutine sparse_matvec(sys, x, y)
    type(sparse_system_t), intent(inout) :: sys     !< system
    real(dp), intent(in) :: x(:)                    !< vector (size neq)
    real(dp), intent(out) :: y(:)                   !< product (size neq)
    integer :: k, i
    real(dp) :: acc

    y = 0.0_dp
    if (.not. allocated(sys%val)) return
    ! (distributed: this process's part, over the pattern of its own elements, then summed)
    if (sys%symmetric) then
      call symmetric_product(sys, x, y)
    else
      ! full storage: rows are independent, so the product is threaded over rows (same sum order as serial)
      !$omp parallel do schedule(static) private(k, acc) if (sys%neq > 2000)
      do i = 1, sys%neq
        acc = 0.0_dp
        do k = sys%row_ptr(i), sys%row_ptr(i + 1) - 1
          acc = acc + sys%val(k) * x(sys%jcn(k))
        end do
        y(i) = acc
      end do
      !$omp end parallel do
    end if
    if (sys%distributed) call parallel_sum(sys%par, y)
  end subroutine sparse_matvec

  !> y += A x for the stored upper triangle mirrored, entry by entry in their order.
  subroutine symmetric_product(sys, x, y)
    type(sparse_system_t), intent(in) :: sys        !< symmetric system
    real(dp), intent(in) :: x(:)                    !< vector (size neq)
    real(dp), intent(inout) :: y(:)                 !< product (size neq)
    integer :: k, i, j

    do k = 1, size(sys%val)
      i = sys%irn(k)
      j = sys%jcn(k)
      y(i) = y(i) + sys%val(k) * x(j)
      if (i /= j) y(j) = y(j) + sys%val(k) * x(i)
    end do
  end subroutine symmetric_product

  !> True when factors from an earlier sparse_factorize are available (possibly of older values).
  logical function sparse_is_factored(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    if (sys%solo) then
      sparse_is_factored = sys%ready .and. sys%solo_factored
    else
      sparse_is_factored = sys%ready .and. mumps_is_factored(sys%solvers(sys%cur))
    end if
  end function sparse_is_factored

  !> Solve A x = rhs for the CURRENT values A by restarted GMRES(m), right-preconditioned by the LAST factors
  !> (possibly of an older matrix: Newton's factorization reused as a preconditioner, Saad 2003, section 9.3.2).
  !> x0 = 0; converged when |rhs - A x| <= rel_tol |rhs|. The preconditioned directions are kept (m vectors) so
  !> the solution needs no extra solve. stat: 0 converged, 1 not converged within max_iter (rhs then holds the
  !> best iterate), < 0 a MUMPS error. Each iteration costs one solve with the factors and one product with A.
  !> Pipelined systems (sparse_pipelined) may refactorize on the way: after refactor_at iterations without
  !> convergence a factorization of the current values begins (sparse_factor_begin, beside the iterations that
  !> follow), the first cycle ends after switch_at iterations, its factors are installed there (sparse_factor_install,
  !> waiting for them if need be) and precondition the cycles that follow (restart each); converged earlier, the
  !> factorization stays pending for the caller to install. The points are counts: the iterates never depend on
  !> when the factorization ends.
  subroutine sparse_solve_krylov(sys, rhs, rel_tol, max_iter, restart, iterations, stat, errmsg, refactor_at, &
      switch_at)
    type(sparse_system_t), intent(inout) :: sys     !< system with current values and factors of some values
    real(dp), intent(inout) :: rhs(:)               !< right-hand side (size neq) in, solution out
    real(dp), intent(in) :: rel_tol                 !< relative residual tolerance
    integer, intent(in) :: max_iter                 !< largest number of GMRES iterations in total
    integer, intent(in) :: restart                  !< Krylov dimension m before a restart
    integer, intent(out) :: iterations              !< GMRES iterations done
    integer, intent(out) :: stat                    !< 0 converged, 1 not converged, < 0 MUMPS error
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, intent(in), optional :: refactor_at    !< pipelined: iterations before a factorization begins
    integer, intent(in), optional :: switch_at      !< pipelined: iterations of the first cycle (> refactor_at)
    real(dp), allocatable :: v(:, :), z(:, :), h(:, :), cs(:), sn(:), g(:), y(:), x(:), w(:), b(:)
    real(dp) :: bnorm
    integer :: n, m, m_cycle, begin_at
    integer(i8) :: c0
    logical :: done
    real(dp) :: t_here0

    stat = 0
    errmsg = ''
    iterations = 0
    if (.not. sparse_is_factored(sys)) then
      stat = -1002
      errmsg = 'sparse_solve_krylov: no factors to precondition with'
      return
    end if
    c0 = clock_count()
    t_here0 = sys%t_factor_here     ! a pipelined factorization run here is factorization time, not solve time
    n = sys%neq
    m = max(1, restart)
    m_cycle = m
    begin_at = -1
    if (present(refactor_at) .and. present(switch_at) .and. sparse_pipelined(sys)) then
      if (.not. associated(sys%job) .and. refactor_at < switch_at) then
        begin_at = refactor_at
        m_cycle = switch_at
      end if
    end if
    allocate (v(n, max(m, m_cycle) + 1), z(n, max(m, m_cycle)), h(max(m, m_cycle) + 1, max(m, m_cycle)), &
      cs(max(m, m_cycle)), sn(max(m, m_cycle)), g(max(m, m_cycle) + 1), y(max(m, m_cycle)), x(n), w(n), b(n))
    b = rhs
    x = 0.0_dp
    bnorm = norm2(b)
    if (bnorm == 0.0_dp) then
      rhs = 0.0_dp
      sys%t_solve = sys%t_solve + seconds_since(c0)
      return
    end if
    stat = 1
    do while (iterations < max_iter)
      call gmres_cycle(sys, b, bnorm, rel_tol, max_iter, m_cycle, begin_at, x, v, z, h, cs, sn, g, y, w, iterations, &
        done, stat, errmsg)
      if (done) exit
      if (begin_at >= 0) then
        ! the first cycle of a refactorization ends: its factors precondition the next cycles
        call sparse_factor_install(sys, stat, errmsg)
        if (stat /= 0) exit
        stat = 1
        begin_at = -1
      end if
      m_cycle = m
    end do
    if (stat == 1) errmsg = 'sparse_solve_krylov: GMRES did not converge within the iteration limit'
    ! a refactorization begun and not installed: a deferred one runs now, while the matrix is the one it was begun
    ! with (an error drops it)
    if (stat < 0) then
      call discard_job(sys)
    else
      call run_deferred(sys)
    end if
    rhs = x
    sys%n_krylov = sys%n_krylov + iterations
    sys%t_solve = sys%t_solve + seconds_since(c0) - (sys%t_factor_here - t_here0)
  end subroutine sparse_solve_krylov

  !> One cycle of GMRES(m) from x: Arnoldi with modified Gram-Schmidt and Givens rotations, right-preconditioned
  !> directions z_j kept, x += Z y at the end. done: converged (stat 0), a MUMPS error (stat < 0), a breakdown
  !> without convergence or the iteration limit reached (stat 1). begin_at >= 0: the pipelined factorization
  !> begins when that many iterations are done without convergence.
  subroutine gmres_cycle(sys, b, bnorm, rel_tol, max_iter, m, begin_at, x, v, z, h, cs, sn, g, y, w, iterations, &
      done, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system
    real(dp), intent(in) :: b(:)                    !< right-hand side
    real(dp), intent(in) :: bnorm                   !< its norm
    real(dp), intent(in) :: rel_tol                 !< relative residual tolerance
    integer, intent(in) :: max_iter                 !< iteration limit in total
    integer, intent(in) :: m                        !< Krylov dimension of this cycle
    integer, intent(in) :: begin_at                 !< iterations before the pipelined factorization (-1: none)
    real(dp), intent(inout) :: x(:)                 !< iterate
    real(dp), intent(inout) :: v(:, :), z(:, :), h(:, :), cs(:), sn(:), g(:), y(:), w(:)  !< work (m columns)
    integer, intent(inout) :: iterations            !< iterations done
    logical, intent(out) :: done                    !< the solve ends
    integer, intent(inout) :: stat                  !< 0 converged, 1 not (yet), < 0 MUMPS error
    character(len=*), intent(inout) :: errmsg       !< reason on failure
    real(dp) :: beta, tmp, hnorm
    integer :: i, j, k

    done = .true.
    call sparse_matvec(sys, x, w)
    v(:, 1) = b - w
    beta = norm2(v(:, 1))
    if (beta <= rel_tol * bnorm) then
      stat = 0
      return
    end if
    v(:, 1) = v(:, 1) / beta
    g = 0.0_dp
    g(1) = beta
    h = 0.0_dp
    k = 0
    arnoldi: do j = 1, m
      if (iterations == begin_at) then
        call sparse_factor_begin(sys, i, errmsg)
        if (i /= 0) then
          stat = i
          return
        end if
      end if
      z(:, j) = v(:, j)
      call factor_solve(sys, z(:, j), i, errmsg)
      if (i /= 0) then
        stat = i
        return
      end if
      sys%n_solve = sys%n_solve + 1
      iterations = iterations + 1
      call sparse_matvec(sys, z(:, j), w)
      do i = 1, j                                   ! modified Gram-Schmidt
        h(i, j) = dot_product(w, v(:, i))
        w = w - h(i, j) * v(:, i)
      end do
      h(j + 1, j) = norm2(w)
      if (h(j + 1, j) > 0.0_dp) v(:, j + 1) = w / h(j + 1, j)
      do i = 1, j - 1                               ! earlier Givens rotations
        tmp = cs(i) * h(i, j) + sn(i) * h(i + 1, j)
        h(i + 1, j) = -sn(i) * h(i, j) + cs(i) * h(i + 1, j)
        h(i, j) = tmp
      end do
      hnorm = hypot(h(j, j), h(j + 1, j))
      if (hnorm == 0.0_dp) exit arnoldi            ! A z_j = 0: breakdown, keep the first j-1 directions
      cs(j) = h(j, j) / hnorm
      sn(j) = h(j + 1, j) / hnorm
      h(j, j) = hnorm
      h(j + 1, j) = 0.0_dp
      g(j + 1) = -sn(j) * g(j)
      g(j) = cs(j) * g(j)
      k = j
      if (abs(g(j + 1)) <= rel_tol * bnorm .or. iterations >= max_iter) exit arnoldi
    end do arnoldi
    do i = k, 1, -1                                 ! back substitution, x += Z y
      y(i) = (g(i) - dot_product(h(i, i + 1:k), y(i + 1:k))) / h(i, i)
    end do
    do i = 1, k
      x = x + y(i) * z(:, i)
    end do
    if (abs(g(k + 1)) <= rel_tol * bnorm) then
      stat = 0
      return
    end if
    if (k < j .and. k < m) return                   ! breakdown without convergence
    done = iterations >= max_iter
  end subroutine gmres_cycle

  !> GMRES iterations done by sparse_solve_krylov.
  integer function sparse_krylov_count(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_krylov_count = sys%n_krylov
  end function sparse_krylov_count

  !> Terminate MUMPS (JOB = -2) and free everything; the timers and counters are reset too.
  subroutine sparse_destroy(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    integer :: k
    call discard_job(sys)                           ! a factorization still running ends first
    if (associated(sys%solvers)) then
      do k = 1, size(sys%solvers)
        call mumps_destroy(sys%solvers(k))
      end do
      deallocate (sys%solvers)
    end if
    sys%cur = 1
    sys%pipelined = .false.
    sys%background = .false.
    sys%t_factor_wait = 0.0_dp
    sys%t_factor_beside = 0.0_dp
    sys%t_factor_here = 0.0_dp
    if (allocated(sys%row_ptr)) deallocate(sys%row_ptr)
    if (allocated(sys%irn)) deallocate(sys%irn)
    if (allocated(sys%jcn)) deallocate(sys%jcn)
    if (allocated(sys%val)) deallocate(sys%val)
    if (allocated(sys%elem_size)) deallocate(sys%elem_size)
    if (allocated(sys%slot_ptr)) deallocate(sys%slot_ptr)
    if (allocated(sys%slot)) deallocate(sys%slot)
    if (allocated(sys%eq_position)) deallocate(sys%eq_position)
    if (allocated(sys%up_entry)) deallocate(sys%up_entry)
    if (allocated(sys%lo_entry)) deallocate(sys%lo_entry)
    if (allocated(sys%val_sym)) deallocate(sys%val_sym)
    sys%distributed = .false.
    sys%solo = .false.
    sys%solo_factored = .false.
    sys%solo_flops = 0.0_dp
    sys%solo_entries = 0
    sys%sym_factors = .false.
    sys%single_factors = .false.
    sys%neq = 0
    sys%ready = .false.
    sys%t_analysis = 0.0_dp
    sys%t_factor = 0.0_dp
    sys%t_solve = 0.0_dp
    sys%n_analysis = 0
    sys%n_factor = 0
    sys%n_solve = 0
    sys%n_krylov = 0
  end subroutine sparse_destroy

  !> Wall seconds in the broadcasts of solutions and sums of products (distributed).
  real(dp) function sparse_time_comm(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_comm = sys%par%t_comm
  end function sparse_time_comm

  !> Stored entries (upper triangle only when symmetric).
  integer(i8) function sparse_nnz(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_nnz = 0
    if (allocated(sys%val)) sparse_nnz = size(sys%val, kind=i8)
  end function sparse_nnz

  !> Number of equations.
  integer function sparse_neq(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_neq = sys%neq
  end function sparse_neq

  !> True for an LDL^T (upper triangle) system.
  logical function sparse_is_symmetric(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_is_symmetric = sys%symmetric
  end function sparse_is_symmetric

  !> Entries in the factors (MUMPS INFOG(29) after a factorization, the INFOG(20) estimate before).
  integer(i8) function sparse_factor_entries(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    if (sys%solo) then
      sparse_factor_entries = sys%solo_entries
    else
      sparse_factor_entries = mumps_factor_entries(sys%solvers(sys%cur))
    end if
  end function sparse_factor_entries

  !> Cumulative wall seconds in setup (pattern, slot maps, ordering, MUMPS analysis).
  real(dp) function sparse_time_analysis(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_analysis = sys%t_analysis
  end function sparse_time_analysis

  !> Cumulative wall seconds in numeric factorizations.
  real(dp) function sparse_time_factor(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_factor = sys%t_factor
  end function sparse_time_factor

  !> Cumulative wall seconds in solves.
  real(dp) function sparse_time_solve(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_time_solve = sys%t_solve
  end function sparse_time_solve

  !> Number of successful factorizations.
  integer function sparse_factor_count(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_factor_count = sys%n_factor
  end function sparse_factor_count

  !> Number of analyses (1 after setup: the analysis is never repeated for a pattern).
  integer function sparse_analysis_count(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_analysis_count = sys%n_analysis
  end function sparse_analysis_count

  !> Number of successful solves.
  integer function sparse_solve_count(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_solve_count = sys%n_solve
  end function sparse_solve_count

  !> The equation order handed to MUMPS (position of each equation).
  subroutine sparse_ordering(sys, position)
    type(sparse_system_t), intent(in) :: sys        !< system after setup
    integer, allocatable, intent(out) :: position(:) !< pivot position of each equation
    if (allocated(sys%eq_position)) then
      position = sys%eq_position
    else
      allocate(position(0))
    end if
  end subroutine sparse_ordering

  !> The pivot order MUMPS reports after its analysis (SYM_PERM).
  subroutine sparse_pivot_order(sys, position)
    type(sparse_system_t), intent(in) :: sys        !< system after setup
    integer, allocatable, intent(out) :: position(:) !< position of each equation
    call mumps_pivot_order(sys%solvers(sys%cur), position)
  end subroutine sparse_pivot_order

  !> Dense copy of the matrix (both triangles), for tests and small-model diagnostics.
  subroutine sparse_to_dense(sys, a)
    type(sparse_system_t), intent(in) :: sys        !< system
    real(dp), intent(out) :: a(:, :)                !< dense matrix (neq x neq)
    integer :: k

    a = 0.0_dp
    if (.not. allocated(sys%val)) return
    do k = 1, size(sys%val)
      a(sys%irn(k), sys%jcn(k)) = a(sys%irn(k), sys%jcn(k)) + sys%val(k)
      if (sys%symmetric .and. sys%irn(k) /= sys%jcn(k)) a(sys%jcn(k), sys%irn(k)) = a(sys%irn(k), sys%jcn(k))
    end do
  end subroutine sparse_to_dense

  integer(i8) function clock_count()
    call system_clock(clock_count)
  end function clock_count

  real(dp) function seconds_since(c0)
    integer(i8), intent(in) :: c0                   !< clock_count() at the start
    integer(i8) :: c1, rate
    call system_clock(c1, rate)
    seconds_since = real(c1 - c0, dp) / real(max(rate, 1_i8), dp)
  end function seconds_since

end module sparse_system
