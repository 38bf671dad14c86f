/* Thread count of the BLAS under MUMPS, set at run time when the linked BLAS is OpenBLAS.
 *
 * openblas_set_num_threads is referenced weakly: with another BLAS (reference BLAS, BLIS, MKL through the
 * Debian alternatives) the symbol is absent, the function pointer is null and nothing happens. The host uses it
 * to keep OpenBLAS's worker threads from spinning on the cores of the OpenMP element loop (docs/performance.md,
 * "BLAS threads"). */
extern void openblas_set_num_threads(int) __attribute__((weak));

/* Returns 1 when the thread count was set (OpenBLAS present), 0 otherwise. */
int ldfcz_blas_set_threads(int n)
{
    if (openblas_set_num_threads) {
        openblas_set_num_threads(n);
        return 1;
    }
    return 0;
}
