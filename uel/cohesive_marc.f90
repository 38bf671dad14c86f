!> MSC.Marc translation layer of the LDF cohesive element: what USELEM needs, host-free and testable. The USELEM
!> entry point (uel/uselem.f) only fetches Marc's update flag and time increment, hands the calls it does not
!> compute back to Marc and stops on an error; this layer unpacks Marc's arrays, calls the same core as the Abaqus
!> UEL (cohesive_input_read, cohesive_element_compute) and packs the stiffness and the internal force in Marc's
!> node-major order. What rests on Marc's documentation and what is inferred: docs/uel.md, "MSC.Marc: USELEM".
!>
!> Inferred, NOT verified in Marc (docs/uel.md lists the evidence for each):
!> * the current total displacement is dispt + disp (dispt total at t_n, disp the increment since t_n);
!> * with the updated Lagrange flag (iupdat = 1) coord holds the positions at t_n, so the reference positions are
!>   coord - dispt; otherwise coord is the reference configuration;
!> * r is the element's internal force f_int (the same sign as xk = dr/du), the opposite of the UEL's RHS;
!> * t(1, ip) is the temperature, t(2:5, ip) the element's history, entering at t_n and left at t_n+1 (as Marc
!>   documents the state variables of HYPELA2).
module cohesive_marc
  use ldfcz_kinds, only: dp
  use cohesive_law, only: cohesive_props
  use cohesive_input, only: cohesive_section, cohesive_input_read, input_ok
  use cohesive_element, only: cohesive_element_compute, nsv_per_ip, element_nip, stat_ok, &
                              stat_bad_input
  implicit none
  private
  public :: cohesive_marc_element, cohesive_marc_kind

  integer, parameter, public :: marc_ok = 0           !< xk, r and t computed
  integer, parameter, public :: marc_bad_input = 1    !< sizes or properties unusable (errmsg says why)
  integer, parameter, public :: marc_bad_state = 2    !< displacements not finite or the element collapsed
  !> Marc state variables per integration point this element needs: the temperature and the 4 history values.
  integer, parameter, public :: marc_nstats = 1 + nsv_per_ip

