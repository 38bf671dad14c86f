#!/usr/bin/env python3
"""*TRANSFORM: boundary conditions, concentrated loads and nodal output in local node systems, against closed forms.

  check_transform.py --exe BIN --out DIR --case NAME

Cases (decks written into DIR; E = 1000):
  roller    a 2 x 1 x 1 C3D8 block (nu = 0.3, NLGEOM=NO) whose edges are turned by Q (35 degrees about (1, 2, 3)),
            so that its end faces are skew to the global axes. The nodes of both end faces carry a TYPE=R transform
            with local x = Q e1 (normal to the faces): a skewed roller (local 1 = 0) on one face, local 1 = d
            prescribed on the other (nonzero value), local 2, 3 of one corner and local 3 of another fixed against
            rigid motion. Closed form, uniaxial stress along local x: the end face's RF1 (local, summed) = E A d / L,
            its mean U1 = d, U2 = -nu d W / (2L), U3 = -nu d H / (2L) (local components, as Abaqus prints them);
            step 2 doubles d by OP=MOD, step 3 (OP=NEW, the roller and the rigid-body fixities given again, the
            prescribed end released) returns linearly to zero, the roller's reaction with it. Within 1e-9 (the linear element is exact here).
  roller_nlgeom  the same block with nu = 0 under NLGEOM, d = 0.4: RF1 and U equal to those of
            the unturned block without transform within 1e-9 (transformed directions are fixed in space, so the
            turned problem is the same problem), and near E ln(1 + d/L) A (2e-3: the hypoelastic material's
            midpoint strain increments approximate the logarithmic strain to O(increment^2)).
  instance  the roller block as a *PART holding its *TRANSFORM (local x = part x), instanced translated and turned
            by 35 degrees about (1, 2, 3): the transform turns with the instance, the step-1 closed form holds.
  cylinder  a quarter of a thick cylinder (a = 1, b = 2), CPE4 8 x 24, plane strain, nu = 0.3: the inner nodes carry a
            TYPE=C transform and a prescribed radial displacement u_a = 0.01 (local 1) with local 2 = 0; the outer
            nodes another TYPE=C transform (no boundary at the inner ones); the symmetry edges global (and local 2 at
            the outer corners). Lame's plane-strain solution with a traction-free outer surface: the outer radial
            displacement (OUTER.U1, local) within 0.3 %, the tangential one (OUTER.U2) below 1e-9 u_a, the inner
            radial reaction (INNER.RF1, summed) against -sigma_r(a) a pi/2 within 0.5 % (straight-edged elements). The
            VTU frame stays global: U of every outer node is OUTER.U1 times (cos, sin), RF of every inner node
            but the two on the symmetry planes radial (1e-6).
  cload     a 2 x 1 x 1 C3D8 cantilever under NLGEOM with a concentrated force at a tip node: given in the node's
            local system (TYPE=R, turned by Q) against the same force given in global components Q F on a run
            without transform. The free tip nodes' displacements agree within 1e-8 of the largest, the loaded
            node's printed U equals Q^T times the global one, and the root reaction is -Q F (within Newton's force
            tolerance, 1e-5). The same with a TYPE=S system (centre c, polar axis through p) against S F, S its
            axes at the node (radial, polar angle, azimuth) computed here. A further run ties the
            loaded node's local 1 displacement to another node's global 1 by *EQUATION (local 1 - global 1 = 0)
            and requires the printed local U1 of the loaded node to equal the other node's U1.
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


def close(name, got, want, rtol, atol=0.0):
    ok = abs(got - want) <= rtol * abs(want) + atol
    print("%-40s got %.12g want %.12g (rtol %g, atol %g) %s" % (name, got, want, rtol, atol, "ok" if ok else "FAIL"))
    if not ok:
        fail(name)


def rot(axis, deg):
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    th = math.radians(deg)
    c, s = math.cos(th), math.sin(th)
    kx = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[(c if i == j else 0.0) + s * kx[i][j] + (1 - c) * k[i] * k[j] for j in range(3)] for i in range(3)]


def mv(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def mtv(a, v):
    return [sum(a[k][i] * v[k] for k in range(3)) for i in range(3)]


Q = rot((1.0, 2.0, 3.0), 35.0)


def run(exe, out, job, lines):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, job + ".inp"), "w") as f:
        f.write("\n".join(lines) + "\n")
    res = subprocess.run([exe, "--quiet", "--out", out, job + ".inp"], cwd=out, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("%s: exit %d" % (job, res.returncode))
    with open(os.path.join(out, job + ".csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def block_nodes(nx, lx, turn):
    """Nodes of an nx x 1 x 1 block of length lx: label -> (xi, X = turn xi)."""
    nodes = {}
    for k in range(2):
        for j in range(2):
            for i in range(nx + 1):
                lab = 1 + i + (nx + 1) * (j + 2 * k)
                xi = (lx * i / nx, float(j), float(k))
                nodes[lab] = (xi, mv(turn, xi) if turn else list(xi))
    return nodes


def block_elements(nx):
    out = []
    for i in range(nx):
        n = [1 + i, 2 + i, 2 + i + (nx + 1), 1 + i + (nx + 1)]
        out.append("%d, %s" % (i + 1, ", ".join(str(x) for x in n + [m + 2 * (nx + 1) for m in n])))
    return out


def mesh_lines(nodes, nx, nu):
    lines = ["*Node"] + ["%d, %.15g, %.15g, %.15g" % ((lab,) + tuple(x)) for lab, (_, x) in sorted(nodes.items())]
    lines += ["*Element, type=C3D8, elset=BLOCK"] + block_elements(nx)
    lines += ["*Solid Section, elset=BLOCK, material=M", "*Material, name=M", "*Elastic", "%g, %g" % (E, nu)]
    return lines


def case_roller(exe, out, nlgeom):
    L, nu, d = 2.0, (0.0 if nlgeom else 0.3), (0.4 if nlgeom else 0.01)
    nodes = block_nodes(2, L, Q)
    roll = sorted(l for l, (xi, _) in nodes.items() if xi[0] == 0.0)
    end = sorted(l for l, (xi, _) in nodes.items() if xi[0] == L)
    origin = [l for l in roll if nodes[l][0] == (0.0, 0.0, 0.0)][0]
    side = [l for l in roll if nodes[l][0] == (0.0, 1.0, 0.0)][0]
    a, b = mv(Q, [1, 0, 0]), mv(Q, [0, 1, 0])
    fix = ["ROLL, 1, 1", "%d, 2, 3" % origin, "%d, 3, 3" % side]
    lines = ["*Heading", "skewed roller (tests/regression/check_transform.py)"] + mesh_lines(nodes, 2, nu)
    lines += ["*Nset, nset=ROLL", ", ".join(map(str, roll)), "*Nset, nset=END", ", ".join(map(str, end)),
              "*Nset, nset=TR", "ROLL, END",
              "*Transform, nset=TR, type=R", ", ".join("%.15g" % c for c in a + b)]
    steps = [("*Boundary", fix + ["END, 1, 1, %g" % d]), ("*Boundary, op=MOD", ["END, 1, 1, %g" % (2 * d)]),
             ("*Boundary, op=NEW", fix)]
    if nlgeom:
        steps = steps[:1]
    for kw, bcs in steps:
        lines += ["*Step, nlgeom=%s" % ("YES" if nlgeom else "NO"), "*Static", "0.25, 1.", kw] + bcs
        lines += ["*Node Print, nset=END", "U1, U2, U3, RF1", "*Node Print, nset=ROLL", "RF1", "*End Step"]
    rows = run(exe, out, "roller", lines)
    if nlgeom:
        # the same block unturned, without transform, with global boundaries: the reference of the turned run
        ref_lines = [l for l in lines if not l.startswith("*Transform")]
        nodes0 = block_nodes(2, L, None)
        i0 = ref_lines.index("*Node")
        ref_lines[i0 + 1:i0 + 1 + len(nodes0)] = ["%d, %.15g, %.15g, %.15g" % ((lab,) + tuple(x))
                                                  for lab, (_, x) in sorted(nodes0.items())]
        del ref_lines[ref_lines.index(", ".join("%.15g" % c for c in a + b))]
        ref = run(exe, os.path.join(out, "unturned"), "roller", ref_lines)
        refs = {"%.9f" % r["step_time"]: r for r in ref}
        if sorted(refs) != sorted("%.9f" % r["step_time"] for r in rows):
            fail("the turned and unturned runs took different increments")
    A, W, H = 1.0, 1.0, 1.0
    for r in rows:
        step, t = int(r["step"]), r["step_time"]
        dd = {1: d * t, 2: d * (1 + t), 3: 2 * d * (1 - t)}[step]
        tag = "step %d t %.2f" % (step, t)
        if nlgeom:
            close(tag + " END.RF1", r["END.RF1"], refs["%.9f" % t]["END.RF1"], 1e-9)
            close(tag + " END.RF1 ~ E ln(1 + d/L) A", r["END.RF1"], E * math.log(1 + dd / L) * A, 2e-3)
            close(tag + " END.U2", r["END.U2"], 0.0, 0.0, 1e-10)
        else:
            # step 3: END is no longer prescribed (its released reaction ramps down as an applied force)
            close(tag + " END.RF1", r["END.RF1"], E * A * dd / L if step < 3 else 0.0, 1e-9, 1e-9 * E * A * d / L)
            close(tag + " ROLL.RF1", r["ROLL.RF1"], -E * A * dd / L, 1e-9, 1e-9 * E * A * d / L)
            # displacements to 1e-9 of the applied one (the forces likewise): a zero value carries the linear
            # solve's round-off, ~1e-14 here
            close(tag + " END.U2", r["END.U2"], -nu * dd / L * W / 2, 1e-9, 1e-9 * d)
            close(tag + " END.U3", r["END.U3"], -nu * dd / L * H / 2, 1e-9, 1e-9 * d)
        close(tag + " END.U1", r["END.U1"], dd, 1e-9, 1e-9 * d)
    if not nlgeom and len(rows) != 4 * len(steps):
        fail("expected %d increments, got %d" % (4 * len(steps), len(rows)))


def case_instance(exe, out):
    """The roller block as a part holding its *TRANSFORM (local x = part x), instanced translated by (1, 2, 3) and
    turned by 35 degrees about the axis through the origin along (1, 2, 3): the transform turns with the instance
    (Abaqus: a part-level transformation is rotated with the part's positioning data), so the local results are the
    unturned closed form."""
    L, nu, d = 2.0, 0.3, 0.01
    nodes = block_nodes(2, L, None)
    roll = sorted(l for l, (xi, _) in nodes.items() if xi[0] == 0.0)
    end = sorted(l for l, (xi, _) in nodes.items() if xi[0] == L)
    origin = [l for l in roll if nodes[l][0] == (0.0, 0.0, 0.0)][0]
    side = [l for l in roll if nodes[l][0] == (0.0, 1.0, 0.0)][0]
    mesh = mesh_lines(nodes, 2, nu)
    mat = mesh[mesh.index("*Material, name=M"):]
    part = mesh[:mesh.index("*Material, name=M")]
    lines = ["*Heading", "skewed roller in a part instance (tests/regression/check_transform.py)", "*Part, name=BLOCK"]
    lines += part + ["*Nset, nset=ROLL", ", ".join(map(str, roll)), "*Nset, nset=END", ", ".join(map(str, end)),
                     "*Nset, nset=TR", "ROLL, END", "*Transform, nset=TR", "1., 0., 0., 0., 1., 0.", "*End Part"]
    lines += ["*Assembly, name=A", "*Instance, name=B-1, part=BLOCK", "1., 2., 3.", "0., 0., 0., 1., 2., 3., 35.",
              "*End Instance", "*End Assembly"] + mat
    lines += ["*Step", "*Static", "0.5, 1.", "*Boundary", "B-1.ROLL, 1, 1", "B-1.%d, 2, 3" % origin,
              "B-1.%d, 3, 3" % side, "B-1.END, 1, 1, %g" % d, "*Node Print, nset=B-1.END", "U1, U2, U3, RF1",
              "*End Step"]
    rows = run(exe, out, "instance", lines)
    for r in rows:
        t = r["step_time"]
        dd = d * t
        tag = "instance t %.2f" % t
        close(tag + " END.RF1", r["B-1.END.RF1"], E * dd / L, 1e-9, 1e-12)
        close(tag + " END.U1", r["B-1.END.U1"], dd, 1e-9, 1e-14)
        close(tag + " END.U2", r["B-1.END.U2"], -nu * dd / L / 2, 1e-9, 1e-14)
        close(tag + " END.U3", r["B-1.END.U3"], -nu * dd / L / 2, 1e-9, 1e-14)
    if len(rows) != 2:
        fail("expected 2 increments, got %d" % len(rows))


def case_cylinder(exe, out):
    a, b, nr, nt, nu, ua = 1.0, 2.0, 8, 24, 0.3, 0.01
    lab = lambda i, j: 1 + i + (nr + 1) * j
    lines = ["*Heading", "quarter cylinder, radial displacement in a cylindrical transform", "*Node"]
    for j in range(nt + 1):
        th = 0.5 * math.pi * j / nt
        for i in range(nr + 1):
            r = a + (b - a) * i / nr
            lines.append("%d, %.15g, %.15g" % (lab(i, j), r * math.cos(th), r * math.sin(th)))
    lines.append("*Element, type=CPE4, elset=RING")
    e = 0
    for j in range(nt):
        for i in range(nr):
            e += 1
            lines.append("%d, %d, %d, %d, %d" % (e, lab(i, j), lab(i + 1, j), lab(i + 1, j + 1), lab(i, j + 1)))
    inner = [lab(0, j) for j in range(nt + 1)]
    outer = [lab(nr, j) for j in range(nt + 1)]
    edge0 = [lab(i, 0) for i in range(1, nr)]
    edge90 = [lab(i, nt) for i in range(1, nr)]
    lines += ["*Solid Section, elset=RING, material=M", "1.", "*Material, name=M", "*Elastic", "%g, %g" % (E, nu)]
    for name, lst in (("INNER", inner), ("OUTER", outer), ("EDGE0", edge0), ("EDGE90", edge90),
                      ("OCORNER", [outer[0], outer[-1]])):
        lines += ["*Nset, nset=" + name] + [", ".join(map(str, lst[k:k + 8])) for k in range(0, len(lst), 8)]
    lines += ["*Transform, nset=INNER, type=C", "0., 0., 0., 0., 0., 1.",
              "*Transform, nset=OUTER, type=C", "0., 0., -1., 0., 0., 3."]
    lines += ["*Step", "*Static", "1., 1.", "*Boundary", "INNER, 1, 1, %g" % ua, "INNER, 2, 2", "EDGE0, 2, 2",
              "EDGE90, 1, 1", "OCORNER, 2, 2", "*Node Print, nset=OUTER", "U1, U2", "*Node Print, nset=INNER", "RF1",
              "*Output, field", "*End Step"]
    rows = run(exe, out, "cylinder", lines)
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    A = ua / (a + (lam + mu) * b * b / (mu * a))
    B = (lam + mu) * A * b * b / mu
    ub = A * b + B / b
    sr_a = 2 * (lam + mu) * A - 2 * mu * B / (a * a)
    r = rows[-1]
    close("OUTER.U1 (radial, mean)", r["OUTER.U1"], ub, 3e-3)
    close("OUTER.U2 (tangential, mean)", r["OUTER.U2"], 0.0, 0.0, 1e-9 * ua)
    close("INNER.RF1 (radial reaction, sum)", r["INNER.RF1"], -sr_a * a * math.pi / 2, 5e-3)
    # the VTU frame stays global: U of each outer node = its radial displacement along (cos, sin), RF of each inner
    # node radial; the point order is the deck's node order (j outer, i inner)
    u, rf = last_frame(out, "cylinder")
    worst_u = worst_rf = 0.0
    for j in range(nt + 1):
        th = 0.5 * math.pi * j / nt
        e = (math.cos(th), math.sin(th))
        po, pi_ = lab(nr, j) - 1, lab(0, j) - 1
        worst_u = max(worst_u, abs(u[po][0] - r["OUTER.U1"] * e[0]), abs(u[po][1] - r["OUTER.U1"] * e[1]))
        if 0 < j < nt:  # (the corner nodes carry the symmetry planes' tangential reaction too)
            worst_rf = max(worst_rf, abs(rf[pi_][0] * e[1] - rf[pi_][1] * e[0]))
    close("VTU U of the outer nodes = U1 (r, theta)", worst_u, 0.0, 0.0, 1e-6 * ua)
    close("VTU RF of the inner nodes radial (cross product)", worst_rf, 0.0, 0.0, 1e-6 * abs(r["INNER.RF1"]))


def last_frame(out, job):
    """Point arrays U and RF of the last VTU frame of JOB.pvd."""
    import xml.etree.ElementTree as ET
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    pvd = ET.parse(os.path.join(out, job + ".pvd")).getroot()
    path = [d.get("file") for d in pvd.iter("DataSet")][-1]
    rd = vtkXMLUnstructuredGridReader()
    rd.SetFileName(os.path.join(out, path))
    rd.Update()
    pd = rd.GetOutput().GetPointData()
    return vtk_to_numpy(pd.GetArray("U")), vtk_to_numpy(pd.GetArray("RF"))


def dat_u(path, label):
    """The last *NODE PRINT row of node label in JOB.dat: U1, U2, U3."""
    got = None
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) == 4 and w[0] == str(label):
                try:
                    got = [float(x) for x in w[1:]]
                except ValueError:
                    pass
    if got is None:
        fail("no printed row of node %d in %s" % (label, path))
    return got


def case_cload(exe, out):
    nodes = block_nodes(2, 2.0, None)
    root = sorted(l for l, (xi, _) in nodes.items() if xi[0] == 0.0)
    tip = sorted(l for l, (xi, _) in nodes.items() if xi[0] == 2.0)
    node = tip[-1]
    other = tip[0]
    F = [3.0, -2.0, 5.0]
    G = mv(Q, F)
    a, b = mv(Q, [1, 0, 0]), mv(Q, [0, 1, 0])

    # a TYPE=S system at the loaded node: 1 radial from the centre c, 3 along (p - c) x (x - c), 2 = 3 x 1
    c, p = [-1.0, 0.3, -0.5], [-0.8, 1.3, -0.1]
    x = nodes[node][1]
    e1 = [x[k] - c[k] for k in range(3)]
    ax = [p[k] - c[k] for k in range(3)]
    e3 = [ax[1] * e1[2] - ax[2] * e1[1], ax[2] * e1[0] - ax[0] * e1[2], ax[0] * e1[1] - ax[1] * e1[0]]
    e1 = [v / math.sqrt(sum(w * w for w in e1)) for v in e1]
    e3 = [v / math.sqrt(sum(w * w for w in e3)) for v in e3]
    e2 = [e3[1] * e1[2] - e3[2] * e1[1], e3[2] * e1[0] - e3[0] * e1[2], e3[0] * e1[1] - e3[1] * e1[0]]
    S = [[e1[i], e2[i], e3[i]] for i in range(3)]

    def deck(local, equation=False):
        lines = ["*Heading", "cantilever, tip force local or global"] + mesh_lines(nodes, 2, 0.3)
        lines += ["*Nset, nset=ROOT", ", ".join(map(str, root))]
        for lab in tip:
            lines += ["*Nset, nset=N%d" % lab, str(lab)]
        if local == "S":
            lines += ["*Transform, nset=N%d, type=S" % node, ", ".join("%.15g" % v for v in c + p)]
        elif local is True:
            lines += ["*Transform, nset=N%d" % node, ", ".join("%.15g" % v for v in a + b)]
        if equation:
            lines += ["*Equation", "2", "%d, 1, 1., %d, 1, -1." % (node, other)]
        lines += ["*Step, nlgeom=YES", "*Static", "0.5, 1.", "*Boundary", "ROOT, 1, 3", "*Cload"]
        force = {True: F, False: G, "S": F, "SG": mv(S, F)}[local]
        lines += ["%d, %d, %.15g" % (node, k + 1, force[k]) for k in range(3)]
        for lab in tip:
            lines += ["*Node Print, nset=N%d" % lab, "U1, U2, U3"]
        lines += ["*Node Print, nset=ROOT", "RF1, RF2, RF3", "*End Step"]
        return lines

    ra = run(exe, os.path.join(out, "local"), "cload", deck(True))[-1]
    rb = run(exe, os.path.join(out, "global"), "cload", deck(False))[-1]
    scale = max(abs(v) for k, v in rb.items() if ".U" in k)
    for lab in tip:
        if lab == node:
            continue
        for k in range(3):
            key = "N%d.U%d" % (lab, k + 1)
            close("free tip node " + key, ra[key], rb[key], 0.0, 1e-8 * scale)
    ug = [rb["N%d.U%d" % (node, k + 1)] for k in range(3)]
    ul = mtv(Q, ug)
    for k in range(3):
        key = "N%d.U%d" % (node, k + 1)
        close("loaded node local " + key, ra[key], ul[k], 0.0, 1e-8 * scale)
    for k in range(3):
        # equilibrium holds to Newton's force tolerance (R_n = 0.005 of the typical force): 1e-5
        close("root RF%d" % (k + 1), ra["ROOT.RF%d" % (k + 1)], -G[k], 1e-5, 1e-5 * max(map(abs, G)))
    # the printed table (JOB.dat) shows the same local components
    pu = dat_u(os.path.join(out, "local", "cload.dat"), node)
    for k in range(3):
        close("JOB.dat U%d of node %d (local)" % (k + 1, node), pu[k], ul[k], 1e-3, 1e-9)
    # TYPE=S: the force in the spherical system at the node against S F in global components
    rs = run(exe, os.path.join(out, "spherical"), "cload", deck("S"))[-1]
    rg = run(exe, os.path.join(out, "spherical_global"), "cload", deck("SG"))[-1]
    ug = [rg["N%d.U%d" % (node, k + 1)] for k in range(3)]
    ul = mtv(S, ug)
    for k in range(3):
        key = "N%d.U%d" % (node, k + 1)
        close("TYPE=S loaded node local " + key, rs[key], ul[k], 0.0, 1e-8 * scale)
        key = "N%d.U%d" % (other, k + 1)
        close("TYPE=S free node " + key, rs[key], rg[key], 0.0, 1e-8 * scale)
    rc = run(exe, os.path.join(out, "equation"), "cload", deck(True, True))[-1]
    close("*EQUATION: local U1 of the loaded node = U1 of node %d" % other, rc["N%d.U1" % node],
          rc["N%d.U1" % other], 1e-10, 1e-14)
    if abs(rc["N%d.U1" % node]) < 1e-6:
        fail("*EQUATION case: no displacement")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=["roller", "roller_nlgeom", "instance", "cylinder", "cload"])
    o = ap.parse_args()
    exe = os.path.abspath(o.exe)
    out = os.path.abspath(o.out)
    os.makedirs(out, exist_ok=True)
    if o.case == "roller":
        case_roller(exe, out, False)
    elif o.case == "roller_nlgeom":
        case_roller(exe, out, True)
    elif o.case == "instance":
        case_instance(exe, out)
    elif o.case == "cylinder":
        case_cylinder(exe, out)
    else:
        case_cload(exe, out)
    print("PASS")


if __name__ == "__main__":
    main()
