!> Properties of the LDF cohesive element in the UEL's layout (docs/uel.md "Interface"), checked and defaulted in one
!> place for every adapter: the Abaqus UEL reads them from PROPS/JPROPS, the Marc USELEM builds the same arrays from
!> its own inputs. Pure and host-free: a bad value is reported through stat and a message naming the entry and its
!> value; the adapter prefixes the element number and stops the analysis the way its host does.
!>
!>   props(1) phi > 0, props(2) delta > 0, props(3) k_c >= 0 (0: phi/delta), props(4) phi_t, props(5) delta_t
!>   (classical law; 0: phi, delta), props(6) eta_v >= 0 (viscous regularisation; 0: none), props(7) thickness of the
!>   2D element (0: 1); jprops(1) unloading 1-3 (0: 1), jprops(2) law 1 LDF, 2 classical (0: 1), jprops(3) 2D
!>   section 0 planar, 1 axisymmetric. Absent trailing entries take their defaults.
module cohesive_input
  use ldfcz_kinds, only: dp
  use ldfcz_finite, only: is_finite
  use cohesive_law, only: cohesive_props, law_ldf, law_classical
  implicit none
  private
  public :: cohesive_section, cohesive_input_read

  integer, parameter, public :: input_ok = 0   !< the properties are valid
  integer, parameter, public :: input_bad = 1  !< a property is invalid (errmsg says which)

  !> Section of the 2D element (docs/uel.md "Section of the 2D element"); the 3D element has the defaults.
  type :: cohesive_section
    real(dp) :: thickness = 1.0_dp      !< out-of-plane thickness of a planar 2D element
    logical :: axisymmetric = .false.   !< 2D element axisymmetric about x2 (x1 = r)
  end type cohesive_section

