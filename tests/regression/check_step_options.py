#!/usr/bin/env python3
"""*MODEL CHANGE (element removal, strain-free reactivation and reactivation with strain), *TIME POINTS with *OUTPUT, TIME POINTS= and
*NODE PRINT, GLOBAL=YES, against closed forms and twin decks.

  check_step_options.py --exe BIN --out DIR --case NAME

Cases (decks written into DIR):
  model_change  two C3D8 unit cubes side by side (bars 1 and 2, E = 1000, nu = 0, bases encastred), the tops of
            both tied by *EQUATION to the top node 5 of bar 1, which carries the force. Step 1 removes bar 2 and
            applies F = 10: the displacement of node 5 equals the twin deck without bar 2 in every increment
            (1e-12), u = F t / k (k = E A / L = 1000). Step 2 adds bar 2 back strain-free and raises F to 20:
            bar 2 starts stress-free where it is, u = 0.01 + 10 t / 2000. Step 3 removes bar 1: its force at
            the end of step 2 (15) is ramped down over the step, so u = 0.01 + (5 + 15 t) / 1000 (bar 2 alone
            carries 20 at the end). Every increment within 1e-10 (the linear element is exact).
  model_change_nlgeom  the same under NLGEOM with bar 2 removed while bar 1 is stretched to 1.2 (prescribed),
            then added back strain-free and the stretch released to a force: bar 2's reference is its length at
            the reactivation, 1.2, so with the hypoelastic *ELASTIC (sigma = E ln of the stretch, nu = 0) the
            force F = E ln(y) + E ln(y / 1.2) at the top position y; the force at the end of step 2 against
            the closed form within 1e-3 (measured 2.8e-5; the hypoelastic integration's O(increment^2) error is
            2e-4 in deck_transform_roller_nlgeom); bar 2 measured from its original length would give 2 % more.
  model_change_with_strain  a column of two C3D8 unit cubes (elements 1 at z in [0, 1] and 2 at [1, 2], E = 1000,
            nu = 0, base encastred, the middle face MID and the top face TOP prescribed in z). Step 1 removes
            element 2 and moves MID to 0.1 and TOP to 0.3 (element 2's nodes move while it is out). Step 2 adds it
            back and moves TOP on to 0.4: WITH STRAIN (Abaqus: the initial configuration is not reset) its stress is
            E times the total strain (u_TOP - u_MID) / 1 = 200 + 100 t in every increment of step 2 (the top
            face's reaction); STRAIN FREE (the twin deck) it is E (u_TOP - 0.3) = 100 t. Every increment within
            1e-9 of the closed form (the linear C3D8 under a uniform strain is exact); MECHSTRAINTORESIDUAL (a
            CalculiX extension) is refused naming its line.
  time_points  the C3D8 uniaxial cube with *TIME POINTS (a list, and GENERATE) named by *OUTPUT, FIELD and
            *OUTPUT, HISTORY, TIME POINTS=, automatic increments of 0.3: JOB.csv has a row at every time point
            (exactly: within 1e-12), the field frames are exactly those times and the step's end; a second step
            without its own *OUTPUT keeps the field and history requests and their time points (frames at the total
            times 1 + t); a third step of DIRECT (fixed) increments 0.4 with its own field request is cut at every
            point too (the history request's carried).
  node_print_global  a C3D8 cube whose top nodes carry a *TRANSFORM turned by 30 degrees about z, loaded and
            partly prescribed in local directions: *NODE PRINT, GLOBAL=YES columns (SET.VARIABLE.GLOBAL) equal T
            times the local columns (GLOBAL=NO, the default) within 1e-12, U the VTU frame's global U (1e-8:
            the frame's 9 digits), RF global of the prescribed local dof; GLOBAL=YES on a set without
            transformed nodes keeps the plain column names and values.
  print_carry  data-file requests carried into later steps until respecified (Abaqus Analysis User's Guide,
            "Requesting output in multiple steps"): step 1 prints node set TOP and element set BAR1, step 2
            gives no print request and prints both, step 3 gives its own *NODE PRINT (BOT) and prints BOT, not
            TOP, with BAR1's element table still carried; every increment of each step has its tables.
  boundary_fixed  *BOUNDARY, FIXED (Keywords Reference *BOUNDARY: the dofs held at their values at the start of
            the step): the bar of model_change without bar 2 (k = 1000) loaded by F = 10 in step 1 (u = 0.01), its
            top held by FIXED in step 2 while the force rises to 14: u stays 0.01 in every increment (1e-12: the
            held value is the converged one) and the top's reaction is 10 - 14 = -4 (1e-9 of 10); a magnitude
            on a FIXED line is refused naming its line.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check(name, got, want, tol):
    if not abs(got - want) <= tol:
        fail("%s: got %.15g want %.15g (tolerance %.3g)" % (name, got, want, tol))


def run(exe, out, job, lines):
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, job), path], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s%s" % (job, r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
    with open(os.path.join(out, job, job + ".csv")) as f:
        return list(csv.DictReader(f))


def bars(with_bar2=True, nlgeom="NO"):
    """Bars 1 (nodes 1..8) and 2 (11..18) of unit cubes, bases encastred, tops tied to node 5's u3."""
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    lines = ["*HEADING", "element removal and reactivation", "*NODE"]
    lines += ["%d, %d., %d., %d." % (k + 1, p[0], p[1], p[2]) for k, p in enumerate(pts)]
    if with_bar2:
        lines += ["%d, %d., %d., %d." % (k + 11, p[0] + 2, p[1], p[2]) for k, p in enumerate(pts)]
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=BAR1\n1, 1, 2, 3, 4, 5, 6, 7, 8")
    if with_bar2:
        lines.append("*ELEMENT, TYPE=C3D8, ELSET=BAR2\n2, 11, 12, 13, 14, 15, 16, 17, 18")
    lines.append("*NSET, NSET=BOT\n1, 2, 3, 4" + (", 11, 12, 13, 14" if with_bar2 else ""))
    lines.append("*NSET, NSET=TOP\n5")
    lines.append("*EQUATION")
    for t in [6, 7, 8] + ([15, 16, 17, 18] if with_bar2 else []):
        lines.append("2\n%d, 3, 1., 5, 3, -1." % t)
    lines.append("*SOLID SECTION, ELSET=BAR1, MATERIAL=M")
    if with_bar2:
        lines.append("*SOLID SECTION, ELSET=BAR2, MATERIAL=M")
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.", "*BOUNDARY", "BOT, ENCASTRE"]
    return lines


