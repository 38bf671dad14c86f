!> Constraint keywords of the deck reader: *EQUATION (model data; linear homogeneous multi-point constraints).
module deck_constraints
  use deck_lines, only: deck_normalize
  use model_types, only: cload_t, equation_t, model_find_nset
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_pos, ctx_allow_params, ctx_split, ctx_get_real, &
    ctx_get_int
  implicit none
  private
  public :: read_equation

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
      if (nterm < 2) then
        call ctx_fail(ctx, i, 'an equation needs at least 2 terms')
        return
      end if
      if (allocated(eqn%terms)) deallocate (eqn%terms)
      allocate (eqn%terms(nterm))
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
            if (verify(trim(f(3 * j - 2)), '0123456789+-') == 0) then
              if (.not. ctx_get_int(ctx, i, f(3 * j - 2), id)) return
              if (id < 1) then
                call ctx_fail(ctx, i, 'node ids must be positive, got '//itoa(id))
                return
              end if
              t%nodes = [-id]
            else
              iset = model_find_nset(ctx%model, deck_normalize(f(3 * j - 2)))
              if (iset == 0) then
                call ctx_fail(ctx, i, 'undefined node set '//deck_normalize(f(3 * j - 2)))
                return
              end if
              t%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
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

end module deck_constraints
