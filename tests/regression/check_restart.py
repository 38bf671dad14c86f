#!/usr/bin/env python3
"""Restart test (issue 6, "no lost results"; docs/host.md, "Restart"):

  check_restart.py --exe BIN --deck DECK --out DIR [--user FILE[,FILE]] [--stop K] [--freq N] [--kill | --term]
                   [--modes stop,term,kill] [--deck-restart] [--other-deck DECK2] [--rel 1e-12] [--atol 0]
                   [--expect-exit 0] [--np N] [--dat] [--compare-files A,B] [--point mid|end] [--no-refusals]

1. runs DECK to the end (reference, DIR/full);
2. runs it again in DIR/cut writing restart data every N increments and stopping after K converged increments
   (--stop-after-increments K), or with --kill: every increment, killed with SIGKILL once JOB.csv holds K rows (the
   run is advanced in ~1 ms slices between SIGSTOP and SIGCONT), or with --term: sent SIGTERM once JOB.csv holds K
   rows, restart data every N increments (N large: the only restart data are those the graceful stop writes); the
   stopped run must end with exit status 143, say so in JOB.log and JOB.sta, and write the closing summary with its
   energy balance;
   with --deck-restart the frequency comes from a `*RESTART, WRITE, FREQUENCY=N` line inserted into a copy of the
   deck (DIR/deck/JOB.inp) instead of the option --restart-write N;
3. restarts from DIR/cut/JOB.rst into DIR/cut (ldfcz --restart-from JOB.rst DECK);
4. checks: exit status 0 (or --expect-exit); JOB.csv has the reference's header and number of rows; every value
   within --rel relative (and --atol absolute) of the reference's (--rel 0: bit for bit, the VTU frames' contents
   too); the VTU frame count and JOB.pvd time stamps are the reference's; the run summary's energy balance
   (JOB.summary.json) is the reference's. Prints the largest relative difference and whether the CSV is bit-identical (same text), which it
   is when the restart repeats the uninterrupted arithmetic.
5. with --other-deck: a restart of DECK's restart file with DECK2 must be refused (exit 2, "different model").
Also refused (exit 2): a truncated restart file, a file that is not a restart file, one of another format version
and one of a build with another summary record.
With --np N (the LDFCZ_MPI build) every run is `mpirun -np N`: one restart file per process (JOB.rst.RofN, read by a
run with the same N; the first restart names rank 0's file JOB.rst.0ofN as it is on disk, the others JOB.rst), the reference and the restart distributed alike; --term sends SIGUSR1 to the launcher, which
forwards it to every process (OpenMPI; SIGTERM to mpirun is tests/mpi/check_launcher_sigterm.py's; the processes
advance in ~1 ms slices between SIGSTOP and SIGCONT, and are resumed only once each holds the forwarded signal
pending, so that a fast run on a loaded machine cannot end before the stop), and the
processes must stop together after the increment under way with the log, status note and closing summary of a
serial stop (mpirun's own exit status is OpenMPI's, not checked).
The refusals of damaged files are the serial run's code and are checked there only. Two distributed runs of one
deck are not bit-identical (MUMPS' parallel factorization sums contribution blocks in message arrival order), so
the distributed restart is compared within --rel (give 1e-9), frame times too.
Several interruptions of one deck against one uninterrupted run: --modes stop,term (stop: --stop-after-increments,
term: SIGTERM, kill: SIGKILL; default: the one --kill/--term say), each into its own directory (DIR/cut, then
DIR/cut_MODE). --dat: JOB.dat must be the uninterrupted run's to the byte too (the stop must fall on a restart point:
--freq 1 with --stop-after-increments, any frequency with SIGTERM, since the graceful stop writes the restart data;
the tables of increments after the restart point would otherwise be printed twice). --compare-files A,B: files the
user routines write into the output directory (appended by the interrupted run and the continuation) must be the
uninterrupted run's to the byte. --point mid|end: the --stop-after-increments stop must leave a restart point within
a step (the continuation resumes it) or at a step's end (the continuation begins the next step). --no-refusals:
skip the refusals of damaged files (the same code for every deck; checked by the tests that keep them).
"""
import argparse
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import time

from ldfcz_tools import outputs


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cmd, cwd, expect=None):
    p = subprocess.run(cmd, capture_output=True, text=True, errors="replace", cwd=cwd, timeout=600)
    print("$ " + " ".join(cmd) + "  -> exit %d" % p.returncode)
    if re.search(r"Fortran runtime error|Backtrace|Program received signal", p.stderr):
        print(p.stderr[-3000:])
        fail("crash")
    if expect is not None and p.returncode not in expect:
        print(p.stdout[-3000:] + p.stderr[-3000:])
        fail("exit status %d, expected %s" % (p.returncode, expect))
    return p


