#!/usr/bin/env python3
"""*ORIENTATION on *SOLID SECTION: a rotated orthotropic UMAT against the unrotated one.

  check_orientation.py --exe BIN --out DIR --user user_umat_ortho.f90
  check_orientation.py --exe BIN --out DIR --material elastic   (the same cases with the host's *ELASTIC,
                                                                 TYPE=ENGINEERING CONSTANTS of the same constants)

A unit C3D8 cube of an orthotropic material (tests/regression/user_umat_ortho.f90) with every node prescribed,
u = t H X (a homogeneous deformation F = I + t H, four fixed increments). For a homogeneous state the nodal
reactions give the first Piola-Kirchhoff stress exactly: P_ij = sum_a RF_a,i X_a,j = the total RFi of the face
X_j = 1 (unit reference volume). Cases:
  small     NLGEOM=NO. (a) without *ORIENTATION, P = C eps (the closed form of the material, eps = sym H);
            (b) an identity *ORIENTATION gives the same; (c) axes turned by Q (DEFINITION=COORDINATES with an
            additional rotation line) under H_Q = Q H Q^T: P_Q = Q P Q^T (the material turned with its loading);
            (d) the same axes from DEFINITION=NODES. Round-off tolerance.
  nlgeom    NLGEOM=YES, |H| ~ 0.3 (stretch, shear and a rigid rotation): identity axes vs turned axes, P_Q = Q P Q^T
            (the local axes follow the material rotation R of F = R U, so the turned problem is the same problem).
            In both, the JOB.dat *EL PRINT stresses are in the local axes, as Abaqus prints them: the turned run
            prints what the unturned one prints (to the 5 printed digits).
  rigid     NLGEOM=YES, turned axes: step 1 stretches (F1 = diag(1.05, 0.98, 1)), step 2 turns the stretched cube
            rigidly by 90 degrees about z in one increment (the Hughes-Winget strain increment of a rigid rotation
            is zero: the Cayley transform is skew). The local axes turn with the material, the local stress stays,
            so P2 = R P1 (axes that stayed fixed would leave the stress unturned and fail this check).
  instance  NLGEOM=NO, the cube as a *PART with its *ORIENTATION (turned axes) and section, instanced twice: as it
            is, and turned by 90 degrees about an axis through (0.3, 0.2, 0) along (1, 1, 1) and translated; the
            placed instance under the placed loading R H R^T must give R P R^T (the orientation's points are placed
            with the instance). P from every node's reaction: P_ij = sum_a RF_a,i X_a,j (reference coordinates).
"""
import argparse
import csv
import math
import os
import subprocess
import sys

PROPS = [1000.0, 400.0, 250.0, 0.25, 0.15, 0.3, 150.0, 120.0, 90.0]
X = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


MATERIAL = ["umat"]  # "umat": user_umat_ortho.f90; "elastic": *ELASTIC, TYPE=ENGINEERING CONSTANTS (main's --material)


def material_lines():
    """The material's lines: the user UMAT's PROPS or the same constants as *ELASTIC engineering constants."""
    head = "*User Material, constants=9" if MATERIAL[0] == "umat" else "*Elastic, type=ENGINEERING CONSTANTS"
    return [head, ", ".join("%.17g" % p for p in PROPS[:8]), "%.17g" % PROPS[8]]


def user_args(user):
    return ["--user", user] if user else []


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def tr(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def rot(axis, deg):
    """Right-handed rotation by deg about a unit axis (Rodrigues)."""
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    th = math.radians(deg)
    c, s = math.cos(th), math.sin(th)
    kx = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[(c if i == j else 0.0) + s * kx[i][j] + (1 - c) * k[i] * k[j] for j in range(3)] for i in range(3)]


def ortho_c():
    e1, e2, e3, n12, n13, n23, g12, g13, g23 = PROPS
    s = [[1 / e1, -n12 / e1, -n13 / e1], [-n12 / e1, 1 / e2, -n23 / e2], [-n13 / e1, -n23 / e2, 1 / e3]]
    det = (s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) - s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0])
           + s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]))
    cof = [[(s[(i + 1) % 3][(j + 1) % 3] * s[(i + 2) % 3][(j + 2) % 3] - s[(i + 1) % 3][(j + 2) % 3] *
             s[(i + 2) % 3][(j + 1) % 3]) / det for j in range(3)] for i in range(3)]
    return cof, (g12, g13, g23)


