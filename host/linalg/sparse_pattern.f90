!> Sparsity pattern of an assembled finite-element matrix and the element -> matrix slot maps, built once.
!>
!> The pattern is CSR with sorted column indices; a symmetric system stores only the upper triangle (j >= i).
!> The slot map gives, for every entry (a, b) of every element matrix, the index into the value array where it is
!> added (0: skipped, because a dof is constrained or, when symmetric, the entry lies in the lower triangle).
!> Slot k of the CSR is also entry k of MUMPS' coordinate input (IRN(k) = row, JCN(k) = column).
module sparse_pattern
  use ldfcz_kinds, only: i8
  use ldfcz_sorting, only: sort_int
  implicit none
  private
  public :: build_pattern, build_slot_map, sort_int, find_in_row

contains

  !> CSR pattern (row_ptr, col) of sum over elements of the element couplings among free equations.
  subroutine build_pattern(neq, elem_ptr, elem_eq, symmetric, row_ptr, col, stat, errmsg, empty_rows)
    integer, intent(in) :: neq                        !< number of equations
    integer, intent(in) :: elem_ptr(:)                !< element CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)                 !< equation of each element dof (0 = constrained)
    logical, intent(in) :: symmetric                  !< store the upper triangle only
    integer, allocatable, intent(out) :: row_ptr(:)   !< CSR row pointers, size neq+1
    integer, allocatable, intent(out) :: col(:)       !< CSR column indices, sorted in each row
    integer, intent(out) :: stat                      !< 0 on success
    character(len=*), intent(out) :: errmsg           !< reason on failure
    !> true: rows without entries are allowed (the part of a distributed process, whose elements touch some
    !> equations only); default false: an equation of no element is an error
    logical, intent(in), optional :: empty_rows
    character(len=*), parameter :: here = 'build_pattern'
    integer, allocatable :: qe_ptr(:), qe_elem(:), fill(:), mark(:)
    integer :: nelem, e, k, i, j, m, cnt, pos
    integer(i8) :: total
    logical :: allow_empty

    stat = 0
    errmsg = ''
    allow_empty = .false.
    if (present(empty_rows)) allow_empty = empty_rows
    nelem = size(elem_ptr) - 1
    if (any(elem_eq < 0) .or. any(elem_eq > neq)) then
      stat = 1
      errmsg = here//': an element equation number is outside 0..neq'
      return
    end if
    ! Equation -> element CSR (an element listed once per dof it has on the equation; duplicates are harmless).
    allocate(qe_ptr(neq + 1), fill(neq), mark(neq))
    qe_ptr = 0
    do e = 1, nelem
      do k = elem_ptr(e), elem_ptr(e + 1) - 1
        i = elem_eq(k)
        if (i > 0) qe_ptr(i + 1) = qe_ptr(i + 1) + 1
      end do
    end do
    qe_ptr(1) = 1
    do i = 1, neq
      qe_ptr(i + 1) = qe_ptr(i + 1) + qe_ptr(i)
    end do
    allocate(qe_elem(max(1, qe_ptr(neq + 1) - 1)))
    fill = qe_ptr(1:neq)
    do e = 1, nelem
      do k = elem_ptr(e), elem_ptr(e + 1) - 1
        i = elem_eq(k)
        if (i > 0) then
          qe_elem(fill(i)) = e
          fill(i) = fill(i) + 1
        end if
      end do
    end do
    ! Count, then fill each row with a marker array.
    allocate(row_ptr(neq + 1))
    mark = 0
    row_ptr(1) = 1
    total = 1
    do i = 1, neq
      cnt = 0
      do m = qe_ptr(i), qe_ptr(i + 1) - 1
        e = qe_elem(m)
        do k = elem_ptr(e), elem_ptr(e + 1) - 1
          j = elem_eq(k)
          if (j <= 0) cycle
          if (symmetric .and. j < i) cycle
          if (mark(j) /= i) then
            mark(j) = i
            cnt = cnt + 1
          end if
        end do
      end do
      if (cnt == 0 .and. .not. allow_empty) then
        stat = 2
        write(errmsg, '(a,a,i0,a)') here, ': equation ', i, ' belongs to no element (empty row)'
        return
      end if
      total = total + cnt
      if (total > huge(1)) then
        stat = 3
        errmsg = here//': more than 2**31-1 matrix entries'
        return
      end if
      row_ptr(i + 1) = int(total)
    end do
    allocate(col(row_ptr(neq + 1) - 1))
    mark = 0
    do i = 1, neq
      pos = row_ptr(i)
      do m = qe_ptr(i), qe_ptr(i + 1) - 1
        e = qe_elem(m)
        do k = elem_ptr(e), elem_ptr(e + 1) - 1
          j = elem_eq(k)
          if (j <= 0) cycle
          if (symmetric .and. j < i) cycle
          if (mark(j) /= i) then
            mark(j) = i
            col(pos) = j
            pos = pos + 1
          end if
        end do
      end do
      call sort_int(col(row_ptr(i):row_ptr(i + 1) - 1))
    end do
  end subroutine build_pattern

  !> Element -> slot maps: slot(slot_ptr(e) + (b-1)*n_e + (a-1)) is the value index of element entry (a, b)
  !> (column-major, as ke(a, b)); 0 when skipped. With keep, only the elements kept get a map (the others an empty
  !> one: a process of a distributed run maps only the elements it adds).
  subroutine build_slot_map(elem_ptr, elem_eq, symmetric, row_ptr, col, slot_ptr, slot, keep)
    integer, intent(in) :: elem_ptr(:)                 !< element CSR pointers into elem_eq
    integer, intent(in) :: elem_eq(:)                  !< equation of each element dof (0 = constrained)
    logical, intent(in) :: symmetric                   !< upper triangle only
    integer, intent(in) :: row_ptr(:)                  !< CSR row pointers
    integer, intent(in) :: col(:)                      !< CSR columns (sorted per row)
    integer(i8), allocatable, intent(out) :: slot_ptr(:) !< start of each element's map, size nelem+1
    integer, allocatable, intent(out) :: slot(:)       !< value index of each element entry (0 = skipped)
    logical, intent(in), optional :: keep(:)           !< (nelem) the elements to map (default: all)
    integer :: nelem, e, ne, a, b, i, j, k0
    integer(i8) :: p

    nelem = size(elem_ptr) - 1
    allocate(slot_ptr(nelem + 1))
    slot_ptr(1) = 1
    do e = 1, nelem
      ne = elem_ptr(e + 1) - elem_ptr(e)
      if (present(keep)) then
        if (.not. keep(e)) ne = 0
      end if
      slot_ptr(e + 1) = slot_ptr(e) + int(ne, i8)**2
    end do
    allocate(slot(slot_ptr(nelem + 1) - 1))
    do e = 1, nelem
      if (slot_ptr(e + 1) == slot_ptr(e)) cycle
      ne = elem_ptr(e + 1) - elem_ptr(e)
      k0 = elem_ptr(e) - 1
      p = slot_ptr(e)
      do b = 1, ne
        j = elem_eq(k0 + b)
        do a = 1, ne
          i = elem_eq(k0 + a)
          if (i <= 0 .or. j <= 0) then
            slot(p) = 0
          else if (symmetric .and. j < i) then
            slot(p) = 0
          else
            slot(p) = find_in_row(col, row_ptr(i), row_ptr(i + 1) - 1, j)
          end if
          p = p + 1
        end do
      end do
    end do
  end subroutine build_slot_map

  !> Index of column j in the sorted segment col(lo:hi) (binary search); 0 if absent.
  pure integer function find_in_row(col, lo, hi, j) result(k)
    integer, intent(in) :: col(:)  !< CSR columns
    integer, intent(in) :: lo      !< first index of the row
    integer, intent(in) :: hi      !< last index of the row
    integer, intent(in) :: j       !< column sought
    integer :: l, h, m

    k = 0
    l = lo
    h = hi
    do while (l <= h)
      m = (l + h) / 2
      if (col(m) == j) then
        k = m
        return
      else if (col(m) < j) then
        l = m + 1
      else
        h = m - 1
      end if
    end do
  end function find_in_row

end module sparse_pattern
