!> material_point: drives SUBROUTINE UMAT through a homogeneous deformation history, exactly as Abaqus/Standard
!> calls it under NLGEOM (Hughes-Winget DSTRAN and DROT from DFGRD0/DFGRD1, STRESS and STRAN rotated by DROT before
!> the call, fresh copies of the converged STRESS/STATEV on every call, PNEWDT cutbacks).
!>
!> Usage:  material_point [case.txt] [key=value ...]     (command-line keys override the file; -h, --help)
!> Keys (file lines "key = value", '#' starts a comment):
!>   mode         uniaxial | shear | deformation
!>                uniaxial: true axial strain ln(lambda_1) = rate*t, lateral Cauchy stresses zero (Newton on the
!>                  two lateral stretches with DDSDDE); rate < 0 is compression
!>                shear: simple shear F = I + rate*t e1 x e2
!>                deformation: F(t) = I + (t/time_end) (f_end - I)
!>   rate         strain rate (1/s)                          [1e-3]
!>   strain_end   |final true strain| (uniaxial) or shear (shear)   [1.0]
!>   time_end     end time for mode = deformation (s)        [1.0]
!>   f_end        9 numbers, F at time_end, row by row       [identity]
!>   steps        number of increments (before cutbacks)     [200]
!>   segment      KIND TARGET DURATION STEPS, repeatable: a history of segments for mode uniaxial or shear,
!>                run in the order given (instead of rate/strain_end/steps). KIND strain: the axial true strain
!>                ln(lambda_1) (uniaxial) or the shear (shear) goes linearly to TARGET in DURATION seconds; stress
!>                (uniaxial only): the axial Cauchy stress goes linearly to TARGET (MPa), the axial stretch follows
!>                (Newton with DDSDDE); hold: the quantity the previous segment controlled stays at its value
!>                (TARGET ignored): relaxation after a strain segment, creep after a stress segment. Unloading
!>                and cycles are segments back to a lower target.
!>   rotation     superposed rigid rotation at the end (degrees), growing linearly in time   [0]
!>   axis         rotation axis 1, 2 or 3                    [3]
!>   props        10 numbers (PROPS, Table 1 order)          [Table 1, PET]
!>   nstatv       number of state variables                  [11; 12 with plane_stress]
!>   plane_stress yes: call UMAT as Abaqus does for a plane-stress element (NDI = 2, NSHR = 1, NTENS = 3,
!>                components 11, 22, 12): the UMAT enforces sigma_33 = 0 itself; the driver controls only
!>                the in-plane stretches (uniaxial: Newton on lambda_2 alone) and takes the thickness stretch
!>                for the CSV from SDV12 = ln(lambda_3) (the Leonov UMAT's plane-stress state variable). The
!>                rotation axis must be 3.                   [no]
!>   output       CSV file                                   [material_point.csv]
!>                (a relative path in the case file is relative to the case file's directory, on the command line
!>                to the current directory)
!>   output_every write every n-th increment                 [1]
!> CSV columns: time, F11..F33 (row by row), S11 S22 S33 S12 S13 S23 (Cauchy, Abaqus order, global frame),
!>   SDV1..SDVn, then strain (ln lambda_1 or shear), stress (material-frame sigma_11 or sigma_12), J.
program material_point
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use ldfcz_kinds, only: dp
  use abaqus_host_state, only: abaqus_stop_requested, abaqus_stop_message
  implicit none

  real(dp), parameter :: pi = acos(-1.0_dp)
  character(len=32) :: mode = 'uniaxial'
  character(len=512) :: output = 'material_point.csv'
  character(len=512) :: case_dir = ''   !< directory of the case file ('' none; ends with '/')
  real(dp) :: rate = 1.0e-3_dp, strain_end = 1.0_dp, time_end = 1.0_dp, rotation = 0.0_dp
  real(dp) :: f_end(3, 3), props(10)
  integer :: steps = 200, axis = 3, nstatv = 11, output_every = 1
  real(dp), allocatable :: statev(:), statev_trial(:)
  real(dp) :: stress(6), stress_trial(6), stran(6), stran_trial(6), ddsdde(6, 6)
  real(dp) :: t, t_total, dt_target, h, f0(3, 3), f1(3, 3), xs(3), xs_trial(3), pnewdt
  integer :: unit, inc, kinc, ncut, iseg, nseg = 0, ctrl
  logical :: ok, plane_stress = .false.
  integer, parameter :: max_seg = 200
  integer, parameter :: ctrl_strain = 1, ctrl_stress = 2
  character(len=8) :: seg_kind(max_seg)
  real(dp) :: seg_target(max_seg), seg_time(max_seg), t0, x0_seg, s0_seg, x_goal
  integer :: seg_steps(max_seg)
  integer :: ios_out

  f_end = identity3()
  props = [1250.0_dp, 0.4_dp, 28.4_dp, 0.486_dp, 0.95_dp, 0.047_dp, 28.2_dp, 0.990_dp, 200.0_dp, -4.0_dp]
  call read_input()
  if (nstatv < 1 .or. steps < 1 .or. output_every < 1) call fail('nstatv, steps and output_every must be >= 1')
  if (plane_stress .and. (nstatv < 12 .or. (axis /= 3 .and. rotation /= 0.0_dp))) &
    call fail('plane_stress needs nstatv >= 12 (SDV12 = ln lambda_3) and a rotation about axis 3 only')
  select case (mode)
  case ('uniaxial', 'shear')
    if (nseg == 0) then
      ! the single ramp of rate and strain_end
      if (rate == 0.0_dp) call fail('rate must not be zero')
      nseg = 1
      seg_kind(1) = 'strain'
      seg_time(1) = abs(strain_end / rate)
      seg_target(1) = rate * seg_time(1)
      seg_steps(1) = steps
    end if
    t_total = sum(seg_time(1:nseg))
  case ('deformation')
    if (nseg > 0) call fail('segments need mode = uniaxial or shear')
    t_total = time_end
    nseg = 1
    seg_kind(1) = 'strain'
    seg_time(1) = time_end
    seg_steps(1) = steps
    seg_target(1) = 0.0_dp
  case default
    call fail('unknown mode "' // trim(mode) // '" (uniaxial, shear, deformation)')
  end select
  if (.not. (t_total > 0.0_dp)) call fail('the history has zero duration')
  allocate (statev(nstatv), statev_trial(nstatv))
  statev = 0.0_dp
  stress = 0.0_dp
  stran = 0.0_dp
  xs = 0.0_dp   ! ln of the three stretches (uniaxial) or the shear (shear, xs(1))

  open (newunit=unit, file=trim(output), status='replace', action='write', iostat=ios_out)
  if (ios_out /= 0) call fail('cannot write ' // trim(output) // ' (does its directory exist? output = FILE sets it)')
  call write_header()
  t = 0.0_dp
  f0 = deformation(0.0_dp, xs)
  call write_row(t, f0)
  kinc = 0
  ncut = 0
  ctrl = ctrl_strain
  do iseg = 1, nseg
    t0 = t
    x0_seg = xs(1)
    s0_seg = axial_stress()
    select case (seg_kind(iseg))
    case ('strain')
      ctrl = ctrl_strain
      x_goal = seg_target(iseg)
    case ('stress')
      ctrl = ctrl_stress
      x_goal = seg_target(iseg)
    case default  ! hold: the controlled quantity keeps its value
      x_goal = merge(x0_seg, s0_seg, ctrl == ctrl_strain)
    end select
    dt_target = seg_time(iseg) / seg_steps(iseg)
    do inc = 1, seg_steps(iseg)
      ! one output increment, with cutbacks on PNEWDT < 1
      h = dt_target
      do while (t < t0 + inc * dt_target - 1.0e-12_dp * dt_target)
        h = min(h, t0 + inc * dt_target - t)
        kinc = kinc + 1
        call increment(t, h, f0, xs, ok, pnewdt, f1, xs_trial)
        if (.not. ok) then
          ncut = ncut + 1
          if (ncut > 10000 .or. h < 1.0e-12_dp * dt_target) call fail('too many cutbacks')
          h = h * min(0.5_dp, max(0.1_dp, pnewdt))
          cycle
        end if
        t = t + h
        f0 = f1
        xs = xs_trial
        stress = stress_trial
        stran = stran_trial
        statev = statev_trial
        h = min(1.5_dp * h, dt_target)
      end do
      if (mod(inc, output_every) == 0 .or. inc == seg_steps(iseg)) call write_row(t, f0)
    end do
  end do
  close (unit)
  write (output_unit, '(a,a,a,i0,a,i0,a)') 'material_point: wrote ', trim(output), ' (', kinc, ' increments, ', &
    ncut, ' cutbacks)'

contains

  pure function identity3() result(a)
    real(dp) :: a(3, 3)
    a = 0.0_dp
    a(1, 1) = 1.0_dp
    a(2, 2) = 1.0_dp
    a(3, 3) = 1.0_dp
  end function identity3

  !> A one-line message and exit status 2 (no runtime error, no backtrace).
  subroutine fail(text)
    character(len=*), intent(in) :: text
    write (error_unit, '(a)') 'material_point: ' // text
    call exit(2)
  end subroutine fail

  !> Rigid rotation at time tt (angle grows linearly to `rotation` degrees at t_total).
  function rot(tt) result(r)
    real(dp), intent(in) :: tt
    real(dp) :: r(3, 3), a, c, s
    integer :: i1, i2
    a = rotation * pi / 180.0_dp * tt / t_total
    c = cos(a)
    s = sin(a)
    r = identity3()
    i1 = mod(axis, 3) + 1
    i2 = mod(axis + 1, 3) + 1
    r(i1, i1) = c
    r(i2, i2) = c
    r(i1, i2) = -s
    r(i2, i1) = s
  end function rot

  !> Material-frame deformation for the state x (uniaxial: ln of the three stretches; shear: x(1) the shear;
  !> deformation: F(tt) of f_end), then rotated by the superposed rotation at time tt.
  function deformation(tt, x) result(f)
    real(dp), intent(in) :: tt, x(3)
    real(dp) :: f(3, 3), fm(3, 3)
    fm = identity3()
    select case (mode)
    case ('uniaxial')
      fm(1, 1) = exp(x(1))
      fm(2, 2) = exp(x(2))
      fm(3, 3) = exp(x(3))
    case ('shear')
      fm(1, 2) = x(1)
      if (plane_stress) fm(3, 3) = exp(x(3))
    case default
      fm = identity3() + (tt / time_end) * (f_end - identity3())
    end select
    f = matmul(rot(tt), fm)
  end function deformation

  !> Controlled quantity of the current segment at time tt: strain (ln lambda_1 or shear) or axial stress.
  real(dp) function segment_value(tt) result(v)
    real(dp), intent(in) :: tt
    real(dp) :: s0
    s0 = merge(x0_seg, s0_seg, ctrl == ctrl_strain)
    v = s0 + (x_goal - s0) * min(1.0_dp, (tt - t0) / seg_time(iseg))
  end function segment_value

  !> Axial (uniaxial: sigma_11; shear: sigma_12) Cauchy stress of the converged state, material frame.
  real(dp) function axial_stress() result(v)
    real(dp) :: r(3, 3), sig_m(3, 3)
    r = rot(t)
    sig_m = matmul(transpose(r), matmul(to_tensor(stress, .false.), r))
    v = merge(sig_m(1, 2), sig_m(1, 1), mode == 'shear')
  end function axial_stress

  real(dp) function det3(a)
    real(dp), intent(in) :: a(3, 3)
    det3 = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
         + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function det3

  function inv3(a) result(b)
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

  function to_tensor(v, eng) result(a)
    real(dp), intent(in) :: v(6)
    logical, intent(in) :: eng     !< shear entries are engineering (2 x tensor) values
    real(dp) :: a(3, 3), sc
    sc = merge(0.5_dp, 1.0_dp, eng)
    a = reshape([v(1), sc * v(4), sc * v(5), sc * v(4), v(2), sc * v(6), sc * v(5), sc * v(6), v(3)], [3, 3])
  end function to_tensor

  function to_voigt(a, eng) result(v)
    real(dp), intent(in) :: a(3, 3)
    logical, intent(in) :: eng
    real(dp) :: v(6), sc
    sc = merge(2.0_dp, 1.0_dp, eng)
    v = [a(1, 1), a(2, 2), a(3, 3), sc * a(1, 2), sc * a(1, 3), sc * a(2, 3)]
  end function to_voigt

  !> One call of UMAT from the converged state for F0 -> F1 in time hh, as Abaqus makes it.
  subroutine call_umat(tt, hh, fa, fb, pnew)
    real(dp), intent(in) :: tt, hh, fa(3, 3), fb(3, 3)
    real(dp), intent(out) :: pnew
    real(dp) :: gmat(3, 3), w(3, 3), drot(3, 3), dstran(6), time(2), sse, spd, scd, rpl, ddsddt(6), drplde(6)
    real(dp) :: drpldt, temp, dtemp, predef(1), dpred(1), coords(3), celent, fa_c(3, 3), fb_c(3, 3), fmid_inv(3, 3)
    real(dp) :: s3(3), e3(3), de3(3), c3(3, 3), r3(3), q3(3)
    integer :: jstep(4)
    integer, parameter :: ip(3) = [1, 2, 4]
    character(len=80) :: cmname
    ! Hughes-Winget: G = grad(du) at the mid-point configuration
    fmid_inv = inv3(0.5_dp * (fa + fb))
    gmat = matmul(fb - fa, fmid_inv)
    w = 0.5_dp * (gmat - transpose(gmat))
    drot = matmul(inv3(identity3() - 0.5_dp * w), identity3() + 0.5_dp * w)
    dstran = to_voigt(0.5_dp * (gmat + transpose(gmat)), .true.)
    stress_trial = to_voigt(matmul(drot, matmul(to_tensor(stress, .false.), transpose(drot))), .false.)
    stran_trial = to_voigt(matmul(drot, matmul(to_tensor(stran, .true.), transpose(drot))), .true.)
    statev_trial = statev
    time = [tt, tt]
    sse = 0.0_dp
    spd = 0.0_dp
    scd = 0.0_dp
    rpl = 0.0_dp
    drpldt = 0.0_dp
    temp = 0.0_dp
    dtemp = 0.0_dp
    predef = 0.0_dp
    dpred = 0.0_dp
    coords = 0.0_dp
    celent = 1.0_dp
    jstep = [1, 1, 1, 0]
    cmname = 'LEONOV'
    pnew = 1.0e36_dp
    ddsdde = 0.0_dp
    fa_c = fa
    fb_c = fb
    if (plane_stress) then
      ! Abaqus' plane-stress call: the in-plane components only; sigma_33 = sigma_13 = sigma_23 = 0
      s3 = stress_trial(ip)
      e3 = stran_trial(ip)
      de3 = dstran(ip)
      c3 = 0.0_dp
      call umat(s3, statev_trial, c3, sse, spd, scd, rpl, r3, q3, drpldt, e3, de3, &
                time, hh, temp, dtemp, predef, dpred, cmname, 2, 1, 3, nstatv, props, 10, coords, drot, pnew, &
                celent, fa_c, fb_c, 1, 1, 1, 1, jstep, kinc)
      stress_trial = 0.0_dp
      stress_trial(ip) = s3
      ddsdde = 0.0_dp
      ddsdde(ip, ip) = c3
      dstran = 0.0_dp
      dstran(ip) = de3
      dstran(3) = statev_trial(12) - statev(12)   ! the thickness log strain increment (no rotation out of plane)
    else
      call umat(stress_trial, statev_trial, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran_trial, &
                dstran, time, hh, temp, dtemp, predef, dpred, cmname, 3, 3, 6, nstatv, props, 10, coords, drot, &
                pnew, celent, fa_c, fb_c, 1, 1, 1, 1, jstep, kinc)
    end if
    stran_trial = stran_trial + dstran
    if (abaqus_stop_requested()) call fail('UMAT stopped the analysis: ' // abaqus_stop_message())
  end subroutine call_umat

  !> One increment t -> t + hh from the state x0: the controlled quantity at t + hh from the segment; for uniaxial
  !> mode a Newton loop on the free log stretches (lateral ones, and the axial one under stress control).
  subroutine increment(tt, hh, fa, x0, success, pnew, fb, x1)
    real(dp), intent(in) :: tt, hh, fa(3, 3), x0(3)
    logical, intent(out) :: success
    real(dp), intent(out) :: pnew, fb(3, 3), x1(3)
    real(dp) :: r(3, 3), sig_m(3, 3), res(3), jac(3, 3), dx(3), dm(3, 3), col(3, 3), jdet, scale, st
    integer :: it, b, first
    success = .false.
    x1 = x0
    if (mode == 'deformation') then
      fb = deformation(tt + hh, x1)
      call call_umat(tt, hh, fa, fb, pnew)
      if (plane_stress) fb(3, 3) = exp(statev_trial(12))
      success = pnew >= 1.0_dp
      return
    end if
    if (ctrl == ctrl_strain) x1(1) = segment_value(tt + hh)
    if (mode == 'shear') then
      fb = deformation(tt + hh, x1)
      call call_umat(tt, hh, fa, fb, pnew)
      if (plane_stress) then
        x1(3) = statev_trial(12)
        fb = deformation(tt + hh, x1)
      end if
      success = pnew >= 1.0_dp
      return
    end if
    st = 0.0_dp
    if (ctrl == ctrl_stress) st = segment_value(tt + hh)
    first = merge(1, 2, ctrl == ctrl_stress)
    r = rot(tt + hh)
    do it = 1, 40
      fb = deformation(tt + hh, x1)
      call call_umat(tt, hh, fa, fb, pnew)
      if (pnew < 1.0_dp) return
      if (plane_stress) then
        x1(3) = statev_trial(12)   ! the UMAT's thickness stretch (it ignores F33)
        fb = deformation(tt + hh, x1)
      end if
      jdet = det3(fb)
      sig_m = matmul(transpose(r), matmul(to_tensor(stress_trial, .false.), r))
      ! residuals in Kirchhoff stress: axial tau_11 - J s (stress control), lateral tau_22 = tau_33 = 0
      res = jdet * [sig_m(1, 1) - st, sig_m(2, 2), sig_m(3, 3)]
      scale = max(1.0_dp, abs(sig_m(1, 1)), abs(st))
      if (maxval(abs(res(first:3))) <= 1.0e-10_dp * scale) then
        success = .true.
        return
      end if
      ! d(J sigma')/d ln(lambda_b) = J R^T [C : (R e_b e_b^T R^T)] R  (no spin: Jaumann = material rate);
      ! d(J s)/d ln(lambda_b) = J s
      do b = 1, 3
        dm = 0.0_dp
        dm(b, b) = 1.0_dp
        dm = matmul(r, matmul(dm, transpose(r)))
        col = to_tensor(matmul(ddsdde, to_voigt(dm, .true.)), .false.)
        col = jdet * matmul(transpose(r), matmul(col, r))
        jac(:, b) = [col(1, 1) - jdet * st, col(2, 2), col(3, 3)]
      end do
      dx = 0.0_dp
      if (plane_stress) then
        ! sigma_33 = 0 is the UMAT's: only the in-plane stretches are unknowns here
        if (first == 1) then
          dx(1:2) = solve2(jac(1:2, 1:2), -res(1:2))
        else
          dx(2) = -res(2) / jac(2, 2)
        end if
      else if (first == 1) then
        dx = solve3(jac, -res)
      else
        dx(2:3) = solve2(jac(2:3, 2:3), -res(2:3))
      end if
      x1 = x1 + dx
    end do
    pnew = 0.5_dp
  end subroutine increment

  function solve3(a, b) result(x)
    real(dp), intent(in) :: a(3, 3), b(3)
    real(dp) :: x(3), a_inv(3, 3)
    ! (the inverse in a variable: gfortran 12 warns about its own temporary for a function result inside MATMUL)
    a_inv = inv3(a)
    x = matmul(a_inv, b)
  end function solve3

  function solve2(a, b) result(x)
    real(dp), intent(in) :: a(2, 2), b(2)
    real(dp) :: x(2), d
    d = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
    x = [a(2, 2) * b(1) - a(1, 2) * b(2), a(1, 1) * b(2) - a(2, 1) * b(1)] / d
  end function solve2

  subroutine write_header()
    integer :: i
    character(len=16) :: name
    write (unit, '(a)', advance='no') 'time,F11,F12,F13,F21,F22,F23,F31,F32,F33,S11,S22,S33,S12,S13,S23'
    do i = 1, nstatv
      write (name, '(a,i0)') ',SDV', i
      write (unit, '(a)', advance='no') trim(name)
    end do
    write (unit, '(a)') ',strain,stress,J'
  end subroutine write_header

  subroutine write_row(tt, f)
    real(dp), intent(in) :: tt, f(3, 3)
    real(dp) :: r(3, 3), sig_m(3, 3), strain, s_ax
    r = rot(tt)
    sig_m = matmul(transpose(r), matmul(to_tensor(stress, .false.), r))
    select case (mode)
    case ('uniaxial')
      strain = xs(1)
      s_ax = sig_m(1, 1)
    case ('shear')
      strain = xs(1)
      s_ax = sig_m(1, 2)
    case default
      strain = 0.0_dp
      s_ax = 0.0_dp
    end select
    write (unit, '(es23.15,*(:,",",es23.15))') tt, transpose(f), stress, statev, strain, s_ax, det3(f)
  end subroutine write_row

  !> Read the optional case file (first argument without '='), then key=value arguments (which override it). A
  !> relative output path in the case file is taken relative to the case file's directory.
  subroutine read_input()
    integer :: i, n, ios, u, k, nfile, nkey
    character(len=1024) :: arg, line
    logical :: there
    n = command_argument_count()
    nfile = 0
    nkey = 0
    do i = 1, n
      call get_command_argument(i, arg)
      if (arg == '-h' .or. arg == '--help') then
        call usage()
        stop
      end if
      if (index(arg, '=') == 0) then
        nfile = nfile + 1
        if (nfile > 1) call fail('only one case file may be given (and key=value arguments): ' // trim(arg))
        inquire (file=trim(arg)//'/.', exist=there)
        if (there) call fail(trim(arg) // ': is a directory, not a case file')
        inquire (file=trim(arg), exist=there)
        if (.not. there) call fail(trim(arg) // ': case file not found (material_point --help)')
        open (newunit=u, file=trim(arg), status='old', action='read', iostat=ios)
        if (ios /= 0) call fail('cannot open case file ' // trim(arg))
        k = index(arg, '/', back=.true.)
        case_dir = arg(1:k)
        do
          read (u, '(a)', iostat=ios) line
          if (is_iostat_end(ios)) exit
          if (ios /= 0) call fail(trim(arg) // ': not a text case file (a line could not be read)')
          ! after its comment, a line is blank or 'key = value' (a DOS line end is a blank)
          k = index(line, '#')
          if (k > 0) line(k:) = ' '
          k = index(line, achar(13))
          if (k > 0) line(k:k) = ' '
          if (index(line, '=') > 0) nkey = nkey + 1
          if (verify(line, ' ' // achar(9) // achar(13)) > 0 .and. index(line, '=') == 0) &
            call fail(trim(arg) // ': not a case file line (key = value expected): ' // trim(printable(line)))
          call set_key(line, .true.)
        end do
        close (u)
        if (nkey == 0) call fail(trim(arg) // ': no ''key = value'' line (an empty case file? material_point --help)')
      end if
    end do
    case_dir = ''
    do i = 1, n
      call get_command_argument(i, arg)
      if (index(arg, '=') > 0) call set_key(arg, .false.)
    end do
  end subroutine read_input

  !> The first 60 characters of a line with non-printable characters shown as '?' (a binary file's line).
  pure function printable(text) result(t)
    character(len=*), intent(in) :: text
    character(len=min(len(text), 60)) :: t
    integer :: i
    t = text(1:len(t))
    do i = 1, len(t)
      if (iachar(t(i:i)) < 32 .or. iachar(t(i:i)) > 126) t(i:i) = '?'
    end do
  end function printable

  subroutine set_key(text, from_file)
    character(len=*), intent(in) :: text
    logical, intent(in) :: from_file   !< a line of the case file (relative paths: from its directory)
    character(len=1024) :: line, key, val
    integer :: k, ios
    line = text
    k = index(line, '#')
    if (k > 0) line(k:) = ' '
    k = index(line, '=')
    if (k == 0) return
    key = adjustl(line(:k - 1))
    val = adjustl(line(k + 1:))
    ios = 0
    select case (trim(key))
    case ('mode')
      mode = trim(val)
    case ('output')
      output = trim(val)
      if (from_file .and. len_trim(case_dir) > 0 .and. output(1:1) /= '/') output = trim(case_dir) // trim(val)
    case ('rate')
      read (val, *, iostat=ios) rate
    case ('strain_end')
      read (val, *, iostat=ios) strain_end
    case ('time_end')
      read (val, *, iostat=ios) time_end
    case ('steps')
      read (val, *, iostat=ios) steps
    case ('rotation')
      read (val, *, iostat=ios) rotation
    case ('axis')
      read (val, *, iostat=ios) axis
    case ('nstatv')
      read (val, *, iostat=ios) nstatv
    case ('plane_stress')
      plane_stress = any(trim(val) == ['yes ', 'YES ', 'true', '1   '])
      if (.not. plane_stress .and. .not. any(trim(val) == ['no   ', 'NO   ', 'false', '0    '])) &
        call fail('plane_stress must be yes or no: ' // trim(val))
    case ('output_every')
      read (val, *, iostat=ios) output_every
    case ('props')
      read (val, *, iostat=ios) props
    case ('segment')
      if (nseg == max_seg) call fail('more than 200 segments')
      nseg = nseg + 1
      read (val, *, iostat=ios) seg_kind(nseg), seg_target(nseg), seg_time(nseg), seg_steps(nseg)
      if (ios == 0) then
        select case (seg_kind(nseg))
        case ('strain', 'hold')
        case ('stress')
          if (mode /= 'uniaxial') call fail('a stress segment needs mode = uniaxial (set mode before the segments)')
        case default
          call fail('segment kind must be strain, stress or hold: '//trim(val))
        end select
        if (.not. (seg_time(nseg) > 0.0_dp) .or. seg_steps(nseg) < 1) &
          call fail('segment needs a duration > 0 and steps >= 1: '//trim(val))
      end if
    case ('f_end')
      read (val, *, iostat=ios) f_end
      f_end = transpose(f_end)
    case default
      call fail('unknown key "' // trim(printable(key)) // '" (material_point --help)')
    end select
    if (ios /= 0) call fail('cannot read the value of ' // trim(key) // ': ' // trim(printable(val)))
    if (axis < 1 .or. axis > 3) call fail('axis must be 1, 2 or 3')
  end subroutine set_key

  subroutine usage()
    write (output_unit, '(a)') 'usage: material_point [case.txt] [key=value ...]', &
      '  Drives SUBROUTINE UMAT through a homogeneous history as Abaqus/Standard calls it under NLGEOM and writes', &
      '  a CSV (time, F, Cauchy stress, SDV, strain, stress, J). Keys (in the case file as "key = value", or on', &
      '  the command line, which overrides the file):', &
      '  mode = uniaxial | shear | deformation', &
      '  rate, strain_end, steps      a single strain ramp (uniaxial: true strain; shear: shear)', &
      '  segment = KIND TARGET DURATION STEPS   repeatable history: KIND strain (to TARGET), stress (uniaxial,', &
      '                               axial Cauchy stress to TARGET MPa) or hold (relaxation after strain,', &
      '                               creep after stress); unloading and cycles are segments back down', &
      '  time_end, f_end (9 numbers)  mode deformation: F(t) = I + t/time_end (f_end - I)', &
      '  rotation, axis               superposed rigid rotation (degrees at the end, about axis 1..3)', &
      '  props (10 numbers), nstatv   the UMAT constants (Table 1, PET, by default) and state size', &
      '  plane_stress = yes           call the UMAT as for a plane-stress element (NTENS = 3; nstatv >= 12)', &
      '  output, output_every         CSV file and output interval', &
      '  examples: decks/material/*.txt (tension, compression, shear, relaxation, creep)'
  end subroutine usage

end program material_point
