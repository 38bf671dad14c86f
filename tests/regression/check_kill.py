#!/usr/bin/env python3
"""Kill test (issue 6, "no lost results"): JOB.csv and JOB.sta are flushed every increment, so a run killed with
SIGKILL at any moment leaves every completed increment readable.

  check_kill.py --exe BIN --deck DECK --out DIR [--rows N] [--kills K]

Starts ldfcz on a long deck, waits until JOB.csv holds at least N data rows (then a random extra delay), sends
SIGKILL, and checks: the header is intact; every newline-terminated row has as many fields as the header, all
numeric and finite, step/inc non-decreasing, step_time increasing within a step; at least as many complete rows as
were seen before the kill (nothing flushed was lost); only the very last line may be unterminated (a write cut by
the kill); every newline-terminated line of JOB.sta is complete (7 columns and an outcome). Repeated K times with
different delays.
"""
import argparse
import csv
import io
import math
import os
import random
import signal
import subprocess
import sys
import time


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def count_rows(path):
    try:
        with open(path) as f:
            return max(0, f.read().count("\n") - 1)
    except FileNotFoundError:
        return 0


def check_csv(path, seen):
    with open(path) as f:
        text = f.read()
    lines = text.split("\n")
    tail = lines.pop()          # '' when the file ends with a newline, else an unterminated (cut) line
    if not lines:
        fail("no header in " + path)
    header = next(csv.reader(io.StringIO(lines[0])))
    rows = [next(csv.reader(io.StringIO(l))) for l in lines[1:]]
    last = None
    for k, r in enumerate(rows, 2):
        if len(r) != len(header):
            fail("%s line %d: %d fields, header has %d" % (path, k, len(r), len(header)))
        try:
            v = [float(x) for x in r]
        except ValueError:
            fail("%s line %d: not numeric: %r" % (path, k, r))
        if not all(math.isfinite(x) for x in v):
            fail("%s line %d: non-finite value" % (path, k))
        if last and (v[0], v[1]) <= (last[0], last[1]):
            fail("%s line %d: step/inc not increasing" % (path, k))
        if last and v[0] == last[0] and v[2] <= last[2]:
            fail("%s line %d: step time not increasing" % (path, k))
        last = v
    if len(rows) < seen:
        fail("%d complete rows after the kill, %d were seen before it" % (len(rows), seen))
    return len(rows), tail


def check_sta(path):
    with open(path) as f:
        text = f.read()
    lines = text.split("\n")
    lines.pop()
    n = 0
    for k, l in enumerate(lines, 1):
        if l.startswith("#") or not l.strip():
            continue
        f = l.split()
        if len(f) < 7 or not (f[6].startswith("converged") or f[6].startswith("cutback") or f[6].startswith("stop")):
            fail("%s line %d incomplete: %r" % (path, k, l[:100]))
        n += 1
    return n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--rows", type=int, default=15)
    ap.add_argument("--kills", type=int, default=3)
    ap.add_argument("--seed", type=int, default=5)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    job = os.path.splitext(os.path.basename(a.deck))[0]
    for kill in range(a.kills):
        d = os.path.join(a.out, "kill%d" % kill)
        os.makedirs(d, exist_ok=True)
        for f in os.listdir(d):
            os.remove(os.path.join(d, f))
        csvp, stap = os.path.join(d, job + ".csv"), os.path.join(d, job + ".sta")
        p = subprocess.Popen([a.exe, "--quiet", "--threads", "1", "--out", d, a.deck], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
        t0 = time.time()
        target = a.rows + kill * 7
        while count_rows(csvp) < target and p.poll() is None and time.time() - t0 < 120:
            time.sleep(0.005)
        time.sleep(rng.uniform(0.0, 0.05))
        seen = count_rows(csvp)
        if p.poll() is not None:
            fail("the run ended (exit %s) before it could be killed: use a longer deck" % p.returncode)
        os.kill(p.pid, signal.SIGKILL)
        p.wait()
        n, tail = check_csv(csvp, seen)
        ns = check_sta(stap)
        print("kill %d: SIGKILL after %d rows seen: %d complete CSV rows, %d complete STA lines, unterminated tail: %s"
              % (kill, seen, n, ns, repr(tail[:40]) if tail else "none"))
    print("ok")


if __name__ == "__main__":
    main()
