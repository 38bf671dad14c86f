#!/usr/bin/env python3
"""*NODE PRINT and *EL PRINT tables in JOB.dat, checked against the closed form of a uniaxial C3D8 cube.

  check_print.py --exe BIN --out DIR

A unit cube (E = 1000, nu = 0.25) on rollers at z = 0, its top moved to w = 0.01 in four fixed increments
(*STATIC, DIRECT), NLGEOM=NO: uniaxial stress S33 = E w t at step time t, MISES = S33, E11 = -nu w t, the top's
RF3 totals E w t (a quarter per node), U3 = w t on the top. Requests: the top set (TOTALS=YES, every increment),
every node (no NSET, FREQ=3: increments 3 and 4, the step's last always printed), the element (SUMMARY=NO,
TOTALS=YES, FREQUENCY=2). The tables must hold exactly these rows and values, in the increments asked.
*MONITOR, NODE=7, DOF=3: each converged line of JOB.sta carries 'monitor U3 <w t>'.
"""
import argparse
import os
import re
import subprocess
import sys

E, NU, W = 1000.0, 0.25, 0.01

DECK = """*Heading
printed output
*Node, nset=all
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*Element, type=C3D8, elset=cube
1, 1, 2, 3, 4, 5, 6, 7, 8
*Nset, nset=bot
1, 2, 3, 4
*Nset, nset=top
5, 6, 7, 8
*Solid Section, elset=cube, material=m
*Material, name=m
*Elastic
1000., 0.25
*Boundary
bot, 3, 3
1, 1, 2
2, 2, 2
*Step
*Static, direct
0.25, 1.
*Boundary
top, 3, 3, 0.01
*Monitor, node=7, dof=3
*Node Print, nset=top, totals=yes
U3, RF3
*Node Print, freq=3
U3
*El Print, elset=cube, summary=no, totals=yes, frequency=2
S33, MISES, E11
*End Step
"""


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(name, got, want, rtol, atol=0.0):
    ok = abs(got - want) <= rtol * abs(want) + atol
    if not ok:
        print("%-50s got %.10g want %.10g FAIL" % (name, got, want))
        fail(name)


def tables(text):
    """{increment: [(title, header columns, rows, summary lines)]} from JOB.dat."""
    out = {}
    for block in re.split(r"\n\s+STEP\s+\d+\s+INCREMENT\s+", text)[1:]:
        inc = int(block.split()[0])
        tabs = []
        for part in block.split("THE FOLLOWING TABLE IS PRINTED")[1:]:
            lines = part.split("\n")
            title = lines[0].strip()
            head = [l for l in lines if "FOOT-" in l][0].split("FOOT-")[1].split()
            rows, extra = [], {}
            for l in lines[1:]:
                f = l.split()
                if not f or "FOOT-" in l or f[0] == "NOTE" or set(l.strip()) <= set("NODEUTPLMAS "):
                    continue
                if f[0] in ("MAXIMUM", "MINIMUM", "TOTAL"):
                    extra[f[0]] = [float(x) for x in f[1:]]
                elif f[0] == "AT":
                    continue
                else:
                    rows.append(f)
            tabs.append((title, head, rows, extra))
        out[inc] = tabs
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    deck = os.path.join(a.out, "print_cube.inp")
    with open(deck, "w") as f:
        f.write(DECK)
    res = subprocess.run([os.path.abspath(a.exe), "-q", deck], cwd=a.out, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if res.returncode != 0:
        print(res.stdout)
        fail("ldfcz exited with %d" % res.returncode)
    with open(os.path.join(a.out, "print_cube.dat")) as f:
        t = tables(f.read())
    if sorted(t) != [1, 2, 3, 4]:
        fail("printed increments %s, expected 1..4" % sorted(t))
    expect_titles = {1: ["NODE SET TOP"], 2: ["NODE SET TOP", "ELEMENT SET CUBE"],
                     3: ["NODE SET TOP", "ALL NODES"], 4: ["NODE SET TOP", "ALL NODES", "ELEMENT SET CUBE"]}
    for inc, tabs in t.items():
        titles = [x[0] for x in tabs]
        for want in expect_titles[inc]:
            if not any(want in ti for ti in titles):
                fail("increment %d: no table for %s (tables: %s)" % (inc, want, titles))
        if len(titles) != len(expect_titles[inc]):
            fail("increment %d: %d tables, expected %d" % (inc, len(titles), len(expect_titles[inc])))
        time = 0.25 * inc
        for title, head, rows, extra in tabs:
            if "NODE SET TOP" in title:
                if head != ["U3", "RF3"] or len(rows) != 4 or "TOTAL" not in extra or "MAXIMUM" not in extra:
                    fail("increment %d: top table %s, %d rows, %s" % (inc, head, len(rows), sorted(extra)))
                for r in rows:
                    close("top U3", float(r[1]), W * time, 1e-4)
                    close("top RF3", float(r[2]), E * W * time / 4, 1e-4)
                close("top TOTAL RF3 = E w t A", extra["TOTAL"][1], E * W * time, 1e-4)
            elif "ALL NODES" in title:
                labels = sorted(int(r[0]) for r in rows)
                if labels != list(range(1, 9)):
                    fail("all-node table rows %s" % labels)
                for r in rows:
                    close("U3 of node " + r[0], float(r[1]), W * time if int(r[0]) > 4 else 0.0, 1e-4, 1e-12)
            else:
                if head != ["S33", "MISES", "E11"] or len(rows) != 8 or "MAXIMUM" in extra:
                    fail("element table %s, %d rows, %s" % (head, len(rows), sorted(extra)))
                for r in rows:
                    close("S33", float(r[2]), E * W * time, 1e-4)
                    close("MISES", float(r[3]), E * W * time, 1e-4)
                    close("E11", float(r[4]), -NU * W * time, 1e-4)
                close("element TOTAL S33 (8 points)", extra["TOTAL"][0], 8 * E * W * time, 1e-4)
    mon = []
    with open(os.path.join(a.out, "print_cube.sta")) as f:
        for line in f:
            w = line.split()
            if len(w) > 9 and w[6] == "converged" and w[7] == "monitor" and w[8] == "U3":
                mon.append((float(w[4]), float(w[9])))
    if len(mon) != 4:
        fail("%d converged JOB.sta lines with the monitor, expected 4" % len(mon))
    for t, v in mon:
        close("monitor U3 of node 7 at t = %g" % t, v, W * t, 1e-6)
    print("printed tables: increments 1..4 with the requested tables and values (4-digit print, rtol 1e-4)")
    print("monitor: U3 of node 7 = w t on the 4 converged lines of JOB.sta")
    print("PASS")


if __name__ == "__main__":
    main()
