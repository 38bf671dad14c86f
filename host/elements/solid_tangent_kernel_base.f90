!> The C3D8 tangent kernels (solid_tangent_kernel.inc) compiled for the baseline instruction set of the build; the
!> module solid_tangent_kernel calls them where the CPU has no wider vectors than the build's baseline.
module solid_tangent_kernel_base
  use ldfcz_kinds, only: dp
  implicit none
  private
  public :: k_point_c3d8, k_point_c3d8_spatial

contains

  include 'solid_tangent_kernel.inc'

end module solid_tangent_kernel_base
