#!/usr/bin/env python3
"""The one-file Abaqus drop-ins (<build>/dropin, tools/make_dropin.py) as a user builds them into Abaqus.

  check_dropins.py --exe BIN --dropins DIR --include DIR --marc-include DIR --marc-stubs FILE --deck DECK --out DIR
                   [--fflags FLAGS] [--exact]

1. Each of ldfcz_abaqus_uel.f, ldfcz_abaqus_umat.f, ldfcz_abaqus.f compiles alone, the way Abaqus compiles a user
   file on Linux (gfortran: -c -fPIC -cpp -ffixed-form -ffixed-line-length-132 -frecursive -O2; Abaqus' own line is
   Intel's ifort with -fpp -extend-source -auto) and with LLVM flang (flang-new-16 -ffixed-form
   -ffixed-line-length=132 -cpp).
   The free-form twins (.f90) compile with both compilers as free form.
2. The UEL and UMAT drop-ins link into one shared library: no symbol defined twice. The Marc drop-ins
   ldfcz_marc_hypela2.f, ldfcz_marc_uselem.f and ldfcz_marc.f (both) compile with both compilers against the test
   doubles of Marc's include files and link with the double of QUIT into a shared library that leaves no symbol
   undefined (-Wl,--no-undefined).
   The open-host utilities ldfcz_open_host_utils.f (.f90) compile with both compilers and supply every symbol
   ldfcz_abaqus.f needs (-Wl,--no-undefined); a program of the UEL drop-in and the utilities alone gives T_max on
   a unit-area element opened by delta (1e-12) and, with phi = 0, stops through XIT with a message and a
   non-zero exit.
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


DRIVER = """program open_host_driver
  ! the UEL drop-in and the open-host utilities, nothing else: one unit-square element opened by delta along its
  ! normal (a good call), then the same call with phi = 0, which must end the program through XIT with a message
  implicit none
  external :: uel
  double precision :: rhs(24, 1), amatrx(24, 24), svars(16), energy(8), props(2), coords(3, 8), u(24), du(24, 1)
  double precision :: v(24), acc(24), params(3), adlmag(1, 1), ddlmag(1, 1), predef(2, 1, 8), pnewdt
  integer :: lflags(5), jdltyp(1, 1), jprops(1), k
  character(len=8) :: arg
  coords = reshape([0d0, 0d0, 0d0, 1d0, 0d0, 0d0, 1d0, 1d0, 0d0, 0d0, 1d0, 0d0, &
                    0d0, 0d0, 0d0, 1d0, 0d0, 0d0, 1d0, 1d0, 0d0, 0d0, 1d0, 0d0], [3, 8])
  u = 0d0
  do k = 5, 8
    u(3 * k) = 0.05d0
  end do
  rhs = 0d0; amatrx = 0d0; svars = 0d0; energy = 0d0; du = 0d0; v = 0d0; acc = 0d0; params = 0d0
  adlmag = 0d0; ddlmag = 0d0; predef = 0d0; jdltyp = 0; jprops = 0; pnewdt = 1d36
  lflags = [1, 1, 1, 0, 0]
  props = [0.2d0, 0.05d0]
  call get_command_argument(1, arg)
  if (arg == 'bad') props(1) = 0d0
  call uel(rhs, amatrx, svars, energy, 24, 1, 16, props, 2, coords, 3, 8, u, du, v, acc, 1, [0d0, 0d0], 1d0, &
           1, 1, 1, params, 0, jdltyp, adlmag, predef, 0, lflags, 24, ddlmag, 1, pnewdt, jprops, 0, 1d0)
  ! T(delta) = phi/(e delta) on a unit area: the top nodes carry -T/4 each in RHS
  write (*, '(a,es23.15)') 'top force ', -sum(rhs(15:24:3, 1))
