!> Benchmark of the host's sparse solver (module sparse_system: METIS node ordering + sequential MUMPS) on
!> hexahedral meshes of increasing size: prints setup (pattern, slot maps, METIS, MUMPS analysis), assembly,
!> factorization and solve wall times against the number of equations, and the fitted exponents
!> time ~ DOFs^p of factorization and solve (least squares in log-log).
!>
!> Usage: bench_linalg [cube|peel] [max_dofs] [sym|unsym]
!>   cube: n x n x n bricks, n = 4, 6, 8, ...   peel: L x 10 x 3 bricks (the paper's application scene, 10
!>   elements across, 3 through the thickness), L = 10, 20, 40, ...  The z = 0 node layer is constrained.
!>   Element matrices are random symmetric positive definite 24 x 24 (the values do not change the sparsity,
!>   the ordering or the flop count of a factorization without delayed pivots).
program bench_linalg
  use, intrinsic :: iso_fortran_env, only: error_unit
  use ldfcz_kinds, only: dp, i8
  use sparse_system
  implicit none
  character(len=16) :: family, symarg
  character(len=32) :: arg
  character(len=256) :: msg
  integer :: max_dofs, nsize, k, stat, ex, ey, ez, e
  logical :: symmetric
  real(dp) :: ldofs(64), lfac(64), lsol(64), t_asm
  integer, allocatable :: elem_ptr(:), elem_eq(:), eq_node(:)
  real(dp), allocatable :: b(:), x(:), r(:)
  real(dp) :: ke(24, 24)
  type(sparse_system_t) :: sys
  integer :: neq
  integer(i8) :: c0, c1, rate

  family = 'cube'
  max_dofs = 60000
  symarg = 'sym'
  if (command_argument_count() >= 1) call get_command_argument(1, family)
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    read (arg, *, iostat=k) max_dofs
    if (k /= 0 .or. max_dofs < 1) then
      write (error_unit, '(a)') 'bench_linalg: the second argument is the largest number of dofs, a positive '// &
        'integer: '//trim(arg)//' (usage: bench_linalg [cube|peel] [max_dofs] [sym|unsym])'
      call exit(2)
    end if
  end if
  if (command_argument_count() >= 3) call get_command_argument(3, symarg)
  if (trim(family) /= 'cube' .and. trim(family) /= 'peel') then
    write (error_unit, '(a)') 'bench_linalg: the first argument is the mesh family, cube or peel: '//trim(family)
    call exit(2)
  end if
  if (trim(symarg) /= 'sym' .and. trim(symarg) /= 'unsym') then
    write (error_unit, '(a)') 'bench_linalg: the third argument is sym or unsym: '//trim(symarg)
    call exit(2)
  end if
  symmetric = trim(symarg) /= 'unsym'
  write(*, '(a,a,a,i0,a,l1)') '# bench_linalg: family ', trim(family), ', max_dofs ', max_dofs, ', symmetric ', &
    symmetric
  write(*, '(a)') '#   elems     dofs        nnz   factor_entries  setup_s  assemble_s   factor_s    solve_s  resid'
  nsize = 0
  k = 0
  do
    k = k + 1
    select case (trim(family))
    case ('peel')
      ex = 10 * 2**(k - 1)
      ey = 10
      ez = 3
    case default
      ex = 2 + 2 * k
      ey = ex
      ez = ex
    end select
    if (3 * (ex + 1) * (ey + 1) * ez > max_dofs .or. k > 60) exit
    call make_mesh(ex, ey, ez, elem_ptr, elem_eq, eq_node, neq)
    call sparse_setup(sys, neq, elem_ptr, elem_eq, eq_node, symmetric, stat, msg)
    if (stat /= 0) then
      write(*, '(a)') trim(msg)
      exit
    end if
    call system_clock(c0, rate)
    call sparse_zero(sys)
    !$omp parallel do private(e, ke) schedule(static)
    do e = 1, size(elem_ptr) - 1
      call element_matrix(e, symmetric, ke)
      call sparse_add_element(sys, e, ke)
    end do
    !$omp end parallel do
    call system_clock(c1)
    t_asm = real(c1 - c0, dp) / real(rate, dp)
    ! Two factorizations and solves: the reported times are the averages.
    allocate(b(neq), x(neq), r(neq))
    b = 1.0_dp
    do e = 1, 2
      call sparse_factorize(sys, stat, msg)
      if (stat /= 0) exit
      x = b
      call sparse_solve(sys, x, stat, msg)
      if (stat /= 0) exit
    end do
    if (stat /= 0) then
      write(*, '(a)') trim(msg)
      exit
    end if
    call sparse_matvec(sys, x, r)
    nsize = nsize + 1
    ldofs(nsize) = log(real(neq, dp))
    lfac(nsize) = log(sparse_time_factor(sys) / 2)
    lsol(nsize) = log(sparse_time_solve(sys) / 2)
    write(*, '(i9,i9,i11,i17,4f11.4,es8.1)') size(elem_ptr) - 1, neq, sparse_nnz(sys), sparse_factor_entries(sys), &
      sparse_time_analysis(sys), t_asm, sparse_time_factor(sys) / 2, sparse_time_solve(sys) / 2, &
      norm2(r - b) / norm2(b)
    call sparse_destroy(sys)
    deallocate(b, x, r)
  end do
  if (nsize >= 3) then
    ! Fit on the larger half of the sizes: small systems are dominated by fixed overheads.
    k = max(1, nsize / 2)
    write(*, '(a,f6.2,a,f6.2)') '# fitted exponent (larger half of the sizes): factor time ~ dofs^', &
      slope(ldofs(k:nsize), lfac(k:nsize)), ', solve time ~ dofs^', slope(ldofs(k:nsize), lsol(k:nsize))
  end if

