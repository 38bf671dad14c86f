!> Time per call of the continuum element routine (host/elements: solid_element_compute) on one distorted C3D8
!> under NLGEOM, with the built-in *ELASTIC and with the Leonov UMAT (umat/umat.f, Table 1 properties):
!>   bench_element_calls [N]     (N calls of each case, N/5 of the plastic one; default 2*10^5)
!> Built by the Release build (build/bin/). Against an older build, compiled with its modules and libraries and
!> LDFCZ_BASELINE_API (the element routine of commit e9cbdfd: no generic_only, no geo_compact; one way):
!>   gfortran -O2 -cpp -fopenmp -DLDFCZ_BASELINE_API -I OLD/build/modules benchmarks/bench_element_calls.F90 \
!>     OLD/build/lib/libldfcz_elements.a OLD/build/lib/libldfcz_umat.a OLD/build/lib/libldfcz_abaqus_utils.a \
!>     OLD/build/lib/libldfcz_kinds.a -o bench_element_calls_old
!> Cases: *ELASTIC with the tangent and forces only; Leonov at an elastic increment (the UMAT's elastic fast path)
!> and at a plastic one (the return), with the tangent. Each case three ways: the generic path (generic_only), the
!> type's fixed-size kernel (solid_c3d8.f90) with the whole reference data (geo), and the kernel with the compact
!> reference data the host keeps for a C3D8 under NLGEOM (geo_compact): the three must give the same fingerprint.
!> The element is the unit cube with its nodes moved by up to 0.08 (every integration point differs), deformed
!> homogeneously from F_n = I + small shear to F_n+1 (elastic: 1e-4 more; plastic: shear 0.1 and stretch 1.02 from
!> Be~_12 = 0.05, dt = 0.5 s, as bench_leonov_calls). Prints microseconds per call (CPU time), the floating-point
!> operations per call of the kernel counted by hand (element_flops below; reports/bench/kernel/flops.md)
!> and the rate they give (the same count for the three ways: it is the work of the formulation), a checksum of the
!> forces, tangents and stresses over the calls and a fingerprint of the bits of the last call's outputs (two builds
!> or two ways compare for speed and results: equal fingerprints, identical outputs). Last, the tangent
!> accumulation alone at each instruction-set build of the point kernel (level 0 baseline, 1 AVX2, 2 AVX-512).
program bench_element_calls
  use, intrinsic :: iso_fortran_env, only: int64
  use ldfcz_kinds, only: dp
#ifdef LDFCZ_BASELINE_API
  use solid_element, only: solid_material_t, solid_element_compute, solid_geometry_t, solid_element_geometry, &
    SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, umat_interface
  use solid_tangent_kernel, only: k_point_c3d8
#else
  use solid_tangent_kernel, only: k_point_c3d8, k_point_c3d8_spatial, tangent_kernel_level, KERNEL_LEVEL_BASE
  use solid_element, only: solid_material_t, solid_element_compute, solid_geometry_t, solid_element_geometry, &
    solid_compact_geometry, SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, umat_interface
#endif
  use leonov_parameters, only: leonov_props_table1
  implicit none
  procedure(umat_interface) :: umat
  integer, parameter :: nn = 8, nip = 8, ntens = 6, nstatv = 11
  real(dp), parameter :: xcube(3, nn) = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, &
    0, 1, 1], [3, nn]) * 1.0_dp
  real(dp), parameter :: jitter(3, nn) = reshape([0.02, -0.03, 0.01, 0.05, 0.04, -0.02, -0.06, 0.03, 0.08, &
    0.01, -0.07, 0.02, 0.03, 0.02, -0.05, -0.04, 0.06, 0.03, 0.07, -0.02, 0.04, -0.03, -0.05, -0.01], [3, nn]) * 1.0_dp
#ifdef LDFCZ_BASELINE_API
  !> the older build's only way
  integer, parameter :: nway = 1
  character(len=16), parameter :: ways(1) = [character(len=16) :: 'older build']
