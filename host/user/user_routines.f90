!> The UEL and UMAT the host calls, as procedure pointers with the exact Abaqus interfaces: a user's own Fortran
!> source compiled at run time into a shared library and loaded with dlopen (as `abaqus job=... user=...` does), or
!> a built-in ldfcz routine that the deck declares by name (builtin_routines.F90, routine_choice.f90). The
!> executable exports XIT, STDB_ABQERR, ... (-rdynamic), so the library resolves them from the host.
module user_routines
  use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_char, c_int, c_null_char, c_null_ptr, c_associated, &
    c_f_procpointer, c_f_pointer, c_size_t
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp
  use ldfcz_text, only: lower_case
  use solid_umat_interface, only: umat_interface
  use command_words, only: user_file_path
  implicit none
  private
  public :: uel_interface, umat_interface, uexternaldb_interface, disp_interface, sigini_interface, &
    sdvini_interface, user_routines_t, &
    user_routines_builtin, builtin_routine, builtin_names
  public :: user_routines_load
  public :: user_source_compile_command, user_routines_connect_units

  abstract interface
    !> Abaqus/Standard UEL (docs/conventions.md). No INTENT: Abaqus user routines are written without it.
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

    !> Abaqus/Standard UEXTERNALDB(LOP, LRESTART, TIME, DTIME, KSTEP, KINC): called at the start of the analysis
    !> (LOP 0, or 4 on a restart), at the start of every increment attempt (1), at the end of every converged
    !> increment (2) and at the end of the analysis (3).
    subroutine uexternaldb_interface(lop, lrestart, time, dtime, kstep, kinc)
      import :: dp
      integer :: lop, lrestart, kstep, kinc
      real(dp) :: time(2), dtime
    end subroutine uexternaldb_interface

    !> Abaqus/Standard DISP(U, KSTEP, KINC, TIME, NODE, NOEL, JDOF, COORDS): U(1) the total prescribed value of dof
    !> JDOF of node NODE (passed in as the magnitude times the amplitude), TIME step time, total time and time
    !> increment, COORDS the node's coordinates.
    subroutine disp_interface(u, kstep, kinc, time, node, noel, jdof, coords)
      import :: dp
      integer :: kstep, kinc, node, noel, jdof
      real(dp) :: u(3), time(3), coords(3)
    end subroutine disp_interface

    !> Abaqus/Standard SIGINI(SIGMA, COORDS, NTENS, NCRDS, NOEL, NPT, LAYER, KSPT, LREBAR, NAMES): the initial
    !> stress SIGMA(NTENS) at point NPT of element NOEL at COORDS (*INITIAL CONDITIONS, TYPE=STRESS, USER).
    subroutine sigini_interface(sigma, coords, ntens, ncrds, noel, npt, layer, kspt, lrebar, names)
      import :: dp
      integer :: ntens, ncrds, noel, npt, layer, kspt, lrebar
      real(dp) :: sigma(ntens), coords(ncrds)
      character(len=80) :: names(2)
    end subroutine sigini_interface

    !> Abaqus/Standard SDVINI(STATEV, COORDS, NSTATV, NCRDS, NOEL, NPT, LAYER, KSPT): the initial state variables
    !> at point NPT of element NOEL (*INITIAL CONDITIONS, TYPE=SOLUTION, USER).
    subroutine sdvini_interface(statev, coords, nstatv, ncrds, noel, npt, layer, kspt)
      import :: dp
      integer :: nstatv, ncrds, noel, npt, layer, kspt
      real(dp) :: statev(nstatv), coords(ncrds)
    end subroutine sdvini_interface
  end interface

  !> The routines in use.
  type :: user_routines_t
    procedure(uel_interface), pointer, nopass :: uel => null()    !< UEL (null: none available)
    procedure(umat_interface), pointer, nopass :: umat => null()  !< UMAT (null: none available)
    procedure(uexternaldb_interface), pointer, nopass :: uexternaldb => null() !< UEXTERNALDB of a user library
    procedure(disp_interface), pointer, nopass :: disp => null()  !< DISP of a user library (*BOUNDARY, USER)
    procedure(sigini_interface), pointer, nopass :: sigini => null()  !< SIGINI of a user library
    procedure(sdvini_interface), pointer, nopass :: sdvini => null()  !< SDVINI of a user library
    character(len=:), allocatable :: uel_origin                   !< 'built-in', the user file, or 'none'
    character(len=:), allocatable :: umat_origin
    type(c_ptr) :: handle = c_null_ptr                            !< dlopen handle of a user library
  end type user_routines_t

  integer(c_int), parameter :: rtld_lazy = 1, rtld_global = 256

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
    function c_mkdir(path, mode) bind(c, name='mkdir') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: rc
    end function c_mkdir
    function c_strlen(p) bind(c, name='strlen') result(n)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: p
      integer(c_size_t) :: n
    end function c_strlen
  end interface

  interface
    !> Points r at the default built-in UEL and UMAT that were linked in (host/user/builtin_routines.F90).
    module subroutine user_routines_builtin(r)
      type(user_routines_t), intent(inout) :: r  !< routines
    end subroutine user_routines_builtin
    !> The built-in routine of a kind ('UMAT', 'UEL') and name: its procedure and source ('' when none).
    module subroutine builtin_routine(kind, name, pu, pm, source)
      character(len=*), intent(in) :: kind
      character(len=*), intent(in) :: name
      procedure(uel_interface), pointer, intent(out) :: pu
      procedure(umat_interface), pointer, intent(out) :: pm
      character(len=:), allocatable, intent(out) :: source
    end subroutine builtin_routine
    !> Names of the built-in routines of a kind, comma-separated ('none' when none was built).
    module function builtin_names(kind) result(names)
      character(len=*), intent(in) :: kind
      character(len=:), allocatable :: names
    end function builtin_names
  end interface

