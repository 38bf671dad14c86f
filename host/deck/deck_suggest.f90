!> Suggestions for misspelt keywords and parameters: the candidate nearest to a word in edit distance (insertions,
!> deletions, substitutions and transpositions of neighbours each count 1: optimal string alignment), offered only
!> when it is near enough to be a typing slip and nearer than any other candidate.
module deck_suggest
  implicit none
  private
  public :: deck_closest, deck_edit_distance

contains

  !> Edit distance between a and b (optimal string alignment: a transposition of two neighbours counts 1).
  pure integer function deck_edit_distance(a, b) result(d)
    character(len=*), intent(in) :: a, b
    integer :: i, j, la, lb, cost
    integer, allocatable :: m(:, :)
    la = len(a)
    lb = len(b)
    allocate (m(0:la, 0:lb))
    m(:, 0) = [(i, i = 0, la)]
    m(0, :) = [(j, j = 0, lb)]
    do i = 1, la
      do j = 1, lb
        cost = merge(0, 1, a(i:i) == b(j:j))
        m(i, j) = min(m(i - 1, j) + 1, m(i, j - 1) + 1, m(i - 1, j - 1) + cost)
        if (i > 1 .and. j > 1) then
          if (a(i:i) == b(j - 1:j - 1) .and. a(i - 1:i - 1) == b(j:j)) m(i, j) = min(m(i, j), m(i - 2, j - 2) + 1)
        end if
      end do
    end do
    d = m(la, lb)
  end function deck_edit_distance

  !> Index of the candidate nearest to word (0: none near enough, or two equally near). Near enough: distance 1 for
  !> words of up to 4 characters, 2 up to 8, 3 beyond (a slip of one or two keys, not another word). The words are
  !> compared as given (the reader passes both in upper case) with trailing blanks ignored; an exact match is no
  !> suggestion.
  pure integer function deck_closest(word, candidates) result(best)
    character(len=*), intent(in) :: word           !< the word as read
    character(len=*), intent(in) :: candidates(:)  !< the names it may have meant
    integer :: k, d, dmin, limit, n
    logical :: tie
    best = 0
    n = len_trim(word)
    if (n == 0) return
    limit = 3
    if (n <= 8) limit = 2
    if (n <= 4) limit = 1
    dmin = huge(1)
    tie = .false.
    do k = 1, size(candidates)
      if (len_trim(candidates(k)) == 0) cycle
      d = deck_edit_distance(word(1:n), trim(candidates(k)))
      if (d == 0) return
      if (d < dmin) then
        dmin = d
        best = k
        tie = .false.
      else if (d == dmin) then
        tie = .true.
      end if
    end do
    if (dmin > limit .or. tie) best = 0
  end function deck_closest

end module deck_suggest
