!> The data types of the continuum element (solid_element): a section's material and an element's reference
!> data, shared by the generic path (solid_element.f90) and the fixed-size kernels (solid_c3d8.f90).
module solid_types
  use ldfcz_kinds, only: dp
  use solid_umat_interface, only: umat_interface
  use solid_elastic, only: elastic_law_t
  implicit none
  private
  public :: solid_material_t, solid_geometry_t, nprops_of, umat_props_pad
  public :: SOLID_MAT_ELASTIC, SOLID_MAT_UMAT, SOLID_PNEWDT_LARGE

  !> Zeros the PROPS array a UMAT gets carries after its NPROPS values: a routine that reads PROPS past NPROPS
  !> (a deck with CONSTANTS smaller than the routine's count) reads 0 every time, not whatever memory follows
  integer, parameter :: umat_props_pad = 16
  integer, parameter :: SOLID_MAT_ELASTIC = 1    !< built-in *ELASTIC (isotropic, hypoelastic under NLGEOM)
  integer, parameter :: SOLID_MAT_UMAT = 2       !< Abaqus UMAT through a procedure pointer
  real(dp), parameter :: SOLID_PNEWDT_LARGE = 1.0e36_dp  !< PNEWDT handed to each UMAT call ("a large value")

  !> Material (and section) data of an element set.
  type :: solid_material_t
    integer :: kind = SOLID_MAT_ELASTIC                 !< SOLID_MAT_ELASTIC or SOLID_MAT_UMAT
    real(dp) :: e = 0.0_dp                              !< *ELASTIC Young's modulus (MPa)
    real(dp) :: nu = 0.0_dp                             !< *ELASTIC Poisson's ratio
    real(dp), allocatable :: props(:)                   !< *USER MATERIAL constants (PROPS)
    integer :: nstatv = 0                               !< *DEPVAR count (NSTATV)
    character(len=80) :: cmname = ' '                   !< material name as passed in CMNAME (upper case in Abaqus)
    logical :: unsymm = .false.                         !< *USER MATERIAL, UNSYMM: keep the unsymmetric tangent
    real(dp) :: thickness = 1.0_dp                      !< *SOLID SECTION thickness of plane elements (CPE4)
    real(dp) :: alpha = 0.0_dp                          !< *EXPANSION isotropic coefficient (thermal strain alpha dT)
    type(elastic_law_t) :: law                          !< law%general: *ELASTIC/*EXPANSION other than constant
                                                        !< isotropic (then used instead of e, nu, alpha)
    procedure(umat_interface), pointer, nopass :: umat => null()  !< the UMAT to call when kind = SOLID_MAT_UMAT
  end type solid_material_t

  !> Reference-configuration data of one element, the same on every call (original coordinates): shape functions,
  !> dN/dX and Gauss weight x det(dX/dxi) at the integration points, dN/dX at the centre and its volume mean. Rows
  !> nnode+1..nnode+nmode of dndx_ref are the incompatible modes' reference gradients (C3D8I, CPE4I). Sized to the
  !> element. A host may compute it once per element (solid_element_geometry) and pass it to solid_element_compute
  !> instead of the per-call recomputation.
  type :: solid_geometry_t
    logical :: valid = .false.                 !< computed, every reference Jacobian > 0
    real(dp), allocatable :: nfun(:, :)        !< (nnode+nmode, nip) N_a at the integration points (0 for modes)
    real(dp), allocatable :: dndx_ref(:, :, :) !< (nnode+nmode, 3, nip) dN_a/dX_j at the integration points
    real(dp), allocatable :: wdet(:)           !< (nip) Gauss weight x det(dX/dxi)
    real(dp), allocatable :: dndx_0c(:, :)     !< (nnode+nmode, 3) dN_a/dX_j at the element centre
    real(dp), allocatable :: dndx_0m(:, :)     !< (nnode+nmode, 3) volume mean of dN_a/dX_j (B-bar, small strain)
    real(dp), allocatable :: gamma(:, :)       !< (nnode, nhg) Flanagan-Belytschko hourglass vectors (one-point types)
    real(dp), allocatable :: hoop(:, :)        !< (nnode+nmode, nip) N_a / R at the points (axisymmetric types)
    real(dp), allocatable :: hoop_0c(:)        !< (nnode+nmode) N_a / R at the element centre (axisymmetric)
    real(dp), allocatable :: hoop_0m(:)        !< (nnode+nmode) volume mean of N_a / R (axisymmetric B-bar)
    integer :: nhg = 0                         !< hourglass vectors (0: none)
    real(dp) :: hg_vsum = 0.0_dp               !< reference volume x sum_(a,j) (dN_a/dX_j)^2 at the point
    !> (nnode, 4) one-point axisymmetric types: sqrt(w_q) (N_a/R - <N_a/R>) at the 2x2 points q, w_q = 2 pi R_q x
    !> Gauss weight x det: sum_q (hoop_fl(:, q) . u_r)^2 = int (hoop strain - its element mean)^2 dV
    real(dp), allocatable :: hoop_fl(:, :)
  end type solid_geometry_t

contains

  !> Number of PROPS of a material (0 when none were given).
  pure integer function nprops_of(mat)
    type(solid_material_t), intent(in) :: mat
    nprops_of = 0
    if (allocated(mat%props)) nprops_of = size(mat%props)
  end function nprops_of

end module solid_types
