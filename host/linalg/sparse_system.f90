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
                          mumps_solution_distributed, mumps_factor_flops
  use blas_threads, only: blas_threads_set
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
    type(mumps_solver_t) :: solver                  !< the MUMPS instance
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
      symmetric_factors, single_factors, par, owned, one_process)
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
    character(len=*), parameter :: here = 'sparse_setup'
    integer, allocatable :: xadj(:), adjncy(:), node_position(:), own_eq(:)
    integer :: nnode, nelem, i, k, m, j
    integer(i8) :: c0
    logical :: metis
    real(dp) :: entries(1)

    stat = 0
    errmsg = ''
    c0 = clock_count()
    call sparse_destroy(sys)
    metis = .true.
    if (present(use_metis)) metis = use_metis
    nelem = size(elem_ptr) - 1
    if (neq < 1) then
      stat = 1
      write(errmsg, '(a,a,i0)') here, ': no equations, neq = ', neq
      return
    end if
    if (size(eq_node) /= neq) then
      stat = 1
      errmsg = here//': eq_node must have neq entries'
      return
    end if
    if (nelem < 1 .or. elem_ptr(1) /= 1 .or. elem_ptr(nelem + 1) - 1 > size(elem_eq)) then
      stat = 1
      errmsg = here//': elem_ptr is not a valid CSR pointer array into elem_eq'
      return
    end if
    if (any(elem_ptr(2:) < elem_ptr(:nelem))) then
      stat = 1
      errmsg = here//': elem_ptr decreases'
      return
    end if
    if (any(eq_node < 1)) then
      stat = 1
      errmsg = here//': eq_node holds a node index < 1'
      return
    end if
    sys%neq = neq
    sys%symmetric = symmetric
    sys%distributed = .false.
    if (present(par)) then
      sys%par = par
      sys%distributed = parallel_distributed(par) .and. present(owned)
    end if
    sys%solo = .false.
    if (sys%distributed .and. present(one_process)) sys%solo = one_process

    ! a process of a distributed run builds its part of the matrix only: the pattern of its own elements (the others
    ! as if all their dofs were constrained). Its entries are its MUMPS input (MUMPS sums the entries that several
    ! processes give) and its part of every product; the whole pattern is never built (docs/performance.md, "Memory
    ! of a process")
    if (sys%distributed) then
      own_eq = elem_eq(1:elem_ptr(nelem + 1) - 1)
      do k = 1, nelem
        if (.not. owned(k)) own_eq(elem_ptr(k):elem_ptr(k + 1) - 1) = 0
      end do
      call build_pattern(neq, elem_ptr, own_eq, symmetric, sys%row_ptr, sys%jcn, stat, errmsg, empty_rows=.true.)
      deallocate (own_eq)
    else
      call build_pattern(neq, elem_ptr, elem_eq(1:elem_ptr(nelem + 1) - 1), symmetric, sys%row_ptr, sys%jcn, &
                         stat, errmsg)
    end if
    if (stat /= 0) return
    allocate(sys%irn(size(sys%jcn)), sys%val(size(sys%jcn)))
    do i = 1, neq
      sys%irn(sys%row_ptr(i):sys%row_ptr(i + 1) - 1) = i
    end do
    sys%val = 0.0_dp
    ! and maps only its own elements (the maps of all elements are 2.3 kB a C3D8: 50 MB on the paper's application
    ! mesh)
    if (sys%distributed) then
      call build_slot_map(elem_ptr, elem_eq, symmetric, sys%row_ptr, sys%jcn, sys%slot_ptr, sys%slot, keep=owned)
    else
      call build_slot_map(elem_ptr, elem_eq, symmetric, sys%row_ptr, sys%jcn, sys%slot_ptr, sys%slot)
    end if
    allocate(sys%elem_size(nelem))
    sys%elem_size = elem_ptr(2:) - elem_ptr(:nelem)

    ! Fill-reducing order: METIS nested dissection of the node graph (of every element: the same order on every
    ! process), expanded to equations.
    nnode = maxval(eq_node)
    allocate(sys%eq_position(neq))
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
      errmsg = here//': the expanded equation order is not a permutation'
      return
    end if

    sys%sym_factors = .false.
    if (present(symmetric_factors)) sys%sym_factors = symmetric_factors .and. .not. symmetric
    sys%single_factors = .false.
    if (present(single_factors)) sys%single_factors = single_factors
    if (sys%sym_factors) then
      ! the upper triangle of the (structurally symmetric: element pattern) full pattern and each entry's mirror
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
          errmsg = here//': the pattern is not structurally symmetric; symmetric factors impossible'
          return
        end if
      end do
      sys%val_sym = 0.0_dp
      if (sys%solo) then
        call solo_analyse(sys, .true., sys%irn(sys%up_entry), sys%jcn(sys%up_entry), stat, errmsg)
      else if (sys%distributed) then
        call mumps_analyse(sys%solver, .true., neq, sys%irn(sys%up_entry), sys%jcn(sys%up_entry), &
          sys%eq_position, stat, errmsg, single=sys%single_factors, comm=sys%par%comm, rank=sys%par%rank)
      else
        call mumps_analyse(sys%solver, .true., neq, sys%irn(sys%up_entry), sys%jcn(sys%up_entry), &
          sys%eq_position, stat, errmsg, single=sys%single_factors)
      end if
    else if (sys%solo) then
      call solo_analyse(sys, symmetric, sys%irn, sys%jcn, stat, errmsg)
    else if (sys%distributed) then
      call mumps_analyse(sys%solver, symmetric, neq, sys%irn, sys%jcn, sys%eq_position, stat, errmsg, &
        single=sys%single_factors, comm=sys%par%comm, rank=sys%par%rank)
    else
      call mumps_analyse(sys%solver, symmetric, neq, sys%irn, sys%jcn, sys%eq_position, stat, errmsg, &
        single=sys%single_factors)
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
    c0 = clock_count()
    ! A factorization with large dense fronts runs its BLAS on the process' threads (the OpenMP element loop is not
    ! running meanwhile); a small one stays on one thread, whose BLAS calls are too small to gain from a second
    ! (docs/performance.md, "BLAS threads")
    wide = sys%factor_threads > 1 .and. mumps_factor_flops(sys%solver) >= sys%factor_min_flops
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
      call mumps_factorize(sys%solver, sys%val_sym, stat, errmsg)
    else
      call mumps_factorize(sys%solver, sys%val, stat, errmsg)
    end if
    if (wide) wide = blas_threads_set(1)
    sys%t_factor = sys%t_factor + seconds_since(c0)
    if (stat == 0) sys%n_factor = sys%n_factor + 1
  end subroutine sparse_factorize

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
      flops = mumps_factor_flops(sys%solver)
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
    if (sys%par%rank == 0) call mumps_analyse(sys%solver, symmetric, sys%neq, all_irn, all_jcn, sys%eq_position, &
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
    if (sys%par%rank == 0) call mumps_factorize(sys%solver, all_values, stat, errmsg)
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
    v = [mumps_factor_flops(sys%solver), real(mumps_factor_entries(sys%solver), dp)]
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
      if (sys%par%rank == 0) call mumps_solve(sys%solver, rhs, stat, errmsg)
      call agree(sys, stat, errmsg)
      if (stat == 0) call parallel_bcast(sys%par, rhs)
      return
    end if
    call mumps_solve(sys%solver, rhs, stat, errmsg)
    if (.not. sys%distributed .or. stat /= 0) return
    if (mumps_solution_distributed(sys%solver)) then
      call mumps_solution_rows(sys%solver, rows)
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
      sparse_is_factored = sys%ready .and. mumps_is_factored(sys%solver)
    end if
  end function sparse_is_factored

  !> Solve A x = rhs for the CURRENT values A by restarted GMRES(m), right-preconditioned by the LAST factors
  !> (possibly of an older matrix: Newton's factorization reused as a preconditioner, Saad 2003, section 9.3.2).
  !> x0 = 0; converged when |rhs - A x| <= rel_tol |rhs|. The preconditioned directions are kept (m vectors) so
  !> the solution needs no extra solve. stat: 0 converged, 1 not converged within max_iter (rhs then holds the
  !> best iterate), < 0 a MUMPS error. Each iteration costs one solve with the factors and one product with A.
  subroutine sparse_solve_krylov(sys, rhs, rel_tol, max_iter, restart, iterations, stat, errmsg)
    type(sparse_system_t), intent(inout) :: sys     !< system with current values and factors of some values
    real(dp), intent(inout) :: rhs(:)               !< right-hand side (size neq) in, solution out
    real(dp), intent(in) :: rel_tol                 !< relative residual tolerance
    integer, intent(in) :: max_iter                 !< largest number of GMRES iterations in total
    integer, intent(in) :: restart                  !< Krylov dimension m before a restart
    integer, intent(out) :: iterations              !< GMRES iterations done
    integer, intent(out) :: stat                    !< 0 converged, 1 not converged, < 0 MUMPS error
    character(len=*), intent(out) :: errmsg         !< reason on failure
    real(dp), allocatable :: v(:, :), z(:, :), h(:, :), cs(:), sn(:), g(:), y(:), x(:), w(:), b(:)
    real(dp) :: beta, bnorm, tmp, hnorm
    integer :: n, m, j, i, k
    integer(i8) :: c0

    stat = 0
    errmsg = ''
    iterations = 0
    if (.not. sparse_is_factored(sys)) then
      stat = -1002
      errmsg = 'sparse_solve_krylov: no factors to precondition with'
      return
    end if
    c0 = clock_count()
    n = sys%neq
    m = max(1, restart)
    allocate (v(n, m + 1), z(n, m), h(m + 1, m), cs(m), sn(m), g(m + 1), y(m), x(n), w(n), b(n))
    b = rhs
    x = 0.0_dp
    bnorm = norm2(b)
    if (bnorm == 0.0_dp) then
      rhs = 0.0_dp
      sys%t_solve = sys%t_solve + seconds_since(c0)
      return
    end if
    stat = 1
    restarts: do while (iterations < max_iter)
      call sparse_matvec(sys, x, w)
      v(:, 1) = b - w
      beta = norm2(v(:, 1))
      if (beta <= rel_tol * bnorm) then
        stat = 0
        exit restarts
      end if
      v(:, 1) = v(:, 1) / beta
      g = 0.0_dp
      g(1) = beta
      h = 0.0_dp
      k = 0
      arnoldi: do j = 1, m
        z(:, j) = v(:, j)
        call factor_solve(sys, z(:, j), i, errmsg)
        if (i /= 0) then
          stat = i
          exit restarts
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
        exit restarts
      end if
      if (k < j .and. k < m) exit restarts           ! breakdown without convergence
    end do restarts
    if (stat == 1) errmsg = 'sparse_solve_krylov: GMRES did not converge within the iteration limit'
    rhs = x
    sys%n_krylov = sys%n_krylov + iterations
    sys%t_solve = sys%t_solve + seconds_since(c0)
  end subroutine sparse_solve_krylov

  !> GMRES iterations done by sparse_solve_krylov.
  integer function sparse_krylov_count(sys)
    type(sparse_system_t), intent(in) :: sys        !< system
    sparse_krylov_count = sys%n_krylov
  end function sparse_krylov_count

  !> Terminate MUMPS (JOB = -2) and free everything; the timers and counters are reset too.
  subroutine sparse_destroy(sys)
    type(sparse_system_t), intent(inout) :: sys     !< system
    call mumps_destroy(sys%solver)
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
      sparse_factor_entries = mumps_factor_entries(sys%solver)
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
    call mumps_pivot_order(sys%solver, position)
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
