#!/usr/bin/env python3
"""Plane stress with a UMAT under NLGEOM: uniaxial stretch to 1.5 and a rigid 90 degree rotation.

  check_plane_stress_umat.py --exe BIN --user tests/regression/user_umat_neohooke.f90 --out DIR

One element (CPS4, CPS4I, CPS4R) on [0, 2] x [0, 1], section thickness t0 = 0.5, the neo-Hookean user UMAT with
mu = 1, lambda = 2000 (nearly incompressible: lambda / mu = 2000, nu = 0.49975), which finds its own thickness
stretch from sigma_33 = 0 (NTENS = 3). The element's thickness is t0 F33 with F33 = 1 / det F_2D (the inferred
Abaqus behaviour, docs/elements.md "Plane stress").

Step 1: x = 0 held at u_1 = 0 (node 1 also u_2 = 0), x = 2 pulled to the stretch l1 = 1.5 in 20 increments, lateral
contraction free. Uniaxial stress in the material: l2 = l3 = s with mu (s^2 - 1) + lambda ln(l1 s^2) = 0 and
sigma_11 = mu (l1^2 - s^2) / J, J = l1 s^2; the element's width H s and thickness t0 / (l1 s) give
  RF_1 = sigma_11 (H s) t0 / (l1 s) = sigma_11 H t0 / l1                           (asked 1e-9 at every increment)
and against the INCOMPRESSIBLE closed form sigma = mu (l1^2 - 1/l1) on the width H / sqrt(l1) and thickness
t0 / sqrt(l1), RF_inc = mu (l1^2 - 1/l1) H t0 / l1: the difference is first order in mu / lambda (0.47 mu / lambda
at l1 = 1.5, about mu / (3 lambda) near l1 = 1), asked within mu / lambda = 5e-4.
Steps 2-10: every node on u = R(theta) x1 - X with x1 = (l1 X, s Y) the stretched element, theta = 10 .. 90
degrees (the increments move along chords; the stress of the hyperelastic UMAT depends on the end state only): the
total reaction of the nodes at X = 2 is R(theta) (RF_1, 0), both components asked to 1e-9 of RF_1.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

MU, LAM, T0, L, H, LAM_END, N, NROT = 1.0, 2000.0, 0.5, 2.0, 1.0, 1.5, 20, 9


def lateral(l1):
    """s = l2 = l3 of the compressible neo-Hookean law in uniaxial stress (Newton on x = ln s)."""
    x = -0.5 * math.log(l1)
    for _ in range(60):
        g = MU * (math.exp(2 * x) - 1) + LAM * (math.log(l1) + 2 * x)
        dx = -g / (2 * MU * math.exp(2 * x) + 2 * LAM)
        x += dx
        if abs(dx) <= 1e-16:
            break
    return math.exp(x)


def reaction(l1):
    s = lateral(l1)
    sig = MU * (l1 ** 2 - s ** 2) / (l1 * s ** 2)
    return sig * H * T0 / l1, s


def deck(path, etype):
    l1 = LAM_END
    rf, s = reaction(l1)
    out = ["*HEADING", "Plane stress UMAT under NLGEOM (tests/regression/check_plane_stress_umat.py)",
           "*NODE", "1, 0., 0.", "2, %g, 0." % L, "3, %g, %g" % (L, H), "4, 0., %g" % H,
           "*ELEMENT, TYPE=%s, ELSET=E" % etype, "1, 1, 2, 3, 4",
           "*NSET, NSET=LEFT", "1, 4", "*NSET, NSET=RIGHT", "2, 3",
           "*SOLID SECTION, ELSET=E, MATERIAL=M", "%g" % T0, "*MATERIAL, NAME=M",
           "*USER MATERIAL, CONSTANTS=2", "%g, %g" % (MU, LAM),
           "*BOUNDARY", "LEFT, 1, 1", "1, 2, 2",
           "*STEP, NLGEOM=YES, INC=100", "*STATIC, DIRECT", "%g, 1." % (1.0 / N),
           "*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-11",
           "*BOUNDARY", "RIGHT, 1, 1, %.17g" % ((l1 - 1.0) * L),
           "*NODE PRINT, NSET=RIGHT, TOTALS=YES", "RF1, RF2", "*END STEP"]
    xy = [(0.0, 0.0), (L, 0.0), (L, H), (0.0, H)]
    for k in range(1, NROT + 1):
        th = math.radians(90.0 * k / NROT)
        c, sn = math.cos(th), math.sin(th)
        out += ["*STEP, NLGEOM=YES, INC=100", "*STATIC, DIRECT", "1., 1.",
                "*CONTROLS, PARAMETERS=FIELD", "1e-12, 1e-11", "*BOUNDARY"]
        for n, (X, Y) in enumerate(xy, start=1):
            x1, y1 = l1 * X, s * Y
            out.append("%d, 1, 1, %.17g" % (n, c * x1 - sn * y1 - X))
            out.append("%d, 2, 2, %.17g" % (n, sn * x1 + c * y1 - Y))
        out += ["*NODE PRINT, NSET=RIGHT, TOTALS=YES", "RF1, RF2", "*END STEP"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--user", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    ok = True
    for etype in ("CPS4", "CPS4I", "CPS4R"):
        job = "umat_" + etype.lower()
        path = os.path.join(a.out, job + ".inp")
        deck(path, etype)
        res = subprocess.run([a.exe, "-q", path, "--user", a.user], cwd=a.out, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        if res.returncode != 0:
            print(res.stdout)
            print("FAIL: ldfcz exited with %d on %s" % (res.returncode, path))
            sys.exit(1)
        # the loud warning of the inferred thickness (standard error with -q, and JOB.log)
        warned = "F33 = 1/det(F_2D)" in res.stdout and "F33 = 1/det(F_2D)" in open(
            os.path.join(a.out, job + ".log")).read()
        rows = list(csv.DictReader(open(os.path.join(a.out, job + ".csv"))))
        s1 = [r for r in rows if int(r["step"]) == 1]
        err_c, err_i = 0.0, 0.0
        for r in s1:
            l1 = 1.0 + (LAM_END - 1.0) * float(r["step_time"])
            rf, _ = reaction(l1)
            rf_inc = MU * (l1 ** 2 - 1.0 / l1) * H * T0 / l1
            got = float(r["RIGHT.RF1"])
            err_c = max(err_c, abs(got - rf) / abs(rf))
            err_i = max(err_i, abs(got - rf_inc) / abs(rf_inc))
        rf_end, _ = reaction(LAM_END)
        err_r = 0.0
        nrot = 0
        for k in range(2, NROT + 2):
            last = [r for r in rows if int(r["step"]) == k]
            if not last:
                continue
            nrot += 1
            th = math.radians(90.0 * (k - 1) / NROT)
            want = (math.cos(th) * rf_end, math.sin(th) * rf_end)
            got = (float(last[-1]["RIGHT.RF1"]), float(last[-1]["RIGHT.RF2"]))
            err_r = max(err_r, max(abs(g - w) for g, w in zip(got, want)) / rf_end)
        good = (len(s1) == N and nrot == NROT and err_c <= 1e-9 and err_i <= MU / LAM and err_r <= 1e-9
                and warned)
        ok = ok and good
        print("%-6s RF1 at l1 = 1.5: %.10f (exact %.10f, incompressible %.10f); max rel. error: exact %.2e, "
              "incompressible %.2e (asked %.0e); after the rotation steps %.2e; warning %s  %s"
              % (etype, float(s1[-1]["RIGHT.RF1"]), rf_end, MU * (LAM_END ** 2 - 1 / LAM_END) * H * T0 / LAM_END,
                 err_c, err_i, MU / LAM, err_r, "yes" if warned else "MISSING", "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
