!> Output files of a run: JOB.csv (history of set totals, one row per converged increment), JOB.sta (one line per
!> increment attempt), JOB.log (messages and the closing summary), JOB.pvd + JOB_NNNN.vtu (ParaView field frames),
!> JOB.dat (standard output of the job: what user routines write to unit 6, as in Abaqus) and a live one-line
!> progress display when the console is a terminal. Host messages go to the console (console_output).
module output_files
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use, intrinsic :: iso_fortran_env, only: iostat_end, iostat_eor
  use ldfcz_kinds, only: dp
  use console_output, only: console_line, console_text, console_to_dat, console_is_terminal
  implicit none
  private
  public :: output_t, output_open, output_close, output_log, output_csv_header, output_csv_row, output_sta
  public :: output_progress, output_progress_clear, output_vtu_frame, output_vtu_t, output_vtu_array_t
  public :: stdout_is_terminal
  public :: output_csv_resume, output_frames_resume, output_sta_note, output_note, output_discard_empty

  !> One data array of a VTU frame (point or cell data): its name, component names (none for a scalar or a
  !> vector written without names) and values, Float64 or Int32. The writer (field_frame) fills them from the
  !> output registry, in VTK's component order.
  type :: output_vtu_array_t
    character(len=64) :: name = ''           !< array name (SDV_key names of *DEPVAR keys may be long)
    integer :: ncomp = 1                     !< components
    character(len=8), allocatable :: comp_names(:) !< (ncomp) ComponentName attributes (absent: none written)
    logical :: int32 = .false.               !< integer values (written as Int32)
    real(dp), allocatable :: v(:, :)         !< (ncomp, npoint or ncell) values
  end type output_vtu_array_t

  !> The mesh and the data arrays of one VTU frame.
  type :: output_vtu_t
    real(dp), allocatable :: x(:, :)         !< (3, npoint) original coordinates
    integer, allocatable :: cell_type(:)     !< VTK cell type per cell
    integer, allocatable :: cell_ptr(:)      !< (ncell+1) into cell_conn
    integer, allocatable :: cell_conn(:)     !< 0-based point indices
    type(output_vtu_array_t), allocatable :: points(:) !< point data
    type(output_vtu_array_t), allocatable :: cells(:)  !< cell data
    character(len=16) :: vectors = ''        !< the point data's active vectors ('' none)
    character(len=16) :: scalars = ''        !< the cell data's active scalars ('' none)
  end type output_vtu_t

  type :: output_t
    character(len=:), allocatable :: job     !< job name
    character(len=:), allocatable :: dir     !< output directory
    logical :: quiet = .false.               !< no echo of the log on standard output
    logical :: silent = .false.              !< writes nothing (a process other than rank 0 of an MPI run)
    integer :: npieces = 1                   !< pieces of a VTU frame (MPI: one per process, JOB_NNNN.pvtu)
    integer :: nblocks = 1                   !< blocks of a frame: 2 = continuum and interface (JOB_NNNN.vtm)
    logical :: tty = .false.                 !< standard output is a terminal
    integer :: csv = -1, sta = -1, log = -1, pvd = -1
    integer :: nframe = 0
    real(dp) :: t_output = 0.0_dp            !< wall seconds spent writing output
    logical :: progress_shown = .false.
    real(dp), allocatable :: frame_times(:)  !< total time of each VTU frame (for JOB.pvd)
  end type output_t

  interface
    function c_rename(from, to) bind(c, name='rename') result(r)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: from(*), to(*)
      integer(c_int) :: r
    end function c_rename
  end interface

