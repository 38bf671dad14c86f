!> Element removal and reactivation (*MODEL CHANGE), as the Abaqus Analysis User's Guide describes it ("Element and
!> contact pair removal and reactivation"): from the start of the step that removes an element it is no longer
!> computed, and the forces it exerted on the rest of the model at the end of the previous step are ramped down to
!> zero over the removal step; an element added back (strain-free, Abaqus' default) starts stress-free in the
!> configuration its nodes have then: its reference is X + u_ref, u_ref the displacement at the reactivation, and
!> its state starts at zero. An element added back WITH STRAIN keeps its initial configuration X: its state starts
!> at zero and its first increment takes the whole displacement since the analysis began as its increment (the
!> work flag from_zero, cleared when that increment converges), so that its strain is that of the total
!> displacement. The active set, the reactivation displacements and the forces to release are analysis state
!> (analysis_state: the restart file holds them); from_zero lives only until the step's first converged increment,
!> before any checkpoint of the step.
module model_change
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, etype_user, model_find_material, model_elements_leave
  use analysis_core, only: analysis_t, element_state_allocate
  use coupling_constraints, only: coupling_mark_used
  use linear_constraints, only: constraints_mark_masters
  use solid_element, only: solid_element_geometry
  use node_rotations, only: element_to_global
  use parallel_context, only: parallel_sum, parallel_distributed
  implicit none
  private
  public :: model_change_release, model_change_step_begin, model_change_resume
  public :: element_active, model_change_prescribable, model_change_deletion

contains

  !> Element ie takes part in the analysis (not removed).
  pure logical function element_active(an, ie)
    type(analysis_t), intent(in) :: an  !< the analysis
    integer, intent(in) :: ie           !< element
    element_active = .true.
    if (size(an%state%active) > 0) element_active = an%state%active(ie)
  end function element_active

  !> (ndof) the dofs a *BOUNDARY prescribes in effect: those in use, and with *MODEL CHANGE also those of removed
  !> elements, whose nodes stay in the model and move as prescribed (Abaqus: the nodes of removed elements remain
  !> in the model), so that an element added back sees the displacement its nodes were given while it was out.
  pure function model_change_prescribable(an, model) result(mask)
    type(analysis_t), intent(in) :: an     !< the analysis
    type(model_t), intent(in) :: model     !< the model
    logical :: mask(an%ndof)
    integer :: ie
    mask = an%used
    if (.not. model_elements_leave(model)) return
    do ie = 1, model%nelem
      mask(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)) = .true.
    end do
  end function model_change_prescribable

  !> After the last increment of step is (converged, before its commit): the forces the elements that step is + 1
  !> removes exert on the rest of the model, -f_e summed at their nodes (this process's elements, summed over the
  !> processes), kept in the state for that step to ramp down.
  subroutine model_change_release(an, model, is)
    type(analysis_t), intent(inout) :: an  !< the analysis (work%fe: the converged element forces)
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: is              !< the step just completed
    integer :: k, j, ie, i
    an%state%last%fremove = 0.0_dp
    if (.not. model%has_model_change .or. is >= model%nstep) return
    associate (st => model%steps(is + 1))
      do k = 1, st%nchange
        if (.not. st%changes(k)%remove) cycle
        do j = 1, size(st%changes(k)%elems)
          ie = st%changes(k)%elems(j)
          if (.not. an%owned(ie)) cycle
          do i = an%elem_ptr(ie), an%elem_ptr(ie + 1) - 1
            an%state%last%fremove(an%elem_dof(i)) = an%state%last%fremove(an%elem_dof(i)) - an%work%fe(i)
          end do
        end do
      end do
    end associate
    if (parallel_distributed(an%par)) call parallel_sum(an%par, an%state%last%fremove)
  end subroutine model_change_release

  !> Start of step is (not a restart within it): its removals (inactive, their state zero, the forces they left
  !> behind ramped down with the released loads), strain-free reactivations (active, u_ref = the converged
  !> displacement of their nodes, zero state, reference geometry at X + u_ref) and reactivations with strain
  !> (active, zero state, reference geometry at X, from_zero), then the dofs in use.
  subroutine model_change_step_begin(an, model, is)
    type(analysis_t), intent(inout) :: an  !< the analysis
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: is              !< the step beginning
    integer :: k, j, ie
    if (.not. model%has_model_change) return
    associate (st => model%steps(is), s => an%state)
      s%loads%cload%released = s%loads%cload%released + s%last%fremove
      do k = 1, st%nchange
        do j = 1, size(st%changes(k)%elems)
          ie = st%changes(k)%elems(j)
          s%active(ie) = .not. st%changes(k)%remove
          s%shifted(ie) = s%active(ie) .and. st%changes(k)%strain_free
          an%work%from_zero(ie) = s%active(ie) .and. .not. st%changes(k)%strain_free
          if (s%shifted(ie)) s%u_ref(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1) = &
            s%u_conv(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1))
          if (.not. an%owned(ie)) cycle
          call element_state_allocate(an, model, ie, s%conv(ie))
          call element_state_allocate(an, model, ie, an%work%trial(ie))
          ! with strain: the reference geometry at X again (a strain-free reactivation before may have moved it)
          if (an%work%from_zero(ie)) call shifted_geometry(an, model, ie, .false.)
        end do
      end do
    end associate
    call reference_geometries(an, model, model%steps(is)%nlgeom)
    call dofs_in_use(an, model)
  end subroutine model_change_step_begin

  !> After a restart: the dofs in use and the reference geometry of the elements reactivated before it.
  subroutine model_change_resume(an, model)
    type(analysis_t), intent(inout) :: an  !< the analysis (state read)
    type(model_t), intent(in) :: model     !< the model
    if (.not. model_elements_leave(model)) return
    if (model%has_model_change) call reference_geometries(an, model, model%steps(an%state%progress%step)%nlgeom)
    call dofs_in_use(an, model)
  end subroutine model_change_resume

  !> After a converged increment (committed): element deletion by a material's state variable (*DEPVAR, DELETE=k;
  !> Analysis User's Guide "User-defined mechanical material behavior": 1 active, 0 deleted). An active element
  !> whose variable k is 0 at every integration point leaves the model, as Abaqus/Standard removes an element once
  !> all its points have failed (Analysis User's Guide "Damage evolution", element removal; the same rule for
  !> DELETE= is inferred): its stress is zeroed (its state variables and strains are kept), it offers no resistance
  !> from the next increment on (no ramp-down: only *MODEL CHANGE, REMOVE ramps forces down) and is never added
  !> back by its variable. ndel: the elements deleted now (over the processes), first: the lowest label of them;
  !> the dofs in use follow.
  subroutine model_change_deletion(an, model, ndel, first)
    type(analysis_t), intent(inout) :: an  !< the analysis (state committed)
    type(model_t), intent(in) :: model     !< the model
    integer, intent(out) :: ndel           !< elements deleted by this increment
    integer, intent(out) :: first          !< the lowest label among them (0: none)
    real(dp) :: gone(model%nelem)
    integer :: ksec(model%nsection), ie, k, im
    ndel = 0
    first = 0
    if (size(an%state%active) == 0) return
    do k = 1, model%nsection
      im = model_find_material(model, model%sections(k)%material)
      ksec(k) = 0
      if (im > 0) ksec(k) = model%materials(im)%delete_sdv
    end do
    if (all(ksec == 0)) return
    gone = 0.0_dp
    do ie = 1, model%nelem
      if (.not. (an%owned(ie) .and. an%state%active(ie)) .or. model%elem_kind(ie) == etype_user) cycle
      if (model%elem_section(ie) < 1) cycle
      k = ksec(model%elem_section(ie))
      if (k == 0) cycle
      if (all(an%state%conv(ie)%statev(k, :) == 0.0_dp)) gone(ie) = 1.0_dp
    end do
    if (parallel_distributed(an%par)) call parallel_sum(an%par, gone)
    do ie = 1, model%nelem
      if (gone(ie) < 0.5_dp) cycle
      ndel = ndel + 1
      if (first == 0 .or. model%elem_id(ie) < first) first = model%elem_id(ie)
      an%state%active(ie) = .false.
      if (an%owned(ie)) then
        an%state%conv(ie)%stress = 0.0_dp
        an%work%trial(ie)%stress = 0.0_dp
      end if
    end do
    if (ndel > 0) call dofs_in_use(an, model)
  end subroutine model_change_deletion

  !> The reference data of this process's reactivated continuum elements: at X + u_ref under NLGEOM (strain-free
  !> in the configuration of their reactivation), at X otherwise (small displacements: the strain of u - u_ref on
  !> the original geometry).
  subroutine reference_geometries(an, model, nlgeom)
    type(analysis_t), intent(inout) :: an  !< the analysis
    type(model_t), intent(in) :: model     !< the model
    logical, intent(in) :: nlgeom          !< the step is geometrically nonlinear
    integer :: ie
    do ie = 1, model%nelem
      if (an%state%shifted(ie) .and. an%owned(ie)) call shifted_geometry(an, model, ie, nlgeom)
    end do
  end subroutine reference_geometries

  !> The dofs of the active elements and of the couplings' reference nodes.
  subroutine dofs_in_use(an, model)
    type(analysis_t), intent(inout) :: an  !< the analysis
    type(model_t), intent(in) :: model     !< the model
    integer :: ie
    an%used = .false.
    do ie = 1, model%nelem
      if (an%state%active(ie)) an%used(an%elem_dof(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)) = .true.
    end do
    call coupling_mark_used(model, an%used)
    call constraints_mark_masters(an%eqs%cs, an%used)
  end subroutine dofs_in_use

  !> The reference data of continuum element ie at X + u_ref (global components), or at X (shift false).
  subroutine shifted_geometry(an, model, ie, shift)
    type(analysis_t), intent(inout) :: an  !< the analysis
    type(model_t), intent(in) :: model     !< the model
    integer, intent(in) :: ie              !< a reactivated element
    logical, intent(in) :: shift           !< at X + u_ref
    real(dp) :: x(model%ndim, model%conn_ptr(ie + 1) - model%conn_ptr(ie))
    real(dp) :: du(an%elem_ptr(ie + 1) - an%elem_ptr(ie))
    if (model%elem_kind(ie) == etype_user .or. an%elem_geo(ie) == 0) return
    associate (nodes => model%conn(model%conn_ptr(ie):model%conn_ptr(ie + 1) - 1))
      du = an%state%u_ref(an%elem_ptr(ie):an%elem_ptr(ie + 1) - 1)
      if (.not. shift) du = 0.0_dp
      if (an%nr%elem_has(ie)) call element_to_global(an%nr, nodes, du)
      x = model%x(1:model%ndim, nodes) + reshape(du, [model%ndim, size(nodes)])
    end associate
    call solid_element_geometry(an%elem_tname(ie), x, an%geo(an%elem_geo(ie)))
  end subroutine shifted_geometry

end module model_change