def descendants(pid):
    """The ldfcz processes started under pid (mpirun's children, or theirs), from /proc; not their own children
    (the compiler a process runs for --user at its start, which it waits for)."""
    parent = {}
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open("/proc/%s/stat" % d) as f:
                    st = f.read()
            except OSError:
                continue
            name = st[st.index("(") + 1:st.rindex(")")]
            parent[int(d)] = (int(st[st.rindex(")") + 2:].split()[1]), name)
    found, todo = [], [pid]
    while todo:
        q = todo.pop()
        for c, (pp, name) in parent.items():
            if pp == q:
                if name.startswith("ldfcz"):
                    found.append(c)
                else:
                    todo.append(c)
    return found


def signal_all(pids, sig):
    for q in pids:
        try:
            os.kill(q, sig)
        except ProcessLookupError:
            pass


def task_status(pid):
    """The /proc status texts of every thread of pid ([] when it is gone)."""
    out = []
    try:
        for t in os.listdir("/proc/%d/task" % pid):
            with open("/proc/%d/task/%s/status" % (pid, t)) as f:
                out.append(f.read())
    except OSError:
        pass
    return out


def stopped(pid):
    """Every thread of pid is stopped (or pid is gone): a signal sent now stays pending until SIGCONT."""
    return all(re.search(r"^State:\s*[TZX]", st, re.M) for st in task_status(pid))


def pending(pid, sig):
    """Whether pid holds sig pending (in any thread, or process-wide) or is gone."""
    sts = task_status(pid)
    bit = 1 << (int(sig) - 1)
    return not sts or any(int(v, 16) & bit for st in sts for v in re.findall(r"^(?:SigPnd|ShdPnd):\s*([0-9a-f]+)", st, re.M))


def read_csv(path):
    with open(path) as f:
        lines = f.read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def frame_times(path):
    if not os.path.exists(path):
        return []
    return re.findall(r'timestep="\s*([^"]+)"', open(path).read())


def summary_energy(outdir, job):
    """The energy balance of the run summary (external work, stored + dissipated; JOB.summary.json)."""
    doc = outputs.read_summary(outdir, job)
    return (doc["energy"]["external_work"], doc["energy"]["stored_dissipated"]) if doc else None


def stopped_by(outdir, job, sig):
    """The run summary says the run was stopped by signal sig after its closing summary was complete."""
    doc = outputs.read_summary(outdir, job)
    return doc is not None and doc["status"] == "stopped_by_signal" and doc["signal"] == sig and \
        doc["energy"]["external_work"] is not None


