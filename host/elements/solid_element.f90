!> Continuum elements C3D8 (8-node hexahedron, 2x2x2 Gauss) and CPE4 (4-node plane-strain quadrilateral, 2x2 Gauss)
!> with the F-bar method of de Souza Neto, Peric, Dutko and Owen (1996, Int. J. Solids Struct. 33, 3277-3296),
!> calling their material exactly as Abaqus/Standard calls a UMAT (../../../shared/CONVENTIONS.md).
!>
!> Kinematics at Gauss point p (updated Lagrange, NLGEOM):
!>   F = dx/dX at t_n (F0, from u - du) and t_n+1 (F1, from u); J = det F; J_c = det F at the element centre.
!>   F-bar:  Fbar = (J_c / J)^(1/m) F  on the in-plane block, m = 3 (C3D8) or m = 2 (CPE4, F33 = 1), so det Fbar = J_c.
!>   Hughes-Winget mid-point increment: G = (Fbar1 - Fbar0) ((Fbar0 + Fbar1) / 2)^-1 = grad(du) w.r.t. x_mid,
!>   DSTRAN = sym G (engineering shears), W = skw G, DROT = (I - W/2)^-1 (I + W/2).
!>   STRESS and STRAN are rotated by DROT before the call; DFGRD0 = Fbar0, DFGRD1 = Fbar1.
!> Without NLGEOM: DSTRAN = sym of grad(du) w.r.t. X with its trace replaced by the centre value (B-bar, the small
!>   strain limit of F-bar), DROT = I, f_int and K on the reference configuration.
!> Local orientation (*ORIENTATION on the section; optional argument orient = T0, local axes as columns): the
!>   material sees STRESS, STRAN, DSTRAN, DDSDDE, DFGRD0/1 in the local axes T = R T0, R the rotation of the polar
!>   decomposition Fbar = R U (T = T0 without NLGEOM), as Abaqus/Standard does for continuum elements (it passes
!>   DFGRD1 = T1^T Fbar1 T0, the stretch in local components); DROT = Tn^T T1 is the rotation of the local axes
!>   over the increment in their own components. The state is stored in global components (output, f_int):
!>   sigma = T1 sigma_local T1^T and DDSDDE turned the same way; the dependence of T on u is left out of the
!>   tangent (exact without NLGEOM).
!>
!> Internal force and tangent (current configuration, dv = J dV):
!>   f_(a i) = int sigma_ij dN_a/dx_j dv
!>   A_ijkl  = DDSDDE_ijkl - 1/2 (d_ik s_jl + d_il s_jk + s_ik d_jl + s_il d_jk) + d_ik s_jl   (material + geometric)
!>   q_ij    = (1/m) sum_(a in-plane) A_ijaa - (1 - 1/m) s_ij                               (F-bar term)
!>   K_(a i)(b k) = int [ dN_a/dx_j A_ijkl dN_b/dx_l + dN_a/dx_j q_ij (dN_b/dx_k|centre - dN_b/dx_k) ] dv
!> The derivation (linearisation of J sigma(Fbar) with d(Fbar) Fbar^-1 = dL + (1/m)(tr dL_c - tr dL) I) is in
!> docs/elements.md; it is exact when DDSDDE is the exact Jaumann tangent of a stress that depends on DFGRD1 only.
!> Without NLGEOM the same formulas hold with x = X, sigma-terms dropped (A = DDSDDE, q = (1/m) sum_a A_ijaa).
!> DDSDDE is symmetrised first unless the material is a UMAT with UNSYMM (Abaqus semantics). k_e itself is NOT
!> symmetrised: the F-bar term (and under NLGEOM the Jaumann/geometric terms) make it unsymmetric, and a
!> symmetrised k_e would cost the quadratic convergence of Newton (it is symmetric for a homogeneous state only).
module solid_element
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use ldfcz_kinds, only: dp
  use solid_umat_interface, only: umat_interface
  use solid_shape, only: solid_shape_eval, solid_gauss_point, SHAPE_C3D8, SHAPE_CPE4
  use solid_elastic, only: elastic_update, elastic_check
  use solid_tangent_kernel, only: k_point_c3d8
  implicit none
  private
  public :: solid_material_t, solid_element_info, solid_element_compute, umat_interface
  public :: solid_geometry_t, solid_element_geometry
  public :: SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, SOLID_PNEWDT_LARGE
  public :: polar_rotation

  integer, parameter :: SOLID_MAT_ELASTIC = 1    !< built-in *ELASTIC (isotropic, hypoelastic under NLGEOM)
  integer, parameter :: SOLID_MAT_UMAT = 2       !< Abaqus UMAT through a procedure pointer
  real(dp), parameter :: SOLID_PNEWDT_LARGE = 1.0e36_dp  !< PNEWDT handed to each UMAT call ("a large value")
  integer, parameter :: maxnode = 8, maxip = 8
  !> Voigt position of tensor component (i,j), order 11,22,33,12,13,23 (CPE4 uses only i,j <= 2: 11,22,12)
  integer, parameter :: vidx(3, 3) = reshape([1, 4, 5, 4, 2, 6, 5, 6, 3], [3, 3])

  !> Material (and section) data of an element set.
  type :: solid_material_t
    integer :: kind = SOLID_MAT_ELASTIC                 !< SOLID_MAT_ELASTIC or SOLID_MAT_UMAT
    real(dp) :: e = 0.0_dp                              !< *ELASTIC Young's modulus (MPa)
    real(dp) :: nu = 0.0_dp                             !< *ELASTIC Poisson's ratio
    real(dp), allocatable :: props(:)                   !< *USER MATERIAL constants (PROPS)
    integer :: nstatv = 0                               !< *DEPVAR count (NSTATV)
    character(len=80) :: cmname = ' '                   !< material name as passed in CMNAME (upper case in Abaqus)
    logical :: unsymm = .false.                         !< *USER MATERIAL, UNSYMM: keep the unsymmetric tangent
    real(dp) :: thickness = 1.0_dp                      !< *SOLID SECTION thickness of plane elements (CPE4)
    real(dp) :: alpha = 0.0_dp                          !< *EXPANSION isotropic coefficient (thermal strain alpha dT)
    procedure(umat_interface), pointer, nopass :: umat => null()  !< the UMAT to call when kind = SOLID_MAT_UMAT
  end type solid_material_t

  !> Reference-configuration data of one element, the same on every call (original coordinates): shape functions,
  !> dN/dX and Gauss weight x det(dX/dxi) at the integration points, dN/dX at the centre. A host may compute it once
  !> per element (solid_element_geometry) and pass it to solid_element_compute instead of the per-call recomputation.
  type :: solid_geometry_t
    logical :: valid = .false.                          !< computed, every reference Jacobian > 0
    ! (no default values: a local copy per element call stays a plain copy; solid_element_geometry sets them all)
    real(dp) :: nfun(maxnode, maxip)           !< N_a at the integration points
    real(dp) :: dndx_ref(maxnode, 3, maxip)    !< dN_a/dX_j at the integration points
    real(dp) :: wdet(maxip)                    !< Gauss weight x det(dX/dxi)
    real(dp) :: dndx_0c(maxnode, 3)            !< dN_a/dX_j at the element centre
  end type solid_geometry_t

