!> The output registry: every output variable of the host declared once (deck name and aliases, components,
!> location, units, meaning, which elements or routines provide it, and which outputs carry it: the JOB.csv columns,
!> the JOB.dat tables, the VTU frames). The reader resolves the variables of *OUTPUT/*NODE OUTPUT/*ELEMENT OUTPUT,
!> *NODE PRINT and *EL PRINT against it (output_lookup) and, once the model is complete, warns once about every
!> request that nothing in the model can provide (output_unprovided_requests); the writers (history_columns,
!> print_tables, field_frame) name and order their columns and arrays from it and write nothing that no element
!> or routine provided. docs/host.md's output-variable table is generated from it (ldfcz_doc_tables outputs) and
!> tested against it (test docs_tables). Adding a variable: docs/extending.md.
module output_registry
  use model_types, only: model_t, source_pos_t, etype_user, model_find_material, name_len, model_elements_leave
  implicit none
  private
  public :: output_variable_t, output_variables, output_lookup, output_component_name, output_ncomp
  public :: output_unprovided_requests, output_max_statev, output_names_text, output_provider_text
  public :: OV_COORD, OV_U, OV_RF, OV_ELEMENT, OV_S, OV_SP, OV_MISES, OV_LE, OV_E, OV_SDV, OV_COHESIVE, OV_OPENING
  public :: OV_TRACTION, OV_DELTA_MAX, OV_S_NODAL, OV_LE_NODAL, OV_DAMAGE, OV_STATUS
  public :: LOC_NODE, LOC_POINT, LOC_ELEMENT, LOC_SVARS, LOC_NODAL
  public :: PROV_MODEL, PROV_SOLUTION, PROV_CONTINUUM, PROV_STATEV, PROV_USER, PROV_USER_OPENING, PROV_SVARS_TRACTION
  public :: PROV_SVARS_DELTA_MAX, PROV_SVARS_DAMAGE, PROV_ACTIVITY
  public :: BLOCK_BOTH, BLOCK_CONTINUUM, BLOCK_INTERFACE, output_block
  public :: VTU_NONE, VTU_ALWAYS, VTU_REQUESTED
  public :: USE_FIELD, USE_NODE_PRINT, USE_EL_PRINT, PRESET_PRESELECT, PRESET_ALL

  !> where a variable lives: at the nodes; at the integration points; per element; in a user element's SVARS; at the
  !> nodes, extrapolated from the integration points of each element and averaged over the elements of a node
  integer, parameter :: LOC_NODE = 1, LOC_POINT = 2, LOC_ELEMENT = 3, LOC_SVARS = 4, LOC_NODAL = 5
  !> what provides it: the model (coordinates, labels), the solution (displacements, reactions), the continuum
  !> elements (stress, strain at the points), their materials' STATEV (*DEPVAR), the user elements, the user
  !> elements with 4 or 8 nodes (opening from the nodal displacements: top - bottom face, the cohesive layout), the
  !> SVARS positions a '**LDFCZ SVARS' line declares (TRACTION=, DELTA MAX=)
  !> and DELTA MAX= with LENGTH PROPERTY= (the damage of the exponential law), a model whose elements may leave it
  !> (*MODEL CHANGE, *DEPVAR, DELETE=)
  integer, parameter :: PROV_MODEL = 1, PROV_SOLUTION = 2, PROV_CONTINUUM = 3, PROV_STATEV = 4, PROV_USER = 5, &
    PROV_USER_OPENING = 6, PROV_SVARS_TRACTION = 7, PROV_SVARS_DELTA_MAX = 8, PROV_SVARS_DAMAGE = 9, &
    PROV_ACTIVITY = 10
  !> the block of a frame an array is in (output_block, from the provider): the continuum elements' block, the
  !> interface (user) elements' block, or both (docs/host.md, "Frames")
  integer, parameter :: BLOCK_BOTH = 0, BLOCK_CONTINUUM = 1, BLOCK_INTERFACE = 2
  !> in the VTU frames: never, in every frame (when provided), when the field request names it
  integer, parameter :: VTU_NONE = 0, VTU_ALWAYS = 1, VTU_REQUESTED = 2
  !> membership of VARIABLE=PRESELECT / ALL
  integer, parameter :: PRESET_PRESELECT = 1, PRESET_ALL = 2
  !> the requests a variable may appear in
  integer, parameter :: USE_FIELD = 1, USE_NODE_PRINT = 2, USE_EL_PRINT = 3

  !> One output variable.
  type :: output_variable_t
    character(len=8) :: key = ''           !< deck name ('' : written by the host unasked, not requestable)
    character(len=16) :: aliases = ''      !< other deck names, blank separated
    character(len=12) :: vtu = ''          !< array name in the VTU frames
    character(len=40) :: components = ''   !< deck component names, blank separated ('' : scalar; SDV: SDVn)
    integer :: vtu_ncomp = 1               !< components in the frames
    character(len=32) :: vtu_components = '' !< their ComponentName attributes (VTK's order), blank separated
    integer :: location = 0                !< LOC_*
    character(len=8) :: units = ''         !< units (mm, N, s, MPa)
    character(len=112) :: meaning = ''      !< what it is
    integer :: provider = 0                !< PROV_*
    logical :: csv = .false.               !< JOB.csv columns (*NODE PRINT, NSET=: U the set mean, RF its sum)
    logical :: dat = .false.               !< JOB.dat tables (*NODE PRINT, *EL PRINT)
    integer :: vtu_mode = VTU_NONE         !< VTU_*
    !> in Abaqus' VARIABLE=PRESELECT list of a static step (PRESET_PRESELECT: and in ALL), in ALL only
    !> (PRESET_ALL), in neither (0): the variables of those lists the host has
    integer :: preset = 0
    !> VTU_REQUESTED of a variable written unasked with another: in the frames when that one (OV_*) is requested
    integer :: follows = 0
  end type output_variable_t

  integer, parameter :: OV_COORD = 1, OV_U = 2, OV_RF = 3, OV_S_NODAL = 4, OV_LE_NODAL = 5, OV_ELEMENT = 6, &
    OV_S = 7, OV_SP = 8, OV_MISES = 9, OV_LE = 10, OV_E = 11, OV_SDV = 12, OV_COHESIVE = 13, OV_OPENING = 14, &
    OV_TRACTION = 15, OV_DELTA_MAX = 16, OV_DAMAGE = 17, OV_STATUS = 18

  !> The variables, in the order the frames hold them (point data, then cell data).
  type(output_variable_t), parameter :: output_variables(18) = [ &
    output_variable_t('COORD', '', '', 'COORD1 COORD2 COORD3', 3, '', LOC_NODE, 'mm', &
      'original coordinates (the points of the frames)', PROV_MODEL, vtu_mode=VTU_ALWAYS), &
    output_variable_t('U', '', 'U', 'U1 U2 U3', 3, '', LOC_NODE, 'mm', &
      'displacement (JOB.dat, JOB.csv: local components at a `*TRANSFORM` node; frames: global)', PROV_SOLUTION, &
      .true., .true., VTU_ALWAYS, PRESET_PRESELECT), &
    output_variable_t('RF', '', 'RF', 'RF1 RF2 RF3', 3, '', LOC_NODE, 'N', &
      'reaction force on prescribed dofs (axisymmetric: total over 2 pi)', PROV_SOLUTION, .true., .true., &
      VTU_ALWAYS, PRESET_PRESELECT), &
    output_variable_t('', '', 'S_nodal', '', 6, 'XX YY ZZ XY YZ XZ', LOC_NODAL, 'MPa', &
      'Cauchy stress S extrapolated from the points of each element and averaged at the node; 0 off the continuum', &
      PROV_CONTINUUM, vtu_mode=VTU_ALWAYS), &
    output_variable_t('', '', 'LE_nodal', '', 6, 'XX YY ZZ XY YZ XZ', LOC_NODAL, '-', &
      'strain LE (tensor shears) extrapolated from the points of each element and averaged at the node', &
      PROV_CONTINUUM, vtu_mode=VTU_REQUESTED, follows=OV_LE), &
    output_variable_t('', '', 'element', '', 1, '', LOC_ELEMENT, '-', 'element label', PROV_MODEL, &
      vtu_mode=VTU_ALWAYS), &
    output_variable_t('S', '', 'S', 'S11 S22 S33 S12 S13 S23', 6, 'XX YY ZZ XY YZ XZ', LOC_POINT, 'MPa', &
      'Cauchy stress (frames: mean over the points)', PROV_CONTINUUM, dat=.true., vtu_mode=VTU_ALWAYS, &
      preset=PRESET_PRESELECT), &
    output_variable_t('SP', '', 'S_principal', '', 3, 'min mid max', LOC_POINT, 'MPa', &
      'principal values of the (mean) stress', PROV_CONTINUUM, vtu_mode=VTU_ALWAYS), &
    output_variable_t('MISES', '', 'Mises', '', 1, '', LOC_POINT, 'MPa', 'von Mises stress', PROV_CONTINUUM, &
      dat=.true., vtu_mode=VTU_ALWAYS), &
    output_variable_t('LE', '', 'LE', 'LE11 LE22 LE33 LE12 LE13 LE23', 6, 'XX YY ZZ XY YZ XZ', LOC_POINT, '-', &
      'integrated strain STRAN (logarithmic under NLGEOM; JOB.dat engineering, frames tensor shears)', &
      PROV_CONTINUUM, dat=.true., vtu_mode=VTU_REQUESTED, preset=PRESET_PRESELECT), &
    output_variable_t('E', 'NE', 'E', 'E11 E22 E33 E12 E13 E23', 6, 'XX YY ZZ XY YZ XZ', LOC_POINT, '-', &
      'the same STRAN under the small-strain name', PROV_CONTINUUM, dat=.true., vtu_mode=VTU_REQUESTED), &
    output_variable_t('SDV', 'STATEV', 'SDV', 'SDVn', 1, '', LOC_POINT, '-', &
      'solution-dependent state variables STATEV of the material (`*DEPVAR`); frames: `SDV<n>` arrays', &
      PROV_STATEV, dat=.true., vtu_mode=VTU_REQUESTED, preset=PRESET_ALL), &
    output_variable_t('', '', 'cohesive', '', 1, '', LOC_ELEMENT, '-', '1 for a user element''s cell, 0 otherwise', &
      PROV_USER, vtu_mode=VTU_ALWAYS), &
    output_variable_t('', '', 'opening', '', 3, '', LOC_ELEMENT, 'mm', &
      'mean opening, top - bottom face displacement (user elements of 8 or 4 nodes, COH3D8/COH2D4 layout)', &
      PROV_USER_OPENING, vtu_mode=VTU_ALWAYS), &
    output_variable_t('', '', 'traction', '', 1, '', LOC_SVARS, 'MPa', &
      'traction magnitude, mean over the points, where `**LDFCZ SVARS` declares `TRACTION=`', PROV_SVARS_TRACTION, &
      vtu_mode=VTU_ALWAYS), &
    output_variable_t('', '', 'Delta_max', '', 1, '', LOC_SVARS, 'mm', &
      'largest opening so far, mean over the points, where `**LDFCZ SVARS` declares `DELTA MAX=`', &
      PROV_SVARS_DELTA_MAX, vtu_mode=VTU_ALWAYS), &
    output_variable_t('', '', 'damage', '', 1, '', LOC_SVARS, '-', &
      'stiffness lost by the secant, 1 - exp(-Delta_max/delta) (exponential law, Eq. 20), mean over the points', &
      PROV_SVARS_DAMAGE, vtu_mode=VTU_ALWAYS), &
    output_variable_t('STATUS', '', 'STATUS', '', 1, '', LOC_ELEMENT, '-', &
      'element status: 1 active, 0 removed (`*MODEL CHANGE`) or deleted (`*DEPVAR, DELETE=`)', PROV_ACTIVITY, &
      vtu_mode=VTU_ALWAYS)]

contains

  !> Resolve a deck word (upper case) to a variable and a component: 'S' -> (OV_S, 0), 'S12' -> (OV_S, 4),
  !> 'NE' -> (OV_E, 0), 'SDV' -> (OV_SDV, 0), 'SDV7' -> (OV_SDV, 7). var = 0 when the registry has no such name.
  pure subroutine output_lookup(word, var, comp)
    character(len=*), intent(in) :: word  !< the deck's variable name
    integer, intent(out) :: var           !< OV_* (0: unknown)
    integer, intent(out) :: comp          !< 0 the whole variable; component number; SDVn: n
    integer :: v, k, ios, n
    type(output_variable_t) :: ov
    var = 0
    comp = 0
    if (len_trim(word) == 0) return
    do v = 1, size(output_variables)
      ov = output_variables(v)
      block
        if (len_trim(ov%key) == 0) cycle
        if (word == ov%key .or. has_word(ov%aliases, word)) then
          var = v
          return
        end if
        if (ov%components == 'SDVn') then
          if (len(word) > 3) then
            if (word(1:3) == 'SDV' .and. verify(trim(word(4:)), '0123456789') == 0) then
              read (word(4:), *, iostat=ios) n
              if (ios == 0 .and. n >= 1) then
                var = v
                comp = n
                return
              end if
            end if
          end if
          cycle
        end if
        do k = 1, output_ncomp(v)
          if (word == output_component_name(v, k)) then
            var = v
            comp = k
            return
          end if
        end do
      end block
    end do
  end subroutine output_lookup

  !> True when word is one of the blank-separated words of list.
  pure logical function has_word(list, word)
    character(len=*), intent(in) :: list, word
    integer :: i, j
    has_word = .false.
    i = 1
    do while (i <= len_trim(list))
      j = index(list(i:), ' ')
      if (j == 0) j = len_trim(list) - i + 2
      if (list(i:i + j - 2) == word) then
        has_word = .true.
        return
      end if
      i = i + j
      do while (i <= len(list))
        if (list(i:i) /= ' ') exit
        i = i + 1
      end do
    end do
  end function has_word

  !> Number of deck components of a variable (0: a scalar or SDV).
  pure integer function output_ncomp(var)
    integer, intent(in) :: var  !< OV_*
    integer :: i
    output_ncomp = 0
    if (output_variables(var)%components == 'SDVn') return
    do i = 1, len_trim(output_variables(var)%components)
      if (output_variables(var)%components(i:i) /= ' ') then
        if (i == 1) then
          output_ncomp = output_ncomp + 1
        else if (output_variables(var)%components(i - 1:i - 1) == ' ') then
          output_ncomp = output_ncomp + 1
        end if
      end if
    end do
  end function output_ncomp

  !> Deck name of component k of a variable ('S12'; SDV: 'SDVk').
  pure function output_component_name(var, k) result(name)
    integer, intent(in) :: var  !< OV_*
    integer, intent(in) :: k    !< component
    character(len=8) :: name
    character(len=len(output_variables(1)%components)) :: c
    integer :: i, j, n
    name = ''
    c = output_variables(var)%components
    if (c == 'SDVn') then
      write (name, '(a,i0)') 'SDV', k
      return
    end if
    n = 0
    i = 1
    do while (i <= len_trim(c))
      do while (c(i:i) == ' ')
        i = i + 1
      end do
      j = i
      do while (j < len(c))
        if (c(j + 1:j + 1) == ' ') exit
        j = j + 1
      end do
      n = n + 1
      if (n == k) then
        name = c(i:j)
        return
      end if
      i = j + 1
    end do
  end function output_component_name

  !> What provides a variable, in words (the documentation's table).
  pure function output_provider_text(var) result(t)
    integer, intent(in) :: var  !< OV_*
    character(len=:), allocatable :: t
    select case (output_variables(var)%provider)
    case (PROV_MODEL)
      t = 'the model'
    case (PROV_SOLUTION)
      t = 'the solution'
    case (PROV_CONTINUUM)
      t = 'continuum elements'
    case (PROV_STATEV)
      t = 'continuum elements whose material has `*DEPVAR`'
    case (PROV_USER)
      t = 'user elements'
    case (PROV_USER_OPENING)
      t = 'user elements of 8 or 4 nodes (host, from U)'
    case (PROV_SVARS_TRACTION)
      t = 'user element types declaring `TRACTION=`'
    case (PROV_SVARS_DELTA_MAX)
      t = 'user element types declaring `DELTA MAX=`'
    case (PROV_SVARS_DAMAGE)
      t = 'user element types declaring `DELTA MAX=` and `LENGTH PROPERTY=`'
    case (PROV_ACTIVITY)
      t = 'models with `*MODEL CHANGE` or `*DEPVAR, DELETE=`'
    case default
      t = '?'
    end select
  end function output_provider_text

  !> The block of a frame that holds variable var: the continuum elements' arrays in the continuum block, the user
  !> elements' in the interface block, the points' arrays, the element label and the cohesive flag in both.
  pure integer function output_block(var) result(b)
    integer, intent(in) :: var  !< OV_*
    select case (output_variables(var)%provider)
    case (PROV_CONTINUUM, PROV_STATEV)
      b = BLOCK_CONTINUUM
    case (PROV_USER_OPENING, PROV_SVARS_TRACTION, PROV_SVARS_DELTA_MAX, PROV_SVARS_DAMAGE)
      b = BLOCK_INTERFACE
    case default
      b = BLOCK_BOTH
    end select
  end function output_block

  !> The names a request may use, for messages: 'U, RF', 'S, MISES, LE, E, SDV'.
  pure function output_names_text(use) result(t)
    integer, intent(in) :: use  !< USE_*
    character(len=:), allocatable :: t
    integer :: v
    t = ''
    do v = 1, size(output_variables)
      if (.not. usable(v, use)) cycle
      if (len(t) > 0) t = t//', '
      t = t//trim(output_variables(v)%key)
    end do
  end function output_names_text

  !> A variable may be named in a request of this kind.
  pure logical function usable(var, use)
    integer, intent(in) :: var, use
    type(output_variable_t) :: ov
    ov = output_variables(var)
    select case (use)
    case (USE_FIELD)
      usable = len_trim(ov%key) > 0
    case (USE_NODE_PRINT)
      usable = ov%dat .and. ov%location == LOC_NODE
    case default
      usable = ov%dat .and. ov%location == LOC_POINT
    end select
  end function usable

  !> The STATEV a continuum element's material has (*DEPVAR; 0 for *ELASTIC and for a user element).
  pure integer function element_statev(model, ie)
    type(model_t), intent(in) :: model
    integer, intent(in) :: ie
    integer :: im
    element_statev = 0
    if (model%elem_kind(ie) == etype_user) return
    if (model%elem_section(ie) < 1) return
    im = model_find_material(model, model%sections(model%elem_section(ie))%material)
    if (im > 0) element_statev = model%materials(im)%nstatv
  end function element_statev

  !> The largest NSTATV over the continuum elements elems (every element when absent).
  pure integer function output_max_statev(model, elems) result(n)
    type(model_t), intent(in) :: model         !< the model (sections and materials resolved)
    integer, intent(in), optional :: elems(:)  !< element indices
    integer :: k
    n = 0
    if (present(elems)) then
      do k = 1, size(elems)
        n = max(n, element_statev(model, elems(k)))
      end do
    else
      do k = 1, model%nelem
        n = max(n, element_statev(model, k))
      end do
    end if
  end function output_max_statev

  !> Why variable var (component comp) cannot be provided for the elements elems of the model ('' when it can):
  !> the routines that provide it (output_variables(var)%provider) are absent.
  pure function unprovided_reason(model, var, comp, elems) result(why)
    type(model_t), intent(in) :: model
    integer, intent(in) :: var, comp, elems(:)
    character(len=:), allocatable :: why
    character(len=16) :: b
    integer :: ns
    logical :: cont
    why = ''
    cont = any(model%elem_kind(elems) /= etype_user)
    select case (output_variables(var)%provider)
    case (PROV_CONTINUUM)
      if (.not. cont) why = 'not written: no continuum element provides it (a user element''s state is its SVARS)'
    case (PROV_STATEV)
      ns = output_max_statev(model, elems)
      if (.not. cont) then
        why = 'not written: user elements have no state variables here (their SVARS are written only as the '// &
          'traction and Delta_max a **LDFCZ SVARS line declares, docs/uel.md)'
      else if (ns == 0) then
        why = 'not written: no material of these elements has state variables (*DEPVAR)'
      else if (comp > ns) then
        write (b, '(i0)') ns
        why = 'not written: the materials of these elements have at most '//trim(b)//' state variables'
      else if (any(model%elem_kind(elems) == etype_user)) then
        why = 'written for the continuum elements only: the SVARS of the user elements are not state variables '// &
          '(their traction and Delta_max are written where **LDFCZ SVARS declares them, docs/uel.md)'
      end if
    case (PROV_ACTIVITY)
      if (.not. model_elements_leave(model)) why = 'not written: no element of this model can leave it (written '// &
        'with *MODEL CHANGE or *DEPVAR, DELETE=)'
    case (PROV_SOLUTION)
      if (comp > model%ndim) then
        write (b, '(i0)') model%ndim
        why = 'not written: the model is '//trim(b)//'D'
      end if
    end select
  end function unprovided_reason

  !> The requests of the model that nothing in it can provide, each once: where it was asked (*OUTPUT/*ELEMENT
  !> OUTPUT, *EL PRINT, *NODE PRINT line) and why. Field requests carried into later steps are the same request.
  pure subroutine output_unprovided_requests(model, pos, msg)
    type(model_t), intent(in) :: model                          !< the model (complete)
    type(source_pos_t), allocatable, intent(out) :: pos(:)      !< where each was asked
    character(len=512), allocatable, intent(out) :: msg(:)      !< what cannot be written and why
    integer :: is, k, j, var, comp
    integer, allocatable :: elems(:), all_elems(:)
    character(len=:), allocatable :: why
    character(len=name_len) :: word
    allocate (pos(0), msg(0))
    all_elems = [(k, k = 1, model%nelem)]
    do is = 1, model%nstep
      associate (st => model%steps(is))
        do k = 1, st%nfield_request
          associate (rq => st%field_requests(k))
            why = unprovided_reason(model, rq%var, rq%comp, all_elems)
            word = output_variables(rq%var)%key
            if (rq%var == OV_SDV .and. rq%comp > 0) word = output_component_name(OV_SDV, rq%comp)
            call add(pos, msg, rq%pos, trim(word)//': '//why, len(why) > 0)
          end associate
        end do
        do k = 1, st%nelprint
          if (st%elprints(k)%set_index > 0) then
            elems = model%elsets(st%elprints(k)%set_index)%elems
          else
            elems = all_elems
          end if
          do j = 1, size(st%elprints(k)%vars)
            call output_lookup(st%elprints(k)%vars(j), var, comp)
            if (var == 0) cycle
            why = unprovided_reason(model, var, comp, elems)
            call add(pos, msg, st%elprints(k)%pos, trim(st%elprints(k)%vars(j))//': '//why, len(why) > 0)
          end do
        end do
        do k = 1, st%nprint
          do j = 1, size(st%prints(k)%vars)
            call output_lookup(st%prints(k)%vars(j), var, comp)
            if (var == 0) cycle
            why = unprovided_reason(model, var, comp, all_elems)
            call add(pos, msg, st%prints(k)%pos, trim(st%prints(k)%vars(j))//': '//why, len(why) > 0)
          end do
        end do
      end associate
    end do
  contains
    !> Append (p, text) when wanted and not there already.
    pure subroutine add(pos, msg, p, text, wanted)
      type(source_pos_t), allocatable, intent(inout) :: pos(:)
      character(len=512), allocatable, intent(inout) :: msg(:)
      type(source_pos_t), intent(in) :: p
      character(len=*), intent(in) :: text
      logical, intent(in) :: wanted
      integer :: i
      if (.not. wanted) return
      do i = 1, size(msg)
        if (msg(i) == text .and. pos(i)%line == p%line .and. pos(i)%file == p%file) return
      end do
      pos = [pos, p]
      msg = [character(len=512) :: msg, text]
    end subroutine add
  end subroutine output_unprovided_requests

end module output_registry
