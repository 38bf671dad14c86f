#!/usr/bin/env python3
"""*DLOAD CENTRIF and ROTA (rotational body forces) against the closed forms of a spinning disc.

  check_rotational_loads.py --exe BIN --out DIR --case NAME

The decks (written into DIR) mesh an annulus a = 1, b = 4 spinning about z (E = 1000, nu = 0.3, density 1,
NLGEOM=NO unless said), with the magnitude omega^2 = 1 of CENTRIF (the force per unit volume is the density times
omega^2 times the distance from the axis).

Cases:
  centrif_plane_stress  a CPS4 quarter annulus on symmetry planes, nr x nt = 16 x 48 and 32 x 96: the radial
            displacement of the inner and outer edges against the plane-stress solution of a rotating annulus with
            free edges, u = r/E (s_t - nu s_r), s_r = (3 + nu)/8 rho w^2 (a^2 + b^2 - a^2 b^2/r^2 - r^2),
            s_t = (3 + nu)/8 rho w^2 (a^2 + b^2 + a^2 b^2/r^2 - (1 + 3 nu)/(3 + nu) r^2): within 0.3 % on the
            coarse mesh and 0.1 % on the fine one (measured -0.24 % and -0.06 % at the inner edge: the
            straight-edged elements' polygon), the error falling at least 3 times per halving (second order).
  centrif_axisymmetric  a CAX4 strip of the annulus (16 radial elements, one in z) held at u_z = 0 on both faces:
            plane strain, the same solution with E / (1 - nu^2) and nu / (1 - nu): 0.3 % (measured -0.06 %).
  centrif_3d  a C3D8 quarter annulus 16 x 48, one element thick, u_z = 0 on both faces, the axis given by a point
            and a direction (0, 0, 1): the plane-strain solution within 0.3 % (measured -0.09 % inner, -0.04 % outer).
  rota      a CPS4 full annulus 16 x 96 clamped at its inner edge under ROTA (alpha = 1 about +z, the d'Alembert
            force -rho alpha z x r): pure shear, tau = rho alpha (b^4 - r^4)/(4 r^2), and the tangential
            displacement u_t(b) = b rho alpha/(8 G) (b^4 (1/a^2 - 1/b^2) + a^2 - b^2), negative (against the
            acceleration): within 0.5 % (measured -0.35 %), the radial one below 1e-3 of it.
  centrif_nlgeom  the C3D8 plane-strain quarter annulus of the neo-Hookean user UMAT (--user; its tangent is
            exact) under NLGEOM spun to omega^2 = 8 (radial strain 10 %): the centrifugal force follows the deforming
            body, and its load stiffness makes Newton quadratic: every increment converges in at most 5 iterations
            to r/q < 1e-8, each ratio below 10 times the square of the one before while that one is above 1e-5
            (measured 1.6e-2, 2.9e-6, 2.8e-11; without the load stiffness the rate is linear, 3.4e-2, 5.9e-4,
            1.1e-5, measured on the plane-stress mesh); the *ELASTIC disc at omega^2 = 0.01 under NLGEOM equals the
            small-strain answer within 1e-3 (they differ by O(strain) = 1.3e-4; measured 1.5e-4).
"""
import argparse
import csv
import math
import os
import subprocess
import sys

E, NU, A, B = 1000.0, 0.3, 1.0, 4.0


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, out, job, lines, user=None):
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = [exe, "-q", "--out", os.path.join(out, job), path]
    if user:
        cmd[1:1] = ["--user", user]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s%s" % (job, r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
    with open(os.path.join(out, job, job + ".csv")) as f:
        return list(csv.DictReader(f))


def u_rotating(r, e=E, nu=NU, w2=1.0, rho=1.0):
    """Radial displacement of a rotating plane-stress annulus a..b with free edges."""
    c = (3 + nu) / 8 * rho * w2
    sr = c * (A * A + B * B - A * A * B * B / r ** 2 - r * r)
    st = c * (A * A + B * B + A * A * B * B / r ** 2 - (1 + 3 * nu) / (3 + nu) * r * r)
    return r / e * (st - nu * sr)


def u_plane_strain(r):
    return u_rotating(r, E / (1 - NU * NU), NU / (1 - NU))


