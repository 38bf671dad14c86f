#!/usr/bin/env python3
"""*COUPLING (*KINEMATIC, *DISTRIBUTING) and *EQUATION over node sets against statics, closed forms and twin decks.

  check_couplings.py --exe BIN --out DIR --case NAME

The decks (written into DIR) are a C3D8I cantilever, L = 10 along x, 1 x 1 section, E = 1000, nu = 0, 20 x 2 x 2
elements, its root face x = 0 encastred, its tip face x = L (surface TIPS) coupled to a reference node R away from
the face; every root and tip node is a node set of its own, so that JOB.csv holds its U and RF to all digits.

Cases:
  kinematic     *KINEMATIC, R at (L + 2, 0.7, 0.4) (off the face's centre), a force F = (0.3, -0.2, 0.5) and a
                torque of 0.4 about x at R (*CLOAD on dof 4). Statics, exact for any mesh: the root reactions sum to
                -F and their moment about the origin to -(x_R x F + M) (1e-9 of |F| L: round-off); the tip face moves
                as a rigid body, u_a - u_b = theta x (x_a - x_b) for the least-squares theta of the face (1e-9 of
                the largest tip displacement), and R with it: u_R = u_a + theta x (x_R - x_a) (1e-9); beam
                theory: the tip's mean deflection under the z force alone (F = 0.01, R on the axis at L + 2)
                against Euler-Bernoulli + Timoshenko shear, w = F L^3/3EI + F L/(kGA) + F d L^2/2EI with the
                offset moment F d (d = 2), within 1 % (C3D8I on 20 x 2 x 2; measured -0.1 %).
  kinematic_twin  *KINEMATIC 1, 3 with R's rotations held by *BOUNDARY R, 4, 6 under NLGEOM (the coupling is exact
                there: every tip node follows R's translation) against the twin deck writing u_tip - u_R = 0 as
                *EQUATION over node sets (the tip set against R, a single node used in every equation): every
                displacement and the root reactions within 1e-9.
  distributing  *DISTRIBUTING (dofs 1..6), R and the loads of 'kinematic': the root statics as there (the force and
                moment reach the root whatever the distribution); and the definition of the reference node's motion:
                u_R = sum w_n u_n + theta x (x_R - x_bar), theta = T^-1 sum w_n r_n x u_n, w_n the normalized
                tributary areas of the tip nodes on the face (1/16, 1/8, 1/4 of the cell area for corner, edge and
                inner nodes of the 2 x 2 face), from the printed tip displacements: within 1e-9 of |u_R|.
  distributing_twin  *DISTRIBUTING 1, 3 (translations), R at the face's centre, force F at R, against the twin deck
                with the same three constraints as *EQUATION (sum w_n u_n,i - u_R,i = 0, a tip node's dof first):
                every displacement and root reaction within 1e-9; *DISTRIBUTING 1, 2 runs as 1, 3 with a warning
                (Abaqus constrains every translation of a distributing coupling; 1e-12).
  kinematic_2d  a CPE4 cantilever 20 x 2 (L = 10, h = 1), *KINEMATIC with R at (L + 1, 0.8), force (0.2, -0.5) and
                a moment 0.3 (*CLOAD dof 6) at R: the root reactions' sum and moment equal -F and -(x_R x F + M)
                (1e-9), the tip edge rigid (1e-9).
  equation_sets *EQUATION over node sets: two unsorted sets written in reverse label order, a sorted set written
                out of order and a single node in every equation, against the same equations written node by
                node: identical results (1e-12); sets of different sizes are refused naming the line of the term.
  equation_chain  a chain of *EQUATIONs (u_17,2 = u_16,2 written before u_16,2 = u_12,2: the dof the second one
                eliminates is a retained term of the first, as Abaqus allows) against the twin deck that writes both
                against node 12 directly: identical results (1e-12: both solve the same reduced system; the chain
                is resolved by substitution with weights 1); two equations that eliminate each other's retained
                dofs, u17 = (u16 + u12)/2 and u16 = (u17 + u12)/2, against the same twin (1e-12: the row that
                comes back to its own slave is solved for it); two equations that are one (u17 = u16 twice, in
                both orders) refused as dependent; a node of no element defined by an equation (midway between
                two nodes) and loaded: the force reaches the two nodes half each (against the twin that loads them
                so, 1e-12), and a one-term equation holds its dof at zero (against *BOUNDARY).
"""
import argparse
import csv
import math
import os
import subprocess
import sys

