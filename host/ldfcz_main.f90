!> ldfcz: the open host. Reads an Abaqus-style deck and runs its static steps, calling UEL and UMAT as
!> Abaqus/Standard does. Usage: ldfcz [options] JOB.inp (ldfcz --help). Exit status: 0 every step completed,
!> 2 deck or option error, 3 the analysis stopped without convergence (converged output kept).
program ldfcz
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use ldfcz_config, only: ldfcz_version, ldfcz_commit, ldfcz_build_type, ldfcz_abaqus_include_dir, &
    ldfcz_install_include_rel
  use model_types, only: model_t
  use deck_reader, only: read_deck
  use user_routines, only: user_routines_connect_units, user_routines_t, user_routines_load
  use routine_choice, only: user_routines_choose, note_len
    use deck_context, only: deck_message_t
  use command_words, only: abaqus_word, abaqus_word_t, deck_path, restart_base, WORD_NONE, WORD_JOB, WORD_INPUT, &
    WORD_USER, WORD_CPUS, WORD_ACCEPTED, WORD_REFUSED
  use output_files, only: output_t, output_open, output_close, output_log, output_note, output_sta_note, &
    output_discard_empty
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
  !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
  implicit none
  character(len=:), allocatable :: arg, deck, outdir, user_file, job, errmsg, fc, fflags
  character(len=:), allocatable :: job_word    !< job=NAME of Abaqus' command line ('' not given)
  character(len=:), allocatable :: input_word  !< input=FILE
  character(len=:), allocatable :: word_notes  !< the Abaqus words accepted without effect, for JOB.log
  integer :: i, n, stat, threads, exit_code, k, nthreads, cpus
  logical :: job_ready   !< the job's name and output directory are known: an input error is recorded there
  logical :: deck_read   !< the deck was read (the model's size is known)
  type(deck_message_t), allocatable :: deck_messages(:)
  logical :: quiet, verbose, exists, reorient, orient_error
  logical :: slow_kernels   !< OpenBLAS runs kernels narrower than the CPU allows (blas_kernels_note)
  logical :: out_open    !< JOB.log is open (an error is logged there too)
  type(interface_check_t) :: orient
  character(len=:), allocatable :: orient_text
  character(len=note_len), allocatable :: routine_notes(:)   !< which routine each material and user element type runs
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
  job_ready = .false.
  deck_read = .false.
  job_word = ''
  input_word = ''
  word_notes = ''
  cpus = 0
  deck = ''
  outdir = '.'
  user_file = ''
  ! LDFCZ_REPRODUCIBLE=1: as --reproducible (docs/host.md, "Running on several processes")
  arg = env_value('LDFCZ_REPRODUCIBLE')
  options%reproducible = len(arg) > 0 .and. arg /= '0'
  fc = env_value('FC')
  fflags = env_value('FFLAGS')
  threads = 0
  nthreads = 1
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
      if (parallel_writer(par)) write (output_unit, '(a)') 'ldfcz '//ldfcz_version//' (commit '// &
        ldfcz_commit//', '//ldfcz_build_type//' build)'
      call parallel_finalize(par)
      stop
    case ('-q', '--quiet')
      quiet = .true.
    case ('-v', '--verbose')
      verbose = .true.
    case ('--reorient-interfaces')
      reorient = .true.
    case ('--reproducible')
      options%reproducible = .true.
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
      ! a file (or NAME.inp) is the deck; otherwise a word of Abaqus' command line (job=, user=, cpus=, ...)
      if (len(deck_path(arg)) == 0) then
        if (take_abaqus_word(arg)) then
          i = i + 1
          cycle
        end if
      end if
      if (len(deck) > 0) call die('only one deck may be given (got '//deck//' and '//arg//')')
      deck = arg
    end select
    i = i + 1
  end do
  call resolve_deck_and_job()
  if ((options%symmetric_factors .or. options%single_factors) .and. options%newton /= newton_krylov .and. &
      options%newton /= newton_auto) &
    call die('--factors other than exact needs --newton krylov or auto (the factors only precondition GMRES)')
  if (threads > 0) then
    !$ call omp_set_num_threads(threads)
  end if
  if (len(restart_from) > 0) call resolve_restart_file()
  call make_directories(outdir)
  inquire (file=outdir//'/.', exist=exists)
  if (.not. exists) call die('--out: cannot create directory '//outdir)
  job_ready = .true.   ! from here an input error is also recorded in JOB.log, JOB.sta and JOB.summary.json
  call abaqus_set_job(job, outdir)
  call abaqus_set_processes(par%rank, par%nranks, par%comm)
  ! JOB.summary.json of an earlier run goes now: the file present after this run is this run's (summary_json)
  if (parallel_writer(par)) call summary_json_clear(outdir, job)

  call checkpoint()   ! the options, the deck's and restart file's presence, the output directory
  call read_deck(deck, model, stat, errmsg, messages=deck_messages)
  if (stat /= 0) call die(errmsg)
  call checkpoint()
  deck_read = .true.

  ! an MPI run writes its log, CSV, status and frames once, from rank 0
  call output_open(out, job, outdir, quiet, stat, errmsg, append=len(restart_from) > 0, &
    silent=.not. parallel_writer(par))
  out%npieces = par%nranks   ! VTU frames: one piece per process (JOB_NNNN.pvtu)
  if (stat /= 0) call die(errmsg)
  out_open = .true.
  call output_log(out, 'ldfcz '//ldfcz_version//' (commit '//ldfcz_commit//', '//ldfcz_build_type// &
    ' build): job '//job//', deck '//deck//', output in '//outdir)
  if (len(word_notes) > 0) call output_note(out, word_notes)
  ! the reader's warnings (already on standard error) and notes (JOB.log only)
  do k = 1, size(deck_messages)
    call output_note(out, 'ldfcz: '//deck_messages(k)%text)
  end do
  if (len(user_file) > 0) then
    ! each process of an MPI run compiles into a directory of its own (no two compilers writing one file)
    user_dir = outdir
    if (parallel_distributed(par)) then
      user_dir = outdir//'/ldfcz_rank'//itoa_local(par%rank)
      call make_directories(user_dir//'/')
    end if
    ! the compile and link commands go to JOB.log always (-q keeps only the console quiet)
    call user_routines_load(routines, user_file, user_dir, include_dir(), stat, errmsg, &
      merge(out%log, -1, parallel_writer(par)), fc, fflags)
    if (stat /= 0) call die(errmsg)
  end if
  ! which routine each *USER MATERIAL and *USER ELEMENT type runs: the user's, a declared built-in one, or a stop
  call user_routines_choose(routines, model, stat, errmsg, routine_notes)
  if (stat /= 0) call die(errmsg)
  do k = 1, size(routine_notes)
    call output_log(out, trim(routine_notes(k)))
  end do
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
  ! an input error found while the analysis was set up leaves no empty JOB.csv or JOB.dat
  if (exit_code == exit_input .and. len(restart_from) == 0) call output_discard_empty(out)
  call output_close(out)
  if (parallel_writer(par)) call write_summary()
  call abaqus_flush_repeats(error_unit)
  call parallel_finalize(par)
  call exit(exit_code)

contains

  !> An argument of Abaqus' command line (command_words): acted on, and true; false when arg is no Abaqus word.
  !> docs/host.md, "Abaqus' command line".
  logical function take_abaqus_word(word_arg) result(taken)
    character(len=*), intent(in) :: word_arg
    type(abaqus_word_t) :: w
    character(len=:), allocatable :: value, werr
    call abaqus_word(word_arg, w, value, werr)
    taken = w%action /= WORD_NONE
    if (.not. taken) return
    if (len(werr) > 0) call die(werr)
    select case (w%action)
    case (WORD_JOB)
      job_word = value
      if (index(value, '/') > 0) call die('job='//value//': a job name, not a path (the deck: input=FILE; the '// &
        'output directory: --out DIR)')
    case (WORD_INPUT)
      if (len(input_word) > 0) call die('input= given twice')
      input_word = value
    case (WORD_USER)
      if (len(user_file) > 0) then
        user_file = user_file//','//value
      else
        user_file = value
      end if
    case (WORD_CPUS)
      read (value, *, iostat=stat) cpus
      if (stat /= 0 .or. verify(value, '0123456789') /= 0 .or. cpus < 1) call die('cpus= needs a positive integer')
      ! cpus=N: N cores in all; under mpirun -np P each process threads its element loop on N/P
      if (mod(cpus, par%nranks) /= 0) call die('cpus='//value//' with '//itoa_local(par%nranks)//' processes: '// &
        'cpus must be a multiple of the processes (each gets cpus/processes threads)')
      threads = cpus / par%nranks
    case (WORD_ACCEPTED)
      if (len(word_notes) == 0) then
        word_notes = 'ldfcz: note: '
      else
        word_notes = word_notes//'; '
      end if
      word_notes = word_notes//trim(w%name)//': accepted without effect ('//trim(w%why)//')'
    case (WORD_REFUSED)
      call die(trim(w%name)//': this word of Abaqus'' command line is not supported by ldfcz: '//trim(w%why))
    end select
  end function take_abaqus_word

  !> The deck and the job name: the deck given (or input=), else job=NAME's NAME.inp; a deck named without its
  !> extension is NAME.inp (as Abaqus completes input= and job=); the job name is job= or the deck's base name.
  subroutine resolve_deck_and_job()
    character(len=:), allocatable :: given, found
    integer :: kk
    if (len(deck) > 0 .and. len(input_word) > 0) call die('only one deck may be given (got '//deck// &
      ' and input='//input_word//')')
    given = deck
    if (len(input_word) > 0) given = input_word
    if (len(given) == 0) given = job_word
    if (len(given) == 0) call die('no deck given (ldfcz --help)')
    found = deck_path(given)
    if (len(found) == 0) then
      if (len(given) > 4) then
        if (given(len(given) - 3:) == '.inp') call die(given//': file not found')
      end if
      call die(given//': file not found (nor '//given//'.inp)')
    end if
    inquire (file=found//'/.', exist=exists)
    if (exists) call die(found//': is a directory, not a deck')
    deck = found
    if (len(job_word) > 0) then
      job = job_word
    else
      kk = index(deck, '/', back=.true.)
      job = deck(kk + 1:)
      kk = index(job, '.', back=.true.)
      if (kk > 1) job = job(1:kk - 1)
    end if
  end subroutine resolve_deck_and_job

  !> --restart-from FILE: an MPI run reads one file per process, JOB.rst.RofN; the name of one of them, as the user
  !> sees them on disk, stands for the set; a set written by another number of processes is refused by name.
  subroutine resolve_restart_file()
    character(len=:), allocatable :: base
    integer :: nwritten
    call restart_base(restart_from, base, nwritten)
    if (nwritten > 1) then
      if (nwritten /= par%nranks) call die('--restart-from: '//restart_from//' is one of the '// &
        itoa_local(nwritten)//' files of a restart written by '//itoa_local(nwritten)//' processes; a restart '// &
        'needs as many: mpirun -np '//itoa_local(nwritten)//' ldfcz --restart-from '//base//' ...')
      restart_from = base
    end if
    inquire (file=parallel_file(par, restart_from), exist=exists)
    if (.not. exists) then
      if (par%nranks == 1) then
        inquire (file=restart_from//'.0of2', exist=exists)
        if (exists) call die('--restart-from: '//restart_from//': file not found (the restart files '// &
          restart_from//'.RofN are those of a run on N processes: continue it on as many, mpirun -np N)')
      end if
      call die('--restart-from: '//parallel_file(par, restart_from)//': file not found')
    end if
    options%restart_from = restart_from
  end subroutine resolve_restart_file

  !> An input error once the job is known: JOB.log (opened here if the outputs were not yet), a status line in
  !> JOB.sta, JOB.summary.json with status input_error, and no empty JOB.csv/JOB.dat left behind.
  subroutine record_input_error(text)
    character(len=*), intent(in) :: text  !< the message ('' : already in JOB.log)
    character(len=:), allocatable :: line
    integer :: ios, nl
    line = text
    nl = index(line, new_line('a'))
    if (nl > 0) line = line(1:nl - 1)
    if (len(line) == 0) line = 'see '//job//'.log'
    if (.not. out_open) then
      ! the error came before the outputs were opened (the deck): JOB.log and JOB.sta of this run
      out%job = job
      out%dir = outdir
      if (len(restart_from) > 0) then
        open (newunit=out%log, file=outdir//'/'//job//'.log', position='append', action='write', iostat=ios)
        if (ios == 0) open (newunit=out%sta, file=outdir//'/'//job//'.sta', position='append', action='write', &
          iostat=ios)
      else
        open (newunit=out%log, file=outdir//'/'//job//'.log', status='replace', action='write', iostat=ios)
        if (ios == 0) open (newunit=out%sta, file=outdir//'/'//job//'.sta', status='replace', action='write', &
          iostat=ios)
        if (ios == 0) write (out%sta, '(a)') '# step  inc  attempt  iterations  step_time  increment  outcome'
      end if
      if (ios /= 0) return
      out_open = .true.
      write (out%log, '(a)') 'ldfcz '//ldfcz_version//': job '//job//', deck '//deck//', output in '//outdir
      if (len(text) > 0) write (out%log, '(a)') 'ldfcz: error: '//text
    end if
    call output_sta_note(out, 'input error (exit status 2): '//line)
    if (len(restart_from) == 0) call output_discard_empty(out)
    exit_code = exit_input
    call output_close(out)
    out_open = .false.
    call write_summary()
  end subroutine record_input_error

  !> JOB.summary.json (summary_json): the run's summary for programs, written last and whole.
  subroutine write_summary()
    type(run_facts_t) :: facts
    facts%job = job
    facts%deck = deck
    facts%output_dir = outdir
    facts%version = ldfcz_version
    facts%commit = ldfcz_commit
    facts%restart_from = restart_from
    facts%exit_code = exit_code
    facts%threads = nthreads
    facts%processes = par%nranks
    if (deck_read) then
      facts%nodes = model%nnode
      facts%elements = model%nelem
      facts%steps = model%nstep
    end if
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
    if (job_ready .and. first == exit_input .and. parallel_writer(par)) call record_input_error(text)
    if (out_open) call output_close(out)
    call parallel_finalize(par)
    call exit(first)
  end subroutine stop_all

  subroutine usage()
    write (output_unit, '(a)') 'usage: ldfcz [options] JOB[.inp]', &
      '       ldfcz job=JOB [input=FILE] [user=FILE] [cpus=N] [interactive] [options]   (as abaqus job=...)', &
      '  Runs the static steps of an Abaqus-style deck; the job name is the deck''s base name (or job=).', &
      '  A deck or input= named without .inp is NAME.inp; a user file without its extension is the first of', &
      '  NAME.f, NAME.for, NAME.f90, NAME.F, NAME.o. cpus=N: N threads (under mpirun, N/processes each);', &
      '  interactive, ask_delete=, double=, memory=, scratch=: accepted without effect; other Abaqus words', &
      '  (oldjob=, background, datacheck, ...) are refused with the ldfcz way (docs/host.md).', &
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
      '  --reproducible     a distributed run (mpirun) factorizes and solves on rank 0 alone, so that identical', &
      '                     runs give identical bits (MUMPS'' parallel factorization sums in message order);', &
      '                     the element loop stays distributed. Also set by LDFCZ_REPRODUCIBLE=1', &
      '  --stop-after-increments K  stop (exit 3) after K converged increments of this run (for restart tests)', &
      '  -h, --help         this text', &
      '  -V, --version      the version', &
      'exit status: 0 all steps completed, 2 deck or option error, 3 no convergence (converged output kept)'
  end subroutine usage

end program ldfcz
