!> Keywords of the deck reader that shape a step's course: *MODEL CHANGE (history data: elements removed or added
!> back, Abaqus "Element and contact pair removal and reactivation") and *TIME POINTS (model data: named step times
!> that *OUTPUT, TIME POINTS= makes the increments end on). Element labels stay negative, sets are kept by index,
!> until finish_model (deck_finish_extras).
module deck_model_change
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: model_change_t, time_points_t, model_find_time_points
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_elset, ctx_fail, ctx_pos, &
    ctx_allow_params, ctx_need_step, ctx_required, ctx_split, ctx_get_real
  implicit none
  private
  public :: read_model_change, read_time_points

  integer, parameter :: max_time_points = 100000  !< bound on the points a GENERATE line may make

contains

  !> *MODEL CHANGE, TYPE=ELEMENT, REMOVE | ADD[=STRAIN FREE | WITH STRAIN] (history data): element labels or
  !> element sets. TYPE=CONTACT PAIR is refused.
  subroutine read_model_change(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(model_change_t) :: mc
    type(model_change_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n, k, id, iset
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'MECHSTRAINTORESIDUAL')) then
      call ctx_fail(ctx, ctx%ir, 'MECHSTRAINTORESIDUAL is a CalculiX extension that Abaqus does not have: '// &
        'not supported')
      return
    end if
    call ctx_allow_params(ctx, [character(len=8) :: 'TYPE', 'REMOVE', 'ADD'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    if (v /= '' .and. v /= 'ELEMENT') then
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (ELEMENT: ldfcz has no contact pairs)')
      return
    end if
    if (deck_has_param(ctx%params, 'REMOVE') .eqv. deck_has_param(ctx%params, 'ADD')) then
      call ctx_fail(ctx, ctx%ir, 'exactly one of REMOVE and ADD is required')
      return
    end if
    mc%remove = deck_has_param(ctx%params, 'REMOVE')
    if (mc%remove .and. len_trim(deck_param_value(ctx%params, 'REMOVE')) > 0) then
      call ctx_fail(ctx, ctx%ir, 'REMOVE takes no value')
      return
    end if
    v = deck_normalize(deck_param_value(ctx%params, 'ADD'))
    mc%strain_free = v /= 'WITH STRAIN'
    if (v /= '' .and. v /= 'STRAIN FREE' .and. v /= 'WITH STRAIN') then
      call ctx_fail(ctx, ctx%ir, 'ADD='//v//' is not one of STRAIN FREE, WITH STRAIN')
      return
    end if
    mc%pos = ctx_pos(ctx, ctx%ir)
    allocate (mc%elems(0), mc%elsets(0))
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (ctx_is_label(ctx, f(k))) then
          if (.not. ctx_get_label(ctx, i, f(k), .false., id)) return
          if (id < 1) then
            call ctx_fail(ctx, i, 'element ids must be positive, got '//itoa(id))
            return
          end if
          mc%elems = [mc%elems, -id]
        else
          iset = ctx_find_elset(ctx, f(k))
          if (iset == 0) then
            call ctx_fail(ctx, i, 'undefined element set '//deck_normalize(f(k)))
            return
          end if
          mc%elsets = [mc%elsets, iset]
        end if
      end do
    end do
    if (size(mc%elems) + size(mc%elsets) == 0) then
      call ctx_fail(ctx, ctx%ir, 'no elements: data lines of element labels or element sets are required')
      return
    end if
    associate (st => ctx%model%steps(ctx%istep))
      if (.not. allocated(st%changes)) allocate (st%changes(2))
      if (st%nchange == size(st%changes)) then
        allocate (tmp(2 * st%nchange))
        tmp(1:st%nchange) = st%changes(1:st%nchange)
        call move_alloc(tmp, st%changes)
      end if
      st%nchange = st%nchange + 1
      st%changes(st%nchange) = mc
    end associate
    ctx%model%has_model_change = .true.
  end subroutine read_model_change

  !> *TIME POINTS, NAME=[, GENERATE] (model data): step times in ascending order, or with GENERATE lines of
  !> start, end, increment (the points start + k increment up to end). TIME=TOTAL TIME is refused.
  subroutine read_time_points(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(time_points_t) :: tp
    type(time_points_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, k, m, j
    real(dp) :: v(3)
    logical :: gen
    call ctx_allow_params(ctx, [character(len=8) :: 'NAME', 'GENERATE', 'TIME'])
    if (ctx%stat /= 0) return
    if (deck_normalize(deck_param_value(ctx%params, 'TIME')) /= '' .and. &
        deck_normalize(deck_param_value(ctx%params, 'TIME')) /= 'STEP TIME') then
      call ctx_fail(ctx, ctx%ir, 'only TIME=STEP TIME is supported (the points are step times)')
      return
    end if
    tp%name = deck_normalize(ctx_required(ctx, 'NAME'))
    if (ctx%stat /= 0) return
    if (model_find_time_points(ctx%model, tp%name) > 0) then
      call ctx_fail(ctx, ctx%ir, 'time points '//trim(tp%name)//' defined twice')
      return
    end if
    gen = deck_has_param(ctx%params, 'GENERATE')
    allocate (tp%t(0))
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      do while (n > 0)
        if (len_trim(f(n)) > 0) exit
        n = n - 1
      end do
      if (gen) then
        if (n /= 3) then
          call ctx_fail(ctx, i, 'GENERATE: expected start, end, increment')
          return
        end if
        do k = 1, 3
          if (.not. ctx_get_real(ctx, i, f(k), v(k))) return
        end do
        if (.not. (v(3) > 0.0_dp .and. v(2) >= v(1))) then
          call ctx_fail(ctx, i, 'GENERATE: the end must not precede the start and the increment must be positive')
          return
        end if
        m = int((v(2) - v(1)) / v(3) * (1.0_dp + 1.0e-12_dp)) + 1
        if (m > max_time_points) then
          call ctx_fail(ctx, i, 'GENERATE: more than '//itoa(max_time_points)//' points')
          return
        end if
        tp%t = [tp%t, (v(1) + (j - 1) * v(3), j = 1, m)]
      else
        do k = 1, n
          if (len_trim(f(k)) == 0) then
            call ctx_fail(ctx, i, 'an empty field in the list of time points')
            return
          end if
          if (.not. ctx_get_real(ctx, i, f(k), v(1))) return
          tp%t = [tp%t, v(1)]
        end do
      end if
    end do
    if (size(tp%t) == 0) then
      call ctx_fail(ctx, ctx%ir, 'no time points given')
      return
    end if
    do k = 1, size(tp%t)
      if (tp%t(k) < 0.0_dp) then
        call ctx_fail(ctx, ctx%ir, 'a negative time point')
        return
      end if
      if (k > 1) then
        if (tp%t(k) <= tp%t(k - 1)) then
          call ctx_fail(ctx, ctx%ir, 'the time points must be in ascending order')
          return
        end if
      end if
    end do
    associate (m => ctx%model)
      if (.not. allocated(m%time_points)) allocate (m%time_points(2))
      if (m%ntime_points == size(m%time_points)) then
        allocate (tmp(2 * m%ntime_points))
        tmp(1:m%ntime_points) = m%time_points(1:m%ntime_points)
        call move_alloc(tmp, m%time_points)
      end if
      m%ntime_points = m%ntime_points + 1
      m%time_points(m%ntime_points) = tp
    end associate
  end subroutine read_time_points

end module deck_model_change
