!> The deck reader's state, passed explicitly to every keyword reader: the source records, the model being built,
!> the keyword block being read, the current material and step, and the error status. Also the helpers every reader
!> shares: messages naming file:line: *KEYWORD, parameter checks, and data-field parsing.
module deck_context
  use ldfcz_kinds, only: dp
  use, intrinsic :: iso_fortran_env, only: error_unit
  use deck_lines, only: deck_source_t, deck_param_t, deck_split_fields, deck_parse_real, deck_parse_int, deck_where, &
    deck_param_value, deck_has_param, deck_normalize
  use model_types, only: model_t, source_pos_t, model_find_nset, model_find_elset, model_find_surface
  use deck_lists, only: itoa, add_member
  use deck_values, only: abaqus_values, expand_value, no_blanks
  use deck_suggest, only: deck_closest
  implicit none
  private
  public :: deck_context_t, flen
  public :: ctx_fail, ctx_fail_kw, ctx_fail_pos, ctx_warn, ctx_warn_pos, ctx_pos, ctx_note, ctx_note_pos
  public :: ctx_report_warning
  public :: deck_message_t
  public :: ctx_allow_params, ctx_need_step, ctx_required, ctx_param_int, ctx_only_value
  public :: ctx_block_fields, ctx_split, ctx_get_real, ctx_get_int, ctx_continued
  public :: part_def_t, scope_model, scope_part, scope_assembly, member_origin_t, ctx_set_member, no_blanks
  public :: ctx_enter_instance, ctx_def_name, ctx_find_nset, ctx_find_elset, ctx_find_surface, ctx_is_label, &
    ctx_get_label

  integer, parameter :: flen = 256  !< longest data field
  integer, parameter :: scope_model = 0     !< model level (a deck without parts, or outside *ASSEMBLY)
  integer, parameter :: scope_part = 1      !< a part's blocks, read for one of its instances
  integer, parameter :: scope_assembly = 2  !< between *ASSEMBLY and *END ASSEMBLY

  !> A *PART ... *END PART definition: its blocks are read once per *INSTANCE of it.
  type :: part_def_t
    character(len=80) :: name = ''  !< upper-case part name
    integer :: ir1 = 0              !< first record after *PART
    integer :: ir2 = 0              !< the *END PART record
    integer :: ninst = 0            !< instances of it
  end type part_def_t

  !> Where the members of one set come from: the record of the data line that added each (negative: a GENERATE
  !> range of that line), so that a member naming no node or element is reported at its own line.
  type :: member_origin_t
    integer, allocatable :: rec(:)   !< record of member k (same order as the set's members while reading)
    integer :: n = 0                 !< entries in use
  end type member_origin_t
  !> A warning or note of the reading, for JOB.log: 'warning: file:line: *KW: text' or 'note: ...'.
  type :: deck_message_t
    character(len=:), allocatable :: text
  end type deck_message_t

  !> Reader state. The keyword block being read is records ir (the keyword line) .. ir_next-1.
  type :: deck_context_t
    type(deck_source_t) :: src                        !< records of the deck and its includes
    type(model_t) :: model                            !< the model being built
    integer :: stat = 0                               !< 0 ok, 2 deck error
    character(len=:), allocatable :: errmsg           !< "file:line: *KEYWORD: what" when stat /= 0
    integer :: wu = error_unit                        !< unit for warnings (-1: silent)
    integer :: ir = 1                                 !< keyword record of the current block
    integer :: ir_next = 1                            !< first record after the current block
    character(len=:), allocatable :: kw               !< current keyword, upper case (e.g. *NODE)
    type(deck_param_t), allocatable :: params(:)      !< its parameters
    integer :: imat = 0                               !< material being defined (0: none)
    integer :: istep = 0                              !< current step
    logical :: in_step = .false.                      !< between *STEP and *END STEP
    integer :: step_rec = 0                           !< record of the *STEP line of the open step
    integer :: restart_freq = 0                       !< *RESTART, WRITE, FREQUENCY in effect (0: none)
    integer :: output_kind = 0                        !< the step's last *OUTPUT: 1 FIELD, 2 HISTORY, 0 none
    integer :: decl_material = 0                      !< material whose definition the last blocks belong to
    integer :: decl_utype = 0                         !< user element type the last blocks belong to
    integer, allocatable :: node_rec(:)               !< record of each node (duplicate-id messages)
    integer, allocatable :: elem_rec(:)               !< record of each element
    integer, allocatable :: conn_raw(:)               !< connectivity as user node ids until finish
    ! model structure: the scope of the labels and names of the block being read (docs/host.md, parts)
    integer :: scope = scope_model                    !< scope_model, scope_part or scope_assembly
    logical :: has_assembly = .false.                 !< the deck has an *ASSEMBLY
    character(len=96) :: def_prefix = ''              !< prefix of names defined ('INSTANCE.' in a part)
    character(len=96) :: ref_prefix = ''              !< prefix tried first for names referenced
    integer :: node_off = 0                           !< added to the node labels of the scope
    integer :: elem_off = 0                           !< added to the element labels of the scope
    logical :: placed = .false.                       !< coordinates are placed: x = place_r x + place_c
    real(dp) :: place_r(3, 3) = 0.0_dp                !< instance rotation
    real(dp) :: place_c(3) = 0.0_dp                   !< instance shift
    logical :: system_on = .false.                    !< *SYSTEM in effect: *NODE coordinates are local
    real(dp) :: system_r(3, 3) = 0.0_dp               !< its axes (columns): x = system_c + system_r x_local
    real(dp) :: system_c(3) = 0.0_dp                  !< its origin
    integer :: top_node = 0                           !< largest model node label so far (instance offsets)
    integer :: top_elem = 0                           !< largest model element label so far
    type(part_def_t), allocatable :: parts(:)         !< *PART definitions
    integer :: npart = 0
    type(member_origin_t), allocatable :: nset_src(:) !< origin of the members of each node set
    type(member_origin_t), allocatable :: elset_src(:) !< origin of the members of each element set
    type(deck_message_t), allocatable :: messages(:)  !< warnings and notes so far (JOB.log)
    integer :: nmessage = 0
  end type deck_context_t

contains

  ! ------------------------------------------------------------------ messages

  !> Source position of record irec (file, line) with the current keyword.
  function ctx_pos(ctx, irec) result(pos)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: irec              !< record index
    type(source_pos_t) :: pos
    pos%file = ctx%src%files(ctx%src%rec(irec)%file_id)%name
    pos%line = ctx%src%rec(irec)%line
    pos%keyword = ctx%kw
  end function ctx_pos

  !> A parameter that ldfcz supports with one value only: true when it is absent or has that value; otherwise
  !> an error 'only NAME=VALUE is supported' (plus note) at record irec.
  logical function ctx_only_value(ctx, irec, name, value, note) result(ok)
    type(deck_context_t), intent(inout) :: ctx      !< reader state
    integer, intent(in) :: irec                     !< record index of the keyword line
    character(len=*), intent(in) :: name            !< parameter name (upper case)
    character(len=*), intent(in) :: value           !< the supported value (normalised form)
    character(len=*), intent(in), optional :: note  !< appended to the message
    character(len=:), allocatable :: v
    v = deck_normalize(deck_param_value(ctx%params, name))
    ok = len(v) == 0 .or. v == value
    if (ok) return
    if (present(note)) then
      call ctx_fail(ctx, irec, 'only '//name//'='//value//' is supported'//note)
    else
      call ctx_fail(ctx, irec, 'only '//name//'='//value//' is supported')
    end if
  end function ctx_only_value

  !> Error at record irec under the current keyword.
  subroutine ctx_fail(ctx, irec, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record index
    character(len=*), intent(in) :: msg         !< what is wrong
    ctx%stat = 2
    ctx%errmsg = deck_where(ctx%src, irec)//': '//shown(ctx%kw)//': '//msg
  end subroutine ctx_fail

  !> Error at record irec under the given keyword.
  subroutine ctx_fail_kw(ctx, irec, keyword, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record index
    character(len=*), intent(in) :: keyword     !< keyword named in the message
    character(len=*), intent(in) :: msg         !< what is wrong
    ctx%stat = 2
    ctx%errmsg = deck_where(ctx%src, irec)//': '//shown(keyword)//': '//msg
  end subroutine ctx_fail_kw

  !> Error at a stored source position.
  subroutine ctx_fail_pos(ctx, pos, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(source_pos_t), intent(in) :: pos       !< position (not a part of ctx)
    character(len=*), intent(in) :: msg         !< what is wrong
    ctx%stat = 2
    ctx%errmsg = pos%file//':'//itoa(pos%line)//': '//trim(pos%keyword)//': '//msg
  end subroutine ctx_fail_pos

  !> Warning at record irec under the current keyword: something that may make the result differ from what the deck
  !> asks for (on standard error at once, and in JOB.log).
  subroutine ctx_warn(ctx, irec, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record index
    character(len=*), intent(in) :: msg         !< what is ignored
    call report(ctx, 'warning: '//deck_where(ctx%src, irec)//': '//shown(ctx%kw)//': '//msg, .true.)
  end subroutine ctx_warn

  !> A keyword as the deck writes it: a declaration '*LDFCZ X' was the comment line '**LDFCZ X'.
  pure function shown(kw) result(t)
    character(len=*), intent(in) :: kw  !< keyword
    character(len=:), allocatable :: t
    t = trim(kw)
    if (len(t) >= 7) then
      if (t(1:7) == '*LDFCZ ') t = '*'//t
    end if
  end function shown

  !> A warning already located ('file:line: *KEYWORD: what'; the reading of the files).
  subroutine ctx_report_warning(ctx, located)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: located     !< the located message
    call report(ctx, 'warning: '//located, .true.)
  end subroutine ctx_report_warning

  !> Warning at a stored source position.
  subroutine ctx_warn_pos(ctx, pos, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(source_pos_t), intent(in) :: pos       !< position
    character(len=*), intent(in) :: msg         !< what is ignored
    call report(ctx, 'warning: '//pos%file//':'//itoa(pos%line)//': '//trim(pos%keyword)//': '//msg, .true.)
  end subroutine ctx_warn_pos

  !> Note at record irec under the current keyword: something of the deck without effect on the results (output
  !> requests ldfcz does not write, Abaqus/CAE's boilerplate); in JOB.log only, not on the console.
  subroutine ctx_note(ctx, irec, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record index
    character(len=*), intent(in) :: msg         !< what has no effect
    call report(ctx, 'note: '//deck_where(ctx%src, irec)//': '//trim(ctx%kw)//': '//msg, .false.)
  end subroutine ctx_note

  !> Note at a stored source position.
  subroutine ctx_note_pos(ctx, pos, msg)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(source_pos_t), intent(in) :: pos       !< position
    character(len=*), intent(in) :: msg         !< what has no effect
    call report(ctx, 'note: '//pos%file//':'//itoa(pos%line)//': '//trim(pos%keyword)//': '//msg, .false.)
  end subroutine ctx_note_pos

  !> Keep a message for JOB.log; a warning also goes to the warning unit now ('ldfcz: warning: ...').
  subroutine report(ctx, text, console)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: text        !< 'warning: ...' or 'note: ...'
    logical, intent(in) :: console              !< also on the warning unit
    type(deck_message_t), allocatable :: tmp(:)
    if (console .and. ctx%wu /= -1) write (ctx%wu, '(a)') 'ldfcz: '//text
    if (.not. allocated(ctx%messages)) allocate (ctx%messages(8))
    if (ctx%nmessage == size(ctx%messages)) then
      allocate (tmp(2 * ctx%nmessage))
      tmp(1:ctx%nmessage) = ctx%messages(1:ctx%nmessage)
      call move_alloc(tmp, ctx%messages)
    end if
    ctx%nmessage = ctx%nmessage + 1
    ctx%messages(ctx%nmessage)%text = text
  end subroutine report

  ! ------------------------------------------------------------------ parameters

  !> Error when a parameter outside the list is present. A parameter name that begins exactly one of the allowed
  !> names is taken for it (Abaqus reads parameters abbreviated as far as they stay unique: FREQ for FREQUENCY),
  !> and so is an enumerated parameter's value that begins exactly one of its Abaqus values (deck_values).
  subroutine ctx_allow_params(ctx, names)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: names(:)    !< allowed parameter names
    integer :: i, j, nmatch, jmatch, n
    character(len=:), allocatable :: list, given, cand
    do i = 1, size(ctx%params)
      if (all(ctx%params(i)%name /= names)) then
        ! blanks on a keyword line are ignored (HOUR GLASS is HOURGLASS), then an abbreviation
        given = no_blanks(ctx%params(i)%name)
        n = len(given)
        nmatch = 0
        jmatch = 0
        do j = 1, size(names)
          cand = no_blanks(names(j))
          if (cand == given) then
            nmatch = 1
            jmatch = j
            exit
          end if
          if (n == 0 .or. n > len(cand)) cycle
          if (cand(1:n) == given) then
            nmatch = nmatch + 1
            jmatch = j
          end if
        end do
        if (nmatch == 1) ctx%params(i)%name = trim(names(jmatch))
      end if
      if (all(ctx%params(i)%name /= names)) then
        ! a slip of the keyboard gets the parameter it is nearest to ("ELSTE: ...; did you mean ELSET?")
        j = deck_closest(ctx%params(i)%name, names)
        if (j > 0) then
          call ctx_fail(ctx, ctx%ir, 'unsupported parameter '//ctx%params(i)%name//'; did you mean '// &
            trim(names(j))//'?')
        else
          call ctx_fail(ctx, ctx%ir, 'unsupported parameter '//ctx%params(i)%name)
        end if
        return
      end if
      ! an abbreviated value of an enumerated parameter: the one Abaqus value it begins (AMPLITUDE=RAM is RAMP)
      list = abaqus_values(ctx%kw, ctx%params(i)%name)
      if (len(list) > 0) ctx%params(i)%value = expand_value(deck_normalize(ctx%params(i)%value), list)
    end do
  end subroutine ctx_allow_params

  !> Error when a history keyword appears outside a step.
  subroutine ctx_need_step(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (.not. ctx%in_step) call ctx_fail(ctx, ctx%ir, 'history keyword outside a step')
  end subroutine ctx_need_step

  !> Required parameter value ('' and an error when missing or empty).
  function ctx_required(ctx, name) result(v)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: name        !< parameter name
    character(len=:), allocatable :: v
    v = ''
    if (.not. deck_has_param(ctx%params, name)) then
      call ctx_fail(ctx, ctx%ir, 'parameter '//name//'= is required')
      return
    end if
    v = deck_param_value(ctx%params, name)
    if (len_trim(v) == 0) call ctx_fail(ctx, ctx%ir, 'parameter '//name//'= has no value')
  end function ctx_required

  !> Integer parameter value, default when absent (error when not an integer).
  integer function ctx_param_int(ctx, name, default) result(v)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: name        !< parameter name
    integer, intent(in) :: default              !< value when absent
    logical :: ok
    character(len=:), allocatable :: why
    v = default
    if (.not. deck_has_param(ctx%params, name)) return
    call deck_parse_int(deck_param_value(ctx%params, name), v, ok, why)
    if (.not. ok) call ctx_fail(ctx, ctx%ir, 'parameter '//name//': '//why)
  end function ctx_param_int

  ! ------------------------------------------------------------------ data fields

  !> Data fields of records i1..i2 concatenated.
  subroutine ctx_block_fields(ctx, i1, i2, fields, nf)
    type(deck_context_t), intent(in) :: ctx                   !< reader state
    integer, intent(in) :: i1                                 !< first record
    integer, intent(in) :: i2                                 !< last record
    character(len=flen), allocatable, intent(out) :: fields(:) !< fields
    integer, intent(out) :: nf                                !< number of fields
    character(len=flen), allocatable :: f(:), tmp(:)
    integer :: i, n
    allocate (fields(16))
    nf = 0
    do i = i1, i2
      call ctx_split(ctx, i, f, n)
      do while (nf + n > size(fields))
        allocate (tmp(2 * size(fields)))
        tmp(1:nf) = fields(1:nf)
        call move_alloc(tmp, fields)
      end do
      fields(nf + 1:nf + n) = f(1:n)
      nf = nf + n
    end do
  end subroutine ctx_block_fields

  !> Data fields of record irec.
  subroutine ctx_split(ctx, irec, f, n)
    type(deck_context_t), intent(in) :: ctx              !< reader state
    integer, intent(in) :: irec                          !< record index
    character(len=flen), allocatable, intent(out) :: f(:) !< fields
    integer, intent(out) :: n                            !< number of fields
    character(len=len(ctx%src%rec(irec)%text)), allocatable :: g(:)
    integer :: i
    call deck_split_fields(ctx%src%rec(irec)%text, g, n)
    allocate (f(n))
    do i = 1, n
      f(i) = g(i)
    end do
  end subroutine ctx_split

  !> True when data record irec ends with a comma and a data record of the block follows: the readers whose
  !> logical data line may span several lines (*ELEMENT with more nodes than a line holds, *INITIAL CONDITIONS,
  !> TYPE=SOLUTION) continue on it; for every other keyword a line ending with a comma is complete.
  logical function ctx_continued(ctx, irec)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: irec              !< record index
    integer :: n
    ctx_continued = .false.
    if (irec >= ctx%ir_next - 1) return
    n = len_trim(ctx%src%rec(irec)%text)
    if (n > 0) ctx_continued = ctx%src%rec(irec)%text(n:n) == ','
  end function ctx_continued

  !> Real data field (error at record irec when not a number).
  logical function ctx_get_real(ctx, irec, field, v)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record of the field
    character(len=*), intent(in) :: field       !< field text
    real(dp), intent(out) :: v                  !< value (not a part of ctx)
    character(len=:), allocatable :: why
    logical :: ok
    call deck_parse_real(field, v, ok, why)
    if (.not. ok) call ctx_fail(ctx, irec, why)
    ctx_get_real = ok
  end function ctx_get_real

  !> Integer data field (error at record irec when not an integer).
  logical function ctx_get_int(ctx, irec, field, v)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record of the field
    character(len=*), intent(in) :: field       !< field text
    integer, intent(out) :: v                   !< value (not a part of ctx)
    character(len=:), allocatable :: why
    logical :: ok
    call deck_parse_int(field, v, ok, why)
    if (.not. ok) call ctx_fail(ctx, irec, why)
    ctx_get_int = ok
  end function ctx_get_int

  ! ------------------------------------------------------------------ set members

  !> Append member v (a raw label as -label, or a resolved index) to node set (is_node) or element set iset,
  !> recording the record irec it comes from (negative: generated by a GENERATE range of record -irec).
  subroutine ctx_set_member(ctx, is_node, iset, v, irec)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: is_node              !< node set (else element set)
    integer, intent(in) :: iset                 !< set index
    integer, intent(in) :: v                    !< member
    integer, intent(in) :: irec                 !< its record (negative: generated)
    if (is_node) then
      call add_member(ctx%model%nsets(iset)%nodes, ctx%model%nsets(iset)%n, v)
      call add_origin(ctx%nset_src, iset, irec)
    else
      call add_member(ctx%model%elsets(iset)%elems, ctx%model%elsets(iset)%n, v)
      call add_origin(ctx%elset_src, iset, irec)
    end if
  end subroutine ctx_set_member

  !> Append irec to the origins of set iset (the list of sets grown as needed).
  pure subroutine add_origin(src, iset, irec)
    type(member_origin_t), allocatable, intent(inout) :: src(:) !< origins of every set
    integer, intent(in) :: iset                                 !< set index
    integer, intent(in) :: irec                                 !< record
    type(member_origin_t), allocatable :: tmp(:)
    if (.not. allocated(src)) allocate (src(8))
    if (iset > size(src)) then
      allocate (tmp(max(2 * size(src), iset)))
      tmp(1:size(src)) = src
      call move_alloc(tmp, src)
    end if
    call add_member(src(iset)%rec, src(iset)%n, irec)
  end subroutine add_origin

  ! ------------------------------------------------------------------ scoped names and labels

  !> Name of a set or surface defined by the current block (prefixed by 'INSTANCE.' inside a part).
  function ctx_def_name(ctx, field) result(name)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< name as written
    character(len=:), allocatable :: name
    name = trim(ctx%def_prefix)//deck_normalize(field)
  end function ctx_def_name

  !> Node set referenced by name: the scope's own first ('INSTANCE.name' in a part or with INSTANCE=), then the
  !> name as written (an assembly set, or a qualified 'INSTANCE.SET'). 0 when undefined.
  integer function ctx_find_nset(ctx, field) result(k)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< name as written
    k = 0
    if (len_trim(ctx%ref_prefix) > 0) k = model_find_nset(ctx%model, trim(ctx%ref_prefix)//deck_normalize(field))
    if (k == 0 .and. ctx%scope /= scope_part) k = model_find_nset(ctx%model, deck_normalize(field))
  end function ctx_find_nset

  !> Element set referenced by name (scoped as ctx_find_nset).
  integer function ctx_find_elset(ctx, field) result(k)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< name as written
    k = 0
    if (len_trim(ctx%ref_prefix) > 0) k = model_find_elset(ctx%model, trim(ctx%ref_prefix)//deck_normalize(field))
    if (k == 0 .and. ctx%scope /= scope_part) k = model_find_elset(ctx%model, deck_normalize(field))
  end function ctx_find_elset

  !> Surface referenced by name (scoped as ctx_find_nset).
  integer function ctx_find_surface(ctx, field) result(k)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< name as written
    k = 0
    if (len_trim(ctx%ref_prefix) > 0) k = model_find_surface(ctx%model, trim(ctx%ref_prefix)//deck_normalize(field))
    if (k == 0 .and. ctx%scope /= scope_part) k = model_find_surface(ctx%model, deck_normalize(field))
  end function ctx_find_surface

  !> True when a data field is a node or element label: digits, or 'INSTANCE.label' of a defined instance.
  logical function ctx_is_label(ctx, field)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< field text
    ctx_is_label = verify(trim(field), '0123456789+-') == 0
    if (.not. ctx_is_label) ctx_is_label = instance_of(ctx, field) > 0
  end function ctx_is_label

  !> Model label of a node (is_node) or element label field: plain labels belong to the current scope (offset
  !> added), 'INSTANCE.label' to that instance. False (and an error at record irec) when not a positive label.
  logical function ctx_get_label(ctx, irec, field, is_node, id) result(ok)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record of the field
    character(len=*), intent(in) :: field       !< field text
    logical, intent(in) :: is_node              !< node (true) or element label
    integer, intent(out) :: id                  !< model label (not a part of ctx)
    integer :: k, off
    character(len=:), allocatable :: t
    t = trim(adjustl(field))
    k = instance_of(ctx, t)
    if (k > 0) then
      off = merge(ctx%model%instances(k)%node_offset, ctx%model%instances(k)%elem_offset, is_node)
      t = t(index(t, '.', back=.true.) + 1:)
    else
      off = merge(ctx%node_off, ctx%elem_off, is_node)
    end if
    ok = ctx_get_int(ctx, irec, t, id)
    if (.not. ok) return
    if (id < 1) then
      call ctx_fail(ctx, irec, trim(merge('node   ', 'element', is_node))//' labels must be positive, got '//t)
      ok = .false.
      return
    end if
    if (id > huge(id) - off) then
      call ctx_fail(ctx, irec, 'label too large: '//t)
      ok = .false.
      return
    end if
    id = id + off
    if (k > 0) then
      ! the instance is complete when it is referenced: a label beyond its part's is an error here
      if (id > merge(ctx%model%instances(k)%node_last, ctx%model%instances(k)%elem_last, is_node)) then
        call ctx_fail(ctx, irec, 'instance '//trim(ctx%model%instances(k)%name)//' has no '// &
          trim(merge('node   ', 'element', is_node))//' '//t)
        ok = .false.
      end if
    end if
  end function ctx_get_label

  !> INSTANCE= on a set or surface definition (assembly level only): labels and names of the data lines refer to
  !> that instance (the caller restores the scope).
  subroutine ctx_enter_instance(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: v
    integer :: k
    if (.not. deck_has_param(ctx%params, 'INSTANCE')) return
    if (ctx%scope /= scope_assembly) then
      call ctx_fail(ctx, ctx%ir, 'INSTANCE= only inside *ASSEMBLY')
      return
    end if
    v = deck_normalize(ctx_required(ctx, 'INSTANCE'))
    if (ctx%stat /= 0) return
    do k = 1, ctx%model%ninstance
      if (ctx%model%instances(k)%name == v) then
        ctx%ref_prefix = v//'.'
        ctx%node_off = ctx%model%instances(k)%node_offset
        ctx%elem_off = ctx%model%instances(k)%elem_offset
        return
      end if
    end do
    call ctx_fail(ctx, ctx%ir, 'undefined instance '//v//' (an *INSTANCE defined before in this *ASSEMBLY)')
  end subroutine ctx_enter_instance

  !> Instance of a field 'INSTANCE.label' (0 when the field is not of that form or names no instance).
  integer function instance_of(ctx, field) result(k)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    character(len=*), intent(in) :: field    !< field text
    integer :: j
    character(len=:), allocatable :: head
    k = 0
    if (ctx%scope == scope_part .or. ctx%model%ninstance == 0) return
    j = index(field, '.', back=.true.)
    if (j <= 1 .or. j >= len_trim(field)) return
    if (verify(trim(field(j + 1:)), '0123456789') /= 0) return
    head = deck_normalize(field(1:j - 1))
    do k = 1, ctx%model%ninstance
      if (ctx%model%instances(k)%name == head) return
    end do
    k = 0
  end function instance_of

end module deck_context
