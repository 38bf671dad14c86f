!> One VTU frame of the converged state: displacements, reactions, element mean stress with its principal values and
!> von Mises stress, the requested strain and state variables (the step's field request), and for the cohesive
!> elements opening, traction and largest opening (docs/host.md, "Outputs").
module field_frame
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, step_t, etype_user, etype_c3d8, etype_cpe4, etype_c3d8i, etype_c3d20, &
    etype_c3d20r, etype_c3d4, etype_c3d10, etype_cpe4i, etype_cpe8, etype_cpe8r, etype_cps4, etype_cps4i, &
    etype_cps8, etype_cps8r, etype_c3d8r, etype_cpe4r, etype_cps4r, etype_cax4, etype_cax4i, etype_cax8, etype_cax8r, &
    etype_cax4r, model_sdv_name
  use stress_measures, only: mises_stress, principal_stresses
  use analysis_core, only: analysis_t
  use node_rotations, only: node_vector_global
  use output_files, only: output_t, output_vtu_frame, output_vtu_t
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
    integer :: ie, nn, k, ncell, nip, ip, nsv, nt, c
    integer, allocatable :: cells(:)
    real(dp) :: s(6), e(6), p(3)
    real(dp), allocatable :: rf(:)
    logical :: want_strain
    ! the cells of this process's elements (every element in a one-process run): an MPI run writes one piece per
    ! process and rank 0 the .pvtu listing them (output_vtu_frame)
    cells = pack([(ie, ie = 1, model%nelem)], an%owned)
    ncell = size(cells)
    allocate (fr%x(3, model%nnode), fr%u(3, model%nnode), fr%rf(3, model%nnode))
    fr%x = model%x
    fr%u = 0.0_dp
    fr%rf = 0.0_dp
    ! reaction = internal minus applied (concentrated and distributed) force on a prescribed dof
    rf = merge(an%fint - an%fext - an%fdl, 0.0_dp, an%prescribed)
    do k = 1, model%nnode
      ! global components also at *TRANSFORM nodes (the frames show the deformed shape)
      fr%u(1:model%ndim, k) = node_vector_global(an%nr, an%u_conv, k)
      fr%rf(1:model%ndim, k) = node_vector_global(an%nr, rf, k)
    end do
    allocate (fr%cell_type(ncell), fr%cell_ptr(ncell + 1), fr%cell_id(ncell))
    fr%cell_ptr(1) = 1
    do c = 1, ncell
      fr%cell_ptr(c + 1) = fr%cell_ptr(c) + model%conn_ptr(cells(c) + 1) - model%conn_ptr(cells(c))
    end do
    allocate (fr%cell_conn(fr%cell_ptr(ncell + 1) - 1))
    do c = 1, ncell
      ie = cells(c)
      fr%cell_conn(fr%cell_ptr(c):fr%cell_ptr(c + 1) - 1) = model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1) - 1
      fr%cell_id(c) = model%elem_id(ie)
    end do
    call sdv_selection(model, an, step, fr%sdv_index)
    ! named state variables (*DEPVAR keys) give their arrays Abaqus' names SDV_key
    fr%sdv_name = [character(len=96) :: (model_sdv_name(model, fr%sdv_index(c)), c = 1, size(fr%sdv_index))]
    want_strain = step%out_le .or. step%out_e
    allocate (fr%stress(6, ncell), fr%principal(3, ncell), fr%mises(ncell), fr%sdv(size(fr%sdv_index), ncell))
    allocate (fr%opening(3, ncell))
    if (want_strain) then
      allocate (fr%strain(6, ncell))
      fr%strain = 0.0_dp
      allocate (fr%strain_names(count([step%out_le, step%out_e])))
      k = 0
      if (step%out_le) then
        k = k + 1
        fr%strain_names(k) = 'LE'
      end if
      if (step%out_e) fr%strain_names(k + 1) = 'E'
    end if
    allocate (fr%traction(ncell), fr%delta_max(ncell), fr%cohesive(ncell))
    fr%stress = 0.0_dp
    fr%principal = 0.0_dp
    fr%mises = 0.0_dp
    fr%sdv = 0.0_dp
    fr%opening = 0.0_dp
    fr%traction = 0.0_dp
    fr%delta_max = 0.0_dp
    fr%cohesive = 0
    do c = 1, ncell
      ie = cells(c)
      nn = model%conn_ptr(ie + 1) - model%conn_ptr(ie)
      ! VTK cell types; Abaqus' node order of these elements is VTK's (corners, then the mid-side nodes edge by edge)
      select case (model%elem_kind(ie))
      case (etype_c3d8, etype_c3d8i, etype_c3d8r)
        fr%cell_type(c) = 12
      case (etype_c3d20, etype_c3d20r)
        fr%cell_type(c) = 25
      case (etype_c3d4)
        fr%cell_type(c) = 10
      case (etype_c3d10)
        fr%cell_type(c) = 24
      case (etype_cpe4, etype_cpe4i, etype_cpe4r, etype_cps4, etype_cps4i, etype_cps4r, etype_cax4, etype_cax4i, &
            etype_cax4r)
        fr%cell_type(c) = 9
      case (etype_cpe8, etype_cpe8r, etype_cps8, etype_cps8r, etype_cax8, etype_cax8r)
        fr%cell_type(c) = 23
      case default
        if (nn == 8) then
          fr%cell_type(c) = 12
        else if (nn == 4) then
          fr%cell_type(c) = 9
        else
          fr%cell_type(c) = 2  ! poly-vertex for other user elements
        end if
      end select
      if (model%elem_kind(ie) == etype_user) then
        fr%cohesive(c) = 1
        ! opening = top - bottom (COH3D8: node k+4 over k; COH2D4: 4 over 1, 3 over 2)
        if (nn == 8 .or. nn == 4) call cell_opening(model, an, ie, nn, fr%opening(:, c))
        ! Delta_max and traction where the element type declares them ('**LDFCZ SVARS', docs/uel.md)
        associate (ut => model%utypes(model%elem_utype(ie)))
          nip = ut%sv_points
          nsv = size(an%conv(ie)%svars)
          if (nip > 0 .and. nsv >= nip * ut%sv_per_point) then
            do ip = 1, nip
              if (ut%sv_delta_max > 0) fr%delta_max(c) = fr%delta_max(c) + &
                an%conv(ie)%svars(ut%sv_per_point * (ip - 1) + ut%sv_delta_max) / nip
              if (ut%sv_traction > 0) fr%traction(c) = fr%traction(c) + &
                an%conv(ie)%svars(ut%sv_per_point * (ip - 1) + ut%sv_traction) / nip
            end do
          end if
        end associate
      else
        nip = size(an%conv(ie)%stress, 2)
        nt = size(an%conv(ie)%stress, 1)
        s = 0.0_dp
        e = 0.0_dp
        do ip = 1, nip
          s(1:nt) = s(1:nt) + an%conv(ie)%stress(:, ip) / nip
          e(1:nt) = e(1:nt) + an%conv(ie)%stran(:, ip) / nip
        end do
        if (nt == 3) then
          ! plane stress (11, 22, 12): sigma33 = 0; the thickness strain is not kept (0 in the frame)
          s(4) = s(3); s(3) = 0.0_dp
          e(4) = e(3); e(3) = 0.0_dp
        end if
        fr%stress(:, c) = s
        call principal_stresses(s, p)
        fr%principal(:, c) = [p(3), p(2), p(1)]
        fr%mises(c) = mises_stress(s)
        if (want_strain) fr%strain(:, c) = [e(1:3), 0.5_dp * e(4:6)]  ! engineering -> tensor shear
        ! the material's STATEV (the rows after them are the element's own: incompatible modes)
        nsv = max(1, an%mats(model%elem_section(ie))%nstatv)
        do k = 1, size(fr%sdv_index)
          if (fr%sdv_index(k) > nsv) cycle
          fr%sdv(k, c) = sum(an%conv(ie)%statev(fr%sdv_index(k), :)) / nip
        end do
      end if
    end do
    call output_vtu_frame(out, fr, ttot, an%par%rank, an%par%nranks)
  end subroutine write_field_frame

  !> The state variables a frame holds: every one (SDV requested), the listed ones (SDVn), the first three when the
  !> request names no variable at all (the frames of earlier versions), none otherwise.
  subroutine sdv_selection(model, an, step, idx)
    type(model_t), intent(in) :: model           !< the model
    type(analysis_t), intent(in) :: an           !< state (the number of state variables per element)
    type(step_t), intent(in) :: step             !< field request
    integer, allocatable, intent(out) :: idx(:)  !< state-variable numbers, ascending, no repeats
    integer :: ie, nmax, k
    nmax = 0
    do ie = 1, model%nelem
      ! every continuum element of the model, not only this process's, so that every piece has the same arrays
      if (model%elem_kind(ie) /= etype_user) nmax = max(nmax, an%mats(model%elem_section(ie))%nstatv, 1)
    end do
    if (step%out_sdv_all) then
      idx = [(k, k = 1, nmax)]
    else if (allocated(step%out_sdv)) then
      idx = [(k, k = 1, maxval([0, step%out_sdv]))]
      idx = pack(idx, [(any(step%out_sdv == k), k = 1, size(idx))])
    else if (.not. step%field_vars_named) then
      idx = [(k, k = 1, min(n_sdv_default, nmax))]
    else
      allocate (idx(0))
    end if
  end subroutine sdv_selection

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
      op(1:model%ndim) = op(1:model%ndim) + (node_vector_global(an%nr, an%u_conv, nt) - &
        node_vector_global(an%nr, an%u_conv, nb)) / (nn / 2)
    end do
  end subroutine cell_opening

end module field_frame
