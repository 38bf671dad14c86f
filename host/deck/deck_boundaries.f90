!> Boundary-condition keywords of the deck reader: *AMPLITUDE (tabular, step time) and *BOUNDARY (model data: the
!> initial conditions; history data: the step's prescribed displacements).
module deck_boundaries
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: amplitude_t, boundary_t, model_find_amplitude
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_fail, ctx_pos, &
    ctx_allow_params, ctx_required, ctx_block_fields, ctx_split, ctx_get_real, ctx_get_int, ctx_only_value
  implicit none
  private
  public :: read_amplitude, read_boundary

contains

  !> *AMPLITUDE, NAME=, DEFINITION=TABULAR|SMOOTH STEP, TIME=STEP TIME|TOTAL TIME: pairs of time and relative
  !> amplitude, times not decreasing.
  subroutine read_amplitude(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(amplitude_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: n, k, ia, ir, ir_next
    real(dp) :: r
    character(len=:), allocatable :: v
    logical :: smooth, total_time, equal
    call ctx_allow_params(ctx, [character(len=16) :: 'NAME', 'DEFINITION', 'TIME', 'VALUE', 'FIXED INTERVAL', &
      'BEGIN', 'SMOOTH'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    v = deck_normalize(deck_param_value(ctx%params, 'DEFINITION'))
    if (v /= '' .and. v /= 'TABULAR' .and. v /= 'SMOOTH STEP' .and. v /= 'EQUALLY SPACED') then
      call ctx_fail(ctx, ir, 'DEFINITION='//v//' is not supported (TABULAR, EQUALLY SPACED, SMOOTH STEP)')
      return
    end if
    ! SMOOTH= (TABULAR, EQUALLY SPACED) smooths the time derivatives of the amplitude only (Abaqus Keywords Guide,
    ! *AMPLITUDE), which a static step does not use
    if (v == 'SMOOTH STEP' .and. deck_has_param(ctx%params, 'SMOOTH')) then
      call ctx_fail(ctx, ir, 'SMOOTH= belongs to TABULAR and EQUALLY SPACED')
      return
    end if
    equal = v == 'EQUALLY SPACED'
    if (equal .neqv. deck_has_param(ctx%params, 'FIXED INTERVAL')) then
      call ctx_fail(ctx, ir, 'FIXED INTERVAL= is required with DEFINITION=EQUALLY SPACED and only there')
      return
    end if
    if (deck_has_param(ctx%params, 'BEGIN') .and. .not. equal) then
      call ctx_fail(ctx, ir, 'BEGIN= belongs to DEFINITION=EQUALLY SPACED')
      return
    end if
    smooth = v == 'SMOOTH STEP'
    v = deck_normalize(deck_param_value(ctx%params, 'TIME'))
    if (v /= '' .and. v /= 'STEP TIME' .and. v /= 'TOTAL TIME') then
      call ctx_fail(ctx, ir, 'TIME='//v//' is not supported (STEP TIME, TOTAL TIME)')
      return
    end if
    total_time = v == 'TOTAL TIME'
    if (.not. ctx_only_value(ctx, ir, 'VALUE', 'RELATIVE')) return
    if (ctx%model%namp == size(ctx%model%amplitudes)) then
      allocate (tmp(2 * size(ctx%model%amplitudes)))
      tmp(1:ctx%model%namp) = ctx%model%amplitudes(1:ctx%model%namp)
      call move_alloc(tmp, ctx%model%amplitudes)
    end if
    ia = ctx%model%namp + 1
    v = deck_normalize(ctx_required(ctx, 'NAME'))
    ctx%model%amplitudes(ia)%name = v
    ctx%model%amplitudes(ia)%smooth = smooth
    ctx%model%amplitudes(ia)%total_time = total_time
    if (ctx%stat /= 0) return
    if (model_find_amplitude(ctx%model, ctx%model%amplitudes(ia)%name) > 0) then
      call ctx_fail(ctx, ir, 'amplitude '//trim(ctx%model%amplitudes(ia)%name)//' defined twice')
      return
    end if
    call ctx_block_fields(ctx, ir + 1, ir_next - 1, f, n)
    if (equal) then
      call equally_spaced(ctx, ia, f, n)
      if (ctx%stat == 0) ctx%model%namp = ia
      return
    end if
    if (n < 2 .or. mod(n, 2) /= 0) then
      call ctx_fail(ctx, ir, 'data must be pairs of time, amplitude')
      return
    end if
    allocate (ctx%model%amplitudes(ia)%t(n / 2), ctx%model%amplitudes(ia)%a(n / 2))
    do k = 1, n / 2
      if (.not. ctx_get_real(ctx, ir + 1, f(2 * k - 1), r)) return
      ctx%model%amplitudes(ia)%t(k) = r
      if (.not. ctx_get_real(ctx, ir + 1, f(2 * k), r)) return
      ctx%model%amplitudes(ia)%a(k) = r
      if (k > 1) then
        if (ctx%model%amplitudes(ia)%t(k) < ctx%model%amplitudes(ia)%t(k - 1)) then
          call ctx_fail(ctx, ir, 'times must not decrease')
          return
        end if
      end if
    end do
    ctx%model%namp = ia
  end subroutine read_amplitude

  !> DEFINITION=EQUALLY SPACED: the values a_1, a_2, ... at BEGIN (default 0) + (i - 1) FIXED INTERVAL, linear
  !> between them as a tabular amplitude (Abaqus Keywords Guide, *AMPLITUDE).
  subroutine equally_spaced(ctx, ia, f, n)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: ia                   !< the amplitude being defined
    character(len=*), intent(in) :: f(:)        !< its data fields
    integer, intent(in) :: n                    !< number of fields
    real(dp) :: dt, t0
    integer :: k
    t0 = 0.0_dp
    if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'FIXED INTERVAL'), dt)) return
    if (deck_has_param(ctx%params, 'BEGIN')) then
      if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'BEGIN'), t0)) return
    end if
    if (.not. (dt > 0.0_dp)) then
      call ctx_fail(ctx, ctx%ir, 'FIXED INTERVAL must be positive')
      return
    end if
    if (n < 1) then
      call ctx_fail(ctx, ctx%ir, 'the amplitude values are required')
      return
    end if
    allocate (ctx%model%amplitudes(ia)%t(n), ctx%model%amplitudes(ia)%a(n))
    do k = 1, n
      ctx%model%amplitudes(ia)%t(k) = t0 + (k - 1) * dt
      if (.not. ctx_get_real(ctx, ctx%ir + 1, f(k), ctx%model%amplitudes(ia)%a(k))) return
    end do
  end subroutine equally_spaced

  !> *BOUNDARY: node or node set, first dof[, last dof[, value]] or a type (XSYMM, ...). Node ids stay negative
  !> user ids until finish_model.
  subroutine read_boundary(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(boundary_t) :: bc, empty_bc
    character(len=flen), allocatable :: f(:)
    integer :: i, n, id, iset, iamp, ir, istep
    logical :: velocity, user, fixed
    character(len=:), allocatable :: v, word
    call ctx_allow_params(ctx, [character(len=12) :: 'AMPLITUDE', 'OP', 'TYPE', 'USER', 'FIXED'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    istep = ctx%istep
    if (.not. parameters_ok()) return
    do i = ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      bc = empty_bc
      bc%amplitude = iamp
      bc%velocity = velocity
      bc%user = user
      bc%fixed = fixed
      bc%pos = ctx_pos(ctx, i)
      if (n < 2) then
        call ctx_fail(ctx, i, 'expected: node or node set, first dof[, last dof[, value]] or a type (XSYMM, ...)')
        return
      end if
      if (ctx_is_label(ctx, f(1))) then
        if (.not. ctx_get_label(ctx, i, f(1), .true., id)) return
        if (id < 1) then
          call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
          return
        end if
        allocate (bc%nodes(1))
        bc%nodes(1) = -id  ! resolved in finish_model
      else
        iset = ctx_find_nset(ctx, f(1))
        if (iset == 0) then
          call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(1)))
          return
        end if
        bc%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
      end if
      word = deck_normalize(f(2))
      if (verify(trim(f(2)), '0123456789+-') /= 0) then
        if (n > 2) then
          if (any(len_trim(f(3:n)) > 0)) then
            call ctx_fail(ctx, i, 'no values may follow a boundary type')
            return
          end if
        end if
        ! the Abaqus types with their rotational dofs (Keywords Reference, *BOUNDARY): rotations exist only at a
        ! coupling's reference node and are dropped elsewhere
        select case (word)
        case ('XSYMM')
          call set_type(1, 1, [5, 6, 0])
        case ('YSYMM')
          call set_type(2, 2, [4, 6, 0])
        case ('ZSYMM')
          call set_type(3, 3, [4, 5, 0])
        case ('ENCASTRE')
          call set_type(1, 3, [4, 5, 6])
        case ('PINNED')
          call set_type(1, 3, [0, 0, 0])
        case default
          call ctx_fail(ctx, i, 'unsupported boundary type '//word//' (XSYMM, YSYMM, ZSYMM, ENCASTRE, PINNED)')
          return
        end select
      else
        if (.not. dof_line_ok(i)) return
      end if
      call push_step_or_model(bc)
    end do

  contains

    !> The parameters (FIXED, USER, TYPE, OP, AMPLITUDE) into fixed, user, velocity and iamp; .false. after a
    !> message when they are not valid.
    logical function parameters_ok() result(ok)
      ok = .false.
      ! FIXED (history data, Keywords Reference *BOUNDARY): the dofs held at their values at the start of the step;
      ! not with TYPE or USER (as documented) nor AMPLITUDE (nothing to scale); a magnitude on its lines is refused
      fixed = deck_has_param(ctx%params, 'FIXED')
      if (fixed) then
        if (.not. ctx%in_step) then
          call ctx_fail(ctx, ir, 'FIXED only inside a step (history data)')
          return
        end if
        if (deck_has_param(ctx%params, 'TYPE') .or. deck_has_param(ctx%params, 'USER') .or. &
            deck_has_param(ctx%params, 'AMPLITUDE')) then
          call ctx_fail(ctx, ir, 'FIXED cannot be combined with TYPE, USER or AMPLITUDE')
          return
        end if
      end if
      ! USER: the magnitudes come from the user subroutine DISP (history data only)
      user = deck_has_param(ctx%params, 'USER')
      if (user .and. .not. ctx%in_step) then
        call ctx_fail(ctx, ir, 'USER only inside a step (history data)')
        return
      end if
      ! TYPE=DISPLACEMENT (the default) or VELOCITY (in a step: the increment of the dof is v dt, v applied as a STEP
      ! unless an amplitude is given, as Abaqus/Standard does in a static step)
      v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
      if (len(v) > 0 .and. v /= 'DISPLACEMENT' .and. v /= 'VELOCITY') then
        call ctx_fail(ctx, ir, 'TYPE='//v//' is not supported (DISPLACEMENT, VELOCITY)')
        return
      end if
      velocity = v == 'VELOCITY'
      if (velocity .and. .not. ctx%in_step) then
        call ctx_fail(ctx, ir, 'TYPE=VELOCITY only inside a step (history data)')
        return
      end if
      v = deck_normalize(deck_param_value(ctx%params, 'OP'))
      if (len(v) > 0 .and. v /= 'MOD' .and. v /= 'NEW') then
        call ctx_fail(ctx, ir, 'OP must be MOD or NEW')
        return
      end if
      if (v == 'NEW') then
        if (.not. ctx%in_step) then
          call ctx_fail(ctx, ir, 'OP=NEW only inside a step')
          return
        end if
        ctx%model%steps(istep)%op_new = .true.
      end if
      iamp = 0
      if (deck_has_param(ctx%params, 'AMPLITUDE')) then
        if (.not. ctx%in_step) then
          call ctx_fail(ctx, ir, 'AMPLITUDE= only inside a step')
          return
        end if
        iamp = model_find_amplitude(ctx%model, deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
        if (iamp == 0) then
          call ctx_fail(ctx, ir, 'undefined amplitude '//deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE')))
          return
        end if
      end if
      ok = .true.
    end function parameters_ok

    !> A data line of dofs: first dof[, last dof[, value]] into bc; .false. after a message when it is not valid.
    logical function dof_line_ok(i) result(ok)
      integer, intent(in) :: i  !< the line
      ok = .false.
      if (.not. ctx_get_int(ctx, i, f(2), bc%first_dof)) return
      bc%last_dof = bc%first_dof
      if (n >= 3) then
        if (len_trim(f(3)) > 0) then
          if (.not. ctx_get_int(ctx, i, f(3), bc%last_dof)) return
        end if
      end if
      if (n >= 4) then
        if (len_trim(f(4)) > 0) then
          if (.not. ctx_get_real(ctx, i, f(4), bc%value)) return
        end if
      end if
      if (n > 4) then
        call ctx_fail(ctx, i, 'too many fields')
        return
      end if
      if (fixed .and. bc%value /= 0.0_dp) then
        call ctx_fail(ctx, i, 'FIXED holds the dofs at their values at the start of the step: no magnitude')
        return
      end if
      if (bc%first_dof < 1 .or. bc%last_dof > 6 .or. bc%last_dof < bc%first_dof) then
        call ctx_fail(ctx, i, 'dof range '//itoa(bc%first_dof)//'..'//itoa(bc%last_dof)//' invalid')
        return
      end if
      ! rotations (dofs 4..6) exist at the reference node of a *COUPLING only: checked when the model is complete
      if (bc%last_dof > 3 .and. bc%user) then
        call ctx_fail(ctx, i, 'USER (the subroutine DISP) on a rotational dof is not supported')
        return
      end if
      ok = .true.
    end function dof_line_ok

    subroutine set_type(d1, d2, rot)
      integer, intent(in) :: d1, d2, rot(3)
      bc%first_dof = d1
      bc%last_dof = d2
      bc%rot_dofs = rot
    end subroutine set_type

    subroutine push_step_or_model(t)
      type(boundary_t), intent(in) :: t
      if (ctx%in_step) then
        call push_bc(ctx%model%steps(istep)%bcs, ctx%model%steps(istep)%nbc, t)
      else
        call push_bc(ctx%model%initial_bcs, ctx%model%n_initial_bc, t)
      end if
    end subroutine push_step_or_model

  end subroutine read_boundary

  !> Append a boundary to a list with n entries, doubling the capacity when full.
  pure subroutine push_bc(list, n, bc)
    type(boundary_t), allocatable, intent(inout) :: list(:) !< boundary list
    integer, intent(inout) :: n                             !< entries in use
    type(boundary_t), intent(in) :: bc                      !< boundary to append
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

end module deck_boundaries
