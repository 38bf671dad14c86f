#!/usr/bin/env python3
"""*COUPLING, ORIENTATION= (constrained dofs in local directions) and partial rotational *DISTRIBUTING against
twin decks written as *EQUATION with hand-computed directions, statics and Saint-Venant torsion.

  check_coupling_local.py --exe BIN --out DIR --case NAME

The cantilever of check_couplings.py (C3D8I, L = 10 along x, 1 x 1 section, E = 1000, nu = 0, root encastred, the
tip face x = L the surface TIPS of the coupling nodes, reference node R = node 100000).

Cases:
  kinematic_cylindrical  *ORIENTATION, SYSTEM=CYLINDRICAL about the beam's axis (y = z = 0.5), *KINEMATIC 2 (the
                tangential dof only: a twist that leaves the radial motion free, the Analysis User's Guide's example),
                R on the axis with its rotation about x prescribed (0.01) and its translations held, against the twin
                deck writing for each tip node e_t . u_s - e_t . (theta x r_s) = 0 as an *EQUATION (e_t = (0, -(z -
                0.5), y - 0.5)/rho, the tangential direction at the node; theta carried by a prescribed dof of a node
                of no element): every tip displacement and root reaction within 1e-9 of the largest. The tip face's
                centre node lies on the axis, where the system defines no tangential direction: it is left free
                (a warning; the twin has no equation for it).
  kinematic_rectangular  an oblique RECTANGULAR orientation (local 1 = (0.8, 0.6, 0), local 2 = (-0.48, 0.64,
                0.6)), *KINEMATIC 1, 2 (two local dofs per node: solved for two global components), R off the face
                with a prescribed translation and rotation, against the twin with e_k . (u_s - u_R - theta x r_s) = 0
                for k = 1, 2 as *EQUATIONs: 1e-9.
  kinematic_assembly  the cylindrical case in Abaqus/CAE's layout (mesh in a *Part; reference node, surface,
                *Orientation with a quoted datum name and *Coupling in the assembly) against the model-level deck:
                1e-12 (the same equations).
  distributing_partial  *DISTRIBUTING 4, 4 (every translation and the rotation about x; dofs 5, 6 released) on an
                L-shaped face (three of the four tip elements: the face's inertia T is not diagonal), R off the
                face, force F and torque M about x at R. Statics, exact: the root reactions sum to -F and their
                moment is -(x_R x F + M) (1e-9 of |F| L), which holds because the reference moment is distributed
                with the full inertia, F_n = w_n (F + T^-1 (M + r_R x F) x r_n); with the inertia about x only the
                reactions would carry a moment about y and z. Twin: the same loads on *DISTRIBUTING 1, 6 (every
                rotation), which transmits the same forces when dofs 5, 6 carry no load: 1e-9. The same for
                *DISTRIBUTING 6, 6 with a torque about z. A moment on a released rotation is refused.
  distributing_torsion  *DISTRIBUTING 4, 4 on the whole square tip face, R at its centre, a torque M = 0.4 about x:
                the twist rate between the sections x = 0.4 L and 0.8 L (least-squares rotations of their nodes, away
                from the warping restrained at the root and from the loaded end) on 6 x 6 and 8 x 8 sections,
                Richardson-extrapolated (error O(h^2): measured -2.31 % and -1.32 %), against Saint-Venant torsion
                M / (G J), G = E/2, J = 0.1406 a^4 (square section, Timoshenko and Goodier): within 0.5 % (the
                constant's 4 digits and the extrapolation's remainder; measured -0.05 %).
"""
import argparse
import csv
import math
import os
import subprocess

from check_couplings import Beam, E, check, compare_rows, cross, fail, run, statics, sub


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def equation(terms):
    """An *EQUATION block from (node, dof, coefficient) terms (zero coefficients dropped)."""
    terms = [t for t in terms if t[2] != 0.0]
    lines = [str(len(terms))]
    for i in range(0, len(terms), 4):
        lines.append(", ".join("%d, %d, %r" % t for t in terms[i:i + 4]))
    return lines


