!> The fixed-size C3D8 kernel of the continuum element (element_catalog: KERNEL_C3D8; docs/elements.md "Kernels",
!> reports/bench/kernel/README.md): the generic path of solid_element_compute for 8 nodes, 2x2x2 points,
!> F-bar under NLGEOM, without *ORIENTATION, written with every size known to the compiler. The formulation is the
!> module header's (solid_element.f90) and so is every operation: each value is formed by the same operations in
!> the same order as in the generic path, so that both give the same bits (bench_element_calls' fingerprints, test
!> test_solid_element's kernel_bits); what differs is the work around them:
!>   - no run-time-sized loops or array sections, the point data copied once into fixed arrays;
!>   - *ELASTIC: DDSDDE formed once per element, not per point, and not symmetrised (it is symmetric);
!>   - the UMAT called with the point's own variables, copied only where the element reuses a value after the call
!>     (TIME, PROPS, CELENT, CMNAME and the integers; STRAN + DSTRAN stored before the call): the Abaqus contract of
!>     call_umat, a routine may overwrite any argument and only STRESS, STATEV, DDSDDE, SSE, SPD, SCD, PNEWDT are
!>     taken back;
!>   - the tangent accumulated by k_point_c3d8_spatial (the F-bar kernel without the small-strain row term, zero
!>     under NLGEOM) and written into k_e directly.
module solid_c3d8
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use ldfcz_kinds, only: dp
  use solid_types, only: solid_material_t, solid_geometry_t, nprops_of, umat_props_pad, SOLID_MAT_ELASTIC, SOLID_PNEWDT_LARGE
  use solid_elastic, only: elastic_isotropic_ddsdde
  use solid_shape, only: solid_shape_eval, solid_gauss_point
  use element_catalog, only: FAM_HEX8
  use solid_tangent_kernel, only: k_point_c3d8_spatial, tangent_kernel_level
  implicit none
  private
  public :: c3d8_nlgeom, c3d8_compact_geometry, c3d8_compact_size

  real(dp), parameter :: third = 1.0_dp / 3.0_dp
  !> entries of the compact reference data of a C3D8 (c3d8_compact_geometry): validity, the 8 weights x det, the
  !> inverse reference Jacobian at the centre and at the 8 points
  integer, parameter :: c3d8_compact_size = 1 + 8 + 9 + 72
  ! The parent shape functions and their derivatives at the 2x2x2 points (xi fastest) and at the centre, as constant
  ! expressions with solid_shape_eval's operations for the HEX8 family (N_a = (1/8) p q r, dN_a/dxi = (1/8) s_a q r,
  ! ..., p = 1 + s_a xi, q = 1 + t_a eta, r = 1 + u_a zeta), so that they are its values to the bit: the compiler
  ! rounds each operation as the run time does
  real(dp), parameter, private :: g2 = 0.577350269189625764509148780502_dp   ! 1/sqrt(3), solid_gauss_point's
  real(dp), parameter, private :: sn(8) = [-1, 1, 1, -1, -1, 1, 1, -1] * 1.0_dp, tn(8) = [-1, -1, 1, 1, -1, -1, 1, 1] &
    * 1.0_dp, un_(8) = [-1, -1, -1, -1, 1, 1, 1, 1] * 1.0_dp
  real(dp), parameter, private :: gx(9) = [-g2, g2, -g2, g2, -g2, g2, -g2, g2, 0.0_dp], &
    gy(9) = [-g2, -g2, g2, g2, -g2, -g2, g2, g2, 0.0_dp], gz(9) = [-g2, -g2, -g2, -g2, g2, g2, g2, g2, 0.0_dp]
  real(dp), parameter, private :: ps(8, 9) = 1 + spread(sn, 2, 9) * spread(gx, 1, 8), &
    qs(8, 9) = 1 + spread(tn, 2, 9) * spread(gy, 1, 8), rs(8, 9) = 1 + spread(un_, 2, 9) * spread(gz, 1, 8)
  real(dp), parameter, private :: parent_n(8, 9) = 0.125_dp * ps * qs * rs
  real(dp), parameter, private :: parent_d1(8, 9) = 0.125_dp * spread(sn, 2, 9) * qs * rs
  real(dp), parameter, private :: parent_d2(8, 9) = 0.125_dp * spread(tn, 2, 9) * ps * rs
  real(dp), parameter, private :: parent_d3(8, 9) = 0.125_dp * spread(un_, 2, 9) * ps * qs
  !> dN_a/dxi_j at point ip (9: the centre)
  real(dp), parameter, private :: parent_d(8, 3, 9) = reshape([parent_d1, parent_d2, parent_d3], [8, 3, 9], &
    order=[1, 3, 2])
  !> Voigt position of tensor component (i,j), order 11,22,33,12,13,23 (solid_element's vidx)
  integer, parameter :: vidx(3, 3) = reshape([1, 4, 5, 4, 2, 6, 5, 6, 3], [3, 3])

contains

  !> solid_element_compute's work for a C3D8 under NLGEOM without local axes, after its argument checks, with the
  !> same results to the bit. stat 1 (inverted element) or 3 (non-finite material output) with errmsg; the caller
  !> then records the failure (solid_element_compute's fail).
  subroutine c3d8_nlgeom(mat, coords0, u, du, stress_old, stran_old, statev_old, time, dtime, kstep, kinc, &
      noel, want_k, f_int, k_e, stress_new, stran_new, statev_new, energy, pnewdt, stat, errmsg, energy_ip_old, &
      energy_ip_new, temp_nodes, dtemp_nodes, field_nodes, dfield_nodes, gp, gc)
    type(solid_material_t), intent(in) :: mat       !< material and section
    real(dp), intent(in) :: coords0(3, 8)           !< original coordinates
    real(dp), intent(in) :: u(24), du(24)           !< total displacement, increment since the converged state
    real(dp), intent(in) :: stress_old(6, 8), stran_old(6, 8)   !< converged stress and strain
    !> (>= max(1, nstatv), 8) converged STATEV (not CONTIGUOUS: the rows of an *ELASTIC element's are 0, and an
    !> empty actual would be copied into a temporary on every call)
    real(dp), intent(in) :: statev_old(:, :)
    real(dp), intent(in) :: time(2), dtime          !< step and total time at the increment's start, increment
    integer, intent(in) :: kstep, kinc, noel        !< step, increment, element label
    logical, intent(in) :: want_k                   !< compute k_e (otherwise 0)
    real(dp), intent(out) :: f_int(24), k_e(24, 24) !< internal force, tangent
    real(dp), intent(out) :: stress_new(6, 8), stran_new(6, 8)  !< stress and strain at the increment's end
    real(dp), intent(out) :: statev_new(:, :)       !< STATEV at the increment's end
    real(dp), intent(out) :: energy(2)              !< element integrals of SSE and SPD
    real(dp), intent(inout) :: pnewdt               !< min of the points' PNEWDT
    integer, intent(out) :: stat                    !< 0, 1 or 3 (solid_element_compute)
    character(len=*), intent(out) :: errmsg         !< message when stat /= 0
    real(dp), intent(in), optional :: energy_ip_old(:, :)        !< (3, 8) converged SSE, SPD, SCD
    real(dp), intent(out), optional :: energy_ip_new(:, :)       !< (3, 8) updated
    real(dp), intent(in), optional :: temp_nodes(:), dtemp_nodes(:)              !< nodal temperatures, increments
    real(dp), intent(in), optional :: field_nodes(:, :), dfield_nodes(:, :)      !< nodal field variables, increments
    !> the element's reference data, either whole (solid_element_geometry, valid) or compact (c3d8_compact_geometry,
    !> valid): one of them
    type(solid_geometry_t), intent(in), optional :: gp
    real(dp), intent(in), optional :: gc(c3d8_compact_size)
    real(dp) :: nfun(8, 8), wdet(8), dndx_0c(8, 3), dt(8, 8, 3), fs(8, 3, 3)
    real(dp) :: u1(3, 8), un(3, 8), dref(8, 3, 8), fg0(3, 3, 8), fg1(3, 3, 8), j0(8), j1(8)
    real(dp) :: fc0(3, 3), fc1(3, 3), jc0, jc1, dndx_c(8, 3), vol, celent, cel(6, 6)
    real(dp) :: kl(8, 3, 3, 8), fe(24), fb0(3, 3), fb1(3, 3), fm(3, 3), g(3, 3), wsk(3, 3), drot(3, 3)
    real(dp) :: sig(3, 3), eps(3, 3), stress(6), stran(6), dstran(6), ddsdde(6, 6), s0(6), sse, spd, scd, pn
    real(dp) :: dndx(8, 3), bc(8, 3), a4(3, 3, 3, 3), q(3, 3), dv, temp_ip, dtemp_ip, finv(3, 3)
    integer :: a, b, k, ip, nsv, np, nfld, level
    logical :: elastic

    stat = 0
    errmsg = ''
    energy = 0.0_dp
    nsv = mat%nstatv
    np = nprops_of(mat)
    nfld = 0
    if (present(field_nodes)) nfld = size(field_nodes, 1)
    elastic = mat%kind == SOLID_MAT_ELASTIC
    do a = 1, 8
      u1(:, a) = u(3 * a - 2:3 * a)
      un(:, a) = u1(:, a) - du(3 * a - 2:3 * a)
    end do
    if (present(gp)) then
      nfun = gp%nfun(1:8, 1:8)
      wdet = gp%wdet(1:8)
      dndx_0c = gp%dndx_0c(1:8, 1:3)
      dref = gp%dndx_ref(1:8, 1:3, 1:8)
    else
      call c3d8_expand_geometry(gc, nfun, wdet, dndx_0c, dref)
    end if
    ! element centre: J_c at t_n and t_n+1 (F-bar), spatial derivatives for the tangent
    fc0 = f_of(un, dndx_0c)
    fc1 = f_of(u1, dndx_0c)
    jc0 = det3(fc0)
    jc1 = det3(fc1)
    if (.not. (jc0 > 0.0_dp .and. jc1 > 0.0_dp)) then
      stat = 1
      errmsg = 'inverted element ' // itoa(noel) // ' (J <= 0 at the centre)'
      return
    end if
    dndx_c = matmul(dndx_0c, inv3(fc1))
    ! first pass: kinematics at the points, checks, the current volume for CELENT
    call first_pass()
    if (stat /= 0) return
    if (elastic) call elastic_isotropic_ddsdde(mat%e, mat%nu, 3, 3, cel)
    fe = 0.0_dp
    if (want_k) then
      kl = 0.0_dp
      level = tangent_kernel_level()
    end if
    ! second pass: the material at each point, internal force, tangent
    do ip = 1, 8
      call rotated_state(ip)
      if (stat /= 0) return
      sse = 0.0_dp
      spd = 0.0_dp
      scd = 0.0_dp
      if (present(energy_ip_old)) then
        sse = energy_ip_old(1, ip)
        spd = energy_ip_old(2, ip)
        scd = energy_ip_old(3, ip)
      end if
      temp_ip = 0.0_dp
      dtemp_ip = 0.0_dp
      if (present(temp_nodes)) temp_ip = dot_product(nfun(:, ip), temp_nodes(1:8))
      if (present(dtemp_nodes)) dtemp_ip = dot_product(nfun(:, ip), dtemp_nodes(1:8))
      if (mat%alpha /= 0.0_dp) dstran(1:3) = dstran(1:3) - mat%alpha * dtemp_ip
      stran_new(:, ip) = stran + dstran
      pn = SOLID_PNEWDT_LARGE
      statev_new(:, ip) = statev_old(:, ip)
      if (elastic) then
        s0 = stress
        stress = stress + matmul(cel, dstran)
        sse = sse + 0.5_dp * dot_product(s0 + stress, dstran)
        ddsdde = cel
      else
        call umat_point(ip)
      end if
      pnewdt = min(pnewdt, pn)
      if (.not. (all(ieee_is_finite(stress)) .and. all(ieee_is_finite(ddsdde)))) then
        stat = 3
        errmsg = 'element ' // itoa(noel) // ': material returned a non-finite stress or DDSDDE at point ' // itoa(ip)
        return
      end if
      stress_new(:, ip) = stress
      if (present(energy_ip_new)) then
        energy_ip_new(:, ip) = 0.0_dp
        energy_ip_new(1:3, ip) = [sse, spd, scd]
      end if
      call force_and_tangent(ip)
    end do
    f_int = fe
    if (want_k) then
      do b = 1, 8
        do k = 1, 3
          do a = 1, 8
            k_e(3 * a - 2:3 * a, 3 * (b - 1) + k) = kl(a, 1:3, k, b)
          end do
        end do
      end do
    else
      k_e = 0.0_dp
    end if

  contains

    !> F and J at the 8 points (the points in the vector lanes: each entry the same sum as f_of and det3), the
    !> checks J > 0, the current volume and CELENT.
    subroutine first_pass()
      integer :: ip
      vol = 0.0_dp
      ! F and J at the 8 points at once, the points in the vector lanes (each entry the same sum as f_of and det3)
      do ip = 1, 8
        dt(ip, :, :) = dref(:, :, ip)
      end do
      call f_points(un, dt, fs)
      j0 = det_points(fs)
      do ip = 1, 8
        fg0(:, :, ip) = fs(ip, :, :)
      end do
      call f_points(u1, dt, fs)
      j1 = det_points(fs)
      do ip = 1, 8
        fg1(:, :, ip) = fs(ip, :, :)
      end do
      do ip = 1, 8
        if (.not. (j0(ip) > 0.0_dp .and. j1(ip) > 0.0_dp)) then
          stat = 1
          errmsg = 'inverted element ' // itoa(noel) // ' (J <= 0 at integration point ' // itoa(ip) // ')'
          return
        end if
        vol = vol + wdet(ip) * j1(ip)
      end do
      celent = vol**third
    end subroutine first_pass

    !> Point ip's increment: the F-bar gradients at t_n and t_n+1, G with respect to the mid-increment configuration
    !> (Hughes-Winget), DROT in closed form, DSTRAN, and the converged stress and strain rotated by DROT.
    subroutine rotated_state(ip)
      integer, intent(in) :: ip
        fb0 = (jc0 / j0(ip))**third * fg0(:, :, ip)
        fb1 = (jc1 / j1(ip))**third * fg1(:, :, ip)
        ! Hughes-Winget: G = grad(du) w.r.t. x_mid with the F-bar gradients; DROT in closed form (solid_element)
        fm = 0.5_dp * (fb0 + fb1)
        if (.not. (det3(fm) > 0.0_dp)) then
          stat = 1
          errmsg = 'inverted element ' // itoa(noel) // ' (mid-increment J <= 0 at integration point ' // &
            itoa(ip) // ')'
          return
        end if
        g = matmul(fb1 - fb0, inv3(fm))
        wsk = 0.25_dp * (g - transpose(g))
        drot = identity() + (2.0_dp / (1.0_dp + wsk(3, 2)**2 + wsk(1, 3)**2 + wsk(2, 1)**2)) * (wsk + matmul(wsk, wsk))
        eps = 0.5_dp * (g + transpose(g))
        dstran = [eps(1, 1), eps(2, 2), eps(3, 3), 2.0_dp * eps(1, 2), 2.0_dp * eps(1, 3), 2.0_dp * eps(2, 3)]
        ! the converged stress and strain rotated by DROT
        sig = sym_of(stress_old(:, ip), 1.0_dp)
        sig = matmul(matmul(drot, sig), transpose(drot))
        stress = [sig(1, 1), sig(2, 2), sig(3, 3), sig(1, 2), sig(1, 3), sig(2, 3)]
        eps = sym_of(stran_old(:, ip), 0.5_dp)
        eps = matmul(matmul(drot, eps), transpose(drot))
        stran = [eps(1, 1), eps(2, 2), eps(3, 3), 2.0_dp * eps(1, 2), 2.0_dp * eps(1, 3), 2.0_dp * eps(2, 3)]
    end subroutine rotated_state

    !> Point ip's internal force and, when wanted, its tangent (spatial derivatives at t_n+1, volume element).
    subroutine force_and_tangent(ip)
      integer, intent(in) :: ip
      integer :: a, i
        ! spatial derivatives, volume element, internal force
        finv = inv3(fg1(:, :, ip))
        dndx = matmul(dref(:, :, ip), finv)
        dv = wdet(ip) * j1(ip) * mat%thickness
        energy = energy + [sse, spd] * dv
        sig = sym_of(stress, 1.0_dp)
        do a = 1, 8
          do i = 1, 3
            fe(3 * (a - 1) + i) = fe(3 * (a - 1) + i) + (sig(i, 1) * dndx(a, 1) + sig(i, 2) * dndx(a, 2) &
              + sig(i, 3) * dndx(a, 3)) * dv
          end do
        end do
        if (want_k) then
          ! Abaqus uses only the symmetric part of DDSDDE unless *USER MATERIAL, UNSYMM (*ELASTIC's is symmetric)
          if (.not. (elastic .or. mat%unsymm)) ddsdde = 0.5_dp * (ddsdde + transpose(ddsdde))
          call spatial_tangent_3d(ddsdde, sig, a4, q)
          bc = dndx_c - dndx
          call k_point_c3d8_spatial(level, a4, q, dndx, bc, dv, kl)
        end if
    end subroutine force_and_tangent

    !> The UMAT at point ip (call_umat's contract without its copies of values the element does not reuse).
    subroutine umat_point(ip)
      integer, intent(in) :: ip
      real(dp) :: c_time(2), c_dtime, c_props(np + umat_props_pad), c_celent, c_coords(3), c_rpl, c_drpldt
      real(dp) :: c_ddsddt(6), c_drplde(6), c_predef(max(1, nfld)), c_dpred(max(1, nfld))
      integer :: c_ndi, c_nshr, c_ntens, c_nstatv, c_nprops, c_noel, c_npt, c_layer, c_kspt, c_jstep(4), c_kinc, j
      character(len=80) :: c_cmname
      real(dp) :: no_statev(1)
      ! Abaqus: the current coordinates under NLGEOM
      do j = 1, 3
        c_coords(j) = dot_product(nfun(:, ip), coords0(j, :) + u1(j, :))
      end do
      ddsdde = 0.0_dp
      c_ddsddt = 0.0_dp
      c_drplde = 0.0_dp
      c_rpl = 0.0_dp
      c_drpldt = 0.0_dp
      c_time = time
      c_dtime = dtime
      c_props = 0.0_dp
      if (np > 0) c_props(1:np) = mat%props
      c_celent = celent
      c_predef = 0.0_dp
      c_dpred = 0.0_dp
      if (present(field_nodes) .and. present(dfield_nodes)) then
        c_predef(1:nfld) = matmul(field_nodes(:, 1:8), nfun(:, ip))
        c_dpred(1:nfld) = matmul(dfield_nodes(:, 1:8), nfun(:, ip))
      end if
      c_ndi = 3
      c_nshr = 3
      c_ntens = 6
      c_nstatv = nsv
      c_nprops = np
      c_noel = noel
      c_npt = ip
      c_layer = 1
      c_kspt = 1
      c_jstep = [kstep, 1, 1, 0]
      c_kinc = kinc
      c_cmname = mat%cmname
      if (nsv == 0) then
        ! NSTATV = 0: one (zero) entry to pass, nothing taken back
        no_statev = 0.0_dp
        call mat%umat(stress, no_statev, ddsdde, sse, spd, scd, c_rpl, c_ddsddt, c_drplde, c_drpldt, stran, &
          dstran, c_time, c_dtime, temp_ip, dtemp_ip, c_predef, c_dpred, c_cmname, c_ndi, c_nshr, c_ntens, c_nstatv, &
          c_props, c_nprops, c_coords, drot, pn, c_celent, fb0, fb1, c_noel, c_npt, c_layer, c_kspt, c_jstep, c_kinc)
        return
      end if
      call mat%umat(stress, statev_new(1:nsv, ip), ddsdde, sse, spd, scd, c_rpl, c_ddsddt, c_drplde, c_drpldt, stran, &
        dstran, c_time, c_dtime, temp_ip, dtemp_ip, c_predef, c_dpred, c_cmname, c_ndi, c_nshr, c_ntens, c_nstatv, &
        c_props, c_nprops, c_coords, drot, pn, c_celent, fb0, fb1, c_noel, c_npt, c_layer, c_kspt, c_jstep, c_kinc)
    end subroutine umat_point

  end subroutine c3d8_nlgeom

  !> The compact reference data of a C3D8 (c3d8_compact_size entries, 720 bytes instead of the 2.5 kB of
  !> solid_geometry_t's arrays and their descriptors): gc(1) = 1 when every reference Jacobian is > 0 (else 0 and
  !> nothing else set), gc(2:9) the points' Gauss weight x det(dX/dxi), gc(10:18) the inverse reference Jacobian at
  !> the centre, gc(19:90) at the 8 points. The same operations as solid_element_geometry
  !> (solid_reference_derivatives), so that c3d8_expand_geometry rebuilds its arrays to the bit.
  pure subroutine c3d8_compact_geometry(coords0, gc)
    real(dp), intent(in) :: coords0(3, 8)                 !< original coordinates
    real(dp), intent(out) :: gc(c3d8_compact_size)        !< compact reference data
    real(dp) :: xi(3), w, detj, jinv(3, 3)
    integer :: ip
    gc = 0.0_dp
    call reference_jacobian([0.0_dp, 0.0_dp, 0.0_dp], detj, jinv)
    if (.not. (detj > 0.0_dp)) return
    gc(10:18) = reshape(jinv, [9])
    do ip = 1, 8
      call solid_gauss_point(2, 3, ip, xi, w)
      call reference_jacobian(xi, detj, jinv)
      if (.not. (detj > 0.0_dp)) then
        gc = 0.0_dp
        return
      end if
      gc(1 + ip) = w * detj
      gc(19 + 9 * (ip - 1):27 + 9 * (ip - 1)) = reshape(jinv, [9])
    end do
    gc(1) = 1.0_dp
  contains
    pure subroutine reference_jacobian(xi, detj, jinv)
      real(dp), intent(in) :: xi(3)
      real(dp), intent(out) :: detj, jinv(3, 3)
      real(dp) :: jac(3, 3), n(8), dndxi(8, 3)
      call solid_shape_eval(FAM_HEX8, xi, n, dndxi)
      jac = matmul(coords0, dndxi)
      detj = det3(jac)
      jinv = 0.0_dp
      if (detj > 0.0_dp) jinv = inv3(jac)
    end subroutine reference_jacobian
  end subroutine c3d8_compact_geometry

  !> solid_geometry_t's arrays of a C3D8 from its compact reference data (valid): N_a at the points, weight x det,
  !> dN_a/dX at the centre and at the points (dN/dxi J^-1 as solid_reference_derivatives forms them, with the
  !> parent values as constants: 1080 operations a call).
  pure subroutine c3d8_expand_geometry(gc, nfun, wdet, dndx_0c, dref)
    real(dp), intent(in) :: gc(c3d8_compact_size)
    real(dp), intent(out) :: nfun(8, 8), wdet(8), dndx_0c(8, 3), dref(8, 3, 8)
    integer :: ip
    dndx_0c = matmul(parent_d(:, :, 9), reshape(gc(10:18), [3, 3]))
    do ip = 1, 8
      dref(:, :, ip) = matmul(parent_d(:, :, ip), reshape(gc(19 + 9 * (ip - 1):27 + 9 * (ip - 1)), [3, 3]))
    end do
    nfun = parent_n(:, 1:8)
    wdet = gc(2:9)
  end subroutine c3d8_expand_geometry

  !> F = I + sum_a disp_a (x) dN_a/dX over the 8 nodes (solid_element_compute's def_grad, in its order).
  pure function f_of(disp, dn) result(f)
    real(dp), intent(in) :: disp(3, 8), dn(8, 3)
    real(dp) :: f(3, 3)
    integer :: aa, ii, jj
    f = identity()
    do jj = 1, 3
      do aa = 1, 8
        do ii = 1, 3
          f(ii, jj) = f(ii, jj) + disp(ii, aa) * dn(aa, jj)
        end do
      end do
    end do
  end function f_of

  !> f_of at the 8 points at once: f(ip, i, j) = delta_ij + sum_a disp(i, a) dt(ip, a, j), dt(ip, a, j) = dN_a/dX_j
  !> at point ip; the points are the vector lanes, each entry is f_of's sum in f_of's order.
  pure subroutine f_points(disp, dt, f)
    real(dp), intent(in) :: disp(3, 8), dt(8, 8, 3)
    real(dp), intent(out) :: f(8, 3, 3)
    integer :: aa, ii, jj
    do jj = 1, 3
      do ii = 1, 3
        f(:, ii, jj) = merge(1.0_dp, 0.0_dp, ii == jj)
        do aa = 1, 8
          f(:, ii, jj) = f(:, ii, jj) + disp(ii, aa) * dt(:, aa, jj)
        end do
      end do
    end do
  end subroutine f_points

  !> det3 of the 8 points' F at once (f_points' layout), det3's operations in det3's order.
  pure function det_points(a) result(d)
    real(dp), intent(in) :: a(8, 3, 3)
    real(dp) :: d(8)
    d = a(:, 1, 1) * (a(:, 2, 2) * a(:, 3, 3) - a(:, 2, 3) * a(:, 3, 2)) &
      - a(:, 1, 2) * (a(:, 2, 1) * a(:, 3, 3) - a(:, 2, 3) * a(:, 3, 1)) &
      + a(:, 1, 3) * (a(:, 2, 1) * a(:, 3, 2) - a(:, 2, 2) * a(:, 3, 1))
  end function det_points

  !> Symmetric tensor of 6 Voigt components (voigt_to_tensor with NTENS = 6).
  pure function sym_of(v, shear_factor) result(t)
    real(dp), intent(in) :: v(6), shear_factor
    real(dp) :: t(3, 3)
    t(1, 1) = v(1)
    t(2, 2) = v(2)
    t(3, 3) = v(3)
    t(1, 2) = shear_factor * v(4)
    t(2, 1) = t(1, 2)
    t(1, 3) = shear_factor * v(5)
    t(3, 1) = t(1, 3)
    t(2, 3) = shear_factor * v(6)
    t(3, 2) = t(2, 3)
  end function sym_of

  !> spatial_tangent for NTENS = 6 under NLGEOM: A_ijkl = DDSDDE + the Jaumann terms, q_ij of F-bar (m = 3), in
  !> spatial_tangent's order of operations.
  pure subroutine spatial_tangent_3d(ddsdde, sig, a4, q)
    real(dp), intent(in) :: ddsdde(6, 6), sig(3, 3)
    real(dp), intent(out) :: a4(3, 3, 3, 3), q(3, 3)
    integer :: i, j, k, l
    do l = 1, 3
      do k = 1, 3
        do j = 1, 3
          do i = 1, 3
            a4(i, j, k, l) = ddsdde(vidx(i, j), vidx(k, l))
          end do
        end do
      end do
    end do
    do l = 1, 3
      do j = 1, 3
        do i = 1, 3
          a4(i, j, i, l) = a4(i, j, i, l) + 0.5_dp * sig(j, l)
          a4(i, j, l, i) = a4(i, j, l, i) - 0.5_dp * sig(j, l)
          a4(i, j, l, j) = a4(i, j, l, j) - 0.5_dp * sig(i, l)
          a4(i, j, j, l) = a4(i, j, j, l) - 0.5_dp * sig(i, l)
        end do
      end do
    end do
    q = 0.0_dp
    do k = 1, 3
      q = q + a4(:, :, k, k) / 3.0_dp
    end do
    q = q - (1.0_dp - 1.0_dp / 3.0_dp) * sig
  end subroutine spatial_tangent_3d

  include 'solid_tensor3.inc'

end module solid_c3d8
