!> *PARAMETER: named values (name = expression, one per data line) and their substitution for <name> in every
!> later keyword and data line, before the keyword readers see the deck (the Abaqus parametric input). Expressions
!> take numbers, earlier parameters, + - * / ** and parentheses; an integer result stays an integer when every
!> operand is one and no '/' is used (docs/host.md). A value in quotes is text, substituted as written.
module deck_parameters
  use ldfcz_kinds, only: dp
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use deck_lines, only: deck_source_t, deck_keyword_parse, deck_param_t, deck_where, deck_parse_real
  implicit none
  private
  public :: apply_parameters

  integer, parameter :: max_param = 512  !< parameters in one deck

  !> One named value.
  type :: param_value_t
    character(len=:), allocatable :: name  !< as written (names are case sensitive, as in Abaqus)
    character(len=:), allocatable :: text  !< value substituted for <name>
    real(dp) :: v = 0.0_dp                 !< numeric value (expressions)
    logical :: is_int = .false.            !< an integer value
    logical :: is_text = .false.           !< a quoted text value
  end type param_value_t

  !> Expression scanner state.
  type :: scan_t
    character(len=:), allocatable :: s    !< the expression
    integer :: p = 1                      !< next character
    character(len=:), allocatable :: err  !< first error ('' when none)
  end type scan_t

