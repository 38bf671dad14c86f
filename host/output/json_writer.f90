!> A small JSON writer (RFC 8259) for the files a run leaves for programs to read (JOB.summary.json): a document
!> is built in memory, member by member, and then written whole to a temporary file that is renamed over the target,
!> so that a reader finds the complete previous file, the complete new one, or none, never a part.
!> Strings are escaped (quote, backslash, control characters); bytes that are not well-formed UTF-8 become U+FFFD.
!> Reals are written with 17 significant digits (they read back to the same double); NaN and infinities as null.
module json_writer
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use ldfcz_kinds, only: dp, i8
  implicit none
  private
  public :: json_t, json_begin, json_end, json_open, json_close, json_put, json_put_null, json_put_real_or_null
  public :: json_text, json_escape, json_real_text, json_write_file, json_remove_file

  !> A document being written: its text and, per nesting level, the bracket that closes it and whether a member was
  !> written there yet.
  type :: json_t
    character(len=:), allocatable :: text        !< the document so far: text(1:n), the rest room to grow
    integer :: n = 0                             !< characters of text used
    integer :: depth = 0                         !< open objects and arrays
    character(len=1), allocatable :: closing(:)  !< '}' or ']' per level (1:depth)
    logical, allocatable :: empty(:)             !< no member written yet at that level (1:depth)
  end type json_t

  !> A member (inside an object: with its key; inside an array: key '') of any scalar kind, or an inline array.
  interface json_put
    module procedure put_int, put_int8, put_real, put_logical, put_string, put_int_array, put_real_array
  end interface json_put

  interface
    !> C library rename(2): atomic replacement of to by from on one file system.
    function c_rename(from, to) bind(c, name='rename') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: from(*), to(*)
      integer(c_int) :: r
    end function c_rename
    !> C library remove(3).
    function c_remove(path) bind(c, name='remove') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: r
    end function c_remove
  end interface

