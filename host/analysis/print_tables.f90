!> Printed output in JOB.dat, laid out as Abaqus/Standard prints it: per printed increment a summary header, then
!> one table per *NODE PRINT request (a line per node: U, RF components) and per *EL PRINT request (a line per
!> element and integration point, one table per element type), with MAXIMUM/MINIMUM lines and their node or
!> element (SUMMARY=YES, the default) and a TOTAL line (TOTALS=YES). A request prints every FREQUENCY-th increment
!> of its step and at the step's last increment (FREQUENCY=0: never).
module print_tables
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t, node_print_t, el_print_t, etype_user
  use element_catalog, only: element_name, element_tensor6
  use output_registry, only: output_lookup, output_component_name, OV_U, OV_RF, OV_S, OV_MISES, OV_LE, OV_E, OV_SDV
  use analysis_core, only: analysis_t, element_geometry
  use node_rotations, only: node_vector_global, node_to_global
  use stress_measures, only: mises_stress
  use solid_element, only: polar_rotation, solid_geometry_t
  implicit none
  private
  public :: print_tables_any, print_tables_write, print_tables_elements

  integer, parameter :: name_w = 8  !< column heading width

contains

  !> True when some step of the model asks for printed output.
  pure logical function print_tables_any(model)
    type(model_t), intent(in) :: model  !< the model
    integer :: is
    print_tables_any = .false.
    do is = 1, model%nstep
      if (model%steps(is)%nprint + model%steps(is)%nelprint > 0) print_tables_any = .true.
    end do
  end function print_tables_any

  !> The tables of step st due at its converged increment kinc (last: the step's final increment).
  subroutine print_tables_write(u, model, an, st, kstep, kinc, step_time, total_time, dt, last)
    integer, intent(in) :: u                    !< JOB.dat unit
    type(model_t), intent(in) :: model          !< the model
    type(analysis_t), intent(in) :: an          !< converged state
    type(step_t), intent(in) :: st              !< the step
    integer, intent(in) :: kstep                !< step number
    integer, intent(in) :: kinc                 !< increment number in the step
    real(dp), intent(in) :: step_time           !< step time completed
    real(dp), intent(in) :: total_time          !< total time completed
    real(dp), intent(in) :: dt                  !< time increment completed
    logical, intent(in) :: last                 !< the step's last increment
    integer :: k
    logical :: header
    header = .false.
    do k = 1, st%nprint
      if (.not. request_due(st%prints(k)%frequency, kinc, last)) cycle
      call write_header()
      call node_table(u, model, an, st%prints(k))
    end do
    do k = 1, st%nelprint
      if (.not. request_due(st%elprints(k)%frequency, kinc, last)) cycle
      call write_header()
      call element_tables(u, model, an, st%elprints(k), st%nlgeom)
    end do
    if (header) flush (u)
  contains
    subroutine write_header()
      if (header) return
      header = .true.
      write (u, '(/,a,i6,a,i6,a,/)') '   STEP', kstep, '   INCREMENT', kinc, '   SUMMARY'
      write (u, '(a,es12.5,a,es12.5)') ' TIME INCREMENT COMPLETED ', dt, ',  FRACTION OF STEP COMPLETED ', &
        step_time / st%period
      write (u, '(a,es12.5,a,es12.5)') ' STEP TIME COMPLETED      ', step_time, ',  TOTAL TIME COMPLETED        ', &
        total_time
    end subroutine write_header
  end subroutine print_tables_write

  !> A request of print frequency freq prints at increment kinc (last: the step's final increment).
  pure logical function request_due(freq, kinc, last) result(due)
    integer, intent(in) :: freq   !< FREQUENCY (0: never)
    integer, intent(in) :: kinc   !< increment number in the step
    logical, intent(in) :: last   !< the step's last increment
    due = .false.
    if (freq <= 0) return
    due = mod(kinc, freq) == 0 .or. last
  end function request_due

  !> The elements whose converged states the *EL PRINT tables of step st due at increment kinc read (each once,
  !> ascending; continuum elements only): in a distributed run their states are gathered before rank 0 prints.
  pure function print_tables_elements(model, st, kinc, last) result(elems)
    type(model_t), intent(in) :: model  !< the model
    type(step_t), intent(in) :: st      !< the step
    integer, intent(in) :: kinc         !< increment number in the step
    logical, intent(in) :: last         !< the step's last increment
    integer, allocatable :: elems(:)
    logical, allocatable :: pick(:)
    integer :: k, ie
    allocate (pick(model%nelem))
    pick = .false.
    do k = 1, st%nelprint
      if (.not. request_due(st%elprints(k)%frequency, kinc, last)) cycle
      if (st%elprints(k)%set_index > 0) then
        pick(model%elsets(st%elprints(k)%set_index)%elems) = .true.
      else
        pick = .true.
      end if
    end do
    pick = pick .and. model%elem_kind(1:model%nelem) /= etype_user
    elems = pack([(ie, ie = 1, model%nelem)], pick)
  end function print_tables_elements

  !> One *NODE PRINT table.
  subroutine node_table(u, model, an, np)
    integer, intent(in) :: u                !< JOB.dat unit
    type(model_t), intent(in) :: model      !< the model
    type(analysis_t), intent(in) :: an      !< converged state
    type(node_print_t), intent(in) :: np    !< the request
    integer, allocatable :: nodes(:)
    real(dp), allocatable :: val(:, :)
    real(dp) :: uv(3), rv(3)
    integer :: k, j, n, nv, comp, dof, var, d
    if (np%set_index > 0) then
      nodes = model%nsets(np%set_index)%nodes
    else
      nodes = [(k, k = 1, model%nnode)]
    end if
    n = size(nodes)
    nv = size(np%vars)
    allocate (val(nv, n))
    do k = 1, n
      ! the node's U and RF in its system components (local at a *TRANSFORM node, Abaqus' GLOBAL=NO), or turned
      ! to global ones (GLOBAL=YES); RF = internal minus applied force on a prescribed dof (as JOB.csv, VTU)
      do d = 1, model%ndim
        dof = (nodes(k) - 1) * model%ndim + d
        uv(d) = an%work%u(dof)
        rv(d) = merge(an%work%fint(dof) - an%work%fext(dof) - an%work%fdl(dof), 0.0_dp, an%eqs%prescribed(dof))
      end do
      if (np%global) then
        uv(1:model%ndim) = node_to_global(an%nr, nodes(k), uv(1:model%ndim))
        rv(1:model%ndim) = node_to_global(an%nr, nodes(k), rv(1:model%ndim))
      end if
      do j = 1, nv
        val(j, k) = 0.0_dp
        ! U1..U3, RF1..RF3 (output registry; the reader keeps components within the model's dimension)
        call output_lookup(np%vars(j), var, comp)
        if (comp < 1 .or. comp > model%ndim) cycle
        if (var == OV_U) val(j, k) = uv(comp)
        if (var == OV_RF) val(j, k) = rv(comp)
      end do
    end do
    where (abs(val) < 1.0e-99_dp) val = 0.0_dp  ! two-digit exponents, as Abaqus prints them
    write (u, '(//,a,//)') '                                       N O D E   O U T P U T'
    if (np%set_index > 0) then
      write (u, '(a,/)') ' THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET '//trim(np%nset)
    else
      write (u, '(a,/)') ' THE FOLLOWING TABLE IS PRINTED FOR ALL NODES'
    end if
    write (u, '(a22,*(a15))') 'NODE FOOT-', (adjustr(np%vars(j)(1:name_w)), j = 1, nv)
    write (u, '(a22,/)') 'NOTE    '
    do k = 1, n
      write (u, '(a20,2x,*(es15.4e2))') label_text(model, model%node_id(nodes(k)), .true.), val(:, k)
    end do
    call summary_lines(u, model, val, [(model%node_id(nodes(k)), k = 1, n)], [(0, k = 1, n)], np%summary, &
      np%totals, .true., 22)
  end subroutine node_table

  !> The tables of one *EL PRINT request: one per continuum element type in the set.
  subroutine element_tables(u, model, an, ep, nlgeom)
    integer, intent(in) :: u                !< JOB.dat unit
    type(model_t), intent(in) :: model      !< the model
    type(analysis_t), intent(in) :: an      !< converged state
    type(el_print_t), intent(in) :: ep      !< the request
    logical, intent(in) :: nlgeom           !< the step's NLGEOM (local axes turn with the material)
    integer, allocatable :: elems(:), kinds(:)
    integer :: k, ik
    if (ep%set_index > 0) then
      elems = model%elsets(ep%set_index)%elems
    else
      elems = [(k, k = 1, model%nelem)]
    end if
    elems = pack(elems, model%elem_kind(elems) /= etype_user)
    allocate (kinds(0))
    do k = 1, size(elems)
      if (.not. any(kinds == model%elem_kind(elems(k)))) kinds = [kinds, model%elem_kind(elems(k))]
    end do
    do ik = 1, size(kinds)
      call element_table(u, model, an, ep, pack(elems, model%elem_kind(elems) == kinds(ik)), kinds(ik), nlgeom)
    end do
  end subroutine element_tables

  !> One table of integration-point values of elements of one type.
  subroutine element_table(u, model, an, ep, elems, kind, nlgeom)
    integer, intent(in) :: u                !< JOB.dat unit
    type(model_t), intent(in) :: model      !< the model
    type(analysis_t), intent(in) :: an      !< converged state
    type(el_print_t), intent(in) :: ep      !< the request
    integer, intent(in) :: elems(:)         !< element indices, one type
    integer, intent(in) :: kind             !< their type
    logical, intent(in) :: nlgeom           !< local axes turn with the material
    character(len=8), allocatable :: cols(:)
    real(dp), allocatable :: val(:, :)
    integer, allocatable :: lab(:), pt(:), cvar(:), ccomp(:)
    integer :: k, j, ie, ip, nrow, row, nsv_max, nsv, c, var
    real(dp) :: s6(6), sl(6), el(6), t(3, 3)
    type(solid_geometry_t) :: g
    logical :: have_geo
    ! columns: the request's variables, SDV expanded to every state variable of these elements
    nsv_max = 0
    do k = 1, size(elems)
      nsv_max = max(nsv_max, an%mats(model%elem_section(elems(k)))%nstatv)
    end do
    allocate (cols(0), cvar(0), ccomp(0))
    do j = 1, size(ep%vars)
      call output_lookup(ep%vars(j), var, c)
      if (var == OV_SDV .and. c == 0) then
        do k = 1, nsv_max
          cols = [character(len=8) :: cols, output_component_name(OV_SDV, k)]
          cvar = [cvar, OV_SDV]
          ccomp = [ccomp, k]
        end do
      else if (var == OV_SDV .and. c > nsv_max) then
        cycle  ! no element of this table has it (warned when the deck was read if none of the set has)
      else
        cols = [character(len=8) :: cols, ep%vars(j)]
        cvar = [cvar, var]
        ccomp = [ccomp, c]
      end if
    end do
    nrow = 0
    do k = 1, size(elems)
      nrow = nrow + size(an%state%conv(elems(k))%stress, 2)
    end do
    allocate (val(size(cols), nrow), lab(nrow), pt(nrow))
    val = 0.0_dp
    row = 0
    do k = 1, size(elems)
      ie = elems(k)
      have_geo = .false.
      nsv = an%mats(model%elem_section(ie))%nstatv
      do ip = 1, size(an%state%conv(ie)%stress, 2)
        row = row + 1
        lab(row) = model%elem_id(ie)
        pt(row) = ip
        ! the 6 components 11, 22, 33, 12, 13, 23 (plane stress: S33 = 0, the thickness strain not kept: 0)
        s6 = element_tensor6(kind, an%state%conv(ie)%stress(:, ip))
        sl = s6
        el = element_tensor6(kind, an%state%conv(ie)%stran(:, ip))
        if (allocated(an%axes(ie)%t)) then
          ! an *ORIENTATION: components in its local axes, as Abaqus prints them
          t = an%axes(ie)%t(:, :, ip)
          if (nlgeom) then
            if (.not. have_geo) call element_geometry(an, model, ie, g)
            have_geo = .true.
            t = matmul(polar_rotation(point_f(model, an, g, ie, ip)), t)
          end if
          sl = turned(s6, t, 1.0_dp)
          el = turned(el, t, 0.5_dp)
        end if
        do j = 1, size(cols)
          select case (cvar(j))
          case (OV_MISES)
            val(j, row) = mises_stress(s6)
          case (OV_SDV)
            if (ccomp(j) <= nsv) val(j, row) = an%state%conv(ie)%statev(ccomp(j), ip)
          case (OV_S)
            val(j, row) = sl(ccomp(j))
          case (OV_LE, OV_E)
            val(j, row) = el(ccomp(j))
          end select
        end do
      end do
    end do
    where (abs(val) < 1.0e-99_dp) val = 0.0_dp  ! two-digit exponents, as Abaqus prints them
    write (u, '(//,a,//)') '                                       E L E M E N T   O U T P U T'
    if (ep%set_index > 0) then
      write (u, '(a,/)') ' THE FOLLOWING TABLE IS PRINTED AT THE INTEGRATION POINTS FOR ELEMENT TYPE '// &
        trim(element_name(kind))//' AND ELEMENT SET '//trim(ep%elset)
    else
      write (u, '(a,/)') ' THE FOLLOWING TABLE IS PRINTED AT THE INTEGRATION POINTS FOR ELEMENT TYPE '// &
        trim(element_name(kind))
    end if
    write (u, '(a28,*(a15))') 'ELEMENT  PT FOOT-', (adjustr(cols(j)), j = 1, size(cols))
    write (u, '(a28,/)') 'NOTE    '
    do row = 1, nrow
      write (u, '(a20,i4,4x,*(es15.4e2))') label_text(model, lab(row), .false.), pt(row), val(:, row)
    end do
    call summary_lines(u, model, val, lab, pt, ep%summary, ep%totals, .false., 28)
  end subroutine element_table

  !> Components (Abaqus order, shears times shear_factor^-1 in the tensor) of a symmetric tensor in the axes t:
  !> t^T A t. shear_factor 1 for stress, 0.5 for engineering strain.
  pure function turned(v, t, shear_factor) result(w)
    real(dp), intent(in) :: v(6)            !< global components 11, 22, 33, 12, 13, 23
    real(dp), intent(in) :: t(3, 3)         !< axes as columns
    real(dp), intent(in) :: shear_factor    !< tensor shear = shear_factor x component
    real(dp) :: w(6), a(3, 3)
    a = reshape([v(1), shear_factor * v(4), shear_factor * v(5), shear_factor * v(4), v(2), shear_factor * v(6), &
      shear_factor * v(5), shear_factor * v(6), v(3)], [3, 3])
    a = matmul(matmul(transpose(t), a), t)
    w = [a(1, 1), a(2, 2), a(3, 3), a(1, 2) / shear_factor, a(1, 3) / shear_factor, a(2, 3) / shear_factor]
  end function turned

  !> Deformation gradient at integration point ip of continuum element ie in the converged state.
  function point_f(model, an, g, ie, ip) result(f)
    type(model_t), intent(in) :: model      !< the model
    type(analysis_t), intent(in) :: an      !< converged state
    type(solid_geometry_t), intent(in) :: g !< the element's reference data (element_geometry)
    integer, intent(in) :: ie               !< element
    integer, intent(in) :: ip               !< integration point
    real(dp) :: f(3, 3), ug(model%ndim)
    integer :: a, i, j, node
    f = 0.0_dp
    do i = 1, 3
      f(i, i) = 1.0_dp
    end do
    do a = 1, model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      node = model%conn(model%conn_ptr(ie) + a - 1)
      ug = node_vector_global(an%nr, an%state%u_conv, node)
      do j = 1, model%ndim
        do i = 1, model%ndim
          f(i, j) = f(i, j) + ug(i) * g%dndx_ref(a, j, ip)
        end do
      end do
    end do
  end function point_f

  !> MAXIMUM / AT NODE|ELEMENT / MINIMUM / AT ... (summary) and TOTAL (totals) lines of a table.
  subroutine summary_lines(u, model, val, lab, pt, summary, totals, is_node, w)
    integer, intent(in) :: u              !< JOB.dat unit
    type(model_t), intent(in) :: model    !< the model
    real(dp), intent(in) :: val(:, :)     !< (ncol, nrow)
    integer, intent(in) :: lab(:)         !< model label of each row
    integer, intent(in) :: pt(:)          !< integration point of each row (0 for nodes)
    logical, intent(in) :: summary        !< SUMMARY=YES
    logical, intent(in) :: totals         !< TOTALS=YES
    logical, intent(in) :: is_node        !< node table
    integer, intent(in) :: w              !< width of the label columns
    integer :: j, imax(size(val, 1)), imin(size(val, 1))
    character(len=24) :: at(size(val, 1))
    character(len=w) :: head
    if (size(val, 2) == 0) return
    if (summary) then
      do j = 1, size(val, 1)
        imax(j) = maxloc(val(j, :), dim=1)
        imin(j) = minloc(val(j, :), dim=1)
      end do
      head = ' MAXIMUM'
      write (u, '(/,a,*(es15.4e2))') head, (val(j, imax(j)), j = 1, size(val, 1))
      do j = 1, size(val, 1)
        at(j) = where_text(imax(j))
      end do
      head = merge(' AT NODE   ', ' AT ELEMENT', is_node)
      write (u, '(a,*(a15))') head, (adjustr(at(j)(1:15)), j = 1, size(val, 1))
      head = ' MINIMUM'
      write (u, '(/,a,*(es15.4e2))') head, (val(j, imin(j)), j = 1, size(val, 1))
      do j = 1, size(val, 1)
        at(j) = where_text(imin(j))
      end do
      head = merge(' AT NODE   ', ' AT ELEMENT', is_node)
      write (u, '(a,*(a15))') head, (adjustr(at(j)(1:15)), j = 1, size(val, 1))
    end if
    head = ' TOTAL'
    if (totals) write (u, '(/,a,*(es15.4e2))') head, merge(0.0_dp, sum(val, dim=2), abs(sum(val, dim=2)) < 1.0e-99_dp)
  contains
    function where_text(row) result(t)
      integer, intent(in) :: row
      character(len=24) :: t
      character(len=8) :: b
      t = adjustl(label_text(model, lab(row), is_node))
      if (pt(row) > 0) then
        write (b, '(i0)') pt(row)
        t = trim(t)//'-'//trim(b)
      end if
      ! the tail fits the 15-character column
      if (len_trim(t) > 14) t = t(len_trim(t) - 13:)
    end function where_text
  end subroutine summary_lines

  !> A label as printed: 'INSTANCE.label' for a part instance's node or element, the model label otherwise.
  function label_text(model, id, is_node) result(t)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: id           !< model label
    logical, intent(in) :: is_node      !< node (true) or element
    character(len=20) :: t
    character(len=40) :: b
    integer :: k, local
    write (b, '(i0)') id
    do k = 1, model%ninstance
      associate (in => model%instances(k))
        if (is_node) then
          if (id <= in%node_offset .or. id > in%node_last) cycle
          local = id - in%node_offset
        else
          if (id <= in%elem_offset .or. id > in%elem_last) cycle
          local = id - in%elem_offset
        end if
        write (b, '(i0)') local
        b = trim(in%name)//'.'//trim(b)
        exit
      end associate
    end do
    t = b(max(1, len_trim(b) - 19):len_trim(b))
    t = adjustr(t)
  end function label_text

end module print_tables
