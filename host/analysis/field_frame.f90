!> One VTU frame of the converged state: the arrays of the output registry (host/output/output_registry.f90) that
!> the model provides and the step's field request asks for (docs/host.md, "Output variables"): displacements and
!> reactions at the points; element label, mean stress with its principal values and von Mises stress, the
!> requested strain and state variables of the continuum elements, and their stress and strain extrapolated to the
!> nodes and averaged there (S_nodal, LE_nodal: point_extrapolation); for user elements the cohesive flag, the
!> geometric opening and the SVARS their '**LDFCZ SVARS' line declares, and the damage. A model with continuum and
!> user elements gets two blocks, the continuum and the interface (output_registry's output_block says which array
!> goes where; the points' arrays, the label and the cohesive flag are in both). An array is written when some
!> element or routine of the model provides it (decided for the whole model, so that every piece of an MPI frame has
!> the same arrays); a cell whose element does not provide it holds 0.
module field_frame
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t, etype_user, model_sdv_name, model_elements_leave
  use element_catalog, only: element_vtk_cell, element_vtk_points, element_tensor6, element_types
  use point_extrapolation, only: point_to_node_matrix
  use output_registry, only: output_variables, output_max_statev, output_component_name, output_block, OV_COORD, &
    OV_U, OV_RF, OV_ELEMENT, OV_S, OV_SP, OV_MISES, OV_LE, OV_E, OV_SDV, OV_COHESIVE, OV_OPENING, OV_TRACTION, &
    OV_DELTA_MAX, OV_S_NODAL, OV_LE_NODAL, OV_DAMAGE, OV_STATUS, PROV_ACTIVITY, &
    LOC_NODE, LOC_NODAL, PROV_CONTINUUM, PROV_STATEV, PROV_USER, &
    PROV_USER_OPENING, PROV_SVARS_TRACTION, PROV_SVARS_DELTA_MAX, PROV_SVARS_DAMAGE, VTU_NONE, VTU_REQUESTED, &
    BLOCK_BOTH, BLOCK_CONTINUUM, BLOCK_INTERFACE
  use stress_measures, only: mises_stress, principal_stresses
  use analysis_core, only: analysis_t
  use node_rotations, only: node_vector_global
  use parallel_context, only: parallel_t, parallel_sum
  use output_files, only: output_t, output_vtu_frame, output_vtu_t, output_vtu_array_t
  implicit none
  private
  public :: write_field_frame, field_frame_blocks

  integer, parameter :: n_sdv_default = 3       !< state variables written when the request names no variable

contains

  !> Blocks of the model's frames: 2 (continuum and interface) when it has continuum and user elements, else 1.
  pure integer function field_frame_blocks(model) result(n)
    type(model_t), intent(in) :: model  !< the model
    n = 1
    if (any(model%elem_kind(1:model%nelem) == etype_user) .and. any(model%elem_kind(1:model%nelem) /= etype_user)) &
      n = 2
  end function field_frame_blocks

  !> The frame of the converged state of an at total time ttot.
  subroutine write_field_frame(out, model, an, ttot, step)
    type(output_t), intent(inout) :: out           !< output files
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< converged state
    real(dp), intent(in) :: ttot                   !< total time of the frame
    type(step_t), intent(in) :: step               !< the step whose field request applies
    type(output_vtu_t), allocatable :: fr(:)
    type(output_vtu_array_t), allocatable :: nodal(:)
    integer :: ie, nb, b, v
    logical :: user
    nb = field_frame_blocks(model)
    allocate (fr(nb))
    ! the nodal averages sum over every process's elements: every process computes them (parallel_sum)
    allocate (nodal(0))
    do v = OV_S_NODAL, OV_LE_NODAL
      if (in_frame(model, step, v)) nodal = [nodal, nodal_array(model, an, v)]
    end do
    do b = 1, nb
      ! the cells of this process's elements (every element in a one-process run) of the block: an MPI run writes
      ! one piece per process and block, rank 0 the .pvtu listing them (output_vtu_frame)
      user = b == 2 .or. (nb == 1 .and. any(model%elem_kind(1:model%nelem) == etype_user))
      call frame_block(model, an, step, pack([(ie, ie = 1, model%nelem)], an%owned .and. &
        (model%elem_kind(1:model%nelem) == etype_user .eqv. user)), merge(0, merge(BLOCK_INTERFACE, &
        BLOCK_CONTINUUM, user), nb == 1), nodal, fr(b))
    end do
    call output_vtu_frame(out, fr, ttot, an%par%rank, an%par%nranks)
  end subroutine write_field_frame

  !> One block of a frame: the cells of the elements cells, every point, the arrays of the block (blk: BLOCK_*; 0
  !> for the one block of a model of one kind, which holds every array) with the nodal averages computed before.
  subroutine frame_block(model, an, step, cells, blk, nodal, fr)
    type(model_t), intent(in) :: model             !< the model
    type(analysis_t), intent(in) :: an             !< converged state
    type(step_t), intent(in) :: step               !< field request
    integer, intent(in) :: cells(:)                !< element of each cell
    integer, intent(in) :: blk                     !< the block (0: the only one)
    type(output_vtu_array_t), intent(in) :: nodal(:) !< S_nodal, LE_nodal (those in the frame)
    type(output_vtu_t), intent(out) :: fr          !< the block
    integer :: ie, nn, c, v, k, ncell
    integer, allocatable :: sdv(:)
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
      if (blk /= 0 .and. output_block(v) /= BLOCK_BOTH .and. output_block(v) /= blk) cycle
      if (output_variables(v)%location == LOC_NODE) then
        fr%points = [fr%points, node_array(model, an, v)]
      else if (output_variables(v)%location == LOC_NODAL) then
        do k = 1, size(nodal)
          if (nodal(k)%name == output_variables(v)%vtu) fr%points = [fr%points, nodal(k)]
        end do
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
    if (in_frame(model, step, OV_MISES) .and. blk /= BLOCK_INTERFACE) fr%scalars = output_variables(OV_MISES)%vtu
    if (blk == BLOCK_INTERFACE .and. in_frame(model, step, OV_DAMAGE)) fr%scalars = output_variables(OV_DAMAGE)%vtu
  end subroutine frame_block

  !> S_nodal or LE_nodal: the stress (strain, tensor shears) of the points of every continuum element extrapolated
  !> to its nodes (point_extrapolation) and averaged over the elements at each node, in VTK's component order; 0 at
  !> a node of no continuum element. Summed over the processes (every process takes part).
  function nodal_array(model, an, v) result(a)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: v              !< OV_S_NODAL or OV_LE_NODAL
    type(output_vtu_array_t) :: a
    type :: matrix_t
      real(dp), allocatable :: e(:, :)
    end type matrix_t
    type(matrix_t), allocatable :: ext(:)
    real(dp), allocatable :: sums(:), pts(:, :), q(:)
    real(dp) :: t6(6)
    type(parallel_t) :: par
    integer :: ie, ip, nn, nip, k, node, kind, stat
    character(len=8) :: names(6)
    a%name = output_variables(v)%vtu
    a%ncomp = 6
    read (output_variables(v)%vtu_components, *) names
    a%comp_names = names
    allocate (ext(size(element_types)), sums(7 * model%nnode), a%v(6, model%nnode))
    sums = 0.0_dp
    do ie = 1, model%nelem
      kind = model%elem_kind(ie)
      if (kind == etype_user .or. .not. an%owned(ie)) cycle
      if (size(an%state%active) > 0) then
        if (.not. an%state%active(ie)) cycle   ! removed or deleted: no stress to average in
      end if
      if (.not. allocated(ext(kind)%e)) then
        call point_to_node_matrix(kind, ext(kind)%e, stat)
        if (stat /= 0) cycle
      end if
      nip = size(an%state%conv(ie)%stress, 2)
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      if (size(ext(kind)%e, 1) /= nn .or. size(ext(kind)%e, 2) /= nip) cycle
      allocate (pts(6, nip))
      do ip = 1, nip
        if (v == OV_S_NODAL) then
          t6 = element_tensor6(kind, an%state%conv(ie)%stress(:, ip))
        else
          t6 = element_tensor6(kind, an%state%conv(ie)%stran(:, ip))
          t6(4:6) = 0.5_dp * t6(4:6)   ! engineering -> tensor shears
        end if
        pts(:, ip) = [t6(1:4), t6(6), t6(5)]   ! 11 22 33 12 13 23 -> VTK's XX YY ZZ XY YZ XZ
      end do
      do k = 1, nn
        node = model%conn(model%conn_ptr(ie) + k - 1)
        q = matmul(pts, ext(kind)%e(k, :))
        sums(7 * node - 6:7 * node - 1) = sums(7 * node - 6:7 * node - 1) + q
        sums(7 * node) = sums(7 * node) + 1.0_dp
      end do
      deallocate (pts)
    end do
    par = an%par
    call parallel_sum(par, sums)
    do node = 1, model%nnode
      a%v(:, node) = 0.0_dp
      if (sums(7 * node) > 0.0_dp) a%v(:, node) = sums(7 * node - 6:7 * node - 1) / sums(7 * node)
    end do
  end function nodal_array

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
      ! a variable written with another (LE_nodal with LE) is in the frames when that one is requested
      if (.not. any(step%field_requests(1:step%nfield_request)%var == &
          merge(output_variables(v)%follows, v, output_variables(v)%follows > 0))) return
    end if
    select case (output_variables(v)%provider)
    case (PROV_CONTINUUM, PROV_STATEV)
      in_frame = any(model%elem_kind(1:model%nelem) /= etype_user)
    case (PROV_USER)
      in_frame = any(model%elem_kind(1:model%nelem) == etype_user)
    case (PROV_ACTIVITY)
      in_frame = model_elements_leave(model)
    case (PROV_USER_OPENING)
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user .and. any(model%conn_ptr(ie + 1) - model%conn_ptr(ie) == [4, 8])) &
          in_frame = .true.
      end do
    case (PROV_SVARS_TRACTION, PROV_SVARS_DELTA_MAX, PROV_SVARS_DAMAGE)
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
      ! the damage needs Delta_max and the length scale delta
      if (v == OV_DAMAGE .and. ut%sv_length_prop > 0) p = ut%sv_delta_max
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
    a%int32 = v == OV_ELEMENT .or. v == OV_COHESIVE .or. v == OV_STATUS
    read (output_variables(v)%vtu_components, *, iostat=i) names(1:nc)
    if (len_trim(output_variables(v)%vtu_components) > 0 .and. i == 0) a%comp_names = names(1:nc)
    allocate (a%v(nc, size(cells)))
    a%v = 0.0_dp
    do c = 1, size(cells)
      ie = cells(c)
      if (v == OV_ELEMENT) then
        a%v(1, c) = model%elem_id(ie)
      else if (v == OV_STATUS) then
        a%v(1, c) = 1
        if (size(an%state%active) > 0) a%v(1, c) = merge(1, 0, an%state%active(ie))
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
        case (OV_DAMAGE)
          a%v(1, c) = damage_mean(model, an, ie)
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

  !> Mean over the points of user element ie of the damage 1 - exp(-Delta_max/delta) (the secant stiffness of the
  !> exponential law, paper Eq. 20, is exp(-Delta_max/delta) times the initial one phi/delta^2; Abaqus' SDEG of a
  !> cohesive element means the same stiffness degradation), Delta_max and delta where '**LDFCZ SVARS' declares them
  !> (DELTA MAX=, LENGTH PROPERTY=); 0 without them or with delta <= 0.
  pure real(dp) function damage_mean(model, an, ie) result(d)
    type(model_t), intent(in) :: model    !< the model
    type(analysis_t), intent(in) :: an    !< converged state
    integer, intent(in) :: ie             !< user element
    real(dp) :: delta, dmax
    integer :: ip, ipr
    d = 0.0_dp
    associate (ut => model%utypes(model%elem_utype(ie)))
      if (ut%sv_points <= 0 .or. ut%sv_delta_max <= 0 .or. ut%sv_length_prop <= 0) return
      if (size(an%state%conv(ie)%svars) < ut%sv_points * ut%sv_per_point) return
      ipr = model%elem_uelprop(ie)
      if (ipr == 0) return
      if (size(model%uelprops(ipr)%props) < ut%sv_length_prop) return
      delta = model%uelprops(ipr)%props(ut%sv_length_prop)
      if (.not. (delta > 0.0_dp)) return
      do ip = 1, ut%sv_points
        dmax = an%state%conv(ie)%svars(ut%sv_per_point * (ip - 1) + ut%sv_delta_max)
        d = d + (1.0_dp - exp(-max(dmax, 0.0_dp) / delta)) / ut%sv_points
      end do
    end associate
  end function damage_mean

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
