#!/usr/bin/env python3
"""Thread-safety test of the element loop: the same deck with --threads 1 and --threads 2 gives the same results.

  check_threads.py --exe BIN --deck DECK --out DIR [--increments K] [--rel 0]

The OpenMP element loop calls the element, UEL and UMAT code of several threads at once. The assembly is coloured
(host/analysis/element_colors.f90: no two elements of one colour share a dof, colours in a fixed order), so every
sum is taken in the same order on any number of threads and the results must be bitwise equal (--rel 0, the
default; before the colouring, atomic additions in a run-dependent order gave ~3e-15). A data race (a static
local array, a SAVEd variable written by two threads) gives O(1) differences or, in the Debug build, a "Recursive
call to nonrecursive procedure" stop. Checks: both runs exit alike, same increments (step, inc, step time), every
CSV value within --rel relative; the same with every factorization on 2 OpenBLAS threads (LDFCZ_BLAS_MIN_FLOPS=0).
Then the kernels of OpenBLAS (host/linalg/blas_kernels.c): those JOB.log names fit the CPU's instructions, and a
user's OPENBLAS_CORETYPE is kept. Then the warning of host/linalg/omp_wait.f90 in JOB.log: present with 2 threads
and OMP_WAIT_POLICY=active or GOMP_SPINCOUNT=infinite, absent with 1 thread, the passive or the default policy.
(`--newton auto` is as reproducible: its GMRES budget is counted in operations, not measured times; test
reproducible_peel3d, tests/regression/check_reproducible.py.)
"""
import argparse
import os
import shutil
import subprocess
import sys

from ldfcz_tools.block_deck import block_deck


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run_block(exe, deck, d, threads, env, what):
    """Runs the block deck into d; returns its CSV rows and JOB.log."""
    p = subprocess.run([exe, "--quiet", "--threads", str(threads), "--out", d, deck], capture_output=True, text=True,
                       errors="replace", timeout=600, env=env)
    if p.returncode != 0:
        fail("block, %s: exit %d\n%s" % (what, p.returncode, p.stderr[-2000:]))
    with open(os.path.join(d, "blk.csv")) as f:
        table = [l.split(",") for l in f.read().split("\n") if l]
    with open(os.path.join(d, "blk.log")) as f:
        return table, f.read()


def reaction_difference(r1, r2, what):
    """Fails unless both runs took the same increments; returns the largest difference of a CSV value relative to
    the largest one."""
    if len(r1) != len(r2) or any(x[:3] != y[:3] for x, y in zip(r1, r2)):
        fail("%s changed the increments" % what)
    scale = max(abs(float(v)) for x in r1[1:] + r2[1:] for v in x[4:])
    worst = max(abs(float(p) - float(q)) for x, y in zip(r1[1:], r2[1:]) for p, q in zip(x[4:], y[4:]))
    return worst / max(scale, 1e-300)


def blas_threads_check(exe, out):
    """Every factorization on 2 OpenBLAS threads (LDFCZ_BLAS_MIN_FLOPS=0: host/linalg/blas_threads.f90) on a
    16x16x8 C3D8 block (fronts large enough for OpenBLAS to split its calls; the deck of tools/ldfcz_tools/block_deck.py,
    2 increments) against 1 thread: the same increments, every reaction within 1e-10 of the largest one (a
    threaded BLAS sums in another order: 3e-15 relative observed on the pull reaction; the zero components carry
    the solve's round-off of the force scale), and JOB.log says so. Skipped when the BLAS is not OpenBLAS."""
    d0 = os.path.join(out, "blas")
    os.makedirs(d0, exist_ok=True)
    deck = os.path.join(d0, "blk.inp")
    with open(deck, "w") as f:
        f.write(block_deck(2, 0.1, nx=16, ny=16, nz=8))
    tables, logs = {}, {}
    for t, flops in ((1, None), (2, "0")):
        d = os.path.join(d0, "t%d" % t)
        e = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "LDFCZ_BLAS_MIN_FLOPS")}
        if flops is not None:
            e["LDFCZ_BLAS_MIN_FLOPS"] = flops
        tables[t], logs[t] = run_block(exe, deck, d, t, e, "%d threads" % t)
    if "OpenBLAS on 1 thread" not in logs[1]:
        print("BLAS is not OpenBLAS: threaded factorizations not checked")
        return
    if "on 2 during factorizations of at least 0.00E+00 flops" not in logs[2]:
        fail("JOB.log does not say that factorizations use 2 BLAS threads")
    worst = reaction_difference(tables[1], tables[2], "threaded factorizations")
    print("block, every factorization on 2 BLAS threads: largest difference to 1 thread %.2e of the largest "
          "reaction (bound 1e-10)" % worst)
    if worst > 1e-10:
        fail("threaded factorizations change the results beyond round-off")


# kernel sets of OpenBLAS 0.3 that use AVX2 and FMA or AVX-512 (host/linalg/blas_kernels.c)
WIDE_KERNELS = ("haswell", "zen", "excavator", "skylakex", "cooperlake", "sapphirerapids")


def cpu_class():
    """'avx512' (F, BW, VL, DQ), 'avx2' (with FMA) or '' from the flags of /proc/cpuinfo."""
    try:
        with open("/proc/cpuinfo") as f:
            flags = next((l.split(":", 1)[1].split() for l in f if l.startswith("flags")), [])
    except OSError:
        return ""
    if all(x in flags for x in ("avx512f", "avx512bw", "avx512vl", "avx512dq")):
        return "avx512"
    if "avx2" in flags and "fma" in flags:
        return "avx2"
    return ""


