!> MSC.Marc translation layer of the compressible Leonov model (paper section 6): what HYPELA2 needs, host-free
!> and testable. The HYPELA2 entry point (umat/hypela2.f) only fetches Marc's time increment and calls this.
!>
!> Verified (Marc Volume D argument list, as quoted in open codes): ffn, ffn1 deformation gradients at t_n, t_n+1
!> (dimension itel = 2 or 3), s stress to be updated, d the stress-strain law, t state variables "at t = n, must be
!> updated to t = n+1", ngens, ndi, nshear.
!> Inferred, NOT verified against the manual: Marc's shear order 11,22,33,12,23,31; with updated Lagrange
!> (iupdat = 1) s is Cauchy stress and d has the form of Abaqus DDSDDE; for itel = 2 the out-of-plane stretch
!> is 1 (plane strain; an axisymmetric hoop stretch is not available this way).
module leonov_marc
  use ldfcz_kinds, only: dp
  use leonov_parameters, only: leonov_props, leonov_props_from_array, leonov_nstatv
  use leonov, only: leonov_state, leonov_update, leonov_state_from_statev, leonov_state_to_statev, &
                    leonov_ok, leonov_step_too_large, leonov_elastic_tangent
  implicit none
  private
  public :: leonov_marc_update, marc_to_abaqus

  !> Position in the Abaqus Voigt order (11,22,33,12,13,23) of Marc's component k (11,22,33,12,23,31).
  integer, parameter :: marc_to_abaqus(6) = [1, 2, 3, 4, 6, 5]

contains

  !> One HYPELA2 call. stat: 0 ok, 1 ok but a smaller step is advised (step_factor < 1), 2 core failure (s, t
  !> unchanged, d elastic, step_factor < 1), 3 bad input (errmsg says why).
  pure subroutine leonov_marc_update(props, ffn, ffn1, itel, timinc, ngens, ndi, nshear, tstate, s, d, &
                                     stat, step_factor, errmsg)
    real(dp), intent(in) :: props(:)             !< Leonov properties, Table 1 order
    integer, intent(in) :: itel                  !< dimension of ffn, ffn1 (2 or 3)
    real(dp), intent(in) :: ffn(itel, itel)      !< deformation gradient at t_n
    real(dp), intent(in) :: ffn1(itel, itel)     !< deformation gradient at t_n+1
    real(dp), intent(in) :: timinc               !< time increment (s)
    integer, intent(in) :: ngens                 !< number of stress components (4 or 6)
    integer, intent(in) :: ndi                   !< direct components (3)
    integer, intent(in) :: nshear                !< shear components (1 or 3)
    real(dp), intent(inout) :: tstate(:)         !< the 11 Leonov state variables (layout of the UMAT's STATEV)
    real(dp), intent(inout) :: s(ngens)          !< Cauchy stress, Marc order
    real(dp), intent(inout) :: d(ngens, ngens)   !< tangent, Marc order
    integer, intent(out) :: stat                 !< status, see above
    real(dp), intent(out) :: step_factor         !< suggested step ratio
    character(len=*), intent(out) :: errmsg      !< reason when stat = 3
    type(leonov_props) :: p
    type(leonov_state) :: old, new
    real(dp) :: f0(3, 3), f1(3, 3), sig(3, 3), c6(6, 6)
    integer :: k, l, ist, ka, la
    integer, parameter :: iv(6) = [1, 2, 3, 1, 1, 2], jv(6) = [1, 2, 3, 2, 3, 3]

    step_factor = 1.0_dp
    errmsg = ''
    stat = 3
    if (ndi /= 3 .or. .not. ((nshear == 1 .and. ngens == 4) .or. (nshear == 3 .and. ngens == 6))) then
      write (errmsg, '(a,i0,a,i0,a,i0)') 'HYPELA2 (Leonov): needs ndi = 3 and ngens = 4 or 6, got ndi = ', ndi, &
        ', nshear = ', nshear, ', ngens = ', ngens
      return
    end if
    if (itel /= 2 .and. itel /= 3) then
      write (errmsg, '(a,i0)') 'HYPELA2 (Leonov): itel must be 2 or 3, got ', itel
      return
    end if
    if (size(tstate) < leonov_nstatv) then
      write (errmsg, '(a,i0,a)') 'HYPELA2 (Leonov): needs 11 state variables after the temperature, got ', &
        size(tstate), ''
      return
    end if
    call leonov_props_from_array(props, p, ist, errmsg)
    if (ist /= 0) then
      errmsg = 'HYPELA2 (Leonov): ' // trim(errmsg)
      return
    end if
    f0 = 0.0_dp
    f1 = 0.0_dp
    f0(3, 3) = 1.0_dp
    f1(3, 3) = 1.0_dp
    f0(1:itel, 1:itel) = ffn
    f1(1:itel, 1:itel) = ffn1
    old = leonov_state_from_statev(tstate(1:leonov_nstatv))
    call leonov_update(p, f0, f1, timinc, old, new, sig, ist, step_factor, c6)
    if (ist /= leonov_ok .and. ist /= leonov_step_too_large) then
      c6 = leonov_elastic_tangent(p)
      do l = 1, ngens
        do k = 1, ngens
          d(k, l) = c6(marc_to_abaqus(k), marc_to_abaqus(l))
        end do
      end do
      stat = 2
      return
    end if
    do k = 1, ngens
      ka = marc_to_abaqus(k)
      s(k) = sig(iv(ka), jv(ka))
      do l = 1, ngens
        la = marc_to_abaqus(l)
        d(k, l) = c6(ka, la)
      end do
    end do
    call leonov_state_to_statev(new, tstate(1:leonov_nstatv))
    stat = merge(1, 0, ist == leonov_step_too_large)
  end subroutine leonov_marc_update

end module leonov_marc