def interrupt(a, mode, base, run_deck, write_opt, out, cut, job):
    """The interrupted run of one mode into cut: --stop-after-increments, SIGKILL or SIGTERM (SIGUSR1 to mpirun)."""
    rst = os.path.join(cut, job + ".rst")
    if a.np and mode == "term":
        # OpenMPI's mpirun forwards SIGUSR1 to every process at once; SIGTERM it does not forward but sends the
        # processes itself, a grace later, before SIGKILL (docs/host.md, tests/mpi/check_launcher_sigterm.py)
        cmd = base + ["--out", cut, "--restart-write", str(a.freq), run_deck]
        print("$ " + " ".join(cmd) + "  (SIGUSR1 to mpirun after %d rows)" % a.stop)
        p = subprocess.Popen(cmd, cwd=out, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        csv = os.path.join(cut, job + ".csv")
        # the processes advance in slices of ~1 ms between SIGSTOP and SIGCONT (sent to them, not to mpirun), so that
        # even a fast run on a loaded machine is caught after about K rows: SIGUSR1 goes to mpirun while they are
        # stopped, and they are resumed only once each holds it pending (the run cannot end first)
        t0 = time.time()
        rows = 0
        sent = False
        while p.poll() is None and time.time() - t0 < 300:
            procs = descendants(p.pid)
            if len(procs) < a.np:
                time.sleep(0.001)
                continue
            signal_all(procs, signal.SIGSTOP)
            t1 = time.time()
            while not all(stopped(q) for q in procs):
                if time.time() - t1 > 60:
                    fail("the processes did not stop within 60 s of SIGSTOP")
                time.sleep(0.0005)
            try:
                with open(csv) as f:
                    rows = f.read().count("\n") - 1
            except FileNotFoundError:
                rows = 0
            if rows >= a.stop:
                p.send_signal(signal.SIGUSR1)
                t1 = time.time()
                while not all(pending(q, signal.SIGUSR1) for q in procs):
                    if time.time() - t1 > 60:
                        signal_all(procs, signal.SIGCONT)
                        fail("mpirun did not forward SIGUSR1 to every process within 60 s")
                    time.sleep(0.01)
                signal_all(procs, signal.SIGCONT)
                sent = True
                break
            signal_all(procs, signal.SIGCONT)
            time.sleep(0.001)
        if not sent:
            fail("the run ended (exit %s) before %d CSV rows were seen: choose a smaller --stop" % (p.poll(), a.stop))
        p.wait(timeout=300)
        log = open(os.path.join(cut, job + ".log"), errors="replace").read()
        if "SIGUSR1 received: stopped after increment" not in log:
            fail("JOB.log does not report the stop by SIGUSR1 (did the run end first? choose a smaller --stop)")
        if not stopped_by(cut, job, "SIGUSR1"):
            fail("no closing summary (JOB.summary.json, status stopped_by_signal) after SIGUSR1")
        for r in range(a.np):
            if not os.path.exists(rst + ".%dof%d" % (r, a.np)):
                fail("no restart file of process %d after SIGUSR1" % r)
        print("all %d processes stopped by SIGUSR1 with %d CSV rows seen, closing summary written" % (a.np, rows))
    elif mode in ("kill", "term"):
        sig = signal.SIGTERM if mode == "term" else signal.SIGKILL
        cmd = base + ["--out", cut, "--restart-write", str(a.freq) if mode == "term" else "1", run_deck]
        print("$ " + " ".join(cmd) + "  (%s after %d rows)" % (sig.name, a.stop))
        p = subprocess.Popen(cmd, cwd=out, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        csv = os.path.join(cut, job + ".csv")
        # the run advances in slices of ~1 ms between SIGSTOP and SIGCONT, so that even a fast run is caught
        # after about K rows (the kill lands at an arbitrary point of the stopped program)
        t0 = time.time()
        rows = 0
        while p.poll() is None and time.time() - t0 < 300:
            p.send_signal(signal.SIGSTOP)
            try:
                with open(csv) as f:
                    rows = f.read().count("\n") - 1
            except FileNotFoundError:
                rows = 0
            if rows >= a.stop:
                p.send_signal(sig)
                if mode == "term":
                    p.send_signal(signal.SIGCONT)
                break
            p.send_signal(signal.SIGCONT)
            time.sleep(0.001)
        rc = p.wait(timeout=300)
        if mode == "term":
            if rc != 128 + signal.SIGTERM:
                fail("exit status %d after SIGTERM, expected %d (graceful stop)" % (rc, 128 + signal.SIGTERM))
            log = open(os.path.join(cut, job + ".log"), errors="replace").read()
            if "SIGTERM received: stopped after increment" not in log:
                fail("JOB.log does not report the stop by SIGTERM")
            if not stopped_by(cut, job, "SIGTERM"):
                fail("no closing summary (JOB.summary.json, status stopped_by_signal) after SIGTERM")
            if "# stopped by SIGTERM" not in open(os.path.join(cut, job + ".sta"), errors="replace").read():
                fail("JOB.sta does not note the stop by SIGTERM")
            print("stopped by SIGTERM with %d CSV rows seen: exit 143, closing summary written" % rows)
        else:
            if rc != -signal.SIGKILL:
                fail("the run ended (exit %d) before the kill: choose a smaller --stop" % rc)
            print("killed with %d CSV rows seen" % rows)
    else:
        run(base + ["--out", cut] + write_opt + ["--stop-after-increments", str(a.stop), run_deck], out, expect=[3])
    rst_file = rst + (".0of%d" % a.np if a.np else "")   # the file of rank 0 when distributed
    if not os.path.exists(rst_file):
        fail("no restart file " + rst_file)
    if os.path.exists(rst + ".tmp"):
        print("note: a JOB.rst.tmp was left by the kill (never read)")


def refusals(a, base, out, rst, run_deck):
    """Refused with exit 2: another deck, the same deck with EXTRAPOLATION changed, a truncated file, a file that is
    not a restart file, a file of a build whose summary record has another size."""
    if a.other_deck:
        user = ["--user", a.other_user] if a.other_user else []
        p = run(base + user + ["--out", os.path.join(out, "other"), "--restart-from", rst,
                               os.path.abspath(a.other_deck)], out, expect=[2])
        if "different model" not in p.stdout + p.stderr:
            fail("the refusal does not say 'different model': " + (p.stdout + p.stderr)[-500:])
    if a.np or a.no_refusals:
        return   # the refusals below are the serial run's code, the same for every deck
    bad = os.path.join(out, "bad")
    os.makedirs(bad)
    # the same deck with another *STEP, EXTRAPOLATION: the continuation would not repeat the run, so refused too
    no_ex = os.path.join(bad, os.path.basename(run_deck))
    with open(no_ex, "w") as f:
        f.write(re.sub(r"(?im)^(\*STEP\b[^\n]*)$", r"\1, EXTRAPOLATION=NO", open(run_deck).read()))
    p = run(base + ["--out", os.path.join(out, "no_extrapolation"), "--restart-from", rst, no_ex], out, expect=[2])
    if "different model" not in p.stdout + p.stderr:
        fail("a restart with EXTRAPOLATION changed is not refused: " + (p.stdout + p.stderr)[-500:])
    data = open(rst, "rb").read()
    with open(os.path.join(bad, "trunc.rst"), "wb") as f:
        f.write(data[: len(data) * 2 // 3])
    p = run(base + ["--out", bad, "--restart-from", os.path.join(bad, "trunc.rst"), run_deck], out, expect=[2])
    if "truncated" not in p.stdout + p.stderr:
        fail("a truncated restart file is not reported as such")
    p = run(base + ["--out", bad, "--restart-from", run_deck, run_deck], out, expect=[2])
    if "not an ldfcz restart file" not in p.stdout + p.stderr:
        fail("a deck given as restart file is not refused as such")
    # a build whose run summary has another field: the header's summary size (bytes 12-15, after the magic and
    # the version) differs by one 8-byte field; refused by name, not read as a damaged or valid file
    bits = struct.unpack("=i", data[12:16])[0]
    with open(os.path.join(bad, "layout.rst"), "wb") as f:
        f.write(data[:12] + struct.pack("=i", bits + 64) + data[16:])
    p = run(base + ["--out", bad, "--restart-from", os.path.join(bad, "layout.rst"), run_deck], out, expect=[2])
    if "written by another build of ldfcz" not in p.stdout + p.stderr:
        fail("a restart file with another summary layout is not refused as such: " + (p.stdout + p.stderr)[-500:])
    # a file of another format version (an older ldfcz): refused by name
    with open(os.path.join(bad, "version.rst"), "wb") as f:
        f.write(data[:8] + struct.pack("=i", struct.unpack("=i", data[8:12])[0] - 1) + data[12:])
    p = run(base + ["--out", bad, "--restart-from", os.path.join(bad, "version.rst"), run_deck], out, expect=[2])
    if "restart file format version" not in p.stdout + p.stderr:
        fail("a restart file of another format version is not refused as such: " + (p.stdout + p.stderr)[-500:])


def same_words(ref, got, rel, atol):
    """Files ref and got word by word: numbers within rel relative + atol, other words equal."""
    r = open(ref, errors="replace").read().split("\n")
    g = open(got, errors="replace").read().split("\n")
    if len(r) != len(g):
        fail("%s: %d lines, %d uninterrupted" % (got, len(g), len(r)))
    for k, (lr, lg) in enumerate(zip(r, g), 1):
        wr, wg = lr.split(), lg.split()
        if len(wr) != len(wg):
            fail("%s line %d: %d words, %d uninterrupted" % (got, k, len(wg), len(wr)))
        for x, y in zip(wr, wg):
            try:
                fx, fy = float(x), float(y)
            except ValueError:
                if x != y:
                    fail("%s line %d: %r against %r uninterrupted" % (got, k, y, x))
                continue
            if abs(fx - fy) > rel * max(abs(fx), abs(fy)) + atol:
                fail("%s line %d: %s against %s uninterrupted" % (got, k, y, x))


def compare(a, full, cut, job, mode):
    """The continuation's outputs against the uninterrupted run's."""
    ref = read_csv(os.path.join(full, job + ".csv"))
    got = read_csv(os.path.join(cut, job + ".csv"))
    if ref[0] != got[0]:
        fail("CSV headers differ:\n%s\n%s" % (ref[0], got[0]))
    if len(ref) != len(got):
        fail("CSV rows: %d after the restart, %d uninterrupted" % (len(got) - 1, len(ref) - 1))
    worst = 0.0
    for k, (r, g) in enumerate(zip(ref[1:], got[1:]), 2):
        rv, gv = r.split(","), g.split(",")
        if len(rv) != len(gv):
            fail("line %d: %d fields, expected %d" % (k, len(gv), len(rv)))
        if rv[:2] != gv[:2]:
            fail("line %d: step/increment %s, expected %s" % (k, gv[:2], rv[:2]))
        for x, y in zip(rv[2:], gv[2:]):
            x, y = float(x), float(y)
            d = abs(x - y)
            if d > 1e-300:
                worst = max(worst, d / max(abs(x), abs(y)))
            if d > a.rel * max(abs(x), abs(y)) + a.atol:
                fail("line %d: %.17g against %.17g uninterrupted (relative %.3e > %.1e)"
                     % (k, y, x, d / max(abs(x), abs(y)), a.rel))
    identical = ref == got
    print("%s: restart: %d rows; largest relative difference %.3e; CSV %s"
          % (mode, len(ref) - 1, worst, "bit-identical" if identical else "NOT bit-identical"))
    ft_ref = frame_times(os.path.join(full, job + ".pvd"))
    ft_got = frame_times(os.path.join(cut, job + ".pvd"))
    if a.np and len(ft_ref) == len(ft_got):
        # distributed: MUMPS' parallel factorization sums contribution blocks in the order messages arrive, so two
        # runs of the same deck differ in the last bits (and the increment sizes with them): times within a.rel
        if any(abs(float(x) - float(y)) > a.rel * max(abs(float(x)), 1e-300) for x, y in zip(ft_ref, ft_got)):
            fail("JOB.pvd frame times differ beyond %.1e: %s vs %s" % (a.rel, ft_got, ft_ref))
    elif ft_ref != ft_got:
        fail("JOB.pvd frames differ: %s vs %s" % (ft_got, ft_ref))
    vtu_ref = sorted(f for f in os.listdir(full) if f.endswith(".vtu"))
    vtu_got = sorted(f for f in os.listdir(cut) if f.endswith(".vtu"))
    if len(vtu_ref) != len(vtu_got):
        fail("%d VTU frames after the restart, %d uninterrupted" % (len(vtu_got), len(vtu_ref)))
    if a.rel == 0.0 and a.atol == 0.0:
        # bit for bit: the frames' contents too
        for f in vtu_ref:
            if open(os.path.join(full, f), "rb").read() != open(os.path.join(cut, f), "rb").read():
                fail("VTU frame %s differs from the uninterrupted run's" % f)
    # the summary's energy balance: the external work continues over the restart, the stored and dissipated
    # energy is summed anew; both the reference's within --rel and --atol (bit for bit with 0)
    e_ref, e_got = summary_energy(full, job), summary_energy(cut, job)
    if e_ref is None or e_got is None or any(
            (x is None) != (y is None) or (x is not None and abs(x - y) > a.rel * abs(y) + a.atol)
            for x, y in zip(e_got, e_ref)):
        fail("energy balance differs: %s against %s uninterrupted" % (e_got, e_ref))
    names = ([job + ".dat"] if a.dat else []) + [f for f in (a.compare_files or "").split(",") if f]
    for name in names:
        r, g = os.path.join(full, name), os.path.join(cut, name)
        if not os.path.exists(r) or not os.path.exists(g):
            fail("%s missing (uninterrupted: %s, continued: %s)" % (name, os.path.exists(r), os.path.exists(g)))
        if open(r, "rb").read() == open(g, "rb").read():
            print("%s: %s bit-identical (%d bytes)" % (mode, name, os.path.getsize(r)))
            continue
        if a.rel == 0.0 and a.atol == 0.0:
            fail("%s differs from the uninterrupted run's (%d against %d bytes)"
                 % (name, os.path.getsize(g), os.path.getsize(r)))
        same_words(r, g, a.rel, a.atol)
        print("%s: %s within %.1e relative + %.1e (not bit-identical)" % (mode, name, a.rel, a.atol))
    print("%s: frames %d, energy balance (external work, stored + dissipated) %r" % (mode, len(ft_ref), e_ref))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--user", help="user routine file(s), comma-separated")
    ap.add_argument("--stop", type=int, default=9, help="stop (or kill) after this many increments")
    ap.add_argument("--freq", type=int, default=1, help="restart data every N increments")
    ap.add_argument("--kill", action="store_true", help="SIGKILL instead of --stop-after-increments")
    ap.add_argument("--term", action="store_true", help="SIGTERM (graceful stop) instead of --stop-after-increments")
    ap.add_argument("--modes", help="interruptions to check one after the other: stop, term, kill (comma-separated)")
    ap.add_argument("--deck-restart", action="store_true", help="*RESTART, WRITE in the deck, not the option")
    ap.add_argument("--other-deck", help="a restart with this deck must be refused")
    ap.add_argument("--other-user", help="the user routine file the other deck needs")
    ap.add_argument("--rel", type=float, default=1e-12, help="relative tolerance of the CSV (0: bit for bit)")
    ap.add_argument("--atol", type=float, default=0.0, help="absolute tolerance added (sums that cancel)")
    ap.add_argument("--expect-exit", type=int, default=0, help="exit status of the complete runs (3: stops early)")
    ap.add_argument("--np", type=int, default=0, help="run every ldfcz under mpirun -np NP (LDFCZ_MPI build)")
    ap.add_argument("--dat", action="store_true", help="JOB.dat must be bit-identical too")
    ap.add_argument("--compare-files", help="files of the output directory that must be bit-identical too")
    ap.add_argument("--point", choices=["mid", "end"], help="where the --stop-after-increments stop falls")
    ap.add_argument("--no-refusals", action="store_true", help="skip the refusals of damaged restart files")
    a = ap.parse_args()
    exe = os.path.abspath(a.exe)
    deck = os.path.abspath(a.deck)
    out = os.path.abspath(a.out)
    job = os.path.splitext(os.path.basename(deck))[0]
    modes = a.modes.split(",") if a.modes else ["kill" if a.kill else "term" if a.term else "stop"]
    shutil.rmtree(out, ignore_errors=True)
    full = os.path.join(out, "full")
    os.makedirs(full)
    base = [exe, "--quiet", "--threads", "1"]
    if a.np:
        os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        base = ["mpirun", "-np", str(a.np), "--oversubscribe", "--bind-to", "none"] + base
    if a.user:
        base += ["--user", ",".join(os.path.abspath(u) for u in a.user.split(","))]

    # 1. the uninterrupted run
    run(base + ["--out", full, deck], out, expect=[a.expect_exit])

    run_deck = deck
    write_opt = ["--restart-write", str(a.freq)]
    if a.deck_restart:
        ddir = os.path.join(out, "deck")
        os.makedirs(ddir)
        text = open(deck).read()
        text, n = re.subn(r"(?im)^(\*STEP\b[^\n]*\n)", r"\1*RESTART, WRITE, FREQUENCY=%d\n" % a.freq, text, count=1)
        if n != 1:
            fail("no *STEP line in " + deck)
        # *INCLUDE paths are relative to the deck: copy the deck's directory's include files along
        for inc in re.findall(r"(?im)^\*INCLUDE\s*,\s*INPUT\s*=\s*(\S+)", text):
            shutil.copy(os.path.join(os.path.dirname(deck), inc), os.path.join(ddir, inc))
        run_deck = os.path.join(ddir, job + ".inp")
        with open(run_deck, "w") as f:
            f.write(text)
        write_opt = []
    for k, mode in enumerate(modes):
        cut = os.path.join(out, "cut" if k == 0 else "cut_" + mode)
        os.makedirs(cut)
        # 2. the interrupted run
        interrupt(a, mode, base, run_deck, write_opt, out, cut, job)
        rst = os.path.join(cut, job + ".rst")
        rows_cut = len(read_csv(os.path.join(cut, job + ".csv"))) - 1
        if k == 0:
            refusals(a, base, out, rst, run_deck)
        # 3. the restart; distributed, the first from rank 0's file as the user sees it on disk (JOB.rst.0ofN stands
        # for the set), the others from the set's name
        given = rst + (".0of%d" % a.np if a.np and k == 0 else "")
        p = run(base + ["--out", cut, "--restart-from", given, run_deck], out, expect=[a.expect_exit])
        log = open(os.path.join(cut, job + ".log"), errors="replace").read()
        resumed = ": resumed from " in log
        print("%s: the interrupted run left %d rows; the continuation %s" % (mode, rows_cut,
              "resumed within a step" if resumed else "began the step after the restart point"))
        if a.point and mode == "stop" and resumed != (a.point == "mid"):
            fail("the restart point is %s, expected %s: choose another --stop"
                 % ("within a step" if resumed else "at a step's end", a.point))
        # 4. comparison
        compare(a, full, cut, job, mode)
    print("ok")


if __name__ == "__main__":
    main()