contains

  !> Start a document whose top level is an object.
  pure subroutine json_begin(w)
    type(json_t), intent(out) :: w  !< the document
    allocate (character(len=4096) :: w%text)
    w%n = 0
    call append(w, '{')
    w%depth = 1
    w%closing = ['}']
    w%empty = [.true.]
  end subroutine json_begin

  !> Close the top-level object (and any level left open).
  pure subroutine json_end(w)
    type(json_t), intent(inout) :: w  !< the document
    do while (w%depth > 0)
      call json_close(w)
    end do
    call append(w, new_line('a'))
  end subroutine json_end

  !> Open an object (kind '{') or an array (kind '[') as a member named key ('' inside an array).
  pure subroutine json_open(w, key, kind)
    type(json_t), intent(inout) :: w      !< the document
    character(len=*), intent(in) :: key   !< member name ('' for an element of an array)
    character(len=1), intent(in) :: kind  !< '{' or '['
    call member(w, key)
    call append(w, kind)
    w%depth = w%depth + 1
    w%closing = [w%closing(1:w%depth - 1), merge(']', '}', kind == '[')]
    w%empty = [w%empty(1:w%depth - 1), .true.]
  end subroutine json_open

  !> Close the innermost open object or array.
  pure subroutine json_close(w)
    type(json_t), intent(inout) :: w  !< the document
    if (w%depth < 1) return
    if (.not. w%empty(w%depth)) call append(w, new_line('a')//repeat('  ', w%depth - 1))
    call append(w, w%closing(w%depth))
    w%depth = w%depth - 1
  end subroutine json_close

  pure subroutine put_int(w, key, value)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    integer, intent(in) :: value         !< the value
    call put_int8(w, key, int(value, i8))
  end subroutine put_int

  pure subroutine put_int8(w, key, value)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    integer(i8), intent(in) :: value     !< the value
    character(len=24) :: buf
    write (buf, '(i0)') value
    call member(w, key)
    call append(w, trim(buf))
  end subroutine put_int8

  pure subroutine put_real(w, key, value)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    real(dp), intent(in) :: value        !< the value (null when not finite)
    call member(w, key)
    call append(w, json_real_text(value))
  end subroutine put_real

  pure subroutine put_logical(w, key, value)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    logical, intent(in) :: value         !< the value
    call member(w, key)
    if (value) then
      call append(w, 'true')
    else
      call append(w, 'false')
    end if
  end subroutine put_logical

  pure subroutine put_string(w, key, value)
    type(json_t), intent(inout) :: w       !< the document
    character(len=*), intent(in) :: key    !< member name ('' in an array)
    character(len=*), intent(in) :: value  !< the value (any bytes: escaped)
    call member(w, key)
    call append(w, '"'//json_escape(value)//'"')
  end subroutine put_string

  !> An array of integers on one line.
  pure subroutine put_int_array(w, key, values)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    integer, intent(in) :: values(:)     !< the values
    character(len=24) :: buf
    integer :: k
    call member(w, key)
    call append(w, '[')
    do k = 1, size(values)
      write (buf, '(i0)') values(k)
      call append(w, trim(buf))
      if (k < size(values)) call append(w, ', ')
    end do
    call append(w, ']')
  end subroutine put_int_array

  !> An array of reals on one line (null for a value that is not finite).
  pure subroutine put_real_array(w, key, values)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    real(dp), intent(in) :: values(:)    !< the values
    integer :: k
    call member(w, key)
    call append(w, '[')
    do k = 1, size(values)
      call append(w, json_real_text(values(k)))
      if (k < size(values)) call append(w, ', ')
    end do
    call append(w, ']')
  end subroutine put_real_array

  !> A null member.
  pure subroutine json_put_null(w, key)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    call member(w, key)
    call append(w, 'null')
  end subroutine json_put_null

  !> A real member that is null unless known (a measure the run did not reach).
  pure subroutine json_put_real_or_null(w, key, value, known)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    real(dp), intent(in) :: value        !< the value
    logical, intent(in) :: known         !< false: null
    if (known) then
      call put_real(w, key, value)
    else
      call json_put_null(w, key)
    end if
  end subroutine json_put_real_or_null

  !> The document's text so far.
  pure function json_text(w) result(s)
    type(json_t), intent(in) :: w  !< the document
    character(len=:), allocatable :: s
    s = w%text(1:w%n)
  end function json_text

  !> Append s to the document (the room doubled when it is full).
  pure subroutine append(w, s)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: s    !< the text
    character(len=:), allocatable :: grown
    if (w%n + len(s) > len(w%text)) then
      allocate (character(len=max(2 * len(w%text), w%n + len(s))) :: grown)
      grown(1:w%n) = w%text(1:w%n)
      call move_alloc(grown, w%text)
    end if
    w%text(w%n + 1:w%n + len(s)) = s
    w%n = w%n + len(s)
  end subroutine append

  !> The separator, line break, indentation and key of the next member of the innermost level.
  pure subroutine member(w, key)
    type(json_t), intent(inout) :: w     !< the document
    character(len=*), intent(in) :: key  !< member name ('' in an array)
    if (.not. w%empty(w%depth)) call append(w, ',')
    w%empty(w%depth) = .false.
    call append(w, new_line('a')//repeat('  ', w%depth))
    if (len(key) > 0) call append(w, '"'//json_escape(key)//'": ')
  end subroutine member

  !> A real as a JSON number: 17 significant digits (round trip of a double), null when NaN or infinite.
  pure function json_real_text(x) result(s)
    real(dp), intent(in) :: x  !< the value
    character(len=:), allocatable :: s
    character(len=32) :: buf
    if (.not. ieee_is_finite(x)) then
      s = 'null'
      return
    end if
    write (buf, '(es24.16e3)') x
    s = trim(adjustl(buf))
  end function json_real_text

  !> The JSON form of a string's content (without the quotes): '"' and '\' escaped, control characters as \n, \t,
  !> ... or \u00XX, well-formed UTF-8 kept as it is, any other byte above 127 as \ufffd (the replacement character).
  pure function json_escape(s) result(e)
    character(len=*), intent(in) :: s  !< the bytes
    character(len=:), allocatable :: e
    character(len=*), parameter :: hex = '0123456789abcdef'
    integer :: k, c, n
    e = ''
    k = 1
    do while (k <= len(s))
      c = iand(ichar(s(k:k)), 255)
      select case (c)
      case (34)
        e = e//'\"'
      case (92)
        e = e//'\\'
      case (8)
        e = e//'\b'
      case (9)
        e = e//'\t'
      case (10)
        e = e//'\n'
      case (12)
        e = e//'\f'
      case (13)
        e = e//'\r'
      case (0:7, 11, 14:31)
        e = e//'\u00'//hex(c / 16 + 1:c / 16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
      case (32:33, 35:91, 93:127)
        e = e//s(k:k)
      case default
        n = utf8_length(s(k:))
        if (n == 0) then
          e = e//'\ufffd'
          n = 1
        else
          e = e//s(k:k + n - 1)
        end if
        k = k + n
        cycle
      end select
      k = k + 1
    end do
  end function json_escape

  !> Bytes of the well-formed UTF-8 sequence that starts s (2 to 4), 0 when it is not one (RFC 3629: no overlong
  !> forms, no surrogates, nothing above U+10FFFF).
  pure integer function utf8_length(s) result(n)
    character(len=*), intent(in) :: s  !< bytes from a lead byte above 127
    integer :: b(4), k, lo, hi
    n = 0
    b = 0
    do k = 1, min(4, len(s))
      b(k) = iand(ichar(s(k:k)), 255)
    end do
    lo = 128
    hi = 191
    select case (b(1))
    case (194:223)
      n = 2
    case (224)
      n = 3
      lo = 160
    case (225:236, 238:239)
      n = 3
    case (237)
      n = 3
      hi = 159
    case (240)
      n = 4
      lo = 144
    case (241:243)
      n = 4
    case (244)
      n = 4
      hi = 143
    case default
      return
    end select
    if (len(s) < n .or. b(2) < lo .or. b(2) > hi) then
      n = 0
      return
    end if
    do k = 3, n
      if (b(k) < 128 .or. b(k) > 191) then
        n = 0
        return
      end if
    end do
  end function utf8_length

  !> Write the document to path: to path.tmp first, then renamed over path (a reader never sees a partial file).
  subroutine json_write_file(w, path, stat, errmsg)
    type(json_t), intent(in) :: w                         !< the complete document (json_end done)
    character(len=*), intent(in) :: path                  !< the file
    integer, intent(out) :: stat                          !< 0 written, else not (path left as it was)
    character(len=:), allocatable, intent(out) :: errmsg  !< why not
    integer :: u
    character(len=256) :: iom
    errmsg = ''
    open (newunit=u, file=path//'.tmp', access='stream', form='unformatted', status='replace', action='write', &
      iostat=stat, iomsg=iom)
    if (stat == 0) write (u, iostat=stat, iomsg=iom) w%text(1:w%n)
    if (stat == 0) then
      close (u, iostat=stat, iomsg=iom)
    else
      close (u, status='delete')
    end if
    if (stat /= 0) then
      errmsg = path//'.tmp: '//trim(iom)
      return
    end if
    if (c_rename(path//'.tmp'//c_null_char, path//c_null_char) /= 0) then
      stat = 1
      errmsg = 'cannot rename '//path//'.tmp to '//path
    end if
  end subroutine json_write_file

  !> Remove path if it exists (a file of an earlier run that this run will write again).
  subroutine json_remove_file(path)
    character(len=*), intent(in) :: path  !< the file
    integer(c_int) :: rc
    logical :: there
    inquire (file=path, exist=there)
    if (there) rc = c_remove(path//c_null_char)
  end subroutine json_remove_file

end module json_writer
