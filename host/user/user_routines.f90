!> The UEL and UMAT the host calls, as procedure pointers with the exact Abaqus interfaces: the built-in ldfcz
!> routines by default, or a user's own Fortran source compiled at run time into a shared library and loaded with
!> dlopen (as `abaqus job=... user=...` does). The executable exports XIT, STDB_ABQERR, ... (-rdynamic), so the
!> library resolves them from the host.
module user_routines
  use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_char, c_int, c_null_char, c_null_ptr, c_associated, &
    c_f_procpointer, c_f_pointer, c_size_t
  use ldfcz_kinds, only: dp
  use solid_umat_interface, only: umat_interface
  implicit none
  private
  public :: uel_interface, umat_interface, user_routines_t, user_routines_builtin, user_routines_load
  public :: user_source_compile_command

  abstract interface
    !> Abaqus/Standard UEL (CONVENTIONS.md). No INTENT: Abaqus user routines are written without it.
    subroutine uel_interface(rhs, amatrx, svars, energy, ndofel, nrhs, nsvars, props, nprops, coords, mcrd, nnode, &
        u, du, v, a, jtype, time, dtime, kstep, kinc, jelem, params, ndload, jdltyp, adlmag, predef, npredf, &
        lflags, mlvarx, ddlmag, mdload, pnewdt, jprops, njprop, period)
      import :: dp
      integer :: ndofel, nrhs, nsvars, nprops, mcrd, nnode, jtype, kstep, kinc, jelem, ndload, npredf, mlvarx
      integer :: mdload, njprop
      integer :: jdltyp(mdload, *), lflags(*), jprops(*)
      real(dp) :: rhs(mlvarx, *), amatrx(ndofel, ndofel), svars(*), energy(8), props(*), coords(mcrd, nnode)
      real(dp) :: u(ndofel), du(mlvarx, *), v(ndofel), a(ndofel), time(2), dtime, params(*)
      real(dp) :: adlmag(mdload, *), predef(2, npredf, nnode), ddlmag(mdload, *), pnewdt, period
    end subroutine uel_interface
  end interface

  !> The routines in use.
  type :: user_routines_t
    procedure(uel_interface), pointer, nopass :: uel => null()    !< UEL (null: none available)
    procedure(umat_interface), pointer, nopass :: umat => null()  !< UMAT (null: none available)
    character(len=:), allocatable :: uel_origin                   !< 'built-in', the user file, or 'none'
    character(len=:), allocatable :: umat_origin
    type(c_ptr) :: handle = c_null_ptr                            !< dlopen handle of a user library
  end type user_routines_t

  integer(c_int), parameter :: rtld_now = 2, rtld_global = 256

  interface
    function c_dlopen(filename, flag) bind(c, name='dlopen') result(h)
      import :: c_ptr, c_char, c_int
      character(kind=c_char), intent(in) :: filename(*)
      integer(c_int), value :: flag
      type(c_ptr) :: h
    end function c_dlopen
    function c_dlsym(handle, symbol) bind(c, name='dlsym') result(f)
      import :: c_ptr, c_funptr, c_char
      type(c_ptr), value :: handle
      character(kind=c_char), intent(in) :: symbol(*)
      type(c_funptr) :: f
    end function c_dlsym
    function c_dlerror() bind(c, name='dlerror') result(p)
      import :: c_ptr
      type(c_ptr) :: p
    end function c_dlerror
    function c_strlen(p) bind(c, name='strlen') result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: p
      integer(c_size_t) :: n
    end function c_strlen
  end interface

  interface
    !> Points r at the built-in UEL and UMAT that were linked in (host/user/builtin_routines.F90).
    module subroutine user_routines_builtin(r)
      type(user_routines_t), intent(inout) :: r  !< routines
    end subroutine user_routines_builtin
  end interface

