!> Which kernels OpenBLAS runs (blas_kernels.c): a restart with the best set for the CPU when OpenBLAS took the CPU
!> for an old one (docs/performance.md, "OpenBLAS kernels"), and the line of JOB.log that says what runs.
module blas_kernels
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use ldfcz_text, only: lower_case
  implicit none
  private
  public :: blas_kernels_restart, blas_kernels_note

  integer, parameter :: name_len = 64

  interface
    integer(c_int) function ldfcz_blas_kernels_restart() bind(C, name='ldfcz_blas_kernels_restart')
      import :: c_int
    end function ldfcz_blas_kernels_restart
    integer(c_int) function ldfcz_blas_kernels(core, chose, best, wide, len) bind(C, name='ldfcz_blas_kernels')
      import :: c_int, c_char
      character(kind=c_char), intent(out) :: core(*), chose(*), best(*)
      integer(c_int), intent(out) :: wide
      integer(c_int), value :: len
    end function ldfcz_blas_kernels
  end interface

contains

  !> When OpenBLAS chose kernels without AVX2 on a CPU with AVX2 and FMA and OPENBLAS_CORETYPE is not set: start
  !> the program again with OPENBLAS_CORETYPE set to the best kernels (does not return then). Call it first, before
  !> MPI is initialised and before anything is read or written.
  subroutine blas_kernels_restart()
    integer(c_int) :: failed
    failed = ldfcz_blas_kernels_restart()   ! 1: the restart failed, reported by blas_kernels_note
  end subroutine blas_kernels_restart

  !> The kernels OpenBLAS runs, for JOB.log ('' without OpenBLAS); slow: true when they are narrower than the CPU
  !> allows although the user did not ask for them (said on standard error as well by the caller).
  subroutine blas_kernels_note(what, slow)
    character(len=:), allocatable, intent(out) :: what   !< the line, without the 'ldfcz: ' prefix
    logical, intent(out) :: slow                         !< kernels narrower than the CPU's, not the user's choice
    character(kind=c_char, len=name_len) :: core, chose, best
    character(len=name_len) :: asked
    integer :: status
    integer(c_int) :: wide

    what = ''
    slow = .false.
    if (ldfcz_blas_kernels(core, chose, best, wide, int(name_len, c_int)) /= 1) return
    call c_to_fortran(core)
    call c_to_fortran(chose)
    call c_to_fortran(best)
    call get_environment_variable('OPENBLAS_CORETYPE', asked, status=status)
    if (len_trim(chose) > 0) then
      ! restarted by blas_kernels_restart
      if (lower_case(core) == lower_case(best)) then
        what = 'OpenBLAS kernels '//trim(core)//' (OpenBLAS took this CPU for '//trim(chose)// &
          ': ldfcz restarted itself with OPENBLAS_CORETYPE='//trim(best)//'; set OPENBLAS_CORETYPE to choose)'
      else
        slow = .true.
        what = 'OpenBLAS kernels '//trim(core)//' although the CPU has the instructions of '//trim(best)// &
          ' (OPENBLAS_CORETYPE='//trim(best)//' was not accepted): dense BLAS kernels up to 5x slower'
      end if
    else if (status == 0) then
      what = 'OpenBLAS kernels '//trim(core)//' (OPENBLAS_CORETYPE='//trim(asked)//')'
    else if (len_trim(best) > 0 .and. wide == 0) then
      slow = .true.
      what = 'OpenBLAS kernels '//trim(core)//' although the CPU has the instructions of '//trim(best)// &
        ' (ldfcz did not restart itself: under valgrind, or the restart failed): dense BLAS kernels up to 5x '// &
        'slower; set OPENBLAS_CORETYPE='//trim(best)//' to get them'
    else
      what = 'OpenBLAS kernels '//trim(core)
    end if
  end subroutine blas_kernels_note

  !> Blank everything from the first NUL on.
  pure subroutine c_to_fortran(s)
    character(len=*), intent(inout) :: s
    integer :: k
    k = index(s, c_null_char)
    if (k > 0) s(k:) = ' '
  end subroutine c_to_fortran

end module blas_kernels