contains

  !> Brick mesh ex x ey x ez, 3 dofs a node, the z = 0 node layer constrained; equations node by node.
  subroutine make_mesh(ex, ey, ez, elem_ptr, elem_eq, eq_node, neq)
    integer, intent(in) :: ex, ey, ez
    integer, allocatable, intent(out) :: elem_ptr(:), elem_eq(:), eq_node(:)
    integer, intent(out) :: neq
    integer, parameter :: di(8) = [0, 1, 1, 0, 0, 1, 1, 0], dj(8) = [0, 0, 1, 1, 0, 0, 1, 1], &
                          dk(8) = [0, 0, 0, 0, 1, 1, 1, 1]
    integer :: i, j, kk, e, a, d, n, nlayer, nelem

    nelem = ex * ey * ez
    nlayer = (ex + 1) * (ey + 1)
    neq = 3 * nlayer * ez
    allocate(elem_ptr(nelem + 1), elem_eq(24 * nelem), eq_node(neq))
    e = 0
    do kk = 0, ez - 1
      do j = 0, ey - 1
        do i = 0, ex - 1
          e = e + 1
          elem_ptr(e) = 24 * (e - 1) + 1
          do a = 1, 8
            n = (i + di(a)) + (j + dj(a)) * (ex + 1) + (kk + dk(a) - 1) * nlayer + 1
            do d = 1, 3
              if (n <= 0) then
                elem_eq(24 * (e - 1) + 3 * (a - 1) + d) = 0
              else
                elem_eq(24 * (e - 1) + 3 * (a - 1) + d) = 3 * (n - 1) + d
                eq_node(3 * (n - 1) + d) = n
              end if
            end do
          end do
        end do
      end do
    end do
    elem_ptr(nelem + 1) = 24 * nelem + 1
  end subroutine make_mesh

  !> Random SPD element matrix (M^T M + I), from a per-element generator (thread-safe, reproducible);
  !> unsymmetric systems get an added random unsymmetric part.
  subroutine element_matrix(e, symmetric, ke)
    integer, intent(in) :: e
    logical, intent(in) :: symmetric
    real(dp), intent(out) :: ke(24, 24)
    real(dp) :: m(24, 24)
    integer(i8) :: seed
    integer :: i, j

    seed = 1000_i8 + 7919_i8 * e
    do j = 1, 24
      do i = 1, 24
        seed = mod(16807_i8 * seed, 2147483647_i8)
        m(i, j) = real(seed, dp) / 2147483647.0_dp - 0.5_dp
      end do
    end do
    ke = matmul(transpose(m), m)
    do i = 1, 24
      ke(i, i) = ke(i, i) + 1.0_dp
    end do
    if (.not. symmetric) ke = ke + 0.5_dp * m
  end subroutine element_matrix

  !> Least-squares slope of y against x.
  pure real(dp) function slope(x, y)
    real(dp), intent(in) :: x(:), y(:)
    real(dp) :: mx, my
    mx = sum(x) / size(x)
    my = sum(y) / size(y)
    slope = sum((x - mx) * (y - my)) / max(sum((x - mx)**2), tiny(1.0_dp))
  end function slope

end program bench_linalg
