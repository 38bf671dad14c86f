#!/usr/bin/env python3
"""Outputs resolved against the output registry (host/output/output_registry.f90, docs/host.md "Output variables").

  check_output_registry.py --exe LDFCZ --decks DECKS_DIR --user-uel tests/regression/user_uel_elastic.f --out DIR

1. A user's own UEL without a '**LDFCZ SVARS' line (decks/single/user_uel.inp with *ELEMENT OUTPUT S, SDV): each
   request is warned about once with the deck's file and line (S: no continuum element; SDV: user elements have no
   state variables here), and the frames hold no array that nothing provided: no S, S_principal, Mises, SDV,
   traction or Delta_max; they hold U, RF, element, cohesive (1) and the geometric opening, whose mean normal
   component is the prescribed 0.01 mm (1e-7: 9 printed digits).
2. The cohesive block (decks/single/cohesive_block.inp: the LDF element declares its SVARS, the block is *ELASTIC)
   with *ELEMENT OUTPUT SDV2 added: warned (no material has state variables), no SDV array; traction and
   Delta_max present and, at the last frame, positive (the interface has opened: Delta_max > 0, T > 0).
3. A plane-stress CPS4 in simple shear u1 = g X2 (small strain, E = 1000, nu = 0.25, g = 1e-3) with *EL PRINT
   S, E: the JOB.dat table is headed "ELEMENT TYPE CPS4" and has S12 = G g = 0.4, S33 = 0, E12 = g at every point
   (1e-4 relative: 5 printed digits); the plane-stress components (11, 22, 12) are placed under their names.
"""
import argparse
import os
import re
import subprocess
import sys

from ldfcz_tools import outputs

from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, deck, out, extra=()):
    os.makedirs(out, exist_ok=True)
    res = subprocess.run([exe, "-q", *extra, deck], cwd=out, capture_output=True, text=True)
    if res.returncode != 0:
        fail("%s: exit %d\n%s%s" % (deck, res.returncode, res.stdout, res.stderr))
    return res.stdout + res.stderr


def frame_arrays(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    arrays = {}
    for data in (g.GetPointData(), g.GetCellData()):
        for i in range(data.GetNumberOfArrays()):
            arrays[data.GetArrayName(i)] = vtk_to_numpy(data.GetArray(i))
    return arrays


def last_frame(out, job, block=""):
    """The arrays of the last frame's block ('' the only one of a model of one kind; 'continuum' or 'interface' of
    a frame of two: JOB_NNNN.vtm)."""
    frames = outputs.pvd_frames(os.path.join(out, job + ".pvd"))
    if not frames:
        fail("%s: no frame" % job)
    blocks = outputs.frame_files(os.path.join(out, frames[-1][1]))
    if block not in blocks:
        fail("%s: the last frame has the blocks %s, not %r" % (job, sorted(blocks), block))
    return frame_arrays(blocks[block][0])


def add_before_end_step(src, dst, lines):
    text = open(src).read()
    k = text.rindex("*END STEP")
    with open(dst, "w") as f:
        f.write(text[:k] + "\n".join(lines) + "\n" + text[k:])
    return text[:k].count("\n") + 1   # line number of the first added line


def warned(log, deck, line, text):
    pat = "%s:%d: " % (os.path.basename(deck), line)
    ok = any(pat in w and text in w for w in log.splitlines())
    print("warning %-58s %s" % ("'%s' at %s" % (text, pat.strip()), "ok" if ok else "MISSING"))
    if not ok:
        fail("no warning '%s' naming %s in:\n%s" % (text, pat, log))


def case_user_uel(a):
    out = os.path.join(a.out, "user_uel")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "user_uel_field.inp")
    first = add_before_end_step(os.path.join(a.decks, "single", "user_uel.inp"), deck,
                                ["*OUTPUT, FIELD", "*ELEMENT OUTPUT", "S, SDV"])
    log = run(a.exe, deck, out, ["--user", a.user_uel])
    warned(log, deck, first + 2, "S: not written")
    warned(log, deck, first + 2, "SDV: not written")
    arr = last_frame(out, "user_uel_field")
    for name in ("S", "S_principal", "Mises", "traction", "Delta_max", "SDV1"):
        if name in arr:
            fail("user UEL without a SVARS declaration: the frame holds %s (%s)" % (name, arr[name]))
    for name in ("U", "RF", "element", "cohesive", "opening"):
        if name not in arr:
            fail("user UEL: the frame lacks %s" % name)
    if int(arr["cohesive"][0]) != 1 or abs(arr["opening"][0][2] - 0.01) > 1e-7:
        fail("user UEL: cohesive %s, opening %s (want 1, 0.01)" % (arr["cohesive"], arr["opening"]))
    print("user UEL without **LDFCZ SVARS: arrays %s, no S/traction/Delta_max/SDV: ok" % sorted(arr))