contains

  !> Define the *PARAMETER values in deck order and substitute <name> in the records after each definition.
  !> The *PARAMETER blocks stay in the deck (the reader skips them). stat = 2 and errmsg "file:line: *KW: ..."
  !> on an error.
  subroutine apply_parameters(src, stat, errmsg)
    type(deck_source_t), intent(inout) :: src           !< the records
    integer, intent(out) :: stat                        !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    type(param_value_t), allocatable :: pars(:)
    integer :: ir, np
    character(len=:), allocatable :: kw, cur_kw
    type(deck_param_t), allocatable :: params(:)
    logical :: in_param
    stat = 0
    errmsg = ''
    allocate (pars(max_param))
    np = 0
    in_param = .false.
    cur_kw = ''
    do ir = 1, src%nrec
      if (src%rec(ir)%keyword) then
        call deck_keyword_parse(src%rec(ir)%text, kw, params)
        cur_kw = kw
        in_param = kw == '*PARAMETER'
        if (in_param .and. size(params) > 0) then
          stat = 2
          errmsg = deck_where(src, ir)//': *PARAMETER: parameter '//params(1)%name//' is not supported '// &
            '(data lines name = expression only)'
          return
        end if
      else if (in_param) then
        call define(src%rec(ir)%text, pars, np, stat, errmsg)
        if (stat /= 0) then
          errmsg = deck_where(src, ir)//': *PARAMETER: '//errmsg
          return
        end if
        cycle
      end if
      if (np > 0 .and. index(src%rec(ir)%text, '<') > 0) then
        call substitute(src%rec(ir)%text, pars(1:np), stat, errmsg)
        if (stat /= 0) then
          errmsg = deck_where(src, ir)//': '//cur_kw//': '//errmsg
          return
        end if
      end if
    end do
  end subroutine apply_parameters

  !> One data line 'name = expression'.
  recursive subroutine define(line, pars, np, stat, errmsg)
    character(len=*), intent(in) :: line                 !< the data line
    type(param_value_t), intent(inout) :: pars(:)        !< parameters so far
    integer, intent(inout) :: np                         !< their number
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: k, j
    character(len=:), allocatable :: name, rhs
    type(param_value_t) :: pv
    type(scan_t) :: sc
    character(len=32) :: b
    stat = 2
    errmsg = ''
    ! a Python comment (a '#' outside quotes) ends the definition (the Abaqus parameter lines are Python statements)
    k = comment_start(line)
    if (k > 0) then
      call define(line(1:k - 1), pars, np, stat, errmsg)
      return
    end if
    k = index(line, '=')
    if (k == 0) then
      errmsg = 'expected: name = expression'
      return
    end if
    name = trim(adjustl(line(1:k - 1)))
    rhs = trim(adjustl(line(k + 1:)))
    if (len(name) == 0 .or. verify(name, 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_') /= 0 &
        .or. index('0123456789', name(1:1)) > 0) then
      errmsg = 'invalid parameter name "'//name//'" (letters, digits and _, not starting with a digit)'
      return
    end if
    if (len(rhs) == 0) then
      errmsg = 'parameter '//name//' has no value'
      return
    end if
    pv%name = name
    if (rhs(1:1) == '"' .or. rhs(1:1) == "'") then
      if (len(rhs) < 2 .or. rhs(len(rhs):len(rhs)) /= rhs(1:1)) then
        errmsg = 'unterminated text value of '//name
        return
      end if
      pv%is_text = .true.
      pv%text = rhs(2:len(rhs) - 1)
    else
      sc%s = rhs
      sc%p = 1
      sc%err = ''
      call expression(sc, pars(1:np), pv%v, pv%is_int)
      call skip_blanks(sc)
      if (len(sc%err) == 0 .and. sc%p <= len(sc%s)) sc%err = 'unexpected "'//sc%s(sc%p:)//'"'
      if (len(sc%err) == 0 .and. .not. ieee_is_finite(pv%v)) sc%err = 'the value is not finite'
      if (len(sc%err) > 0) then
        errmsg = 'parameter '//name//': '//sc%err
        return
      end if
      if (pv%is_int .and. abs(pv%v) < 1.0e15_dp) then
        write (b, '(i0)') nint(pv%v, kind=8)
      else
        write (b, '(es24.16e3)') pv%v
      end if
      pv%text = trim(adjustl(b))
    end if
    do j = 1, np
      if (pars(j)%name == name) then
        pars(j) = pv
        stat = 0
        return
      end if
    end do
    if (np == size(pars)) then
      errmsg = 'more than 512 parameters'
      return
    end if
    np = np + 1
    pars(np) = pv
    stat = 0
  end subroutine define

  !> Position of a '#' outside quotes (0: none).
  pure integer function comment_start(line) result(k)
    character(len=*), intent(in) :: line  !< definition line
    character(len=1) :: q
    integer :: i
    q = ' '
    k = 0
    do i = 1, len(line)
      if (q /= ' ') then
        if (line(i:i) == q) q = ' '
      else if (line(i:i) == '"' .or. line(i:i) == "'") then
        q = line(i:i)
      else if (line(i:i) == '#') then
        k = i
        return
      end if
    end do
  end function comment_start

  !> Replace every <name> in text by the parameter's value.
  subroutine substitute(text, pars, stat, errmsg)
    character(len=:), allocatable, intent(inout) :: text !< record text
    type(param_value_t), intent(in) :: pars(:)           !< parameters defined so far
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: a, b, j, from
    character(len=:), allocatable :: name
    stat = 0
    errmsg = ''
    from = 1
    do
      a = index(text(from:), '<')
      if (a == 0) return
      a = a + from - 1
      b = index(text(a:), '>')
      if (b == 0) then
        stat = 2
        errmsg = '"<" without ">" (a parameter is written <name>)'
        return
      end if
      b = b + a - 1
      name = trim(adjustl(text(a + 1:b - 1)))
      do j = 1, size(pars)
        if (pars(j)%name == name) exit
      end do
      if (j > size(pars)) then
        stat = 2
        errmsg = 'undefined parameter <'//name//'> (define it on an earlier *PARAMETER)'
        return
      end if
      text = text(1:a - 1)//pars(j)%text//text(b + 1:)
      from = a + len(pars(j)%text)
      if (from > len(text)) return
    end do
  end subroutine substitute

  ! ------------------------------------------------------------------ expressions (recursive descent)

  !> expression = term {(+|-) term}
  recursive subroutine expression(sc, pars, v, is_int)
    type(scan_t), intent(inout) :: sc           !< scanner
    type(param_value_t), intent(in) :: pars(:)  !< parameters
    real(dp), intent(out) :: v                  !< value
    logical, intent(out) :: is_int              !< integer value
    real(dp) :: w
    logical :: wi
    character(len=1) :: op
    call term(sc, pars, v, is_int)
    do while (len(sc%err) == 0)
      call skip_blanks(sc)
      if (sc%p > len(sc%s)) exit
      op = sc%s(sc%p:sc%p)
      if (op /= '+' .and. op /= '-') exit
      sc%p = sc%p + 1
      call term(sc, pars, w, wi)
      if (op == '+') v = v + w
      if (op == '-') v = v - w
      is_int = is_int .and. wi
    end do
  end subroutine expression

  !> term = power {(*|/) power}
  recursive subroutine term(sc, pars, v, is_int)
    type(scan_t), intent(inout) :: sc           !< scanner
    type(param_value_t), intent(in) :: pars(:)  !< parameters
    real(dp), intent(out) :: v                  !< value
    logical, intent(out) :: is_int              !< integer value
    real(dp) :: w
    logical :: wi
    character(len=1) :: op
    call power(sc, pars, v, is_int)
    do while (len(sc%err) == 0)
      call skip_blanks(sc)
      if (sc%p > len(sc%s)) exit
      op = sc%s(sc%p:sc%p)
      if (op /= '*' .and. op /= '/') exit
      if (op == '*' .and. sc%p < len(sc%s)) then
        if (sc%s(sc%p + 1:sc%p + 1) == '*') exit  ! '**' belongs to power
      end if
      sc%p = sc%p + 1
      call power(sc, pars, w, wi)
      if (len(sc%err) > 0) return
      if (op == '*') then
        v = v * w
        is_int = is_int .and. wi
      else
        if (w == 0.0_dp) then
          sc%err = 'division by zero'
          return
        end if
        v = v / w
        is_int = .false.
      end if
    end do
  end subroutine term

  !> power = unary [** power]
  recursive subroutine power(sc, pars, v, is_int)
    type(scan_t), intent(inout) :: sc           !< scanner
    type(param_value_t), intent(in) :: pars(:)  !< parameters
    real(dp), intent(out) :: v                  !< value
    logical, intent(out) :: is_int              !< integer value
    real(dp) :: w
    logical :: wi
    call unary(sc, pars, v, is_int)
    if (len(sc%err) > 0) return
    call skip_blanks(sc)
    if (sc%p + 1 > len(sc%s)) return
    if (sc%s(sc%p:sc%p + 1) /= '**') return
    sc%p = sc%p + 2
    call power(sc, pars, w, wi)
    if (len(sc%err) > 0) return
    if (v < 0.0_dp .and. .not. wi) then
      sc%err = 'a negative number to a non-integer power'
      return
    end if
    if (v == 0.0_dp .and. w < 0.0_dp) then
      sc%err = 'zero to a negative power'
      return
    end if
    if (abs(w) * log(max(abs(v), 1.0_dp)) > 700.0_dp) then
      sc%err = 'overflow'
      return
    end if
    if (wi) then
      v = v**nint(w)
    else
      v = v**w
    end if
    is_int = is_int .and. wi .and. w >= 0.0_dp
  end subroutine power

  !> unary = [+|-] unary | number | name | ( expression )
  recursive subroutine unary(sc, pars, v, is_int)
    type(scan_t), intent(inout) :: sc           !< scanner
    type(param_value_t), intent(in) :: pars(:)  !< parameters
    real(dp), intent(out) :: v                  !< value
    logical, intent(out) :: is_int              !< integer value
    integer :: q, j
    character(len=1) :: c
    character(len=:), allocatable :: tok, why
    logical :: ok
    v = 0.0_dp
    is_int = .false.
    call skip_blanks(sc)
    if (sc%p > len(sc%s)) then
      sc%err = 'expression ends early'
      return
    end if
    c = sc%s(sc%p:sc%p)
    if (c == '-' .or. c == '+') then
      sc%p = sc%p + 1
      call unary(sc, pars, v, is_int)
      if (c == '-') v = -v
    else if (c == '(') then
      sc%p = sc%p + 1
      call expression(sc, pars, v, is_int)
      if (len(sc%err) > 0) return
      call skip_blanks(sc)
      if (sc%p > len(sc%s)) then
        sc%err = '")" missing'
        return
      end if
      if (sc%s(sc%p:sc%p) /= ')') then
        sc%err = '")" missing'
        return
      end if
      sc%p = sc%p + 1
    else if (index('0123456789.', c) > 0) then
      q = sc%p
      do while (q <= len(sc%s))
        if (index('0123456789.', sc%s(q:q)) > 0) then
          q = q + 1
        else if (index('eEdD', sc%s(q:q)) > 0) then
          q = q + 1
          if (q <= len(sc%s)) then
            if (index('+-', sc%s(q:q)) > 0) q = q + 1
          end if
        else
          exit
        end if
      end do
      tok = sc%s(sc%p:q - 1)
      sc%p = q
      call deck_parse_real(tok, v, ok, why)
      if (.not. ok) then
        sc%err = why
        return
      end if
      is_int = verify(tok, '0123456789') == 0
    else if (index('ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_', c) > 0) then
      q = sc%p
      do while (q <= len(sc%s))
        if (index('ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_', sc%s(q:q)) == 0) exit
        q = q + 1
      end do
      tok = sc%s(sc%p:q - 1)
      sc%p = q
      do j = 1, size(pars)
        if (pars(j)%name == tok) exit
      end do
      if (j > size(pars)) then
        sc%err = 'undefined parameter '//tok
        return
      end if
      if (pars(j)%is_text) then
        sc%err = 'parameter '//tok//' is text, not a number'
        return
      end if
      v = pars(j)%v
      is_int = pars(j)%is_int
    else
      sc%err = 'unexpected "'//c//'" (numbers, parameter names, + - * / ** and parentheses)'
    end if
  end subroutine unary

  !> Skip blanks.
  subroutine skip_blanks(sc)
    type(scan_t), intent(inout) :: sc  !< scanner
    do while (sc%p <= len(sc%s))
      if (sc%s(sc%p:sc%p) /= ' ') exit
      sc%p = sc%p + 1
    end do
  end subroutine skip_blanks

end module deck_parameters
