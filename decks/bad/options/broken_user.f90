! deliberately broken user file (option-set corpus: --user with a compilation error)
subroutine umat(
