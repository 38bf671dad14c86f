!> The built-in library's registry: the routines linked into ldfcz that a deck may run by name with the
!> declaration '**LDFCZ BUILTIN, UMAT=name' or 'UEL=name' (host/deck/deck_declarations.f90). The host knows the
!> routines only through this table: their names, the source they are built from and their procedure. A part that
!> was not built (targets ldfcz_umat, ldfcz_uel) is not in the table.
submodule (user_routines) builtin_routines
  implicit none
contains

  !> The built-in routine KIND ('UMAT' or 'UEL') called NAME (upper case): its procedure (pu or pm, the other null)
  !> and the source it is built from; source = '' (and both pointers null) when the table has no such routine.
  module subroutine builtin_routine(kind, name, pu, pm, source)
    character(len=*), intent(in) :: kind                  !< 'UMAT' or 'UEL'
    character(len=*), intent(in) :: name                  !< routine name, upper case
    procedure(uel_interface), pointer, intent(out) :: pu  !< the UEL (kind 'UEL')
    procedure(umat_interface), pointer, intent(out) :: pm !< the UMAT (kind 'UMAT')
    character(len=:), allocatable, intent(out) :: source  !< its source in the project ('' when not found)
#ifdef LDFCZ_HAVE_UEL
    procedure(uel_interface) :: uel
#endif
#ifdef LDFCZ_HAVE_UMAT
    procedure(umat_interface) :: umat
#endif
    pu => null()
    pm => null()
    source = ''
#ifdef LDFCZ_HAVE_UMAT
    ! the Leonov-Eyring UMAT of the paper's coating (docs/umat.md)
    if (kind == 'UMAT' .and. name == 'LEONOV') then
      pm => umat
      source = 'umat/umat.f'
    end if
#endif
#ifdef LDFCZ_HAVE_UEL
    ! the LDF cohesive user element of the paper's interface (docs/uel.md)
    if (kind == 'UEL' .and. name == 'LDF') then
      pu => uel
      source = 'uel/uel.f'
    end if
#endif
  end subroutine builtin_routine

  !> Names of the built-in routines of a kind, comma-separated ('none' when none was built).
  module function builtin_names(kind) result(names)
    character(len=*), intent(in) :: kind  !< 'UMAT' or 'UEL'
    character(len=:), allocatable :: names
    names = 'none'
#ifdef LDFCZ_HAVE_UMAT
    if (kind == 'UMAT') names = 'LEONOV'
#endif
#ifdef LDFCZ_HAVE_UEL
    if (kind == 'UEL') names = 'LDF'
#endif
  end function builtin_names

  !> Points r at the default built-in UEL and UMAT (LDF and LEONOV; null when not built): for programs that drive
  !> the element loop without a deck's declarations (tests).
  module subroutine user_routines_builtin(r)
    type(user_routines_t), intent(inout) :: r  !< routines
    character(len=:), allocatable :: source
    procedure(uel_interface), pointer :: pu, pu_unused
    procedure(umat_interface), pointer :: pm, pm_unused
    call builtin_routine('UEL', 'LDF', pu, pm_unused, source)
    r%uel => pu
    r%uel_origin = 'none'
    if (len(source) > 0) r%uel_origin = 'built-in UEL LDF ('//source//')'
    call builtin_routine('UMAT', 'LEONOV', pu_unused, pm, source)
    r%umat => pm
    r%umat_origin = 'none'
    if (len(source) > 0) r%umat_origin = 'built-in UMAT LEONOV ('//source//')'
  end subroutine user_routines_builtin

end submodule builtin_routines
