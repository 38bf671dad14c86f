!> The discretised model the Newton solver works on: dof numbering (ndim dofs per node, prescribed dofs eliminated),
!> per-element converged and trial state, the threaded element loop calling UEL/UMAT exactly as Abaqus/Standard
!> does (docs/conventions.md), and the assembly into the sparse system.
module analysis_core
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp, i8
  use ldfcz_text, only: upper_case
  use model_types, only: model_t, material_t, etype_user, orientation_axes, model_dof_node, model_dof
  use element_catalog, only: element_name, element_family, element_types, element_nnode, element_ndim
  use solid_shape, only: solid_first_order_temperature, solid_gauss_point, solid_shape_eval
  use solid_types, only: umat_props_pad
  use solid_element, only: solid_material_t, solid_element_info, solid_element_compute, SOLID_MAT_ELASTIC, &
    solid_geometry_t, solid_element_geometry, solid_compact_geometry_size, solid_compact_geometry, &
    SOLID_MAT_UMAT, SOLID_PNEWDT_LARGE
  use element_colors, only: color_elements
  use sparse_system, only: sparse_system_t, sparse_setup, sparse_zero, sparse_add_element, sparse_destroy, &
    sparse_set_factor_threads, sparse_time_factor, sparse_time_solve, sparse_time_analysis, sparse_factor_count, &
    sparse_time_factor_beside, sparse_time_factor_wait
  use user_routines, only: user_routines_t
  use material_law, only: material_elastic_law
  use distributed_loads, only: dload_element, dload_uel_arrays, dload_has
  use element_state, only: elem_state_t, element_state_free, element_state_copy
  use analysis_state, only: analysis_state_t, analysis_state_init
  use increment, only: increment_t, increment_time, increment_end
  use solver_options, only: solver_options_t, newton_auto
  use solver_text, only: itoa, rtoa
  use abaqus_host_state, only: abaqus_set_caller, abaqus_stop_requested, abaqus_stop_element, abaqus_stop_message, &
    abaqus_request_stop
  use parallel_context, only: parallel_t, parallel_distributed, parallel_sum, parallel_min, parallel_max, &
    parallel_any, parallel_lowest
  use element_partition, only: partition_elements
  use linear_constraints, only: constraint_set_t, constraints_build, constraints_extend, constraints_transform, &
    constraints_mark_masters
  use coupling_constraints, only: coupling_mark_used
  use pretension_sections, only: pretension_element_dofs
  use node_rotations, only: node_rotation_t, node_rotations_build, element_to_global, element_to_local, &
    element_matrix_to_local
  implicit none
  private
  public :: analysis_t, elem_state_t, analysis_init, analysis_number_equations, analysis_assemble, analysis_commit
  public :: analysis_restore, pnewdt_large, elem_type_name, n_cost_class, element_geometry, element_state_allocate
  public :: continuum_state_dims, element_state_free, close_loop_trace

  real(dp), parameter :: pnewdt_large = SOLID_PNEWDT_LARGE  !< PNEWDT handed to each user-routine call
  integer, parameter :: n_cost_class = 3  !< cost classes of elements (cost_class)
  integer, parameter :: mdload = 8   !< MDLOAD: distributed loads of a user element at most (Un on one element)
  integer, parameter :: svars_guard = 4   !< guard entries on each side of the SVARS copy a UEL gets
  !> what the guard entries hold: a finite value no routine writes by chance (check_svars_guards)
  real(dp), parameter :: svars_guard_value = -1.2345678901234567e307_dp

  !> Local material axes of a continuum element with an *ORIENTATION (unallocated: none).
  type :: elem_axes_t
    real(dp), allocatable :: t(:, :, :)    !< (3, 3, nip) axes as columns at each integration point, reference
  end type elem_axes_t

  !> How the sparse system is factored (solver_options).
  type :: factoring_t
    logical :: symmetric_part = .false.   !< unsymmetric: factors of the symmetric part (preconditioner only)
    logical :: single = .false.           !< factors in single precision (preconditioner only)
    integer :: blas_threads = 0           !< BLAS threads of a large factorization (0: BLAS untouched)
    real(dp) :: min_flops = 0.0_dp        !< operations from which a factorization uses them
    logical :: one_process = .false.      !< distributed: factorize and solve on rank 0 (--reproducible)
    logical :: pipelined = .false.        !< two factor instances: refactorizations beside GMRES (Newton auto)
    logical :: background = .false.       !< the pipelined factorization on a thread of its own (2+ threads)
  end type factoring_t

  !> The equations of the current step: the free dofs numbered (prescribed ones and *EQUATION/*TIE-eliminated ones
  !> excluded), the element colours of the assembly and the sparse system (working data, rebuilt when the set of
  !> prescribed dofs changes).
  type :: equation_system_t
    integer :: neq = 0                          !< free equations
    integer, allocatable :: eq(:)               !< (ndof) equation of each dof, 0 if prescribed or unused
    integer, allocatable :: elem_eq(:)          !< equation of each element dof (0: prescribed/unused)
    logical, allocatable :: prescribed(:)       !< (ndof) the dof is prescribed in this step
    type(constraint_set_t) :: cs                !< *EQUATION constraints (linear_constraints), eliminated
    integer :: ncolor = 0                       !< element colours (element_colors: no shared dof within one)
    integer, allocatable :: color_ptr(:)        !< (ncolor+1) into color_elem
    integer, allocatable :: color_elem(:)       !< (nelem) elements by colour
    type(sparse_system_t) :: sys                !< sparse tangent
    logical :: sys_ready = .false.              !< sys is set up for the current numbering
    type(factoring_t) :: factoring              !< how sys is factored
  end type equation_system_t

  !> A stop asked by a user routine (XIT, STDB_ABQERR) in the last element loop.
  type :: stop_request_t
    logical :: asked = .false.                  !< a routine asked to end the analysis
    integer :: elem = 0                         !< the element that asked (lowest index; 0: not known)
    character(len=:), allocatable :: text       !< the routine's message
    integer :: rank = 0                         !< the process whose element asked (distributed run)
  end type stop_request_t

  !> The solver's working data of an increment (never checkpointed): the current iterate and what the last element
  !> loop computed at it.
  type :: solver_work_t
    real(dp), allocatable :: u(:)               !< (ndof) current total displacement
    type(elem_state_t), allocatable :: trial(:) !< (nelem) element states of the last element loop (the owned ones)
    real(dp), allocatable :: fint(:)            !< (ndof) internal force (all dofs)
    real(dp), allocatable :: fext(:)            !< (ndof) external nodal force at the end of the increment
    real(dp), allocatable :: fdl(:)             !< (ndof) distributed-load nodal forces at the current estimate
    real(dp), allocatable :: fe(:)              !< element internal forces (elem_ptr layout)
    real(dp), allocatable :: fdle(:)            !< element distributed-load forces (elem_ptr layout)
    real(dp), allocatable :: temp_end(:)        !< (nnode) temperatures at the end of the increment
    real(dp), allocatable :: field_end(:)       !< (nfield*nnode) field variables at its end
    type(stop_request_t) :: stop                !< a stop asked in the last element loop
    !> (nelem with *MODEL CHANGE, else 0) reactivated WITH STRAIN and its first increment not converged yet: the
    !> element's increment starts from zero displacement (model_change; cleared by analysis_commit)
    logical, allocatable :: from_zero(:)
  end type solver_work_t

  !> Times and counts of the element loops and of the sparse systems gone (run summary), and the loop trace.
  type :: loop_timings_t
    real(dp) :: t_factor_done = 0.0_dp          !< factorization seconds of earlier sparse systems (pattern changes)
    real(dp) :: t_solve_done = 0.0_dp           !< solve seconds of earlier sparse systems
    real(dp) :: t_beside_done = 0.0_dp          !< of t_factor_done: factorizations on their own thread
    real(dp) :: t_wait_done = 0.0_dp            !< of t_solve_done: waits for them
    real(dp) :: t_setup_done = 0.0_dp           !< setup seconds of earlier sparse systems
    integer :: n_factor_done = 0                !< factorizations of earlier sparse systems
    real(dp) :: t_assembly = 0.0_dp             !< wall seconds in element loops
    !> distributed: the slowest process's seconds of each element loop, summed over the loops (what the run waits
    !> for; against the mean of t_assembly it gives the imbalance loop by loop, not only over the run)
    real(dp) :: t_assembly_slowest = 0.0_dp
    !> distributed: this process's seconds of each element loop up to the first reduction (what the slowest
    !> process's time of a loop is the largest of), summed over the loops: the per-process totals of the balance
    !> line, so that the sum of the loops' largest bounds their largest exactly (t_assembly also counts the few
    !> statements after the reductions, in which an oversubscribed process may be descheduled)
    real(dp) :: t_loop_own = 0.0_dp
    !> distributed: seconds this process waited at the end of its element loops for the slowest process (the first
    !> reduction after a loop; part of par%t_comm)
    real(dp) :: t_loop_wait = 0.0_dp
    integer :: n_assembly = 0                   !< element loops
    real(dp) :: class_time(n_cost_class) = 0.0_dp     !< wall seconds in element routines, per cost class
    integer(i8) :: class_calls(n_cost_class) = 0      !< element calls per cost class (this process)
    !> unit of the element-loop trace (LDFCZ_LOOP_TRACE=PREFIX: PREFIX.rankR.csv, one row per element loop with
    !> this process's seconds per cost class; docs/host.md "Diagnostics"); 0: off
    integer :: loop_trace = 0
  end type loop_timings_t

  !> The analysis: the discretised model (fixed after analysis_init: dof maps, element data, materials, partition)
  !> and, by role, the analysis state (what a continuation needs), the equations of the step, the solver's working
  !> data and the timings.
  type :: analysis_t
    integer :: ndim = 3                         !< 2 or 3
    integer :: ndof = 0                         !< ndim * nnode
    logical :: symmetric = .true.               !< LDL^T with symmetrised element matrices
    integer, allocatable :: elem_ptr(:)         !< (nelem+1) into elem_dof
    integer, allocatable :: elem_dof(:)         !< global dof of each element dof
    integer :: max_ndofel = 0                   !< largest number of dofs of an element
    logical, allocatable :: used(:)             !< (ndof) dof attached to an element
    integer, allocatable :: elem_nip(:)         !< integration points per element (continuum)
    character(len=8), allocatable :: elem_tname(:) !< Abaqus element type name ('C3D8', ...) or 'U'
    type(solid_material_t), allocatable :: mats(:)  !< per section
    type(elem_axes_t), allocatable :: axes(:)   !< (nelem) local material axes (*ORIENTATION)
    !> (nelem) where the reference data of a continuum element this process computes is kept: k > 0 in geo(k),
    !> k < 0 in geo_compact(:, -k); 0 otherwise (user elements, other processes' elements: element_geometry
    !> computes theirs)
    integer, allocatable :: elem_geo(:)
    type(solid_geometry_t), allocatable :: geo(:)  !< reference data of those elements (computed once)
    !> compact reference data (solid_compact_geometry) of the elements whose type's fixed-size kernel serves them
    !> in every step (C3D8 under NLGEOM without *ORIENTATION): 720 bytes a C3D8 instead of about 3.4 kB in geo
    real(dp), allocatable :: geo_compact(:, :)
    type(node_rotation_t) :: nr                 !< *TRANSFORM local node systems (node_rotations): u, u_conv, fint,
                                                !< fext, fdl and the system are in their components at those nodes
    type(user_routines_t) :: routines           !< UEL and UMAT in use
    type(parallel_t) :: par                     !< processes of the run (parallel_context)
    logical, allocatable :: owned(:)            !< (nelem) elements this process computes (all in a serial run)
    !> METIS vertex weight of each cost class (cost_class: UMAT continuum, *ELASTIC continuum, user element)
    integer :: cost_weight(n_cost_class) = [6, 5, 1]
    integer(i8) :: partition_sig = 0            !< signature of the partition (0: one process)
    type(analysis_state_t) :: state             !< what a continuation needs (analysis_state; restart_file)
    type(equation_system_t) :: eqs              !< the equations of the step
    type(solver_work_t) :: work                 !< the current iterate and the element loop's results
    type(loop_timings_t) :: timing              !< times and counts
  end type analysis_t

contains

  pure function elem_type_name(kind) result(s)
    integer, intent(in) :: kind
    character(len=8) :: s
    s = 'U'
    if (kind /= etype_user) s = element_name(kind)
  end function elem_type_name

  !> Dof maps, materials and initial (zero) states.
  subroutine analysis_init(an, model, routines, stat, errmsg, options)
    type(analysis_t), intent(inout) :: an                !< analysis data (filled; an%par set by the caller)
    type(model_t), intent(in) :: model                   !< the model
    type(user_routines_t), intent(in) :: routines        !< UEL and UMAT to call
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    !> the partition's weights and pieces, the factorization's choices (default: solver_options_t's)
    type(solver_options_t), intent(in), optional :: options
    type(solver_options_t) :: opt
    logical :: beside

    stat = 0
    errmsg = ''
    if (present(options)) opt = options
    an%cost_weight = opt%element_weights
    ! Newton auto's refactorizations pipelined beside GMRES, on a thread of their own with two threads or more
    ! (LDFCZ_PIPELINE_THREAD=0: in sequence, for measurements; the results are the same: docs/host.md)
    beside = .not. env_is_zero('LDFCZ_PIPELINE_THREAD')
    an%eqs%factoring = factoring_t(opt%symmetric_factors, opt%single_factors, opt%factor_blas_threads, &
      opt%factor_min_flops, opt%reproducible, opt%newton == newton_auto, opt%threads > 1 .and. beside)
    an%routines = routines
    an%ndim = model%ndim
    ! the displacement dofs of the nodes, then the rotational dofs of the couplings' reference nodes (model_dof)
    ! and the extra dofs of the pre-tension sections' moving side (pretension_sections)
    an%ndof = model%ndim * model%nnode + model%nrot + model%npret_dof
    call element_dof_maps(an, model, stat, errmsg)
    if (stat /= 0) return
    call section_materials(an, model, routines, stat, errmsg)
    if (stat /= 0) return
    call partition(an, model, opt%partition_pieces, stat, errmsg)
    if (stat /= 0) return
    call allocate_element_states(an, model)
    call reference_geometry(an, model)
    call element_axes(an, model, stat, errmsg)
    if (stat /= 0) return
    call apply_initial_conditions(an, model, stat, errmsg)
    if (stat /= 0) return
    call open_loop_trace(an)
    call node_rotations_build(an%nr, model, stat, errmsg)
    if (stat /= 0) return
    call constraints_build(an%eqs%cs, model, an%used, stat, errmsg)
    if (stat /= 0) return
    call constraints_mark_masters(an%eqs%cs, an%used)
    call check_loads_attached(an, model, stat, errmsg)
    if (stat /= 0) return
    call allocate_working_arrays(an, model)
  end subroutine analysis_init

  !> A concentrated load on a dof that no element and no constraint holds (a node without an element, a reference
  !> node's dof that its coupling does not constrain) would act on nothing: an error at its *CLOAD line.
  subroutine check_loads_attached(an, model, stat, errmsg)
    type(analysis_t), intent(in) :: an                   !< analysis data (used set)
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: is, k, j, i
    stat = 0
    errmsg = ''
    do is = 1, model%nstep
      do k = 1, model%steps(is)%ncload
        associate (cl => model%steps(is)%cloads(k))
          if (cl%value == 0.0_dp) cycle
          do j = 1, size(cl%nodes)
            i = model_dof(model, cl%nodes(j), cl%dof)
            if (i == 0) cycle
            if (an%used(i)) cycle
            stat = 2
            errmsg = cl%pos%file//':'//itoa(cl%pos%line)//': *CLOAD: dof '//itoa(cl%dof)//' of node '// &
              itoa(model%node_id(cl%nodes(j)))//' belongs to no element and no constraint: the load would act '// &
              'on nothing'
            return
          end do
        end associate
      end do
    end do
  end subroutine check_loads_attached

  !> Each element's global dofs (elem_ptr, elem_dof: ndim per node, or a user element type's active dofs), the
  !> dofs attached to an element or a coupling (used) and the element colours of the threaded assembly.
  subroutine element_dof_maps(an, model, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: ie, k, a, j, nn, iu, nact
    character(len=16) :: b
    stat = 0
    errmsg = ''
    allocate (an%elem_ptr(model%nelem + 1), an%elem_nip(model%nelem), an%elem_tname(model%nelem))
    an%elem_ptr(1) = 1
    an%elem_nip = 0
    do ie = 1, model%nelem
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      an%elem_tname(ie) = elem_type_name(model%elem_kind(ie))
      if (model%elem_kind(ie) == etype_user) then
        nact = size(model%utypes(model%elem_utype(ie))%active)
      else
        nact = model%ndim
      end if
      an%elem_ptr(ie + 1) = an%elem_ptr(ie) + nn * nact
    end do
    allocate (an%elem_dof(an%elem_ptr(model%nelem + 1) - 1), an%used(an%ndof))
    an%used = .false.
    do ie = 1, model%nelem
      k = an%elem_ptr(ie)
      do a = model%conn_ptr(ie), model%conn_ptr(ie + 1) - 1
        if (model%elem_kind(ie) == etype_user) then
          iu = model%elem_utype(ie)
          do j = 1, size(model%utypes(iu)%active)
            if (model%utypes(iu)%active(j) > model%ndim) then
              stat = 2
              write (b, '(i0)') model%elem_id(ie)
              errmsg = model%utypes(iu)%pos%file//': *USER ELEMENT: type '//trim(model%utypes(iu)%name)// &
                ' has an active dof beyond the model dimension (element '//trim(b)//')'
              return
            end if
            an%elem_dof(k) = (model%conn(a) - 1) * model%ndim + model%utypes(iu)%active(j)
            k = k + 1
          end do
        else
          do j = 1, model%ndim
            an%elem_dof(k) = (model%conn(a) - 1) * model%ndim + j
            k = k + 1
          end do
        end if
      end do
      an%used(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)) = .true.
    end do
    if (model%npretension > 0) then
      ! the elements on a section's side hold its extra dofs instead of the section's nodes
      call pretension_element_dofs(model, an%elem_ptr, an%elem_dof)
      an%used = .false.
      an%used(an%elem_dof) = .true.
    end if
    call coupling_mark_used(model, an%used)
    an%max_ndofel = maxval(an%elem_ptr(2:) - an%elem_ptr(1:model%nelem))
    call color_elements(model%nelem, an%ndof, an%elem_ptr, an%elem_dof, an%eqs%ncolor, an%eqs%color_ptr, an%eqs%color_elem)
  end subroutine element_dof_maps

  !> The material of each section (an%mats) and whether the system is symmetric (no UNSYMM material, user element
  !> type or step); a *USER MATERIAL without a UMAT, or user elements without a UEL, is an error.
  subroutine section_materials(an, model, routines, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    type(user_routines_t), intent(in) :: routines        !< UEL and UMAT to call
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: is, im, k, iu
    stat = 0
    errmsg = ''
    allocate (an%mats(max(1, model%nsection)))
    an%symmetric = .true.
    do is = 1, model%nsection
      im = 0
      do k = 1, model%nmat
        if (model%materials(k)%name == model%sections(is)%material) im = k
      end do
      call section_material(model%materials(im), model%sections(is)%thickness, routines, an%mats(is), stat, errmsg)
      if (stat /= 0) return
      if (.not. model%materials(im)%has_elastic .and. model%materials(im)%unsymm) an%symmetric = .false.
    end do
    do iu = 1, model%nutype
      if (model%utypes(iu)%unsymm .and. any(model%elem_utype == iu)) an%symmetric = .false.
    end do
    if (any(model%elem_kind == etype_user) .and. .not. associated(routines%uel)) then
      stat = 2
      errmsg = model%utypes(1)%pos%file//': *USER ELEMENT: user elements need a UEL: give one with --user FILE'
      return
    end if
    do is = 1, model%nstep
      if (model%steps(is)%unsymm) an%symmetric = .false.
    end do
  end subroutine section_materials

  !> One section's material: *ELASTIC (with its law: material_law.f90) or the user's UMAT with its constants.
  subroutine section_material(mt, thickness, routines, sm, stat, errmsg)
    type(material_t), intent(in) :: mt                   !< the section's material
    real(dp), intent(in) :: thickness                    !< the section's thickness
    type(user_routines_t), intent(in) :: routines        !< UEL and UMAT to call
    type(solid_material_t), intent(inout) :: sm          !< the material as the element computes it
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    sm%thickness = thickness
    ! CMNAME: Abaqus reads names case-insensitively and passes them in upper case
    sm%cmname = upper_case(mt%given_name)
    sm%alpha = mt%alpha
    ! *ELASTIC/*EXPANSION other than constant isotropic (material_law.f90)
    call material_elastic_law(mt, sm%law, stat, errmsg)
    if (stat /= 0) return
    if (mt%has_elastic) then
      sm%kind = SOLID_MAT_ELASTIC
      sm%e = mt%young
      sm%nu = mt%poisson
    else
      sm%kind = SOLID_MAT_UMAT
      sm%props = mt%props
      sm%nstatv = mt%nstatv
      sm%unsymm = mt%unsymm
      if (.not. associated(routines%umat)) then
        stat = 2
        errmsg = mt%pos%file//': *MATERIAL: material '//trim(mt%given_name)//' uses *USER MATERIAL but no '// &
          'UMAT is available: give one with --user FILE'
        return
      end if
      sm%umat => routines%umat
    end if
  end subroutine section_material

  !> Integration points of every continuum element, and the converged states of this process's elements only
  !> (all in a one-process run; state_gather brings another process's converged state where output needs it).
  subroutine allocate_element_states(an, model)
    type(analysis_t), intent(inout) :: an  !< analysis data
    type(model_t), intent(in) :: model     !< the model
    integer :: ie, nnode, ndim, nip, ntens, ndi, nshr, nextra
    allocate (an%state%conv(model%nelem))
    do ie = 1, model%nelem
      if (model%elem_kind(ie) /= etype_user) then
        call solid_element_info(an%elem_tname(ie), nnode, ndim, nip, ntens, ndi, nshr, nextra)
        an%elem_nip(ie) = nip
      end if
      if (an%owned(ie)) call element_state_allocate(an, model, ie, an%state%conv(ie))
    end do
  end subroutine allocate_element_states

  !> Reference shape-function derivatives and weights, once (original coordinates), of the continuum elements this
  !> process computes: all in a one-process run, its own in a distributed one (element_geometry gives another
  !> process's element when output needs it; 41 MB a process on the paper's application mesh when all are kept).
  !> An element whose type's fixed-size kernel serves it in every step (C3D8: every step NLGEOM, no *ORIENTATION
  !> on its section, no *MODEL CHANGE, whose reactivation moves the reference) keeps the kernel's compact form
  !> (about a fifth of the memory; the kernel rebuilds the arrays from it to the bit), the others the whole arrays.
  subroutine reference_geometry(an, model)
    type(analysis_t), intent(inout) :: an  !< analysis data
    type(model_t), intent(in) :: model     !< the model
    integer :: ie, n, nc, kc, k, is
    logical :: all_nlgeom
    allocate (an%elem_geo(model%nelem))
    an%elem_geo = 0
    n = 0
    nc = 0
    kc = 0
    all_nlgeom = model%nstep > 0
    do is = 1, model%nstep
      all_nlgeom = all_nlgeom .and. model%steps(is)%nlgeom
    end do
    do ie = 1, model%nelem
      if (model%elem_kind(ie) == etype_user .or. .not. an%owned(ie)) cycle
      k = 0
      if (all_nlgeom .and. model%sections(model%elem_section(ie))%iorient == 0 .and. .not. model%has_model_change) &
        k = solid_compact_geometry_size(an%elem_tname(ie))
      if (k > 0 .and. (kc == 0 .or. k == kc)) then
        kc = k
        nc = nc + 1
        an%elem_geo(ie) = -nc
      else
        n = n + 1
        an%elem_geo(ie) = n
      end if
    end do
    allocate (an%geo(n), an%geo_compact(kc, nc))
    do ie = 1, model%nelem
      if (an%elem_geo(ie) > 0) then
        call solid_element_geometry(an%elem_tname(ie), &
          model%x(1:model%ndim, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)), an%geo(an%elem_geo(ie)))
      else if (an%elem_geo(ie) < 0) then
        call solid_compact_geometry(an%elem_tname(ie), &
          model%x(1:model%ndim, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)), &
          an%geo_compact(:, -an%elem_geo(ie)))
      end if
    end do
  end subroutine reference_geometry

  !> The state before the first increment (analysis_state: the model data's boundaries, the initial temperatures
  !> and field variables; the element states are already there) and the solver's working arrays, zero.
  subroutine allocate_working_arrays(an, model)
    type(analysis_t), intent(inout) :: an  !< analysis data
    type(model_t), intent(in) :: model     !< the model
    call analysis_state_init(an%state, model, an%ndof)
    ! *MODEL CHANGE: the displacements at reactivation, per element dof (model_change)
    allocate (an%state%u_ref(merge(size(an%elem_dof), 0, model%has_model_change)))
    an%state%u_ref = 0.0_dp
    an%work%temp_end = an%state%temp_start
    an%work%field_end = an%state%field_start
    an%work%trial = an%state%conv
    allocate (an%work%from_zero(size(an%state%active)))
    an%work%from_zero = .false.
    allocate (an%work%u(an%ndof), an%work%fint(an%ndof), an%work%fe(an%elem_ptr(model%nelem + 1) - 1))
    an%work%u = 0.0_dp
    an%work%fint = 0.0_dp
    an%work%fe = 0.0_dp
    allocate (an%work%fext(an%ndof), an%work%fdl(an%ndof), an%work%fdle(size(an%work%fe)))
    an%work%fext = 0.0_dp
    an%work%fdl = 0.0_dp
    an%work%fdle = 0.0_dp
    allocate (an%eqs%prescribed(an%ndof), an%eqs%eq(an%ndof))
    an%eqs%prescribed = .false.
    an%eqs%eq = 0
  end subroutine allocate_working_arrays

  !> Equation numbers for the free dofs (an%eqs%prescribed set by the caller) and the sparse system (pattern,
  !> METIS ordering, MUMPS analysis) when the set of free dofs changed.
  subroutine analysis_number_equations(an, model, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer, allocatable :: eq_new(:), eq_node(:)
    integer :: i, n
    character(len=512) :: msg
    stat = 0
    errmsg = ''
    allocate (eq_new(an%ndof))
    eq_new = 0
    n = 0
    do i = 1, an%ndof
      if (an%used(i) .and. .not. an%eqs%prescribed(i) .and. an%eqs%cs%of_dof(i) == 0) then
        n = n + 1
        eq_new(i) = n
      end if
      if (an%eqs%prescribed(i) .and. an%eqs%cs%of_dof(i) /= 0) then
        stat = 2
        write (msg, '(a,i0,a,i0)') 'a *BOUNDARY prescribes dof ', mod(i - 1, an%ndim) + 1, ' of node ', &
          model%node_id(model_dof_node(model, i))
        errmsg = trim(msg)//', which an *EQUATION (its first term), a *TIE (a slave node) or a kinematic *COUPLING '// &
          '(a coupling node) eliminates: prescribe another dof of the constraint (the reference node of a coupling), '// &
          'or drop it from the slave surface'
        return
      end if
    end do
    if (an%eqs%sys_ready .and. all(eq_new == an%eqs%eq)) return
    if (.not. an%eqs%sys_ready .and. n == 0 .and. all(eq_new == an%eqs%eq)) return
    an%eqs%eq = eq_new
    an%eqs%neq = n
    if (an%eqs%sys_ready) then
      ! the old system goes away with its timers: keep them for the summary
      an%timing%t_factor_done = an%timing%t_factor_done + sparse_time_factor(an%eqs%sys)
      an%timing%t_solve_done = an%timing%t_solve_done + sparse_time_solve(an%eqs%sys)
      an%timing%t_beside_done = an%timing%t_beside_done + sparse_time_factor_beside(an%eqs%sys)
      an%timing%t_wait_done = an%timing%t_wait_done + sparse_time_factor_wait(an%eqs%sys)
      an%timing%t_setup_done = an%timing%t_setup_done + sparse_time_analysis(an%eqs%sys)
      an%timing%n_factor_done = an%timing%n_factor_done + sparse_factor_count(an%eqs%sys)
    end if
    if (n == 0) then
      ! every dof prescribed: only reactions to compute, no linear system
      if (an%eqs%sys_ready) call sparse_destroy(an%eqs%sys)
      an%eqs%sys_ready = .false.
      return
    end if
    allocate (eq_node(n))
    do i = 1, an%ndof
      if (an%eqs%eq(i) > 0) eq_node(an%eqs%eq(i)) = model_dof_node(model, i)
    end do
    an%eqs%elem_eq = an%eqs%eq(an%elem_dof)
    if (an%eqs%cs%n > 0) then
      ! eliminated dofs: extended element lists (masters appended), colours of the extended lists
      if (allocated(an%eqs%cs%xptr)) deallocate (an%eqs%cs%xptr, an%eqs%cs%xeq, an%eqs%cs%xdof, an%eqs%cs%tptr, an%eqs%cs%trow, &
        an%eqs%cs%tcol, an%eqs%cs%tw)
      call constraints_extend(an%eqs%cs, an%elem_ptr, an%elem_dof, an%eqs%eq)
      call color_elements(model%nelem, an%ndof, an%eqs%cs%xptr, an%eqs%cs%xdof, an%eqs%ncolor, an%eqs%color_ptr, an%eqs%color_elem)
      call sparse_setup(an%eqs%sys, n, an%eqs%cs%xptr, an%eqs%cs%xeq, eq_node, an%symmetric, stat, msg, &
        symmetric_factors=an%eqs%factoring%symmetric_part, single_factors=an%eqs%factoring%single, par=an%par, &
        owned=an%owned, one_process=an%eqs%factoring%one_process, pipelined=an%eqs%factoring%pipelined, &
        background=an%eqs%factoring%background)
    else
      call sparse_setup(an%eqs%sys, n, an%elem_ptr, an%eqs%elem_eq, eq_node, an%symmetric, stat, msg, &
        symmetric_factors=an%eqs%factoring%symmetric_part, single_factors=an%eqs%factoring%single, par=an%par, &
        owned=an%owned, one_process=an%eqs%factoring%one_process, pipelined=an%eqs%factoring%pipelined, &
        background=an%eqs%factoring%background)
    end if
    if (stat /= 0) then
      errmsg = 'sparse solver setup failed: '//trim(msg)
      stat = 2
      return
    end if
    call sparse_set_factor_threads(an%eqs%sys, an%eqs%factoring%blas_threads, an%eqs%factoring%min_flops)
    an%eqs%sys_ready = .true.
    if (.false.) print *, model%nnode
  end subroutine analysis_number_equations

  !> True when the environment variable is set to 0.
  logical function env_is_zero(name)
    character(len=*), intent(in) :: name            !< variable
    character(len=8) :: val
    integer :: length, status
    call get_environment_variable(name, val, length, status)
    env_is_zero = status == 0 .and. trim(val) == '0'
  end function env_is_zero

  !> Element loop at the current estimate an%work%u (increment du = u - u_conv): every element gets a fresh copy of its
  !> converged state; internal forces into an%work%fint, tangents into an%eqs%sys when want_k. pnewdt_min is the smallest
  !> PNEWDT requested; stat /= 0 when an element failed (errmsg names it). The increment inc gives the elements
  !> KSTEP, KINC, TIME, DTIME, PERIOD, NLGEOM and whether the start is extrapolated (LFLAGS(5)).
  subroutine analysis_assemble(an, model, inc, want_k, pnewdt_min, stat, errmsg, pnewdt_who, carry, k_carry)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    type(increment_t), intent(in) :: inc                 !< the increment
    logical, intent(in) :: want_k                        !< assemble the tangent
    real(dp), intent(out) :: pnewdt_min                  !< smallest PNEWDT of the user routines
    integer, intent(out) :: stat                         !< 0 ok, 1 an element failed
    character(len=:), allocatable, intent(out) :: errmsg !< message of the first failure
    !> which element asked for the smallest PNEWDT < 1 (label, routine, value), '' when none did
    character(len=:), allocatable, intent(out), optional :: pnewdt_who
    !> (ndof) a displacement change to carry through the tangent (the first iteration's prescribed increment,
    !> newton_iteration); with it (and want_k) k_carry = K carry, K the element tangents as the solver assembles them
    !> (symmetrised for LDL^T) over all dofs, prescribed ones included
    real(dp), intent(in), optional :: carry(:)
    real(dp), intent(out), optional :: k_carry(:)          !< (ndof) K carry
    integer :: fail_elem, pn_elem
    real(dp), allocatable :: fk(:)
    real(dp) :: ctime(n_cost_class)        !< seconds in the element routines per cost class (this loop)
    integer(i8) :: ccalls(n_cost_class)    !< calls per cost class
    real(dp) :: pn_worst, comm0, comm1, loop_own, loop_slowest, cpu0, cpu1
    character(len=256) :: first_msg
    character(len=:), allocatable :: who, fail_text
    integer(i8) :: c0, c1, rate
    logical :: with_carry

    call system_clock(c0, rate)
    cpu0 = 0.0_dp
    cpu1 = 0.0_dp
    if (an%timing%loop_trace /= 0) call cpu_time(cpu0)
    comm0 = an%par%t_comm
    stat = 0
    errmsg = ''
    pnewdt_min = pnewdt_large
    fail_elem = huge(1)
    first_msg = ''
    pn_worst = 1.0_dp
    pn_elem = 0
    if (want_k .and. an%eqs%neq > 0) call sparse_zero(an%eqs%sys)
    an%work%fdle = 0.0_dp
    with_carry = present(carry) .and. present(k_carry) .and. want_k
    if (with_carry) then
      allocate (fk(size(an%elem_dof)))
      fk = 0.0_dp
    end if
    ctime = 0.0_dp
    ccalls = 0
    call colour_loop(an, model, inc, want_k, with_carry, pnewdt_min, fail_elem, first_msg, pn_worst, pn_elem, ctime, &
      ccalls, carry, fk)
    an%timing%class_time = an%timing%class_time + ctime / real(rate, dp)
    an%timing%class_calls = an%timing%class_calls + ccalls
    call record_stop_request(an)
    ! the element forces into the dofs' (and K carry's)
    call scatter_add(an, an%work%fe, an%work%fint)
    call scatter_add(an, an%work%fdle, an%work%fdl)
    if (present(k_carry)) then
      k_carry = 0.0_dp
      if (with_carry) call scatter_add(an, fk, k_carry)
    end if
    who = ''
    if (pn_elem > 0) who = 'element '//itoa(model%elem_id(pn_elem))//' ('// &
      trim(merge('UEL ', 'UMAT', model%elem_kind(pn_elem) == etype_user))//') requested PNEWDT = '//rtoa(pn_worst)
    fail_text = trim(first_msg)
    ! this process's loop, before any reduction (what the slowest process's time is the largest of)
    call system_clock(c1)
    loop_own = real(c1 - c0, dp) / real(rate, dp)
    if (an%timing%loop_trace /= 0) call cpu_time(cpu1)
    loop_slowest = loop_own
    if (parallel_distributed(an%par)) then
      comm1 = an%par%t_comm
      loop_slowest = parallel_max(an%par, loop_own)
      an%timing%t_assembly_slowest = an%timing%t_assembly_slowest + loop_slowest
      an%timing%t_loop_own = an%timing%t_loop_own + loop_own
      an%timing%t_loop_wait = an%timing%t_loop_wait + (an%par%t_comm - comm1)
      if (with_carry) then
        call reduce_over_processes(an, pnewdt_min, pn_worst, pn_elem, who, fail_elem, fail_text, k_carry)
      else
        call reduce_over_processes(an, pnewdt_min, pn_worst, pn_elem, who, fail_elem, fail_text)
      end if
    end if
    if (fail_elem /= huge(1)) then
      stat = 1
      errmsg = fail_text
    end if
    if (present(pnewdt_who)) pnewdt_who = who
    call system_clock(c1)
    ! the reductions are communication, not assembly
    an%timing%t_assembly = an%timing%t_assembly + real(c1 - c0, dp) / real(rate, dp) - (an%par%t_comm - comm0)
    an%timing%n_assembly = an%timing%n_assembly + 1
    if (an%timing%loop_trace /= 0) write (an%timing%loop_trace, '(i0,3(",",i0),6(",",es10.4e2),3(",",i0))') &
      an%timing%n_assembly, inc%step, inc%kinc, merge(1, 0, want_k), loop_own, loop_slowest, cpu1 - cpu0, &
      ctime / real(rate, dp), ccalls
  end subroutine analysis_assemble

  !> The element loop of analysis_assemble: every element this process computes, colour by colour, its force into
  !> an%work%fe and its tangent into the sparse system (with carry: its K carry into fk); the first failure (lowest
  !> label), the smallest PNEWDT and the element that asked for the smallest below 1, the time and calls per class.
  subroutine colour_loop(an, model, inc, want_k, with_carry, pnewdt_min, fail_elem, first_msg, pn_worst, pn_elem, &
      ctime, ccalls, carry, fk)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    type(increment_t), intent(in) :: inc                 !< the increment
    logical, intent(in) :: want_k                        !< assemble the tangent
    logical, intent(in) :: with_carry                    !< K carry wanted (carry and fk present)
    real(dp), intent(inout) :: pnewdt_min                !< smallest PNEWDT (in: pnewdt_large)
    integer, intent(inout) :: fail_elem                  !< label of the first failed element (in: huge)
    character(len=*), intent(inout) :: first_msg         !< its message
    real(dp), intent(inout) :: pn_worst                  !< smallest PNEWDT below 1 (in: 1)
    integer, intent(inout) :: pn_elem                    !< the element that asked for it (in: 0)
    real(dp), intent(inout) :: ctime(n_cost_class)       !< clock ticks in the element routines per cost class
    integer(i8), intent(inout) :: ccalls(n_cost_class)   !< calls per cost class
    real(dp), intent(in), optional :: carry(:)           !< (ndof) the displacement change carried
    real(dp), intent(inout), optional :: fk(:)           !< (element dofs) K carry per element
    integer :: ie, ic, c, n, st, kc
    real(dp), allocatable :: ke(:, :), fel(:), kx(:, :)
    integer(i8) :: e0, e1
    real(dp) :: pn
    character(len=256) :: msg

    ! colour by colour (no dof shared within a colour): no atomic updates, and each matrix entry sums its element
    ! contributions in the same order on any number of threads
    !$omp parallel default(shared) private(ic, ie, c, n, ke, fel, pn, st, msg, kx, kc, e0, e1)
    allocate (ke(an%max_ndofel, an%max_ndofel), fel(an%max_ndofel))
    allocate (kx(max(1, an%eqs%cs%max_x), max(1, an%eqs%cs%max_x)))
    do c = 1, an%eqs%ncolor
      !$omp do schedule(dynamic, 8) reduction(min: pnewdt_min) reduction(+: ctime, ccalls)
      do ic = an%eqs%color_ptr(c), an%eqs%color_ptr(c + 1) - 1
        ie = an%eqs%color_elem(ic)
        if (.not. an%owned(ie)) cycle   ! another process's element (distributed run)
        n = an%elem_ptr(ie + 1) - an%elem_ptr(ie)
        if (size(an%state%active) > 0) then
          if (.not. an%state%active(ie)) then
            ! removed (*MODEL CHANGE): not computed, no force, no tangent
            an%work%fe(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1) = 0.0_dp
            cycle
          end if
        end if
        pn = pnewdt_large
        call abaqus_set_caller(ie)
        call system_clock(e0)
        call element_compute(an, model, ie, n, inc, want_k, fel(1:n), ke(1:n, 1:n), pn, st, msg)
        call system_clock(e1)
        kc = cost_class(an, model, ie)
        ctime(kc) = ctime(kc) + real(e1 - e0, dp)
        ccalls(kc) = ccalls(kc) + 1
        if (st /= 0) then
          !$omp critical (analysis_fail)
          if (model%elem_id(ie) < fail_elem) then
            fail_elem = model%elem_id(ie)
            first_msg = msg
          end if
          !$omp end critical (analysis_fail)
          fel(1:n) = 0.0_dp
          ke(1:n, 1:n) = 0.0_dp
        end if
        pnewdt_min = min(pnewdt_min, pn)
        if (pn < 1.0_dp) then
          !$omp critical (analysis_pnewdt)
          if (pn < pn_worst .or. (pn == pn_worst .and. pn_elem > 0 .and. ie < pn_elem)) then
            pn_worst = pn
            pn_elem = ie
          end if
          !$omp end critical (analysis_pnewdt)
        end if
        an%work%fe(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1) = fel(1:n)
        if (want_k .and. an%eqs%neq > 0) then
          if (with_carry) then
            call add_element_tangent(an, ie, ke(1:n, 1:n), kx, carry, fk)
          else
            call add_element_tangent(an, ie, ke(1:n, 1:n), kx)
          end if
        end if
      end do
      !$omp end do
    end do
    call abaqus_set_caller(0)
    deallocate (ke, fel, kx)
    !$omp end parallel
  end subroutine colour_loop

  !> A stop asked by a user routine in the element loop, with the element recorded when it asked.
  subroutine record_stop_request(an)
    type(analysis_t), intent(inout) :: an                !< analysis data
    an%work%stop%asked = abaqus_stop_requested()
    an%work%stop%elem = 0
    an%work%stop%text = ''
    if (an%work%stop%asked) then
      an%work%stop%elem = abaqus_stop_element()
      an%work%stop%text = abaqus_stop_message()
    end if
  end subroutine record_stop_request

  !> Element ie's tangent ke into the sparse system (symmetrised for LDL^T; T^T K T on the extended dofs of an
  !> element holding *EQUATION-eliminated dofs, kx the work matrix for it); with carry, fk of the element = K carry.
  !> Called within the colour loop: no other thread touches the element's entries.
  subroutine add_element_tangent(an, ie, ke, kx, carry, fk)
    type(analysis_t), intent(inout) :: an           !< analysis data
    integer, intent(in) :: ie                       !< element
    real(dp), intent(inout) :: ke(:, :)             !< (n, n) its tangent (symmetrised here when an%symmetric)
    real(dp), intent(inout) :: kx(:, :)             !< work: the extended element matrix
    real(dp), intent(in), optional :: carry(:)      !< (ndof) displacement change carried through the tangent
    real(dp), intent(inout), optional :: fk(:)      !< (elem_ptr layout) K carry per element dof
    integer :: n, m
    n = size(ke, 1)
    if (an%symmetric) ke = 0.5_dp * (ke + transpose(ke))
    if (present(carry)) fk(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1) = &
      matmul(ke, carry(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)))
    if (an%eqs%cs%n > 0) then
      ! T^T K T on the element's extended dofs (eliminated *EQUATION dofs)
      call constraints_transform(an%eqs%cs, ie, ke(1:n, 1:n), m, kx)
      call sparse_add_element(an%eqs%sys, ie, kx(1:m, 1:m), exclusive=.true.)
    else
      call sparse_add_element(an%eqs%sys, ie, ke(1:n, 1:n), exclusive=.true.)
    end if
  end subroutine add_element_tangent

  !> v (ndof) = the sum of the element-dof values ve (elem_ptr layout) at each dof.
  subroutine scatter_add(an, ve, v)
    type(analysis_t), intent(in) :: an      !< analysis data (dof maps)
    real(dp), intent(in) :: ve(:)           !< per element dof
    real(dp), intent(out) :: v(:)           !< per dof
    integer :: k
    v = 0.0_dp
    do k = 1, size(an%elem_dof)
      v(an%elem_dof(k)) = v(an%elem_dof(k)) + ve(k)
    end do
  end subroutine scatter_add

  !> A distributed run's element loop: the processes' parts combined, forces summed, the smallest PNEWDT, the first
  !> failing element and the element that asked to stop (lowest label or index over the processes), so that every
  !> process decides alike.
  subroutine reduce_over_processes(an, pnewdt_min, pn_worst, pn_elem, who, fail_elem, fail_text, k_carry)
    type(analysis_t), intent(inout) :: an                    !< analysis data (forces, stop request)
    real(dp), intent(inout) :: pnewdt_min                    !< smallest PNEWDT
    real(dp), intent(in) :: pn_worst                         !< this process's smallest PNEWDT < 1 (1: none)
    integer, intent(inout) :: pn_elem                        !< its element (0: none)
    character(len=:), allocatable, intent(inout) :: who      !< who asked for the smallest PNEWDT
    integer, intent(inout) :: fail_elem                      !< label of the first failing element (huge: none)
    character(len=:), allocatable, intent(inout) :: fail_text !< its message
    real(dp), intent(inout), optional :: k_carry(:)          !< K carry
    call parallel_sum(an%par, an%work%fint)
    call parallel_sum(an%par, an%work%fdl)
    if (present(k_carry)) call parallel_sum(an%par, k_carry)
    pnewdt_min = parallel_min(an%par, pnewdt_min)
    if (parallel_min(an%par, pn_worst) < pn_worst) pn_elem = 0
    call parallel_lowest(an%par, pn_elem, who)
    if (fail_elem == huge(1)) fail_elem = 0
    call parallel_lowest(an%par, fail_elem, fail_text)
    if (fail_elem == 0) fail_elem = huge(1)
    an%work%stop%asked = parallel_any(an%par, an%work%stop%asked)
    if (an%work%stop%asked) call parallel_lowest(an%par, an%work%stop%elem, an%work%stop%text, an%work%stop%rank)
  end subroutine reduce_over_processes

  !> One element: UEL through the procedure pointer, or the continuum element with its material; then, at nodes
  !> with a *TRANSFORM, back to the system components.
  subroutine element_compute(an, model, ie, n, inc, want_k, fel, ke, pnewdt, stat, msg)
    type(analysis_t), intent(inout) :: an
    type(model_t), intent(in) :: model
    integer, intent(in) :: ie, n
    type(increment_t), intent(in) :: inc
    logical, intent(in) :: want_k
    real(dp), intent(out) :: fel(n), ke(n, n)
    real(dp), intent(inout) :: pnewdt
    integer, intent(out) :: stat
    character(len=*), intent(out) :: msg
    if (model%elem_kind(ie) == etype_user) then
      call user_element_compute(an, model, ie, n, inc, want_k, fel, ke, pnewdt, stat, msg)
    else
      call continuum_element_compute(an, model, ie, n, inc, want_k, fel, ke, pnewdt, stat, msg)
    end if
    if (an%nr%elem_has(ie)) then
      ! back to the system components of the transformed nodes (T_e^T f, T_e^T K T_e)
      associate (nodes => model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1))
        call element_to_local(an%nr, nodes, fel)
        if (model%elem_kind(ie) /= etype_user) call element_to_local(an%nr, nodes, &
          an%work%fdle(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1))
        if (want_k) call element_matrix_to_local(an%nr, nodes, ke)
      end associate
    end if
  end subroutine element_compute

  !> The displacement an element reactivated strain-free (model_change) works from: it sees X + u_ref and the
  !> displacement u - u_ref; zero for every other element (system components).
  subroutine element_shift(an, ie, n, ushift)
    type(analysis_t), intent(in) :: an  !< the analysis
    integer, intent(in) :: ie, n        !< the element, its dofs
    real(dp), intent(out) :: ushift(n)  !< u_ref at its dofs
    ushift = 0.0_dp
    if (size(an%state%shifted) > 0) then
      if (an%state%shifted(ie)) ushift = an%state%u_ref(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)
    end if
  end subroutine element_shift

  !> The displacement increment element ie sees (system components): u - u_conv, or u whole in the first increment
  !> of an element reactivated WITH STRAIN (model_change: its strain is that of the displacement since the
  !> analysis began).
  subroutine element_increment(an, ie, n, ue, due)
    type(analysis_t), intent(in) :: an  !< the analysis
    integer, intent(in) :: ie, n        !< the element, its dofs
    real(dp), intent(in) :: ue(n)       !< its current displacement
    real(dp), intent(out) :: due(n)     !< its increment
    due = ue - an%state%u_conv(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1))
    if (size(an%work%from_zero) > 0) then
      if (an%work%from_zero(ie)) due = ue
    end if
  end subroutine element_increment

  !> A user element: the UEL through the procedure pointer, with the Abaqus arguments (docs/conventions.md).
  subroutine user_element_compute(an, model, ie, n, inc, want_k, fel, ke, pnewdt, stat, msg)
    type(analysis_t), intent(inout) :: an
    type(model_t), intent(in) :: model
    integer, intent(in) :: ie, n
    type(increment_t), intent(in) :: inc
    logical, intent(in) :: want_k
    real(dp), intent(out) :: fel(n), ke(n, n)
    real(dp), intent(inout) :: pnewdt
    integer, intent(out) :: stat
    character(len=*), intent(out) :: msg
    integer :: nn, a, iu, ip, mcrd, nsv, nf, nd, nact, jd
    real(dp) :: ue(n), due(n, 1), rhs(n, 1), v(n), acc(n), energy(8), ushift(n)
    real(dp) :: params(3), adlmag(mdload, 1), ddlmag(mdload, 1)
    real(dp), allocatable :: predef(:, :, :), xc(:, :), props(:), sv(:)
    integer :: jdltyp(mdload, 1), lflags(5), ndload
    integer, allocatable :: jprops(:)
    character(len=16) :: b
    integer :: kstep, kinc
    real(dp) :: time(2), dtime, period
    logical :: nlgeom

    ! copies of the increment's values (a user routine may write to its arguments)
    kstep = inc%step
    kinc = inc%kinc
    time = increment_time(inc)
    dtime = inc%dt
    period = inc%period
    nlgeom = inc%nlgeom
    stat = 0
    msg = ''
    nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
    ue = an%work%u(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1))
    call element_increment(an, ie, n, ue, due(:, 1))
    call element_shift(an, ie, n, ushift)
    ue = ue - ushift
    if (an%nr%elem_has(ie)) then
      ! *TRANSFORM: the element works in global components
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), ue)
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), due(:, 1))
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), ushift)
    end if
    iu = model%elem_utype(ie)
    mcrd = model%utypes(iu)%mcrd
    nf = model%nfield
    allocate (xc(mcrd, nn), predef(2, 1 + nf, nn))
    nact = size(model%utypes(iu)%active)
    do a = 1, nn
      xc(:, a) = model%x(1:mcrd, model%conn(model%conn_ptr(ie) + a - 1))
      if (.not. nlgeom) cycle
      do jd = 1, nact
        if (model%utypes(iu)%active(jd) <= mcrd) xc(model%utypes(iu)%active(jd), a) = &
          xc(model%utypes(iu)%active(jd), a) + ushift((a - 1) * nact + jd)
      end do
    end do
    ! PREDEF(1,1,a): temperature at the end of the increment, PREDEF(2,1,a): its increment; PREDEF(1:2,1+k,a) the
    ! same of field variable k (Abaqus UEL: NPREDF = 1 + the number of field variables, temperature first)
    do a = 1, nn
      nd = model%conn(model%conn_ptr(ie) + a - 1)
      predef(1, 1, a) = an%work%temp_end(nd)
      predef(2, 1, a) = predef(1, 1, a) - an%state%temp_start(nd)
      predef(1, 2:1 + nf, a) = an%work%field_end((nd - 1) * nf + 1:nd * nf)
      predef(2, 2:1 + nf, a) = predef(1, 2:1 + nf, a) - an%state%field_start((nd - 1) * nf + 1:nd * nf)
    end do
    ip = model%elem_uelprop(ie)
    if (ip > 0) then
      props = model%uelprops(ip)%props
      jprops = model%uelprops(ip)%jprops
    else
      allocate (props(0), jprops(0))
    end if
    ! zeros after NPROPS and NJPROPS, as for a UMAT: a routine reading past them reads 0 on every run
    props = [props, spread(0.0_dp, 1, umat_props_pad)]
    jprops = [jprops, spread(0, 1, umat_props_pad)]
    nsv = model%utypes(iu)%nsvars
    ! a fresh copy of the converged SVARS and ENERGY on every call (docs/conventions.md), between two guard bands
    ! of svars_guard entries that the routine must leave alone (a write outside SVARS(1:NSVARS) stops the run below)
    allocate (sv(max(nsv, 1) + 2 * svars_guard))
    sv = svars_guard_value
    sv(svars_guard + 1:svars_guard + nsv) = an%state%conv(ie)%svars
    if (nsv == 0) sv(svars_guard + 1) = 0.0_dp   ! NSVARS = 0: one defined entry to pass
    energy = an%state%conv(ie)%energy
    rhs = 0.0_dp
    ke = 0.0_dp
    v = 0.0_dp
    acc = 0.0_dp
    params = 0.0_dp
    ! Un loads: NDLOAD active ones, JDLTYP(k,1) = n, ADLMAG(k,1) magnitude at the end of the increment,
    ! DDLMAG(k,1) its increment (Abaqus UEL interface)
    call dload_uel_arrays(an%state%loads%dload, model, ie, time(1) + dtime, dtime, ndload, jdltyp(:, 1), adlmag(:, 1), &
      ddlmag(:, 1))
    ! LFLAGS(3) = 1: RHS and AMATRX (every normal iteration, free equations or not); 5: RHS only (the host
    ! reuses a factorization or skips the tangent). LFLAGS(5) = 1: the start of an increment extrapolated from
    ! the previous one. PARAMS(1:3) (the dynamic procedures' integration parameters) are 0 in a static step.
    lflags = [1, merge(1, 0, nlgeom), merge(1, 5, want_k), 0, merge(1, 0, inc%extrapolated)]
    call an%routines%uel(rhs, ke, sv(svars_guard + 1), energy, n, 1, nsv, props, model%utypes(iu)%nprops, xc, mcrd, &
      nn, ue, due, v, acc, model%utypes(iu)%jtype, time, dtime, kstep, kinc, model%elem_id(ie), params, ndload, jdltyp, &
      adlmag, predef, 1 + nf, lflags, n, ddlmag, mdload, pnewdt, jprops, model%utypes(iu)%njprops, period)
    fel = -rhs(:, 1)
    if (.not. (all(ieee_is_finite(fel)) .and. all(ieee_is_finite(ke)))) then
      write (b, '(i0)') model%elem_id(ie)
      stat = 1
      msg = 'element '//trim(b)//' (UEL): returned a non-finite RHS or AMATRX'
      return
    end if
    call check_svars_guards(sv, nsv, model%elem_id(ie))
    if (nsv > 0) an%work%trial(ie)%svars = sv(svars_guard + 1:svars_guard + nsv)
    an%work%trial(ie)%energy = energy
    ! AMATRX symmetrised unless the type is UNSYMM (Abaqus)
    if (want_k .and. .not. model%utypes(iu)%unsymm) ke = 0.5_dp * (ke + transpose(ke))
  end subroutine user_element_compute

  !> A UEL that wrote outside SVARS(1:NSVARS) (into the guard bands around the copy it was given: SVARS(0), a loop
  !> one too long) asks the run to stop, naming the element and the first index written: in Abaqus such a write lands
  !> in another element's state without a word; here it would be lost, so neither run could be trusted.
  subroutine check_svars_guards(sv, nsv, label)
    real(dp), intent(in) :: sv(:)    !< the guarded copy (svars_guard entries, max(NSVARS, 1), svars_guard entries)
    integer, intent(in) :: nsv       !< NSVARS
    integer, intent(in) :: label     !< element label
    integer :: k, first
    first = huge(1)
    do k = 1, svars_guard
      if (sv(k) /= svars_guard_value) first = min(first, k - svars_guard)
    end do
    do k = svars_guard + max(nsv, 1) + 1, size(sv)
      if (sv(k) /= svars_guard_value .and. first == huge(1)) first = k - svars_guard
    end do
    if (first == huge(1)) return
    call abaqus_request_stop('element '//itoa(label)//' (UEL): the routine wrote SVARS('//itoa(first)// &
      '), outside SVARS(1:'//itoa(nsv)//') (NSVARS = '//itoa(nsv)//'; Abaqus would have overwritten another '// &
      'element''s state there without a word): correct the index in the routine')
  end subroutine check_svars_guards

  !> A continuum element (solid_element_compute) with its section's material, and its distributed loads. Fixed-size
  !> work arrays (at most 20 nodes, 60 dofs): no heap allocation per call.
  subroutine continuum_element_compute(an, model, ie, n, inc, want_k, fel, ke, pnewdt, stat, msg)
    type(analysis_t), intent(inout) :: an
    type(model_t), intent(in) :: model
    integer, intent(in) :: ie, n
    type(increment_t), intent(in) :: inc
    logical, intent(in) :: want_k
    real(dp), intent(out) :: fel(n), ke(n, n)
    real(dp), intent(inout) :: pnewdt
    integer, intent(out) :: stat
    character(len=*), intent(out) :: msg
    integer, parameter :: mnode = 20, mdof = 3 * mnode
    integer :: nn, a, nd, im
    real(dp) :: ue(mdof), due(mdof), coords(3, mnode), t0(mnode), dtn(mnode), e2(2), fl(mdof), kl(mdof, mdof), rho
    real(dp) :: ushift(mdof)
    real(dp) :: no_fields(0, mnode)
    real(dp), allocatable :: fld0(:, :), dfld(:, :)
    type(solid_geometry_t) :: gw
    character(len=16) :: b
    integer :: kstep, kinc
    real(dp) :: time(2), dtime
    logical :: nlgeom

    kstep = inc%step
    kinc = inc%kinc
    time = increment_time(inc)
    dtime = inc%dt
    nlgeom = inc%nlgeom
    stat = 0
    msg = ''
    nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
    ue(1:n) = an%work%u(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1))
    call element_increment(an, ie, n, ue(1:n), due(1:n))
    call element_shift(an, ie, n, ushift(1:n))
    ue(1:n) = ue(1:n) - ushift(1:n)
    if (an%nr%elem_has(ie)) then
      ! *TRANSFORM: the element works in global components
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), ue(1:n))
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), due(1:n))
      call element_to_global(an%nr, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1), ushift(1:n))
    end if
    do a = 1, nn
      nd = model%conn(model%conn_ptr(ie) + a - 1)
      coords(1:an%ndim, a) = model%x(1:an%ndim, nd)
      if (nlgeom) coords(1:an%ndim, a) = coords(1:an%ndim, a) + ushift((a - 1) * an%ndim + 1:a * an%ndim)
      t0(a) = an%state%temp_start(nd)
      dtn(a) = an%work%temp_end(nd) - an%state%temp_start(nd)
    end do
    ! second-order quadrilaterals and hexahedra: the temperature field of their first-order part (as Abaqus)
    call solid_first_order_temperature(element_family(model%elem_kind(ie)), t0(1:nn))
    call solid_first_order_temperature(element_family(model%elem_kind(ie)), dtn(1:nn))
    if (model%nfield > 0) then
      fld0 = element_fields(an%state%field_start)
      dfld = element_fields(an%work%field_end) - fld0
      call element_call(fld0, dfld)
    else
      call element_call(no_fields(:, 1:nn), no_fields(:, 1:nn))
    end if
    if (stat /= 0) then
      ! the element's own message names the element already; say which routine it came from
      write (b, '(i0)') model%elem_id(ie)
      if (index(msg, 'element '//trim(b)//':') == 1) msg = msg(len('element '//trim(b)//':') + 2:)
      msg = 'element '//trim(b)//' ('//trim(merge('UMAT    ', '*ELASTIC', &
        an%mats(model%elem_section(ie))%kind == SOLID_MAT_UMAT))//'): '//trim(msg)
      stat = 1
    end if
    if (stat == 0 .and. dload_has(an%state%loads%dload, ie)) then
      ! distributed loads: forces apart (external), follower-pressure load stiffness into the tangent
      im = model%elem_section(ie)
      rho = 0.0_dp
      if (im > 0) rho = model_density(model, im)
      if (an%elem_geo(ie) < 0) then
        ! compact reference data: the whole arrays computed for the load (elements with distributed loads only)
        call element_geometry(an, model, ie, gw)
        call dload_element(an%state%loads%dload, model, ie, time(1) + dtime, coords(1:an%ndim, 1:nn), ue(1:n), &
          nlgeom, gw%nfun(1:nn, 1:an%elem_nip(ie)), gw%wdet(1:an%elem_nip(ie)), an%mats(im)%thickness, rho, &
          want_k, fl(1:n), kl(1:n, 1:n))
      else
        associate (g => an%geo(an%elem_geo(ie)))
          call dload_element(an%state%loads%dload, model, ie, time(1) + dtime, coords(1:an%ndim, 1:nn), ue(1:n), &
            nlgeom, g%nfun(1:nn, 1:an%elem_nip(ie)), g%wdet(1:an%elem_nip(ie)), an%mats(im)%thickness, rho, &
            want_k, fl(1:n), kl(1:n, 1:n))
        end associate
      end if
      an%work%fdle(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1) = fl(1:n)
      if (want_k) ke = ke + kl(1:n, 1:n)
    end if

  contains

    !> (nfield, nnode) the field variables of the element's nodes in v (an%state%field_start or an%work%field_end).
    pure function element_fields(v) result(fe)
      real(dp), intent(in) :: v(:)
      real(dp) :: fe(model%nfield, model%conn_ptr(ie + 1) - model%conn_ptr(ie))
      integer :: b, m
      do b = 1, size(fe, 2)
        m = model%conn(model%conn_ptr(ie) + b - 1)
        fe(:, b) = v((m - 1) * model%nfield + 1:m * model%nfield)
      end do
    end function element_fields

    !> solid_element_compute with the element's data and its reference data in the form the host keeps.
    subroutine element_call(fields0, dfields)
      real(dp), intent(in) :: fields0(:, :), dfields(:, :)   !< (nfield, nn) field variables, increments
      associate (st => an%work%trial(ie), cv => an%state%conv(ie))
        if (an%elem_geo(ie) < 0) then
          call solid_element_compute(an%elem_tname(ie), coords(1:an%ndim, 1:nn), ue(1:n), due(1:n), &
            an%mats(model%elem_section(ie)), cv%stress, cv%stran, cv%statev, time, dtime, kstep, kinc, &
            model%elem_id(ie), nlgeom, want_k, fel, ke, st%stress, st%stran, st%statev, e2, pnewdt, stat, msg, &
            energy_ip_old=cv%eip, energy_ip_new=st%eip, geo_compact=an%geo_compact(:, -an%elem_geo(ie)), &
            temp_nodes=t0(1:nn), dtemp_nodes=dtn(1:nn), orient=an%axes(ie)%t, field_nodes=fields0, &
            dfield_nodes=dfields)
        else
          call solid_element_compute(an%elem_tname(ie), coords(1:an%ndim, 1:nn), ue(1:n), due(1:n), &
            an%mats(model%elem_section(ie)), cv%stress, cv%stran, cv%statev, time, dtime, kstep, kinc, &
            model%elem_id(ie), nlgeom, want_k, fel, ke, st%stress, st%stran, st%statev, e2, pnewdt, stat, msg, &
            energy_ip_old=cv%eip, energy_ip_new=st%eip, geo=an%geo(an%elem_geo(ie)), temp_nodes=t0(1:nn), &
            dtemp_nodes=dtn(1:nn), orient=an%axes(ie)%t, field_nodes=fields0, dfield_nodes=dfields)
        end if
        st%energy = 0.0_dp
        st%energy(2) = e2(1)
        st%energy(4) = e2(2)
      end associate
    end subroutine element_call
  end subroutine continuum_element_compute

  !> Local material axes at the integration points of the elements whose section has an *ORIENTATION (the points'
  !> reference coordinates for CYLINDRICAL). A plane element's axes must keep local 3 along z.
  subroutine element_axes(an, model, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 undefined axes
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: ie, ip, nn, io, a
    real(dp) :: x(3)
    logical :: ok
    type(solid_geometry_t) :: g
    stat = 0
    errmsg = ''
    allocate (an%axes(model%nelem))
    do ie = 1, model%nelem
      if (model%elem_kind(ie) == etype_user) cycle
      io = model%sections(model%elem_section(ie))%iorient
      if (io == 0) cycle
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      allocate (an%axes(ie)%t(3, 3, an%elem_nip(ie)))
      ! every element's axes on every process (the same errors everywhere; rank 0 prints any element's tables)
      call element_geometry(an, model, ie, g)
      do ip = 1, an%elem_nip(ie)
        x = 0.0_dp
        do a = 1, nn
          x = x + g%nfun(a, ip) * model%x(:, model%conn(model%conn_ptr(ie) + a - 1))
        end do
        call orientation_axes(model%orientations(io), x, an%axes(ie)%t(:, :, ip), ok)
        if (ok .and. model%ndim == 2) ok = abs(abs(an%axes(ie)%t(3, 3, ip)) - 1.0_dp) <= 1.0e-9_dp
        if (.not. ok) then
          stat = 2
          errmsg = model%orientations(io)%pos%file//':'//itoa(model%orientations(io)%pos%line)// &
            ': *ORIENTATION: orientation '//trim(model%orientations(io)%name)//' has no axes at point '// &
            itoa(ip)//' of element '//itoa(model%elem_id(ie))//' (coinciding points, a point on the cylinder '// &
            'axis, or, in a plane model, local 3 not along z)'
          return
        end if
      end do
    end do
  end subroutine element_axes

  !> State arrays of element ie, zero, in the shapes the model gives it: a user element's SVARS (NSVARS), a
  !> continuum element's stress and strain (ntens x nip), STATEV (the material's NSTATV, then the element's own
  !> incompatible-mode parameters, x nip) and energy densities (3 x nip).
  subroutine element_state_allocate(an, model, ie, state)
    type(analysis_t), intent(in) :: an              !< analysis data (materials, element type names)
    type(model_t), intent(in) :: model              !< the model
    integer, intent(in) :: ie                       !< element
    type(elem_state_t), intent(inout) :: state      !< its state (any earlier arrays replaced)
    integer :: d(3)
    call element_state_free(state)
    if (model%elem_kind(ie) == etype_user) then
      allocate (state%svars(model%utypes(model%elem_utype(ie))%nsvars))
      state%svars = 0.0_dp
      return
    end if
    d = continuum_state_dims(an, model, ie)
    allocate (state%stress(d(1), d(2)), state%stran(d(1), d(2)), state%statev(d(3), d(2)), state%eip(3, d(2)))
    state%stress = 0.0_dp
    state%stran = 0.0_dp
    state%statev = 0.0_dp
    state%eip = 0.0_dp
  end subroutine element_state_allocate

  !> Dimensions of continuum element ie's state arrays: ntens, nip, and the STATEV rows (the material's NSTATV,
  !> then the element's own incompatible-mode parameters; at least 1).
  pure function continuum_state_dims(an, model, ie) result(d)
    type(analysis_t), intent(in) :: an              !< analysis data (materials, element type names)
    type(model_t), intent(in) :: model              !< the model
    integer, intent(in) :: ie                       !< continuum element
    integer :: d(3)
    integer :: nnode, ndim, nip, ntens, ndi, nshr, nextra
    call solid_element_info(an%elem_tname(ie), nnode, ndim, nip, ntens, ndi, nshr, nextra)
    d = [ntens, nip, max(1, an%mats(model%elem_section(ie))%nstatv + nextra)]
  end function continuum_state_dims

  !> Reference data (solid_element_geometry) of continuum element ie: this process's stored copy, or computed here
  !> when it keeps none (another process's element in a distributed run).
  subroutine element_geometry(an, model, ie, g)
    type(analysis_t), intent(in) :: an          !< analysis data
    type(model_t), intent(in) :: model          !< the model
    integer, intent(in) :: ie                   !< continuum element
    type(solid_geometry_t), intent(out) :: g    !< its reference data
    if (allocated(an%elem_geo)) then
      if (an%elem_geo(ie) > 0) then
        g = an%geo(an%elem_geo(ie))
        return
      end if
    end if
    call solid_element_geometry(an%elem_tname(ie), &
      model%x(1:model%ndim, model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)), g)
  end subroutine element_geometry

  !> The elements this process computes: all of them in a one-process run; with several processes the METIS
  !> partition of the element graph (element_partition), each element weighted by the cost of its class in the
  !> element loop (an%cost_weight: by default 6, 5, 1 for UMAT continuum, *ELASTIC continuum, user element, as
  !> measured on the 3D peel family; --element-weights sets others: every run measures its classes' costs and
  !> run_summary prints them). The partition is interleaved: METIS pieces, pieces_given per process
  !> (partition_pieces_default when 0; --partition-pieces), dealt out in turn, so that a costly region that moves
  !> (a plastic zone at the delamination front) is shared by the processes.
  !> The owner map's signature goes into the restart fingerprint: a restart needs the same partition.
  subroutine partition(an, model, pieces_given, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data (an%par set)
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: pieces_given                  !< pieces per process (0: partition_pieces_default)
    integer, intent(out) :: stat                         !< 0 ok
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer, allocatable :: weight(:), owner(:)
    character(len=256) :: msg
    integer :: ie, pieces
    stat = 0
    errmsg = ''
    allocate (an%owned(model%nelem))
    an%owned = .true.
    if (.not. parallel_distributed(an%par)) return
    allocate (weight(model%nelem))
    do ie = 1, model%nelem
      weight(ie) = an%cost_weight(cost_class(an, model, ie))
    end do
    pieces = pieces_given
    if (pieces == 0) pieces = partition_pieces_default(model%nelem, an%par%nranks)
    call partition_elements(model%nnode, model%conn_ptr, model%conn(1:model%conn_ptr(model%nelem + 1) - 1), &
      weight, an%par%nranks, pieces, owner, stat, msg)
    if (stat /= 0) then
      errmsg = trim(msg)
      stat = 2
      return
    end if
    an%owned = owner == an%par%rank
    ! the same on every process (the same owner map): part of the restart fingerprint
    an%partition_sig = 1
    do ie = 1, model%nelem
      an%partition_sig = mod(an%partition_sig * 131_i8 + int(owner(ie) + 1, i8), 1000000007_i8)
    end do
  end subroutine partition

  !> The element-loop trace when LDFCZ_LOOP_TRACE=PREFIX is set (a diagnostic of the element loop's balance;
  !> tools/loop_trace.py reads it): PREFIX.rankR.csv on every process R, a header, then one row per element loop
  !> (analysis_assemble): loop, step, increment, tangent assembled (1/0), this process's wall seconds up to the
  !> first reduction, the largest of them over the processes (the process's own in a one-process run), the
  !> process's CPU seconds over the same span (all its threads), then seconds and calls per cost class (cost_class:
  !> UMAT continuum, *ELASTIC continuum, user element).
  subroutine open_loop_trace(an)
    type(analysis_t), intent(inout) :: an                !< analysis data (an%par set)
    character(len=:), allocatable :: prefix, path
    integer :: length, st, ios
    character(len=256) :: iomsg
    call get_environment_variable('LDFCZ_LOOP_TRACE', length=length, status=st)
    if (st /= 0 .or. length == 0) return
    allocate (character(len=length) :: prefix)
    call get_environment_variable('LDFCZ_LOOP_TRACE', prefix)
    path = prefix//'.rank'//itoa(an%par%rank)//'.csv'
    open (newunit=an%timing%loop_trace, file=path, status='replace', action='write', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      ! a diagnostic that cannot change the analysis: the run goes on (a failure on one process only must not
      ! part the processes), said on the error output by the process concerned
      an%timing%loop_trace = 0
      write (error_unit, '(a)') 'ldfcz: warning: LDFCZ_LOOP_TRACE: cannot write '//path//' ('//trim(iomsg)// &
        '): no element-loop trace from process '//itoa(an%par%rank)
      return
    end if
    write (an%timing%loop_trace, '(a)') 'loop,step,increment,tangent,loop_s,slowest_s,cpu_s,umat_s,elastic_s,user_s,' // &
      'umat_calls,elastic_calls,user_calls'
  end subroutine open_loop_trace

  !> Closes the element-loop trace (when open) at the end of the analysis, before the processes part: left to the
  !> program's exit, its last lines were lost on the processes that mpirun ended as soon as another one had exited
  !> with a non-zero status (a run stopped by --stop-after-increments or SIGTERM, exit 3 or 128+n).
  subroutine close_loop_trace(an)
    type(analysis_t), intent(inout) :: an  !< analysis data
    if (an%timing%loop_trace == 0) return
    close (an%timing%loop_trace)
    an%timing%loop_trace = 0
  end subroutine close_loop_trace

  !> Pieces per process of the interleaved partition when --partition-pieces is not given: 32, as measured on the
  !> paper's application scene with 2 processes (element loop balance max/mean 1.07 -> 1.01 over its first 62
  !> increments, docs/performance.md "Interleaved partition"), but no piece smaller than 300 elements, about the
  !> size measured there (340), so that more processes do not cut the mesh into ever smaller pieces whose shared
  !> nodes add entries to MUMPS' input and to the products. On 4-16 processes (4-18 pieces each) the balance stayed
  !> at 1.04-1.08 against up to 1.34 with one part each (docs/performance.md "On 4 to 16 processes").
  pure integer function partition_pieces_default(nelem, nranks) result(pieces)
    integer, intent(in) :: nelem   !< elements of the model
    integer, intent(in) :: nranks  !< processes
    integer, parameter :: pieces_measured = 32, min_elements = 300
    pieces = max(1, min(pieces_measured, nelem / (max(1, nranks) * min_elements)))
  end function partition_pieces_default

  !> Cost class of an element for the partition weights and the measured costs: 1 continuum element with a UMAT,
  !> 2 continuum element with *ELASTIC, 3 user element (UEL).
  pure integer function cost_class(an, model, ie) result(k)
    type(analysis_t), intent(in) :: an                   !< analysis data (materials)
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(in) :: ie                            !< element
    if (model%elem_kind(ie) == etype_user) then
      k = 3
    else if (an%mats(model%elem_section(ie))%kind == SOLID_MAT_UMAT) then
      k = 1
    else
      k = 2
    end if
  end function cost_class


  !> *INITIAL CONDITIONS, TYPE=STRESS (every integration point of the element gets the given stress; not in
  !> equilibrium, it is equilibrated by the first increment as in Abaqus without *GEOSTATIC) and TYPE=SOLUTION (the
  !> UMAT's NSTATV state variables at every integration point), in deck order (a later line wins).
  subroutine apply_initial_conditions(an, model, stat, errmsg)
    type(analysis_t), intent(inout) :: an                !< analysis data
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: k, j, ie, nt, nv, ip, nnode, ndim, nip, ndi, nshr, nextra
    character(len=16) :: b, c
    stat = 0
    errmsg = ''
    ! every element is checked on every process (the same errors everywhere); the values go to this process's own
    do k = 1, model%ninit
      associate (ic => model%inits(k))
        do j = 1, size(ic%elems)
          ie = ic%elems(j)
          write (b, '(i0)') model%elem_id(ie)
          write (c, '(i0)') ic%pos%line
          if (model%elem_kind(ie) == etype_user) then
            stat = 2
            errmsg = ic%pos%file//':'//trim(c)//': *INITIAL CONDITIONS: element '//trim(b)//' is a user element '// &
              '(initial stress and solution only for continuum elements)'
            return
          end if
          if (ic%user) then
            if (.not. an%owned(ie)) cycle
            call user_initial_values(an, model, ic%kind, ie, stat)
            if (stat /= 0) then
              errmsg = ic%pos%file//':'//trim(c)//': *INITIAL CONDITIONS: USER needs the user library''s '// &
                trim(merge('SIGINI', 'SDVINI', ic%kind == 1))//' (ldfcz --user FILE with that routine)'
              return
            end if
            cycle
          end if
          nv = size(ic%values)
          if (ic%kind == 1) then
            call solid_element_info(an%elem_tname(ie), nnode, ndim, nip, nt, ndi, nshr, nextra)
            if (nv > nt) then
              if (any(ic%values(nt + 1:) /= 0.0_dp)) then
                stat = 2
                errmsg = ic%pos%file//':'//trim(c)//': *INITIAL CONDITIONS: element '//trim(b)//' has only '// &
                  char(48 + nt)//' stress components'
                return
              end if
            end if
            if (.not. an%owned(ie)) cycle
            do ip = 1, size(an%state%conv(ie)%stress, 2)
              an%state%conv(ie)%stress(1:min(nt, nv), ip) = ic%values(1:min(nt, nv))
            end do
          else
            if (nv /= an%mats(model%elem_section(ie))%nstatv) then
              write (c, '(i0)') an%mats(model%elem_section(ie))%nstatv
              stat = 2
              errmsg = ic%pos%file//':'//itoa(ic%pos%line)//': *INITIAL CONDITIONS: element '//trim(b)// &
                ' has NSTATV = '//trim(c)//' state variables (*DEPVAR); TYPE=SOLUTION needs exactly that many '// &
                'values on one logical data line (continue lines with a trailing comma)'
              return
            end if
            if (.not. an%owned(ie)) cycle
            do ip = 1, size(an%state%conv(ie)%statev, 2)
              an%state%conv(ie)%statev(1:nv, ip) = ic%values
            end do
          end if
        end do
      end associate
    end do
  end subroutine apply_initial_conditions

  !> SIGINI (kind 1: the stress) or SDVINI (kind 2: the state variables, where NSTATV > 0) of the user library at
  !> every integration point of continuum element ie, with the point's coordinates in the reference configuration
  !> (Abaqus: COORDS of the material point); LAYER = KSPT = 1, LREBAR = 0, NAMES blank. stat = 2: no such routine.
  subroutine user_initial_values(an, model, kind, ie, stat)
    type(analysis_t), intent(inout) :: an  !< analysis data (its user routines, the element states)
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: kind, ie        !< 1 stress, 2 state variables; the element
    integer, intent(out) :: stat           !< 0 ok, 2 the routine is missing
    integer :: ip, nt, nsv, ncrds, noel, npt, layer, kspt, lrebar
    real(dp) :: coords(3), sig(6)
    character(len=80) :: names(2)
    stat = 0
    if ((kind == 1 .and. .not. associated(an%routines%sigini)) .or. &
        (kind == 2 .and. .not. associated(an%routines%sdvini))) then
      stat = 2
      return
    end if
    associate (cv => an%state%conv(ie))
      nt = size(cv%stress, 1)
      nsv = an%mats(model%elem_section(ie))%nstatv
      if (kind == 2 .and. nsv == 0) return
      do ip = 1, size(cv%stress, 2)
        coords = point_coordinates(model, ie, ip)
        ncrds = model%ndim
        noel = model%elem_id(ie)
        npt = ip
        layer = 1
        kspt = 1
        lrebar = 0
        names = ''
        if (kind == 1) then
          sig(1:nt) = cv%stress(1:nt, ip)
          call an%routines%sigini(sig(1:nt), coords(1:ncrds), nt, ncrds, noel, npt, layer, kspt, lrebar, names)
          cv%stress(1:nt, ip) = sig(1:nt)
        else
          call an%routines%sdvini(cv%statev(1:nsv, ip), coords(1:ncrds), nsv, ncrds, noel, npt, layer, kspt)
        end if
      end do
    end associate
  end subroutine user_initial_values

  !> Reference coordinates of integration point ip of continuum element ie (the catalogue's rule and shape
  !> functions; 0 in the third component of 2D models).
  function point_coordinates(model, ie, ip) result(x)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie, ip       !< element, point
    real(dp) :: x(3)
    real(dp) :: xi(3), w, n(20), dn(20, 3)
    integer :: kind, nn, nd, a
    kind = model%elem_kind(ie)
    nn = element_nnode(kind)
    nd = element_ndim(kind)
    call solid_gauss_point(element_types(kind)%rule, nd, ip, xi, w)
    call solid_shape_eval(element_family(kind), xi(1:nd), n(1:nn), dn(1:nn, 1:nd))
    x = 0.0_dp
    do a = 1, nn
      x(1:nd) = x(1:nd) + n(a) * model%x(1:nd, model%conn(model%conn_ptr(ie) + a - 1))
    end do
  end function point_coordinates

  !> Density of the material of section isec (0 without *DENSITY).
  pure real(dp) function model_density(model, isec) result(rho)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: isec         !< section
    integer :: k
    rho = 0.0_dp
    do k = 1, model%nmat
      if (model%materials(k)%name == model%sections(isec)%material) rho = model%materials(k)%density
    end do
  end function model_density

  !> The increment converged: the trial state becomes the converged one.
  subroutine analysis_commit(an)
    type(analysis_t), intent(inout) :: an  !< analysis data
    integer :: ie
    an%state%u_conv = an%work%u
    an%work%from_zero = .false.
    do ie = 1, size(an%state%conv)
      call element_state_copy(an%work%trial(ie), an%state%conv(ie))
    end do
  end subroutine analysis_commit

  !> The attempt failed: back to the converged displacement (states are always recomputed from conv).
  subroutine analysis_restore(an)
    type(analysis_t), intent(inout) :: an  !< analysis data
    an%work%u = an%state%u_conv
  end subroutine analysis_restore

end module analysis_core
