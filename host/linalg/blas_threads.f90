!> Thread count of the BLAS used by MUMPS (OpenBLAS only; see blas_threads.c).
!>
!> The sequential MUMPS is parallel only inside large BLAS calls. Measured on the paper's application scene
!> (89 595 DOFs, docs/performance.md "BLAS threads"): a second OpenBLAS thread does not shorten the
!> factorizations, while its worker keeps spinning for a while after every BLAS call and takes a core from the
!> OpenMP element loop. The host therefore runs OpenBLAS on one thread unless the user chose a count with
!> OPENBLAS_NUM_THREADS.
module blas_threads
  use, intrinsic :: iso_c_binding, only: c_int
  implicit none
  private
  public :: blas_threads_default

  interface
    integer(c_int) function ldfcz_blas_set_threads(n) bind(C, name='ldfcz_blas_set_threads')
      import :: c_int
      integer(c_int), value :: n
    end function ldfcz_blas_set_threads
  end interface

contains

  !> One BLAS thread unless OPENBLAS_NUM_THREADS is set; returns the description for the log ('' when
  !> nothing was changed: another BLAS, or the user's own setting).
  subroutine blas_threads_default(what)
    character(len=:), allocatable, intent(out) :: what  !< what was done, for JOB.log
    integer :: length, status

    what = ''
    call get_environment_variable('OPENBLAS_NUM_THREADS', length=length, status=status)
    if (status == 0) return
    if (ldfcz_blas_set_threads(1_c_int) == 1) what = 'OpenBLAS on 1 thread (set OPENBLAS_NUM_THREADS to change)'
  end subroutine blas_threads_default

end module blas_threads
