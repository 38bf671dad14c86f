!> Partition of the elements over the processes of a distributed run (LDFCZ_MPI): METIS_PartGraphKway on the
!> element graph (two elements are adjacent when they share a node), each element weighted by its estimated cost
!> so that every process gets about the same element-loop time (a Leonov C3D8 costs far more than a cohesive or an
!> elastic element: analysis_core sets the weights). METIS runs with its default options, so the partition is
!> deterministic: every process computes the same one from the same model (test partition_*: each element is
!> owned exactly once over the processes).
!> Interleaved partition (pieces > 1): METIS cuts the graph into pieces x processes parts of equal weight and deals
!> them out in turn (part k to process mod(k, processes)), so that every process holds pieces all over the mesh. A
!> region whose elements cost more than their weight says (the plastic zone at a moving delamination front) then
!> falls on several processes instead of one (docs/performance.md, "Interleaved partition").
module element_partition
  use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_ptr, c_null_ptr
  implicit none
  private
  public :: partition_elements

  integer(c_int), parameter :: metis_ok = 1_c_int  !< METIS_OK in metis.h
  !> fewest elements per piece of an interleaved partition (fewer pieces on a small mesh)
  integer, parameter :: min_piece_elements = 10

  interface
    !> int METIS_PartGraphKway(idx_t *nvtxs, idx_t *ncon, idx_t *xadj, idx_t *adjncy, idx_t *vwgt, idx_t *vsize,
    !>   idx_t *adjwgt, idx_t *nparts, real_t *tpwgts, real_t *ubvec, idx_t *options, idx_t *objval, idx_t *part)
    function c_metis_kway(nvtxs, ncon, xadj, adjncy, vwgt, vsize, adjwgt, nparts, tpwgts, ubvec, options, objval, &
        part) bind(c, name='METIS_PartGraphKway') result(status)
      import :: c_int, c_int32_t, c_ptr
      integer(c_int32_t), intent(in) :: nvtxs, ncon
      integer(c_int32_t), intent(in) :: xadj(*), adjncy(*), vwgt(*)
      type(c_ptr), value :: vsize, adjwgt, tpwgts, ubvec, options
      integer(c_int32_t), intent(in) :: nparts
      integer(c_int32_t), intent(out) :: objval
      integer(c_int32_t), intent(out) :: part(*)
      integer(c_int) :: status
    end function c_metis_kway
  end interface

contains

  !> owner(e) in 0..nparts-1 for every element e of the mesh given by its node lists (conn_ptr, conn), with the
  !> cost weight(e) >= 1 of each element, in pieces pieces per process (1: one connected part each; fewer when
  !> a piece would have fewer than min_piece_elements elements). stat /= 0: METIS failed (errmsg).
  subroutine partition_elements(nnode, conn_ptr, conn, weight, nparts, pieces, owner, stat, errmsg)
    integer, intent(in) :: nnode                    !< nodes of the mesh
    integer, intent(in) :: conn_ptr(:)              !< (nelem+1) CSR pointers into conn
    integer, intent(in) :: conn(:)                  !< node of each element node
    integer, intent(in) :: weight(:)                !< (nelem) cost of each element (>= 1)
    integer, intent(in) :: nparts                   !< processes
    integer, intent(in) :: pieces                   !< pieces per process (>= 1)
    integer, allocatable, intent(out) :: owner(:)   !< (nelem) process of each element
    integer, intent(out) :: stat                    !< 0 ok
    character(len=*), intent(out) :: errmsg         !< reason on failure
    integer, allocatable :: ne_ptr(:), ne_elem(:), fill(:), mark(:), xadj(:), adjncy(:)
    integer(c_int32_t), allocatable :: cx(:), ca(:), cw(:), cpart(:)
    integer(c_int32_t) :: nv, ncon, np, objval
    integer :: nelem, e, k, a, f, cnt, pos, n, npieces

    stat = 0
    errmsg = ''
    nelem = size(conn_ptr) - 1
    allocate (owner(nelem))
    owner = 0
    if (nparts <= 1 .or. nelem <= 1) return
    if (nelem <= nparts) then
      owner = [(mod(e - 1, nparts), e = 1, nelem)]
      return
    end if
    ! node -> elements
    allocate (ne_ptr(nnode + 1), fill(nnode))
    ne_ptr = 0
    do k = 1, conn_ptr(nelem + 1) - 1
      ne_ptr(conn(k) + 1) = ne_ptr(conn(k) + 1) + 1
    end do
    ne_ptr(1) = 1
    do n = 1, nnode
      ne_ptr(n + 1) = ne_ptr(n + 1) + ne_ptr(n)
    end do
    allocate (ne_elem(max(1, ne_ptr(nnode + 1) - 1)))
    fill = ne_ptr(1:nnode)
    do e = 1, nelem
      do k = conn_ptr(e), conn_ptr(e + 1) - 1
        ne_elem(fill(conn(k))) = e
        fill(conn(k)) = fill(conn(k)) + 1
      end do
    end do
    ! element -> elements sharing a node (no self loops, each once): counted, then filled
    allocate (mark(nelem), xadj(nelem + 1))
    mark = 0
    xadj(1) = 1
    do e = 1, nelem
      cnt = 0
      do k = conn_ptr(e), conn_ptr(e + 1) - 1
        do a = ne_ptr(conn(k)), ne_ptr(conn(k) + 1) - 1
          f = ne_elem(a)
          if (f == e .or. mark(f) == e) cycle
          mark(f) = e
          cnt = cnt + 1
        end do
      end do
      xadj(e + 1) = xadj(e) + cnt
    end do
    allocate (adjncy(max(1, xadj(nelem + 1) - 1)))
    mark = 0
    pos = 0
    do e = 1, nelem
      do k = conn_ptr(e), conn_ptr(e + 1) - 1
        do a = ne_ptr(conn(k)), ne_ptr(conn(k) + 1) - 1
          f = ne_elem(a)
          if (f == e .or. mark(f) == e) cycle
          mark(f) = e
          pos = pos + 1
          adjncy(pos) = f
        end do
      end do
    end do
    if (pos == 0) then
      ! no element shares a node with another: deal them out by weight order
      owner = [(mod(e - 1, nparts), e = 1, nelem)]
      return
    end if
    cx = int(xadj - 1, c_int32_t)
    ca = int(adjncy(1:pos) - 1, c_int32_t)
    cw = int(max(1, weight), c_int32_t)
    allocate (cpart(nelem))
    nv = int(nelem, c_int32_t)
    ncon = 1
    npieces = max(1, min(pieces, nelem / (nparts * min_piece_elements)))
    np = int(nparts * npieces, c_int32_t)
    if (c_metis_kway(nv, ncon, cx, ca, cw, c_null_ptr, c_null_ptr, np, c_null_ptr, c_null_ptr, c_null_ptr, &
        objval, cpart) /= metis_ok) then
      stat = 1
      errmsg = 'METIS_PartGraphKway failed on the element graph'
      return
    end if
    owner = mod(int(cpart), nparts)
  end subroutine partition_elements

end module element_partition
