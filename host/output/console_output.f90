!> The console (the terminal or pipe the program was started with) and unit 6 of a job: after console_to_dat,
!> standard output (unit 6 of every Fortran runtime in the process, C's stdout) goes to JOB.dat as in Abaqus, and
!> the host's messages go through console_line / console_text (host/output/console_streams.c).
module console_output
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private
  public :: console_line, console_text, console_to_dat, console_is_terminal

  interface
    function c_stdout_to_file(path, append) bind(c, name='ldfcz_stdout_to_file') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: append
      integer(c_int) :: rc
    end function c_stdout_to_file
    subroutine c_console_write(text, n, newline) bind(c, name='ldfcz_console_write')
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: text(*)
      integer(c_int), value :: n, newline
    end subroutine c_console_write
    function c_console_is_terminal() bind(c, name='ldfcz_console_is_terminal') result(r)
      import :: c_int
      integer(c_int) :: r
    end function c_console_is_terminal
  end interface

contains

  !> A line of text on the console.
  subroutine console_line(text)
    character(len=*), intent(in) :: text  !< the line, without its newline
    call c_console_write(text, len(text, kind=c_int), 1_c_int)
  end subroutine console_line

  !> Text on the console without a newline (a progress display).
  subroutine console_text(text)
    character(len=*), intent(in) :: text  !< the text
    call c_console_write(text, len(text, kind=c_int), 0_c_int)
  end subroutine console_text

  !> Sends standard output (unit 6) to path: created, or continued when append (a restart). stat 0 on success.
  subroutine console_to_dat(path, append, stat)
    character(len=*), intent(in) :: path  !< JOB.dat
    logical, intent(in) :: append         !< continue the file
    integer, intent(out) :: stat          !< 0 ok, 2 cannot write
    flush (output_unit)
    stat = 0
    if (c_stdout_to_file(path//c_null_char, merge(1_c_int, 0_c_int, append)) /= 0) stat = 2
  end subroutine console_to_dat

  !> True when the console is a terminal.
  logical function console_is_terminal()
    console_is_terminal = c_console_is_terminal() == 1_c_int
  end function console_is_terminal

end module console_output
