!> Integration-point values of a continuum element extrapolated to its nodes, as post-processors do for contour
!> plots (Abaqus/CAE extrapolates from the points with the element's interpolation and averages at the nodes; the
!> frames' S_nodal, LE_nodal: field_frame). The values at the points are fitted by the polynomial that the rule's
!> points determine exactly, and that polynomial is evaluated at the nodes:
!>   n x n (x n) Gauss points: the tensor-product polynomial of degree n - 1 in each parent coordinate (n = 1: the
!>     constant; 2 x 2 x 2: trilinear, the usual extrapolation of C3D8, C3D8I and C3D20R; 3 x 3 x 3: triquadratic);
!>   the 4-point tetrahedron: linear (C3D10); the centroid rule: the constant (C3D4);
!>   the wedge's 2 points: linear through the thickness, constant in the triangle (C3D6);
!>   the triangle's 3 points: linear (CPE6, CPS6, CAX6); its centroid: the constant (CPE3, CPS3, CAX3);
!>   the 15-node wedge's 3 x 3 points: linear in the triangle times quadratic through the thickness (C3D15).
!> A constant field is reproduced exactly at every node (the rows of the matrix sum to 1), and so is any field of the
!> polynomial's degree. Which polynomial Abaqus fits for each rule is not documented in the pages found: inferred.
module point_extrapolation
  use ldfcz_kinds, only: dp
  use element_catalog, only: element_types, element_family, element_nnode, element_ndim, &
    RULE_TET1, RULE_TET4, RULE_WEDGE2, RULE_TRI1, RULE_TRI3, RULE_WEDGE9
  use solid_shape, only: solid_gauss_point, solid_node_parent
  implicit none
  private
  public :: point_to_node_matrix

contains

  !> The matrix e(a, ip) that takes the values at the integration points of an element of catalogue type kind to
  !> its nodes: v_node(a) = sum_ip e(a, ip) v_point(ip). stat /= 0 when the rule's points do not determine the
  !> polynomial (not for any type of the catalogue).
  pure subroutine point_to_node_matrix(kind, e, stat)
    integer, intent(in) :: kind                  !< element type (catalogue index)
    real(dp), allocatable, intent(out) :: e(:, :) !< (nnode, nip)
    integer, intent(out) :: stat                 !< 0 ok
    integer, allocatable :: pw(:, :)
    real(dp), allocatable :: pp(:, :), pn(:, :)
    real(dp) :: xi(3), w
    integer :: nnode, nip, ndim, ip, a, rule
    nnode = element_nnode(kind)
    nip = element_types(kind)%nip
    rule = element_types(kind)%rule
    ndim = element_ndim(kind)
    call basis_powers(rule, ndim, pw)
    allocate (pp(nip, nip), pn(nnode, nip), e(nnode, nip))
    do ip = 1, nip
      call solid_gauss_point(rule, ndim, ip, xi, w)
      pp(ip, :) = monomials(pw, xi)
    end do
    do a = 1, nnode
      pn(a, :) = monomials(pw, solid_node_parent(element_family(kind), a))
    end do
    ! e = pn pp^-1: solve pp^T e^T = pn^T
    call solve_transposed(pp, pn, e, stat)
  end subroutine point_to_node_matrix

  !> Exponents (3, nip) of the monomials xi^i eta^j zeta^k of a rule's polynomial.
  pure subroutine basis_powers(rule, ndim, pw)
    integer, intent(in) :: rule, ndim
    integer, allocatable, intent(out) :: pw(:, :)
    integer :: i, j, k, m
    select case (rule)
    case (RULE_TET1, RULE_TRI1)
      pw = reshape([0, 0, 0], [3, 1])
    case (RULE_TRI3)
      pw = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0], [3, 3])
    case (RULE_WEDGE9)
      pw = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 0, 0, 2, 1, 0, 2, 0, 1, 2], [3, 9])
    case (RULE_TET4)
      pw = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 4])
    case (RULE_WEDGE2)
      pw = reshape([0, 0, 0, 0, 0, 1], [3, 2])
    case default
      allocate (pw(3, rule**ndim))
      pw = 0
      m = 0
      do k = 0, merge(rule - 1, 0, ndim == 3)
        do j = 0, rule - 1
          do i = 0, rule - 1
            m = m + 1
            pw(:, m) = [i, j, k]
          end do
        end do
      end do
    end select
  end subroutine basis_powers

  pure function monomials(pw, xi) result(p)
    integer, intent(in) :: pw(:, :)
    real(dp), intent(in) :: xi(3)
    real(dp) :: p(size(pw, 2))
    integer :: m
    do m = 1, size(pw, 2)
      p(m) = xi(1)**pw(1, m) * xi(2)**pw(2, m) * xi(3)**pw(3, m)
    end do
  end function monomials

  !> x = b a^-1 (a square, b with as many columns) by Gauss elimination with partial pivoting on a^T.
  pure subroutine solve_transposed(a, b, x, stat)
    real(dp), intent(in) :: a(:, :), b(:, :)
    real(dp), intent(out) :: x(:, :)
    integer, intent(out) :: stat
    real(dp) :: m(size(a, 1), size(a, 1)), r(size(a, 1), size(b, 1)), f
    integer :: n, i, k, piv
    n = size(a, 1)
    m = transpose(a)
    r = transpose(b)
    stat = 0
    do k = 1, n
      piv = k - 1 + maxloc(abs(m(k:n, k)), 1)
      if (abs(m(piv, k)) <= 1.0e-12_dp * maxval(abs(m))) then
        stat = 1
        x = 0.0_dp
        return
      end if
      if (piv /= k) then
        m([k, piv], :) = m([piv, k], :)
        r([k, piv], :) = r([piv, k], :)
      end if
      do i = k + 1, n
        f = m(i, k) / m(k, k)
        m(i, k:n) = m(i, k:n) - f * m(k, k:n)
        r(i, :) = r(i, :) - f * r(k, :)
      end do
    end do
    do k = n, 1, -1
      r(k, :) = (r(k, :) - matmul(m(k, k + 1:n), r(k + 1:n, :))) / m(k, k)
    end do
    x = transpose(r)
  end subroutine solve_transposed

end module point_extrapolation
