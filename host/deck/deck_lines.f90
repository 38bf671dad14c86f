!> Low-level reading of Abaqus-style input: files (with *INCLUDE, INPUT=) to logical records that keep their
!> file and line, keyword-line parameters, comma-separated data fields and strict number parsing.
module deck_lines
  use ldfcz_kinds, only: dp
  use ldfcz_text, only: upper_case
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: iostat_eor
  implicit none
  private
  public :: deck_record_t, deck_source_t, deck_param_t, file_name_t
  public :: deck_load, deck_split_fields, deck_keyword_parse, deck_upper, deck_parse_real, deck_parse_int
  public :: deck_where, deck_param_value, deck_has_param, deck_normalize

  integer, parameter :: max_include_depth = 10  !< guard against recursive includes
  integer, parameter :: max_line_len = 1000000  !< longest line read (guards against endless files such as /dev/zero)
  integer, parameter :: ios_too_long = 987654   !< read_line status: line longer than max_line_len

  !> One logical record: a keyword line or a data line (continuations joined).
  type :: deck_record_t
    character(len=:), allocatable :: text  !< record text, comments and trailing blanks removed
    integer :: file_id = 0                 !< index into deck_source_t%files
    integer :: line = 0                    !< line number where the record starts
    logical :: keyword = .false.           !< starts with a single '*'
  end type deck_record_t

  type :: file_name_t
    character(len=:), allocatable :: name
  end type file_name_t

  !> All records of a deck in reading order.
  type :: deck_source_t
    type(deck_record_t), allocatable :: rec(:)
    integer :: nrec = 0
    type(file_name_t), allocatable :: files(:)
    integer :: nfile = 0
  end type deck_source_t

  !> One NAME[=VALUE] parameter of a keyword line.
  type :: deck_param_t
    character(len=:), allocatable :: name   !< upper case, blanks normalised
    character(len=:), allocatable :: value  !< as written (trimmed); '' when absent
  end type deck_param_t

