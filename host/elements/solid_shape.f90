!> Shape functions and integration rules of the element families of the catalogue (element_catalog.f90: the types,
!> their families, rules and switches), in Abaqus node and integration-point order. solid_element.f90 has ONE
!> kinematics and UMAT-calling path for all of them.
!>
!> Families (parent coordinates, Abaqus node order):
!>   HEX8   nodes 1-4 on zeta = -1 counter-clockwise seen from +zeta, 5-8 above them on zeta = +1.
!>   HEX20  corners 1-8 as HEX8; mid-side 9-12 on the edges 1-2, 2-3, 3-4, 4-1; 13-16 on 5-6, 6-7, 7-8, 8-5;
!>          17-20 on 1-5, 2-6, 3-7, 4-8 (serendipity).
!>   TET4   corners 1 (0,0,0), 2 (1,0,0), 3 (0,1,0), 4 (0,0,1): 1-2-3 counter-clockwise seen from node 4.
!>   TET10  corners as TET4; mid-side 5 on 1-2, 6 on 2-3, 7 on 3-1, 8 on 1-4, 9 on 2-4, 10 on 3-4.
!>   WEDGE6 (g, h, r), g, h >= 0, g + h <= 1, -1 <= r <= 1: nodes 1 (0,0,-1), 2 (1,0,-1), 3 (0,1,-1) counter-clockwise
!>          seen from +r, 4-6 above them on r = +1; N_a = L_a (1 - r)/2, N_(a+3) = L_a (1 + r)/2 with L = (1 - g - h,
!>          g, h) (the Abaqus Theory Manual's first-order wedge).
!>   WEDGE15 corners as WEDGE6; mid-side 7-9 on 1-2, 2-3, 3-1, 10-12 on 4-5, 5-6, 6-4, 13-15 on 1-4, 2-5, 3-6;
!>          corner a: L_a ((2 L_a - 1)(1 + r_a r) - (1 - r^2)) / 2, triangle edge ij: 2 L_i L_j (1 + r_m r),
!>          vertical edge above a: L_a (1 - r^2) (r_a, r_m = -1 below, +1 above).
!>   QUAD4  counter-clockwise (-1,-1), (1,-1), (1,1), (-1,1).
!>   QUAD8  corners as QUAD4; mid-side 5 on 1-2, 6 on 2-3, 7 on 3-4, 8 on 4-1.
!>   TRI3   (g, h), g, h >= 0, g + h <= 1: nodes 1 (0,0), 2 (1,0), 3 (0,1) counter-clockwise; N = (1 - g - h, g, h).
!>   TRI6   corners as TRI3; mid-side 4 on 1-2, 5 on 2-3, 6 on 3-1; N_a = L_a (2 L_a - 1), N_(ij) = 4 L_i L_j.
!> Rules: Gauss n x n (x n) with xi fastest, then eta, then zeta (points at -g, [0,] +g in that order); tetrahedra:
!> 1 point at the centroid, or 4 points (volume coordinates a = 0.5854..., b = 0.1382...), point k nearest corner k;
!> wedge: the triangle's centroid at r = -1/sqrt(3) (point 1, nodes 1-3 side) and r = +1/sqrt(3) (point 2);
!> C3D15: the triangle's 3 points (below) fastest, then r = -sqrt(3/5), 0, +sqrt(3/5) (9 points);
!> triangles: the centroid (CPE3, CPS3, CAX3), or 3 points at (1/6, 1/6), (2/3, 1/6), (1/6, 2/3) (weights 1/6:
!> exact for quadratics; CPE6, CPS6, CAX6), point k nearest corner k.
!> The 2x2x2 order is Abaqus' documented one; for 3x3x3, 3x3, the 4-point tetrahedron, the wedge and the 3-point
!> triangle the same convention is inferred (docs/elements.md).
module solid_shape
  use ldfcz_kinds, only: dp
  use element_catalog, only: FAM_HEX8, FAM_HEX20, FAM_TET4, FAM_TET10, FAM_QUAD4, FAM_QUAD8, FAM_WEDGE6, &
    FAM_TRI3, FAM_TRI6, FAM_WEDGE15, RULE_TET1, RULE_TET4, RULE_WEDGE2, RULE_TRI1, RULE_TRI3, RULE_WEDGE9
  implicit none
  private
  public :: solid_shape_eval, solid_gauss_point, solid_parent_centre, solid_hourglass_base, solid_node_parent
  public :: solid_first_order_temperature

  real(dp), parameter :: hex_nodes(3, 20) = reshape([ &
    -1.0_dp, -1.0_dp, -1.0_dp,   1.0_dp, -1.0_dp, -1.0_dp,   1.0_dp, 1.0_dp, -1.0_dp,   -1.0_dp, 1.0_dp, -1.0_dp, &
    -1.0_dp, -1.0_dp,  1.0_dp,   1.0_dp, -1.0_dp,  1.0_dp,   1.0_dp, 1.0_dp,  1.0_dp,   -1.0_dp, 1.0_dp,  1.0_dp, &
     0.0_dp, -1.0_dp, -1.0_dp,   1.0_dp,  0.0_dp, -1.0_dp,   0.0_dp, 1.0_dp, -1.0_dp,   -1.0_dp, 0.0_dp, -1.0_dp, &
     0.0_dp, -1.0_dp,  1.0_dp,   1.0_dp,  0.0_dp,  1.0_dp,   0.0_dp, 1.0_dp,  1.0_dp,   -1.0_dp, 0.0_dp,  1.0_dp, &
    -1.0_dp, -1.0_dp,  0.0_dp,   1.0_dp, -1.0_dp,  0.0_dp,   1.0_dp, 1.0_dp,  0.0_dp,   -1.0_dp, 1.0_dp,  0.0_dp], &
    [3, 20])
  real(dp), parameter :: quad_nodes(2, 8) = reshape([ &
    -1.0_dp, -1.0_dp,   1.0_dp, -1.0_dp,   1.0_dp, 1.0_dp,   -1.0_dp, 1.0_dp, &
     0.0_dp, -1.0_dp,   1.0_dp,  0.0_dp,   0.0_dp, 1.0_dp,   -1.0_dp, 0.0_dp], [2, 8])
  !> TET10 mid-side nodes 5..10: the two corners of their edge
  integer, parameter :: tet_edges(2, 6) = reshape([1, 2, 2, 3, 3, 1, 1, 4, 2, 4, 3, 4], [2, 6])
  !> TRI6 mid-side nodes 4..6: the two corners of their edge (the first three edges of the tetrahedron's)
  integer, parameter :: tri_edges(2, 3) = tet_edges(:, 1:3)
  !> WEDGE15 mid-side nodes 7..15: the two corners of their edge
  integer, parameter :: wedge_edges(2, 9) = reshape([1, 2, 2, 3, 3, 1, 4, 5, 5, 6, 6, 4, 1, 4, 2, 5, 3, 6], [2, 9])

contains

  !> Parent coordinates of the element centre (centroid for tetrahedra).
  pure function solid_parent_centre(family) result(xi)
    integer, intent(in) :: family
    real(dp) :: xi(3)
    xi = 0.0_dp
    if (family == FAM_TET4 .or. family == FAM_TET10) xi = 0.25_dp
    if (any(family == [FAM_WEDGE6, FAM_WEDGE15, FAM_TRI3, FAM_TRI6])) xi(1:2) = 1.0_dp / 3
  end function solid_parent_centre

  !> Parent coordinates of node a of a family (the node tables of the module header; xi(3) = 0 in 2D).
  pure function solid_node_parent(family, a) result(xi)
    integer, intent(in) :: family  !< FAM_*
    integer, intent(in) :: a       !< node
    real(dp) :: xi(3)
    real(dp), parameter :: tet(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, &
      0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 4])
    real(dp), parameter :: wedge(3, 6) = reshape([0.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, &
      0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 1.0_dp], [3, 6])
    xi = 0.0_dp
    select case (family)
    case (FAM_HEX8, FAM_HEX20)
      xi = hex_nodes(:, a)
    case (FAM_QUAD4, FAM_QUAD8)
      xi(1:2) = quad_nodes(:, a)
    case (FAM_TET4, FAM_TET10)
      if (a <= 4) then
        xi = tet(:, a)
      else
        xi = 0.5_dp * (tet(:, tet_edges(1, a - 4)) + tet(:, tet_edges(2, a - 4)))
      end if
    case (FAM_WEDGE6, FAM_WEDGE15)
      if (a <= 6) then
        xi = wedge(:, a)
      else
        xi = 0.5_dp * (wedge(:, wedge_edges(1, a - 6)) + wedge(:, wedge_edges(2, a - 6)))
      end if
    case (FAM_TRI3, FAM_TRI6)
      if (a <= 3) then
        xi(1:2) = tet(1:2, a)
      else
        xi(1:2) = 0.5_dp * (tet(1:2, tri_edges(1, a - 3)) + tet(1:2, tri_edges(2, a - 3)))
      end if
    end select
  end function solid_node_parent

  !> Hourglass base vectors h(a, m) of the linear hexahedron (xi eta, eta zeta, zeta xi, xi eta zeta at the nodes:
  !> 4 vectors) or quadrilateral (xi eta: 1 vector); nh = their number (0 for other families).
  pure subroutine solid_hourglass_base(family, h, nh)
    integer, intent(in) :: family
    real(dp), intent(out) :: h(8, 4)
    integer, intent(out) :: nh
    h = 0.0_dp
    nh = 0
    select case (family)
    case (FAM_HEX8)
      nh = 4
      h(:, 1) = hex_nodes(1, 1:8) * hex_nodes(2, 1:8)
      h(:, 2) = hex_nodes(2, 1:8) * hex_nodes(3, 1:8)
      h(:, 3) = hex_nodes(3, 1:8) * hex_nodes(1, 1:8)
      h(:, 4) = hex_nodes(1, 1:8) * hex_nodes(2, 1:8) * hex_nodes(3, 1:8)
    case (FAM_QUAD4)
      nh = 1
      h(1:4, 1) = quad_nodes(1, 1:4) * quad_nodes(2, 1:4)
    end select
  end subroutine solid_hourglass_base

  !> Shape functions n(a) and their derivatives dndxi(a, k) = dN_a / dxi_k at the parent point xi.
  pure subroutine solid_shape_eval(family, xi, n, dndxi)
    integer, intent(in) :: family         !< FAM_*
    real(dp), intent(in) :: xi(:)         !< parent coordinates (3 or 2)
    real(dp), intent(out) :: n(:)         !< shape functions (nnode)
    real(dp), intent(out) :: dndxi(:, :)  !< derivatives (nnode x ndim)
    real(dp) :: p, q, r, s, l(4), dl(4, 3)
    integer :: a, k, i, j

    select case (family)
    case (FAM_HEX8)
      do a = 1, 8
        p = 1 + hex_nodes(1, a) * xi(1)
        q = 1 + hex_nodes(2, a) * xi(2)
        r = 1 + hex_nodes(3, a) * xi(3)
        n(a) = 0.125_dp * p * q * r
        dndxi(a, 1) = 0.125_dp * hex_nodes(1, a) * q * r
        dndxi(a, 2) = 0.125_dp * hex_nodes(2, a) * p * r
        dndxi(a, 3) = 0.125_dp * hex_nodes(3, a) * p * q
      end do
    case (FAM_HEX20)
      do a = 1, 8
        p = 1 + hex_nodes(1, a) * xi(1)
        q = 1 + hex_nodes(2, a) * xi(2)
        r = 1 + hex_nodes(3, a) * xi(3)
        s = hex_nodes(1, a) * xi(1) + hex_nodes(2, a) * xi(2) + hex_nodes(3, a) * xi(3) - 2
        n(a) = 0.125_dp * p * q * r * s
        dndxi(a, 1) = 0.125_dp * hex_nodes(1, a) * q * r * (s + p)
        dndxi(a, 2) = 0.125_dp * hex_nodes(2, a) * p * r * (s + q)
        dndxi(a, 3) = 0.125_dp * hex_nodes(3, a) * p * q * (s + r)
      end do
      do a = 9, 20
        ! the direction k in which the node sits at 0: N = (1 - xi_k^2)(1 + xi_i xi_ia)(1 + xi_j xi_ja) / 4
        k = minloc(abs(hex_nodes(:, a)), 1)
        i = modulo(k, 3) + 1
        j = modulo(k + 1, 3) + 1
        p = 1 - xi(k)**2
        q = 1 + hex_nodes(i, a) * xi(i)
        r = 1 + hex_nodes(j, a) * xi(j)
        n(a) = 0.25_dp * p * q * r
        dndxi(a, k) = -0.5_dp * xi(k) * q * r
        dndxi(a, i) = 0.25_dp * p * hex_nodes(i, a) * r
        dndxi(a, j) = 0.25_dp * p * q * hex_nodes(j, a)
      end do
    case (FAM_TET4, FAM_TET10)
      call simplex_shape(3, family == FAM_TET10, xi, n, dndxi)
    case (FAM_WEDGE6)
      ! L = (1 - g - h, g, h) in the triangle times the linear (1 -+ r)/2 through the thickness
      l(1:3) = [1 - xi(1) - xi(2), xi(1), xi(2)]
      dl = 0.0_dp
      dl(1, 1:2) = -1.0_dp
      dl(2, 1) = 1.0_dp
      dl(3, 2) = 1.0_dp
      do a = 1, 3
        do k = 1, 2
          r = 0.5_dp * (1 + (2 * k - 3) * xi(3))   ! (1 - r)/2 for the bottom nodes, (1 + r)/2 for the top ones
          i = a + 3 * (k - 1)
          n(i) = l(a) * r
          dndxi(i, 1:2) = dl(a, 1:2) * r
          dndxi(i, 3) = 0.5_dp * (2 * k - 3) * l(a)
        end do
      end do
    case (FAM_WEDGE15)
      call wedge15_shape(xi, n, dndxi)
    case (FAM_QUAD4)
      do a = 1, 4
        p = 1 + quad_nodes(1, a) * xi(1)
        q = 1 + quad_nodes(2, a) * xi(2)
        n(a) = 0.25_dp * p * q
        dndxi(a, 1) = 0.25_dp * quad_nodes(1, a) * q
        dndxi(a, 2) = 0.25_dp * quad_nodes(2, a) * p
      end do
    case (FAM_QUAD8)
      do a = 1, 4
        p = 1 + quad_nodes(1, a) * xi(1)
        q = 1 + quad_nodes(2, a) * xi(2)
        s = quad_nodes(1, a) * xi(1) + quad_nodes(2, a) * xi(2) - 1
        n(a) = 0.25_dp * p * q * s
        dndxi(a, 1) = 0.25_dp * quad_nodes(1, a) * q * (s + p)
        dndxi(a, 2) = 0.25_dp * quad_nodes(2, a) * p * (s + q)
      end do
      do a = 5, 8
        k = minloc(abs(quad_nodes(:, a)), 1)
        i = 3 - k
        p = 1 - xi(k)**2
        q = 1 + quad_nodes(i, a) * xi(i)
        n(a) = 0.5_dp * p * q
        dndxi(a, k) = -xi(k) * q
        dndxi(a, i) = 0.5_dp * p * quad_nodes(i, a)
      end do
    case (FAM_TRI3, FAM_TRI6)
      call simplex_shape(2, family == FAM_TRI6, xi, n, dndxi)
    case default
      n = 0.0_dp
      dndxi = 0.0_dp
    end select
  end subroutine solid_shape_eval

  !> Shape functions of the linear or quadratic simplex of dimension nd (tetrahedron 3, triangle 2; module
  !> header): L_1 = 1 - sum(xi), L_(k+1) = xi_k; corners L_a (or L_a (2 L_a - 1)), mid-side nodes 4 L_i L_j on the
  !> edges tet_edges(:, 1:6) (their first three are the triangle's).
  pure subroutine simplex_shape(nd, quadratic, xi, n, dndxi)
    integer, intent(in) :: nd
    logical, intent(in) :: quadratic
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: n(:), dndxi(:, :)
    real(dp) :: l(nd + 1), dl(nd + 1, nd)
    integer :: a, k, i, j
    l(1) = 1.0_dp
    dl = 0.0_dp
    dl(1, :) = -1.0_dp
    do k = 1, nd
      l(1) = l(1) - xi(k)      ! (1 - xi) - eta - zeta, left to right
      l(k + 1) = xi(k)
      dl(k + 1, k) = 1.0_dp
    end do
    if (.not. quadratic) then
      n(1:nd + 1) = l
      dndxi(1:nd + 1, 1:nd) = dl
      return
    end if
    do a = 1, nd + 1
      n(a) = l(a) * (2 * l(a) - 1)
      dndxi(a, 1:nd) = (4 * l(a) - 1) * dl(a, :)
    end do
    do a = nd + 2, size(n)
      i = tet_edges(1, a - nd - 1)
      j = tet_edges(2, a - nd - 1)
      n(a) = 4 * l(i) * l(j)
      dndxi(a, 1:nd) = 4 * (dl(i, :) * l(j) + l(i) * dl(j, :))
    end do
  end subroutine simplex_shape

  !> Nodal temperatures (or their increments) of a second-order quadrilateral or hexahedron replaced by those of
  !> their first-order part, as Abaqus/Standard interpolates temperatures in second-order stress elements ("if the
  !> underlying elements are of second order, the displacements are interpolated using quadratic functions,
  !> whereas the temperature field is interpolated using linear shape functions": Analysis User's Guide, quoted in
  !> the Eng-Tips thread 349349, 2012). Which linear field: the L2 projection, in parent coordinates, of the
  !> element's quadratic interpolant onto the (bi/tri)linear one. It reproduces the integration-point temperatures
  !> that thread measured in Abaqus for a CPS8 (weights 0.1958, -0.2333, -0.0624, -0.2333, 0.5915, 0.0751, 0.0751,
  !> 0.5915 at its first point); for the hexahedron the same projection is **inferred**. The projected corner value
  !> is T_a (1 - d/3) + sum over the d edges at corner a of (2 T_mid - T_other corner)/3 (d = 2 in 2D, 3 in 3D);
  !> the mid-side nodes get the mean of their corners, so the element's own interpolation of the returned values is
  !> that linear field. Linear fields are unchanged. Other families: t unchanged.
  pure subroutine solid_first_order_temperature(family, t)
    integer, intent(in) :: family     !< FAM_*
    real(dp), intent(inout) :: t(:)   !< nodal values (nnode)
    integer, parameter :: quad_e(2, 4) = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])
    integer, parameter :: hex_e(2, 12) = reshape([1, 2, 2, 3, 3, 4, 4, 1, 5, 6, 6, 7, 7, 8, 8, 5, 1, 5, 2, 6, 3, 7, &
      4, 8], [2, 12])
    select case (family)
    case (FAM_QUAD8)
      call project(t, 4, quad_e, 2.0_dp)
    case (FAM_HEX20)
      call project(t, 8, hex_e, 3.0_dp)
    end select
  contains
    pure subroutine project(t, nc, edges, d)
      real(dp), intent(inout) :: t(:)          !< nodal values
      integer, intent(in) :: nc, edges(:, :)   !< corners; edge k joins corners edges(:, k), its mid-side node nc + k
      real(dp), intent(in) :: d                !< edges at a corner
      real(dp) :: tc(nc)
      integer :: k, a, b
      tc = t(1:nc) * (1.0_dp - d / 3)
      do k = 1, size(edges, 2)
        a = edges(1, k)
        b = edges(2, k)
        tc(a) = tc(a) + (2 * t(nc + k) - t(b)) / 3
        tc(b) = tc(b) + (2 * t(nc + k) - t(a)) / 3
      end do
      t(1:nc) = tc
      do k = 1, size(edges, 2)
        t(nc + k) = 0.5_dp * (tc(edges(1, k)) + tc(edges(2, k)))
      end do
    end subroutine project
  end subroutine solid_first_order_temperature

  !> The 15-node wedge's shape functions and derivatives (module header) at (g, h, r).
  pure subroutine wedge15_shape(xi, n, dndxi)
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: n(:), dndxi(:, :)
    real(dp) :: l(3), dl(3, 2), r, ra, c
    integer :: a, i, j, m
    l = [1 - xi(1) - xi(2), xi(1), xi(2)]
    dl = reshape([-1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 0.0_dp, 1.0_dp], [3, 2])
    r = xi(3)
    do a = 1, 6
      i = modulo(a - 1, 3) + 1          ! the triangle corner of node a
      ra = merge(-1.0_dp, 1.0_dp, a <= 3)
      c = (2 * l(i) - 1) * (1 + ra * r) - (1 - r * r)
      n(a) = 0.5_dp * l(i) * c
      dndxi(a, 1:2) = 0.5_dp * dl(i, :) * c + 0.5_dp * l(i) * 2 * dl(i, :) * (1 + ra * r)
      dndxi(a, 3) = 0.5_dp * l(i) * ((2 * l(i) - 1) * ra + 2 * r)
    end do
    do m = 7, 12                        ! mid-side nodes of the triangle edges, below then above
      i = wedge_edges(1, m - 6) - merge(0, 3, m <= 9)
      j = wedge_edges(2, m - 6) - merge(0, 3, m <= 9)
      ra = merge(-1.0_dp, 1.0_dp, m <= 9)
      n(m) = 2 * l(i) * l(j) * (1 + ra * r)
      dndxi(m, 1:2) = 2 * (dl(i, :) * l(j) + l(i) * dl(j, :)) * (1 + ra * r)
      dndxi(m, 3) = 2 * l(i) * l(j) * ra
    end do
    do m = 13, 15                       ! mid-side nodes of the vertical edges
      i = m - 12
      n(m) = l(i) * (1 - r * r)
      dndxi(m, 1:2) = dl(i, :) * (1 - r * r)
      dndxi(m, 3) = -2 * l(i) * r
    end do
  end subroutine wedge15_shape

  !> Parent coordinates xi and weight w of integration point ip of a rule (Abaqus numbering, see the module header).
  pure subroutine solid_gauss_point(rule, ndim, ip, xi, w)
    integer, intent(in) :: rule    !< Gauss points per direction (1..3) or RULE_TET1, _TET4, _WEDGE2, _WEDGE9, _TRI1, _TRI3
    integer, intent(in) :: ndim    !< 2 or 3
    integer, intent(in) :: ip      !< integration point
    real(dp), intent(out) :: xi(3) !< parent coordinates (xi(3) = 0 in 2D)
    real(dp), intent(out) :: w     !< weight
    real(dp), parameter :: g2 = 0.577350269189625764509148780502_dp   ! 1/sqrt(3)
    real(dp), parameter :: g3 = 0.774596669241483377035853079956_dp   ! sqrt(3/5)
    real(dp), parameter :: ta = 0.585410196624968500_dp, tb = 0.138196601125010500_dp  ! (5 +- 3 sqrt 5)/20
    real(dp) :: pts(3), wts(3)
    integer :: k, d, m
    xi = 0.0_dp
    w = 0.0_dp
    select case (rule)
    case (RULE_TET1)
      xi = 0.25_dp
      w = 1.0_dp / 6
    case (RULE_TET4)
      xi = tb
      if (ip > 1) xi(ip - 1) = ta
      w = 1.0_dp / 24
    case (RULE_WEDGE2)
      ! the triangle's centroid (weight its area 1/2) x 2 Gauss points through the thickness (weight 1)
      xi = [1.0_dp / 3, 1.0_dp / 3, merge(-g2, g2, ip == 1)]
      w = 0.5_dp
    case (RULE_WEDGE9)
      ! the triangle's 3 points (weights 1/6) fastest, then 3 Gauss points through the thickness
      k = modulo(ip - 1, 3)
      m = (ip - 1) / 3 + 1
      xi(1:2) = 1.0_dp / 6
      if (k > 0) xi(k) = 2.0_dp / 3
      pts = [-g3, 0.0_dp, g3]
      wts = [5.0_dp / 9, 8.0_dp / 9, 5.0_dp / 9]
      xi(3) = pts(m)
      w = wts(m) / 6
    case (RULE_TRI1)
      xi(1:2) = 1.0_dp / 3
      w = 0.5_dp
    case (RULE_TRI3)
      xi(1:2) = 1.0_dp / 6
      if (ip > 1) xi(ip - 1) = 2.0_dp / 3
      w = 1.0_dp / 6
    case (1, 2, 3)
      select case (rule)
      case (1)
        pts(1) = 0.0_dp
        wts(1) = 2.0_dp
      case (2)
        pts(1:2) = [-g2, g2]
        wts(1:2) = 1.0_dp
      case default
        pts = [-g3, 0.0_dp, g3]
        wts = [5.0_dp / 9, 8.0_dp / 9, 5.0_dp / 9]
      end select
      k = ip - 1
      w = 1.0_dp
      do d = 1, ndim
        m = mod(k, rule) + 1
        k = k / rule
        xi(d) = pts(m)
        w = w * wts(m)
      end do
    end select
  end subroutine solid_gauss_point

end module solid_shape