def local_twin(beam, ref, dirs, u_ref, theta):
    """*EQUATIONs e . (u_s - u_R - theta x r_s) = 0 for each tip node s and direction e in dirs(s) (R = node 100000,
    theta = the translations of node 100001, both prescribed): the first term the node's largest component."""
    eq = ["*EQUATION"]
    for n in beam.tip:
        r = sub(beam.x[n], ref)
        for e in dirs(n):
            first = max(range(3), key=lambda i: abs(e[i]))
            terms = [(n, first + 1, e[first])] + [(n, i + 1, e[i]) for i in range(3) if i != first]
            terms += [(100000, i + 1, -e[i]) for i in range(3)]
            g = [[1.0 if i == j else 0.0 for i in range(3)] for j in range(3)]
            terms += [(100001, j + 1, -dot(cross(g[j], r), e)) for j in range(3)]
            eq += equation(terms)
    bc = ["*BOUNDARY"] + ["100000, %d, %d, %r" % (i + 1, i + 1, u_ref[i]) for i in range(3)]
    bc += ["100001, %d, %d, %r" % (i + 1, i + 1, theta[i]) for i in range(3)]
    return ["*NODE", "100001, 0., 0., 0."] + eq, bc


def oriented_pair(exe, out, name, beam, ref, orientation, kind, dirs, u_ref, theta, warn=None):
    """The coupling deck (R prescribed) and its *EQUATION twin, run and compared."""
    bc = ["*BOUNDARY"] + ["REF, %d, %d, %r" % (i + 1, i + 1, u_ref[i]) for i in range(3)]
    bc += ["REF, %d, %d, %r" % (i + 4, i + 4, theta[i]) for i in range(3)]
    lines = beam.mesh(ref) + orientation
    lines += ["*COUPLING, CONSTRAINT NAME=C1, REF NODE=REF, SURFACE=TIPS, ORIENTATION=OR"] + kind
    lines += ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1."] + bc + beam.prints() + ["*END STEP"]
    path = os.path.join(out, name + ".inp")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, name), path], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s" % (name, r.returncode, r.stderr[-2000:]))
    if warn is not None and warn not in r.stderr:
        fail("%s: expected the warning '%s', got: %s" % (name, warn, r.stderr[-1000:]))
    with open(os.path.join(out, name, name + ".csv")) as f:
        a = list(csv.DictReader(f))[-1]
    eq, twin_bc = local_twin(beam, ref, dirs, u_ref, theta)
    lines = beam.mesh(ref) + eq + ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1."] + twin_bc
    b = run(exe, out, name + "_equation_twin", "\n".join(lines + beam.prints() + ["*END STEP"]) + "\n")[-1]
    compare_rows(a, b, 1e-9)


def case_kinematic_cylindrical(exe, out):
    beam = Beam()
    ref = [beam.L + 1.0, 0.5, 0.5]

    def tangential(n):
        y, z = beam.x[n][1] - 0.5, beam.x[n][2] - 0.5
        rho = math.hypot(y, z)
        return [] if rho < 1e-12 else [[0.0, -z / rho, y / rho]]
    orientation = ["*ORIENTATION, NAME=OR, SYSTEM=CYLINDRICAL", "0., 0.5, 0.5, 1., 0.5, 0.5"]
    oriented_pair(exe, out, "kinematic_cylindrical", beam, ref, orientation, ["*KINEMATIC", "2"], tangential,
                  [0.0, 0.0, 0.0], [0.01, 0.0, 0.0], warn="lies on the axis of cylindrical orientation OR")


