!> *ELASTIC and *EXPANSION of a material as tables over temperature (Abaqus Keywords Guide, *ELASTIC and *EXPANSION;
!> Analysis User's Guide, "Linear elastic behavior", "Thermal expansion", "Material data definition"): each data
!> point is a group of data lines holding the constants in the guide's order, 8 values a line, then the
!> temperature; several points give temperature-dependent data (ascending temperatures), which the element
!> interpolates linearly and holds constant outside the range. Field-variable dependence is refused.
module deck_elastic
  use ldfcz_kinds, only: dp
  use deck_lines, only: deck_param_value, deck_has_param, deck_normalize
  use deck_lists, only: itoa
  use deck_context, only: deck_context_t, flen, ctx_fail, ctx_pos, ctx_allow_params, ctx_param_int, ctx_split, &
    ctx_get_real
  implicit none
  private
  public :: read_elastic, read_expansion

  !> *ELASTIC, TYPE= values read here, in the order of solid_elastic's law_* codes, their constants per data point
  !> and data lines per point (8 values a line, the temperature after the constants)
  character(len=24), parameter :: elastic_types(5) = [character(len=24) :: 'ISOTROPIC', 'ORTHOTROPIC', &
    'ENGINEERING CONSTANTS', 'LAMINA', 'ANISOTROPIC']
  integer, parameter :: elastic_ncons(5) = [2, 9, 9, 6, 21]
  !> *EXPANSION, TYPE= values (codes 1..3) and their coefficients per data point
  character(len=8), parameter :: expansion_types(3) = [character(len=8) :: 'ISO', 'ORTHO', 'ANISO']
  integer, parameter :: expansion_ncons(3) = [1, 3, 6]

contains

  !> *ELASTIC[, TYPE=ISOTROPIC | ORTHOTROPIC | ENGINEERING CONSTANTS | LAMINA | ANISOTROPIC]: one data point per
  !> temperature. The constants are checked (a positive definite stiffness) when the analysis is set up.
  subroutine read_elastic(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: kind, k
    if (ctx%imat == 0) then
      call ctx_fail(ctx, ctx%ir, 'material option outside a *MATERIAL definition')
      return
    end if
    call ctx_allow_params(ctx, [character(len=12) :: 'TYPE', 'DEPENDENCIES', 'MODULI'])
    if (ctx%stat /= 0) return
    call no_dependencies(ctx)
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'MODULI')) then
      call ctx_fail(ctx, ctx%ir, 'MODULI= (long-term or instantaneous moduli of a viscoelastic material) is not '// &
        'supported')
      return
    end if
    kind = type_code(ctx, elastic_types, 'ISOTROPIC, ORTHOTROPIC, ENGINEERING CONSTANTS, LAMINA, ANISOTROPIC')
    if (kind == 0) return
    associate (m => ctx%model%materials(ctx%imat))
      call read_table(ctx, elastic_ncons(kind), m%elastic_temp, m%elastic_data)
      if (ctx%stat /= 0) return
      m%has_elastic = .true.
      m%elastic_kind = kind
      m%elastic_pos = ctx_pos(ctx, ctx%ir)
      if (kind == 1) then
        ! the isotropic constants checked here, with the line of the point
        do k = 1, size(m%elastic_temp)
          if (.not. (m%elastic_data(1, k) > 0.0_dp .and. m%elastic_data(2, k) > -1.0_dp .and. &
              m%elastic_data(2, k) < 0.5_dp)) then
            call ctx_fail(ctx, ctx%ir + k, 'need E > 0 and -1 < nu < 0.5')
            return
          end if
        end do
        m%young = m%elastic_data(1, 1)
        m%poisson = m%elastic_data(2, 1)
      end if
    end associate
  end subroutine read_elastic

  !> *EXPANSION[, TYPE=ISO | ORTHO | ANISO][, ZERO=]: the coefficients per temperature (ZERO: the temperature the
  !> coefficients are measured from, 0 by default; without effect when they do not depend on temperature).
  subroutine read_expansion(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    integer :: kind
    real(dp) :: zero
    if (ctx%imat == 0) then
      call ctx_fail(ctx, ctx%ir, 'material option outside a *MATERIAL definition')
      return
    end if
    call ctx_allow_params(ctx, [character(len=12) :: 'TYPE', 'ZERO', 'DEPENDENCIES', 'USER', 'PORE FLUID'])
    if (ctx%stat /= 0) return
    call no_dependencies(ctx)
    if (ctx%stat /= 0) return
    if (deck_has_param(ctx%params, 'USER') .or. deck_has_param(ctx%params, 'PORE FLUID')) then
      call ctx_fail(ctx, ctx%ir, 'USER (subroutine UEXPAN) and PORE FLUID are not supported')
      return
    end if
    kind = type_code(ctx, expansion_types, 'ISO, ORTHO, ANISO')
    if (kind == 0) return
    zero = 0.0_dp
    if (deck_has_param(ctx%params, 'ZERO')) then
      if (.not. ctx_get_real(ctx, ctx%ir, deck_param_value(ctx%params, 'ZERO'), zero)) return
    end if
    associate (m => ctx%model%materials(ctx%imat))
      call read_table(ctx, expansion_ncons(kind), m%expansion_temp, m%expansion_data)
      if (ctx%stat /= 0) return
      m%has_expansion = .true.
      m%expansion_kind = kind
      m%expansion_zero = zero
      if (kind == 1) m%alpha = m%expansion_data(1, 1)
    end associate
  end subroutine read_expansion

  !> TYPE= of the block as its index in types (the first when TYPE= is absent: the keyword's default); 0 and an
  !> error naming the supported ones when it is not one of them.
  integer function type_code(ctx, types, supported) result(kind)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    character(len=*), intent(in) :: types(:)    !< supported values, the default first
    character(len=*), intent(in) :: supported   !< their list for the message
    character(len=:), allocatable :: v
    integer :: k
    v = trim(types(1))
    if (deck_has_param(ctx%params, 'TYPE')) v = deck_normalize(deck_param_value(ctx%params, 'TYPE'))
    kind = 0
    do k = 1, size(types)
      if (v == types(k)) kind = k
    end do
    if (kind == 0) call ctx_fail(ctx, ctx%ir, 'TYPE='//v//' is not supported ('//supported//')')
  end function type_code

  !> DEPENDENCIES=n > 0 (field-variable dependence) is refused.
  subroutine no_dependencies(ctx)
    type(deck_context_t), intent(inout) :: ctx  !< reader state
    if (ctx_param_int(ctx, 'DEPENDENCIES', 0) /= 0) call ctx_fail(ctx, ctx%ir, 'DEPENDENCIES= (field-variable '// &
      'dependence) is not supported')
  end subroutine no_dependencies

  !> The data points of the block: groups of ceiling((ncons + 1) / 8) lines, each the ncons constants (empty or
  !> omitted ones 0, as Abaqus takes omitted numeric data) then the temperature. One point: its temperature is not
  !> used; several: their temperatures must be given and ascend.
  subroutine read_table(ctx, ncons, temps, data)
    type(deck_context_t), intent(inout) :: ctx        !< reader state
    integer, intent(in) :: ncons                      !< constants per point
    real(dp), allocatable, intent(out) :: temps(:)    !< (npoint) temperatures
    real(dp), allocatable, intent(out) :: data(:, :)  !< (ncons, npoint) constants
    character(len=flen), allocatable :: f(:)
    integer :: lpp, nrec, np, ip, il, irec, n, k, pos
    logical :: has_temp
    lpp = (ncons + 1 + 7) / 8
    nrec = ctx%ir_next - ctx%ir - 1
    if (nrec == 0) then
      call ctx_fail(ctx, ctx%ir, 'data lines with the constants are required')
      return
    end if
    if (mod(nrec, lpp) /= 0) then
      call ctx_fail(ctx, ctx%ir_next - 1, 'each data point takes '//itoa(lpp)//' lines ('//itoa(ncons)// &
        ' constants, 8 a line, then the temperature): '//itoa(nrec)//' lines given')
      return
    end if
    np = nrec / lpp
    allocate (temps(np), data(ncons, np))
    temps = 0.0_dp
    data = 0.0_dp
    do ip = 1, np
      has_temp = .false.
      pos = 0
      do il = 1, lpp
        irec = ctx%ir + (ip - 1) * lpp + il
        call ctx_split(ctx, irec, f, n)
        if (n > 8) then
          call ctx_fail(ctx, irec, 'at most 8 values a line')
          return
        end if
        do k = 1, n
          pos = pos + 1
          if (len_trim(f(k)) == 0) cycle
          if (pos <= ncons) then
            if (.not. ctx_get_real(ctx, irec, f(k), data(pos, ip))) return
          else if (pos == ncons + 1) then
            if (.not. ctx_get_real(ctx, irec, f(k), temps(ip))) return
            has_temp = .true.
          else
            call ctx_fail(ctx, irec, 'a value after the temperature (field-variable dependence) is not supported')
            return
          end if
        end do
        ! a line that is not the point's last holds 8 values (the next values start on the next line)
        if (il < lpp) pos = il * 8
      end do
      if (np > 1 .and. .not. has_temp) then
        call ctx_fail(ctx, irec, 'temperature-dependent data: give the temperature of every data point')
        return
      end if
      if (ip > 1) then
        if (.not. (temps(ip) > temps(ip - 1))) then
          call ctx_fail(ctx, irec, 'the temperatures of the data points must ascend')
          return
        end if
      end if
    end do
  end subroutine read_table

end module deck_elastic
