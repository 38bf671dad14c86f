#!/usr/bin/env python3
"""Read the element-loop trace of a run (LDFCZ_LOOP_TRACE=PREFIX: PREFIX.rankR.csv, one file per process, one row
per element loop; docs/host.md "Diagnostics") and say where the loop-by-loop imbalance of a distributed run comes
from.

    benchmarks/loop_trace.py PREFIX [--reference SERIAL_PREFIX] [--rerun PREFIX2] [--class all|user|umat|elastic]
                        [--slow 1.3] [--pool F ...]

Printed:
- the balance: the processes' totals (largest / mean) and loop by loop (the slowest process of each loop summed,
  against the mean: what the processes wait for at the force reduction);
- wall against CPU seconds of the loops (a process descheduled inside its loop shows wall > CPU);
- each process's microseconds per call of each element class over the run, their spread over the processes and
  the correlation between classes (processes slower in every class: they ran on slower cores, or computed costlier
  elements of every class); with --rerun, a second run of the same deck and partition on as many processes: the
  correlation of each process's seconds per call between the two runs (near 1: its elements cost more; near 0:
  where the process ran decided its speed);
- the speed factor of each process in each loop: the loop's seconds in the element routines over what its calls
  take at the process's median seconds per call (per element class, over the loops of the same kind: with or
  without the tangent; --class takes one class only, e.g. the user elements, whose cost does not depend on a
  material's state). 1 is the process's usual speed, 2 half of it. Its share of slow loops, its lag-1
  autocorrelation (slow spells that last several loops), and the correlation between the speed factors of two
  element classes in the same loop (near 1: the whole process ran slower, not a costlier element);
- with --pool F: what sharing a fraction F of every loop's work between the processes would have given with the
  traced speeds (idealised: sharing costs nothing), dealt out as the loop runs or before it by the previous
  loop's speeds;
- the loop-by-loop excess that processes whose speed factors were drawn independently from the measured
  distribution would show: E[max of P draws] / E[one draw] (the excess of the loops' maxima over their mean when
  each process does the same work). With --reference, the same from another trace (a one-process run), so that a
  machine's speed variation measured without any partner process predicts a distributed run's excess.
"""
import argparse
import csv
import glob
import math
import re
import statistics
import sys

CLASSES = ("umat", "elastic", "user")


def fail(msg):
    print("loop_trace.py: error: " + msg, file=sys.stderr)
    sys.exit(2)


def read_trace(prefix):
    """Rows of every process, rank order: {rank: [row dict with floats/ints]}."""
    files = glob.glob(glob.escape(prefix) + ".rank*.csv")
    if not files:
        fail(f"no trace files {prefix}.rankR.csv")
    ranks = {}
    for path in files:
        m = re.search(r"\.rank(\d+)\.csv$", path)
        if not m:
            continue
        rows = []
        with open(path, newline="") as fh:
            for line_no, row in enumerate(csv.DictReader(fh), start=2):
                try:
                    rows.append({k: (int(v) if k.endswith("calls") or k in ("loop", "step", "increment", "tangent")
                                     else float(v)) for k, v in row.items()})
                except (TypeError, ValueError):
                    fail(f"{path}:{line_no}: not a trace row: {row}")
        ranks[int(m.group(1))] = rows
    if sorted(ranks) != list(range(len(ranks))):
        fail(f"trace files of processes {sorted(ranks)}: one is missing")
    n = {len(r) for r in ranks.values()}
    if len(n) != 1:
        fail(f"the processes' traces have different numbers of loops: {sorted(n)} (a run cut off?)")
    return [ranks[k] for k in sorted(ranks)]


def speed_factors(rows, cls):
    """Speed factor of each loop (None where it has no calls): the loop's seconds in the element routines over what
    its calls take at the process's median seconds per call (per class, over the loops of the same kind: with or
    without the tangent). cls: one class only, or 'all' (every class, weighted by its time)."""
    classes = CLASSES if cls == "all" else (cls,)
    med = {}
    for c in classes:
        for kind in (0, 1):
            v = [r[c + "_s"] / r[c + "_calls"] for r in rows if r["tangent"] == kind and r[c + "_calls"] > 0]
            med[c, kind] = statistics.median(v) if v else 0.0
    out = []
    for r in rows:
        spent = sum(r[c + "_s"] for c in classes if r[c + "_calls"] > 0)
        usual = sum(r[c + "_calls"] * med[c, r["tangent"]] for c in classes if r[c + "_calls"] > 0)
        out.append(spent / usual if usual > 0 else None)
    return out


def correlation(x, y):
    """Pearson's correlation to 2 decimals, or a word where it is undefined (a constant series)."""
    try:
        return f"{statistics.correlation(x, y):.2f}"
    except statistics.StatisticsError:
        return "undefined (constant)"


def expected_max(values, p):
    """E[max of p independent draws] from the empirical distribution of values (order statistics)."""
    x = sorted(values)
    n = len(x)
    return sum(v * (((i + 1) / n) ** p - (i / n) ** p) for i, v in enumerate(x))


