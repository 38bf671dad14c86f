#!/usr/bin/env python3
"""The host's *ELASTIC and *EXPANSION laws against closed forms and twin decks (docs/host.md, *ELASTIC).

  check_materials.py --exe BIN --out DIR --case CASE

A unit C3D8 cube (or a unit CPS4 square of thickness 1) with symmetry planes x = 0, y = 0, z = 0, loaded so that
its state is homogeneous; the element is then exact and every figure is a closed form up to round-off:
  compliance   TYPE=ENGINEERING CONSTANTS, uniaxial stress sigma = 1 along x, y and z in turn (*CLOAD on the
               face): the corner (1, 1, 1) moves by the column of the compliance S (1/E_i, -nu_ij/E_i); again with
               an *ORIENTATION whose axis 1 is global y (90 degrees about z): loading along x loads the material's
               axis 2 (tolerance 1e-12 of the largest displacement: one linear increment)
  twins        the same constants as ENGINEERING CONSTANTS, ORTHOTROPIC (D = S^-1 computed here) and ANISOTROPIC
               (the 21 D_ijkl) under a general homogeneous deformation with NLGEOM, four increments: the reactions
               agree to 1e-10 (the three differ in how C is formed: round-off)
  temperature  E(T) at the points (0, 1000), (100, 600), (200, 400), nu = 0.3: a bar stretched by 1e-3 while its
               temperature goes from 0 to T (4 increments): RF = E(T) 1e-3, linear between the points, constant
               outside (T = -50, 50, 150, 300); and a free cube heated from T0 = 20 to T with alpha(T) at (0, 1e-5),
               (100, 2e-5), ZERO = 10: u = (alpha(T)(T - ZERO) - alpha(T0)(T0 - ZERO)) L; ORTHO alpha_i = (1, 2, 3)
               x the table: u_i = that times i (tolerance 1e-9: the increments converge at r/q ~ 1e-11)
  lamina       TYPE=LAMINA on CPS4, uniaxial stress along x and y: the plane-stress compliance (1/E1, -nu12/E1;
               1/E2, -nu12/E1)
"""
import argparse
import csv
import os
import subprocess
import sys

EC = [1000.0, 400.0, 250.0, 0.25, 0.15, 0.3, 150.0, 120.0, 90.0]  # E1, E2, E3, nu12, nu13, nu23, G12, G13, G23
NODES = [(1, 0, 0, 0), (2, 1, 0, 0), (3, 1, 1, 0), (4, 0, 1, 0), (5, 0, 0, 1), (6, 1, 0, 1), (7, 1, 1, 1),
         (8, 0, 1, 1)]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check(name, got, want, scale, tol):
    err = max(abs(g - w) for g, w in zip(got, want))
    print("%-62s max |diff| / scale = %.3g (tolerance %g)" % (name, err / scale, tol))
    if not err <= tol * scale:
        print("  got ", ["%.15g" % v for v in got])
        print("  want", ["%.15g" % v for v in want])
        fail(name)


def compliance():
    """6x6 compliance of EC (Voigt 11, 22, 33, 12, 13, 23, engineering shears)."""
    e1, e2, e3, n12, n13, n23, g12, g13, g23 = EC
    s = [[0.0] * 6 for _ in range(6)]
    s[0][0], s[1][1], s[2][2] = 1 / e1, 1 / e2, 1 / e3
    s[0][1] = s[1][0] = -n12 / e1
    s[0][2] = s[2][0] = -n13 / e1
    s[1][2] = s[2][1] = -n23 / e2
    s[3][3], s[4][4], s[5][5] = 1 / g12, 1 / g13, 1 / g23
    return s


def inverse(a):
    """Gauss-Jordan inverse of a small matrix."""
    n = len(a)
    w = [row[:] + [1.0 if i == j else 0.0 for j in range(n)] for i, row in enumerate(a)]
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(w[i][k]))
        w[k], w[p] = w[p], w[k]
        w[k] = [v / w[k][k] for v in w[k]]
        for i in range(n):
            if i != k:
                w[i] = [vi - w[i][k] * vk for vi, vk in zip(w[i], w[k])]
    return [row[n:] for row in w]


