"""Thick cylinders under bore pressure and their closed form (Lame): the decks of the regression checks of loads
(tests/regression/check_loads.py) and of the locking study (locking_study.py): quarter or full rings in plane
strain (CPE4, C3D8 one element thick), quadratic rings (CPE8(R), C3D20(R), CPS8(R)) and axisymmetric cylinders
(CAX4, CAX8(R)).
"""
import math


def write(path, lines):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def ring_deck(path, a, b, nr, nt, p, quarter=True, three_d=False, nlgeom=False, material=None, steps=1,
              surface=True, unsymm=False):
    """Thick cylinder a < r < b under internal pressure p: plane strain CPE4 (or C3D8 one element thick with
    u3 = 0), a quarter with symmetry planes or the full ring (held against rigid motion at three inner nodes)."""
    span = math.pi / 2 if quarter else 2 * math.pi
    ntn = nt + 1 if quarter else nt
    layers = 2 if three_d else 1
    nid = lambda i, j, k=0: k * (nr + 1) * ntn + (j % ntn) * (nr + 1) + i + 1
    out = ["*HEADING", "thick cylinder under pressure (tools/ldfcz_tools/ring_decks.py)", "*NODE, NSET=ALL"]
    for k in range(layers):
        for j in range(ntn):
            for i in range(nr + 1):
                r = a + (b - a) * i / nr
                t = span * j / nt
                out.append("%d, %.15g, %.15g" % (nid(i, j, k), r * math.cos(t), r * math.sin(t)) +
                           (", %g" % (0.1 * k) if three_d else ""))
    out.append("*ELEMENT, TYPE=%s, ELSET=RING" % ("C3D8" if three_d else "CPE4"))
    e = 1
    for j in range(nt):
        for i in range(nr):
            c = [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)]
            if three_d:
                c = c + [nid(i, j, 1), nid(i + 1, j, 1), nid(i + 1, j + 1, 1), nid(i, j + 1, 1)]
            out.append("%d, %s" % (e, ", ".join(str(n) for n in c)))
            e += 1
    out.append("*ELSET, ELSET=INNER")
    out += ["%d," % (j * nr + 1) for j in range(nt)]
    out += ["*NSET, NSET=RIN"] + ["%d," % nid(0, 0)] + ["*NSET, NSET=ROUT"] + ["%d," % nid(nr, 0)]
    face = "S6" if three_d else "S4"
    if quarter:
        out += ["*NSET, NSET=T0"] + ["%d," % nid(i, 0, k) for k in range(layers) for i in range(nr + 1)]
        out += ["*NSET, NSET=T90"] + ["%d," % nid(i, nt, k) for k in range(layers) for i in range(nr + 1)]
    mat = material or ["*ELASTIC", "1000., 0.3"]
    out += ["*SOLID SECTION, ELSET=RING, MATERIAL=M", "*MATERIAL, NAME=M"] + mat
    if surface:
        out += ["*SURFACE, NAME=BORE", "INNER, %s" % face]
    out += ["*BOUNDARY"]
    if quarter:
        out += ["T0, 2, 2", "T90, 1, 1"]
    else:
        q = nt // 4
        out += ["%d, 2, 2" % nid(0, 0), "%d, 2, 2" % nid(0, 2 * q), "%d, 1, 1" % nid(0, q)]
    if three_d:
        out += ["ALL, 3, 3"]
    for st in range(steps):
        out += ["*STEP, NLGEOM=%s, INC=100%s" % ("YES" if nlgeom else "NO", ", UNSYMM=YES" if unsymm else ""),
                "*STATIC", "%g, 1., 1e-5, %g" % (0.25, 0.25)]
        if surface:
            out += ["*DSLOAD", "BORE, P, %.15g" % (p * (st + 1))]
        else:
            out += ["*DLOAD", "INNER, P%s, %.15g" % (face[1], p * (st + 1))]
        out += ["*NODE PRINT, NSET=RIN", "U1", "*NODE PRINT, NSET=ROUT", "U1", "*END STEP"]
    write(path, out)


def lame(r, a, b, p, e, nu):
    """Plane-strain radial displacement of a thick cylinder under internal pressure p (Lame)."""
    big_a = p * a * a / (b * b - a * a)
    big_b = p * a * a * b * b / (b * b - a * a)
    return (1 + nu) / e * ((1 - 2 * nu) * big_a * r + big_b / r)


def lame_plane_stress(r, a, b, p, e, nu):
    """Plane-stress radial displacement of a thin disc with a hole under internal pressure p (Lame)."""
    big_a = p * a * a / (b * b - a * a)
    big_b = p * a * a * b * b / (b * b - a * a)
    return ((1 - nu) * big_a * r + (1 + nu) * big_b / r) / e


