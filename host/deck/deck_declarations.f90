!> Declarations for this host that an Abaqus deck carries as comments: a line '**LDFCZ KEYWORD, ...' is a comment
!> for Abaqus, so the deck stays valid Abaqus input, and reaches this reader as '*LDFCZ KEYWORD'. They tell the host
!> what a user routine stores where, so that the host needs no knowledge of a particular routine:
!>   **LDFCZ SVARS, TYPE=Un, POINTS=n, PER POINT=m, DELTA MAX=i, OPENING=j, TRACTION=k, LENGTH PROPERTY=p
!>     the SVARS of user elements of type Un are point-major, m per point, n points; within a point's block, entry
!>     i is the largest opening so far, j the current opening magnitude, k the traction magnitude (each optional,
!>     0 or absent: not stored); PROPS(p) is the opening length scale (delta). Used by the VTU cell data
!>     (Delta_max, traction) and the accuracy control --max-opening-increment (needs OPENING and LENGTH PROPERTY).
!>   **LDFCZ STATEV, MATERIAL=name, PLASTIC STRAIN=k
!>     STATEV(k) of the material's UMAT is an equivalent plastic strain: the summary reports its largest increment
!>     and --max-plastic-increment bounds it.
!>   **LDFCZ BUILTIN, UMAT=name [, MATERIAL=material]   or   **LDFCZ BUILTIN, UEL=name [, TYPE=Un]
!>     without --user, the material's *USER MATERIAL (the type's user elements) runs ldfcz's built-in routine of
!>     that name (host/user/builtin_routines.F90 lists them); without MATERIAL= (TYPE=) the declaration belongs to
!>     the *MATERIAL (*USER ELEMENT) whose definition it follows. A --user library's own routine always wins.
module deck_declarations
  use deck_lines, only: deck_has_param, deck_normalize, deck_param_value
  use model_types, only: model_find_user_type, model_find_material
  use deck_context, only: deck_context_t, ctx_fail, ctx_allow_params, ctx_required, ctx_param_int, ctx_pos
  implicit none
  private
  public :: read_ldfcz_declaration, track_declaration_owner

