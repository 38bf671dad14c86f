!> A warning when the OpenMP runtime was told to keep idle threads spinning.
!>
!> The element loop is threaded; MUMPS (sequential) and the rest of the Newton iteration run on the main thread.
!> Measured on the 40x40x10 C3D8 block of tools/bench_calculix.py (docs/performance.md "Idle OpenMP threads beside
!> the factorization"): with libgomp's default policy an idle worker sleeps after a few milliseconds and takes no
!> CPU during a factorization, with OMP_WAIT_POLICY=passive likewise; with OMP_WAIT_POLICY=active it spins through
!> every factorization and, on 2 cores shared with other work, the factorizations took 2.2x longer. The policy is
!> read by the runtime when the program loads, before any of ldfcz's code runs, so ldfcz cannot change it: it says
!> so in JOB.log instead.
module omp_wait
  use ldfcz_text, only: upper_case
  implicit none
  private
  public :: omp_wait_note

contains

  !> what: a warning for JOB.log when nthreads > 1 and OMP_WAIT_POLICY=active or GOMP_SPINCOUNT=infinite/infinity
  !> are set ('' otherwise).
  subroutine omp_wait_note(nthreads, what)
    integer, intent(in) :: nthreads                     !< threads of the element loop
    character(len=:), allocatable, intent(out) :: what  !< the warning, or ''
    character(len=32) :: v, u
    integer :: status
    what = ''
    if (nthreads <= 1) return
    call get_environment_variable('OMP_WAIT_POLICY', v, status=status)
    if (status == 0 .and. upper_case(adjustl(v)) == 'ACTIVE') what = 'OMP_WAIT_POLICY=active'
    call get_environment_variable('GOMP_SPINCOUNT', v, status=status)
    u = upper_case(adjustl(v))
    if (status == 0 .and. (u == 'INFINITE' .or. u == 'INFINITY')) what = 'GOMP_SPINCOUNT='//trim(v)
    if (len(what) > 0) what = 'warning: '//what//': the idle threads of the element loop spin through every '// &
      'factorization and solve, taking a core from MUMPS (factorizations 2.2x slower on 2 shared cores, '// &
      'docs/performance.md); unset it, or use OMP_WAIT_POLICY=passive'
  end subroutine omp_wait_note

end module omp_wait