contains

  !> Upper-case copy of a string.
  pure function deck_upper(s) result(u)
    character(len=*), intent(in) :: s  !< input
    character(len=len(s)) :: u
    u = upper_case(s)
  end function deck_upper

  !> Upper case, trimmed, inner runs of blanks collapsed to one ("SOLID   section" -> "SOLID SECTION").
  pure recursive function deck_normalize(s) result(u)
    character(len=*), intent(in) :: s  !< input
    character(len=:), allocatable :: u
    character(len=len(s)) :: t
    integer :: i
    logical :: blank
    t = deck_upper(adjustl(s))
    u = ''
    blank = .false.
    do i = 1, len_trim(t)
      if (t(i:i) == ' ' .or. t(i:i) == achar(9)) then
        blank = .true.
      else
        if (blank .and. len(u) > 0) u = u//' '
        u = u//t(i:i)
        blank = .false.
      end if
    end do
    ! a name in double quotes (which may hold blanks): the quotes are not part of it
    if (len(u) >= 2) then
      if (u(1:1) == '"' .and. u(len(u):len(u)) == '"') u = deck_normalize(u(2:len(u) - 1))
    end if
  end function deck_normalize

  !> "file:line" of a record, for messages.
  function deck_where(src, irec) result(w)
    type(deck_source_t), intent(in) :: src  !< the deck
    integer, intent(in) :: irec             !< record index
    character(len=:), allocatable :: w
    character(len=16) :: num
    if (irec < 1 .or. irec > src%nrec) then
      ! no such record (e.g. an empty deck): the top-level file, line 1
      w = '?:1'
      if (src%nfile >= 1) w = src%files(1)%name//':1'
      return
    end if
    write (num, '(i0)') src%rec(irec)%line
    w = src%files(src%rec(irec)%file_id)%name//':'//trim(num)
  end function deck_where

  !> Read a deck file (and its *INCLUDE files) into records.
  subroutine deck_load(path, src, stat, errmsg, warnings)
    character(len=*), intent(in) :: path          !< top-level file
    type(deck_source_t), intent(out) :: src       !< records
    integer, intent(out) :: stat                  !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message naming file and line
    !> warnings of the reading of the files ('file:line: *KEYWORD: what'), for the reader to report with its own
    type(file_name_t), allocatable, intent(out) :: warnings(:)
    allocate (src%rec(256), src%files(4), warnings(0))
    stat = 0
    errmsg = ''
    call load_file(path, src, 0, stat, errmsg, warnings)
  end subroutine deck_load

  recursive subroutine load_file(path, src, depth, stat, errmsg, warnings)
    character(len=*), intent(in) :: path
    type(deck_source_t), intent(inout) :: src
    integer, intent(in) :: depth
    integer, intent(out) :: stat
    character(len=:), allocatable, intent(out) :: errmsg
    type(file_name_t), allocatable, intent(inout) :: warnings(:)
    integer :: unit, ios, iline, fid, k, irec_cont
    character(len=:), allocatable :: line, text, incname, dir
    logical :: exists, cont_keyword
    type(deck_param_t), allocatable :: params(:)
    character(len=:), allocatable :: kw
    character(len=16) :: num

    stat = 0
    errmsg = ''
    inquire (file=path, exist=exists)
    if (.not. exists) then
      stat = 2
      errmsg = path//': file not found'
      return
    end if
    inquire (file=path//'/.', exist=exists)
    if (exists) then
      stat = 2
      errmsg = path//': is a directory, not a deck file'
      return
    end if
    open (newunit=unit, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) then
      stat = 2
      errmsg = path//': cannot open'
      return
    end if
    if (src%nfile == size(src%files)) call grow_files(src)
    src%nfile = src%nfile + 1
    fid = src%nfile
    src%files(fid)%name = path
    k = index(path, '/', back=.true.)
    dir = path(1:k)

    iline = 0
    cont_keyword = .false.
    irec_cont = 0
    do
      call read_line(unit, line, ios)
      if (is_iostat_end(ios)) exit
      if (ios /= 0) then
        ! not an end of file: a line without end, a device or an unreadable file
        write (num, '(i0)') iline + 1
        stat = 2
        if (ios == ios_too_long) then
          errmsg = path//':'//trim(num)//': line longer than 1000000 characters (not a deck file?)'
        else
          errmsg = path//':'//trim(num)//': cannot read the file (an unreadable file?)'
        end if
        exit
      end if
      iline = iline + 1
      ! strip CR (files from Windows) and trailing blanks
      k = index(line, achar(13))
      if (k > 0) line = line(1:k - 1)
      ! tabs separate fields like blanks
      do k = 1, len(line)
        if (line(k:k) == achar(9)) line(k:k) = ' '
      end do
      ! leading blanks are allowed before keywords, comments and data
      text = trim(adjustl(line))
      if (len(adjustl(text)) >= 2) then
        ! a '**LDFCZ' comment line is a declaration for this host (Abaqus reads it as a comment): kept as the
        ! keyword line '*LDFCZ ...'; every other '**' line is a comment
        if (len(text) >= 7) then
          if (deck_upper(text(1:7)) == '**LDFCZ') text = text(2:)
        end if
        if (adjustl(text) == '**' .or. text(1:min(2, len(text))) == '**') cycle
      end if
      if (len_trim(text) == 0) then
        ! a blank line ends a continuation; Abaqus ignores blank lines in data
        cycle
      end if
      if (cont_keyword) then
        ! only keyword lines are continued here; a data line that ends with a comma is complete unless its
        ! keyword's reader needs more fields (an *ELEMENT with more nodes than one line holds)
        src%rec(irec_cont)%text = src%rec(irec_cont)%text//' '//trim(adjustl(text))
        cont_keyword = ends_with_comma(text)
        if (.not. cont_keyword) then
          call handle_include(irec_cont)
          if (stat /= 0) exit
        end if
        cycle
      end if
      if (src%nrec == size(src%rec)) call grow_records(src)
      src%nrec = src%nrec + 1
      src%rec(src%nrec)%text = trim(adjustl(text))
      src%rec(src%nrec)%file_id = fid
      src%rec(src%nrec)%line = iline
      src%rec(src%nrec)%keyword = (text(1:1) == '*')
      irec_cont = src%nrec
      if (src%rec(src%nrec)%keyword) then
        cont_keyword = ends_with_comma(text)
        if (.not. cont_keyword) then
          call handle_include(src%nrec)
          if (stat /= 0) exit
        end if
      end if
    end do
    close (unit)
    if (stat == 0 .and. cont_keyword) then
      write (num, '(i0)') src%rec(irec_cont)%line
      stat = 2
      errmsg = path//':'//trim(num)//': keyword line continued with a comma but the file ends'
    end if

  contains

    !> Keep a warning of the reading for the reader to report.
    subroutine add_warning(text)
      character(len=*), intent(in) :: text
      type(file_name_t), allocatable :: tmp(:)
      integer :: nw
      nw = size(warnings)
      allocate (tmp(nw + 1))
      tmp(1:nw) = warnings
      tmp(nw + 1)%name = text
      call move_alloc(tmp, warnings)
    end subroutine add_warning

    !> If record ir is *INCLUDE, replace it by the records of the included file.
    recursive subroutine handle_include(ir)
      integer, intent(in) :: ir
      character(len=:), allocatable :: emsg
      integer :: st
      call deck_keyword_parse(src%rec(ir)%text, kw, params)
      if (kw /= '*INCLUDE') return
      write (num, '(i0)') src%rec(ir)%line
      if (deck_has_param(params, 'INPUT')) then
        incname = deck_param_value(params, 'INPUT')
      else if (deck_has_param(params, 'FILE')) then
        ! FILE= for INPUT=: not in Abaqus' keyword reference, but Abaqus/Standard R2018x read the file so named in a
        ! published run (its .dat lists the included keywords; docs/host.md, *INCLUDE); warned
        incname = deck_param_value(params, 'FILE')
        call add_warning(path//':'//trim(num)//': *INCLUDE: FILE= read as INPUT= (the documented parameter; '// &
          'Abaqus/Standard accepts FILE= too)')
      else
        stat = 2
        errmsg = path//':'//trim(num)//': *INCLUDE: parameter INPUT= is required'
        return
      end if
      if (len(incname) > 1) then
        if (incname(1:1) == '"' .and. incname(len(incname):len(incname)) == '"') incname = incname(2:len(incname) - 1)
      end if
      if (depth >= max_include_depth) then
        stat = 2
        errmsg = path//':'//trim(num)//': *INCLUDE: nesting deeper than 10 files (recursive include?)'
        return
      end if
      ! the record is consumed: the included records take its place
      src%nrec = src%nrec - 1
      if (incname(1:1) /= '/') then
        inquire (file=dir//incname, exist=exists)
        if (exists) incname = dir//incname
      end if
      inquire (file=incname, exist=exists)
      if (.not. exists) then
        stat = 2
        errmsg = path//':'//trim(num)//': *INCLUDE: file not found: '//incname
        return
      end if
      inquire (file=incname//'/.', exist=exists)
      if (exists) then
        stat = 2
        errmsg = path//':'//trim(num)//': *INCLUDE: is a directory, not a file: '//incname
        return
      end if
      call load_file(incname, src, depth + 1, st, emsg, warnings)
      if (st /= 0) then
        stat = st
        errmsg = emsg
      end if
    end subroutine handle_include

  end subroutine load_file

  pure logical function ends_with_comma(text)
    character(len=*), intent(in) :: text
    integer :: n
    n = len_trim(text)
    ends_with_comma = .false.
    if (n > 0) ends_with_comma = (text(n:n) == ',')
  end function ends_with_comma

  !> Read one line of any length.
  subroutine read_line(unit, line, ios)
    integer, intent(in) :: unit
    character(len=:), allocatable, intent(out) :: line
    integer, intent(out) :: ios
    character(len=512) :: buf
    integer :: nread
    line = ''
    do
      read (unit, '(a)', advance='no', iostat=ios, size=nread) buf
      line = line//buf(1:nread)
      if (ios /= 0) exit
      if (len(line) > max_line_len) then
        ios = ios_too_long   ! e.g. *INCLUDE, INPUT=/dev/zero: never ends
        return
      end if
    end do
    if (ios == iostat_eor) ios = 0
  end subroutine read_line

  subroutine grow_records(src)
    type(deck_source_t), intent(inout) :: src
    type(deck_record_t), allocatable :: tmp(:)
    allocate (tmp(2 * size(src%rec)))
    tmp(1:src%nrec) = src%rec(1:src%nrec)
    call move_alloc(tmp, src%rec)
  end subroutine grow_records

  subroutine grow_files(src)
    type(deck_source_t), intent(inout) :: src
    type(file_name_t), allocatable :: tmp(:)
    allocate (tmp(2 * size(src%files)))
    tmp(1:src%nfile) = src%files(1:src%nfile)
    call move_alloc(tmp, src%files)
  end subroutine grow_files

  !> Split a record into comma-separated fields (trimmed). A trailing comma gives no empty last field.
  pure subroutine deck_split_fields(text, fields, nfield)
    character(len=*), intent(in) :: text  !< data or keyword text
    character(len=*), allocatable, intent(out) :: fields(:) !< fields (deferred to caller's length)
    integer, intent(out) :: nfield        !< number of fields
    integer :: i, start, n
    n = 1
    do i = 1, len_trim(text)
      if (text(i:i) == ',') n = n + 1
    end do
    allocate (fields(n))
    nfield = 0
    start = 1
    do i = 1, len_trim(text) + 1
      if (i > len_trim(text)) then
        nfield = nfield + 1
        fields(nfield) = adjustl(text(start:len_trim(text)))
      else if (text(i:i) == ',') then
        nfield = nfield + 1
        fields(nfield) = adjustl(text(start:i - 1))
        start = i + 1
      end if
    end do
    ! drop one empty trailing field after a final comma
    if (nfield > 1) then
      if (len_trim(fields(nfield)) == 0 .and. text(len_trim(text):len_trim(text)) == ',') nfield = nfield - 1
    end if
  end subroutine deck_split_fields

  !> Split a keyword line into its keyword (upper case, normalised, with '*') and parameters.
  pure subroutine deck_keyword_parse(text, keyword, params)
    character(len=*), intent(in) :: text                  !< keyword line
    character(len=:), allocatable, intent(out) :: keyword !< e.g. '*SOLID SECTION'
    type(deck_param_t), allocatable, intent(out) :: params(:) !< parameters in order
    character(len=len(text)), allocatable :: fields(:)
    integer :: nfield, i, k, np
    call deck_split_fields(text, fields, nfield)
    keyword = deck_normalize(fields(1))
    np = 0
    do i = 2, nfield
      if (len_trim(fields(i)) > 0) np = np + 1
    end do
    allocate (params(np))
    np = 0
    do i = 2, nfield
      if (len_trim(fields(i)) == 0) cycle
      np = np + 1
      k = index(fields(i), '=')
      if (k > 0) then
        params(np)%name = deck_normalize(fields(i)(1:k - 1))
        params(np)%value = trim(adjustl(fields(i)(k + 1:)))
      else
        params(np)%name = deck_normalize(fields(i))
        params(np)%value = ''
      end if
    end do
  end subroutine deck_keyword_parse

  !> True when the parameter is present.
  pure logical function deck_has_param(params, name)
    type(deck_param_t), intent(in) :: params(:)  !< parameters
    character(len=*), intent(in) :: name          !< upper-case name
    integer :: i
    deck_has_param = .false.
    do i = 1, size(params)
      if (params(i)%name == name) deck_has_param = .true.
    end do
  end function deck_has_param

  !> Value of a parameter ('' when absent or without value).
  pure function deck_param_value(params, name) result(v)
    type(deck_param_t), intent(in) :: params(:)  !< parameters
    character(len=*), intent(in) :: name          !< upper-case name
    character(len=:), allocatable :: v
    integer :: i
    v = ''
    do i = 1, size(params)
      if (params(i)%name == name) v = params(i)%value
    end do
  end function deck_param_value

  !> Strict real parsing: digits, sign, point, exponent only; NaN and Inf rejected. ok = .false. on failure.
  subroutine deck_parse_real(field, value, ok, why)
    character(len=*), intent(in) :: field        !< text
    real(dp), intent(out) :: value               !< parsed value
    logical, intent(out) :: ok                   !< success
    character(len=:), allocatable, intent(out) :: why !< reason on failure
    integer :: i, ios
    character(len=:), allocatable :: t
    value = 0.0_dp
    ok = .false.
    t = trim(adjustl(field))
    if (len(t) == 0) then
      why = 'empty number field'
      return
    end if
    if (index(deck_upper(t), 'NAN') > 0 .or. index(deck_upper(t), 'INF') > 0) then
      why = 'not a finite number: "'//t//'"'
      return
    end if
    do i = 1, len(t)
      if (index('0123456789+-.eEdD', t(i:i)) == 0) then
        why = 'not a number: "'//t//'"'
        return
      end if
    end do
    if (.not. in_range(t)) then
      why = 'number out of the double precision range: "'//t//'"'
      return
    end if
    read (t, *, iostat=ios) value
    if (ios /= 0) then
      why = 'not a number: "'//t//'"'
      return
    end if
    if (.not. ieee_is_finite(value)) then
      why = 'not a finite number: "'//t//'"'
      return
    end if
    ok = .true.
    why = ''
  end subroutine deck_parse_real

  !> False when the decimal exponent of a well-formed number text would overflow (checked before reading, so that
  !> a floating-point trap cannot fire inside READ).
  pure logical function in_range(t)
    character(len=*), intent(in) :: t  !< number text (digits, sign, point, exponent letter)
    integer :: k, e, i, lead, ios
    character(len=len(t)) :: m
    in_range = .true.
    k = scan(t, 'eEdD')
    m = t
    e = 0
    if (k > 0) then
      if (k == len(t)) return
      if (verify(t(k + 1:), '+-0123456789') /= 0) return
      if (len_trim(t(k + 1:)) > 6) then
        in_range = index(t(k + 1:), '-') > 0
        return
      end if
      read (t(k + 1:), *, iostat=ios) e
      if (ios /= 0) return
      m = t(1:k - 1)
    end if
    ! leading digits of the mantissa before the point, ignoring leading zeros
    lead = 0
    do i = 1, len_trim(m)
      if (m(i:i) == '.') exit
      if (index('123456789', m(i:i)) > 0 .or. (lead > 0 .and. m(i:i) == '0')) lead = lead + 1
    end do
    in_range = e + lead <= 308
  end function in_range

  !> Strict integer parsing.
  subroutine deck_parse_int(field, value, ok, why)
    character(len=*), intent(in) :: field        !< text
    integer, intent(out) :: value                !< parsed value
    logical, intent(out) :: ok                   !< success
    character(len=:), allocatable, intent(out) :: why !< reason on failure
    integer :: i, ios
    character(len=:), allocatable :: t
    value = 0
    ok = .false.
    t = trim(adjustl(field))
    if (len(t) == 0) then
      why = 'empty integer field'
      return
    end if
    do i = 1, len(t)
      if (index('0123456789+-', t(i:i)) == 0) then
        why = 'not an integer: "'//t//'"'
        return
      end if
    end do
    read (t, *, iostat=ios) value
    if (ios /= 0) then
      why = 'not an integer: "'//t//'"'
      return
    end if
    ok = .true.
    why = ''
  end subroutine deck_parse_int

end module deck_lines
