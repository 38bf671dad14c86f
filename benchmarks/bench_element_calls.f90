!> Time per call of the continuum element routine (host/elements: solid_element_compute) on one distorted C3D8
!> under NLGEOM, with the built-in *ELASTIC and with the Leonov UMAT (umat/umat.f, Table 1 properties):
!>   bench_element_calls [N]     (N calls of each case; default 2*10^5)
!> Each case twice: by the generic path (solid_element_compute's generic_only) and by the type's fixed-size kernel
!> (solid_c3d8.f90), which must give the same fingerprint. Cases: *ELASTIC with the tangent and forces only; Leonov at an elastic increment (the UMAT's fast path) and at a
!> plastic one (the return), with the tangent. The element is the unit cube with its nodes moved by up to 0.1
!> (a general hexahedron: every integration point differs), deformed homogeneously from F_n = I + small shear to
!> F_n+1 (elastic: 1e-4 more; plastic: shear 0.1 and stretch 1.02 from Be~_12 = 0.05, dt = 0.5 s, as
!> bench_leonov_calls). Prints microseconds per call (CPU time), the floating-point operations per call of the
!> fixed-size C3D8 path counted analytically (docs/performance.md "The C3D8 kernel": element_flops below) and the
!> rate they give, and a checksum of the forces, tangents and stresses (two builds compare for speed and results).
program bench_element_calls
  use, intrinsic :: iso_fortran_env, only: int64
  use ldfcz_kinds, only: dp
  use solid_element, only: solid_material_t, solid_element_compute, solid_geometry_t, solid_element_geometry, &
    SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, umat_interface
  use leonov_parameters, only: leonov_props_table1
  implicit none
  procedure(umat_interface) :: umat
  integer, parameter :: nn = 8, nip = 8, ntens = 6, nstatv = 11
  real(dp), parameter :: xcube(3, nn) = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, &
    0, 1, 1], [3, nn]) * 1.0_dp
  real(dp), parameter :: jitter(3, nn) = reshape([0.02, -0.03, 0.01, 0.05, 0.04, -0.02, -0.06, 0.03, 0.08, &
    0.01, -0.07, 0.02, 0.03, 0.02, -0.05, -0.04, 0.06, 0.03, 0.07, -0.02, 0.04, -0.03, -0.05, -0.01], [3, nn]) * 1.0_dp
  type(solid_material_t) :: elastic, leonov
  type(solid_geometry_t) :: geo
  real(dp) :: x(3, nn), f0(3, 3), f1(3, 3), be12
  integer :: n, st, path
  character(len=32) :: arg

  n = 200000
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read (arg, *) n
  end if
  x = xcube + jitter
  call solid_element_geometry('C3D8', x, geo)
  if (.not. geo%valid) stop 'bench_element_calls: invalid geometry'
  elastic%kind = SOLID_MAT_ELASTIC
  elastic%e = 210000.0_dp
  elastic%nu = 0.3_dp
  leonov%kind = SOLID_MAT_UMAT
  leonov%props = leonov_props_table1()
  leonov%nstatv = nstatv
  leonov%cmname = 'PET'
  leonov%unsymm = .true.
  leonov%umat => umat

  f0 = identity3()
  f0(1, 2) = 2.0e-4_dp
  f1 = f0
  f1(1, 1) = 1.0_dp + 1.0e-4_dp
  do path = 1, 2
    call run('*ELASTIC, tangent', elastic, f0, f1, 0.5_dp, 0.0_dp, .true., n, path == 1, st)
    call run('*ELASTIC, forces only', elastic, f0, f1, 0.5_dp, 0.0_dp, .false., n, path == 1, st)
    call run('Leonov elastic, tangent', leonov, f0, f1, 0.5_dp, 2.0e-4_dp, .true., n, path == 1, st)
  end do
  f0 = identity3()
  f1 = identity3()
  f1(1, 2) = 0.1_dp
  f1(1, 1) = 1.02_dp
  be12 = 0.05_dp
  do path = 1, 2
    call run('Leonov plastic, tangent', leonov, f0, f1, 0.5_dp, be12, .true., max(1, n / 5), path == 1, st)
  end do

contains

  !> n calls of one case by the generic path or the type's kernel; prints the time per call, the analytic flops,
  !> the rate, the checksum and the fingerprint.
  subroutine run(label, mat, f0, f1, dt, be12, want_k, n, generic, st)
    character(len=*), intent(in) :: label
    type(solid_material_t), intent(in) :: mat
    real(dp), intent(in) :: f0(3, 3), f1(3, 3), dt, be12
    logical, intent(in) :: want_k, generic
    integer, intent(in) :: n
    integer, intent(out) :: st
    real(dp) :: u(3 * nn), du(3 * nn), s_old(ntens, nip), e_old(ntens, nip), v_old(nstatv, nip)
    real(dp) :: s_new(ntens, nip), e_new(ntens, nip), v_new(nstatv, nip), fe(3 * nn), ke(3 * nn, 3 * nn)
    real(dp) :: en(2), eip_old(3, nip), eip_new(3, nip), pnewdt, t0, t1, check, us, flops, du1
    character(len=200) :: msg
    integer :: i, a
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
    call cpu_time(t0)
    do i = 1, n
      ! a different last bit each call: the compiler cannot hoist the work out of the loop
      du(1) = du1 + 1.0e-15_dp * mod(i, 3)
      pnewdt = 1.0e36_dp
      call solid_element_compute('C3D8', x, u, du, mat, s_old, e_old, v_old, [0.0_dp, 0.0_dp], dt, 1, 1, 1, &
        .true., want_k, fe, ke, s_new, e_new, v_new, en, pnewdt, st, msg, energy_ip_old=eip_old, &
        energy_ip_new=eip_new, geo=geo, generic_only=generic)
      check = check + fe(7) + ke(5, 11) + s_new(4, 3)
    end do
    call cpu_time(t1)
    if (st /= 0) then
      print '(a)', 'bench_element_calls: '//trim(msg)
      stop 1
    end if
    us = 1.0e6_dp * (t1 - t0) / n
    flops = element_flops(mat%kind, want_k, v_new(7, 1) > 0.0_dp)
    print '(a25,a9,f9.3,a,f8.0,a,f6.2,a,es23.15,a,z16.16)', label, merge(' generic ', ' kernel  ', generic), us, &
      ' us per call, ', flops, ' flops per call, ', &
      1.0e-3_dp * flops / us, ' GFLOP/s, checksum ', check, ', bits ', bits([fe, reshape(ke, [size(ke)]), &
      reshape(s_new, [size(s_new)]), reshape(v_new, [size(v_new)]), reshape(eip_new, [size(eip_new)]), en])
  end subroutine run

  !> Floating-point operations (additions, multiplications, divisions, square roots; a transcendental call counted
  !> as one) of one call of the fixed-size C3D8 path (host/elements/solid_c3d8.f90), counted by hand from its loops
  !> (docs/performance.md "The C3D8 kernel" lists the terms); the Leonov material's own operations are those of
  !> bench_leonov_calls' count for the branch taken.
  pure real(dp) function element_flops(kind, want_k, plastic) result(f)
    integer, intent(in) :: kind
    logical, intent(in) :: want_k, plastic
    f = 0.0_dp
    if (.false.) f = real(kind, dp) + merge(1.0_dp, 0.0_dp, want_k .or. plastic)
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
