!> Restart file JOB.rst (docs/host.md, "Restart"): the checkpoint of a converged increment, written and read whole,
!> so that a continuation repeats the uninterrupted run's arithmetic bit for bit. A checkpoint is the analysis state
!> (analysis_state: position, increment control, prescribed conditions, every load and predefined field, the
!> converged solution and element states, the last increment) and the record of checkpoint_t (the model's
!> fingerprint, the output marks, the run summary, the VTU frame times). The solver's working data (trial states,
!> sparse system, work vectors, timings) are never in it.
!>
!> Format (version 10): unformatted stream, native byte order: magic 'LDFCZRST', format version, the size in bits
!> of the run summary record (written whole, so that a build whose summary type has other fields refuses the file
!> by name instead of misreading it), the fingerprint (nodes, elements, dofs, checksum of the model's numbers:
!> restart_checksum), the analysis state (scalars, then each array preceded by its size, element states by their
!> shape or -1 when a process does not hold them), the output marks, the summary, the frame times and the end
!> marker 'LDFCZEND' (a truncated file is refused). Written to JOB.rst.tmp, flushed, closed and renamed over
!> JOB.rst (rename(2) is atomic): a kill at any moment leaves the previous or the new restart file, never a
!> partial one.
module restart_file
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t, boundary_t, cload_t
  use element_state, only: elem_state_t
  use analysis_state, only: analysis_state_t
  use step_loads, only: load_state_t
  use distributed_loads, only: dload_state_t, dload_reindex
  use step_output, only: output_marks_t
  use run_summary, only: run_summary_t
  use solver_text, only: itoa
  implicit none
  private
  public :: checkpoint_t, restart_write, restart_read, restart_checksum, restart_magic, restart_version

  character(len=8), parameter :: restart_magic = 'LDFCZRST'  !< first 8 bytes of a restart file
  character(len=8), parameter :: end_magic = 'LDFCZEND'      !< last 8 bytes
  !> format version: 6 adds the summary record's size to the header; 7: a process of a distributed run writes the
  !> states of its own elements only; 8: the whole analysis state (loads, predefined fields, distributed loads,
  !> velocity boundaries and OP=NEW releases: a restart of every deck), the internal forces no longer; 9: the
  !> active elements and reactivation displacements (*MODEL CHANGE), the forces of removed elements, the axes of
  !> CENTRIF/ROTA loads; 10: the increment before the last (EXTRAPOLATION=PARABOLIC)
  integer, parameter :: restart_version = 10
  integer, parameter :: max_records = 100000000  !< sanity bound on a count read from a file

  !> The checkpoint's record beside the analysis state.
  type :: checkpoint_t
    integer :: nnode = 0                     !< fingerprint: nodes,
    integer :: nelem = 0                     !< elements,
    integer :: ndof = 0                      !< dofs
    integer(i8) :: checksum = 0              !< and the checksum of the model (and the partition: static_step)
    type(output_marks_t) :: marks            !< what the output files hold (CSV rows, last frame, next mark)
    type(run_summary_t) :: summary           !< summary counters and accumulators (factorizations: the whole run's)
    real(dp), allocatable :: frame_times(:)  !< total time of each VTU frame written (JOB.pvd)
  end type checkpoint_t

  !> A running pair of 31-bit polynomial hashes over the 32-bit halves of numbers (restart_checksum).
  type :: hash_t
    integer(i8) :: a = 1
    integer(i8) :: b = 7
  end type hash_t

  interface
    function c_rename(from, to) bind(c, name='rename') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: from(*), to(*)
      integer(c_int) :: r
    end function c_rename
  end interface

contains

  !> Checksum of the numbers of the model that determine the analysis: coordinates, connectivity, element kinds,
  !> *TRANSFORM systems, sections, materials, user element types and properties, amplitudes, initial conditions of
  !> temperatures and fields, boundaries, loads and the steps' data (not the output requests).
  function restart_checksum(model) result(h)
    type(model_t), intent(in) :: model  !< the model
    integer(i8) :: h
    type(hash_t) :: hs
    integer :: k
    call hash_mesh(hs, model)
    call hash_materials(hs, model)
    do k = 1, model%namp
      call hash_reals(hs, model%amplitudes(k)%t)
      call hash_reals(hs, model%amplitudes(k)%a)
      call hash_ints(hs, [merge(1, 0, model%amplitudes(k)%smooth), merge(1, 0, model%amplitudes(k)%total_time)])
    end do
    ! (the lists are passed only when they hold definitions: an empty one may be unallocated)
    if (model%n_initial_bc > 0) call hash_boundaries(hs, model%initial_bcs, model%n_initial_bc)
    if (model%ntemp_init > 0) call hash_cloads(hs, model%temp_inits, model%ntemp_init)
    if (model%nfield_init > 0) call hash_cloads(hs, model%field_inits, model%nfield_init)
    call hash_int(hs, model%nfield)
    call hash_couplings(hs, model)
    call hash_int(hs, model%nstep)
    do k = 1, model%nstep
      call hash_step(hs, model, k)
    end do
    h = hs%a * 2147483648_i8 + hs%b
  end function restart_checksum

  !> Nodes, elements, connectivity, sections and user properties of elements, *TRANSFORM systems.
  subroutine hash_mesh(hs, model)
    type(hash_t), intent(inout) :: hs   !< the hash
    type(model_t), intent(in) :: model  !< the model
    integer :: k
    call hash_ints(hs, [model%ndim, model%nnode, model%nelem])
    if (model%nnode > 0) then
      call hash_ints(hs, model%node_id(1:model%nnode))
      call hash_reals(hs, reshape(model%x(:, 1:model%nnode), [3 * model%nnode]))
    end if
    if (model%nelem == 0) return
    call hash_ints(hs, model%elem_id(1:model%nelem))
    call hash_ints(hs, model%elem_kind(1:model%nelem))
    call hash_ints(hs, model%conn_ptr(1:model%nelem + 1))
    call hash_ints(hs, model%conn(1:model%conn_ptr(model%nelem + 1) - 1))
    if (allocated(model%elem_section)) call hash_ints(hs, model%elem_section)
    if (allocated(model%elem_uelprop)) call hash_ints(hs, model%elem_uelprop)
    if (allocated(model%elem_utype)) call hash_ints(hs, model%elem_utype(1:model%nelem))
    ! *TRANSFORM: the solution vector holds local components at those nodes
    if (allocated(model%node_transform)) then
      if (any(model%node_transform /= 0)) call hash_ints(hs, model%node_transform)
      do k = 1, model%ntransform
        call hash_reals(hs, [model%transforms(k)%axes%a, model%transforms(k)%axes%b, model%transforms(k)%axes%c])
        call hash_int(hs, model%transforms(k)%axes%system)
      end do
    end if
  end subroutine hash_mesh

  !> *COUPLING definitions: reference node, coupling nodes, type, dofs, weighting; the rotational dofs; the
  !> pre-tension sections.
  subroutine hash_couplings(hs, model)
    type(hash_t), intent(inout) :: hs   !< the hash
    type(model_t), intent(in) :: model  !< the model
    integer :: k
    call hash_ints(hs, [model%ncoupling, model%nrot])
    do k = 1, model%ncoupling
      associate (c => model%couplings(k))
        call hash_ints(hs, [c%ref, c%weighting, merge(1, 0, c%kinematic), merge(1, 0, c%dofs)])
        call hash_ints(hs, c%nodes)
        call hash_reals(hs, [c%radius])
        if (c%iorient /= 0) call hash_ints(hs, [c%iorient])
      end associate
    end do
    ! *PRE-TENSION SECTION (hashed only when present: older decks keep their fingerprint)
    do k = 1, model%npretension
      associate (p => model%pretensions(k))
        call hash_ints(hs, [p%node, p%dof0, p%nodes, p%elems])
        call hash_reals(hs, p%normal)
      end associate
    end do
  end subroutine hash_couplings

  !> Sections, materials, user element types and their properties.
  subroutine hash_materials(hs, model)
    type(hash_t), intent(inout) :: hs   !< the hash
    type(model_t), intent(in) :: model  !< the model
    integer :: k
    do k = 1, model%nsection
      call hash_reals(hs, [model%sections(k)%thickness])
      call hash_string(hs, model%sections(k)%material)
    end do
    do k = 1, model%nmat
      call hash_string(hs, model%materials(k)%name)
      call hash_reals(hs, [model%materials(k)%young, model%materials(k)%poisson, model%materials(k)%density, &
        model%materials(k)%alpha])
      call hash_ints(hs, [model%materials(k)%nstatv, merge(1, 0, model%materials(k)%unsymm)])
      if (allocated(model%materials(k)%props)) call hash_reals(hs, model%materials(k)%props)
      ! the general *ELASTIC/*EXPANSION tables (the constant isotropic ones are young, poisson above)
      if (allocated(model%materials(k)%elastic_data)) call hash_reals(hs, [real(model%materials(k)%elastic_kind, dp), &
        model%materials(k)%elastic_temp, pack(model%materials(k)%elastic_data, .true.)])
      if (allocated(model%materials(k)%expansion_data)) call hash_reals(hs, [real(model%materials(k)%expansion_kind, dp), &
        model%materials(k)%expansion_zero, model%materials(k)%expansion_temp, &
        pack(model%materials(k)%expansion_data, .true.)])
    end do
    do k = 1, model%nutype
      associate (ut => model%utypes(k))
        call hash_ints(hs, [ut%jtype, ut%nnode, ut%mcrd, ut%nprops, ut%njprops, ut%nsvars, merge(1, 0, ut%unsymm)])
        if (allocated(ut%active)) call hash_ints(hs, ut%active)
      end associate
    end do
    do k = 1, model%n_uelprop
      call hash_reals(hs, model%uelprops(k)%props)
      call hash_ints(hs, model%uelprops(k)%jprops)
    end do
  end subroutine hash_materials

  !> Step k's procedure, controls, boundaries and loads.
  subroutine hash_step(hs, model, k)
    type(hash_t), intent(inout) :: hs   !< the hash
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: k            !< the step
    integer :: j
    associate (st => model%steps(k))
      call hash_ints(hs, merge(1, 0, [st%nlgeom, st%direct, st%extrapolate, st%unsymm, st%op_new, st%amp_step, &
        st%cload_op_new, st%dload_op_new, st%parabolic]))
      call hash_ints(hs, [st%max_inc, st%max_iter, st%nbc, st%ncload, st%ndload, st%ntemp, st%nfielddef])
      call hash_reals(hs, [st%dt_initial, st%period, st%dt_min, st%dt_max, st%r_n, st%c_n])
      if (st%nbc > 0) call hash_boundaries(hs, st%bcs, st%nbc)
      if (st%ncload > 0) call hash_cloads(hs, st%cloads, st%ncload)
      if (st%ntemp > 0) call hash_cloads(hs, st%temps, st%ntemp)
      if (st%nfielddef > 0) call hash_cloads(hs, st%fields, st%nfielddef)
      if (allocated(st%field_new)) call hash_ints(hs, st%field_new)
      if (allocated(st%cut_points)) call hash_reals(hs, st%cut_points)
      do j = 1, st%nchange
        call hash_ints(hs, [merge(1, 0, st%changes(j)%remove), st%changes(j)%elems])
      end do
      do j = 1, st%ndload
        associate (dl => st%dloads(j))
          call hash_ints(hs, dl%elems)
          if (allocated(dl%faces)) call hash_ints(hs, dl%faces)
          call hash_ints(hs, [dl%kind, dl%label, dl%amplitude])
          call hash_reals(hs, [dl%value, dl%dir, dl%point])
        end associate
      end do
    end associate
  end subroutine hash_step

  !> *BOUNDARY definitions list(1:n).
  subroutine hash_boundaries(hs, list, n)
    type(hash_t), intent(inout) :: hs     !< the hash
    type(boundary_t), intent(in) :: list(:)  !< definitions
    integer, intent(in) :: n              !< definitions in use
    integer :: j
    do j = 1, n
      call hash_ints(hs, list(j)%nodes)
      call hash_ints(hs, [list(j)%first_dof, list(j)%last_dof, list(j)%amplitude, merge(1, 0, list(j)%velocity), &
        merge(1, 0, list(j)%user), list(j)%rot_dofs])
      call hash_reals(hs, [list(j)%value])
    end do
  end subroutine hash_boundaries

  !> *CLOAD-like definitions list(1:n) (concentrated loads, temperatures, field variables).
  subroutine hash_cloads(hs, list, n)
    type(hash_t), intent(inout) :: hs     !< the hash
    type(cload_t), intent(in) :: list(:)  !< definitions
    integer, intent(in) :: n              !< definitions in use
    integer :: j
    do j = 1, n
      call hash_ints(hs, list(j)%nodes)
      call hash_ints(hs, [list(j)%dof, list(j)%amplitude])
      call hash_reals(hs, [list(j)%value])
    end do
  end subroutine hash_cloads

  subroutine hash_word(hs, w)
    type(hash_t), intent(inout) :: hs
    integer(i8), intent(in) :: w   ! 0 <= w < 2**32
    hs%a = mod(hs%a * 16777619_i8 + w, 2147483647_i8)
    hs%b = mod(hs%b * 1000003_i8 + w + 1_i8, 2147483629_i8)
  end subroutine hash_word

  subroutine hash_int(hs, i)
    type(hash_t), intent(inout) :: hs
    integer, intent(in) :: i
    call hash_word(hs, ibits(int(i, i8), 0, 32))
    call hash_word(hs, ibits(int(i, i8), 32, 32))
  end subroutine hash_int

  subroutine hash_ints(hs, v)
    type(hash_t), intent(inout) :: hs
    integer, intent(in) :: v(:)
    integer :: m
    call hash_int(hs, size(v))
    do m = 1, size(v)
      call hash_int(hs, v(m))
    end do
  end subroutine hash_ints

  subroutine hash_reals(hs, v)
    type(hash_t), intent(inout) :: hs
    real(dp), intent(in) :: v(:)
    integer :: m
    call hash_int(hs, size(v))
    do m = 1, size(v)
      call hash_word(hs, ibits(transfer(v(m), 0_i8), 0, 32))
      call hash_word(hs, ibits(transfer(v(m), 0_i8), 32, 32))
    end do
  end subroutine hash_reals

  subroutine hash_string(hs, s)
    type(hash_t), intent(inout) :: hs
    character(len=*), intent(in) :: s
    integer :: m
    do m = 1, len_trim(s)
      call hash_int(hs, ichar(s(m:m)))
    end do
    call hash_int(hs, -1)
  end subroutine hash_string

  !> Write the checkpoint (ck and the analysis state s) atomically: path.tmp, flush, close, rename to path.
  !> stat /= 0: not written (errmsg).
  subroutine restart_write(path, ck, s, stat, errmsg)
    character(len=*), intent(in) :: path                 !< JOB.rst (JOB.rst.RofN of a distributed run)
    type(checkpoint_t), intent(in) :: ck                 !< fingerprint, output marks, summary, frames
    type(analysis_state_t), intent(in) :: s              !< the analysis state
    integer, intent(out) :: stat                         !< 0 ok
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: u, ios, ie
    character(len=256) :: iom
    stat = 0
    errmsg = ''
    open (newunit=u, file=path//'.tmp', access='stream', form='unformatted', status='replace', action='write', &
      iostat=ios, iomsg=iom)
    if (ios /= 0) then
      stat = 1
      errmsg = 'cannot write '//path//'.tmp: '//trim(iom)
      return
    end if
    write (u, iostat=ios, iomsg=iom) restart_magic, restart_version, summary_bits(), ck%nnode, ck%nelem, ck%ndof, &
      ck%checksum
    call write_state(u, s, ios, iom)
    do ie = 1, size(s%conv)
      call write_element(u, s%conv(ie), ios, iom)
    end do
    if (ios == 0) write (u, iostat=ios, iomsg=iom) ck%marks%csv_rows, ck%marks%last_frame_inc, ck%marks%next_mark, &
      ck%summary
    if (allocated(ck%frame_times)) then
      call put_reals(u, ck%frame_times, ios, iom)
    else
      call put_reals(u, [real(dp) ::], ios, iom)
    end if
    if (ios == 0) write (u, iostat=ios, iomsg=iom) end_magic
    if (ios /= 0) then
      close (u, status='delete')
      stat = 1
      errmsg = 'cannot write '//path//'.tmp: '//trim(iom)
      return
    end if
    flush (u, iostat=ios)
    close (u, iostat=ios)
    if (c_rename(path//'.tmp'//c_null_char, path//c_null_char) /= 0) then
      stat = 1
      errmsg = 'cannot rename '//path//'.tmp to '//path
    end if
  end subroutine restart_write

  !> The analysis state but the element states (nothing written once ios /= 0).
  subroutine write_state(u, s, ios, iom)
    integer, intent(in) :: u                     !< unit (stream, unformatted)
    type(analysis_state_t), intent(in) :: s      !< the state
    integer, intent(inout) :: ios                !< iostat
    character(len=*), intent(inout) :: iom       !< iomsg
    if (ios /= 0) return
    associate (p => s%progress, sc => s%progress%sc)
      write (u, iostat=ios, iomsg=iom) p%step, p%kinc, p%kinc_total, p%reuse_count, p%t_total0, p%q_sum, &
        sc%period, sc%dt_min, sc%dt_max, merge(1, 0, sc%direct), sc%easy_iterations, sc%t, sc%dt, sc%easy_count, &
        sc%cutbacks, sc%total_cutbacks
    end associate
    call put_flags(u, s%bc%on, ios, iom)
    call put_flags(u, s%bc%init, ios, iom)
    call put_flags(u, s%bc%vel, ios, iom)
    call put_flags(u, s%bc%user, ios, iom)
    call put_reals(u, s%bc%val, ios, iom)
    call put_ints(u, s%bc%amp, ios, iom)
    call put_reals(u, s%bc%rate, ios, iom)
    call put_reals(u, s%bc%u_start, ios, iom)
    call write_load(u, s%loads%cload, ios, iom)
    call write_load(u, s%loads%temperature, ios, iom)
    call write_load(u, s%loads%field, ios, iom)
    call write_dload(u, s%loads%dload, ios, iom)
    if (ios == 0) write (u, iostat=ios, iomsg=iom) s%last%dt, s%last%dt_before
    call put_reals(u, s%last%du, ios, iom)
    call put_reals(u, s%last%du_before, ios, iom)
    call put_reals(u, s%last%rf, ios, iom)
    call put_reals(u, s%last%fext, ios, iom)
    call put_reals(u, s%last%fcl, ios, iom)
    call put_reals(u, s%last%fremove, ios, iom)
    call put_reals(u, s%u_conv, ios, iom)
    call put_reals(u, s%temp_start, ios, iom)
    call put_reals(u, s%field_start, ios, iom)
    call put_flags(u, s%active, ios, iom)
    call put_flags(u, s%shifted, ios, iom)
    call put_reals(u, s%u_ref, ios, iom)
  end subroutine write_state

  subroutine write_load(u, ls, ios, iom)
    integer, intent(in) :: u
    type(load_state_t), intent(in) :: ls
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    call put_flags(u, ls%on, ios, iom)
    call put_reals(u, ls%base, ios, iom)
    call put_reals(u, ls%target, ios, iom)
    call put_ints(u, ls%amp, ios, iom)
    call put_reals(u, ls%released, ios, iom)
  end subroutine write_load

  !> The distributed-load records 1:n (their index by element is rebuilt on reading).
  subroutine write_dload(u, ds, ios, iom)
    integer, intent(in) :: u
    type(dload_state_t), intent(in) :: ds
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    integer :: n
    if (ios /= 0) return
    n = 0
    if (allocated(ds%elem)) n = ds%n
    write (u, iostat=ios, iomsg=iom) n, ds%step, ds%t_total0
    if (n == 0) return
    call put_ints(u, ds%elem(1:n), ios, iom)
    call put_ints(u, ds%kind(1:n), ios, iom)
    call put_ints(u, ds%label(1:n), ios, iom)
    call put_ints(u, ds%amp(1:n), ios, iom)
    call put_flags(u, ds%removed(1:n), ios, iom)
    call put_reals(u, reshape(ds%base(:, 1:n), [3 * n]), ios, iom)
    call put_reals(u, reshape(ds%target(:, 1:n), [3 * n]), ios, iom)
    call put_reals(u, reshape(ds%axis(:, 1:n), [6 * n]), ios, iom)
  end subroutine write_dload

  !> One element's converged state, each array preceded by its shape (-1: not held by this process).
  subroutine write_element(u, e, ios, iom)
    integer, intent(in) :: u
    type(elem_state_t), intent(in) :: e
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    if (ios /= 0) return
    write (u, iostat=ios, iomsg=iom) e%energy
    if (ios /= 0) return
    if (allocated(e%svars)) then
      write (u, iostat=ios, iomsg=iom) size(e%svars), e%svars
    else
      write (u, iostat=ios, iomsg=iom) -1
    end if
    call put_matrix(e%stress)
    call put_matrix(e%stran)
    call put_matrix(e%statev)
    call put_matrix(e%eip)
  contains
    subroutine put_matrix(m)
      real(dp), allocatable, intent(in) :: m(:, :)
      if (ios /= 0) return
      if (allocated(m)) then
        write (u, iostat=ios, iomsg=iom) size(m, 1), size(m, 2), m
      else
        write (u, iostat=ios, iomsg=iom) -1, -1
      end if
    end subroutine put_matrix
  end subroutine write_element

  subroutine put_reals(u, v, ios, iom)
    integer, intent(in) :: u
    real(dp), intent(in) :: v(:)
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    if (ios == 0) write (u, iostat=ios, iomsg=iom) size(v), v
  end subroutine put_reals

  subroutine put_ints(u, v, ios, iom)
    integer, intent(in) :: u
    integer, intent(in) :: v(:)
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    if (ios == 0) write (u, iostat=ios, iomsg=iom) size(v), v
  end subroutine put_ints

  subroutine put_flags(u, v, ios, iom)
    integer, intent(in) :: u
    logical, intent(in) :: v(:)
    integer, intent(inout) :: ios
    character(len=*), intent(inout) :: iom
    if (ios == 0) write (u, iostat=ios, iomsg=iom) size(v), merge(1, 0, v)
  end subroutine put_flags

  !> Size in bits of the run summary record as this build writes it (restart_write writes the type whole).
  pure integer function summary_bits()
    type(run_summary_t) :: probe
    summary_bits = int(storage_size(probe))
  end function summary_bits

  !> Read a checkpoint written for the model whose fingerprint ck holds (nnode, nelem, ndof, checksum) into ck and
  !> the analysis state s, which the analysis has initialised from the deck: every array of the file must have the
  !> size and shape the deck gives it (element states: those this process holds). stat: 0 ok, 2 not readable or
  !> another model (errmsg); s is then undefined.
  subroutine restart_read(path, ck, s, stat, errmsg)
    character(len=*), intent(in) :: path                 !< JOB.rst (JOB.rst.RofN of a distributed run)
    type(checkpoint_t), intent(inout) :: ck              !< in: the fingerprint of this run; out: the record read
    type(analysis_state_t), intent(inout) :: s           !< the analysis state (initialised from the deck)
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: u, ios, ie
    character(len=8) :: magic
    character(len=256) :: iom
    logical :: ok
    stat = 2
    open (newunit=u, file=path, access='stream', form='unformatted', status='old', action='read', iostat=ios, &
      iomsg=iom)
    if (ios /= 0) then
      errmsg = path//': cannot open the restart file: '//trim(iom)
      return
    end if
    call read_header(u, path, ck, errmsg)
    if (len(errmsg) > 0) then
      close (u)
      return
    end if
    ios = 0
    ok = .true.
    call read_state(u, s, ck%nelem, ios, ok)
    if (.not. ok .and. ios == 0) then
      errmsg = path//': the analysis state has other dimensions than the deck''s'
      close (u)
      return
    end if
    do ie = 1, size(s%conv)
      call read_element(u, s%conv(ie), ios, ok)
      if (.not. ok .and. ios == 0) then
        errmsg = path//': the state of element number '//itoa(ie)//' has other dimensions than the deck''s'
        close (u)
        return
      end if
    end do
    if (ios == 0 .and. ok) read (u, iostat=ios) ck%marks%csv_rows, ck%marks%last_frame_inc, ck%marks%next_mark, &
      ck%summary
    call get_reals_sized(u, ck%frame_times, ios, ok)
    magic = ''
    if (ios == 0 .and. ok) read (u, iostat=ios) magic
    close (u)
    if (ios /= 0 .or. .not. ok .or. magic /= end_magic) then
      errmsg = path//': truncated or damaged restart file'
    else if (s%progress%step < 1 .or. s%progress%kinc < 1 .or. ck%marks%csv_rows < 0 .or. &
        s%progress%kinc_total < 1) then
      errmsg = path//': damaged restart file (step/increment counters)'
    else
      stat = 0
    end if
  end subroutine restart_read

  !> The header: magic, version, summary size, fingerprint against ck's; errmsg = '' when they agree.
  subroutine read_header(u, path, ck, errmsg)
    integer, intent(in) :: u                             !< unit (stream, unformatted)
    character(len=*), intent(in) :: path                 !< the file (messages)
    type(checkpoint_t), intent(in) :: ck                 !< the expected fingerprint
    character(len=:), allocatable, intent(out) :: errmsg !< '' or why the file is refused
    character(len=8) :: magic
    character(len=200) :: line
    integer :: ios, version, bits, nnode, nelem, ndof
    integer(i8) :: checksum
    errmsg = ''
    magic = ''
    read (u, iostat=ios) magic
    if (ios /= 0 .or. magic /= restart_magic) then
      errmsg = path//': not an ldfcz restart file'
      return
    end if
    read (u, iostat=ios) version
    if (ios /= 0 .or. version /= restart_version) then
      write (line, '(a,i0,a,i0,a)') ': restart file format version ', version, ', this ldfcz reads version ', &
        restart_version, ' only (a file of another version of ldfcz: restart with the program that wrote it)'
      errmsg = path//trim(line)
      return
    end if
    read (u, iostat=ios) bits
    if (ios == 0 .and. bits /= summary_bits()) then
      write (line, '(a,i0,a,i0,a)') ': written by another build of ldfcz (its run summary record holds ', bits / 8, &
        ' bytes, this build''s ', summary_bits() / 8, '); restart with the program that wrote the file'
      errmsg = path//trim(line)
      return
    end if
    if (ios == 0) read (u, iostat=ios) nnode, nelem, ndof, checksum
    if (ios /= 0) then
      errmsg = path//': truncated restart file'
      return
    end if
    if (nnode /= ck%nnode .or. nelem /= ck%nelem .or. ndof /= ck%ndof .or. checksum /= ck%checksum) then
      write (line, '(3(a,i0,a,i0),a)') ' (file: ', nnode, ' nodes, deck: ', ck%nnode, '; ', nelem, &
        ' elements vs ', ck%nelem, '; ', ndof, ' dofs vs ', ck%ndof, ')'
      if (nnode == ck%nnode .and. nelem == ck%nelem .and. ndof == ck%ndof) &
        line = ' (same sizes, but the checksum of the numbers differs; a distributed run: or another partition, '// &
        'i.e. other --element-weights or --partition-pieces)'
      errmsg = path//': the restart file was written for a different model than this deck'//trim(line)// &
        '; restart with the deck that wrote it'
    end if
  end subroutine read_header

  !> The analysis state but the element states, into the arrays the deck sized (ok = .false.: another size).
  subroutine read_state(u, s, nelem, ios, ok)
    integer, intent(in) :: u                     !< unit (stream, unformatted)
    type(analysis_state_t), intent(inout) :: s   !< the state
    integer, intent(in) :: nelem                 !< elements of the model
    integer, intent(inout) :: ios                !< iostat
    logical, intent(inout) :: ok                 !< the sizes agree
    integer :: idirect
    if (ios /= 0 .or. .not. ok) return
    associate (p => s%progress, sc => s%progress%sc)
      read (u, iostat=ios) p%step, p%kinc, p%kinc_total, p%reuse_count, p%t_total0, p%q_sum, sc%period, sc%dt_min, &
        sc%dt_max, idirect, sc%easy_iterations, sc%t, sc%dt, sc%easy_count, sc%cutbacks, sc%total_cutbacks
      sc%direct = idirect == 1
    end associate
    call get_flags(u, s%bc%on, ios, ok)
    call get_flags(u, s%bc%init, ios, ok)
    call get_flags(u, s%bc%vel, ios, ok)
    call get_flags(u, s%bc%user, ios, ok)
    call get_reals(u, s%bc%val, ios, ok)
    call get_ints(u, s%bc%amp, ios, ok)
    call get_reals(u, s%bc%rate, ios, ok)
    call get_reals(u, s%bc%u_start, ios, ok)
    call read_load(u, s%loads%cload, ios, ok)
    call read_load(u, s%loads%temperature, ios, ok)
    call read_load(u, s%loads%field, ios, ok)
    call read_dload(u, s%loads%dload, nelem, ios, ok)
    if (ios == 0 .and. ok) read (u, iostat=ios) s%last%dt, s%last%dt_before
    call get_reals(u, s%last%du, ios, ok)
    call get_reals(u, s%last%du_before, ios, ok)
    call get_reals(u, s%last%rf, ios, ok)
    call get_reals(u, s%last%fext, ios, ok)
    call get_reals(u, s%last%fcl, ios, ok)
    call get_reals(u, s%last%fremove, ios, ok)
    call get_reals(u, s%u_conv, ios, ok)
    call get_reals(u, s%temp_start, ios, ok)
    call get_reals(u, s%field_start, ios, ok)
    call get_flags(u, s%active, ios, ok)
    call get_flags(u, s%shifted, ios, ok)
    call get_reals(u, s%u_ref, ios, ok)
  end subroutine read_state

  subroutine read_load(u, ls, ios, ok)
    integer, intent(in) :: u
    type(load_state_t), intent(inout) :: ls
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    call get_flags(u, ls%on, ios, ok)
    call get_reals(u, ls%base, ios, ok)
    call get_reals(u, ls%target, ios, ok)
    call get_ints(u, ls%amp, ios, ok)
    call get_reals(u, ls%released, ios, ok)
  end subroutine read_load

  !> The distributed-load records as many as the file holds, then their index by element.
  subroutine read_dload(u, ds, nelem, ios, ok)
    integer, intent(in) :: u
    type(dload_state_t), intent(inout) :: ds
    integer, intent(in) :: nelem
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: n
    real(dp), allocatable :: v(:)
    if (ios /= 0 .or. .not. ok) return
    read (u, iostat=ios) n, ds%step, ds%t_total0
    if (ios /= 0) return
    if (n < 0 .or. n > max_records) then
      ios = -1
      return
    end if
    ds%n = n
    if (allocated(ds%elem)) deallocate (ds%elem, ds%kind, ds%label, ds%amp, ds%removed, ds%base, ds%target, ds%axis)
    allocate (ds%elem(n), ds%kind(n), ds%label(n), ds%amp(n), ds%removed(n), ds%base(3, n), ds%target(3, n), &
      ds%axis(6, n))
    if (n > 0) then
      call get_ints(u, ds%elem, ios, ok)
      call get_ints(u, ds%kind, ios, ok)
      call get_ints(u, ds%label, ios, ok)
      call get_ints(u, ds%amp, ios, ok)
      call get_flags(u, ds%removed, ios, ok)
      allocate (v(3 * n))
      call get_reals(u, v, ios, ok)
      ds%base = reshape(v, [3, n])
      call get_reals(u, v, ios, ok)
      ds%target = reshape(v, [3, n])
      deallocate (v)
      allocate (v(6 * n))
      call get_reals(u, v, ios, ok)
      ds%axis = reshape(v, [6, n])
      if (ios /= 0 .or. .not. ok) return
      if (any(ds%elem < 1 .or. ds%elem > nelem)) then
        ios = -1
        return
      end if
    end if
    call dload_reindex(ds, nelem)
  end subroutine read_dload

  !> One element's converged state into the arrays the deck gave it (ok = .false.: another shape or holder).
  subroutine read_element(u, e, ios, ok)
    integer, intent(in) :: u
    type(elem_state_t), intent(inout) :: e
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: m
    if (ios /= 0 .or. .not. ok) return
    read (u, iostat=ios) e%energy, m
    if (ios /= 0) return
    if (m < 0) then
      ok = .not. allocated(e%svars)
    else if (.not. allocated(e%svars)) then
      ok = .false.
    else if (size(e%svars) /= m) then
      ok = .false.
    else
      read (u, iostat=ios) e%svars
    end if
    call get_matrix(e%stress)
    call get_matrix(e%stran)
    call get_matrix(e%statev)
    call get_matrix(e%eip)
  contains
    subroutine get_matrix(a)
      real(dp), allocatable, intent(inout) :: a(:, :)
      integer :: m1, m2
      if (ios /= 0 .or. .not. ok) return
      read (u, iostat=ios) m1, m2
      if (ios /= 0) return
      if (m1 < 0) then
        ok = .not. allocated(a)
      else if (.not. allocated(a)) then
        ok = .false.
      else if (size(a, 1) /= m1 .or. size(a, 2) /= m2) then
        ok = .false.
      else
        read (u, iostat=ios) a
      end if
    end subroutine get_matrix
  end subroutine read_element

  !> v (sized by the deck) from the file; ok = .false. when the file's size differs.
  subroutine get_reals(u, v, ios, ok)
    integer, intent(in) :: u
    real(dp), intent(inout) :: v(:)
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: m
    if (ios /= 0 .or. .not. ok) return
    read (u, iostat=ios) m
    if (ios /= 0) return
    ok = m == size(v)
    if (ok) read (u, iostat=ios) v
  end subroutine get_reals

  subroutine get_ints(u, v, ios, ok)
    integer, intent(in) :: u
    integer, intent(inout) :: v(:)
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: m
    if (ios /= 0 .or. .not. ok) return
    read (u, iostat=ios) m
    if (ios /= 0) return
    ok = m == size(v)
    if (ok) read (u, iostat=ios) v
  end subroutine get_ints

  subroutine get_flags(u, v, ios, ok)
    integer, intent(in) :: u
    logical, intent(inout) :: v(:)
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: w(size(v))
    call get_ints(u, w, ios, ok)
    if (ios == 0 .and. ok) v = w == 1
  end subroutine get_flags

  !> v, sized by the file.
  subroutine get_reals_sized(u, v, ios, ok)
    integer, intent(in) :: u
    real(dp), allocatable, intent(inout) :: v(:)
    integer, intent(inout) :: ios
    logical, intent(inout) :: ok
    integer :: m
    if (ios /= 0 .or. .not. ok) return
    read (u, iostat=ios) m
    if (ios /= 0) return
    if (m < 0 .or. m > max_records) then
      ios = -1
      return
    end if
    if (allocated(v)) deallocate (v)
    allocate (v(m))
    read (u, iostat=ios) v
  end subroutine get_reals_sized

end module restart_file
