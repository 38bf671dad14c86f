!> Material properties of the compressible Leonov model (paper section 6, Table 1) and their validation.
!>
!> PROPS order (fixed, Table 1 order): E, nu, S_a, eta_0r (MPa s), tau_0 (MPa), mu, G_r (MPa), r0, r1, r2;
!> optional PROPS(11): the accuracy bound dgamma_max on the equivalent plastic strain increment (default 0.05).
!> Derived: shear modulus G = E/(2(1+nu)) and bulk modulus kappa = E/(3(1-2nu)) (Eq. 33).
module leonov_parameters
  use ldfcz_finite, only: is_finite
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: leonov_props, leonov_props_from_array, leonov_props_table1
  public :: leonov_nprops, leonov_nprops_max, leonov_nstatv, leonov_dgamma_max

  integer, parameter :: leonov_nprops = 10   !< number of PROPS the model needs (Table 1)
  integer, parameter :: leonov_nprops_max = 11  !< with the optional accuracy bound PROPS(11)
  integer, parameter :: leonov_nstatv = 11   !< minimum number of state variables (see docs/umat.md)
  !> Default largest equivalent plastic strain increment accepted for accuracy; above it the adapters ask for a
  !> smaller increment (PNEWDT < 1). The step-size study (reports/umat/step_study.md) shows the error it allows;
  !> PROPS(11) overrides it (the peel study `plastic-bound` measures the structural error of larger bounds).
  real(dp), parameter :: leonov_dgamma_max = 0.05_dp

  !> Properties of the compressible Leonov model.
  type :: leonov_props
    real(dp) :: e = 0.0_dp        !< Young's modulus E (MPa)
    real(dp) :: nu = 0.0_dp       !< Poisson's ratio nu (-)
    real(dp) :: s_a = 0.0_dp      !< state parameter S_a (-), Eq. 41
    real(dp) :: eta_0r = 0.0_dp   !< rejuvenated zero viscosity eta_0,r (MPa s), Eq. 37
    real(dp) :: tau_0 = 0.0_dp    !< characteristic stress tau_0 (MPa), Eq. 39
    real(dp) :: mu = 0.0_dp       !< pressure dependence mu (-), Eq. 37
    real(dp) :: g_r = 0.0_dp      !< strain hardening modulus G_r (MPa), Eq. 32
    real(dp) :: r0 = 0.0_dp       !< softening parameter r0 (-), Eq. 42
    real(dp) :: r1 = 0.0_dp       !< softening parameter r1 (-), Eq. 42
    real(dp) :: r2 = 0.0_dp       !< softening parameter r2 (-), Eq. 42
    real(dp) :: g = 0.0_dp        !< shear modulus G = E/(2(1+nu)) (MPa), Eq. 33
    real(dp) :: kappa = 0.0_dp    !< bulk modulus kappa = E/(3(1-2nu)) (MPa), Eq. 33
    real(dp) :: dgamma_max = leonov_dgamma_max  !< accuracy bound on the plastic strain increment, PROPS(11)
    ! derived constants of the flow rule, set with the moduli (the logs the update would otherwise repeat per call)
    real(dp) :: ln_r0 = 0.0_dp        !< ln r0 (Eq. 42)
    real(dp) :: softplus_0 = 0.0_dp   !< ln(1 + r0^r1) = softplus(r1 ln r0): ln R_gamma(0) = 0 (Eq. 42)
    real(dp) :: ln_eta_0r = 0.0_dp    !< ln eta_0,r (Eq. 37)
    real(dp) :: ln_tau_0 = 0.0_dp     !< ln tau_0 (Eq. 39)
  end type leonov_props

  character(len=*), parameter :: names(leonov_nprops_max) = [character(len=10) :: &
    'E', 'nu', 'S_a', 'eta_0r', 'tau_0', 'mu', 'G_r', 'r0', 'r1', 'r2', 'dgamma_max']

