!> *SECTION CONTROLS and *HOURGLASS STIFFNESS, and CONTROLS= of *SOLID SECTION (decks written by Abaqus/CAE for
!> reduced-integration elements carry them). ldfcz's one-point elements have their own hourglass control, the
!> Flanagan-Belytschko stiffness form (docs/elements.md), which Abaqus' HOURGLASS= choices and stiffness values do
!> not change here: the keywords are read, checked and said in a warning (Abaqus' own default hourglass control
!> is not reproduced either). A control that changes the analysis otherwise (ELEMENT DELETION=YES) is refused.
module deck_section_controls
  use deck_lines, only: deck_has_param, deck_param_value, deck_normalize
  use deck_context, only: deck_context_t, ctx_fail, ctx_warn, ctx_allow_params, ctx_required
  implicit none
  private
  public :: read_section_controls

contains

  !> *SECTION CONTROLS, NAME=[, HOURGLASS=][, ...] or *HOURGLASS STIFFNESS (data line: the stiffness values).
  subroutine read_section_controls(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: name
    if (ctx%kw == '*HOURGLASS STIFFNESS') then
      call ctx_allow_params(ctx, [character(len=8) ::])
      if (ctx%stat /= 0) return
      call ctx_warn(ctx, ctx%ir, 'read without effect: the one-point elements use ldfcz''s hourglass stiffness '// &
        '(k = G V sum (dN/dX)^2, docs/elements.md), not these values')
      return
    end if
    call ctx_allow_params(ctx, [character(len=24) :: 'NAME', 'HOURGLASS', 'ELEMENT DELETION', 'KINEMATIC SPLIT', &
      'SECOND ORDER ACCURACY', 'DISTORTION CONTROL', 'MAX DEGRADATION', 'VISCOSITY', 'ELEMENT CONVERSION'])
    if (ctx%stat /= 0) return
    name = deck_normalize(ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'ELEMENT DELETION')) then
      if (deck_normalize(deck_param_value(ctx%params, 'ELEMENT DELETION')) /= 'NO') then
        call ctx_fail(ctx, ctx%ir, 'ELEMENT DELETION is not supported')
        return
      end if
    end if
    if (deck_has_param(ctx%params, 'ELEMENT CONVERSION') .or. deck_has_param(ctx%params, 'MAX DEGRADATION')) then
      call ctx_fail(ctx, ctx%ir, 'ELEMENT CONVERSION and MAX DEGRADATION are not supported')
      return
    end if
    call ctx_warn(ctx, ctx%ir, 'section controls '//name//' read without effect: the one-point elements use '// &
      'ldfcz''s Flanagan-Belytschko hourglass stiffness whatever HOURGLASS= says (docs/elements.md); the other '// &
      'controls concern Abaqus/Explicit')
  end subroutine read_section_controls

end module deck_section_controls
