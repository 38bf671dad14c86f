/* Which kernels OpenBLAS runs, and a restart with better ones when it took this CPU for an old one.
 *
 * OpenBLAS built for many CPUs (Debian's libopenblas0, DYNAMIC_ARCH) chooses its kernels once, when the library is
 * loaded, from the CPU's family and model numbers. A model it does not know (Debian 12 ships OpenBLAS 0.3.21; newer
 * Xeons, and many virtual machines that report a generic "Intel Xeon Processor") gets the generic Prescott (SSE3)
 * kernels, even where the CPU has AVX2 or AVX-512: measured on such a machine, MUMPS factorized a 3D block 2.1x
 * and the application scene's single-precision factors 1.6x faster with the SkylakeX kernels (docs/performance.md,
 * "OpenBLAS kernels").
 * OpenBLAS reads OPENBLAS_CORETYPE only while it loads, before main, so the only way to change the choice of a
 * running program is to start it again: ldfcz_blas_kernels_restart sets OPENBLAS_CORETYPE and execs the program
 * anew (same process, same arguments and environment), before MPI or anything else has started. Not under
 * valgrind (its preload library in LD_PRELOAD): the exec would leave the tool.
 *
 * openblas_get_corename is referenced weakly: with another BLAS (reference BLAS, BLIS, MKL through the Debian
 * alternatives) it is absent and nothing is done. A user's OPENBLAS_CORETYPE is always kept. */
#define _POSIX_C_SOURCE 200809L  /* readlink, setenv, strcasecmp */
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <stdio.h>
#include <unistd.h>
#include <fcntl.h>

extern char *openblas_get_corename(void) __attribute__((weak));

/* Marker of a restart made here: its value is the kernels OpenBLAS had chosen by itself. */
static const char *const restart_marker = "LDFCZ_OPENBLAS_CHOSE";

/* Kernel sets of OpenBLAS 0.3 that use AVX2 and FMA or AVX-512 (names as openblas_get_corename gives them). */
static int has_wide_kernels(const char *core)
{
    static const char *const wide[] = {"haswell", "skylakex", "cooperlake", "sapphirerapids", "zen", "excavator"};
    size_t i;
    for (i = 0; i < sizeof wide / sizeof wide[0]; ++i)
        if (strcasecmp(core, wide[i]) == 0) return 1;
    return 0;
}

/* The best kernel set of OpenBLAS 0.3.21 for this CPU's instructions; NULL without AVX2 and FMA. Not Cooperlake
 * for CPUs with AVX-512 BF16: its double and single precision kernels are SkylakeX's, and OPENBLAS_CORETYPE of
 * 0.3.21 does not know the name ("Core not found", then its own detection). */
static const char *best_kernels(void)
{
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
        return "SkylakeX";
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
    return NULL;
}

/* The program's arguments as the kernel holds them (/proc/self/cmdline), as a NULL-terminated array. */
static char **own_arguments(void)
{
    int fd = open("/proc/self/cmdline", O_RDONLY);
    size_t size = 0, cap = 4096, n = 0, i;
    ssize_t got;
    char *buf, **argv;
    if (fd < 0) return NULL;
    buf = malloc(cap + 1);
    while (buf && (got = read(fd, buf + size, cap - size)) > 0) {
        size += (size_t)got;
        if (size == cap) {
            char *bigger = realloc(buf, 2 * cap + 1);
            if (!bigger) { free(buf); buf = NULL; break; }
            buf = bigger;
            cap *= 2;
        }
    }
    close(fd);
    if (!buf || size == 0) { free(buf); return NULL; }
    buf[size] = '\0';
    for (i = 0; i < size; ++i) if (buf[i] == '\0') ++n;
    argv = malloc((n + 1) * sizeof *argv);
    if (!argv) { free(buf); return NULL; }
    n = 0;
    for (i = 0; i < size; i += strlen(buf + i) + 1) argv[n++] = buf + i;
    argv[n] = NULL;
    return argv;
}

/* When OpenBLAS chose kernels without AVX2 on a CPU that has AVX2 and FMA (and the user did not set
 * OPENBLAS_CORETYPE): set OPENBLAS_CORETYPE to the best kernel set for the CPU and exec this program again.
 * Returns only when nothing was done or the exec failed (then 1). */
int ldfcz_blas_kernels_restart(void)
{
    const char *target;
    char **argv;
    const char *preload = getenv("LD_PRELOAD");
    char path[4096];
    ssize_t len;
    if (!openblas_get_corename || getenv("OPENBLAS_CORETYPE") || getenv(restart_marker)) return 0;  /* once only */
    if (has_wide_kernels(openblas_get_corename())) return 0;
    target = best_kernels();
    if (!target) return 0;
    /* under valgrind the exec would leave the tool (unless it traces children): keep the process as it is */
    if (preload && strstr(preload, "vgpreload")) return 1;
    len = readlink("/proc/self/exe", path, sizeof path - 1);
    argv = own_arguments();
    if (len <= 0 || (size_t)len >= sizeof path - 1 || !argv) return 1;
    path[len] = '\0';
    if (setenv(restart_marker, openblas_get_corename(), 1) != 0 || setenv("OPENBLAS_CORETYPE", target, 1) != 0)
        return 1;
    execv(path, argv);
    unsetenv("OPENBLAS_CORETYPE");  /* the exec failed: go on with the kernels chosen */
    unsetenv(restart_marker);
    return 1;
}

/* What OpenBLAS runs: its kernels (into core; *wide = 1 when they use AVX2 and FMA or AVX-512), the kernels it had
 * chosen itself before a restart made here (into chose, "" if none), and the best set for this CPU (into best, ""
 * without AVX2). Returns 0 without OpenBLAS. */
int ldfcz_blas_kernels(char *core, char *chose, char *best, int *wide, int len)
{
    const char *from = getenv(restart_marker), *target = best_kernels();
    if (!openblas_get_corename || len < 1) return 0;
    *wide = has_wide_kernels(openblas_get_corename());
    snprintf(core, (size_t)len, "%s", openblas_get_corename());
    snprintf(chose, (size_t)len, "%s", from ? from : "");
    snprintf(best, (size_t)len, "%s", target ? target : "");
    return 1;
}
