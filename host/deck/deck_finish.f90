!> Last pass of the deck reader: resolves user node and element ids to indices (connectivity, sets, boundaries),
!> assigns sections and user-element properties to elements, and checks the model is complete.
module deck_finish
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_where
  use model_types, only: model_t, boundary_t, cload_t, dload_t, dload_user, dload_grav, source_pos_t, &
    etype_user, model_find_elset, model_find_material, model_label_text, orientation_axes
  use deck_lists, only: itoa, grow_int, unique
  use deck_context, only: deck_context_t, ctx_fail_kw, ctx_fail_pos, ctx_warn_pos, ctx_note_pos
  use output_registry, only: output_unprovided_requests
  implicit none
  private
  public :: finish_model

contains

  !> Resolve ids and check the model read from the deck (stat = 2 with a message naming file:line on error).
  subroutine finish_model(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: maxid, i, k, id, ie, isec, iset, im, is, ib, iu
    logical, allocatable :: has_section(:)
    type(source_pos_t) :: pos
    type(boundary_t) :: bc
    type(cload_t) :: cl
    character(len=:), allocatable :: what
    associate (model => ctx%model)
      if (model%nnode == 0) then
        call ctx_fail_kw(ctx, 1, '*NODE', 'the deck defines no nodes')
        return
      end if
      if (model%nelem == 0) then
        call ctx_fail_kw(ctx, 1, '*ELEMENT', 'the deck defines no elements')
        return
      end if
      if (model%nstep == 0) then
        call ctx_fail_kw(ctx, ctx%src%nrec, '*STEP', 'the deck defines no step')
        return
      end if
      ! node ids
      maxid = maxval(model%node_id(1:model%nnode))
      allocate (model%node_index(maxid))
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
      ! element ids and connectivity
      maxid = maxval(model%elem_id(1:model%nelem))
      allocate (model%elem_index(maxid))
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
          if (id <= 0 .or. id > size(model%node_index)) then
            call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'undefined node '//model_label_text(ctx%model, id, &
              .true.))
            return
          end if
          if (model%node_index(id) == 0) then
            call ctx_fail_kw(ctx, ctx%elem_rec(ie), '*ELEMENT', 'undefined node '//model_label_text(ctx%model, id, &
              .true.))
            return
          end if
          ctx%conn_raw(k) = model%node_index(id)
        end do
      end do
      model%conn = ctx%conn_raw(1:model%conn_ptr(model%nelem + 1) - 1)
      model%elem_id = model%elem_id(1:model%nelem)
      model%elem_kind = model%elem_kind(1:model%nelem)
      model%elem_utype = model%elem_utype(1:model%nelem)
      model%conn_ptr = model%conn_ptr(1:model%nelem + 1)
      ! sets: negative raw ids -> indices, duplicates removed
      do iset = 1, model%n_nset
        model%nsets(iset)%nodes = model%nsets(iset)%nodes(1:model%nsets(iset)%n)
        what = 'node set '//trim(model%nsets(iset)%name)
        call resolve_nodes(ctx, iset, what)
        if (ctx%stat /= 0) return
      end do
      do iset = 1, model%n_elset
        model%elsets(iset)%elems = model%elsets(iset)%elems(1:model%elsets(iset)%n)
        associate (el => model%elsets(iset)%elems)
          do k = 1, size(el)
            if (el(k) < 0) then
              id = -el(k)
              if (id > size(model%elem_index)) then
                ie = 0
              else
                ie = model%elem_index(id)
              end if
              if (ie == 0) then
                call ctx_fail_kw(ctx, 1, '*ELSET', 'element set '//trim(model%elsets(iset)%name)// &
                  ': undefined element '//itoa(id))
                return
              end if
              el(k) = ie
            end if
          end do
        end associate
        call unique(model%elsets(iset)%elems)
        model%elsets(iset)%n = size(model%elsets(iset)%elems)
      end do
      ! boundaries
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
          if (size(cl%nodes) /= size(model%equations(ib)%terms(1)%nodes)) then
            pos = model%equations(ib)%pos
            call ctx_fail_pos(ctx, pos, 'the node sets of the terms differ in size (one equation per member)')
            return
          end if
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
      call resolve_orientations(ctx)
      if (ctx%stat /= 0) return
      call resolve_transforms(ctx)
      if (ctx%stat /= 0) return
      if (model%monitor_node > 0) then
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
      end if
      ! sections
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
      do isec = 1, model%nsection
        pos = model%sections(isec)%pos
        associate (sec => model%sections(isec))
          iset = model_find_elset(model, sec%elset)
          if (iset == 0) then
            call ctx_fail_pos(ctx, pos, 'undefined element set '//trim(sec%elset))
            return
          end if
          if (len_trim(sec%orientation) > 0) then
            do k = 1, model%norient
              if (model%orientations(k)%name == sec%orientation) sec%iorient = k
            end do
            if (sec%iorient == 0) then
              call ctx_fail_pos(ctx, pos, 'undefined orientation '//trim(sec%orientation))
              return
            end if
          end if
          im = model_find_material(model, sec%material)
          if (im == 0) then
            call ctx_fail_pos(ctx, pos, 'undefined material '//trim(sec%material))
            return
          end if
          if (.not. (model%materials(im)%has_elastic .or. model%materials(im)%has_user)) then
            pos = model%materials(im)%pos
            call ctx_fail_pos(ctx, pos, 'material '//trim(sec%material)//' has no *ELASTIC or *USER MATERIAL')
            return
          end if
          if (model%materials(im)%has_elastic .and. model%materials(im)%has_user) then
            pos = model%materials(im)%pos
            call ctx_fail_pos(ctx, pos, 'material '//trim(sec%material)//' has both *ELASTIC and *USER MATERIAL')
            return
          end if
          do k = 1, size(model%elsets(iset)%elems)
            ie = model%elsets(iset)%elems(k)
            if (model%elem_kind(ie) == etype_user) then
              call ctx_fail_pos(ctx, pos, 'element '//model_label_text(model, model%elem_id(ie), .false.)// &
                ' is a user element (use *UEL PROPERTY)')
              return
            end if
            if (has_section(ie)) then
              call ctx_fail_pos(ctx, pos, 'element '//model_label_text(model, model%elem_id(ie), .false.)// &
                ' has two sections')
              return
            end if
            has_section(ie) = .true.
            model%elem_section(ie) = isec
          end do
        end associate
      end do
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
      call carry_field_requests(model)
      if (ctx%stat == 0) call resolve_surfaces(ctx)
      if (ctx%stat == 0) call resolve_dloads(ctx)
      if (ctx%stat == 0) call warn_unprovided_outputs(ctx)
    end associate
  end subroutine finish_model

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
            if (dl%kind == dload_grav) then
              im = model_find_material(model, model%sections(model%elem_section(ie))%material)
              if (.not. model%materials(im)%has_density) then
                call ctx_fail_pos(ctx, pos, 'GRAV on element '//model_label_text(model, model%elem_id(ie), .false.)// &
                  ' whose material '// &
                  trim(model%materials(im)%given_name)//' has no *DENSITY')
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
        if (model%inits(k)%elset > 0) then
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
        if (any([((model%steps(is)%dloads(k)%kind == dload_grav, k = 1, model%steps(is)%ndload), &
            is = 1, model%nstep)])) cycle
        pos = model%materials(im)%pos
        call ctx_note_pos(ctx, pos, 'material '//trim(model%materials(im)%given_name)//': *DENSITY has no effect '// &
          'in a static analysis without GRAV loads')
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
    if (cl%dof > ctx%model%ndim) call ctx_fail_pos(ctx, cl%pos, 'dof '//itoa(cl%dof)//' does not exist in this '// &
      itoa(ctx%model%ndim)//'D model')
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
    if (bc%last_dof > ctx%model%ndim) then
      if (bc%first_dof > ctx%model%ndim) then
        ! e.g. ZSYMM or dof 3 in a 2D model: nothing to constrain, like Abaqus for inactive dofs
        call ctx_warn_pos(ctx, bc%pos, 'dof '//itoa(bc%first_dof)//' does not exist in this 2D model: ignored')
      end if
      bc%last_dof = ctx%model%ndim
    end if
  end subroutine resolve_bc

  !> Node set iset: user ids -> indices, sorted, duplicates removed.
  subroutine resolve_nodes(ctx, iset, what)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer, intent(in) :: iset                 !< node set index
    character(len=*), intent(in) :: what        !< set named in messages (not a part of ctx)
    integer :: k, id
    associate (list => ctx%model%nsets(iset)%nodes, node_index => ctx%model%node_index)
      do k = 1, size(list)
        if (list(k) < 0) then
          id = -list(k)
          if (id > size(node_index)) then
            call ctx_fail_kw(ctx, 1, '*NSET', what//': undefined node '//itoa(id))
            return
          end if
          if (node_index(id) == 0) then
            call ctx_fail_kw(ctx, 1, '*NSET', what//': undefined node '//itoa(id))
            return
          end if
          list(k) = node_index(id)
        end if
      end do
    end associate
    call unique(ctx%model%nsets(iset)%nodes)
  end subroutine resolve_nodes

end module deck_finish