end program open_host_driver
"""


def open_host(a, objs):
    """The utilities for open hosts: compile (both forms, both compilers), supply every symbol the Abaqus drop-ins
    call (shared library with --no-undefined), and a program of drop-in + utilities runs a good call and stops with
    XIT's message and a non-zero exit on bad input."""
    util = os.path.join(a.dropins, "ldfcz_open_host_utils")
    for comp, flags in (("gfortran", ["-ffixed-form", "-ffixed-line-length-132"]),
                        ("flang-new-16", ["-ffixed-form", "-ffixed-line-length=132"])):
        sh([comp, "-c", "-fPIC", "-O2"] + flags + [util + ".f", "-o", os.path.join(a.out, comp, "utils.o")])
        sh([comp, "-c", "-fPIC", "-O2", "-ffree-form", util + ".f90", "-o", os.path.join(a.out, comp, "utils90.o")])
        print("%-13s compiles ldfcz_open_host_utils.f and .f90: ok" % comp)
    uo = os.path.join(a.out, "gfortran", "utils.o")
    sh(["gfortran", "-shared", "-Wl,--no-undefined", "-o", os.path.join(a.out, "open.so"),
        objs[("gfortran", "ldfcz_abaqus")], uo])
    print("ldfcz_abaqus.f + ldfcz_open_host_utils.f link with no undefined symbol: ok")
    drv = os.path.join(a.out, "open_host_driver.f90")
    with open(drv, "w") as f:
        f.write(DRIVER)
    exe = os.path.join(a.out, "open_host_driver")
    sh(["gfortran", "-o", exe, drv, objs[("gfortran", "ldfcz_abaqus_uel")], uo])
    good = subprocess.run([exe], capture_output=True, text=True)
    tmax = 0.2 / (2.718281828459045 * 0.05)
    force = float(good.stdout.split()[-1]) if good.returncode == 0 and good.stdout.split() else float("nan")
    if not abs(force - tmax) <= 1e-12 * tmax:
        fail("open-host driver, good call: exit %d, force %r (want T_max = %.15g)\n%s"
             % (good.returncode, force, tmax, good.stdout + good.stderr))
    bad = subprocess.run([exe, "bad"], capture_output=True, text=True)
    if bad.returncode == 0 or "XIT" not in bad.stderr or "phi" not in bad.stderr or "top force" in bad.stdout:
        fail("open-host driver, phi = 0: exit %d (want non-zero, a message naming phi and XIT, no result)\n%s"
             % (bad.returncode, bad.stdout + bad.stderr))
    print("open host: drop-in + utilities give T_max on a good call (%.3e relative); phi = 0 stops with XIT's"
          " message, exit %d: ok" % (abs(force - tmax) / tmax, bad.returncode))


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
    stub = os.path.join(a.out, "marc_stubs.o")
    sh(["gfortran", "-c", "-fPIC", "-ffixed-line-length-132", "-I" + a.marc_include, a.marc_stubs, "-o", stub])
    for name in ("ldfcz_marc_hypela2", "ldfcz_marc_uselem", "ldfcz_marc"):
        marc = os.path.join(a.dropins, name + ".f")
        for comp, flags in (("gfortran", ["-ffixed-form", "-ffixed-line-length-132", "-frecursive"]),
                            ("flang-new-16", ["-ffixed-form", "-ffixed-line-length=132"])):
            d = os.path.join(a.out, comp, name)
            os.makedirs(d)
            obj = os.path.join(d, name + ".o")
            cmd = [comp, "-c", "-fPIC", "-cpp", "-O2"] + flags + ["-I" + a.marc_include, marc, "-o", obj]
            cmd[1:1] = ["-J" + d] if comp == "gfortran" else ["-module-dir", d]
            sh(cmd)
            print("%-13s compiles %s.f: ok" % (comp, name))
            if comp == "gfortran":
                sh(["gfortran", "-shared", "-Wl,--no-undefined", "-o", os.path.join(d, "marc.so"), obj, stub])
                print("%s.f + QUIT links with no undefined symbol: ok" % name)
    open_host(a, objs)
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
