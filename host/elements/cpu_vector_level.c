/* The widest build of the C3D8 tangent kernels that this CPU runs (host/elements/solid_tangent_kernel.f90):
 * 2 AVX-512 (AVX512F), 1 AVX2, 0 the baseline. libgcc's feature test also checks that the operating system saves
 * the vector registers (XGETBV). LDFCZ_VECTOR_KERNELS is defined where the build compiled the wider kernels
 * (gfortran on x86-64, host/elements/CMakeLists.txt); elsewhere every level is the baseline. No state: the CPU
 * model is read on every call (a few loads). */
int ldfcz_cpu_vector_level(void)
{
#if defined(LDFCZ_VECTOR_KERNELS) && (defined(__x86_64__) || defined(__i386__))
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f"))
        return 2;
    if (__builtin_cpu_supports("avx2"))
        return 1;
#endif
    return 0;
}
