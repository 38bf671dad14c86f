!> Tangent kernels of the C3D8 element (solid_element.f90, solid_c3d8.f90): the contribution of one integration
!> point to the element matrix, K_(a i)(b k) += int [dN_a/dx_j A_ijkl dN_b/dx_l + dN_a/dx_j q_ij (dN_b/dx_k|centre
!> - dN_b/dx_k)] dv (solid_tangent_kernel.inc). One source built three times (host/elements/CMakeLists.txt): for
!> the build's baseline instruction set, for AVX2 and for AVX-512 (gfortran on x86-64; elsewhere the three are the
!> same code), each at -O3 without fused multiply-add; tangent_kernel_level says which one this CPU runs, and the
!> callers pass it. The three give the same bits (no operation differs, only the vector width), so a run gives the
!> same results on every CPU that runs the same build; AVX-512 computes a C3D8 tangent about 4x faster than the
!> baseline SSE2 (reports/bench/kernel/README.md).
module solid_tangent_kernel
  use, intrinsic :: iso_c_binding, only: c_int
  use ldfcz_kinds, only: dp
  use solid_tangent_kernel_base, only: k_base => k_point_c3d8, ks_base => k_point_c3d8_spatial
  use solid_tangent_kernel_avx2, only: k_avx2 => k_point_c3d8, ks_avx2 => k_point_c3d8_spatial
  use solid_tangent_kernel_avx512, only: k_avx512 => k_point_c3d8, ks_avx512 => k_point_c3d8_spatial
  implicit none
  private
  public :: tangent_kernel_level, k_point_c3d8, k_point_c3d8_spatial
  public :: KERNEL_LEVEL_BASE, KERNEL_LEVEL_AVX2, KERNEL_LEVEL_AVX512

  !> the kernels' builds: baseline, AVX2, AVX-512
  integer, parameter :: KERNEL_LEVEL_BASE = 0, KERNEL_LEVEL_AVX2 = 1, KERNEL_LEVEL_AVX512 = 2

  interface
    !> host/elements/cpu_vector_level.c: the widest kernel build this CPU runs (a KERNEL_LEVEL_*)
    pure function cpu_vector_level() bind(c, name='ldfcz_cpu_vector_level') result(level)
      import :: c_int
      integer(c_int) :: level
    end function cpu_vector_level
  end interface

contains

  !> The kernel build for this CPU (KERNEL_LEVEL_*): AVX-512 or AVX2 where the CPU and the operating system support
  !> them and the build has them, the baseline otherwise.
  pure integer function tangent_kernel_level()
    tangent_kernel_level = int(cpu_vector_level())
  end function tangent_kernel_level

  !> One point's tangent contribution with the small-strain row term (solid_tangent_kernel.inc), by the build of
  !> the given level (KERNEL_LEVEL_*; from tangent_kernel_level, or lower).
  pure subroutine k_point_c3d8(level, a4, q, dndx, bc, bcr, dv, kl)
    integer, intent(in) :: level                 !< KERNEL_LEVEL_*
    real(dp), intent(in) :: a4(3, 3, 3, 3), q(3, 3), dndx(8, 3), bc(8, 3), bcr(8, 3), dv
    real(dp), intent(inout) :: kl(8, 3, 3, 8)    !< kl(a, i, k, b)
    select case (level)
    case (KERNEL_LEVEL_AVX512)
      call k_avx512(a4, q, dndx, bc, bcr, dv, kl)
    case (KERNEL_LEVEL_AVX2)
      call k_avx2(a4, q, dndx, bc, bcr, dv, kl)
    case default
      call k_base(a4, q, dndx, bc, bcr, dv, kl)
    end select
  end subroutine k_point_c3d8

  !> One point's tangent contribution under NLGEOM (no row term; solid_tangent_kernel.inc), by the build of the given
  !> level.
  pure subroutine k_point_c3d8_spatial(level, a4, q, dndx, bc, dv, kl)
    integer, intent(in) :: level                 !< KERNEL_LEVEL_*
    real(dp), intent(in) :: a4(3, 3, 3, 3), q(3, 3), dndx(8, 3), bc(8, 3), dv
    real(dp), intent(inout) :: kl(8, 3, 3, 8)    !< kl(a, i, k, b)
    select case (level)
    case (KERNEL_LEVEL_AVX512)
      call ks_avx512(a4, q, dndx, bc, dv, kl)
    case (KERNEL_LEVEL_AVX2)
      call ks_avx2(a4, q, dndx, bc, dv, kl)
    case default
      call ks_base(a4, q, dndx, bc, dv, kl)
    end select
  end subroutine k_point_c3d8_spatial

end module solid_tangent_kernel
