!> Fallback for the part of pFUnit's `funit` module that ldfcz's suites use (see README.md in this folder).
!> Each assertion records a failure with the .pf file, line, expected and actual values; the generated driver
!> runs every test and ends with "N passed, N failed" and a non-zero exit status when any test failed.
module funit
  use, intrinsic :: iso_fortran_env, only: real32, real64, int32, int64, output_unit
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
  implicit none
  private
  public :: assertEqual, assertRelativelyEqual, assertTrue, assertFalse
  public :: pf_ordering, assertIsFinite
  public :: anyExceptions, pf_begin_test, pf_end_test, pf_summary, pf_selected

  integer, parameter :: dp = real64

  interface assertEqual
    module procedure equal_ss, equal_11, equal_22, equal_s1, equal_s2
  end interface assertEqual

  interface assertRelativelyEqual
    module procedure releq_ss, releq_11, releq_22, releq_s1, releq_s2
  end interface assertRelativelyEqual

  interface assertTrue
    module procedure true_s, true_1
  end interface assertTrue

  interface assertFalse
    module procedure false_s, false_1
  end interface assertFalse

  interface assertIsFinite
    module procedure finite_s
  end interface assertIsFinite

  !> The ordering assertions (@assertLessThan, ...; pfpp.py passes the assertion's name as KIND): only the pairs of
  !> kinds pFUnit accepts (see the specific procedures).
  interface pf_ordering
    module procedure ord_i4i4, ord_i8i8, ord_i4i8, ord_i4r4, ord_i4r8, ord_r4r4, ord_r4r8, ord_r8r8
  end interface pf_ordering

  character(len=:), allocatable :: current_test  !< name of the running test
  integer :: failures_in_test = 0                 !< failed assertions in the running test
  integer :: n_passed = 0                         !< tests that passed
  integer :: n_failed = 0                         !< tests that failed
  logical :: args_read = .false.                  !< the command line has been read
  character(len=:), allocatable :: name_filter    !< -f/--filter PATTERN: only tests whose name contains it
  integer :: n_selected = 0                       !< tests the filter let through

contains

  ! ---------------------------------------------------------------- runner support

  !> True when the running test has a failed assertion (pFUnit's anyExceptions()).
  logical function anyExceptions()
    anyExceptions = failures_in_test > 0
  end function anyExceptions

  !> Whether the test procedure NAME (as written in its suite) runs: every test, or with -f PATTERN (--filter
  !> PATTERN, --filter=PATTERN) those whose name contains PATTERN, as pFUnit 4's driver selects (its NameFilter: a
  !> substring of the test method's name, case-sensitive). The command line is read at the first call.
  logical function pf_selected(name)
    character(len=*), intent(in) :: name
    if (.not. args_read) call read_arguments()
    pf_selected = .true.
    if (allocated(name_filter)) pf_selected = index(name, name_filter) > 0
    if (pf_selected) n_selected = n_selected + 1
  end function pf_selected

  !> The options of pFUnit 4's driver that the fallback supports: -f/--filter PATTERN, -d/-v/--debug/--verbose
  !> (accepted; every test's PASS/FAIL line is printed anyway), -h/--help. Anything else ends the run (status 2).
  subroutine read_arguments()
    integer :: i, n, length
    character(len=:), allocatable :: arg
    args_read = .true.
    n = command_argument_count()
    i = 1
    do while (i <= n)
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      call get_command_argument(i, arg)
      select case (arg)
      case ('-f', '--filter')
        if (i == n) call usage('option ' // arg // ' needs a PATTERN')
        i = i + 1
        call get_command_argument(i, length=length)
        allocate (character(len=length) :: name_filter)
        call get_command_argument(i, name_filter)
      case ('-d', '-v', '--debug', '--verbose')
      case ('-h', '--help')
        call usage('')
      case default
        if (index(arg, '--filter=') == 1) then
          name_filter = arg(10:)
        else
          call usage('unknown argument ' // arg)
        end if
      end select
      deallocate (arg)
      i = i + 1
    end do
  end subroutine read_arguments

  subroutine usage(problem)
    character(len=*), intent(in) :: problem
    if (len(problem) > 0) write (output_unit, '(a)') 'pFUnit fallback: ' // problem
    write (output_unit, '(a)') 'usage: SUITE [-h] [-d] [-f PATTERN]'
    write (output_unit, '(a)') '  -f, --filter PATTERN   only run the tests whose name contains PATTERN'
    write (output_unit, '(a)') '  -d, -v, --debug, --verbose   accepted (every test is reported)'
    flush (output_unit)
    if (len(problem) > 0) error stop 2
    stop
  end subroutine usage

  subroutine pf_begin_test(name)
    character(len=*), intent(in) :: name
    current_test = name
    failures_in_test = 0
  end subroutine pf_begin_test

  subroutine pf_end_test()
    if (failures_in_test == 0) then
      n_passed = n_passed + 1
      write (output_unit, '(a)') 'PASS ' // current_test
    else
      n_failed = n_failed + 1
      write (output_unit, '(a)') 'FAIL ' // current_test
    end if
    flush (output_unit)
  end subroutine pf_end_test

  !> The closing line and the exit status: 1 when a test failed; 2 when a filter selected no test (pFUnit runs no
  !> test and succeeds; here a misspelt name does not pass silently).
  subroutine pf_summary()
    write (output_unit, '(i0,a,i0,a)') n_passed, ' passed, ', n_failed, ' failed'
    flush (output_unit)
    if (n_failed > 0) error stop 1
    if (allocated(name_filter) .and. n_selected == 0) then
      write (output_unit, '(a)') 'pFUnit fallback: no test name contains "' // name_filter // '"'
      flush (output_unit)
      error stop 2
    end if
  end subroutine pf_summary

  subroutine fail(kind, detail, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind, detail
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    character(len=:), allocatable :: who
    failures_in_test = failures_in_test + 1
    who = 'unknown test'
    if (allocated(current_test)) who = current_test
    write (output_unit, '(a,a,a,a,a,i0,a,a)') 'Failure in ', who, ' at ', pf_file, ':', pf_line, ': ', kind
    write (output_unit, '(4x,a)') detail
    if (present(message)) write (output_unit, '(4x,a,a)') 'message: ', message
    flush (output_unit)
  end subroutine fail

  ! ---------------------------------------------------------------- conversions

  !> A numeric scalar of any supported kind as real(dp); ok = .false. for other types.
  subroutine to_real(x, r, ok)
    class(*), intent(in) :: x
    real(dp), intent(out) :: r
    logical, intent(out) :: ok
    ok = .true.
    select type (x)
    type is (real(real64))
      r = x
    type is (real(real32))
      r = real(x, dp)
    type is (integer(int32))
      r = real(x, dp)
    type is (integer(int64))
      r = real(x, dp)
    class default
      r = 0.0_dp
      ok = .false.
    end select
  end subroutine to_real

  pure logical function is_integer(x)
    class(*), intent(in) :: x
    select type (x)
    type is (integer(int32))
      is_integer = .true.
    type is (integer(int64))
      is_integer = .true.
    class default
      is_integer = .false.
    end select
  end function is_integer

  function fmt(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=40) :: buf
    write (buf, '(es24.16)') x
    s = trim(adjustl(buf))
  end function fmt

  function tol_of(tolerance) result(t)
    class(*), intent(in), optional :: tolerance
    real(dp) :: t
    logical :: ok
    t = 0.0_dp
    if (present(tolerance)) call to_real(tolerance, t, ok)
  end function tol_of

  ! ---------------------------------------------------------------- assertEqual

  !> Core of assertEqual on one pair of numbers: |e - a| <= tol (tol = 0: exact).
  logical function numbers_equal(e, a, t)
    real(dp), intent(in) :: e, a, t
    if (ieee_is_nan(e) .or. ieee_is_nan(a)) then
      numbers_equal = .false.
    else
      numbers_equal = abs(e - a) <= t
    end if
  end function numbers_equal

  subroutine equal_ss(expected, actual, tolerance, message, pf_file, pf_line)
    class(*), intent(in) :: expected, actual
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp) :: e, a, t
    logical :: ok1, ok2
    select type (expected)
    type is (character(len=*))
      select type (actual)
      type is (character(len=*))
        if (expected /= actual) call fail('assertEqual', 'expected "' // expected // '" but found "' // actual // '"', &
                                          message, pf_file, pf_line)
        return
      end select
    end select
    call to_real(expected, e, ok1)
    call to_real(actual, a, ok2)
    if (.not. (ok1 .and. ok2)) then
      call fail('assertEqual', 'unsupported argument types', message, pf_file, pf_line)
      return
    end if
    t = tol_of(tolerance)
    if (.not. numbers_equal(e, a, t)) then
      if (is_integer(expected) .and. is_integer(actual)) then
        call fail('assertEqual', 'expected ' // itoa(nint(e)) // ' but found ' // itoa(nint(a)), message, pf_file, pf_line)
      else
        call fail('assertEqual', 'expected ' // fmt(e) // ' but found ' // fmt(a) // ' (difference ' // fmt(abs(e - a)) // &
                  ' > tolerance ' // fmt(t) // ')', message, pf_file, pf_line)
      end if
    end if
  end subroutine equal_ss

  function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function itoa

  !> Compare flattened arrays element by element; report the worst entry.
  subroutine compare_arrays(kind, e, a, t, relative, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    real(dp), intent(in) :: e(:), a(:)
    real(dp), intent(in) :: t
    logical, intent(in) :: relative
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    integer :: i, worst
    real(dp) :: excess, worst_excess, bound
    if (size(e) /= size(a)) then
      call fail(kind, 'arrays differ in size: expected ' // itoa(size(e)) // ' but found ' // itoa(size(a)), &
                message, pf_file, pf_line)
      return
    end if
    worst = 0
    worst_excess = 0.0_dp
    do i = 1, size(e)
      bound = t
      if (relative) bound = t * abs(e(i))
      if (ieee_is_nan(e(i)) .or. ieee_is_nan(a(i))) then
        worst = i
        exit
      end if
      excess = abs(e(i) - a(i)) - bound
      if (excess > 0.0_dp .and. (worst == 0 .or. excess > worst_excess)) then
        worst = i
        worst_excess = excess
      end if
    end do
    if (worst > 0) then
      bound = t
      if (relative) bound = t * abs(e(worst))
      call fail(kind, 'at (flattened) index ' // itoa(worst) // ': expected ' // fmt(e(worst)) // ' but found ' // &
                fmt(a(worst)) // ' (difference ' // fmt(abs(e(worst) - a(worst))) // ' > allowed ' // fmt(bound) // ')', &
                message, pf_file, pf_line)
    end if
  end subroutine compare_arrays

  subroutine flatten(x, r, ok)
    class(*), intent(in) :: x(:)
    real(dp), allocatable, intent(out) :: r(:)
    logical, intent(out) :: ok
    integer :: i
    allocate (r(size(x)))
    ok = .true.
    do i = 1, size(x)
      call to_real(x(i), r(i), ok)
      if (.not. ok) return
    end do
  end subroutine flatten

  subroutine equal_11(expected, actual, tolerance, message, pf_file, pf_line)
    class(*), intent(in) :: expected(:), actual(:)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp), allocatable :: e(:), a(:)
    logical :: ok1, ok2
    call flatten(expected, e, ok1)
    call flatten(actual, a, ok2)
    if (.not. (ok1 .and. ok2)) then
      call fail('assertEqual', 'unsupported argument types', message, pf_file, pf_line)
      return
    end if
    call compare_arrays('assertEqual', e, a, tol_of(tolerance), .false., message, pf_file, pf_line)
  end subroutine equal_11

  subroutine equal_22(expected, actual, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: expected(:, :), actual(:, :)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (any(shape(expected) /= shape(actual))) then
      call fail('assertEqual', 'arrays differ in shape', message, pf_file, pf_line)
      return
    end if
    call compare_arrays('assertEqual', reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), &
                        tol_of(tolerance), .false., message, pf_file, pf_line)
  end subroutine equal_22

  subroutine equal_s1(expected, actual, tolerance, message, pf_file, pf_line)
    class(*), intent(in) :: expected
    class(*), intent(in) :: actual(:)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp) :: e
    real(dp), allocatable :: a(:)
    logical :: ok1, ok2
    call to_real(expected, e, ok1)
    call flatten(actual, a, ok2)
    if (.not. (ok1 .and. ok2)) then
      call fail('assertEqual', 'unsupported argument types', message, pf_file, pf_line)
      return
    end if
    call compare_arrays('assertEqual', spread(e, 1, size(a)), a, tol_of(tolerance), .false., message, pf_file, pf_line)
  end subroutine equal_s1

  subroutine equal_s2(expected, actual, tolerance, message, pf_file, pf_line)
    class(*), intent(in) :: expected
    real(dp), intent(in) :: actual(:, :)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp) :: e
    logical :: ok
    call to_real(expected, e, ok)
    call compare_arrays('assertEqual', spread(e, 1, size(actual)), reshape(actual, [size(actual)]), tol_of(tolerance), &
                        .false., message, pf_file, pf_line)
  end subroutine equal_s2

  ! ---------------------------------------------------------------- assertRelativelyEqual

  subroutine releq_ss(expected, actual, tolerance, message, pf_file, pf_line)
    class(*), intent(in) :: expected, actual
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp) :: e, a
    logical :: ok1, ok2
    call to_real(expected, e, ok1)
    call to_real(actual, a, ok2)
    if (.not. (ok1 .and. ok2)) then
      call fail('assertRelativelyEqual', 'unsupported argument types', message, pf_file, pf_line)
      return
    end if
    call releq_core([e], [a], tolerance, message, pf_file, pf_line)
  end subroutine releq_ss

  subroutine releq_core(e, a, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: e(:), a(:)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (any(e == 0.0_dp)) then
      ! pFUnit refuses a relative comparison with an expected value of zero; so does the fallback.
      call fail('assertRelativelyEqual', 'expected value 0 (use assertEqual with a tolerance)', message, pf_file, pf_line)
      return
    end if
    call compare_arrays('assertRelativelyEqual', e, a, tol_of(tolerance), .true., message, pf_file, pf_line)
  end subroutine releq_core

  subroutine releq_11(expected, actual, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: expected(:), actual(:)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (size(expected) /= size(actual)) then
      call fail('assertRelativelyEqual', 'arrays differ in size', message, pf_file, pf_line)
      return
    end if
    call releq_core(expected, actual, tolerance, message, pf_file, pf_line)
  end subroutine releq_11

  subroutine releq_22(expected, actual, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: expected(:, :), actual(:, :)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (any(shape(expected) /= shape(actual))) then
      call fail('assertRelativelyEqual', 'arrays differ in shape', message, pf_file, pf_line)
      return
    end if
    call releq_core(reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), tolerance, message, &
                    pf_file, pf_line)
  end subroutine releq_22

  subroutine releq_s1(expected, actual, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: expected
    real(dp), intent(in) :: actual(:)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call releq_core(spread(expected, 1, size(actual)), actual, tolerance, message, pf_file, pf_line)
  end subroutine releq_s1

  subroutine releq_s2(expected, actual, tolerance, message, pf_file, pf_line)
    real(dp), intent(in) :: expected
    real(dp), intent(in) :: actual(:, :)
    class(*), intent(in), optional :: tolerance
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call releq_core(spread(expected, 1, size(actual)), reshape(actual, [size(actual)]), tolerance, message, &
                    pf_file, pf_line)
  end subroutine releq_s2

  ! ---------------------------------------------------------------- logical assertions

  subroutine true_s(condition, message, pf_file, pf_line)
    logical, intent(in) :: condition
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (.not. condition) call fail('assertTrue', 'condition is false', message, pf_file, pf_line)
  end subroutine true_s

  subroutine true_1(condition, message, pf_file, pf_line)
    logical, intent(in) :: condition(:)
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (.not. all(condition)) call fail('assertTrue', 'condition false at index ' // itoa(findloc(condition, .false., 1)), &
                                        message, pf_file, pf_line)
  end subroutine true_1

  subroutine false_s(condition, message, pf_file, pf_line)
    logical, intent(in) :: condition
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (condition) call fail('assertFalse', 'condition is true', message, pf_file, pf_line)
  end subroutine false_s

  subroutine false_1(condition, message, pf_file, pf_line)
    logical, intent(in) :: condition(:)
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (any(condition)) call fail('assertFalse', 'condition true at index ' // itoa(findloc(condition, .true., 1)), &
                                  message, pf_file, pf_line)
  end subroutine false_1

  ! ---------------------------------------------------------------- ordering assertions

  !> Core of the ordering assertions on two numbers of any kind the specific procedures accept.
  subroutine ordered(kind, x, y, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    real(dp), intent(in) :: x, y
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (.not. holds(kind, x, y)) call fail(kind, 'not true for ' // fmt(x) // ' and ' // fmt(y), message, pf_file, &
                                            pf_line)
  end subroutine ordered

  !> The same on two integers (compared as integers: no rounding of large values).
  subroutine ordered_int(kind, i, j, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int64), intent(in) :: i, j
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    logical :: ok
    select case (kind)
    case ('assertLessThan')
      ok = i < j
    case ('assertLessThanOrEqual')
      ok = i <= j
    case ('assertGreaterThan')
      ok = i > j
    case default
      ok = i >= j
    end select
    if (.not. ok) call fail(kind, 'not true for ' // itoa8(i) // ' and ' // itoa8(j), message, pf_file, pf_line)
  end subroutine ordered_int

  pure logical function holds(kind, x, y)
    character(len=*), intent(in) :: kind
    real(dp), intent(in) :: x, y
    select case (kind)
    case ('assertLessThan')
      holds = x < y
    case ('assertLessThanOrEqual')
      holds = x <= y
    case ('assertGreaterThan')
      holds = x > y
    case default
      holds = x >= y
    end select
  end function holds

  function itoa8(i) result(s)
    integer(int64), intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function itoa8

  ! The specific procedures of pf_ordering: the pairs of kinds pFUnit 4 accepts in an ordering assertion (its
  ! Assert_Integer "useful" and Assert_Real "no_tol" lists): both integers of one kind or a default integer before a
  ! 64-bit one; an integer or a real before a real of the same or a higher kind. A first argument of a higher kind
  ! than the second (a real64 before an integer, a real64 before a real32) has no procedure, as in pFUnit: the suite
  ! does not compile ("no specific subroutine for the generic 'pf_ordering'").

  subroutine ord_i4i4(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int32), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered_int(kind, int(a, int64), int(b, int64), message, pf_file, pf_line)
  end subroutine ord_i4i4

  subroutine ord_i8i8(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int64), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered_int(kind, a, b, message, pf_file, pf_line)
  end subroutine ord_i8i8

  subroutine ord_i4i8(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int32), intent(in) :: a
    integer(int64), intent(in) :: b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered_int(kind, int(a, int64), b, message, pf_file, pf_line)
  end subroutine ord_i4i8

  subroutine ord_i4r4(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int32), intent(in) :: a
    real(real32), intent(in) :: b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered(kind, real(a, dp), real(b, dp), message, pf_file, pf_line)
  end subroutine ord_i4r4

  subroutine ord_i4r8(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    integer(int32), intent(in) :: a
    real(real64), intent(in) :: b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered(kind, real(a, dp), b, message, pf_file, pf_line)
  end subroutine ord_i4r8

  subroutine ord_r4r4(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    real(real32), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered(kind, real(a, dp), real(b, dp), message, pf_file, pf_line)
  end subroutine ord_r4r4

  subroutine ord_r4r8(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    real(real32), intent(in) :: a
    real(real64), intent(in) :: b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered(kind, real(a, dp), b, message, pf_file, pf_line)
  end subroutine ord_r4r8

  subroutine ord_r8r8(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    real(real64), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered(kind, a, b, message, pf_file, pf_line)
  end subroutine ord_r8r8

  ! ---------------------------------------------------------------- assertIsFinite

  subroutine finite_s(x, message, pf_file, pf_line)
    real(dp), intent(in) :: x
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (.not. ieee_is_finite(x)) call fail('assertIsFinite', 'value is not finite', message, pf_file, pf_line)
  end subroutine finite_s

end module funit
