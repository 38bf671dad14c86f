!> Run-time choices of the static solver (command line) and the codes they use: exit status of a run, Newton
!> variant. Shared by the entry point (static_solver), the increment loop (static_step) and the Newton iteration.
module solver_options
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: solver_options_t, exit_ok, exit_input, exit_no_convergence
  public :: newton_full, newton_modified, newton_krylov, newton_auto, newton_mode_code, newton_mode_name

  integer, parameter :: exit_ok = 0, exit_input = 2, exit_no_convergence = 3
  !> Newton variants (docs/performance.md): full = fresh tangent and factorization every iteration; modified =
  !> factors kept across iterations and increments, elements called for the residual only (UEL LFLAGS(3) = 5),
  !> a fresh tangent when the residual contracts poorly; krylov = fresh tangent every iteration, solved by GMRES
  !> preconditioned with the last factorization to 1e-8 (the iterates of full Newton), refactorized when GMRES
  !> does not converge quickly; auto = inexact Newton-Krylov: GMRES stopped at the forcing terms of Eisenstat and
  !> Walker (newton_iteration), its budget set from the operation counts of a factorization and of a GMRES iteration.
  integer, parameter :: newton_full = 1, newton_modified = 2, newton_krylov = 3, newton_auto = 4

  !> Run-time choices of the solver (command line; defaults: Abaqus-like full Newton, no accuracy control).
  type :: solver_options_t
    integer :: newton = newton_full             !< newton_full, newton_modified, newton_krylov, newton_auto
    real(dp) :: max_opening = 0.0_dp            !< > 0: largest cohesive opening increment / delta per increment
    integer :: plastic_statev = -1              !< STATEV whose largest increment is reported (-1: by the UMAT, 0 none)
    real(dp) :: max_plastic = 0.0_dp            !< > 0: next increment aims at this STATEV(plastic_statev) increment
    integer :: restart_write = -1               !< JOB.rst every n increments (-1: as *RESTART in the deck; 0 never)
    character(len=:), allocatable :: restart_from  !< continue from this restart file (docs/host.md, "Restart")
    integer :: stop_after = 0                   !< > 0: stop after so many converged increments (restart tests)
    logical :: symmetric_factors = .false.      !< unsymmetric systems: LDL^T of (K + K^T)/2 as GMRES preconditioner
    logical :: single_factors = .false.         !< factors in single precision as GMRES preconditioner
    !> METIS vertex weights of a distributed run's partition (analysis_core, cost classes): UMAT continuum,
    !> *ELASTIC continuum, user element; measured on the 3D peel family (docs/performance.md, "Distributed runs":
    !> a Leonov C3D8 75-100 us per call, an elastic C3D8 70-90 us, a cohesive U1 12 us); --element-weights
    integer :: element_weights(3) = [6, 5, 1]
    !> pieces per process of a distributed run's partition (> 1: interleaved, element_partition; 0: the default
    !> rule of analysis_core, 32 but at least 300 elements a piece); --partition-pieces
    integer :: partition_pieces = 0
    !> BLAS threads of a large factorization (blas_threads_default; 0: the BLAS is left as it is)
    integer :: factor_blas_threads = 0
    real(dp) :: factor_min_flops = 0.0_dp       !< operations from which a factorization uses them
    !> a distributed run factorizes and solves its linear systems on rank 0 alone, so that identical runs give
    !> identical bits (MUMPS' parallel factorization sums in the order its messages arrive); --reproducible
    logical :: reproducible = .false.
    integer :: threads = 1                      !< threads of the element loop (a second one runs pipelined
                                                !< factorizations of --newton auto beside GMRES)
  end type solver_options_t

contains

  !> Name of a Newton variant.
  pure function newton_mode_name(code) result(name)
    integer, intent(in) :: code  !< newton_full, newton_modified, newton_krylov or newton_auto
    character(len=8) :: name
    select case (code)
    case (newton_modified)
      name = 'modified'
    case (newton_krylov)
      name = 'krylov'
    case (newton_auto)
      name = 'auto'
    case default
      name = 'full'
    end select
  end function newton_mode_name

  !> Code of a Newton variant name (full, modified, krylov, auto); 0 when unknown.
  pure integer function newton_mode_code(name) result(code)
    character(len=*), intent(in) :: name  !< variant name as given on the command line
    select case (name)
    case ('full')
      code = newton_full
    case ('modified')
      code = newton_modified
    case ('krylov')
      code = newton_krylov
    case ('auto')
      code = newton_auto
    case default
      code = 0
    end select
  end function newton_mode_code

end module solver_options