def lag1(values):
    m = statistics.mean(values)
    c0 = sum((v - m) ** 2 for v in values)
    if c0 == 0:
        return 0.0
    return sum((values[i] - m) * (values[i + 1] - m) for i in range(len(values) - 1)) / c0


def pick_class(procs, asked):
    if asked != "all" and not any(r[asked + "_calls"] for rows in procs for r in rows):
        fail(f"class {asked} has no calls in this trace")
    return asked


def pool_simulation(procs, factors, fraction):
    """Sum over the loops of the slowest process's time if a fraction of every loop's work were a pool shared
    between the processes, against the measured sum: (measured, mean, dynamic, predicted). Each process's work in a
    loop at its usual speed is its loop seconds over its speed factor; the pool is dealt out either as the loop
    runs (a process that has finished its own part takes from the pool: the finish time T solves sum_p
    max(0, T - t_p) / s_p = pool, t_p the end of its own part) or before it, in proportion to the speeds of the
    previous loop. Idealised: taking from the pool costs nothing."""
    nprocs = len(procs)
    measured = mean = dynamic = predicted = 0.0
    for i in range(len(procs[0])):
        s = [factors[p][i] for p in range(nprocs)]
        if any(x is None for x in s):
            continue
        work = [procs[p][i]["loop_s"] / s[p] for p in range(nprocs)]
        measured += max(procs[p][i]["loop_s"] for p in range(nprocs))
        mean += sum(procs[p][i]["loop_s"] for p in range(nprocs)) / nprocs
        own = [s[p] * (1 - fraction) * work[p] for p in range(nprocs)]
        pool = fraction * sum(work)
        lo, hi = max(own), max(own) + pool * max(s)
        for _ in range(60):
            t = 0.5 * (lo + hi)
            if sum(max(0.0, t - own[p]) / s[p] for p in range(nprocs)) >= pool:
                hi = t
            else:
                lo = t
        dynamic += hi
        prev = [factors[p][i - 1] if i > 0 and factors[p][i - 1] else 1.0 for p in range(nprocs)]
        speed = [1.0 / x for x in prev]
        predicted += max(s[p] * ((1 - fraction) * work[p] + pool * speed[p] / sum(speed)) for p in range(nprocs))
    return measured, mean, dynamic, predicted


