#!/usr/bin/env python3
"""Plane stress under NLGEOM with the built-in *ELASTIC: a uniaxial stretch against its closed form.

  check_plane_stress_nlgeom.py --exe BIN --out DIR

One element (CPS4, CPS4I, CPS4R) on [0, 2] x [0, 1], section thickness t0 = 0.5, E = 1000, nu = 0.3: x = 0 held at
u_1 = 0 (node 1 also u_2 = 0), x = 2 pulled to the stretch lambda_1 = 1.5 in N = 20 increments, lateral contraction
free. The hypoelastic law (Abaqus' linear elasticity under NLGEOM, docs/elements.md) with the Hughes-Winget
increment d = 2 (l_k - l_k-1) / (l_k + l_k-1) of each increment of the axial stretch l gives, in uniaxial stress:
  sigma_11 = E sum d,   lateral: d_22 = -nu d, so lambda_2,k = lambda_2,k-1 (2 - nu d) / (2 + nu d),
  thickness (plane stress, sigma_33 = 0): d eps_33 = -nu/(1 - nu) (d + d_22) = -nu d, lambda_3,k = lambda_3,k-1 e^(-nu d)
and the axial force RF_1 = sigma_11 (H lambda_2) (t0 lambda_3). Asked: 1e-9 relative at every increment (residual
tolerance tightened with *CONTROLS); without the thickness stretch the force would be off by 1 - lambda_3 = 11 %.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

E, NU, T0, L, H, LAM_END, N = 1000.0, 0.3, 0.5, 2.0, 1.0, 1.5, 20


def deck(path, etype):
    out = ["*HEADING", "Plane stress uniaxial stretch under NLGEOM (tests/regression/check_plane_stress_nlgeom.py)",
           "*NODE", "1, 0., 0.", "2, %g, 0." % L, "3, %g, %g" % (L, H), "4, 0., %g" % H,
           "*ELEMENT, TYPE=%s, ELSET=E" % etype, "1, 1, 2, 3, 4",
           "*NSET, NSET=LEFT", "1, 4", "*NSET, NSET=RIGHT", "2, 3",
           "*SOLID SECTION, ELSET=E, MATERIAL=M", "%g" % T0, "*MATERIAL, NAME=M", "*ELASTIC", "%g, %g" % (E, NU),
           "*BOUNDARY", "LEFT, 1, 1", "1, 2, 2",
           "*STEP, NLGEOM=YES, INC=100", "*STATIC, DIRECT", "%g, 1." % (1.0 / N),
           "*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-11",
           "*BOUNDARY", "RIGHT, 1, 1, %.15g" % ((LAM_END - 1.0) * L),
           "*NODE PRINT, NSET=RIGHT, TOTALS=YES", "RF1", "*END STEP"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


def closed_form():
    sig, l2, l3, prev, forces = 0.0, 1.0, 1.0, 1.0, []
    for k in range(1, N + 1):
        lam = 1.0 + (LAM_END - 1.0) * k / N
        d = 2.0 * (lam - prev) / (lam + prev)
        sig += E * d
        l2 *= (2.0 - NU * d) / (2.0 + NU * d)
        l3 *= math.exp(-NU * d)
        prev = lam
        forces.append(sig * H * l2 * T0 * l3)
    return forces, l3


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    expect, l3 = closed_form()
    ok = True
    for etype in ("CPS4", "CPS4I", "CPS4R"):
        job = "uniaxial_" + etype.lower()
        path = os.path.join(a.out, job + ".inp")
        deck(path, etype)
        res = subprocess.run([a.exe, "-q", path], cwd=a.out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
        if res.returncode != 0:
            print(res.stdout)
            print("FAIL: ldfcz exited with %d on %s" % (res.returncode, path))
            sys.exit(1)
        rows = list(csv.DictReader(open(os.path.join(a.out, job + ".csv"))))
        worst = max(abs(float(r["RIGHT.RF1"]) - f) / abs(f) for r, f in zip(rows, expect))
        good = len(rows) == N and worst <= 1e-9
        ok = ok and good
        print("%-6s %d increments, final RF1 %.9f (closed form %.9f, thickness stretch %.6f), max rel. error %.2e %s"
              % (etype, len(rows), float(rows[-1]["RIGHT.RF1"]), expect[-1], l3, worst, "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
