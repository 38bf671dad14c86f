#!/usr/bin/env python3
"""Newton convergence of a UMAT under NLGEOM with and without *ORIENTATION (docs/host.md, "Local orientations").

  python3 tools/orientation_newton_study.py --exe build/bin/ldfcz [--out DIR]

A cantilever of 8 C3D8 (8 x 1 x 1, root clamped) of the hypoelastic orthotropic UMAT tests/regression/user_umat_ortho.f90
(--user), bent under NLGEOM by a fixed-direction tip force of 3 N in z (tip rotation about 50 degrees, stress about
0.1 E), automatic increments (initial 0.1, maximum 0.25): (a) without orientation (the material axes follow the
Jaumann spin), (b) with an identity *ORIENTATION (the axes follow the polar rotation R, T = R: the tangent leaves
out dT/du), (c) with the axes turned by 30 degrees about z (another material response, for the scale only).
Prints increments, attempts, cutbacks, Newton iterations and the tip displacement of each, and the residual ratios
of the first increments, from the runs' JOB.sta and JOB.csv.
"""
import argparse
import os
import subprocess
import sys

PROPS = [1000.0, 400.0, 250.0, 0.25, 0.15, 0.3, 150.0, 120.0, 90.0]
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT


def deck(path, orient_angle):
    nx, length = 8, 8.0
    lab = lambda i, j, k: 1 + i + (nx + 1) * (j + 2 * k)
    lines = ["*Heading", "orthotropic cantilever (tools/orientation_newton_study.py)", "*Node"]
    for k in range(2):
        for j in range(2):
            for i in range(nx + 1):
                lines.append("%d, %g, %g, %g" % (lab(i, j, k), length * i / nx, j, k))
    lines.append("*Element, type=C3D8, elset=B")
    for i in range(nx):
        n = [lab(i, 0, 0), lab(i + 1, 0, 0), lab(i + 1, 1, 0), lab(i, 1, 0), lab(i, 0, 1), lab(i + 1, 0, 1),
             lab(i + 1, 1, 1), lab(i, 1, 1)]
        lines.append("%d, %s" % (i + 1, ", ".join(map(str, n))))
    lines += ["*Nset, nset=ROOT", ", ".join(str(lab(0, j, k)) for j in range(2) for k in range(2)),
              "*Nset, nset=TIP", ", ".join(str(lab(nx, j, k)) for j in range(2) for k in range(2))]
    if orient_angle is None:
        lines += ["*Solid Section, elset=B, material=O"]
    else:
        lines += ["*Orientation, name=ORI", "1., 0., 0., 0., 1., 0.", "3, %g" % orient_angle,
                  "*Solid Section, elset=B, material=O, orientation=ORI"]
    lines += ["*Material, name=O", "*User Material, constants=9", ", ".join("%g" % p for p in PROPS[:8]),
              "%g" % PROPS[8], "*Step, nlgeom=YES, inc=200", "*Static", "0.1, 1., 1e-5, 0.25", "*Boundary",
              "ROOT, 1, 3", "*Cload", "TIP, 3, 0.75", "*Node Print, nset=TIP", "U1, U3", "*End Step"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", default="orientation_newton_study")
    o = ap.parse_args()
    executable(o.exe, 'ldfcz program')
    out = os.path.abspath(o.out)
    os.makedirs(out, exist_ok=True)
    user = os.path.join(ROOT, "tests", "regression", "user_umat_ortho.f90")
    for job, angle, what in (("none", None, "no orientation"), ("identity", 0.0, "identity axes (T = R)"),
                             ("turned", 30.0, "axes turned 30 deg about z")):
        path = os.path.join(out, job + ".inp")
        deck(path, angle)
        res = subprocess.run([os.path.abspath(o.exe), "-q", "--user", user, "--out", out, path],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        with open(os.path.join(out, job + ".sta")) as f:
            sta = [l.split() for l in f if not l.startswith("#")]
        conv = [w for w in sta if w[6] == "converged"]
        iters = sum(int(w[3]) for w in sta)
        with open(os.path.join(out, job + ".csv")) as f:
            last = f.read().splitlines()[-1].split(",")
        print("%-28s exit %d: %2d increments, %2d attempts (%d cutbacks), %3d Newton iterations, tip U1 %.4f U3 %.4f"
              % (what, res.returncode, len(conv), len(sta), len(sta) - len(conv), iters, float(last[4]),
                 float(last[5])))
        for w in sta[:3]:
            print("    inc %s attempt %s: r/q %s" % (w[1], w[2], " ".join(w[w.index("r/q:") + 1:])))


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('orientation_newton_study'))
