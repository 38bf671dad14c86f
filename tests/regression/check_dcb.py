#!/usr/bin/env python3
"""Double-cantilever beam bonded by the LDF cohesive element (tools/dcb_deck.py): beam theory and orientation.

  check_dcb.py --exe BIN --out DIR [--c3d8i]     (--c3d8i: only check 5, a test of its own)

1. Correctly oriented mesh (4 C3D8 through each arm, 0.2 mm along it, --max-opening-increment 0.3): the force on the
   propagation branch (total opening 0.33-0.5 mm, past the peak at 0.29 mm
   once the cohesive zone has formed; the crack front at 6-7.5 mm) within 1 % of simple beam theory,
   F^2 = 8 (phi E b^2 h^3/12)^1.5 / (E b h^3 opening). Beam theory leaves out shear (0.6 (h/a)^2 of the compliance,
   about 1 %, so about 0.3 % of the force) and the finite rotations (opening/a about 2 %); a shift of the crack
   length (root rotation, the cohesive zone) does not change this relation. Measured: +0.4 to +0.6 %.
2. The two classic meshing mistakes (faces numbered clockwise; top face given first) are refused before the
   analysis: exit 2, a message naming the mis-oriented elements and their count.
3. With --reorient-interfaces both run (the first 40 increments, up to the peak) and give the force of the correct
   mesh: clockwise is reordered back to the very same connectivity (equal to round-off, 1e-12); swapped lists each
   face's nodes from the other face, so round-off differs and the Newton iterates agree within the Newton
   tolerance (R_n = 0.005): 1e-4 of the peak force (measured 5e-13 Release, 2e-6 Debug).
4. With phi = 0 every one of the 75 cohesive elements rejects its properties (STDB_ABQERR + XIT): exit 2, the
   routine's message printed once and its repeats counted, not 75+ times.
5. C3D8I arms (incompatible modes) with ONE element through each arm's thickness, 0.2 mm along it: the force on
   the propagation branch within 0.5 % of beam theory (measured +0.10 to +0.36 %); C3D8 would lock in bending.
"""
import argparse
import csv
import os
import subprocess
import sys

from ldfcz_tools import dcb_deck

GEN = ["--le", "0.2", "--nz", "4", "--opening", "0.5"]
N_SOLID = 2 * 100 * 4           # C3D8 elements of the deck above: labels 1..800, cohesive from 801 on
N_COHESIVE = 75                 # bonded length 15 mm / 0.2 mm


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, out, flip, extra=()):
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "dcb_%s.inp" % flip)
    with open(deck, "w") as f:
        f.write(dcb_deck.build(0.2, 4, flip, 0.5))
    p = subprocess.run([exe, "-q", "-o", out, "--max-opening-increment", "0.3", *extra, deck],
                       capture_output=True, text=True)
    return p, os.path.join(out, "dcb_%s.csv" % flip), os.path.join(out, "dcb_%s.log" % flip)


def curve(path):
    with open(path) as f:
        return [(2 * float(r["LOAD_TOP.U3"]), float(r["LOAD_TOP.RF3"])) for r in csv.DictReader(f)]