contains

  !> The compiler command that turns a user source into a shared library.
  function user_source_compile_command(source, library, include_dir) result(cmd)
    character(len=*), intent(in) :: source       !< user's Fortran file (.f, .for fixed form; .f90 free form)
    character(len=*), intent(in) :: library      !< shared library to write
    character(len=*), intent(in) :: include_dir  !< directory of ABA_PARAM.INC
    character(len=:), allocatable :: cmd
    character(len=:), allocatable :: form
    integer :: k
    k = index(source, '.', back=.true.)
    form = ''
    if (k > 0) then
      select case (source(k + 1:))
      case ('f', 'F', 'for', 'FOR', 'f77', 'F77')
        form = ' -ffixed-form -ffixed-line-length-132'  ! Abaqus compiles fixed form with -extend-source
      case default
        form = ' -ffree-form'
      end select
    end if
    ! -Bsymbolic: the library's own routines bind inside it, never to same-named host symbols; -frecursive: local
    ! variables on the stack, as Abaqus' -auto, since the threaded element loop calls the routines concurrently
    cmd = 'gfortran -shared -fPIC -O2 -frecursive -Wl,-Bsymbolic'//form//' -I'''//include_dir//''' -o '''// &
      library//''' '''//source//''''
  end function user_source_compile_command

  !> Compile a user's Fortran source into outdir and load its UEL and/or UMAT in place of the built-in ones.
  subroutine user_routines_load(r, source, outdir, include_dir, stat, errmsg, log_unit)
    type(user_routines_t), intent(inout) :: r            !< routines (built-in ones replaced where found)
    character(len=*), intent(in) :: source               !< user source file
    character(len=*), intent(in) :: outdir               !< output directory (the library goes there)
    character(len=*), intent(in) :: include_dir          !< directory of ABA_PARAM.INC
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer, intent(in) :: log_unit                      !< where to echo the compile command (-1: nowhere)
    character(len=:), allocatable :: lib, cmd, base
    integer :: estat, cstat, k
    logical :: exists
    type(c_funptr) :: f
    procedure(uel_interface), pointer :: pu
    procedure(umat_interface), pointer :: pm

    stat = 0
    errmsg = ''
    inquire (file=source, exist=exists)
    if (.not. exists) then
      stat = 2
      errmsg = '--user: file not found: '//source
      return
    end if
    inquire (file=include_dir//'/ABA_PARAM.INC', exist=exists)
    if (.not. exists) then
      stat = 2
      errmsg = '--user: ABA_PARAM.INC not found in '//include_dir
      return
    end if
    k = index(source, '/', back=.true.)
    base = source(k + 1:)
    k = index(base, '.', back=.true.)
    if (k > 1) base = base(1:k - 1)
    lib = outdir//'/libldfcz_user_'//base//'.so'
    if (lib(1:1) /= '/') lib = './'//lib
    cmd = user_source_compile_command(source, lib, include_dir)
    if (log_unit /= -1) write (log_unit, '(a)') 'ldfcz: compiling user routines: '//cmd
    call execute_command_line(cmd, wait=.true., exitstat=estat, cmdstat=cstat)
    if (cstat /= 0 .or. estat /= 0) then
      stat = 2
      errmsg = '--user: compilation of '//source//' failed (command: '//cmd//')'
      return
    end if
    r%handle = c_dlopen(lib//c_null_char, ior(rtld_now, rtld_global))
    if (.not. c_associated(r%handle)) then
      stat = 2
      errmsg = '--user: dlopen failed: '//dl_error()
      return
    end if
    f = c_dlsym(r%handle, 'uel_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, pu)
      r%uel => pu
      r%uel_origin = source
    end if
    f = c_dlsym(r%handle, 'umat_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, pm)
      r%umat => pm
      r%umat_origin = source
    end if
    if (r%uel_origin /= source .and. r%umat_origin /= source) then
      stat = 2
      errmsg = '--user: '//source//' defines neither SUBROUTINE UEL nor SUBROUTINE UMAT'
    end if
  end subroutine user_routines_load

  function dl_error() result(s)
    character(len=:), allocatable :: s
    type(c_ptr) :: p
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    p = c_dlerror()
    if (.not. c_associated(p)) then
      s = 'unknown error'
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = chars(i)
    end do
  end function dl_error

end module user_routines
