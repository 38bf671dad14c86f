!> The columns of JOB.csv: one per (node set, variable) that a *NODE PRINT of any step requests, in the order of
!> first request, and their values at a converged increment (U: the set's mean, RF: its sum over prescribed dofs;
!> the variables and components of the output registry, host/output/output_registry.f90).
module history_columns
  use ldfcz_kinds, only: dp
  use model_types, only: model_t
  use output_registry, only: output_lookup, OV_RF
  use node_rotations, only: node_rotation_t, node_to_global
  implicit none
  private
  public :: history_columns_t, history_columns_build, history_columns_values

  integer, parameter :: column_name_len = 96  !< longest column name (SET.VARIABLE)

  !> The columns of the run's history CSV.
  type :: history_columns_t
    integer :: n = 0                                           !< columns
    character(len=column_name_len), allocatable :: names(:)    !< (n) SET.VARIABLE
    integer, allocatable :: set_index(:)                       !< (n) index into model%nsets
    integer, allocatable :: component(:)                       !< (n) 1..3 the dof of the variable
    logical, allocatable :: reaction(:)                        !< (n) RF (sum) rather than U (mean)
    logical, allocatable :: global(:)                          !< (n) *NODE PRINT, GLOBAL=YES at *TRANSFORM nodes
  end type history_columns_t

contains

  !> Every (set, variable) of the *NODE PRINT requests of the model (a request over every node has a JOB.dat table
  !> only).
  pure subroutine history_columns_build(model, cols)
    type(model_t), intent(in) :: model            !< the model
    type(history_columns_t), intent(out) :: cols  !< its columns
    integer :: is, i, j, k, var, comp
    character(len=column_name_len) :: name
    k = 0
    do is = 1, model%nstep
      do i = 1, model%steps(is)%nprint
        k = k + size(model%steps(is)%prints(i)%vars)
      end do
    end do
    allocate (cols%names(k), cols%set_index(k), cols%component(k), cols%reaction(k), cols%global(k))
    do is = 1, model%nstep
      do i = 1, model%steps(is)%nprint
        associate (pr => model%steps(is)%prints(i))
          if (pr%set_index == 0) cycle
          do j = 1, size(pr%vars)
            name = trim(pr%nset)//'.'//trim(pr%vars(j))
            ! GLOBAL=YES on a set with *TRANSFORM nodes: its own column, SET.VARIABLE.GLOBAL
            if (pr%global .and. transformed(model, pr%set_index)) name = trim(name)//'.GLOBAL'
            if (any(cols%names(1:cols%n) == name)) cycle
            cols%n = cols%n + 1
            cols%names(cols%n) = name
            cols%set_index(cols%n) = pr%set_index
            cols%global(cols%n) = pr%global .and. transformed(model, pr%set_index)
            ! the reader keeps the components of the registry's JOB.csv variables (U1..U3, RF1..RF3)
            call output_lookup(pr%vars(j), var, comp)
            cols%reaction(cols%n) = var == OV_RF
            cols%component(cols%n) = comp
          end do
        end associate
      end do
    end do
  end subroutine history_columns_build

  !> Node set iset holds a node with a *TRANSFORM.
  pure logical function transformed(model, iset)
    type(model_t), intent(in) :: model  !< the model
    integer, intent(in) :: iset         !< node set
    transformed = .false.
    if (allocated(model%node_transform)) transformed = any(model%node_transform(model%nsets(iset)%nodes) /= 0)
  end function transformed

  !> The columns' values: U the mean over the set's nodes, RF the sum of fint - fext - fdl over its prescribed dofs
  !> (a component beyond the model's dimension is 0); a GLOBAL=YES column in global components (nr).
  pure subroutine history_columns_values(cols, model, u, fint, fext, fdl, prescribed, values, nr)
    type(history_columns_t), intent(in) :: cols  !< the columns
    type(model_t), intent(in) :: model           !< the model
    real(dp), intent(in) :: u(:)                 !< (ndof) displacement
    real(dp), intent(in) :: fint(:)              !< (ndof) internal force
    real(dp), intent(in) :: fext(:)              !< (ndof) concentrated loads
    real(dp), intent(in) :: fdl(:)               !< (ndof) distributed-load forces
    logical, intent(in) :: prescribed(:)         !< (ndof) prescribed dofs
    real(dp), intent(out) :: values(:)           !< (n) the values
    type(node_rotation_t), intent(in) :: nr      !< the *TRANSFORM systems (GLOBAL=YES columns)
    integer :: ic, k, dof, nn, i, d
    real(dp) :: v, w(model%ndim)
    do ic = 1, cols%n
      v = 0.0_dp
      nn = size(model%nsets(cols%set_index(ic))%nodes)
      do k = 1, nn
        if (cols%component(ic) > model%ndim) cycle
        i = model%nsets(cols%set_index(ic))%nodes(k)
        if (cols%global(ic)) then
          ! the node's vector in system components, turned to global ones
          do d = 1, model%ndim
            dof = (i - 1) * model%ndim + d
            w(d) = u(dof)
            if (cols%reaction(ic)) w(d) = merge(fint(dof) - fext(dof) - fdl(dof), 0.0_dp, prescribed(dof))
          end do
          w = node_to_global(nr, i, w)
          v = v + w(cols%component(ic))
          cycle
        end if
        dof = (i - 1) * model%ndim + cols%component(ic)
        if (cols%reaction(ic)) then
          if (prescribed(dof)) v = v + fint(dof) - fext(dof) - fdl(dof)
        else
          v = v + u(dof)
        end if
      end do
      if (.not. cols%reaction(ic) .and. nn > 0) v = v / real(nn, dp)
      values(ic) = v
    end do
  end subroutine history_columns_values

end module history_columns