def check_c3d8i(a):
    """Check 5 of the module docstring."""
    out_i = os.path.join(a.out, "c3d8i")
    os.makedirs(out_i, exist_ok=True)
    deck = os.path.join(out_i, "dcb_c3d8i.inp")
    with open(deck, "w") as f:
        f.write(dcb_deck.build(0.2, 1, "none", 0.5, "C3D8I"))
    p = subprocess.run([a.exe, "-q", "-o", out_i, "--max-opening-increment", "0.3", deck], capture_output=True,
                       text=True)
    if p.returncode != 0:
        fail("C3D8I arms: exit %d: %s" % (p.returncode, p.stderr))
    prop = [(u, f) for u, f in curve(os.path.join(out_i, "dcb_c3d8i.csv")) if u >= 0.33]
    if len(prop) < 10:
        fail("C3D8I arms: too few increments on the propagation branch")
    worst = max(abs(f / dcb_deck.beam_theory_force(u) - 1) for u, f in prop)
    print("C3D8I arms, one element through the thickness: %d increments, largest |F/F_beam - 1| = %.4f (limit 0.005)"
          % (len(prop), worst))
    if worst > 0.005:
        fail("C3D8I arms: force off beam theory by more than 0.5 %")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--c3d8i", action="store_true", help="only the DCB with C3D8I arms (check 5)")
    a = ap.parse_args()
    if a.c3d8i:
        check_c3d8i(a)
        print("dcb C3D8I: ok")
        return
    assert GEN  # the deck parameters above are those of dcb_deck.build(0.2, 4, ..., 0.5)

    p, csv_ok, _ = run(a.exe, os.path.join(a.out, "none"), "none")
    if p.returncode != 0:
        fail("correct mesh: exit %d: %s" % (p.returncode, p.stderr))
    ref = curve(csv_ok)
    prop = [(u, f) for u, f in ref if u >= 0.33]
    if len(prop) < 10:
        fail("too few increments on the propagation branch")
    worst = max(abs(f / dcb_deck.beam_theory_force(u) - 1) for u, f in prop)
    print("propagation branch: %d increments, largest |F/F_beam - 1| = %.4f (limit 0.01)" % (len(prop), worst))
    if worst > 0.01:
        fail("force off beam theory by more than 1 %")

    for flip in ("clockwise", "swap"):
        p, _, log = run(a.exe, os.path.join(a.out, flip), flip)
        text = p.stderr
        want = "%d of %d interface elements are mis-oriented: elements %d, %d" % (N_COHESIVE, N_COHESIVE,
                                                                                   N_SOLID + 1, N_SOLID + 2)
        if p.returncode != 2 or want not in text or "--reorient-interfaces" not in text:
            fail("%s: exit %d, message %r (want exit 2 and %r)" % (flip, p.returncode, text, want))
        print("%s mesh refused: ok" % flip)
        p, csv_fix, log = run(a.exe, os.path.join(a.out, flip + "_fixed"), flip,
                              ["--reorient-interfaces", "--stop-after-increments", "40"])
        if p.returncode != 3:
            fail("%s with --reorient-interfaces: exit %d: %s" % (flip, p.returncode, p.stderr))
        with open(log) as f:
            if "reversed the face order of %d interface element" % N_COHESIVE not in f.read():
                fail("%s: the log does not say what was reordered" % flip)
        got = curve(csv_fix)
        if len(got) != 40:
            fail("%s reordered: %d increments, want 40" % (flip, len(got)))
        tol = 1e-12 if flip == "clockwise" else 1e-4
        fmax = max(abs(f) for _, f in ref)
        err = max(abs(g[1] - r[1]) for g, r in zip(got, ref)) / fmax
        print("%s reordered: largest relative force difference %.2e (limit %g)" % (flip, err, tol))
        if err > tol:
            fail("%s reordered differs from the correct mesh" % flip)
    out = os.path.join(a.out, "phi_zero")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "dcb_phi_zero.inp")
    with open(deck, "w") as f:
        f.write(dcb_deck.build(0.2, 4, "none", 0.5).replace("%.10g, %.10g, 0, 1, 1" % (dcb_deck.PHI, dcb_deck.DELTA),
                                                             "0, %.10g, 0, 1, 1" % dcb_deck.DELTA))
    p = subprocess.run([a.exe, "-q", "-o", out, deck], capture_output=True, text=True)
    n_err = p.stderr.count("***ERROR")
    print("phi = 0: exit %d, %d routine error line(s), repeats noted: %s" % (p.returncode, n_err,
                                                                            "repeated" in p.stderr))
    if p.returncode != 2 or n_err != 1 or "repeated" not in p.stderr:
        fail("the UEL's property error should be printed once with its repeats counted: " + p.stderr[:2000])
    print("dcb: ok")


if __name__ == "__main__":
    main()