#else
  !> the ways of computing an element: generic path, kernel with geo, kernel with geo_compact
  integer, parameter :: nway = 3
  character(len=16), parameter :: ways(3) = [character(len=16) :: 'generic', 'kernel', 'kernel, compact']
#endif
  type(solid_material_t) :: elastic, leonov
  type(solid_geometry_t) :: geo
  real(dp) :: x(3, nn), f0(3, 3), f1(3, 3), gc(90)
  integer :: n, way
  character(len=32) :: arg

  n = 200000
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read (arg, *) n
  end if
  x = xcube + jitter
  call solid_element_geometry('C3D8', x, geo)
  gc = 1.0_dp
#ifndef LDFCZ_BASELINE_API
  call solid_compact_geometry('C3D8', x, gc)
#endif
  if (.not. (geo%valid .and. gc(1) == 1.0_dp)) stop 'bench_element_calls: invalid geometry'
  elastic%kind = SOLID_MAT_ELASTIC
  elastic%e = 210000.0_dp
  elastic%nu = 0.3_dp
  leonov%kind = SOLID_MAT_UMAT
  leonov%props = leonov_props_table1()
  leonov%nstatv = nstatv
  leonov%cmname = 'PET'
  leonov%unsymm = .true.
  leonov%umat => umat

  print '(a)', 'case                     way              us per call   flops per call  GFLOP/s  checksum' // &
    '                fingerprint'
  f0 = identity3()
  f0(1, 2) = 2.0e-4_dp
  f1 = f0
  f1(1, 1) = 1.0_dp + 1.0e-4_dp
  do way = 1, nway
    call run('*ELASTIC, tangent', elastic, f0, f1, 0.0_dp, .true., n, way)
  end do
  do way = 1, nway
    call run('*ELASTIC, forces only', elastic, f0, f1, 0.0_dp, .false., n, way)
  end do
  do way = 1, nway
    call run('Leonov elastic, tangent', leonov, f0, f1, 2.0e-4_dp, .true., n, way)
  end do
  f0 = identity3()
  f1 = identity3()
  f1(1, 2) = 0.1_dp
  f1(1, 1) = 1.02_dp
  do way = 1, nway
    call run('Leonov plastic, tangent', leonov, f0, f1, 0.05_dp, .true., max(1, n / 5), way)
  end do
  call tangent_alone(n)

contains

  !> n calls of one case one way (dt = 0.5 s, converged Be~_12 = be12 for the Leonov material); prints the time
  !> per call, the counted flops, the rate, the checksum and the fingerprint.
  subroutine run(label, mat, f0, f1, be12, want_k, n, way)
    character(len=*), intent(in) :: label
    type(solid_material_t), intent(in) :: mat
    real(dp), intent(in) :: f0(3, 3), f1(3, 3), be12
    logical, intent(in) :: want_k
    integer, intent(in) :: n, way
    real(dp) :: u(3 * nn), du(3 * nn), s_old(ntens, nip), e_old(ntens, nip), v_old(nstatv, nip)
    real(dp) :: s_new(ntens, nip), e_new(ntens, nip), v_new(nstatv, nip), fe(3 * nn), ke(3 * nn, 3 * nn)
    real(dp) :: en(2), eip_old(3, nip), eip_new(3, nip), pnewdt, t0, t1, check, us, flops, du1
    character(len=200) :: msg
    character(len=25) :: lab
    integer :: i, a, st
    do a = 1, nn
      u(3 * a - 2:3 * a) = matmul(f1, x(:, a)) - x(:, a)
      du(3 * a - 2:3 * a) = u(3 * a - 2:3 * a) - (matmul(f0, x(:, a)) - x(:, a))
    end do
    du1 = du(1)
    s_old = 0.0_dp
    e_old = 0.0_dp
    v_old = 0.0_dp
    v_old(4, :) = be12            ! Leonov STATEV(4) = Be~_12 (Be~ - I, Voigt order)
    eip_old = 0.0_dp
    check = 0.0_dp
    st = 0
    call cpu_time(t0)
    do i = 1, n
      ! a different last bit each call: the compiler cannot hoist the work out of the loop
      du(1) = du1 + 1.0e-15_dp * mod(i, 3)
      pnewdt = 1.0e36_dp
      select case (way)
