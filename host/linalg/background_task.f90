!> A task on a thread of its own beside the caller (POSIX threads, background_task.c): start it with a procedure
!> of interface task_procedure and its argument, join it later. sparse_system runs its pipelined factorizations
!> there. The task must touch only data that the caller leaves alone until the join.
module background_task
  use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_int, c_associated
  implicit none
  private
  public :: task_start, task_join

  interface
    type(c_ptr) function ldfcz_task_start(fn, arg) bind(C, name='ldfcz_task_start')
      import :: c_ptr, c_funptr
      type(c_funptr), value :: fn
      type(c_ptr), value :: arg
    end function ldfcz_task_start
    integer(c_int) function ldfcz_task_join(handle) bind(C, name='ldfcz_task_join')
      import :: c_ptr, c_int
      type(c_ptr), value :: handle
    end function ldfcz_task_join
  end interface

contains

  !> Start fn(arg) (fn: c_funloc of a bind(C) subroutine taking one type(c_ptr), value) on a new thread; the handle,
  !> or a null pointer when no thread could be started (the caller then runs the task itself).
  type(c_ptr) function task_start(fn, arg) result(handle)
    type(c_funptr), intent(in) :: fn                 !< the task
    type(c_ptr), intent(in) :: arg                   !< its argument
    handle = ldfcz_task_start(fn, arg)
  end function task_start

  !> Wait for the task of handle to end (nothing for a null handle); 0, or pthread_join's error.
  integer function task_join(handle) result(stat)
    type(c_ptr), intent(in) :: handle                !< from task_start
    stat = 0
    if (c_associated(handle)) stat = int(ldfcz_task_join(handle))
  end function task_join

end module background_task