contains

  !> The command that compiles one user source into an object as Abaqus compiles user files on Linux: preprocessed
  !> (-cpp, with ABQ_LNX86_64 and ABQ_FORTRAN defined), fixed form with 132 columns for .f/.for/.f77 (Abaqus'
  !> -extend-source), free form otherwise, position-independent, locals on the stack (Abaqus' -auto: the threaded
  !> element loop calls the routines concurrently), Cray pointers accepted (the SMA arrays of Abaqus' examples are
  !> used through them; Intel Fortran accepts them by default), argument mismatches between calls a warning (as
  !> Intel Fortran takes them). compiler is gfortran (default) or an LLVM flang;
  !> fflags (--fflags, FFLAGS) come last, so they can override.
  function user_source_compile_command(compiler, source, object, include_dirs, fflags) result(cmd)
    character(len=*), intent(in) :: compiler      !< Fortran compiler (FC, --fc)
    character(len=*), intent(in) :: source        !< user's Fortran file
    character(len=*), intent(in) :: object        !< object file to write
    character(len=*), intent(in) :: include_dirs  !< -I options (quoted directories)
    character(len=*), intent(in) :: fflags        !< the user's extra options ('' for none)
    character(len=:), allocatable :: cmd
    character(len=:), allocatable :: form, extra
    logical :: flang
    integer :: k
    flang = index(compiler, 'flang') > 0
    k = index(source, '.', back=.true.)
    ! free form: lines longer than 132 characters compile, as Intel Fortran (Abaqus' compiler) takes them (a
    ! published routine with such lines ran in Abaqus)
    form = ' -ffree-form -ffree-line-length-none'
    if (flang) form = ' -ffree-form'
    if (k > 0) then
      select case (source(k + 1:))
      case ('f', 'F', 'for', 'FOR', 'f77', 'F77')
        if (flang) then
          form = ' -ffixed-form -ffixed-line-length=132'
        else
          form = ' -ffixed-form -ffixed-line-length-132'
        end if
      end select
    end if
    ! -fallow-argument-mismatch: a call whose actual argument differs in rank or type from another call of the
    ! same routine (a scalar where an array is expected) is a warning, not an error, as Intel Fortran (Abaqus'
    ! compiler) takes it: published user routines rely on it
    extra = ' -O2 -frecursive -fcray-pointer -fallow-argument-mismatch'
    if (flang) extra = ' -O2'
    cmd = compiler//' -c -fPIC -cpp -DABQ_LNX86_64 -DABQ_FORTRAN'//extra//form//include_dirs
    if (len_trim(fflags) > 0) cmd = cmd//' '//trim(fflags)
    cmd = cmd//' -o '''//object//''' '''//source//''''
  end function user_source_compile_command

  !> Compiles the user's files (a comma-separated list of Fortran sources and object files .o, .a, .so) into one
  !> shared library in outdir, loads it with lazy binding (a symbol the files leave undefined is an error only when
  !> it is called, as in Abaqus' link, and the loader names it) and takes its UEL and/or UMAT.
  subroutine user_routines_load(r, source, outdir, include_dir, stat, errmsg, log_unit, compiler, fflags)
    type(user_routines_t), intent(inout) :: r            !< routines (built-in ones replaced where found)
    character(len=*), intent(in) :: source               !< user files, comma-separated
    character(len=*), intent(in) :: outdir               !< output directory (the library goes there)
    character(len=*), intent(in) :: include_dir          !< directory of ABA_PARAM.INC
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer, intent(in) :: log_unit                      !< where to echo the compile command (-1: nowhere)
    character(len=*), intent(in), optional :: compiler   !< Fortran compiler (default gfortran)
    character(len=*), intent(in), optional :: fflags     !< extra compiler options (default none)
    character(len=:), allocatable :: lib, fc, incs, objs, flags
    if (.not. allocated(r%uel_origin)) r%uel_origin = 'none'
    if (.not. allocated(r%umat_origin)) r%umat_origin = 'none'
    fc = 'gfortran'
    if (present(compiler)) then
      if (len_trim(compiler) > 0) fc = trim(compiler)
    end if
    flags = ''
    if (present(fflags)) flags = trim(fflags)
    call prepare_includes(outdir, include_dir, incs, stat, errmsg)
    if (stat == 0) call compile_user_files(source, outdir, fc, incs, flags, log_unit, objs, stat, errmsg)
    if (stat == 0 .and. index(fc, 'flang') > 0) call add_flang_units(fc, outdir, objs, stat, errmsg)
    if (stat /= 0) return
    lib = user_library_path(source, outdir)
    call link_user_library(lib, objs, fc, log_unit, stat, errmsg)
    if (stat /= 0) return
    r%handle = c_dlopen(lib//c_null_char, ior(rtld_lazy, rtld_global))
    if (.not. c_associated(r%handle)) then
      stat = 2
      errmsg = '--user: dlopen failed: '//dl_error()
      return
    end if
    call take_user_symbols(r, source)
    if (r%uel_origin /= source .and. r%umat_origin /= source .and. .not. associated(r%disp)) then
      stat = 2
      errmsg = '--user: '//source//' defines none of SUBROUTINE UEL, UMAT and DISP'
    end if
  end subroutine user_routines_load

  !> The -I options of a user compilation: ABA_PARAM.INC of include_dir, also under the names user files include
  !> it by (public routines write include 'aba_param.inc'; Abaqus on Windows does not tell the cases apart).
  subroutine prepare_includes(outdir, include_dir, incs, stat, errmsg)
    character(len=*), intent(in) :: outdir               !< output directory
    character(len=*), intent(in) :: include_dir          !< directory of ABA_PARAM.INC
    character(len=:), allocatable, intent(out) :: incs   !< -I options (quoted directories)
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: case_dir
    logical :: exists
    stat = 0
    errmsg = ''
    incs = ''
    inquire (file=include_dir//'/ABA_PARAM.INC', exist=exists)
    if (.not. exists) then
      stat = 2
      errmsg = '--user: ABA_PARAM.INC not found in '//include_dir
      return
    end if
    case_dir = outdir//'/ldfcz_user_include'
    call make_case_copies(include_dir//'/ABA_PARAM.INC', case_dir, stat, errmsg)
    if (stat /= 0) return
    incs = ' -I'''//case_dir//''' -I'''//include_dir//''''
  end subroutine prepare_includes

  !> Each file of the comma-separated list: a Fortran source compiled into outdir, an object or library taken as
  !> it is; objs lists what goes into the library (quoted, space-separated).
  subroutine compile_user_files(source, outdir, fc, incs, flags, log_unit, objs, stat, errmsg)
    character(len=*), intent(in) :: source               !< user files, comma-separated
    character(len=*), intent(in) :: outdir               !< output directory
    character(len=*), intent(in) :: fc                   !< Fortran compiler
    character(len=*), intent(in) :: incs                 !< -I options
    character(len=*), intent(in) :: flags                !< the user's extra options
    integer, intent(in) :: log_unit                      !< where to echo the compile command (-1: nowhere)
    character(len=:), allocatable, intent(out) :: objs   !< objects to link
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: rest, file
    integer :: k, nfile
    stat = 0
    errmsg = ''
    objs = ''
    nfile = 0
    rest = source
    do while (len(rest) > 0)
      k = index(rest, ',')
      if (k == 0) then
        file = trim(adjustl(rest))
        rest = ''
      else
        file = trim(adjustl(rest(1:k - 1)))
        rest = rest(k + 1:)
      end if
      if (len(file) == 0) cycle
      nfile = nfile + 1
      call compile_user_file(file, outdir, fc, incs, flags, log_unit, objs, stat, errmsg)
      if (stat /= 0) return
    end do
    if (nfile == 0) then
      stat = 2
      errmsg = '--user: no file given'
    end if
  end subroutine compile_user_files

  !> One user file: located as Abaqus takes user=NAME (a name without its extension: the first of NAME.f, .for,
  !> .f90, .F, .o), compiled unless it is an object or library, and appended to objs.
  subroutine compile_user_file(given, outdir, fc, incs, flags, log_unit, objs, stat, errmsg)
    character(len=*), intent(in) :: given                !< the file as the user named it
    character(len=*), intent(in) :: outdir               !< output directory
    character(len=*), intent(in) :: fc                   !< Fortran compiler
    character(len=*), intent(in) :: incs                 !< -I options
    character(len=*), intent(in) :: flags                !< the user's extra options
    integer, intent(in) :: log_unit                      !< where to echo the compile command (-1: nowhere)
    character(len=:), allocatable, intent(inout) :: objs !< objects to link
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: file, base, obj, cmd
    integer :: k, estat, cstat
    logical :: exists
    stat = 0
    errmsg = ''
    if (len(user_file_path(given)) == 0) then
      stat = 2
      errmsg = '--user: file not found: '//given//' (nor '//given//'.f, .for, .f90, .F or .o)'
      return
    end if
    file = user_file_path(given)
    inquire (file=file//'/.', exist=exists)
    if (exists) then
      stat = 2
      errmsg = '--user: '//file//' is a directory, not a Fortran or object file'
      return
    end if
    k = index(file, '.', back=.true.)
    if (k > 0) then
      select case (file(k + 1:))
      case ('o', 'a', 'so')
        objs = objs//' '''//file//''''
        return
      end select
    end if
    k = index(file, '/', back=.true.)
    base = file(k + 1:)
    k = index(base, '.', back=.true.)
    if (k > 1) base = base(1:k - 1)
    obj = outdir//'/ldfcz_user_'//base//'.o'
    call case_blind_includes(file, outdir//'/ldfcz_user_include', log_unit, 0, stat, errmsg)
    if (stat /= 0) return
    cmd = user_source_compile_command(fc, file, obj, incs//' -I'''//dir_of(file)//'''', flags)
    if (log_unit /= -1) write (log_unit, '(a)') 'ldfcz: compiling user routines: '//cmd
    call execute_command_line(cmd, wait=.true., exitstat=estat, cmdstat=cstat)
    if (cstat /= 0 .or. estat /= 0) then
      stat = 2
      errmsg = '--user: compilation of '//file//' failed (command: '//cmd//')'
      return
    end if
    objs = objs//' '''//obj//''''
  end subroutine compile_user_file

  !> The files a user file INCLUDEs ('name' or "name", Fortran's INCLUDE line or cpp's #include) that are not in
  !> its directory under that name but are under another case (INCLUDE 'PARAM_UMAT.INC' beside param_umat.inc:
  !> routines written on Windows, where Abaqus' compiler does not tell the cases apart) are copied into case_dir,
  !> which the compiler searches first, under the name the source uses; each said on the console and in JOB.log. The
  !> copies are searched in their turn (depth at most 5). Names with a directory and names found as written are left
  !> alone.
  recursive subroutine case_blind_includes(file, case_dir, log_unit, depth, stat, errmsg)
    character(len=*), intent(in) :: file                 !< the user file (or an included file)
    character(len=*), intent(in) :: case_dir             !< the directory of the copies (searched first)
    integer, intent(in) :: log_unit                      !< JOB.log (-1: another process; nothing said)
    integer, intent(in) :: depth                         !< include depth
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=2048) :: line
    character(len=:), allocatable :: name, dir, found, text
    character(len=16) :: num
    integer :: u, ios, iline
    logical :: exists
    stat = 0
    errmsg = ''
    if (depth > 5) return
    dir = dir_of(file)
    open (newunit=u, file=file, status='old', action='read', iostat=ios)
    if (ios /= 0) return
    iline = 0
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      iline = iline + 1
      name = included_name(line)
      if (len(name) == 0) cycle
      if (index(name, '/') > 0) cycle
      inquire (file=dir//'/'//name, exist=exists)
      if (exists) cycle
      inquire (file=case_dir//'/'//name, exist=exists)
      if (exists) cycle
      found = same_name_any_case(dir, name, case_dir)
      if (len(found) == 0) cycle
      call copy_text_file(dir//'/'//found, case_dir//'/'//name, stat)
      if (stat /= 0) then
        errmsg = '--user: cannot write '//case_dir//'/'//name
        exit
      end if
      if (log_unit /= -1) then
        write (num, '(i0)') iline
        text = 'ldfcz: warning: --user: '//file//':'//trim(num)//': INCLUDE '''//name//''' is '//found// &
          ' (file names compared without case, as Windows does)'
        write (error_unit, '(a)') text
        write (log_unit, '(a)') text
      end if
      call case_blind_includes(case_dir//'/'//name, case_dir, log_unit, depth + 1, stat, errmsg)
      if (stat /= 0) exit
    end do
    close (u)
  end subroutine case_blind_includes

  !> The file named by an INCLUDE line ('' when the line is none): INCLUDE 'x' or INCLUDE "x" (any case, after
  !> blanks; fixed-form comments in column 1 and free-form ! comments are no INCLUDE), or #include "x".
  pure function included_name(line) result(name)
    character(len=*), intent(in) :: line  !< a source line
    character(len=:), allocatable :: name
    character(len=:), allocatable :: t
    character :: q
    integer :: e
    name = ''
    if (len_trim(line) == 0) return
    if (scan(line(1:1), 'cC*!') > 0) return
    t = trim(adjustl(line))
    if (t(1:1) == '#') t = trim(adjustl(t(2:)))
    if (len(t) < 10) return
    if (lower_case(t(1:7)) /= 'include') return
    t = trim(adjustl(t(8:)))
    q = t(1:1)
    if (q /= "'" .and. q /= '"') return
    e = index(t(2:), q)
    if (e < 2) return
    name = trim(t(2:e))
  end function included_name

  !> The entry of dir whose name equals name but for case ('' when none); dir listed into a file of work_dir.
  function same_name_any_case(dir, name, work_dir) result(found)
    character(len=*), intent(in) :: dir       !< directory
    character(len=*), intent(in) :: name      !< name sought
    character(len=*), intent(in) :: work_dir  !< where the listing is written (then deleted)
    character(len=:), allocatable :: found
    character(len=1024) :: entry
    character(len=:), allocatable :: listing
    integer :: u, ios, estat, cstat
    found = ''
    listing = work_dir//'/ldfcz_listing.txt'
    call execute_command_line('ls -1A '''//dir//''' > '''//listing//''' 2>/dev/null', wait=.true., &
      exitstat=estat, cmdstat=cstat)
    if (cstat /= 0 .or. estat /= 0) return
    open (newunit=u, file=listing, status='old', action='read', iostat=ios)
    if (ios /= 0) return
    do
      read (u, '(a)', iostat=ios) entry
      if (ios /= 0) exit
      if (lower_case(trim(entry)) == lower_case(name)) then
        found = trim(entry)
        exit
      end if
    end do
    close (u, status='delete')
  end function same_name_any_case

  !> Copies a text file line by line (stat 2 when either cannot be opened).
  subroutine copy_text_file(from, to, stat)
    character(len=*), intent(in) :: from  !< source
    character(len=*), intent(in) :: to    !< copy
    integer, intent(out) :: stat          !< 0 ok, 2 error
    character(len=4096) :: line
    integer :: uin, uout, ios
    stat = 2
    open (newunit=uin, file=from, status='old', action='read', iostat=ios)
    if (ios /= 0) return
    open (newunit=uout, file=to, status='replace', action='write', iostat=ios)
    if (ios /= 0) then
      close (uin)
      return
    end if
    do
      read (uin, '(a)', iostat=ios) line
      if (ios /= 0) exit
      write (uout, '(a)') trim(line)
    end do
    close (uin)
    close (uout)
    stat = 0
  end subroutine copy_text_file

  !> flang's run time has its own unit 7: a small routine of the same compiler connects it to JOB.msg.
  subroutine add_flang_units(fc, outdir, objs, stat, errmsg)
    character(len=*), intent(in) :: fc                   !< Fortran compiler (an LLVM flang)
    character(len=*), intent(in) :: outdir               !< output directory
    character(len=:), allocatable, intent(inout) :: objs !< objects to link
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: obj, cmd
    integer :: estat, cstat
    call write_flang_unit_opener(outdir//'/ldfcz_flang_units.f90', stat, errmsg)
    if (stat /= 0) return
    obj = outdir//'/ldfcz_flang_units.o'
    cmd = user_source_compile_command(fc, outdir//'/ldfcz_flang_units.f90', obj, '', '')
    call execute_command_line(cmd, wait=.true., exitstat=estat, cmdstat=cstat)
    if (cstat /= 0 .or. estat /= 0) then
      stat = 2
      errmsg = '--user: compilation failed (command: '//cmd//')'
      return
    end if
    objs = objs//' '''//obj//''''
  end subroutine add_flang_units

  !> The shared library's path: outdir/libldfcz_user_BASE.so, BASE the first file's name without directory and
  !> extension (./ before a relative path, for dlopen).
  pure function user_library_path(source, outdir) result(lib)
    character(len=*), intent(in) :: source  !< user files, comma-separated
    character(len=*), intent(in) :: outdir  !< output directory
    character(len=:), allocatable :: lib
    character(len=:), allocatable :: base
    integer :: k
    k = index(source, ',')
    base = source
    if (k > 1) base = source(1:k - 1)
    k = index(base, '/', back=.true.)
    base = base(k + 1:)
    k = index(base, '.', back=.true.)
    if (k > 1) base = base(1:k - 1)
    lib = outdir//'/libldfcz_user_'//base//'.so'
    if (lib(1:1) /= '/') lib = './'//lib
  end function user_library_path

  !> Links the objects into lib with gfortran, the host's compiler. Files compiled by LLVM flang also need flang's
  !> run-time library (Fortran I/O, intrinsics): its static archives, found beside the compiler, go into it.
  subroutine link_user_library(lib, objs, fc, log_unit, stat, errmsg)
    character(len=*), intent(in) :: lib                  !< shared library to write
    character(len=*), intent(in) :: objs                 !< objects (quoted, space-separated)
    character(len=*), intent(in) :: fc                   !< Fortran compiler of the user files
    integer, intent(in) :: log_unit                      !< where to echo the link command (-1: nowhere)
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: cmd, runtime
    integer :: estat, cstat
    stat = 0
    errmsg = ''
    runtime = ''
    if (index(fc, 'flang') > 0) runtime = ' "$(dirname "$(readlink -f "$(command -v '//fc//')")")/../lib/'// &
      'libFortranRuntime.a" "$(dirname "$(readlink -f "$(command -v '//fc//')")")/../lib/libFortranDecimal.a"'// &
      ' -lstdc++ -lm'
    cmd = 'gfortran -shared -fPIC -Wl,-Bsymbolic -o '''//lib//''''//objs//runtime
    if (log_unit /= -1) write (log_unit, '(a)') 'ldfcz: linking user routines: '//cmd
    call execute_command_line(cmd, wait=.true., exitstat=estat, cmdstat=cstat)
    if (cstat /= 0 .or. estat /= 0) then
      stat = 2
      errmsg = '--user: linking the user routines failed (command: '//cmd//')'
    end if
  end subroutine link_user_library

  !> The UEL, UMAT, UEXTERNALDB and DISP that the loaded library defines replace r's (UEL and UMAT marked as
  !> coming from source).
  subroutine take_user_symbols(r, source)
    type(user_routines_t), intent(inout) :: r  !< routines (r%handle: the loaded library)
    character(len=*), intent(in) :: source     !< user files, comma-separated
    type(c_funptr) :: f
    procedure(uel_interface), pointer :: pu
    procedure(umat_interface), pointer :: pm
    procedure(uexternaldb_interface), pointer :: px
    procedure(disp_interface), pointer :: pd
    procedure(sigini_interface), pointer :: ps
    procedure(sdvini_interface), pointer :: pv
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
    f = c_dlsym(r%handle, 'uexternaldb_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, px)
      r%uexternaldb => px
    end if
    f = c_dlsym(r%handle, 'disp_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, pd)
      r%disp => pd
    end if
    f = c_dlsym(r%handle, 'sigini_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, ps)
      r%sigini => ps
    end if
    f = c_dlsym(r%handle, 'sdvini_'//c_null_char)
    if (c_associated(f)) then
      call c_f_procpointer(f, pv)
      r%sdvini => pv
    end if
  end subroutine take_user_symbols

  !> Connects unit 7 of the user library's own Fortran run time (a library compiled by LLVM flang) to msg_path
  !> (JOB.msg, which the host has created); nothing for the built-in routines or a gfortran-compiled library, whose
  !> unit 7 is the host's.
  subroutine user_routines_connect_units(r, msg_path)
    type(user_routines_t), intent(in) :: r    !< routines
    character(len=*), intent(in) :: msg_path  !< JOB.msg
    abstract interface
      subroutine opener(path, n) bind(c)
        import :: c_char, c_int
        integer(c_int), value :: n
        character(kind=c_char), intent(in) :: path(n)
      end subroutine opener
    end interface
    procedure(opener), pointer :: open_units
    type(c_funptr) :: f
    if (.not. c_associated(r%handle)) return
    f = c_dlsym(r%handle, 'ldfcz_flang_units'//c_null_char)
    if (.not. c_associated(f)) return
    call c_f_procpointer(f, open_units)
    call open_units(msg_path, len(msg_path, kind=c_int))
  end subroutine user_routines_connect_units

  !> Source of the routine that connects flang's unit 7 to a file (appending: the host created it).
  subroutine write_flang_unit_opener(file, stat, errmsg)
    character(len=*), intent(in) :: file                 !< Fortran file to write
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: u, ios
    stat = 0
    errmsg = ''
    open (newunit=u, file=file, status='replace', action='write', iostat=ios)
    if (ios /= 0) then
      stat = 2
      errmsg = '--user: cannot write '//file
      return
    end if
    write (u, '(a)') '! written by ldfcz: unit 7 of this run time to JOB.msg', &
      'subroutine ldfcz_flang_units(path, n) bind(c, name=''ldfcz_flang_units'')', &
      '  use, intrinsic :: iso_c_binding, only: c_char, c_int', &
      '  implicit none', &
      '  integer(c_int), value :: n', &
      '  character(kind=c_char), intent(in) :: path(n)', &
      '  character(len=n) :: p', &
      '  integer :: i', &
      '  do i = 1, n', &
      '    p(i:i) = path(i)', &
      '  end do', &
      '  open (unit=7, file=p, position=''append'', action=''write'')', &
      'end subroutine ldfcz_flang_units'
    close (u)
  end subroutine write_flang_unit_opener

  !> Directory part of a path ('.' when none).
  pure function dir_of(path) result(d)
    character(len=*), intent(in) :: path  !< file path
    character(len=:), allocatable :: d
    integer :: k
    k = index(path, '/', back=.true.)
    if (k > 1) then
      d = path(1:k - 1)
    else if (k == 1) then
      d = '/'
    else
      d = '.'
    end if
  end function dir_of

  !> Copies of the include file under the upper-, lower- and mixed-case names, in a directory of their own.
  subroutine make_case_copies(inc, dir, stat, errmsg)
    character(len=*), intent(in) :: inc                  !< ABA_PARAM.INC of the installation
    character(len=*), intent(in) :: dir                  !< directory to write the copies into
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=16), parameter :: names(3) = [character(len=16) :: 'ABA_PARAM.INC', 'aba_param.inc', &
      'Aba_Param.inc']
    integer :: k
    integer(c_int) :: rc
    stat = 0
    errmsg = ''
    rc = c_mkdir(dir//c_null_char, int(o'755', c_int))
    do k = 1, size(names)
      call copy_text_file(inc, dir//'/'//trim(names(k)), stat)
      if (stat /= 0) then
        errmsg = '--user: cannot write '//dir//'/'//trim(names(k))
        return
      end if
    end do
  end subroutine make_case_copies

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