def deck(path, h, nlgeom, orient, h2=None):
    """orient: None, or (lines of *ORIENTATION, with NAME=ORI); node sets FX, FY, FZ: faces X_j = 1."""
    out = ["*Heading", "orthotropic cube (tests/regression/check_orientation.py)", "*Node"]
    out += ["%d, %g, %g, %g" % ((a + 1,) + x) for a, x in enumerate(X)]
    out += ["*Element, type=C3D8, elset=CUBE", "1, 1, 2, 3, 4, 5, 6, 7, 8",
            "*Nset, nset=FX", "2, 3, 6, 7", "*Nset, nset=FY", "3, 4, 7, 8", "*Nset, nset=FZ", "5, 6, 7, 8"]
    if orient:
        out += orient
        out += ["*Solid Section, elset=CUBE, material=ORTHO, orientation=ORI"]
    else:
        out += ["*Solid Section, elset=CUBE, material=ORTHO"]
    out += ["*Material, name=ORTHO"] + material_lines() + [
            "*Step, nlgeom=%s" % ("YES" if nlgeom else "NO"), "*Static, direct", "0.25, 1.",
            "*Boundary"]
    for a, x in enumerate(X):
        for i in range(3):
            out.append("%d, %d, %d, %.17g" % (a + 1, i + 1, i + 1, sum(h[i][j] * x[j] for j in range(3))))
    prints = ["*Node Print, nset=FX, totals=YES", "RF", "*Node Print, nset=FY, totals=YES", "RF",
              "*Node Print, nset=FZ, totals=YES", "RF", "*El Print, elset=CUBE, summary=NO", "S", "*End Step"]
    out += prints
    if h2 is not None:
        out += ["*Step, nlgeom=YES", "*Static, direct", "1., 1.", "*Boundary"]
        for a, x in enumerate(X):
            for i in range(3):
                out.append("%d, %d, %d, %.17g" % (a + 1, i + 1, i + 1, sum(h2[i][j] * x[j] for j in range(3))))
        out += prints
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def run(exe, out, user, job, h, nlgeom, orient, h2=None, step=None):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, job + ".inp")
    deck(path, h, nlgeom, orient, h2)
    res = subprocess.run([exe, "-q"] + user_args(user) + [path], cwd=out, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("ldfcz exited with %d on %s" % (res.returncode, path))
    with open(os.path.join(out, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    if step is not None:
        rows = [r for r in rows if int(r["step"]) == step]
    r = rows[-1]
    return [[float(r["F%s.RF%d" % ("XYZ"[j], i + 1)]) for j in range(3)] for i in range(3)]


def printed_stress(out, job):
    """The S11..S23 rows (8 points) of the last *EL PRINT table in JOB.dat."""
    with open(os.path.join(out, job + ".dat")) as f:
        text = f.read()
    table = text.split("ELEMENT  PT FOOT-")[-1].split("\n")
    rows = []
    for line in table[1:]:
        w = line.split()
        if len(w) == 8 and w[0] == "1":
            rows.append([float(v) for v in w[2:]])
    if len(rows) != 8:
        fail("%s.dat: %d stress rows in the last table, expected 8" % (job, len(rows)))
    return rows


def compare_printed(name, a, b):
    """The same printed stress (es15.4: 5 significant digits) at every point."""
    scale = max(abs(v) for r in a for v in r)
    err = max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))
    print("%-58s max |diff| / max |S| = %.3g (print precision 1e-4)" % (name, err / scale))
    if not err <= 1e-4 * scale:
        fail(name)


def compare(name, got, want, rtol):
    scale = max(abs(v) for row in want for v in row)
    err = max(abs(got[i][j] - want[i][j]) for i in range(3) for j in range(3))
    print("%-58s max |diff| / max |P| = %.3g (tolerance %g)" % (name, err / scale, rtol))
    if not err <= rtol * scale:
        for row_g, row_w in zip(got, want):
            print("  got", ["%.10g" % v for v in row_g], "want", ["%.10g" % v for v in row_w])
        fail(name)


def orientation_lines(q, extra=None, nodes=False):
    if nodes:
        # nodes 9, 10 placed at q e1 and q e2 (not attached to elements): DEFINITION=NODES
        return ["*Node", "9, %.17g, %.17g, %.17g" % tuple(q[i][0] for i in range(3)),
                "10, %.17g, %.17g, %.17g" % tuple(q[i][1] for i in range(3)),
                "*Orientation, name=ORI, definition=NODES", "9, 10"]
    lines = ["*Orientation, name=ORI, system=RECTANGULAR",
             "%.17g, %.17g, %.17g, %.17g, %.17g, %.17g" % (tuple(q[i][0] for i in range(3)) +
                                                            tuple(q[i][1] for i in range(3)))]
    if extra:
        lines.append("%d, %.17g" % extra)
    return lines


def part_deck(path, h, place, q1, extra):
    """The cube as a part with its orientation; one instance placed by place = (translation, rotation line) or
    None; every node a set N1..N8 (per-node reactions). Returns the placed reference coordinates."""
    r, c = placement(place)
    xs = [tuple(sum(r[i][k] * x[k] for k in range(3)) + c[i] for i in range(3)) for x in X]
    out = ["*Heading", "orthotropic cube in a part (tests/regression/check_orientation.py)", "*Part, name=CUBE",
           "*Node"]
    out += ["%d, %g, %g, %g" % ((a + 1,) + x) for a, x in enumerate(X)]
    out += ["*Element, type=C3D8, elset=CUBE", "1, 1, 2, 3, 4, 5, 6, 7, 8"]
    out += orientation_lines(q1, extra)
    out += ["*Solid Section, elset=CUBE, material=ORTHO, orientation=ORI", "*End Part", "*Assembly, name=A",
            "*Instance, name=C-1, part=CUBE"]
    if place:
        out += ["%.17g, %.17g, %.17g" % place[0], ", ".join("%.17g" % v for v in place[1])]
    out += ["*End Instance"]
    for a in range(8):
        out += ["*Nset, nset=N%d, instance=C-1" % (a + 1), "%d," % (a + 1)]
    out += ["*End Assembly", "*Material, name=ORTHO"] + material_lines() + ["*Step, nlgeom=NO", "*Static, direct",
            "0.5, 1.", "*Boundary"]
    for a, x in enumerate(xs):
        for i in range(3):
            out.append("C-1.%d, %d, %d, %.17g" % (a + 1, i + 1, i + 1, sum(h[i][j] * x[j] for j in range(3))))
    for a in range(8):
        out += ["*Node Print, nset=N%d, totals=YES" % (a + 1), "RF"]
    out += ["*End Step"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return xs


def placement(place):
    """x = R (x_part + t - a) + a, as *INSTANCE (translation, then rotation about a -> b)."""
    if not place:
        return [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], [0.0, 0.0, 0.0]
    t, rl = place
    a, b, ang = rl[0:3], rl[3:6], rl[6]
    r = rot([b[i] - a[i] for i in range(3)], ang)
    c = [a[i] + sum(r[i][k] * (t[k] - a[k]) for k in range(3)) for i in range(3)]
    return r, c


def run_part(exe, out, user, job, h, place, q1, extra):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, job + ".inp")
    xs = part_deck(path, h, place, q1, extra)
    res = subprocess.run([exe, "-q"] + user_args(user) + [path], cwd=out, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("ldfcz exited with %d on %s" % (res.returncode, path))
    with open(os.path.join(out, job + ".csv")) as f:
        r = list(csv.DictReader(f))[-1]
    # P_ij = sum_a RF_a,i X_a,j over the unit reference volume (homogeneous state)
    return [[sum(float(r["N%d.RF%d" % (a + 1, i + 1)]) * xs[a][j] for a in range(8)) for j in range(3)]
            for i in range(3)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--user")
    ap.add_argument("--material", choices=["umat", "elastic"], default="umat")
    ap.add_argument("--case", required=True, choices=["small", "nlgeom", "rigid", "instance"])
    a = ap.parse_args()
    MATERIAL[0] = a.material
    if a.material == "umat" and not a.user:
        fail("--material umat needs --user user_umat_ortho.f90")
    exe, out, user = os.path.abspath(a.exe), os.path.abspath(a.out), os.path.abspath(a.user) if a.user else None
    # axes turned by Q = Q2 Q1: the points a, b of Q1, then an additional 25 degree rotation about local axis 3
    q1 = matmul(rot((1, 2, 2), 40.0), rot((0, 0, 1), 0.0))
    q = matmul(q1, rot((0, 0, 1), 25.0))
    identity = [[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]]
    ident_lines = ["*Orientation, name=ORI", "1., 0., 0., 0., 1., 0."]
    if a.case == "small":
        h = [[2e-3, 5e-4, -3e-4], [1e-4, -1e-3, 6e-4], [7e-4, -2e-4, 1.5e-3]]
        hq = matmul(matmul(q, h), tr(q))
        p0 = run(exe, out, user, "plain", h, False, None)
        c, (g12, g13, g23) = ortho_c()
        eps = [[0.5 * (h[i][j] + h[j][i]) for j in range(3)] for i in range(3)]
        d = [eps[0][0], eps[1][1], eps[2][2]]
        want = [[0.0] * 3 for _ in range(3)]
        for i in range(3):
            want[i][i] = sum(c[i][k] * d[k] for k in range(3))
        for (i, j), g in (((0, 1), g12), ((0, 2), g13), ((1, 2), g23)):
            want[i][j] = want[j][i] = g * 2 * eps[i][j]
        compare("no orientation: P = C eps (closed form)", p0, want, 1e-9)
        pi = run(exe, out, user, "identity", h, False, ident_lines)
        compare("identity orientation = none", pi, p0, 1e-12)
        pq = run(exe, out, user, "turned", hq, False, orientation_lines(q1, (3, 25.0)))
        compare("turned axes under turned loading: P_Q = Q P Q^T", pq, matmul(matmul(q, p0), tr(q)), 1e-10)
        compare_printed("JOB.dat S in the local axes: turned = plain", printed_stress(out, "turned"),
                        printed_stress(out, "plain"))
        pn = run(exe, out, user, "nodes", hq, False, orientation_lines(q, nodes=True))
        compare("DEFINITION=NODES: P_Q = Q P Q^T", pn, matmul(matmul(q, p0), tr(q)), 1e-10)
    elif a.case == "instance":
        h = [[2e-3, 5e-4, -3e-4], [1e-4, -1e-3, 6e-4], [7e-4, -2e-4, 1.5e-3]]
        place = ((0.5, -1.0, 2.0), (0.3, 0.2, 0.0, 1.3, 1.2, 1.0, 90.0))
        r, _ = placement(place)
        hr = matmul(matmul(r, h), tr(r))
        p0 = run_part(exe, out, user, "part_plain", h, None, q1, (3, 25.0))
        pq = run(exe, out, user, "part_flat", h, False, orientation_lines(q1, (3, 25.0)))
        compare("part instance = the same cube written flat", p0, pq, 1e-10)
        pr = run_part(exe, out, user, "part_placed", hr, place, q1, (3, 25.0))
        compare("placed instance under placed loading: P_R = R P R^T", pr, matmul(matmul(r, p0), tr(r)), 1e-10)
    elif a.case == "rigid":
        f1 = [[1.05, 0, 0], [0, 0.98, 0], [0, 0, 1.0]]
        r90 = rot((0, 0, 1), 90.0)
        h1 = [[f1[i][j] - (1.0 if i == j else 0.0) for j in range(3)] for i in range(3)]
        f2 = matmul(r90, f1)
        h2 = [[f2[i][j] - (1.0 if i == j else 0.0) for j in range(3)] for i in range(3)]
        lines = orientation_lines(q1, (3, 25.0))
        p1 = run(exe, out, user, "rigid", h1, True, lines, h2=h2, step=1)
        p2 = run(exe, out, user, "rigid", h1, True, lines, h2=h2, step=2)
        compare("rigid 90 degree turn after a stretch: P2 = R P1", p2, matmul(r90, p1), 1e-10)
    else:
        # stretch, shear and a 20 degree rigid rotation: F = R0 (I + S), H = F - I
        s = [[0.25, 0.1, 0.0], [0.05, -0.1, 0.08], [0.0, 0.03, 0.15]]
        r0 = rot((0.2, 0.3, 1.0), 20.0)
        f = matmul(r0, [[(1.0 if i == j else 0.0) + s[i][j] for j in range(3)] for i in range(3)])
        h = [[f[i][j] - (1.0 if i == j else 0.0) for j in range(3)] for i in range(3)]
        hq = matmul(matmul(q, h), tr(q))
        pi = run(exe, out, user, "nl_identity", h, True, ident_lines)
        pq = run(exe, out, user, "nl_turned", hq, True, orientation_lines(q1, (3, 25.0)))
        compare("NLGEOM, turned axes under turned loading: P_Q = Q P Q^T", pq, matmul(matmul(q, pi), tr(q)), 1e-10)
        compare_printed("NLGEOM: JOB.dat S in the turning local axes: turned = identity",
                        printed_stress(out, "nl_turned"), printed_stress(out, "nl_identity"))
    print("PASS")


if __name__ == "__main__":
    main()
