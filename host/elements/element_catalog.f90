!> The element catalogue: every continuum element type of the host declared once, with everything the reader, the
!> element kernel, the face logic, the writers and the notices need to know about it. An element kind in the model
!> (model_t%elem_kind) is an index into element_types; a user element (UEL) has no entry (model_types' etype_user).
!>
!> Two tables:
!>   element_families  the node layout of a shape-function family: dimension, nodes, faces S1..Sn (node lists in the
!>                     connectivity, OUTWARD order, see below), the VTK cell and the VTK point order;
!>   element_types     one row per Abaqus element name: its family, kinematic class (3D, plane strain, plane stress,
!>                     axisymmetric), integration rule and number of points, and the formulation switches (F-bar,
!>                     incompatible modes, one point with hourglass stiffness) with a line for the documentation.
!> The shape functions and integration rules of the families are the kernel's (solid_shape.f90); adding a type is
!> its row here (and, for a new family, the family's row plus its shape functions and rule in solid_shape):
!> docs/extending.md. docs/elements.md's type table is generated from these rows (tools: ldfcz_doc_tables) and
!> tested against them (test docs_tables).
!>
!> Faces: 3D face corners ordered so that the right-hand rule gives the OUTWARD normal (the reverse of the order in
!> which the Abaqus element library lists them, whose right-hand normal points into the element: the first node
!> kept, the others reversed); quadratic faces follow with their mid-side nodes, the one between corners 1 and 2
!> first (8-node quadrilateral and 6-node triangle order). 2D: face Sn is the edge from local(1) to local(2) with
!> the element on its left (Abaqus' counterclockwise node order), so the outward normal is (dy, -dx) of that edge;
!> local(3) is its mid-side node (8-node quadrilaterals).
module element_catalog
  use ldfcz_kinds, only: dp
  use ldfcz_text, only: upper_case
  implicit none
  private
  public :: element_family_t, element_type_t, element_families, element_types
  public :: element_kind_of, element_hybrid_twin, element_name, element_family, element_nnode, element_ndim
  public :: element_ndi, element_nshr
  public :: element_is_axisymmetric, element_is_plane_stress, element_face_nodes, element_vtk_cell
  public :: element_vtk_points, element_names_text, element_rule_text, element_kinematics_text, element_tensor6
  public :: FAM_HEX8, FAM_HEX20, FAM_TET4, FAM_TET10, FAM_QUAD4, FAM_QUAD8, FAM_WEDGE6, FAM_TRI3, FAM_TRI6, &
    FAM_WEDGE15
  public :: RULE_TET1, RULE_TET4, RULE_WEDGE2, RULE_TRI1, RULE_TRI3, RULE_WEDGE9
  public :: KIN_3D, KIN_PLANE_STRAIN, KIN_PLANE_STRESS, KIN_AXISYMMETRIC
  public :: KERNEL_GENERIC, KERNEL_C3D8

  !> shape-function families (solid_shape: shape functions, parent coordinates, node order)
  integer, parameter :: FAM_HEX8 = 1, FAM_HEX20 = 2, FAM_TET4 = 3, FAM_TET10 = 4, FAM_QUAD4 = 5, FAM_QUAD8 = 6, &
    FAM_WEDGE6 = 7, FAM_TRI3 = 8, FAM_TRI6 = 9, FAM_WEDGE15 = 10
  !> integration rules: n > 0 Gauss points per direction; the tetrahedral centroid (1) and 4-point rules; the wedge's
  !> triangle centroid times 2 Gauss points through the thickness, and the triangle's 3 points times 3; the
  !> triangle's centroid and its 3-point rule (solid_shape: solid_gauss_point)
  integer, parameter :: RULE_TET1 = -1, RULE_TET4 = -4, RULE_WEDGE2 = -12, RULE_TRI1 = -21, RULE_TRI3 = -23, &
    RULE_WEDGE9 = -19
  !> kinematic classes: NDI, NSHR of the material call and the meaning of the coordinates
  integer, parameter :: KIN_3D = 1, KIN_PLANE_STRAIN = 2, KIN_PLANE_STRESS = 3, KIN_AXISYMMETRIC = 4
  !> element kernels (solid_element): the generic path, sized at run time, serves every type; a type with a
  !> fixed-size kernel takes it where the kernel covers the call (KERNEL_C3D8: 8 nodes, 2x2x2 points, F-bar, under
  !> NLGEOM without *ORIENTATION; solid_c3d8.f90), with the same results to the bit
  integer, parameter :: KERNEL_GENERIC = 0, KERNEL_C3D8 = 1

  !> The node layout of a shape-function family.
  type :: element_family_t
    character(len=8) :: name = ''          !< e.g. 'HEX8'
    integer :: ndim = 0                    !< coordinates and displacement dofs per node
    integer :: nnode = 0                   !< nodes
    integer :: nface = 0                   !< faces S1..S(nface)
    integer :: face_nnode(6) = 0           !< nodes of each face
    integer :: faces(8, 6) = 0             !< face node positions in the connectivity (outward order, header)
    integer :: vtk_cell = 0                !< VTK cell type of the frames
    integer :: vtk_points(20) = 0          !< VTK point k of the cell is the element's node vtk_points(k)
  end type element_family_t

  !> One element type.
  type :: element_type_t
    character(len=8) :: name = ''          !< Abaqus name (also the JOB.dat table label: "ELEMENT TYPE name")
    integer :: family = 0                  !< FAM_*
    integer :: kinematics = 0              !< KIN_*
    integer :: rule = 0                    !< Gauss points per direction (> 0) or RULE_*
    integer :: nip = 0                     !< integration points
    logical :: fbar = .false.              !< F-bar (NLGEOM) / mean-dilatation B-bar (small strain)
    integer :: nmode = 0                   !< incompatible displacement modes (each ndim parameters), condensed
    logical :: hourglass = .false.         !< one point with Flanagan-Belytschko hourglass stiffness
    character(len=112) :: formulation = ''  !< the formulation in a few words (docs/elements.md)
    integer :: kernel = KERNEL_GENERIC     !< KERNEL_*: the fixed-size kernel of the type, if it has one
  end type element_type_t

  integer, parameter :: ident20(20) = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20]
  ! hexahedra: S1 1-2-3-4, S2 5-8-7-6, S3 1-5-6-2, S4 2-6-7-3, S5 3-7-8-4, S6 4-8-5-1 (Abaqus), reversed: outward;
  ! 20 nodes: mid-side 9-12 (edges 1-2, 2-3, 3-4, 4-1), 13-16 (5-6, 6-7, 7-8, 8-5), 17-20 (1-5, 2-6, 3-7, 4-8)
  integer, parameter :: hex_faces(8, 6) = reshape([ &
    1, 4, 3, 2, 12, 11, 10, 9, &
    5, 6, 7, 8, 13, 14, 15, 16, &
    1, 2, 6, 5, 9, 18, 13, 17, &
    2, 3, 7, 6, 10, 19, 14, 18, &
    3, 4, 8, 7, 11, 20, 15, 19, &
    4, 1, 5, 8, 12, 17, 16, 20], [8, 6])
  ! tetrahedra: S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1 (Abaqus), reversed: outward; 10 nodes: mid-side 5 (1-2),
  ! 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4)
  integer, parameter :: tet_faces(8, 6) = reshape([ &
    1, 3, 2, 7, 6, 5, 0, 0, &
    2, 4, 1, 9, 8, 5, 0, 0, &
    3, 4, 2, 10, 9, 6, 0, 0, &
    1, 4, 3, 8, 10, 7, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0], [8, 6])
  ! wedges: S1 1-2-3, S2 4-6-5, S3 1-4-5-2, S4 2-5-6-3, S5 3-6-4-1 (Abaqus), reversed: outward
  integer, parameter :: wedge_faces(8, 6) = reshape([ &
    1, 3, 2, 0, 0, 0, 0, 0, &
    4, 5, 6, 0, 0, 0, 0, 0, &
    1, 2, 5, 4, 0, 0, 0, 0, &
    2, 3, 6, 5, 0, 0, 0, 0, &
    3, 1, 4, 6, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0], [8, 6])
  ! quadrilaterals: S1 1-2, S2 2-3, S3 3-4, S4 4-1; 8 nodes: mid-side nodes 5-8
  integer, parameter :: quad_faces(8, 6) = reshape([ &
    1, 2, 5, 0, 0, 0, 0, 0, &
    2, 3, 6, 0, 0, 0, 0, 0, &
    3, 4, 7, 0, 0, 0, 0, 0, &
    4, 1, 8, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0], [8, 6])
  ! 15-node wedges: the same faces with their mid-side nodes (7-9 on 1-2, 2-3, 3-1; 10-12 on 4-5, 5-6, 6-4;
  ! 13-15 on 1-4, 2-5, 3-6)
  integer, parameter :: wedge15_faces(8, 6) = reshape([ &
    1, 3, 2, 9, 8, 7, 0, 0, &
    4, 5, 6, 10, 11, 12, 0, 0, &
    1, 2, 5, 4, 7, 14, 10, 13, &
    2, 3, 6, 5, 8, 15, 11, 14, &
    3, 1, 4, 6, 9, 13, 12, 15, &
    0, 0, 0, 0, 0, 0, 0, 0], [8, 6])
  ! triangles: S1 1-2, S2 2-3, S3 3-1; 6 nodes: mid-side nodes 4 (1-2), 5 (2-3), 6 (3-1)
  integer, parameter :: tri_faces(8, 6) = reshape([ &
    1, 2, 4, 0, 0, 0, 0, 0, &
    2, 3, 5, 0, 0, 0, 0, 0, &
    3, 1, 6, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0, &
    0, 0, 0, 0, 0, 0, 0, 0], [8, 6])

  !> The families. VTK cells: 12 hexahedron, 25 quadratic hexahedron, 10 tetrahedron, 24 quadratic tetrahedron,
  !> 9 quadrilateral, 23 quadratic quadrilateral, 5 triangle, 22 quadratic triangle (Abaqus' node order is VTK's
  !> for all of these), 13 wedge and 26 quadratic wedge: VTK's base triangle
  !> 0-1-2 has its right-hand normal pointing AWAY from the top triangle 3-4-5, Abaqus' 1-2-3 towards 4-5-6
  !> (counterclockwise seen from the top), so the frames list the nodes 1, 3, 2, 4, 6, 5 (and the mid-side nodes of
  !> the edges VTK's order then names: 9, 8, 7 below, 12, 11, 10 above, 13, 15, 14 between).
  type(element_family_t), parameter :: element_families(10) = [ &
    element_family_t('HEX8', 3, 8, 6, [4, 4, 4, 4, 4, 4], hex_faces, 12, ident20), &
    element_family_t('HEX20', 3, 20, 6, [8, 8, 8, 8, 8, 8], hex_faces, 25, ident20), &
    element_family_t('TET4', 3, 4, 4, [3, 3, 3, 3, 0, 0], tet_faces, 10, ident20), &
    element_family_t('TET10', 3, 10, 4, [6, 6, 6, 6, 0, 0], tet_faces, 24, ident20), &
    element_family_t('QUAD4', 2, 4, 4, [2, 2, 2, 2, 0, 0], quad_faces, 9, ident20), &
    element_family_t('QUAD8', 2, 8, 4, [3, 3, 3, 3, 0, 0], quad_faces, 23, ident20), &
    element_family_t('WEDGE6', 3, 6, 5, [3, 3, 4, 4, 4, 0], wedge_faces, 13, &
      [1, 3, 2, 4, 6, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]), &
    element_family_t('TRI3', 2, 3, 3, [2, 2, 2, 0, 0, 0], tri_faces, 5, ident20), &
    element_family_t('TRI6', 2, 6, 3, [3, 3, 3, 0, 0, 0], tri_faces, 22, ident20), &
    element_family_t('WEDGE15', 3, 15, 5, [6, 6, 8, 8, 8, 0], wedge15_faces, 26, &
      [1, 3, 2, 4, 6, 5, 9, 8, 7, 12, 11, 10, 13, 15, 14, 0, 0, 0, 0, 0])]

  !> The element types (docs/elements.md: the table generated from these rows).
  type(element_type_t), parameter :: element_types(29) = [ &
    element_type_t('C3D8', FAM_HEX8, KIN_3D, 2, 8, fbar=.true., &
      formulation='F-bar under NLGEOM; mean-dilatation B-bar without', kernel=KERNEL_C3D8), &
    element_type_t('C3D8I', FAM_HEX8, KIN_3D, 2, 8, nmode=3, &
      formulation='incompatible modes (3 x 3 parameters, condensed)'), &
    element_type_t('C3D8R', FAM_HEX8, KIN_3D, 1, 1, hourglass=.true., &
      formulation='uniform gradient + Flanagan-Belytschko hourglass stiffness c = 1 (not Abaqus'' default control)'), &
    element_type_t('C3D20', FAM_HEX20, KIN_3D, 3, 27, formulation='displacement'), &
    element_type_t('C3D20R', FAM_HEX20, KIN_3D, 2, 8, formulation='displacement, reduced integration'), &
    element_type_t('C3D4', FAM_TET4, KIN_3D, RULE_TET1, 1, formulation='displacement (constant strain)'), &
    element_type_t('C3D10', FAM_TET10, KIN_3D, RULE_TET4, 4, formulation='displacement'), &
    element_type_t('C3D6', FAM_WEDGE6, KIN_3D, RULE_WEDGE2, 2, &
      formulation='displacement (constant strain in the triangle, linear through the thickness)'), &
    element_type_t('CPE4', FAM_QUAD4, KIN_PLANE_STRAIN, 2, 4, fbar=.true., &
      formulation='plane strain, F-bar / B-bar as C3D8'), &
    element_type_t('CPE4I', FAM_QUAD4, KIN_PLANE_STRAIN, 2, 4, nmode=2, &
      formulation='plane strain, incompatible modes (2 x 2 parameters)'), &
    element_type_t('CPE4R', FAM_QUAD4, KIN_PLANE_STRAIN, 1, 1, hourglass=.true., &
      formulation='plane strain, hourglass stiffness'), &
    element_type_t('CPE8', FAM_QUAD8, KIN_PLANE_STRAIN, 3, 9, formulation='plane strain, displacement'), &
    element_type_t('CPE8R', FAM_QUAD8, KIN_PLANE_STRAIN, 2, 4, &
      formulation='plane strain, displacement, reduced integration'), &
    element_type_t('CPS4', FAM_QUAD4, KIN_PLANE_STRESS, 2, 4, formulation='plane stress (no F-bar)'), &
    element_type_t('CPS4I', FAM_QUAD4, KIN_PLANE_STRESS, 2, 4, nmode=2, &
      formulation='plane stress, incompatible modes (2 x 2 parameters)'), &
    element_type_t('CPS4R', FAM_QUAD4, KIN_PLANE_STRESS, 1, 1, hourglass=.true., &
      formulation='plane stress, hourglass stiffness'), &
    element_type_t('CPS8', FAM_QUAD8, KIN_PLANE_STRESS, 3, 9, formulation='plane stress, displacement'), &
    element_type_t('CPS8R', FAM_QUAD8, KIN_PLANE_STRESS, 2, 4, &
      formulation='plane stress, displacement, reduced integration'), &
    element_type_t('CAX4', FAM_QUAD4, KIN_AXISYMMETRIC, 2, 4, fbar=.true., &
      formulation='axisymmetric, F-bar / B-bar with the hoop stretch (m = 3)'), &
    element_type_t('CAX4R', FAM_QUAD4, KIN_AXISYMMETRIC, 1, 1, hourglass=.true., &
      formulation='axisymmetric, 2 pi R weighted uniform gradient and hoop mean + hourglass and hoop-variation '// &
      'stiffness'), &
    element_type_t('CAX8', FAM_QUAD8, KIN_AXISYMMETRIC, 3, 9, formulation='axisymmetric, displacement'), &
    element_type_t('CAX8R', FAM_QUAD8, KIN_AXISYMMETRIC, 2, 4, &
      formulation='axisymmetric, displacement, reduced integration'), &
    element_type_t('CPE3', FAM_TRI3, KIN_PLANE_STRAIN, RULE_TRI1, 1, &
      formulation='plane strain, displacement (constant strain)'), &
    element_type_t('CPE6', FAM_TRI6, KIN_PLANE_STRAIN, RULE_TRI3, 3, formulation='plane strain, displacement'), &
    element_type_t('CPS3', FAM_TRI3, KIN_PLANE_STRESS, RULE_TRI1, 1, &
      formulation='plane stress, displacement (constant strain)'), &
    element_type_t('CPS6', FAM_TRI6, KIN_PLANE_STRESS, RULE_TRI3, 3, formulation='plane stress, displacement'), &
    element_type_t('CAX3', FAM_TRI3, KIN_AXISYMMETRIC, RULE_TRI1, 1, &
      formulation='axisymmetric, displacement (hoop strain at the centroid)'), &
    element_type_t('CAX6', FAM_TRI6, KIN_AXISYMMETRIC, RULE_TRI3, 3, formulation='axisymmetric, displacement'), &
    element_type_t('C3D15', FAM_WEDGE15, KIN_3D, RULE_WEDGE9, 9, formulation='displacement')]

contains

  !> Kind (index in element_types) of an Abaqus element name (case-insensitive, blanks around it ignored); 0 when
  !> the catalogue has no such type.
  pure integer function element_kind_of(name) result(kind)
    character(len=*), intent(in) :: name  !< element type name, e.g. 'C3D8', 'cpe4'
    character(len=16) :: up
    integer :: i, first, last
    kind = 0
    first = verify(name, ' ')
    last = len_trim(name)
    if (first == 0) return
    if (last - first + 1 > len(up)) return
    up = upper_case(name(first:last))
    do i = 1, size(element_types)
      if (up == element_types(i)%name) then
        kind = i
        return
      end if
    end do
  end function element_kind_of

  !> True for a kind of the catalogue.
  pure logical function known(kind)
    integer, intent(in) :: kind
    known = kind >= 1 .and. kind <= size(element_types)
  end function known

  !> The kind that reads an Abaqus hybrid name (the type's name followed by H: C3D8H, C3D8RH, CPE4H, CAX4RH), 0 when
  !> none does: a type whose volumetric strain is constant over the element (the F-bar / mean-dilatation B-bar types
  !> and the one-point types). With a constant element pressure, Abaqus' hybrid formulation of such a type solves the
  !> same discrete equations for a linear elastic material (the mixed / selectively reduced equivalence of Malkus and
  !> Hughes 1978) and nearly the same ones otherwise: inferred, said where the reader warns (docs/elements.md).
  pure integer function element_hybrid_twin(name) result(kind)
    character(len=*), intent(in) :: name  !< element type name ending in H
    integer :: n, k
    kind = 0
    n = len_trim(name)
    if (n < 5) return
    if (name(n:n) /= 'H' .and. name(n:n) /= 'h') return
    k = element_kind_of(name(1:n - 1))
    if (.not. known(k)) return
    if (element_types(k)%kinematics == KIN_PLANE_STRESS) return
    if (element_types(k)%fbar .or. element_types(k)%hourglass) kind = k
  end function element_hybrid_twin

  !> Abaqus name of a kind ('' outside the catalogue).
  pure function element_name(kind) result(name)
    integer, intent(in) :: kind  !< element kind
    character(len=8) :: name
    name = ''
    if (known(kind)) name = element_types(kind)%name
  end function element_name

  !> Shape-function family of a kind (0 outside the catalogue).
  pure integer function element_family(kind)
    integer, intent(in) :: kind  !< element kind
    element_family = 0
    if (known(kind)) element_family = element_types(kind)%family
  end function element_family

  !> Nodes of a kind (0 outside the catalogue).
  pure integer function element_nnode(kind)
    integer, intent(in) :: kind  !< element kind
    element_nnode = 0
    if (known(kind)) element_nnode = element_families(element_types(kind)%family)%nnode
  end function element_nnode

  !> Coordinates and displacement dofs per node of a kind (0 outside the catalogue).
  pure integer function element_ndim(kind)
    integer, intent(in) :: kind  !< element kind
    element_ndim = 0
    if (known(kind)) element_ndim = element_families(element_types(kind)%family)%ndim
  end function element_ndim

  !> Direct stress components passed to the material (NDI): 2 in plane stress, 3 otherwise (0 outside).
  pure integer function element_ndi(kind)
    integer, intent(in) :: kind  !< element kind
    element_ndi = 0
    if (.not. known(kind)) return
    element_ndi = merge(2, 3, element_types(kind)%kinematics == KIN_PLANE_STRESS)
  end function element_ndi

  !> Shear stress components passed to the material (NSHR): 3 in 3D, 1 in 2D (0 outside).
  pure integer function element_nshr(kind)
    integer, intent(in) :: kind  !< element kind
    element_nshr = 0
    if (.not. known(kind)) return
    element_nshr = merge(3, 1, element_types(kind)%kinematics == KIN_3D)
  end function element_nshr

  !> True for the axisymmetric kinds (x1 = r, x2 = z; loads, forces and volumes are totals over 2 pi radians).
  pure logical function element_is_axisymmetric(kind)
    integer, intent(in) :: kind  !< element kind
    element_is_axisymmetric = .false.
    if (known(kind)) element_is_axisymmetric = element_types(kind)%kinematics == KIN_AXISYMMETRIC
  end function element_is_axisymmetric

  !> True for the plane-stress kinds (NDI = 2: sigma_33 = 0, the thickness strain free).
  pure logical function element_is_plane_stress(kind)
    integer, intent(in) :: kind  !< element kind
    element_is_plane_stress = .false.
    if (known(kind)) element_is_plane_stress = element_types(kind)%kinematics == KIN_PLANE_STRESS
  end function element_is_plane_stress

  !> Connectivity positions local(1:nfn) of face `face` (1.. = S1..) of an element of kind `kind` (outward order,
  !> module header); nfn = 0 when the kind has no such face.
  pure subroutine element_face_nodes(kind, face, local, nfn)
    integer, intent(in) :: kind       !< element kind
    integer, intent(in) :: face       !< 1.. = S1..
    integer, intent(out) :: local(8)  !< positions in the connectivity
    integer, intent(out) :: nfn       !< face nodes, 0 if the face does not exist
    integer :: f
    local = 0
    nfn = 0
    if (.not. known(kind)) return
    f = element_types(kind)%family
    if (face < 1 .or. face > element_families(f)%nface) return
    nfn = element_families(f)%face_nnode(face)
    local(1:nfn) = element_families(f)%faces(1:nfn, face)
  end subroutine element_face_nodes

  !> VTK cell type of a kind in the frames (0 outside the catalogue).
  pure integer function element_vtk_cell(kind)
    integer, intent(in) :: kind  !< element kind
    element_vtk_cell = 0
    if (known(kind)) element_vtk_cell = element_families(element_types(kind)%family)%vtk_cell
  end function element_vtk_cell

  !> The element's nodes in VTK's point order: positions in the connectivity (identity outside the catalogue).
  pure function element_vtk_points(kind, nn) result(p)
    integer, intent(in) :: kind  !< element kind
    integer, intent(in) :: nn    !< nodes of the element
    integer :: p(nn)
    integer :: k
    p = [(k, k = 1, nn)]
    if (.not. known(kind)) return
    if (element_nnode(kind) /= nn) return
    p = element_families(element_types(kind)%family)%vtk_points(1:nn)
  end function element_vtk_points

  !> The 6 components 11, 22, 33, 12, 13, 23 of a symmetric tensor given as the NTENS components a material of
  !> this kind works with (NDI direct, then NSHR shear: 3D 11..23; plane strain and axisymmetric 11, 22, 33, 12;
  !> plane stress 11, 22, 12, its 33 component 0).
  pure function element_tensor6(kind, t) result(f)
    integer, intent(in) :: kind      !< element kind
    real(dp), intent(in) :: t(:)     !< NTENS components
    real(dp) :: f(6)
    integer :: ndi, nshr
    f = 0.0_dp
    ndi = element_ndi(kind)
    nshr = element_nshr(kind)
    if (size(t) < ndi + nshr) return
    f(1:ndi) = t(1:ndi)
    f(4:3 + nshr) = t(ndi + 1:ndi + nshr)
  end function element_tensor6

  !> The names of the catalogue, comma separated ('C3D8, C3D8I, ...').
  pure function element_names_text() result(t)
    character(len=:), allocatable :: t
    integer :: k
    t = trim(element_types(1)%name)
    do k = 2, size(element_types)
      t = t//', '//trim(element_types(k)%name)
    end do
  end function element_names_text

  !> The integration rule as the documentation writes it: '2x2x2', '3x3', '1', '4 (tetrahedral)', '1x2 (wedge)'.
  pure function element_rule_text(kind) result(t)
    integer, intent(in) :: kind  !< element kind
    character(len=:), allocatable :: t
    character(len=1) :: n
    t = ''
    if (.not. known(kind)) return
    select case (element_types(kind)%rule)
    case (RULE_TET1)
      t = '1 (centroid)'
    case (RULE_TET4)
      t = '4 (tetrahedral)'
    case (RULE_WEDGE2)
      t = '1x2 (centroid x 2 through the thickness)'
    case (RULE_WEDGE9)
      t = '3x3 (3 in the triangle x 3 through the thickness)'
    case (RULE_TRI1)
      t = '1 (centroid)'
    case (RULE_TRI3)
      t = '3 (triangular)'
    case (1)
      t = '1'
    case default
      write (n, '(i1)') element_types(kind)%rule
      t = n//'x'//n
      if (element_ndim(kind) == 3) t = t//'x'//n
    end select
  end function element_rule_text

  !> The kinematic class in words: '3D', 'plane strain', 'plane stress', 'axisymmetric'.
  pure function element_kinematics_text(kind) result(t)
    integer, intent(in) :: kind  !< element kind
    character(len=:), allocatable :: t
    t = ''
    if (.not. known(kind)) return
    select case (element_types(kind)%kinematics)
    case (KIN_3D)
      t = '3D'
    case (KIN_PLANE_STRAIN)
      t = 'plane strain'
    case (KIN_PLANE_STRESS)
      t = 'plane stress'
    case (KIN_AXISYMMETRIC)
      t = 'axisymmetric'
    end select
  end function element_kinematics_text

end module element_catalog
