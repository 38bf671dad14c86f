!> One VTU frame of the converged state: the arrays of the output registry (host/output/output_registry.f90) that
!> the model provides and the step's field request asks for (docs/host.md, "Output variables"): displacements and
!> reactions at the points; element label, mean stress with its principal values and von Mises stress, the
!> requested strain and state variables of the continuum elements; for user elements the cohesive flag, the
!> geometric opening and the SVARS their '**LDFCZ SVARS' line declares. An array is written when some element or
!> routine of the model provides it (decided for the whole model, so that every piece of an MPI frame has the same
!> arrays); a cell whose element does not provide it holds 0.
module field_frame
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t, etype_user, model_sdv_name
  use element_catalog, only: element_vtk_cell, element_vtk_points, element_tensor6
  use output_registry, only: output_variables, output_max_statev, output_component_name, OV_COORD, OV_U, OV_RF, OV_ELEMENT, &
    OV_S, OV_SP, OV_MISES, OV_LE, OV_E, OV_SDV, OV_COHESIVE, OV_OPENING, OV_TRACTION, OV_DELTA_MAX, LOC_NODE, &
    PROV_CONTINUUM, PROV_STATEV, PROV_USER, PROV_USER_OPENING, PROV_SVARS_TRACTION, PROV_SVARS_DELTA_MAX, &
    VTU_NONE, VTU_REQUESTED
  use stress_measures, only: mises_stress, principal_stresses
  use analysis_core, only: analysis_t
  use node_rotations, only: node_vector_global
  use output_files, only: output_t, output_vtu_frame, output_vtu_t, output_vtu_array_t
  implicit none
  private
  public :: write_field_frame

  integer, parameter :: n_sdv_default = 3       !< state variables written when the request names no variable

