#!/usr/bin/env python3
"""*BOUNDARY, USER: the user subroutine DISP gives the prescribed values (Abaqus' interface and arguments).

  check_boundary_user.py --exe BIN --out DIR --user user_disp.f

A C3D8 block 2 x 1 x 1 (E = 1000, nu = 0, NLGEOM=NO), bottom face z = 0 held in z (and a corner against rigid
motion), its top face moved in z by *BOUNDARY, USER with magnitude 0.01 (ramped) in step 1, and in step 2 with
magnitude 0.02 and an amplitude. DISP (tests/regression/user_disp.f) records its arguments and returns
2 U(1) + 0.001 x. Checks, for every call: NODE a top-face node, JDOF = 3, NOEL = 0, KSTEP the step, KINC the
increment number, TIME(1) the step time at the increment's end, TIME(2) the total time, TIME(3) the increment, COORDS
the node's coordinates, U(1) passed in = the magnitude times the ramp or amplitude (1e-12), and TIME(1) the sum of
the converged increments' TIME(3); for every increment: the mean top U3 = the mean of what DISP returned
(2 a + 0.001 x, a the magnitude times the ramp), and with nu = 0 (S33 = E E33 at every point) the top reaction
RF3 = E A (2 a + 0.001 x_mean) / H (1e-9). Without --user the deck is refused naming the *BOUNDARY data line.
"""
import argparse
import csv
import os
import subprocess
import sys

E = 1000.0


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(name, got, want, rtol, atol):
    if abs(got - want) > rtol * abs(want) + atol:
        fail("%s: got %.15g want %.15g" % (name, got, want))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--user", required=True)
    o = ap.parse_args()
    out = os.path.abspath(o.out)
    os.makedirs(out, exist_ok=True)
    nodes = {}
    lab = 0
    for k in range(2):
        for j in range(2):
            for i in range(3):
                lab += 1
                nodes[lab] = (float(i), float(j), float(k))
    top = [l for l, x in nodes.items() if x[2] == 1.0]
    bottom = [l for l, x in nodes.items() if x[2] == 0.0]
    lines = ["*Heading", "user-defined boundary (tests/regression/check_boundary_user.py)", "*Node"]
    lines += ["%d, %g, %g, %g" % ((l,) + x) for l, x in nodes.items()]
    lines += ["*Element, type=C3D8, elset=B", "1, 1, 2, 5, 4, 7, 8, 11, 10", "2, 2, 3, 6, 5, 8, 9, 12, 11",
              "*Nset, nset=TOP", ", ".join(map(str, top)), "*Nset, nset=BOTTOM", ", ".join(map(str, bottom)),
              "*Solid Section, elset=B, material=M", "*Material, name=M", "*Elastic", "%g, 0." % E,
              "*Amplitude, name=UP", "0., 0.5, 1., 1.",
              "*Boundary", "BOTTOM, 3, 3", "1, 1, 2", "2, 2, 2",
              "*Step", "*Static", "0.25, 1.", "*Boundary, user", "TOP, 3, 3, 0.01"]
    lines += ["*Node Print, nset=TOP", "RF3, U3", "*End Step"]
    lines += ["*Step", "*Static", "0.5, 1.", "*Boundary, user, amplitude=UP", "TOP, 3, 3, 0.02", "*End Step"]
    deck = os.path.join(out, "buser.inp")
    with open(deck, "w") as f:
        f.write("\n".join(lines) + "\n")
    calls = os.path.join(out, "disp_calls.txt")
    if os.path.exists(calls):
        os.remove(calls)
    # without DISP: refused, naming the *BOUNDARY line
    res = subprocess.run([o.exe, "--quiet", "--out", out, deck], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    want_line = "buser.inp:%d: *BOUNDARY" % (lines.index("TOP, 3, 3, 0.01") + 1)
    if res.returncode != 2 or want_line not in res.stdout:
        fail("without --user: exit %d, output %r (expected 2 and %s)" % (res.returncode, res.stdout, want_line))
    print("without DISP: refused naming %s" % want_line)
    res = subprocess.run([o.exe, "--quiet", "--out", out, "--user", os.path.abspath(o.user), deck],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("exit %d" % res.returncode)
    with open(os.path.join(out, "buser.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    ncall = 0
    seen = set()
    # a converged increment's calls are its last attempt's: keep the last record per (step, inc, node)
    last = {}
    with open(calls) as f:
        for line in f:
            w = line.split()
            node, jdof, kstep, kinc, noel = map(int, w[:5])
            t1, t2, t3, x, y, z, u = map(float, w[5:])
            ncall += 1
            if node not in top or jdof != 3 or noel != 0:
                fail("DISP called for node %d dof %d NOEL %d" % (node, jdof, noel))
            close("COORDS of node %d" % node, x, nodes[node][0], 0, 1e-14)
            close("COORDS of node %d" % node, y, nodes[node][1], 0, 1e-14)
            close("COORDS of node %d" % node, z, nodes[node][2], 0, 1e-14)
            t0 = 0.0 if kstep == 1 else 1.0
            close("TIME(2) = start of step + TIME(1)", t2, t0 + t1, 0, 1e-14)
            want_u = 0.01 * t1 if kstep == 1 else 0.02 * (0.5 + 0.5 * t1)
            close("U(1) passed in (step %d, t %.3f)" % (kstep, t1), u, want_u, 1e-12, 1e-15)
            last[(kstep, kinc, node)] = (t1, t3, u)
    for r in rows:
        kstep, t = int(r["step"]), r["step_time"]
        recs = [(k, v) for k, v in last.items() if k[0] == kstep and abs(v[0] - t) < 1e-12]
        if len(recs) != len(top):
            fail("step %d t %g: %d DISP calls recorded for %d top nodes" % (kstep, t, len(recs), len(top)))
        kinc = recs[0][0][1]
        seen.add((kstep, kinc))
        a = 0.01 * t if kstep == 1 else 0.02 * (0.5 + 0.5 * t)
        xmean = sum(nodes[n][0] for n in top) / len(top)
        # nu = 0: S33 = E E33 at every point, and the mean of E33 over the top face is the mean of the prescribed
        # u_z over H (bilinear interpolation, bottom at u_z = 0): RF3 = E A (2 a + 0.001 x_mean) / H, A = 2, H = 1
        want_rf = E * 2.0 * (2 * a + 0.001 * xmean)
        close("step %d t %g TOP.RF3" % (kstep, t), r["TOP.RF3"], want_rf, 1e-9, 1e-12)
        close("step %d t %g TOP.U3 (mean of what DISP returned)" % (kstep, t), r["TOP.U3"], 2 * a + 0.001 * xmean,
              1e-12, 1e-15)
        print("step %d inc %d t %.3f: TOP.RF3 %.12g = E A (2 a + 0.001 x_mean) / H ok" % (kstep, kinc, t, r["TOP.RF3"]))
    # the increments' TIME(3) and KINC: the step times of the CSV are cumulative sums of TIME(3)
    for kstep in (1, 2):
        incs = sorted(k[1] for k in seen if k[0] == kstep)
        if incs != list(range(1, len(incs) + 1)):
            fail("step %d: KINC of the converged increments %s" % (kstep, incs))
        tsum = 0.0
        for kinc in incs:
            rec = [v for k, v in last.items() if k[0] == kstep and k[1] == kinc][0]
            tsum += rec[1]
            close("step %d inc %d: TIME(1) = sum of TIME(3)" % (kstep, kinc), rec[0], tsum, 0, 1e-12)
    print("%d DISP calls, arguments as documented" % ncall)
    print("PASS")


if __name__ == "__main__":
    main()