E = 1000.0


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check(name, got, want, tol):
    if not abs(got - want) <= tol:
        fail("%s: got %.12g want %.12g (tolerance %.3g)" % (name, got, want, tol))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def solve3(a, b):
    """Solve the 3 x 3 system a x = b (Cramer)."""
    def det(m):
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    d = det(a)
    x = []
    for j in range(3):
        m = [row[:] for row in a]
        for i in range(3):
            m[i][j] = b[i]
        x.append(det(m) / d)
    return x


def run(exe, out, job, text, expect=0):
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, job), path], capture_output=True, text=True)
    if r.returncode != expect:
        fail("%s: exit %d (expected %d)\n%s%s" % (job, r.returncode, expect, r.stdout[-2000:], r.stderr[-2000:]))
    if expect != 0:
        return r.stderr + r.stdout
    with open(os.path.join(out, job, job + ".csv")) as f:
        return list(csv.DictReader(f))


class Beam:
    """The cantilever's mesh (3D C3D8I or 2D CPE4) and the deck text around its coupling."""

    def __init__(self, three_d=True, nx=20, ny=2, nz=2, length=10.0):
        self.three_d, self.nx, self.ny, self.nz, self.L = three_d, nx, ny, nz, length
        self.x = {}
        nz1 = nz + 1 if three_d else 1
        for k in range(nz1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    self.x[self.nid(i, j, k)] = [length * i / nx, j / ny, (k / nz) if three_d else 0.0]
        self.root = sorted(n for n, p in self.x.items() if p[0] == 0.0)
        self.tip = sorted(n for n, p in self.x.items() if p[0] == length)

    def nid(self, i, j, k=0):
        return 1 + i + (self.nx + 1) * (j + (self.ny + 1) * k)

    def mesh(self, ref):
        nd = 3 if self.three_d else 2
        lines = ["*HEADING", "cantilever with a coupling at its tip", "*NODE"]
        lines += ["%d, %s" % (n, ", ".join(repr(c) for c in p[:nd])) for n, p in sorted(self.x.items())]
        lines.append("100000, %s" % ", ".join(repr(c) for c in ref[:nd]))
        lines.append("*NSET, NSET=REF\n100000")
        lines.append("*ELEMENT, TYPE=%s, ELSET=BEAM" % ("C3D8I" if self.three_d else "CPE4"))
        e, tip = 0, []
        for k in range(self.nz if self.three_d else 1):
            for j in range(self.ny):
                for i in range(self.nx):
                    e += 1
                    q = [self.nid(i, j, k), self.nid(i + 1, j, k), self.nid(i + 1, j + 1, k), self.nid(i, j + 1, k)]
                    if self.three_d:
                        q += [self.nid(i, j, k + 1), self.nid(i + 1, j, k + 1), self.nid(i + 1, j + 1, k + 1),
                              self.nid(i, j + 1, k + 1)]
                    lines.append("%d, %s" % (e, ", ".join(map(str, q))))
                    if i == self.nx - 1:
                        tip.append(e)
        lines.append("*ELSET, ELSET=TIPE\n" + ", ".join(map(str, tip)))
        lines.append("*NSET, NSET=ROOT\n" + ", ".join(map(str, self.root)))
        lines.append("*NSET, NSET=TIPN\n" + ", ".join(map(str, self.tip)))
        for n in self.root + self.tip:
            lines.append("*NSET, NSET=N%d\n%d" % (n, n))
        lines.append("*SURFACE, NAME=TIPS\nTIPE, %s" % ("S4" if self.three_d else "S2"))
        lines += ["*SOLID SECTION, ELSET=BEAM, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "%r, 0." % E]
        return lines

    def prints(self):
        lines = ["*NODE PRINT, NSET=REF", "U"]
        for n in self.root:
            lines += ["*NODE PRINT, NSET=N%d" % n, "RF"]
        for n in self.tip:
            lines += ["*NODE PRINT, NSET=N%d" % n, "U"]
        return lines


def vec(row, name, var, nd=3):
    return [float(row["%s.%s%d" % (name, var, i + 1)]) for i in range(nd)] + [0.0] * (3 - nd)


def statics(beam, row, ref, force, moment, tol_rel=1e-9):
    """Root reactions: sum -F, moment about the origin -(x_R x F + M)."""
    nd = 3 if beam.three_d else 2
    s = [0.0, 0.0, 0.0]
    m = [0.0, 0.0, 0.0]
    for n in beam.root:
        rf = vec(row, "N%d" % n, "RF", nd)
        s = [a + b for a, b in zip(s, rf)]
        m = [a + b for a, b in zip(m, cross(beam.x[n], rf))]
    scale = math.sqrt(sum(f * f for f in force)) * beam.L
    for i in range(3):
        check("root reaction sum %d" % (i + 1), s[i], -force[i], tol_rel * scale)
    want = [-(a + b) for a, b in zip(cross(ref, force), moment)]
    for i in range(3):
        check("root reaction moment %d" % (i + 1), m[i], want[i], tol_rel * scale)
    print("statics: reaction sum %s, moment %s (want %s)" % (s, m, want))


def rigid_theta(beam, row, nd):
    """Least-squares rotation of the tip face from its nodes' displacements (small rotation)."""
    u = {n: vec(row, "N%d" % n, "U", nd) for n in beam.tip}
    xc = [sum(beam.x[n][i] for n in beam.tip) / len(beam.tip) for i in range(3)]
    uc = [sum(u[n][i] for n in beam.tip) / len(beam.tip) for i in range(3)]
    if nd == 2:
        num = sum((beam.x[n][0] - xc[0]) * (u[n][1] - uc[1]) - (beam.x[n][1] - xc[1]) * (u[n][0] - uc[0])
                  for n in beam.tip)
        den = sum((beam.x[n][0] - xc[0]) ** 2 + (beam.x[n][1] - xc[1]) ** 2 for n in beam.tip)
        return [0.0, 0.0, num / den], u
    a = [[0.0] * 3 for _ in range(3)]
    b = [0.0, 0.0, 0.0]
    for n in beam.tip:
        r = sub(beam.x[n], xc)
        rr = sum(c * c for c in r)
        for i in range(3):
            for j in range(3):
                a[i][j] += (rr if i == j else 0.0) - r[i] * r[j]
        b = [p + q for p, q in zip(b, cross(r, sub(u[n], uc)))]
    return solve3(a, b), u


def rigid_face(beam, row, ref):
    nd = 3 if beam.three_d else 2
    theta, u = rigid_theta(beam, row, nd)
    umax = max(max(abs(c) for c in v) for v in u.values())
    a = beam.tip[0]
    for n in beam.tip:
        want = [p + q for p, q in zip(u[a], cross(theta, sub(beam.x[n], beam.x[a])))]
        for i in range(nd):
            check("rigid tip face: node %d U%d" % (n, i + 1), u[n][i], want[i], 1e-9 * umax)
    ur = vec(row, "REF", "U", nd)
    want = [p + q for p, q in zip(u[a], cross(theta, sub(ref, beam.x[a])))]
    for i in range(nd):
        check("reference node follows the face: U%d" % (i + 1), ur[i], want[i], 1e-9 * umax)
    print("rigid tip face and reference node: theta %s" % theta)


def coupling_deck(beam, ref, kind_lines, loads, nlgeom="NO", extra=()):
    lines = beam.mesh(ref)
    lines += ["*COUPLING, CONSTRAINT NAME=C1, REF NODE=REF, SURFACE=TIPS"] + list(kind_lines)
    lines += ["*BOUNDARY", "ROOT, ENCASTRE"] + list(extra)
    lines += ["*STEP, NLGEOM=%s" % nlgeom, "*STATIC", "1., 1.", "*CLOAD"] + list(loads)
    lines += beam.prints() + ["*END STEP"]
    return "\n".join(lines) + "\n"


def case_kinematic(exe, out):
    beam = Beam()
    ref = [beam.L + 2.0, 0.7, 0.4]
    force, moment = [0.3, -0.2, 0.5], [0.4, 0.0, 0.0]
    loads = ["REF, %d, %r" % (i + 1, force[i]) for i in range(3)] + ["REF, 4, %r" % moment[0]]
    row = run(exe, out, "kinematic", coupling_deck(beam, ref, ["*KINEMATIC"], loads))[-1]
    statics(beam, row, ref, force, moment)
    rigid_face(beam, row, ref)
    # beam theory: a transverse force F at R on the axis, d = 2 beyond the tip
    f, d = 0.01, 2.0
    ref = [beam.L + d, 0.5, 0.5]
    row = run(exe, out, "kinematic_beam", coupling_deck(beam, ref, ["*KINEMATIC"], ["REF, 3, %r" % f]))[-1]
    w = sum(float(row["N%d.U3" % n]) for n in beam.tip) / len(beam.tip)
    i_area, g_mod, k_shear = 1.0 / 12.0, E / 2.0, 5.0 / 6.0
    want = f * beam.L ** 3 / (3 * E * i_area) + f * beam.L / (k_shear * g_mod) + f * d * beam.L ** 2 / (2 * E * i_area)
    print("tip deflection %.8g, beam theory %.8g (%+.3f %%)" % (w, want, 100 * (w / want - 1)))
    check("tip deflection against beam theory", w, want, 0.01 * want)


def case_kinematic_twin(exe, out):
    beam = Beam()
    ref = [beam.L + 2.0, 0.7, 0.4]
    loads = ["REF, 1, 0.3", "REF, 2, -0.2", "REF, 3, 0.5"]
    kin = coupling_deck(beam, ref, ["*KINEMATIC", "1, 3"], loads, nlgeom="YES", extra=["REF, 4, 6"])
    eq = ["*EQUATION"] + ["2\nTIPN, %d, 1., REF, %d, -1." % (d, d) for d in (1, 2, 3)]
    lines = beam.mesh(ref) + eq + ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP, NLGEOM=YES", "*STATIC", "1., 1.",
                                   "*CLOAD"] + loads + beam.prints() + ["*END STEP"]
    a = run(exe, out, "kinematic_fixed_rotation", kin)[-1]
    b = run(exe, out, "kinematic_equation_twin", "\n".join(lines) + "\n")[-1]
    compare_rows(a, b, 1e-9)


def compare_rows(a, b, rtol):
    keys = [k for k in a if "." in k]
    scale = {}
    for k in keys:
        var = k.split(".")[1][:-1]
        scale[var] = max(scale.get(var, 0.0), abs(float(a[k])))
    for k in keys:
        var = k.split(".")[1][:-1]
        check("twin " + k, float(a[k]), float(b[k]), rtol * scale[var])
    print("%d columns equal to the twin deck's within %g of each variable's largest value" % (len(keys), rtol))


def tip_weights(beam):
    """Normalized tributary areas of the tip nodes on the regular face grid."""
    w = {}
    for n in beam.tip:
        j = round(beam.x[n][1] * beam.ny)
        k = round(beam.x[n][2] * beam.nz)
        w[n] = (0.5 if j in (0, beam.ny) else 1.0) * (0.5 if k in (0, beam.nz) else 1.0)
    s = sum(w.values())
    return {n: v / s for n, v in w.items()}


def case_distributing(exe, out):
    beam = Beam()
    ref = [beam.L + 2.0, 0.7, 0.4]
    force, moment = [0.3, -0.2, 0.5], [0.4, 0.0, 0.0]
    loads = ["REF, %d, %r" % (i + 1, force[i]) for i in range(3)] + ["REF, 4, %r" % moment[0]]
    row = run(exe, out, "distributing", coupling_deck(beam, ref, ["*DISTRIBUTING, WEIGHTING METHOD=UNIFORM",
                                                                  "1, 6"], loads))[-1]
    statics(beam, row, ref, force, moment)
    w = tip_weights(beam)
    u = {n: vec(row, "N%d" % n, "U") for n in beam.tip}
    xb = [sum(w[n] * beam.x[n][i] for n in beam.tip) for i in range(3)]
    a = [[0.0] * 3 for _ in range(3)]
    b = [0.0, 0.0, 0.0]
    for n in beam.tip:
        r = sub(beam.x[n], xb)
        rr = sum(c * c for c in r)
        for i in range(3):
            for j in range(3):
                a[i][j] += w[n] * ((rr if i == j else 0.0) - r[i] * r[j])
        b = [p + w[n] * q for p, q in zip(b, cross(r, u[n]))]
    theta = solve3(a, b)
    want = [sum(w[n] * u[n][i] for n in beam.tip) for i in range(3)]
    want = [p + q for p, q in zip(want, cross(theta, sub(ref, xb)))]
    ur = vec(row, "REF", "U")
    scale = max(abs(c) for c in ur)
    for i in range(3):
        check("distributing: U%d of the reference node" % (i + 1), ur[i], want[i], 1e-9 * scale)
    print("reference node %s = weighted mean motion of the face %s" % (ur, want))


def case_distributing_twin(exe, out):
    beam = Beam()
    ref = [beam.L, 0.5, 0.5]
    loads = ["REF, 1, 0.3", "REF, 2, -0.2", "REF, 3, 0.5"]
    dist = coupling_deck(beam, ref, ["*DISTRIBUTING", "1, 3"], loads)
    w = tip_weights(beam)
    first = beam.tip[len(beam.tip) // 2]
    eq = ["*EQUATION"]
    for d in (1, 2, 3):
        terms = [(first, d, w[first])] + [(n, d, w[n]) for n in beam.tip if n != first] + [(100000, d, -1.0)]
        eq.append(str(len(terms)))
        for i in range(0, len(terms), 4):
            eq.append(", ".join("%d, %d, %r" % t for t in terms[i:i + 4]))
    lines = beam.mesh(ref) + eq + ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1.", "*CLOAD"] + loads
    a = run(exe, out, "distributing_translations", dist)[-1]
    b = run(exe, out, "distributing_equation_twin", "\n".join(lines + beam.prints() + ["*END STEP"]) + "\n")[-1]
    compare_rows(a, b, 1e-9)
    # dofs 1, 2 only: Abaqus constrains every translation of a distributing coupling anyway (a warning here)
    text = coupling_deck(beam, ref, ["*DISTRIBUTING", "1, 2"], loads)
    path = os.path.join(out, "distributing_released.inp")
    with open(path, "w") as f:
        f.write(text)
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, "distributing_released"), path], capture_output=True,
                       text=True)
    if r.returncode != 0 or "constrains every translation" not in r.stderr:
        fail("*DISTRIBUTING 1, 2: expected a run with a warning, got %d: %s" % (r.returncode, r.stderr[-1000:]))
    with open(os.path.join(out, "distributing_released", "distributing_released.csv")) as f:
        c = list(csv.DictReader(f))[-1]
    compare_rows(c, a, 1e-12)


