!> Fallback for the part of pFUnit's `funit` module that ldfcz's suites use (see README.md in this folder).
!> Each assertion records a failure with the .pf file, line, expected and actual values; the generated driver
!> runs every test and ends with "N passed, N failed" and a non-zero exit status when any test failed.
module funit
  use, intrinsic :: iso_fortran_env, only: real32, real64, int32, int64, output_unit
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
  implicit none
  private
  public :: assertEqual, assertRelativelyEqual, assertTrue, assertFalse
  public :: assertLessThan, assertLessThanOrEqual, assertGreaterThan, assertGreaterThanOrEqual, assertIsFinite
  public :: anyExceptions, pf_begin_test, pf_end_test, pf_summary

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

  character(len=:), allocatable :: current_test  !< name of the running test
  integer :: failures_in_test = 0                 !< failed assertions in the running test
  integer :: n_passed = 0                         !< tests that passed
  integer :: n_failed = 0                         !< tests that failed

contains

  ! ---------------------------------------------------------------- runner support

  !> True when the running test has a failed assertion (pFUnit's anyExceptions()).
  logical function anyExceptions()
    anyExceptions = failures_in_test > 0
  end function anyExceptions

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

  subroutine pf_summary()
    write (output_unit, '(i0,a,i0,a)') n_passed, ' passed, ', n_failed, ' failed'
    flush (output_unit)
    if (n_failed > 0) error stop 1
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

  subroutine ordered(kind, a, b, message, pf_file, pf_line)
    character(len=*), intent(in) :: kind
    class(*), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    real(dp) :: x, y
    logical :: ok1, ok2, holds
    call to_real(a, x, ok1)
    call to_real(b, y, ok2)
    if (.not. (ok1 .and. ok2)) then
      call fail(kind, 'unsupported argument types', message, pf_file, pf_line)
      return
    end if
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
    if (.not. holds) call fail(kind, 'not true for ' // fmt(x) // ' and ' // fmt(y), message, pf_file, pf_line)
  end subroutine ordered

  subroutine assertLessThan(a, b, message, pf_file, pf_line)
    class(*), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered('assertLessThan', a, b, message, pf_file, pf_line)
  end subroutine assertLessThan

  subroutine assertLessThanOrEqual(a, b, message, pf_file, pf_line)
    class(*), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered('assertLessThanOrEqual', a, b, message, pf_file, pf_line)
  end subroutine assertLessThanOrEqual

  subroutine assertGreaterThan(a, b, message, pf_file, pf_line)
    class(*), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered('assertGreaterThan', a, b, message, pf_file, pf_line)
  end subroutine assertGreaterThan

  subroutine assertGreaterThanOrEqual(a, b, message, pf_file, pf_line)
    class(*), intent(in) :: a, b
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    call ordered('assertGreaterThanOrEqual', a, b, message, pf_file, pf_line)
  end subroutine assertGreaterThanOrEqual

  ! ---------------------------------------------------------------- assertIsFinite

  subroutine finite_s(x, message, pf_file, pf_line)
    real(dp), intent(in) :: x
    character(len=*), intent(in), optional :: message
    character(len=*), intent(in) :: pf_file
    integer, intent(in) :: pf_line
    if (.not. ieee_is_finite(x)) call fail('assertIsFinite', 'value is not finite', message, pf_file, pf_line)
  end subroutine finite_s

end module funit