#ifdef LDFCZ_BASELINE_API
      case (1)
        call solid_element_compute('C3D8', x, u, du, mat, s_old, e_old, v_old, [0.0_dp, 0.0_dp], 0.5_dp, 1, 1, 1, &
          .true., want_k, fe, ke, s_new, e_new, v_new, en, pnewdt, st, msg, energy_ip_old=eip_old, &
          energy_ip_new=eip_new, geo=geo)
#else
      case (1)
        call solid_element_compute('C3D8', x, u, du, mat, s_old, e_old, v_old, [0.0_dp, 0.0_dp], 0.5_dp, 1, 1, 1, &
          .true., want_k, fe, ke, s_new, e_new, v_new, en, pnewdt, st, msg, energy_ip_old=eip_old, &
          energy_ip_new=eip_new, geo=geo, generic_only=.true.)
      case (2)
        call solid_element_compute('C3D8', x, u, du, mat, s_old, e_old, v_old, [0.0_dp, 0.0_dp], 0.5_dp, 1, 1, 1, &
          .true., want_k, fe, ke, s_new, e_new, v_new, en, pnewdt, st, msg, energy_ip_old=eip_old, &
          energy_ip_new=eip_new, geo=geo)
      case default
        call solid_element_compute('C3D8', x, u, du, mat, s_old, e_old, v_old, [0.0_dp, 0.0_dp], 0.5_dp, 1, 1, 1, &
          .true., want_k, fe, ke, s_new, e_new, v_new, en, pnewdt, st, msg, energy_ip_old=eip_old, &
          energy_ip_new=eip_new, geo_compact=gc)