def case_kinematic_assembly(exe, out):
    """The cylindrical case as Abaqus/CAE writes it: the mesh in a part, the reference node, the surface, the
    *Orientation (a quoted datum name) and the *Coupling in the assembly; against the model-level deck."""
    beam = Beam()
    ref = [beam.L + 1.0, 0.5, 0.5]
    flat = beam.mesh(ref)
    part = [l for l in flat[flat.index("*NODE"):flat.index("*SURFACE, NAME=TIPS\nTIPE, S4")]
            if not l.startswith("100000,") and l != "*NSET, NSET=REF\n100000"]
    tip = flat[[i for i, l in enumerate(flat) if l.startswith("*ELSET, ELSET=TIPE")][0]].split("\n")[1]
    bc = ["*BOUNDARY", "REF, 1, 3", "REF, 4, 4, 0.01", "REF, 5, 6"]
    orient = ["0., 0.5, 0.5, 1., 0.5, 0.5"]
    cae = ["*Heading", "CAE layout", "*Part, name=Beam"] + part + ["*Solid Section, elset=BEAM, material=M", ",",
           "*End Part", "*Assembly, name=Assembly", "*Instance, name=I, part=Beam", "*End Instance",
           "*Node", "100000, %r, %r, %r" % tuple(ref), "*Nset, nset=REF", "100000",
           "*Elset, elset=_T_S4, internal, instance=I", tip, "*Surface, type=ELEMENT, name=T", "_T_S4, S4",
           '*Orientation, name="Datum csys-1", system=CYLINDRICAL'] + orient + [
           '*Coupling, constraint name=C1, ref node=REF, surface=T, orientation="Datum csys-1"', "*Kinematic", "2",
           "*End Assembly", "*Material, name=M", "*Elastic", "%r, 0." % E, "*Boundary", "I.ROOT, ENCASTRE",
           "*Step", "*Static", "1., 1."] + bc
    for n in beam.root:
        cae += ["*NODE PRINT, NSET=I.N%d" % n, "RF"]
    for n in beam.tip:
        cae += ["*NODE PRINT, NSET=I.N%d" % n, "U"]
    a = run(exe, out, "kinematic_assembly", "\n".join(cae + ["*End Step"]) + "\n")[-1]
    flat_deck = flat + ["*ORIENTATION, NAME=OR, SYSTEM=CYLINDRICAL"] + orient + [
        "*COUPLING, CONSTRAINT NAME=C1, REF NODE=REF, SURFACE=TIPS, ORIENTATION=OR", "*KINEMATIC", "2",
        "*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1."] + bc + beam.prints()[2:] + ["*END STEP"]
    b = run(exe, out, "kinematic_model_level", "\n".join(flat_deck) + "\n")[-1]
    a = {k[2:] if k.startswith("I.") else k: v for k, v in a.items()}
    compare_rows(a, b, 1e-12)


def case_kinematic_rectangular(exe, out):
    beam = Beam()
    ref = [beam.L + 2.0, 0.7, 0.4]
    e1, e2 = [0.8, 0.6, 0.0], [-0.48, 0.64, 0.6]
    orientation = ["*ORIENTATION, NAME=OR", "%r, %r, %r, %r, %r, %r" % tuple(e1 + e2)]
    oriented_pair(exe, out, "kinematic_rectangular", beam, ref, orientation, ["*KINEMATIC", "1, 2"],
                  lambda n: [e1, e2], [0.001, -0.002, 0.0015], [0.0004, -0.0003, 0.0002])


def l_face_deck(beam, ref, dofs, loads):
    """The cantilever with its coupling on three of the four tip elements (an L-shaped face)."""
    lines = beam.mesh(ref)
    tip = [e for e in range(1, beam.nx * beam.ny * beam.nz + 1) if e % beam.nx == 0]
    lines += ["*ELSET, ELSET=TIPL\n" + ", ".join(map(str, tip[:-1])), "*SURFACE, NAME=TIPSL\nTIPL, S4"]
    lines += ["*COUPLING, CONSTRAINT NAME=C1, REF NODE=REF, SURFACE=TIPSL", "*DISTRIBUTING"] + dofs
    lines += ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1.", "*CLOAD"] + loads
    return "\n".join(lines + beam.prints() + ["*END STEP"]) + "\n"


