!> Orientation check of zero-thickness interface elements before the analysis (docs/host.md, "Interface
!> orientation").
!>
!> A user element is taken for an interface element when its nodes form two coinciding faces, numbered as Abaqus'
!> cohesive elements: COH3D8 (8 nodes: 1-4 the bottom face, node k+4 on node k) or COH2D4 (4 nodes: 1-2 the bottom
!> face, node 3 on node 2, node 4 on node 1). Such an element measures opening as top minus bottom along the normal
!> of its bottom face (3D: t_xi x t_eta, the face counter-clockwise seen from its top; 2D: e_z x (x_2 - x_1)), so
!> that normal must point away from the solid its bottom face is glued to and into the solid of its top face. An
!> element meshed clockwise, or with its faces swapped, has it the other way round: opening is read as penetration
!> and the contact penalty holds the interface shut, a wrong answer without any other symptom. The check decides by
!> geometry only (the host knows nothing of a particular UEL): the centroids of the continuum elements that hold all
!> nodes of a face tell on which side each solid lies. A flipped element is repaired by reversing the order of both
!> faces (3D: 1,4,3,2 / 5,8,7,6; 2D: 2,1 / 4,3), which turns its normal and keeps node k+4 on node k.
module interface_orientation
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, etype_user
  use solver_text, only: itoa
  implicit none
  private
  public :: interface_check_t, check_interface_orientation, interface_check_messages

  !> Outcome of the check.
  type :: interface_check_t
    integer :: n_interface = 0              !< interface elements found (coinciding faces)
    integer :: n_checked = 0                !< of these, attached to at least one solid
    integer :: n_flipped = 0                !< normal pointing into the solid of the bottom face
    integer :: n_unchecked = 0              !< attached to no solid: orientation unknown
    integer, allocatable :: flipped(:)      !< labels of the flipped elements (all of them)
    integer, allocatable :: unchecked(:)    !< labels of the unchecked ones
    logical :: reordered = .false.          !< the flipped elements were reordered in the model
  end type interface_check_t

  real(dp), parameter :: coincide_tol = 1.0e-8_dp  !< |x_top - x_bottom| / element size below which faces coincide

contains

  !> Finds the interface elements of the model, checks their orientation against the solids they join and, with
  !> fix, reverses the face order of the flipped ones in model%conn.
  subroutine check_interface_orientation(model, fix, res)
    type(model_t), intent(inout) :: model         !< the model (connectivity changed only with fix)
    logical, intent(in) :: fix                    !< reorder the flipped elements
    type(interface_check_t), intent(out) :: res   !< what was found
    integer, allocatable :: node_ptr(:), node_elems(:)
    integer :: ie, nn, nf, p0, side
    integer :: perm(8)
    real(dp) :: nrm(3), mid(3), c(3)
    logical :: found, flipped, any_solid
    allocate (res%flipped(0), res%unchecked(0))
    if (.not. any(model%elem_kind(1:model%nelem) == etype_user)) return
    call solids_of_nodes(model, node_ptr, node_elems)
    do ie = 1, model%nelem
      if (model%elem_kind(ie) /= etype_user) cycle
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      if (.not. is_interface(model, ie, nn)) cycle
      res%n_interface = res%n_interface + 1
      nf = nn / 2
      p0 = model%conn_ptr(ie)
      call face_normal(model, ie, nn, nrm, mid)
      flipped = .false.
      any_solid = .false.
      ! side 1: the solid holding the bottom face must lie behind the normal; side 2: the top face's, in front
      do side = 1, 2
        call solid_centroid(model, node_ptr, node_elems, model%conn(p0 + (side - 1) * nf:p0 + side * nf - 1), ie, &
          c, found)
        if (.not. found) cycle
        any_solid = .true.
        if (side == 1 .and. dot_product(c - mid, nrm) > 0.0_dp) flipped = .true.
        if (side == 2 .and. dot_product(c - mid, nrm) < 0.0_dp) flipped = .true.
      end do
      if (.not. any_solid) then
        res%n_unchecked = res%n_unchecked + 1
        res%unchecked = [res%unchecked, model%elem_id(ie)]
        cycle
      end if
      res%n_checked = res%n_checked + 1
      if (.not. flipped) cycle
      res%n_flipped = res%n_flipped + 1
      res%flipped = [res%flipped, model%elem_id(ie)]
      if (fix) then
        if (nn == 8) then
          perm = [1, 4, 3, 2, 5, 8, 7, 6]
        else
          perm(1:4) = [2, 1, 4, 3]
        end if
        model%conn(p0:p0 + nn - 1) = model%conn(p0 + perm(1:nn) - 1)
        res%reordered = .true.
      end if
    end do
  end subroutine check_interface_orientation

  !> The messages of a check: an error (with the first labels, the count and the fix in words) when elements are
  !> flipped and not reordered, a note of what was reordered, a warning for unchecked elements. error = .true. when
  !> the run must not go on.
  subroutine interface_check_messages(res, lines, error)
    type(interface_check_t), intent(in) :: res           !< outcome of check_interface_orientation
    character(len=:), allocatable, intent(out) :: lines  !< messages, one per line (new-line separated), or ''
    logical, intent(out) :: error                        !< flipped elements left as they are
    character(len=*), parameter :: nl = new_line('a')
    lines = ''
    error = .false.
    if (res%n_flipped > 0) then
      if (res%reordered) then
        lines = 'ldfcz: warning: --reorient-interfaces: reversed the face order of '//itoa(res%n_flipped)// &
          ' interface element(s) whose normal pointed into the solid of their bottom face: '// &
          label_list(res%flipped, 20)
      else
        error = .true.
        lines = 'ldfcz: error: '//itoa(res%n_flipped)//' of '//itoa(res%n_interface)//' interface elements are '// &
          'mis-oriented: '//label_list(res%flipped, 10)//'.'//nl// &
          '  Their bottom-face normal (nodes 1-4 counter-clockwise seen from the top, as COH3D8; nodes 1-2 as '// &
          'COH2D4) points into the solid glued to their bottom face, so opening would be read as penetration.'// &
          nl//'  Fix: number each face counter-clockwise seen from the top solid, bottom face first (node k+4 on '// &
          'node k), or run with --reorient-interfaces to reverse them automatically.'
      end if
    end if
    if (res%n_unchecked > 0) then
      if (len(lines) > 0) lines = lines//nl
      lines = lines//'ldfcz: warning: '//itoa(res%n_unchecked)//' interface element(s) are attached to no '// &
        'continuum element on either face; their orientation is not checked: '//label_list(res%unchecked, 5)
    end if
  end subroutine interface_check_messages

  !> "elements 1, 2, 3 and 7 more" from the first nshow labels.
  pure function label_list(labels, nshow) result(t)
    integer, intent(in) :: labels(:)  !< element labels
    integer, intent(in) :: nshow      !< how many to name
    character(len=:), allocatable :: t
    integer :: k
    t = 'element'
    if (size(labels) > 1) t = t//'s'
    do k = 1, min(nshow, size(labels))
      if (k == 1) then
        t = t//' '//itoa(labels(k))
      else
        t = t//', '//itoa(labels(k))
      end if
    end do
    if (size(labels) > nshow) t = t//' and '//itoa(size(labels) - nshow)//' more'
  end function label_list

  !> Node k+nn/2 on node k (3D, COH3D8) or node 3 on 2 and 4 on 1 (2D, COH2D4), within coincide_tol of the size.
  pure logical function is_interface(model, ie, nn) result(yes)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie, nn       !< element and its node count
    integer :: k, p0, top
    real(dp) :: size_e, gap
    yes = .false.
    p0 = model%conn_ptr(ie)
    if (nn == 8 .and. model%ndim == 3) then
      continue
    else if (nn == 4 .and. model%ndim == 2) then
      continue
    else
      return
    end if
    size_e = 0.0_dp
    do k = 2, nn
      size_e = max(size_e, norm2(model%x(:, model%conn(p0 + k - 1)) - model%x(:, model%conn(p0))))
    end do
    if (size_e <= 0.0_dp) return
    gap = 0.0_dp
    do k = 1, nn / 2
      top = merge(k + 4, 5 - k, nn == 8)
      gap = max(gap, norm2(model%x(:, model%conn(p0 + top - 1)) - model%x(:, model%conn(p0 + k - 1))))
    end do
    yes = gap <= coincide_tol * size_e
  end function is_interface

  !> Unit normal of the bottom face (3D: t_xi x t_eta at the centre; 2D: e_z x (x_2 - x_1)) and its centre.
  pure subroutine face_normal(model, ie, nn, nrm, mid)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie, nn       !< element and its node count
    real(dp), intent(out) :: nrm(3)     !< unit normal (0 when the face is degenerate)
    real(dp), intent(out) :: mid(3)     !< centre of the bottom face
    real(dp) :: x(3, 4), t1(3), t2(3), l
    integer :: k, p0
    p0 = model%conn_ptr(ie)
    do k = 1, nn / 2
      x(:, k) = model%x(:, model%conn(p0 + k - 1))
    end do
    if (nn == 8) then
      t1 = x(:, 2) + x(:, 3) - x(:, 1) - x(:, 4)
      t2 = x(:, 3) + x(:, 4) - x(:, 1) - x(:, 2)
      nrm = [t1(2) * t2(3) - t1(3) * t2(2), t1(3) * t2(1) - t1(1) * t2(3), t1(1) * t2(2) - t1(2) * t2(1)]
      mid = sum(x, dim=2) / 4
    else
      t1 = x(:, 2) - x(:, 1)
      nrm = [-t1(2), t1(1), 0.0_dp]
      mid = 0.5_dp * (x(:, 1) + x(:, 2))
    end if
    l = norm2(nrm)
    if (l > 0.0_dp) then
      nrm = nrm / l
    else
      nrm = 0.0_dp
    end if
  end subroutine face_normal

  !> Centroid of the first continuum element (not ie) that holds every node of face; found_one = .false. if none.
  pure subroutine solid_centroid(model, node_ptr, node_elems, face, ie, c, found_one)
    type(model_t), intent(in) :: model            !< the model
    integer, intent(in) :: node_ptr(:), node_elems(:)  !< continuum elements of each node (CSR)
    integer, intent(in) :: face(:)                !< node indices of the face
    integer, intent(in) :: ie                     !< the interface element itself
    real(dp), intent(out) :: c(3)                 !< centroid of the solid
    logical, intent(out) :: found_one             !< a solid was found
    integer :: j, je, k, nn, p0
    logical :: all_in
    found_one = .false.
    c = 0.0_dp
    do j = node_ptr(face(1)), node_ptr(face(1) + 1) - 1
      je = node_elems(j)
      if (je == ie) cycle
      p0 = model%conn_ptr(je)
      nn = model%conn_ptr(je + 1) - p0
      all_in = .true.
      do k = 1, size(face)
        if (.not. any(model%conn(p0:p0 + nn - 1) == face(k))) all_in = .false.
      end do
      if (.not. all_in) cycle
      do k = 1, nn
        c = c + model%x(:, model%conn(p0 + k - 1)) / nn
      end do
      found_one = .true.
      return
    end do
  end subroutine solid_centroid

  !> For every node, the continuum (non-user) elements that hold it, in CSR form.
  pure subroutine solids_of_nodes(model, node_ptr, node_elems)
    type(model_t), intent(in) :: model                 !< the model
    integer, allocatable, intent(out) :: node_ptr(:)   !< (nnode+1) pointers
    integer, allocatable, intent(out) :: node_elems(:) !< element indices
    integer, allocatable :: fill(:)
    integer :: ie, k, nd
    allocate (node_ptr(model%nnode + 1), fill(model%nnode))
    node_ptr = 0
    do ie = 1, model%nelem
      if (model%elem_kind(ie) == etype_user) cycle
      do k = model%conn_ptr(ie), model%conn_ptr(ie + 1) - 1
        node_ptr(model%conn(k) + 1) = node_ptr(model%conn(k) + 1) + 1
      end do
    end do
    node_ptr(1) = 1
    do k = 1, model%nnode
      node_ptr(k + 1) = node_ptr(k + 1) + node_ptr(k)
    end do
    allocate (node_elems(node_ptr(model%nnode + 1) - 1))
    fill = node_ptr(1:model%nnode)
    do ie = 1, model%nelem
      if (model%elem_kind(ie) == etype_user) cycle
      do k = model%conn_ptr(ie), model%conn_ptr(ie + 1) - 1
        nd = model%conn(k)
        node_elems(fill(nd)) = ie
        fill(nd) = fill(nd) + 1
      end do
    end do
  end subroutine solids_of_nodes

end module interface_orientation