def prediction_lines(label, factors, nprocs):
    vals = [f for f in factors if f is not None]
    mean = statistics.mean(vals)
    counts = sorted({2, 4, 8, 16} | {nprocs}) if nprocs > 1 else [2, 4, 8, 16]
    parts = [f"{p}: {expected_max(vals, p) / mean:.3f}" for p in counts if p > 1]
    print(f"  {label}: loop-by-loop excess of independent processes (E[max] / E[one]) " + ", ".join(parts))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("prefix", help="LDFCZ_LOOP_TRACE value of the run (PREFIX.rankR.csv)")
    ap.add_argument("--reference", help="the trace of another run (one process) whose speed variation predicts")
    ap.add_argument("--rerun", help="the trace of a second run of the same deck and partition (as many processes)")
    ap.add_argument("--class", dest="cls", choices=CLASSES + ("all",), default="all",
                    help="element class whose seconds per call measure a process's speed (default: all classes, "
                    "weighted by their time)")
    ap.add_argument("--slow", type=float, default=1.3, help="speed factor from which a loop counts as slow")
    ap.add_argument("--pool", type=float, nargs="*", default=[],
                    help="fractions of the work to simulate as a pool shared between the processes in every loop")
    a = ap.parse_args()

    procs = read_trace(a.prefix)
    nprocs, nloops = len(procs), len(procs[0])
    for rows in procs[1:]:
        if [r["loop"] for r in rows] != [r["loop"] for r in procs[0]]:
            fail("the processes' traces do not list the same loops")
    if nloops == 0:
        fail("the trace holds no element loop")
    ntan = sum(r["tangent"] for r in procs[0])
    print(f"{a.prefix}: {nprocs} process(es), {nloops} element loops ({ntan} with the tangent)")

    totals = [sum(r["loop_s"] for r in rows) for rows in procs]
    cpu = [sum(r["cpu_s"] for r in rows) for rows in procs]
    # the classes every process called and timed (a class whose seconds round to 0 has no measurable speed)
    present = [c for c in CLASSES
               if all(any(r[c + "_calls"] for r in rows) and sum(r[c + "_s"] for r in rows) > 0 for rows in procs)]
    per_call = [{c: sum(r[c + "_s"] for r in rows) / sum(r[c + "_calls"] for r in rows) for c in present}
                for rows in procs]
    for k in range(nprocs):
        calls = ", ".join(f"{c} {1e6 * per_call[k][c]:.2f}" for c in present)
        print(f"  process {k}: loops {totals[k]:.3f} s wall, {cpu[k]:.3f} s CPU (CPU / wall {cpu[k] / totals[k]:.3f}); "
              f"us per call: {calls}")
    if nprocs > 1:
        mean_total = statistics.mean(totals)
        sum_max = sum(max(rows[i]["loop_s"] for rows in procs) for i in range(nloops))
        print(f"  balance of the totals: largest / mean {max(totals) / mean_total:.3f}")
        print(f"  loop by loop: slowest process of each loop summed {sum_max:.3f} s, against the mean "
              f"{sum_max / mean_total:.3f}")
        # a process's own speed over the whole run: the same element class costs each process alike where the
        # processes run at the same speed (the user elements' cost, unlike a material's, does not depend on state)
        spread = ", ".join(f"{c} {max(x[c] for x in per_call) / min(x[c] for x in per_call):.2f}" for c in present)
        print(f"  seconds per call over the run, largest / smallest over the processes: {spread}")
        if len(present) > 1 and nprocs > 2:   # two points always correlate to +-1
            for i, c in enumerate(present):
                for d in present[i + 1:]:
                    corr = correlation([math.log(x[c]) for x in per_call], [math.log(x[d]) for x in per_call])
                    print(f"  correlation over the processes of the log seconds per call of {c} and {d}: {corr} "
                          f"(near 1: some processes ran slower throughout, whatever they computed)")

    if a.rerun:
        other = read_trace(a.rerun)
        if len(other) != nprocs:
            fail(f"--rerun {a.rerun}: {len(other)} processes against {nprocs}")
        if nprocs < 3:
            fail("--rerun needs 3 processes or more (two points always correlate to +-1)")
        for c in present:
            calls = [sum(r[c + "_calls"] for r in rows) for rows in procs]
            calls2 = [sum(r[c + "_calls"] for r in rows) for rows in other]
            if any(abs(x - y) > 0.05 * x for x, y in zip(calls, calls2)):
                fail(f"--rerun {a.rerun}: the processes' {c} calls differ by more than 5 %: not the same partition")
            mine = [math.log(x[c]) for x in per_call]
            if any(sum(r[c + "_s"] for r in rows) <= 0 for rows in other):
                fail(f"--rerun {a.rerun}: a process's {c} seconds sum to 0")
            theirs = [math.log(sum(r[c + "_s"] for r in rows) / sum(r[c + "_calls"] for r in rows)) for rows in other]
            print(f"  rerun {a.rerun}: correlation over the processes of the log seconds per call of {c} between the "
                  f"two runs: {correlation(mine, theirs)}")
    cls = pick_class(procs, a.cls)
    factors = [speed_factors(rows, cls) for rows in procs]
    what = "every class's" if cls == "all" else f"the {cls} class's"
    print(f"  speed factor: {what} seconds per call over the process's median (loops of the same kind)")
    for k in range(nprocs):
        v = [f for f in factors[k] if f is not None]
        slow = sum(f >= a.slow for f in v) / len(v)
        print(f"    process {k}: mean {statistics.mean(v):.3f}, largest {max(v):.2f}, loops at >= {a.slow} x: "
              f"{100 * slow:.1f} %, lag-1 autocorrelation {lag1(v):.2f}")
        for i, c in enumerate(present):
            for d in present[i + 1:]:
                f, g = speed_factors(procs[k], c), speed_factors(procs[k], d)
                pairs = [(math.log(x), math.log(y)) for x, y in zip(f, g) if x and y]
                if len(pairs) > 2:
                    corr = statistics.correlation([p[0] for p in pairs], [p[1] for p in pairs])
                    print(f"      correlation of the log speed factors of {c} and {d} in the same loop: {corr:.2f}")
    if nprocs > 1:
        paired = []
        for i in range(nloops):
            f = [factors[k][i] for k in range(nprocs)]
            if all(x is not None for x in f):
                paired.append(f)
        if paired:
            mean_f = statistics.mean(x for f in paired for x in f)
            print(f"  speed factors as paired in the run: E[max] / E[one] {statistics.mean(max(f) for f in paired) / mean_f:.3f}")
            if nprocs == 2:
                corr = statistics.correlation([math.log(f[0]) for f in paired], [math.log(f[1]) for f in paired])
                print(f"  correlation of the two processes' log speed factors loop by loop: {corr:.2f}")
    prediction_lines("this run's speed factors", [x for f in factors for x in f], nprocs)
    if nprocs > 1:
        for fraction in a.pool:
            if not 0 < fraction <= 1:
                fail(f"--pool {fraction}: a fraction in (0, 1]")
            measured, mean, dynamic, predicted = pool_simulation(procs, factors, fraction)
            print(f"  a pool of {fraction:.2f} of each loop's work (idealised): slowest process of each loop summed "
                  f"{measured:.1f} s as run ({measured / mean:.3f} x the mean), {dynamic:.1f} s shared as the loop runs "
                  f"({dynamic / mean:.3f}), {predicted:.1f} s split by the previous loop's speeds ({predicted / mean:.3f})")
    if a.reference:
        ref = read_trace(a.reference)
        rcls = pick_class(ref, cls)
        rf = [x for rows in ref for x in speed_factors(rows, rcls)]
        v = [x for x in rf if x is not None]
        print(f"  reference {a.reference} ({len(ref)} process(es), {len(ref[0])} loops, {rcls} class): loops at >= "
              f"{a.slow} x: {100 * sum(x >= a.slow for x in v) / len(v):.1f} %")
        prediction_lines("reference's speed factors", rf, nprocs)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
