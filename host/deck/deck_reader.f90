!> Abaqus keyword deck reader: builds a model_t from the records of deck_lines.
!> Subset documented in docs/host.md. A keyword or parameter that would change the physics and is not supported is an
!> error; cosmetic/output keywords that are not supported give a warning. Every error names file:line: *KEYWORD.
!> This module dispatches the keyword blocks to the readers of deck_mesh, deck_materials, deck_user_elements,
!> deck_boundaries and deck_steps, which share the state in a deck_context_t, and lets deck_finish complete the model.
module deck_reader
  use deck_lines, only: deck_load, deck_keyword_parse, deck_where, file_name_t
  use model_types, only: model_t
  use deck_context, only: deck_context_t, ctx_fail, ctx_fail_kw, ctx_warn, ctx_note, ctx_allow_params, ctx_need_step, &
    scope_model, scope_assembly, no_blanks, deck_message_t, ctx_report_warning
  use deck_suggest, only: deck_closest
  use deck_assembly, only: prescan_assembly, read_part_def, begin_assembly, end_assembly, begin_instance, &
    end_instance, allowed_in_assembly, mesh_keyword
  use deck_mesh, only: read_node, read_element, read_set, read_system
  use deck_materials, only: read_material, read_density, read_user_material, read_depvar, read_solid_section
  use deck_elastic, only: read_elastic, read_expansion
  use deck_section_controls, only: read_section_controls
  use deck_user_elements, only: read_user_element, read_uel_property
  use deck_boundaries, only: read_amplitude, read_boundary
  use deck_steps, only: read_step, read_static, read_controls, read_restart, read_output, read_node_print, &
    read_field_variables, read_el_print, read_monitor
  use deck_loads, only: read_cload, read_dload, read_dsload, read_surface
  use deck_fields, only: read_initial_conditions, read_temperature, read_field
  use deck_constraints, only: read_equation, read_tie, read_mpc
  use deck_finish, only: finish_model
  use deck_parameters, only: apply_parameters
  use deck_generate, only: read_ngen, read_nfill, read_ncopy, read_elgen
  use deck_orientation, only: read_orientation, read_transform
  use deck_declarations, only: read_ldfcz_declaration, track_declaration_owner
  use deck_couplings, only: read_coupling, read_coupling_kind
  use deck_pretension, only: read_pretension_section
  use deck_model_change, only: read_model_change, read_time_points
  implicit none
  private
  public :: read_deck, reader_keywords

  !> The keyword table: every keyword read_block dispatches (keep the two in step: test deck_messages compares
  !> them), the names a misspelt keyword is compared with ("*ELASTC: ...; did you mean *ELASTIC?").
  character(len=*), parameter :: reader_keywords(*) = [character(len=20) :: &
    '*PART', '*END PART', '*ASSEMBLY', '*END ASSEMBLY', '*INSTANCE', '*END INSTANCE', '*ORIENTATION', &
    '*TRANSFORM', '*SYSTEM', '*NGEN', '*NFILL', '*NCOPY', '*ELGEN', '*PARAMETER', '*HEADING', '*NODE', '*ELEMENT', &
    '*NSET', '*ELSET', '*SOLID SECTION', '*MATERIAL', '*ELASTIC', '*USER MATERIAL', '*DEPVAR', '*USER ELEMENT', &
    '*UEL PROPERTY', '*AMPLITUDE', '*BOUNDARY', '*CLOAD', '*DLOAD', '*DSLOAD', '*SURFACE', '*DENSITY', &
    '*INITIAL CONDITIONS', '*TEMPERATURE', '*FIELD', '*EXPANSION', '*EQUATION', '*TIE', '*MPC', '*COUPLING', &
    '*KINEMATIC', '*DISTRIBUTING', '*PRE-TENSION SECTION', '*MODEL CHANGE', '*TIME POINTS', '*STEP', &
    '*STATIC', '*VISCO', '*CONTROLS', '*OUTPUT', '*NODE OUTPUT', '*ELEMENT OUTPUT', '*NODE PRINT', '*EL PRINT', &
    '*MONITOR', '*END STEP', '*RESTART', '*LDFCZ SVARS', '*LDFCZ STATEV', '*LDFCZ BUILTIN', '*SECTION CONTROLS', &
    '*HOURGLASS STIFFNESS', '*ENERGY PRINT', '*PREPRINT', &
    '*FILE FORMAT', '*NODE FILE', '*EL FILE', '*ENERGY OUTPUT', '*CONTACT OUTPUT', '*PRINT', '*ENERGY FILE', &
    '*DIAGNOSTICS', '*SECTION PRINT']
  !> Abaqus/Standard keywords ldfcz does not read (each may change the analysis: an error), so that a misspelling
  !> of one is recognised as such and a real one is not taken for a misspelling of a supported keyword (*PLASTIC is
  !> one edit from *ELASTIC). Not complete: a keyword missing here gets no suggestion or, at worst, a wrong one.
  character(len=*), parameter :: other_abaqus_keywords(*) = [character(len=36) :: &
    '*PLASTIC', '*HYPERELASTIC', '*HYPERFOAM', '*VISCOELASTIC', '*CREEP', '*SWELLING', '*MULLINS EFFECT', &
    '*DAMAGE INITIATION', '*DAMAGE EVOLUTION', '*DAMAGE STABILIZATION', '*CONDUCTIVITY', '*SPECIFIC HEAT', &
    '*LATENT HEAT', '*DAMPING', '*DYNAMIC', '*FREQUENCY', '*BUCKLE', '*HEAT TRANSFER', &
    '*COUPLED TEMPERATURE-DISPLACEMENT', '*GEOSTATIC', '*SOILS', '*STEADY STATE DYNAMICS', '*MODAL DYNAMIC', &
    '*SHELL SECTION', '*SHELL GENERAL SECTION', '*MEMBRANE SECTION', '*BEAM SECTION', '*BEAM GENERAL SECTION', &
    '*COHESIVE SECTION', '*CONNECTOR SECTION', '*GASKET SECTION', &
    '*CONTACT PAIR', '*CONTACT', '*CONTACT INCLUSIONS', '*CONTACT PROPERTY ASSIGNMENT', '*SURFACE INTERACTION', &
    '*SURFACE BEHAVIOR', '*FRICTION', '*CLEARANCE', '*RIGID BODY', &
    '*SPRING', '*DASHPOT', '*MASS', '*ROTARY INERTIA', '*EMBEDDED ELEMENT', '*PHYSICAL CONSTANTS', &
    '*DISTRIBUTION', '*DISTRIBUTION TABLE', '*DSFLUX', '*CFLUX', '*FILM', &
    '*ADAPTIVE MESH', '*IMPORT']


