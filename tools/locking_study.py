#!/usr/bin/env python3
"""Volumetric locking of each continuum type: the thick cylinder under bore pressure (plane strain) with a nearly
incompressible material, against Lame.

  python3 tools/locking_study.py --exe build/bin/ldfcz [--out DIR] [--nu 0.4999]

The quarter ring 1 < r < 2 under bore pressure p = 1 (decks of tests/regression/check_loads.py: CPE4-family and
C3D8-family on 8 x 24 elements, one element thick with u3 = 0; CPE8/C3D20 families on 4 x 8 with curved edges;
CAX on 16 (linear) or 8 (quadratic) radial elements with u_z = 0), *ELASTIC E = 1000 with nu = 0.3 and nu = 0.4999,
NLGEOM=NO. Printed: the bore displacement over Lame's u(a) = (1 + nu)/E ((1 - 2 nu) A a + B / a) for both nu. Near
nu = 0.5 the exact field is divergence-free; an element that cannot represent it with the bulk modulus 1700 times
the shear modulus locks: its ratio falls far below 1 (the F-bar / B-bar types, reduced-integration quadratic
types and one-point types do not). A study command (docs/elements.md "Volumetric locking"), not a test.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "regression"))
import check_loads as cl  # noqa: E402

A, B, P = 1.0, 2.0, 1.0


def with_nu_and_type(writer, nu, etype, base):
    def w(path):
        writer(path)
        text = open(path).read().replace("*ELASTIC\n1000., 0.3", "*ELASTIC\n1000., %r" % nu)
        if base:
            text = text.replace("*ELEMENT, TYPE=%s," % base, "*ELEMENT, TYPE=%s," % etype)
        open(path, "w").write(text)
    return w


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", default="locking_study")
    ap.add_argument("--nu", type=float, default=0.4999)
    a = ap.parse_args()
    a.exe = os.path.abspath(a.exe)   # the runs are made in --out
    cases = []
    for t in ("CPE4", "CPE4I", "CPE4R"):
        cases.append((t, "8 x 24", lambda d: cl.ring_deck(d, A, B, 8, 24, P), "CPE4"))
    for t in ("C3D8", "C3D8I", "C3D8R"):
        cases.append((t, "8 x 24 x 1", lambda d: cl.ring_deck(d, A, B, 8, 24, P, three_d=True), "C3D8"))
    for t in ("CPE8", "CPE8R", "C3D20", "C3D20R"):
        cases.append((t, "4 x 8", (lambda tt: lambda d: cl.quadratic_ring_deck(d, tt, A, B, 4, 8, P))(t), None))
    for t, n in (("CAX4", 16), ("CAX8", 8), ("CAX8R", 8)):
        cases.append((t, "%d" % n, (lambda tt, nn: lambda d: cl.axisymmetric_cylinder_deck(d, tt, A, B, nn, P))(t, n),
                      None))
    print("%-7s %-11s %14s %14s" % ("type", "mesh", "u/u_Lame 0.3", "u/u_Lame %g" % a.nu))
    for etype, mesh, writer, base in cases:
        ratios = []
        for nu in (0.3, a.nu):
            job = "lock_%s_%s" % (etype.lower(), str(nu).replace(".", "p"))
            rows = cl.run(a.exe, a.out, job, with_nu_and_type(writer, nu, etype, base))
            ratios.append(rows[-1]["RIN.U1"] / cl.lame(A, A, B, P, 1000.0, nu))
        print("%-7s %-11s %14.4f %14.4f" % (etype, mesh, ratios[0], ratios[1]))


if __name__ == "__main__":
    main()