def annulus(nr, nt, sweep, etype, z=None):
    """Nodes and elements of an annulus sector (sweep in degrees); z: two layers at 0 and z (C3D8)."""
    nodes, elems = {}, []
    closed = sweep >= 360.0
    ntn = nt if closed else nt + 1
    layers = [0.0] if z is None else [0.0, z]
    def nid(i, j, k=0):
        return 1 + i + (nr + 1) * (j % ntn + ntn * k)
    for k, zz in enumerate(layers):
        for j in range(ntn):
            th = math.radians(sweep) * j / nt
            for i in range(nr + 1):
                r = A + (B - A) * i / nr
                nodes[nid(i, j, k)] = (r * math.cos(th), r * math.sin(th), zz)
    for j in range(nt):
        for i in range(nr):
            q = [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]
            if z is not None:
                q += [nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)]
            elems.append(q)
    lines = ["*HEADING", "spinning annulus", "*NODE"]
    nd = 2 if z is None else 3
    lines += ["%d, %s" % (n, ", ".join(repr(c) for c in p[:nd])) for n, p in sorted(nodes.items())]
    lines.append("*ELEMENT, TYPE=%s, ELSET=DISC" % etype)
    lines += ["%d, %s" % (e + 1, ", ".join(map(str, q))) for e, q in enumerate(elems)]
    ks = range(len(layers))
    lines.append("*NSET, NSET=XAX\n" + ", ".join(str(nid(i, 0, k)) for i in range(nr + 1) for k in ks))
    if not closed:
        lines.append("*NSET, NSET=YAX\n" + ", ".join(str(nid(i, nt, k)) for i in range(nr + 1) for k in ks))
    lines.append("*NSET, NSET=INNER\n" + ", ".join(str(nid(0, j, k)) for j in range(ntn) for k in ks))
    lines.append("*NSET, NSET=RIN\n%d" % nid(0, 0))
    lines.append("*NSET, NSET=ROUT\n%d" % nid(nr, 0))
    if z is not None:
        lines.append("*NSET, NSET=ALL\n" + ", ".join(map(str, sorted(nodes))))
    return lines


def material(thickness=None, hyperelastic=False):
    lines = ["*SOLID SECTION, ELSET=DISC, MATERIAL=M"]
    if thickness is not None:
        lines.append(repr(thickness))
    law = ["*ELASTIC", "%r, %r" % (E, NU)]
    if hyperelastic:
        # the neo-Hookean user UMAT (mu, lambda of E, nu): its tangent is exact, so Newton's rate shows the load's
        mu, lam = E / (2 * (1 + NU)), E * NU / ((1 + NU) * (1 - 2 * NU))
        law = ["*USER MATERIAL, CONSTANTS=2", "%r, %r" % (mu, lam)]
    return lines + ["*MATERIAL, NAME=M"] + law + ["*DENSITY", "1."]


def step(load, nlgeom="NO", inc="1., 1.", extra=()):
    return ["*STEP, NLGEOM=%s, INC=200" % nlgeom, "*STATIC", inc, "*DLOAD", load] + list(extra) + [
        "*NODE PRINT, NSET=RIN", "U", "*NODE PRINT, NSET=ROUT", "U", "*END STEP"]


def quarter_plane_stress(nr, nt, load, nlgeom="NO", inc="1., 1.", hyperelastic=False):
    return (annulus(nr, nt, 90.0, "CPS4") + material(1.0, hyperelastic) + ["*BOUNDARY", "XAX, 2, 2", "YAX, 1, 1"]
            + step(load, nlgeom, inc))


def check_radial(row, want, tol, what):
    for key, r in (("RIN.U1", A), ("ROUT.U1", B)):
        got = float(row[key])
        err = got / want(r) - 1
        print("%s %s: %.10g, closed form %.10g (%+.4f %%)" % (what, key, got, want(r), 100 * err))
        if abs(err) > tol:
            fail("%s %s: error %.3g beyond %.3g" % (what, key, err, tol))
    return float(row["RIN.U1"]) / want(A) - 1


def case_centrif_plane_stress(exe, out):
    errs = []
    for nr, nt, tol in ((16, 48, 3e-3), (32, 96, 1e-3)):
        row = run(exe, out, "disc_%d" % nr, quarter_plane_stress(nr, nt, "DISC, CENTRIF, 1.0, 0., 0., 0., 0., 0., 1."))
        errs.append(check_radial(row[-1], u_rotating, tol, "plane stress %d x %d" % (nr, nt)))
    if not abs(errs[0]) >= 3 * abs(errs[1]):
        fail("the error does not fall at second order: %.3g then %.3g" % tuple(errs))


def case_centrif_axisymmetric(exe, out):
    nr, h = 16, 0.25
    lines = ["*HEADING", "spinning cylinder, axisymmetric, plane strain", "*NODE"]
    for i in range(nr + 1):
        r = A + (B - A) * i / nr
        lines += ["%d, %r, 0." % (i + 1, r), "%d, %r, %r" % (i + 101, r, h)]
    lines.append("*ELEMENT, TYPE=CAX4, ELSET=DISC")
    lines += ["%d, %d, %d, %d, %d" % (i + 1, i + 1, i + 2, i + 102, i + 101) for i in range(nr)]
    lines.append("*NSET, NSET=FACES\n" + ", ".join(str(n) for i in range(nr + 1) for n in (i + 1, i + 101)))
    lines += ["*NSET, NSET=RIN\n1", "*NSET, NSET=ROUT\n%d" % (nr + 1)]
    lines += material() + ["*BOUNDARY", "FACES, 2, 2"]
    row = run(exe, out, "disc_cax4", lines + step("DISC, CENTRIF, 1.0"))
    check_radial(row[-1], u_plane_strain, 3e-3, "axisymmetric plane strain")


