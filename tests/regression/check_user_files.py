#!/usr/bin/env python3
"""--user as Abaqus builds user code (test deck_user_files).

  check_user_files.py --exe BIN --decks DIR --fixtures DIR --out DIR

1. Two files given as two --user options: a fixed-form UMAT with `include 'aba_param.inc'` in lower case, an #ifdef
   block (Abaqus preprocesses user files; ABQ_LNX86_64 is defined), a WRITE(7) that must land in JOB.msg, a call to a
   routine no file defines on a branch never taken (lazy binding), and its helper in a free-form second file.
   decks/single/user_umat_files.inp stretches two elastic bricks by 1e-3 with free lateral faces, so
   RF3(TOP) = E 1e-3 A = 1 N (small strain, linear: exact to round-off, rtol 1e-9).
2. The same with the helper given as an object file (compiled here with gfortran -c -fPIC), comma-separated.
3. --fc flang-new-16 (LLVM flang) compiling the fixed-form spring-bed UEL of decks/single/user_uel.inp: RF3 = k w A = 1 N;
   and the UMAT of case 1: flang's own units 6 and 7 reach JOB.dat and JOB.msg.
4. Abaqus' thread utilities (user_files/umat_threads.f, 2 threads): under mutex 7 each call numbers itself in a global
   SMA integer array and adds 1 to a global float array created with 1.0, and counts itself in a thread-local array.
   The global numbers in JOB.dat must be exactly 1..N, the float value N + 1, each thread's own counts 1..n_t with
   sum n_t = N, every call sees 2 threads and its thread number below 2, and GETNUMCPUS/GETRANK/GETCOMMUNICATOR
   give 1/0/0 (one process without MPI). The same file compiled with --fflags -DLDFCZ_TEST_BAD_MUTEX locks mutex
   101: the run must stop with an error naming MutexLock(101).
5. Unit 6 of a user routine lands in JOB.dat, not on the console.
6. UEXTERNALDB (in umat_threads.f) is called as Abaqus documents: LOP 0 once at the start, 1 at the start of
   every increment attempt (TIME at its start, DTIME its size), 2 at the end of every converged increment (TIME
   at its end: the CSV row's times), 3 once at the end; KSTEP/KINC of the increment.
7. A routine written on Windows (user_files/case_include): INCLUDE 'PAST_NPROPS.INC' beside past_nprops.inc compiles,
   with a warning naming the file, line and the name found; the same routine reads the 16 PROPS after NPROPS and
   reports their sum to JOB.msg: 0 exactly (ldfcz passes zeros there, not whatever memory follows); RF3 as case 1.
8. A UEL that writes SVARS(0) (user_uel_elastic.f compiled with --fflags -DLDFCZ_TEST_SVARS_SLIP: a loop index
   starting one too low, as in a published UEL) stops the run with a non-zero exit and a message naming the element
   and SVARS(0) (in Abaqus the write would land in another element's state); without the flag it runs (case 3).
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, out, args, deck, quiet=True, console=None):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    p = subprocess.run([exe, "-o", out] + (["-q"] if quiet else []) + args + [deck], capture_output=True, text=True)
    if p.returncode != 0:
        fail("exit %d: %s" % (p.returncode, p.stderr[-3000:]))
    if console is not None:
        console.append(p.stdout)
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[-1], job


def read(path):
    with open(path) as f:
        return f.read()


def check_threads(out, job):
    """The SMA_CALL lines of umat_threads.f in JOB.dat (see the module docstring, case 4)."""
    text = read(os.path.join(out, job + ".dat"))
    calls = [line.split() for line in text.splitlines() if line.startswith("SMA_CALL")]
    info = [line.split() for line in text.splitlines() if line.startswith("SMA_INFO")]
    n = len(calls)
    if n == 0 or n % 16:
        fail("SMA_CALL lines: %d (want a positive multiple of 16: 2 bricks x 8 points per assembly)" % n)
    numbers = sorted(int(c[1]) for c in calls)
    if numbers != list(range(1, n + 1)):
        fail("global call numbers are not exactly 1..%d: the mutex or the global array failed" % n)
    per_thread = {}
    for c in calls:
        thread, local, nthreads, value = int(c[3]), int(c[5]), int(c[7]), float(c[9])
        if nthreads != 2 or not 0 <= thread < 2:
            fail("GETNUMTHREADS %d / GET_THREAD_ID %d with -t 2" % (nthreads, thread))
        if value != int(c[1]) + 1:
            fail("global float array: %g after call %s (created with 1.0, +1 per call)" % (value, c[1]))
        per_thread.setdefault(thread, []).append(local)
    for thread, counts in per_thread.items():
        if sorted(counts) != list(range(1, len(counts) + 1)):
            fail("thread %d: local counts are not 1..%d (thread-local array shared?)" % (thread, len(counts)))
    if sum(len(c) for c in per_thread.values()) != n:
        fail("thread-local counts do not add up to the calls")
    if len(info) != 1 or info[0][2:] != ["1", "RANK", "0", "COMM", "0", "SIZE", "1"]:
        fail("GETNUMCPUS/GETRANK/GETCOMMUNICATOR/SMAIntArraySize line: %s" % info)
    print("thread utilities: %d calls numbered 1..%d under the mutex, threads %s with private counts: ok"
          % (n, n, sorted(per_thread)))


def check_uexternaldb(out, job):
    """The UEXT lines of umat_threads.f in JOB.dat against the CSV history (module docstring, case 6)."""
    text = read(os.path.join(out, job + ".dat"))
    calls = [line.split()[1:] for line in text.splitlines() if line.startswith("UEXT")]
    lops = "".join(c[0] for c in calls)
    with open(os.path.join(out, job + ".csv")) as f:
        hist = list(csv.DictReader(f))
    if not re.fullmatch(r"0(1+2)+3", lops):
        fail("UEXTERNALDB LOP sequence %s (want 0, then 1..1 2 per increment, then 3)" % lops)
    ends = [c for c in calls if c[0] == "2"]
    if len(ends) != len(hist):
        fail("%d LOP=2 calls for %d converged increments" % (len(ends), len(hist)))
    for c, row in zip(ends, hist):
        kstep, kinc, t1, t2 = int(c[2]), int(c[3]), float(c[4]), float(c[5])
        if (kstep, kinc) != (int(row["step"]), int(row["inc"])) or abs(t1 - float(row["step_time"])) > 1e-12 or \
                abs(t2 - float(row["total_time"])) > 1e-12:
            fail("LOP=2 call %s does not match the CSV row %s" % (c, row))
    for i, c in enumerate(calls):
        if c[0] == "2":
            start = calls[i - 1]  # the attempt that converged
            if abs(float(start[4]) + float(start[6]) - float(c[4])) > 1e-12 or start[3] != c[3]:
                fail("LOP=1 %s and LOP=2 %s: start time + DTIME is not the end time" % (start, c))
    print("UEXTERNALDB: LOP sequence %s, %d converged increments matching the history: ok" % (lops, len(ends)))


def check_rf(name, row, col, want):
    got = float(row[col])
    ok = abs(got - want) <= 1e-9 * abs(want)
    print("%-34s %s = %.12g (want %g) %s" % (name, col, got, want, "ok" if ok else "FAIL"))
    if not ok:
        fail(name)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--fixtures", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    fx = os.path.join(a.fixtures, "user_files")
    deck = os.path.join(a.decks, "single", "user_umat_files.inp")

    out = os.path.join(a.out, "two_files")
    console = []
    row, job = run(a.exe, out, ["--user", os.path.join(fx, "umat_fixed.f"), "--user",
                                os.path.join(fx, "elastic_helper.f90")], deck, quiet=False, console=console)
    check_rf("two --user files", row, "TOP.RF3", 1.0)
    if "UMAT_FIXED: unit 6" not in read(os.path.join(out, job + ".dat")):
        fail("WRITE(6) of the user routine is not in JOB.dat")
    if "UMAT_FIXED" in console[0] or "ldfcz" not in console[0]:
        fail("the console should carry the host's messages and not the user's unit 6:\n" + console[0][-2000:])
    print("WRITE(6) in JOB.dat, host messages on the console: ok")
    with open(os.path.join(out, job + ".msg")) as f:
        if "UMAT_FIXED: compiled for Linux" not in f.read():
            fail("WRITE(7) of the #ifdef block did not reach JOB.msg")
    print("WRITE(7) in JOB.msg, #ifdef ABQ_LNX86_64 taken: ok")

    out = os.path.join(a.out, "object")
    os.makedirs(a.out, exist_ok=True)
    obj = os.path.join(a.out, "elastic_helper.o")
    subprocess.run(["gfortran", "-c", "-fPIC", "-o", obj, os.path.join(fx, "elastic_helper.f90")], check=True)
    row, _ = run(a.exe, out, ["--user", os.path.join(fx, "umat_fixed.f") + "," + obj], deck)
    check_rf("source + object file", row, "TOP.RF3", 1.0)

    out = os.path.join(a.out, "flang")
    row, _ = run(a.exe, out, ["--fc", "flang-new-16", "--user", os.path.join(a.fixtures, "user_uel_elastic.f")],
                 os.path.join(a.decks, "single", "user_uel.inp"))
    check_rf("UEL compiled by LLVM flang", row, "TOP.RF3", 1.0)

    out = os.path.join(a.out, "flang_units")
    row, job = run(a.exe, out, ["--fc", "flang-new-16", "--user", os.path.join(fx, "umat_fixed.f") + "," +
                                os.path.join(fx, "elastic_helper.f90")], deck)
    check_rf("UMAT compiled by LLVM flang", row, "TOP.RF3", 1.0)
    if "UMAT_FIXED: unit 6" not in read(os.path.join(out, job + ".dat")):
        fail("flang: WRITE(6) not in JOB.dat")
    if "UMAT_FIXED: compiled for Linux" not in read(os.path.join(out, job + ".msg")):
        fail("flang: WRITE(7) not in JOB.msg")
    print("flang's units 6 and 7 in JOB.dat and JOB.msg: ok")

    out = os.path.join(a.out, "threads")
    threads_files = os.path.join(fx, "umat_threads.f") + "," + os.path.join(fx, "elastic_helper.f90")
    row, job = run(a.exe, out, ["-t", "2", "--user", threads_files], deck)
    check_rf("thread utilities", row, "TOP.RF3", 1.0)
    check_threads(out, job)
    check_uexternaldb(out, job)

    out = os.path.join(a.out, "case_include")
    console = []
    row, job = run(a.exe, out, ["--user", os.path.join(fx, "case_include", "umat_case_include.f") + "," +
                                os.path.join(fx, "elastic_helper.f90")], deck, quiet=False, console=console)
    check_rf("INCLUDE under another case", row, "TOP.RF3", 1.0)
    log = read(os.path.join(out, job + ".log"))
    want = "umat_case_include.f:12: INCLUDE 'PAST_NPROPS.INC' is past_nprops.inc"
    if want not in log:
        fail("no warning '%s' in JOB.log" % want)
    print("INCLUDE 'PAST_NPROPS.INC' found as past_nprops.inc, warned: ok")
    sums = re.findall(r"PAST_NPROPS: sum of \|PROPS\(NPROPS\+1:NPROPS\+16\)\| =\s*(\S+)",
                      read(os.path.join(out, job + ".msg")))
    if not sums or any(float(v) != 0.0 for v in sums):
        fail("PROPS after NPROPS are not 0: %s" % sums)
    print("the 16 PROPS after NPROPS read 0 in %d calls: ok" % len(sums))

    out = os.path.join(a.out, "svars_zero")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    p = subprocess.run([a.exe, "-q", "-o", out, "--fflags", "-DLDFCZ_TEST_SVARS_SLIP", "--user",
                        os.path.join(a.fixtures, "user_uel_elastic.f"), os.path.join(a.decks, "single", "user_uel.inp")],
                       capture_output=True, text=True)
    if p.returncode == 0 or not re.search(r"element 1 \(UEL\): the routine wrote SVARS\(0\), outside SVARS\(1:1\)",
                                          p.stderr):
        fail("SVARS(0): want a non-zero exit naming element 1 and SVARS(0), got %d: %s" % (p.returncode,
                                                                                      p.stderr[-1000:]))
    print("a UEL writing SVARS(0) stops the run: " + p.stderr.strip().splitlines()[-1][:160])

    out = os.path.join(a.out, "bad_mutex")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    p = subprocess.run([a.exe, "-q", "-o", out, "--fflags", "-DLDFCZ_TEST_BAD_MUTEX", "--user", threads_files, deck],
                       capture_output=True, text=True)
    if p.returncode == 0 or "MutexLock(101)" not in p.stderr:
        fail("MutexLock(101): want a non-zero exit naming it, got %d: %s" % (p.returncode, p.stderr[-1000:]))
    print("MutexLock(101) stops the run with: " + p.stderr.strip().splitlines()[-1])
    print("user files: ok")


if __name__ == "__main__":
    main()
