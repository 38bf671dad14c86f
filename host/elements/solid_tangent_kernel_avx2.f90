!> The C3D8 tangent kernels (solid_tangent_kernel.inc) compiled for AVX2 (host/elements/CMakeLists.txt): the same
!> results to the bit as the baseline build of module solid_tangent_kernel, which calls them on a CPU that has
!> AVX2.
module solid_tangent_kernel_avx2
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: k_point_c3d8, k_point_c3d8_spatial

contains

  include 'solid_tangent_kernel.inc'

end module solid_tangent_kernel_avx2