contains

  !> Sizes of an element type: nodes, spatial dimensions, integration points, stress components.
  !> Unknown etype: every output 0.
  pure subroutine solid_element_info(etype, nnode, ndim, nip, ntens, ndi, nshr)
    character(len=*), intent(in) :: etype  !< 'C3D8' or 'CPE4' (case-insensitive)
    integer, intent(out) :: nnode          !< nodes per element
    integer, intent(out) :: ndim           !< coordinates and displacement dofs per node
    integer, intent(out) :: nip            !< integration points
    integer, intent(out) :: ntens          !< stress components (ndi + nshr)
    integer, intent(out) :: ndi            !< direct stress components
    integer, intent(out) :: nshr           !< shear stress components

    select case (shape_of(etype))
    case (SHAPE_C3D8)
      nnode = 8; ndim = 3; nip = 8; ntens = 6; ndi = 3; nshr = 3
    case (SHAPE_CPE4)
      nnode = 4; ndim = 2; nip = 4; ntens = 4; ndi = 3; nshr = 1
    case default
      nnode = 0; ndim = 0; nip = 0; ntens = 0; ndi = 0; nshr = 0
    end select
  end subroutine solid_element_info

  !> Reference-configuration data of an element (solid_geometry_t); geo%valid = .false. for an unknown type, sizes
  !> that do not match it, or a reference Jacobian <= 0 (solid_element_compute then reports the element itself).
  subroutine solid_element_geometry(etype, coords0, geo)
    character(len=*), intent(in) :: etype             !< 'C3D8' or 'CPE4'
    real(dp), intent(in) :: coords0(:, :)             !< (ndim, nnode) original coordinates
    type(solid_geometry_t), intent(out) :: geo        !< reference data
    integer :: shape, nnode, ndim, nip, ntens, ndi, nshr, ip
    real(dp) :: xi(3), w, detj, nc(maxnode)
    geo%nfun = 0.0_dp
    geo%dndx_ref = 0.0_dp
    geo%wdet = 0.0_dp
    geo%dndx_0c = 0.0_dp
    shape = shape_of(etype)
    call solid_element_info(etype, nnode, ndim, nip, ntens, ndi, nshr)
    if (nnode == 0) return
    if (size(coords0, 1) /= ndim .or. size(coords0, 2) /= nnode) return
    xi = 0.0_dp
    call solid_reference_derivatives(shape, nnode, ndim, coords0, xi, nc, geo%dndx_0c, detj)
    if (.not. (detj > 0.0_dp)) return
    do ip = 1, nip
      call solid_gauss_point(shape, ip, xi, w)
      call solid_reference_derivatives(shape, nnode, ndim, coords0, xi, geo%nfun(:, ip), geo%dndx_ref(:, :, ip), detj)
      if (.not. (detj > 0.0_dp)) return
      geo%wdet(ip) = w * detj
    end do
    geo%valid = .true.
  end subroutine solid_element_geometry

  !> Shape functions and reference derivatives dN/dX at parent point xi; detj = det(dX/dxi) (dndx = 0 if <= 0).
  pure subroutine solid_reference_derivatives(shape, nnode, ndim, coords0, xi, n_p, dndx_p, detj)
    integer, intent(in) :: shape, nnode, ndim
    real(dp), intent(in) :: coords0(:, :), xi(3)
    real(dp), intent(out) :: n_p(maxnode), dndx_p(maxnode, 3), detj
    real(dp) :: dndxi(maxnode, 3), jac(3, 3), jinv(3, 3)
    dndxi = 0.0_dp
    n_p = 0.0_dp
    call solid_shape_eval(shape, xi(1:ndim), n_p(1:nnode), dndxi(1:nnode, 1:ndim))
    jac = identity()
    jac(1:ndim, 1:ndim) = matmul(coords0(1:ndim, 1:nnode), dndxi(1:nnode, 1:ndim))
    detj = det3(jac)
    dndx_p = 0.0_dp
    if (detj > 0.0_dp) then
      jinv = inv3(jac)
      dndx_p(1:nnode, 1:ndim) = matmul(dndxi(1:nnode, 1:ndim), jinv(1:ndim, 1:ndim))
    end if
  end subroutine solid_reference_derivatives


  !> Internal force, tangent and updated integration-point state of one element for the current Newton estimate.
  !> Never produces NaN: on failure (stat /= 0) f_int = 0, k_e = 0, the new state equals the old one.
  subroutine solid_element_compute(etype, coords0, u, du, mat, stress_old, stran_old, statev_old, time, dtime, &
      kstep, kinc, noel, nlgeom, want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, errmsg, &
      energy_ip_old, energy_ip_new, geo, temp_nodes, dtemp_nodes, orient, field_nodes, dfield_nodes)
    character(len=*), intent(in) :: etype             !< 'C3D8' or 'CPE4'
    real(dp), intent(in) :: coords0(:, :)             !< (ndim, nnode) original coordinates
    real(dp), intent(in) :: u(:)                      !< (ndim*nnode) total displacement, current Newton estimate
    real(dp), intent(in) :: du(:)                     !< (ndim*nnode) increment since the last converged state
    type(solid_material_t), intent(in) :: mat         !< material and section
    real(dp), intent(in) :: stress_old(:, :)          !< (ntens, nip) converged Cauchy stress
    real(dp), intent(in) :: stran_old(:, :)           !< (ntens, nip) converged strain (engineering shears)
    real(dp), intent(in) :: statev_old(:, :)          !< (>= nstatv, nip) converged state variables
    real(dp), intent(in) :: time(2)                   !< step time and total time at the start of the increment
    real(dp), intent(in) :: dtime                     !< time increment
    integer, intent(in) :: kstep                      !< step number
    integer, intent(in) :: kinc                       !< increment number
    integer, intent(in) :: noel                       !< element label (NOEL)
    logical, intent(in) :: nlgeom                     !< geometric nonlinearity
    logical, intent(in) :: want_k                     !< compute k_e (otherwise k_e = 0)
    real(dp), intent(out) :: f_int(:)                 !< (ndim*nnode) internal force
    real(dp), intent(out) :: k_e(:, :)                !< (ndim*nnode)^2 tangent d f_int / d u (unsymmetric)
    real(dp), intent(out) :: stress_new(:, :)         !< (ntens, nip) Cauchy stress at the end of the increment
    real(dp), intent(out) :: stran_new(:, :)          !< (ntens, nip) rotated old strain + DSTRAN
    real(dp), intent(out) :: statev_new(:, :)         !< (>= nstatv, nip) state variables from the material
    real(dp), intent(out) :: energy(2)                !< element integrals of SSE and SPD (N mm)
    real(dp), intent(inout) :: pnewdt                 !< min over points of the materials' PNEWDT (unchanged if none)
    integer, intent(out) :: stat                      !< 0 ok; 1 inverted element; 2 bad input; 3 non-finite material
    character(len=*), intent(out) :: errmsg           !< message when stat /= 0
    real(dp), intent(in), optional :: energy_ip_old(:, :)  !< (3, nip) converged SSE, SPD, SCD (zeros if absent)
    real(dp), intent(out), optional :: energy_ip_new(:, :) !< (3, nip) updated SSE, SPD, SCD
    !> reference data of this element from solid_element_geometry (computed here when absent or not valid)
    type(solid_geometry_t), intent(in), optional, target :: geo
    real(dp), intent(in), optional :: temp_nodes(:)   !< (nnode) nodal temperatures at the start of the increment
    real(dp), intent(in), optional :: dtemp_nodes(:)  !< (nnode) their increments (TEMP, DTEMP interpolated to points)
    real(dp), intent(in), optional :: orient(:, :, :) !< (3, 3, nip) local material axes T0 (columns) per point
    real(dp), intent(in), optional :: field_nodes(:, :)  !< (nfield, nnode) field variables at the increment's start
    real(dp), intent(in), optional :: dfield_nodes(:, :) !< (nfield, nnode) their increments (PREDEF, DPRED at points)
    real(dp) :: temp_ip, dtemp_ip, tn(3, 3), t1(3, 3), drot_m(3, 3), fl0(3, 3), fl1(3, 3)
    real(dp) :: s_unit(6), col_g(6, 6)
    logical :: local

    integer :: nnode, ndim, nip, ntens, ndi, nshr, ndof, nsv, np
    integer :: a, b, i, k, ip, r, c, jstep(4)
    real(dp) :: xref(3, maxnode), un(3, maxnode), u1(3, maxnode), dun(3, maxnode)
    type(solid_geometry_t), target :: gl          ! reference data computed here when the host has none
    type(solid_geometry_t), pointer :: gp         ! the reference data in use (no per-call copy of the host's)
    real(dp) :: fg0(3, 3, maxip), fg1(3, 3, maxip), dndx_c(maxnode, 3)
    real(dp) :: fc0(3, 3), fc1(3, 3), jc0, jc1, j0, j1, vol, celent
    real(dp) :: fb0(3, 3), fb1(3, 3), fm(3, 3), g(3, 3), wsk(3, 3), drot(3, 3), eye(3, 3)
    real(dp) :: sig(3, 3), eps(3, 3), dndx(maxnode, 3), finv(3, 3), dv, gc(3, 3), trc, trg, m
    real(dp) :: stress(6), stran(6), dstran(6), ddsdde(6, 6), coords(3)
    real(dp) :: sse, spd, scd, pn, a4(3, 3, 3, 3), q(3, 3), bc(maxnode, 3), t(3, 3), kl(maxnode, 3, 3, maxnode)
    real(dp) :: sv(max(1, mat%nstatv)), pr(max(1, nprops_of(mat)))
    character(len=80) :: cmname
    character(len=*), parameter :: here = 'solid_element_compute: '

    stat = 0
    errmsg = ''
    f_int = 0.0_dp
    energy = 0.0_dp
    call solid_element_info(etype, nnode, ndim, nip, ntens, ndi, nshr)
    ndof = ndim * nnode
    nsv = mat%nstatv
    np = nprops_of(mat)

    ! ---- argument checks (bad input: stat = 2)
    if (nnode == 0) then
      call fail(2, here // 'unknown element type "' // trim(etype) // '"')
      return
    end if
    if (size(coords0, 1) /= ndim .or. size(coords0, 2) /= nnode .or. size(u) /= ndof .or. size(du) /= ndof .or. &
        size(f_int) /= ndof .or. size(k_e, 1) /= ndof .or. size(k_e, 2) /= ndof .or. &
        size(stress_old, 1) /= ntens .or. size(stress_old, 2) /= nip .or. size(stran_old, 1) /= ntens .or. &
        size(stran_old, 2) /= nip .or. size(stress_new, 1) /= ntens .or. size(stress_new, 2) /= nip .or. &
        size(stran_new, 1) /= ntens .or. size(stran_new, 2) /= nip .or. size(statev_old, 1) < nsv .or. &
        size(statev_old, 2) /= nip .or. size(statev_new, 1) < nsv .or. size(statev_new, 2) /= nip) then
      call fail(2, here // 'array sizes do not match element type ' // trim(etype))
      return
    end if
    if (present(energy_ip_old)) then
      if (size(energy_ip_old, 1) < 3 .or. size(energy_ip_old, 2) /= nip) then
        call fail(2, here // 'energy_ip_old must be (3, nip)')
        return
      end if
    end if
    if (present(energy_ip_new)) then
      if (size(energy_ip_new, 1) < 3 .or. size(energy_ip_new, 2) /= nip) then
        call fail(2, here // 'energy_ip_new must be (3, nip)')
        return
      end if
    end if
    select case (mat%kind)
    case (SOLID_MAT_ELASTIC)
      call elastic_check(mat%e, mat%nu, i, errmsg)
      if (i /= 0) then
        call fail(2, here // trim(errmsg))
        return
      end if
    case (SOLID_MAT_UMAT)
      if (.not. associated(mat%umat)) then
        call fail(2, here // 'material kind UMAT without a UMAT procedure')
        return
      end if
    case default
      call fail(2, here // 'unknown material kind')
      return
    end select
    if (.not. (mat%thickness > 0.0_dp)) then
      call fail(2, here // 'section thickness must be > 0')
      return
    end if

    eye = identity()
    m = real(ndim, dp)
    xref = 0.0_dp
    un = 0.0_dp
    u1 = 0.0_dp
    dun = 0.0_dp
    do a = 1, nnode
      xref(1:ndim, a) = coords0(:, a)
      u1(1:ndim, a) = u(ndim * (a - 1) + 1:ndim * a)
      dun(1:ndim, a) = du(ndim * (a - 1) + 1:ndim * a)
      un(1:ndim, a) = u1(1:ndim, a) - dun(1:ndim, a)
    end do

    ! ---- reference data (shape functions, dN/dX, weights): the host's copy or computed now
    gp => gl
    if (present(geo)) then
      if (geo%valid) gp => geo
    end if
    if (.not. gp%valid) call solid_element_geometry(etype, coords0, gl)
    if (.not. gp%valid) then
      call fail(1, 'inverted element ' // itoa(noel) // ' (reference Jacobian <= 0 at the centre or at an ' // &
                'integration point)')
      return
    end if

    ! ---- element centre: J_c at t_n and t_n+1, spatial derivatives for the F-bar tangent
    fc0 = def_grad(un, gp%dndx_0c)
    fc1 = def_grad(u1, gp%dndx_0c)
    jc0 = det3(fc0)
    jc1 = det3(fc1)
    if (.not. (jc0 > 0.0_dp .and. jc1 > 0.0_dp)) then
      call fail(1, 'inverted element ' // itoa(noel) // ' (J <= 0 at the centre)')
      return
    end if
    if (nlgeom) then
      finv = inv3(fc1)
      dndx_c = 0.0_dp
      dndx_c(1:nnode, 1:ndim) = matmul(gp%dndx_0c(1:nnode, 1:ndim), finv(1:ndim, 1:ndim))
    else
      dndx_c = gp%dndx_0c
    end if

    ! ---- first pass: kinematics at the integration points, checks, volume for CELENT
    vol = 0.0_dp
    do ip = 1, nip
      fg0(:, :, ip) = def_grad(un, gp%dndx_ref(:, :, ip))
      fg1(:, :, ip) = def_grad(u1, gp%dndx_ref(:, :, ip))
      j0 = det3(fg0(:, :, ip))
      j1 = det3(fg1(:, :, ip))
      if (.not. (j0 > 0.0_dp .and. j1 > 0.0_dp)) then
        call fail(1, 'inverted element ' // itoa(noel) // ' (J <= 0 at integration point ' // itoa(ip) // ')')
        return
      end if
      vol = vol + gp%wdet(ip) * merge(j1, 1.0_dp, nlgeom)
    end do
    celent = vol**(1.0_dp / m)

    jstep = [kstep, 1, merge(1, 0, nlgeom), 0]
    cmname = mat%cmname
    if (np > 0) pr(1:np) = mat%props

    ! ---- second pass: material calls, internal force, tangent
    if (want_k) kl = 0.0_dp
    do ip = 1, nip
      j0 = det3(fg0(:, :, ip))
      j1 = det3(fg1(:, :, ip))
      fb0 = fg0(:, :, ip)
      fb1 = fg1(:, :, ip)
      fb0(1:ndim, 1:ndim) = (jc0 / j0)**(1.0_dp / m) * fb0(1:ndim, 1:ndim)
      fb1(1:ndim, 1:ndim) = (jc1 / j1)**(1.0_dp / m) * fb1(1:ndim, 1:ndim)

      if (nlgeom) then
        ! Hughes-Winget: G = grad(du) w.r.t. x_mid, with the F-bar modified gradients
        fm = 0.5_dp * (fb0 + fb1)
        if (.not. (det3(fm) > 0.0_dp)) then
          call fail(1, 'inverted element ' // itoa(noel) // ' (mid-increment J <= 0 at integration point ' &
                    // itoa(ip) // ')')
          return
        end if
        g = matmul(fb1 - fb0, inv3(fm))
        ! DROT = (I - W/2)^-1 (I + W/2), W = (G - G^T)/2 (Hughes-Winget), in closed form: with A = W/2 (skew,
        ! axial vector a), A^3 = -|a|^2 A gives (I - A)^-1 = I + (A + A^2)/(1 + |a|^2),
        ! so DROT = I + 2 (A + A^2)/(1 + |a|^2)
        wsk = 0.25_dp * (g - transpose(g))
        drot = eye + (2.0_dp / (1.0_dp + wsk(3, 2)**2 + wsk(1, 3)**2 + wsk(2, 1)**2)) * (wsk + matmul(wsk, wsk))
      else
        ! small strain: grad(du) w.r.t. X with the centre dilatation (B-bar)
        g = def_grad(dun, gp%dndx_ref(:, :, ip)) - eye
        gc = def_grad(dun, gp%dndx_0c) - eye
        trg = 0.0_dp
        trc = 0.0_dp
        do i = 1, ndim
          trg = trg + g(i, i)
          trc = trc + gc(i, i)
        end do
        do i = 1, ndim
          g(i, i) = g(i, i) + (trc - trg) / m
        end do
        drot = eye
      end if
      call tensor_to_voigt(0.5_dp * (g + transpose(g)), ntens, dstran, 2.0_dp)

      local = present(orient)
      drot_m = drot
      fl0 = fb0
      fl1 = fb1
      if (local) then
        ! local axes at the start and end of the increment; the material gets every tensor in their components
        tn = orient(:, :, ip)
        t1 = orient(:, :, ip)
        if (nlgeom) then
          tn = matmul(polar_rotation(fb0), tn)
          t1 = matmul(polar_rotation(fb1), t1)
        end if
        call voigt_to_tensor(stress_old(:, ip), ntens, sig, 1.0_dp)
        call tensor_to_voigt(matmul(matmul(transpose(tn), sig), tn), ntens, stress, 1.0_dp)
        call voigt_to_tensor(stran_old(:, ip), ntens, eps, 0.5_dp)
        call tensor_to_voigt(matmul(matmul(transpose(tn), eps), tn), ntens, stran, 2.0_dp)
        call voigt_to_tensor(dstran, ntens, eps, 0.5_dp)
        call tensor_to_voigt(matmul(matmul(transpose(t1), eps), t1), ntens, dstran, 2.0_dp)
        drot_m = matmul(transpose(tn), t1)
        fl0 = matmul(matmul(transpose(tn), fb0), orient(:, :, ip))
        fl1 = matmul(matmul(transpose(t1), fb1), orient(:, :, ip))
      else
        ! rotate the converged stress and strain by DROT (identity without NLGEOM)
        call voigt_to_tensor(stress_old(:, ip), ntens, sig, 1.0_dp)
        sig = matmul(matmul(drot, sig), transpose(drot))
        call tensor_to_voigt(sig, ntens, stress, 1.0_dp)
        call voigt_to_tensor(stran_old(:, ip), ntens, eps, 0.5_dp)
        eps = matmul(matmul(drot, eps), transpose(drot))
        call tensor_to_voigt(eps, ntens, stran, 2.0_dp)
      end if

      sse = 0.0_dp
      spd = 0.0_dp
      scd = 0.0_dp
      if (present(energy_ip_old)) then
        sse = energy_ip_old(1, ip)
        spd = energy_ip_old(2, ip)
        scd = energy_ip_old(3, ip)
      end if
      ! temperature at the point (TEMP, DTEMP of the UMAT); *EXPANSION: mechanical strain increment = total -
      ! alpha dT on the direct components (Abaqus subtracts the thermal strain before the material is called)
      temp_ip = 0.0_dp
      dtemp_ip = 0.0_dp
      if (present(temp_nodes)) temp_ip = dot_product(gp%nfun(1:nnode, ip), temp_nodes(1:nnode))
      if (present(dtemp_nodes)) dtemp_ip = dot_product(gp%nfun(1:nnode, ip), dtemp_nodes(1:nnode))
      if (mat%alpha /= 0.0_dp) dstran(1:ndi) = dstran(1:ndi) - mat%alpha * dtemp_ip
      ddsdde = 0.0_dp
      pn = SOLID_PNEWDT_LARGE
      select case (mat%kind)
      case (SOLID_MAT_ELASTIC)
        call elastic_update(mat%e, mat%nu, ndi, nshr, stress(1:ntens), dstran(1:ntens), ddsdde(1:ntens, 1:ntens), sse)
      case default
        sv = 0.0_dp
        if (nsv > 0) sv(1:nsv) = statev_old(1:nsv, ip)
        do i = 1, 3
          ! Abaqus: the current coordinates under NLGEOM, the original ones otherwise
          coords(i) = dot_product(gp%nfun(1:nnode, ip), xref(i, 1:nnode) + merge(u1(i, 1:nnode), 0.0_dp, nlgeom))
        end do
        ! PREDEF, DPRED: the field variables interpolated to the point (start of the increment) and their increments
        if (present(field_nodes) .and. present(dfield_nodes)) then
          call call_umat(mat%umat, stress, sv, ddsdde, sse, spd, scd, stran, dstran, time, dtime, cmname, ndi, &
            nshr, ntens, nsv, pr, np, coords, drot_m, pn, celent, fl0, fl1, noel, ip, jstep, kinc, temp_ip, &
            dtemp_ip, matmul(field_nodes(:, 1:nnode), gp%nfun(1:nnode, ip)), &
            matmul(dfield_nodes(:, 1:nnode), gp%nfun(1:nnode, ip)))
        else
          call call_umat(mat%umat, stress, sv, ddsdde, sse, spd, scd, stran, dstran, time, dtime, cmname, ndi, &
            nshr, ntens, nsv, pr, np, coords, drot_m, pn, celent, fl0, fl1, noel, ip, jstep, kinc, temp_ip, dtemp_ip)
        end if
        statev_new(1:nsv, ip) = sv(1:nsv)
      end select
      pnewdt = min(pnewdt, pn)
      if (.not. (all(ieee_is_finite(stress(1:ntens))) .and. all(ieee_is_finite(ddsdde(1:ntens, 1:ntens))))) then
        call fail(3, 'element ' // itoa(noel) // ': material returned a non-finite stress or DDSDDE at point ' &
                  // itoa(ip))
        return
      end if
      if (local) then
        ! back to global components: stress, strain and the tangent (column by column of unit global strains)
        call voigt_to_tensor(stress(1:ntens), ntens, sig, 1.0_dp)
        call tensor_to_voigt(matmul(matmul(t1, sig), transpose(t1)), ntens, stress, 1.0_dp)
        call voigt_to_tensor(stran(1:ntens), ntens, eps, 0.5_dp)
        call tensor_to_voigt(matmul(matmul(t1, eps), transpose(t1)), ntens, stran, 2.0_dp)
        call voigt_to_tensor(dstran(1:ntens), ntens, eps, 0.5_dp)
        call tensor_to_voigt(matmul(matmul(t1, eps), transpose(t1)), ntens, dstran, 2.0_dp)
        do c = 1, ntens
          s_unit = 0.0_dp
          s_unit(c) = 1.0_dp
          call voigt_to_tensor(s_unit(1:ntens), ntens, eps, 0.5_dp)
          call tensor_to_voigt(matmul(matmul(transpose(t1), eps), t1), ntens, s_unit, 2.0_dp)
          s_unit(1:ntens) = matmul(ddsdde(1:ntens, 1:ntens), s_unit(1:ntens))
          call voigt_to_tensor(s_unit(1:ntens), ntens, sig, 1.0_dp)
          call tensor_to_voigt(matmul(matmul(t1, sig), transpose(t1)), ntens, s_unit, 1.0_dp)
          col_g(1:ntens, c) = s_unit(1:ntens)
        end do
        ddsdde(1:ntens, 1:ntens) = col_g(1:ntens, 1:ntens)
      end if
      if (mat%kind == SOLID_MAT_ELASTIC .and. nsv > 0) statev_new(1:nsv, ip) = statev_old(1:nsv, ip)
      if (size(statev_new, 1) > nsv) statev_new(nsv + 1:, ip) = statev_old(nsv + 1:, ip)
      stress_new(:, ip) = stress(1:ntens)
      stran_new(:, ip) = stran(1:ntens) + dstran(1:ntens)
      if (present(energy_ip_new)) then
        energy_ip_new(:, ip) = 0.0_dp
        energy_ip_new(1:3, ip) = [sse, spd, scd]
      end if

      ! spatial derivatives and volume element
      dndx = 0.0_dp
      if (nlgeom) then
        finv = inv3(fg1(:, :, ip))
        dndx(1:nnode, 1:ndim) = matmul(gp%dndx_ref(1:nnode, 1:ndim, ip), finv(1:ndim, 1:ndim))
        dv = gp%wdet(ip) * j1 * mat%thickness
      else
        dndx(1:nnode, 1:ndim) = gp%dndx_ref(1:nnode, 1:ndim, ip)
        dv = gp%wdet(ip) * mat%thickness
      end if
      energy = energy + [sse, spd] * dv

      call voigt_to_tensor(stress(1:ntens), ntens, sig, 1.0_dp)
      ! bc(b, k) = dN_b/dx_k at the centre minus at the point: the F-bar (B-bar) dilatation operator
      bc(1:nnode, 1:ndim) = dndx_c(1:nnode, 1:ndim) - dndx(1:nnode, 1:ndim)
      do a = 1, nnode
        do i = 1, ndim
          r = ndim * (a - 1) + i
          f_int(r) = f_int(r) + dot_product(sig(i, 1:ndim), dndx(a, 1:ndim)) * dv
        end do
      end do

      if (want_k) then
        if (.not. (mat%kind == SOLID_MAT_UMAT .and. mat%unsymm)) then
          ! Abaqus uses only the symmetric part of DDSDDE unless *USER MATERIAL, UNSYMM
          ddsdde(1:ntens, 1:ntens) = 0.5_dp * (ddsdde(1:ntens, 1:ntens) + transpose(ddsdde(1:ntens, 1:ntens)))
        end if
        call spatial_tangent(ddsdde, sig, ndim, nlgeom, a4, q)
        ! column (b k): t_ij = [sum_l A_ijkl dN_b/dx_l + q_ij bc_bk] dv, then K_(a i)(b k) += sum_j dN_a/dx_j t_ij
        ! (factorised: ~4 ndim^3 nnode^2 multiplications fewer than the direct quadruple sum)
        ! (dndx, q, a4 and t are zero beyond ndim, so fixed 3-term sums also serve CPE4; kl is a contiguous local)
        if (ndim == 3 .and. nnode == 8) then
          call k_point_c3d8(a4, q, dndx, bc, dv, kl)
        else
          do b = 1, nnode
            do k = 1, ndim
              t = (q * bc(b, k) + a4(:, :, k, 1) * dndx(b, 1) + a4(:, :, k, 2) * dndx(b, 2) &
                   + a4(:, :, k, 3) * dndx(b, 3)) * dv
              do i = 1, ndim
                kl(1:nnode, i, k, b) = kl(1:nnode, i, k, b) + t(i, 1) * dndx(1:nnode, 1) &
                                       + t(i, 2) * dndx(1:nnode, 2) + t(i, 3) * dndx(1:nnode, 3)
              end do
            end do
          end do
        end if
      end if
    end do
    if (want_k) then
      do b = 1, nnode
        do k = 1, ndim
          c = ndim * (b - 1) + k
          do a = 1, nnode
            r = ndim * (a - 1)
            k_e(r + 1:r + ndim, c) = kl(a, 1:ndim, k, b)
          end do
        end do
      end do
    else
      k_e = 0.0_dp
    end if

  contains

    !> Record a failure: zero force and tangent, old state kept, cutback requested for an inverted element.
    subroutine fail(code, msg)
      integer, intent(in) :: code
      character(len=*), intent(in) :: msg
      stat = code
      errmsg = msg
      f_int = 0.0_dp
      k_e = 0.0_dp
      energy = 0.0_dp
      if (size(stress_new, 1) == size(stress_old, 1) .and. size(stress_new, 2) == size(stress_old, 2)) &
        stress_new = stress_old
      if (size(stran_new, 1) == size(stran_old, 1) .and. size(stran_new, 2) == size(stran_old, 2)) &
        stran_new = stran_old
      if (size(statev_new, 1) == size(statev_old, 1) .and. size(statev_new, 2) == size(statev_old, 2)) &
        statev_new = statev_old
      if (present(energy_ip_new)) then
        energy_ip_new = 0.0_dp
        if (present(energy_ip_old)) then
          if (size(energy_ip_new, 1) == size(energy_ip_old, 1) .and. size(energy_ip_new, 2) == size(energy_ip_old, 2)) &
            energy_ip_new = energy_ip_old
        end if
      end if
      if (code == 1 .or. code == 3) pnewdt = min(pnewdt, 0.25_dp)
    end subroutine fail

    !> Deformation gradient I + sum_a disp_a (x) dN_a/dX (3x3, F33 = 1 in plane strain).
    pure function def_grad(disp, dn) result(f)
      real(dp), intent(in) :: disp(3, maxnode), dn(maxnode, 3)
      real(dp) :: f(3, 3)
      integer :: aa, ii, jj
      f = identity()
      do jj = 1, ndim
        do aa = 1, nnode
          do ii = 1, ndim
            f(ii, jj) = f(ii, jj) + disp(ii, aa) * dn(aa, jj)
          end do
        end do
      end do
    end function def_grad

  end subroutine solid_element_compute

  !> Call the UMAT through the pointer with contiguous explicit-shape copies of every argument (a user routine
  !> may overwrite any of them; only STRESS, STATEV, DDSDDE, SSE, SPD, SCD and PNEWDT are taken back).
  subroutine call_umat(umat, stress, statev, ddsdde, sse, spd, scd, stran, dstran, time, dtime, cmname, ndi, nshr, &
      ntens, nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, jstep, kinc, temp, dtemp, &
      predef, dpred)
    procedure(umat_interface) :: umat                    !< the UMAT
    real(dp), intent(in) :: temp, dtemp                  !< temperature at the start of the increment, its increment
    real(dp), intent(in), optional :: predef(:), dpred(:) !< field variables at the start of the increment, increments
    integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, kinc, jstep(4)
    real(dp), intent(inout) :: stress(6), statev(:), ddsdde(6, 6), sse, spd, scd, pnewdt
    real(dp), intent(in) :: stran(6), dstran(6), time(2), dtime, coords(3), drot(3, 3), celent
    real(dp), intent(in) :: props(:), dfgrd0(3, 3), dfgrd1(3, 3)
    character(len=80), intent(in) :: cmname
    real(dp) :: c_stress(ntens), c_ddsdde(ntens, ntens), c_ddsddt(ntens), c_drplde(ntens), c_stran(ntens)
    real(dp) :: c_dstran(ntens), c_statev(size(statev)), c_props(size(props)), c_rpl, c_drpldt
    real(dp) :: c_time(2), c_dtime, c_temp, c_dtemp
    real(dp), allocatable :: c_predef(:), c_dpred(:)
    real(dp) :: c_coords(3), c_drot(3, 3), c_celent, c_f0(3, 3), c_f1(3, 3)
    integer :: c_ndi, c_nshr, c_ntens, c_nstatv, c_nprops, c_noel, c_npt, c_layer, c_kspt, c_jstep(4), c_kinc
    character(len=80) :: c_cmname

    c_stress = stress(1:ntens); c_ddsdde = 0.0_dp; c_ddsddt = 0.0_dp; c_drplde = 0.0_dp
    c_stran = stran(1:ntens); c_dstran = dstran(1:ntens); c_statev = statev; c_props = props
    c_rpl = 0.0_dp; c_drpldt = 0.0_dp
    c_time = time; c_dtime = dtime; c_temp = temp; c_dtemp = dtemp
    ! NPREDF-sized PREDEF and DPRED (at least one entry, 0, without field variables)
    allocate (c_predef(1), c_dpred(1))
    c_predef = 0.0_dp
    c_dpred = 0.0_dp
    if (present(predef) .and. present(dpred)) then
      if (size(predef) > 0) then
        c_predef = predef
        c_dpred = dpred
      end if
    end if
    c_coords = coords; c_drot = drot; c_celent = celent; c_f0 = dfgrd0; c_f1 = dfgrd1
    c_ndi = ndi; c_nshr = nshr; c_ntens = ntens; c_nstatv = nstatv; c_nprops = nprops; c_noel = noel; c_npt = npt
    c_layer = 1; c_kspt = 1; c_jstep = jstep; c_kinc = kinc; c_cmname = cmname
    call umat(c_stress, c_statev, c_ddsdde, sse, spd, scd, c_rpl, c_ddsddt, c_drplde, c_drpldt, c_stran, c_dstran, &
      c_time, c_dtime, c_temp, c_dtemp, c_predef, c_dpred, c_cmname, c_ndi, c_nshr, c_ntens, c_nstatv, c_props, &
      c_nprops, c_coords, c_drot, pnewdt, c_celent, c_f0, c_f1, c_noel, c_npt, c_layer, c_kspt, c_jstep, c_kinc)
    stress(1:ntens) = c_stress
    ddsdde(1:ntens, 1:ntens) = c_ddsdde
    statev = c_statev
  end subroutine call_umat

  !> Spatial tangent A_ijkl (material + geometric, from DDSDDE by the Jaumann correction of CONVENTIONS.md) and the
  !> F-bar coefficient q_ij; without NLGEOM A = DDSDDE and q = (1/m) sum_a A_ijaa.
  pure subroutine spatial_tangent(ddsdde, sig, ndim, nlgeom, a4, q)
    real(dp), intent(in) :: ddsdde(6, 6), sig(3, 3)
    integer, intent(in) :: ndim
    logical, intent(in) :: nlgeom
    real(dp), intent(out) :: a4(3, 3, 3, 3), q(3, 3)
    integer :: i, j, k, l
    real(dp) :: m

    m = real(ndim, dp)
    a4 = 0.0_dp
    q = 0.0_dp
    do l = 1, ndim
      do k = 1, ndim
        do j = 1, ndim
          do i = 1, ndim
            a4(i, j, k, l) = ddsdde(vidx(i, j), vidx(k, l))
          end do
        end do
      end do
    end do
    if (nlgeom) then
      ! - 1/2 (d_ik s_jl + d_il s_jk + s_ik d_jl + s_il d_jk) + d_ik s_jl, term by term over the Kronecker deltas
      do l = 1, ndim
        do j = 1, ndim
          do i = 1, ndim
            a4(i, j, i, l) = a4(i, j, i, l) + 0.5_dp * sig(j, l)
            a4(i, j, l, i) = a4(i, j, l, i) - 0.5_dp * sig(j, l)
            a4(i, j, l, j) = a4(i, j, l, j) - 0.5_dp * sig(i, l)
            a4(i, j, j, l) = a4(i, j, j, l) - 0.5_dp * sig(i, l)
          end do
        end do
      end do
    end if
    do k = 1, ndim
      q(1:ndim, 1:ndim) = q(1:ndim, 1:ndim) + a4(1:ndim, 1:ndim, k, k) / m
    end do
    if (nlgeom) q(1:ndim, 1:ndim) = q(1:ndim, 1:ndim) - (1.0_dp - 1.0_dp / m) * sig(1:ndim, 1:ndim)
  end subroutine spatial_tangent

  !> Number of PROPS of a material (0 when none were given).
  pure integer function nprops_of(mat)
    type(solid_material_t), intent(in) :: mat
    nprops_of = 0
    if (allocated(mat%props)) nprops_of = size(mat%props)
  end function nprops_of

  !> Symmetric tensor from Voigt components; shear_factor 1 for stress, 1/2 for engineering strain.
  pure subroutine voigt_to_tensor(v, ntens, t, shear_factor)
    real(dp), intent(in) :: v(:)
    integer, intent(in) :: ntens
    real(dp), intent(out) :: t(3, 3)
    real(dp), intent(in) :: shear_factor
    t = 0.0_dp
    t(1, 1) = v(1); t(2, 2) = v(2); t(3, 3) = v(3)
    t(1, 2) = shear_factor * v(4); t(2, 1) = t(1, 2)
    if (ntens >= 6) then
      t(1, 3) = shear_factor * v(5); t(3, 1) = t(1, 3)
      t(2, 3) = shear_factor * v(6); t(3, 2) = t(2, 3)
    end if
  end subroutine voigt_to_tensor

  !> Voigt components of a symmetric tensor; shear_factor 1 for stress, 2 for engineering strain.
  pure subroutine tensor_to_voigt(t, ntens, v, shear_factor)
    real(dp), intent(in) :: t(3, 3)
    integer, intent(in) :: ntens
    real(dp), intent(out) :: v(6)
    real(dp), intent(in) :: shear_factor
    v = 0.0_dp
    v(1) = t(1, 1); v(2) = t(2, 2); v(3) = t(3, 3)
    v(4) = shear_factor * t(1, 2)
    if (ntens >= 6) then
      v(5) = shear_factor * t(1, 3)
      v(6) = shear_factor * t(2, 3)
    end if
  end subroutine tensor_to_voigt

  pure integer function shape_of(etype)
    character(len=*), intent(in) :: etype
    character(len=16) :: up
    integer :: i, first, last
    shape_of = 0
    first = verify(etype, ' ')
    last = len_trim(etype)
    if (first == 0 .or. last - first + 1 > len(up)) return
    up = etype(first:last)
    do i = 1, len(up)
      if (up(i:i) >= 'a' .and. up(i:i) <= 'z') up(i:i) = achar(iachar(up(i:i)) - 32)
    end do
    select case (trim(up))
    case ('C3D8')
      shape_of = SHAPE_C3D8
    case ('CPE4')
      shape_of = SHAPE_CPE4
    case default
      shape_of = 0
    end select
  end function shape_of

  !> Rotation R of the polar decomposition F = R U (det F > 0), by the Newton iteration X <- (X + X^-T)/2, which
  !> converges quadratically to R from X = F.
  pure function polar_rotation(f) result(r)
    real(dp), intent(in) :: f(3, 3)  !< deformation gradient
    real(dp) :: r(3, 3), x(3, 3)
    integer :: it
    r = f
    do it = 1, 60
      x = 0.5_dp * (r + transpose(inv3(r)))
      if (maxval(abs(x - r)) <= 4.0_dp * epsilon(1.0_dp)) then
        r = x
        return
      end if
      r = x
    end do
  end function polar_rotation

  pure function identity() result(e)
    real(dp) :: e(3, 3)
    e = 0.0_dp
    e(1, 1) = 1.0_dp; e(2, 2) = 1.0_dp; e(3, 3) = 1.0_dp
  end function identity

  pure real(dp) function det3(a)
    real(dp), intent(in) :: a(3, 3)
    det3 = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
         + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function det3

  !> Inverse of a 3x3 matrix by its adjugate (callers ensure det > 0).
  pure function inv3(a) result(b)
    real(dp), intent(in) :: a(3, 3)
    real(dp) :: b(3, 3)
    b(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
    b(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
    b(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
    b(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
    b(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
    b(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
    b(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
    b(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
    b(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
    b = b / det3(a)
  end function inv3

  pure function itoa(n) result(s)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    character(len=16) :: buf
    write (buf, '(i0)') n
    s = trim(buf)
  end function itoa

end module solid_element
