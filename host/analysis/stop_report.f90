!> The log message of a stop requested by a user routine (XIT, STDB_ABQERR with LOP = -3), pointing at the deck
!> line of the properties the routine rejected.
module stop_report
  use ldfcz_kinds, only: dp
  use model_types, only: model_t, etype_user
  use analysis_core, only: analysis_t, analysis_assemble
  use abaqus_host_state, only: abaqus_stop_requested, abaqus_stop_message, abaqus_clear_stop
  use solver_text, only: itoa
  implicit none
  private
  public :: stop_message

contains

  !> Message of a stop requested by a user routine (XIT, STDB_ABQERR with LOP = -3): the deck position of the
  !> properties of the first element whose call asks to stop (*UEL PROPERTY or *USER MATERIAL data line), found by
  !> element loops over growing prefixes of the element list (residual only), then the routine's message.
  function stop_message(an, model, is, kinc, time, dt, period, nlgeom) result(text)
    type(analysis_t), intent(inout) :: an          !< analysis data (element loops rerun)
    type(model_t), intent(in) :: model             !< the model
    integer, intent(in) :: is, kinc                !< step and increment of the stop
    real(dp), intent(in) :: time(2), dt, period    !< times of the increment, step period
    logical, intent(in) :: nlgeom                  !< geometric nonlinearity
    character(len=:), allocatable :: text
    character(len=:), allocatable :: what
    type(model_t), allocatable :: sub
    integer :: lo, hi, mid, ie, ip, im
    text = abaqus_stop_message()
    if (len_trim(text) == 0) text = 'XIT called without a message'
    allocate (sub, source=model)
    ! smallest prefix length whose element loop asks to stop: doubling, then bisection
    lo = 0
    hi = 1
    do
      hi = min(hi, model%nelem)
      if (prefix_stops(sub, hi)) exit
      if (hi == model%nelem) then
        hi = 0
        exit
      end if
      lo = hi
      hi = 2 * hi
    end do
    if (hi > 0) then
      do while (hi - lo > 1)
        mid = (lo + hi) / 2
        if (prefix_stops(sub, mid)) then
          hi = mid
        else
          lo = mid
        end if
      end do
    end if
    call abaqus_clear_stop()
    ie = hi
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

  contains

    !> True when the element loop over the first n elements (residual only) has a user routine ask to stop.
    logical function prefix_stops(sub, n)
      type(model_t), intent(inout) :: sub
      integer, intent(in) :: n
      character(len=:), allocatable :: em
      integer :: st2
      real(dp) :: pn
      sub%nelem = n
      call abaqus_clear_stop()
      call analysis_assemble(an, sub, is, kinc, time, dt, period, nlgeom, .false., pn, st2, em)
      prefix_stops = abaqus_stop_requested()
    end function prefix_stops

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