contains

  !> The element's law parameters and section from the UEL property arrays, or stat = input_bad and a message.
  pure subroutine cohesive_input_read(ndim, props, jprops, pr, sec, stat, errmsg)
    integer, intent(in) :: ndim                    !< 2 (plane) or 3
    real(dp), intent(in) :: props(:)               !< real properties, PROPS(1:NPROPS)
    integer, intent(in) :: jprops(:)               !< integer properties, JPROPS(1:NJPROP)
    type(cohesive_props), intent(out) :: pr        !< law parameters, defaults applied
    type(cohesive_section), intent(out) :: sec     !< section of the 2D element
    integer, intent(out) :: stat                   !< input_ok or input_bad
    character(len=*), intent(out) :: errmsg        !< the offending entry and its value when stat = input_bad

    call read_real_props(props, pr, stat, errmsg)
    if (stat /= input_ok) return
    call read_integer_props(jprops, pr, stat, errmsg)
    if (stat /= input_ok) return
    call read_section(ndim, props, jprops, sec, stat, errmsg)
  end subroutine cohesive_input_read

  !> PROPS(1:6): phi, delta (> 0), k_c, phi_t, delta_t, eta_v (>= 0, 0 = default); PROPS(7) is checked here too.
  pure subroutine read_real_props(props, pr, stat, errmsg)
    real(dp), intent(in) :: props(:)
    type(cohesive_props), intent(inout) :: pr
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    integer :: i

    stat = input_bad
    errmsg = ''
    if (size(props) < 2) then
      write (errmsg, '(a,i0,a)') 'NPROPS=', size(props), ', need at least 2 (PROPS(1)=phi, PROPS(2)=delta)'
      return
    end if
    do i = 1, min(size(props), 7)
      if (.not. is_finite(props(i))) then
        write (errmsg, '(a,i0,a)') 'PROPS(', i, ') is not a finite number (NaN or Inf)'
        return
      end if
    end do
    if (.not. (props(1) > 0.0_dp)) then
      write (errmsg, '(a,es12.4)') 'PROPS(1) = phi (work of separation) must be > 0, got ', props(1)
      return
    end if
    if (.not. (props(2) > 0.0_dp)) then
      write (errmsg, '(a,es12.4)') 'PROPS(2) = delta (characteristic opening) must be > 0, got ', props(2)
      return
    end if
    do i = 3, min(size(props), 7)
      if (props(i) < 0.0_dp) then
        write (errmsg, '(a,i0,a,es12.4)') 'PROPS(', i, ') (3 k_c, 4 phi_t, 5 delta_t, 6 eta_v, 7 thickness) must be' &
          // ' >= 0, got ', props(i)
        return
      end if
    end do
    pr%phi = props(1)
    pr%delta = props(2)
    ! default k_c = phi/delta: T_c(Delta_c = -delta) = e*T_max
    pr%kc = positive_or(props, 3, props(1) / props(2))
    pr%phi_t = positive_or(props, 4, props(1))
    pr%delta_t = positive_or(props, 5, props(2))
    pr%eta_v = positive_or(props, 6, 0.0_dp)
    stat = input_ok
  end subroutine read_real_props

  !> JPROPS(1) unloading (0: reversible), JPROPS(2) law (0: LDF); the classical law is reversible only.
  pure subroutine read_integer_props(jprops, pr, stat, errmsg)
    integer, intent(in) :: jprops(:)
    type(cohesive_props), intent(inout) :: pr
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    integer :: iunl, law

    stat = input_bad
    errmsg = ''
    iunl = nonzero_or(jprops, 1, 1)
    law = nonzero_or(jprops, 2, law_ldf)
    if (iunl < 1 .or. iunl > 3) then
      write (errmsg, '(a,i0,a)') 'JPROPS(1) = unloading type ', iunl, ' unknown; use 1 reversible, 2 elastic damage,' &
        // ' 3 plastic'
      return
    end if
    if (law /= law_ldf .and. law /= law_classical) then
      write (errmsg, '(a,i0,a)') 'JPROPS(2) = law ', law, ' unknown; use 1 LDF, 2 classical'
      return
    end if
    if (law == law_classical .and. iunl /= 1) then
      write (errmsg, '(a,i0,a)') 'the classical law (JPROPS(2)=2) is reversible only; JPROPS(1)=', iunl, &
        ' must be 0 or 1'
      return
    end if
    pr%unloading = iunl
    pr%law = law
    stat = input_ok
  end subroutine read_integer_props

  !> PROPS(7) thickness and JPROPS(3) axisymmetric flag: 2D element only, not both at once.
  pure subroutine read_section(ndim, props, jprops, sec, stat, errmsg)
    integer, intent(in) :: ndim
    real(dp), intent(in) :: props(:)
    integer, intent(in) :: jprops(:)
    type(cohesive_section), intent(inout) :: sec
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    integer :: isec

    stat = input_bad
    errmsg = ''
    sec%thickness = positive_or(props, 7, 1.0_dp)
    isec = 0
    if (size(jprops) >= 3) isec = jprops(3)
    if (isec /= 0 .and. isec /= 1) then
      write (errmsg, '(a,i0,a)') 'JPROPS(3) = ', isec, ' unknown; use 0 planar (thickness PROPS(7)), 1 axisymmetric'
      return
    end if
    if (ndim == 3 .and. (isec /= 0 .or. sec%thickness /= 1.0_dp)) then
      errmsg = 'PROPS(7) (thickness) and JPROPS(3) (axisymmetric) apply to the 2D element only; leave them 0 or' &
               // ' absent in 3D'
      return
    end if
    if (isec == 1 .and. sec%thickness /= 1.0_dp) then
      write (errmsg, '(a,es12.4,a)') 'axisymmetric (JPROPS(3) = 1) takes no thickness, PROPS(7) = ', sec%thickness, &
        ': the forces are totals over 2 pi'
      return
    end if
    sec%axisymmetric = isec == 1
    stat = input_ok
  end subroutine read_section

  !> props(i) where it is present and > 0, otherwise the default.
  pure real(dp) function positive_or(props, i, default) result(v)
    real(dp), intent(in) :: props(:)
    integer, intent(in) :: i
    real(dp), intent(in) :: default
    v = default
    if (size(props) >= i) then
      if (props(i) > 0.0_dp) v = props(i)
    end if
  end function positive_or

  !> jprops(i) where it is present and non-zero, otherwise the default.
  pure integer function nonzero_or(jprops, i, default) result(v)
    integer, intent(in) :: jprops(:)
    integer, intent(in) :: i
    integer, intent(in) :: default
    v = default
    if (size(jprops) >= i) then
      if (jprops(i) /= 0) v = jprops(i)
    end if
  end function nonzero_or

end module cohesive_input