def case_distributing_partial(exe, out):
    beam = Beam()
    ref = [beam.L + 2.0, 0.7, 0.4]
    force = [0.3, -0.2, 0.5]
    for axis in (1, 3):
        moment = [0.4 if i == axis - 1 else 0.0 for i in range(3)]
        loads = ["REF, %d, %r" % (i + 1, force[i]) for i in range(3)] + ["REF, %d, %r" % (axis + 3, 0.4)]
        name = "distributing_partial_%d" % (axis + 3)
        a = run(exe, out, name, l_face_deck(beam, ref, ["%d, %d" % (axis + 3, axis + 3)], loads))[-1]
        statics(beam, a, ref, force, moment)
        b = run(exe, out, name + "_all", l_face_deck(beam, ref, ["1, 6"], loads))[-1]
        compare_rows(a, b, 1e-9)
    loads = ["REF, 3, 0.5", "REF, 5, 0.4"]
    text = l_face_deck(beam, ref, ["4, 4"], loads)
    msg = run(exe, out, "distributing_released_moment", text, expect=2)
    line = text.split("\n").index("REF, 5, 0.4") + 1
    if "distributing_released_moment.inp:%d: *CLOAD:" % line not in msg:
        fail("a moment on a released rotation: expected an error at line %d, got: %s" % (line, msg))
    print("a moment on a released rotation refused: " + msg.strip().splitlines()[-1])


def twist_rate(exe, out, n):
    """The twist rate between x = 0.4 L and 0.8 L of the n x n section's cantilever under a tip torque."""
    beam = Beam(ny=n, nz=n)
    ref = [beam.L, 0.5, 0.5]
    moment = 0.4
    sections = (2 * beam.nx // 5, 4 * beam.nx // 5)
    lines = beam.mesh(ref) + ["*COUPLING, CONSTRAINT NAME=C1, REF NODE=REF, SURFACE=TIPS", "*DISTRIBUTING", "4, 4"]
    for i in sections:
        lines.append("*NSET, NSET=X%d\n" % i + ", ".join(str(beam.nid(i, j, k)) for j in range(n + 1)
                                                          for k in range(n + 1)))
    lines += ["*BOUNDARY", "ROOT, ENCASTRE", "*STEP", "*STATIC", "1., 1.", "*CLOAD", "REF, 4, %r" % moment]
    lines += ["*NODE PRINT, NSET=X%d\nU" % i for i in sections]
    job = "distributing_torsion_%d" % n
    run(exe, out, job, "\n".join(lines + beam.prints() + ["*END STEP"]) + "\n")
    u = read_dat_u(os.path.join(out, job, job + ".dat"))
    rot = []
    for i in sections:
        nodes = [beam.nid(i, j, k) for j in range(n + 1) for k in range(n + 1)]
        num = sum((beam.x[m][1] - 0.5) * u[m][2] - (beam.x[m][2] - 0.5) * u[m][1] for m in nodes)
        den = sum((beam.x[m][1] - 0.5) ** 2 + (beam.x[m][2] - 0.5) ** 2 for m in nodes)
        rot.append(num / den)
    rate = (rot[1] - rot[0]) / (beam.L * (sections[1] - sections[0]) / beam.nx)
    print("%d x %d section: twist rate %.8g" % (n, n, rate))
    return rate


def case_distributing_torsion(exe, out):
    r6, r8 = twist_rate(exe, out, 6), twist_rate(exe, out, 8)
    rate = (64.0 * r8 - 36.0 * r6) / 28.0
    want = 0.4 / (E / 2.0 * 0.1406)
    print("extrapolated twist rate %.8g, Saint-Venant %.8g (%+.3f %%)" % (rate, want, 100 * (rate / want - 1)))
    check("twist rate against Saint-Venant torsion", rate, want, 0.005 * want)


def read_dat_u(path):
    """The last U1..U3 of each node in the JOB.dat tables."""
    u = {}
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 4 and p[0].isdigit():
                u[int(p[0])] = [float(v) for v in p[1:]]
    return u


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--case", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = {"kinematic_cylindrical": case_kinematic_cylindrical,
             "kinematic_rectangular": case_kinematic_rectangular, "kinematic_assembly": case_kinematic_assembly,
             "distributing_partial": case_distributing_partial, "distributing_torsion": case_distributing_torsion}
    if a.case not in cases:
        fail("unknown case " + a.case)
    cases[a.case](a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
