!> The continuum elements of the host, ONE kinematics and UMAT-calling path for every type of the element catalogue
!> (element_catalog.f90: C3D8, C3D8I, C3D8R, C3D20, C3D20R, C3D4, C3D10, C3D6, C3D15, CPE4/CPE4I/CPE4R/CPE8/CPE8R,
!> CPS4/CPS4I/CPS4R/CPS8/CPS8R, CAX4/CAX4R/CAX8/CAX8R, the triangles CPE3/CPE6/CPS3/CPS6/CAX3/CAX6; shape
!> functions and rules in solid_shape.f90), calling their material exactly as Abaqus/Standard calls a UMAT
!> (docs/conventions.md). Types differ only by data: shape functions, integration rule, and the switches
!> F-bar (C3D8, CPE4, CAX4: de Souza Neto, Peric, Dutko and Owen 1996, Int. J. Solids Struct. 33, 3277-3296),
!> incompatible modes (condensed pseudo-nodes, element-level Newton), one point with Flanagan-Belytschko hourglass
!> stiffness (CAX4R: with the 2 pi R weighted means and a hoop-variation stiffness), plane stress (NTENS = 3) and
!> axisymmetry (hoop strain u_r / r, totals over 2 pi). docs/elements.md.
!> Plane stress under NLGEOM: *ELASTIC keeps its thickness stretch lambda_3 (plane-stress condition of the hypoelastic
!> law); a UMAT gets F33 = 1 / det(F_2D) in DFGRD0/DFGRD1 and the element follows that thickness (J = 1; inferred
!> Abaqus behaviour from a user report, docs/elements.md "Plane stress").
!>
!> Kinematics at Gauss point p (updated Lagrange, NLGEOM):
!>   F = dx/dX at t_n (F0, from u - du) and t_n+1 (F1, from u); J = det F; J_c = det F at the element centre.
!>   F-bar:  Fbar = (J_c / J)^(1/m) F  on the in-plane block, m = 3 (C3D8) or m = 2 (CPE4, F33 = 1), so det Fbar = J_c;
!>           CAX4: the whole 3x3 F with its hoop stretch r/R, m = 3, J_c = det F at the centre with r_c / R_c.
!>   Hughes-Winget mid-point increment: G = (Fbar1 - Fbar0) ((Fbar0 + Fbar1) / 2)^-1 = grad(du) w.r.t. x_mid,
!>   DSTRAN = sym G (engineering shears), W = skw G, DROT = (I - W/2)^-1 (I + W/2).
!>   STRESS and STRAN are rotated by DROT before the call; DFGRD0 = Fbar0, DFGRD1 = Fbar1.
!> Without NLGEOM: DSTRAN = sym of grad(du) w.r.t. X with its trace replaced by the element's volume mean (B-bar of
!>   Hughes 1980, the mean-dilatation small-strain counterpart of F-bar; CAX4: the trace includes the hoop strain
!>   u_r / R and the mean is weighted by 2 pi R dA), DROT = I, f_int and K on the reference
!>   configuration with the B-bar virtual strain as well: f = int Bbar^T sigma dV, K = int Bbar^T DDSDDE Bbar dV,
!>   symmetric for a symmetric DDSDDE (one Newton correction for a linear elastic problem with the symmetric solve).
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
!> Without NLGEOM the same formulas hold with x = X, sigma-terms dropped (A = DDSDDE, q = (1/m) sum_a A_ijaa), the
!> mean instead of the centre derivatives, and the row term K_(a i)(b k) += (1/m) bc_ai sum_n t_nn of Bbar^T.
!> DDSDDE is symmetrised first unless the material is a UMAT with UNSYMM (Abaqus semantics). k_e itself is NOT
!> symmetrised: the F-bar term (and under NLGEOM the Jaumann/geometric terms) make it unsymmetric, and a
!> symmetrised k_e would cost the quadratic convergence of Newton (it is symmetric for a homogeneous state only).
module solid_element
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use ldfcz_kinds, only: dp
  use solid_umat_interface, only: umat_interface
  use solid_types, only: solid_material_t, solid_geometry_t, nprops_of, umat_props_pad, SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, &
    SOLID_PNEWDT_LARGE
  use solid_c3d8, only: c3d8_nlgeom, c3d8_compact_geometry, c3d8_compact_size
  use element_catalog, only: element_types, element_kind_of, element_nnode, element_ndim, element_ndi, &
    element_nshr, element_is_axisymmetric, element_is_plane_stress, KERNEL_C3D8
  use solid_shape, only: solid_shape_eval, solid_gauss_point, solid_parent_centre, solid_hourglass_base
  use solid_elastic, only: elastic_update, elastic_check, elastic_law_update, elastic_law_check, &
    thermal_strain_increment, elastic_law_shear_modulus, elastic_thickness_increment, law_lamina
  use solid_tangent_kernel, only: k_point_c3d8, tangent_kernel_level
  implicit none
  private
  public :: solid_material_t, solid_element_info, solid_element_compute, umat_interface
  public :: solid_geometry_t, solid_element_geometry, polar_rotation
  public :: solid_compact_geometry_size, solid_compact_geometry
  public :: SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, SOLID_PNEWDT_LARGE

  !> nodes (plus incompatible-mode pseudo-nodes) and integration points at most
  integer, parameter :: maxnode = 20, maxip = 27
  real(dp), parameter :: no_field(0) = [real(dp) ::]  !< PREDEF/DPRED of a model without field variables
  integer, parameter :: maxalpha = 9             !< incompatible-mode parameters at most (3 modes x 3 components)
  !> hourglass stiffness factor c of the one-point elements: k = c G V sum_(a,j) (dN_a/dX_j)^2 per hourglass
  !> mode and direction (Flanagan-Belytschko stiffness form; c = 1 is 0.56 of the exact bending stiffness of a
  !> cube's xi-eta mode at nu = 0, docs/elements.md)
  real(dp), parameter :: hourglass_factor = 1.0_dp
  !> Voigt position of tensor component (i,j), order 11,22,33,12,13,23 (CPE4 uses only i,j <= 2: 11,22,12)
  integer, parameter :: vidx(3, 3) = reshape([1, 4, 5, 4, 2, 6, 5, 6, 3], [3, 3])
  !> the same for plane stress (NTENS = 3: 11,22,12; no 33 entry, never addressed in 2D)
  integer, parameter :: vidx_ps(3, 3) = reshape([1, 3, 0, 3, 2, 0, 0, 0, 0], [3, 3])

contains

  !> Sizes of an element type: nodes, spatial dimensions, integration points, stress components, and the rows of
  !> the STATEV array per point the element keeps for itself after the material's NSTATV (nextra: incompatible
  !> modes). Unknown etype: every output 0.
  pure subroutine solid_element_info(etype, nnode, ndim, nip, ntens, ndi, nshr, nextra)
    character(len=*), intent(in) :: etype  !< Abaqus element name, e.g. 'C3D8', 'C3D20R', 'cpe4' (case-insensitive)
    integer, intent(out) :: nnode          !< nodes per element
    integer, intent(out) :: ndim           !< coordinates and displacement dofs per node
    integer, intent(out) :: nip            !< integration points
    integer, intent(out) :: ntens          !< stress components (ndi + nshr)
    integer, intent(out) :: ndi            !< direct stress components
    integer, intent(out) :: nshr           !< shear stress components
    integer, intent(out), optional :: nextra  !< STATEV rows per point after NSTATV used by the element itself
    integer :: it
    it = element_kind_of(etype)
    nnode = 0; ndim = 0; nip = 0; ntens = 0; ndi = 0; nshr = 0
    if (present(nextra)) nextra = 0
    if (it == 0) return
    associate (tp => element_types(it))
      nnode = element_nnode(it); ndim = element_ndim(it); nip = tp%nip; ndi = element_ndi(it); nshr = element_nshr(it)
      ntens = ndi + nshr
      if (present(nextra)) then
        nextra = (ndim * tp%nmode + tp%nip - 1) / tp%nip
        if (tp%hourglass) nextra = max(nextra, 1)   ! the hourglass shear modulus, fixed at the first increment
        if (element_is_plane_stress(it)) nextra = nextra + 1         ! plane stress: ln of the thickness stretch (the last row)
      end if
    end associate
  end subroutine solid_element_info

  !> Reference-configuration data of an element (solid_geometry_t); geo%valid = .false. for an unknown type, sizes
  !> that do not match it, or a reference Jacobian <= 0 (solid_element_compute then reports the element itself).
  !> Incompatible modes M_m = 1 - xi_m^2 (Wilson, Taylor; with Taylor, Beresford and Wilson's correction so that the
  !> patch test is passed): G_m = (j0 / j) dM_m/dxi J0^-1, j0 and J0 at the centre, so that int G_m dV = 0.
  subroutine solid_element_geometry(etype, coords0, geo)
    character(len=*), intent(in) :: etype             !< element type name
    real(dp), intent(in) :: coords0(:, :)             !< (ndim, nnode) original coordinates
    type(solid_geometry_t), intent(out) :: geo        !< reference data
    integer :: it, nnode, ndim, nip, nne, ip, m
    real(dp) :: xi(3), w, detj, det0, nc(maxnode), j0inv(3, 3), jinv(3, 3)
    it = element_kind_of(etype)
    if (it == 0) return
    associate (tp => element_types(it))
      nnode = element_nnode(it)
      ndim = element_ndim(it)
      nip = tp%nip
      nne = nnode + tp%nmode
      allocate (geo%nfun(nne, nip), geo%dndx_ref(nne, 3, nip), geo%wdet(nip), geo%dndx_0c(nne, 3), &
        geo%dndx_0m(nne, 3))
      geo%nfun = 0.0_dp
      geo%dndx_ref = 0.0_dp
      geo%wdet = 0.0_dp
      geo%dndx_0c = 0.0_dp
      geo%dndx_0m = 0.0_dp
      if (size(coords0, 1) /= ndim .or. size(coords0, 2) /= nnode) return
      xi = solid_parent_centre(tp%family)
      call solid_reference_derivatives(tp%family, nnode, ndim, coords0, xi, nc, geo%dndx_0c(1:nnode, :), det0, j0inv)
      if (.not. (det0 > 0.0_dp)) return
      do ip = 1, nip
        call solid_gauss_point(tp%rule, ndim, ip, xi, w)
        call solid_reference_derivatives(tp%family, nnode, ndim, coords0, xi, geo%nfun(1:nnode, ip), &
          geo%dndx_ref(1:nnode, :, ip), detj, jinv)
        if (.not. (detj > 0.0_dp)) return
        geo%wdet(ip) = w * detj
        do m = 1, tp%nmode
          geo%dndx_ref(nnode + m, 1:ndim, ip) = (det0 / detj) * (-2.0_dp * xi(m)) * j0inv(m, 1:ndim)
        end do
        geo%dndx_0m = geo%dndx_0m + geo%wdet(ip) * geo%dndx_ref(:, :, ip)
      end do
      if (element_is_axisymmetric(it)) then
        ! axisymmetric: wdet becomes the reference volume weight 2 pi R x (Gauss weight x det), so that volumes,
        ! forces and energies are totals around the circumference (Abaqus); hoop operator N_a / R
        allocate (geo%hoop(nne, nip), geo%hoop_0c(nne), geo%hoop_0m(nne))
        geo%hoop = 0.0_dp
        geo%hoop_0c = 0.0_dp
        geo%hoop_0m = 0.0_dp
        ! the centre's hoop operator (F-bar: J_c includes the hoop stretch r_c / R_c)
        w = dot_product(nc(1:nnode), coords0(1, :))
        if (.not. (w > 0.0_dp)) return
        geo%hoop_0c(1:nnode) = nc(1:nnode) / w
        do ip = 1, nip
          w = dot_product(geo%nfun(1:nnode, ip), coords0(1, :))
          if (.not. (w > 0.0_dp)) return
          geo%hoop(1:nnode, ip) = geo%nfun(1:nnode, ip) / w
          geo%wdet(ip) = 2 * acos(-1.0_dp) * w * geo%wdet(ip)
        end do
        ! volume means weighted by the axisymmetric volume 2 pi R dA (B-bar: the mean dilatation includes the
        ! hoop strain u_r / R)
        geo%dndx_0m = 0.0_dp
        do ip = 1, nip
          geo%dndx_0m = geo%dndx_0m + geo%wdet(ip) * geo%dndx_ref(:, :, ip)
          geo%hoop_0m = geo%hoop_0m + geo%wdet(ip) * geo%hoop(:, ip)
        end do
        geo%hoop_0m = geo%hoop_0m / sum(geo%wdet)
      end if
      geo%dndx_0m = geo%dndx_0m / sum(geo%wdet)
      if (tp%hourglass) then
        ! the one point's gradient operator is the element mean (Flanagan-Belytschko's uniform gradient,
        ! integrated with the 2x2(x2) rule, exact), and its weight the element volume: the centre derivatives
        ! alone fail the patch test of a distorted hexahedron. Axisymmetric (CAX4R): the means and the volume
        ! weighted by 2 pi R (exact with 2x2 points: the integrands R dN/dR detj and N detj are at most cubic per
        ! direction), the hoop operator the mean of N_a / R = (2 pi / V) int N_a dA, so that f = V (B_m^T sigma +
        ! hoop_m sigma_tt) is the exact integral for a uniform stress and a linear field (u_r = a R: hoop strain a)
        ! has its exact strains
        block
          real(dp) :: nq(maxnode), dq(maxnode, 3), vq, wq, xq(3), rq, hq(maxnode), wall(8)
          integer :: iq
          geo%dndx_ref(:, :, 1) = 0.0_dp
          vq = 0.0_dp
          hq = 0.0_dp
          if (element_is_axisymmetric(it)) allocate (geo%hoop_fl(nnode, 2**ndim))
          do iq = 1, 2**ndim
            call solid_gauss_point(2, ndim, iq, xq, wq)
            call solid_reference_derivatives(tp%family, nnode, ndim, coords0, xq, nq(1:nnode), dq(1:nnode, :), detj, &
              jinv)
            if (.not. (detj > 0.0_dp)) return
            wq = wq * detj
            if (element_is_axisymmetric(it)) then
              rq = dot_product(nq(1:nnode), coords0(1, :))
              if (.not. (rq > 0.0_dp)) return
              wq = 2 * acos(-1.0_dp) * rq * wq
              hq(1:nnode) = hq(1:nnode) + wq * nq(1:nnode) / rq
              geo%hoop_fl(:, iq) = nq(1:nnode) / rq
              wall(iq) = wq
            end if
            geo%dndx_ref(1:nnode, :, 1) = geo%dndx_ref(1:nnode, :, 1) + wq * dq(1:nnode, :)
            vq = vq + wq
          end do
          geo%dndx_ref(:, :, 1) = geo%dndx_ref(:, :, 1) / vq
          geo%wdet(1) = vq
          geo%dndx_0m = geo%dndx_ref(:, :, 1)
          if (element_is_axisymmetric(it)) then
            geo%hoop(1:nnode, 1) = hq(1:nnode) / vq
            do iq = 1, 2**ndim
              geo%hoop_fl(:, iq) = sqrt(wall(iq)) * (geo%hoop_fl(:, iq) - geo%hoop(1:nnode, 1))
            end do
          end if
        end block
        ! Flanagan-Belytschko (1981): gamma_m = (h_m - sum_j (h_m . X_j) b_j) / nnode with b_j = dN/dX_j at the
        ! single (centre) point, orthogonal to every linear field (gamma_m . X_j = 0): no hourglass force in a
        ! homogeneous deformation or a rigid motion of any size
        block
          real(dp) :: h(8, 4)
          integer :: j
          call solid_hourglass_base(tp%family, h, geo%nhg)
          allocate (geo%gamma(nnode, geo%nhg))
          do m = 1, geo%nhg
            geo%gamma(:, m) = h(1:nnode, m)
            do j = 1, ndim
              geo%gamma(:, m) = geo%gamma(:, m) - dot_product(h(1:nnode, m), coords0(j, :)) * &
                geo%dndx_ref(1:nnode, j, 1)
            end do
            geo%gamma(:, m) = geo%gamma(:, m) / nnode
          end do
          geo%hg_vsum = geo%wdet(1) * sum(geo%dndx_ref(1:nnode, 1:ndim, 1)**2)
        end block
      end if
    end associate
    geo%valid = .true.
  end subroutine solid_element_geometry

  !> Entries of the compact reference data of a type (solid_compact_geometry), 0 for a type without one (only the
  !> types with a fixed-size kernel have it: C3D8, 90 entries).
  pure integer function solid_compact_geometry_size(etype) result(n)
    character(len=*), intent(in) :: etype             !< element type name
    integer :: it
    n = 0
    it = element_kind_of(etype)
    if (it == 0) return
    if (element_types(it)%kernel == KERNEL_C3D8) n = c3d8_compact_size
  end function solid_compact_geometry_size

  !> The compact reference data of an element of a type with a fixed-size kernel (solid_compact_geometry_size
  !> entries; gc(1) = 1 when valid): what the kernel rebuilds solid_element_geometry's arrays from, to the bit, at a
  !> small cost per call (C3D8: 720 bytes instead of about 3.4 kB with the arrays' descriptors). gc = 0 (not valid)
  !> for a type without one or coordinates of another size.
  pure subroutine solid_compact_geometry(etype, coords0, gc)
    character(len=*), intent(in) :: etype             !< element type name
    real(dp), intent(in) :: coords0(:, :)             !< (ndim, nnode) original coordinates
    real(dp), intent(out) :: gc(:)                    !< (solid_compact_geometry_size(etype)) compact reference data
    gc = 0.0_dp
    if (solid_compact_geometry_size(etype) /= c3d8_compact_size .or. size(gc) /= c3d8_compact_size) return
    if (size(coords0, 1) /= 3 .or. size(coords0, 2) /= 8) return
    call c3d8_compact_geometry(coords0, gc)
  end subroutine solid_compact_geometry

  !> Shape functions and reference derivatives dN/dX at parent point xi; detj = det(dX/dxi), jinv its inverse
  !> (dndx = 0 if detj <= 0).
  pure subroutine solid_reference_derivatives(family, nnode, ndim, coords0, xi, n_p, dndx_p, detj, jinv)
    integer, intent(in) :: family, nnode, ndim
    real(dp), intent(in) :: coords0(:, :), xi(3)
    real(dp), intent(out) :: n_p(:), dndx_p(:, :), detj, jinv(3, 3)
    real(dp) :: dndxi(maxnode, 3), jac(3, 3)
    dndxi = 0.0_dp
    n_p = 0.0_dp
    call solid_shape_eval(family, xi(1:ndim), n_p(1:nnode), dndxi(1:nnode, 1:ndim))
    jac = identity()
    jac(1:ndim, 1:ndim) = matmul(coords0(1:ndim, 1:nnode), dndxi(1:nnode, 1:ndim))
    detj = det3(jac)
    dndx_p = 0.0_dp
    jinv = 0.0_dp
    if (detj > 0.0_dp) then
      jinv = inv3(jac)
      dndx_p(1:nnode, 1:ndim) = matmul(dndxi(1:nnode, 1:ndim), jinv(1:ndim, 1:ndim))
    end if
  end subroutine solid_reference_derivatives


  !> Internal force, tangent and updated integration-point state of one element for the current Newton estimate.
  !> Never produces NaN: on failure (stat /= 0) f_int = 0, k_e = 0, the new state equals the old one.
  subroutine solid_element_compute(etype, coords0, u, du, mat, stress_old, stran_old, statev_old, time, dtime, &
      kstep, kinc, noel, nlgeom, want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, errmsg, &
      energy_ip_old, energy_ip_new, geo, temp_nodes, dtemp_nodes, energy_hg, orient, field_nodes, dfield_nodes, &
      generic_only, geo_compact)
    character(len=*), intent(in) :: etype             !< element type name (element_catalog)
    real(dp), intent(in) :: coords0(:, :)             !< (ndim, nnode) original coordinates
    real(dp), intent(in) :: u(:)                      !< (ndim*nnode) total displacement, current Newton estimate
    real(dp), intent(in) :: du(:)                     !< (ndim*nnode) increment since the last converged state
    type(solid_material_t), intent(in) :: mat         !< material and section
    real(dp), intent(in) :: stress_old(:, :)          !< (ntens, nip) converged Cauchy stress
    real(dp), intent(in) :: stran_old(:, :)           !< (ntens, nip) converged strain (engineering shears)
    !> (>= nstatv + nextra, nip) converged state variables; rows nstatv+1.. hold the element's own (solid_element_info)
    real(dp), intent(in) :: statev_old(:, :)
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
    real(dp), intent(out) :: statev_new(:, :)         !< (>= nstatv + nextra, nip) state variables
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
    !> hourglass energy of a one-point element (included in energy(1); Abaqus reports it apart, as ALLAE)
    real(dp), intent(out), optional :: energy_hg
    real(dp), intent(in), optional :: orient(:, :, :) !< (3, 3, nip) local material axes T0 (columns) per point
    real(dp), intent(in), optional :: field_nodes(:, :)  !< (nfield, nnode) field variables at the increment's start
    real(dp), intent(in), optional :: dfield_nodes(:, :) !< (nfield, nnode) their increments (PREDEF, DPRED at points)
    !> .true.: the generic path even where the type's fixed-size kernel would serve (tests and benchmarks compare
    !> the two; the results are the same bits)
    logical, intent(in), optional :: generic_only
    !> compact reference data (solid_compact_geometry) instead of geo, for a type with a fixed-size kernel: the
    !> kernel rebuilds the arrays it needs from it (the generic path, where it serves, computes them from coords0)
    real(dp), intent(in), optional :: geo_compact(:)

    integer, parameter :: max_local_iter = 30      ! element-level Newton on the incompatible modes
    integer :: it, nnode, nne, ndim, nip, ntens, ndi, nshr, nextra, ndof, ndofe, nalpha, nsv, np
    integer :: a, b, i, k, r, c, jstep(4)
    logical :: fbar
    real(dp) :: xref(3, maxnode), un(3, maxnode), u1(3, maxnode), dun(3, maxnode)
    type(solid_geometry_t), target :: gl          ! reference data computed here when the host has none
    type(solid_geometry_t), pointer :: gp         ! the reference data in use (no per-call copy of the host's)
    real(dp) :: fc0(3, 3), fc1(3, 3), jc0, jc1, celent, eye(3, 3), m, finv(3, 3), dndx_c(maxnode, 3)
    ! F-bar / B-bar block: nf = 3 in 3D and axisymmetry (the hoop stretch is part of J), 2 in plane strain (F33 = 1);
    ! hcc: the centre's (mean's) hoop operator N_a / r of an axisymmetric F-bar type, the column k = 1 of its
    ! dilatation operator beside dndx_c
    integer :: nf
    real(dp) :: mf, hcc(maxnode)
    real(dp) :: fe(3 * maxnode), ke(3 * maxnode, 3 * maxnode), kl(maxnode, 3, 3, maxnode)
    real(dp) :: alpha_n(maxalpha), g_shear
    real(dp) :: sv(max(1, mat%nstatv)), pr(nprops_of(mat) + umat_props_pad)
    character(len=80) :: cmname
    integer :: kgeo
    character(len=*), parameter :: here = 'solid_element_compute: '

    stat = 0
    errmsg = ''
    f_int = 0.0_dp
    energy = 0.0_dp
    if (present(energy_hg)) energy_hg = 0.0_dp
    g_shear = 0.0_dp
    it = element_kind_of(etype)
    call solid_element_info(etype, nnode, ndim, nip, ntens, ndi, nshr, nextra)
    ndof = ndim * nnode
    nsv = mat%nstatv
    np = nprops_of(mat)

    call check_arguments()
    if (stat /= 0) return

    call run_kernel(kgeo)   ! a type's fixed-size kernel where it covers the call (element_catalog: kernel)
    if (kgeo /= 0) return

    call reference_and_nodal_state()
    if (stat == 0) call centre_operators()
    if (stat /= 0) return

    jstep = [kstep, 1, merge(1, 0, nlgeom), 0]
    cmname = mat%cmname
    pr = 0.0_dp
    if (np > 0) pr(1:np) = mat%props

    if (nalpha == 0) then
      call element_pass(want_k)
      if (stat /= 0) return
      f_int = fe(1:ndof)
      if (want_k) k_e = ke(1:ndof, 1:ndof)
      if (element_types(it)%hourglass) call hourglass_terms()
    else
      call incompatible_modes()
      if (stat /= 0) return
    end if
    if (.not. want_k) k_e = 0.0_dp

  contains

    !> The element type (its sizes with the incompatible modes: nne, ndofe, nalpha; fbar), the arguments' sizes
    !> against it, the energies' shapes, the material and the section (bad input: stat = 2).
    subroutine check_arguments()
      integer :: i
      if (it == 0) then
        call fail(2, here // 'unknown element type "' // trim(etype) // '"')
        return
      end if
      nne = nnode + element_types(it)%nmode
      ndofe = ndim * nne
      nalpha = ndofe - ndof
      fbar = element_types(it)%fbar
      if (size(coords0, 1) /= ndim .or. size(coords0, 2) /= nnode .or. size(u) /= ndof .or. size(du) /= ndof .or. &
          size(f_int) /= ndof .or. size(k_e, 1) /= ndof .or. size(k_e, 2) /= ndof .or. &
          size(stress_old, 1) /= ntens .or. size(stress_old, 2) /= nip .or. size(stran_old, 1) /= ntens .or. &
          size(stran_old, 2) /= nip .or. size(stress_new, 1) /= ntens .or. size(stress_new, 2) /= nip .or. &
          size(stran_new, 1) /= ntens .or. size(stran_new, 2) /= nip .or. size(statev_old, 1) < nsv + nextra .or. &
          size(statev_old, 2) /= nip .or. size(statev_new, 1) < nsv + nextra .or. size(statev_new, 2) /= nip) then
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
        if (mat%law%general) then
          call elastic_law_check(mat%law, i, errmsg)
          if (i == 0 .and. mat%law%kind == law_lamina .and. .not. (element_is_plane_stress(it) .and. .not. nlgeom)) &
            errmsg = '*ELASTIC, TYPE=LAMINA: plane-stress elements without NLGEOM only (its constants give no '// &
            'through-thickness stiffness; ENGINEERING CONSTANTS give it)'
          if (len_trim(errmsg) > 0) i = 1
        else
          call elastic_check(mat%e, mat%nu, i, errmsg)
        end if
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
    end subroutine check_arguments

    !> The type's fixed-size kernel (C3D8 under NLGEOM, without *ORIENTATION or a general elastic law) with the
    !> host's reference data in either form, or computed now; kgeo = 0: the generic path serves (no kernel, or no
    !> valid reference data: the generic path reports the inverted element).
    subroutine run_kernel(kgeo)
      integer, intent(out) :: kgeo  !< 1 geo, 2 geo_compact, 3 computed here; 0 the generic path
      character(len=200) :: kmsg
      kgeo = 0
      if (.not. (element_types(it)%kernel == KERNEL_C3D8 .and. nlgeom .and. .not. present(orient) .and. &
          .not. mat%law%general .and. .not. flag(generic_only))) return
      if (present(geo)) then
        if (geo%valid) kgeo = 1
      end if
      if (kgeo == 0 .and. present(geo_compact)) then
        if (size(geo_compact) == c3d8_compact_size) then
          if (geo_compact(1) == 1.0_dp) kgeo = 2
        end if
      end if
      if (kgeo == 0) then
        ! no reference data from the host: computed now (as the generic path would)
        call solid_element_geometry(etype, coords0, gl)
        if (gl%valid) kgeo = 3
      end if
      if (kgeo == 1) then
        call c3d8_nlgeom(mat, coords0, u, du, stress_old, stran_old, statev_old, time, dtime, kstep, kinc, noel, &
          want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, kmsg, energy_ip_old, &
          energy_ip_new, temp_nodes, dtemp_nodes, field_nodes, dfield_nodes, gp=geo)
      else if (kgeo == 3) then
        call c3d8_nlgeom(mat, coords0, u, du, stress_old, stran_old, statev_old, time, dtime, kstep, kinc, noel, &
          want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, kmsg, energy_ip_old, &
          energy_ip_new, temp_nodes, dtemp_nodes, field_nodes, dfield_nodes, gp=gl)
      else if (kgeo == 2) then
        call c3d8_nlgeom(mat, coords0, u, du, stress_old, stran_old, statev_old, time, dtime, kstep, kinc, noel, &
          want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, kmsg, energy_ip_old, &
          energy_ip_new, temp_nodes, dtemp_nodes, field_nodes, dfield_nodes, gc=geo_compact)
      end if
      if (kgeo /= 0) then
        if (stat /= 0) call fail(stat, trim(kmsg))
      end if
    end subroutine run_kernel

    !> The reference data in use (gp: the host's copy, or computed now; stat = 1 when not valid), the nodal
    !> coordinates and displacements at t_n and t_n+1 and the converged incompatible-mode parameters alpha_n.
    subroutine reference_and_nodal_state()
      ! ---- reference data (shape functions, dN/dX, weights): the host's copy or computed now
      gp => gl
      if (present(geo)) then
        if (geo%valid) gp => geo
      end if
      if (.not. gp%valid) call solid_element_geometry(etype, coords0, gl)
      if (.not. gp%valid) then
        call fail(1, 'inverted element ' // itoa(noel) // ' (reference Jacobian <= 0 at the centre or at an ' // &
                  'integration point, or radius <= 0 at a point of an axisymmetric element)')
        return
      end if

      eye = identity()
      m = real(ndim, dp)
      nf = merge(3, ndim, element_is_axisymmetric(it))
      mf = real(nf, dp)
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
      ! incompatible-mode parameters of the last converged state, kept after NSTATV in the STATEV rows
      alpha_n = 0.0_dp
      do k = 1, nalpha
        alpha_n(k) = statev_old(nsv + 1 + (k - 1) / nip, mod(k - 1, nip) + 1)
      end do
    end subroutine reference_and_nodal_state

    !> The element centre: J_c at t_n and t_n+1 (J <= 0: stat = 1), the spatial derivatives dndx_c (and hcc) of
    !> the F-bar (B-bar) tangent.
    subroutine centre_operators()
      ! ---- element centre: J_c at t_n and t_n+1, spatial derivatives for the F-bar tangent
      fc0 = def_grad(un, gp%dndx_0c)
      fc1 = def_grad(u1, gp%dndx_0c)
      if (element_is_axisymmetric(it)) then
        ! hoop stretch at the centre r_c / R_c: J_c is the 3D volume ratio there
        fc0(3, 3) = 1.0_dp + dot_product(gp%hoop_0c(1:nne), un(1, 1:nne))
        fc1(3, 3) = 1.0_dp + dot_product(gp%hoop_0c(1:nne), u1(1, 1:nne))
      end if
      jc0 = det3(fc0)
      jc1 = det3(fc1)
      if (.not. (jc0 > 0.0_dp .and. jc1 > 0.0_dp)) then
        call fail(1, 'inverted element ' // itoa(noel) // ' (J <= 0 at the centre)')
        return
      end if
      dndx_c = 0.0_dp
      hcc = 0.0_dp
      if (fbar) then
        if (nlgeom) then
          finv = inv3(fc1)
          dndx_c(1:nne, 1:ndim) = matmul(gp%dndx_0c(1:nne, 1:ndim), finv(1:ndim, 1:ndim))
          if (element_is_axisymmetric(it)) hcc(1:nne) = gp%hoop_0c(1:nne) / fc1(3, 3)   ! N_a / r_c, current
        else
          dndx_c(1:nne, :) = gp%dndx_0m
          if (element_is_axisymmetric(it)) hcc(1:nne) = gp%hoop_0m(1:nne)
        end if
      end if
    end subroutine centre_operators

    !> Hourglass stiffness of a one-point element added to f_int, k_e and the energies.
    subroutine hourglass_terms()
      integer :: mh, a, b, i, r, c
      real(dp) :: ghg, khg, qhg(3)
      ! ---- hourglass stiffness (Flanagan-Belytschko stiffness form on the total displacement, reference
      ! configuration): q_im = sum_a gamma_am u_ia, f_ia += k sum_m gamma_am q_im, k = c G V sum (dN/dX)^2.
      ! G: *ELASTIC's shear modulus; for a UMAT the mean shear diagonal of DDSDDE at the first call, then kept
      ! (STATEV row nstatv+1) so that k is constant and the tangent consistent after the first increment.
      if (mat%kind == SOLID_MAT_ELASTIC .and. mat%law%general) then
        ghg = elastic_law_shear_modulus(mat%law)
      else if (mat%kind == SOLID_MAT_ELASTIC) then
        ghg = mat%e / (2 * (1 + mat%nu))
      else
        ghg = statev_old(nsv + 1, 1)
        if (.not. (ghg > 0.0_dp)) ghg = max(g_shear, 0.0_dp)
      end if
      statev_new(nsv + 1, 1) = ghg
      ! (axisymmetric: hg_vsum has the 2 pi R weighted volume; no section thickness)
      khg = hourglass_factor * ghg * gp%hg_vsum * merge(1.0_dp, mat%thickness, element_is_axisymmetric(it))
      do mh = 1, gp%nhg
        qhg(1:ndim) = matmul(u1(1:ndim, 1:nnode), gp%gamma(:, mh))
        do a = 1, nnode
          r = ndim * (a - 1)
          f_int(r + 1:r + ndim) = f_int(r + 1:r + ndim) + khg * gp%gamma(a, mh) * qhg(1:ndim)
          if (want_k) then
            do b = 1, nnode
              c = ndim * (b - 1)
              do i = 1, ndim
                k_e(r + i, c + i) = k_e(r + i, c + i) + khg * gp%gamma(a, mh) * gp%gamma(b, mh)
              end do
            end do
          end if
        end do
        energy(1) = energy(1) + 0.5_dp * khg * sum(qhg(1:ndim)**2)
        if (present(energy_hg)) energy_hg = energy_hg + 0.5_dp * khg * sum(qhg(1:ndim)**2)
      end do
      if (allocated(gp%hoop_fl)) then
        ! axisymmetric one point (CAX4R): the mean hoop strain at the point misses the variation of u_r / R over
        ! the element, and u_r = Z - c, u_z = -R (c = <Z/R> / <1/R>) is a zero-energy mode that the
        ! Flanagan-Belytschko vectors (orthogonal to every linear field) cannot see. Stabilisation: the shear
        ! part of the energy of that variation, (1/2) 2 G int (u_r/R - <u_r/R>)^2 dV (the bulk part would lock),
        ! zero for u_r = a R (constant hoop strain): the patch test is kept
        khg = hourglass_factor * 2 * ghg
        do mh = 1, size(gp%hoop_fl, 2)
          qhg(1) = dot_product(gp%hoop_fl(:, mh), u1(1, 1:nnode))
          do a = 1, nnode
            r = ndim * (a - 1) + 1
            f_int(r) = f_int(r) + khg * gp%hoop_fl(a, mh) * qhg(1)
            if (want_k) then
              do b = 1, nnode
                c = ndim * (b - 1) + 1
                k_e(r, c) = k_e(r, c) + khg * gp%hoop_fl(a, mh) * gp%hoop_fl(b, mh)
              end do
            end if
          end do
          energy(1) = energy(1) + 0.5_dp * khg * qhg(1)**2
          if (present(energy_hg)) energy_hg = energy_hg + 0.5_dp * khg * qhg(1)**2
        end do
      end if
    end subroutine hourglass_terms

    !> Incompatible modes: Newton on the internal parameters alpha, then static condensation into f_int, k_e;
    !> alpha into the STATEV rows after NSTATV.
    subroutine incompatible_modes()
      integer :: iter, k, i
      logical :: last
      real(dp) :: alpha(maxalpha), dalpha(maxalpha), kaa(maxalpha, maxalpha), rhs(maxalpha, 3 * maxnode + 1), scale
      ! ---- incompatible modes: Newton on the internal parameters alpha (f_alpha = 0) from the converged alpha_n,
      ! then static condensation f = f_u - K_ua K_aa^-1 f_a, K = K_uu - K_ua K_aa^-1 K_au (exact at f_a = 0, and
      ! f_u - K_ua K_aa^-1 f_a corrects a residual f_a to first order)
      alpha = alpha_n
      last = .false.
      do iter = 1, max_local_iter
        do k = 1, nalpha
          u1(k - 1 - ndim * ((k - 1) / ndim) + 1, nnode + 1 + (k - 1) / ndim) = alpha(k)
          un(k - 1 - ndim * ((k - 1) / ndim) + 1, nnode + 1 + (k - 1) / ndim) = alpha_n(k)
        end do
        dun = u1 - un
        call element_pass(.true.)
        if (stat /= 0) return
        ! scale of the terms that make up f_alpha: the element forces, and stiffness x (displacement or element
        ! size): the round-off floor of f_alpha is about eps E L^2 whatever the deformation (current coordinates
        ! of order L), so an element with f_u ~ 0 (a neutral axis, a tiny increment) still converges
        scale = max(maxval(abs(fe(1:ndof))), maxval(abs(ke(ndof + 1:ndofe, 1:ndofe))) * &
          max(maxval(abs(u1(:, 1:nne))), celent))
        if (maxval(abs(fe(ndof + 1:ndofe))) <= 1.0e-11_dp * scale .or. last) exit
        kaa(1:nalpha, 1:nalpha) = ke(ndof + 1:ndofe, ndof + 1:ndofe)
        rhs(1:nalpha, 1) = -fe(ndof + 1:ndofe)
        call dense_solve(kaa(1:nalpha, 1:nalpha), rhs(1:nalpha, 1:1), i)
        if (i /= 0) then
          call fail(3, 'element ' // itoa(noel) // ': singular incompatible-mode stiffness')
          return
        end if
        dalpha(1:nalpha) = rhs(1:nalpha, 1)
        alpha(1:nalpha) = alpha(1:nalpha) + dalpha(1:nalpha)
        ! round-off floor: the correction no longer changes alpha; one more pass at it and stop
        last = maxval(abs(dalpha(1:nalpha))) <= 1.0e-14_dp * max(maxval(abs(alpha(1:nalpha))), celent)
        if (iter == max_local_iter) then
          call fail(3, 'element ' // itoa(noel) // ': incompatible modes did not converge')
          return
        end if
      end do
      kaa(1:nalpha, 1:nalpha) = ke(ndof + 1:ndofe, ndof + 1:ndofe)
      rhs(1:nalpha, 1) = fe(ndof + 1:ndofe)
      rhs(1:nalpha, 2:ndof + 1) = ke(ndof + 1:ndofe, 1:ndof)
      call dense_solve(kaa(1:nalpha, 1:nalpha), rhs(1:nalpha, 1:ndof + 1), i)
      if (i /= 0) then
        call fail(3, 'element ' // itoa(noel) // ': singular incompatible-mode stiffness')
        return
      end if
      f_int = fe(1:ndof) - matmul(ke(1:ndof, ndof + 1:ndofe), rhs(1:nalpha, 1))
      if (want_k) k_e = ke(1:ndof, 1:ndof) - matmul(ke(1:ndof, ndof + 1:ndofe), rhs(1:nalpha, 2:ndof + 1))
      do k = 1, nalpha
        statev_new(nsv + 1 + (k - 1) / nip, mod(k - 1, nip) + 1) = alpha(k)
      end do
    end subroutine incompatible_modes

    !> One pass over the integration points at the current (u1, un) including the mode pseudo-nodes: material
    !> calls, new point state, fe(1:ndofe) and (want) ke(1:ndofe, 1:ndofe).
    subroutine element_pass(want)
      logical, intent(in) :: want
      integer :: ip
      real(dp) :: fg0(3, 3, maxip), fg1(3, 3, maxip), j0, j1
      real(dp) :: fb0(3, 3), fb1(3, 3), g(3, 3), drot(3, 3)
      real(dp) :: sig(3, 3), eps(3, 3), dndx(maxnode, 3), dv
      real(dp) :: stress(6), stran(6), dstran(6), ddsdde(6, 6)
      real(dp) :: sse, spd, scd, bc(maxnode, 3)
      real(dp) :: bcr(maxnode, 3), trs
      real(dp) :: kl8(8, 3, 3, 8)   ! C3D8: contiguous fixed-size accumulator of the vectorised kernel
      real(dp) :: hc(maxnode), thk, lt1(maxip)
      real(dp) :: tn(3, 3), t1(3, 3), drot_m(3, 3), fl0(3, 3), fl1(3, 3)
      logical :: k8, axi, local
      axi = element_is_axisymmetric(it)
      ! section thickness of plane elements; axisymmetric volumes are per 2 pi radians already (geometry)
      thk = merge(1.0_dp, mat%thickness, axi)
      lt1 = 0.0_dp

      fe = 0.0_dp
      energy = 0.0_dp
      call first_pass(axi, fg0, fg1, lt1)
      if (stat /= 0) return

      ! ---- second pass: material calls, internal force, tangent
      k8 = ndim == 3 .and. nne == 8
      if (want) then
        if (k8) then
          kl8 = 0.0_dp
        else
          kl(1:nne, :, :, 1:nne) = 0.0_dp
        end if
      end if
      do ip = 1, nip
        j0 = det3(fg0(:, :, ip))
        j1 = det3(fg1(:, :, ip))
        fb0 = fg0(:, :, ip)
        fb1 = fg1(:, :, ip)
        if (fbar) then
          ! (axisymmetric: the whole 3x3 F with its hoop stretch, m = 3, so that det Fbar = J_c)
          fb0(1:nf, 1:nf) = (jc0 / j0)**(1.0_dp / mf) * fb0(1:nf, 1:nf)
          fb1(1:nf, 1:nf) = (jc1 / j1)**(1.0_dp / mf) * fb1(1:nf, 1:nf)
        end if

        call strain_increment(ip, axi, fb0, fb1, g, drot)
        if (stat /= 0) return
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

        call point_material(ip, local, t1, drot_m, fl0, fl1, stress, stran, dstran, ddsdde, sse, spd, scd)
        if (stat /= 0) return
        if (mat%kind == SOLID_MAT_ELASTIC .and. nsv > 0) statev_new(1:nsv, ip) = statev_old(1:nsv, ip)
        if (size(statev_new, 1) > nsv) statev_new(nsv + 1:, ip) = statev_old(nsv + 1:, ip)
        if (element_is_plane_stress(it) .and. nlgeom) statev_new(nsv + nextra, ip) = lt1(ip)
        stress_new(:, ip) = stress(1:ntens)
        stran_new(:, ip) = stran(1:ntens) + dstran(1:ntens)
        if (present(energy_ip_new)) then
          energy_ip_new(:, ip) = 0.0_dp
          energy_ip_new(1:3, ip) = [sse, spd, scd]
        end if

        ! spatial derivatives and volume element
        dndx = 0.0_dp
        hc = 0.0_dp
        if (nlgeom) then
          finv = inv3(fg1(:, :, ip))
          dndx(1:nne, 1:ndim) = matmul(gp%dndx_ref(1:nne, 1:ndim, ip), finv(1:ndim, 1:ndim))
          dv = gp%wdet(ip) * j1 * thk
          if (axi) hc(1:nne) = gp%hoop(:, ip) / fg1(3, 3, ip)   ! N_a / r, current radius
        else
          dndx(1:nne, 1:ndim) = gp%dndx_ref(1:nne, 1:ndim, ip)
          dv = gp%wdet(ip) * thk
          if (axi) hc(1:nne) = gp%hoop(:, ip)
        end if
        energy = energy + [sse, spd] * dv

        call voigt_to_tensor(stress(1:ntens), ntens, sig, 1.0_dp)
        ! bc(b, k) = dN_b/dx_k at the centre (mean without NLGEOM) minus at the point: the F-bar (B-bar)
        ! dilatation operator (0 for the other element types)
        bc = 0.0_dp
        if (fbar) bc(1:nne, 1:ndim) = dndx_c(1:nne, 1:ndim) - dndx(1:nne, 1:ndim)
        ! axisymmetric: the dilatation of a radial nodal motion includes its hoop strain N_b / r
        if (fbar .and. axi) bc(1:nne, 1) = bc(1:nne, 1) + hcc(1:nne) - hc(1:nne)
        ! without NLGEOM the virtual strain is the B-bar one too (f = int Bbar^T sigma dV), so that
        ! K = int Bbar^T C Bbar is symmetric for a symmetric DDSDDE; under NLGEOM f = int B^T sigma dv
        ! (de Souza Neto et al., 1996)
        trs = 0.0_dp
        if (.not. nlgeom) trs = (sig(1, 1) + sig(2, 2) + merge(sig(3, 3), 0.0_dp, nf == 3)) / mf
        bcr = 0.0_dp
        if (.not. nlgeom) bcr(1:nne, 1:ndim) = bc(1:nne, 1:ndim)
        do a = 1, nne
          do i = 1, ndim
            r = ndim * (a - 1) + i
            fe(r) = fe(r) + (dot_product(sig(i, 1:ndim), dndx(a, 1:ndim)) + trs * bcr(a, i)) * dv
          end do
          ! axisymmetric: the hoop virtual strain du_r / r
          if (axi) fe(ndim * (a - 1) + 1) = fe(ndim * (a - 1) + 1) + sig(3, 3) * hc(a) * dv
        end do

        if (want) call point_tangent(ddsdde, sig, dndx, bc, bcr, hc, dv, k8, axi, kl8)
      end do
      if (want) then
        if (k8) kl(1:8, :, :, 1:8) = kl8
        do b = 1, nne
          do k = 1, ndim
            c = ndim * (b - 1) + k
            do a = 1, nne
              r = ndim * (a - 1)
              ke(r + 1:r + ndim, c) = kl(a, 1:ndim, k, b)
            end do
          end do
        end do
      end if
    end subroutine element_pass

    !> First pass of element_pass: the deformation gradients at t_n and t_n+1 at the points (the hoop stretch of
    !> axisymmetric types, the thickness stretch of plane stress under NLGEOM into lt1), J > 0 checked (stat = 1),
    !> the volume for CELENT.
    subroutine first_pass(axi, fg0, fg1, lt1)
      logical, intent(in) :: axi                  !< axisymmetric type
      real(dp), intent(out) :: fg0(3, 3, maxip), fg1(3, 3, maxip)  !< F at t_n and t_n+1 per point
      real(dp), intent(inout) :: lt1(maxip)       !< ln of the thickness stretch at t_n+1 (plane stress, NLGEOM)
      integer :: ip, i
      real(dp) :: j0, j1, vol, f2m(2, 2), g2(2, 2), dt_ip, t_ip, a2(2, 2), fm(3, 3), r33(3, 3)
      vol = 0.0_dp
      do ip = 1, nip
        fg0(:, :, ip) = def_grad(un, gp%dndx_ref(:, :, ip))
        fg1(:, :, ip) = def_grad(u1, gp%dndx_ref(:, :, ip))
        if (axi) then
          ! hoop stretch r / R = 1 + u_r / R
          fg0(3, 3, ip) = 1.0_dp + dot_product(gp%hoop(:, ip), un(1, 1:nne))
          fg1(3, 3, ip) = 1.0_dp + dot_product(gp%hoop(:, ip), u1(1, 1:nne))
        end if
        if (element_is_plane_stress(it) .and. nlgeom .and. mat%kind /= SOLID_MAT_ELASTIC) then
          ! plane stress with a UMAT under NLGEOM (**inferred** Abaqus behaviour, docs/elements.md): the NTENS = 3
          ! contract returns no thickness strain, so DFGRD0/DFGRD1 get F33 = 1 / det(F_2D) (J = 1, the value a
          ! user report gives for Abaqus), off-plane terms 0, and the element's thickness follows the same F33:
          ! t = t0 F33, so dv = J dV t0 = dV t0 (J = 1) and d(dv)/du = 0 in the tangent, which is then exact for
          ! a DDSDDE that is the Jaumann tangent of the Cauchy stress ((1/J) tau^J with J = det DFGRD1 = 1).
          do i = 0, 1
            f2m = merge(fg1(1:2, 1:2, ip), fg0(1:2, 1:2, ip), i == 1)
            j1 = f2m(1, 1) * f2m(2, 2) - f2m(1, 2) * f2m(2, 1)
            if (.not. (j1 > 0.0_dp)) then
              call fail(1, 'inverted element ' // itoa(noel) // ' (J <= 0 at integration point ' // itoa(ip) // ')')
              return
            end if
            if (i == 1) fg1(3, 3, ip) = 1.0_dp / j1
            if (i == 0) fg0(3, 3, ip) = 1.0_dp / j1
          end do
          lt1(ip) = log(fg1(3, 3, ip))
        else if (element_is_plane_stress(it) .and. nlgeom) then
          ! plane stress under NLGEOM (*ELASTIC): the thickness stretch lambda_3 from the plane-stress
          ! condition of the hypoelastic law, d eps_33 = -nu/(1 - nu) (d eps_11 + d eps_22) + (1 + nu)/(1 - nu)
          ! alpha dT (sigma_33 = 0 with the mechanical strain), the in-plane increments being the Hughes-Winget
          ! ones; ln lambda_3 accumulates d eps_33 (a logarithmic strain, like STRAN) in the element's last STATEV
          ! row. F33 = lambda_3 enters DFGRD0/DFGRD1 and J, so dv = J dV t0 uses the current thickness t0 lambda_3.
          f2m = 0.5_dp * (fg0(1:2, 1:2, ip) + fg1(1:2, 1:2, ip))
          j1 = f2m(1, 1) * f2m(2, 2) - f2m(1, 2) * f2m(2, 1)
          if (.not. (j1 > 0.0_dp)) then
            call fail(1, 'inverted element ' // itoa(noel) // ' (mid-increment J <= 0 at integration point ' &
                      // itoa(ip) // ')')
            return
          end if
          g2 = matmul(fg1(1:2, 1:2, ip) - fg0(1:2, 1:2, ip), &
                      reshape([f2m(2, 2), -f2m(2, 1), -f2m(1, 2), f2m(1, 1)], [2, 2]) / j1)
          dt_ip = 0.0_dp
          if (present(dtemp_nodes)) dt_ip = dot_product(gp%nfun(1:nnode, ip), dtemp_nodes(1:nnode))
          if (mat%law%general) then
            ! the general law: its compliance in the material axes (turned with the material, as the stress)
            t_ip = 0.0_dp
            if (present(temp_nodes)) t_ip = dot_product(gp%nfun(1:nnode, ip), temp_nodes(1:nnode))
            a2 = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
            if (present(orient)) then
              fm = fg1(:, :, ip)
              fm(3, 3) = 1.0_dp
              r33 = matmul(polar_rotation(fm), orient(:, :, ip))
              a2 = r33(1:2, 1:2)
            end if
            lt1(ip) = statev_old(nsv + nextra, ip) + elastic_thickness_increment(mat%law, t_ip, dt_ip, a2, &
              [g2(1, 1), g2(2, 2), g2(1, 2) + g2(2, 1)])
          else
            lt1(ip) = statev_old(nsv + nextra, ip) - mat%nu / (1.0_dp - mat%nu) * (g2(1, 1) + g2(2, 2)) &
                      + (1.0_dp + mat%nu) / (1.0_dp - mat%nu) * mat%alpha * dt_ip
          end if
          fg0(3, 3, ip) = exp(statev_old(nsv + nextra, ip))
          fg1(3, 3, ip) = exp(lt1(ip))
        end if
        j0 = det3(fg0(:, :, ip))
        j1 = det3(fg1(:, :, ip))
        if (.not. (j0 > 0.0_dp .and. j1 > 0.0_dp)) then
          call fail(1, 'inverted element ' // itoa(noel) // ' (J <= 0 at integration point ' // itoa(ip) // ')')
          return
        end if
        if (axi) then
          ! CELENT from the area of the (r, z) section: divide the volume weight by 2 pi R
          vol = vol + gp%wdet(ip) * merge(j1 / fg1(3, 3, ip), 1.0_dp, nlgeom) / &
            (2 * acos(-1.0_dp) * dot_product(gp%nfun(1:nnode, ip), xref(1, 1:nnode)))
        else
          ! (plane stress: the (x, y) area, without the thickness stretch F33)
          vol = vol + gp%wdet(ip) * merge(j1 / fg1(3, 3, ip), 1.0_dp, nlgeom .and. ndim == 2) &
                    * merge(j1, 1.0_dp, nlgeom .and. ndim == 3)
        end if
      end do
      celent = vol**(1.0_dp / m)
    end subroutine first_pass

    !> The strain increment's gradient g at point ip and the rotation increment drot: Hughes-Winget at the
    !> mid-increment configuration under NLGEOM (J <= 0 there: stat = 1), the small-strain gradient otherwise (the
    !> B-bar mean dilatation for F-bar types); fb0, fb1 the point's (F-bar modified) gradients.
    subroutine strain_increment(ip, axi, fb0, fb1, g, drot)
      integer, intent(in) :: ip                   !< integration point
      logical, intent(in) :: axi                  !< axisymmetric type
      real(dp), intent(in) :: fb0(3, 3), fb1(3, 3)
      real(dp), intent(out) :: g(3, 3), drot(3, 3)
      real(dp) :: fm(3, 3), wsk(3, 3), gc(3, 3), trc, trg
      integer :: i
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
        ! small strain: grad(du) w.r.t. X, with the mean dilatation of the element for F-bar types (B-bar)
        g = def_grad(dun, gp%dndx_ref(:, :, ip)) - eye
        if (axi) g(3, 3) = dot_product(gp%hoop(:, ip), dun(1, 1:nne))   ! hoop strain increment du_r / R
        if (fbar) then
          gc = def_grad(dun, gp%dndx_0m) - eye
          ! axisymmetric: the mean dilatation includes the mean hoop strain (2 pi R weighted)
          if (axi) gc(3, 3) = dot_product(gp%hoop_0m(1:nne), dun(1, 1:nne))
          trg = 0.0_dp
          trc = 0.0_dp
          do i = 1, nf
            trg = trg + g(i, i)
            trc = trc + gc(i, i)
          end do
          do i = 1, nf
            g(i, i) = g(i, i) + (trc - trg) / mf
          end do
        end if
        drot = eye
      end if
    end subroutine strain_increment

    !> The material at point ip: the temperature and the thermal strain, *ELASTIC or the UMAT (in the local axes
    !> when local: back to global components after it, the tangent column by column), non-finite results stat = 3.
    subroutine point_material(ip, local, t1, drot_m, fl0, fl1, stress, stran, dstran, ddsdde, sse, spd, scd)
      integer, intent(in) :: ip                   !< integration point
      logical, intent(in) :: local                !< local material axes (*ORIENTATION)
      real(dp), intent(in) :: t1(3, 3)            !< the local axes at t_n+1 (local only)
      real(dp), intent(in) :: drot_m(3, 3), fl0(3, 3), fl1(3, 3)  !< DROT, DFGRD0, DFGRD1 as the material sees them
      real(dp), intent(inout) :: stress(6), stran(6), dstran(6)   !< rotated old stress and strain, DSTRAN
      real(dp), intent(out) :: ddsdde(6, 6)       !< the material's tangent (global components)
      real(dp), intent(out) :: sse, spd, scd      !< the point's energies
      real(dp) :: temp_ip, dtemp_ip, dth(6), coords(3), pn, sig(3, 3), eps(3, 3), s_unit(6), col_g(6, 6)
      integer :: i, k, icol
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
      if (mat%law%general) then
        call thermal_strain_increment(mat%law, temp_ip, dtemp_ip, ndi, nshr, dth(1:ntens))
        dstran(1:ntens) = dstran(1:ntens) - dth(1:ntens)
      else if (mat%alpha /= 0.0_dp) then
        dstran(1:ndi) = dstran(1:ndi) - mat%alpha * dtemp_ip
      end if
      ddsdde = 0.0_dp
      pn = SOLID_PNEWDT_LARGE
      select case (mat%kind)
      case (SOLID_MAT_ELASTIC)
        if (mat%law%general) then
          call elastic_law_update(mat%law, temp_ip, dtemp_ip, ndi, nshr, stress(1:ntens), stran(1:ntens), &
            dstran(1:ntens), ddsdde(1:ntens, 1:ntens), sse)
        else
          call elastic_update(mat%e, mat%nu, ndi, nshr, stress(1:ntens), dstran(1:ntens), ddsdde(1:ntens, 1:ntens), &
            sse)
        end if
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
            nshr, ntens, nsv, pr, np, coords, drot_m, pn, celent, fl0, fl1, noel, ip, jstep, kinc, temp_ip, &
            dtemp_ip, no_field, no_field)
        end if
        statev_new(1:nsv, ip) = sv(1:nsv)
      end select
      pnewdt = min(pnewdt, pn)
      if (ip == 1) g_shear = sum([(ddsdde(k, k), k = ndi + 1, ntens)]) / nshr
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
        do icol = 1, ntens
          s_unit = 0.0_dp
          s_unit(icol) = 1.0_dp
          call voigt_to_tensor(s_unit(1:ntens), ntens, eps, 0.5_dp)
          call tensor_to_voigt(matmul(matmul(transpose(t1), eps), t1), ntens, s_unit, 2.0_dp)
          s_unit(1:ntens) = matmul(ddsdde(1:ntens, 1:ntens), s_unit(1:ntens))
          call voigt_to_tensor(s_unit(1:ntens), ntens, sig, 1.0_dp)
          call tensor_to_voigt(matmul(matmul(t1, sig), transpose(t1)), ntens, s_unit, 1.0_dp)
          col_g(1:ntens, icol) = s_unit(1:ntens)
        end do
        ddsdde(1:ntens, 1:ntens) = col_g(1:ntens, 1:ntens)
      end if
    end subroutine point_material

    !> The point's contribution to the element tangent: column (b k) t_ij = [sum_l A_ijkl dN_b/dx_l + q_ij bc_bk] dv,
    !> then K_(a i)(b k) += sum_j dN_a/dx_j t_ij + (1/m) bcr_ai tr t, into kl (kl8 for a C3D8).
    subroutine point_tangent(ddsdde, sig, dndx, bc, bcr, hc, dv, k8, axi, kl8)
      real(dp), intent(inout) :: ddsdde(6, 6)     !< the material's tangent (symmetrised here unless UNSYMM)
      real(dp), intent(in) :: sig(3, 3)           !< Cauchy stress
      real(dp), intent(in) :: dndx(maxnode, 3), bc(maxnode, 3), bcr(maxnode, 3), hc(maxnode)  !< operators
      real(dp), intent(in) :: dv                  !< volume element
      logical, intent(in) :: k8, axi              !< the C3D8 accumulator; axisymmetric type
      real(dp), intent(inout) :: kl8(8, 3, 3, 8)  !< the C3D8 accumulator
      real(dp) :: a4(3, 3, 3, 3), q(3, 3), t(3, 3), trs, d8(8, 3), b8(8, 3), r8(8, 3)
      integer :: b, k, i
      if (.not. (mat%kind == SOLID_MAT_UMAT .and. mat%unsymm)) then
        ! Abaqus uses only the symmetric part of DDSDDE unless *USER MATERIAL, UNSYMM
        ddsdde(1:ntens, 1:ntens) = 0.5_dp * (ddsdde(1:ntens, 1:ntens) + transpose(ddsdde(1:ntens, 1:ntens)))
      end if
      ! (axisymmetric: the full 3x3 spatial tangent, the hoop direction being the third)
      call spatial_tangent(ddsdde, ntens, sig, merge(3, ndim, axi), nlgeom, a4, q)
      ! column (b k): t_ij = [sum_l A_ijkl dN_b/dx_l + q_ij bc_bk] dv, then
      ! K_(a i)(b k) += sum_j dN_a/dx_j t_ij + (1/m) bcr_ai tr t
      ! (factorised: ~4 ndim^3 nnode^2 multiplications fewer than the direct quadruple sum)
      ! (dndx, q, a4 and t are zero beyond ndim, so fixed 3-term sums also serve 2D; kl is a contiguous local)
      if (k8) then
        d8 = dndx(1:8, :)
        b8 = bc(1:8, :)
        r8 = bcr(1:8, :) / mf
        call k_point_c3d8(tangent_kernel_level(), a4, q, d8, b8, r8, dv, kl8)
      else
        do b = 1, nne
          do k = 1, ndim
            t = (q * bc(b, k) + a4(:, :, k, 1) * dndx(b, 1) + a4(:, :, k, 2) * dndx(b, 2) &
                 + a4(:, :, k, 3) * dndx(b, 3)) * dv
            ! axisymmetric: the column's hoop gradient L_33 = N_b / r for k = 1
            if (axi .and. k == 1) t = t + a4(:, :, 3, 3) * hc(b) * dv
            trs = (t(1, 1) + t(2, 2) + t(3, 3)) / mf
            do i = 1, ndim
              kl(1:nne, i, k, b) = kl(1:nne, i, k, b) + t(i, 1) * dndx(1:nne, 1) &
                + t(i, 2) * dndx(1:nne, 2) + t(i, 3) * dndx(1:nne, 3) + trs * bcr(1:nne, i)
            end do
            ! and the row's hoop virtual strain for i = 1
            if (axi) kl(1:nne, 1, k, b) = kl(1:nne, 1, k, b) + t(3, 3) * hc(1:nne)
          end do
        end do
      end if
    end subroutine point_tangent

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

    !> Deformation gradient I + sum_a disp_a (x) dN_a/dX (3x3, F33 = 1 in plane strain), over the nodes and the
    !> incompatible-mode pseudo-nodes.
    pure function def_grad(disp, dn) result(f)
      real(dp), intent(in) :: disp(3, maxnode), dn(:, :)
      real(dp) :: f(3, 3)
      integer :: aa, ii, jj
      f = identity()
      do jj = 1, ndim
        do aa = 1, nne
          do ii = 1, ndim
            f(ii, jj) = f(ii, jj) + disp(ii, aa) * dn(aa, jj)
          end do
        end do
      end do
    end function def_grad

  end subroutine solid_element_compute

  !> An optional flag's value (.false. when absent).
  pure logical function flag(f)
    logical, intent(in), optional :: f
    flag = .false.
    if (present(f)) flag = f
  end function flag

  !> Solve a x = b in place (b holds x on return) by Gaussian elimination with partial pivoting; stat 1 when a is
  !> singular (zero pivot).
  pure subroutine dense_solve(a, b, stat)
    real(dp), intent(inout) :: a(:, :), b(:, :)
    integer, intent(out) :: stat
    integer :: n, i, p, k
    real(dp) :: t, row(size(a, 2)), rowb(size(b, 2))
    n = size(a, 1)
    stat = 0
    do k = 1, n
      p = k - 1 + maxloc(abs(a(k:n, k)), 1)
      if (.not. (abs(a(p, k)) > 0.0_dp)) then
        stat = 1
        return
      end if
      if (p /= k) then
        row = a(k, :); a(k, :) = a(p, :); a(p, :) = row
        rowb = b(k, :); b(k, :) = b(p, :); b(p, :) = rowb
      end if
      do i = k + 1, n
        t = a(i, k) / a(k, k)
        a(i, k:n) = a(i, k:n) - t * a(k, k:n)
        b(i, :) = b(i, :) - t * b(k, :)
      end do
    end do
    do k = n, 1, -1
      b(k, :) = (b(k, :) - matmul(a(k, k + 1:n), b(k + 1:n, :))) / a(k, k)
    end do
  end subroutine dense_solve

  !> Call the UMAT through the pointer with contiguous explicit-shape copies of every argument (a user routine
  !> may overwrite any of them; only STRESS, STATEV, DDSDDE, SSE, SPD, SCD and PNEWDT are taken back).
  subroutine call_umat(umat, stress, statev, ddsdde, sse, spd, scd, stran, dstran, time, dtime, cmname, ndi, nshr, &
      ntens, nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, jstep, kinc, temp, dtemp, &
      predef, dpred)
    procedure(umat_interface) :: umat                    !< the UMAT
    real(dp), intent(in) :: temp, dtemp                  !< temperature at the start of the increment, its increment
    real(dp), intent(in) :: predef(:), dpred(:)          !< field variables at the start of the increment, increments
    integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, kinc, jstep(4)
    real(dp), intent(inout) :: stress(6), statev(:), ddsdde(6, 6), sse, spd, scd, pnewdt
    real(dp), intent(in) :: stran(6), dstran(6), time(2), dtime, coords(3), drot(3, 3), celent
    real(dp), intent(in) :: props(:), dfgrd0(3, 3), dfgrd1(3, 3)
    character(len=80), intent(in) :: cmname
    real(dp) :: c_stress(ntens), c_ddsdde(ntens, ntens), c_ddsddt(ntens), c_drplde(ntens), c_stran(ntens)
    real(dp) :: c_dstran(ntens), c_statev(size(statev)), c_props(size(props)), c_rpl, c_drpldt
    real(dp) :: c_time(2), c_dtime, c_temp, c_dtemp
    real(dp) :: c_predef(max(1, size(predef))), c_dpred(max(1, size(dpred)))  ! NPREDF entries, at least one (0)
    real(dp) :: c_coords(3), c_drot(3, 3), c_celent, c_f0(3, 3), c_f1(3, 3)
    integer :: c_ndi, c_nshr, c_ntens, c_nstatv, c_nprops, c_noel, c_npt, c_layer, c_kspt, c_jstep(4), c_kinc
    character(len=80) :: c_cmname

    c_stress = stress(1:ntens); c_ddsdde = 0.0_dp; c_ddsddt = 0.0_dp; c_drplde = 0.0_dp
    c_stran = stran(1:ntens); c_dstran = dstran(1:ntens); c_statev = statev; c_props = props
    c_rpl = 0.0_dp; c_drpldt = 0.0_dp
    c_time = time; c_dtime = dtime; c_temp = temp; c_dtemp = dtemp; c_predef = 0.0_dp; c_dpred = 0.0_dp
    c_predef(1:size(predef)) = predef; c_dpred(1:size(dpred)) = dpred
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

  !> Spatial tangent A_ijkl (material + geometric, from DDSDDE by the Jaumann correction of docs/conventions.md) and the
  !> F-bar coefficient q_ij; without NLGEOM A = DDSDDE and q = (1/m) sum_a A_ijaa.
  pure subroutine spatial_tangent(ddsdde, ntens, sig, ndim, nlgeom, a4, q)
    real(dp), intent(in) :: ddsdde(6, 6), sig(3, 3)
    integer, intent(in) :: ntens, ndim
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
            if (ntens == 3) then
              a4(i, j, k, l) = ddsdde(vidx_ps(i, j), vidx_ps(k, l))
            else
              a4(i, j, k, l) = ddsdde(vidx(i, j), vidx(k, l))
            end if
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

  !> Symmetric tensor from Voigt components; shear_factor 1 for stress, 1/2 for engineering strain. Layout by
  !> ntens: 6 (11,22,33,12,13,23), 4 (11,22,33,12: plane strain), 3 (11,22,12: plane stress).
  pure subroutine voigt_to_tensor(v, ntens, t, shear_factor)
    real(dp), intent(in) :: v(:)
    integer, intent(in) :: ntens
    real(dp), intent(out) :: t(3, 3)
    real(dp), intent(in) :: shear_factor
    t = 0.0_dp
    t(1, 1) = v(1); t(2, 2) = v(2)
    if (ntens == 3) then
      t(1, 2) = shear_factor * v(3); t(2, 1) = t(1, 2)
      return
    end if
    t(3, 3) = v(3)
    t(1, 2) = shear_factor * v(4); t(2, 1) = t(1, 2)
    if (ntens >= 6) then
      t(1, 3) = shear_factor * v(5); t(3, 1) = t(1, 3)
      t(2, 3) = shear_factor * v(6); t(3, 2) = t(2, 3)
    end if
  end subroutine voigt_to_tensor

  !> Voigt components of a symmetric tensor; shear_factor 1 for stress, 2 for engineering strain (layout as in
  !> voigt_to_tensor; entries beyond ntens are 0).
  pure subroutine tensor_to_voigt(t, ntens, v, shear_factor)
    real(dp), intent(in) :: t(3, 3)
    integer, intent(in) :: ntens
    real(dp), intent(out) :: v(6)
    real(dp), intent(in) :: shear_factor
    v = 0.0_dp
    v(1) = t(1, 1); v(2) = t(2, 2)
    if (ntens == 3) then
      v(3) = shear_factor * t(1, 2)
      return
    end if
    v(3) = t(3, 3)
    v(4) = shear_factor * t(1, 2)
    if (ntens >= 6) then
      v(5) = shear_factor * t(1, 3)
      v(6) = shear_factor * t(2, 3)
    end if
  end subroutine tensor_to_voigt

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

  include 'solid_tensor3.inc'

end module solid_element
