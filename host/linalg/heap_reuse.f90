!> Freed large blocks kept in the heap for reuse (glibc; see heap_reuse.c). The solver allocates and frees its
!> largest work arrays (MUMPS's factorization workspace, the GMRES basis) in every Newton iteration; by default
!> glibc returns them to the kernel, which maps and clears the pages again at the next allocation. The host keeps
!> them unless the user tunes glibc's allocator through the environment (GLIBC_TUNABLES, MALLOC_MMAP_MAX_,
!> MALLOC_TRIM_THRESHOLD_).
module heap_reuse
  use, intrinsic :: iso_c_binding, only: c_int
  implicit none
  private
  public :: heap_reuse_default

  interface
    integer(c_int) function ldfcz_heap_reuse() bind(C, name='ldfcz_heap_reuse')
      import :: c_int
    end function ldfcz_heap_reuse
  end interface

contains

  !> Keep freed large blocks unless the environment tunes the allocator; returns the description for the log ('' when
  !> nothing was changed).
  subroutine heap_reuse_default(what)
    character(len=:), allocatable, intent(out) :: what  !< what was done, for JOB.log
    character(len=*), parameter :: names(3) = [character(len=22) :: 'GLIBC_TUNABLES', 'MALLOC_MMAP_MAX_', &
                                                'MALLOC_TRIM_THRESHOLD_']
    integer :: k, length, status

    what = ''
    do k = 1, size(names)
      call get_environment_variable(trim(names(k)), length=length, status=status)
      if (status == 0) return
    end do
    if (ldfcz_heap_reuse() == 1) what = 'freed large blocks kept in the heap for reuse (glibc mallopt; ' // &
      'GLIBC_TUNABLES overrides)'
  end subroutine heap_reuse_default

end module heap_reuse
