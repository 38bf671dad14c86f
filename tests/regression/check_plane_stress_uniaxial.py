#!/usr/bin/env python3
"""The Leonov UMAT's plane-stress branch (NDI = 2, NSHR = 1, NTENS = 3) in uniaxial stress against the 3D UMAT.

  check_plane_stress_uniaxial.py --mp MATERIAL_POINT --out DIR

Runs bin/material_point in mode=uniaxial twice on the same history (tension to ln(lambda_1) = 0.4 at 1e-3/s, a
relaxation hold of 100 s, unloading to 0.1, a superposed 60 degree rotation about axis 3): once with the 3D call
(NTENS = 6; the driver's Newton makes sigma_22 = sigma_33 = 0) and once with plane_stress=yes (NTENS = 3; the driver
makes sigma_22 = 0, the UMAT itself sigma_33 = 0 by its local Newton on the thickness stretch, SDV12). Both are
uniaxial stress on the same axial stretch, so the axial stress, the lateral stretches and the state must agree to
the drivers' equilibrium tolerance (1e-10 of the stress): asked 1e-8 of the peak stress, stretches 1e-8.
"""
import argparse
import csv
import os
import subprocess
import sys

HISTORY = ["segment=strain 0.4 400 80", "segment=hold 0 100 10", "segment=strain 0.1 300 60",
           "rotation=60", "axis=3"]


def run(mp, out, extra):
    res = subprocess.run([mp, "mode=uniaxial", "output=" + out] + HISTORY + extra, capture_output=True, text=True)
    if res.returncode != 0:
        print(res.stdout + res.stderr)
        print("FAIL: material_point " + " ".join(extra))
        sys.exit(1)
    return list(csv.DictReader(open(out)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mp", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    r3 = run(a.mp, os.path.join(a.out, "uniaxial_3d.csv"), ["nstatv=11"])
    rp = run(a.mp, os.path.join(a.out, "uniaxial_plane_stress.csv"), ["nstatv=12", "plane_stress=yes"])
    if len(r3) != len(rp) or len(r3) < 100:
        print("FAIL: rows %d vs %d" % (len(r3), len(rp)))
        sys.exit(1)
    peak = max(abs(float(r["stress"])) for r in r3)
    ds = max(abs(float(p["stress"]) - float(q["stress"])) for p, q in zip(r3, rp)) / peak
    dsig = max(abs(float(p[k]) - float(q[k])) for p, q in zip(r3, rp) for k in ("S11", "S22", "S33", "S12")) / peak
    df = max(abs(float(p[k]) - float(q[k])) for p, q in zip(r3, rp) for k in ("F11", "F12", "F21", "F22", "F33"))
    dg = max(abs(float(p["SDV7"]) - float(q["SDV7"])) for p, q in zip(r3, rp))
    ln_l3 = max(abs(float(q["SDV12"]) - __import__("math").log(float(q["F33"]))) for q in rp)
    print("rows %d, peak axial stress %.3f MPa, plastic strain at the end %.4f" % (len(r3), peak, float(r3[-1]["SDV7"])))
    print("max |axial stress diff| / peak %.2e, max |Cauchy diff| / peak %.2e, max |F diff| %.2e, "
          "max |gamma_p diff| %.2e" % (ds, dsig, df, dg))
    ok = peak > 30.0 and float(r3[-1]["SDV7"]) > 0.1 and ds <= 1e-8 and dsig <= 1e-8 and df <= 1e-8 and dg <= 1e-8 \
        and ln_l3 <= 1e-12
    print("ok" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
