!> The log message of a stop requested by a user routine (XIT, STDB_ABQERR with LOP = -3), pointing at the deck
!> line of the properties the routine rejected.
module stop_report
  use model_types, only: model_t, etype_user
  use solver_text, only: itoa
  implicit none
  private
  public :: stop_message

contains

  !> Message of a stop requested by a user routine (XIT, STDB_ABQERR with LOP = -3): the deck position of the
  !> properties of the element whose call asked to stop (recorded when it asked: abaqus_stop_element; the lowest
  !> element when several did), *UEL PROPERTY or *USER MATERIAL data line, then the routine's message.
  function stop_message(model, ie, routine_text, is, kinc) result(text)
    type(model_t), intent(in) :: model             !< the model
    integer, intent(in) :: ie                      !< element that asked to stop (0: not known)
    character(len=*), intent(in) :: routine_text   !< the routine's message
    integer, intent(in) :: is, kinc                !< step and increment of the stop
    character(len=:), allocatable :: text
    character(len=:), allocatable :: what
    integer :: ip, im
    text = trim(routine_text)
    if (len_trim(text) == 0) text = 'XIT called without a message'
    what = ''
    if (ie > 0) then
      if (model%elem_kind(ie) == etype_user) then
        ip = 0
        if (allocated(model%elem_uelprop)) ip = model%elem_uelprop(ie)
        if (ip > 0) what = model%uelprops(ip)%pos%file//':'//itoa(model%uelprops(ip)%pos%line)// &
          ': *UEL PROPERTY: rejected by UEL: '
      else
        im = material_of(model, ie)
        if (im > 0) then
          if (model%materials(im)%has_user .and. allocated(model%materials(im)%user_pos%file)) what = &
            model%materials(im)%user_pos%file//':'//itoa(model%materials(im)%user_pos%line)// &
            ': *USER MATERIAL: rejected by UMAT: '
        end if
      end if
      if (len(what) == 0) what = 'a user routine asked to end the analysis (XIT): '
      text = what//text//' (element '//itoa(model%elem_id(ie))//', step '//itoa(is)//', increment '// &
        itoa(kinc)//')'
    else
      text = 'a user routine asked to end the analysis (XIT): '//text
    end if
  end function stop_message

  !> Material index of continuum element ie (0: none).
  integer function material_of(model, ie) result(im)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: ie           !< element index
    integer :: isec
    im = 0
    if (.not. allocated(model%elem_section)) return
    isec = model%elem_section(ie)
    if (isec < 1 .or. isec > model%nsection) return
    do im = 1, model%nmat
      if (model%materials(im)%name == model%sections(isec)%material) return
    end do
    im = 0
  end function material_of

end module stop_report
