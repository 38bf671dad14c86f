/* ldfcz_heap_reuse (host/linalg/heap_reuse.c): after it, a freed 64 MiB block (above glibc's largest mmap
 * threshold, 32 MiB) is reused by the next allocation of that size without new page faults. Without it glibc maps
 * a fresh block, and writing it faults on each of its 16384 pages; the bound, 1024, separates the two by a factor
 * 16. Not glibc: skipped (exit 77). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

int ldfcz_heap_reuse(void);

static long minor_faults(void)
{
    struct rusage r;
    getrusage(RUSAGE_SELF, &r);
    return r.ru_minflt;
}

static volatile char sink;
/* called through a volatile pointer: the compiler may not drop the writes to a block that is freed next */
static void *(*volatile fill)(void *, int, size_t) = memset;

static void touch_block(size_t n, int value)
{
    char *a = malloc(n);
    if (!a) {
        printf("allocation of %zu bytes failed\n", n);
        exit(1);
    }
    fill(a, value, n);
    sink = a[n - 1];
    free(a);
}

int main(void)
{
    const size_t n = (size_t)64 << 20;
    long f0, f1;
    if (!ldfcz_heap_reuse()) {
        printf("not glibc: skipped\n");
        return 77;
    }
    touch_block(n, 1);
    f0 = minor_faults();
    touch_block(n, 2);
    f1 = minor_faults();
    printf("page faults writing a second 64 MiB block: %ld (a fresh block: %zu)\n", f1 - f0, n / 4096);
    return f1 - f0 < (long)(n / 4096 / 16) ? 0 : 1;
}
