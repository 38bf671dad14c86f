#!/usr/bin/env python3
"""The 2D LDF cohesive user element with an axisymmetric or a plane-stress section between two continuum layers.

  check_cohesive_section.py --exe BIN --out DIR

Two elastic layers (E = 1000 MPa, nu = 0.3, heights 0.4 and 0.6 mm) bonded by a row of U2 cohesive elements
(phi = 0.2 N/mm, delta = 0.05 mm), every node held at u_1 = 0, the bottom at u_2 = 0 and the top pulled to
u_2 = U (10 increments to U = 0.03, NLGEOM=NO): no peeling, a uniform opening Delta and a uniform stress
sigma_22 = M eps in each layer with M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) for CAX4 (eps_rr = eps_tt = 0:
u_r = 0) and M = E / (1 - nu^2) for CPS4 (eps_11 = 0, sigma_33 = 0). Equilibrium across the interface gives
T(Delta) = M eps with T(Delta) = (phi / delta^2) Delta exp(-Delta / delta) (Eq. 20, normal opening) and
U = Delta + eps (h_1 + h_2): Delta from this scalar equation (bisection to 1e-15). The reaction at the top:
  * CAX4 on 1 <= r <= 3, the cohesive element with JPROPS(3) = 1 (axisymmetric): RF_2 = T pi (b^2 - a^2), the total
    over 2 pi of the continuum elements (and Abaqus');
  * CPS4 of thickness 0.25 (*SOLID SECTION), the cohesive element with PROPS(7) = 0.25: RF_2 = T L t.
Asked: 1e-8 relative at every increment (*CONTROLS, PARAMETERS=FIELD: residual 1e-11 of the time-averaged force,
so equilibrium is met to round-off; the default 5e-3 leaves 1e-6 in the reaction); a cohesive element weighting per radian or
per unit thickness would be off by 2 pi or 4.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

E, NU, PHI, DELTA = 1000.0, 0.3, 0.2, 0.05
H1, H2, U_END, STEPS, NX = 0.4, 0.6, 0.03, 10, 4


def traction(d):
    return PHI / DELTA ** 2 * d * math.exp(-d / DELTA)


def opening(u, m):
    lo, hi = 0.0, u
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid + traction(mid) / m * (H1 + H2) > u:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def deck(path, kind):
    x0, x1 = (1.0, 3.0) if kind == "cax" else (0.0, 2.0)
    xs = [x0 + (x1 - x0) * i / NX for i in range(NX + 1)]
    rows = [0.0, H1, H1, H1 + H2]          # bottom, lower interface, upper interface, top
    nid = lambda row, i: row * (NX + 1) + i + 1
    out = ["*HEADING", "Bilayer with a %s cohesive interface (tests/regression/check_cohesive_section.py)" % kind,
           "*NODE, NSET=ALL"]
    for row, z in enumerate(rows):
        for i, x in enumerate(xs):
            out.append("%d, %.15g, %.15g" % (nid(row, i), x, z))
    etype = "CAX4" if kind == "cax" else "CPS4"
    out.append("*ELEMENT, TYPE=%s, ELSET=BULK" % etype)
    e = 0
    for lo, hi in ((0, 1), (2, 3)):
        for i in range(NX):
            e += 1
            out.append("%d, %d, %d, %d, %d" % (e, nid(lo, i), nid(lo, i + 1), nid(hi, i + 1), nid(hi, i)))
    nprops, njprops = (2, 3) if kind == "cax" else (7, 2)
    out += ["*USER ELEMENT, TYPE=U2, NODES=4, COORDINATES=2, PROPERTIES=%d, I PROPERTIES=%d, VARIABLES=8, UNSYMM"
            % (nprops, njprops), "1, 2", "**LDFCZ BUILTIN, UEL=LDF", "*ELEMENT, TYPE=U2, ELSET=COH"]
    for i in range(NX):
        e += 1
        out.append("%d, %d, %d, %d, %d" % (e, nid(1, i), nid(1, i + 1), nid(2, i + 1), nid(2, i)))
    out.append("*UEL PROPERTY, ELSET=COH")
    if kind == "cax":
        out.append("%g, %g, 1, 1, 1" % (PHI, DELTA))
    else:
        out += ["%g, %g, 0, 0, 0, 0, 0.25, 1," % (PHI, DELTA), "1"]
    out += ["*NSET, NSET=BOTTOM"] + [", ".join(str(nid(0, i)) for i in range(NX + 1))]
    out += ["*NSET, NSET=TOP"] + [", ".join(str(nid(3, i)) for i in range(NX + 1))]
    out += ["*SOLID SECTION, ELSET=BULK, MATERIAL=M"] + (["0.25"] if kind == "cps" else [])
    out += ["*MATERIAL, NAME=M", "*ELASTIC", "%g, %g" % (E, NU),
            "*BOUNDARY", "ALL, 1, 1", "BOTTOM, 2, 2",
            "*STEP, NLGEOM=NO, INC=100", "*STATIC, DIRECT", "%g, 1." % (1.0 / STEPS),
            "*CONTROLS, PARAMETERS=FIELD", "1e-11, 1e-10",
            "*BOUNDARY", "TOP, 2, 2, %.15g" % U_END,
            "*NODE PRINT, NSET=TOP, TOTALS=YES", "RF2", "*END STEP"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")
    area = math.pi * (x1 ** 2 - x0 ** 2) if kind == "cax" else (x1 - x0) * 0.25
    m = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) if kind == "cax" else E / (1 - NU ** 2)
    return area, m


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    ok = True
    for kind in ("cax", "cps"):
        path = os.path.join(a.out, "bilayer_%s.inp" % kind)
        area, m = deck(path, kind)
        res = subprocess.run([a.exe, "-q", path], cwd=a.out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
        if res.returncode != 0:
            print(res.stdout)
            print("FAIL: ldfcz exited with %d on %s" % (res.returncode, path))
            sys.exit(1)
        rows = list(csv.DictReader(open(os.path.join(a.out, "bilayer_%s.csv" % kind))))
        worst, n = 0.0, 0
        for r in rows:
            t = float(r["step_time"])
            u = U_END * t
            d = opening(u, m)
            expect = traction(d) * area
            rf = sum(float(v) for k, v in r.items() if k.endswith(".RF2"))
            worst = max(worst, abs(rf - expect) / expect)
            n += 1
        good = n == STEPS and worst <= 1e-8
        ok = ok and good
        print("%s: %d increments, final RF2 %.6f N (expected T(Delta) x area %.6f), max relative error %.2e %s"
              % (kind, n, rf, expect, worst, "ok" if good else "FAIL"))
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