def case_centrif_3d(exe, out):
    lines = annulus(16, 48, 90.0, "C3D8", z=0.25) + material() + ["*BOUNDARY", "XAX, 2, 2", "YAX, 1, 1", "ALL, 3, 3"]
    row = run(exe, out, "disc_c3d8", lines + step("DISC, CENTRIF, 1.0, 0., 0., 0., 0., 0., 1."))
    check_radial(row[-1], u_plane_strain, 3e-3, "C3D8 plane strain")


def case_rota(exe, out):
    lines = annulus(16, 96, 360.0, "CPS4") + material(1.0) + ["*BOUNDARY", "INNER, ENCASTRE"]
    row = run(exe, out, "disc_rota", lines + step("DISC, ROTA, 1.0, 0., 0., 0., 0., 0., 1."))[-1]
    g = E / (2 * (1 + NU))
    want = B / (8 * g) * (B ** 4 * (1 / A ** 2 - 1 / B ** 2) + A * A - B * B)
    ut, ur = -float(row["ROUT.U2"]), float(row["ROUT.U1"])
    # the outer node on +x: tangential = +y; the d'Alembert force opposes the acceleration: u_t = -want
    print("ROTA: tangential displacement at b %.10g, closed form %.10g (%+.4f %%), radial %.3g"
          % (-ut, -want, 100 * (ut / want - 1), ur))
    if abs(ut / want - 1) > 5e-3:
        fail("ROTA: tangential displacement off by %.3g" % (ut / want - 1))
    if abs(ur) > 1e-3 * abs(want):
        fail("ROTA: radial displacement %.3g" % ur)


def sta_ratios(path):
    """Per converged increment, the r/q ratios of its iterations."""
    out = []
    with open(path) as f:
        for line in f:
            if " converged " not in line or "r/q:" not in line:
                continue
            out.append([float(x) for x in line.split("r/q:")[1].split()])
    return out


def case_centrif_nlgeom(exe, out, user):
    if not user:
        fail("centrif_nlgeom needs --user (the neo-Hookean UMAT)")
    load = "DISC, CENTRIF, 8.0, 0., 0., 0., 0., 0., 1."
    lines = annulus(16, 48, 90.0, "C3D8", z=0.25) + material(None, True) + ["*BOUNDARY", "XAX, 2, 2", "YAX, 1, 1",
                                                                            "ALL, 3, 3"]
    row = run(exe, out, "disc_nlgeom", lines + step(load, "YES", "0.25, 1."), user)[-1]
    print("NLGEOM omega^2 = 8: outer radial displacement %s (linear %.6g)" % (row["ROUT.U1"], 8 * u_rotating(B)))
    for k, r in enumerate(sta_ratios(os.path.join(out, "disc_nlgeom", "disc_nlgeom.sta"))):
        print("increment %d: r/q %s" % (k + 1, " ".join("%.2e" % x for x in r)))
        if len(r) > 6 or r[-1] > 1e-8:
            fail("increment %d: not converged quadratically in 5 iterations: %s" % (k + 1, r))
        # quadratic: each ratio at most 10 times the square of the one before, while that one is above the
        # round-off floor (1e-5)
        for j in range(2, len(r)):
            if r[j - 1] > 1e-5 and not r[j] <= 10 * r[j - 1] ** 2:
                fail("increment %d: ratio %.3g is not of the order of the square of %.3g" % (k + 1, r[j], r[j - 1]))
    small = "DISC, CENTRIF, 0.01, 0., 0., 0., 0., 0., 1."
    lin = run(exe, out, "disc_small", quarter_plane_stress(16, 48, small))[-1]
    nl = run(exe, out, "disc_small_nlgeom", quarter_plane_stress(16, 48, small, "YES"))[-1]
    for key in ("RIN.U1", "ROUT.U1"):
        a, b = float(lin[key]), float(nl[key])
        print("small spin %s: NLGEOM %.10g, small strain %.10g" % (key, b, a))
        if abs(b / a - 1) > 1e-3:
            fail("small spin: NLGEOM differs from the small-strain answer by %.3g" % (b / a - 1))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--case", required=True)
    p.add_argument("--user", help="the neo-Hookean user UMAT (centrif_nlgeom)")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = {"centrif_plane_stress": case_centrif_plane_stress, "centrif_axisymmetric": case_centrif_axisymmetric,
             "centrif_3d": case_centrif_3d, "rota": case_rota, "centrif_nlgeom": None}
    if a.case not in cases:
        fail("unknown case " + a.case)
    if a.case == "centrif_nlgeom":
        case_centrif_nlgeom(a.exe, a.out, a.user)
    else:
        cases[a.case](a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