def blas_kernels_check(exe, out):
    """The kernels OpenBLAS runs (host/linalg/blas_kernels.c), on the 16x16x8 block of blas_threads_check: without
    OPENBLAS_CORETYPE, those JOB.log names use AVX2 or AVX-512 when the CPU has them (OpenBLAS 0.3.21 takes CPUs it
    does not know for Prescott, and ldfcz then restarts itself with OPENBLAS_CORETYPE set); with
    OPENBLAS_CORETYPE=Prescott, Prescott runs and JOB.log says it was asked for; both runs take the same increments
    and their reactions agree within 1e-10 of the largest one (other kernels sum in another order)."""
    deck = os.path.join(out, "blas", "blk.inp")
    tables, lines = {}, {}
    for label, core in (("default", None), ("prescott", "Prescott")):
        d = os.path.join(out, "kernels", label)
        e = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_CORETYPE", "LDFCZ_OPENBLAS_CHOSE")}
        if core:
            e["OPENBLAS_CORETYPE"] = core
        tables[label], log = run_block(exe, deck, d, 1, e, "kernels " + label)
        lines[label] = next((l.strip() for l in log.split("\n") if l.startswith("ldfcz: OpenBLAS kernels ")), "")
        print("kernels %s: %s" % (label, lines[label] or "(no line: the BLAS is not OpenBLAS)"))
    if not lines["default"]:
        print("BLAS is not OpenBLAS: kernels not checked")
        return
    if not lines["prescott"].startswith("ldfcz: OpenBLAS kernels Prescott (OPENBLAS_CORETYPE=Prescott)"):
        fail("OPENBLAS_CORETYPE=Prescott was not kept or not reported")
    core = lines["default"].split()[3].lower()
    cls = cpu_class()
    if cls and core not in WIDE_KERNELS:
        fail("the CPU has %s but OpenBLAS runs the %s kernels" % (cls.upper(), core))
    worst = reaction_difference(tables["default"], tables["prescott"], "the kernels")
    print("block, %s kernels (CPU class %s) against Prescott: largest difference %.2e of the largest reaction "
          "(bound 1e-10)" % (core, cls or "without AVX2", worst))
    if worst > 1e-10:
        fail("the kernels change the results beyond round-off")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--increments", type=int, default=40, help="stop after so many increments (0: the whole deck)")
    ap.add_argument("--rel", type=float, default=0.0)
    a = ap.parse_args()
    job = os.path.splitext(os.path.basename(a.deck))[0]
    shutil.rmtree(a.out, ignore_errors=True)
    rows, codes = {}, {}
    for t in (1, 2):
        d = os.path.join(a.out, "t%d" % t)
        cmd = [a.exe, "--quiet", "--threads", str(t), "--out", d]
        if a.increments > 0:
            cmd += ["--stop-after-increments", str(a.increments)]
        p = subprocess.run(cmd + [a.deck], capture_output=True, text=True, errors="replace", timeout=600)
        print("$ " + " ".join(cmd + [a.deck]) + "  -> exit %d" % p.returncode)
        if p.returncode not in (0, 3) or "Fortran runtime error" in p.stderr:
            fail("threads %d: exit %d\n%s" % (t, p.returncode, p.stderr[-2000:]))
        codes[t] = p.returncode
        with open(os.path.join(d, job + ".csv")) as f:
            rows[t] = [l.split(",") for l in f.read().split("\n") if l]
    if codes[1] != codes[2]:
        fail("exit status %d with 1 thread, %d with 2" % (codes[1], codes[2]))
    r1, r2 = rows[1], rows[2]
    if r1[0] != r2[0] or len(r1) != len(r2):
        fail("CSV header or row count differ: %d and %d rows" % (len(r1) - 1, len(r2) - 1))
    if len(r1) < 3:
        fail("too few increments to compare")
    worst = 0.0
    for k, (x, y) in enumerate(zip(r1[1:], r2[1:]), 2):
        if x[:3] != y[:3]:
            fail("line %d: increment %s with 1 thread, %s with 2" % (k, x[:3], y[:3]))
        for p, q in zip(x[3:], y[3:]):
            p, q = float(p), float(q)
            if p != q:
                worst = max(worst, abs(p - q) / max(abs(p), abs(q)))
    print("%d increments, largest relative difference 1 vs 2 threads %.2e (bound %.0e)" % (len(r1) - 1, worst, a.rel))
    if worst > a.rel or (a.rel == 0.0 and any(x != y for x, y in zip(r1, r2))):
        fail("results depend on the thread count beyond round-off")
    blas_threads_check(a.exe, a.out)
    blas_kernels_check(a.exe, a.out)
    # idle threads told to spin (host/linalg/omp_wait.f90): a warning in JOB.log with 2 threads, none with 1 thread
    # or the default policy
    for t, env, want in ((2, {"OMP_WAIT_POLICY": "active"}, True), (1, {"OMP_WAIT_POLICY": "Active"}, False),
                         (2, {"GOMP_SPINCOUNT": "infinite"}, True), (2, {"OMP_WAIT_POLICY": "passive"}, False),
                         (2, {}, False)):
        d = os.path.join(a.out, "wait")
        e = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
        e.update(env)
        p = subprocess.run([a.exe, "--quiet", "--threads", str(t), "--out", d, "--stop-after-increments", "1", a.deck],
                           capture_output=True, text=True, errors="replace", timeout=600, env=e)
        if p.returncode not in (0, 3):
            fail("threads %d %s: exit %d" % (t, env, p.returncode))
        with open(os.path.join(d, job + ".log")) as f:
            has = "the idle threads of the element loop spin" in f.read()
        print("threads %d %s: spin warning %s" % (t, env, "yes" if has else "no"))
        if has != want:
            fail("spin warning %s expected with %d threads and %s" % ("" if want else "not", t, env))
    print("ok")


if __name__ == "__main__":
    main()
