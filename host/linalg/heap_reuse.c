/* Reuse of freed large blocks (glibc only).
 *
 * glibc serves an allocation above its mmap threshold (adjusted at run time, at most 32 MB on 64-bit systems) with
 * a fresh mmap() and gives it back to the kernel on free(). MUMPS allocates its factorization workspace, and GMRES
 * its Krylov basis, anew in every Newton iteration, so the kernel mapped and cleared those pages again each time
 * (page faults in the serial part of the iteration). With mmap() off for allocations (M_MMAP_MAX = 0) and a trim
 * threshold of 1 GiB, freed blocks stay in the heap and the next allocation reuses them (docs/performance.md,
 * fifth pass). Elsewhere than glibc nothing happens. */
#include <stdlib.h> /* defines __GLIBC__ with glibc */
#ifdef __GLIBC__
#include <malloc.h>
#endif

/* Returns 1 when glibc accepted both settings, 0 otherwise. */
int ldfcz_heap_reuse(void)
{
#ifdef __GLIBC__
    if (mallopt(M_MMAP_MAX, 0) == 1 && mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1) return 1;
#endif
    return 0;
}
