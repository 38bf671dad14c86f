!> Faces of the continuum elements in Abaqus' numbering (S1..S6), as positions in the element's connectivity.
!> 3D: the face corners are ordered so that the right-hand rule gives the OUTWARD normal (the reverse of the order
!> in which the Abaqus element library lists them, whose right-hand normal points into the element); quadratic
!> faces follow with their mid-side nodes, the one between corners 1 and 2 first (8-node quadrilateral and 6-node
!> triangle order).
!> 2D: face Sn is the edge from local(1) to local(2) with the element on its left (for the counterclockwise node
!> order Abaqus requires), so the outward normal is (dy, -dx) of that edge; local(3) is its mid-side node (CPE8).
module element_faces
  use model_types, only: etype_c3d8, etype_cpe4, etype_c3d8i, etype_c3d20, etype_c3d20r, etype_c3d4, etype_c3d10, &
    etype_cpe4i, etype_cpe8, etype_cpe8r, etype_cps4, etype_cps4i, etype_cps8, etype_cps8r, etype_c3d8r, etype_cpe4r, &
    etype_cps4r, etype_cax4, etype_cax4i, etype_cax8, etype_cax8r, etype_cax4r
  implicit none
  private
  public :: element_face_nodes

  ! hexahedra: S1 1-2-3-4, S2 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3, S5 3-7-8-4, S6 4-8-5-1 (Abaqus), reversed: outward;
  ! C3D20 mid-side nodes 9-12 (edges 1-2, 2-3, 3-4, 4-1), 13-16 (5-6, 6-7, 7-8, 8-5), 17-20 (1-5, 2-6, 3-7, 4-8)
  integer, parameter :: hex_faces(8, 6) = reshape([ &
    1, 4, 3, 2, 12, 11, 10, 9, &
    5, 6, 7, 8, 13, 14, 15, 16, &
    1, 2, 6, 5, 9, 18, 13, 17, &
    2, 3, 7, 6, 10, 19, 14, 18, &
    3, 4, 8, 7, 11, 20, 15, 19, &
    4, 1, 5, 8, 12, 17, 16, 20], [8, 6])
  ! tetrahedra: S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1 (Abaqus), reversed: outward; C3D10 mid-side nodes 5 (1-2),
  ! 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4)
  integer, parameter :: tet_faces(6, 4) = reshape([ &
    1, 3, 2, 7, 6, 5, &
    2, 4, 1, 9, 8, 5, &
    3, 4, 2, 10, 9, 6, &
    1, 4, 3, 8, 10, 7], [6, 4])
  ! quadrilaterals: S1 1-2, S2 2-3, S3 3-4, S4 4-1; CPE8 mid-side nodes 5-8
  integer, parameter :: quad_faces(3, 4) = reshape([1, 2, 5, 2, 3, 6, 3, 4, 7, 4, 1, 8], [3, 4])

contains

  !> Connectivity positions local(1:nfn) of face `face` (1..6 = S1..S6) of an element of kind `kind`; nfn = 0 when
  !> the element kind has no such face. nfn: 4 or 8 (hexahedra), 3 or 6 (tetrahedra), 2 or 3 (quadrilaterals).
  pure subroutine element_face_nodes(kind, face, local, nfn)
    integer, intent(in) :: kind       !< etype_* of model_types
    integer, intent(in) :: face       !< 1..6 = S1..S6
    integer, intent(out) :: local(8)  !< positions in the connectivity (outward order, see above)
    integer, intent(out) :: nfn       !< face nodes, 0 if the face does not exist
    local = 0
    nfn = 0
    select case (kind)
    case (etype_c3d8, etype_c3d8i, etype_c3d8r, etype_c3d20, etype_c3d20r)
      if (face < 1 .or. face > 6) return
      nfn = merge(8, 4, kind == etype_c3d20 .or. kind == etype_c3d20r)
      local(1:nfn) = hex_faces(1:nfn, face)
    case (etype_c3d4, etype_c3d10)
      if (face < 1 .or. face > 4) return
      nfn = merge(6, 3, kind == etype_c3d10)
      local(1:nfn) = tet_faces(1:nfn, face)
    case (etype_cpe4, etype_cpe4i, etype_cpe4r, etype_cpe8, etype_cpe8r, etype_cps4, etype_cps4i, etype_cps4r, &
          etype_cps8, etype_cps8r, etype_cax4, etype_cax4i, etype_cax8, etype_cax8r, etype_cax4r)
      if (face < 1 .or. face > 4) return
      nfn = merge(3, 2, any(kind == [etype_cpe8, etype_cpe8r, etype_cps8, etype_cps8r, etype_cax8, etype_cax8r]))
      local(1:nfn) = quad_faces(1:nfn, face)
    end select
  end subroutine element_face_nodes

end module element_faces
