!> Local node systems of *TRANSFORM (docs/host.md, "Transformed node systems"). The solver works in "system
!> components": at a transformed node the displacement, force, residual and tangent components are those of its
!> local directions T (columns, fixed in space: u_global = T u_local), elsewhere the global ones. Boundary
!> conditions, concentrated loads, *EQUATION terms and printed nodal output then act in the local system as in
!> Abaqus, and the elements, which work in global components, see their vectors and matrices turned at the
!> element's transformed nodes: u_e = T_e u_s, f_s = T_e^T f_e, K_s = T_e^T K_e T_e (T_e block diagonal).
module node_rotations
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, etype_user, orientation_axes, model_label_text
  implicit none
  private
  public :: node_rotation_t, node_rotations_build, element_to_global, element_to_local, element_matrix_to_local, &
    node_vector_global, node_to_global

  type :: node_rotation_t
    integer :: n = 0                         !< transformed nodes
    integer :: ndim = 3                      !< model dimension
    integer, allocatable :: of_node(:)       !< (nnode) index into t, 0: global system
    real(dp), allocatable :: t(:, :, :)      !< (3, 3, n) local directions (columns) of each transformed node
    logical, allocatable :: elem_has(:)      !< (nelem) the element has a transformed node
  end type node_rotation_t

contains

  pure function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

  !> The rotations of the model's transformed nodes (model%node_transform, deck_finish). A user element at a
  !> transformed node must have all ndim displacement dofs active there, in order (Abaqus: the transformation must
  !> be consistent with the dofs that exist at the node).
  subroutine node_rotations_build(nr, model, stat, errmsg)
    type(node_rotation_t), intent(out) :: nr            !< rotations
    type(model_t), intent(in) :: model                   !< the model
    integer, intent(out) :: stat                         !< 0 ok, 2 model error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: i, k, ie, iu, nd
    logical :: ok
    stat = 0
    errmsg = ''
    nr%ndim = model%ndim
    allocate (nr%of_node(model%nnode), nr%elem_has(model%nelem))
    nr%of_node = 0
    nr%elem_has = .false.
    if (.not. allocated(model%node_transform)) return
    nr%n = count(model%node_transform /= 0)
    allocate (nr%t(3, 3, nr%n))
    k = 0
    do i = 1, model%nnode
      if (model%node_transform(i) == 0) cycle
      k = k + 1
      nr%of_node(i) = k
      call orientation_axes(model%transforms(model%node_transform(i))%axes, model%x(:, i), nr%t(:, :, k), ok)
    end do
    do ie = 1, model%nelem
      nr%elem_has(ie) = any(nr%of_node(model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)) /= 0)
      if (.not. nr%elem_has(ie) .or. model%elem_kind(ie) /= etype_user) cycle
      iu = model%elem_utype(ie)
      nd = size(model%utypes(iu)%active)
      if (nd == model%ndim) then
        if (all(model%utypes(iu)%active == [(k, k = 1, nd)])) cycle
      end if
      stat = 2
      k = maxval(model%node_transform(model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1)))
      associate (tr => model%transforms(k))
        errmsg = tr%pos%file//':'//itoa(tr%pos%line)//': *TRANSFORM: user element '// &
          model_label_text(model, model%elem_id(ie), .false.)// &
          ' of type '//trim(model%utypes(iu)%name)//' is attached to a transformed node but does not have the '// &
          'displacement dofs 1..ndim active there: a local system needs every displacement dof of the node'
      end associate
      return
    end do
  end subroutine node_rotations_build

  !> Global components of node i's vector in v (ndof, system components).
  pure function node_vector_global(nr, v, i) result(w)
    type(node_rotation_t), intent(in) :: nr  !< rotations
    real(dp), intent(in) :: v(:)             !< (ndof) vector
    integer, intent(in) :: i                 !< node index
    real(dp) :: w(nr%ndim)
    integer :: d
    d = nr%ndim
    w = v((i - 1) * d + 1:i * d)
    if (nr%of_node(i) /= 0) w = matmul(nr%t(1:d, 1:d, nr%of_node(i)), w)
  end function node_vector_global

  !> Global components of node i's vector v given in its system components (ndim of them).
  pure function node_to_global(nr, i, v) result(w)
    type(node_rotation_t), intent(in) :: nr  !< rotations
    integer, intent(in) :: i                 !< node index
    real(dp), intent(in) :: v(:)             !< (ndim) system components
    real(dp) :: w(size(v))
    w = v
    if (nr%of_node(i) /= 0) w = matmul(nr%t(1:size(v), 1:size(v), nr%of_node(i)), v)
  end function node_to_global

  !> Element vector ve (ndim dofs per node, nodes in connectivity order) from system to global components.
  pure subroutine element_to_global(nr, nodes, ve)
    type(node_rotation_t), intent(in) :: nr  !< rotations
    integer, intent(in) :: nodes(:)          !< the element's node indices
    real(dp), intent(inout) :: ve(:)         !< element vector
    integer :: a, d, k
    d = nr%ndim
    do a = 1, size(nodes)
      k = nr%of_node(nodes(a))
      if (k == 0) cycle
      ve((a - 1) * d + 1:a * d) = matmul(nr%t(1:d, 1:d, k), ve((a - 1) * d + 1:a * d))
    end do
  end subroutine element_to_global

  !> Element vector ve from global to system components: T_e^T ve.
  pure subroutine element_to_local(nr, nodes, ve)
    type(node_rotation_t), intent(in) :: nr  !< rotations
    integer, intent(in) :: nodes(:)          !< the element's node indices
    real(dp), intent(inout) :: ve(:)         !< element vector
    integer :: a, d, k
    d = nr%ndim
    do a = 1, size(nodes)
      k = nr%of_node(nodes(a))
      if (k == 0) cycle
      ve((a - 1) * d + 1:a * d) = matmul(ve((a - 1) * d + 1:a * d), nr%t(1:d, 1:d, k))
    end do
  end subroutine element_to_local

  !> Element matrix ke from global to system components: T_e^T ke T_e.
  pure subroutine element_matrix_to_local(nr, nodes, ke)
    type(node_rotation_t), intent(in) :: nr  !< rotations
    integer, intent(in) :: nodes(:)          !< the element's node indices
    real(dp), intent(inout) :: ke(:, :)      !< element matrix
    integer :: a, d, k, i1, i2
    d = nr%ndim
    do a = 1, size(nodes)
      k = nr%of_node(nodes(a))
      if (k == 0) cycle
      i1 = (a - 1) * d + 1
      i2 = a * d
      ke(i1:i2, :) = matmul(transpose(nr%t(1:d, 1:d, k)), ke(i1:i2, :))
      ke(:, i1:i2) = matmul(ke(:, i1:i2), nr%t(1:d, 1:d, k))
    end do
  end subroutine element_matrix_to_local

end module node_rotations