def case_kinematic_2d(exe, out):
    beam = Beam(three_d=False)
    ref = [beam.L + 1.0, 0.8, 0.0]
    force, moment = [0.2, -0.5, 0.0], [0.0, 0.0, 0.3]
    loads = ["REF, 1, 0.2", "REF, 2, -0.5", "REF, 6, 0.3"]
    row = run(exe, out, "kinematic_2d", coupling_deck(beam, ref, ["*KINEMATIC"], loads))[-1]
    statics(beam, row, ref, force, moment)
    rigid_face(beam, row, ref)


def equation_block(b_labels, eq_lines, sets):
    """Cube A (nodes 1..8, x in [0, 1]) and cube B (x in [1, 2]) whose x = 1 face nodes coincide with A's; B's
    labels at (1,0,0), (2,0,0), (2,1,0), (1,1,0), (1,0,1), (2,0,1), (2,1,1), (1,1,1) are b_labels. A's base is
    encastred, B's far face loaded; eq_lines tie the faces."""
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    lines = ["*HEADING", "two cubes tied by *EQUATION", "*NODE"]
    for k, p in enumerate(pts):
        lines.append("%d, %d., %d., %d." % (k + 1, p[0], p[1], p[2]))
        lines.append("%d, %d., %d., %d." % (b_labels[k], p[0] + 1, p[1], p[2]))
    labels = list(range(1, 9)) + list(b_labels)
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=A\n1, 1, 2, 3, 4, 5, 6, 7, 8",
              "*ELEMENT, TYPE=C3D8, ELSET=B\n2, %s" % ", ".join(map(str, b_labels)),
              "*NSET, NSET=BASE\n1, 4, 5, 8"] + list(sets)
    for n in labels:
        lines.append("*NSET, NSET=N%d\n%d" % (n, n))
    lines += ["*SOLID SECTION, ELSET=A, MATERIAL=M", "*SOLID SECTION, ELSET=B, MATERIAL=M", "*MATERIAL, NAME=M",
              "*ELASTIC", "1000., 0.3"] + list(eq_lines)
    far = [b_labels[1], b_labels[2], b_labels[5], b_labels[6]]
    lines += ["*BOUNDARY", "BASE, ENCASTRE", "*STEP", "*STATIC", "1., 1.", "*CLOAD"]
    lines += ["%d, %d, %r" % (n, d, f) for n in far for d, f in ((1, 0.1), (2, 0.05), (3, 0.2))]
    for n in labels:
        lines += ["*NODE PRINT, NSET=N%d" % n, "U"]
    return "\n".join(lines + ["*END STEP"]) + "\n"


