#!/usr/bin/env python3
"""Volumetric locking of each continuum type: the thick cylinder under bore pressure (plane strain) with a nearly
incompressible material, against Lame.

  python3 tools/locking_study.py --exe build/bin/ldfcz [--out DIR] [--nu 0.4999]

The quarter ring 1 < r < 2 under bore pressure p = 1 (decks of tests/regression/check_loads.py: CPE4-family and
C3D8-family on 8 x 24 elements, one element thick with u3 = 0; CPE8/C3D20 families on 4 x 8 with curved edges;
CAX on 16 (linear) or 8 (quadratic) radial elements with u_z = 0; C3D4 and C3D10: the hexahedra of the C3D8 (8 x 24)
or C3D20 (4 x 8) ring, one layer thick with u3 = 0, each split into 6 tetrahedra around its diagonal (Freudenthal /
Kuhn: conforming between neighbours), C3D10 mid-side nodes at the (r, theta, z) midpoints, i.e. on the arcs),
*ELASTIC E = 1000 with nu = 0.3 and nu = 0.4999,
NLGEOM=NO. Printed: the bore displacement over Lame's u(a) = (1 + nu)/E ((1 - 2 nu) A a + B / a) for both nu. Near
nu = 0.5 the exact field is divergence-free; an element that cannot represent it with the bulk modulus 1700 times
the shear modulus locks: its ratio falls far below 1 (the F-bar / B-bar types, reduced-integration quadratic
types and one-point types do not). A study command (docs/elements.md "Volumetric locking"), not a test.
"""
import argparse
import math
import os
import subprocess
import sys

from ldfcz_tools import outputs
from ldfcz_tools import ring_decks as cl
from ldfcz_tools.cli import executable

A, B, P = 1.0, 2.0, 1.0


# the 6 tetrahedra of a hexahedron (corners 0-3 at z = 0 counter-clockwise, 4-7 above) around its diagonal 0-6
KUHN = ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6))
TET_EDGES = ((0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3))            # C3D10 mid-side nodes 5..10
TET_FACES = {1: (0, 1, 2), 2: (0, 3, 1), 3: (1, 3, 2), 4: (2, 3, 0)}    # S1..S4 (Abaqus)


