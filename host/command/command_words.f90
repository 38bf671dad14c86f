!> The command line as an Abaqus user types it: `ldfcz job=NAME [input=FILE] [user=FILE] [cpus=N] [interactive]`
!> beside ldfcz's own options, and the file names Abaqus completes (NAME -> NAME.inp, a user file without its
!> extension). docs/host.md, "Abaqus' command line", maps every word to ldfcz's options. Pure lookups: the program
!> (ldfcz_main) acts on them.
module command_words
  use ldfcz_text, only: lower_case
  implicit none
  private
  public :: abaqus_word, abaqus_word_t, deck_path, user_file_path, restart_base, user_extensions
  public :: WORD_NONE, WORD_JOB, WORD_INPUT, WORD_USER, WORD_CPUS, WORD_ACCEPTED, WORD_REFUSED

  !> what a word does: not an Abaqus word; the job name; the deck; the user files; the threads; accepted without
  !> effect on ldfcz (it already behaves so); refused with the reason
  integer, parameter :: WORD_NONE = 0, WORD_JOB = 1, WORD_INPUT = 2, WORD_USER = 3, WORD_CPUS = 4, &
    WORD_ACCEPTED = 5, WORD_REFUSED = 6

  !> One word of Abaqus' execution procedure (Abaqus Analysis User's Guide, "Abaqus/Standard and Abaqus/Explicit
  !> execution"): its name, whether it takes a value (name=value), what ldfcz does with it and why.
  type :: abaqus_word_t
    character(len=24) :: name = ''
    logical :: valued = .false.
    integer :: action = WORD_NONE
    character(len=120) :: why = ''
  end type abaqus_word_t

  !> The extensions tried, in this order, for a user file named without one: Abaqus' own Fortran source extensions
  !> first (.f, .for), then free-form and preprocessed sources, then an object (the order is inferred, see
  !> docs/host.md: the Abaqus execution page says only that a source or an object file is given)
  character(len=4), parameter :: user_extensions(5) = [character(len=4) :: '.f', '.for', '.f90', '.F', '.o']

  type(abaqus_word_t), parameter :: words(26) = [ &
    abaqus_word_t('job', .true., WORD_JOB, 'the job name'), &
    abaqus_word_t('input', .true., WORD_INPUT, 'the deck'), &
    abaqus_word_t('user', .true., WORD_USER, 'the user routines (--user)'), &
    abaqus_word_t('cpus', .true., WORD_CPUS, 'the threads (--threads)'), &
    abaqus_word_t('interactive', .false., WORD_ACCEPTED, 'ldfcz always runs in the foreground'), &
    abaqus_word_t('ask_delete', .true., WORD_ACCEPTED, 'ldfcz replaces the files of an earlier run of the job '// &
      'without asking'), &
    abaqus_word_t('double', .true., WORD_ACCEPTED, 'ldfcz computes in double precision always'), &
    abaqus_word_t('memory', .true., WORD_ACCEPTED, 'ldfcz allocates what the model needs'), &
    abaqus_word_t('scratch', .true., WORD_ACCEPTED, 'ldfcz writes no scratch files'), &
    abaqus_word_t('analysis', .false., WORD_ACCEPTED, 'ldfcz always runs the analysis'), &
    abaqus_word_t('mp_mode', .true., WORD_REFUSED, 'processes: mpirun -np N ldfcz (an LDFCZ_MPI build); '// &
      'threads: --threads N or cpus=N'), &
    abaqus_word_t('threads_per_mpi_process', .true., WORD_REFUSED, 'use --threads N under mpirun'), &
    abaqus_word_t('standard_parallel', .true., WORD_REFUSED, 'the element loop is threaded always (--threads)'), &
    abaqus_word_t('parallel', .true., WORD_REFUSED, 'the element loop is threaded always (--threads)'), &
    abaqus_word_t('domains', .true., WORD_REFUSED, 'processes: mpirun -np N ldfcz (an LDFCZ_MPI build)'), &
    abaqus_word_t('gpus', .true., WORD_REFUSED, 'ldfcz does not use GPUs'), &
    abaqus_word_t('oldjob', .true., WORD_REFUSED, 'ldfcz restarts on the unchanged deck: '// &
      '--restart-from OLDJOB.rst (docs/host.md, "Restart")'), &
    abaqus_word_t('background', .false., WORD_REFUSED, 'ldfcz runs in the foreground: use the shell '// &
      '(nohup ldfcz ... &)'), &
    abaqus_word_t('queue', .true., WORD_REFUSED, 'ldfcz has no queues: use the shell or a batch system'), &
    abaqus_word_t('after', .true., WORD_REFUSED, 'ldfcz has no queues: use the shell or a batch system'), &
    abaqus_word_t('datacheck', .false., WORD_REFUSED, 'ldfcz reads and checks the whole deck before the '// &
      'analysis: a deck error stops it at once'), &
    abaqus_word_t('syntaxcheck', .false., WORD_REFUSED, 'ldfcz reads and checks the whole deck before the '// &
      'analysis: a deck error stops it at once'), &
    abaqus_word_t('parametercheck', .false., WORD_REFUSED, 'ldfcz reads and checks the whole deck before '// &
      'the analysis: a deck error stops it at once'), &
    abaqus_word_t('continue', .false., WORD_REFUSED, 'continue a stopped run with --restart-from JOB.rst'), &
    abaqus_word_t('recover', .false., WORD_REFUSED, 'continue a stopped run with --restart-from JOB.rst'), &
    abaqus_word_t('information', .true., WORD_REFUSED, 'ldfcz --version, ldfcz --help')]