def case_model_change(exe, out):
    step = ["*STATIC", "0.25, 1."]
    prints = ["*NODE PRINT, NSET=TOP", "U3"]
    deck = bars() + ["*STEP"] + step + ["*MODEL CHANGE, REMOVE", "BAR2", "*CLOAD", "TOP, 3, 10."] + prints
    deck += ["*END STEP", "*STEP"] + step + ["*MODEL CHANGE, ADD", "BAR2", "*CLOAD", "TOP, 3, 20.", "*END STEP"]
    deck += ["*STEP"] + step + ["*MODEL CHANGE, REMOVE", "BAR1", "*END STEP"]
    twin = bars(False) + ["*STEP"] + step + ["*CLOAD", "TOP, 3, 10."] + prints + ["*END STEP"]
    rows = run(exe, out, "model_change", deck)
    trows = run(exe, out, "model_change_twin", twin)
    for r, t in zip(rows, trows):
        check("step 1 increment %s against the deck without bar 2" % r["inc"], float(r["TOP.U3"]),
              float(t["TOP.U3"]), 1e-12 * abs(float(t["TOP.U3"])))
    want = {1: lambda t: 10.0 * t / 1000.0, 2: lambda t: 0.01 + 10.0 * t / 2000.0,
            3: lambda t: 0.01 + (5.0 + 15.0 * t) / 1000.0}
    for r in rows:
        s, t = int(r["step"]), float(r["step_time"])
        check("step %d time %g: U3" % (s, t), float(r["TOP.U3"]), want[s](t), 1e-10 * want[s](t))
        print("step %d time %.3f: U3 %.15g (closed form %.15g)" % (s, t, float(r["TOP.U3"]), want[s](t)))