def tet_ring_deck(path, etype, a, b, nr, nt, p, h=0.1):
    """Quarter ring a < r < b, one layer 0 < z < h, nr x nt hexahedral cells in (r, theta) split into 6 tetrahedra
    each (C3D4, or C3D10 with mid-side nodes at the parametric midpoints: on the arcs); u2 = 0 on theta = 0,
    u1 = 0 on theta = 90 deg, u3 = 0 everywhere, *DSLOAD p on the bore faces, *ELASTIC E = 1000, nu = 0.3."""
    quad = etype == "C3D10"
    ids, pts = {}, []

    def node(q):            # q: doubled parametric indices (2i, 2j, 2k), mid-side nodes at odd entries
        if q not in ids:
            ids[q] = len(ids) + 1
            r = a + (b - a) * q[0] / (2.0 * nr)
            t = 0.5 * math.pi * q[1] / (2.0 * nt)
            pts.append((ids[q], r * math.cos(t), r * math.sin(t), h * q[2] / 2.0))
        return ids[q]

    def x(q):
        return pts[ids[q] - 1][1:]

    elems, bore = [], {f: [] for f in TET_FACES}
    for j in range(nt):
        for i in range(nr):
            cube = [(2 * i, 2 * j, 0), (2 * i + 2, 2 * j, 0), (2 * i + 2, 2 * j + 2, 0), (2 * i, 2 * j + 2, 0)]
            cube += [(c[0], c[1], 2) for c in cube]
            for tet in KUHN:
                c = [cube[v] for v in tet]
                for q in c:
                    node(q)
                x0, x1, x2, x3 = (x(q) for q in c)
                d = [[x1[m] - x0[m], x2[m] - x0[m], x3[m] - x0[m]] for m in range(3)]
                vol = (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] -
                       d[1][2] * d[2][0]) + d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]))
                if vol < 0:                     # 1-2-3 counter-clockwise seen from 4
                    c[1], c[2] = c[2], c[1]
                conn = [node(q) for q in c]
                if quad:
                    conn += [node(tuple((c[e0][m] + c[e1][m]) // 2 for m in range(3))) for e0, e1 in TET_EDGES]
                elems.append(conn)
                for f, loc in TET_FACES.items():
                    if all(c[v][0] == 0 for v in loc):
                        bore[f].append(len(elems))
    out = ["*HEADING", "quarter ring of tetrahedra, %s (tools/locking_study.py)" % etype, "*NODE, NSET=ALL"]
    out += ["%d, %.15g, %.15g, %.15g" % q for q in pts]
    out.append("*ELEMENT, TYPE=%s, ELSET=RING" % etype)
    out += ["%d, %s" % (e + 1, ", ".join(str(n) for n in c)) for e, c in enumerate(elems)]
    out += ["*NSET, NSET=RIN", "%d," % ids[(0, 0, 0)], "*NSET, NSET=T0"]
    out += ["%d," % v for q, v in sorted(ids.items(), key=lambda kv: kv[1]) if q[1] == 0]
    out += ["*NSET, NSET=T90"] + ["%d," % v for q, v in sorted(ids.items(), key=lambda kv: kv[1]) if q[1] == 2 * nt]
    surf = []
    for f, els in bore.items():
        if els:
            out += ["*ELSET, ELSET=BORE%d" % f] + ["%d," % e for e in els]
            surf.append("BORE%d, S%d" % (f, f))
    out += ["*SOLID SECTION, ELSET=RING, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3",
            "*SURFACE, NAME=BORE"] + surf
    out += ["*BOUNDARY", "T0, 2, 2", "T90, 1, 1", "ALL, 3, 3", "*STEP, NLGEOM=NO", "*STATIC", "1., 1.",
            "*DSLOAD", "BORE, P, %.15g" % p, "*NODE PRINT, NSET=RIN", "U1", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def with_nu_and_type(writer, nu, etype, base):
    def w(path):
        writer(path)
        text = open(path).read().replace("*ELASTIC\n1000., 0.3", "*ELASTIC\n1000., %r" % nu)
        if base:
            text = text.replace("*ELEMENT, TYPE=%s," % base, "*ELEMENT, TYPE=%s," % etype)
        open(path, "w").write(text)
    return w


def run(exe, out, job, deck_writer):
    """Write the deck out/JOB.inp, run it in out; the rows of JOB.csv (the study stops on a failed run)."""
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, job + ".inp")
    deck_writer(deck)
    res = subprocess.run([exe, "-q", deck], cwd=out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        sys.exit("locking_study: ldfcz exited with %d on %s" % (res.returncode, deck))
    return outputs.read_csv(os.path.join(out, job + ".csv"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", default=os.path.join("out", "locking_study"))
    ap.add_argument("--nu", type=float, default=0.4999)
    a = ap.parse_args()
    executable(a.exe, 'ldfcz program')
    a.exe = os.path.abspath(a.exe)   # the runs are made in --out
    cases = []
    for t in ("CPE4", "CPE4I", "CPE4R"):
        cases.append((t, "8 x 24", lambda d: cl.ring_deck(d, A, B, 8, 24, P), "CPE4"))
    for t in ("C3D8", "C3D8I", "C3D8R"):
        cases.append((t, "8 x 24 x 1", lambda d: cl.ring_deck(d, A, B, 8, 24, P, three_d=True), "C3D8"))
    for t in ("CPE8", "CPE8R", "C3D20", "C3D20R"):
        cases.append((t, "4 x 8", (lambda tt: lambda d: cl.quadratic_ring_deck(d, tt, A, B, 4, 8, P))(t), None))
    for t, n in (("CAX4", 16), ("CAX4R", 16), ("CAX8", 8), ("CAX8R", 8)):
        cases.append((t, "%d" % n, (lambda tt, nn: lambda d: cl.axisymmetric_cylinder_deck(d, tt, A, B, nn, P))(t, n),
                      None))
    for t, mesh, nr, nt in (("C3D4", "8 x 24 x 1 x 6", 8, 24), ("C3D10", "4 x 8 x 1 x 6", 4, 8)):
        cases.append((t, mesh, (lambda tt, n1, n2: lambda d: tet_ring_deck(d, tt, A, B, n1, n2, P))(t, nr, nt), None))
    print("%-7s %-14s %14s %14s" % ("type", "mesh", "u/u_Lame 0.3", "u/u_Lame %g" % a.nu))
    for etype, mesh, writer, base in cases:
        ratios = []
        for nu in (0.3, a.nu):
            job = "lock_%s_%s" % (etype.lower(), str(nu).replace(".", "p"))
            rows = run(a.exe, a.out, job, with_nu_and_type(writer, nu, etype, base))
            ratios.append(rows[-1]["RIN.U1"] / cl.lame(A, A, B, P, 1000.0, nu))
        print("%-7s %-14s %14.4f %14.4f" % (etype, mesh, ratios[0], ratios[1]))


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('locking_study'))
