!> ldfcz: the open host. Reads an Abaqus-style deck and runs its static steps, calling UEL and UMAT as
!> Abaqus/Standard does. Usage: ldfcz [options] JOB.inp (ldfcz --help). Exit status: 0 every step completed,
!> 2 deck or option error, 3 the analysis stopped without convergence (converged output kept).
program ldfcz
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use ldfcz_config, only: ldfcz_version, ldfcz_abaqus_include_dir, ldfcz_install_include_rel
  use model_types, only: model_t
  use deck_reader, only: read_deck
  use user_routines, only: user_routines_t, user_routines_builtin, user_routines_load
  use output_files, only: output_t, output_open, output_close, output_log
  use static_solver, only: run_analysis, run_summary_t, exit_input, solver_options_t, newton_mode_code
  use abaqus_host_state, only: abaqus_set_job
  !$ use omp_lib, only: omp_set_num_threads
  implicit none
  character(len=:), allocatable :: arg, deck, outdir, user_file, job, errmsg
  integer :: i, n, stat, threads, exit_code, k
  logical :: quiet, verbose, exists
  type(model_t) :: model
  type(user_routines_t) :: routines
  type(output_t) :: out
  type(run_summary_t) :: summary
  type(solver_options_t) :: options

  deck = ''
  outdir = '.'
  user_file = ''
  threads = 0
  quiet = .false.
  verbose = .false.
  n = command_argument_count()
  i = 1
  do while (i <= n)
    arg = get_arg(i)
    select case (arg)
    case ('-h', '--help')
      call usage()
      stop
    case ('-V', '--version')
      write (output_unit, '(a)') 'ldfcz '//ldfcz_version
      stop
    case ('-q', '--quiet')
      quiet = .true.
    case ('-v', '--verbose')
      verbose = .true.
    case ('--newton', '--max-opening-increment', '--plastic-statev', '--max-plastic-increment')
      if (i == n) call die('option '//arg//' needs a value')
      i = i + 1
      select case (arg)
      case ('--newton')
        options%newton = newton_mode_code(get_arg(i))
        if (options%newton == 0) call die('--newton needs full, modified, krylov or auto')
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
    case ('-o', '--out', '-t', '--threads', '-u', '--user')
      if (i == n) call die('option '//arg//' needs a value')
      i = i + 1
      select case (arg)
      case ('-o', '--out')
        outdir = get_arg(i)
      case ('-t', '--threads')
        arg = get_arg(i)
        read (arg, *, iostat=stat) threads
        if (stat /= 0 .or. threads < 1) call die('--threads needs a positive integer')
      case default
        user_file = get_arg(i)
      end select
    case default
      if (arg(1:1) == '-') call die('unknown option '//arg//' (ldfcz --help)')
      if (len(deck) > 0) call die('only one deck may be given')
      deck = arg
    end select
    i = i + 1
  end do
  if (len(deck) == 0) call die('no deck given (ldfcz --help)')
  inquire (file=deck, exist=exists)
  if (.not. exists) call die(deck//': file not found')
  if (threads > 0) then
    !$ call omp_set_num_threads(threads)
  end if
  k = index(deck, '/', back=.true.)
  job = deck(k + 1:)
  k = index(job, '.', back=.true.)
  if (k > 1) job = job(1:k - 1)
  call execute_command_line('mkdir -p '''//outdir//'''', exitstat=stat)
  inquire (file=outdir//'/.', exist=exists)
  if (.not. exists) call die('--out: cannot create directory '//outdir)
  call abaqus_set_job(job, outdir)

  call read_deck(deck, model, stat, errmsg)
  if (stat /= 0) call die(errmsg)

  call user_routines_builtin(routines)
  call output_open(out, job, outdir, quiet, stat, errmsg)
  if (stat /= 0) call die(errmsg)
  call output_log(out, 'ldfcz '//ldfcz_version//': job '//job//', deck '//deck//', output in '//outdir)
  if (len(user_file) > 0) then
    call user_routines_load(routines, user_file, outdir, include_dir(), stat, errmsg, &
      merge(-1, out%log, quiet))
    if (stat /= 0) then
      call output_log(out, 'ldfcz: error: '//errmsg)
      call output_close(out)
      write (error_unit, '(a)') 'ldfcz: error: '//errmsg
      call exit(exit_input)
    end if
  end if
  call run_analysis(model, routines, out, verbose, summary, exit_code, options)
  call output_close(out)
  call exit(exit_code)

contains

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

  subroutine die(msg)
    character(len=*), intent(in) :: msg
    write (error_unit, '(a)') 'ldfcz: error: '//msg
    call exit(exit_input)
  end subroutine die

  subroutine usage()
    write (output_unit, '(a)') 'usage: ldfcz [options] JOB.inp', &
      '  Runs the static steps of an Abaqus-style deck; the job name is the deck''s base name.', &
      'options:', &
      '  -o, --out DIR      write JOB.csv, JOB.sta, JOB.log, JOB.pvd/vtu into DIR (default .)', &
      '  -t, --threads N    threads of the element loop (default: OMP_NUM_THREADS or all cores)', &
      '  -u, --user FILE    compile FILE (Fortran UEL and/or UMAT, fixed .f/.for or free .f90) and use it', &
      '                     instead of the built-in routines, as abaqus job=... user=FILE', &
      '  -q, --quiet        no messages on standard output (JOB.log is still written)', &
      '  -v, --verbose      residual, force and correction of every Newton iteration in JOB.log', &
      '  --newton MODE      full (default: new tangent and factorization every iteration), modified (factors', &
      '                     kept while the residual contracts), krylov (new tangent, GMRES preconditioned by', &
      '                     the last factors), auto (krylov, GMRES budget from the measured costs)', &
      '  --max-opening-increment F  limit increments so that the cohesive opening changes by at most F*delta', &
      '                     per increment (built-in UEL SVARS; paper section 7: F <= 1/3 -> >= 99% of phi)', &
      '  --plastic-statev N report the largest increment of STATEV(N) (default 7 = gamma_p of the built-in', &
      '                     UMAT; 0: none)', &
      '  --max-plastic-increment X  choose the next increment so that STATEV(N) changes by about 0.8 X', &
      '  -h, --help         this text', &
      '  -V, --version      the version', &
      'exit status: 0 all steps completed, 2 deck or option error, 3 no convergence (converged output kept)'
  end subroutine usage

end program ldfcz