def case_model_change_nlgeom(exe, out):
    step = ["*STATIC", "0.1, 1., 1e-5, 0.1"]
    deck = bars(nlgeom="YES") + ["*STEP, NLGEOM=YES, INC=100"] + step
    deck += ["*MODEL CHANGE, REMOVE", "BAR2", "*BOUNDARY", "TOP, 3, 3, 0.2", "*NODE PRINT, NSET=TOP", "U3, RF3",
             "*END STEP"]
    # step 2: bar 2 back strain-free at the stretch 1.2; the top released (OP=NEW) and held by the force it had
    force1 = 1000.0 * math.log(1.2)
    deck += ["*STEP, NLGEOM=YES, INC=100"] + step + ["*MODEL CHANGE, ADD", "BAR2", "*BOUNDARY, OP=NEW",
                                                     "BOT, ENCASTRE", "*CLOAD", "TOP, 3, %r" % (force1 + 50.0),
                                                     "*END STEP"]
    rows = run(exe, out, "model_change_nlgeom", deck)
    r1 = [r for r in rows if r["step"] == "1"][-1]
    print("step 1: U3 %s, RF3 %s (E ln 1.2 = %.10g)" % (r1["TOP.U3"], r1["TOP.RF3"], force1))
    y = 1.0 + float(rows[-1]["TOP.U3"])
    f = 1000.0 * math.log(y) + 1000.0 * math.log(y / 1.2)
    print("step 2: top at %.10g: bars carry %.10g (F = %.10g); bar 2 measured from length 1 would give %.10g"
          % (y, f, force1 + 50.0, 1000.0 * math.log(y) + 1000.0 * math.log(y - 0.2)))
    check("step 2: force of the bars at the top position", f, force1 + 50.0, 1e-3 * (force1 + 50.0))


def column(free):
    """Elements 1 (z in [0, 1]) and 2 (z in [1, 2]) of a column of unit cubes: step 1 removes 2 and moves its
    nodes, step 2 adds it back (strain free or with strain) and moves the top on."""
    pts = [(0, 0), (1, 0), (1, 1), (0, 1)]
    lines = ["*HEADING", "reactivation with strain", "*NODE"]
    lines += ["%d, %d., %d., %d." % (4 * z + k + 1, p[0], p[1], z) for z in range(3) for k, p in enumerate(pts)]
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=E1", "1, 1, 2, 3, 4, 5, 6, 7, 8",
              "*ELEMENT, TYPE=C3D8, ELSET=E2", "2, 5, 6, 7, 8, 9, 10, 11, 12",
              "*NSET, NSET=BOT", "1, 2, 3, 4", "*NSET, NSET=MID", "5, 6, 7, 8", "*NSET, NSET=TOP", "9, 10, 11, 12",
              "*ELSET, ELSET=ALL", "E1, E2", "*SOLID SECTION, ELSET=ALL, MATERIAL=M",
              "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.", "*BOUNDARY", "BOT, ENCASTRE", "1, 1, 2", "2, 2, 2",
              "4, 1, 1", "5, 1, 2", "6, 2, 2", "8, 1, 1", "9, 1, 2", "10, 2, 2", "12, 1, 1"]
    step = ["*STATIC", "0.25, 1."]
    lines += ["*STEP"] + step + ["*MODEL CHANGE, REMOVE", "2", "*BOUNDARY", "MID, 3, 3, 0.1", "TOP, 3, 3, 0.3",
                                 "*NODE PRINT, NSET=TOP, TOTALS=YES", "RF3", "*END STEP"]
    lines += ["*STEP"] + step + ["*MODEL CHANGE, ADD=%s" % ("STRAIN FREE" if free else "WITH STRAIN"), "E2",
                                 "*BOUNDARY", "TOP, 3, 3, 0.4", "*END STEP"]
    return lines


