#!/usr/bin/env python3
"""*PRE-TENSION SECTION against the closed forms of a bar cut by the section (docs/host.md, "Pre-tension sections").

  check_pretension.py --exe BIN --out DIR --case NAME

The decks (written into DIR) are a bar along x, L = 10, section 1 x 1, E = 1000, nu = 0 (so that the state is
uniaxial and every element type here reproduces it exactly), its end faces x = 0 and x = L held along x (rigid
motions across held at two nodes of x = 0), cut at x = a = 4 by the faces x = a of the elements on its left
(surface CUT; those elements move with the section), pre-tension node P (a node of no element). With A = 1 and
the force N across the section, both parts carry N: u(x) = N x / EA left of the cut, -N (L - x) / EA right of it
(the nodes at x = a are the right part's: the model's nodes are not split in the output), u_P = N L / EA (the
relative displacement of the two sides along the normal), the end reactions -N and +N. Tolerances 1e-9 of the
largest value: linear elastic, exact for the mesh; round-off only.

Cases:
  force_2d      CPE4 10 x 2, the normal computed (the faces' outward normal, +x), *CLOAD F = 5 on P's dof 1: N = F
                (tension); the *NODE PRINT tables of every node and of a set of all nodes list exactly the deck's
                nodes (no duplicated section node shows).
  fixed_2d      two steps: the force of force_2d, then P held by *BOUNDARY, FIXED while a force Q = 3 (+x) acts on
                the face x = b = 7 (consistent nodal forces Q/4, Q/2, Q/4): two springs from x = b, k1 = EA/b and
                k2 = EA/(L-b), the section's force becomes F + Q (L - b) / L (the reaction at P), u_P stays F L/EA,
                u(b) grows by Q b (L - b) / (E A L).
  mod_2d        as fixed_2d with *BOUNDARY, OP=MOD, P, 1, 1, F L/EA (the length step 1 reached) instead of FIXED:
                the same results (1e-9).
  reversed_3d   C3D8 10 x 2 x 2, the normal given on the data line as (-1, 0, 0), into the moving side: dof 1 is
                the relative displacement along that normal, so F = 5 compresses the bar (N = -F), u_P = F L / EA.
  tet_3d        C3D4 (each cube of a 10 x 2 x 2 grid in six tetrahedra): elements that touch the section at an
                edge or a vertex only move with it when they lie on its side; the closed form of force_2d.
  length_2d     the length change prescribed, *BOUNDARY P, 1, 2, 0.01 (dof 2 is not active: warned at its line):
                N = EA u_P / L, the reaction at P equal to N.
  nlgeom_2d     force_2d under NLGEOM with F = 0.1 (strain 1e-4): the reactions -F and +F to 1e-6 (equilibrium to
                the Newton tolerance),
                u_P = F L / EA within 1e-3 (the strain measures differ by the order of the strain).
"""
import argparse
import csv
import os
import re
import subprocess
import sys

E, L, A, XA, XB = 1000.0, 10.0, 1.0, 4.0, 7.0
F, Q = 5.0, 3.0


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check(name, got, want, tol):
    if not abs(got - want) <= tol:
        fail("%s: got %.12g want %.12g (tolerance %.3g)" % (name, got, want, tol))
    print("ok %s: %.10g (want %.10g)" % (name, got, want))


def run(exe, out, job, text):
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, job), path], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s%s" % (job, r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
    with open(os.path.join(out, job, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, job, job + ".dat")) as f:
        return rows, f.read()