#endif
      end select
      check = check + fe(7) + ke(5, 11) + s_new(4, 3)
    end do
    call cpu_time(t1)
    if (st /= 0) then
      print '(a)', 'bench_element_calls: ' // trim(msg)
      stop 1
    end if
    us = 1.0e6_dp * (t1 - t0) / n
    flops = element_flops(mat%kind, want_k, v_new(7, 1) > 0.0_dp)
    lab = label
    print '(a25,a16,f10.3,f17.0,f9.2,es24.15,2x,z16.16)', lab, ways(way), us, flops, 1.0e-3_dp * flops / us, check, &
      bits([fe, reshape(ke, [size(ke)]), reshape(s_new, [size(s_new)]), reshape(v_new, [size(v_new)]), &
      reshape(eip_new, [size(eip_new)]), en])
  end subroutine run

  !> The tangent accumulation alone: the 8 points' calls of the point kernel (solid_tangent_kernel) for one element,
  !> random operands: under NLGEOM (no row term) at each instruction-set build this CPU runs, and with the row
  !> term (the generic path's small-strain call; the older build has only this one, called under NLGEOM with a zero
  !> row term). 41 472 flops a C3D8 (216 columns' t_ij x 8 per point, 576 entries x 6), 51 072 with the row term
  !> (576 entries x 8, 24 traces x 2).
  subroutine tangent_alone(n)
    integer, intent(in) :: n
    real(dp) :: a4(3, 3, 3, 3), q(3, 3), d(8, 3), bc(8, 3), bcr(8, 3), kl(8, 3, 3, 8), t0, t1, s
    integer :: i, ip, level, variant
    character(len=40) :: lab
    call random_seed(put=[(4321 + 7 * i, i = 1, 64)])
    call random_number(a4)
    call random_number(q)
    call random_number(d)
    call random_number(bc)
    bcr = 0.0_dp
#ifdef LDFCZ_BASELINE_API
    do variant = 2, 2
      level = 0
#else
    do variant = 1, 2
      do level = KERNEL_LEVEL_BASE, tangent_kernel_level()
#endif
        s = 0.0_dp
        call cpu_time(t0)
        do i = 1, n
          kl = 0.0_dp
          do ip = 1, 8
#ifdef LDFCZ_BASELINE_API
            call k_point_c3d8(a4, q, d, bc, bcr, 1.0_dp + 1.0e-9_dp * ip, kl)
#else
            if (variant == 1) then
              call k_point_c3d8_spatial(level, a4, q, d, bc, 1.0_dp + 1.0e-9_dp * ip, kl)
            else
              call k_point_c3d8(level, a4, q, d, bc, bcr, 1.0_dp + 1.0e-9_dp * ip, kl)
            end if
#endif
          end do
          s = s + kl(3, 2, 1, 5)
          d(1, 1) = d(1, 1) + 1.0e-12_dp
        end do
        call cpu_time(t1)
        write (lab, '(a,a,i0)') trim(merge('tangent alone, NLGEOM   ', 'tangent alone, row term ', variant == 1)), &
          ', level ', level
        print '(a40,f10.3,f17.0,f9.2,es24.15)', lab, 1.0e6_dp * (t1 - t0) / n, &
          merge(41472.0_dp, 51072.0_dp, variant == 1), merge(41472.0_dp, 51072.0_dp, variant == 1) * 1.0e-3_dp &
          / (1.0e6_dp * (t1 - t0) / n), s
#ifndef LDFCZ_BASELINE_API
      end do
#endif
    end do
  end subroutine tangent_alone

  !> Floating-point operations (+, -, *, /, sqrt; a call of exp, log, pow, tanh or sinh counted as one) of one call of
  !> the C3D8 kernel (host/elements/solid_c3d8.f90), counted by hand from its loops, as the element runs here (no
  !> temperatures, no field variables; reports/bench/kernel/flops.md lists the terms):
  !>   per element 3070: u_n 24, F and J at the centre at t_n, t_n+1 316, dN/dx there 170, F and J at the 8 points
  !>     8 x 318, CELENT 1, the *ELASTIC matrix 15;
  !>   per point, forces 818: F-bar 22, mid-point F, its J and inverse 82, G 54, DROT 97, DSTRAN 21, STRESS and STRAN
  !>     rotated 189, STRAN + DSTRAN 6, dN/dx at the point 170, dv, energies and the stress tensor 9, f_int 168;
  !>   per point, material: *ELASTIC 91 (C : DSTRAN, SSE); UMAT 69 (COORDS) + the Leonov UMAT: its adapter
  !>     (umat.f: PROPS, STATEV, energies) 160 and the core (umat/leonov.f90) 954 at an elastic increment, 5080 at
  !>     this plastic one (bench_leonov_calls: the same increments; its 4 evaluations of g, 5 local residuals,
  !>     4 Newton steps, 1 Jacobi rotation counted by an instrumented build);
  !>   per point, tangent 5496: the Jaumann terms and q 288, bc 24, the kernel 5184 (216 columns' t_ij x 8, 576
  !>     entries x 6).
  pure real(dp) function element_flops(kind, want_k, plastic) result(f)
    integer, intent(in) :: kind
    logical, intent(in) :: want_k, plastic
    f = 3070.0_dp + 8 * 818.0_dp
    if (kind == SOLID_MAT_ELASTIC) then
      f = f + 8 * 91.0_dp
    else
      f = f + 8 * (69.0_dp + 160.0_dp + merge(5080.0_dp, 954.0_dp, plastic))
    end if
    if (want_k) f = f + 8 * 5496.0_dp
  end function element_flops

  !> A fingerprint of the bits of the last call's outputs: equal fingerprints mean identical outputs (to the bit,
  !> barring a collision of the 64-bit mix).
  pure integer(int64) function bits(v) result(h)
    real(dp), intent(in) :: v(:)
    integer :: k
    h = 0_int64
    do k = 1, size(v)
      h = ieor(ishftc(h, 7), transfer(v(k), 0_int64)) + int(k, int64)
    end do
  end function bits

  pure function identity3() result(e)
    real(dp) :: e(3, 3)
    e = 0.0_dp
    e(1, 1) = 1.0_dp
    e(2, 2) = 1.0_dp
    e(3, 3) = 1.0_dp
  end function identity3

end program bench_element_calls
