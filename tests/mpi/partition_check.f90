!> Partition test of the distributed assembly (run under mpirun -np N; tests/mpi.cmake): the deck's elements are
!> partitioned over the processes (analysis_core, METIS on the element graph) and
!>   1. every element is owned by exactly one process (the ownership flags summed over the processes are all 1);
!>   2. with N > 1 and more elements than processes, no process owns every element (the partition distributes);
!>      with PIECES > 1 the processes' elements form more than N connected pieces in all (the interleaving took
!>      effect: two elements are connected when they share a node);
!>   3. at a non-trivial displacement (u_i = a sin(i), a = 1e-3 of the model size: finite strains in every element,
!>      cohesive openings below the critical one) the assembled internal force of the distributed element loop
!>      (each process its own elements, summed over the processes) and its tangent (each process's part of the
!>      sparse matrix, summed over the processes) equal those of one process assembling every element, to
!>      1e-12 of the largest entry: the two differ only in the order of the floating-point additions (a few ulp
!>      per entry), while an element missing or a shared-node contribution summed twice would change entries by
!>      their full size;
!>   4. the product of that tangent with a vector (v_i = cos i) computed distributed (sparse_matvec: each process
!>      over the entries its elements touch, summed over the processes) equals the serial product to 1e-12 of its
!>      largest entry (again only the order of the additions differs).
!> Usage: partition_check DECK [PIECES] (pieces per process of the interleaved partition, as ldfcz
!> --partition-pieces; default: ldfcz's default rule, one piece per process on these small decks).
!> Exit 0 when all hold, 1 otherwise (the failures are printed by rank 0).
program partition_check
  use ldfcz_kinds, only: dp
  use model_types, only: model_t
  use deck_reader, only: read_deck
  use analysis_core, only: analysis_t, analysis_init, analysis_number_equations, analysis_assemble
  use increment, only: increment_t
  use solver_options, only: solver_options_t
  use user_routines, only: user_routines_t, user_routines_builtin
  use sparse_system, only: sparse_to_dense, sparse_matvec
  use parallel_context, only: parallel_t, parallel_init, parallel_finalize, parallel_sum, parallel_writer
  implicit none
  type(parallel_t) :: par
  type(model_t) :: model
  type(user_routines_t) :: routines
  type(analysis_t) :: dist, ser
  type(increment_t) :: inc         ! step 1, increment 1 at time 0 of a step of period 1, dt 0.1, NLGEOM
  type(solver_options_t) :: opt
  character(len=512) :: deck, arg
  character(len=:), allocatable :: errmsg
  real(dp), allocatable :: own(:), kd(:, :), ks(:, :), flat(:), v(:), yd(:), ys(:)
  real(dp) :: pn, size_model, err_f, err_k, fmax, kmax, err_y, ncomp(1)
  integer :: stat, i, nfail, nown, pieces
  logical :: ok

  call parallel_init(par)
  nfail = 0
  call get_command_argument(1, deck)
  pieces = 0                            ! ldfcz's default rule
  if (command_argument_count() >= 2) then
    call get_command_argument(2, arg)
    read (arg, *, iostat=stat) pieces
    call check(stat == 0 .and. pieces >= 1, 'PIECES must be an integer >= 1')
  end if
  call read_deck(trim(deck), model, stat, errmsg)
  call check(stat == 0, 'deck read: '//errmsg)
  call user_routines_builtin(routines)
  dist%par = par
  opt%partition_pieces = pieces
  inc = increment_t(step=1, kinc=1, dt=0.1_dp, period=1.0_dp, nlgeom=.true.)
  call analysis_init(dist, model, routines, stat, errmsg, opt)
  call check(stat == 0, 'distributed analysis_init: '//errmsg)
  call analysis_init(ser, model, routines, stat, errmsg)   ! one process's view: every element
  call check(stat == 0, 'serial analysis_init: '//errmsg)

  ! 1., 2.: ownership
  own = merge(1.0_dp, 0.0_dp, dist%owned)
  call parallel_sum(par, own)
  call check(all(own == 1.0_dp), 'an element is owned by no process or by several')
  nown = count(dist%owned)
  if (par%nranks > 1 .and. model%nelem >= par%nranks) &
    call check(nown < model%nelem, 'one process owns every element: nothing distributed')
  ncomp(1) = real(owned_components(), dp)
  call parallel_sum(par, ncomp)
  if (pieces > 1 .and. par%nranks > 1) &
    call check(ncomp(1) > real(par%nranks, dp), 'interleaved partition: each process holds one connected part')

  ! 3.: forces and tangents at a deformed state, the dofs of the first node prescribed
  size_model = maxval(model%x(1:model%ndim, 1:model%nnode)) - minval(model%x(1:model%ndim, 1:model%nnode))
  call prepare(dist)
  call prepare(ser)
  call analysis_assemble(dist, model, inc, .true., pn, stat, errmsg)
  call check(stat == 0, 'distributed assembly: '//errmsg)
  call analysis_assemble(ser, model, inc, .true., pn, stat, errmsg)
  call check(stat == 0, 'serial assembly: '//errmsg)
  fmax = maxval(abs(ser%work%fint))
  err_f = maxval(abs(dist%work%fint - ser%work%fint)) / max(fmax, tiny(1.0_dp))
  allocate (kd(dist%eqs%neq, dist%eqs%neq), ks(ser%eqs%neq, ser%eqs%neq))
  call sparse_to_dense(dist%eqs%sys, kd)
  call sparse_to_dense(ser%eqs%sys, ks)
  flat = reshape(kd, [size(kd)])
  call parallel_sum(par, flat)          ! the processes' parts of the matrix
  kd = reshape(flat, shape(kd))
  kmax = maxval(abs(ks))
  err_k = maxval(abs(kd - ks)) / max(kmax, tiny(1.0_dp))
  call check(fmax > 0.0_dp .and. kmax > 0.0_dp, 'trivial state: zero forces or tangent')
  call check(err_f <= 1.0e-12_dp, 'distributed internal force differs from the serial one')
  call check(err_k <= 1.0e-12_dp, 'distributed tangent differs from the serial one')

  ! 4.: products with the tangent
  allocate (v(ser%eqs%neq), yd(ser%eqs%neq), ys(ser%eqs%neq))
  v = [(cos(real(i, dp)), i = 1, ser%eqs%neq)]
  call sparse_matvec(dist%eqs%sys, v, yd)
  call sparse_matvec(ser%eqs%sys, v, ys)
  err_y = maxval(abs(yd - ys)) / max(maxval(abs(ys)), tiny(1.0_dp))
  call check(maxval(abs(ys)) > 0.0_dp, 'trivial product')
  call check(err_y <= 1.0e-12_dp, 'distributed product differs from the serial one')
  if (parallel_writer(par)) then
    print '(a,i0,a,i0,a,i0,a,i0,a)', 'partition_check: ', par%nranks, ' processes, ', model%nelem, &
      ' elements (', nown, ' on rank 0), ', dist%eqs%neq, ' equations'
    print '(a,i0,a,i0,a)', 'partition_check: ', pieces, ' pieces per process asked (0: default), ', &
      nint(ncomp(1)), ' connected pieces in all'
    print '(a,es10.2,a,es10.2,a,es10.2,a)', 'partition_check: force difference ', err_f, ', tangent difference ', &
      err_k, ', product difference ', err_y, ' (of the largest entry)'
    if (nfail == 0) print '(a)', 'PASS'
  end if
  ok = nfail == 0
  call parallel_finalize(par)
  if (.not. ok) error stop 1

contains

  !> Connected pieces of this process's elements (union-find over the elements that share a node).
  integer function owned_components() result(nc)
    integer, allocatable :: root(:), first(:)
    integer :: e, k, n, a, b
    allocate (root(model%nelem), first(model%nnode))
    root = [(e, e = 1, model%nelem)]
    first = 0
    do e = 1, model%nelem
      if (.not. dist%owned(e)) cycle
      do k = model%conn_ptr(e), model%conn_ptr(e + 1) - 1
        n = model%conn(k)
        if (first(n) == 0) then
          first(n) = e
        else
          a = find_root(root, first(n))
          b = find_root(root, e)
          if (a /= b) root(max(a, b)) = min(a, b)
        end if
      end do
    end do
    nc = 0
    do e = 1, model%nelem
      if (dist%owned(e) .and. find_root(root, e) == e) nc = nc + 1
    end do
  end function owned_components

  !> Root of element x in the union-find forest root.
  pure integer function find_root(root, x) result(r)
    integer, intent(in) :: root(:)  !< parent of each element
    integer, intent(in) :: x        !< element
    r = x
    do while (root(r) /= r)
      r = root(r)
    end do
  end function find_root

  subroutine prepare(an)
    type(analysis_t), intent(inout) :: an
    an%eqs%prescribed = .false.
    an%eqs%prescribed(1:model%ndim) = .true.
    call analysis_number_equations(an, model, stat, errmsg)
    call check(stat == 0, 'equations: '//errmsg)
    do i = 1, an%ndof
      an%work%u(i) = 1.0e-3_dp * size_model * sin(real(i, dp))
    end do
    an%work%u(1:model%ndim) = 0.0_dp
    an%state%u_conv = 0.0_dp
  end subroutine prepare

  subroutine check(cond, what)
    logical, intent(in) :: cond
    character(len=*), intent(in) :: what
    if (cond) return
    nfail = nfail + 1
    if (parallel_writer(par)) print '(a)', 'FAIL: '//what
  end subroutine check

end program partition_check