class Bar:
    """The bar's mesh: CPE4 (2D), C3D8 or C3D4 (3D); the section's surface and the deck around it."""

    def __init__(self, kind, nx=10, ny=2, nz=2):
        self.kind, self.nx, self.ny = kind, nx, ny
        self.nz = nz if kind != "CPE4" else 0
        self.x = {}
        for k in range(self.nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    self.x[self.nid(i, j, k)] = [L * i / nx, j / ny, k / nz if self.nz else 0.0]
        self.icut = int(round(XA / L * nx))

    def nid(self, i, j, k=0):
        return 1 + i + (self.nx + 1) * (j + (self.ny + 1) * k)

    def elements(self):
        """(label, nodes, column, face label on x = a or None)."""
        out, e = [], 0
        for k in range(max(self.nz, 1)):
            for j in range(self.ny):
                for i in range(self.nx):
                    n = self.nid
                    if self.kind == "CPE4":
                        e += 1
                        out.append((e, [n(i, j), n(i + 1, j), n(i + 1, j + 1), n(i, j + 1)], i, "S2"))
                        continue
                    c = [n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k), n(i, j, k + 1),
                         n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1), n(i, j + 1, k + 1)]
                    if self.kind == "C3D8":
                        e += 1
                        out.append((e, c, i, "S4"))
                        continue
                    # Kuhn's six tetrahedra of the cube along its diagonal c0 -> c6 (positive volumes)
                    for p in ([0, 1, 2, 6], [0, 2, 3, 6], [0, 3, 7, 6], [0, 7, 4, 6], [0, 4, 5, 6], [0, 5, 1, 6]):
                        e += 1
                        out.append((e, [c[q] for q in p], i, None))
        return out

    def cut_faces(self):
        """The faces on x = a of the elements of the column left of it."""
        faces = []
        tet_faces = {"S1": [0, 1, 2], "S2": [0, 3, 1], "S3": [1, 3, 2], "S4": [2, 3, 0]}
        for e, nodes, col, face in self.elements():
            if col != self.icut - 1:
                continue
            if self.kind != "C3D4":
                faces.append((e, face))
                continue
            for lab, loc in tet_faces.items():
                if all(abs(self.x[nodes[q]][0] - XA) < 1e-12 for q in loc):
                    faces.append((e, lab))
        return faces

    def deck(self, steps, normal=None, nlgeom=False):
        nd = 2 if self.kind == "CPE4" else 3
        lines = ["*HEADING", "bar cut by a pre-tension section", "*NODE, NSET=ALLN"]
        lines += ["%d, %s" % (n, ", ".join(repr(c) for c in p[:nd])) for n, p in sorted(self.x.items())]
        lines += ["1000, 0., 0.%s" % (", 0." if nd == 3 else ""), "*NSET, NSET=P", "1000"]
        lines.append("*ELEMENT, TYPE=%s, ELSET=BAR" % self.kind)
        lines += ["%d, %s" % (e, ", ".join(map(str, c))) for e, c, _, _ in self.elements()]
        left = sorted(n for n, p in self.x.items() if p[0] == 0.0)
        right = sorted(n for n, p in self.x.items() if p[0] == L)
        lines += ["*NSET, NSET=LEFT", ", ".join(map(str, left)), "*NSET, NSET=RIGHT", ", ".join(map(str, right))]
        for n in self.bottom():
            lines += ["*NSET, NSET=N%d" % n, str(n)]
        lines += ["*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "1." if nd == 2 else "",
                  "*MATERIAL, NAME=STEEL", "*ELASTIC", "%r, 0." % E, "*SURFACE, NAME=CUT"]
        lines = [x for x in lines if x != ""]
        lines += ["%d, %s" % (e, f) for e, f in self.cut_faces()]
        lines.append("*PRE-TENSION SECTION, SURFACE=CUT, NODE=P")
        if normal:
            lines.append(", ".join(repr(c) for c in normal))
        lines += ["*BOUNDARY", "LEFT, 1, 1", "RIGHT, 1, 1", "%d, 2, %d" % (self.nid(0, 0), nd)]
        if nd == 3:
            lines.append("%d, 3, 3" % self.nid(0, self.ny, 0))
        prints = ["*NODE PRINT, NSET=P", "U1, RF1", "*NODE PRINT, NSET=LEFT", "RF1", "*NODE PRINT, NSET=RIGHT", "RF1"]
        prints += ["*NODE PRINT, NSET=N%d\nU1" % n for n in self.bottom()]
        for s in steps:
            lines += ["*STEP%s" % (", NLGEOM=YES" if nlgeom else ""), "*STATIC", "1., 1."] + s + prints + \
                ["*END STEP"]
        return "\n".join(lines) + "\n"

    def bottom(self):
        return [self.nid(i, 0) for i in range(self.nx + 1)]

    def face_b_loads(self):
        """Consistent nodal forces of a total Q along +x on the face x = b."""
        ib = int(round(XB / L * self.nx))
        out = []
        for k in range(self.nz + 1):
            for j in range(self.ny + 1):
                wy = (0.5 if j in (0, self.ny) else 1.0) / self.ny
                wz = 1.0 if not self.nz else (0.5 if k in (0, self.nz) else 1.0) / self.nz
                out.append("%d, 1, %r" % (self.nid(i=ib, j=j, k=k), Q * wy * wz))
        return out


def last(rows, col):
    return float(rows[-1][col])


def step_rows(rows, step):
    return [r for r in rows if int(r["step"]) == step]


def check_bar(bar, rows, n_force, label, f_applied=F):
    """Displacements along the bottom row, u_P and the end reactions against the closed form of force N."""
    umax = abs(n_force) * L / (E * A)
    check(label + " u_P", last(rows, "P.U1"), f_applied * L / (E * A), 1e-9 * umax)
    for n in bar.bottom():
        x = bar.x[n][0]
        want = n_force * x / (E * A) if x < XA - 1e-9 else -n_force * (L - x) / (E * A)
        check("%s U1 at x = %g" % (label, x), last(rows, "N%d.U1" % n), want, 1e-9 * umax)
    check(label + " RF1 left", last(rows, "LEFT.RF1"), -n_force, 1e-9 * abs(n_force))
    check(label + " RF1 right", last(rows, "RIGHT.RF1"), n_force, 1e-9 * abs(n_force))


def printed_nodes(dat, nset):
    """Node labels of the last *NODE PRINT table of set nset in JOB.dat."""
    blocks = dat.split("THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET " + nset)
    if len(blocks) < 2:
        fail("no table for set " + nset)
    table = blocks[-1].split(" MAXIMUM")[0]
    return [int(m.group(1)) for m in re.finditer(r"^\s+(\d+)\s+[-+0-9.E]+", table, re.M)]


