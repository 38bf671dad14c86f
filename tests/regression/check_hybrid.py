#!/usr/bin/env python3
"""Hybrid element names (docs/elements.md, "Hybrid names"): test deck_hybrid_names.

  check_hybrid.py --exe BIN --out DIR

1. A nearly incompressible cantilever (linear elasticity, E = 1000, nu = 0.4999, 6 x 2 x 2 C3D8H, NLGEOM=NO,
   clamped at x = 0, a shear force at x = 6) runs with the warning that names the type it is read as, and its
   displacements (the last VTU frame, 9 significant digits) equal those of an independent constant-pressure mixed
   (u-p, Q1P0) solution computed here: the element pressure condensed, K_e = int B_dev^T 2 mu B_dev dV +
   kappa V_e b b^T with b the element's mean volumetric row. Tolerance 1e-7 of the largest displacement: the printed
   digits (5e-9) and the conditioning (kappa / mu = 1.7e4, well inside 1e-7 in double precision). The plain
   displacement solution, computed here too, locks: it must differ from the mixed one by more than 10 % (so the
   comparison can tell them apart).
2. The same deck with C3D8 gives the same numbers to the bit (the name is read as that type, nothing else changes).
3. CPE4H and CAX4RH run; C3D20H, C3D10H and C3D4H stop with exit 2 naming the line and the hybrid names read.
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

NX, NY, NZ = 6, 2, 2
LX, LY, LZ = 6.0, 1.0, 1.0
E, NU = 1000.0, 0.4999
FORCE = 0.01


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def node_id(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def mesh():
    nodes = [(node_id(i, j, k), LX * i / NX, LY * j / NY, LZ * k / NZ)
             for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)]
    elems = []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                elems.append([node_id(i, j, k), node_id(i + 1, j, k), node_id(i + 1, j + 1, k),
                              node_id(i, j + 1, k), node_id(i, j, k + 1), node_id(i + 1, j, k + 1),
                              node_id(i + 1, j + 1, k + 1), node_id(i, j + 1, k + 1)])
    return sorted(nodes), elems


def deck(etype):
    nodes, elems = mesh()
    clamp = [n[0] for n in nodes if n[1] == 0.0]
    tip = [n[0] for n in nodes if n[1] == LX]
    lines = ["*Heading", "hybrid names: nearly incompressible cantilever", "*Node"]
    lines += ["%d, %.17g, %.17g, %.17g" % n for n in nodes]
    lines += ["*Element, type=%s, elset=E" % etype]
    lines += ["%d, %s" % (e + 1, ", ".join(str(v) for v in c)) for e, c in enumerate(elems)]
    lines += ["*Nset, nset=CLAMP"] + [", ".join(str(v) for v in clamp[i:i + 8]) for i in range(0, len(clamp), 8)]
    lines += ["*Nset, nset=TIP"] + [", ".join(str(v) for v in tip[i:i + 8]) for i in range(0, len(tip), 8)]
    lines += ["*Solid Section, elset=E, material=M", "*Material, name=M", "*Elastic", "%g, %g" % (E, NU),
              "*Boundary", "CLAMP, 1, 3", "*Step", "*Static", "1., 1.", "*Cload"]
    lines += ["%d, 3, %.17g" % (t, FORCE / len(tip)) for t in tip]
    lines += ["*Output, field", "*Node output", "U", "*End step"]
    return "\n".join(lines) + "\n"


def run(exe, out, name, text):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, name + ".inp")
    with open(path, "w") as f:
        f.write(text)
    d = os.path.join(out, name)
    p = subprocess.run([exe, "-q", "--threads", "1", "--out", d, path], capture_output=True, text=True)
    return p, d


def last_u(d, job):
    frames = sorted(f for f in os.listdir(d) if re.match(re.escape(job) + r"_\d+\.vtu$", f))
    text = open(os.path.join(d, frames[-1])).read()
    m = re.search(r'<DataArray[^>]*Name="U"[^>]*>([^<]*)<', text)
    return np.array(m.group(1).split(), float).reshape(-1, 3)


def reference(mixed):
    """The cantilever by a mixed (constant pressure, condensed) or the plain displacement C3D8, 2x2x2 Gauss."""
    nodes, elems = mesh()
    x = np.array([n[1:] for n in nodes])
    n = len(nodes)
    mu, kappa = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))
    lam = kappa - 2 * mu / 3
    d_dev = 2 * mu * (np.diag([1, 1, 1, 0.5, 0.5, 0.5]) - np.r_[np.ones(3), np.zeros(3)][:, None] *
                      np.r_[np.ones(3), np.zeros(3)][None, :] / 3)
    d_full = np.diag([2 * mu] * 3 + [mu] * 3)
    d_full[:3, :3] += lam
    corners = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                        [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], float)
    g = 1 / np.sqrt(3)
    k_glob = np.zeros((3 * n, 3 * n))
    for conn in elems:
        idx = [c - 1 for c in conn]
        xe = x[idx]
        bs, ws = [], []
        for p in corners * g:
            dn = corners * (1 + corners[:, [1, 2, 0]] * p[[1, 2, 0]]) * (1 + corners[:, [2, 0, 1]] * p[[2, 0, 1]]) / 8
            jac = dn.T @ xe
            dx = dn @ np.linalg.inv(jac).T
            b = np.zeros((6, 24))
            for a in range(8):
                b[0, 3 * a], b[1, 3 * a + 1], b[2, 3 * a + 2] = dx[a]
                b[3, 3 * a], b[3, 3 * a + 1] = dx[a, 1], dx[a, 0]
                b[4, 3 * a + 1], b[4, 3 * a + 2] = dx[a, 2], dx[a, 1]
                b[5, 3 * a], b[5, 3 * a + 2] = dx[a, 2], dx[a, 0]
            bs.append(b)
            ws.append(np.linalg.det(jac))
        if mixed:
            vol = sum(ws)
            bvol = sum(w * b[:3].sum(axis=0) for b, w in zip(bs, ws)) / vol
            ke = sum(w * b.T @ d_dev @ b for b, w in zip(bs, ws)) + kappa * vol * np.outer(bvol, bvol)
        else:
            ke = sum(w * b.T @ d_full @ b for b, w in zip(bs, ws))
        dofs = np.array([[3 * i, 3 * i + 1, 3 * i + 2] for i in idx]).ravel()
        k_glob[np.ix_(dofs, dofs)] += ke
    f = np.zeros(3 * n)
    tip = [i for i in range(n) if x[i, 0] == LX]
    f[[3 * i + 2 for i in tip]] = FORCE / len(tip)
    free = np.array([d for i in range(n) if x[i, 0] != 0.0 for d in (3 * i, 3 * i + 1, 3 * i + 2)])
    u = np.zeros(3 * n)
    u[free] = np.linalg.solve(k_glob[np.ix_(free, free)], f[free])
    return u.reshape(-1, 3)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    exe, out = os.path.abspath(a.exe), os.path.abspath(a.out)

    p, d = run(exe, out, "c3d8h", deck("C3D8H"))
    if p.returncode != 0:
        fail("C3D8H: exit %d: %s" % (p.returncode, p.stderr[-2000:]))
    if "hybrid type C3D8H read as C3D8" not in p.stderr or not re.search(r"c3d8h\.inp:\d+: \*ELEMENT", p.stderr):
        fail("no located warning naming the type C3D8H is read as: " + p.stderr)
    u = last_u(d, "c3d8h")
    mixed, plain = reference(True), reference(False)
    scale = np.abs(mixed).max()
    diff = np.abs(u - mixed).max() / scale
    locked = np.abs(plain - mixed).max() / scale
    print("C3D8H against the constant-pressure mixed solution: %.2e of the largest displacement (tip %.6g); "
          "the plain displacement element differs by %.1f %%" % (diff, mixed[:, 2].max(), 100 * locked))
    if diff > 1e-7:
        fail("C3D8H differs from the constant-pressure mixed element by %.2e" % diff)
    if locked < 0.1:
        fail("the plain displacement solution does not lock (%.3g): the test cannot tell the elements apart" % locked)

    p2, d2 = run(exe, out, "c3d8", deck("C3D8"))
    if p2.returncode != 0 or not np.array_equal(last_u(d2, "c3d8"), u):
        fail("C3D8 and C3D8H differ")
    print("C3D8 twin: identical displacements")

    for etype, ok in (("CPE4H", True), ("CAX4RH", True), ("C3D20H", False), ("C3D10H", False), ("C3D4H", False)):
        nn = {"CPE4H": 4, "CAX4RH": 4, "C3D20H": 20, "C3D10H": 10, "C3D4H": 4}[etype]
        text = "*Node\n" + "".join("%d, %d., %d., 0.\n" % (i + 1, i % 2, i // 2) for i in range(nn)) + \
            "*Element, type=%s\n1, %s\n" % (etype, ", ".join(str(i + 1) for i in range(nn)))
        if ok:
            text = "*Node\n1, 0., 0.\n2, 1., 0.\n3, 1., 1.\n4, 0., 1.\n*Element, type=%s, elset=E\n1, 1, 2, 3, 4\n" \
                   "*Solid Section, elset=E, material=M\n1.\n*Material, name=M\n*Elastic\n1000., 0.3\n" \
                   "*Boundary\n1, 1, 2\n2, 2, 2\n4, 1, 1\n*Step\n*Static\n1., 1.\n*Boundary\n3, 2, 2, 0.01\n" \
                   "4, 2, 2, 0.01\n*End step\n" % etype
        p, _ = run(exe, out, etype.lower(), text)
        if ok and (p.returncode != 0 or "hybrid type %s read as %s" % (etype, etype[:-1]) not in p.stderr):
            fail("%s: exit %d, stderr %s" % (etype, p.returncode, p.stderr[-1000:]))
        if not ok and (p.returncode != 2 or "%s.inp:" % etype.lower() not in p.stderr or "C3D8H, C3D8RH" not in
                       p.stderr):
            fail("%s: want exit 2 naming the line and the hybrid names read, got %d: %s" % (
                etype, p.returncode, p.stderr[-1000:]))
        print("%-7s %s" % (etype, "read as " + etype[:-1] if ok else "refused: " + p.stderr.strip().splitlines()[-1]))
    print("PASS")


if __name__ == "__main__":
    main()
