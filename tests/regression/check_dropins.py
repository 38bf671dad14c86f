#!/usr/bin/env python3
"""The one-file Abaqus drop-ins (<build>/dropin, tools/make_dropin.py) as a user builds them into Abaqus.

  check_dropins.py --exe BIN --dropins DIR --include DIR --marc-include DIR --marc-stubs FILE --deck DECK --out DIR
                   [--fflags FLAGS] [--exact]

1. Each of ldfcz_abaqus_uel.f, ldfcz_abaqus_umat.f, ldfcz_abaqus.f compiles alone, the way Abaqus compiles a user
   file on Linux (gfortran: -c -fPIC -cpp -ffixed-form -ffixed-line-length-132 -frecursive -O2; Abaqus' own line is
   Intel's ifort with -fpp -extend-source -auto) and with LLVM flang (flang-new-16 -ffixed-form
   -ffixed-line-length=132 -cpp).
   The free-form twins (.f90) compile with both compilers as free form.
2. The UEL and UMAT drop-ins link into one shared library: no symbol defined twice. The Marc drop-in
   ldfcz_marc_hypela2.f compiles with both compilers against the test doubles of Marc's include files and links
   with the double of QUIT into a shared library that leaves no symbol undefined (-Wl,--no-undefined).
3. ldfcz --user ldfcz_abaqus.f on the peel deck (30 increments: cohesive UEL + Leonov UMAT) against the built-in
   routines. With --fflags set to the flags the build compiled the built-in routines with and --exact (the Debug
   configuration, where every source has the same flags), the history must be identical bit for bit; otherwise
   (Release: the built-in Leonov core at -O3, the rest at -O2, the drop-in one file) to 1e-10 relative, round-off
   of other optimisation only.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys


OUT = ['']  # the test's output directory (main)


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def sh(cmd):
    # run from the test's own directory: gfortran and flang look for module files in the working directory first,
    # and a stale .mod of another build there would hide the drop-in's own modules
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=OUT[0] or None)
    if p.returncode != 0:
        fail("%s\n%s" % (" ".join(cmd), p.stdout + p.stderr))


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser()
    for k in ("exe", "dropins", "include", "marc-include", "marc-stubs", "deck", "out"):
        ap.add_argument("--" + k, required=True)
    ap.add_argument("--fflags", default="")
    ap.add_argument("--exact", action="store_true")
    a = ap.parse_args()
    for k in ("exe", "dropins", "include", "marc_include", "marc_stubs", "deck", "out"):
        setattr(a, k, os.path.abspath(getattr(a, k)))
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    OUT[0] = a.out
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
    for name in ("ldfcz_abaqus_uel", "ldfcz_abaqus_umat", "ldfcz_abaqus"):
        src = os.path.join(a.dropins, name + ".f90")
        for comp in ("gfortran", "flang-new-16"):
            d = os.path.join(a.out, comp, name + "_free")
            os.makedirs(d)
            cmd = [comp, "-c", "-fPIC", "-cpp", "-O2", "-ffree-form", "-I" + a.include, src,
                   "-o", os.path.join(d, name + ".o")]
            cmd[1:1] = ["-J" + d] if comp == "gfortran" else ["-module-dir", d]
            sh(cmd)
            print("%-13s compiles %s.f90 (free form): ok" % (comp, name))
    sh(["gfortran", "-shared", "-o", os.path.join(a.out, "both.so"), objs[("gfortran", "ldfcz_abaqus_uel")],
        objs[("gfortran", "ldfcz_abaqus_umat")]])
    print("UEL and UMAT drop-ins linked together: ok")
    marc = os.path.join(a.dropins, "ldfcz_marc_hypela2.f")
    for comp, flags in (("gfortran", ["-ffixed-form", "-ffixed-line-length-132", "-frecursive"]),
                        ("flang-new-16", ["-ffixed-form", "-ffixed-line-length=132"])):
        d = os.path.join(a.out, comp, "marc")
        os.makedirs(d)
        obj = os.path.join(d, "ldfcz_marc_hypela2.o")
        cmd = [comp, "-c", "-fPIC", "-cpp", "-O2"] + flags + ["-I" + a.marc_include, marc, "-o", obj]
        cmd[1:1] = ["-J" + d] if comp == "gfortran" else ["-module-dir", d]
        sh(cmd)
        print("%-13s compiles ldfcz_marc_hypela2.f: ok" % comp)
        if comp == "gfortran":
            stub = os.path.join(d, "stubs.o")
            sh(["gfortran", "-c", "-fPIC", "-ffixed-line-length-132", "-I" + a.marc_include, a.marc_stubs, "-o", stub])
            sh(["gfortran", "-shared", "-Wl,--no-undefined", "-o", os.path.join(d, "marc.so"), obj, stub])
            print("ldfcz_marc_hypela2.f + QUIT links with no undefined symbol: ok")
    ref, dro = os.path.join(a.out, "builtin"), os.path.join(a.out, "dropin")
    job = os.path.splitext(os.path.basename(a.deck))[0]
    flags = ["--fflags", a.fflags] if a.fflags else []
    for out, extra in ((ref, []), (dro, flags + ["--user", os.path.join(a.dropins, "ldfcz_abaqus.f")])):
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
    if a.exact:
        same = open(os.path.join(ref, job + ".csv"), "rb").read() == open(os.path.join(dro, job + ".csv"), "rb").read()
        print("--user ldfcz_abaqus.f --fflags '%s' against the built-in routines: histories %s"
              % (a.fflags, "identical bit for bit" if same else "DIFFERENT (largest relative %.2e)" % worst))
        if not same:
            fail("the drop-in compiled with the build's flags is not bit-for-bit the built-in result")
    else:
        print("--user ldfcz_abaqus.f against the built-in routines: largest relative difference %.2e (limit 1e-10)"
              % worst)
        if worst > 1e-10:
            fail("the drop-in differs from the built-in routines")
    print("dropins: ok")


if __name__ == "__main__":
    main()
