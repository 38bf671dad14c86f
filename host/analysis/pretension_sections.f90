!> Pre-tension sections in the analysis (docs/host.md, "Pre-tension sections"): the mesh is cut at the section
!> without new nodes in the model. The elements on the surface's side (model%pretensions(k)%elems) see, at the
!> section's nodes, extra dofs u' (ndim per node, after the nodes' and the rotations' dofs), which are eliminated as
!> linear constraints u'_i = u_i + n_i u_p: the two sides move together in the section's plane and apart by u_p
!> (the pre-tension node's dof 1) along the normal n, the same everywhere on the section (inferred: the Analysis
!> User's Guide makes dof 1 "the relative displacement at the two sides of the cut in the direction of the
!> normal"). The conjugate force of u_p is sum_a n . f'_a, the force the surface's side carries across the
!> section: a *CLOAD there is the pre-tension force, the reaction of a *BOUNDARY there the fastener's force. The
!> other side's nodes keep their numbers: output lists the model's nodes as the deck wrote them.
module pretension_sections
  use ldfcz_kinds, only: dp
  use model_types, only: model_t
  implicit none
  private
  public :: pretension_element_dofs, pretension_rows

contains

  !> The element dofs of the moving elements at section nodes replaced by the section's extra dofs.
  pure subroutine pretension_element_dofs(model, elem_ptr, elem_dof)
    type(model_t), intent(in) :: model       !< the model
    integer, intent(in) :: elem_ptr(:)       !< (nelem+1) element dof pointers
    integer, intent(inout) :: elem_dof(:)    !< global dof of each element dof
    integer :: k, j, e, ie, kk, g, node, d, base, nd
    integer, allocatable :: local(:)
    nd = model%ndim
    base = nd * model%nnode + model%nrot
    allocate (local(model%nnode))
    do k = 1, model%npretension
      associate (p => model%pretensions(k))
        local = 0
        local(p%nodes) = [(j, j = 1, size(p%nodes))]
        do e = 1, size(p%elems)
          ie = p%elems(e)
          do kk = elem_ptr(ie), elem_ptr(ie + 1) - 1
            g = elem_dof(kk)
            if (g > nd * model%nnode) cycle
            node = (g - 1) / nd + 1
            d = mod(g - 1, nd) + 1
            if (local(node) > 0) elem_dof(kk) = base + p%dof0 + (local(node) - 1) * nd + d
          end do
        end do
      end associate
    end do
  end subroutine pretension_element_dofs

  !> The constraint rows u'_i = u_i + n_i u_p of every section node and dof: slave(r) = sum over
  !> mdof(ptr(r):ptr(r+1)-1) of w u(mdof) (a zero component of n gives no term).
  pure subroutine pretension_rows(model, slave, ptr, mdof, w)
    type(model_t), intent(in) :: model              !< the model
    integer, allocatable, intent(out) :: slave(:)   !< (nrow) eliminated extra dofs
    integer, allocatable, intent(out) :: ptr(:)     !< (nrow+1) into mdof, w
    integer, allocatable, intent(out) :: mdof(:)    !< retained dofs
    real(dp), allocatable, intent(out) :: w(:)      !< their weights
    integer :: k, j, d, r, m, nd, base
    nd = model%ndim
    base = nd * model%nnode + model%nrot
    allocate (slave(model%npret_dof), ptr(model%npret_dof + 1), mdof(2 * model%npret_dof), w(2 * model%npret_dof))
    r = 0
    m = 0
    ptr(1) = 1
    do k = 1, model%npretension
      associate (p => model%pretensions(k))
        do j = 1, size(p%nodes)
          do d = 1, nd
            r = r + 1
            slave(r) = base + p%dof0 + (j - 1) * nd + d
            m = m + 1
            mdof(m) = (p%nodes(j) - 1) * nd + d
            w(m) = 1.0_dp
            if (p%normal(d) /= 0.0_dp) then
              m = m + 1
              mdof(m) = (p%node - 1) * nd + 1
              w(m) = p%normal(d)
            end if
            ptr(r + 1) = m + 1
          end do
        end do
      end associate
    end do
    mdof = mdof(1:m)
    w = w(1:m)
  end subroutine pretension_rows

end module pretension_sections
