!> Graceful stop on SIGTERM, SIGINT and SIGUSR1 (docs/host.md, "Stopping a run"; SIGUSR1 because OpenMPI's mpirun
!> forwards it to every process, while it ends the job itself on SIGTERM). The first signal only records its number;
!> the increment loop reads it after each converged increment and ends the run there as a complete one would end:
!> restart data (when restart data are written), a last field frame, the closing summary with the energy balance,
!> exit status 128 + the signal number. The handler restores the default action, so that a second signal ends the
!> program at once (the CSV and status file are complete to the last converged increment in any case).
module stop_signal
  use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_null_funptr
  implicit none
  private
  public :: stop_signal_install, stop_signal_received, stop_signal_name

  integer(c_int), parameter :: sig_int = 2, sig_usr1 = 10, sig_term = 15   ! POSIX numbers on Linux
  !> number of the signal received (0: none); written by the handler only
  integer(c_int), volatile, save :: received = 0

  interface
    !> C library signal(): install handler for sig, return the previous one.
    function c_signal(sig, handler) bind(C, name='signal') result(previous)
      import :: c_int, c_funptr
      integer(c_int), value, intent(in) :: sig       !< signal number
      type(c_funptr), value, intent(in) :: handler   !< new handler (C_NULL_FUNPTR: SIG_DFL)
      type(c_funptr) :: previous
    end function c_signal
  end interface

contains

  !> Catch SIGTERM, SIGINT and SIGUSR1 from now on.
  subroutine stop_signal_install()
    type(c_funptr) :: previous
    received = 0
    previous = c_signal(sig_term, c_funloc(on_signal))
    previous = c_signal(sig_int, c_funloc(on_signal))
    previous = c_signal(sig_usr1, c_funloc(on_signal))
  end subroutine stop_signal_install

  !> The handler: record the signal, give the default action back for the next one (signal() is async-signal-safe).
  subroutine on_signal(sig) bind(C)
    integer(c_int), value, intent(in) :: sig  !< signal number
    type(c_funptr) :: previous
    received = sig
    previous = c_signal(sig, c_null_funptr)
  end subroutine on_signal

  !> The signal received since stop_signal_install (0: none).
  integer function stop_signal_received() result(sig)
    sig = int(received)
  end function stop_signal_received

  !> Name of a signal number this module catches.
  pure function stop_signal_name(sig) result(name)
    integer, intent(in) :: sig  !< signal number
    character(len=:), allocatable :: name
    select case (sig)
    case (sig_term)
      name = 'SIGTERM'
    case (sig_int)
      name = 'SIGINT'
    case (sig_usr1)
      name = 'SIGUSR1'
    case default
      name = 'signal'
    end select
  end function stop_signal_name

end module stop_signal