def case_cohesive_block(a):
    out = os.path.join(a.out, "cohesive_block")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "cohesive_block_sdv.inp")
    first = add_before_end_step(os.path.join(a.decks, "single", "cohesive_block.inp"), deck,
                                ["*ELEMENT OUTPUT", "SDV2"])
    log = run(a.exe, deck, out)
    warned(log, deck, first + 1, "SDV2: not written: no material of these elements has state variables")
    cont = last_frame(out, "cohesive_block_sdv", "continuum")
    arr = last_frame(out, "cohesive_block_sdv", "interface")
    if any(k.startswith("SDV") for k in list(arr) + list(cont)):
        fail("cohesive block (*ELASTIC): SDV arrays %s" % [k for k in list(arr) + list(cont) if k.startswith("SDV")])
    coh = arr["cohesive"] == 1
    if not (arr["traction"][coh] > 0).all() or not (arr["Delta_max"][coh] > 0).all():
        fail("declared SVARS: traction %s, Delta_max %s" % (arr["traction"], arr["Delta_max"]))
    print("declared SVARS: traction %.4g MPa, Delta_max %.4g mm; no SDV array: ok"
          % (arr["traction"][coh][0], arr["Delta_max"][coh][0]))


def case_plane_stress_table(a):
    out = os.path.join(a.out, "cps4_table")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "cps4_shear.inp")
    g, e, nu = 1e-3, 1000.0, 0.25
    x = [(0, 0), (1, 0), (1, 1), (0, 1)]
    lines = ["*HEADING", "CPS4 in simple shear (tests/regression/check_output_registry.py)", "*NODE"]
    lines += ["%d, %g, %g" % (i + 1, p[0], p[1]) for i, p in enumerate(x)]
    lines += ["*ELEMENT, TYPE=CPS4, ELSET=E", "1, 1, 2, 3, 4", "*SOLID SECTION, ELSET=E, MATERIAL=M", "1.",
              "*MATERIAL, NAME=M", "*ELASTIC", "%g, %g" % (e, nu), "*STEP", "*STATIC", "1., 1.", "*BOUNDARY"]
    for i, p in enumerate(x):
        lines += ["%d, 1, 1, %.15g" % (i + 1, g * p[1]), "%d, 2, 2, 0." % (i + 1)]
    lines += ["*EL PRINT, ELSET=E", "S, E", "*END STEP"]
    with open(deck, "w") as f:
        f.write("\n".join(lines) + "\n")
    run(a.exe, deck, out)
    text = open(os.path.join(out, "cps4_shear.dat")).read()
    if "FOR ELEMENT TYPE CPS4 AND ELEMENT SET E" not in text:
        fail("JOB.dat: no table headed ELEMENT TYPE CPS4")
    head = [l for l in text.splitlines() if "ELEMENT  PT FOOT-" in l][-1].split()[3:]
    rows = [l.split() for l in text.splitlines() if re.match(r"^\s+1\s+\d\s", l)]
    want = {"S11": 0.0, "S22": 0.0, "S33": 0.0, "S12": e / (2 * (1 + nu)) * g, "E11": 0.0, "E22": 0.0, "E33": 0.0,
            "E12": g}
    if sorted(head) != sorted(want) or len(rows) != 4:
        fail("JOB.dat: columns %s, %d rows" % (head, len(rows)))
    for r in rows:
        for name, v in zip(head, r[2:]):
            if abs(float(v) - want[name]) > 1e-4 * max(abs(want[name]), 1e-3 * g):
                fail("JOB.dat CPS4 point %s: %s = %s, want %g" % (r[1], name, v, want[name]))
    print("JOB.dat CPS4 table: heading and S12 = %g, S33 = 0, E12 = %g at 4 points: ok" % (want["S12"], g))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--user-uel", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    case_user_uel(a)
    case_cohesive_block(a)
    case_plane_stress_table(a)
    print("PASS")


if __name__ == "__main__":
    main()
