!> Constraint keywords of the deck reader: *EQUATION (model data; linear homogeneous multi-point constraints) and
!> *TIE (slave surface nodes tied to master surface faces).
module deck_constraints
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_normalize, deck_param_value, deck_has_param
  use model_types, only: cload_t, equation_t, tie_t
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_is_label, ctx_get_label, ctx_find_nset, ctx_find_surface, &
    ctx_fail, ctx_pos, ctx_allow_params, ctx_split, ctx_get_real, ctx_get_int
  implicit none
  private
  public :: read_equation, read_tie, read_mpc

contains

  !> *EQUATION: blocks of a line with the number of terms N, then N terms (node or node set, dof, coefficient),
  !> four terms per line at most. Node ids stay negative until finish_model.
  subroutine read_equation(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(equation_t) :: eqn
    type(equation_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    integer :: i, n, nterm, k, j, id, iset, last
    call ctx_allow_params(ctx, [character(len=8) ::])
    if (ctx%stat /= 0) return
    i = ctx%ir + 1
    if (i >= ctx%ir_next) then
      call ctx_fail(ctx, ctx%ir, 'no data lines')
      return
    end if
    do while (i < ctx%ir_next)
      call ctx_split(ctx, i, f, n)
      if (.not. ctx_get_int(ctx, i, f(1), nterm)) return
      ! one term: A1 u = 0, the dof held at zero (the Keywords Reference sets no minimum; inferred)
      if (nterm < 1) then
        call ctx_fail(ctx, i, 'an equation needs at least 1 term')
        return
      end if
      if (allocated(eqn%terms)) deallocate (eqn%terms, eqn%term_set)
      allocate (eqn%terms(nterm), eqn%term_set(nterm))
      eqn%term_set = 0
      eqn%pos = ctx_pos(ctx, i)
      k = 0
      do while (k < nterm)
        i = i + 1
        if (i >= ctx%ir_next) then
          call ctx_fail(ctx, i - 1, 'the equation has fewer terms than announced ('//itoa(nterm)//')')
          return
        end if
        call ctx_split(ctx, i, f, n)
        last = n
        do while (last > 0)
          if (len_trim(f(last)) > 0) exit
          last = last - 1
        end do
        if (mod(last, 3) /= 0 .or. last == 0 .or. last > 12) then
          call ctx_fail(ctx, i, 'expected up to four terms: node or node set, dof, coefficient')
          return
        end if
        do j = 1, last / 3
          k = k + 1
          if (k > nterm) then
            call ctx_fail(ctx, i, 'more terms than announced ('//itoa(nterm)//')')
            return
          end if
          associate (t => eqn%terms(k))
            t%pos = ctx_pos(ctx, i)
            if (ctx_is_label(ctx, f(3 * j - 2))) then
              if (.not. ctx_get_label(ctx, i, f(3 * j - 2), .true., id)) return
              if (id < 1) then
                call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
                return
              end if
              t%nodes = [-id]
            else
              iset = ctx_find_nset(ctx, f(3 * j - 2))
              if (iset == 0) then
                call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(3 * j - 2)))
                return
              end if
              t%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
              eqn%term_set(k) = iset
            end if
            if (.not. ctx_get_int(ctx, i, f(3 * j - 1), t%dof)) return
            if (t%dof < 1 .or. t%dof > 3) then
              call ctx_fail(ctx, i, 'dof '//itoa(t%dof)//' does not exist in ldfcz models (1..3)')
              return
            end if
            if (.not. ctx_get_real(ctx, i, f(3 * j), t%value)) return
          end associate
        end do
      end do
      if (.not. allocated(ctx%model%equations)) allocate (ctx%model%equations(4))
      if (ctx%model%nequation == size(ctx%model%equations)) then
        allocate (tmp(2 * ctx%model%nequation))
        tmp(1:ctx%model%nequation) = ctx%model%equations(1:ctx%model%nequation)
        call move_alloc(tmp, ctx%model%equations)
      end if
      ctx%model%nequation = ctx%model%nequation + 1
      ctx%model%equations(ctx%model%nequation) = eqn
      i = i + 1
    end do
  end subroutine read_equation

  !> *TIE, NAME=[, POSITION TOLERANCE=][, ADJUST=NO]: data lines slave surface, master surface. ADJUST=YES (the
  !> Abaqus default) moves nothing here: a slave node farther from the master surface than the tolerance is an
  !> error at the start of the analysis; TYPE=SURFACE TO SURFACE is tied node to surface (accepted by the issue).
  subroutine read_tie(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(tie_t) :: t
    type(tie_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: v
    integer :: i, n
    call ctx_allow_params(ctx, [character(len=20) :: 'NAME', 'POSITION TOLERANCE', 'ADJUST', 'TYPE'])
    if (ctx%stat /= 0) return
    v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    if (v /= '' .and. v /= 'SURFACE TO SURFACE' .and. v /= 'NODE TO SURFACE') then
      call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported (NODE TO SURFACE, SURFACE TO SURFACE: both tie '// &
        'the slave nodes to the master faces here)')
      return
    end if
    v = deck_normalize(deck_param_value(ctx%params, 'ADJUST'))
    if (v /= '' .and. v /= 'YES' .and. v /= 'NO') then
      call ctx_fail(ctx, ctx%ir, 'ADJUST must be YES or NO')
      return
    end if
    t%name = deck_normalize(deck_param_value(ctx%params, 'NAME'))
    if (deck_has_param(ctx%params, 'POSITION TOLERANCE')) then
      if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'POSITION TOLERANCE'), t%tolerance)) return
    end if
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      if (n < 2) then
        call ctx_fail(ctx, i, 'expected: slave surface, master surface')
        return
      end if
      t%slave = ctx_find_surface(ctx, f(1))
      t%master = ctx_find_surface(ctx, f(2))
      if (t%slave == 0 .or. t%master == 0) then
        call ctx_fail(ctx, i, 'undefined surface '//deck_normalize(f(merge(1, 2, t%slave == 0))))
        return
      end if
      t%pos = ctx_pos(ctx, i)
      if (.not. allocated(ctx%model%ties)) allocate (ctx%model%ties(2))
      if (ctx%model%ntie == size(ctx%model%ties)) then
        allocate (tmp(2 * ctx%model%ntie))
        tmp(1:ctx%model%ntie) = ctx%model%ties(1:ctx%model%ntie)
        call move_alloc(tmp, ctx%model%ties)
      end if
      ctx%model%ntie = ctx%model%ntie + 1
      ctx%model%ties(ctx%model%ntie) = t
    end do
    if (ctx%ir_next == ctx%ir + 1) call ctx_fail(ctx, ctx%ir, 'no data line (slave surface, master surface)')
  end subroutine read_tie

  !> *MPC: data lines "TIE, dependent node or node set, independent node or node set": every displacement dof of
  !> the first node equal to that of the second (stored as *EQUATION u_a - u_b = 0, the first eliminated). Other MPC
  !> types (BEAM, PIN, ... need rotational dofs or are not implemented) are errors.
  subroutine read_mpc(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(equation_t) :: eqn
    type(equation_t), allocatable :: tmp(:)
    character(len=flen), allocatable :: f(:)
    character(len=:), allocatable :: typ
    integer :: i, n, d, nd, j, id, iset
    integer, allocatable :: nodes(:, :)
    call ctx_allow_params(ctx, [character(len=8) ::])
    if (ctx%stat /= 0) return
    nd = ctx%model%ndim
    if (nd == 0) nd = 3
    do i = ctx%ir + 1, ctx%ir_next - 1
      call ctx_split(ctx, i, f, n)
      typ = deck_normalize(f(1))
      if (typ /= 'TIE') then
        call ctx_fail(ctx, i, 'MPC type '//typ//' is not supported (TIE; BEAM and PIN need rotational dofs)')
        return
      end if
      if (n /= 3) then
        call ctx_fail(ctx, i, 'expected: TIE, dependent node or node set, independent node or node set')
        return
      end if
      do j = 1, 2
        if (ctx_is_label(ctx, f(j + 1))) then
          if (.not. ctx_get_label(ctx, i, f(j + 1), .true., id)) return
          if (id < 1) then
            call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
            return
          end if
          if (j == 1) allocate (nodes(1, 2))
          if (size(nodes, 1) /= 1) then
            call ctx_fail(ctx, i, 'a node and a node set of different sizes')
            return
          end if
          nodes(1, j) = -id
        else
          iset = ctx_find_nset(ctx, f(j + 1))
          if (iset == 0) then
            call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(j + 1)))
            return
          end if
          if (j == 1) allocate (nodes(ctx%model%nsets(iset)%n, 2))
          if (size(nodes, 1) /= ctx%model%nsets(iset)%n) then
            call ctx_fail(ctx, i, 'the two node sets differ in size')
            return
          end if
          nodes(:, j) = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
        end if
      end do
      do d = 1, nd
        if (allocated(eqn%terms)) deallocate (eqn%terms)
        allocate (eqn%terms(2))
        eqn%pos = ctx_pos(ctx, i)
        eqn%mpc = .true.
        eqn%terms(1)%nodes = nodes(:, 1)
        eqn%terms(1)%dof = d
        eqn%terms(1)%value = 1.0_dp
        eqn%terms(1)%pos = eqn%pos
        eqn%terms(2)%nodes = nodes(:, 2)
        eqn%terms(2)%dof = d
        eqn%terms(2)%value = -1.0_dp
        eqn%terms(2)%pos = eqn%pos
        if (.not. allocated(ctx%model%equations)) allocate (ctx%model%equations(4))
        if (ctx%model%nequation == size(ctx%model%equations)) then
          allocate (tmp(2 * ctx%model%nequation))
          tmp(1:ctx%model%nequation) = ctx%model%equations(1:ctx%model%nequation)
          call move_alloc(tmp, ctx%model%equations)
        end if
        ctx%model%nequation = ctx%model%nequation + 1
        ctx%model%equations(ctx%model%nequation) = eqn
      end do
      deallocate (nodes)
    end do
  end subroutine read_mpc

end module deck_constraints