def case_model_change_with_strain(exe, out):
    want = {True: lambda t: 100.0 * t, False: lambda t: 200.0 + 100.0 * t}
    for free in (False, True):
        job = "with_strain" if not free else "strain_free"
        rows = run(exe, out, job, column(free))
        cols = [c for c in rows[0] if c.endswith("RF3")]
        if len(cols) != 1:
            fail("%s: expected one RF3 total column, got %s" % (job, cols))
        for r in rows:
            s, t = int(r["step"]), float(r["step_time"])
            got = float(r[cols[0]])
            w = 0.0 if s == 1 else want[free](t)
            check("%s step %d time %g: force of element 2 (E times its strain)" % (job, s, t), got, w, 1e-9 * 300.0)
            print("%s step %d time %.3f: top reaction %.12g (closed form %.12g)" % (job, s, t, got, w))
    deck = column(False)
    k = deck.index("*MODEL CHANGE, ADD=WITH STRAIN")
    deck[k] = "*MODEL CHANGE, ADD, MECHSTRAINTORESIDUAL"
    path = os.path.join(out, "mechstrain.inp")
    with open(path, "w") as f:
        f.write("\n".join(deck) + "\n")
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, "mechstrain"), path], capture_output=True, text=True)
    where = "mechstrain.inp:%d" % (k + 1)
    if r.returncode != 2 or where not in r.stderr or "MECHSTRAINTORESIDUAL" not in r.stderr:
        fail("MECHSTRAINTORESIDUAL: expected exit 2 naming %s, got %d: %s" % (where, r.returncode, r.stderr))
    print("MECHSTRAINTORESIDUAL refused: " + r.stderr.strip().splitlines()[-1])


def frames(out, job):
    pvd = ET.parse(os.path.join(out, job, job + ".pvd")).getroot()
    return [float(d.get("timestep")) for d in pvd.iter("DataSet")]


def case_time_points(exe, out):
    with open(os.path.join(os.path.dirname(__file__), "..", "..", "decks", "single", "c3d8_uniaxial.inp")) as f:
        base = f.read().split("\n")
    deck = []
    for line in base:
        if line.startswith("*STEP"):
            deck += ["*TIME POINTS, NAME=TP", "0.13, 0.5, 0.77", "*TIME POINTS, NAME=TG, GENERATE", "0.05, 0.25, 0.1"]
        if line.startswith("0.1, 1.0, 1e-4, 0.1"):
            line = "0.3, 1.0, 1e-4, 0.3"
        if line.startswith("*OUTPUT, FIELD"):
            deck += ["*OUTPUT, FIELD, TIME POINTS=TP", "*OUTPUT, HISTORY, TIME POINTS=TG"]
            continue
        if line.startswith("*END STEP"):
            deck += [line, "*STEP, NLGEOM=YES, INC=100", "*STATIC", "0.3, 1.0, 1e-4, 0.3", "*BOUNDARY",
                     "TOP, 3, 3, 0.3", line, "*STEP, NLGEOM=YES, INC=100", "*STATIC, DIRECT", "0.4, 1.0",
                     "*BOUNDARY", "TOP, 3, 3, 0.35", "*OUTPUT, FIELD, TIME POINTS=TP", line]
            break
        deck.append(line)
    deck = [l for l in deck if l]
    rows = run(exe, out, "time_points", deck)
    times = {1: [], 2: [], 3: []}
    for r in rows:
        times[int(r["step"])].append(float(r["step_time"]))
    # step 2 keeps step 1's requests; step 3 has its own field request (TP) and keeps the history one (TG), and its
    # fixed increments of 0.4 are cut at every point as well
    pts = [0.05, 0.13, 0.15, 0.25, 0.5, 0.77]
    want = {1: pts, 2: pts, 3: pts}
    for s in (1, 2, 3):
        print("step %d increments end at %s" % (s, " ".join("%.15g" % t for t in times[s])))
        for p in want[s]:
            if not any(abs(t - p) <= 1e-12 for t in times[s]):
                fail("step %d: no increment ends at time point %g" % (s, p))
        if abs(times[s][-1] - 1.0) > 1e-12:
            fail("step %d does not end at its period" % s)
    if len(times[3]) != 7:
        fail("step 3 (DIRECT 0.4): expected the 7 increments 0.05 0.13 0.15 0.25 0.5 0.77 1, got %s" % times[3])
    got = frames(out, "time_points")
    want_frames = [0.0] + [p for p in (0.13, 0.5, 0.77, 1.0)] + [1.0 + p for p in (0.13, 0.5, 0.77, 1.0)] + \
        [2.0 + p for p in (0.13, 0.5, 0.77, 1.0)]
    print("frames at total times %s" % " ".join("%.12g" % t for t in got))
    if len(got) != len(want_frames) or any(abs(a - b) > 1e-12 for a, b in zip(got, want_frames)):
        fail("frames at %s, expected %s" % (got, want_frames))


