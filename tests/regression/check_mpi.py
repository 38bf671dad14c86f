#!/usr/bin/env python3
"""A deck run distributed (mpirun -np N, the LDFCZ_MPI build) against the same deck on one process.

Checks, for every N given:
  - the exit status is the one expected (0, or 2 for a deck whose user routine calls XIT);
  - the same increments, attempts, cutbacks and Newton iterations (closing summary) and the same attempt history in
    JOB.sta (step, increment, attempt, iterations, outcome of every line): the processes take the serial run's
    decisions;
  - JOB.csv: the same rows (step, increment; times to 1e-9 of the column: with increments sized from round-off-
    affected quantities, e.g. the plastic bound, the sums differ at 1e-12, while another increment choice would
    differ by dt/t >= 1e-3), every value within TOL * (largest magnitude of its
    column) of the one-process run. The runs differ only in the order in which element contributions are summed
    (per process, then over the processes) and in MUMPS' distributed factorization, i.e. in rounding; the converged
    solutions then differ by far less than the Newton tolerance (R_n = 5e-3 of the typical force). TOL = 1e-6
    still catches any wrong sum: an element missing or counted twice changes the forces by O(1);
  - the last field frame: JOB_NNNN.pvtu with one piece per process; the pieces hold every element exactly once,
    their cell data (by element label) and point data within TOL of the one-process JOB_NNNN.vtu (read with VTK;
    the ASCII frames hold 9 significant digits, so a difference of ~5e-9 of an array is printing, not physics);
  - with --xit: the message names the same element and deck line on every N.
The observed largest differences are printed.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

from ldfcz_tools import outputs


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, deck, out, np, user, extra, threads, trace=None):
    if os.path.isdir(out):
        shutil.rmtree(out)
    os.makedirs(out)
    cmd = ["mpirun", "-np", str(np), "--oversubscribe", "--bind-to", "none", exe, "-q", "--threads", str(threads),
           "--out", out]
    if user:
        cmd += ["--user", user]
    cmd += extra + [deck]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl_vader_single_copy_mechanism="none", OMPI_MCA_rmaps_base_oversubscribe="1",
               OMPI_MCA_mpi_yield_when_idle="1")
    env.pop("LDFCZ_LOOP_TRACE", None)
    if trace:
        env["LDFCZ_LOOP_TRACE"] = trace
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    return p.returncode, p.stdout + p.stderr


def job_files(out, deck):
    job = os.path.splitext(os.path.basename(deck))[0]
    return os.path.join(out, job)


def summary_counts(summary):
    """Increments, attempts, cutbacks and Newton iterations of a run summary (None without one)."""
    if summary is None:
        return None
    return tuple(summary["counters"][k] for k in ("increments", "attempts", "cutbacks", "iterations"))


def sta_lines(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                continue
            w = line.split()
            if len(w) < 7:
                continue
            outcome = " ".join(w[6:]).split("  r/q:")[0].split(" r/q:")[0]
            outcome = re.sub(r"[-+]?\d+\.\d+(e[-+]?\d+)?", "#", outcome)  # numbers in a cutback reason
            rows.append((w[0], w[1], w[2], w[3], outcome))
    return rows


def csv_rows(path):
    with open(path) as f:
        lines = [ln.strip() for ln in f if ln.strip()]
    head = lines[0].split(",")
    data = [[float(x) for x in ln.split(",")] for ln in lines[1:]]
    return head, data


def numbers(path):
    with open(path) as f:
        text = f.read()
    return [float(x) for x in re.findall(r"(?<![\w.])[-+]?\d+\.\d+(?:[eE][-+]?\d+)?", text)]


def read_grid(path):
    """Cell arrays by element label and point arrays of a .vtu, or of a .pvtu (its pieces merged), with VTK."""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLPUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    cd, pd = g.GetCellData(), g.GetPointData()
    ids = vtk_to_numpy(cd.GetArray("element"))
    cells = {}
    for k in range(cd.GetNumberOfArrays()):
        name = cd.GetArrayName(k)
        vals = vtk_to_numpy(cd.GetArray(k))
        cells[name] = {int(e): vals[i] for i, e in enumerate(ids)}
    points = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)) for k in range(pd.GetNumberOfArrays())}
    return g.GetNumberOfCells(), cells, points


def compare_frames(vtu, pvtu, np_):
    """Largest difference (relative to each array's largest value) between the one-process frame and the pieces
    of the distributed one: every cell once, the same cell data by element label, the same point data (each piece
    holds every point)."""
    import numpy
    n1, c1, p1 = read_grid(vtu)
    n, c, p = read_grid(pvtu)
    if n != n1 or sorted(c["element"]) != sorted(c1["element"]):
        fail(f"-np {np_}: the pieces hold {n} cells, one process {n1}: not every element exactly once")
    worst = 0.0
    for name, by_elem in c1.items():
        if name not in c:
            fail(f"-np {np_}: cell array {name} missing in the pieces")
        scale = max(max((float(numpy.max(numpy.abs(v))) for v in by_elem.values()), default=0.0), 1e-300)
        for e, v in by_elem.items():
            worst = max(worst, float(numpy.max(numpy.abs(numpy.asarray(c[name][e]) - v))) / scale)
    for name, v1 in p1.items():
        v = p[name].reshape(np_, *v1.shape)   # the pieces one after the other, every point in each
        scale = max(float(numpy.max(numpy.abs(v1))), 1e-300)
        worst = max(worst, float(numpy.max(numpy.abs(v - v1))) / scale)
    return worst


def read_trace(prefix, np_):
    """The element-loop trace of a run (LDFCZ_LOOP_TRACE): one list of rows (dicts of strings) per process."""
    procs = []
    for k in range(np_):
        path = f"{prefix}.rank{k}.csv"
        if not os.path.isfile(path):
            fail(f"-np {np_}: no element-loop trace {path}")
        with open(path, newline="") as fh:
            procs.append(list(csv.DictReader(fh)))
    if os.path.exists(f"{prefix}.rank{np_}.csv"):
        fail(f"-np {np_}: a trace file for process {np_}")
    return procs


CLASSES = ("umat", "elastic", "user")


def check_trace(ref, procs, np_, nelem):
    """ref: the one-process run's trace, procs: the distributed run's. The same loops (step, increment, tangent) in
    the same order on every process; in every loop each element computed exactly once over the processes (the
    calls of each class summed over the processes equal the one-process run's, which computes all nelem); the
    slowest process's time is the largest process's own time (the same number on every process)."""
    for r in ref[0]:
        if sum(int(r[c + "_calls"]) for c in CLASSES) != nelem:
            fail(f"one process: loop {r['loop']} computed {sum(int(r[c + '_calls']) for c in CLASSES)} elements "
                 f"of {nelem}")
        if r["slowest_s"] != r["loop_s"]:
            fail(f"one process: loop {r['loop']}: slowest {r['slowest_s']} s is not its own {r['loop_s']} s")
    key = ("loop", "step", "increment", "tangent")
    for k, rows in enumerate(procs):
        if [tuple(r[x] for x in key) for r in rows] != [tuple(r[x] for x in key) for r in ref[0]]:
            fail(f"-np {np_}: process {k}'s trace lists other loops than the one-process run's "
                 f"({len(rows)} against {len(ref[0])})")
    for i, r1 in enumerate(ref[0]):
        for c in CLASSES:
            got = sum(int(rows[i][c + "_calls"]) for rows in procs)
            if got != int(r1[c + "_calls"]):
                fail(f"-np {np_}: loop {r1['loop']}: {got} {c} calls over the processes against {r1[c + '_calls']}")
        slowest = {rows[i]["slowest_s"] for rows in procs}
        own = max(float(rows[i]["loop_s"]) for rows in procs)
        if len(slowest) != 1 or float(slowest.pop()) != own:
            fail(f"-np {np_}: loop {r1['loop']}: slowest process's time {[rows[i]['slowest_s'] for rows in procs]} "
                 f"is not the largest own time {own}")
    print(f"-np {np_}: element-loop trace: {len(ref[0])} loops as on one process, each element computed once per "
          f"loop, the slowest time the largest process's")


def check_trace_tool(prefix, np_, t_slowest):
    """benchmarks/loop_trace.py on the distributed run's trace: its slowest process of each loop, summed from the rows
    (4 digits each), is the closing summary's (summed in double precision): within 0.1 % and 1 ms."""
    tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "loop_trace.py")
    p = subprocess.run([sys.executable, tool, prefix, "--pool", "0.1"], capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        fail(f"-np {np_}: benchmarks/loop_trace.py failed:\n{p.stdout}{p.stderr}")
    m = re.search(r"slowest process of each loop summed ([\d.]+) s", p.stdout)
    if not m or "a pool of 0.10" not in p.stdout:
        fail(f"-np {np_}: benchmarks/loop_trace.py printed no loop-by-loop balance or pool line:\n{p.stdout}")
    got = float(m.group(1))
    if abs(got - t_slowest) > 1e-3 * t_slowest + 1e-3:
        fail(f"-np {np_}: benchmarks/loop_trace.py sums the slowest loops to {got} s, the summary to {t_slowest} s")
    print(f"-np {np_}: benchmarks/loop_trace.py: slowest process of each loop summed {got} s (summary {t_slowest} s)")
    if np_ >= 3:
        # --rerun pairs each process of one run with the same process of another: a trace against itself
        # correlates exactly (1.00 for every element class it holds)
        p = subprocess.run([sys.executable, tool, prefix, "--rerun", prefix], capture_output=True, text=True,
                           timeout=120)
        corr = re.findall(r"log seconds per call of (\w+) between the two runs: (\S+)", p.stdout)
        if p.returncode != 0 or not corr or any(v != "1.00" for _, v in corr):
            fail(f"-np {np_}: benchmarks/loop_trace.py --rerun of a trace against itself: {corr}\n{p.stdout}{p.stderr}")
        print(f"-np {np_}: benchmarks/loop_trace.py --rerun against itself: {corr}")


NUMBER = re.compile(r"^[-+]?\d+\.\d+E[-+]\d+$")


def compare_dat(path1, path, np_):
    """JOB.dat (the *NODE PRINT / *EL PRINT tables, written by rank 0) against the one-process run's: the same
    lines and words; printed numbers (5 significant digits) equal, one unit of the last digit allowed (a rounding
    that the runs' round-off differences can flip). The node or element under MAXIMUM/MINIMUM ('AT NODE', 'AT
    ELEMENT') may differ: points of a symmetric model tie, and round-off picks one (the values themselves are
    compared on every row). Returns the number of values compared."""
    lines1 = open(path1).read().split("\n")
    lines = open(path).read().split("\n") if os.path.isfile(path) else []
    if len(lines) != len(lines1):
        fail(f"-np {np_}: {os.path.basename(path)} has {len(lines)} lines against {len(lines1)}")
    count = 0
    for k, (a, b) in enumerate(zip(lines1, lines)):
        wa, wb = a.split(), b.split()
        if len(wa) != len(wb):
            fail(f"-np {np_}: {os.path.basename(path)} line {k + 1}: '{b}' against '{a}'")
        if wa[:1] == ["AT"] and wb[:1] == ["AT"]:
            if wa[:2] != wb[:2]:
                fail(f"-np {np_}: {os.path.basename(path)} line {k + 1}: '{b}' against '{a}'")
            continue
        for x, y in zip(wa, wb):
            if NUMBER.match(x) and NUMBER.match(y):
                count += 1
                fx, fy = float(x), float(y)
                unit = 10.0 ** (int(x.split("E")[1]) - 4)
                if abs(fx - fy) > 1.01 * unit:
                    fail(f"-np {np_}: {os.path.basename(path)} line {k + 1}: {y} against {x}:\n  {b}\n  {a}")
            elif x != y:
                fail(f"-np {np_}: {os.path.basename(path)} line {k + 1}: '{b}' against '{a}'")
    return count


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--np", type=int, nargs="+", default=[2, 3])
    ap.add_argument("--user")
    ap.add_argument("--xit", action="store_true", help="the deck's routine calls XIT: exit 2, same message")
    ap.add_argument("--remote-at", type=int, nargs="*", default=[],
                    help="with --xit: for these N the element must be computed by a process other than rank 0")
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--expect-exit", type=int, default=0, help="exit status of a run that is not an XIT stop "
                    "(3 with --stop-after-increments)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--dat", action="store_true", help="compare JOB.dat (printed tables) with the one-process "
                    "run's; the one-process JOB.dat must hold element tables")
    ap.add_argument("--trace", action="store_true", help="run with LDFCZ_LOOP_TRACE and check the traces "
                    "(and that an unwritable trace path only warns)")
    ap.add_argument("extra", nargs="*", help="more ldfcz options (after --)")
    a = ap.parse_args()
    if shutil.which("mpirun") is None:
        fail("mpirun not found (tools/setup.sh installs openmpi-bin for the LDFCZ_MPI build)")
    ref_out = os.path.join(a.out, "np1")
    trace_of = (lambda out: os.path.join(out, "trace")) if a.trace else (lambda out: None)
    rc1, text1 = run(a.exe, a.deck, ref_out, 1, a.user, a.extra, a.threads, trace_of(ref_out))
    want = 2 if a.xit else a.expect_exit
    if rc1 != want:
        fail(f"one process: exit {rc1}, expected {want}\n{text1[-3000:]}")
    base1 = job_files(ref_out, a.deck)
    summary1 = outputs.read_summary(ref_out, os.path.basename(base1))
    log1 = open(base1 + ".log").read() if a.xit else ""   # the XIT message users read
    for np in a.np:
        out = os.path.join(a.out, f"np{np}")
        rc, text = run(a.exe, a.deck, out, np, a.user, a.extra, a.threads, trace_of(out))
        if rc != want:
            fail(f"-np {np}: exit {rc}, expected {want}\n{text[-3000:]}")
        base = job_files(out, a.deck)
        summary = outputs.read_summary(out, os.path.basename(base))
        if a.xit:
            log = open(base + ".log").read()   # the XIT message users read
            m1 = re.findall(r"ldfcz: error: .*", log1)
            m = re.findall(r"ldfcz: error: .*", log)
            if not m1 or not m or m1[-1] != m[-1]:
                fail(f"-np {np}: XIT message differs:\n  1: {m1[-1:]}\n  {np}: {m[-1:]}")
            if "(element " not in m[-1]:
                fail(f"-np {np}: the XIT message names no element: {m[-1]}")
            who = re.findall(r"the element is computed by process (\d+) of", log)
            if not who:
                fail(f"-np {np}: the log does not say which process computed the element")
            if np in a.remote_at and who[-1] == "0":
                fail(f"-np {np}: the element is rank 0's: the test needs it on another process")
            print(f"-np {np}: exit 2 everywhere, element on process {who[-1]}, message: {m[-1]}")
            continue
        c1, c = summary_counts(summary1), summary_counts(summary)
        if c1 is None or c != c1:
            fail(f"-np {np}: increments/attempts/cutbacks/iterations {c} against {c1} on one process")
        mpi = summary["mpi"]
        if summary["processes"] != np or mpi is None or mpi["processes"] != np:
            fail(f"-np {np}: the summary does not report {np} processes")
        # the element loop's balance: the slowest process of each loop, summed over the loops, is at least the
        # largest process total (a sum of maxima bounds the maximum of the sums: both count each loop up to its
        # first reduction) and at least the mean; allowed below: the sums' rounding (1 us)
        t_max, t_slowest = mpi["element_loop_max_s"], mpi["element_loop_slowest_summed_s"]
        if t_slowest < t_max - 1e-6:
            fail(f"-np {np}: slowest process of each loop summed {t_slowest} s < the largest process total {t_max} s")
        # rank 0's wait for the slowest process at the end of its loops is a part of its host communication: the
        # two parts add up to the communication's total (to round-off)
        wait, rest, comm = mpi["loop_end_wait_s"], mpi["reductions_s"], mpi["communication_s"]
        if wait < 0 or rest < 0 or abs(wait + rest - comm) > 1e-9 * max(comm, 1.0):
            fail(f"-np {np}: waiting {wait} s + the rest {rest} s != the host communication {comm} s")
        s1, s = sta_lines(base1 + ".sta"), sta_lines(base + ".sta")
        if s1 != s:
            for k, (x, y) in enumerate(zip(s1, s)):
                if x != y:
                    fail(f"-np {np}: JOB.sta line {k + 1} differs: {y} against {x}")
            fail(f"-np {np}: JOB.sta has {len(s)} attempts against {len(s1)}")
        h1, d1 = csv_rows(base1 + ".csv")
        h, d = csv_rows(base + ".csv")
        if h != h1 or len(d) != len(d1):
            fail(f"-np {np}: CSV header or row count differs ({len(d)} against {len(d1)})")
        worst = 0.0
        for j in range(len(h1)):
            col1 = [r[j] for r in d1]
            scale = max(max(abs(x) for x in col1), 1e-300)
            for x, y in zip(col1, (r[j] for r in d)):
                rel = abs(x - y) / scale
                lim = 1e-9 if j < 4 else a.tol
                if rel > lim:
                    fail(f"-np {np}: CSV column {h1[j]}: {y} against {x} (relative to the column {rel:.2e} > {lim})")
                worst = max(worst, rel)
        frames1 = sorted(f for f in os.listdir(ref_out) if f.endswith(".vtu"))
        frames = sorted(f for f in os.listdir(out) if f.endswith(".pvtu"))
        if [f[:-5] for f in frames] != [f[:-4] for f in frames1]:
            fail(f"-np {np}: .pvtu frames {frames} against the .vtu frames {frames1} of one process")
        vworst = 0.0
        if frames:
            # every block of the last frame (JOB_NNNN and, with user and continuum elements, JOB_NNNN_interface)
            last = re.match(r"(.*_\d{4})", frames1[-1]).group(1)
            for f1 in (f for f in frames1 if f.startswith(last)):
                vworst = max(vworst, compare_frames(os.path.join(ref_out, f1), os.path.join(out, f1[:-4] + ".pvtu"),
                                                    np))
            if vworst > a.tol:
                fail(f"-np {np}: last frame differs by {vworst:.2e} of an array's largest value")
        print(f"-np {np}: {c[0]} increments, {c[1]} attempts, {c[3]} Newton iterations as on one process; "
              f"largest CSV difference {worst:.2e} of the column, last VTU frame {vworst:.2e}")
        if a.dat:
            if "E L E M E N T   O U T P U T" not in open(base1 + ".dat").read():
                fail("the one-process JOB.dat holds no element table: the deck does not test *EL PRINT")
            n = compare_dat(base1 + ".dat", base + ".dat", np)
            print(f"-np {np}: JOB.dat equal to the one-process run's ({n} printed values)")
        if a.trace:
            check_trace(read_trace(trace_of(ref_out), 1), read_trace(trace_of(out), np), np,
                        summary1["model"]["elements"])
            check_trace_tool(trace_of(out), np, t_slowest)
    if a.trace:
        # a trace that cannot be written: every process warns and the run goes on, its results unchanged
        out = os.path.join(a.out, "trace_unwritable")
        np = a.np[0]
        rc, text = run(a.exe, a.deck, out, np, a.user, a.extra, a.threads,
                       os.path.join(out, "no_such_directory", "trace"))
        if rc != want:
            fail(f"-np {np}, unwritable LDFCZ_LOOP_TRACE: exit {rc}, expected {want}\n{text[-3000:]}")
        warned = sorted(re.findall(r"no element-loop trace from process (\d+)", text))
        if warned != [str(k) for k in range(np)]:
            fail(f"-np {np}, unwritable LDFCZ_LOOP_TRACE: warnings from processes {warned}\n{text[-3000:]}")
        if sta_lines(job_files(out, a.deck) + ".sta") != sta_lines(base1 + ".sta"):
            fail(f"-np {np}, unwritable LDFCZ_LOOP_TRACE: JOB.sta differs from the one-process run's")
        print(f"-np {np}: an unwritable LDFCZ_LOOP_TRACE warns on every process, the run is unchanged")
    print("PASS")


if __name__ == "__main__":
    main()
