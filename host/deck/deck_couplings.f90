!> Coupling keywords of the deck reader: *COUPLING (reference node, element-based surface of the coupling nodes,
!> influence radius) followed by *KINEMATIC (the coupling nodes follow the reference node's rigid-body motion) or
!> *DISTRIBUTING (the reference node follows the coupling nodes' weighted mean motion), as the Abaqus Keywords
!> Reference defines them (docs/host.md, "Coupling constraints"). The reference node is a negative label, or a node
!> set, until finish_model (deck_finish_extras).
module deck_couplings
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: coupling_t
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_surface, ctx_warn, &
    ctx_fail, ctx_pos, ctx_allow_params, ctx_required, ctx_split, ctx_get_real, ctx_get_int, ctx_only_value
  implicit none
  private
  public :: read_coupling, read_coupling_kind

contains

  !> *COUPLING, CONSTRAINT NAME=, REF NODE= (a node or a node set of one node), SURFACE= (element-based)[,
  !> INFLUENCE RADIUS=][, ADJUST=NO][, ORIENTATION=] (the *ORIENTATION, resolved in finish_model, whose local
  !> directions the constrained dofs of the *KINEMATIC or *DISTRIBUTING lines are in; 3D only); no data lines.
  subroutine read_coupling(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(coupling_t) :: c
    type(coupling_t), allocatable :: tmp(:)
    character(len=:), allocatable :: v
    integer :: id
    call ctx_allow_params(ctx, [character(len=16) :: 'CONSTRAINT NAME', 'REF NODE', 'SURFACE', 'INFLUENCE RADIUS', &
      'ORIENTATION', 'ADJUST'])
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'ORIENTATION')) then
      c%orientation = deck_normalize(deck_param_value(ctx%params, 'ORIENTATION'))
      if (len_trim(c%orientation) == 0) then
        call ctx_fail(ctx, ctx%ir, 'ORIENTATION= needs the name of an *ORIENTATION')
        return
      end if
    end if
    if (.not. ctx_only_value(ctx, ctx%ir, 'ADJUST', 'NO', ' (ldfcz does not move the reference node)')) return
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, '*COUPLING has no data lines (the constraint type follows: *KINEMATIC or '// &
        '*DISTRIBUTING)')
      return
    end if
    c%name = deck_normalize(ctx_required(ctx, 'CONSTRAINT NAME'))
    if (ctx%stat /= 0) return
    v = ctx_required(ctx, 'REF NODE')
    if (ctx%stat /= 0) return
    if (ctx_is_label(ctx, v)) then
      if (.not. ctx_get_label(ctx, ctx%ir, v, .true., id)) return
      if (id < 1) then
        call ctx_fail(ctx, ctx%ir, 'REF NODE: node ids must be positive, got '//itoa(id))
        return
      end if
      c%ref = -id
    else
      c%ref_set = ctx_find_nset(ctx, v)
      if (c%ref_set == 0) then
        call ctx_fail(ctx, ctx%ir, 'REF NODE: undefined node set '//deck_normalize(v))
        return
      end if
    end if
    v = ctx_required(ctx, 'SURFACE')
    if (ctx%stat /= 0) return
    c%surface = ctx_find_surface(ctx, v)
    if (c%surface == 0) then
      call ctx_fail(ctx, ctx%ir, 'SURFACE: undefined surface '//deck_normalize(v)//' (an element-based *SURFACE '// &
        'defined before)')
      return
    end if
    if (deck_has_param(ctx%params, 'INFLUENCE RADIUS')) then
      if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'INFLUENCE RADIUS'), c%radius)) return
      if (.not. c%radius > 0.0_dp) then
        call ctx_fail(ctx, ctx%ir, 'INFLUENCE RADIUS must be positive')
        return
      end if
    end if
    c%pos = ctx_pos(ctx, ctx%ir)
    associate (m => ctx%model)
      if (.not. allocated(m%couplings)) allocate (m%couplings(2))
      if (m%ncoupling == size(m%couplings)) then
        allocate (tmp(2 * m%ncoupling))
        tmp(1:m%ncoupling) = m%couplings(1:m%ncoupling)
        call move_alloc(tmp, m%couplings)
      end if
      m%ncoupling = m%ncoupling + 1
      m%couplings(m%ncoupling) = c
    end associate
  end subroutine read_coupling

  !> *KINEMATIC or *DISTRIBUTING[, WEIGHTING METHOD=][, COUPLING=CONTINUUM] after a *COUPLING: data lines first
  !> dof[, last dof] (none: every dof). A distributing coupling constrains every translation; of the rotations all
  !> or none (the reference node's rotations as the weighted least-squares rotation of the coupling nodes).
  subroutine read_coupling_kind(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n, d1, d2
    logical :: dofs(6), kinematic
    kinematic = ctx%kw == '*KINEMATIC'
    if (kinematic) then
      call ctx_allow_params(ctx, [character(len=16) ::])
    else
      call ctx_allow_params(ctx, [character(len=16) :: 'WEIGHTING METHOD', 'COUPLING'])
    end if
    if (ctx%stat /= 0) return
    if (ctx%model%ncoupling == 0) then
      call ctx_fail(ctx, ctx%ir, 'must follow a *COUPLING')
      return
    end if
    associate (c => ctx%model%couplings(ctx%model%ncoupling))
      if (c%kind_pos%line /= 0) then
        call ctx_fail(ctx, ctx%ir, 'must follow a *COUPLING (coupling '//trim(c%name)//' has its type already)')
        return
      end if
      c%kinematic = kinematic
      c%kind_pos = ctx_pos(ctx, ctx%ir)
      if (.not. kinematic) then
        if (.not. ctx_only_value(ctx, ctx%ir, 'COUPLING', 'CONTINUUM', ' (STRUCTURAL needs the coupling nodes'' '// &
          'rotations, which continuum nodes do not have)')) return
        v = deck_normalize(deck_param_value(ctx%params, 'WEIGHTING METHOD'))
        select case (v)
        case ('', 'UNIFORM')
          c%weighting = 1
        case ('LINEAR')
          c%weighting = 2
        case ('QUADRATIC')
          c%weighting = 3
        case ('CUBIC')
          c%weighting = 4
        case default
          call ctx_fail(ctx, ctx%ir, 'WEIGHTING METHOD='//v//' is not one of UNIFORM, LINEAR, QUADRATIC, CUBIC')
          return
        end select
      end if
      dofs = .false.
      do i = ctx%ir + 1, ctx%ir_next - 1
        call ctx_split(ctx, i, f, n)
        if (n == 0) cycle
        if (n > 2) then
          if (any(len_trim(f(3:n)) > 0)) then
            call ctx_fail(ctx, i, 'expected: first dof[, last dof]')
            return
          end if
        end if
        if (len_trim(f(1)) == 0) then
          dofs = .true.
          cycle
        end if
        if (.not. ctx_get_int(ctx, i, f(1), d1)) return
        d2 = d1
        if (n >= 2) then
          if (len_trim(f(2)) > 0) then
            if (.not. ctx_get_int(ctx, i, f(2), d2)) return
          end if
        end if
        if (d1 < 1 .or. d2 > 6 .or. d2 < d1) then
          call ctx_fail(ctx, i, 'dof range '//itoa(d1)//'..'//itoa(d2)//' invalid (1..6)')
          return
        end if
        dofs(d1:d2) = .true.
      end do
      if (ctx%ir_next == ctx%ir + 1) dofs = .true.
      c%dofs = dofs
      if (kinematic .and. .not. any(dofs(1:3))) then
        call ctx_fail(ctx, ctx%ir, 'constrains no translation: the coupling nodes of a continuum surface have '// &
          'translations only')
        return
      end if
      ! a distributing coupling: "Only rotational degrees of freedom can be released. All available translational
      ! degrees of freedom are constrained" (Keywords Reference *DISTRIBUTING): so here, with a warning
      if (.not. kinematic .and. .not. all(dofs(1:3))) then
        call ctx_warn(ctx, ctx%ir, 'a distributing coupling constrains every translation, as Abaqus does (only '// &
          'rotations can be released): dofs 1..3 constrained')
        dofs(1:3) = .true.
        c%dofs = dofs
      end if
    end associate
  end subroutine read_coupling_kind

end module deck_couplings