def case_node_print_global(exe, out):
    c, s = math.cos(math.radians(30.0)), math.sin(math.radians(30.0))
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    lines = ["*HEADING", "GLOBAL=YES on *NODE PRINT", "*NODE"]
    lines += ["%d, %d., %d., %d." % (k + 1, p[0], p[1], p[2]) for k, p in enumerate(pts)]
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8", "*NSET, NSET=BOT\n1, 2, 3, 4",
              "*NSET, NSET=LOADED\n7", "*NSET, NSET=HELD\n6", "*NSET, NSET=PLAIN\n8", "*NSET, NSET=TOPT\n6, 7",
              "*TRANSFORM, NSET=TOPT", "%r, %r, 0., %r, %r, 0." % (c, s, -s, c),
              "*SOLID SECTION, ELSET=CUBE, MATERIAL=M", "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3",
              "*BOUNDARY", "BOT, ENCASTRE", "*STEP", "*STATIC", "1., 1.", "*BOUNDARY", "HELD, 1, 1, 0.01",
              "*CLOAD", "LOADED, 1, 5.", "LOADED, 2, -3.", "LOADED, 3, 2.", "*OUTPUT, FIELD", "*NODE OUTPUT", "U, RF"]
    for name in ("LOADED", "HELD", "PLAIN"):
        lines += ["*NODE PRINT, NSET=%s" % name, "U, RF", "*NODE PRINT, NSET=%s, GLOBAL=YES" % name, "U, RF"]
    rows = run(exe, out, "node_print_global", lines + ["*END STEP"])
    r = rows[-1]
    t = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
    for name in ("LOADED", "HELD"):
        for var in ("U", "RF"):
            loc = [float(r["%s.%s%d" % (name, var, i + 1)]) for i in range(3)]
            glo = [float(r["%s.%s%d.GLOBAL" % (name, var, i + 1)]) for i in range(3)]
            want = [sum(t[i][j] * loc[j] for j in range(3)) for i in range(3)]
            scale = max(abs(x) for x in loc)
            for i in range(3):
                check("%s.%s%d.GLOBAL = T local" % (name, var, i + 1), glo[i], want[i], 1e-12 * scale)
            print("%s %s local %s, global %s" % (name, var, loc, glo))
    if abs(float(r["HELD.RF1"])) < 1e-6:
        fail("the prescribed local dof of HELD has no reaction")
    for var in ("U1", "U2", "U3", "RF1", "RF2", "RF3"):
        if "PLAIN.%s.GLOBAL" % var in r:
            fail("GLOBAL=YES on a set without transformed nodes must keep the plain column name")
    # the VTU frame is global
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    pvd = ET.parse(os.path.join(out, "node_print_global", "node_print_global.pvd")).getroot()
    path = [d.get("file") for d in pvd.iter("DataSet")][-1]
    rd = vtkXMLUnstructuredGridReader()
    rd.SetFileName(os.path.join(out, "node_print_global", path))
    rd.Update()
    u = vtk_to_numpy(rd.GetOutput().GetPointData().GetArray("U"))
    for i in range(3):
        check("VTU U%d of node 7 = LOADED.U%d.GLOBAL" % (i + 1, i + 1), float(u[6][i]),
              float(r["LOADED.U%d.GLOBAL" % (i + 1)]), 1e-8 * max(abs(float(x)) for x in u[6]))


