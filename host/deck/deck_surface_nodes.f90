!> The nodes of an element-based surface's faces (continuum element faces), the one implementation the couplings
!> and the pre-tension sections take their nodes from (deck_finish_extras, deck_pretension).
module deck_surface_nodes
  use model_types, only: source_pos_t, etype_user, model_label_text
  use element_catalog, only: element_face_nodes
  use deck_lists, only: itoa, unique
  use deck_context, only: deck_context_t, ctx_fail_pos
  implicit none
  private
  public :: surface_face_nodes

contains

  !> nodes: the distinct nodes (ascending) of the faces of surface isurf. A face of a user element (no faces known)
  !> or a surface without faces is an error at pos, which says what needs the nodes (purpose).
  subroutine surface_face_nodes(ctx, isurf, pos, purpose, nodes)
    type(deck_context_t), intent(inout) :: ctx      !< reader state
    integer, intent(in) :: isurf                    !< surface index
    type(source_pos_t), intent(in) :: pos           !< where the definition that needs the nodes is
    character(len=*), intent(in) :: purpose         !< e.g. 'couplings need continuum element faces'
    integer, allocatable, intent(out) :: nodes(:)   !< the nodes (model indices)
    integer :: j, ie, loc(8), nfn
    allocate (nodes(0))
    associate (model => ctx%model, sf => ctx%model%surfaces(isurf))
      do j = 1, size(sf%relems)
        ie = sf%relems(j)
        nfn = 0
        if (model%elem_kind(ie) /= etype_user) call element_face_nodes(model%elem_kind(ie), sf%rfaces(j), loc, nfn)
        if (nfn == 0) then
          call ctx_fail_pos(ctx, pos, 'surface '//trim(sf%name)//': element '// &
            model_label_text(model, model%elem_id(ie), .false.)//' has no face S'//itoa(sf%rfaces(j))// &
            ' ('//purpose//')')
          return
        end if
        nodes = [nodes, model%conn(model%conn_ptr(ie) + loc(1:nfn) - 1)]
      end do
    end associate
    call unique(nodes)
  end subroutine surface_face_nodes

end module deck_surface_nodes
