!> ldfcz_doc_tables: the documentation's tables written from the declarations they document, so that the two
!> cannot disagree (tests/regression/check_doc_tables.py compares them with docs/, and rewrites them with --write).
!>   ldfcz_doc_tables elements       the element type table of docs/elements.md (element_catalog)
!>   ldfcz_doc_tables element-list   one line per type: name, nodes, dimension, VTK cell (for test scripts)
!>   ldfcz_doc_tables outputs        the output-variable table of docs/host.md (output_registry)
program ldfcz_doc_tables
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use element_catalog, only: element_types, element_families, element_ndi, element_nshr, element_nnode, &
    element_ndim, element_vtk_cell, element_rule_text, element_kinematics_text
  use output_registry, only: output_variable_t, output_variables, output_provider_text, LOC_NODE, LOC_POINT, LOC_ELEMENT, &
    LOC_NODAL, VTU_ALWAYS, VTU_REQUESTED
  implicit none
  character(len=32) :: what
  integer :: k

  call get_command_argument(1, what)
  select case (what)
  case ('elements')
    write (output_unit, '(a)') '| type | nodes | integration points | kinematics | NDI, NSHR (NTENS) | faces | '// &
      'VTK cell | formulation |'
    write (output_unit, '(a)') '|---|---|---|---|---|---|---|---|'
    do k = 1, size(element_types)
      write (output_unit, '(a)') element_row(k)
    end do
  case ('element-list')
    do k = 1, size(element_types)
      write (output_unit, '(a,3(1x,i0))') trim(element_types(k)%name), element_nnode(k), element_ndim(k), &
        element_vtk_cell(k)
    end do
  case ('outputs')
    write (output_unit, '(a)') '| variable | components | location | units | meaning | provided by | JOB.csv | '// &
      'JOB.dat | VTU frames |'
    write (output_unit, '(a)') '|---|---|---|---|---|---|---|---|---|'
    do k = 1, size(output_variables)
      write (output_unit, '(a)') output_row(k)
    end do
  case default
    write (error_unit, '(a)') 'usage: ldfcz_doc_tables elements | element-list | outputs'
    error stop 2
  end select

contains

  !> One row of the element table.
  function element_row(k) result(row)
    integer, intent(in) :: k
    character(len=:), allocatable :: row
    row = '| '//trim(element_types(k)%name)//' | '//itoa(element_nnode(k))//' | '//element_rule_text(k)//' | '// &
      element_kinematics_text(k)//' | '//itoa(element_ndi(k))//', '//itoa(element_nshr(k))//' ('// &
      itoa(element_ndi(k) + element_nshr(k))//') | '//faces_text(element_types(k)%family)//' | '// &
      itoa(element_vtk_cell(k))//' ('//vtk_name(element_vtk_cell(k))//') | '// &
      trim(element_types(k)%formulation)//' |'
  end function element_row

  !> One row of the output-variable table.
  function output_row(v) result(row)
    integer, intent(in) :: v
    character(len=:), allocatable :: row, name, comps, loc, vtu
    type(output_variable_t) :: ov
    ov = output_variables(v)
    name = '(written unasked)'
    if (len_trim(ov%key) > 0) name = '`'//trim(ov%key)//'`'
    if (len_trim(ov%aliases) > 0) name = name//' (alias `'//trim(ov%aliases)//'`)'
    comps = trim(ov%components)
    if (len(comps) == 0) comps = '-'
    select case (ov%location)
    case (LOC_NODE)
      loc = 'node'
    case (LOC_POINT)
      loc = 'integration point'
    case (LOC_ELEMENT)
      loc = 'element'
    case (LOC_NODAL)
      loc = 'node (averaged)'
    case default
      loc = 'user-element SVARS'
    end select
    select case (ov%vtu_mode)
    case (VTU_ALWAYS)
      vtu = '`'//trim(ov%vtu)//'` (every frame)'
      if (len_trim(ov%vtu) == 0) vtu = 'the points'
    case (VTU_REQUESTED)
      vtu = '`'//trim(ov%vtu)//'` (when requested)'
      if (trim(ov%components) == 'SDVn') vtu = '`SDV<n>` (when requested; the first 3 when no variable is named)'
      if (ov%follows > 0) vtu = '`'//trim(ov%vtu)//'` (when `'//trim(output_variables(ov%follows)%key)//'` is requested)'
    case default
      vtu = '-'
    end select
    row = '| '//name//' | '//comps//' | '//loc//' | '//trim(ov%units)//' | '//trim(ov%meaning)//' | '// &
      output_provider_text(v)//' | '//yes_no(ov%csv)//' | '//yes_no(ov%dat)//' | '//vtu//' |'
  end function output_row

  function yes_no(b) result(t)
    logical, intent(in) :: b
    character(len=:), allocatable :: t
    t = 'no'
    if (b) t = 'yes'
  end function yes_no

  !> The faces of a family: 'S1..S6: 4 nodes', 'S1..S2: 3 nodes, S3..S5: 4 nodes'.
  function faces_text(f) result(t)
    integer, intent(in) :: f
    character(len=:), allocatable :: t
    integer :: a, b
    t = ''
    a = 1
    do while (a <= element_families(f)%nface)
      b = a
      do while (b < element_families(f)%nface)
        if (element_families(f)%face_nnode(b + 1) /= element_families(f)%face_nnode(a)) exit
        b = b + 1
      end do
      if (len(t) > 0) t = t//', '
      t = t//'S'//itoa(a)
      if (b > a) t = t//'..S'//itoa(b)
      t = t//': '//itoa(element_families(f)%face_nnode(a))//' nodes'
      a = b + 1
    end do
  end function faces_text

  !> VTK's name of the cell types the catalogue uses.
  function vtk_name(c) result(t)
    integer, intent(in) :: c
    character(len=:), allocatable :: t
    select case (c)
    case (5)
      t = 'VTK_TRIANGLE'
    case (9)
      t = 'VTK_QUAD'
    case (10)
      t = 'VTK_TETRA'
    case (12)
      t = 'VTK_HEXAHEDRON'
    case (13)
      t = 'VTK_WEDGE'
    case (22)
      t = 'VTK_QUADRATIC_TRIANGLE'
    case (23)
      t = 'VTK_QUADRATIC_QUAD'
    case (24)
      t = 'VTK_QUADRATIC_TETRA'
    case (25)
      t = 'VTK_QUADRATIC_HEXAHEDRON'
    case (26)
      t = 'VTK_QUADRATIC_WEDGE'
    case default
      t = '?'
    end select
  end function vtk_name

  function itoa(i) result(t)
    integer, intent(in) :: i
    character(len=:), allocatable :: t
    character(len=16) :: b
    write (b, '(i0)') i
    t = trim(b)
  end function itoa

end program ldfcz_doc_tables
