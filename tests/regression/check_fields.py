#!/usr/bin/env python3
"""Predefined fields and velocity boundaries against closed forms (tests deck_fields, deck_boundary_velocity).

--case fields: one C3D8 unit cube with a user UMAT (user_umat_fields.f) and a two-node user element between its
corners 1 and 7 (user_uel_fields.f), both recording what the host passes. Field variable 1 is set by *INITIAL
CONDITIONS only (5 + 2x at the nodes), field variable 2 starts at 1 + 3z, is driven in step 1 by *FIELD with a
TABULAR amplitude (value A(t) * 10, A = 2t) and in step 2 by *FIELD, OP=NEW (the top nodes ramp to 7, the others
return to their initial value 1); the temperature goes 300 -> 310 in step 1 (*TEMPERATURE, ramp), and in step 2
*TEMPERATURE, OP=NEW ramps the top nodes to 320 and returns the others to 300 (OP=NEW of one variable leaves the
others: field variable 1 stays). The UMAT must get
PREDEF(n) = the trilinear interpolation of the nodal values at the start of the increment at its COORDS (exact on
the unit cube) and DPRED(n) its increment; the UEL PREDEF(1, k, a) the value of node a at the end of the increment
and PREDEF(2, k, a) its increment, k = 1 the temperature and k = 1 + n field variable n (NPREDF = 3). Tolerance
1e-12 relative to the field's scale (the values are sums of a few products of exact decimals).

--case velocity: a unit C3D8 bar (E = 1000, nu = 0) on rollers at z = 0 whose top moves with *BOUNDARY,
TYPE=VELOCITY: step 1 v = 0.01 (a STEP: u = v t), step 2 v = 0.01 with a TABULAR amplitude A(t) = 1 + 2t, so the
increment of each of the fixed increments dt is v A(t_end) dt; step 3 *BOUNDARY, TYPE=DISPLACEMENT back to 0 (a
RAMP from the value reached). The top's U3 after each increment and the reaction RF3 = -E u3 (sum over the top
nodes, uniaxial stress) must match to 1e-12.
"""
import argparse
import os
import subprocess
import sys

CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(name, got, want, tol):
    if abs(got - want) > tol:
        fail("%s: got %.16g want %.16g (tol %g)" % (name, got, want, tol))


