#!/usr/bin/env python3
"""Element deletion by a UMAT's state variable (*DEPVAR, DELETE=; docs/host.md), against the closed form.

  check_element_deletion.py --exe BIN --deck tests/restart/element_deletion.inp --user UMAT --out DIR

The deck: two C3D8 unit bars in parallel (E = 1000, nu = 0), their tops tied to node 5, whose u3 rises to 0.02 in
ten increments; the UMAT (tests/regression/user_umat_delete.f90) sets state variable 1, the deletion variable, to 0
beyond a strain of 0.0105 in bar 2 (increment 6) and zeroes the stress in that increment only. The reaction at the
top must be 2000 u3 up to increment 5 (both bars) and 1000 u3 from increment 6 on (bar 1 alone: bar 2 deleted),
within 1e-9 of the largest force 20 (the linear element under a uniform strain is exact; the CSV has 16 digits);
the log names the deleted element; the VTU frames' cell array STATUS (Abaqus' element status) is 1 for both
elements up to increment 5 and 0 for element 2 from increment 6 on. The same deck without DELETE= (the host keeps calling the UMAT, which loads
bar 2 again from zero) must differ from increment 7 on: the check can fail.
"""
import argparse
import csv
import os
import subprocess
import sys
import xml.etree.ElementTree as ET


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, deck, user, out):
    r = subprocess.run([exe, "-q", "--user", user, "--out", out, deck], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: exit %d\n%s%s" % (deck, r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
    job = os.path.splitext(os.path.basename(deck))[0]
    with open(os.path.join(out, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, job + ".log")) as f:
        log = f.read()
    return rows, log


def frame_status(out):
    """STATUS by element label in each frame after the initial one, in the order of JOB.pvd."""
    pvd = ET.parse(os.path.join(out, "element_deletion.pvd")).getroot()
    result = []
    for ds in pvd.iter("DataSet"):
        cells = {}
        for arr in ET.parse(os.path.join(out, ds.get("file"))).getroot().iter("DataArray"):
            if arr.get("Name") in ("element", "STATUS"):
                cells[arr.get("Name")] = [int(float(x)) for x in arr.text.split()]
        if "STATUS" not in cells:
            fail("frame %s has no STATUS array" % ds.get("file"))
        result.append(dict(zip(cells["element"], cells["STATUS"])))
    return result[1:]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--user", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows, log = run(a.exe, a.deck, a.user, os.path.join(a.out, "deletion"))
    if len(rows) != 10:
        fail("expected 10 increments, got %d" % len(rows))
    for r in rows:
        k, u, f = int(r["inc"]), float(r["TOP.U3"]), float(r["TOP.RF3"])
        want = (2000.0 if k <= 5 else 1000.0) * u
        print("increment %d: u3 %.6g, reaction %.12g (closed form %.12g)" % (k, u, f, want))
        if abs(f - want) > 1e-9 * 20.0:
            fail("increment %d: reaction %.15g, closed form %.15g" % (k, f, want))
    if "step 1 increment 6: 1 element(s) deleted" not in log or "(element 2" not in log:
        fail("the log does not name element 2 deleted in increment 6")
    status = frame_status(os.path.join(a.out, "deletion"))
    for k, st in enumerate(status, start=1):
        if st != {1: 1, 2: 1 if k <= 5 else 0}:
            fail("increment %d: STATUS %s" % (k, st))
    print("STATUS of element 2 by increment: %s" % [st[2] for st in status])
    twin = os.path.join(a.out, "no_delete.inp")
    with open(a.deck) as f:
        text = f.read()
    with open(twin, "w") as f:
        f.write(text.replace("*DEPVAR, DELETE=1", "*DEPVAR"))
    trows, tlog = run(a.exe, twin, a.user, os.path.join(a.out, "no_delete"))
    if "deleted" in tlog:
        fail("the deck without DELETE= deleted an element")
    if abs(float(trows[6]["TOP.RF3"]) - float(rows[6]["TOP.RF3"])) < 1.0:
        fail("without DELETE= increment 7 gives the same force: the check cannot tell deletion from the UMAT")
    print("without DELETE=: increment 7 reaction %s (bar 2 loaded again)" % trows[6]["TOP.RF3"])
    print("PASS")


if __name__ == "__main__":
    main()
