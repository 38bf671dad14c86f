!> Thread count of the BLAS used by MUMPS (OpenBLAS only; see blas_threads.c).
!>
!> The sequential MUMPS is parallel only inside large BLAS calls. Measured (docs/performance.md, "BLAS threads"):
!> on the paper's application scene (89 595 DOFs, small 3D fronts) a second OpenBLAS thread does not shorten the
!> factorizations, while its worker keeps spinning for a while after every BLAS call and takes a core from the
!> OpenMP element loop; on a 3D block with large fronts two threads factorize 1.6x faster. The host therefore runs
!> OpenBLAS on one thread, and on the element loop's threads only during a factorization of at least
!> blas_parallel_min_flops (sparse_system), unless the user chose a count with OPENBLAS_NUM_THREADS.
module blas_threads
  use, intrinsic :: iso_c_binding, only: c_int
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: blas_threads_default, blas_threads_set, blas_parallel_min_flops

  !> Factorizations of at least this many floating-point operations (MUMPS RINFOG(1)/(3)) run their BLAS on the
  !> element loop's threads (docs/performance.md, "BLAS threads"); LDFCZ_BLAS_MIN_FLOPS overrides it
  real(dp), parameter :: blas_parallel_min_flops = 1.0e10_dp

  interface
    integer(c_int) function ldfcz_blas_set_threads(n) bind(C, name='ldfcz_blas_set_threads')
      import :: c_int
      integer(c_int), value :: n
    end function ldfcz_blas_set_threads
  end interface

contains

  !> One BLAS thread unless OPENBLAS_NUM_THREADS is set; factor_threads: the threads a large factorization may use
  !> (nthreads when the host controls the BLAS, else 0: leave it alone). what: the description for the log ('' when
  !> nothing was changed: another BLAS, or the user's own setting).
  subroutine blas_threads_default(nthreads, what, factor_threads, min_flops)
    integer, intent(in) :: nthreads                      !< threads of the element loop
    character(len=:), allocatable, intent(out) :: what   !< what was done, for JOB.log
    integer, intent(out) :: factor_threads               !< BLAS threads of a large factorization (0: untouched)
    real(dp), intent(out) :: min_flops                   !< operations from which a factorization uses them
    integer :: length, status
    character(len=24) :: num
    character(len=160) :: line
    real(dp) :: v

    what = ''
    factor_threads = 0
    min_flops = blas_parallel_min_flops
    call get_environment_variable('LDFCZ_BLAS_MIN_FLOPS', num, status=status)
    if (status == 0) then
      read (num, *, iostat=status) v
      if (status == 0 .and. v >= 0.0_dp) min_flops = v
    end if
    call get_environment_variable('OPENBLAS_NUM_THREADS', length=length, status=status)
    if (status == 0) return
    if (ldfcz_blas_set_threads(1_c_int) /= 1) return
    what = 'OpenBLAS on 1 thread (set OPENBLAS_NUM_THREADS to change)'
    if (nthreads > 1) then
      factor_threads = nthreads
      write (num, '(es9.2)') min_flops
      write (line, '(a,i0,a)') 'OpenBLAS on 1 thread, on ', nthreads, ' during factorizations of at least '
      what = trim(line)//' '//trim(adjustl(num))//' flops (set OPENBLAS_NUM_THREADS to fix the count)'
    end if
  end subroutine blas_threads_default

  !> Set the OpenBLAS thread count; false when the BLAS is not OpenBLAS (nothing done).
  logical function blas_threads_set(n) result(done)
    integer, intent(in) :: n                             !< threads (>= 1)
    done = ldfcz_blas_set_threads(int(max(n, 1), c_int)) == 1
  end function blas_threads_set

end module blas_threads