contains

  !> True when the console (standard output as the program was started) is a terminal.
  logical function stdout_is_terminal()
    stdout_is_terminal = console_is_terminal()
  end function stdout_is_terminal

  !> Open JOB.csv, JOB.sta and JOB.log in dir and send standard output (unit 6) to JOB.dat. append (a restart):
  !> JOB.sta, JOB.log and JOB.dat are continued and JOB.csv is left closed for output_csv_resume. silent (ranks
  !> other than 0 of an MPI run): nothing is opened and standard output stays on the console.
  subroutine output_open(out, job, dir, quiet, stat, errmsg, append, silent)
    type(output_t), intent(out) :: out                   !< output state
    character(len=*), intent(in) :: job                  !< job name
    character(len=*), intent(in) :: dir                  !< directory (must exist)
    logical, intent(in) :: quiet                         !< no echo
    integer, intent(out) :: stat                         !< 0 ok, 2 cannot write
    character(len=:), allocatable, intent(out) :: errmsg !< message
    logical, intent(in), optional :: append              !< continue the files of an earlier run (restart)
    !> open nothing and write nothing (the processes other than rank 0 of an MPI run: output is written once)
    logical, intent(in), optional :: silent
    integer :: ios
    logical :: cont
    cont = .false.
    if (present(append)) cont = append
    out%job = job
    out%dir = dir
    out%quiet = quiet
    out%tty = stdout_is_terminal() .and. .not. quiet
    stat = 0
    errmsg = ''
    if (present(silent)) out%silent = silent
    if (out%silent) then
      out%quiet = .true.
      out%tty = .false.
      return
    end if
    if (cont) then
      open (newunit=out%sta, file=path(out, '.sta'), status='unknown', position='append', action='write', iostat=ios)
    else
      open (newunit=out%sta, file=path(out, '.sta'), status='replace', action='write', iostat=ios)
    end if
    if (ios /= 0) then
      stat = 2
      errmsg = 'cannot write '//path(out, '.sta')
      return
    end if
    if (.not. cont) write (out%sta, '(a)') '# step  inc  attempt  iterations  step_time  increment  outcome'
    flush (out%sta)
    call console_to_dat(path(out, '.dat'), cont, ios)
    if (ios /= 0) then
      stat = 2
      errmsg = 'cannot write '//path(out, '.dat')
      return
    end if
    if (cont) then
      open (newunit=out%log, file=path(out, '.log'), status='unknown', position='append', action='write', iostat=ios)
      return
    end if
    open (newunit=out%log, file=path(out, '.log'), status='replace', action='write', iostat=ios)
    open (newunit=out%csv, file=path(out, '.csv'), status='replace', action='write', iostat=ios)
    if (ios /= 0) then
      stat = 2
      errmsg = 'cannot write '//path(out, '.csv')
    end if
  end subroutine output_open

  !> Restart: continue JOB.csv after its first nrows data rows. The header must be the one this run writes; rows
  !> after nrows (written by the interrupted run after its last restart point) are dropped (the file is rewritten
  !> through JOB.csv.tmp and rename(2)). Without a JOB.csv in the output directory a new one starts with the header
  !> (fresh = .true.). stat = 2: the file has another header or fewer rows.
  subroutine output_csv_resume(out, columns, nrows, fresh, stat, errmsg)
    type(output_t), intent(inout) :: out                 !< output state (JOB.csv closed)
    character(len=*), intent(in) :: columns(:)           !< column names after the four time columns
    integer, intent(in) :: nrows                         !< data rows to keep
    logical, intent(out) :: fresh                        !< no JOB.csv was there: a new one was started
    integer, intent(out) :: stat                         !< 0 ok, 2 error
    character(len=:), allocatable, intent(out) :: errmsg !< message
    character(len=:), allocatable :: header, line, fname
    integer :: u, v, ios, k, i
    logical :: exists
    stat = 0
    errmsg = ''
    fresh = .false.
    if (out%silent) return
    fname = path(out, '.csv')
    header = 'step,inc,step_time,total_time'
    do i = 1, size(columns)
      header = header//','//trim(columns(i))
    end do
    inquire (file=fname, exist=exists)
    if (.not. exists) then
      fresh = .true.
      open (newunit=out%csv, file=fname, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
        stat = 2
        errmsg = 'cannot write '//fname
        return
      end if
      call output_csv_header(out, columns)
      return
    end if
    open (newunit=u, file=fname, status='old', action='read', iostat=ios)
    if (ios /= 0) then
      stat = 2
      errmsg = 'cannot read '//fname
      return
    end if
    open (newunit=v, file=fname//'.tmp', status='replace', action='write', iostat=ios)
    if (ios /= 0) then
      close (u)
      stat = 2
      errmsg = 'cannot write '//fname//'.tmp'
      return
    end if
    call read_line(u, line, ios)
    if (ios /= 0 .or. line /= header) then
      stat = 2
      errmsg = fname//': its header is not the one of this deck ('//header//'): restart into the output '// &
        'directory of the run that wrote the restart file'
    else
      write (v, '(a)') line
      do k = 1, nrows
        call read_line(u, line, ios)
        if (ios /= 0) exit
        write (v, '(a)') line
      end do
      if (ios /= 0) then
        stat = 2
        write (errmsg, '(i0)') nrows
        errmsg = fname//': fewer data rows than the '//errmsg//' of the restart file: restart into the output '// &
          'directory of the run that wrote it'
      end if
    end if
    close (u)
    if (stat /= 0) then
      close (v, status='delete')
      return
    end if
    close (v)
    if (c_rename(fname//'.tmp'//c_null_char, fname//c_null_char) /= 0) then
      stat = 2
      errmsg = 'cannot rename '//fname//'.tmp to '//fname
      return
    end if
    open (newunit=out%csv, file=fname, status='old', position='append', action='write', iostat=ios)
    if (ios /= 0) then
      stat = 2
      errmsg = 'cannot write '//fname
    end if
  end subroutine output_csv_resume

  !> One line of any length (ios /= 0 at the end of the file; an unterminated last line counts as a line).
  subroutine read_line(u, line, ios)
    integer, intent(in) :: u
    character(len=:), allocatable, intent(out) :: line
    integer, intent(out) :: ios
    character(len=4096) :: buf
    integer :: n
    line = ''
    do
      read (u, '(a)', advance='no', iostat=ios, size=n) buf
      line = line//buf(1:n)
      if (ios /= 0) exit
    end do
    if (ios == iostat_eor) then
      ios = 0
    else if (ios == iostat_end .and. len(line) > 0) then
      ios = 0
    end if
  end subroutine read_line

  !> Restart: the VTU frames 1..size(frame_times) of the interrupted run are kept; JOB.pvd is rewritten with them and
  !> the next frame gets the next number.
  subroutine output_frames_resume(out, frame_times)
    type(output_t), intent(inout) :: out      !< output state
    real(dp), intent(in) :: frame_times(:)    !< total time of each frame written
    out%frame_times = frame_times
    out%nframe = size(frame_times)
    if (out%nframe > 0 .and. .not. out%silent) call write_pvd(out)
  end subroutine output_frames_resume

  function path(out, suffix) result(p)
    type(output_t), intent(in) :: out
    character(len=*), intent(in) :: suffix
    character(len=:), allocatable :: p
    p = out%dir//'/'//out%job//suffix
  end function path

  !> A line to JOB.log and (unless quiet) standard output.
  subroutine output_log(out, line)
    type(output_t), intent(inout) :: out  !< output state
    character(len=*), intent(in) :: line  !< text
    if (out%log /= -1) then
      write (out%log, '(a)') line
      flush (out%log)
    end if
    if (.not. out%quiet) then
      call output_progress_clear(out)
      call console_line(line)
    end if
  end subroutine output_log

  !> A line to JOB.log only (notes: what has no effect on the results; the console shows warnings, not notes).
  subroutine output_note(out, line)
    type(output_t), intent(inout) :: out  !< output state
    character(len=*), intent(in) :: line  !< text
    if (out%log == -1) return
    write (out%log, '(a)') line
    flush (out%log)
  end subroutine output_note

  !> A run that stops before its analysis (an input error): JOB.csv and JOB.dat are removed when nothing was written
  !> to them, so that no empty job file is left that looks like a result.
  subroutine output_discard_empty(out)
    type(output_t), intent(inout) :: out  !< output state
    integer :: u, ios
    integer(8) :: sz
    logical :: there
    if (out%silent) return
    if (out%csv /= -1) then
      flush (out%csv)
      inquire (file=path(out, '.csv'), size=sz)
      if (sz == 0) then
        close (out%csv, status='delete')
        out%csv = -1
      end if
    end if
    inquire (file=path(out, '.dat'), exist=there, size=sz)
    if (there .and. sz == 0) then
      open (newunit=u, file=path(out, '.dat'), status='old', iostat=ios)
      if (ios == 0) close (u, status='delete')
    end if
  end subroutine output_discard_empty

  !> Header of JOB.csv.
  subroutine output_csv_header(out, columns)
    type(output_t), intent(inout) :: out          !< output state
    character(len=*), intent(in) :: columns(:)    !< column names after the four time columns
    integer :: i
    if (out%silent) return
    write (out%csv, '(a)', advance='no') 'step,inc,step_time,total_time'
    do i = 1, size(columns)
      write (out%csv, '(a)', advance='no') ','//trim(columns(i))
    end do
    write (out%csv, '(a)') ''
    flush (out%csv)
  end subroutine output_csv_header

  !> One row of JOB.csv, flushed.
  subroutine output_csv_row(out, kstep, kinc, step_time, total_time, values)
    type(output_t), intent(inout) :: out  !< output state
    integer, intent(in) :: kstep, kinc    !< step, increment
    real(dp), intent(in) :: step_time, total_time  !< times at the end of the increment
    real(dp), intent(in) :: values(:)     !< column values
    character(len=32) :: b
    integer :: i
    if (out%silent) return
    write (out%csv, '(i0,a,i0,2(a,es23.15e3))', advance='no') kstep, ',', kinc, ',', step_time, ',', total_time
    do i = 1, size(values)
      write (b, '(es23.15e3)') values(i)
      write (out%csv, '(a)', advance='no') ','//trim(adjustl(b))
    end do
    write (out%csv, '(a)') ''
    flush (out%csv)
  end subroutine output_csv_row

  !> One line of JOB.sta, flushed; residual ratios of the iterations are written with it when given.
  subroutine output_sta(out, kstep, kinc, attempt, iterations, step_time, dt, outcome, ratios)
    type(output_t), intent(inout) :: out          !< output state
    integer, intent(in) :: kstep, kinc, attempt, iterations
    real(dp), intent(in) :: step_time             !< step time at the end of the attempt
    real(dp), intent(in) :: dt                    !< increment size
    character(len=*), intent(in) :: outcome       !< converged, cutback: ..., failed: ...
    real(dp), intent(in), optional :: ratios(:)   !< r_max / q_avg per iteration
    integer :: i
    if (out%silent) return
    write (out%sta, '(i5,i6,i5,i6,2es14.6,2x,a)', advance='no') kstep, kinc, attempt, iterations, step_time, dt, &
      trim(outcome)
    if (present(ratios)) then
      if (size(ratios) > 0) then
        write (out%sta, '(a)', advance='no') '  r/q:'
        do i = 1, size(ratios)
          write (out%sta, '(es10.2)', advance='no') ratios(i)
        end do
      end if
    end if
    write (out%sta, '(a)') ''
    flush (out%sta)
  end subroutine output_sta

  !> A comment line ('# text') in JOB.sta, flushed.
  subroutine output_sta_note(out, text)
    type(output_t), intent(inout) :: out  !< output state
    character(len=*), intent(in) :: text  !< the note
    if (out%silent) return
    write (out%sta, '(a)') '# '//text
    flush (out%sta)
  end subroutine output_sta_note

  !> Live progress line (terminal only): step, percent of the step, increment, ETA of the step.
  subroutine output_progress(out, kstep, nstep, kinc, step_time, period, wall_step)
    type(output_t), intent(inout) :: out
    integer, intent(in) :: kstep, nstep, kinc
    real(dp), intent(in) :: step_time, period, wall_step  !< step time, period, wall seconds since the step began
    real(dp) :: frac, eta
    character(len=120) :: line
    if (.not. out%tty) return
    frac = step_time / max(period, tiny(1.0_dp))
    eta = 0.0_dp
    if (frac > 0.0_dp) eta = wall_step * (1.0_dp - frac) / frac
    write (line, '(a,i0,a,i0,a,f6.2,a,i0,a,f9.1,a)') 'step ', kstep, '/', nstep, '  ', 100.0_dp * frac, &
      '%  inc ', kinc, '  ETA ', eta, ' s'
    call console_text(achar(13)//trim(line)//achar(27)//'[K')
    out%progress_shown = .true.
  end subroutine output_progress

  subroutine output_progress_clear(out)
    type(output_t), intent(inout) :: out
    if (.not. out%progress_shown) return
    call console_text(achar(13)//achar(27)//'[K')
    out%progress_shown = .false.
  end subroutine output_progress_clear

  !> Write one ASCII VTU frame and rewrite JOB.pvd with every frame so far (valid after each increment). A frame is one
  !> block (JOB_NNNN.vtu) or two: the continuum elements in JOB_NNNN.vtu and the interface (user) elements in
  !> JOB_NNNN_interface.vtu, put together by the multiblock file JOB_NNNN.vtm (blocks named continuum and
  !> interface), which JOB.pvd lists; ParaView opens JOB.pvd (or a .vtm) directly. With npieces > 1 (an MPI run) a
  !> block is this process's piece JOB_NNNN[_interface]_R.vtu (its elements' cells, every point), and the writing
  !> process (rank 0) writes JOB_NNNN[_interface].pvtu listing the pieces, which the .vtm or JOB.pvd lists.
  subroutine output_vtu_frame(out, blocks, total_time, piece, npieces)
    type(output_t), intent(inout) :: out          !< output state
    type(output_vtu_t), intent(in) :: blocks(:)   !< the blocks: one, or the continuum and the interface
    real(dp), intent(in) :: total_time            !< time stamp of the frame
    integer, intent(in), optional :: piece        !< this process's piece (0-based)
    integer, intent(in), optional :: npieces      !< pieces of the frame (processes)
    character(len=:), allocatable :: stem
    character(len=16) :: b, bp
    integer :: k, ios
    integer(8) :: c0, c1, rate
    call system_clock(c0, rate)
    out%nframe = out%nframe + 1
    out%nblocks = size(blocks)
    write (b, '(i4.4)') out%nframe
    if (present(npieces)) out%npieces = max(1, npieces)
    if (.not. allocated(out%frame_times)) allocate (out%frame_times(0))
    out%frame_times = [out%frame_times, total_time]
    do k = 1, size(blocks)
      stem = out%job//'_'//trim(b)//trim(merge('          ', '_interface', k == 1))
      if (out%npieces > 1) then
        write (bp, '(i0)') piece
        if (.not. out%silent) call write_pvtu(out, stem, blocks(k))
        call write_vtu_piece(out%dir//'/'//stem//'_'//trim(bp)//'.vtu', blocks(k), ios)
      else if (.not. out%silent) then
        call write_vtu_piece(out%dir//'/'//stem//'.vtu', blocks(k), ios)
      end if
    end do
    if (.not. out%silent) then
      if (size(blocks) > 1) call write_vtm(out, out%job//'_'//trim(b))
      call write_pvd(out)
    end if
    call system_clock(c1)
    out%t_output = out%t_output + real(c1 - c0, dp) / real(rate, dp)
  end subroutine output_vtu_frame

  !> JOB_NNNN.vtm: the frame's two blocks, continuum and interface (VTK's multiblock file); in an MPI run each
  !> block is a block of the processes' pieces JOB_NNNN[_interface]_R.vtu (VTK 9.1's multiblock reader does not
  !> read .pvtu blocks).
  subroutine write_vtm(out, stem)
    type(output_t), intent(in) :: out
    character(len=*), intent(in) :: stem        !< JOB_NNNN
    integer :: v, ios, k, r
    character(len=*), parameter :: names(2) = [character(len=9) :: 'continuum', 'interface']
    character(len=16) :: bk, br
    open (newunit=v, file=out%dir//'/'//stem//'.vtm', status='replace', action='write', iostat=ios)
    if (ios /= 0) return
    write (v, '(a)') '<?xml version="1.0"?>'
    write (v, '(a)') '<VTKFile type="vtkMultiBlockDataSet" version="1.0" byte_order="LittleEndian">'
    write (v, '(a)') '<vtkMultiBlockDataSet>'
    do k = 1, 2
      write (bk, '(i0)') k - 1
      associate (block => stem//trim(merge('          ', '_interface', k == 1)))
        if (out%npieces > 1) then
          write (v, '(a)') '<Block index="'//trim(bk)//'" name="'//trim(names(k))//'">'
          do r = 0, out%npieces - 1
            write (br, '(i0)') r
            write (v, '(a)') '<DataSet index="'//trim(br)//'" name="process '//trim(br)//'" file="'//block// &
              '_'//trim(br)//'.vtu"/>'
          end do
          write (v, '(a)') '</Block>'
        else
          write (v, '(a)') '<DataSet index="'//trim(bk)//'" name="'//trim(names(k))//'" file="'//block//'.vtu"/>'
        end if
      end associate
    end do
    write (v, '(a)') '</vtkMultiBlockDataSet></VTKFile>'
    close (v)
  end subroutine write_vtm

  !> STEM.pvtu: the arrays of the pieces (names, types, components as write_vtu_piece writes them) and the piece
  !> files of every process, STEM_R.vtu.
  subroutine write_pvtu(out, stem, frame)
    type(output_t), intent(in) :: out
    character(len=*), intent(in) :: stem
    type(output_vtu_t), intent(in) :: frame
    integer :: v, j, ios
    character(len=16) :: bj
    open (newunit=v, file=out%dir//'/'//stem//'.pvtu', status='replace', action='write', iostat=ios)
    if (ios /= 0) return
    write (v, '(a)') '<?xml version="1.0"?>'
    write (v, '(a)') '<VTKFile type="PUnstructuredGrid" version="0.1" byte_order="LittleEndian">'
    write (v, '(a)') '<PUnstructuredGrid GhostLevel="0">'
    write (v, '(a)') '<PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>'
    call pvtu_arrays(v, 'PPointData', frame%points, frame%vectors, 'Vectors')
    call pvtu_arrays(v, 'PCellData', frame%cells, frame%scalars, 'Scalars')
    do j = 0, out%npieces - 1
      write (bj, '(i0)') j
      write (v, '(a)') '<Piece Source="'//stem//'_'//trim(bj)//'.vtu"/>'
    end do
    write (v, '(a)') '</PUnstructuredGrid></VTKFile>'
    close (v)
  end subroutine write_pvtu

  !> The <PPointData>/<PCellData> block of a .pvtu.
  subroutine pvtu_arrays(v, tag, arrays, active, attr)
    integer, intent(in) :: v
    character(len=*), intent(in) :: tag, active, attr
    type(output_vtu_array_t), intent(in) :: arrays(:)
    integer :: j
    character(len=16) :: bc
    if (len_trim(active) > 0) then
      write (v, '(a)') '<'//tag//' '//attr//'="'//trim(active)//'">'
    else
      write (v, '(a)') '<'//tag//'>'
    end if
    do j = 1, size(arrays)
      write (bc, '(i0)') arrays(j)%ncomp
      write (v, '(a)') '<PDataArray type="'//trim(merge('Int32  ', 'Float64', arrays(j)%int32))//'" Name="'// &
        trim(arrays(j)%name)//'"'//trim(merge(' NumberOfComponents="'//trim(bc)//'"', repeat(' ', 30), &
        arrays(j)%ncomp > 1))//'/>'
    end do
    write (v, '(a)') '</'//tag//'>'
  end subroutine pvtu_arrays

  !> One .vtu file: the block's points, cells and arrays (ios /= 0: not written).
  subroutine write_vtu_piece(file, frame, ios)
    character(len=*), intent(in) :: file
    type(output_vtu_t), intent(in) :: frame
    integer, intent(out) :: ios
    integer :: u, i, np, nc, k
    np = size(frame%x, 2)
    nc = size(frame%cell_type)
    open (newunit=u, file=file, status='replace', action='write', iostat=ios)
    if (ios /= 0) return
    write (u, '(a)') '<?xml version="1.0"?>'
    write (u, '(a)') '<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">'
    write (u, '(a)') '<UnstructuredGrid>'
    write (u, '(a,i0,a,i0,a)') '<Piece NumberOfPoints="', np, '" NumberOfCells="', nc, '">'
    write (u, '(a)') '<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">'
    write (u, '(3es16.8)') frame%x
    write (u, '(a)') '</DataArray></Points>'
    write (u, '(a)') '<Cells><DataArray type="Int32" Name="connectivity" format="ascii">'
    do i = 1, nc
      write (u, '(*(i0,1x))') (frame%cell_conn(k), k = frame%cell_ptr(i), frame%cell_ptr(i + 1) - 1)
    end do
    write (u, '(a)') '</DataArray><DataArray type="Int32" Name="offsets" format="ascii">'
    write (u, '(*(i0,1x))') frame%cell_ptr(2:) - 1
    write (u, '(a)') '</DataArray><DataArray type="UInt8" Name="types" format="ascii">'
    write (u, '(*(i0,1x))') frame%cell_type
    write (u, '(a)') '</DataArray></Cells>'
    call write_arrays(u, 'PointData', frame%points, frame%vectors, 'Vectors')
    call write_arrays(u, 'CellData', frame%cells, frame%scalars, 'Scalars')
    write (u, '(a)') '</Piece></UnstructuredGrid></VTKFile>'
    close (u)
  end subroutine write_vtu_piece

  !> The <PointData>/<CellData> block: each array with its components (Float64: 6 values a line, or one point's or
  !> cell's components a line for 3 and 6 components; Int32: one line).
  subroutine write_arrays(u, tag, arrays, active, attr)
    integer, intent(in) :: u
    character(len=*), intent(in) :: tag, active, attr
    type(output_vtu_array_t), intent(in) :: arrays(:)
    integer :: j, c
    character(len=:), allocatable :: head
    character(len=16) :: bc
    if (len_trim(active) > 0) then
      write (u, '(a)') '<'//tag//' '//attr//'="'//trim(active)//'">'
    else
      write (u, '(a)') '<'//tag//'>'
    end if
    do j = 1, size(arrays)
      associate (a => arrays(j))
        head = '<DataArray type="'//trim(merge('Int32  ', 'Float64', a%int32))//'" Name="'//trim(a%name)//'"'
        if (a%ncomp > 1) then
          write (bc, '(i0)') a%ncomp
          head = head//' NumberOfComponents="'//trim(bc)//'"'
        end if
        if (allocated(a%comp_names)) then
          do c = 1, size(a%comp_names)
            write (bc, '(i0)') c - 1
            head = head//' ComponentName'//trim(bc)//'="'//trim(a%comp_names(c))//'"'
          end do
        end if
        write (u, '(a)') head//' format="ascii">'
        if (a%int32) then
          write (u, '(*(i0,1x))') nint(a%v)
        else if (a%ncomp == 3) then
          write (u, '(3es16.8)') a%v
        else
          write (u, '(6es16.8)') a%v
        end if
        write (u, '(a)') '</DataArray>'
      end associate
    end do
    write (u, '(a)') '</'//tag//'>'
  end subroutine write_arrays

  !> JOB.pvd with the frames 1..out%nframe.
  subroutine write_pvd(out)
    type(output_t), intent(in) :: out
    integer :: u, i, ios
    character(len=16) :: b
    open (newunit=u, file=out%dir//'/'//out%job//'.pvd', status='replace', action='write', iostat=ios)
    if (ios /= 0) return
    write (u, '(a)') '<?xml version="1.0"?>'
    write (u, '(a)') '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">'
    write (u, '(a)') '<Collection>'
    do i = 1, out%nframe
      write (b, '(i4.4)') i
      write (u, '(a,es23.15,a)') '<DataSet timestep="', out%frame_times(i), '" group="" part="0" file="'// &
        out%job//'_'//trim(b)//frame_extension(out)//'"/>'
    end do
    write (u, '(a)') '</Collection></VTKFile>'
    close (u)
  end subroutine write_pvd

  !> The extension of the frame files JOB.pvd lists: .vtm for two blocks, .pvtu for pieces, else .vtu.
  pure function frame_extension(out) result(ext)
    type(output_t), intent(in) :: out
    character(len=:), allocatable :: ext
    if (out%nblocks > 1) then
      ext = '.vtm'
    else if (out%npieces > 1) then
      ext = '.pvtu'
    else
      ext = '.vtu'
    end if
  end function frame_extension

  !> Close all files. Standard output stays on JOB.dat until the program ends: a user library with its own Fortran
  !> run time (LLVM flang) flushes its unit 6 only then.
  subroutine output_close(out)
    type(output_t), intent(inout) :: out  !< output state
    call output_progress_clear(out)
    if (out%csv /= -1) close (out%csv)
    if (out%sta /= -1) close (out%sta)
    if (out%log /= -1) close (out%log)
    out%csv = -1
    out%sta = -1
    out%log = -1
  end subroutine output_close

end module output_files