def quadratic_ring_deck(path, etype, a, b, nr, nt, p):
    """Quarter of the thick cylinder a < r < b under internal pressure p (*DSLOAD on S4 / S6) meshed with quadratic
    elements (CPE8, CPE8R; C3D20, C3D20R one element thick with u3 = 0): mid-side nodes on the circles (curved,
    isoparametric edges), symmetry planes t = 0 and t = 90 degrees."""
    three_d = etype.startswith("C3D")
    ids = {}

    def nid(i, j, k=0):
        return ids[(i, j, k)]
    out = ["*HEADING", "thick cylinder, quadratic %s elements (tools/ldfcz_tools/ring_decks.py)" % etype,
           "*NODE, NSET=ALL"]
    # doubled grid; only the nodes an element uses (no face or body centres)
    for k in range(3 if three_d else 1):
        for j in range(2 * nt + 1):
            for i in range(2 * nr + 1):
                odd = (i % 2) + (j % 2) + (k % 2)
                if odd > 1:
                    continue
                ids[(i, j, k)] = len(ids) + 1
                r = a + (b - a) * i / (2 * nr)
                t = math.pi / 2 * j / (2 * nt)
                out.append("%d, %.15g, %.15g" % (ids[(i, j, k)], r * math.cos(t), r * math.sin(t)) +
                           (", %g" % (0.05 * k) if three_d else ""))
    out.append("*ELEMENT, TYPE=%s, ELSET=RING" % etype)
    e = 1
    for j in range(nt):
        for i in range(nr):
            I, J = 2 * i, 2 * j
            if three_d:
                c = [nid(I, J), nid(I + 2, J), nid(I + 2, J + 2), nid(I, J + 2),
                     nid(I, J, 2), nid(I + 2, J, 2), nid(I + 2, J + 2, 2), nid(I, J + 2, 2),
                     nid(I + 1, J), nid(I + 2, J + 1), nid(I + 1, J + 2), nid(I, J + 1),
                     nid(I + 1, J, 2), nid(I + 2, J + 1, 2), nid(I + 1, J + 2, 2), nid(I, J + 1, 2),
                     nid(I, J, 1), nid(I + 2, J, 1), nid(I + 2, J + 2, 1), nid(I, J + 2, 1)]
            else:
                c = [nid(I, J), nid(I + 2, J), nid(I + 2, J + 2), nid(I, J + 2),
                     nid(I + 1, J), nid(I + 2, J + 1), nid(I + 1, J + 2), nid(I, J + 1)]
            # at most 16 entries on a data line (Abaqus): continue on the next line
            line = ", ".join(str(n) for n in [e] + c[:15])
            out.append(line + ("," if len(c) > 15 else ""))
            if len(c) > 15:
                out.append(", ".join(str(n) for n in c[15:]))
            e += 1
    out.append("*ELSET, ELSET=INNER")
    out += ["%d," % (j * nr + 1) for j in range(nt)]
    out += ["*NSET, NSET=RIN", "%d," % nid(0, 0), "*NSET, NSET=ROUT", "%d," % nid(2 * nr, 0)]
    out += ["*NSET, NSET=T0"] + ["%d," % v for (i, j, k), v in sorted(ids.items()) if j == 0]
    out += ["*NSET, NSET=T90"] + ["%d," % v for (i, j, k), v in sorted(ids.items()) if j == 2 * nt]
    out += ["*SOLID SECTION, ELSET=RING, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3"]
    out += ["*SURFACE, NAME=BORE", "INNER, %s" % ("S6" if three_d else "S4")]
    out += ["*BOUNDARY", "T0, 2, 2", "T90, 1, 1"] + (["ALL, 3, 3"] if three_d else [])
    out += ["*STEP, NLGEOM=NO", "*STATIC", "1., 1.", "*DSLOAD", "BORE, P, %.15g" % p,
            "*NODE PRINT, NSET=RIN", "U1", "*NODE PRINT, NSET=ROUT", "U1", "*END STEP"]
    write(path, out)


def axisymmetric_cylinder_deck(path, etype, a, b, nr, p, h=0.2, nu=0.3):
    """Axisymmetric thick cylinder a < r < b, one element layer 0 < z < h (CAX4, CAX8, CAX8R; mid-side nodes of
    CAX8 at the edge midpoints), *DSLOAD pressure p on the bore (S4), u_z = 0 everywhere (plane strain);
    *ELASTIC E = 1000 with Poisson's ratio nu."""
    quad = etype.startswith("CAX8")
    ids = {}
    out = ["*HEADING", "axisymmetric thick cylinder, %s (tools/ldfcz_tools/ring_decks.py)" % etype, "*NODE, NSET=ALL"]
    nz = 2 if quad else 1
    ni = 2 * nr if quad else nr
    for k in range(nz + 1):
        for i in range(ni + 1):
            if quad and k == 1 and i % 2 == 1:
                continue
            ids[(i, k)] = len(ids) + 1
            out.append("%d, %.15g, %.15g" % (ids[(i, k)], a + (b - a) * i / ni, h * k / nz))
    out.append("*ELEMENT, TYPE=%s, ELSET=TUBE" % etype)
    for e in range(nr):
        if quad:
            i = 2 * e
            c = [ids[(i, 0)], ids[(i + 2, 0)], ids[(i + 2, 2)], ids[(i, 2)], ids[(i + 1, 0)], ids[(i + 2, 1)],
                 ids[(i + 1, 2)], ids[(i, 1)]]
        else:
            c = [ids[(e, 0)], ids[(e + 1, 0)], ids[(e + 1, 1)], ids[(e, 1)]]
        out.append("%d, %s" % (e + 1, ", ".join(str(n) for n in c)))
    out += ["*ELSET, ELSET=INNER", "1,", "*NSET, NSET=RIN", "%d," % ids[(0, 0)], "*NSET, NSET=ROUT",
            "%d," % ids[(ni, 0)], "*NSET, NSET=BOTTOM"] + ["%d," % v for (i, k), v in sorted(ids.items()) if k == 0]
    out += ["*SOLID SECTION, ELSET=TUBE, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., %r" % nu,
            "*SURFACE, NAME=BORE", "INNER, S4", "*BOUNDARY", "ALL, 2, 2",
            "*STEP, NLGEOM=NO", "*STATIC", "1., 1.", "*DSLOAD", "BORE, P, %.15g" % p,
            "*NODE PRINT, NSET=RIN", "U1", "*NODE PRINT, NSET=ROUT", "U1", "*NODE PRINT, NSET=BOTTOM, TOTALS=YES",
            "RF2", "*END STEP"]
    write(path, out)
