!> Which routine each *USER MATERIAL and *USER ELEMENT type of a model runs: the user's own (a --user library that
!> defines UMAT or UEL; as in Abaqus, one UMAT and one UEL serve every material and type), else the built-in one
!> the deck declares by name ('**LDFCZ BUILTIN, UMAT=name' under the *MATERIAL, 'UEL=name' after the *USER
!> ELEMENT), else a stop that names the material or type and both fixes. Nothing runs silently in the user's
!> place. The notes say, for JOB.log, which routine runs for each material and type and from which file.
module routine_choice
  use model_types, only: model_t, source_pos_t
  use deck_lists, only: itoa
  use user_routines, only: user_routines_t, uel_interface, umat_interface, builtin_routine, builtin_names
  implicit none
  private
  public :: user_routines_choose, note_len

  integer, parameter :: note_len = 2000  !< longest JOB.log note (two deck paths and a routine path)

contains

  !> Choose the routines of r for the model (r holds a --user library's UEL/UMAT, if any, on entry). stat = 2 and
  !> errmsg ("file:line: keyword: ...") when a material or type has no routine, or names no built-in one.
  subroutine user_routines_choose(r, model, stat, errmsg, notes)
    type(user_routines_t), intent(inout) :: r                  !< routines (null pointers: none from --user)
    type(model_t), intent(in) :: model                         !< the model read from the deck
    integer, intent(out) :: stat                               !< 0 ok, 2 a material or type without routine
    character(len=:), allocatable, intent(out) :: errmsg       !< message naming file:line and both fixes
    character(len=note_len), allocatable, intent(out) :: notes(:) !< one JOB.log line per material and type
    logical :: user_umat, user_uel
    integer :: k, n
    stat = 0
    errmsg = ''
    if (.not. allocated(r%umat_origin)) r%umat_origin = 'none'
    if (.not. allocated(r%uel_origin)) r%uel_origin = 'none'
    user_umat = associated(r%umat)
    user_uel = associated(r%uel)
    allocate (notes(model%nmat + model%nutype))
    n = 0
    do k = 1, model%nmat
      associate (m => model%materials(k))
        n = n + 1
        if (.not. m%has_user) then
          if (len_trim(m%builtin) > 0) then
            stat = 2
            errmsg = where(m%builtin_pos)//': **LDFCZ BUILTIN: material '//trim(m%given_name)//' has no *USER '// &
              'MATERIAL for the UMAT it declares'
            return
          end if
          notes(n) = 'ldfcz: material '//trim(m%given_name)//' ('//where(m%pos)//'): the host''s *ELASTIC'
          cycle
        end if
        call choose_one(r, 'UMAT', user_umat, 'material '//trim(m%given_name), m%pos, '*USER MATERIAL', &
          m%builtin, m%builtin_pos, notes(n), stat, errmsg)
      end associate
      if (stat /= 0) return
    end do
    do k = 1, model%nutype
      associate (u => model%utypes(k))
        n = n + 1
        call choose_one(r, 'UEL', user_uel, 'user element type '//trim(u%name), u%pos, '*USER ELEMENT', &
          u%builtin, u%builtin_pos, notes(n), stat, errmsg)
      end associate
      if (stat /= 0) return
    end do
  end subroutine user_routines_choose

  !> The routine of one material (kind UMAT) or user element type (UEL); sets r%umat/r%uel when a built-in runs.
  subroutine choose_one(r, kind, from_user, what, pos, keyword, builtin, builtin_pos, note, stat, errmsg)
    type(user_routines_t), intent(inout) :: r            !< routines
    character(len=*), intent(in) :: kind                 !< 'UMAT' or 'UEL'
    logical, intent(in) :: from_user                     !< the --user library defines this kind
    character(len=*), intent(in) :: what                 !< 'material NAME' or 'user element type Un'
    type(source_pos_t), intent(in) :: pos                !< the *MATERIAL or *USER ELEMENT line
    character(len=*), intent(in) :: keyword              !< '*USER MATERIAL' or '*USER ELEMENT'
    character(len=*), intent(in) :: builtin              !< declared built-in name ('' none)
    type(source_pos_t), intent(in) :: builtin_pos        !< where it was declared
    character(len=*), intent(out) :: note                !< JOB.log line
    integer, intent(inout) :: stat                       !< 2 on error
    character(len=:), allocatable, intent(inout) :: errmsg !< message
    procedure(uel_interface), pointer :: pu
    procedure(umat_interface), pointer :: pm
    character(len=:), allocatable :: source, origin, owner, suggest, owner_kw
    if (from_user) then
      if (kind == 'UMAT') then
        origin = r%umat_origin
      else
        origin = r%uel_origin
      end if
      note = 'ldfcz: '//what//' ('//where(pos)//'): '//keyword//' runs the '//kind//' of '//origin//' (--user)'
      if (len_trim(builtin) > 0) note = trim(note)//'; its **LDFCZ BUILTIN, '//kind//'='//trim(builtin)// &
        ' ('//where(builtin_pos)//') does not apply: the user''s routine runs'
      return
    end if
    owner = trim(merge('under the *MATERIAL    ', 'after the *USER ELEMENT', kind == 'UMAT'))
    if (len_trim(builtin) == 0) then
      ! the one built-in routine of the kind is named in the fix; with several (or none) the list is
      suggest = builtin_names(kind)
      if (index(suggest, ',') > 0 .or. suggest == 'none') suggest = 'NAME'
      stat = 2
      owner_kw = ' ('//keyword//')'
      if (trim(pos%keyword) == keyword) owner_kw = ''
      errmsg = where(pos)//': '//trim(pos%keyword)//': '//what//owner_kw//' has no '//kind//': give your '// &
        'own routine with --user '// &
        'FILE, or run ldfcz''s built-in one by declaring it '//owner//' with the comment line **LDFCZ BUILTIN, '// &
        kind//'='//suggest//' (built-in '//kind//'s here: '//builtin_names(kind)//'; docs/'// &
        trim(merge('umat.md', 'uel.md ', kind == 'UMAT'))//')'
      return
    end if
    call builtin_routine(kind, trim(builtin), pu, pm, source)
    if (len(source) == 0) then
      stat = 2
      errmsg = where(builtin_pos)//': **LDFCZ BUILTIN: no built-in '//kind//' named '//trim(builtin)// &
        ' in this ldfcz (built-in '//kind//'s: '//builtin_names(kind)//')'
      return
    end if
    origin = 'built-in '//kind//' '//trim(builtin)//' ('//source//')'
    if (kind == 'UMAT') then
      call take(r%umat_origin, origin, stat, errmsg)
      if (stat == 0) r%umat => pm
    else
      call take(r%uel_origin, origin, stat, errmsg)
      if (stat == 0) r%uel => pu
    end if
    if (stat /= 0) then
      errmsg = where(builtin_pos)//': **LDFCZ BUILTIN: '//what//' declares the '//origin//', another one the '// &
        errmsg//': a run calls one '//kind//' for every '//keyword//', as Abaqus does'
      return
    end if
    note = 'ldfcz: '//what//' ('//where(pos)//'): '//keyword//' runs the '//origin//', declared at '// &
      where(builtin_pos)//' (no --user '//kind//')'
  end subroutine choose_one

  !> Record the built-in routine a run calls (stat = 2 and errmsg = the other one when another was chosen).
  subroutine take(current, origin, stat, errmsg)
    character(len=:), allocatable, intent(inout) :: current !< the run's routine so far ('none')
    character(len=*), intent(in) :: origin                 !< the one declared now
    integer, intent(inout) :: stat                         !< 2 on conflict
    character(len=:), allocatable, intent(inout) :: errmsg !< the other routine on conflict
    if (current == 'none' .or. current == origin) then
      current = origin
    else
      stat = 2
      errmsg = current
    end if
  end subroutine take

  !> "file:line" of a source position.
  function where(pos) result(w)
    type(source_pos_t), intent(in) :: pos  !< position
    character(len=:), allocatable :: w
    if (allocated(pos%file)) then
      w = pos%file//':'//itoa(pos%line)
    else
      w = '?'
    end if
  end function where

end module routine_choice
