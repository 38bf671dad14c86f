!> Abaqus keyword deck reader: builds a model_t from the records of deck_lines.
!> Subset documented in docs/host.md. A keyword or parameter that would change the physics and is not supported is an
!> error; cosmetic/output keywords that are not supported give a warning. Every error names file:line: *KEYWORD.
module deck_reader
  use ldfcz_kinds, only: dp
  use, intrinsic :: iso_fortran_env, only: error_unit
  use deck_lines, only: deck_source_t, deck_param_t, deck_load, deck_split_fields, deck_keyword_parse, deck_upper, &
    deck_parse_real, deck_parse_int, deck_where, deck_param_value, deck_has_param, deck_normalize
  use model_types, only: model_t, node_set_t, elem_set_t, material_t, section_t, user_element_type_t, amplitude_t, &
    boundary_t, node_print_t, step_t, uel_property_t, source_pos_t, etype_c3d8, etype_cpe4, etype_user, name_len, &
    model_find_nset, model_find_elset, model_find_material, model_find_amplitude, model_find_user_type
  implicit none
  private
  public :: read_deck

  character(len=*), parameter :: field_len_msg = 'field too long'
  integer, parameter :: flen = 256  !< longest data field

contains

  !> Read an Abaqus-style deck into a model. stat = 0 ok, 2 error (errmsg = "file:line: *KEYWORD: what").
  subroutine read_deck(path, model, stat, errmsg, warn_unit)
    character(len=*), intent(in) :: path                 !< deck file
    type(model_t), intent(out) :: model                  !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 deck error
    character(len=:), allocatable, intent(out) :: errmsg !< error message
    integer, intent(in), optional :: warn_unit           !< unit for warnings (default stderr; -1: silent)
    type(deck_source_t) :: src
    integer :: wu, ir, ir_next, imat, istep
    character(len=:), allocatable :: kw
    type(deck_param_t), allocatable :: params(:)
    integer, allocatable :: elem_rec(:), conn_raw(:), node_rec(:)
    logical :: in_step
    integer :: restart_freq  !< *RESTART, WRITE, FREQUENCY in effect (0: none)

    wu = error_unit
    if (present(warn_unit)) wu = warn_unit
    call deck_load(path, src, stat, errmsg)
    if (stat /= 0) return

    allocate (model%node_id(64), model%x(3, 64), node_rec(64))
    allocate (model%elem_id(64), model%elem_kind(64), model%elem_utype(64), model%conn_ptr(65), conn_raw(512))
    allocate (elem_rec(64))
    model%conn_ptr(1) = 1
    allocate (model%nsets(8), model%elsets(8), model%materials(4), model%sections(4), model%utypes(2))
    allocate (model%uelprops(2), model%amplitudes(2), model%initial_bcs(4), model%steps(2))
    model%heading = ''
    imat = 0
    istep = 0
    in_step = .false.
    restart_freq = 0

    ir = 1
    do while (ir <= src%nrec)
      if (.not. src%rec(ir)%keyword) then
        call fail(ir, '(data)', 'data line without a keyword before it')
        return
      end if
      call deck_keyword_parse(src%rec(ir)%text, kw, params)
      ! the records of this block: ir+1 .. ir_next-1
      ir_next = ir + 1
      do while (ir_next <= src%nrec)
        if (src%rec(ir_next)%keyword) exit
        ir_next = ir_next + 1
      end do
      if (in_step .and. is_model_keyword(kw)) then
        call fail(ir, kw, 'model-data keyword inside a step (*STEP ... *END STEP)')
        return
      end if
      select case (kw)
      case ('*HEADING')
        if (ir_next > ir + 1) model%heading = src%rec(ir + 1)%text
      case ('*NODE')
        call read_node()
      case ('*ELEMENT')
        call read_element()
      case ('*NSET')
        call read_set(.true.)
      case ('*ELSET')
        call read_set(.false.)
      case ('*SOLID SECTION')
        call read_solid_section()
      case ('*MATERIAL')
        call read_material()
      case ('*ELASTIC')
        call read_elastic()
      case ('*USER MATERIAL')
        call read_user_material()
      case ('*DEPVAR')
        call read_depvar()
      case ('*USER ELEMENT')
        call read_user_element()
      case ('*UEL PROPERTY')
        call read_uel_property()
      case ('*AMPLITUDE')
        call read_amplitude()
      case ('*BOUNDARY')
        call read_boundary()
      case ('*STEP')
        call read_step()
      case ('*STATIC')
        call read_static()
      case ('*CONTROLS')
        call read_controls()
      case ('*OUTPUT')
        call read_output()
      case ('*NODE OUTPUT', '*ELEMENT OUTPUT')
        call need_step()
        if (stat == 0) call allow_params([character(len=16) :: 'ELSET', 'NSET', 'VARIABLE', 'POSITION', &
          'DIRECTIONS', 'INVARIANT'])
      case ('*NODE PRINT')
        call read_node_print()
      case ('*END STEP')
        if (.not. in_step) then
          call fail(ir, kw, '*END STEP without *STEP')
        else
          in_step = .false.
        end if
      case ('*RESTART')
        call read_restart()
      case ('*EL PRINT', '*ENERGY PRINT', '*PREPRINT', '*FILE FORMAT', '*NODE FILE', '*EL FILE', &
            '*MONITOR', '*ENERGY OUTPUT', '*CONTACT OUTPUT', '*PRINT', '*ENERGY FILE', '*DIAGNOSTICS')
        call warn(ir, kw, 'output/cosmetic keyword not supported by ldfcz: ignored with its data lines')
      case default
        call fail(ir, kw, 'unsupported keyword (ldfcz never ignores a keyword that may change the analysis)')
      end select
      if (stat /= 0) return
      ir = ir_next
    end do
    if (in_step) then
      call fail(src%nrec, '*STEP', 'the deck ends inside a step: *END STEP missing')
      return
    end if
    call finish_model()

  contains

    ! ------------------------------------------------------------------ messages
    !> Source position of record irec (file, line) with the current keyword.
    subroutine set_pos(pos, irec)
      type(source_pos_t), intent(out) :: pos
      integer, intent(in) :: irec
      pos%file = src%files(src%rec(irec)%file_id)%name
      pos%line = src%rec(irec)%line
      pos%keyword = kw
    end subroutine set_pos

    subroutine fail(irec, keyword, msg)
      integer, intent(in) :: irec
      character(len=*), intent(in) :: keyword, msg
      stat = 2
      errmsg = deck_where(src, irec)//': '//trim(keyword)//': '//msg
    end subroutine fail

    subroutine warn(irec, keyword, msg)
      integer, intent(in) :: irec
      character(len=*), intent(in) :: keyword, msg
      if (wu /= -1) write (wu, '(a)') 'ldfcz: warning: '//deck_where(src, irec)//': '//trim(keyword)//': '//msg
    end subroutine warn

    !> Error when a parameter outside the list is present.
    subroutine allow_params(names)
      character(len=*), intent(in) :: names(:)
      integer :: i
      do i = 1, size(params)
        if (all(params(i)%name /= names)) then
          call fail(ir, kw, 'unsupported parameter '//params(i)%name)
          return
        end if
      end do
    end subroutine allow_params

    subroutine need_step()
      if (.not. in_step) call fail(ir, kw, 'history keyword outside a step')
    end subroutine need_step

    !> Required parameter value, upper case for names.
    function required(name) result(v)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: v
      v = ''
      if (.not. deck_has_param(params, name)) then
        call fail(ir, kw, 'parameter '//name//'= is required')
        return
      end if
      v = deck_param_value(params, name)
      if (len_trim(v) == 0) call fail(ir, kw, 'parameter '//name//'= has no value')
    end function required

    integer function param_int(name, default) result(v)
      character(len=*), intent(in) :: name
      integer, intent(in) :: default
      logical :: ok
      character(len=:), allocatable :: why
      v = default
      if (.not. deck_has_param(params, name)) return
      call deck_parse_int(deck_param_value(params, name), v, ok, why)
      if (.not. ok) call fail(ir, kw, 'parameter '//name//': '//why)
    end function param_int

    !> Data fields of records i1..i2 concatenated.
    subroutine block_fields(i1, i2, fields, nf)
      integer, intent(in) :: i1, i2
      character(len=flen), allocatable, intent(out) :: fields(:)
      integer, intent(out) :: nf
      character(len=flen), allocatable :: f(:), tmp(:)
      integer :: i, n
      allocate (fields(16))
      nf = 0
      do i = i1, i2
        call split(i, f, n)
        do while (nf + n > size(fields))
          allocate (tmp(2 * size(fields)))
          tmp(1:nf) = fields(1:nf)
          call move_alloc(tmp, fields)
        end do
        fields(nf + 1:nf + n) = f(1:n)
        nf = nf + n
      end do
    end subroutine block_fields

    subroutine split(irec, f, n)
      integer, intent(in) :: irec
      character(len=flen), allocatable, intent(out) :: f(:)
      integer, intent(out) :: n
      character(len=len(src%rec(irec)%text)), allocatable :: g(:)
      integer :: i
      call deck_split_fields(src%rec(irec)%text, g, n)
      allocate (f(n))
      do i = 1, n
        f(i) = g(i)
      end do
    end subroutine split

    logical function get_real(irec, field, v)
      integer, intent(in) :: irec
      character(len=*), intent(in) :: field
      real(dp), intent(out) :: v
      character(len=:), allocatable :: why
      logical :: ok
      call deck_parse_real(field, v, ok, why)
      if (.not. ok) call fail(irec, kw, why)
      get_real = ok
    end function get_real

    logical function get_int(irec, field, v)
      integer, intent(in) :: irec
      character(len=*), intent(in) :: field
      integer, intent(out) :: v
      character(len=:), allocatable :: why
      logical :: ok
      call deck_parse_int(field, v, ok, why)
      if (.not. ok) call fail(irec, kw, why)
      get_int = ok
    end function get_int

    ! ------------------------------------------------------------------ model data
    subroutine read_node()
      integer :: i, n, id, k, iset
      character(len=flen), allocatable :: f(:)
      real(dp) :: c
      character(len=:), allocatable :: setname
      call allow_params([character(len=8) :: 'NSET', 'SYSTEM', 'INPUT'])
      if (stat /= 0) return
      if (deck_has_param(params, 'SYSTEM')) then
        if (deck_upper(deck_param_value(params, 'SYSTEM')) /= 'R') then
          call fail(ir, kw, 'only SYSTEM=R (rectangular) is supported')
          return
        end if
      end if
      if (deck_has_param(params, 'INPUT')) then
        call fail(ir, kw, 'INPUT= on *NODE is not supported: use *INCLUDE')
        return
      end if
      iset = 0
      if (deck_has_param(params, 'NSET')) then
        setname = deck_normalize(required('NSET'))
        iset = get_nset(setname)
      end if
      do i = ir + 1, ir_next - 1
        call split(i, f, n)
        if (n < 2 .or. n > 4) then
          call fail(i, kw, 'expected: node number, x, y[, z]')
          return
        end if
        if (.not. get_int(i, f(1), id)) return
        if (id <= 0) then
          call fail(i, kw, 'node numbers must be positive')
          return
        end if
        if (model%nnode == size(model%node_id)) call grow_nodes()
        model%nnode = model%nnode + 1
        model%node_id(model%nnode) = id
        node_rec(model%nnode) = i
        model%x(:, model%nnode) = 0.0_dp
        do k = 2, n
          if (len_trim(f(k)) == 0) cycle
          if (.not. get_real(i, f(k), c)) return
          model%x(k - 1, model%nnode) = c
        end do
        if (iset > 0) call add_member(model%nsets(iset)%nodes, model%nsets(iset)%n, -id)
      end do
    end subroutine read_node

    subroutine read_element()
      character(len=:), allocatable :: tname, setname
      integer :: kind, nn, iu, i, n, k, id, iset
      character(len=flen), allocatable :: f(:)
      call allow_params([character(len=8) :: 'TYPE', 'ELSET'])
      if (stat /= 0) return
      tname = deck_normalize(required('TYPE'))
      if (stat /= 0) return
      iu = 0
      select case (tname)
      case ('C3D8')
        kind = etype_c3d8
        nn = 8
        call set_dim(3)
      case ('CPE4')
        kind = etype_cpe4
        nn = 4
        call set_dim(2)
      case default
        iu = model_find_user_type(model, tname)
        if (iu == 0) then
          if (tname(1:1) == 'U') then
            call fail(ir, kw, 'user element type '//tname//' not defined by an earlier *USER ELEMENT')
          else
            call fail(ir, kw, 'element type '//tname//' not supported (C3D8, CPE4 and user types Un)')
          end if
          return
        end if
        kind = etype_user
        nn = model%utypes(iu)%nnode
        call set_dim(model%utypes(iu)%mcrd)
      end select
      if (stat /= 0) return
      iset = 0
      if (deck_has_param(params, 'ELSET')) then
        setname = deck_normalize(required('ELSET'))
        iset = get_elset(setname)
      end if
      do i = ir + 1, ir_next - 1
        call split(i, f, n)
        if (n /= nn + 1) then
          call fail(i, kw, 'element type '//tname//' needs '//itoa(nn)//' nodes, '//itoa(n - 1)//' given')
          return
        end if
        if (.not. get_int(i, f(1), id)) return
        if (id <= 0) then
          call fail(i, kw, 'element numbers must be positive')
          return
        end if
        if (model%nelem == size(model%elem_id)) call grow_elems()
        model%nelem = model%nelem + 1
        model%elem_id(model%nelem) = id
        model%elem_kind(model%nelem) = kind
        model%elem_utype(model%nelem) = iu
        elem_rec(model%nelem) = i
        do while (model%conn_ptr(model%nelem) + nn > size(conn_raw))
          call grow_int(conn_raw)
        end do
        do k = 1, nn
          if (.not. get_int(i, f(k + 1), conn_raw(model%conn_ptr(model%nelem) + k - 1))) return
        end do
        model%conn_ptr(model%nelem + 1) = model%conn_ptr(model%nelem) + nn
        if (iset > 0) call add_member(model%elsets(iset)%elems, model%elsets(iset)%n, -id)
      end do
    end subroutine read_element

    subroutine set_dim(nd)
      integer, intent(in) :: nd
      if (nd /= 2 .and. nd /= 3) then
        call fail(ir, kw, 'only 2D (plane strain) and 3D models are supported')
      else if (model%ndim == 0) then
        model%ndim = nd
      else if (model%ndim /= nd) then
        call fail(ir, kw, 'mixing 2D and 3D element types in one model is not supported')
      end if
    end subroutine set_dim

    !> *NSET / *ELSET. Members are stored as negative user ids until finish_model resolves them; set names in data
    !> lines are expanded at once (they must be defined before).
    subroutine read_set(is_node)
      logical, intent(in) :: is_node
      character(len=:), allocatable :: setname
      integer :: iset, i, n, k, a, b, s, other, j
      character(len=flen), allocatable :: f(:)
      logical :: gen
      if (is_node) then
        call allow_params([character(len=12) :: 'NSET', 'GENERATE', 'INTERNAL', 'UNSORTED', 'ELSET'])
        if (stat /= 0) return
        setname = deck_normalize(required('NSET'))
      else
        call allow_params([character(len=12) :: 'ELSET', 'GENERATE', 'INTERNAL', 'UNSORTED'])
        if (stat /= 0) return
        setname = deck_normalize(required('ELSET'))
      end if
      if (stat /= 0) return
      if (is_node .and. deck_has_param(params, 'ELSET')) then
        call fail(ir, kw, 'NSET from ELSET= is not supported: list the nodes')
        return
      end if
      gen = deck_has_param(params, 'GENERATE')
      if (is_node) then
        iset = get_nset(setname)
      else
        iset = get_elset(setname)
      end if
      do i = ir + 1, ir_next - 1
        call split(i, f, n)
        if (gen) then
          if (n < 2 .or. n > 3) then
            call fail(i, kw, 'GENERATE expects: first, last[, increment]')
            return
          end if
          if (.not. get_int(i, f(1), a)) return
          if (.not. get_int(i, f(2), b)) return
          s = 1
          if (n == 3) then
            if (len_trim(f(3)) > 0) then
              if (.not. get_int(i, f(3), s)) return
            end if
          end if
          if (s <= 0 .or. b < a) then
            call fail(i, kw, 'GENERATE needs first <= last and a positive increment')
            return
          end if
          if (a < 1) then
            call fail(i, kw, 'ids must be positive, got '//itoa(a))
            return
          end if
          do k = a, b, s
            if (is_node) then
              call add_member(model%nsets(iset)%nodes, model%nsets(iset)%n, -k)
            else
              call add_member(model%elsets(iset)%elems, model%elsets(iset)%n, -k)
            end if
          end do
        else
          do k = 1, n
            if (len_trim(f(k)) == 0) cycle
            if (verify(trim(f(k)), '0123456789+-') == 0) then
              if (.not. get_int(i, f(k), a)) return
              if (a < 1) then
                call fail(i, kw, 'ids must be positive, got '//itoa(a))
                return
              end if
              if (is_node) then
                call add_member(model%nsets(iset)%nodes, model%nsets(iset)%n, -a)
              else
                call add_member(model%elsets(iset)%elems, model%elsets(iset)%n, -a)
              end if
            else
              if (is_node) then
                other = model_find_nset(model, deck_normalize(f(k)))
              else
                other = model_find_elset(model, deck_normalize(f(k)))
              end if
              if (other == 0 .or. other == iset) then
                call fail(i, kw, 'undefined set '//trim(deck_normalize(f(k))))
                return
              end if
              if (is_node) then
                do j = 1, model%nsets(other)%n
                  call add_member(model%nsets(iset)%nodes, model%nsets(iset)%n, model%nsets(other)%nodes(j))
                end do
              else
                do j = 1, model%elsets(other)%n
                  call add_member(model%elsets(iset)%elems, model%elsets(iset)%n, model%elsets(other)%elems(j))
                end do
              end if
            end if
          end do
        end if
      end do
    end subroutine read_set

    integer function get_nset(name) result(k)
      character(len=*), intent(in) :: name
      type(node_set_t), allocatable :: tmp(:)
      k = model_find_nset(model, name)
      if (k > 0) return
      if (model%n_nset == size(model%nsets)) then
        allocate (tmp(2 * size(model%nsets)))
        tmp(1:model%n_nset) = model%nsets(1:model%n_nset)
        call move_alloc(tmp, model%nsets)
      end if
      model%n_nset = model%n_nset + 1
      k = model%n_nset
      model%nsets(k)%name = name
      allocate (model%nsets(k)%nodes(0))
    end function get_nset

    integer function get_elset(name) result(k)
      character(len=*), intent(in) :: name
      type(elem_set_t), allocatable :: tmp(:)
      k = model_find_elset(model, name)
      if (k > 0) return
      if (model%n_elset == size(model%elsets)) then
        allocate (tmp(2 * size(model%elsets)))
        tmp(1:model%n_elset) = model%elsets(1:model%n_elset)
        call move_alloc(tmp, model%elsets)
      end if
      model%n_elset = model%n_elset + 1
      k = model%n_elset
      model%elsets(k)%name = name
      allocate (model%elsets(k)%elems(0))
    end function get_elset

    subroutine read_solid_section()
      type(section_t), allocatable :: tmp(:)
      character(len=flen), allocatable :: f(:)
      integer :: n, k
      real(dp) :: t
      call allow_params([character(len=12) :: 'ELSET', 'MATERIAL'])
      if (stat /= 0) return
      if (model%nsection == size(model%sections)) then
        allocate (tmp(2 * size(model%sections)))
        tmp(1:model%nsection) = model%sections(1:model%nsection)
        call move_alloc(tmp, model%sections)
      end if
      k = model%nsection + 1
      model%sections(k)%elset = deck_normalize(required('ELSET'))
      if (stat /= 0) return
      model%sections(k)%material = deck_normalize(required('MATERIAL'))
      if (stat /= 0) return
      model%sections(k)%pos%file = src%files(src%rec(ir)%file_id)%name
      model%sections(k)%pos%line = src%rec(ir)%line
      model%sections(k)%pos%keyword = kw
      model%sections(k)%thickness = 1.0_dp
      if (ir_next > ir + 2) then
        call fail(ir + 2, kw, 'more than one data line (only the thickness line is read)')
        return
      end if
      if (ir_next == ir + 2) then
        call split(ir + 1, f, n)
        if (n > 1) then
          do k = 2, n
            if (len_trim(f(k)) > 0) then
              call fail(ir + 1, kw, 'only the first field (thickness) of the data line is supported')
              return
            end if
          end do
        end if
        if (len_trim(f(1)) > 0) then
          if (.not. get_real(ir + 1, f(1), t)) return
          if (t <= 0.0_dp) then
            call fail(ir + 1, kw, 'thickness must be positive')
            return
          end if
          model%sections(model%nsection + 1)%thickness = t
        end if
      end if
      model%nsection = model%nsection + 1
    end subroutine read_solid_section

    subroutine read_material()
      type(material_t), allocatable :: tmp(:)
      character(len=:), allocatable :: name
      call allow_params([character(len=8) :: 'NAME'])
      if (stat /= 0) return
      name = required('NAME')
      if (stat /= 0) return
      if (model_find_material(model, deck_normalize(name)) > 0) then
        call fail(ir, kw, 'material '//name//' defined twice')
        return
      end if
      if (model%nmat == size(model%materials)) then
        allocate (tmp(2 * size(model%materials)))
        tmp(1:model%nmat) = model%materials(1:model%nmat)
        call move_alloc(tmp, model%materials)
      end if
      model%nmat = model%nmat + 1
      imat = model%nmat
      model%materials(imat)%name = deck_normalize(name)
      model%materials(imat)%given_name = name
      model%materials(imat)%pos%file = src%files(src%rec(ir)%file_id)%name
      model%materials(imat)%pos%line = src%rec(ir)%line
      model%materials(imat)%pos%keyword = kw
      if (ir_next > ir + 1) call fail(ir + 1, kw, 'no data lines expected')
    end subroutine read_material

    subroutine need_material()
      if (imat == 0) call fail(ir, kw, 'material option outside a *MATERIAL definition')
    end subroutine need_material

    subroutine read_elastic()
      character(len=flen), allocatable :: f(:)
      integer :: n
      real(dp) :: e, nu
      call need_material()
      if (stat /= 0) return
      call allow_params([character(len=8) :: 'TYPE'])
      if (stat /= 0) return
      if (deck_has_param(params, 'TYPE')) then
        if (deck_normalize(deck_param_value(params, 'TYPE')) /= 'ISOTROPIC') then
          call fail(ir, kw, 'only TYPE=ISOTROPIC is supported')
          return
        end if
      end if
      if (ir_next /= ir + 2) then
        call fail(ir, kw, 'exactly one data line (E, nu) expected (no temperature dependence)')
        return
      end if
      call split(ir + 1, f, n)
      if (n < 2) then
        call fail(ir + 1, kw, 'data line needs E, nu')
        return
      end if
      if (n > 2) then
        if (len_trim(f(3)) > 0) then
          call fail(ir + 1, kw, 'temperature-dependent elasticity is not supported')
          return
        end if
      end if
      if (.not. get_real(ir + 1, f(1), e)) return
      if (.not. get_real(ir + 1, f(2), nu)) return
      if (e <= 0.0_dp .or. nu <= -1.0_dp .or. nu >= 0.5_dp) then
        call fail(ir + 1, kw, 'need E > 0 and -1 < nu < 0.5')
        return
      end if
      model%materials(imat)%has_elastic = .true.
      model%materials(imat)%young = e
      model%materials(imat)%poisson = nu
    end subroutine read_elastic

    subroutine read_user_material()
      character(len=flen), allocatable :: f(:)
      integer :: n, nc, k
      call need_material()
      if (stat /= 0) return
      call allow_params([character(len=12) :: 'CONSTANTS', 'UNSYMM', 'TYPE'])
      if (stat /= 0) return
      if (deck_has_param(params, 'TYPE')) then
        if (deck_normalize(deck_param_value(params, 'TYPE')) /= 'MECHANICAL') then
          call fail(ir, kw, 'only TYPE=MECHANICAL is supported')
          return
        end if
      end if
      nc = param_int('CONSTANTS', 0)
      if (stat /= 0) return
      call block_fields(ir + 1, ir_next - 1, f, n)
      if (n /= nc) then
        call fail(ir, kw, 'CONSTANTS='//itoa(nc)//' but '//itoa(n)//' values given')
        return
      end if
      allocate (model%materials(imat)%props(nc))
      do k = 1, nc
        if (.not. get_real(ir + 1, f(k), model%materials(imat)%props(k))) return
      end do
      model%materials(imat)%has_user = .true.
      model%materials(imat)%unsymm = deck_has_param(params, 'UNSYMM')
      call set_pos(model%materials(imat)%user_pos, min(ir + 1, ir_next - 1))
    end subroutine read_user_material

    subroutine read_depvar()
      character(len=flen), allocatable :: f(:)
      integer :: n
      call need_material()
      if (stat /= 0) return
      call allow_params([character(len=8) :: 'DELETE'])
      if (stat /= 0) return
      if (deck_has_param(params, 'DELETE')) then
        call fail(ir, kw, 'DELETE= (element deletion) is not supported')
        return
      end if
      if (ir_next /= ir + 2) then
        call fail(ir, kw, 'one data line (number of state variables) expected')
        return
      end if
      call split(ir + 1, f, n)
      if (.not. get_int(ir + 1, f(1), model%materials(imat)%nstatv)) return
      if (model%materials(imat)%nstatv < 0) call fail(ir + 1, kw, 'negative number of state variables')
    end subroutine read_depvar

    subroutine read_user_element()
      type(user_element_type_t) :: ut
      type(user_element_type_t), allocatable :: tmp(:)
      character(len=flen), allocatable :: f(:)
      integer :: n, k
      call allow_params([character(len=12) :: 'TYPE', 'NODES', 'COORDINATES', 'PROPERTIES', 'I PROPERTIES', &
        'VARIABLES', 'UNSYMM', 'INTEGRATION', 'TENSOR'])
      if (stat /= 0) return
      if (deck_has_param(params, 'INTEGRATION') .or. deck_has_param(params, 'TENSOR')) then
        call fail(ir, kw, 'INTEGRATION/TENSOR (UMAT inside UEL) are not supported')
        return
      end if
      ut%name = deck_normalize(required('TYPE'))
      if (stat /= 0) return
      if (ut%name(1:1) /= 'U' .or. verify(trim(ut%name(2:)), '0123456789') /= 0 .or. len_trim(ut%name) < 2) then
        call fail(ir, kw, 'TYPE must be Un with n a number, got '//trim(ut%name))
        return
      end if
      read (ut%name(2:), *) ut%jtype
      if (model_find_user_type(model, ut%name) > 0) then
        call fail(ir, kw, 'user element '//trim(ut%name)//' defined twice')
        return
      end if
      ut%nnode = param_int('NODES', 0)
      ut%mcrd = param_int('COORDINATES', 3)
      ut%nprops = param_int('PROPERTIES', 0)
      ut%njprops = param_int('I PROPERTIES', 0)
      ut%nsvars = param_int('VARIABLES', 1)
      if (stat /= 0) return
      if (ut%nnode <= 0) then
        call fail(ir, kw, 'NODES= must be given and positive')
        return
      end if
      if (ut%mcrd < 2 .or. ut%mcrd > 3) then
        call fail(ir, kw, 'COORDINATES must be 2 or 3')
        return
      end if
      if (ut%nprops < 0 .or. ut%njprops < 0 .or. ut%nsvars < 0) then
        call fail(ir, kw, 'negative PROPERTIES, I PROPERTIES or VARIABLES')
        return
      end if
      ut%unsymm = deck_has_param(params, 'UNSYMM')
      if (ir_next == ir + 1) then
        call fail(ir, kw, 'the active-dof data line is missing')
        return
      end if
      if (ir_next > ir + 2) then
        call fail(ir + 2, kw, 'node-dependent active-dof lines are not supported (one line for all nodes)')
        return
      end if
      call split(ir + 1, f, n)
      allocate (ut%active(n))
      do k = 1, n
        if (.not. get_int(ir + 1, f(k), ut%active(k))) return
        if (ut%active(k) < 1 .or. ut%active(k) > ut%mcrd) then
          call fail(ir + 1, kw, 'active dof '//itoa(ut%active(k))//' not a displacement dof 1..COORDINATES')
          return
        end if
      end do
      ut%pos%file = src%files(src%rec(ir)%file_id)%name
      ut%pos%line = src%rec(ir)%line
      ut%pos%keyword = kw
      if (model%nutype == size(model%utypes)) then
        allocate (tmp(2 * size(model%utypes)))
        tmp(1:model%nutype) = model%utypes(1:model%nutype)
        call move_alloc(tmp, model%utypes)
      end if
      model%nutype = model%nutype + 1
      model%utypes(model%nutype) = ut
    end subroutine read_user_element

    subroutine read_uel_property()
      character(len=:), allocatable :: setname
      integer :: iset, iu, k, n, e, ie, ip, np, nj
      character(len=flen), allocatable :: f(:)
      type(uel_property_t), allocatable :: tmp(:)
      call allow_params([character(len=8) :: 'ELSET'])
      if (stat /= 0) return
      setname = deck_normalize(required('ELSET'))
      if (stat /= 0) return
      iset = model_find_elset(model, setname)
      if (iset == 0) then
        call fail(ir, kw, 'undefined element set '//setname)
        return
      end if
      ! the user type of the set's elements
      iu = 0
      do k = 1, model%elsets(iset)%n
        e = -model%elsets(iset)%elems(k)
        ie = find_elem_raw(e)
        if (ie == 0) then
          call fail(ir, kw, 'element '//itoa(e)//' of set '//setname//' is not defined')
          return
        end if
        if (model%elem_kind(ie) /= etype_user) then
          call fail(ir, kw, 'element '//itoa(e)//' of set '//setname//' is not a user element')
          return
        end if
        if (iu == 0) iu = model%elem_utype(ie)
        if (model%elem_utype(ie) /= iu) then
          call fail(ir, kw, 'set '//setname//' mixes user element types')
          return
        end if
      end do
      if (iu == 0) then
        call fail(ir, kw, 'element set '//setname//' is empty')
        return
      end if
      np = model%utypes(iu)%nprops
      nj = model%utypes(iu)%njprops
      call block_fields(ir + 1, ir_next - 1, f, n)
      if (n /= np + nj) then
        call fail(ir, kw, 'type '//trim(model%utypes(iu)%name)//' needs PROPERTIES='//itoa(np)//' reals and '// &
          'I PROPERTIES='//itoa(nj)//' integers, '//itoa(n)//' values given')
        return
      end if
      if (model%n_uelprop == size(model%uelprops)) then
        allocate (tmp(2 * size(model%uelprops)))
        tmp(1:model%n_uelprop) = model%uelprops(1:model%n_uelprop)
        call move_alloc(tmp, model%uelprops)
      end if
      ip = model%n_uelprop + 1
      allocate (model%uelprops(ip)%props(np), model%uelprops(ip)%jprops(nj))
      do k = 1, np
        if (.not. get_real(ir + 1, f(k), model%uelprops(ip)%props(k))) return
      end do
      do k = 1, nj
        if (.not. get_int(ir + 1, f(np + k), model%uelprops(ip)%jprops(k))) then
          errmsg = errmsg//' (integer property '//itoa(k)//')'
          return
        end if
      end do
      model%n_uelprop = ip
      call set_pos(model%uelprops(ip)%pos, min(ir + 1, ir_next - 1))
      if (.not. allocated(model%elem_uelprop)) then
        allocate (model%elem_uelprop(size(model%elem_id)))
        model%elem_uelprop = 0
      end if
      if (size(model%elem_uelprop) < model%nelem) call grow_int(model%elem_uelprop, model%nelem)
      do k = 1, model%elsets(iset)%n
        ie = find_elem_raw(-model%elsets(iset)%elems(k))
        model%elem_uelprop(ie) = ip
      end do
    end subroutine read_uel_property

    !> Element index of a user element id while reading (linear search only in *UEL PROPERTY).
    integer function find_elem_raw(id) result(ie)
      integer, intent(in) :: id
      do ie = 1, model%nelem
        if (model%elem_id(ie) == id) return
      end do
      ie = 0
    end function find_elem_raw

    subroutine read_amplitude()
      type(amplitude_t), allocatable :: tmp(:)
      character(len=flen), allocatable :: f(:)
      integer :: n, k, ia
      character(len=:), allocatable :: v
      call allow_params([character(len=12) :: 'NAME', 'DEFINITION', 'TIME', 'VALUE'])
      if (stat /= 0) return
      v = deck_normalize(deck_param_value(params, 'DEFINITION'))
      if (len(v) > 0 .and. v /= 'TABULAR') then
        call fail(ir, kw, 'only DEFINITION=TABULAR is supported')
        return
      end if
      v = deck_normalize(deck_param_value(params, 'TIME'))
      if (len(v) > 0 .and. v /= 'STEP TIME') then
        call fail(ir, kw, 'only TIME=STEP TIME is supported')
        return
      end if
      v = deck_normalize(deck_param_value(params, 'VALUE'))
      if (len(v) > 0 .and. v /= 'RELATIVE') then
        call fail(ir, kw, 'only VALUE=RELATIVE is supported')
        return
      end if
      if (model%namp == size(model%amplitudes)) then
        allocate (tmp(2 * size(model%amplitudes)))
        tmp(1:model%namp) = model%amplitudes(1:model%namp)
        call move_alloc(tmp, model%amplitudes)
      end if
      ia = model%namp + 1
      model%amplitudes(ia)%name = deck_normalize(required('NAME'))
      if (stat /= 0) return
      if (model_find_amplitude(model, model%amplitudes(ia)%name) > 0) then
        call fail(ir, kw, 'amplitude '//trim(model%amplitudes(ia)%name)//' defined twice')
        return
      end if
      call block_fields(ir + 1, ir_next - 1, f, n)
      if (n < 2 .or. mod(n, 2) /= 0) then
        call fail(ir, kw, 'data must be pairs of time, amplitude')
        return
      end if
      allocate (model%amplitudes(ia)%t(n / 2), model%amplitudes(ia)%a(n / 2))
      do k = 1, n / 2
        if (.not. get_real(ir + 1, f(2 * k - 1), model%amplitudes(ia)%t(k))) return
        if (.not. get_real(ir + 1, f(2 * k), model%amplitudes(ia)%a(k))) return
        if (k > 1) then
          if (model%amplitudes(ia)%t(k) < model%amplitudes(ia)%t(k - 1)) then
            call fail(ir, kw, 'times must not decrease')
            return
          end if
        end if
      end do
      model%namp = ia
    end subroutine read_amplitude

    subroutine read_boundary()
      type(boundary_t) :: bc, empty_bc
      character(len=flen), allocatable :: f(:)
      integer :: i, n, id, iset, iamp
      character(len=:), allocatable :: v, word
      call allow_params([character(len=12) :: 'AMPLITUDE', 'OP', 'TYPE'])
      if (stat /= 0) return
      v = deck_normalize(deck_param_value(params, 'TYPE'))
      if (len(v) > 0 .and. v /= 'DISPLACEMENT') then
        call fail(ir, kw, 'only TYPE=DISPLACEMENT is supported')
        return
      end if
      v = deck_normalize(deck_param_value(params, 'OP'))
      if (len(v) > 0 .and. v /= 'MOD' .and. v /= 'NEW') then
        call fail(ir, kw, 'OP must be MOD or NEW')
        return
      end if
      if (v == 'NEW') then
        if (.not. in_step) then
          call fail(ir, kw, 'OP=NEW only inside a step')
          return
        end if
        model%steps(istep)%op_new = .true.
      end if
      iamp = 0
      if (deck_has_param(params, 'AMPLITUDE')) then
        if (.not. in_step) then
          call fail(ir, kw, 'AMPLITUDE= only inside a step')
          return
        end if
        iamp = model_find_amplitude(model, deck_normalize(deck_param_value(params, 'AMPLITUDE')))
        if (iamp == 0) then
          call fail(ir, kw, 'undefined amplitude '//deck_normalize(deck_param_value(params, 'AMPLITUDE')))
          return
        end if
      end if
      do i = ir + 1, ir_next - 1
        call split(i, f, n)
        bc = empty_bc
        bc%amplitude = iamp
        bc%pos%file = src%files(src%rec(i)%file_id)%name
        bc%pos%line = src%rec(i)%line
        bc%pos%keyword = kw
        if (n < 2) then
          call fail(i, kw, 'expected: node or node set, first dof[, last dof[, value]] or a type (XSYMM, ...)')
          return
        end if
        if (verify(trim(f(1)), '0123456789+-') == 0) then
          if (.not. get_int(i, f(1), id)) return
          if (id < 1) then
            call fail(i, kw, 'node ids must be positive, got '//itoa(id))
            return
          end if
          allocate (bc%nodes(1))
          bc%nodes(1) = -id  ! resolved in finish_model
        else
          iset = model_find_nset(model, deck_normalize(f(1)))
          if (iset == 0) then
            call fail(i, kw, 'undefined node set '//deck_normalize(f(1)))
            return
          end if
          bc%nodes = model%nsets(iset)%nodes(1:model%nsets(iset)%n)
        end if
        word = deck_normalize(f(2))
        if (verify(trim(f(2)), '0123456789+-') /= 0) then
          if (n > 2) then
            if (any(len_trim(f(3:n)) > 0)) then
              call fail(i, kw, 'no values may follow a boundary type')
              return
            end if
          end if
          select case (word)
          case ('XSYMM')
            bc%first_dof = 1
            bc%last_dof = 1
          case ('YSYMM')
            bc%first_dof = 2
            bc%last_dof = 2
          case ('ZSYMM')
            bc%first_dof = 3
            bc%last_dof = 3
          case ('ENCASTRE', 'PINNED')
            bc%first_dof = 1
            bc%last_dof = 3
          case default
            call fail(i, kw, 'unsupported boundary type '//word//' (XSYMM, YSYMM, ZSYMM, ENCASTRE, PINNED)')
            return
          end select
        else
          if (.not. get_int(i, f(2), bc%first_dof)) return
          bc%last_dof = bc%first_dof
          if (n >= 3) then
            if (len_trim(f(3)) > 0) then
              if (.not. get_int(i, f(3), bc%last_dof)) return
            end if
          end if
          if (n >= 4) then
            if (len_trim(f(4)) > 0) then
              if (.not. get_real(i, f(4), bc%value)) return
            end if
          end if
          if (n > 4) then
            call fail(i, kw, 'too many fields')
            return
          end if
          if (bc%first_dof < 1 .or. bc%last_dof > 6 .or. bc%last_dof < bc%first_dof) then
            call fail(i, kw, 'dof range '//itoa(bc%first_dof)//'..'//itoa(bc%last_dof)//' invalid')
            return
          end if
          if (bc%last_dof > 3) then
            call fail(i, kw, 'rotational dofs 4..6 do not exist in ldfcz models')
            return
          end if
        end if
        if (in_step) then
          call push_bc(model%steps(istep)%bcs, model%steps(istep)%nbc, bc)
        else
          call push_bc(model%initial_bcs, model%n_initial_bc, bc)
        end if
      end do
    end subroutine read_boundary

    !> *RESTART, WRITE, FREQUENCY=n (model or history data; in effect for the following steps until changed):
    !> JOB.rst after every n-th increment and at the end of each step. READ is refused: ldfcz restarts with
    !> --restart-from JOB.rst JOB.inp on the unchanged deck (docs/host.md).
    subroutine read_restart()
      integer :: n
      call allow_params([character(len=16) :: 'WRITE', 'READ', 'FREQUENCY', 'OVERLAY', 'NUMBER INTERVAL', &
        'TIME MARKS', 'STEP', 'INC', 'END STEP'])
      if (stat /= 0) return
      if (deck_has_param(params, 'READ')) then
        call fail(ir, kw, 'READ is not supported: restart with ldfcz --restart-from JOB.rst JOB.inp on the '// &
          'unchanged deck (docs/host.md)')
        return
      end if
      if (.not. deck_has_param(params, 'WRITE')) then
        call fail(ir, kw, 'WRITE (or READ) is required')
        return
      end if
      if (deck_has_param(params, 'NUMBER INTERVAL') .or. deck_has_param(params, 'TIME MARKS')) then
        call fail(ir, kw, 'only FREQUENCY=n is supported (restart data after every n-th increment)')
        return
      end if
      n = param_int('FREQUENCY', 1)
      if (stat /= 0) return
      if (n < 0) then
        call fail(ir, kw, 'FREQUENCY must be >= 0 (0: no restart file)')
        return
      end if
      if (ir_next > ir + 1) then
        call fail(ir + 1, kw, 'no data lines expected')
        return
      end if
      restart_freq = n
      if (in_step) model%steps(istep)%restart_frequency = n
    end subroutine read_restart

    ! ------------------------------------------------------------------ history data
    subroutine read_step()
      type(step_t), allocatable :: tmp(:)
      type(step_t) :: empty_step
      character(len=:), allocatable :: v
      integer :: k
      if (in_step) then
        call fail(ir, kw, '*STEP inside a step: *END STEP missing')
        return
      end if
      call allow_params([character(len=16) :: 'NAME', 'NLGEOM', 'INC', 'UNSYMM', 'AMPLITUDE', 'EXTRAPOLATION', &
        'PERTURBATION'])
      if (stat /= 0) return
      if (deck_has_param(params, 'PERTURBATION')) then
        call fail(ir, kw, 'PERTURBATION steps are not supported')
        return
      end if
      if (model%nstep == size(model%steps)) then
        allocate (tmp(2 * size(model%steps)))
        tmp(1:model%nstep) = model%steps(1:model%nstep)
        call move_alloc(tmp, model%steps)
      end if
      model%nstep = model%nstep + 1
      istep = model%nstep
      model%steps(istep) = empty_step
      allocate (model%steps(istep)%bcs(4), model%steps(istep)%prints(2))
      ! NLGEOM carries over from the previous step, as in Abaqus
      if (istep > 1) model%steps(istep)%nlgeom = model%steps(istep - 1)%nlgeom
      ! a *RESTART, WRITE request stays in effect until changed (Abaqus)
      model%steps(istep)%restart_frequency = restart_freq
      if (deck_has_param(params, 'NLGEOM')) then
        v = deck_normalize(deck_param_value(params, 'NLGEOM'))
        if (v == '' .or. v == 'YES') then
          model%steps(istep)%nlgeom = .true.
        else if (v == 'NO') then
          if (istep > 1) then  ! (no short-circuit in Fortran: steps(0) must not be evaluated)
            if (model%steps(istep - 1)%nlgeom) then
              call fail(ir, kw, 'NLGEOM cannot be switched off after a geometrically nonlinear step')
              return
            end if
          end if
          model%steps(istep)%nlgeom = .false.
        else
          call fail(ir, kw, 'NLGEOM must be YES or NO')
          return
        end if
      end if
      model%steps(istep)%max_inc = param_int('INC', 100)
      if (stat /= 0) return
      if (model%steps(istep)%max_inc <= 0) then
        call fail(ir, kw, 'INC must be positive')
        return
      end if
      v = deck_normalize(deck_param_value(params, 'AMPLITUDE'))
      if (len(v) > 0 .and. v /= 'RAMP') then
        call fail(ir, kw, 'only AMPLITUDE=RAMP is supported in static steps')
        return
      end if
      v = deck_normalize(deck_param_value(params, 'EXTRAPOLATION'))
      if (len(v) > 0 .and. v /= 'NO') call warn(ir, kw, 'EXTRAPOLATION='//v//' ignored: ldfcz never extrapolates')
      v = deck_normalize(deck_param_value(params, 'UNSYMM'))
      if (v == 'YES' .or. v == '') then
        model%steps(istep)%unsymm = deck_has_param(params, 'UNSYMM')
      else if (v /= 'NO') then
        call fail(ir, kw, 'UNSYMM must be YES or NO')
        return
      end if
      model%steps(istep)%name = deck_param_value(params, 'NAME')
      model%steps(istep)%pos%file = src%files(src%rec(ir)%file_id)%name
      model%steps(istep)%pos%line = src%rec(ir)%line
      model%steps(istep)%pos%keyword = kw
      model%steps(istep)%period = -1.0_dp  ! marks "no *STATIC yet"
      do k = ir + 1, ir_next - 1
        ! a title line is allowed
        continue
      end do
      in_step = .true.
      imat = 0
    end subroutine read_step

    subroutine read_static()
      character(len=flen), allocatable :: f(:)
      integer :: n
      real(dp) :: v(4)
      logical :: given(4)
      integer :: k
      call need_step()
      if (stat /= 0) return
      call allow_params([character(len=12) :: 'DIRECT'])
      if (stat /= 0) return
      if (model%steps(istep)%period > 0.0_dp) then
        call fail(ir, kw, 'a second procedure in one step')
        return
      end if
      v = 0.0_dp
      given = .false.
      n = 0
      if (ir_next > ir + 2) then
        call fail(ir + 2, kw, 'one data line expected')
        return
      end if
      if (ir_next == ir + 2) then
        call split(ir + 1, f, n)
        if (n > 4) then
          call fail(ir + 1, kw, 'only initial, period, minimum and maximum increments are supported')
          return
        end if
        do k = 1, n
          if (len_trim(f(k)) == 0) cycle
          if (.not. get_real(ir + 1, f(k), v(k))) return
          if (v(k) <= 0.0_dp) then
            call fail(ir + 1, kw, 'time values must be positive')
            return
          end if
          given(k) = .true.
        end do
      end if
      associate (s => model%steps(istep))
        s%period = 1.0_dp
        if (given(2)) s%period = v(2)
        s%dt_initial = s%period
        if (given(1)) s%dt_initial = v(1)
        s%dt_min = min(s%dt_initial, 1.0e-5_dp * s%period)
        if (given(3)) s%dt_min = v(3)
        s%dt_max = s%period
        if (given(4)) s%dt_max = v(4)
        s%direct = deck_has_param(params, 'DIRECT')
        if (s%dt_initial > s%period * (1.0_dp + 1.0e-12_dp)) then
          call fail(ir + 1, kw, 'initial increment larger than the step period')
          return
        end if
        if (s%dt_min > s%dt_initial .and. .not. s%direct) then
          call fail(ir + 1, kw, 'minimum increment larger than the initial increment')
          return
        end if
        if (s%dt_max < s%dt_initial .and. .not. s%direct) then
          call fail(ir + 1, kw, 'maximum increment smaller than the initial increment')
          return
        end if
      end associate
    end subroutine read_static

    subroutine read_controls()
      character(len=:), allocatable :: v
      character(len=flen), allocatable :: f(:)
      integer :: n, k, iv
      real(dp) :: r
      call need_step()
      if (stat /= 0) return
      call allow_params([character(len=12) :: 'PARAMETERS', 'RESET', 'ANALYSIS'])
      if (stat /= 0) return
      if (deck_has_param(params, 'ANALYSIS')) then
        call fail(ir, kw, 'ANALYSIS= is not supported')
        return
      end if
      if (deck_has_param(params, 'RESET')) then
        model%steps(istep)%max_iter = 16
        model%steps(istep)%r_n = 0.005_dp
        model%steps(istep)%c_n = 0.01_dp
        if (.not. deck_has_param(params, 'PARAMETERS')) return
      end if
      v = deck_normalize(required('PARAMETERS'))
      if (stat /= 0) return
      if (ir_next > ir + 2) then
        call fail(ir + 2, kw, 'only the first data line is supported')
        return
      end if
      if (ir_next == ir + 1) return
      call split(ir + 1, f, n)
      select case (v)
      case ('TIME INCREMENTATION')
        ! I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A: ldfcz supports I_C (iteration cap); others must stay blank
        do k = 1, n
          if (len_trim(f(k)) == 0) cycle
          if (k /= 4) then
            call fail(ir + 1, kw, 'only field 4 (I_C, maximum iterations) of TIME INCREMENTATION is supported')
            return
          end if
          if (.not. get_int(ir + 1, f(k), iv)) return
          if (iv < 2) then
            call fail(ir + 1, kw, 'I_C must be at least 2')
            return
          end if
          model%steps(istep)%max_iter = iv
        end do
      case ('FIELD')
        ! R_n, C_n, q0, qu, R_P, eps_l, ...: ldfcz supports R_n and C_n
        do k = 1, n
          if (len_trim(f(k)) == 0) cycle
          if (k > 2) then
            call fail(ir + 1, kw, 'only R_n and C_n (fields 1, 2) of FIELD are supported')
            return
          end if
          if (.not. get_real(ir + 1, f(k), r)) return
          if (r <= 0.0_dp .or. r >= 1.0_dp) then
            call fail(ir + 1, kw, 'tolerances must lie in (0, 1)')
            return
          end if
          if (k == 1) model%steps(istep)%r_n = r
          if (k == 2) model%steps(istep)%c_n = r
        end do
      case default
        call fail(ir, kw, 'PARAMETERS='//v//' not supported (TIME INCREMENTATION, FIELD)')
      end select
    end subroutine read_controls

    subroutine read_output()
      integer :: k
      call need_step()
      if (stat /= 0) return
      call allow_params([character(len=16) :: 'FIELD', 'HISTORY', 'FREQUENCY', 'NUMBER INTERVAL', 'VARIABLE', &
        'TIME MARKS', 'OP'])
      if (stat /= 0) return
      if (deck_has_param(params, 'FIELD')) then
        model%steps(istep)%field_output = .true.
        k = param_int('FREQUENCY', 1)
        if (stat /= 0) return
        if (k < 0) then
          call fail(ir, kw, 'FREQUENCY must not be negative')
          return
        end if
        model%steps(istep)%field_frequency = k
        k = param_int('NUMBER INTERVAL', 0)
        if (stat /= 0) return
        if (k < 0) then
          call fail(ir, kw, 'NUMBER INTERVAL must not be negative')
          return
        end if
        model%steps(istep)%field_intervals = k
      else if (.not. deck_has_param(params, 'HISTORY')) then
        call fail(ir, kw, 'FIELD or HISTORY required')
      end if
    end subroutine read_output

    subroutine read_node_print()
      type(node_print_t) :: np
      type(node_print_t), allocatable :: tmp(:)
      character(len=flen), allocatable :: f(:)
      character(len=8), allocatable :: vars(:)
      integer :: i, n, k, nv
      character(len=:), allocatable :: name, v
      call need_step()
      if (stat /= 0) return
      call allow_params([character(len=12) :: 'NSET', 'TOTALS', 'FREQUENCY', 'SUMMARY', 'GLOBAL'])
      if (stat /= 0) return
      np%nset = deck_normalize(required('NSET'))
      if (stat /= 0) return
      np%set_index = model_find_nset(model, np%nset)
      if (np%set_index == 0) then
        call fail(ir, kw, 'undefined node set '//trim(np%nset))
        return
      end if
      v = deck_normalize(deck_param_value(params, 'TOTALS'))
      if (v /= 'YES') call warn(ir, kw, 'ldfcz writes set totals (RF sums, U means) to JOB.csv as with TOTALS=YES')
      allocate (vars(3 * (ir_next - ir) * 8 + 6))
      nv = 0
      do i = ir + 1, ir_next - 1
        call split(i, f, n)
        do k = 1, n
          name = deck_normalize(f(k))
          if (len(name) == 0) cycle
          select case (name)
          case ('U1', 'U2', 'U3', 'RF1', 'RF2', 'RF3')
            call add_var(vars, nv, name)
          case ('U')
            call add_var(vars, nv, 'U1')
            call add_var(vars, nv, 'U2')
            if (model%ndim /= 2) call add_var(vars, nv, 'U3')
          case ('RF')
            call add_var(vars, nv, 'RF1')
            call add_var(vars, nv, 'RF2')
            if (model%ndim /= 2) call add_var(vars, nv, 'RF3')
          case default
            call warn(i, kw, 'variable '//name//' not supported in JOB.csv (U1..U3, RF1..RF3): ignored')
          end select
        end do
      end do
      if (nv == 0) then
        call warn(ir, kw, 'no supported variable requested: no column written')
        return
      end if
      np%vars = vars(1:nv)
      associate (s => model%steps(istep))
        if (s%nprint == size(s%prints)) then
          allocate (tmp(2 * size(s%prints)))
          tmp(1:s%nprint) = s%prints(1:s%nprint)
          call move_alloc(tmp, s%prints)
        end if
        s%nprint = s%nprint + 1
        s%prints(s%nprint) = np
      end associate
    end subroutine read_node_print

    ! ------------------------------------------------------------------ resolution and checks
    subroutine finish_model()
      integer :: maxid, i, k, id, ie, isec, iset, im, is, ib, iu
      logical, allocatable :: has_section(:)
      if (model%nnode == 0) then
        call fail(1, '*NODE', 'the deck defines no nodes')
        return
      end if
      if (model%nelem == 0) then
        call fail(1, '*ELEMENT', 'the deck defines no elements')
        return
      end if
      if (model%nstep == 0) then
        call fail(src%nrec, '*STEP', 'the deck defines no step')
        return
      end if
      ! node ids
      maxid = maxval(model%node_id(1:model%nnode))
      allocate (model%node_index(maxid))
      model%node_index = 0
      do i = 1, model%nnode
        id = model%node_id(i)
        if (model%node_index(id) /= 0) then
          call fail(node_rec(i), '*NODE', 'node '//itoa(id)//' defined twice (first at '// &
            deck_where(src, node_rec(model%node_index(id)))//')')
          return
        end if
        model%node_index(id) = i
      end do
      model%node_id = model%node_id(1:model%nnode)
      model%x = model%x(:, 1:model%nnode)
      ! element ids and connectivity
      maxid = maxval(model%elem_id(1:model%nelem))
      allocate (model%elem_index(maxid))
      model%elem_index = 0
      do ie = 1, model%nelem
        id = model%elem_id(ie)
        if (model%elem_index(id) /= 0) then
          call fail(elem_rec(ie), '*ELEMENT', 'element '//itoa(id)//' defined twice (first at '// &
            deck_where(src, elem_rec(model%elem_index(id)))//')')
          return
        end if
        model%elem_index(id) = ie
        do k = model%conn_ptr(ie), model%conn_ptr(ie + 1) - 1
          id = conn_raw(k)
          if (id <= 0 .or. id > size(model%node_index)) then
            call fail(elem_rec(ie), '*ELEMENT', 'undefined node '//itoa(id))
            return
          end if
          if (model%node_index(id) == 0) then
            call fail(elem_rec(ie), '*ELEMENT', 'undefined node '//itoa(id))
            return
          end if
          conn_raw(k) = model%node_index(id)
        end do
      end do
      model%conn = conn_raw(1:model%conn_ptr(model%nelem + 1) - 1)
      model%elem_id = model%elem_id(1:model%nelem)
      model%elem_kind = model%elem_kind(1:model%nelem)
      model%elem_utype = model%elem_utype(1:model%nelem)
      model%conn_ptr = model%conn_ptr(1:model%nelem + 1)
      ! sets: negative raw ids -> indices, duplicates removed
      do iset = 1, model%n_nset
        model%nsets(iset)%nodes = model%nsets(iset)%nodes(1:model%nsets(iset)%n)
        call resolve_nodes(model%nsets(iset)%nodes, 'node set '//trim(model%nsets(iset)%name), ok=k)
        if (stat /= 0) return
      end do
      do iset = 1, model%n_elset
        model%elsets(iset)%elems = model%elsets(iset)%elems(1:model%elsets(iset)%n)
        associate (el => model%elsets(iset)%elems)
          do k = 1, size(el)
            if (el(k) < 0) then
              id = -el(k)
              if (id > size(model%elem_index)) then
                ie = 0
              else
                ie = model%elem_index(id)
              end if
              if (ie == 0) then
                call fail(1, '*ELSET', 'element set '//trim(model%elsets(iset)%name)//': undefined element '//itoa(id))
                return
              end if
              el(k) = ie
            end if
          end do
        end associate
        call unique(model%elsets(iset)%elems)
        model%elsets(iset)%n = size(model%elsets(iset)%elems)
      end do
      ! boundaries
      do ib = 1, model%n_initial_bc
        call resolve_bc(model%initial_bcs(ib))
        if (stat /= 0) return
      end do
      do is = 1, model%nstep
        do ib = 1, model%steps(is)%nbc
          call resolve_bc(model%steps(is)%bcs(ib))
          if (stat /= 0) return
        end do
        if (model%steps(is)%period < 0.0_dp) then
          stat = 2
          errmsg = model%steps(is)%pos%file//':'//itoa(model%steps(is)%pos%line)//': *STEP: no procedure '// &
            '(*STATIC) in this step'
          return
        end if
      end do
      ! sections
      allocate (model%elem_section(model%nelem), has_section(model%nelem))
      model%elem_section = 0
      has_section = .false.
      if (.not. allocated(model%elem_uelprop)) then
        allocate (model%elem_uelprop(model%nelem))
        model%elem_uelprop = 0
      else
        model%elem_uelprop = model%elem_uelprop(1:model%nelem)
        if (size(model%elem_uelprop) < model%nelem) call grow_int(model%elem_uelprop, model%nelem)
      end if
      do isec = 1, model%nsection
        associate (sec => model%sections(isec))
          iset = model_find_elset(model, sec%elset)
          if (iset == 0) then
            call fail_pos(sec%pos, 'undefined element set '//trim(sec%elset))
            return
          end if
          im = model_find_material(model, sec%material)
          if (im == 0) then
            call fail_pos(sec%pos, 'undefined material '//trim(sec%material))
            return
          end if
          if (.not. (model%materials(im)%has_elastic .or. model%materials(im)%has_user)) then
            call fail_pos(model%materials(im)%pos, 'material '//trim(sec%material)// &
              ' has no *ELASTIC or *USER MATERIAL')
            return
          end if
          if (model%materials(im)%has_elastic .and. model%materials(im)%has_user) then
            call fail_pos(model%materials(im)%pos, 'material '//trim(sec%material)// &
              ' has both *ELASTIC and *USER MATERIAL')
            return
          end if
          do k = 1, size(model%elsets(iset)%elems)
            ie = model%elsets(iset)%elems(k)
            if (model%elem_kind(ie) == etype_user) then
              call fail_pos(sec%pos, 'element '//itoa(model%elem_id(ie))//' is a user element (use *UEL PROPERTY)')
              return
            end if
            if (has_section(ie)) then
              call fail_pos(sec%pos, 'element '//itoa(model%elem_id(ie))//' has two sections')
              return
            end if
            has_section(ie) = .true.
            model%elem_section(ie) = isec
          end do
        end associate
      end do
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user) then
          iu = model%elem_utype(ie)
          if (model%elem_uelprop(ie) == 0 .and. model%utypes(iu)%nprops + model%utypes(iu)%njprops > 0) then
            call fail(elem_rec(ie), '*ELEMENT', 'user element '//itoa(model%elem_id(ie))//' of type '// &
              trim(model%utypes(iu)%name)//' has no *UEL PROPERTY (missing properties)')
            return
          end if
        else if (.not. has_section(ie)) then
          call fail(elem_rec(ie), '*ELEMENT', 'element '//itoa(model%elem_id(ie))//' has no *SOLID SECTION')
          return
        end if
      end do
    end subroutine finish_model

    subroutine fail_pos(pos, msg)
      type(source_pos_t), intent(in) :: pos
      character(len=*), intent(in) :: msg
      stat = 2
      errmsg = pos%file//':'//itoa(pos%line)//': '//trim(pos%keyword)//': '//msg
    end subroutine fail_pos

    subroutine resolve_bc(bc)
      type(boundary_t), intent(inout) :: bc
      integer :: k, id
      do k = 1, size(bc%nodes)
        if (bc%nodes(k) < 0) then
          id = -bc%nodes(k)
          if (id > size(model%node_index)) then
            call fail_pos(bc%pos, 'undefined node '//itoa(id))
            return
          end if
          if (model%node_index(id) == 0) then
            call fail_pos(bc%pos, 'undefined node '//itoa(id))
            return
          end if
          bc%nodes(k) = model%node_index(id)
        end if
      end do
      if (bc%last_dof > model%ndim) then
        if (bc%first_dof > model%ndim) then
          ! e.g. ZSYMM or dof 3 in a 2D model: nothing to constrain, like Abaqus for inactive dofs
          call warn_pos(bc%pos, 'dof '//itoa(bc%first_dof)//' does not exist in this 2D model: ignored')
        end if
        bc%last_dof = model%ndim
      end if
    end subroutine resolve_bc

    subroutine warn_pos(pos, msg)
      type(source_pos_t), intent(in) :: pos
      character(len=*), intent(in) :: msg
      if (wu /= -1) write (wu, '(a)') 'ldfcz: warning: '//pos%file//':'//itoa(pos%line)//': '//trim(pos%keyword)// &
        ': '//msg
    end subroutine warn_pos

    subroutine resolve_nodes(list, what, ok)
      integer, allocatable, intent(inout) :: list(:)
      character(len=*), intent(in) :: what
      integer, intent(out) :: ok
      integer :: k, id
      ok = 0
      do k = 1, size(list)
        if (list(k) < 0) then
          id = -list(k)
          if (id > size(model%node_index)) then
            call fail(1, '*NSET', what//': undefined node '//itoa(id))
            return
          end if
          if (model%node_index(id) == 0) then
            call fail(1, '*NSET', what//': undefined node '//itoa(id))
            return
          end if
          list(k) = model%node_index(id)
        end if
      end do
      call unique(list)
    end subroutine resolve_nodes

    subroutine grow_nodes()
      integer, allocatable :: t1(:), t3(:)
      real(dp), allocatable :: t2(:, :)
      integer :: n
      n = size(model%node_id)
      allocate (t1(2 * n), t2(3, 2 * n), t3(2 * n))
      t1(1:n) = model%node_id
      t2(:, 1:n) = model%x
      t3(1:n) = node_rec
      call move_alloc(t1, model%node_id)
      call move_alloc(t2, model%x)
      call move_alloc(t3, node_rec)
    end subroutine grow_nodes

    subroutine grow_elems()
      integer :: n
      n = size(model%elem_id)
      call grow_int(model%elem_id, 2 * n)
      call grow_int(model%elem_kind, 2 * n)
      call grow_int(model%elem_utype, 2 * n)
      call grow_int(model%conn_ptr, 2 * n + 1)
      call grow_int(elem_rec, 2 * n)
      if (allocated(model%elem_uelprop)) call grow_int(model%elem_uelprop, 2 * n)
    end subroutine grow_elems

  end subroutine read_deck

  ! ==================================================================== helpers outside the reader's state

  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

  logical function is_model_keyword(kw)
    character(len=*), intent(in) :: kw
    select case (kw)
    case ('*NODE', '*ELEMENT', '*NSET', '*ELSET', '*SOLID SECTION', '*MATERIAL', '*ELASTIC', '*USER MATERIAL', &
          '*DEPVAR', '*USER ELEMENT', '*UEL PROPERTY', '*AMPLITUDE', '*HEADING')
      is_model_keyword = .true.
    case default
      is_model_keyword = .false.
    end select
  end function is_model_keyword


  !> Append a print variable once.
  pure subroutine add_var(vars, nv, v)
    character(len=8), intent(inout) :: vars(:)
    integer, intent(inout) :: nv
    character(len=*), intent(in) :: v
    if (nv == size(vars)) return
    if (any(vars(1:nv) == v)) return
    nv = nv + 1
    vars(nv) = v
  end subroutine add_var

  !> Append a boundary to a list with n entries, doubling the capacity when full.
  subroutine push_bc(list, n, bc)
    type(boundary_t), allocatable, intent(inout) :: list(:)
    integer, intent(inout) :: n
    type(boundary_t), intent(in) :: bc
    type(boundary_t), allocatable :: t(:)
    if (.not. allocated(list)) allocate (list(4))
    if (n == size(list)) then
      allocate (t(2 * n))
      t(1:n) = list(1:n)
      call move_alloc(t, list)
    end if
    n = n + 1
    list(n) = bc
  end subroutine push_bc

  !> Append v to a(1:n), doubling the capacity when full.
  subroutine add_member(a, n, v)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(inout) :: n
    integer, intent(in) :: v
    integer, allocatable :: t(:)
    if (.not. allocated(a)) allocate (a(0))
    if (n == size(a)) then
      allocate (t(max(16, 2 * n)))
      t(1:n) = a(1:n)
      call move_alloc(t, a)
    end if
    n = n + 1
    a(n) = v
  end subroutine add_member

  subroutine grow_int(a, nnew)
    integer, allocatable, intent(inout) :: a(:)
    integer, intent(in), optional :: nnew
    integer, allocatable :: t(:)
    integer :: n, m
    n = size(a)
    m = 2 * n
    if (present(nnew)) m = nnew
    allocate (t(m))
    t = 0
    t(1:min(n, m)) = a(1:min(n, m))
    call move_alloc(t, a)
  end subroutine grow_int

  !> Sort (heap sort, O(n log n)) and remove duplicates (insertion order is not meaningful for sets).
  subroutine unique(a)
    integer, allocatable, intent(inout) :: a(:)
    integer :: i, j, n, t
    n = size(a)
    do i = n / 2, 1, -1
      call sift(i, n)
    end do
    do i = n, 2, -1
      t = a(1)
      a(1) = a(i)
      a(i) = t
      call sift(1, i - 1)
    end do
    j = 0
    do i = 1, n
      if (j > 0) then
        if (a(i) == a(j)) cycle
      end if
      j = j + 1
      a(j) = a(i)
    end do
    a = a(1:j)
  contains
    subroutine sift(start, last)
      integer, intent(in) :: start, last
      integer :: root, child, tmp
      root = start
      do while (2 * root <= last)
        child = 2 * root
        if (child < last) then
          if (a(child + 1) > a(child)) child = child + 1
        end if
        if (a(root) >= a(child)) return
        tmp = a(root)
        a(root) = a(child)
        a(child) = tmp
        root = child
      end do
    end subroutine sift
  end subroutine unique

end module deck_reader