contains

  !> Element kind from Marc's sizes: 3 (8 nodes, >= 3 coordinates and dofs), 2 (4 nodes, >= 2), 0 unsupported.
  pure integer function cohesive_marc_kind(nnode, ncrd, ndeg) result(ndim)
    integer, intent(in) :: nnode  !< nodes per element
    integer, intent(in) :: ncrd   !< coordinates per node
    integer, intent(in) :: ndeg   !< degrees of freedom per node
    ndim = 0
    if (nnode == 8 .and. ncrd >= 3 .and. ndeg >= 3) ndim = 3
    if (nnode == 4 .and. ncrd >= 2 .and. ndeg >= 2) ndim = 2
  end function cohesive_marc_kind

  !> One stiffness / internal-force call of USELEM. props, jprops: the UEL's property layout (docs/uel.md).
  !> On marc_ok: xk (idss x idss, node-major with ndeg dofs per node, extra dofs zero), r (ndeg x nnode) and
  !> t(2:5, 1:nip) are written; otherwise nothing is.
  pure subroutine cohesive_marc_element(props, jprops, coord, dispt, disp, updated_lagrange, timinc, t, xk, r, &
                                        stat, errmsg)
    real(dp), intent(in) :: props(:)              !< real properties, UEL layout
    integer, intent(in) :: jprops(:)              !< integer properties, UEL layout
    real(dp), intent(in) :: coord(:,:)            !< (ncrd, nnode) nodal coordinates as Marc passes them
    real(dp), intent(in) :: dispt(:,:)            !< (ndeg, nnode) total displacements at t_n
    real(dp), intent(in) :: disp(:,:)             !< (ndeg, nnode) displacement increments since t_n
    logical, intent(in) :: updated_lagrange       !< Marc's iupdat = 1: coord are the positions at t_n
    real(dp), intent(in) :: timinc                !< time increment (viscous regularisation only)
    real(dp), intent(inout) :: t(:,:)             !< (nstats, intel) state variables
    real(dp), intent(inout) :: xk(:,:)            !< (idss, idss) element stiffness dr/du
    real(dp), intent(inout) :: r(:,:)             !< (ndeg, nnode) element internal force
    integer, intent(out) :: stat                  !< marc_ok, marc_bad_input or marc_bad_state
    character(len=*), intent(out) :: errmsg       !< reason when stat /= marc_ok
    type(cohesive_props) :: pr
    type(cohesive_section) :: sec
    real(dp), allocatable :: x0(:,:), u(:), ustart(:), fint(:), kmat(:,:), hold(:), hnew(:)
    real(dp) :: esto, edis, evis, eds0
    integer :: ndim, nnode, ndeg, nip, ist

    ndim = cohesive_marc_kind(size(coord, 2), size(coord, 1), size(dispt, 1))
    nnode = size(coord, 2)
    ndeg = size(dispt, 1)
    call check_sizes(ndim, coord, dispt, disp, t, xk, r, stat, errmsg)
    if (stat /= marc_ok) return
    call cohesive_input_read(ndim, props, jprops, pr, sec, ist, errmsg)
    if (ist /= input_ok) then
      stat = marc_bad_input
      return
    end if
    nip = element_nip(ndim)
    x0 = coord(1:ndim, :)
    if (updated_lagrange) x0 = x0 - dispt(1:ndim, :)
    ustart = reshape(dispt(1:ndim, :), [ndim * nnode])
    u = ustart + reshape(disp(1:ndim, :), [ndim * nnode])
    hold = reshape(t(2:marc_nstats, 1:nip), [nsv_per_ip * nip])
    allocate (fint(ndim * nnode), kmat(ndim * nnode, ndim * nnode), hnew(size(hold)))
    call cohesive_element_compute(ndim, x0, u, pr, hold, .true., fint, kmat, hnew, esto, edis, ist, errmsg, &
                                  u_start=ustart, dtime=timinc, e_visc=evis, e_diss_start=eds0, &
                                  thickness=sec%thickness, axisymmetric=sec%axisymmetric)
    if (ist /= stat_ok) then
      stat = merge(marc_bad_input, marc_bad_state, ist == stat_bad_input)
      return
    end if
    call scatter(ndim, ndeg, fint, kmat, xk, r)
    t(2:marc_nstats, 1:nip) = reshape(hnew, [nsv_per_ip, nip])
    stat = marc_ok
  end subroutine cohesive_marc_element

  !> Marc's sizes against the element kind: nodes, coordinates and dofs, idss, state variables, points.
  pure subroutine check_sizes(ndim, coord, dispt, disp, t, xk, r, stat, errmsg)
    integer, intent(in) :: ndim
    real(dp), intent(in) :: coord(:,:), dispt(:,:), disp(:,:), t(:,:), xk(:,:), r(:,:)
    integer, intent(out) :: stat
    character(len=*), intent(out) :: errmsg
    integer :: nnode, ndeg

    stat = marc_bad_input
    errmsg = ''
    nnode = size(coord, 2)
    ndeg = size(dispt, 1)
    if (ndim == 0) then
      write (errmsg, '(a,i0,a,i0,a,i0,a)') 'unsupported element nnode=', nnode, ' ncrd=', size(coord, 1), ' ndeg=', &
        ndeg, '; need 8 nodes with 3 coordinates and dofs (3D) or 4 nodes with 2 (plane)'
    else if (any(shape(disp) /= shape(dispt)) .or. size(dispt, 2) /= nnode .or. any(shape(r) /= shape(dispt))) then
      errmsg = 'disp, dispt and r must all be (ndeg, nnode)'
    else if (size(xk, 1) < ndeg * nnode .or. size(xk, 2) < ndeg * nnode) then
      write (errmsg, '(a,i0,a,i0)') 'idss=', size(xk, 1), ' smaller than ndeg*nnode=', ndeg * nnode
    else if (size(t, 1) < marc_nstats) then
      write (errmsg, '(a,i0,a,i0,a)') 'nstats=', size(t, 1), ' state variables per point; need ', marc_nstats, &
        ' (the temperature and 4 history values): STATE VARS >= 5'
    else if (size(t, 2) < element_nip(ndim)) then
      write (errmsg, '(a,i0,a,i0)') 'intel=', size(t, 2), ' integration points; the element needs ', &
        element_nip(ndim)
    else if (.not. all(abs(coord(1:ndim, :)) <= huge(1.0_dp))) then
      errmsg = 'coord not finite'
    else
      stat = marc_ok
    end if
  end subroutine check_sizes

  !> Core order (node-major, ndim dofs per node) to Marc's (node-major, ndeg dofs per node; extra dofs zero).
  pure subroutine scatter(ndim, ndeg, fint, kmat, xk, r)
    integer, intent(in) :: ndim, ndeg
    real(dp), intent(in) :: fint(:), kmat(:,:)
    real(dp), intent(inout) :: xk(:,:), r(:,:)
    integer :: a, b, na, nb, nnode

    nnode = size(r, 2)
    r = 0.0_dp
    xk(1:ndeg * nnode, 1:ndeg * nnode) = 0.0_dp
    do na = 1, nnode
      r(1:ndim, na) = fint(ndim * (na - 1) + 1:ndim * na)
      do nb = 1, nnode
        do b = 1, ndim
          do a = 1, ndim
            xk(ndeg * (na - 1) + a, ndeg * (nb - 1) + b) = kmat(ndim * (na - 1) + a, ndim * (nb - 1) + b)
          end do
        end do
      end do
    end do
  end subroutine scatter

end module cohesive_marc
