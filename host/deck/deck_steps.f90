!> History keywords of the deck reader: *STEP, *STATIC, *CONTROLS, *RESTART, *OUTPUT, *NODE PRINT, *EL PRINT (their
!> variables resolved against the output registry, host/output/output_registry.f90).
module deck_steps
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use model_types, only: step_t, node_print_t, el_print_t, output_request_t, model_find_time_points
  use output_registry, only: output_lookup, output_variables, output_ncomp, output_component_name, &
    output_names_text, OV_SDV, LOC_NODE, LOC_POINT, USE_FIELD, USE_NODE_PRINT, USE_EL_PRINT, PRESET_ALL
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_find_nset, ctx_find_elset, ctx_fail, ctx_warn, ctx_note, ctx_pos, &
    ctx_allow_params, ctx_need_step, ctx_required, ctx_get_label, ctx_param_int, ctx_split, ctx_get_real, &
    ctx_get_int, ctx_only_value
  implicit none
  private
  public :: read_field_variables, read_step, read_static, read_controls, read_restart, read_output, read_node_print
  public :: read_el_print, read_monitor

contains

  !> *STEP, NAME=, NLGEOM=, INC=, UNSYMM=, AMPLITUDE=RAMP|STEP: opens a step (NLGEOM and the restart request carry over).
  subroutine read_step(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(step_t), allocatable :: tmp(:)
    type(step_t) :: empty_step
    character(len=:), allocatable :: v
    integer :: istep, ir, max_inc
    if (ctx%in_step) then
      call ctx_fail(ctx, ctx%ir, '*STEP inside a step: *END STEP missing')
      return
    end if
    call ctx_allow_params(ctx, [character(len=16) :: 'NAME', 'NLGEOM', 'INC', 'UNSYMM', 'AMPLITUDE', 'EXTRAPOLATION', &
      'PERTURBATION'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    if (deck_has_param(ctx%params, 'PERTURBATION')) then
      call ctx_fail(ctx, ir, 'PERTURBATION steps are not supported')
      return
    end if
    if (ctx%model%nstep == size(ctx%model%steps)) then
      allocate (tmp(2 * size(ctx%model%steps)))
      tmp(1:ctx%model%nstep) = ctx%model%steps(1:ctx%model%nstep)
      call move_alloc(tmp, ctx%model%steps)
    end if
    ctx%model%nstep = ctx%model%nstep + 1
    istep = ctx%model%nstep
    ctx%istep = istep
    ctx%model%steps(istep) = empty_step
    ctx%output_kind = 0
    allocate (ctx%model%steps(istep)%bcs(4), ctx%model%steps(istep)%prints(2), ctx%model%steps(istep)%cloads(4), &
      ctx%model%steps(istep)%dloads(4))
    ! NLGEOM carries over from the previous step, as in Abaqus
    if (istep > 1) ctx%model%steps(istep)%nlgeom = ctx%model%steps(istep - 1)%nlgeom
    ! a *RESTART, WRITE request stays in effect until changed (Abaqus)
    ctx%model%steps(istep)%restart_frequency = ctx%restart_freq
    if (deck_has_param(ctx%params, 'NLGEOM')) then
      v = deck_normalize(deck_param_value(ctx%params, 'NLGEOM'))
      if (v == '' .or. v == 'YES') then
        ctx%model%steps(istep)%nlgeom = .true.
      else if (v == 'NO') then
        if (istep > 1) then  ! (no short-circuit in Fortran: steps(0) must not be evaluated)
          if (ctx%model%steps(istep - 1)%nlgeom) then
            call ctx_fail(ctx, ir, 'NLGEOM cannot be switched off after a geometrically nonlinear step')
            return
          end if
        end if
        ctx%model%steps(istep)%nlgeom = .false.
      else
        call ctx_fail(ctx, ir, 'NLGEOM must be YES or NO')
        return
      end if
    end if
    max_inc = ctx_param_int(ctx, 'INC', 100)
    ctx%model%steps(istep)%max_inc = max_inc
    if (ctx%stat /= 0) return
    if (max_inc <= 0) then
      call ctx_fail(ctx, ir, 'INC must be positive')
      return
    end if
    v = deck_normalize(deck_param_value(ctx%params, 'AMPLITUDE'))
    select case (v)
    case ('', 'RAMP')
      ctx%model%steps(istep)%amp_step = .false.
    case ('STEP')
      ctx%model%steps(istep)%amp_step = .true.
    case default
      call ctx_fail(ctx, ir, 'AMPLITUDE must be RAMP or STEP')
      return
    end select
    v = deck_normalize(deck_param_value(ctx%params, 'EXTRAPOLATION'))
    select case (v)
    case ('', 'LINEAR')
      ctx%model%steps(istep)%extrapolate = .true.
    case ('NO')
      ctx%model%steps(istep)%extrapolate = .false.
    case ('PARABOLIC')
      ctx%model%steps(istep)%extrapolate = .true.
      ctx%model%steps(istep)%parabolic = .true.
    case default
      call ctx_fail(ctx, ir, 'EXTRAPOLATION must be LINEAR, PARABOLIC or NO')
      return
    end select
    v = deck_normalize(deck_param_value(ctx%params, 'UNSYMM'))
    if (v == 'YES' .or. v == '') then
      ctx%model%steps(istep)%unsymm = deck_has_param(ctx%params, 'UNSYMM')
    else if (v /= 'NO') then
      call ctx_fail(ctx, ir, 'UNSYMM must be YES or NO')
      return
    end if
    ctx%model%steps(istep)%name = deck_param_value(ctx%params, 'NAME')
    ctx%model%steps(istep)%pos = ctx_pos(ctx, ir)
    ctx%model%steps(istep)%period = -1.0_dp  ! marks "no *STATIC yet"
    ! data lines (a title line) are allowed and not read
    ctx%in_step = .true.
    ctx%imat = 0
  end subroutine read_step

  !> *STATIC[, DIRECT] or *VISCO[, CETOL=]: initial increment, period, minimum and maximum increments. *VISCO is the
  !> quasi-static step of rate-dependent materials: the same equilibrium step here (the UMAT sees the real time).
  subroutine read_static(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    integer :: n, ir, ir_next
    real(dp) :: v(4)
    logical :: given(4)
    integer :: k
    real(dp) :: cetol
    logical :: visco
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    visco = ctx%kw == '*VISCO'
    if (visco) then
      call ctx_allow_params(ctx, [character(len=12) :: 'CETOL'])
    else
      call ctx_allow_params(ctx, [character(len=12) :: 'DIRECT', 'SOLVER'])
    end if
    if (ctx%stat /= 0) return
    ! SOLVER= (CalculiX: SPOOLES, PARDISO, ITERATIVE ...) chooses how the linear systems are solved, not the solution
    if (deck_has_param(ctx%params, 'SOLVER')) call ctx_warn(ctx, ctx%ir, 'SOLVER='// &
      deck_param_value(ctx%params, 'SOLVER')//' read without effect: ldfcz solves with MUMPS (the same solution)')
    ir = ctx%ir
    ir_next = ctx%ir_next
    if (visco .and. deck_has_param(ctx%params, 'CETOL')) then
      if (.not. ctx_get_real(ctx, ir, deck_param_value(ctx%params, 'CETOL'), cetol)) return
      if (cetol <= 0.0_dp) then
        call ctx_fail(ctx, ir, 'CETOL must be positive')
        return
      end if
      call ctx_warn(ctx, ir, 'CETOL: the host does not see a UMAT''s creep strain; the increments are controlled '// &
        'by the Newton iteration and the UMAT''s PNEWDT (Abaqus applies CETOL to its built-in creep laws)')
    end if
    if (ctx%model%steps(ctx%istep)%period > 0.0_dp) then
      call ctx_fail(ctx, ir, 'a second procedure in one step')
      return
    end if
    v = 0.0_dp
    given = .false.
    n = 0
    if (ir_next > ir + 2) then
      call ctx_fail(ctx, ir + 2, 'one data line expected')
      return
    end if
    if (ir_next == ir + 2) then
      call ctx_split(ctx, ir + 1, f, n)
      if (n > 4) then
        call ctx_fail(ctx, ir + 1, 'only initial, period, minimum and maximum increments are supported')
        return
      end if
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (.not. ctx_get_real(ctx, ir + 1, f(k), v(k))) return
        if (v(k) <= 0.0_dp) then
          call ctx_fail(ctx, ir + 1, 'time values must be positive')
          return
        end if
        given(k) = .true.
      end do
    end if
    associate (s => ctx%model%steps(ctx%istep))
      s%period = 1.0_dp
      if (given(2)) s%period = v(2)
      s%dt_initial = s%period
      if (given(1)) s%dt_initial = v(1)
      s%dt_min = min(s%dt_initial, 1.0e-5_dp * s%period)
      if (given(3)) s%dt_min = v(3)
      s%dt_max = s%period
      if (given(4)) s%dt_max = v(4)
      ! *VISCO: fixed increments unless CETOL is given (Abaqus); *STATIC: DIRECT
      s%direct = deck_has_param(ctx%params, 'DIRECT')
      if (visco) s%direct = .not. deck_has_param(ctx%params, 'CETOL')
      if (s%dt_initial > s%period * (1.0_dp + 1.0e-12_dp)) then
        call ctx_fail(ctx, ir + 1, 'initial increment larger than the step period')
      else if (s%dt_min > s%dt_initial .and. .not. s%direct) then
        call ctx_fail(ctx, ir + 1, 'minimum increment larger than the initial increment')
      else if (s%dt_max < s%dt_initial .and. .not. s%direct) then
        ! decks that ran in Abaqus give it (Abaqus' rule for it not found): the initial increment is capped
        call ctx_warn(ctx, ir + 1, 'maximum increment smaller than the initial increment: the first increment '// &
          'takes the maximum')
        s%dt_initial = s%dt_max
      end if
    end associate
  end subroutine read_static

  !> *CONTROLS, PARAMETERS=TIME INCREMENTATION (I_C) or FIELD (R_n, C_n); RESET restores the defaults.
  subroutine read_controls(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=:), allocatable :: v
    character(len=flen), allocatable :: f(:)
    integer :: n, k, iv, ir, ir_next, istep
    real(dp) :: r
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'PARAMETERS', 'RESET', 'ANALYSIS', 'FIELD'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    istep = ctx%istep
    ! FIELD=: the controls of one field; ldfcz's one field is the displacement (GLOBAL: every field)
    if (deck_has_param(ctx%params, 'FIELD')) then
      v = deck_normalize(deck_param_value(ctx%params, 'FIELD'))
      if (v /= 'DISPLACEMENT' .and. v /= 'GLOBAL') then
        call ctx_warn(ctx, ir, 'FIELD='//v//': a field this model does not have; without effect')
        return
      end if
    end if
    if (deck_has_param(ctx%params, 'ANALYSIS')) then
      call ctx_fail(ctx, ir, 'ANALYSIS= is not supported')
      return
    end if
    if (deck_has_param(ctx%params, 'RESET')) then
      ctx%model%steps(istep)%max_iter = 16
      ctx%model%steps(istep)%r_n = 0.005_dp
      ctx%model%steps(istep)%c_n = 0.01_dp
      if (.not. deck_has_param(ctx%params, 'PARAMETERS')) return
    end if
    v = deck_normalize(ctx_required(ctx, 'PARAMETERS'))
    if (ctx%stat /= 0) return
    if (ir_next == ir + 1) return
    ! the controls ldfcz has: I_C of TIME INCREMENTATION, R_n and C_n of FIELD; the others (Abaqus' other
    ! iteration counts, cutback factors and tolerances) steer its own increment control and are read without
    ! effect, said in a warning: they change how the solution is reached, not the equilibrium it satisfies
    if (ir_next > ir + 2) call ctx_warn(ctx, ir + 2, 'the data lines after the first are read without effect '// &
      '(ldfcz''s increment control and tolerances apply)')
    call ctx_split(ctx, ir + 1, f, n)
    select case (v)
    case ('TIME INCREMENTATION')
      ! I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A: ldfcz reads I_C (iteration cap)
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (k /= 4) then
          call ctx_warn(ctx, ir + 1, 'field '//itoa(k)//' read without effect (ldfcz reads I_C, field 4; its own '// &
            'increment control applies)')
          cycle
        end if
        if (.not. ctx_get_int(ctx, ir + 1, f(k), iv)) return
        if (iv < 2) then
          call ctx_fail(ctx, ir + 1, 'I_C must be at least 2')
          return
        end if
        ctx%model%steps(istep)%max_iter = iv
      end do
    case ('FIELD')
      ! R_n, C_n, q0, qu, R_P, eps_l, ...: ldfcz supports R_n and C_n
      do k = 1, n
        if (len_trim(f(k)) == 0) cycle
        if (k > 2) then
          call ctx_warn(ctx, ir + 1, 'field '//itoa(k)//' read without effect (ldfcz reads R_n and C_n, fields '// &
            '1 and 2)')
          cycle
        end if
        if (.not. ctx_get_real(ctx, ir + 1, f(k), r)) return
        if (r <= 0.0_dp .or. r > 1.0_dp) then
          call ctx_fail(ctx, ir + 1, 'tolerances must lie in (0, 1]')
          return
        end if
        if (k == 1) ctx%model%steps(istep)%r_n = r
        if (k == 2) ctx%model%steps(istep)%c_n = r
      end do
    case ('LINE SEARCH')
      ! a line search changes the path, not the solution; ldfcz has none
      call ctx_warn(ctx, ir, 'PARAMETERS=LINE SEARCH read without effect (ldfcz has no line search)')
    case default
      call ctx_fail(ctx, ir, 'PARAMETERS='//v//' not supported (TIME INCREMENTATION, FIELD, LINE SEARCH)')
    end select
  end subroutine read_controls

  !> *RESTART, WRITE, FREQUENCY=n (model or history data; in effect for the following steps until changed):
  !> JOB.rst after every n-th increment and at the end of each step. READ is refused: ldfcz restarts with
  !> --restart-from JOB.rst JOB.inp on the unchanged deck (docs/host.md).
  subroutine read_restart(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: n, ir
    call ctx_allow_params(ctx, [character(len=16) :: 'WRITE', 'READ', 'FREQUENCY', 'OVERLAY', 'NUMBER INTERVAL', &
      'TIME MARKS', 'STEP', 'INC', 'END STEP'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    if (deck_has_param(ctx%params, 'READ')) then
      call ctx_fail(ctx, ir, 'READ is not supported: restart with ldfcz --restart-from JOB.rst JOB.inp on the '// &
        'unchanged deck (docs/host.md)')
      return
    end if
    if (.not. deck_has_param(ctx%params, 'WRITE')) then
      call ctx_fail(ctx, ir, 'WRITE (or READ) is required')
      return
    end if
    if (deck_has_param(ctx%params, 'NUMBER INTERVAL')) then
      ! Abaqus: restart data at n evenly spaced times of the step; ldfcz's checkpoint is written after increments,
      ! so it is written after every one (a superset: a restart can start from any of them); restart data only,
      ! the analysis is unchanged
      n = ctx_param_int(ctx, 'NUMBER INTERVAL', 1)
      if (ctx%stat /= 0) return
      if (n < 1) then
        call ctx_fail(ctx, ir, 'NUMBER INTERVAL must be >= 1')
        return
      end if
      if (deck_has_param(ctx%params, 'FREQUENCY')) then
        call ctx_fail(ctx, ir, 'FREQUENCY and NUMBER INTERVAL are mutually exclusive')
        return
      end if
      call ctx_warn(ctx, ir, 'NUMBER INTERVAL='//itoa(n)//': ldfcz writes its checkpoint after every increment '// &
        'instead (restart data only; the analysis is unchanged)')
      n = 1
    else
      if (deck_has_param(ctx%params, 'TIME MARKS')) call ctx_warn(ctx, ir, 'TIME MARKS applies to NUMBER '// &
        'INTERVAL only: ignored (restart data only)')
      n = ctx_param_int(ctx, 'FREQUENCY', 1)
      if (ctx%stat /= 0) return
    end if
    if (n < 0) then
      call ctx_fail(ctx, ir, 'FREQUENCY must be >= 0 (0: no restart file)')
      return
    end if
    if (ctx%ir_next > ir + 1) then
      call ctx_fail(ctx, ir + 1, 'no data lines expected')
      return
    end if
    ctx%restart_freq = n
    if (ctx%in_step) ctx%model%steps(ctx%istep)%restart_frequency = n
  end subroutine read_restart

  !> *OUTPUT, FIELD (FREQUENCY=, NUMBER INTERVAL=) or HISTORY.
  subroutine read_output(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k
    character(len=:), allocatable :: v
    real(dp), allocatable :: points(:)
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=16) :: 'FIELD', 'HISTORY', 'FREQUENCY', 'NUMBER INTERVAL', 'VARIABLE', &
      'TIME MARKS', 'OP', 'TIME INTERVAL', 'TIME POINTS'])
    if (ctx%stat /= 0) return
    call output_time_points(ctx, points)
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'FIELD')) then
      ctx%output_kind = 1
      ctx%model%steps(ctx%istep)%field_output = .true.
      ctx%model%steps(ctx%istep)%field_given = .true.
      v = deck_normalize(deck_param_value(ctx%params, 'OP'))
      select case (v)
      case ('', 'ADD', 'REPLACE')
      case ('NEW')
        ctx%model%steps(ctx%istep)%field_op_new = .true.
      case default
        call ctx_fail(ctx, ctx%ir, 'OP must be ADD, NEW or REPLACE')
        return
      end select
      v = deck_normalize(deck_param_value(ctx%params, 'VARIABLE'))
      select case (v)
      case ('')
      case ('PRESELECT', 'ALL')
        ! Abaqus' default field list of a static step (or every variable); here those the host has (the registry)
        call preset_variables(ctx, v == 'ALL', .true., .true.)
      case default
        call ctx_fail(ctx, ctx%ir, 'VARIABLE must be PRESELECT or ALL')
        return
      end select
      k = ctx_param_int(ctx, 'FREQUENCY', 1)
      if (ctx%stat /= 0) return
      if (k < 0) then
        call ctx_fail(ctx, ctx%ir, 'FREQUENCY must not be negative')
        return
      end if
      ctx%model%steps(ctx%istep)%field_frequency = k
      k = ctx_param_int(ctx, 'NUMBER INTERVAL', 0)
      if (ctx%stat /= 0) return
      if (k < 0) then
        call ctx_fail(ctx, ctx%ir, 'NUMBER INTERVAL must not be negative')
        return
      end if
      ctx%model%steps(ctx%istep)%field_intervals = k
      ! TIME INTERVAL=dt: frames at the first increment at or after each multiple of dt, as NUMBER INTERVAL =
      ! period / dt does (Abaqus' TIME MARKS=NO: the increments are not cut to hit the marks)
      if (deck_has_param(ctx%params, 'TIME INTERVAL')) call time_interval(ctx)
      if (allocated(points)) then
        ctx%model%steps(ctx%istep)%field_points = points
        ctx%model%steps(ctx%istep)%field_points_given = .true.
      end if
    else if (deck_has_param(ctx%params, 'HISTORY')) then
      ctx%output_kind = 2
      ctx%model%steps(ctx%istep)%history_given = .true.
      if (allocated(points)) then
        ctx%model%steps(ctx%istep)%history_points = points
        call ctx_note(ctx, ctx%ir, 'history output is written as JOB.csv columns of *NODE PRINT only; '// &
          'this request and its *NODE/*ELEMENT OUTPUT lines write nothing (its TIME POINTS do end increments)')
      else
        call ctx_note(ctx, ctx%ir, 'history output is written as JOB.csv columns of *NODE PRINT only; '// &
          'this request and its *NODE/*ELEMENT OUTPUT lines write nothing')
      end if
    else
      call ctx_fail(ctx, ctx%ir, 'FIELD or HISTORY required')
    end if
  end subroutine read_output

  !> *OUTPUT, FIELD, TIME INTERVAL=dt as NUMBER INTERVAL = period / dt (a period that is not a multiple of dt
  !> within 1e-6 is refused: the frames would not fall at the multiples of dt).
  subroutine time_interval(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    real(dp) :: dt, n
    if (deck_has_param(ctx%params, 'NUMBER INTERVAL')) then
      call ctx_fail(ctx, ctx%ir, 'TIME INTERVAL and NUMBER INTERVAL exclude each other')
      return
    end if
    if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'TIME INTERVAL'), dt)) return
    associate (st => ctx%model%steps(ctx%istep))
      if (.not. (dt > 0.0_dp) .or. st%period <= 0.0_dp) then
        call ctx_fail(ctx, ctx%ir, 'TIME INTERVAL must be positive and follow the step''s procedure line')
        return
      end if
      n = st%period / dt
      if (abs(n - nint(n)) > 1.0e-6_dp * n .or. nint(n) < 1) then
        call ctx_fail(ctx, ctx%ir, 'TIME INTERVAL must divide the step period')
        return
      end if
      st%field_intervals = nint(n)
    end associate
  end subroutine time_interval

  !> *OUTPUT, TIME POINTS=name: the step times of a *TIME POINTS definition (points unallocated when absent); the
  !> increments of the step end on every one of them (Abaqus/Standard adjusts its increments to the time points).
  !> Combined with FREQUENCY or NUMBER INTERVAL it is an error (Abaqus allows one of them).
  subroutine output_time_points(ctx, points)
    type(deck_context_t), intent(inout) :: ctx        !< reader state
    real(dp), allocatable, intent(out) :: points(:)   !< the step times
    integer :: k
    character(len=:), allocatable :: v
    if (.not. deck_has_param(ctx%params, 'TIME POINTS')) return
    if (deck_has_param(ctx%params, 'FREQUENCY') .or. deck_has_param(ctx%params, 'NUMBER INTERVAL') .or. &
        deck_has_param(ctx%params, 'TIME INTERVAL')) then
      call ctx_fail(ctx, ctx%ir, 'TIME POINTS= with FREQUENCY, NUMBER INTERVAL or TIME INTERVAL (give one of them)')
      return
    end if
    v = deck_normalize(ctx_required(ctx, 'TIME POINTS'))
    if (ctx%stat /= 0) return
    k = model_find_time_points(ctx%model, v)
    if (k == 0) then
      call ctx_fail(ctx, ctx%ir, 'TIME POINTS: undefined time points '//v//' (*TIME POINTS in the model data)')
      return
    end if
    points = ctx%model%time_points(k)%t
  end subroutine output_time_points

  !> *ELEMENT OUTPUT / *NODE OUTPUT under *OUTPUT, FIELD: the variables of the data lines (or VARIABLE=) join the
  !> step's field request; a variable the host cannot write is warned about with its line (never silently dropped).
  subroutine read_field_variables(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, k, n
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=16) :: 'ELSET', 'NSET', 'VARIABLE', 'POSITION', 'DIRECTIONS', &
      'INVARIANT', 'EXTERIOR'])
    if (ctx%stat /= 0) return
    if (ctx%output_kind /= 1) then
      if (ctx%output_kind == 0) then
        call ctx_fail(ctx, ctx%ir, 'must follow *OUTPUT, FIELD or *OUTPUT, HISTORY')
      end if
      return  ! history output: warned at *OUTPUT, HISTORY
    end if
    if (deck_has_param(ctx%params, 'ELSET') .or. deck_has_param(ctx%params, 'NSET')) &
      call ctx_note(ctx, ctx%ir, 'ELSET/NSET: ldfcz writes the requested variables for the whole model')
    v = deck_normalize(deck_param_value(ctx%params, 'VARIABLE'))
    select case (v)
    case ('')
    case ('PRESELECT', 'ALL')
      call preset_variables(ctx, v == 'ALL', ctx%kw == '*NODE OUTPUT', ctx%kw /= '*NODE OUTPUT')
    case default
      call ctx_fail(ctx, ctx%ir, 'VARIABLE must be PRESELECT or ALL')
      return
    end select
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      do k = 1, n
        v = deck_normalize(f(k))
        if (len(v) > 0) call field_variable(ctx, i, v)
      end do
    end do
  end subroutine read_field_variables

  !> The variables of VARIABLE=PRESELECT (or ALL) that the registry marks, at the keyword line: those at the nodes
  !> and/or those of the elements.
  subroutine preset_variables(ctx, all, nodal, elemental)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: all                  !< VARIABLE=ALL
    logical, intent(in) :: nodal                !< the node variables
    logical, intent(in) :: elemental            !< the element variables
    integer :: v
    do v = 1, size(output_variables)
      if (output_variables(v)%preset == 0) cycle
      if (output_variables(v)%preset == PRESET_ALL .and. .not. all) cycle
      if (output_variables(v)%location == LOC_NODE) then
        if (.not. nodal) cycle
      else if (.not. elemental) then
        cycle
      end if
      call field_variable(ctx, ctx%ir, trim(output_variables(v)%key))
    end do
  end subroutine preset_variables

  !> One requested field variable (upper case) read at record irec, resolved against the output registry: a
  !> variable the host cannot write is warned about with its line (never silently dropped); whether the model can
  !> provide it is checked when the model is complete (deck_finish).
  subroutine field_variable(ctx, irec, name)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: irec                 !< record of the request
    character(len=*), intent(in) :: name        !< variable key
    type(output_request_t), allocatable :: tmp(:)
    integer :: var, comp
    associate (st => ctx%model%steps(ctx%istep))
      st%field_vars_named = .true.
      call output_lookup(name, var, comp)
      ! field output names whole variables (a component is a *NODE PRINT / *EL PRINT name); SDVn is one
      if (var == 0 .or. (comp > 0 .and. var /= OV_SDV)) then
        call ctx_warn(ctx, irec, 'output variable '//name//' cannot be written by ldfcz and is not written '// &
          '(written: '//output_names_text(USE_FIELD)//', SDVn and the cohesive cell data; docs/host.md, '// &
          '"Output variables")')
        return
      end if
      if (.not. allocated(st%field_requests)) allocate (st%field_requests(4))
      if (st%nfield_request == size(st%field_requests)) then
        allocate (tmp(2 * size(st%field_requests)))
        tmp(1:st%nfield_request) = st%field_requests(1:st%nfield_request)
        call move_alloc(tmp, st%field_requests)
      end if
      st%nfield_request = st%nfield_request + 1
      st%field_requests(st%nfield_request) = output_request_t(var, comp, ctx_pos(ctx, irec))
    end associate
  end subroutine field_variable

  !> *NODE PRINT[, NSET=][, FREQUENCY=][, TOTALS=][, SUMMARY=]: a table of U1..U3, RF1..RF3 per node in JOB.dat
  !> and the set totals (RF sums, U means) as JOB.csv columns (with NSET only).
  subroutine read_node_print(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(node_print_t) :: np
    type(node_print_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=8), allocatable :: vars(:)
    integer :: i, n, k, nv, ir, ir_next, nd, j, var, comp
    logical :: ok
    character(len=:), allocatable :: name
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'NSET', 'TOTALS', 'FREQUENCY', 'SUMMARY', 'GLOBAL'])
    if (ctx%stat /= 0) return
    ir = ctx%ir
    ir_next = ctx%ir_next
    if (deck_has_param(ctx%params, 'NSET')) then
      np%nset = deck_normalize(ctx_required(ctx, 'NSET'))
      if (ctx%stat /= 0) return
      np%set_index = ctx_find_nset(ctx, np%nset)
      if (np%set_index == 0) then
        call ctx_fail(ctx, ir, 'undefined node set '//trim(np%nset))
        return
      end if
    end if
    call print_options(ctx, np%frequency, np%totals, np%summary)
    if (ctx%stat /= 0) return
    ! GLOBAL=YES: vector output in the global directions at *TRANSFORM nodes (default NO: their local directions)
    name = deck_normalize(deck_param_value(ctx%params, 'GLOBAL'))
    if (name /= '' .and. name /= 'YES' .and. name /= 'NO') then
      call ctx_fail(ctx, ir, 'GLOBAL must be YES or NO')
      return
    end if
    np%global = name == 'YES'
    allocate (vars(3 * (ir_next - ir) * 8 + 6))
    nv = 0
    nd = merge(2, 3, ctx%model%ndim == 2)
    do i = ir + 1, ir_next - 1
      call ctx_split(ctx, i, f, n)
      do k = 1, n
        name = deck_normalize(f(k))
        if (len(name) == 0) cycle
        call output_lookup(name, var, comp)
        ok = var > 0
        if (ok) ok = output_variables(var)%dat .and. output_variables(var)%location == LOC_NODE
        if (.not. ok) then
          call ctx_warn(ctx, i, 'variable '//name//' not supported by *NODE PRINT ('//output_names_text(USE_NODE_PRINT)// &
            ' and their components): ignored')
        else if (comp > nd) then
          call ctx_warn(ctx, i, 'variable '//name//' not written: the model is 2D')
        else if (comp > 0) then
          call add_var(vars, nv, name)
        else
          do j = 1, min(nd, output_ncomp(var))
            call add_var(vars, nv, output_component_name(var, j))
          end do
        end if
      end do
    end do
    if (nv == 0) then
      call ctx_warn(ctx, ir, 'no supported variable requested: no column written')
      return
    end if
    np%vars = vars(1:nv)
    np%pos = ctx_pos(ctx, ir)
    associate (s => ctx%model%steps(ctx%istep))
      if (s%nprint == size(s%prints)) then
        allocate (tmp(2 * size(s%prints)))
        tmp(1:s%nprint) = s%prints(1:s%nprint)
        call move_alloc(tmp, s%prints)
      end if
      s%nprint = s%nprint + 1
      s%prints(s%nprint) = np
    end associate
  end subroutine read_node_print

  !> *MONITOR, NODE=, DOF=[, FREQUENCY=]: the displacement of one dof written on each converged increment's line of
  !> JOB.sta (as the MONITOR column of an Abaqus .sta file); the last *MONITOR of the deck is in effect.
  subroutine read_monitor(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: id, dof
    call ctx_allow_params(ctx, [character(len=12) :: 'NODE', 'DOF', 'FREQUENCY'])
    if (ctx%stat /= 0) return
    if (.not. ctx_get_label(ctx, ctx%ir, ctx_required(ctx, 'NODE'), .true., id)) return
    if (ctx%stat /= 0) return
    if (.not. ctx_get_int(ctx, ctx%ir, ctx_required(ctx, 'DOF'), dof)) return
    if (dof < 1 .or. dof > 3) then
      call ctx_fail(ctx, ctx%ir, 'DOF must be 1, 2 or 3 (displacements)')
      return
    end if
    if (ctx%ir_next > ctx%ir + 1) then
      call ctx_fail(ctx, ctx%ir + 1, 'no data lines expected')
      return
    end if
    ctx%model%monitor_node = id
    ctx%model%monitor_dof = dof
    ctx%model%monitor_pos = ctx_pos(ctx, ctx%ir)
  end subroutine read_monitor

  !> FREQUENCY, TOTALS and SUMMARY of a print request.
  subroutine print_options(ctx, frequency, totals, summary)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(out) :: frequency           !< FREQUENCY (default 1)
    logical, intent(out) :: totals              !< TOTALS=YES
    logical, intent(out) :: summary             !< SUMMARY=YES (default)
    character(len=:), allocatable :: v
    totals = .false.
    summary = .true.
    frequency = ctx_param_int(ctx, 'FREQUENCY', 1)
    if (ctx%stat /= 0) return
    if (frequency < 0) then
      call ctx_fail(ctx, ctx%ir, 'FREQUENCY must not be negative')
      return
    end if
    v = deck_normalize(deck_param_value(ctx%params, 'TOTALS'))
    if (v /= '' .and. v /= 'YES' .and. v /= 'NO') then
      call ctx_fail(ctx, ctx%ir, 'TOTALS must be YES or NO')
      return
    end if
    totals = v == 'YES'
    v = deck_normalize(deck_param_value(ctx%params, 'SUMMARY'))
    if (v /= '' .and. v /= 'YES' .and. v /= 'NO') then
      call ctx_fail(ctx, ctx%ir, 'SUMMARY must be YES or NO')
      return
    end if
    summary = v /= 'NO'
  end subroutine print_options

  !> *EL PRINT[, ELSET=][, FREQUENCY=][, TOTALS=][, SUMMARY=][, POSITION=INTEGRATION POINTS]: a table of the
  !> integration-point values of continuum elements in JOB.dat: S (S11..), MISES, E/LE (E11.., engineering shear as
  !> the UMAT's STRAN), SDV (every state variable) or SDVn.
  subroutine read_el_print(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(el_print_t) :: ep
    type(el_print_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=8), allocatable :: vars(:)
    integer :: i, n, k, j, nv, nc, var, ic
    character(len=:), allocatable :: name
    logical :: ok
    call ctx_need_step(ctx)
    if (ctx%stat /= 0) return
    call ctx_allow_params(ctx, [character(len=12) :: 'ELSET', 'TOTALS', 'FREQUENCY', 'SUMMARY', 'POSITION', &
      'DIRECTIONS'])
    if (ctx%stat /= 0) return
    if (.not. ctx_only_value(ctx, ctx%ir, 'POSITION', 'INTEGRATION POINTS')) return
    if (deck_has_param(ctx%params, 'ELSET')) then
      ep%elset = deck_normalize(ctx_required(ctx, 'ELSET'))
      if (ctx%stat /= 0) return
      ep%set_index = ctx_find_elset(ctx, ep%elset)
      if (ep%set_index == 0) then
        call ctx_fail(ctx, ctx%ir, 'undefined element set '//trim(ep%elset))
        return
      end if
    end if
    call print_options(ctx, ep%frequency, ep%totals, ep%summary)
    if (ctx%stat /= 0) return
    nc = merge(4, 6, ctx%model%ndim == 2)
    allocate (vars(16 * (ctx%ir_next - ctx%ir) * 8 + 16))
    nv = 0
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      do k = 1, n
        name = deck_normalize(f(k))
        if (len(name) == 0) cycle
        call output_lookup(name, var, ic)
        ok = var > 0
        if (ok) ok = output_variables(var)%dat .and. output_variables(var)%location == LOC_POINT
        ! in 2D the tensors have the components 11, 22, 33, 12
        if (ok .and. var /= OV_SDV) ok = ic <= nc
        if (.not. ok) then
          call ctx_warn(ctx, i, 'variable '//name//' not supported by *EL PRINT ('//output_names_text(USE_EL_PRINT)// &
            ' and their components): ignored')
        else if (ic == 0 .and. output_ncomp(var) > 0) then
          do j = 1, nc
            call add_var(vars, nv, output_component_name(var, j))
          end do
        else if (ic == 0) then
          call add_var(vars, nv, output_variables(var)%key)
        else
          call add_var(vars, nv, output_component_name(var, ic))
        end if
      end do
    end do
    if (nv == 0) then
      call ctx_warn(ctx, ctx%ir, 'no supported variable requested: no table written')
      return
    end if
    ep%vars = vars(1:nv)
    ep%pos = ctx_pos(ctx, ctx%ir)
    associate (s => ctx%model%steps(ctx%istep))
      if (.not. allocated(s%elprints)) allocate (s%elprints(2))
      if (s%nelprint == size(s%elprints)) then
        allocate (tmp(2 * size(s%elprints)))
        tmp(1:s%nelprint) = s%elprints(1:s%nelprint)
        call move_alloc(tmp, s%elprints)
      end if
      s%nelprint = s%nelprint + 1
      s%elprints(s%nelprint) = ep
    end associate
  end subroutine read_el_print

  !> Append a print variable once.
  pure subroutine add_var(vars, nv, v)
    character(len=8), intent(inout) :: vars(:) !< variables
    integer, intent(inout) :: nv               !< variables in use
    character(len=*), intent(in) :: v          !< variable to add
    if (nv == size(vars)) return
    if (any(vars(1:nv) == v)) return
    nv = nv + 1
    vars(nv) = v
  end subroutine add_var

end module deck_steps
