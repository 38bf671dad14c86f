!> Fill-reducing ordering of the host's sparse systems: METIS nested dissection (METIS_NodeND) of the NODE graph,
!> expanded to equations.
!>
!> Two nodes are adjacent when they share an element. Ordering the node graph instead of the equation graph is
!> smaller (3x fewer vertices in 3D) and keeps the dofs of a node together in the pivot order; the equations of a
!> node are numbered consecutively at the node's position. The result is handed to MUMPS as a user ordering
!> (ICNTL(7) = 1, PERM_IN) because Debian's sequential MUMPS is built without METIS.
!>
!> METIS 5.1 is called directly through bind(C) interfaces; idx_t is 32-bit in Debian's build (metis.h:
!> IDXTYPEWIDTH 32), which matches c_int32_t below. The call uses METIS' default options (options = NULL), so the
!> ordering is deterministic.
!>
!> Permutation convention (METIS 5 manual, METIS_NodeND: "row (column) i of A' is the perm[i] row (column) of A,
!> and row (column) i of A is the iperm[i] row (column) of A'"): iperm(v) is the POSITION of vertex v, which is
!> what MUMPS wants in PERM_IN(i) ("position of variable i in the pivot order", MUMPS 5.5 user guide, ICNTL(7)).
module metis_ordering
  use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_ptr, c_null_ptr
  use sparse_pattern, only: sort_int
  implicit none
  private
  public :: node_graph_from_elements, metis_node_order, equation_order_from_nodes, is_permutation

  integer(c_int), parameter :: metis_ok = 1_c_int  !< METIS_OK in metis.h

  interface
    !> int METIS_NodeND(idx_t *nvtxs, idx_t *xadj, idx_t *adjncy, idx_t *vwgt, idx_t *options,
    !>                  idx_t *perm, idx_t *iperm)
    function c_metis_nodend(nvtxs, xadj, adjncy, vwgt, options, perm, iperm) bind(c, name='METIS_NodeND') &
        result(status)
      import :: c_int, c_int32_t, c_ptr
      integer(c_int32_t), intent(in) :: nvtxs          !< number of vertices
      integer(c_int32_t), intent(in) :: xadj(*)        !< 0-based CSR pointers, size nvtxs+1
      integer(c_int32_t), intent(in) :: adjncy(*)      !< 0-based neighbour lists (no self loops, symmetric)
      type(c_ptr), value :: vwgt                       !< vertex weights (NULL: unit)
      type(c_ptr), value :: options                    !< options (NULL: defaults)
      integer(c_int32_t), intent(out) :: perm(*)       !< perm(k) = vertex at position k (0-based)
      integer(c_int32_t), intent(out) :: iperm(*)      !< iperm(v) = position of vertex v (0-based)
      integer(c_int) :: status
    end function c_metis_nodend
  end interface

contains

  !> Node adjacency graph (CSR, 1-based, no self loops, each list sorted) from the element -> equation map.
  !> Node of element dof k = eq_node(elem_eq(k)) for free dofs (elem_eq(k) > 0); constrained dofs are skipped.
  subroutine node_graph_from_elements(nnode, elem_ptr, elem_eq, eq_node, xadj, adjncy)
    integer, intent(in) :: nnode                       !< number of nodes (max of eq_node)
    integer, intent(in) :: elem_ptr(:)                 !< element CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)                  !< equation of each element dof (0 = constrained)
    integer, intent(in) :: eq_node(:)                  !< node of each equation
    integer, allocatable, intent(out) :: xadj(:)       !< CSR pointers, size nnode+1
    integer, allocatable, intent(out) :: adjncy(:)     !< neighbours
    integer, allocatable :: en_ptr(:), en_node(:), ne_ptr(:), ne_elem(:), mark(:), fill(:)
    integer :: nelem, e, k, n, m, i, j, cnt, pos

    nelem = size(elem_ptr) - 1
    ! Distinct nodes of each element (element -> node CSR).
    allocate(mark(nnode), en_ptr(nelem + 1))
    mark = 0
    en_ptr(1) = 1
    allocate(en_node(max(1, size(elem_eq))))
    pos = 0
    do e = 1, nelem
      do k = elem_ptr(e), elem_ptr(e + 1) - 1
        if (elem_eq(k) <= 0) cycle
        n = eq_node(elem_eq(k))
        if (mark(n) /= e) then
          mark(n) = e
          pos = pos + 1
          en_node(pos) = n
        end if
      end do
      en_ptr(e + 1) = pos + 1
    end do
    ! Node -> element CSR.
    allocate(ne_ptr(nnode + 1), fill(nnode))
    ne_ptr = 0
    do k = 1, pos
      ne_ptr(en_node(k) + 1) = ne_ptr(en_node(k) + 1) + 1
    end do
    ne_ptr(1) = 1
    do n = 1, nnode
      ne_ptr(n + 1) = ne_ptr(n + 1) + ne_ptr(n)
    end do
    allocate(ne_elem(max(1, pos)))
    fill = ne_ptr(1:nnode)
    do e = 1, nelem
      do k = en_ptr(e), en_ptr(e + 1) - 1
        n = en_node(k)
        ne_elem(fill(n)) = e
        fill(n) = fill(n) + 1
      end do
    end do
    ! Two passes over the node neighbourhoods: count, then fill.
    allocate(xadj(nnode + 1))
    mark = 0
    xadj(1) = 1
    do n = 1, nnode
      cnt = 0
      do i = ne_ptr(n), ne_ptr(n + 1) - 1
        e = ne_elem(i)
        do j = en_ptr(e), en_ptr(e + 1) - 1
          m = en_node(j)
          if (m /= n .and. mark(m) /= n) then
            mark(m) = n
            cnt = cnt + 1
          end if
        end do
      end do
      xadj(n + 1) = xadj(n) + cnt
    end do
    allocate(adjncy(max(1, xadj(nnode + 1) - 1)))
    mark = 0
    do n = 1, nnode
      pos = xadj(n)
      do i = ne_ptr(n), ne_ptr(n + 1) - 1
        e = ne_elem(i)
        do j = en_ptr(e), en_ptr(e + 1) - 1
          m = en_node(j)
          if (m /= n .and. mark(m) /= n) then
            mark(m) = n
            adjncy(pos) = m
            pos = pos + 1
          end if
        end do
      end do
      call sort_int(adjncy(xadj(n):xadj(n + 1) - 1))
    end do
  end subroutine node_graph_from_elements

  !> Nested-dissection order of a graph by METIS_NodeND: position(v) = pivot position of vertex v (1-based).
  !> Graphs without edges (or with fewer than 3 vertices) keep the natural order: nothing to reduce.
  subroutine metis_node_order(nvtx, xadj, adjncy, position, stat, errmsg)
    integer, intent(in) :: nvtx                        !< number of vertices
    integer, intent(in) :: xadj(:)                     !< 1-based CSR pointers, size nvtx+1
    integer, intent(in) :: adjncy(:)                   !< 1-based neighbours
    integer, allocatable, intent(out) :: position(:)   !< position of each vertex in the order
    integer, intent(out) :: stat                       !< 0 on success
    character(len=*), intent(out) :: errmsg            !< reason on failure
    character(len=*), parameter :: here = 'metis_node_order'
    integer(c_int32_t), allocatable :: cxadj(:), cadj(:), perm(:), iperm(:)
    integer(c_int32_t) :: cn
    integer(c_int) :: status
    integer :: i, nedge

    stat = 0
    errmsg = ''
    allocate(position(nvtx))
    position = [(i, i = 1, nvtx)]
    nedge = xadj(nvtx + 1) - 1
    if (nvtx < 3 .or. nedge <= 0) return
    allocate(cxadj(nvtx + 1), cadj(nedge), perm(nvtx), iperm(nvtx))
    cxadj = int(xadj(1:nvtx + 1) - 1, c_int32_t)
    cadj = int(adjncy(1:nedge) - 1, c_int32_t)
    cn = int(nvtx, c_int32_t)
    status = c_metis_nodend(cn, cxadj, cadj, c_null_ptr, c_null_ptr, perm, iperm)
    if (status /= metis_ok) then
      stat = 1
      write(errmsg, '(a,a,i0)') here, ': METIS_NodeND failed with status ', status
      return
    end if
    position = int(iperm, kind(position)) + 1
    if (.not. is_permutation(position)) then
      stat = 2
      errmsg = here//': METIS_NodeND returned an invalid permutation'
    end if
  end subroutine metis_node_order

  !> Expand a node order to equations: the equations of the node at node position 1 come first (in increasing
  !> equation number), then those of the node at position 2, ... eq_position(i) = pivot position of equation i.
  pure subroutine equation_order_from_nodes(nnode, node_position, eq_node, eq_position)
    integer, intent(in) :: nnode                       !< number of nodes
    integer, intent(in) :: node_position(:)            !< position of each node, size nnode
    integer, intent(in) :: eq_node(:)                  !< node of each equation
    integer, intent(out) :: eq_position(:)             !< position of each equation, size(eq_node)
    integer, allocatable :: first(:), node_at(:)
    integer :: i, n, k

    allocate(first(nnode + 1), node_at(nnode))
    do n = 1, nnode
      node_at(node_position(n)) = n
    end do
    ! first(k) = first equation position of the node at node position k
    first = 0
    do i = 1, size(eq_node)
      k = node_position(eq_node(i))
      first(k + 1) = first(k + 1) + 1
    end do
    first(1) = 1
    do k = 1, nnode
      first(k + 1) = first(k + 1) + first(k)
    end do
    do i = 1, size(eq_node)
      k = node_position(eq_node(i))
      eq_position(i) = first(k)
      first(k) = first(k) + 1
    end do
  end subroutine equation_order_from_nodes

  !> True when p is a permutation of 1..size(p).
  pure logical function is_permutation(p)
    integer, intent(in) :: p(:)                        !< candidate permutation
    logical, allocatable :: seen(:)
    integer :: i

    is_permutation = .false.
    allocate(seen(size(p)))
    seen = .false.
    do i = 1, size(p)
      if (p(i) < 1 .or. p(i) > size(p)) return
      if (seen(p(i))) return
      seen(p(i)) = .true.
    end do
    is_permutation = .true.
  end function is_permutation

end module metis_ordering