def case_force_2d(exe, out):
    bar = Bar("CPE4")
    text = bar.deck([["*CLOAD", "P, 1, %r" % F]]).replace("*END STEP", "*NODE PRINT, NSET=ALLN\nU\n*END STEP")
    rows, dat = run(exe, out, "force_2d", text)
    check_bar(bar, rows, F, "force_2d")
    if printed_nodes(dat, "ALLN") != sorted(bar.x) + [1000]:
        fail("the table of set ALLN lists %s, not the deck's nodes" % printed_nodes(dat, "ALLN")[:40])
    print("ok: the table of set ALLN lists the deck's %d nodes once each" % (len(bar.x) + 1))


def two_step(exe, out, job, hold):
    bar = Bar("CPE4")
    rows, _ = run(exe, out, job, bar.deck([["*CLOAD", "P, 1, %r" % F],
                                           hold + ["*CLOAD, OP=NEW"] + bar.face_b_loads()]))
    s2 = step_rows(rows, 2)
    n_sec = F + Q * (L - XB) / L
    check(job + " bolt force (reaction at P)", last(s2, "P.RF1"), n_sec, 1e-9 * n_sec)
    check(job + " u_P held", last(s2, "P.U1"), F * L / (E * A), 1e-9 * F * L / (E * A))
    ib = bar.nid(int(round(XB / L * bar.nx)), 0)
    want = -F * (L - XB) / (E * A) + Q * XB * (L - XB) / (E * A * L)
    check(job + " U1 at x = b", last(s2, "N%d.U1" % ib), want, 1e-9 * F * L / (E * A))
    check(job + " RF1 left", last(s2, "LEFT.RF1"), -n_sec, 1e-9 * n_sec)
    check(job + " RF1 right", last(s2, "RIGHT.RF1"), F - Q * XB / L, 1e-9 * n_sec)
    return s2


def case_fixed_2d(exe, out):
    two_step(exe, out, "fixed_2d", ["*BOUNDARY, FIXED", "P, 1, 1"])


def case_mod_2d(exe, out):
    a = two_step(exe, out, "mod_2d", ["*BOUNDARY, OP=MOD", "P, 1, 1, %r" % (F * L / (E * A))])
    b = two_step(exe, out, "mod_2d_fixed", ["*BOUNDARY, FIXED", "P, 1, 1"])
    for col in a[-1]:
        if "." in col and not col.endswith("time"):
            check("OP=MOD against FIXED " + col, float(a[-1][col]), float(b[-1][col]), 1e-9 * F)


def case_reversed_3d(exe, out):
    bar = Bar("C3D8")
    rows, _ = run(exe, out, "reversed_3d", bar.deck([["*CLOAD", "P, 1, %r" % F]], normal=(-1.0, 0.0, 0.0)))
    check_bar(bar, rows, -F, "reversed_3d")


def case_tet_3d(exe, out):
    bar = Bar("C3D4")
    rows, _ = run(exe, out, "tet_3d", bar.deck([["*CLOAD", "P, 1, %r" % F]]))
    check_bar(bar, rows, F, "tet_3d")


def case_length_2d(exe, out):
    bar = Bar("CPE4")
    up = 0.01
    text = bar.deck([["*BOUNDARY", "P, 1, 2, %r" % up]])
    path = os.path.join(out, "length_2d.inp")
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, "length_2d"), path], capture_output=True, text=True)
    line = text.split("\n").index("P, 1, 2, %r" % up) + 1
    want = "length_2d.inp:%d: *BOUNDARY: dofs 2.. of pre-tension node 1000 are not active" % line
    if r.returncode != 0 or want not in r.stderr:
        fail("length_2d: exit %d, expected 0 and the warning '%s'; stderr: %s" % (r.returncode, want, r.stderr))
    print("ok: warned at line %d (dof 2 of the pre-tension node is not active)" % line)
    rows, _ = run(exe, out, "length_2d", text)
    n_force = E * A * up / L
    check_bar(bar, rows, n_force, "length_2d", f_applied=n_force)
    check("length_2d bolt force (reaction at P)", last(rows, "P.RF1"), n_force, 1e-9 * n_force)


def case_nlgeom_2d(exe, out):
    bar = Bar("CPE4")
    f = 0.1
    rows, _ = run(exe, out, "nlgeom_2d", bar.deck([["*CLOAD", "P, 1, %r" % f]], nlgeom=True))
    # equilibrium to the Newton tolerance (the converged residual; measured 5e-9 of f)
    check("nlgeom_2d RF1 left", last(rows, "LEFT.RF1"), -f, 1e-6 * f)
    check("nlgeom_2d RF1 right", last(rows, "RIGHT.RF1"), f, 1e-6 * f)
    check("nlgeom_2d u_P", last(rows, "P.U1"), f * L / (E * A), 1e-3 * f * L / (E * A))


CASES = {"force_2d": case_force_2d, "fixed_2d": case_fixed_2d, "mod_2d": case_mod_2d,
         "reversed_3d": case_reversed_3d, "tet_3d": case_tet_3d, "nlgeom_2d": case_nlgeom_2d,
         "length_2d": case_length_2d}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    CASES[a.case](a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