contains

  !> Read an Abaqus-style deck into a model. stat = 0 ok, 2 error (errmsg = "file:line: *KEYWORD: what").
  subroutine read_deck(path, model, stat, errmsg, warn_unit, messages)
    character(len=*), intent(in) :: path                 !< deck file
    type(model_t), intent(out) :: model                  !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 deck error
    character(len=:), allocatable, intent(out) :: errmsg !< error message
    integer, intent(in), optional :: warn_unit           !< unit for warnings (default stderr; -1: silent)
    !> the warnings (also written to warn_unit at once) and the notes (written nowhere else) of the reading, in order,
    !> for JOB.log: 'warning: file:line: *KW: ...', 'note: file:line: *KW: ...'
    type(deck_message_t), allocatable, intent(out), optional :: messages(:)
    type(deck_context_t) :: ctx
    type(file_name_t), allocatable :: file_warnings(:)
    integer :: iw

    if (present(warn_unit)) ctx%wu = warn_unit
    call deck_load(path, ctx%src, stat, errmsg, file_warnings)
    if (stat /= 0) return
    do iw = 1, size(file_warnings)
      call ctx_report_warning(ctx, file_warnings(iw)%name)
    end do
    call apply_parameters(ctx%src, stat, errmsg)
    if (stat /= 0) return
    ctx%stat = stat
    call move_alloc(errmsg, ctx%errmsg)
    call start_model(ctx)
    call prescan_assembly(ctx)
    call read_blocks(ctx)
    if (ctx%stat == 0) call finish_model(ctx)
    model = ctx%model
    stat = ctx%stat
    if (allocated(ctx%errmsg)) call move_alloc(ctx%errmsg, errmsg)
    if (present(messages)) then
      if (allocated(ctx%messages)) then
        messages = ctx%messages(1:ctx%nmessage)
      else
        allocate (messages(0))
      end if
    end if
  end subroutine read_deck

  !> Initial capacities of the growing lists (they double when full).
  subroutine start_model(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    associate (model => ctx%model)
      allocate (model%node_id(64), model%x(3, 64), ctx%node_rec(64))
      allocate (model%elem_id(64), model%elem_kind(64), model%elem_utype(64), model%conn_ptr(65), ctx%conn_raw(512))
      allocate (ctx%elem_rec(64))
      model%conn_ptr(1) = 1
      allocate (model%nsets(8), model%elsets(8), model%materials(4), model%sections(4), model%utypes(2))
      allocate (model%uelprops(2), model%amplitudes(2), model%initial_bcs(4), model%steps(2))
      model%heading = ''
    end associate
    ctx%imat = 0
    ctx%istep = 0
    ctx%in_step = .false.
    ctx%restart_freq = 0
  end subroutine start_model

  !> Read the keyword blocks in order; stops at the first error.
  subroutine read_blocks(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    call read_range(ctx, 1, ctx%src%nrec)
    if (ctx%stat /= 0) return
    ! the open step named at its own *STEP line
    if (ctx%in_step) call ctx_fail_kw(ctx, ctx%step_rec, '*STEP', 'the deck ends inside this step: *END STEP '// &
      'missing')
    if (ctx%stat == 0 .and. ctx%scope == scope_assembly) &
      call ctx_fail_kw(ctx, ctx%src%nrec, '*ASSEMBLY', 'the deck ends inside the assembly: *END ASSEMBLY missing')
  end subroutine read_blocks

  !> Read the keyword blocks of records i1..i2 (the whole deck, or a part's blocks for one of its instances).
  recursive subroutine read_range(ctx, i1, i2)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: i1                   !< first record
    integer, intent(in) :: i2                   !< last record
    integer :: ir, ir_next
    ir = i1
    do while (ir <= i2)
      ctx%ir = ir
      if (.not. ctx%src%rec(ir)%keyword) then
        call ctx_fail_kw(ctx, ir, '(data)', 'data line without a keyword before it')
        return
      end if
      call deck_keyword_parse(ctx%src%rec(ir)%text, ctx%kw, ctx%params)
      call canonical_keyword(ctx, ir)
      ! the records of this block: ir+1 .. ir_next-1
      ir_next = ir + 1
      do while (ir_next <= i2)
        if (ctx%src%rec(ir_next)%keyword) exit
        ir_next = ir_next + 1
      end do
      ctx%ir_next = ir_next
      if (ctx%in_step .and. is_model_keyword(ctx%kw)) then
        call ctx_fail(ctx, ir, 'model-data keyword inside a step (*STEP ... *END STEP)')
        return
      end if
      if (ctx%scope == scope_assembly .and. .not. allowed_in_assembly(ctx%kw)) then
        call ctx_fail(ctx, ir, 'not supported inside *ASSEMBLY (ldfcz reads *INSTANCE, *NODE, *ELEMENT, *NSET, '// &
          '*ELSET, *SURFACE, *EQUATION, *TIE, *MPC, *COUPLING, *TRANSFORM, *SYSTEM there)')
        return
      end if
      if (ctx%scope == scope_model .and. ctx%has_assembly .and. mesh_keyword(ctx%kw)) then
        call ctx_fail(ctx, ir, 'in a deck with an *ASSEMBLY, mesh, sets and sections belong in a *PART or in '// &
          'the *ASSEMBLY')
        return
      end if
      call read_block(ctx)
      if (ctx%stat /= 0) return
      call track_declaration_owner(ctx)
      ! a *PART or *INSTANCE block reaches past its end keyword
      ir = max(ir_next, ctx%ir_next)
    end do
  end subroutine read_range

  !> *INSTANCE ... *END INSTANCE: the part's blocks read with the instance's labels, names and placement.
  recursive subroutine read_instance(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: ip, ir_end, ir_inst, ir1, ir2
    ir_inst = ctx%ir
    call begin_instance(ctx, ip, ir_end, ir1, ir2)
    if (ctx%stat /= 0) return
    call read_range(ctx, ir1, ir2)
    if (ctx%stat /= 0) then
      ctx%errmsg = ctx%errmsg//' (part '//trim(ctx%parts(ip)%name)//', read for instance '// &
        trim(ctx%model%instances(ctx%model%ninstance)%name)//')'
      return
    end if
    ! messages of end_instance name the *INSTANCE line
    ctx%ir = ir_inst
    ctx%kw = '*INSTANCE'
    call end_instance(ctx)
    if (ctx%stat /= 0) return
    ctx%ir_next = ir_end + 1
  end subroutine read_instance

  !> Dispatch the block of keyword ctx%kw to its reader.
  recursive subroutine read_block(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    select case (ctx%kw)
    case ('*PART')
      call read_part_def(ctx)
    case ('*END PART')
      call ctx_fail(ctx, ctx%ir, '*END PART without *PART')
    case ('*ASSEMBLY')
      call begin_assembly(ctx)
    case ('*END ASSEMBLY')
      call end_assembly(ctx)
    case ('*INSTANCE')
      call read_instance(ctx)
    case ('*END INSTANCE')
      call ctx_fail(ctx, ctx%ir, '*END INSTANCE without *INSTANCE')
    case ('*ORIENTATION')
      call read_orientation(ctx)
    case ('*TRANSFORM')
      call read_transform(ctx)
    case ('*SYSTEM')
      call read_system(ctx)
    case ('*NGEN')
      call read_ngen(ctx)
    case ('*NFILL')
      call read_nfill(ctx)
    case ('*NCOPY')
      call read_ncopy(ctx)
    case ('*ELGEN')
      call read_elgen(ctx)
    case ('*PARAMETER')
      ! defined and substituted before the blocks are read (deck_parameters)
    case ('*HEADING')
      if (ctx%ir_next > ctx%ir + 1) ctx%model%heading = ctx%src%rec(ctx%ir + 1)%text
    case ('*NODE')
      call read_node(ctx)
    case ('*ELEMENT')
      call read_element(ctx)
    case ('*NSET')
      call read_set(ctx, .true.)
    case ('*ELSET')
      call read_set(ctx, .false.)
    case ('*SOLID SECTION')
      call read_solid_section(ctx)
    case ('*MATERIAL')
      call read_material(ctx)
    case ('*ELASTIC')
      call read_elastic(ctx)
    case ('*USER MATERIAL')
      call read_user_material(ctx)
    case ('*DEPVAR')
      call read_depvar(ctx)
    case ('*USER ELEMENT')
      call read_user_element(ctx)
    case ('*UEL PROPERTY')
      call read_uel_property(ctx)
    case ('*AMPLITUDE')
      call read_amplitude(ctx)
    case ('*BOUNDARY')
      call read_boundary(ctx)
    case ('*CLOAD')
      call read_cload(ctx)
    case ('*DLOAD')
      call read_dload(ctx)
    case ('*DSLOAD')
      call read_dsload(ctx)
    case ('*SURFACE')
      call read_surface(ctx)
    case ('*DENSITY')
      call read_density(ctx)
    case ('*INITIAL CONDITIONS')
      call read_initial_conditions(ctx)
    case ('*TEMPERATURE')
      call read_temperature(ctx)
    case ('*FIELD')
      call read_field(ctx)
    case ('*EXPANSION')
      call read_expansion(ctx)
    case ('*EQUATION')
      call read_equation(ctx)
    case ('*TIE')
      call read_tie(ctx)
    case ('*MPC')
      call read_mpc(ctx)
    case ('*COUPLING')
      call read_coupling(ctx)
    case ('*KINEMATIC', '*DISTRIBUTING')
      call read_coupling_kind(ctx)
    case ('*PRE-TENSION SECTION')
      call read_pretension_section(ctx)
    case ('*MODEL CHANGE')
      call read_model_change(ctx)
    case ('*TIME POINTS')
      call read_time_points(ctx)
    case ('*STEP')
      if (ctx%in_step) then
        call ctx_fail(ctx, ctx%ir, '*STEP inside a step: *END STEP missing for the *STEP at '// &
          deck_where(ctx%src, ctx%step_rec))
        return
      end if
      ctx%step_rec = ctx%ir
      call read_step(ctx)
    case ('*STATIC', '*VISCO')
      call read_static(ctx)
    case ('*CONTROLS')
      call read_controls(ctx)
    case ('*OUTPUT')
      call read_output(ctx)
    case ('*NODE OUTPUT', '*ELEMENT OUTPUT')
      call read_field_variables(ctx)
    case ('*NODE PRINT')
      call read_node_print(ctx)
    case ('*EL PRINT')
      call read_el_print(ctx)
    case ('*MONITOR')
      call read_monitor(ctx)
    case ('*END STEP')
      if (.not. ctx%in_step) then
        call ctx_fail(ctx, ctx%ir, '*END STEP without *STEP')
      else
        ctx%in_step = .false.
      end if
    case ('*RESTART')
      call read_restart(ctx)
    case ('*LDFCZ SVARS', '*LDFCZ STATEV', '*LDFCZ BUILTIN')
      call read_ldfcz_declaration(ctx)
    case ('*SECTION CONTROLS', '*HOURGLASS STIFFNESS')
      call read_section_controls(ctx)
    case ('*ENERGY PRINT', '*PREPRINT', '*FILE FORMAT', '*NODE FILE', '*EL FILE', &
          '*ENERGY OUTPUT', '*CONTACT OUTPUT', '*PRINT', '*ENERGY FILE', '*DIAGNOSTICS', '*SECTION PRINT')
      ! output and listing requests that cannot change a result (Abaqus/CAE writes some into every deck): a note
      call ctx_note(ctx, ctx%ir, 'output/cosmetic keyword without effect on the results; ldfcz does not write '// &
        'this output: ignored with its data lines')
    case default
      call ctx_fail(ctx, ctx%ir, unknown_keyword_text(ctx%kw))
    end select
  end subroutine read_block

  !> The keyword as ldfcz names it: Abaqus ignores blanks on keyword lines (*SOLIDSECTION is *SOLID SECTION) and
  !> reads keywords abbreviated as long as they stay unique ("Input syntax rules"). An abbreviation is taken only
  !> word by word (*SECTION CONTROL for *SECTION CONTROLS, never *CONTACT for *CONTACT OUTPUT) and only among the
  !> keywords ldfcz reads, so it is said in a warning.
  subroutine canonical_keyword(ctx, ir)
    type(deck_context_t), intent(inout) :: ctx  !< reader state (ctx%kw replaced)
    integer, intent(in) :: ir                   !< the keyword record
    integer :: k, n, j
    if (any(reader_keywords == ctx%kw)) return
    do k = 1, size(reader_keywords)
      if (no_blanks(reader_keywords(k)) == no_blanks(ctx%kw)) then
        ctx%kw = trim(reader_keywords(k))
        return
      end if
    end do
    n = 0
    do k = 1, size(reader_keywords)
      if (word_prefix(ctx%kw, trim(reader_keywords(k)))) then
        n = n + 1
        j = k
      end if
    end do
    if (n /= 1) return
    call ctx_warn(ctx, ir, 'taken as '//trim(reader_keywords(j))//' (an abbreviated keyword)')
    ctx%kw = trim(reader_keywords(j))
  end subroutine canonical_keyword

  !> short has as many blank-separated words as long and each begins the corresponding word of long.
  pure logical function word_prefix(short, long)
    character(len=*), intent(in) :: short, long  !< keywords (single blanks between words)
    integer :: a, b, c, d
    word_prefix = .false.
    a = 1
    c = 1
    do
      b = index(short(a:), ' ')
      d = index(long(c:), ' ')
      if ((b == 0) .neqv. (d == 0)) return
      if (b == 0) then
        b = len(short) - a + 2
        d = len(long) - c + 2
      end if
      if (b > d) return
      if (short(a:a + b - 2) /= long(c:c + b - 2)) return
      if (a + b - 1 > len(short)) exit
      a = a + b
      c = c + d
    end do
    word_prefix = .true.
  end function word_prefix

  !> Why a keyword is refused, with the supported keyword (or the Abaqus keyword) it is a slip from, if any.
  pure function unknown_keyword_text(kw) result(t)
    character(len=*), intent(in) :: kw  !< the keyword as read (upper case)
    character(len=:), allocatable :: t
    integer :: k
    if (any(other_abaqus_keywords == kw)) then
      t = 'an Abaqus keyword that ldfcz does not support (ldfcz never ignores a keyword that may change the '// &
        'analysis; docs/host.md lists what it reads)'
      return
    end if
    t = 'unknown keyword'
    k = deck_closest(kw, [character(len=36) :: reader_keywords, other_abaqus_keywords])
    if (k > size(reader_keywords)) then
      t = t//'; did you mean '//trim(other_abaqus_keywords(k - size(reader_keywords)))//' (not supported by ldfcz)?'
    else if (k > 0) then
      t = t//'; did you mean '//trim(reader_keywords(k))//'?'
    else
      t = t//' (ldfcz never ignores a keyword that may change the analysis; docs/host.md lists what it reads)'
    end if
  end function unknown_keyword_text

  !> Keywords of model data (not allowed between *STEP and *END STEP). *AMPLITUDE is model or history data in Abaqus
  !> (a curve defined in a step is a model-wide name from there on), so it is not among them.
  pure logical function is_model_keyword(kw)
    character(len=*), intent(in) :: kw  !< keyword, upper case
    select case (kw)
    case ('*NODE', '*ELEMENT', '*NSET', '*ELSET', '*SOLID SECTION', '*MATERIAL', '*ELASTIC', '*USER MATERIAL', &
          '*DEPVAR', '*USER ELEMENT', '*UEL PROPERTY', '*HEADING', '*SURFACE', '*DENSITY', &
          '*SECTION CONTROLS', '*HOURGLASS STIFFNESS', &
          '*INITIAL CONDITIONS', '*EXPANSION', '*EQUATION', '*TIE', '*MPC', '*PART', '*END PART', '*ASSEMBLY', &
          '*END ASSEMBLY', '*INSTANCE', '*END INSTANCE', '*NGEN', '*NFILL', '*NCOPY', '*ELGEN', '*ORIENTATION', &
          '*TRANSFORM', '*SYSTEM', '*COUPLING', '*KINEMATIC', '*DISTRIBUTING', '*TIME POINTS', &
          '*PRE-TENSION SECTION')
      is_model_keyword = .true.
    case default
      is_model_keyword = .false.
    end select
  end function is_model_keyword

end module deck_reader