contains

  !> '**LDFCZ SVARS' or '**LDFCZ STATEV' (keyword *LDFCZ SVARS / *LDFCZ STATEV).
  subroutine read_ldfcz_declaration(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: name
    integer :: iu, im, k
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, 'a **LDFCZ declaration has no data lines')
      return
    end if
    select case (ctx%kw)
    case ('*LDFCZ SVARS')
      call ctx_allow_params(ctx, [character(len=16) :: 'TYPE', 'POINTS', 'PER POINT', 'DELTA MAX', 'OPENING', &
        'TRACTION', 'LENGTH PROPERTY'])
      if (ctx%stat /= 0) return
      name = deck_normalize(ctx_required(ctx, 'TYPE'))
      if (ctx%stat /= 0) return
      iu = model_find_user_type(ctx%model, name)
      if (iu == 0) then
        call ctx_fail(ctx, ctx%ir, 'TYPE='//name//' is not a *USER ELEMENT defined before this line')
        return
      end if
      associate (ut => ctx%model%utypes(iu))
        ut%sv_points = ctx_param_int(ctx, 'POINTS', 0)
        ut%sv_per_point = ctx_param_int(ctx, 'PER POINT', 0)
        ut%sv_delta_max = ctx_param_int(ctx, 'DELTA MAX', 0)
        ut%sv_opening = ctx_param_int(ctx, 'OPENING', 0)
        ut%sv_traction = ctx_param_int(ctx, 'TRACTION', 0)
        ut%sv_length_prop = ctx_param_int(ctx, 'LENGTH PROPERTY', 0)
        if (ctx%stat /= 0) return
        if (ut%sv_points < 1 .or. ut%sv_per_point < 1) then
          call ctx_fail(ctx, ctx%ir, 'POINTS and PER POINT must be >= 1')
        else if (ut%sv_points * ut%sv_per_point > ut%nsvars) then
          call ctx_fail(ctx, ctx%ir, 'POINTS x PER POINT exceeds the VARIABLES of *USER ELEMENT, TYPE='//name)
        else if (any([ut%sv_delta_max, ut%sv_opening, ut%sv_traction] < 0) .or. &
                 any([ut%sv_delta_max, ut%sv_opening, ut%sv_traction] > ut%sv_per_point)) then
          call ctx_fail(ctx, ctx%ir, 'DELTA MAX, OPENING and TRACTION must lie within 1..PER POINT (0: none)')
        else if (ut%sv_length_prop < 0 .or. ut%sv_length_prop > ut%nprops) then
          call ctx_fail(ctx, ctx%ir, 'LENGTH PROPERTY must lie within 1..PROPERTIES of the type (0: none)')
        end if
      end associate
    case ('*LDFCZ STATEV')
      call ctx_allow_params(ctx, [character(len=16) :: 'MATERIAL', 'PLASTIC STRAIN'])
      if (ctx%stat /= 0) return
      name = deck_normalize(ctx_required(ctx, 'MATERIAL'))
      if (ctx%stat /= 0) return
      im = model_find_material(ctx%model, name)
      if (im == 0) then
        call ctx_fail(ctx, ctx%ir, 'MATERIAL='//name//' is not a *MATERIAL defined before this line')
        return
      end if
      k = ctx_param_int(ctx, 'PLASTIC STRAIN', 0)
      if (ctx%stat /= 0) return
      if (k < 1) then
        call ctx_fail(ctx, ctx%ir, 'PLASTIC STRAIN must be a STATEV number >= 1')
        return
      end if
      ctx%model%materials(im)%plastic_statev = k
    case ('*LDFCZ BUILTIN')
      call read_builtin(ctx)
    case default
      call ctx_fail(ctx, ctx%ir, 'unknown **LDFCZ declaration (SVARS, STATEV or BUILTIN)')
    end select
  end subroutine read_ldfcz_declaration

  !> '**LDFCZ BUILTIN, UMAT=name [, MATERIAL=]' or '**LDFCZ BUILTIN, UEL=name [, TYPE=]': the built-in routine a
  !> material or user element type runs when no --user library gives one (the name is checked against the
  !> built-in library when the routines are chosen, host/user/routine_choice.f90).
  subroutine read_builtin(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: name, owner
    integer :: k
    call ctx_allow_params(ctx, [character(len=16) :: 'UMAT', 'UEL', 'MATERIAL', 'TYPE'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'UMAT') .eqv. deck_has_param(ctx%params, 'UEL')) then
      call ctx_fail(ctx, ctx%ir, 'give exactly one of UMAT=name (under a *MATERIAL) and UEL=name (after a '// &
        '*USER ELEMENT)')
      return
    end if
    if (deck_has_param(ctx%params, 'UMAT')) then
      name = deck_normalize(ctx_required(ctx, 'UMAT'))
      if (deck_has_param(ctx%params, 'TYPE')) call ctx_fail(ctx, ctx%ir, 'TYPE= belongs to UEL=; UMAT= takes MATERIAL=')
      if (ctx%stat /= 0) return
      k = ctx%decl_material
      if (deck_has_param(ctx%params, 'MATERIAL')) then
        owner = deck_normalize(ctx_required(ctx, 'MATERIAL'))
        if (ctx%stat /= 0) return
        k = model_find_material(ctx%model, owner)
        if (k == 0) then
          call ctx_fail(ctx, ctx%ir, 'MATERIAL='//owner//' is not a *MATERIAL defined before this line')
          return
        end if
      else if (k == 0) then
        call ctx_fail(ctx, ctx%ir, 'UMAT= without MATERIAL= belongs inside a *MATERIAL definition (after '// &
          '*MATERIAL or one of its options)')
        return
      end if
      if (len_trim(ctx%model%materials(k)%builtin) > 0) then
        call ctx_fail(ctx, ctx%ir, 'material '//trim(ctx%model%materials(k)%given_name)//' already declares '// &
          'a built-in UMAT')
        return
      end if
      ctx%model%materials(k)%builtin = name
      ctx%model%materials(k)%builtin_pos = ctx_pos(ctx, ctx%ir)
    else
      name = deck_normalize(ctx_required(ctx, 'UEL'))
      if (deck_has_param(ctx%params, 'MATERIAL')) call ctx_fail(ctx, ctx%ir, 'MATERIAL= belongs to UMAT=; UEL= '// &
        'takes TYPE=')
      if (ctx%stat /= 0) return
      k = ctx%decl_utype
      if (deck_has_param(ctx%params, 'TYPE')) then
        owner = deck_normalize(ctx_required(ctx, 'TYPE'))
        if (ctx%stat /= 0) return
        k = model_find_user_type(ctx%model, owner)
        if (k == 0) then
          call ctx_fail(ctx, ctx%ir, 'TYPE='//owner//' is not a *USER ELEMENT defined before this line')
          return
        end if
      else if (k == 0) then
        call ctx_fail(ctx, ctx%ir, 'UEL= without TYPE= belongs right after a *USER ELEMENT block')
        return
      end if
      if (len_trim(ctx%model%utypes(k)%builtin) > 0) then
        ! (a part's declaration read again for its next instance)
        if (ctx%model%utypes(k)%builtin_pos%line == ctx%src%rec(ctx%ir)%line) return
        call ctx_fail(ctx, ctx%ir, 'user element type '//trim(ctx%model%utypes(k)%name)//' already declares '// &
          'a built-in UEL')
        return
      end if
      ctx%model%utypes(k)%builtin = name
      ctx%model%utypes(k)%builtin_pos = ctx_pos(ctx, ctx%ir)
    end if
  end subroutine read_builtin

  !> After each keyword block: the material or user element type that a following '**LDFCZ BUILTIN' without
  !> MATERIAL= or TYPE= belongs to (a material's definition runs over its option keywords; declarations keep it).
  subroutine track_declaration_owner(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    select case (ctx%kw)
    case ('*MATERIAL', '*ELASTIC', '*USER MATERIAL', '*DEPVAR', '*DENSITY', '*EXPANSION')
      ctx%decl_material = ctx%imat
      ctx%decl_utype = 0
    case ('*USER ELEMENT')
      ctx%decl_material = 0
      ctx%decl_utype = ctx%model%nutype
    case ('*LDFCZ SVARS', '*LDFCZ STATEV', '*LDFCZ BUILTIN')
    case default
      ctx%decl_material = 0
      ctx%decl_utype = 0
    end select
  end subroutine track_declaration_owner

end module deck_declarations