contains

  !> The Abaqus word an argument is: 'job=Job-1' -> job, value 'Job-1'; 'int' -> interactive (a word may be
  !> abbreviated while it stays unique, as Abaqus' command line takes 'j=' and 'int'). w%action = WORD_NONE when arg
  !> is no Abaqus word (a deck name or an ldfcz option); errmsg says what is wrong with a word that is one.
  pure subroutine abaqus_word(arg, w, value, errmsg)
    character(len=*), intent(in) :: arg                  !< the command-line argument
    type(abaqus_word_t), intent(out) :: w                !< the word (action WORD_NONE: not one)
    character(len=:), allocatable, intent(out) :: value  !< its value ('' for a word without one)
    character(len=:), allocatable, intent(out) :: errmsg !< '' or what is wrong
    character(len=:), allocatable :: key
    integer :: k, j, nmatch
    value = ''
    errmsg = ''
    if (len(arg) == 0) return
    if (arg(1:1) == '-') return
    k = index(arg, '=')
    if (k > 0) then
      key = lower_case(arg(1:k - 1))
      value = arg(k + 1:)
    else
      key = lower_case(arg)
    end if
    if (len(key) == 0 .or. verify(key, 'abcdefghijklmnopqrstuvwxyz_') /= 0) return
    nmatch = 0
    do j = 1, size(words)
      if (len(key) > len_trim(words(j)%name)) cycle
      if (words(j)%name(1:len(key)) /= key) cycle
      if (key == trim(words(j)%name)) then
        nmatch = 1
        w = words(j)
        exit
      end if
      nmatch = nmatch + 1
      w = words(j)
    end do
    if (nmatch == 0) return
    if (nmatch > 1) then
      w = abaqus_word_t('', .false., WORD_REFUSED, '')
      errmsg = 'the Abaqus word '''//key//''' is ambiguous: write it out (ldfcz --help)'
      return
    end if
    if (w%valued .and. k == 0) then
      errmsg = trim(w%name)//'= needs a value ('//trim(w%name)//'=...)'
    else if (w%valued .and. len(value) == 0) then
      errmsg = trim(w%name)//'= needs a value (got an empty one)'
    else if (.not. w%valued .and. k > 0) then
      errmsg = trim(w%name)//' takes no value'
    end if
  end subroutine abaqus_word

  !> The deck a name means: the file itself, else name.inp (as Abaqus completes job=NAME and input=NAME); '' when
  !> neither exists.
  function deck_path(name) result(path)
    character(len=*), intent(in) :: name  !< as typed
    character(len=:), allocatable :: path
    logical :: there
    path = ''
    if (len(name) == 0) return
    inquire (file=name, exist=there)
    if (there) then
      path = name
      return
    end if
    inquire (file=name//'.inp', exist=there)
    if (there) path = name//'.inp'
  end function deck_path

  !> The user file a name means: the file itself, else the first of name + user_extensions that exists; '' when
  !> none does.
  function user_file_path(name) result(path)
    character(len=*), intent(in) :: name  !< as typed
    character(len=:), allocatable :: path
    logical :: there
    integer :: k
    path = ''
    if (len(name) == 0) return
    inquire (file=name, exist=there)
    if (there) then
      path = name
      return
    end if
    do k = 1, size(user_extensions)
      inquire (file=name//trim(user_extensions(k)), exist=there)
      if (there) then
        path = name//trim(user_extensions(k))
        return
      end if
    end do
  end function user_file_path

  !> A restart file named as one process's file of a distributed run's set, 'JOB.rst.RofN' (R in 0..N-1): the name
  !> of the set, 'JOB.rst', and N; other names: the name itself and nwritten = 0.
  pure subroutine restart_base(path, base, nwritten)
    character(len=*), intent(in) :: path                 !< as given to --restart-from
    character(len=:), allocatable, intent(out) :: base   !< the name of the set
    integer, intent(out) :: nwritten                     !< processes that wrote it (0: not a per-process name)
    integer :: k, j, r, ios
    base = path
    nwritten = 0
    k = index(path, '.', back=.true.)
    if (k <= 1 .or. k == len(path)) return
    j = index(path(k + 1:), 'of')
    if (j <= 1) return
    associate (rank_text => path(k + 1:k + j - 1), n_text => path(k + j + 2:))
      if (len(n_text) == 0) return
      if (verify(rank_text, '0123456789') /= 0 .or. verify(n_text, '0123456789') /= 0) return
      read (rank_text, *, iostat=ios) r
      if (ios /= 0) return
      read (n_text, *, iostat=ios) nwritten
      if (ios /= 0 .or. r >= nwritten .or. nwritten < 1) then
        nwritten = 0
        return
      end if
    end associate
    base = path(1:k - 1)
  end subroutine restart_base

end module command_words