def node_equations(pairs, dofs=(1, 2, 3)):
    lines = ["*EQUATION"]
    for a, b in pairs:
        for d in dofs:
            lines.append("2\n%d, %d, 1., %d, %d, -1." % (b, d, a, d))
    return lines


def case_equation_sets(exe, out):
    # B labelled so that the sorted face sets pair coincident nodes: sets written out of order must be sorted by
    # label (Abaqus' sorted sets) to pair them; a single node (12) is used in every equation of a set
    b1 = [11, 12, 13, 14, 15, 16, 17, 18]
    pairs1 = [(2, 11), (3, 14), (6, 15), (7, 18)]
    sets1 = ["*NSET, NSET=AF\n7, 2, 6, 3", "*NSET, NSET=BF\n11, 18, 14, 15", "*NSET, NSET=BT\n16, 17"]
    eq1 = ["*EQUATION", "2", "BF, 1, 1., AF, 1, -1.", "2", "BF, 2, 1., AF, 2, -1.", "2", "BF, 3, 1., AF, 3, -1.",
           "2", "BT, 2, 1., 12, 2, -1."]
    twin1 = node_equations(pairs1) + ["2\n16, 2, 1., 12, 2, -1.", "2\n17, 2, 1., 12, 2, -1."]
    a = run(exe, out, "equation_sets_sorted", equation_block(b1, eq1, sets1))[-1]
    b = run(exe, out, "equation_nodes_sorted", equation_block(b1, twin1, sets1))[-1]
    compare_rows(a, b, 1e-12)
    # B labelled so that sorted sets would pair the wrong nodes: UNSORTED sets in matching order pair them
    b2 = [18, 22, 23, 15, 14, 26, 27, 11]
    pairs2 = [(2, 18), (3, 15), (6, 14), (7, 11)]
    sets2 = ["*NSET, NSET=AF, UNSORTED\n2, 3, 6, 7", "*NSET, NSET=BF, UNSORTED\n18, 15, 14, 11"]
    eq2 = ["*EQUATION", "2", "BF, 1, 1., AF, 1, -1.", "2", "BF, 2, 1., AF, 2, -1.", "2", "BF, 3, 1., AF, 3, -1."]
    a = run(exe, out, "equation_sets_unsorted", equation_block(b2, eq2, sets2))[-1]
    b = run(exe, out, "equation_nodes_unsorted", equation_block(b2, node_equations(pairs2), sets2))[-1]
    compare_rows(a, b, 1e-12)
    # sets of different sizes: refused, naming the line of the offending term
    sets3 = sets1 + ["*NSET, NSET=BTHREE\n11, 14, 15"]
    eq3 = ["*EQUATION", "2", "BF, 1, 1.,", "BTHREE, 1, -1."]
    text = equation_block(b1, eq3, sets3)
    msg = run(exe, out, "equation_sets_sizes", text, expect=2)
    line = text.split("\n").index("BTHREE, 1, -1.") + 1
    if "equation_sets_sizes.inp:%d: *EQUATION:" % line not in msg or "3 nodes" not in msg:
        fail("sets of different sizes: the message must name line %d and the sizes, got: %s" % (line, msg))
    print("sets of different sizes refused: " + msg.strip().splitlines()[-1])


