!> Element colouring for the threaded assembly: elements of one colour share no degree of freedom, so their
!> element matrices go into the sparse matrix without atomic updates, and the sum of the contributions to each
!> matrix entry is taken in colour order, then element order: the same on any number of threads (the tangent, and
!> with it every Newton iterate, is bitwise independent of --threads; atomic updates in a dynamic schedule sum in
!> a run-dependent order).
!> Greedy first-fit colouring in element order; a bit mask of the colours taken per dof (64 colours per word,
!> as many words as needed: a hexahedral mesh needs about 8, cohesive layers a few more).
module element_colors
  use ldfcz_kinds, only: i8
  implicit none
  private
  public :: color_elements

contains

  !> Colour the elements: color_ptr(c):color_ptr(c+1)-1 indexes color_elem for the elements of colour c.
  pure subroutine color_elements(nelem, ndof, elem_ptr, elem_dof, ncolor, color_ptr, color_elem)
    integer, intent(in) :: nelem                         !< number of elements
    integer, intent(in) :: ndof                          !< number of dofs
    integer, intent(in) :: elem_ptr(:)                   !< (nelem+1) dofs of e: elem_dof(elem_ptr(e):elem_ptr(e+1)-1)
    integer, intent(in) :: elem_dof(:)                   !< global dof of each element dof (1..ndof)
    integer, intent(out) :: ncolor                       !< number of colours
    integer, allocatable, intent(out) :: color_ptr(:)    !< (ncolor+1)
    integer, allocatable, intent(out) :: color_elem(:)   !< (nelem) elements sorted by colour, in element order
    integer(i8), allocatable :: taken(:, :), grown(:, :)
    integer(i8) :: used
    integer, allocatable :: color(:), count(:)
    integer :: e, k, w, nw, b, c

    nw = 1
    allocate (taken(nw, ndof), color(nelem))
    taken = 0_i8
    ncolor = 0
    do e = 1, nelem
      c = 0
      do w = 1, nw
        used = 0_i8
        do k = elem_ptr(e), elem_ptr(e + 1) - 1
          used = ior(used, taken(w, elem_dof(k)))
        end do
        if (not(used) /= 0_i8) then
          b = trailz(not(used))
          c = 64 * (w - 1) + b + 1
          exit
        end if
      end do
      if (c == 0) then
        ! every colour of every word taken: one more word
        allocate (grown(nw + 1, ndof))
        grown(1:nw, :) = taken
        grown(nw + 1, :) = 0_i8
        call move_alloc(grown, taken)
        nw = nw + 1
        c = 64 * (nw - 1) + 1
      end if
      color(e) = c
      ncolor = max(ncolor, c)
      w = (c - 1) / 64 + 1
      b = mod(c - 1, 64)
      do k = elem_ptr(e), elem_ptr(e + 1) - 1
        taken(w, elem_dof(k)) = ibset(taken(w, elem_dof(k)), b)
      end do
    end do
    allocate (count(ncolor + 1), color_ptr(ncolor + 1), color_elem(nelem))
    count = 0
    do e = 1, nelem
      count(color(e)) = count(color(e)) + 1
    end do
    color_ptr(1) = 1
    do c = 1, ncolor
      color_ptr(c + 1) = color_ptr(c) + count(c)
    end do
    count(1:ncolor) = color_ptr(1:ncolor)
    do e = 1, nelem
      color_elem(count(color(e))) = e
      count(color(e)) = count(color(e)) + 1
    end do
  end subroutine color_elements

end module element_colors
