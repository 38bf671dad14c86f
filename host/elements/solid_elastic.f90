!> Built-in *ELASTIC with Abaqus/Standard semantics: isotropic (E, nu), and the general laws of elastic_law_t
!> (TYPE=ORTHOTROPIC, ENGINEERING CONSTANTS, LAMINA, ANISOTROPIC, temperature-dependent data) with *EXPANSION
!> (ISO, ORTHO, ANISO, temperature-dependent).
!>
!> Under NLGEOM Abaqus integrates linear elasticity as a hypoelastic law in the co-rotational (Jaumann) frame:
!> the host has already rotated the stress by DROT (Hughes-Winget), then
!>     sigma_new = DROT sigma_old DROT^T + C : DSTRAN,        DDSDDE = C,
!> which is exactly what a linear-elastic UMAT does. Without NLGEOM it is ordinary small-strain elasticity.
!> Voigt order of docs/conventions.md (11,22,33,12,13,23 or 11,22,33,12), engineering shear strains.
module solid_elastic
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: elastic_isotropic_ddsdde, elastic_update, elastic_check
  public :: elastic_law_t, law_isotropic, law_orthotropic, law_engineering, law_lamina, law_anisotropic
  public :: expansion_none, expansion_iso, expansion_ortho, expansion_aniso, law_ncons, law_nexp
  public :: elastic_law_stiffness, elastic_law_update, elastic_law_check, thermal_strain_increment
  public :: elastic_law_shear_modulus, elastic_thickness_increment, elastic_law_compliance

  integer, parameter :: law_isotropic = 1     !< E, nu
  integer, parameter :: law_orthotropic = 2   !< D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323
  integer, parameter :: law_engineering = 3   !< E1, E2, E3, nu12, nu13, nu23, G12, G13, G23
  integer, parameter :: law_lamina = 4        !< E1, E2, nu12, G12, G13, G23 (plane stress only)
  integer, parameter :: law_anisotropic = 5   !< the 21 D_ijkl in the order of the Abaqus Keywords Guide
  integer, parameter :: law_ncons(5) = [2, 9, 9, 6, 21]  !< constants per temperature point of each law
  integer, parameter :: expansion_none = 0    !< no *EXPANSION
  integer, parameter :: expansion_iso = 1     !< alpha
  integer, parameter :: expansion_ortho = 2   !< alpha11, alpha22, alpha33
  integer, parameter :: expansion_aniso = 3   !< alpha11, alpha22, alpha33, alpha12, alpha13, alpha23
  integer, parameter :: law_nexp(0:3) = [0, 1, 3, 6]   !< coefficients per temperature point of each expansion
  !> Voigt position (Abaqus order 11,22,33,12,13,23) of the row and column of each of the 21 anisotropic D_ijkl
  integer, parameter :: aniso_row(21) = [1, 1, 2, 1, 2, 3, 1, 2, 3, 4, 1, 2, 3, 4, 5, 1, 2, 3, 4, 5, 6]
  integer, parameter :: aniso_col(21) = [1, 2, 2, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6]

  !> A material's *ELASTIC and *EXPANSION data in the material's axes (its *ORIENTATION, or the global axes),
  !> each a table over temperature: linear between the data points, constant outside their range (Abaqus Analysis
  !> User's Guide, "Material data definition"). general = .false.: the constant isotropic law that the element
  !> evaluates from E, nu and alpha directly (elastic_update), which this type then does not hold.
  type :: elastic_law_t
    logical :: general = .false.             !< the tables below are in use
    integer :: kind = law_isotropic          !< law_*
    real(dp), allocatable :: temp(:)         !< (npoint) temperatures of the data points, ascending
    real(dp), allocatable :: data(:, :)      !< (law_ncons(kind), npoint) the constants
    integer :: exp_kind = expansion_none     !< expansion_*
    real(dp), allocatable :: exp_temp(:)     !< (npoint) temperatures of the expansion data, ascending
    real(dp), allocatable :: exp_data(:, :)  !< (law_nexp(exp_kind), npoint) the coefficients
    real(dp) :: zero = 0.0_dp                !< *EXPANSION, ZERO=: reference temperature of the coefficients
  end type elastic_law_t

contains

  !> Isotropic elasticity matrix in Abaqus Voigt order (engineering shears): lambda, mu from E, nu. NDI = 2 is
  !> plane stress (Abaqus CPS elements: NDI = 2, NSHR = 1): E/(1 - nu^2) [1 nu; nu 1] and G, sigma33 = 0.
  pure subroutine elastic_isotropic_ddsdde(e, nu, ndi, nshr, ddsdde)
    real(dp), intent(in) :: e, nu            !< Young's modulus (MPa), Poisson's ratio
    integer, intent(in) :: ndi, nshr         !< direct and shear component counts
    real(dp), intent(out) :: ddsdde(:, :)    !< (ndi+nshr)^2 elasticity matrix
    real(dp) :: lam, mu
    integer :: i

    lam = e * nu / ((1 + nu) * (1 - 2 * nu))
    mu = e / (2 * (1 + nu))
    ddsdde = 0.0_dp
    if (ndi == 2) lam = 2 * mu * lam / (lam + 2 * mu)   ! plane stress: lambda* = 2 mu lambda / (lambda + 2 mu)
    ddsdde(1:ndi, 1:ndi) = lam
    do i = 1, ndi
      ddsdde(i, i) = lam + 2 * mu
    end do
    do i = ndi + 1, ndi + nshr
      ddsdde(i, i) = mu
    end do
  end subroutine elastic_isotropic_ddsdde

  !> Stress update: stress (already rotated by DROT) += C : dstran; sse += (sigma_old + sigma_new)/2 : dstran
  !> (trapezoidal elastic energy density, exact for linear elasticity without rotation).
  pure subroutine elastic_update(e, nu, ndi, nshr, stress, dstran, ddsdde, sse)
    real(dp), intent(in) :: e, nu            !< Young's modulus, Poisson's ratio
    integer, intent(in) :: ndi, nshr         !< direct and shear component counts
    real(dp), intent(inout) :: stress(:)     !< in: rotated start-of-increment Cauchy stress; out: end of increment
    real(dp), intent(in) :: dstran(:)        !< strain increment (engineering shears)
    real(dp), intent(out) :: ddsdde(:, :)    !< tangent C
    real(dp), intent(inout) :: sse           !< elastic energy density
    real(dp) :: s0(size(stress))

    call elastic_isotropic_ddsdde(e, nu, ndi, nshr, ddsdde)
    s0 = stress
    stress = stress + matmul(ddsdde, dstran)
    sse = sse + 0.5_dp * dot_product(s0 + stress, dstran)
  end subroutine elastic_update

  !> Validate the constants: E > 0 and -1 < nu < 0.5. stat = 0 when valid.
  pure subroutine elastic_check(e, nu, stat, errmsg)
    real(dp), intent(in) :: e, nu            !< Young's modulus, Poisson's ratio
    integer, intent(out) :: stat             !< 0 valid, 1 invalid
    character(len=*), intent(out) :: errmsg  !< reason when invalid
    stat = 0
    errmsg = ''
    if (.not. (e > 0.0_dp)) then
      stat = 1
      errmsg = '*ELASTIC: Young''s modulus must be > 0'
    else if (.not. (nu > -1.0_dp .and. nu < 0.5_dp)) then
      stat = 1
      errmsg = '*ELASTIC: Poisson''s ratio must lie in (-1, 0.5)'
    end if
  end subroutine elastic_check

  ! ------------------------------------------------------------------ general laws (elastic_law_t)

  !> Column of a table at temperature t: linear between the data points, the first/last column outside their
  !> range (Abaqus: material data are constant outside the range given).
  pure function table_at(temps, data, t) result(v)
    real(dp), intent(in) :: temps(:)    !< (npoint) ascending temperatures
    real(dp), intent(in) :: data(:, :)  !< (n, npoint) values
    real(dp), intent(in) :: t           !< temperature
    real(dp) :: v(size(data, 1))
    integer :: i, np
    real(dp) :: w
    np = size(temps)
    if (np == 1 .or. t <= temps(1)) then
      v = data(:, 1)
      return
    end if
    if (t >= temps(np)) then
      v = data(:, np)
      return
    end if
    do i = 1, np - 1
      if (t < temps(i + 1)) exit
    end do
    w = (t - temps(i)) / (temps(i + 1) - temps(i))
    v = (1.0_dp - w) * data(:, i) + w * data(:, i + 1)
  end function table_at

  !> 3D stiffness (6x6, Voigt 11,22,33,12,13,23, engineering shear strains) of constants d of a law other than
  !> LAMINA (ok = .false. when the engineering constants give a singular compliance).
  pure subroutine stiffness_3d(kind, d, c6, ok)
    integer, intent(in) :: kind         !< law_*
    real(dp), intent(in) :: d(:)        !< the law's constants
    real(dp), intent(out) :: c6(6, 6)   !< stiffness
    logical, intent(out) :: ok          !< .false.: not invertible
    real(dp) :: s6(6, 6)
    integer :: k
    c6 = 0.0_dp
    ok = .true.
    select case (kind)
    case (law_isotropic)
      call elastic_isotropic_ddsdde(d(1), d(2), 3, 3, c6)
    case (law_orthotropic)
      c6(1, 1) = d(1)
      c6(1, 2) = d(2)
      c6(2, 2) = d(3)
      c6(1, 3) = d(4)
      c6(2, 3) = d(5)
      c6(3, 3) = d(6)
      c6(4, 4) = d(7)
      c6(5, 5) = d(8)
      c6(6, 6) = d(9)
    case (law_engineering)
      ! compliance: S_ii = 1/E_i, S_ij = -nu_ij/E_i (nu_ij/E_i = nu_ji/E_j), S_44..66 = 1/G
      s6 = 0.0_dp
      s6(1, 1) = 1.0_dp / d(1)
      s6(2, 2) = 1.0_dp / d(2)
      s6(3, 3) = 1.0_dp / d(3)
      s6(1, 2) = -d(4) / d(1)
      s6(1, 3) = -d(5) / d(1)
      s6(2, 3) = -d(6) / d(2)
      s6(4, 4) = 1.0_dp / d(7)
      s6(5, 5) = 1.0_dp / d(8)
      s6(6, 6) = 1.0_dp / d(9)
      do k = 1, 6
        s6(k + 1:6, k) = s6(k, k + 1:6)
      end do
      call invert(s6, c6, ok)
      return
    case (law_anisotropic)
      do k = 1, 21
        c6(aniso_row(k), aniso_col(k)) = d(k)
      end do
    end select
    do k = 1, 6
      c6(k + 1:6, k) = c6(k, k + 1:6)
    end do
  end subroutine stiffness_3d

  !> Plane-stress stiffness (3x3: 11, 22, 12) of a LAMINA: E1, E2, nu12, G12 (nu21 = nu12 E2/E1).
  pure function lamina_q(d) result(q)
    real(dp), intent(in) :: d(:)  !< E1, E2, nu12, G12, G13, G23
    real(dp) :: q(3, 3), den
    den = 1.0_dp - d(3) * d(3) * d(2) / d(1)
    q = 0.0_dp
    q(1, 1) = d(1) / den
    q(2, 2) = d(2) / den
    q(1, 2) = d(3) * d(2) / den
    q(2, 1) = q(1, 2)
    q(3, 3) = d(4)
  end function lamina_q

  !> DDSDDE of the law at temperature t for NDI direct and NSHR shear components: the 3D stiffness (NDI = 3), its
  !> rows and columns 11, 22, 33, 12 (plane strain, axisymmetric: NSHR = 1), or the plane-stress stiffness
  !> (NDI = 2): the inverse of the in-plane block of the compliance (sigma_33 = sigma_13 = sigma_23 = 0).
  pure subroutine elastic_law_stiffness(law, t, ndi, nshr, ddsdde)
    type(elastic_law_t), intent(in) :: law  !< the law
    real(dp), intent(in) :: t               !< temperature
    integer, intent(in) :: ndi, nshr        !< direct and shear components
    real(dp), intent(out) :: ddsdde(:, :)   !< (ntens, ntens)
    real(dp) :: c6(6, 6), s6(6, 6), sp(3, 3), q(3, 3)
    logical :: ok
    integer, parameter :: plane(3) = [1, 2, 4]
    ddsdde = 0.0_dp
    if (law%kind == law_lamina) then
      ddsdde(1:3, 1:3) = lamina_q(table_at(law%temp, law%data, t))
      return
    end if
    call stiffness_3d(law%kind, table_at(law%temp, law%data, t), c6, ok)
    if (ndi == 3) then
      ddsdde(1:3 + nshr, 1:3 + nshr) = c6(1:3 + nshr, 1:3 + nshr)
    else
      call invert(c6, s6, ok)
      sp = s6(plane, plane)
      call invert(sp, q, ok)
      ddsdde(1:3, 1:3) = q
    end if
  end subroutine elastic_law_stiffness

  !> Full 3D compliance (6x6) of the law at temperature t (not for LAMINA, which has none).
  pure subroutine elastic_law_compliance(law, t, s6, ok)
    type(elastic_law_t), intent(in) :: law  !< the law
    real(dp), intent(in) :: t               !< temperature
    real(dp), intent(out) :: s6(6, 6)       !< compliance
    logical, intent(out) :: ok              !< invertible
    real(dp) :: c6(6, 6)
    call stiffness_3d(law%kind, table_at(law%temp, law%data, t), c6, ok)
    if (ok) call invert(c6, s6, ok)
  end subroutine elastic_law_compliance

  !> Stress update of the general law (the material axes' components): sigma = C(T) : eps_el in rate form,
  !> sigma_new = sigma_rot + C(T1) : deps + (C(T1) - C(T0)) : eps_rot, which is the hypoelastic update of the
  !> constant law (elastic_update) when C does not change and keeps sigma = C(T) : eps_el when it does. sse as
  !> elastic_update (trapezoidal).
  pure subroutine elastic_law_update(law, t0, dt, ndi, nshr, stress, stran, dstran, ddsdde, sse)
    type(elastic_law_t), intent(in) :: law   !< the law
    real(dp), intent(in) :: t0, dt           !< temperature at the start of the increment and its increment
    integer, intent(in) :: ndi, nshr         !< direct and shear components
    real(dp), intent(inout) :: stress(:)     !< in: rotated start-of-increment stress; out: end of increment
    real(dp), intent(in) :: stran(:)         !< rotated mechanical strain at the start of the increment
    real(dp), intent(in) :: dstran(:)        !< mechanical strain increment (engineering shears)
    real(dp), intent(out) :: ddsdde(:, :)    !< tangent C(T1)
    real(dp), intent(inout) :: sse           !< elastic energy density
    real(dp) :: s0(size(stress)), c0(size(stress), size(stress))
    call elastic_law_stiffness(law, t0 + dt, ndi, nshr, ddsdde)
    s0 = stress
    stress = stress + matmul(ddsdde, dstran)
    if (size(law%temp) > 1 .and. dt /= 0.0_dp) then
      call elastic_law_stiffness(law, t0, ndi, nshr, c0)
      stress = stress + matmul(ddsdde - c0, stran)
    end if
    sse = sse + 0.5_dp * dot_product(s0 + stress, dstran)
  end subroutine elastic_law_update

  !> Thermal strain increment of the *EXPANSION (the material axes' components, engineering shears): eps_th(T) =
  !> alpha(T) (T - ZERO) (Abaqus: the thermal strain of temperature-dependent coefficients, measured from ZERO; its
  !> value at the initial temperature cancels in increments), so deps_th = alpha(T1)(T1 - ZERO) - alpha(T0)(T0 -
  !> ZERO); with one data point alpha dT. ORTHO: 11, 22, 33; ANISO also 12, 13, 23 (tensor components: the
  !> engineering shear strain is 2 alpha_ij dT, inferred). Plane stress (NDI = 2): the in-plane components only.
  pure subroutine thermal_strain_increment(law, t0, dt, ndi, nshr, deps)
    type(elastic_law_t), intent(in) :: law  !< the law
    real(dp), intent(in) :: t0, dt          !< temperature at the start of the increment and its increment
    integer, intent(in) :: ndi, nshr        !< direct and shear components
    real(dp), intent(out) :: deps(:)        !< (ntens) thermal strain increment
    real(dp) :: e6(6)
    e6 = thermal_strain6(law, t0, dt)
    deps = 0.0_dp
    deps(1:ndi) = e6(1:ndi)
    if (nshr >= 1) deps(ndi + 1:ndi + nshr) = e6(4:3 + nshr)
  end subroutine thermal_strain_increment

  !> Thermal strain increment as a 6-vector (11, 22, 33, 12, 13, 23; engineering shears).
  pure function thermal_strain6(law, t0, dt) result(e6)
    type(elastic_law_t), intent(in) :: law  !< the law
    real(dp), intent(in) :: t0, dt          !< temperature and increment
    real(dp) :: e6(6), a1(6), a0(6)
    integer :: n
    e6 = 0.0_dp
    if (law%exp_kind == expansion_none) return
    n = law_nexp(law%exp_kind)
    a1 = 0.0_dp
    a0 = 0.0_dp
    if (size(law%exp_temp) == 1) then
      a1(1:n) = law%exp_data(:, 1) * dt
    else
      a1(1:n) = table_at(law%exp_temp, law%exp_data, t0 + dt) * (t0 + dt - law%zero)
      a0(1:n) = table_at(law%exp_temp, law%exp_data, t0) * (t0 - law%zero)
      a1 = a1 - a0
    end if
    select case (law%exp_kind)
    case (expansion_iso)
      e6(1:3) = a1(1)
    case (expansion_ortho)
      e6(1:3) = a1(1:3)
    case (expansion_aniso)
      e6(1:3) = a1(1:3)
      e6(4:6) = 2.0_dp * a1(4:6)
    end select
  end function thermal_strain6

  !> Thickness strain increment of a plane-stress point (sigma_33 = sigma_13 = sigma_23 = 0): deps_33 = deps_33^th
  !> + S_3p Q (deps_p - deps_p^th) in the material axes, deps_p the in-plane strain increment (11, 22, 12) given
  !> in global components deps_g and turned into the material axes a2 (2x2, the axes as columns).
  pure function elastic_thickness_increment(law, t0, dt, a2, deps_g) result(d33)
    type(elastic_law_t), intent(in) :: law  !< the law (not LAMINA)
    real(dp), intent(in) :: t0, dt          !< temperature and increment
    real(dp), intent(in) :: a2(2, 2)        !< material axes in the plane (columns)
    real(dp), intent(in) :: deps_g(3)       !< in-plane strain increment 11, 22, 12 (engineering), global
    real(dp) :: d33, e(2, 2), s6(6, 6), q(3, 3), dp3(3), th(6)
    logical :: ok
    integer, parameter :: plane(3) = [1, 2, 4]
    e = reshape([deps_g(1), 0.5_dp * deps_g(3), 0.5_dp * deps_g(3), deps_g(2)], [2, 2])
    e = matmul(matmul(transpose(a2), e), a2)
    th = thermal_strain6(law, t0, dt)
    dp3 = [e(1, 1), e(2, 2), 2.0_dp * e(1, 2)] - th(plane)
    call elastic_law_compliance(law, t0 + dt, s6, ok)
    call elastic_law_stiffness(law, t0 + dt, 2, 1, q)
    d33 = th(3) + dot_product(s6(3, plane), matmul(q, dp3))
  end function elastic_thickness_increment

  !> Shear modulus for the hourglass stiffness of reduced-integration elements: the mean of the shear diagonal of
  !> the 3D stiffness at the first data point (G12 for LAMINA).
  pure function elastic_law_shear_modulus(law) result(g)
    type(elastic_law_t), intent(in) :: law  !< the law
    real(dp) :: g, c6(6, 6)
    logical :: ok
    if (law%kind == law_lamina) then
      g = law%data(4, 1)
      return
    end if
    call stiffness_3d(law%kind, law%data(:, 1), c6, ok)
    g = (c6(4, 4) + c6(5, 5) + c6(6, 6)) / 3.0_dp
  end function elastic_law_shear_modulus

  !> The law is usable: at every data point a positive definite stiffness (LAMINA: Q positive definite and G13,
  !> G23 > 0), finite constants. stat = 1 and errmsg naming the point otherwise.
  pure subroutine elastic_law_check(law, stat, errmsg)
    type(elastic_law_t), intent(in) :: law   !< the law
    integer, intent(out) :: stat             !< 0 valid, 1 invalid
    character(len=*), intent(out) :: errmsg  !< reason
    real(dp) :: c6(6, 6), q(3, 3)
    logical :: ok
    integer :: ip
    character(len=16) :: b
    stat = 0
    errmsg = ''
    do ip = 1, size(law%temp)
      write (b, '(i0)') ip
      if (law%kind == law_lamina) then
        q = lamina_q(law%data(:, ip))
        ok = law%data(1, ip) > 0.0_dp .and. law%data(2, ip) > 0.0_dp .and. positive_definite(q) .and. &
          law%data(5, ip) > 0.0_dp .and. law%data(6, ip) > 0.0_dp
      else
        ok = .true.
        ! (the moduli of engineering constants are divided by: positive first)
        if (law%kind == law_engineering) ok = all(law%data([1, 2, 3, 7, 8, 9], ip) > 0.0_dp)
        if (ok) then
          call stiffness_3d(law%kind, law%data(:, ip), c6, ok)
          ok = ok .and. positive_definite(c6)
        end if
      end if
      if (.not. ok) then
        stat = 1
        errmsg = '*ELASTIC: the constants of data point '//trim(b)//' give no positive definite stiffness '// &
          '(the material would not be stable)'
        return
      end if
    end do
  end subroutine elastic_law_check

  !> Symmetric matrix a is positive definite (Cholesky without breakdown).
  pure logical function positive_definite(a) result(pd)
    real(dp), intent(in) :: a(:, :)  !< symmetric matrix
    real(dp) :: l(size(a, 1), size(a, 1)), s
    integer :: i, j, n
    n = size(a, 1)
    l = 0.0_dp
    pd = .false.
    do j = 1, n
      s = a(j, j) - sum(l(j, 1:j - 1)**2)
      if (.not. (s > 0.0_dp)) return
      l(j, j) = sqrt(s)
      do i = j + 1, n
        l(i, j) = (a(i, j) - sum(l(i, 1:j - 1) * l(j, 1:j - 1))) / l(j, j)
      end do
    end do
    pd = .true.
  end function positive_definite

  !> Inverse of a small square matrix by Gauss-Jordan elimination with partial pivoting (ok = .false. when
  !> singular).
  pure subroutine invert(a, ainv, ok)
    real(dp), intent(in) :: a(:, :)      !< matrix
    real(dp), intent(out) :: ainv(:, :)  !< its inverse
    logical, intent(out) :: ok           !< .false.: singular
    real(dp) :: w(size(a, 1), 2 * size(a, 1)), row(2 * size(a, 1))
    integer :: i, k, p, n
    n = size(a, 1)
    w = 0.0_dp
    w(:, 1:n) = a
    do i = 1, n
      w(i, n + i) = 1.0_dp
    end do
    ok = .false.
    ainv = 0.0_dp
    do k = 1, n
      p = k - 1 + maxloc(abs(w(k:n, k)), 1)
      if (.not. (abs(w(p, k)) > 0.0_dp)) return
      row = w(p, :)
      w(p, :) = w(k, :)
      w(k, :) = row / row(k)
      do i = 1, n
        if (i /= k) w(i, :) = w(i, :) - w(i, k) * w(k, :)
      end do
    end do
    ainv = w(:, n + 1:2 * n)
    ok = .true.
  end subroutine invert

end module solid_elastic
