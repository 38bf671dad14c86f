!> The built-in UEL (target ldfcz_uel) and UMAT (target ldfcz_umat) as default procedure targets; a part that was
!> not built leaves its pointer null (a deck that needs it then fails with a clear message).
submodule (user_routines) builtin_routines
  implicit none
contains
  module subroutine user_routines_builtin(r)
    type(user_routines_t), intent(inout) :: r  !< routines
#ifdef LDFCZ_HAVE_UEL
    procedure(uel_interface) :: uel
#endif
#ifdef LDFCZ_HAVE_UMAT
    procedure(umat_interface) :: umat
#endif
#ifdef LDFCZ_HAVE_UEL
    r%uel => uel
    r%uel_origin = 'built-in ldfcz UEL'
#else
    r%uel => null()
    r%uel_origin = 'none'
#endif
#ifdef LDFCZ_HAVE_UMAT
    r%umat => umat
    r%umat_origin = 'built-in ldfcz UMAT'
#else
    r%umat => null()
    r%umat_origin = 'none'
#endif
  end subroutine user_routines_builtin
end submodule builtin_routines