contains

  !> Table 1 of the paper (PET), in mm-N-s-MPa units, as a PROPS array.
  pure function leonov_props_table1() result(props)
    real(dp) :: props(leonov_nprops)
    props = [1250.0_dp, 0.4_dp, 28.4_dp, 0.486_dp, 0.95_dp, 0.047_dp, 28.2_dp, 0.990_dp, 200.0_dp, -4.0_dp]
  end function leonov_props_table1

  !> Read and validate the properties from a PROPS array. stat = 0 on success; otherwise errmsg names
  !> the property, its PROPS index, the requirement and the value found.
  pure subroutine leonov_props_from_array(props, p, stat, errmsg)
    real(dp), intent(in) :: props(:)             !< PROPS, Table 1 order
    type(leonov_props), intent(out) :: p         !< validated properties with derived moduli
    integer, intent(out) :: stat                 !< 0 valid, 1 invalid
    character(len=*), intent(out) :: errmsg      !< reason when stat /= 0
    integer :: i

    stat = 0
    errmsg = ''
    if (size(props) < leonov_nprops) then
      stat = 1
      write (errmsg, '(a,i0,a,i0)') 'the Leonov model needs NPROPS = ', leonov_nprops, ' properties, got ', size(props)
      return
    end if
    do i = 1, min(size(props), leonov_nprops_max)
      if (.not. is_finite(props(i))) then
        stat = 1
        write (errmsg, '(a,a,a,i0,a)') 'property ', trim(names(i)), ' (PROPS(', i, ')) is not a finite number'
        return
      end if
    end do
    p%e = props(1)
    p%nu = props(2)
    p%s_a = props(3)
    p%eta_0r = props(4)
    p%tau_0 = props(5)
    p%mu = props(6)
    p%g_r = props(7)
    p%r0 = props(8)
    p%r1 = props(9)
    p%r2 = props(10)
    if (size(props) >= leonov_nprops_max) p%dgamma_max = props(11)
    if (p%e <= 0.0_dp) then
      call bad(props, 1, 'must be > 0', stat, errmsg)
    else if (p%nu <= -1.0_dp .or. p%nu >= 0.5_dp) then
      call bad(props, 2, 'must lie in (-1, 0.5)', stat, errmsg)
    else if (p%eta_0r <= 0.0_dp) then
      call bad(props, 4, 'must be > 0 (MPa s)', stat, errmsg)
    else if (p%tau_0 <= 0.0_dp) then
      call bad(props, 5, 'must be > 0 (MPa)', stat, errmsg)
    else if (p%g_r < 0.0_dp) then
      call bad(props, 7, 'must be >= 0 (MPa)', stat, errmsg)
    else if (p%r0 <= 0.0_dp) then
      call bad(props, 8, 'must be > 0', stat, errmsg)
    else if (p%r1 <= 0.0_dp) then
      call bad(props, 9, 'must be > 0', stat, errmsg)
    else if (p%dgamma_max <= 0.0_dp) then
      call bad(props, 11, 'must be > 0 (the accuracy bound on the plastic strain increment)', stat, errmsg)
    end if
    if (stat /= 0) return
    p%g = p%e / (2.0_dp * (1.0_dp + p%nu))
    p%kappa = p%e / (3.0_dp * (1.0_dp - 2.0_dp * p%nu))
    p%ln_r0 = log(p%r0)
    p%softplus_0 = abs(p%r1 * p%ln_r0)
    if (p%softplus_0 > 30.0_dp) then
      p%softplus_0 = exp(-p%softplus_0)   ! ln(1 + e^-y) = e^-y to round-off (0 below e^-745)
    else
      p%softplus_0 = log(1.0_dp + exp(-p%softplus_0))
    end if
    p%softplus_0 = max(p%r1 * p%ln_r0, 0.0_dp) + p%softplus_0
    p%ln_eta_0r = log(p%eta_0r)
    p%ln_tau_0 = log(p%tau_0)
  end subroutine leonov_props_from_array

  !> Message for property i violating its requirement.
  pure subroutine bad(props, i, requirement, stat, errmsg)
    real(dp), intent(in) :: props(:)          !< PROPS
    integer, intent(in) :: i                  !< index of the offending property
    character(len=*), intent(in) :: requirement
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    stat = 1
    write (errmsg, '(a,a,a,i0,a,a,a,es12.5)') 'property ', trim(names(i)), ' (PROPS(', i, ')) ', requirement, &
      ', got ', props(i)
  end subroutine bad

end module leonov_parameters
