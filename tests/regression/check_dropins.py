#!/usr/bin/env python3
"""The one-file Abaqus drop-ins (<build>/dropin, tools/make_dropin.py) as a user builds them into Abaqus.

  check_dropins.py --exe BIN --dropins DIR --include DIR --deck DECK --out DIR

1. Each of ldfcz_abaqus_uel.f, ldfcz_abaqus_umat.f, ldfcz_abaqus.f compiles alone, the way Abaqus compiles a user
   file on Linux (gfortran: -c -fPIC -cpp -ffixed-form -ffixed-line-length-132 -frecursive -O2; Abaqus' own line is
   Intel's ifort with -fpp -extend-source -auto) and with LLVM flang (flang-new-16 -ffixed-form
   -ffixed-line-length=132 -cpp).
2. The UEL and UMAT drop-ins link into one shared library: no symbol defined twice.
3. ldfcz --user ldfcz_abaqus.f on the peel deck (30 increments: cohesive UEL + Leonov UMAT) gives the built-in
   routines' result to 1e-10 relative (the same code compiled with other optimisation flags: round-off only,
   measured 4e-14).
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


def sh(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        fail("%s\n%s" % (" ".join(cmd), p.stdout + p.stderr))


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser()
    for k in ("exe", "dropins", "include", "deck", "out"):
        ap.add_argument("--" + k, required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    objs = {}
    for name in ("ldfcz_abaqus_uel", "ldfcz_abaqus_umat", "ldfcz_abaqus"):
        src = os.path.join(a.dropins, name + ".f")
        for comp, flags in (("gfortran", ["-ffixed-form", "-ffixed-line-length-132", "-frecursive"]),
                            ("flang-new-16", ["-ffixed-form", "-ffixed-line-length=132"])):
            d = os.path.join(a.out, comp, name)
            os.makedirs(d)
            obj = os.path.join(d, name + ".o")
            cmd = [comp, "-c", "-fPIC", "-cpp", "-O2", "-DABQ_LNX86_64"] + flags + ["-I" + a.include, src, "-o", obj]
            if comp == "gfortran":
                cmd.insert(1, "-J" + d)
            else:
                cmd.insert(1, "-module-dir")
                cmd.insert(2, d)
            sh(cmd)
            objs[(comp, name)] = obj
            print("%-13s compiles %s.f: ok" % (comp, name))
    sh(["gfortran", "-shared", "-o", os.path.join(a.out, "both.so"), objs[("gfortran", "ldfcz_abaqus_uel")],
        objs[("gfortran", "ldfcz_abaqus_umat")]])
    print("UEL and UMAT drop-ins linked together: ok")
    ref, dro = os.path.join(a.out, "builtin"), os.path.join(a.out, "dropin")
    job = os.path.splitext(os.path.basename(a.deck))[0]
    for out, extra in ((ref, []), (dro, ["--user", os.path.join(a.dropins, "ldfcz_abaqus.f")])):
        p = subprocess.run([a.exe, "-q", "--stop-after-increments", "30", "-o", out] + extra + [a.deck],
                           capture_output=True, text=True)
        if p.returncode != 3:
            fail("exit %d (want 3 after 30 increments): %s" % (p.returncode, p.stderr[-2000:]))
    r1, r2 = rows(os.path.join(ref, job + ".csv")), rows(os.path.join(dro, job + ".csv"))
    if len(r1) != 30 or len(r2) != 30:
        fail("rows %d / %d" % (len(r1), len(r2)))
    worst = 0.0
    for x, y in zip(r1, r2):
        for k in x:
            if k in ("step", "inc"):
                continue
            fx, fy = float(x[k]), float(y[k])
            worst = max(worst, abs(fx - fy) / max(abs(fx), 1e-12))
    print("--user ldfcz_abaqus.f against the built-in routines: largest relative difference %.2e (limit 1e-10)"
          % worst)
    if worst > 1e-10:
        fail("the drop-in differs from the built-in routines")
    print("dropins: ok")


if __name__ == "__main__":
    main()
