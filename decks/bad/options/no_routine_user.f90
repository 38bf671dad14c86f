! a user file without UEL or UMAT (option-set corpus)
subroutine helper(x)
  real, intent(inout) :: x
  x = 2 * x
end subroutine helper