def run_text(exe, out, job, text):
    return run(exe, out, job, text)[-1]


def case_equation_chain(exe, out):
    b1 = [11, 12, 13, 14, 15, 16, 17, 18]
    pairs1 = [(2, 11), (3, 14), (6, 15), (7, 18)]
    sets1 = ["*NSET, NSET=AF\n7, 2, 6, 3"]
    chain = node_equations(pairs1) + ["2\n17, 2, 1., 16, 2, -1.", "2\n16, 2, 1., 12, 2, -1."]
    twin = node_equations(pairs1) + ["2\n17, 2, 1., 12, 2, -1.", "2\n16, 2, 1., 12, 2, -1."]
    a = run(exe, out, "equation_chain", equation_block(b1, chain, sets1))[-1]
    b = run(exe, out, "equation_chain_twin", equation_block(b1, twin, sets1))[-1]
    compare_rows(a, b, 1e-12)
    check("chained node 17 moves with node 12 in y", float(a["N17.U2"]), float(a["N12.U2"]),
          1e-12 * abs(float(a["N12.U2"])))
    # each eliminates a retained dof of the other: u17 = (u16 + u12) / 2, u16 = (u17 + u12) / 2, so u16 = u17 = u12
    mutual = node_equations(pairs1) + ["3\n17, 2, 1., 16, 2, -0.5, 12, 2, -0.5",
                                       "3\n16, 2, 1., 17, 2, -0.5, 12, 2, -0.5"]
    c = run(exe, out, "equation_mutual", equation_block(b1, mutual, sets1))[-1]
    compare_rows(c, b, 1e-12)
    loop = node_equations(pairs1) + ["2\n17, 2, 1., 16, 2, -1.", "2\n16, 2, 1., 17, 2, -1."]
    msg = run(exe, out, "equation_loop", equation_block(b1, loop, sets1), expect=2)
    if "dependent" not in msg:
        fail("two equations that are one: the message must say they are dependent, got: " + msg)
    print("dependent equations refused: " + msg.strip().splitlines()[-1])
    # a node of no element whose motion an equation defines (u99 = (u2 + u3) / 2, node 99 midway between them) and
    # carrying a force: the force reaches nodes 2 and 3 half each (the twin loads them so); a one-term equation
    # holds its dof at zero (the twin prescribes it with *BOUNDARY)
    mid = ["*NODE\n99, 1., 0.5, 0."] + sets1
    orphan = node_equations(pairs1) + ["*EQUATION"] + ["3\n99, %d, 1., 2, %d, -0.5, 3, %d, -0.5" % (d, d, d)
                                                       for d in (1, 2, 3)] + ["1\n16, 3, 1."]
    text = equation_block(b1, orphan, mid).replace("*END STEP", "*CLOAD\n99, 2, 0.3\n*END STEP")
    twin = node_equations(pairs1) + ["*BOUNDARY\n16, 3, 3"]
    ttext = equation_block(b1, twin, mid).replace("*END STEP", "*CLOAD\n2, 2, 0.15\n3, 2, 0.15\n*END STEP")
    d = run_text(exe, out, "equation_orphan", text)
    e = run_text(exe, out, "equation_orphan_twin", ttext)
    compare_rows(d, e, 1e-12)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--case", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = {"kinematic": case_kinematic, "kinematic_twin": case_kinematic_twin, "distributing": case_distributing,
             "distributing_twin": case_distributing_twin, "kinematic_2d": case_kinematic_2d,
             "equation_sets": case_equation_sets, "equation_chain": case_equation_chain}
    if a.case not in cases:
        fail("unknown case " + a.case)
    cases[a.case](a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
