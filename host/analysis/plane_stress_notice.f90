!> The run's warning for plane-stress elements with a UMAT under NLGEOM (docs/elements.md "Plane stress"): the
!> element gives the UMAT F33 = 1 / det(F_2D) and follows that thickness, an **inferred** Abaqus behaviour; a
!> compressible material's own thickness change is not represented. One line per section concerned.
module plane_stress_notice
  use model_types, only: model_t
  use element_catalog, only: element_types, element_is_plane_stress
  use analysis_core, only: analysis_t
  use solid_element, only: SOLID_MAT_UMAT
  implicit none
  private
  public :: plane_stress_umat_warnings

contains

  !> Warning lines (none when no step has NLGEOM or no plane-stress element has a UMAT section).
  subroutine plane_stress_umat_warnings(model, an, lines)
    type(model_t), intent(in) :: model                      !< the model
    type(analysis_t), intent(in) :: an                      !< analysis data (materials per section)
    character(len=512), allocatable, intent(out) :: lines(:) !< the warnings
    character(len=:), allocatable :: types
    integer :: is, k
    allocate (lines(0))
    if (model%nstep == 0 .or. model%nsection == 0) return
    if (.not. any(model%steps(1:model%nstep)%nlgeom)) return
    do is = 1, model%nsection
      if (an%mats(is)%kind /= SOLID_MAT_UMAT) cycle
      types = ''
      do k = 1, size(element_types)
        if (.not. element_is_plane_stress(k)) cycle
        if (any(model%elem_kind(1:model%nelem) == k .and. model%elem_section(1:model%nelem) == is)) &
          types = types//' '//trim(element_types(k)%name)
      end do
      if (len(types) == 0) cycle
      lines = [character(len=512) :: lines, 'ldfcz: warning: element set '//trim(model%sections(is)%elset)// &
        ' (plane stress:'//types//') with a UMAT under NLGEOM: the UMAT gets DFGRD1(3,3) = F33 = 1/det(F_2D) '// &
        'and the element thickness follows t = t0 F33 (J = 1), as Abaqus is reported to do (inferred, '// &
        'docs/elements.md); a compressible material''s own thickness change is not represented']
    end do
  end subroutine plane_stress_umat_warnings

end module plane_stress_notice
