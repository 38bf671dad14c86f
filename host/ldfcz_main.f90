!> ldfcz: the open host. Reads an Abaqus-style deck and runs its static steps, calling UEL and UMAT as
!> Abaqus/Standard does. Usage: ldfcz [options] JOB.inp (ldfcz --help). Exit status: 0 every step completed,
!> 2 deck or option error, 3 the analysis stopped without convergence (converged output kept).
program ldfcz
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use ldfcz_config, only: ldfcz_version, ldfcz_abaqus_include_dir, ldfcz_install_include_rel
  use model_types, only: model_t
  use deck_reader, only: read_deck
  use user_routines, only: user_routines_connect_units, user_routines_t, user_routines_builtin, user_routines_load
  use output_files, only: output_t, output_open, output_close, output_log
  use static_solver, only: run_analysis, run_summary_t, exit_input, solver_options_t, newton_mode_code, &
    newton_krylov, newton_auto
  use abaqus_host_state, only: abaqus_set_job, abaqus_flush_repeats, abaqus_set_processes
  use blas_threads, only: blas_threads_default
  use blas_kernels, only: blas_kernels_restart, blas_kernels_note
  use omp_wait, only: omp_wait_note
  use parallel_context, only: parallel_t, parallel_init, parallel_finalize, parallel_writer, parallel_distributed, &
    parallel_file, parallel_first_error
  use heap_reuse, only: heap_reuse_default
  use interface_orientation, only: interface_check_t, check_interface_orientation, interface_check_messages
  use summary_json, only: run_facts_t, summary_json_write, summary_json_clear
  use summary_commit, only: build_commit
  !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
  implicit none
  character(len=:), allocatable :: arg, deck, outdir, user_file, job, errmsg, fc, fflags
  integer :: i, n, stat, threads, exit_code, k, nthreads
  logical :: quiet, verbose, exists, reorient, orient_error
  logical :: slow_kernels   !< OpenBLAS runs kernels narrower than the CPU allows (blas_kernels_note)
  logical :: out_open    !< JOB.log is open (an error is logged there too)
  type(interface_check_t) :: orient
  character(len=:), allocatable :: orient_text
  type(model_t) :: model
  type(user_routines_t) :: routines
  type(output_t) :: out
  type(run_summary_t) :: summary
  type(solver_options_t) :: options
  character(len=:), allocatable :: restart_from, blas_note, heap_note, user_dir, wait_note
  type(parallel_t) :: par

  interface
    !> mkdir(2); mode_t is a 32-bit unsigned integer on Linux
    function c_mkdir(path, mode) bind(c, name='mkdir') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: r
    end function c_mkdir
  end interface

  ! OpenBLAS' kernels for this CPU: may start the program again (so first, before MPI or any file)
  call blas_kernels_restart()
  call parallel_init(par)   ! MPI_Init in the LDFCZ_MPI build (mpirun -np N ldfcz ...); nothing in a serial one
  out_open = .false.
  deck = ''
  outdir = '.'
  user_file = ''
  fc = env_value('FC')
  fflags = env_value('FFLAGS')
  threads = 0
  quiet = .false.
  verbose = .false.
  reorient = .false.
  restart_from = ''
  n = command_argument_count()
  i = 1
  do while (i <= n)
    arg = get_arg(i)
    select case (arg)
    case ('-h', '--help')
      if (parallel_writer(par)) call usage()
      call parallel_finalize(par)
      stop
    case ('-V', '--version')
      if (parallel_writer(par)) write (output_unit, '(a)') 'ldfcz '//ldfcz_version
      call parallel_finalize(par)
      stop
    case ('-q', '--quiet')
      quiet = .true.
    case ('-v', '--verbose')
      verbose = .true.
    case ('--reorient-interfaces')
      reorient = .true.
    case ('--newton', '--factors', '--max-opening-increment', '--plastic-statev', '--max-plastic-increment', &
          '--element-weights', '--partition-pieces')
      if (i == n) call die('option '//arg//' needs a value')
      i = i + 1
      select case (arg)
      case ('--newton')
        options%newton = newton_mode_code(get_arg(i))
        if (options%newton == 0) call die('--newton needs full, modified, krylov or auto')
      case ('--factors')
        arg = get_arg(i)
        options%symmetric_factors = arg == 'symmetric' .or. arg == 'symmetric-single'
        options%single_factors = arg == 'single' .or. arg == 'symmetric-single'
        if (.not. (options%symmetric_factors .or. options%single_factors .or. arg == 'exact')) &
          call die('--factors needs exact, symmetric, single or symmetric-single')
      case ('--element-weights')
        ! METIS vertex weights of the classes UMAT continuum, *ELASTIC continuum, user element (a distributed
        ! run's partition; the closing summary prints the measured ones)
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%element_weights
        if (stat /= 0 .or. any(options%element_weights < 1) .or. any(options%element_weights > 1000000)) &
          call die('--element-weights needs three integers 1..1000000 separated by commas (UMAT continuum, '// &
            'elastic continuum, user element), e.g. 6,5,1')
      case ('--partition-pieces')
        ! METIS pieces per process, dealt out in turn (element_partition)
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%partition_pieces
        if (stat /= 0 .or. options%partition_pieces < 1 .or. options%partition_pieces > 10000) &
          call die('--partition-pieces needs an integer 1..10000 (METIS pieces per process; 1: one part each; '// &
            'default 32 with at least 300 elements a piece)')
      case ('--max-opening-increment')
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%max_opening
        if (stat /= 0 .or. .not. (options%max_opening >= 0.0 .and. options%max_opening < huge(1.0))) &
          call die('--max-opening-increment needs a number >= 0 (fraction of delta; 0: off)')
      case ('--max-plastic-increment')
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%max_plastic
        if (stat /= 0 .or. .not. (options%max_plastic >= 0.0 .and. options%max_plastic < huge(1.0))) &
          call die('--max-plastic-increment needs a number >= 0 (0: off)')
      case default
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%plastic_statev
        if (stat /= 0 .or. options%plastic_statev < 0) call die('--plastic-statev needs an integer >= 0 (0: none)')
      end select
    case ('--restart-write')
      ! optional value: the increment frequency (default 1)
      options%restart_write = 1
      if (i < n) then
        arg = get_arg(i + 1)
        if (len(arg) > 0) then
          if (verify(arg, '0123456789') == 0) then
            i = i + 1
            read (arg, *, iostat=stat) options%restart_write
            if (stat /= 0) call die('--restart-write needs an integer >= 0 (0: never)')
          end if
        end if
      end if
    case ('--restart-from', '--stop-after-increments')
      if (i == n) call die('option '//arg//' needs a value')
      i = i + 1
      if (arg == '--restart-from') then
        restart_from = get_arg(i)
        if (len(restart_from) == 0) call die('--restart-from needs a restart file (JOB.rst)')
      else
        arg = get_arg(i)
        read (arg, *, iostat=stat) options%stop_after
        if (stat /= 0 .or. options%stop_after < 1) call die('--stop-after-increments needs a positive integer')
      end if
    case ('-o', '--out', '-t', '--threads', '-u', '--user', '--fc', '--fflags')
      if (i == n) call die('option '//arg//' needs a value')
      i = i + 1
      select case (arg)
      case ('-o', '--out')
        outdir = get_arg(i)
        if (len(outdir) == 0) call die('--out needs a directory name (got an empty one)')
      case ('-t', '--threads')
        arg = get_arg(i)
        read (arg, *, iostat=stat) threads
        if (stat /= 0 .or. threads < 1) call die('--threads needs a positive integer')
      case ('--fc')
        fc = get_arg(i)
        if (len(fc) == 0) call die('--fc needs a compiler name')
      case ('--fflags')
        fflags = get_arg(i)
      case default
        ! several --user options or a comma-separated list: every file goes into the one user library
        if (len(user_file) > 0) then
          user_file = user_file//','//get_arg(i)
        else
          user_file = get_arg(i)
        end if
        if (len(get_arg(i)) == 0) call die('--user needs a file name')
      end select
    case default
      if (arg(1:1) == '-') call die('unknown option '//arg//' (ldfcz --help)')
      if (len(deck) > 0) call die('only one deck may be given')
      deck = arg
    end select
    i = i + 1
  end do
  if (len(deck) == 0) call die('no deck given (ldfcz --help)')
  if ((options%symmetric_factors .or. options%single_factors) .and. options%newton /= newton_krylov .and. &
      options%newton /= newton_auto) &
    call die('--factors other than exact needs --newton krylov or auto (the factors only precondition GMRES)')
  inquire (file=deck, exist=exists)
  if (.not. exists) call die(deck//': file not found')
  if (threads > 0) then
    !$ call omp_set_num_threads(threads)
  end if
  k = index(deck, '/', back=.true.)
  job = deck(k + 1:)
  k = index(job, '.', back=.true.)
  if (k > 1) job = job(1:k - 1)
  if (len(restart_from) > 0) then
    ! an MPI run reads one file per process (JOB.rst.RofN): a process may miss its own
    inquire (file=parallel_file(par, restart_from), exist=exists)
    if (.not. exists) call die('--restart-from: '//parallel_file(par, restart_from)//': file not found')
    options%restart_from = restart_from
  end if
  call make_directories(outdir)
  inquire (file=outdir//'/.', exist=exists)
  if (.not. exists) call die('--out: cannot create directory '//outdir)
  call abaqus_set_job(job, outdir)
  call abaqus_set_processes(par%rank, par%nranks, par%comm)
  ! JOB.summary.json of an earlier run goes now: the file present after this run is this run's (summary_json)
  if (parallel_writer(par)) call summary_json_clear(outdir, job)

  call checkpoint()   ! the options, the deck's and restart file's presence, the output directory
  call read_deck(deck, model, stat, errmsg)
  if (stat /= 0) call die(errmsg)
  call checkpoint()

  call user_routines_builtin(routines)
  ! an MPI run writes its log, CSV, status and frames once, from rank 0
  call output_open(out, job, outdir, quiet, stat, errmsg, append=len(restart_from) > 0, &
    silent=.not. parallel_writer(par))
  out%npieces = par%nranks   ! VTU frames: one piece per process (JOB_NNNN.pvtu)
  if (stat /= 0) call die(errmsg)
  out_open = .true.
  call output_log(out, 'ldfcz '//ldfcz_version//': job '//job//', deck '//deck//', output in '//outdir)
  if (len(user_file) > 0) then
    ! each process of an MPI run compiles into a directory of its own (no two compilers writing one file)
    user_dir = outdir
    if (parallel_distributed(par)) then
      user_dir = outdir//'/ldfcz_rank'//itoa_local(par%rank)
      call make_directories(user_dir//'/')
    end if
    call user_routines_load(routines, user_file, user_dir, include_dir(), stat, errmsg, &
      merge(-1, out%log, quiet .or. .not. parallel_writer(par)), fc, fflags)
    if (stat /= 0) call die(errmsg)
  end if
  call checkpoint()   ! the output files opened, the user library compiled and loaded on every process
  ! interface elements meshed the wrong way round read opening as penetration: refuse them (or reorder them)
  call check_interface_orientation(model, reorient, orient)
  call interface_check_messages(orient, orient_text, orient_error)
  if (len(orient_text) > 0) then
    call output_log(out, orient_text)
    if ((quiet .or. orient_error) .and. parallel_writer(par)) write (error_unit, '(a)') orient_text
  end if
  ! (every process finds the same: the message is already in the log)
  if (orient_error) call stop_all(exit_input, '')
  ! as in Abaqus, a user routine's WRITE(7, ...) goes to JOB.msg (and unit 6 to JOB.dat: output_open)
  if (len(restart_from) > 0) then
    open (unit=7, file=outdir//'/'//job//'.msg', position='append', action='write', iostat=stat)
  else
    open (unit=7, file=outdir//'/'//job//'.msg', status='replace', action='write', iostat=stat)
  end if
  call user_routines_connect_units(routines, outdir//'/'//job//'.msg')
  nthreads = 1
  !$ nthreads = omp_get_max_threads()
  call blas_kernels_note(blas_note, slow_kernels)
  if (len(blas_note) > 0) call output_log(out, 'ldfcz: '//blas_note)
  if (slow_kernels .and. parallel_writer(par)) write (error_unit, '(a)') 'ldfcz: warning: '//blas_note
  options%threads = nthreads
  call blas_threads_default(nthreads, blas_note, options%factor_blas_threads, options%factor_min_flops)
  if (len(blas_note) > 0) call output_log(out, 'ldfcz: '//blas_note)
  call omp_wait_note(nthreads, wait_note)
  if (len(wait_note) > 0) call output_log(out, 'ldfcz: '//wait_note)
  call heap_reuse_default(heap_note)
  if (len(heap_note) > 0) call output_log(out, 'ldfcz: '//heap_note)
  call run_analysis(model, routines, out, verbose, summary, exit_code, options, par)
  call output_close(out)
  if (parallel_writer(par)) call write_summary()
  call abaqus_flush_repeats(error_unit)
  call parallel_finalize(par)
  call exit(exit_code)

contains

  !> JOB.summary.json (summary_json): the run's summary for programs, written last and whole.
  subroutine write_summary()
    type(run_facts_t) :: facts
    facts%job = job
    facts%deck = deck
    facts%output_dir = outdir
    facts%version = ldfcz_version
    facts%commit = build_commit
    facts%restart_from = restart_from
    facts%exit_code = exit_code
    facts%threads = nthreads
    facts%processes = par%nranks
    facts%nodes = model%nnode
    facts%elements = model%nelem
    facts%steps = model%nstep
    facts%stop_after = options%stop_after
    call summary_json_write(outdir, job, facts, summary, stat, errmsg)
    if (stat /= 0) write (error_unit, '(a)') 'ldfcz: warning: '//out%job//'.summary.json not written: '//errmsg
  end subroutine write_summary

  pure function itoa_local(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa_local

  !> The value of an environment variable ('' when unset).
  function env_value(name) result(v)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: v
    integer :: l, st
    call get_environment_variable(name, length=l, status=st)
    if (st /= 0 .or. l == 0) then
      v = ''
      return
    end if
    allocate (character(len=l) :: v)
    call get_environment_variable(name, v)
  end function env_value

  !> mkdir -p without a shell: every parent of dir, then dir (existing ones are fine; failures show in the check
  !> that follows the call).
  subroutine make_directories(dir)
    character(len=*), intent(in) :: dir
    integer :: k
    integer(c_int) :: rc
    do k = 2, len(dir)
      if (dir(k:k) == '/' .and. dir(k - 1:k - 1) /= '/') rc = c_mkdir(dir(1:k - 1)//c_null_char, int(o'777', c_int))
    end do
    rc = c_mkdir(dir//c_null_char, int(o'777', c_int))
  end subroutine make_directories

  !> Directory of ABA_PARAM.INC: <prefix>/include/ldfcz next to an installed program, else the source tree's.
  function include_dir() result(d)
    character(len=:), allocatable :: d
    character(len=4096) :: exe
    integer :: l, k2
    logical :: there
    d = ldfcz_abaqus_include_dir
    call get_command_argument(0, exe, length=l)
    if (index(exe, '/') == 0) return
    k2 = index(exe(1:l), '/', back=.true.)
    inquire (file=exe(1:k2)//'../'//ldfcz_install_include_rel//'/ABA_PARAM.INC', exist=there)
    if (there) d = exe(1:k2)//'../'//ldfcz_install_include_rel
  end function include_dir

  function get_arg(j) result(s)
    integer, intent(in) :: j
    character(len=:), allocatable :: s
    integer :: l
    call get_command_argument(j, length=l)
    allocate (character(len=l) :: s)
    if (l > 0) call get_command_argument(j, s)
  end function get_arg

  !> An input error found by this process: every process ends with status 2 and the message, written once
  !> (an MPI run: by rank 0, after the next checkpoint of the others; docs/host.md).
  subroutine die(msg)
    character(len=*), intent(in) :: msg
    call stop_all(exit_input, msg)
  end subroutine die

  !> A point of the start-up that every process passes: if a process found an error before it (die), every
  !> process ends here with that error.
  subroutine checkpoint()
    call stop_all(0, '')
  end subroutine checkpoint

  !> The first error of the processes (this one's: code /= 0 and msg; none: code = 0) ends every process: the
  !> message once on standard error (and in JOB.log when open: rank 0's) unless it is '' (already reported), MPI ended
  !> normally (no MPI_Abort), exit status code. Returns when no process reported an error.
  subroutine stop_all(code, msg)
    integer, intent(in) :: code
    character(len=*), intent(in) :: msg
    integer :: first
    character(len=:), allocatable :: text
    first = code
    text = msg
    call parallel_first_error(par, first, text)
    if (first == 0) return
    if (len(text) > 0 .and. parallel_writer(par)) then
      if (out_open .and. out%log /= -1) write (out%log, '(a)') 'ldfcz: error: '//text
      write (error_unit, '(a)') 'ldfcz: error: '//text
    end if
    if (out_open) call output_close(out)
    call parallel_finalize(par)
    call exit(first)
  end subroutine stop_all

  subroutine usage()
    write (output_unit, '(a)') 'usage: ldfcz [options] JOB.inp', &
      '  Runs the static steps of an Abaqus-style deck; the job name is the deck''s base name.', &
      'options:', &
      '  -o, --out DIR      write JOB.csv, JOB.sta, JOB.log, JOB.pvd/vtu into DIR (default .)', &
      '  -t, --threads N    threads of the element loop (default: OMP_NUM_THREADS or all cores)', &
      '  -u, --user FILE    compile FILE (Fortran UEL and/or UMAT, fixed .f/.for or free .f90, preprocessed;', &
      '                     or objects .o/.a/.so; several: repeat --user or FILE1,FILE2) into one library and use', &
      '                     it instead of the built-in routines, as abaqus job=... user=FILE', &
      '  --fc COMPILER      Fortran compiler for --user (default: $FC, else gfortran; LLVM flang-new works)', &
      '  --fflags FLAGS     extra compiler options for --user, after the Abaqus-like ones (default: $FFLAGS)', &
      '  -q, --quiet        no messages on standard output (JOB.log is still written)', &
      '  -v, --verbose      residual, force and correction of every Newton iteration in JOB.log', &
      '  --reorient-interfaces  reverse the face order of interface elements whose normal points into the', &
      '                     solid of their bottom face (default: such elements are an error)', &
      '  --newton MODE      full (default: new tangent and factorization every iteration), modified (factors', &
      '                     kept while the residual contracts), krylov (new tangent, GMRES preconditioned by', &
      '                     the last factors), auto (inexact Newton-Krylov: GMRES to Eisenstat-Walker', &
      '                     tolerances, budget from the factors'' operation counts; for large 3D models)', &
      '  --factors KIND     exact (default: LU/LDL^T of the tangent), symmetric (unsymmetric tangents: LDL^T', &
      '                     of (K+K^T)/2), single (single precision) or symmetric-single: factors that only', &
      '                     precondition GMRES (half the factor work or memory traffic; needs krylov/auto)', &
      '  --max-opening-increment F  limit increments so that the cohesive opening changes by at most F*delta', &
      '                     per increment (element types that declare **LDFCZ SVARS OPENING=, LENGTH', &
      '                     PROPERTY=; paper section 7: F <= 1/3 -> >= 99% of phi)', &
      '  --element-weights U,E,C  partition weights of a distributed run (mpirun): cost of a UMAT continuum,', &
      '                     an *ELASTIC continuum and a user element (default 6,5,1; the closing summary', &
      '                     of any run prints the measured ones); a restart needs the same', &
      '  --partition-pieces P  a distributed run cuts the mesh into P pieces per process, dealt out in turn,', &
      '                     so that a costly moving region (a plastic zone) is shared by the processes', &
      '                     (default 32, but pieces of at least 300 elements; 1: one part per process; at', &
      '                     least 10 elements a piece); a restart needs the same', &
      '  --plastic-statev N report the largest increment of STATEV(N) (default: the STATEV a material', &
      '                     declares by **LDFCZ STATEV, PLASTIC STRAIN=n; 0: none)', &
      '  --max-plastic-increment X  choose the next increment so that STATEV(N) changes by about 0.8 X', &
      '  --restart-write [N]  write JOB.rst (restart data) after every N-th increment (default 1) and at the', &
      '                     end of each step; overrides *RESTART, WRITE, FREQUENCY=n of the deck; 0: never', &
      '  --restart-from FILE  continue the analysis of the deck from the restart file FILE (JOB.rst, the same', &
      '                     deck): JOB.csv/.sta/.log are continued, VTU frames numbered on', &
      '  --stop-after-increments K  stop (exit 3) after K converged increments of this run (for restart tests)', &
      '  -h, --help         this text', &
      '  -V, --version      the version', &
      'exit status: 0 all steps completed, 2 deck or option error, 3 no convergence (converged output kept)'
  end subroutine usage

end program ldfcz
