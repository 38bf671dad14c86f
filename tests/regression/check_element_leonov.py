#!/usr/bin/env python3
"""The built-in Leonov UMAT in ONE element of each continuum type against bin/material_point on the same history.

  check_element_leonov.py --exe BIN --mp MATERIAL_POINT --out DIR

Each deck is one element on the unit cube (unit square, thickness 1, for the plane-strain types) with EVERY node
prescribed on u = (F(t) - I) X, F(t) = I + t/T (F_end - I) with stretch and shear (NLGEOM, T = 300 s, 30 DIRECT
increments: the PET of Table 1 yields). A homogeneous F is reproduced exactly by every type (F-bar: J_c = J;
incompatible modes: f_alpha = sigma F^-T int G_m dV J = 0, so alpha = 0; one-point types: no hourglass force), so
every point calls the UMAT with the F of the driver's mode=deformation. The host's nodal reactions give the first
Piola-Kirchhoff stress: sum_a RF_a (x) X_a = P V0 with P = J sigma F^-T, compared at every increment with the
driver's Cauchy stress: max |P_host - P_driver| <= 1e-8 of the peak (the two differ only by round-off).

Axisymmetric types (CAX4, CAX4R, CAX8, CAX8R): the element on 1 <= r <= 2, 0 <= z <= 1 with r = a R, z = c Z + d R, a
homogeneous F = [[a, 0, 0], [d, c, 0], [0, 0, a]] in (r, z, theta) whose hoop stretch r/R = a is the radial one.
The reactions are totals over 2 pi; the same virtual-work identity with the virtual fields X_j e_i, whose hoop
strain is delta u_r / R, gives sum_a RF_a,i X_a,j = int (P_iJ + delta_ir P_tt X_j / R) dV0: V0 (P_rR + P_tt) for
(r, R), P_rZ V0 + P_tt 2 pi int Z dR dZ = P_rZ V0 + pi P_tt for (r, Z), V0 P_zJ for the z rows, V0 = 3 pi,
P_tt = J sigma_tt / a. Those sums are compared with the driver's stress on the same 3x3 F to 1e-8 of the peak.

Plane-stress types (CPS4, CPS4I, CPS4R, CPS8, CPS8R; DEPVAR 12) against the driver's plane-stress call
(plane_stress=yes, the UMAT's own thickness stretch lambda_3): under NLGEOM the element's thickness is t0 / det F_2D
(J = 1; the inferred Abaqus behaviour, docs/elements.md), so sum_a RF_a (x) X_a = sigma F_2D^-T V0 = P_driver / J_m
with J_m = det F_2D lambda_3 the Leonov's own volume ratio; asked to 1e-8 of the peak, and J_m - 1 is reported.

Plane stress in uniaxial stress (type name CPS4-uniaxial: a CPS4, NLGEOM=NO): the driver in mode=uniaxial with
plane_stress=yes (NTENS = 3, SDV12 = ln lambda_3, the UMAT's own sigma_33 = 0 iteration) gives the uniaxial
stress history with its lateral stretch lambda_2(t) (sigma_22 = 0 to the driver's tolerance); the host's unit
square, thickness 1, has every node on u = diag(lambda_1 - 1, lambda_2 - 1) X through two tabular *AMPLITUDEs
holding the driver's stretches at each increment time (exact there, 15 digits), so the UMAT sees the same DFGRD0,
DFGRD1 in-plane blocks (the Leonov UMAT works from them; DFGRD(3,3) is ignored in plane stress). Without NLGEOM the
forces are f = int B^T sigma dV0, so sum_a RF_a (x) X_a = sigma V0 with the Cauchy stress: compared with the
driver's (sigma_11 and sigma_22 = 0 included) to 1e-8 of the peak, the same round-off rationale.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

PROPS = "1250., 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.990\n200., -4."
F3 = [[1.25, 0.10, 0.0], [0.05, 0.92, 0.03], [0.0, -0.02, 0.95]]
F2 = [[1.25, 0.10, 0.0], [0.05, 0.92, 0.0], [0.0, 0.0, 1.0]]
FAX = [[1.18, 0.0, 0.0], [0.05, 0.72, 0.0], [0.0, 0.0, 1.18]]   # (r, z, theta): hoop = radial stretch, J = 1.0025
T, STEPS = 300.0, 30

CORNERS3 = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
HEX20_EDGES = [(1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5), (1, 5), (2, 6), (3, 7), (4, 8)]
TET_EDGES = [(1, 2), (2, 3), (3, 1), (1, 4), (2, 4), (3, 4)]
CORNERS2 = [(0, 0), (1, 0), (1, 1), (0, 1)]
QUAD_EDGES = [(1, 2), (2, 3), (3, 4), (4, 1)]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def nodes_of(etype):
    if etype.startswith("C3D4") or etype.startswith("C3D10"):
        x = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
        edges = TET_EDGES if etype == "C3D10" else []
    elif etype == "C3D6":
        # the wedge: triangle 1-2-3 counter-clockwise seen from the top face 4-5-6 (Abaqus), volume 1/2
        x = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1)]
        edges = []
    elif etype.startswith("C3D"):
        x = list(CORNERS3)
        edges = HEX20_EDGES if etype.startswith("C3D20") else []
    elif etype.startswith("CAX"):
        x = [(1.0 + p[0], p[1]) for p in CORNERS2]
        edges = QUAD_EDGES if etype.startswith("CAX8") else []
    else:
        x = list(CORNERS2)
        edges = QUAD_EDGES if etype.startswith(("CPE8", "CPS8")) else []
    for a, b in edges:
        x.append(tuple(0.5 * (p + q) for p, q in zip(x[a - 1], x[b - 1])))
    return x


def deck(path, etype):
    x = nodes_of(etype)
    nd = len(x[0])
    f = F3 if nd == 3 else (FAX if etype.startswith("CAX") else F2)
    out = ["*HEADING", "Leonov UMAT, one %s, homogeneous F (tests/regression/check_element_leonov.py)" % etype,
           "*NODE, NSET=ALL"]
    out += ["%d, %s" % (i + 1, ", ".join("%.15g" % c for c in p)) for i, p in enumerate(x)]
    conn = ", ".join(str(i + 1) for i in range(len(x)))
    out += ["*ELEMENT, TYPE=%s, ELSET=E" % etype]
    if len(x) > 15:
        out += ["1, " + ", ".join(str(i + 1) for i in range(15)) + ",",
                ", ".join(str(i + 1) for i in range(15, len(x)))]
    else:
        out += ["1, " + conn]
    for i in range(len(x)):
        out += ["*NSET, NSET=N%d" % (i + 1), "%d," % (i + 1)]
    out += ["*SOLID SECTION, ELSET=E, MATERIAL=PET", "*MATERIAL, NAME=PET", "**LDFCZ BUILTIN, UMAT=LEONOV",
            "*USER MATERIAL, CONSTANTS=10, UNSYMM",
            PROPS, "*DEPVAR", "12" if etype.startswith("CPS") else "11", "**LDFCZ STATEV, MATERIAL=PET, PLASTIC STRAIN=7",
            "*STEP, NLGEOM=YES, INC=1000", "*STATIC, DIRECT", "%g, %g" % (T / STEPS, T), "*BOUNDARY"]
    for i, p in enumerate(x):
        for d in range(nd):
            u = sum(f[d][c] * p[c] for c in range(nd)) - p[d]
            out.append("%d, %d, %d, %.15g" % (i + 1, d + 1, d + 1, u))
    for i in range(len(x)):
        out += ["*NODE PRINT, NSET=N%d, TOTALS=YES" % (i + 1), "RF1, RF2" + (", RF3" if nd == 3 else "")]
    out += ["*END STEP"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")
    return x, f


def det3(a):
    return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))


def inv3(a):
    d = det3(a)
    c = [[a[1][1] * a[2][2] - a[1][2] * a[2][1], a[0][2] * a[2][1] - a[0][1] * a[2][2],
          a[0][1] * a[1][2] - a[0][2] * a[1][1]],
         [a[1][2] * a[2][0] - a[1][0] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0],
          a[0][2] * a[1][0] - a[0][0] * a[1][2]],
         [a[1][0] * a[2][1] - a[1][1] * a[2][0], a[0][1] * a[2][0] - a[0][0] * a[2][1],
          a[0][0] * a[1][1] - a[0][1] * a[1][0]]]
    return [[c[i][j] / d for j in range(3)] for i in range(3)]


def amplitude(name, times, values):
    pairs = ["%.15g, %.15g" % tv for tv in zip(times, values)]
    return ["*AMPLITUDE, NAME=%s, DEFINITION=TABULAR" % name] + [", ".join(pairs[i:i + 4])
                                                                  for i in range(0, len(pairs), 4)]


def plane_stress_case(a):
    """CPS4, NLGEOM=NO, uniaxial stress against material_point plane_stress=yes (module docstring)."""
    csv_path = os.path.join(a.out, "mp_cps.csv")
    res = subprocess.run([a.mp, "mode=uniaxial", "plane_stress=yes", "nstatv=12", "rate=%.15g" % (0.3 / T),
                          "strain_end=0.3", "steps=%d" % STEPS, "output=" + csv_path], capture_output=True, text=True)
    if res.returncode != 0:
        fail("material_point (plane stress) failed: " + res.stderr)
    drv = list(csv.DictReader(open(csv_path)))
    times = [float(r["time"]) for r in drv]
    lam = [[float(r["F11"]) for r in drv], [float(r["F22"]) for r in drv]]
    x = list(CORNERS2)
    out = ["*HEADING", "Leonov UMAT, one CPS4 in uniaxial stress, NLGEOM=NO (tests/regression/check_element_leonov.py)",
           "*NODE, NSET=ALL"] + ["%d, %g, %g" % (i + 1, p[0], p[1]) for i, p in enumerate(x)]
    out += ["*ELEMENT, TYPE=CPS4, ELSET=E", "1, 1, 2, 3, 4"]
    for i in range(len(x)):
        out += ["*NSET, NSET=N%d" % (i + 1), "%d," % (i + 1)]
    out += amplitude("L1", times, [v - 1.0 for v in lam[0]]) + amplitude("L2", times, [v - 1.0 for v in lam[1]])
    out += ["*SOLID SECTION, ELSET=E, MATERIAL=PET", "1.", "*MATERIAL, NAME=PET",
            "**LDFCZ BUILTIN, UMAT=LEONOV", "*USER MATERIAL, CONSTANTS=10, UNSYMM",
            PROPS, "*DEPVAR", "12", "**LDFCZ STATEV, MATERIAL=PET, PLASTIC STRAIN=7",
            "*STEP, NLGEOM=NO, INC=1000", "*STATIC, DIRECT", "%g, %g" % (T / STEPS, T), "*BOUNDARY"]
    for i, p in enumerate(x):
        for d in range(2):
            if p[d] == 0:
                out.append("%d, %d, %d, 0." % (i + 1, d + 1, d + 1))
    out += ["*BOUNDARY, AMPLITUDE=L1"] + ["%d, 1, 1, 1." % (i + 1) for i, p in enumerate(x) if p[0] == 1]
    out += ["*BOUNDARY, AMPLITUDE=L2"] + ["%d, 2, 2, 1." % (i + 1) for i, p in enumerate(x) if p[1] == 1]
    for i in range(len(x)):
        out += ["*NODE PRINT, NSET=N%d, TOTALS=YES" % (i + 1), "RF1, RF2"]
    out += ["*END STEP"]
    path = os.path.join(a.out, "cps4.inp")
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")
    res = subprocess.run([a.exe, "-q", path], cwd=a.out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("ldfcz exited with %d on %s" % (res.returncode, path))
    by_time = {round(t, 6): r for t, r in zip(times, drv)}
    worst, peak, n = 0.0, 0.0, 0
    for r in csv.DictReader(open(os.path.join(a.out, "cps4.csv"))):
        mp = by_time.get(round(float(r["step_time"]), 6))
        if mp is None:
            continue
        s = [float(mp[k]) for k in ("S11", "S22", "S12")]
        sig = [[s[0], s[2]], [s[2], s[1]]]
        # V0 = 1 (unit square, thickness 1)
        s_host = [[sum(float(r["N%d.RF%d" % (k + 1, i + 1)]) * x[k][j] for k in range(len(x))) for j in range(2)]
                  for i in range(2)]
        for i in range(2):
            for j in range(2):
                worst = max(worst, abs(s_host[i][j] - sig[i][j]))
                peak = max(peak, abs(sig[i][j]))
        n += 1
    ok = n == STEPS and peak > 25.0 and worst <= 1e-8 * peak
    print("%-7s increments %d, peak |sigma| %.3f MPa, max |sigma_host - sigma_driver| / peak %.2e %s"
          % ("CPS4", n, peak, worst / max(peak, 1e-300), "ok" if ok else "FAIL"))
    if not ok:
        fail("CPS4 (plane stress, NLGEOM=NO)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--mp", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--types",
                    default="C3D8,C3D8I,C3D8R,C3D20,C3D20R,C3D4,C3D10,C3D6,CPE4,CPE4I,CPE4R,CPE8,CPE8R,CAX4,CAX4R,"
                    "CAX8,CAX8R,CPS4,CPS4I,CPS4R,CPS8,CPS8R,CPS4-uniaxial")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    drivers = {}
    for nd, f in ((3, F3), (2, F2), ("ax", FAX), ("ps", F2)):
        csv_path = os.path.join(a.out, "mp_%sd.csv" % nd)
        extra = ["plane_stress=yes", "nstatv=12"] if nd == "ps" else []
        res = subprocess.run([a.mp, "mode=deformation", "time_end=%g" % T, "steps=%d" % STEPS,
                              "f_end=" + " ".join("%.15g" % v for row in f for v in row), "output=" + csv_path] + extra,
                             capture_output=True, text=True)
        if res.returncode != 0:
            fail("material_point failed: " + res.stderr)
        drivers[nd] = {round(float(r["time"]), 6): r for r in csv.DictReader(open(csv_path))}
    for etype in a.types.split(","):
        if etype == "CPS4-uniaxial":
            plane_stress_case(a)
            continue
        job = etype.lower()
        path = os.path.join(a.out, job + ".inp")
        x, f_end = deck(path, etype)
        nd = len(x[0])
        axi = etype.startswith("CAX")
        pstress = etype.startswith("CPS")
        vol = 1.0 / 6.0 if etype in ("C3D4", "C3D10") else (3.0 * math.pi if axi else (0.5 if etype == "C3D6" else 1.0))
        res = subprocess.run([a.exe, "-q", path], cwd=a.out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
        if res.returncode != 0:
            print(res.stdout)
            fail("ldfcz exited with %d on %s" % (res.returncode, path))
        worst, peak, n, jm_dev = 0.0, 0.0, 0, 0.0
        for r in csv.DictReader(open(os.path.join(a.out, job + ".csv"))):
            t = round(float(r["step_time"]), 6)
            mp = drivers["ax" if axi else ("ps" if pstress else nd)].get(t)
            if mp is None:
                continue
            fm = [[float(mp["F%d%d" % (i + 1, j + 1)]) for j in range(3)] for i in range(3)]
            s = [float(mp[k]) for k in ("S11", "S22", "S33", "S12", "S13", "S23")]
            sig = [[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]]
            fit = inv3(fm)
            jd = det3(fm)
            if pstress:
                # the element's thickness is t0 / det F_2D (J = 1, docs/elements.md "Plane stress"), not the
                # UMAT's own t0 lambda_3 (F33 of the driver): P_host = sigma F^-T = P_driver / J_m
                jm_dev = max(jm_dev, abs(jd - 1.0))
                jd = 1.0
            p_drv = [[jd * sum(sig[i][k] * fit[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
            p_host = [[sum(float(r["N%d.RF%d" % (a_ + 1, i + 1)]) * x[a_][j] for a_ in range(len(x))) / vol
                       for j in range(nd)] for i in range(nd)]
            if axi:
                # remove the hoop parts of the virtual-work sums (module docstring)
                p_tt = p_drv[2][2]
                p_host[0][0] -= p_tt
                p_host[0][1] -= p_tt * math.pi / vol
            for i in range(nd):
                for j in range(nd):
                    worst = max(worst, abs(p_host[i][j] - p_drv[i][j]))
                    peak = max(peak, abs(p_drv[i][j]))
            n += 1
        ok = n == STEPS and peak > 30.0 and worst <= 1e-8 * peak
        print("%-7s increments %d, peak |P| %.3f MPa, max |P_host - P_driver| / peak %.2e%s %s"
              % (etype, n, peak, worst / max(peak, 1e-300),
                 ", Leonov's own J_m = det F_2D lambda_3 differs from the element's J = 1 by up to %.2e" % jm_dev
                 if pstress else "", "ok" if ok else "FAIL"))
        if not ok:
            fail(etype)
    print("PASS")


if __name__ == "__main__":
    main()
