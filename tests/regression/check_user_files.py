#!/usr/bin/env python3
"""--user as Abaqus builds user code (test deck_user_files).

  check_user_files.py --exe BIN --decks DIR --fixtures DIR --out DIR

1. Two files given as two --user options: a fixed-form UMAT with `include 'aba_param.inc'` in lower case, an #ifdef
   block (Abaqus preprocesses user files; ABQ_LNX86_64 is defined), a WRITE(7) that must land in JOB.msg, a call to a
   routine no file defines on a branch never taken (lazy binding), and its helper in a free-form second file.
   decks/single/user_umat_files.inp stretches two elastic bricks by 1e-3 with free lateral faces, so
   RF3(TOP) = E 1e-3 A = 1 N (small strain, linear: exact to round-off, rtol 1e-9).
2. The same with the helper given as an object file (compiled here with gfortran -c -fPIC), comma-separated.
3. --fc flang-new-16 (LLVM flang) compiling the fixed-form spring-bed UEL of decks/single/user_uel.inp: RF3 = k w A = 1 N.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, out, args, deck):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    p = subprocess.run([exe, "-q", "-o", out] + args + [deck], capture_output=True, text=True)
    if p.returncode != 0:
        fail("exit %d: %s" % (p.returncode, p.stderr[-3000:]))
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[-1], job


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
    row, job = run(a.exe, out, ["--user", os.path.join(fx, "umat_fixed.f"), "--user",
                                os.path.join(fx, "elastic_helper.f90")], deck)
    check_rf("two --user files", row, "TOP.RF3", 1.0)
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
    print("user files: ok")


if __name__ == "__main__":
    main()
