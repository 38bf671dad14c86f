#!/usr/bin/env python3
"""Errors of the start-up end a distributed run cleanly (mpirun -np N, the LDFCZ_MPI build).

Each case runs `mpirun -np N ldfcz ...` with something wrong, found by every process (a malformed deck, an unknown
option or option value, a missing --user file; a restart with other --element-weights or --partition-pieces than
the run that wrote the restart files, i.e. another partition, found when the restart files are read) or by one
process only (its own restart file JOB.rst.RofN missing; JOB.sta not writable, which only rank 0, the writer,
opens). Each must:
  - end within the time limit (a process that gave up while the others wait in a collective call would hang);
  - end with exit status 2 (mpirun passes on the processes' status);
  - print the expected message (file, line and keyword for a deck error) exactly once, from whichever process
    found it;
  - show no MPI_Abort report and no crash (a Fortran runtime error or backtrace).
mpirun's own note that a process returned a non-zero status is allowed (mpirun -q hides it; docs/host.md).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

LIMIT_S = 120   # a start-up error takes < 2 s per process here; a hang waits for this
CRASH = re.compile(r"MPI_ABORT|MPI_Abort|Backtrace|runtime error|Error termination|SIGSEGV|signal \d", re.I)


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--decks", required=True, help="the project's decks/ directory")
    ap.add_argument("--out", required=True)
    ap.add_argument("--np", type=int, nargs="+", default=[2, 3])
    ap.add_argument("--peel", required=True, help="tests/mpi/peel_ps_short.inp (UMAT coating, cohesive UEL)")
    args = ap.parse_args()
    args.exe = os.path.abspath(args.exe)
    args.decks = os.path.abspath(args.decks)
    args.out = os.path.abspath(args.out)
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)
    bad = os.path.join(args.decks, "bad", "bad_bad_number.inp")
    good = os.path.join(args.decks, "single", "cohesive_block.inp")
    user_deck = os.path.join(args.decks, "single", "user_uel.inp")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_mpi_yield_when_idle="1")
    for np in args.np:
        out = os.path.join(args.out, "np%d" % np)
        os.makedirs(out)
        # one process only: the restart file of the last rank is missing (the others find theirs)
        rst = os.path.join(out, "cohesive_block.rst")
        for r in range(np - 1):
            with open("%s.%dof%d" % (rst, r, np), "w") as f:
                f.write("not read: the run stops before\n")
        missing = "%s.%dof%d" % (rst, np - 1, np)
        # one process only: rank 0's JOB.sta cannot be created (a directory of that name)
        writer_dir = os.path.join(out, "writer")
        os.makedirs(os.path.join(writer_dir, "cohesive_block.sta"))
        # restart files of a run partitioned with the default weights, then a restart with others
        rdir = os.path.join(out, "restart")
        os.makedirs(rdir)
        cmd = ["mpirun", "-np", str(np), "--oversubscribe", "--bind-to", "none", args.exe, "-q", "--threads", "1",
               "--out", rdir, "--restart-write", "1", "--stop-after-increments", "2", args.peel]
        p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=LIMIT_S, cwd=out)
        if p.returncode != 3:
            fail("np %d: the run writing restart files ended with %d, want 3:\n%s" % (np, p.returncode,
                                                                                   (p.stdout + p.stderr)[-2000:]))
        peel_rst = os.path.join(rdir, "peel_ps_short.rst")
        cases = [
            ("restart with another partition", ["--out", rdir, "--restart-from", peel_rst, "--element-weights",
                                                "1,1,100", args.peel],
             "another partition"),
            ("restart with an interleaved partition", ["--out", rdir, "--restart-from", peel_rst,
                                                       "--partition-pieces", "3", args.peel],
             "another partition"),
            ("bad --partition-pieces", ["--partition-pieces", "0", good],
             re.escape("--partition-pieces needs an integer 1..10000")),
            ("malformed deck", [bad], re.escape("bad_bad_number.inp:10: *NODE: not a number")),
            ("unknown option", ["--no-such-option", good], re.escape("unknown option --no-such-option")),
            ("missing deck", [os.path.join(out, "absent.inp")], re.escape("absent.inp: file not found")),
            ("missing --user file", ["--user", os.path.join(out, "absent_uel.f"), user_deck], "absent_uel\\.f"),
            ("restart file of rank %d only missing" % (np - 1), ["--restart-from", rst, good],
             re.escape("--restart-from: " + missing + ": file not found")),
            ("JOB.sta not writable (rank 0 only)", ["--out", writer_dir, good],
             re.escape("cannot write " + os.path.join(writer_dir, "cohesive_block.sta"))),
        ]
        for name, extra, want in cases:
            cmd = ["mpirun", "-np", str(np), "--oversubscribe", "--bind-to", "none", args.exe, "-q", "--threads",
                   "1", "--out", out] + extra
            try:
                p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=LIMIT_S, cwd=out)
            except subprocess.TimeoutExpired:
                fail("np %d, %s: no exit within %d s (hang)" % (np, name, LIMIT_S))
            text = p.stdout + p.stderr
            if p.returncode != 2:
                fail("np %d, %s: exit status %d, want 2:\n%s" % (np, name, p.returncode, text[-2000:]))
            hits = re.findall(r"^ldfcz: error: .*" + want + ".*$", text, re.M)
            if len(hits) != 1:
                fail("np %d, %s: the message /%s/ printed %d times, want once:\n%s" %
                     (np, name, want, len(hits), text[-2000:]))
            errors = re.findall(r"^ldfcz: error:", text, re.M)
            if len(errors) != 1:
                fail("np %d, %s: %d error lines, want 1:\n%s" % (np, name, len(errors), text[-2000:]))
            if CRASH.search(text):
                fail("np %d, %s: abort or crash report:\n%s" % (np, name, text[-2000:]))
            print("np %d, %s: exit 2, once: %s" % (np, name, hits[0]))
    print("PASS")


if __name__ == "__main__":
    main()
