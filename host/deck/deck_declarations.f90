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
module deck_declarations
  use deck_lines, only: deck_has_param, deck_normalize, deck_param_value
  use model_types, only: model_find_user_type, model_find_material
  use deck_context, only: deck_context_t, ctx_fail, ctx_allow_params, ctx_required, ctx_param_int
  implicit none
  private
  public :: read_ldfcz_declaration

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
    case default
      call ctx_fail(ctx, ctx%ir, 'unknown **LDFCZ declaration (SVARS or STATEV)')
    end select
  end subroutine read_ldfcz_declaration

end module deck_declarations
