!> Restart file JOB.rst (docs/host.md, "Restart"): everything the static solver needs to continue an analysis from
!> a converged increment so that the continuation repeats the uninterrupted run's arithmetic bit for bit.
!>
!> Format: unformatted stream (native byte order), in this order: magic 'LDFCZRST', format version, the size in
!> bits of the run summary record (written whole, so that a build whose summary type has other fields refuses the
!> file by name instead of misreading it), the model fingerprint (nodes, elements, dofs, checksum of the model's
!> numbers: restart_checksum), the increment loop's state whole (analysis_state: position, counters, times,
!> increment control, boundary tables, the dof vectors the next increment starts from), the converged displacement
!> and internal forces, per element the converged ENERGY, SVARS, stress, strain, STATEV and energy densities (each
!> array preceded by its shape), the summary counters, the VTU frame times, and the end marker 'LDFCZEND' (a
!> truncated file is refused). Written to JOB.rst.tmp, flushed, closed and renamed over JOB.rst (rename(2) is
!> atomic): a kill at any moment leaves the previous or the new restart file, never a partial one.
module restart_file
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use ldfcz_kinds, only: dp, i8
  use model_types, only: model_t
  use analysis_core, only: elem_state_t
  use analysis_state, only: analysis_state_t, analysis_state_write, analysis_state_read
  use run_summary, only: run_summary_t
  implicit none
  private
  public :: restart_state_t, restart_write, restart_read, restart_checksum, restart_magic, restart_version

  character(len=8), parameter :: restart_magic = 'LDFCZRST'  !< first 8 bytes of a restart file
  character(len=8), parameter :: end_magic = 'LDFCZEND'      !< last 8 bytes
  !> format version: 6 adds the summary record's size to the header (version 5 files of builds before and after
  !> the summary gained a field could not be told apart); 7: a process of a distributed run writes the states of
  !> its own elements only (the others as absent), which a version 6 reader would take for another model
  integer, parameter :: restart_version = 7

  !> The solver state at the end of a converged increment (element states are passed separately).
  type :: restart_state_t
    ! model fingerprint
    integer :: nnode = 0, nelem = 0, ndof = 0
    integer(i8) :: checksum = 0
    type(analysis_state_t) :: state      !< the increment loop's state, whole (analysis_state)
    real(dp), allocatable :: u_conv(:)   !< (ndof) converged displacement
    real(dp), allocatable :: fint(:)     !< (ndof) its internal forces
    type(run_summary_t) :: summary       !< summary counters and accumulators (factorizations: the whole run's)
    ! VTU frames
    integer :: nframe = 0                !< frames written (JOB_0001.vtu ...)
    real(dp), allocatable :: frame_times(:) !< (nframe) total time of each frame (JOB.pvd)
  end type restart_state_t

  interface
    function c_rename(from, to) bind(c, name='rename') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: from(*), to(*)
      integer(c_int) :: r
    end function c_rename
  end interface

contains

  !> Checksum of the numbers of the model that determine the analysis: coordinates, connectivity, element kinds,
  !> sections, materials, user element types and properties, amplitudes, boundaries and the steps' data (not the
  !> output requests). Two 31-bit polynomial hashes over the 32-bit halves of every number, combined.
  function restart_checksum(model) result(h)
    type(model_t), intent(in) :: model  !< the model
    integer(i8) :: h
    integer(i8) :: a, b
    integer :: k, j
    a = 1
    b = 7
    call hi(model%ndim)
    call hi(model%nnode)
    call hi(model%nelem)
    if (model%nnode > 0) then
      call hia(model%node_id(1:model%nnode))
      call hra(reshape(model%x(:, 1:model%nnode), [3 * model%nnode]))
    end if
    if (model%nelem > 0) then
      call hia(model%elem_id(1:model%nelem))
      call hia(model%elem_kind(1:model%nelem))
      call hia(model%conn_ptr(1:model%nelem + 1))
      call hia(model%conn(1:model%conn_ptr(model%nelem + 1) - 1))
      if (allocated(model%elem_section)) call hia(model%elem_section)
      if (allocated(model%elem_uelprop)) call hia(model%elem_uelprop)
      if (allocated(model%elem_utype)) call hia(model%elem_utype(1:model%nelem))
      ! *TRANSFORM: the solution vector holds local components at those nodes
      if (allocated(model%node_transform)) then
        if (any(model%node_transform /= 0)) call hia(model%node_transform)
        do k = 1, model%ntransform
          call hra([model%transforms(k)%axes%a, model%transforms(k)%axes%b, model%transforms(k)%axes%c])
          call hi(model%transforms(k)%axes%system)
        end do
      end if
    end if
    do k = 1, model%nsection
      call hr(model%sections(k)%thickness)
      call hs(model%sections(k)%material)
    end do
    do k = 1, model%nmat
      call hs(model%materials(k)%name)
      call hr(model%materials(k)%young)
      call hr(model%materials(k)%poisson)
      call hi(model%materials(k)%nstatv)
      call hl(model%materials(k)%unsymm)
      if (allocated(model%materials(k)%props)) call hra(model%materials(k)%props)
      ! the general *ELASTIC/*EXPANSION tables (the constant isotropic ones are young, poisson above)
      if (allocated(model%materials(k)%elastic_data)) call hra([real(model%materials(k)%elastic_kind, dp), &
        model%materials(k)%elastic_temp, pack(model%materials(k)%elastic_data, .true.)])
      if (allocated(model%materials(k)%expansion_data)) call hra([real(model%materials(k)%expansion_kind, dp), &
        model%materials(k)%expansion_zero, model%materials(k)%expansion_temp, &
        pack(model%materials(k)%expansion_data, .true.)])
    end do
    do k = 1, model%nutype
      associate (ut => model%utypes(k))
        call hia([ut%jtype, ut%nnode, ut%mcrd, ut%nprops, ut%njprops, ut%nsvars])
        call hl(ut%unsymm)
        if (allocated(ut%active)) call hia(ut%active)
      end associate
    end do
    do k = 1, model%n_uelprop
      call hra(model%uelprops(k)%props)
      call hia(model%uelprops(k)%jprops)
    end do
    do k = 1, model%namp
      call hra(model%amplitudes(k)%t)
      call hra(model%amplitudes(k)%a)
    end do
    do k = 1, model%n_initial_bc
      call hbc(model%initial_bcs(k)%nodes, model%initial_bcs(k)%first_dof, model%initial_bcs(k)%last_dof, &
        model%initial_bcs(k)%value, model%initial_bcs(k)%amplitude)
    end do
    call hi(model%nstep)
    do k = 1, model%nstep
      associate (st => model%steps(k))
        call hl(st%nlgeom)
        call hl(st%direct)
        call hl(st%extrapolate)
        call hl(st%unsymm)
        call hl(st%op_new)
        call hia([st%max_inc, st%max_iter, st%nbc])
        call hra([st%dt_initial, st%period, st%dt_min, st%dt_max, st%r_n, st%c_n])
        do j = 1, st%nbc
          call hbc(st%bcs(j)%nodes, st%bcs(j)%first_dof, st%bcs(j)%last_dof, st%bcs(j)%value, st%bcs(j)%amplitude)
        end do
      end associate
    end do
    h = a * 2147483648_i8 + b

  contains

    subroutine h32(w)
      integer(i8), intent(in) :: w   ! 0 <= w < 2**32
      a = mod(a * 16777619_i8 + w, 2147483647_i8)
      b = mod(b * 1000003_i8 + w + 1_i8, 2147483629_i8)
    end subroutine h32

    subroutine h64(w)
      integer(i8), intent(in) :: w
      call h32(ibits(w, 0, 32))
      call h32(ibits(w, 32, 32))
    end subroutine h64

    subroutine hi(i)
      integer, intent(in) :: i
      call h64(int(i, i8))
    end subroutine hi

    subroutine hia(v)
      integer, intent(in) :: v(:)
      integer :: m
      call hi(size(v))
      do m = 1, size(v)
        call hi(v(m))
      end do
    end subroutine hia

    subroutine hr(x)
      real(dp), intent(in) :: x
      call h64(transfer(x, 0_i8))
    end subroutine hr

    subroutine hra(v)
      real(dp), intent(in) :: v(:)
      integer :: m
      call hi(size(v))
      do m = 1, size(v)
        call hr(v(m))
      end do
    end subroutine hra

    subroutine hl(l)
      logical, intent(in) :: l
      call hi(merge(1, 0, l))
    end subroutine hl

    subroutine hs(s)
      character(len=*), intent(in) :: s
      integer :: m
      do m = 1, len_trim(s)
        call hi(ichar(s(m:m)))
      end do
      call hi(-1)
    end subroutine hs

    subroutine hbc(nodes, d1, d2, v, amp)
      integer, intent(in) :: nodes(:), d1, d2, amp
      real(dp), intent(in) :: v
      call hia(nodes)
      call hia([d1, d2, amp])
      call hr(v)
    end subroutine hbc

  end function restart_checksum

  !> Write the restart file atomically: path.tmp, close, fsync, rename to path. stat /= 0: not written (errmsg).
  subroutine restart_write(path, rs, elems, stat, errmsg)
    character(len=*), intent(in) :: path                 !< JOB.rst
    type(restart_state_t), intent(in) :: rs              !< solver state
    type(elem_state_t), intent(in) :: elems(:)           !< converged element states
    integer, intent(out) :: stat                         !< 0 ok
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: u, ios, ie, nfr
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
    write (u, iostat=ios, iomsg=iom) restart_magic, restart_version, summary_bits(), rs%nnode, rs%nelem, rs%ndof, &
      rs%checksum
    if (ios == 0) call analysis_state_write(u, rs%state, ios, iom)
    if (ios == 0) write (u, iostat=ios, iomsg=iom) rs%u_conv, rs%fint
    do ie = 1, size(elems)
      if (ios /= 0) exit
      write (u, iostat=ios, iomsg=iom) elems(ie)%energy
      if (ios == 0) call write_vec(elems(ie)%svars)
      if (ios == 0) call write_mat(elems(ie)%stress)
      if (ios == 0) call write_mat(elems(ie)%stran)
      if (ios == 0) call write_mat(elems(ie)%statev)
      if (ios == 0) call write_mat(elems(ie)%eip)
    end do
    if (ios == 0) write (u, iostat=ios, iomsg=iom) rs%summary
    nfr = 0
    if (allocated(rs%frame_times)) nfr = size(rs%frame_times)
    if (ios == 0 .and. nfr > 0) write (u, iostat=ios, iomsg=iom) nfr, rs%frame_times, end_magic
    if (ios == 0 .and. nfr == 0) write (u, iostat=ios, iomsg=iom) nfr, end_magic
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

  contains

    subroutine write_vec(v)
      real(dp), allocatable, intent(in) :: v(:)
      if (allocated(v)) then
        write (u, iostat=ios, iomsg=iom) size(v), v
      else
        write (u, iostat=ios, iomsg=iom) -1
      end if
    end subroutine write_vec

    subroutine write_mat(m)
      real(dp), allocatable, intent(in) :: m(:, :)
      if (allocated(m)) then
        write (u, iostat=ios, iomsg=iom) size(m, 1), size(m, 2), m
      else
        write (u, iostat=ios, iomsg=iom) -1, -1
      end if
    end subroutine write_mat

  end subroutine restart_write

  !> Size in bits of the run summary record as this build writes it (restart_write writes the type whole).
  pure integer function summary_bits()
    type(run_summary_t) :: probe
    summary_bits = int(storage_size(probe))
  end function summary_bits

  !> Read a restart file written for the model whose fingerprint is in expect (nnode, nelem, ndof, checksum).
  !> The element states go into elems, whose arrays must already have the shapes of the file's (the analysis
  !> allocates them from the deck): a different shape is refused. stat: 0 ok, 2 not readable or another model.
  subroutine restart_read(path, expect, rs, elems, stat, errmsg)
    character(len=*), intent(in) :: path                 !< JOB.rst
    type(restart_state_t), intent(in) :: expect          !< fingerprint of the model of this run
    type(restart_state_t), intent(out) :: rs             !< solver state read
    type(elem_state_t), intent(inout) :: elems(:)        !< element states (allocated by the analysis)
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    integer :: u, ios, ie, version, bits
    character(len=8) :: magic
    character(len=256) :: iom
    character(len=200) :: line
    logical :: shape_ok
    stat = 2
    errmsg = ''
    open (newunit=u, file=path, access='stream', form='unformatted', status='old', action='read', iostat=ios, &
      iomsg=iom)
    if (ios /= 0) then
      errmsg = path//': cannot open the restart file: '//trim(iom)
      return
    end if
    magic = ''
    read (u, iostat=ios) magic
    if (ios /= 0 .or. magic /= restart_magic) then
      errmsg = path//': not an ldfcz restart file'
      close (u)
      return
    end if
    read (u, iostat=ios) version
    if (ios /= 0 .or. version /= restart_version) then
      write (line, '(a,i0,a,i0,a)') ': restart file format version ', version, ', this ldfcz reads version ', &
        restart_version, ' only'
      errmsg = path//trim(line)
      close (u)
      return
    end if
    read (u, iostat=ios) bits
    if (ios == 0 .and. bits /= summary_bits()) then
      write (line, '(a,i0,a,i0,a)') ': written by another build of ldfcz (its run summary record holds ', bits / 8, &
        ' bytes, this build''s ', summary_bits() / 8, '); restart with the program that wrote the file'
      errmsg = path//trim(line)
      close (u)
      return
    end if
    if (ios == 0) read (u, iostat=ios) rs%nnode, rs%nelem, rs%ndof, rs%checksum
    if (ios /= 0) then
      errmsg = path//': truncated restart file'
      close (u)
      return
    end if
    if (rs%nnode /= expect%nnode .or. rs%nelem /= expect%nelem .or. rs%ndof /= expect%ndof .or. &
        rs%checksum /= expect%checksum) then
      write (line, '(3(a,i0,a,i0),a)') ' (file: ', rs%nnode, ' nodes, deck: ', expect%nnode, '; ', rs%nelem, &
        ' elements vs ', expect%nelem, '; ', rs%ndof, ' dofs vs ', expect%ndof, ')'
      if (rs%nnode == expect%nnode .and. rs%nelem == expect%nelem .and. rs%ndof == expect%ndof) &
        line = ' (same sizes, but the checksum of the numbers differs; a distributed run: or another partition, '// &
        'i.e. other --element-weights or --partition-pieces)'
      errmsg = path//': the restart file was written for a different model than this deck'//trim(line)// &
        '; restart with the deck that wrote it'
      close (u)
      return
    end if
    call analysis_state_read(u, rs%ndof, rs%state, ios)
    allocate (rs%u_conv(rs%ndof), rs%fint(rs%ndof))
    if (ios == 0) read (u, iostat=ios) rs%u_conv, rs%fint
    shape_ok = .true.
    do ie = 1, size(elems)
      if (ios /= 0 .or. .not. shape_ok) exit
      read (u, iostat=ios) elems(ie)%energy
      if (ios == 0) call read_vec(elems(ie)%svars)
      if (ios == 0 .and. shape_ok) call read_mat(elems(ie)%stress)
      if (ios == 0 .and. shape_ok) call read_mat(elems(ie)%stran)
      if (ios == 0 .and. shape_ok) call read_mat(elems(ie)%statev)
      if (ios == 0 .and. shape_ok) call read_mat(elems(ie)%eip)
      if (.not. shape_ok) then
        write (line, '(a,i0,a)') ': the state of element number ', ie, ' has other dimensions than the deck''s'
        errmsg = path//trim(line)
        close (u)
        return
      end if
    end do
    if (ios == 0) read (u, iostat=ios) rs%summary
    if (ios == 0) read (u, iostat=ios) rs%nframe
    if (ios == 0 .and. (rs%nframe < 0 .or. rs%nframe > 100000000)) ios = -1
    if (ios == 0) then
      allocate (rs%frame_times(rs%nframe))
      read (u, iostat=ios) rs%frame_times, magic
    end if
    close (u)
    if (ios /= 0 .or. magic /= end_magic) then
      errmsg = path//': truncated or damaged restart file'
      return
    end if
    if (rs%state%step < 1 .or. rs%state%kinc < 1 .or. rs%state%csv_rows < 0 .or. rs%state%kinc_total < 1) then
      errmsg = path//': damaged restart file (step/increment counters)'
      return
    end if
    stat = 0

  contains

    subroutine read_vec(v)
      real(dp), allocatable, intent(inout) :: v(:)
      integer :: m
      read (u, iostat=ios) m
      if (ios /= 0) return
      if (m < 0) then
        shape_ok = .not. allocated(v)
        return
      end if
      if (.not. allocated(v)) then
        shape_ok = .false.
        return
      end if
      if (size(v) /= m) then
        shape_ok = .false.
        return
      end if
      read (u, iostat=ios) v
    end subroutine read_vec

    subroutine read_mat(m)
      real(dp), allocatable, intent(inout) :: m(:, :)
      integer :: m1, m2
      read (u, iostat=ios) m1, m2
      if (ios /= 0) return
      if (m1 < 0) then
        shape_ok = .not. allocated(m)
        return
      end if
      if (.not. allocated(m)) then
        shape_ok = .false.
        return
      end if
      if (size(m, 1) /= m1 .or. size(m, 2) /= m2) then
        shape_ok = .false.
        return
      end if
      read (u, iostat=ios) m
    end subroutine read_mat

  end subroutine restart_read

end module restart_file