def run(exe, out, job, lines, user):
    os.makedirs(out, exist_ok=True)
    for f in os.listdir(out):
        if f.endswith(".txt"):
            os.remove(os.path.join(out, f))
    deck = os.path.join(out, job + ".inp")
    with open(deck, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = [exe, "-q", "--threads", "1", deck] + (["--user", user] if user else [])
    res = subprocess.run(cmd, cwd=out, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("ldfcz exited with %d on %s" % (res.returncode, deck))
    return deck


def cube_nodes():
    return ["*NODE, NSET=ALL"] + ["%d, %g, %g, %g" % ((i + 1,) + c) for i, c in enumerate(CUBE)]


def nodal_fields(step, t):
    """(temperature, field 1, field 2) of every cube node at step time t of step (step 0: the initial state)."""
    out = []
    for (x, y, z) in CUBE:
        temp0, f1, f20 = 300.0, 5.0 + 2.0 * x, 1.0 + 3.0 * z
        if step == 0:
            out.append((temp0, f1, f20))
        elif step == 1:
            out.append((temp0 + 10.0 * t, f1, 2.0 * t * 10.0))
        else:
            end1 = 2.0 * 1.0 * 10.0
            goal = 7.0 if z == 1 else f20
            tgoal = 320.0 if z == 1 else temp0
            out.append((310.0 + t * (tgoal - 310.0), f1, end1 + t * (goal - end1)))
    return out


def at_start(step, t, dt):
    """Nodal values at the start of an increment that begins at step time t (the first increment of a step starts
    from the previous step's end)."""
    if t == 0.0:
        return nodal_fields(step - 1, 1.0) if step > 1 else nodal_fields(0, 0.0)
    return nodal_fields(step, t)


def trilinear(vals, p):
    x, y, z = p
    s = 0.0
    for (cx, cy, cz), v in zip(CUBE, vals):
        s += (x if cx else 1 - x) * (y if cy else 1 - y) * (z if cz else 1 - z) * v
    return s


def case_fields(exe, out, user):
    lines = ["*HEADING", "predefined fields to a UMAT and a UEL (tests/regression/check_fields.py)"] + cube_nodes()
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=CUBE", "1, 1, 2, 3, 4, 5, 6, 7, 8",
              "*USER ELEMENT, TYPE=U1, NODES=2, COORDINATES=3, PROPERTIES=1", "1, 2, 3",
              "*ELEMENT, TYPE=U1, ELSET=SPRING", "2, 1, 7", "*UEL PROPERTY, ELSET=SPRING", "1.",
              "*NSET, NSET=BOTTOM", "1, 2, 3, 4", "*NSET, NSET=TOP", "5, 6, 7, 8",
              "*SOLID SECTION, ELSET=CUBE, MATERIAL=M", "*MATERIAL, NAME=M", "*USER MATERIAL, CONSTANTS=2",
              "1000., 0.3", "*AMPLITUDE, NAME=TAB", "0., 0., 1., 2.",
              "*INITIAL CONDITIONS, TYPE=TEMPERATURE", "ALL, 300.",
              "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=1"]
    lines += ["%d, %g" % (i + 1, 5.0 + 2.0 * c[0]) for i, c in enumerate(CUBE)]
    lines += ["*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=2", "ALL, 1.", "TOP, 4.",
              "*BOUNDARY", "ALL, 1, 3",
              "*STEP", "*STATIC, DIRECT", "0.25, 1.", "*TEMPERATURE", "ALL, 310.",
              "*FIELD, VARIABLE=2, AMPLITUDE=TAB", "ALL, 10.", "*END STEP",
              "*STEP", "*STATIC, DIRECT", "0.5, 1.", "*FIELD, VARIABLE=2, OP=NEW", "TOP, 7.",
              "*TEMPERATURE, OP=NEW", "TOP, 320.", "*END STEP"]
    run(exe, out, "fields", lines, user)
    umat = [l.split() for l in open(os.path.join(out, "umat_fields.txt"))]
    uel = [l.split() for l in open(os.path.join(out, "uel_fields.txt"))]
    incs = set()
    for r in umat:
        noel, npt, kstep, kinc = (int(v) for v in r[:4])
        t, _, dt, temp, dtemp, cx, cy, cz, p1, p2, d1, d2 = (float(v) for v in r[4:])
        incs.add((kstep, kinc))
        start = at_start(kstep, t, dt)
        end = nodal_fields(kstep, t + dt)
        where = "UMAT step %d inc %d point %d" % (kstep, kinc, npt)
        for k, (got, dgot) in enumerate([(temp, dtemp), (p1, d1), (p2, d2)]):
            v0 = trilinear([n[k] for n in start], (cx, cy, cz))
            v1 = trilinear([n[k] for n in end], (cx, cy, cz))
            scale = 1e-12 * max(1.0, abs(v0), abs(v1))
            name = ["TEMP", "PREDEF(1)", "PREDEF(2)"][k]
            close(where + " " + name, got, v0, scale)
            close(where + " " + ["DTEMP", "DPRED(1)", "DPRED(2)"][k], dgot, v1 - v0, scale)
    if incs != {(1, 1), (1, 2), (1, 3), (1, 4), (2, 1), (2, 2)}:
        fail("UMAT increments %s, expected 4 in step 1 and 2 in step 2" % sorted(incs))
    print("UMAT: %d calls, TEMP/DTEMP, PREDEF(1:2), DPRED(1:2) as the closed form (1e-12)" % len(umat))
    for r in uel:
        jelem, kstep, kinc, npredf, nnode = (int(v) for v in r[:5])
        t, _, dt = (float(v) for v in r[5:8])
        pre = [float(v) for v in r[8:]]
        if jelem != 2 or npredf != 3 or nnode != 2 or len(pre) != 2 * npredf * nnode:
            fail("UEL call: JELEM %d NPREDF %d NNODE %d (expected 2, 3 = 1 + 2 field variables, 2)" %
                 (jelem, npredf, nnode))
        start = at_start(kstep, t, dt)
        end = nodal_fields(kstep, t + dt)
        for a, node in enumerate((1, 7)):
            for k in range(npredf):
                v0, v1 = start[node - 1][k], end[node - 1][k]
                got_end = pre[(a * npredf + k) * 2]
                got_inc = pre[(a * npredf + k) * 2 + 1]
                where = "UEL step %d inc %d PREDEF(%%d,%d,%d)" % (kstep, kinc, k + 1, a + 1)
                scale = 1e-12 * max(1.0, abs(v0), abs(v1))
                close(where % 1, got_end, v1, scale)
                close(where % 2, got_inc, v1 - v0, scale)
    if not uel:
        fail("no UEL call recorded")
    print("UEL: %d calls, PREDEF(1:2, 1:3, 1:2) as the closed form (1e-12)" % len(uel))


def case_velocity(exe, out):
    import csv
    e, v = 1000.0, 0.01
    lines = ["*HEADING", "velocity boundary (tests/regression/check_fields.py)"] + cube_nodes()
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=BAR", "1, 1, 2, 3, 4, 5, 6, 7, 8",
              "*NSET, NSET=BOTTOM", "1, 2, 3, 4", "*NSET, NSET=TOP", "5, 6, 7, 8", "*NSET, NSET=X0", "1, 4, 5, 8",
              "*NSET, NSET=Y0", "1, 2, 5, 6", "*SOLID SECTION, ELSET=BAR, MATERIAL=M", "*MATERIAL, NAME=M",
              "*ELASTIC", "%g, 0." % e, "*AMPLITUDE, NAME=GROW", "0., 1., 1., 3.",
              "*BOUNDARY", "BOTTOM, 3, 3", "X0, 1, 1", "Y0, 2, 2",
              "*STEP", "*STATIC, DIRECT", "0.5, 2.", "*BOUNDARY, TYPE=VELOCITY", "TOP, 3, 3, %g" % v,
              "*NODE PRINT, NSET=TOP", "U3, RF3", "*END STEP",
              "*STEP", "*STATIC, DIRECT", "0.25, 1.", "*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=GROW",
              "TOP, 3, 3, %g" % v, "*END STEP",
              "*STEP", "*STATIC, DIRECT", "0.5, 1.", "*BOUNDARY, TYPE=DISPLACEMENT", "TOP, 3, 3, 0.", "*END STEP"]
    run(exe, out, "velocity", lines, None)
    with open(os.path.join(out, "velocity.csv")) as f:
        rows = [{k: float(x) for k, x in r.items()} for r in csv.DictReader(f)]
    u, u_end2, n = 0.0, None, 0
    for r in rows:
        s, t = int(r["step"]), r["step_time"]
        if t == 0.0:
            continue
        if s == 1:
            u = v * t
        elif s == 2:
            # sum over the increments of 0.25 ending at t of v A(t_k) dt, A = 1 + 2 t
            k = round(t / 0.25)
            u = 2 * v + sum(v * (1 + 2 * 0.25 * j) * 0.25 for j in range(1, k + 1))
            u_end2 = u
        else:
            u = u_end2 * (1 - t)
        close("step %d t %g TOP.U3" % (s, t), r["TOP.U3"], u, 1e-12 * 0.05)
        close("step %d t %g TOP.RF3 = E u" % (s, t), r["TOP.RF3"], e * u, 1e-12 * 50)
        n += 1
    if n != 4 + 4 + 2:
        fail("%d increments in the CSV, expected 10" % n)
    print("velocity boundary: U3 = integral of v dt and RF3 = E A u / L in %d increments (1e-12)" % n)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=["fields", "velocity"])
    ap.add_argument("--user")
    a = ap.parse_args()
    if a.case == "fields":
        case_fields(a.exe, a.out, a.user)
    else:
        case_velocity(a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
