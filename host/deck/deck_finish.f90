!> Last pass of the deck reader: resolves user node and element ids to indices (connectivity, sets, boundaries),
!> assigns sections and user-element properties to elements, and checks the model is complete.
module deck_finish
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_where, deck_keyword_parse, deck_param_t
  use model_types, only: model_t, boundary_t, cload_t, dload_t, dload_user, dload_grav, dload_centrif, dload_rota, source_pos_t, &
    etype_user, model_find_elset, model_find_material, model_label_text, orientation_axes, elastic_lamina, &
    model_find_orientation
  use element_catalog, only: element_is_plane_stress
  use deck_lists, only: itoa, grow_int, unique
  use deck_context, only: deck_context_t, ctx_fail_kw, ctx_fail_pos, ctx_warn_pos, ctx_note_pos
  use output_registry, only: output_unprovided_requests
  use deck_finish_extras, only: finish_extras
  use deck_pretension, only: finish_pretensions
  implicit none
  private
  public :: finish_model

contains

  !> Resolve ids and check the model read from the deck (stat = 2 with a message naming file:line on error).
  subroutine finish_model(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, allocatable :: has_section(:)
    call check_model_nonempty(ctx)
    if (ctx%stat == 0) call resolve_node_ids(ctx)
    if (ctx%stat == 0) call resolve_element_ids(ctx)
    if (ctx%stat == 0) call resolve_all_sets(ctx)
    if (ctx%stat == 0) call resolve_model_conditions(ctx)
    if (ctx%stat == 0) call resolve_step_conditions(ctx)
    if (ctx%stat == 0) call resolve_orientations(ctx)
    if (ctx%stat == 0) call resolve_transforms(ctx)
    if (ctx%stat == 0) call resolve_monitor(ctx)
    if (ctx%stat /= 0) return
    call prepare_section_arrays(ctx%model, has_section)
    call assign_sections(ctx, has_section)
    if (ctx%stat == 0) call check_element_sections(ctx, has_section)
    if (ctx%stat /= 0) return
    call carry_field_requests(ctx%model)
    call carry_print_requests(ctx%model)
    if (ctx%stat == 0) call resolve_surfaces(ctx)
    if (ctx%stat == 0) call resolve_dloads(ctx)
    if (ctx%stat == 0) call finish_extras(ctx)
    if (ctx%stat == 0) call finish_pretensions(ctx)
    if (ctx%stat == 0) call warn_unprovided_outputs(ctx)
  end subroutine finish_model

  !> A model needs nodes, elements and a step.
  subroutine check_model_nonempty(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (ctx%model%nnode == 0) then
      call ctx_fail_kw(ctx, 1, '*NODE', 'the deck defines no nodes')
    else if (ctx%model%nelem == 0) then
      call ctx_fail_kw(ctx, 1, '*ELEMENT', 'the deck defines no elements')
    else if (ctx%model%nstep == 0) then
      call ctx_fail_kw(ctx, ctx%src%nrec, '*STEP', 'the deck defines no step')
    end if
  end subroutine check_model_nonempty

  !> Node labels -> indices (node_index); a label defined twice is an error at its second *NODE line.
  subroutine resolve_node_ids(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: i, id
    associate (model => ctx%model)
      allocate (model%node_index(maxval(model%node_id(1:model%nnode))))
      model%node_index = 0
      do i = 1, model%nnode
        id = model%node_id(i)
        if (model%node_index(id) /= 0) then
          call ctx_fail_kw(ctx, ctx%node_rec(i), '*NODE', 'node '//model_label_text(model, id, .true.)// &
            ' defined twice (first at '// &
            deck_where(ctx%src, ctx%node_rec(model%node_index(id)))//')')
          return
        end if
        model%node_index(id) = i
      end do
      model%node_id = model%node_id(1:model%nnode)
      model%x = model%x(:, 1:model%nnode)
    end associate
  end subroutine resolve_node_ids

  !> Element labels -> indices (elem_index) and the connectivity's node labels -> node indices.
  subroutine resolve_element_ids(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, id, ie
    associate (model => ctx%model)
      allocate (model%elem_index(maxval(model%elem_id(1:model%nelem))))
      model%elem_index = 0
      do ie = 1, model%nelem
        id = model%elem_id(ie)
        if (model%elem_index(id) /= 0) then
          call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'element '//model_label_text(model, id, .false.)// &
            ' defined twice (first at '// &
            deck_where(ctx%src, ctx%elem_rec(model%elem_index(id)))//')')
          return
        end if
        model%elem_index(id) = ie
        do k = model%conn_ptr(ie), model%conn_ptr(ie + 1) - 1
          id = ctx%conn_raw(k)
          if (id > 0 .and. id <= size(model%node_index)) then
            if (model%node_index(id) /= 0) then
              ctx%conn_raw(k) = model%node_index(id)
              cycle
            end if
          end if
          call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'undefined node '//model_label_text(ctx%model, id, &
            .true.))
          return
        end do
      end do
      model%conn = ctx%conn_raw(1:model%conn_ptr(model%nelem + 1) - 1)
      model%elem_id = model%elem_id(1:model%nelem)
      model%elem_kind = model%elem_kind(1:model%nelem)
      model%elem_utype = model%elem_utype(1:model%nelem)
      model%conn_ptr = model%conn_ptr(1:model%nelem + 1)
    end associate
  end subroutine resolve_element_ids

  !> Node and element sets: raw labels -> indices, duplicates removed.
  subroutine resolve_all_sets(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: iset
    do iset = 1, ctx%model%n_nset
      ctx%model%nsets(iset)%nodes = ctx%model%nsets(iset)%nodes(1:ctx%model%nsets(iset)%n)
      call resolve_members(ctx, .true., iset)
      if (ctx%stat /= 0) return
    end do
    do iset = 1, ctx%model%n_elset
      ctx%model%elsets(iset)%elems = ctx%model%elsets(iset)%elems(1:ctx%model%elsets(iset)%n)
      call resolve_members(ctx, .false., iset)
      if (ctx%stat /= 0) return
    end do
  end subroutine resolve_all_sets

  !> Model-level node data: initial boundaries, *EQUATION terms, initial temperatures and field variables.
  subroutine resolve_model_conditions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: ib, k
    type(boundary_t) :: bc
    type(cload_t) :: cl
    ! (each item is resolved as a copy: resolve_bc and resolve_cload also change ctx)
    associate (model => ctx%model)
      do ib = 1, model%n_initial_bc
        bc = model%initial_bcs(ib)
        call resolve_bc(ctx, bc)
        model%initial_bcs(ib) = bc
        if (ctx%stat /= 0) return
      end do
      do ib = 1, model%nequation
        do k = 1, size(model%equations(ib)%terms)
          cl = model%equations(ib)%terms(k)
          call resolve_cload(ctx, cl)
          model%equations(ib)%terms(k) = cl
          if (ctx%stat /= 0) return
        end do
      end do
      do ib = 1, model%ntemp_init
        cl = model%temp_inits(ib)
        call resolve_cload(ctx, cl)
        model%temp_inits(ib) = cl
        if (ctx%stat /= 0) return
      end do
      do ib = 1, model%nfield_init
        cl = model%field_inits(ib)
        call resolve_cload(ctx, cl, .true.)
        model%field_inits(ib) = cl
        if (ctx%stat /= 0) return
      end do
    end associate
  end subroutine resolve_model_conditions

  !> Each step's boundaries, concentrated loads, temperatures and field variables; every step needs a procedure.
  subroutine resolve_step_conditions(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: is, ib
    type(boundary_t) :: bc
    type(cload_t) :: cl
    ! (each item is resolved as a copy: resolve_bc and resolve_cload also change ctx)
    associate (model => ctx%model)
      do is = 1, model%nstep
        do ib = 1, model%steps(is)%nbc
          bc = model%steps(is)%bcs(ib)
          call resolve_bc(ctx, bc)
          model%steps(is)%bcs(ib) = bc
          if (ctx%stat /= 0) return
        end do
        do ib = 1, model%steps(is)%ncload
          cl = model%steps(is)%cloads(ib)
          call resolve_cload(ctx, cl)
          model%steps(is)%cloads(ib) = cl
          if (ctx%stat /= 0) return
        end do
        do ib = 1, model%steps(is)%ntemp
          cl = model%steps(is)%temps(ib)
          call resolve_cload(ctx, cl)
          model%steps(is)%temps(ib) = cl
          if (ctx%stat /= 0) return
        end do
        do ib = 1, model%steps(is)%nfielddef
          cl = model%steps(is)%fields(ib)
          call resolve_cload(ctx, cl, .true.)
          model%steps(is)%fields(ib) = cl
          if (ctx%stat /= 0) return
        end do
        if (model%steps(is)%period < 0.0_dp) then
          ctx%stat = 2
          ctx%errmsg = model%steps(is)%pos%file//':'//itoa(model%steps(is)%pos%line)//': *STEP: no procedure '// &
            '(*STATIC) in this step'
          return
        end if
      end do
    end associate
  end subroutine resolve_step_conditions

  !> The **LDFCZ monitor node: label -> index, its dof within the model's dimension.
  subroutine resolve_monitor(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: id, k
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      if (model%monitor_node <= 0) return
      id = model%monitor_node
      k = 0
      if (id <= size(model%node_index)) k = model%node_index(id)
      pos = model%monitor_pos
      if (k == 0) then
        call ctx_fail_pos(ctx, pos, 'undefined node '//model_label_text(model, id, .true.))
        return
      end if
      if (model%monitor_dof > model%ndim) then
        call ctx_fail_pos(ctx, pos, 'dof '//itoa(model%monitor_dof)//' does not exist in this '// &
          itoa(model%ndim)//'D model')
        return
      end if
      model%monitor_node = k
    end associate
  end subroutine resolve_monitor

  !> Per-element section and user-element property indices, sized to the model's elements (0: none yet).
  pure subroutine prepare_section_arrays(model, has_section)
    type(model_t), intent(inout) :: model                   !< the model
    logical, allocatable, intent(out) :: has_section(:)     !< element has a section (all false)
    allocate (model%elem_section(model%nelem), has_section(model%nelem))
    model%elem_section = 0
    has_section = .false.
    if (.not. allocated(model%elem_uelprop)) then
      allocate (model%elem_uelprop(model%nelem))
      model%elem_uelprop = 0
    else
      model%elem_uelprop = model%elem_uelprop(1:model%nelem)
      if (size(model%elem_uelprop) < model%nelem) call grow_int(model%elem_uelprop, model%nelem)
    end if
  end subroutine prepare_section_arrays

  !> *SOLID SECTION: its element set, orientation and material resolved, and the section given to each element
  !> of the set (one section per element; not to user elements).
  subroutine assign_sections(ctx, has_section)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(inout) :: has_section(:)    !< element has a section
    integer :: isec, iset, im, k
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do isec = 1, model%nsection
        pos = model%sections(isec)%pos
        associate (sec => model%sections(isec))
          iset = model_find_elset(model, sec%elset)
          if (iset == 0) then
            call ctx_fail_pos(ctx, pos, 'undefined element set '//trim(sec%elset))
            return
          end if
          if (len_trim(sec%orientation) > 0) then
            sec%iorient = model_find_orientation(model, sec%orientation)
            if (sec%iorient == 0) then
              call ctx_fail_pos(ctx, pos, 'undefined orientation '//trim(sec%orientation))
              return
            end if
          end if
          call section_material(ctx, isec, im)
          if (ctx%stat /= 0) return
          do k = 1, size(model%elsets(iset)%elems)
            call give_section(ctx, isec, im, model%elsets(iset)%elems(k), has_section)
            if (ctx%stat /= 0) return
          end do
        end associate
      end do
    end associate
  end subroutine assign_sections

  !> The material of section isec: defined, and with exactly one of *ELASTIC and *USER MATERIAL.
  subroutine section_material(ctx, isec, im)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: isec                 !< section index
    integer, intent(out) :: im                  !< material index
    type(source_pos_t) :: pos
    associate (model => ctx%model, name => ctx%model%sections(isec)%material)
      im = model_find_material(model, name)
      if (im == 0) then
        pos = model%sections(isec)%pos
        call ctx_fail_pos(ctx, pos, 'undefined material '//trim(name))
        return
      end if
      pos = model%materials(im)%pos
      if (.not. (model%materials(im)%has_elastic .or. model%materials(im)%has_user)) then
        call ctx_fail_pos(ctx, pos, 'material '//trim(name)//' has no *ELASTIC or *USER MATERIAL')
      else if (model%materials(im)%has_elastic .and. model%materials(im)%has_user) then
        call ctx_fail_pos(ctx, pos, 'material '//trim(name)//' has both *ELASTIC and *USER MATERIAL')
      else if (model%materials(im)%delete_sdv > 0 .and. .not. model%materials(im)%has_user) then
        pos = model%materials(im)%delete_pos
        call ctx_fail_pos(ctx, pos, 'DELETE= of material '//trim(name)//' needs a *USER MATERIAL (its UMAT sets '// &
          'the deletion variable)')
      end if
    end associate
  end subroutine section_material

  !> Element ie takes section isec (material im): not a user element, not already sectioned, and a LAMINA
  !> material only on plane-stress elements without NLGEOM.
  subroutine give_section(ctx, isec, im, ie, has_section)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: isec                 !< section index
    integer, intent(in) :: im                   !< its material
    integer, intent(in) :: ie                   !< element index
    logical, intent(inout) :: has_section(:)    !< element has a section
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      pos = model%sections(isec)%pos
      if (model%elem_kind(ie) == etype_user) then
        call ctx_fail_pos(ctx, pos, 'element '//model_label_text(model, model%elem_id(ie), .false.)// &
          ' is a user element (use *UEL PROPERTY)')
        return
      end if
      ! *ELASTIC, TYPE=LAMINA has no through-thickness constants: plane-stress elements, small strain
      if (model%materials(im)%elastic_kind == elastic_lamina) then
        if (.not. element_is_plane_stress(model%elem_kind(ie)) .or. any(model%steps(1:model%nstep)%nlgeom)) then
          call ctx_fail_pos(ctx, model%materials(im)%elastic_pos, 'TYPE=LAMINA (material '// &
            trim(model%materials(im)%given_name)//', element '// &
            model_label_text(model, model%elem_id(ie), .false.)//') needs plane-stress elements (CPS) '// &
            'without NLGEOM: its constants give no through-thickness stiffness (ENGINEERING CONSTANTS do)')
          return
        end if
      end if
      if (has_section(ie)) then
        call ctx_fail_pos(ctx, pos, 'element '//model_label_text(model, model%elem_id(ie), .false.)// &
          ' has two sections')
        return
      end if
      has_section(ie) = .true.
      model%elem_section(ie) = isec
    end associate
  end subroutine give_section

  !> Every continuum element has a section; every user element with properties has its *UEL PROPERTY.
  subroutine check_element_sections(ctx, has_section)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: has_section(:)       !< element has a section
    integer :: ie, iu
    associate (model => ctx%model)
      do ie = 1, model%nelem
        if (model%elem_kind(ie) == etype_user) then
          iu = model%elem_utype(ie)
          if (model%elem_uelprop(ie) == 0 .and. model%utypes(iu)%nprops + model%utypes(iu)%njprops > 0) then
            call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'user element '//model_label_text(model, &
              model%elem_id(ie), .false.)// &
              ' of type '//trim(model%utypes(iu)%name)//' has no *UEL PROPERTY (missing properties)')
            return
          end if
        else if (.not. has_section(ie)) then
          call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'element '//model_label_text(model, &
            model%elem_id(ie), .false.)// &
            ' has no *SOLID SECTION')
          return
        end if
      end do
    end associate
  end subroutine check_element_sections

  !> A warning, once per request line, for every output request that nothing in the model provides (output
  !> registry: e.g. SDV5 with materials of 3 state variables, S in a model of user elements only, SDV of user
  !> elements); it is not written.
  subroutine warn_unprovided_outputs(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(source_pos_t), allocatable :: pos(:)
    character(len=512), allocatable :: msg(:)
    integer :: k
    call output_unprovided_requests(ctx%model, pos, msg)
    do k = 1, size(msg)
      ! a request written for part of the model only (SDV of a model with user elements) cannot surprise: a note
      if (index(msg(k), ': not written') > 0) then
        call ctx_warn_pos(ctx, pos(k), trim(msg(k)))
      else
        call ctx_note_pos(ctx, pos(k), trim(msg(k)))
      end if
    end do
  end subroutine warn_unprovided_outputs

  !> *ORIENTATION, DEFINITION=NODES: the nodes' (reference) coordinates become the points a, b[, c].
  subroutine resolve_orientations(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, j, id
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do k = 1, model%norient
        if (.not. model%orientations(k)%by_nodes) cycle
        do j = 1, 3
          id = model%orientations(k)%nodes(j)
          if (id == 0) cycle
          if (id > size(model%node_index)) then
            pos = model%orientations(k)%pos
            call ctx_fail_pos(ctx, pos, 'undefined node '//model_label_text(model, id, .true.))
            return
          end if
          if (model%node_index(id) == 0) then
            pos = model%orientations(k)%pos
            call ctx_fail_pos(ctx, pos, 'undefined node '//model_label_text(model, id, .true.))
            return
          end if
          select case (j)
          case (1)
            model%orientations(k)%a = model%x(:, model%node_index(id))
          case (2)
            model%orientations(k)%b = model%x(:, model%node_index(id))
          case (3)
            model%orientations(k)%c = model%x(:, model%node_index(id))
          end select
        end do
      end do
    end associate
  end subroutine resolve_orientations

  !> *TRANSFORM: the transform of each node (at most one per node, as Abaqus requires); its axes must be defined at
  !> the node (not on a cylinder's axis, at a sphere's centre or on its polar axis).
  subroutine resolve_transforms(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: k, j, nd
    real(dp) :: t(3, 3)
    logical :: ok
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      allocate (model%node_transform(model%nnode))
      model%node_transform = 0
      do k = 1, model%ntransform
        pos = model%transforms(k)%pos
        associate (set => model%nsets(model%transforms(k)%nset))
          do j = 1, size(set%nodes)
            nd = set%nodes(j)
            if (model%node_transform(nd) /= 0) then
              call ctx_fail_pos(ctx, pos, 'node '//model_label_text(model, model%node_id(nd), .true.)// &
                ' already has a *TRANSFORM (line '//itoa(model%transforms(model%node_transform(nd))%pos%line)// &
                '): one transformation per node')
              return
            end if
            call orientation_axes(model%transforms(k)%axes, model%x(:, nd), t, ok)
            if (.not. ok) then
              call ctx_fail_pos(ctx, pos, 'the local directions are undefined at node '// &
                model_label_text(model, model%node_id(nd), .true.)//' (on the axis or at the centre of TYPE='// &
                model%transforms(k)%kind//')')
              return
            end if
            if (model%ndim == 2 .and. abs(t(3, 3) - 1.0_dp) > 1.0e-9_dp) then
              call ctx_fail_pos(ctx, pos, 'in a 2D model the local system must keep local 3 along global Z (a '// &
                'rotation in the plane); it does not at node '//model_label_text(model, model%node_id(nd), .true.))
              return
            end if
            model%node_transform(nd) = k
          end do
        end associate
      end do
    end associate
  end subroutine resolve_transforms

  !> Element-based surfaces: element sets and ids expanded into (element index, face) pairs.
  subroutine resolve_surfaces(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: isf, m, j, id, ie
    integer, allocatable :: el(:), fc(:)
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do isf = 1, model%nsurf
        allocate (el(0), fc(0))
        do m = 1, model%surfaces(isf)%n
          if (model%surfaces(isf)%elsets(m) > 0) then
            j = model%surfaces(isf)%elsets(m)
            el = [el, model%elsets(j)%elems]
            fc = [fc, (model%surfaces(isf)%faces(m), id = 1, size(model%elsets(j)%elems))]
          else
            id = -model%surfaces(isf)%elems(m)
            ie = 0
            if (id <= size(model%elem_index)) ie = model%elem_index(id)
            if (ie == 0) then
              pos = model%surfaces(isf)%pos
              call ctx_fail_pos(ctx, pos, 'surface '//trim(model%surfaces(isf)%name)//': undefined element '// &
                itoa(id))
              return
            end if
            el = [el, ie]
            fc = [fc, model%surfaces(isf)%faces(m)]
          end if
        end do
        call move_alloc(el, model%surfaces(isf)%relems)
        call move_alloc(fc, model%surfaces(isf)%rfaces)
      end do
    end associate
  end subroutine resolve_surfaces

  !> Distributed loads: element sets and surfaces expanded into element lists with their faces, ids resolved;
  !> pressure, BX..BZ and GRAV only on continuum elements (GRAV with a *DENSITY), Un only on user elements.
  subroutine resolve_dloads(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: is, k, j, m, ie, id, im, isf
    integer, allocatable :: el(:), fc(:)
    character(len=:), allocatable :: what
    type(dload_t) :: dl
    type(source_pos_t) :: pos
    associate (model => ctx%model)
      do is = 1, model%nstep
        do k = 1, model%steps(is)%ndload
          dl = model%steps(is)%dloads(k)
          pos = dl%pos
          allocate (el(0), fc(0))
          if (dl%elset > 0) then
            el = model%elsets(dl%elset)%elems
            fc = [(dl%label, j = 1, size(el))]
          else if (dl%elset == 0) then
            id = -dl%elems(1)
            ie = 0
            if (id <= size(model%elem_index)) ie = model%elem_index(id)
            if (ie == 0) then
              call ctx_fail_pos(ctx, pos, 'undefined element '//model_label_text(ctx%model, id, .false.))
              return
            end if
            el = [ie]
            fc = [dl%label]
          else
            isf = -dl%elset
            do m = 1, model%surfaces(isf)%n
              if (model%surfaces(isf)%elsets(m) > 0) then
                j = model%surfaces(isf)%elsets(m)
                el = [el, model%elsets(j)%elems]
                fc = [fc, (model%surfaces(isf)%faces(m), id = 1, size(model%elsets(j)%elems))]
              else
                id = -model%surfaces(isf)%elems(m)
                ie = 0
                if (id <= size(model%elem_index)) ie = model%elem_index(id)
                if (ie == 0) then
                  pos = model%surfaces(isf)%pos
                  call ctx_fail_pos(ctx, pos, 'surface '//trim(model%surfaces(isf)%name)//': undefined element '// &
                    itoa(id))
                  return
                end if
                el = [el, ie]
                fc = [fc, model%surfaces(isf)%faces(m)]
              end if
            end do
          end if
          do j = 1, size(el)
            ie = el(j)
            if (dl%kind == dload_user .neqv. model%elem_kind(ie) == etype_user) then
              if (dl%kind == dload_user) then
                call ctx_fail_pos(ctx, pos, 'load type U'//itoa(dl%label)//' on element '// &
                  model_label_text(model, model%elem_id(ie), .false.)//', which is not a user element')
              else
                call ctx_fail_pos(ctx, pos, 'user element '//model_label_text(model, model%elem_id(ie), .false.)// &
                  ' takes only load types Un '// &
                  '(its UEL receives them), not BX/BY/BZ/GRAV/P')
              end if
              return
            end if
            if (dl%kind == dload_grav .or. dl%kind == dload_centrif .or. dl%kind == dload_rota) then
              im = model_find_material(model, model%sections(model%elem_section(ie))%material)
              if (.not. model%materials(im)%has_density) then
                what = 'GRAV'
                if (dl%kind == dload_centrif) what = 'CENTRIF'
                if (dl%kind == dload_rota) what = 'ROTA'
                call ctx_fail_pos(ctx, pos, what//' on element '// &
                  model_label_text(model, model%elem_id(ie), .false.)// &
                  ' whose material '// &
                  trim(model%materials(im)%given_name)//' has no *DENSITY')
                return
              end if
              if (model%materials(im)%density_varies) then
                call ctx_fail_pos(ctx, pos, 'GRAV on material '//trim(model%materials(im)%given_name)// &
                  ' whose *DENSITY depends on temperature (not supported with GRAV)')
                return
              end if
            end if
          end do
          call move_alloc(el, model%steps(is)%dloads(k)%elems)
          call move_alloc(fc, model%steps(is)%dloads(k)%faces)
        end do
      end do
      ! initial conditions: element ids and sets resolved
      do k = 1, model%ninit
        if (model%inits(k)%user) then
          ! USER: every continuum element (SIGINI / SDVINI at each of its points)
          model%inits(k)%elems = pack([(ie, ie = 1, model%nelem)], model%elem_kind(1:model%nelem) /= etype_user)
        else if (model%inits(k)%elset > 0) then
          model%inits(k)%elems = model%elsets(model%inits(k)%elset)%elems
        else
          id = -model%inits(k)%elems(1)
          ie = 0
          if (id <= size(model%elem_index)) ie = model%elem_index(id)
          if (ie == 0) then
            pos = model%inits(k)%pos
            call ctx_fail_pos(ctx, pos, 'undefined element '//model_label_text(ctx%model, id, .false.))
            return
          end if
          model%inits(k)%elems = [ie]
        end if
      end do
      ! a density without gravity loads cannot change a static result: accepted with a note
      do im = 1, model%nmat
        if (.not. model%materials(im)%has_density) cycle
        if (any([((any(model%steps(is)%dloads(k)%kind == [dload_grav, dload_centrif, dload_rota]), &
            k = 1, model%steps(is)%ndload), is = 1, model%nstep)])) cycle
        pos = model%materials(im)%pos
        call ctx_note_pos(ctx, pos, 'material '//trim(model%materials(im)%given_name)//': *DENSITY has no effect '// &
          'in a static analysis without GRAV, CENTRIF or ROTA loads')
      end do
    end associate
  end subroutine resolve_dloads

  !> Concentrated-load node ids -> indices; a dof beyond the model dimension is an error (no such force exists).
  subroutine resolve_cload(ctx, cl, any_dof)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(cload_t), intent(inout) :: cl          !< load (a copy, not a part of ctx)
    logical, intent(in), optional :: any_dof    !< dof is a field variable number, not a displacement dof
    integer :: k, id
    do k = 1, size(cl%nodes)
      if (cl%nodes(k) < 0) then
        id = -cl%nodes(k)
        if (id > size(ctx%model%node_index)) then
          call ctx_fail_pos(ctx, cl%pos, 'undefined node '//model_label_text(ctx%model, id, .true.))
          return
        end if
        if (ctx%model%node_index(id) == 0) then
          call ctx_fail_pos(ctx, cl%pos, 'undefined node '//model_label_text(ctx%model, id, .true.))
          return
        end if
        cl%nodes(k) = ctx%model%node_index(id)
      end if
    end do
    if (present(any_dof)) then
      if (any_dof) return
    end if
    ! (a moment, dof 4..6, exists at a coupling's reference node only: deck_finish_extras checks it)
    if (cl%dof > ctx%model%ndim .and. cl%dof <= 3) call ctx_fail_pos(ctx, cl%pos, 'dof '//itoa(cl%dof)// &
      ' does not exist in this '//itoa(ctx%model%ndim)//'D model')
  end subroutine resolve_cload

  !> Field output requests stay in effect in later steps until changed, as in Abaqus: a step without its own
  !> *OUTPUT, FIELD takes the previous step's request; a step with one adds its variables to the inherited ones
  !> (OP=ADD, the default, and REPLACE) or starts afresh (OP=NEW). Frequency and intervals are the step's own.
  pure subroutine carry_field_requests(model)
    type(model_t), intent(inout) :: model  !< the model
    integer :: is
    do is = 2, model%nstep
      associate (st => model%steps(is), prev => model%steps(is - 1))
        if (.not. prev%field_output) cycle
        if (.not. st%field_given) then
          st%field_output = .true.
          st%field_frequency = prev%field_frequency
          st%field_intervals = prev%field_intervals
        else if (st%field_op_new) then
          cycle
        end if
        st%field_vars_named = st%field_vars_named .or. prev%field_vars_named
        if (prev%nfield_request > 0) then
          if (.not. allocated(st%field_requests)) allocate (st%field_requests(0))
          st%field_requests = [st%field_requests(1:st%nfield_request), prev%field_requests(1:prev%nfield_request)]
          st%nfield_request = size(st%field_requests)
        end if
      end associate
    end do
  end subroutine carry_field_requests

  !> Data-file requests stay in effect in later steps until respecified (Abaqus Analysis User's Guide, "Requesting
  !> output in multiple steps": output requests apply to the step that defines them and to all later steps until
  !> they are respecified): a step without its own *NODE PRINT takes the previous step's *NODE PRINT requests, one
  !> without *EL PRINT the previous step's *EL PRINT requests; a step with its own replaces them (as its own *OUTPUT,
  !> FIELD does; that one request of a kind replaces all the earlier ones is inferred, docs/host.md).
  pure subroutine carry_print_requests(model)
    type(model_t), intent(inout) :: model  !< the model
    integer :: is
    do is = 2, model%nstep
      associate (st => model%steps(is), prev => model%steps(is - 1))
        if (st%nprint == 0 .and. prev%nprint > 0) then
          st%prints = prev%prints(1:prev%nprint)
          st%nprint = prev%nprint
        end if
        if (st%nelprint == 0 .and. prev%nelprint > 0) then
          st%elprints = prev%elprints(1:prev%nelprint)
          st%nelprint = prev%nelprint
        end if
      end associate
    end do
  end subroutine carry_print_requests

  !> Boundary node ids -> indices; dofs beyond the model dimension dropped (with a warning when none is left).
  subroutine resolve_bc(ctx, bc)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    type(boundary_t), intent(inout) :: bc       !< boundary (a copy, not a part of ctx)
    integer :: k, id
    do k = 1, size(bc%nodes)
      if (bc%nodes(k) < 0) then
        id = -bc%nodes(k)
        if (id > size(ctx%model%node_index)) then
          call ctx_fail_pos(ctx, bc%pos, 'undefined node '//model_label_text(ctx%model, id, .true.))
          return
        end if
        if (ctx%model%node_index(id) == 0) then
          call ctx_fail_pos(ctx, bc%pos, 'undefined node '//model_label_text(ctx%model, id, .true.))
          return
        end if
        bc%nodes(k) = ctx%model%node_index(id)
      end if
    end do
    ! e.g. ZSYMM or dof 3 in a 2D model: nothing to constrain, like Abaqus for inactive dofs (the dofs a node does
    ! not have are skipped when the boundaries are applied; rotations 4..6: deck_finish_extras)
    if (bc%first_dof > ctx%model%ndim .and. bc%first_dof <= 3) &
      call ctx_warn_pos(ctx, bc%pos, 'dof '//itoa(bc%first_dof)//' does not exist in this 2D model: ignored')
  end subroutine resolve_bc

  !> Labels of the members of a node set (is_node) or element set to indices, duplicates removed. A label that
  !> names no node or element is an error at the data line that added it; one from a GENERATE range is left out
  !> with a warning at that line (a range over a numbering gap; what Abaqus does is not documented: inferred,
  !> CalculiX leaves them out).
  subroutine resolve_members(ctx, is_node, iset)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    logical, intent(in) :: is_node              !< node set (else element set)
    integer, intent(in) :: iset                 !< set index
    integer, allocatable :: list(:), origin(:), index(:)
    integer :: k, id, idx, nkeep, ndrop, rdrop, r
    character(len=:), allocatable :: what
    if (is_node) then
      call move_alloc(ctx%model%nsets(iset)%nodes, list)
      what = 'node set '//trim(ctx%model%nsets(iset)%name)
      if (size(list) > 0) origin = ctx%nset_src(iset)%rec
      index = ctx%model%node_index
    else
      call move_alloc(ctx%model%elsets(iset)%elems, list)
      what = 'element set '//trim(ctx%model%elsets(iset)%name)
      if (size(list) > 0) origin = ctx%elset_src(iset)%rec
      index = ctx%model%elem_index
    end if
    nkeep = 0
    ndrop = 0
    rdrop = 0
    do k = 1, size(list)
      idx = list(k)
      if (idx < 0) then
        id = -idx
        idx = 0
        if (id <= size(index)) idx = index(id)
        r = origin(k)
        if (idx == 0 .and. r < 0) then
          ndrop = ndrop + 1
          if (rdrop == 0) rdrop = -r
          cycle
        end if
        if (idx == 0) then
          call ctx_fail_kw(ctx, r, block_keyword(ctx, r), what//': undefined '// &
            trim(merge('node   ', 'element', is_node))//' '//model_label_text(ctx%model, id, is_node))
          exit
        end if
      end if
      nkeep = nkeep + 1
      list(nkeep) = idx
    end do
    list = list(1:nkeep)
    call unique(list)
    if (is_node) then
      call move_alloc(list, ctx%model%nsets(iset)%nodes)
      ctx%model%nsets(iset)%n = size(ctx%model%nsets(iset)%nodes)
    else
      call move_alloc(list, ctx%model%elsets(iset)%elems)
      ctx%model%elsets(iset)%n = size(ctx%model%elsets(iset)%elems)
    end if
    if (ctx%stat == 0 .and. ndrop > 0 .and. ctx%wu /= -1) write (ctx%wu, '(a)') 'ldfcz: warning: '// &
      deck_where(ctx%src, rdrop)//': '//block_keyword(ctx, rdrop)//': '//what//': GENERATE ranges include '// &
      itoa(ndrop)//' number(s) with no '//trim(merge('node   ', 'element', is_node))//': left out of the set'
  end subroutine resolve_members

  !> Keyword of the block that record irec belongs to (the record itself or the keyword line before it).
  function block_keyword(ctx, irec) result(kw)
    type(deck_context_t), intent(in) :: ctx  !< reader state
    integer, intent(in) :: irec              !< record index
    character(len=:), allocatable :: kw
    type(deck_param_t), allocatable :: params(:)
    integer :: r
    r = max(1, min(irec, ctx%src%nrec))
    do while (r > 1 .and. .not. ctx%src%rec(r)%keyword)
      r = r - 1
    end do
    call deck_keyword_parse(ctx%src%rec(r)%text, kw, params)
  end function block_keyword

end module deck_finish