contains

  !> The frame of the converged state of an at total time ttot.
  subroutine write_field_frame(out, model, an, ttot, step)
    type(output_t), intent(inout) :: out           !< output files
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< converged state
    real(dp), intent(in) :: ttot                   !< total time of the frame
    type(step_t), intent(in) :: step               !< the step whose field request applies
    type(output_vtu_t) :: fr
    integer :: ie, nn, c, v, k, ncell
    integer, allocatable :: cells(:), sdv(:)
    ! the cells of this process's elements (every element in a one-process run): an MPI run writes one piece per
    ! process and rank 0 the .pvtu listing them (output_vtu_frame)
    cells = pack([(ie, ie = 1, model%nelem)], an%owned)
    ncell = size(cells)
    fr%x = model%x
    allocate (fr%cell_type(ncell), fr%cell_ptr(ncell + 1))
    fr%cell_ptr(1) = 1
    do c = 1, ncell
      fr%cell_ptr(c + 1) = fr%cell_ptr(c) + model%conn_ptr(cells(c) + 1) - model%conn_ptr(cells(c))
    end do
    allocate (fr%cell_conn(fr%cell_ptr(ncell + 1) - 1))
    do c = 1, ncell
      ie = cells(c)
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      ! the element's nodes in VTK's point order (element_catalog; a user element's as given)
      fr%cell_conn(fr%cell_ptr(c):fr%cell_ptr(c + 1) - 1) = &
        model%conn(model%conn_ptr(ie) - 1 + element_vtk_points(model%elem_kind(ie), nn)) - 1
      ! VTK cell types of the catalogue; a user element: hexahedron (8 nodes, COH3D8 layout), quadrilateral (4)
      fr%cell_type(c) = element_vtk_cell(model%elem_kind(ie))
      if (model%elem_kind(ie) == etype_user) then
        if (nn == 8) then
          fr%cell_type(c) = 12
        else if (nn == 4) then
          fr%cell_type(c) = 9
        else
          fr%cell_type(c) = 2  ! poly-vertex for other user elements
        end if
      end if
    end do
    allocate (fr%points(0), fr%cells(0))
    do v = 1, size(output_variables)
      if (v == OV_COORD .or. .not. in_frame(model, step, v)) cycle
      if (output_variables(v)%location == LOC_NODE) then
        fr%points = [fr%points, node_array(model, an, v)]
      else if (v == OV_SDV) then
        sdv = sdv_selection(model, step)
        do k = 1, size(sdv)
          fr%cells = [fr%cells, cell_array(model, an, cells, v, sdv(k))]
        end do
      else
        fr%cells = [fr%cells, cell_array(model, an, cells, v, 0)]
      end if
    end do
    if (in_frame(model, step, OV_U)) fr%vectors = output_variables(OV_U)%vtu
    if (in_frame(model, step, OV_MISES)) fr%scalars = output_variables(OV_MISES)%vtu
    call output_vtu_frame(out, fr, ttot, an%par%rank, an%par%nranks)
  end subroutine write_field_frame

  !> Variable v is in the frames of this model and step: the registry writes it in frames, some element or routine
  !> of the model provides it, and (VTU_REQUESTED) the field request names it.
  pure logical function in_frame(model, step, v)
    type(model_t), intent(in) :: model  !< the model
    type(step_t), intent(in) :: step    !< field request
    integer, intent(in) :: v            !< OV_*
    integer :: ie
    in_frame = .false.
    if (output_variables(v)%vtu_mode == VTU_NONE) return
    if (output_variables(v)%vtu_mode == VTU_REQUESTED .and. v /= OV_SDV) then
      if (step%nfield_request == 0) return
      if (.not. any(step%field_requests(1:step%nfield_request)%var == v)) return
    end if
    select case (output_variables(v)%provider)
    case (PROV_CONTINUUM, PROV_STATEV)
      in_frame = any(model%elem_kind(1:model%nelem) /= etype_user)
    case (PROV_USER)
      in_frame = any(model%elem_kind(1:model%nelem) == etype_user)
    case (PROV_USER_OPENING)
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user .and. any(model%conn_ptr(ie + 1) - model%conn_ptr(ie) == [4, 8])) &
          in_frame = .true.
      end do
    case (PROV_SVARS_TRACTION, PROV_SVARS_DELTA_MAX)
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user) then
          if (svars_position(model, ie, v) > 0) in_frame = .true.
        end if
      end do
    case default
      in_frame = .true.
    end select
  end function in_frame

  !> Position within a point's SVARS block of variable v (traction, Delta_max) for user element ie, as its type's
  !> '**LDFCZ SVARS' line declares it (0: not declared).
  pure integer function svars_position(model, ie, v) result(p)
    type(model_t), intent(in) :: model
    integer, intent(in) :: ie, v
    p = 0
    associate (ut => model%utypes(model%elem_utype(ie)))
      if (ut%sv_points <= 0) return
      if (v == OV_TRACTION) p = ut%sv_traction
      if (v == OV_DELTA_MAX) p = ut%sv_delta_max
    end associate
  end function svars_position

  !> A point array: U or RF in global components (also at *TRANSFORM nodes: the frames show the deformed shape).
  function node_array(model, an, v) result(a)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: v              !< OV_U or OV_RF
    type(output_vtu_array_t) :: a
    real(dp), allocatable :: rf(:)
    integer :: k
    a%name = output_variables(v)%vtu
    a%ncomp = 3
    allocate (a%v(3, model%nnode))
    a%v = 0.0_dp
    if (v == OV_RF) then
      ! reaction = internal minus applied (concentrated and distributed) force on a prescribed dof
      rf = merge(an%work%fint - an%work%fext - an%work%fdl, 0.0_dp, an%eqs%prescribed)
      do k = 1, model%nnode
        a%v(1:model%ndim, k) = node_vector_global(an%nr, rf, k)
      end do
    else
      do k = 1, model%nnode
        a%v(1:model%ndim, k) = node_vector_global(an%nr, an%state%u_conv, k)
      end do
    end if
  end function node_array

  !> A cell array of variable v (sdv: the state variable of an SDV array) over the cells; 0 in cells whose element
  !> does not provide it. Tensors in VTK's order XX, YY, ZZ, XY, YZ, XZ (strains with tensor shears).
  function cell_array(model, an, cells, v, sdv) result(a)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: cells(:)       !< element of each cell
    integer, intent(in) :: v              !< OV_*
    integer, intent(in) :: sdv            !< state variable number (SDV)
    type(output_vtu_array_t) :: a
    character(len=8) :: names(6)
    integer :: c, ie, nc, i
    real(dp) :: s(6), e(6), p(3)
    a%name = output_variables(v)%vtu
    ! named state variables (*DEPVAR keys, Abaqus/CAE) give their arrays Abaqus' names SDV_key
    if (v == OV_SDV) a%name = model_sdv_name(model, sdv)
    nc = output_variables(v)%vtu_ncomp
    a%ncomp = nc
    a%int32 = v == OV_ELEMENT .or. v == OV_COHESIVE
    read (output_variables(v)%vtu_components, *, iostat=i) names(1:nc)
    if (len_trim(output_variables(v)%vtu_components) > 0 .and. i == 0) a%comp_names = names(1:nc)
    allocate (a%v(nc, size(cells)))
    a%v = 0.0_dp
    do c = 1, size(cells)
      ie = cells(c)
      if (v == OV_ELEMENT) then
        a%v(1, c) = model%elem_id(ie)
      else if (model%elem_kind(ie) == etype_user) then
        select case (v)
        case (OV_COHESIVE)
          a%v(1, c) = 1
        case (OV_OPENING)
          ! opening = top - bottom (COH3D8: node k+4 over k; COH2D4: 4 over 1, 3 over 2)
          i = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
          if (i == 8 .or. i == 4) call cell_opening(model, an, ie, i, a%v(:, c))
        case (OV_TRACTION, OV_DELTA_MAX)
          a%v(1, c) = svars_mean(model, an, ie, svars_position(model, ie, v))
        end select
      else
        call point_means(model, an, ie, s, e)
        select case (v)
        case (OV_S)
          a%v(:, c) = [s(1:4), s(6), s(5)]
        case (OV_SP)
          call principal_stresses(s, p)
          a%v(:, c) = [p(3), p(2), p(1)]
        case (OV_MISES)
          a%v(1, c) = mises_stress(s)
        case (OV_LE, OV_E)
          ! engineering -> tensor shears
          a%v(:, c) = [e(1:3), 0.5_dp * e(4), 0.5_dp * e(6), 0.5_dp * e(5)]
        case (OV_SDV)
          ! the material's STATEV (the rows after them are the element's own: incompatible modes, hourglass)
          if (sdv <= an%mats(model%elem_section(ie))%nstatv) &
            a%v(1, c) = sum(an%state%conv(ie)%statev(sdv, :)) / size(an%state%conv(ie)%statev, 2)
        end select
      end if
    end do
  end function cell_array

  !> Mean over the points of stress and strain of continuum element ie, as 6 components 11, 22, 33, 12, 13, 23
  !> (plane stress: sigma33 = 0 and the thickness strain, not kept, 0).
  subroutine point_means(model, an, ie, s, e)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: ie             !< element
    real(dp), intent(out) :: s(6), e(6)   !< mean stress, mean strain (engineering shears)
    real(dp) :: sm(6), em(6)
    integer :: nip, nt, ip
    nip = size(an%state%conv(ie)%stress, 2)
    nt = size(an%state%conv(ie)%stress, 1)
    sm = 0.0_dp
    em = 0.0_dp
    do ip = 1, nip
      sm(1:nt) = sm(1:nt) + an%state%conv(ie)%stress(:, ip) / nip
      em(1:nt) = em(1:nt) + an%state%conv(ie)%stran(:, ip) / nip
    end do
    s = element_tensor6(model%elem_kind(ie), sm(1:nt))
    e = element_tensor6(model%elem_kind(ie), em(1:nt))
  end subroutine point_means

  !> Mean over the points of the SVARS entry at position pos of each point's block of user element ie.
  pure real(dp) function svars_mean(model, an, ie, pos) result(m)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: ie             !< user element
    integer, intent(in) :: pos            !< position within a point's block (0: not declared)
    integer :: ip
    m = 0.0_dp
    if (pos <= 0) return
    associate (ut => model%utypes(model%elem_utype(ie)))
      if (size(an%state%conv(ie)%svars) < ut%sv_points * ut%sv_per_point) return
      do ip = 1, ut%sv_points
        m = m + an%state%conv(ie)%svars(ut%sv_per_point * (ip - 1) + pos) / ut%sv_points
      end do
    end associate
  end function svars_mean

  !> The state variables a frame holds: every one (SDV requested), the listed ones (SDVn), the first three when the
  !> request names no variable at all (the frames of earlier versions), none otherwise; never beyond the largest
  !> NSTATV of the model's materials (a request beyond it is warned about when the deck is read).
  pure function sdv_selection(model, step) result(idx)
    type(model_t), intent(in) :: model           !< the model
    type(step_t), intent(in) :: step             !< field request
    integer, allocatable :: idx(:)               !< state-variable numbers, ascending, no repeats
    integer :: nmax, k
    logical, allocatable :: pick(:)
    ! every continuum element of the model, not only this process's, so that every piece has the same arrays
    nmax = output_max_statev(model)
    allocate (pick(nmax))
    pick = .false.
    if (.not. step%field_vars_named) pick(1:min(n_sdv_default, nmax)) = .true.
    do k = 1, step%nfield_request
      if (step%field_requests(k)%var /= OV_SDV) cycle
      if (step%field_requests(k)%comp == 0) then
        pick = .true.
      else if (step%field_requests(k)%comp <= nmax) then
        pick(step%field_requests(k)%comp) = .true.
      end if
    end do
    idx = pack([(k, k = 1, nmax)], pick)
  end function sdv_selection

  !> Mean opening (top - bottom face displacement) of cohesive element ie with nn nodes.
  subroutine cell_opening(model, an, ie, nn, op)
    type(model_t), intent(in) :: model     !< the model
    type(analysis_t), intent(in) :: an     !< converged state
    integer, intent(in) :: ie, nn          !< element index and node count
    real(dp), intent(out) :: op(3)         !< mean opening
    integer :: k, nb, nt
    op = 0.0_dp
    do k = 1, nn / 2
      nb = model%conn(model%conn_ptr(ie) + k - 1)
      if (nn == 8) then
        nt = model%conn(model%conn_ptr(ie) + k + 3)
      else
        nt = model%conn(model%conn_ptr(ie) + 4 - k)
      end if
      op(1:model%ndim) = op(1:model%ndim) + (node_vector_global(an%nr, an%state%u_conv, nt) - &
        node_vector_global(an%nr, an%state%u_conv, nb)) / (nn / 2)
    end do
  end subroutine cell_opening

end module field_frame