def run(exe, out, job, lines):
    """Write JOB.inp, run it, return the last CSV row."""
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    p = subprocess.run([exe, "-q", "--threads", "1", path], cwd=out, capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        fail("ldfcz exited with %d on %s" % (p.returncode, path))
    with open(os.path.join(out, job + ".csv")) as f:
        return list(csv.DictReader(f))[-1]


def cube(material, step, extra=()):
    """The unit cube with symmetry planes, a material block, extra model lines and one step's lines."""
    out = ["*Heading", "host elastic law check", "*Node"] + ["%d, %g, %g, %g" % n for n in NODES]
    out += ["*Element, type=C3D8, elset=E", "1, 1, 2, 3, 4, 5, 6, 7, 8",
            "*Nset, nset=X0", "1, 4, 5, 8", "*Nset, nset=Y0", "1, 2, 5, 6", "*Nset, nset=Z0", "1, 2, 3, 4",
            "*Nset, nset=X1", "2, 3, 6, 7", "*Nset, nset=Y1", "3, 4, 7, 8", "*Nset, nset=Z1", "5, 6, 7, 8",
            "*Nset, nset=CORNER", "7"] + list(extra)
    out += ["*Solid Section, elset=E, material=M" + (", orientation=ORI" if any("*Orientation" in x for x in extra)
                                                      else ""), "*Material, name=M"] + material
    out += ["*Boundary", "X0, 1, 1", "Y0, 2, 2", "Z0, 3, 3"] + step
    return out


def ec_lines():
    return ["*Elastic, type=ENGINEERING CONSTANTS", ", ".join("%.17g" % v for v in EC[:8]), "%.17g" % EC[8]]


def case_compliance(exe, out):
    s = compliance()
    faces = ["X1", "Y1", "Z1"]
    for turned in (False, True):
        extra = ["*Orientation, name=ORI", "0., 1., 0., -1., 0., 0."] if turned else []
        for d in range(3):
            step = ["*Step", "*Static", "1., 1.", "*Cload", "%s, %d, 0.25" % (faces[d], d + 1),
                    "*Node print, nset=CORNER", "U", "*End step"]
            r = run(exe, out, "compliance_%s%d" % ("turned_" if turned else "", d + 1), cube(ec_lines(), step, extra))
            got = [float(r["CORNER.U%d" % (i + 1)]) for i in range(3)]
            if turned:
                # local 1 = global y, local 2 = -global x, local 3 = z: global strain = Q S Q^T sigma
                q = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
                sig_l = [q[d][i] for i in range(3)]  # sigma_local = Q^T e_d e_d^T Q: diagonal (q_di)^2
                sig_l = [v * v for v in sig_l]
                eps_l = [sum(s[i][j] * sig_l[j] for j in range(3)) for i in range(3)]
                want = [sum(q[i][k] ** 2 * eps_l[k] for k in range(3)) for i in range(3)]
            else:
                want = [s[i][d] for i in range(3)]
            check("%s uniaxial sigma_%d%d = 1: corner = compliance column" % ("turned axes," if turned else
                                                                             "global axes,", d + 1, d + 1),
                  got, want, max(abs(v) for v in want), 1e-12)


def case_twins(exe, out):
    c = inverse(compliance())
    ortho = [c[0][0], c[0][1], c[1][1], c[0][2], c[1][2], c[2][2], c[3][3], c[4][4], c[5][5]]
    row = [0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4, 0, 1, 2, 3, 4, 5]
    col = [0, 1, 1, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5]
    aniso = [c[i][j] for i, j in zip(row, col)]
    laws = {"engineering": ec_lines(),
            "orthotropic": ["*Elastic, type=ORTHOTROPIC", ", ".join("%.17g" % v for v in ortho[:8]),
                            "%.17g" % ortho[8]],
            "anisotropic": ["*Elastic, type=ANISOTROPIC", ", ".join("%.17g" % v for v in aniso[:8]),
                            ", ".join("%.17g" % v for v in aniso[8:16]), ", ".join("%.17g" % v for v in aniso[16:])]}
    h = [[0.08, 0.03, -0.02], [0.01, -0.04, 0.05], [0.02, 0.06, 0.1]]
    res = {}
    for name, mat in laws.items():
        lines = ["*Heading", "twin", "*Node"] + ["%d, %g, %g, %g" % n for n in NODES]
        lines += ["*Element, type=C3D8, elset=E", "1, 1, 2, 3, 4, 5, 6, 7, 8", "*Nset, nset=ALL", "1, 2, 3, 4, 5, 6,"
                  " 7, 8"] + ["*Nset, nset=N%d\n%d," % (n[0], n[0]) for n in NODES]
        lines += ["*Solid Section, elset=E, material=M", "*Material, name=M"] + mat
        lines += ["*Step, nlgeom=YES", "*Static, direct", "0.25, 1.", "*Boundary"]
        for n, x, y, z in NODES:
            u = [sum(h[i][j] * v for j, v in enumerate((x, y, z))) for i in range(3)]
            lines += ["%d, %d, %d, %.17g" % (n, i + 1, i + 1, u[i]) for i in range(3)]
        lines += ["*Node print, nset=N%d\nRF" % n[0] for n in NODES] + ["*End step"]
        r = run(exe, out, "twin_" + name, lines)
        res[name] = [float(r["N%d.RF%d" % (n[0], i + 1)]) for n in NODES for i in range(3)]
    scale = max(abs(v) for v in res["engineering"])
    check("NLGEOM: ORTHOTROPIC (D = S^-1) = ENGINEERING CONSTANTS", res["orthotropic"], res["engineering"], scale,
          1e-10)
    check("NLGEOM: ANISOTROPIC (21 D_ijkl) = ENGINEERING CONSTANTS", res["anisotropic"], res["engineering"], scale,
          1e-10)


def table(points, t):
    """Linear between (T, v) points, constant outside."""
    if t <= points[0][0]:
        return points[0][1]
    if t >= points[-1][0]:
        return points[-1][1]
    for (t0, v0), (t1, v1) in zip(points, points[1:]):
        if t <= t1:
            return v0 + (v1 - v0) * (t - t0) / (t1 - t0)


def case_temperature(exe, out):
    e_pts = [(0.0, 1000.0), (100.0, 600.0), (200.0, 400.0)]
    mat = ["*Elastic"] + ["%g, 0.3, %g" % (e, t) for t, e in e_pts]
    # (tolerance 1e-9: the increments converge at r/q ~ 1e-11, JOB.sta; the element itself is exact)
    for t in (-50.0, 50.0, 150.0, 300.0):
        step = ["*Step", "*Static", "0.25, 1.", "*Boundary", "X1, 1, 1, 1e-3", "*Temperature", "ALL, %g" % t,
                "*Node print, nset=X1", "RF", "*End step"]
        extra = ["*Nset, nset=ALL, generate", "1, 8", "*Initial conditions, type=temperature", "ALL, 0."]
        r = run(exe, out, "modulus_%g" % t, cube(mat, step, extra))
        want = table(e_pts, t) * 1e-3
        check("E(T = %g) from the table: RF = E(T) 1e-3" % t, [float(r["X1.RF1"])], [want], want, 1e-9)
    a_pts = [(0.0, 1e-5), (100.0, 2e-5)]
    t0, zero = 20.0, 10.0
    for kind in ("ISO", "ORTHO"):
        exp = ["*Elastic", "1000., 0.3", "*Expansion, type=%s, zero=%g" % (kind, zero)]
        mult = [1.0, 1.0, 1.0] if kind == "ISO" else [1.0, 2.0, 3.0]
        exp += [", ".join("%g" % (a * m) for m in (mult[:1] if kind == "ISO" else mult)) + ", %g" % t for t, a in
                a_pts]
        for t in (50.0, 150.0):
            step = ["*Step", "*Static", "0.25, 1.", "*Temperature", "ALL, %g" % t, "*Node print, nset=CORNER", "U",
                    "*End step"]
            extra = ["*Nset, nset=ALL, generate", "1, 8", "*Initial conditions, type=temperature", "ALL, %g" % t0]
            r = run(exe, out, "expansion_%s_%g" % (kind.lower(), t), cube(exp, step, extra))
            got = [float(r["CORNER.U%d" % (i + 1)]) for i in range(3)]
            u = table(a_pts, t) * (t - zero) - table(a_pts, t0) * (t0 - zero)
            want = [u * m for m in mult]
            check("*EXPANSION, TYPE=%s, alpha(T = %g), ZERO = %g: u = alpha(T)(T-Z) - alpha(T0)(T0-Z)"
                  % (kind, t, zero), got, want, max(abs(v) for v in want), 1e-9)


def case_lamina(exe, out):
    e1, e2, n12, g12 = 1000.0, 400.0, 0.25, 150.0
    for d in range(2):
        lines = ["*Heading", "lamina", "*Node", "1, 0., 0.", "2, 1., 0.", "3, 1., 1.", "4, 0., 1.",
                 "*Element, type=CPS4, elset=E", "1, 1, 2, 3, 4", "*Nset, nset=X0", "1, 4", "*Nset, nset=Y0", "1, 2",
                 "*Nset, nset=X1", "2, 3", "*Nset, nset=Y1", "3, 4", "*Nset, nset=CORNER", "3",
                 "*Solid Section, elset=E, material=M", "1.", "*Material, name=M", "*Elastic, type=LAMINA",
                 "%g, %g, %g, %g, 100., 100." % (e1, e2, n12, g12), "*Boundary", "X0, 1, 1", "Y0, 2, 2",
                 "*Step", "*Static", "1., 1.", "*Cload", "%s, %d, 0.5" % (["X1", "Y1"][d], d + 1),
                 "*Node print, nset=CORNER", "U", "*End step"]
        r = run(exe, out, "lamina_%d" % (d + 1), lines)
        got = [float(r["CORNER.U%d" % (i + 1)]) for i in range(2)]
        want = [1 / e1, -n12 / e1] if d == 0 else [-n12 / e1, 1 / e2]
        check("LAMINA on CPS4, uniaxial sigma_%d%d = 1: plane-stress compliance" % (d + 1, d + 1), got, want,
              max(abs(v) for v in want), 1e-12)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=["compliance", "twins", "temperature", "lamina"])
    a = ap.parse_args()
    globals()["case_" + a.case](os.path.abspath(a.exe), os.path.abspath(a.out))
    print("PASS")


if __name__ == "__main__":
    main()
