!> Faces of the continuum elements in Abaqus' numbering (S1..S6), as positions in the element's connectivity.
!> 3D: the face nodes are ordered so that the right-hand rule gives the OUTWARD normal (the reverse of the order in
!> which the Abaqus element library lists them, whose right-hand normal points into the element).
!> 2D: face Sn is the edge from local(1) to local(2) with the element on its left (for the counterclockwise node
!> order Abaqus requires), so the outward normal is (dy, -dx) of that edge.
module element_faces
  use model_types, only: etype_c3d8, etype_cpe4
  implicit none
  private
  public :: element_face_nodes

  ! C3D8: S1 1-2-3-4, S2 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3, S5 3-7-8-4, S6 4-8-5-1 (Abaqus), reversed: outward
  integer, parameter :: c3d8_faces(4, 6) = reshape([1, 4, 3, 2, 5, 6, 7, 8, 1, 2, 6, 5, 2, 3, 7, 6, 3, 4, 8, 7, &
    4, 1, 5, 8], [4, 6])
  ! CPE4: S1 1-2, S2 2-3, S3 3-4, S4 4-1
  integer, parameter :: cpe4_faces(2, 4) = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])

contains

  !> Connectivity positions local(1:nfn) of face `face` (1..6 = S1..S6) of an element of kind `kind`; nfn = 0 when
  !> the element kind has no such face.
  pure subroutine element_face_nodes(kind, face, local, nfn)
    integer, intent(in) :: kind       !< etype_* of model_types
    integer, intent(in) :: face       !< 1..6 = S1..S6
    integer, intent(out) :: local(8)  !< positions in the connectivity (outward order, see above)
    integer, intent(out) :: nfn       !< face nodes, 0 if the face does not exist
    local = 0
    nfn = 0
    select case (kind)
    case (etype_c3d8)
      if (face < 1 .or. face > 6) return
      nfn = 4
      local(1:4) = c3d8_faces(:, face)
    case (etype_cpe4)
      if (face < 1 .or. face > 4) return
      nfn = 2
      local(1:2) = cpe4_faces(:, face)
    end select
  end subroutine element_face_nodes

end module element_faces