def case_print_carry(exe, out):
    step = ["*STATIC", "0.5, 1."]
    deck = bars(False) + ["*STEP"] + step + ["*CLOAD", "TOP, 3, 10.", "*NODE PRINT, NSET=TOP", "U3",
                                             "*EL PRINT, ELSET=BAR1", "S33", "*END STEP"]
    deck += ["*STEP"] + step + ["*CLOAD", "TOP, 3, 12.", "*END STEP"]
    deck += ["*STEP"] + step + ["*CLOAD", "TOP, 3, 14.", "*NODE PRINT, NSET=BOT", "RF3", "*END STEP"]
    rows = run(exe, out, "print_carry", deck)
    with open(os.path.join(out, "print_carry", "print_carry.dat")) as f:
        text = f.read()
    tables = {}   # (step, increment) -> the sets printed
    key = None
    for line in text.splitlines():
        w = line.split()
        if len(w) >= 5 and w[0] == "STEP" and w[2] == "INCREMENT" and w[4] == "SUMMARY":
            key = (int(w[1]), int(w[3]))
            tables[key] = set()
        elif key and "BELONGING TO NODE SET" in line:
            tables[key].add("node " + w[-1])
        elif key and "AND ELEMENT SET" in line:
            tables[key].add("element " + w[-1])
    want = {1: {"node TOP", "element BAR1"}, 2: {"node TOP", "element BAR1"}, 3: {"node BOT", "element BAR1"}}
    incs = sorted((int(r["step"]), int(r["inc"])) for r in rows)
    if sorted(tables) != incs:
        fail("printed increments %s, converged %s" % (sorted(tables), incs))
    for k in incs:
        if tables[k] != want[k[0]]:
            fail("step %d increment %d prints %s, want %s" % (k[0], k[1], sorted(tables[k]), sorted(want[k[0]])))
    print("print_carry: %d increments, step 2 carries TOP and BAR1, step 3 prints BOT and BAR1" % len(incs))


def case_boundary_fixed(exe, out):
    step = ["*STATIC", "0.5, 1."]
    prints = ["*NODE PRINT, NSET=TOP", "U3, RF3"]
    deck = bars(False) + ["*STEP"] + step + ["*CLOAD", "TOP, 3, 10."] + prints + ["*END STEP"]
    deck += ["*STEP"] + step + ["*BOUNDARY, FIXED", "TOP, 3, 3", "*CLOAD", "TOP, 3, 14.", "*END STEP"]
    rows = run(exe, out, "boundary_fixed", deck)
    for r in rows:
        if int(r["step"]) != 2:
            continue
        check("step 2 time %s: U3 held" % r["step_time"], float(r["TOP.U3"]), 0.01, 1e-12)
    last = rows[-1]
    check("reaction at the held top", float(last["TOP.RF3"]), -4.0, 1e-9 * 10.0)
    print("step 2: U3 %.15g held, RF3 %.15g (10 - 14)" % (float(last["TOP.U3"]), float(last["TOP.RF3"])))
    bad = deck[:]
    k = bad.index("*BOUNDARY, FIXED")
    bad[k + 1] = "TOP, 3, 3, 0.5"
    path = os.path.join(out, "boundary_fixed_value.inp")
    with open(path, "w") as f:
        f.write("\n".join(bad) + "\n")
    r = subprocess.run([exe, "-q", "--out", os.path.join(out, "boundary_fixed_value"), path], capture_output=True,
                       text=True)
    where = "boundary_fixed_value.inp:%d: *BOUNDARY" % ("\n".join(bad).split("\n").index("TOP, 3, 3, 0.5") + 1)
    if r.returncode != 2 or where not in r.stderr:
        fail("a magnitude with FIXED: expected exit 2 naming %s, got %d: %s" % (where, r.returncode, r.stderr))
    print("a magnitude with FIXED refused: " + r.stderr.strip().splitlines()[-1])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--case", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    cases = {"model_change": case_model_change, "model_change_nlgeom": case_model_change_nlgeom,
             "model_change_with_strain": case_model_change_with_strain,
             "time_points": case_time_points, "node_print_global": case_node_print_global,
             "boundary_fixed": case_boundary_fixed, "print_carry": case_print_carry}
    if a.case not in cases:
        fail("unknown case " + a.case)
    cases[a.case](a.exe, a.out)
    print("PASS")


if __name__ == "__main__":
    main()
