#!/usr/bin/env python3
"""SIGTERM to the launcher of a distributed run (docs/host.md, "Graceful stop"):

  check_launcher_sigterm.py --exe BIN --deck DECK --out DIR [--np 2] [--rows 3] [--grace 1]

OpenMPI 4's mpirun does not forward SIGTERM: it ends the job itself, sending every process SIGCONT, then SIGTERM
`odls_base_sigkill_timeout` seconds later (default 1), then SIGKILL as many seconds after that. ldfcz stops
gracefully on the SIGTERM (the increment under way finished, restart files, the closing summary), so the stop
succeeds when it takes less than that grace. This runs DECK under `mpirun -np NP` with
OMPI_MCA_odls_base_sigkill_timeout=GRACE and restart data only at the stop (--restart-write 1000000), sends SIGTERM
to mpirun once JOB.csv holds ROWS rows, and checks that the processes stopped as a serial run does on SIGTERM:
JOB.log reports the stop, the closing summary with its energy balance is written, JOB.sta notes it, and every
process wrote its restart file; the run must not have ended by itself first (the stop increment is below the
deck's last), and the SIGTERM must have reached the processes after about GRACE seconds (the increments the run
went on for prove the delay: more than one). mpirun's own exit status is OpenMPI's and is printed, not checked.
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import time


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def csv_rows(path):
    try:
        with open(path) as f:
            return max(0, f.read().count("\n") - 1)
    except FileNotFoundError:
        return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--rows", type=int, default=3, help="SIGTERM to mpirun once JOB.csv holds this many rows")
    ap.add_argument("--grace", type=int, default=1, help="odls_base_sigkill_timeout (s; OpenMPI's default 1)")
    a = ap.parse_args()
    if shutil.which("mpirun") is None:
        fail("mpirun not found (tools/setup.sh installs openmpi-bin for the LDFCZ_MPI build)")
    out = os.path.abspath(a.out)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    job = os.path.splitext(os.path.basename(a.deck))[0]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_odls_base_sigkill_timeout=str(a.grace))
    cmd = ["mpirun", "-np", str(a.np), "--oversubscribe", "--bind-to", "none", os.path.abspath(a.exe), "--quiet",
           "--threads", "1", "--out", out, "--restart-write", "1000000", os.path.abspath(a.deck)]
    print("$ OMPI_MCA_odls_base_sigkill_timeout=%d " % a.grace + " ".join(cmd))
    p = subprocess.Popen(cmd, cwd=out, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                         errors="replace")
    csv = os.path.join(out, job + ".csv")
    t0 = time.time()
    rows_at_signal = None
    while p.poll() is None and time.time() - t0 < 300:
        rows = csv_rows(csv)
        if rows >= a.rows:
            p.send_signal(signal.SIGTERM)
            rows_at_signal = rows
            break
        time.sleep(0.005)
    text, _ = p.communicate(timeout=300)
    if rows_at_signal is None:
        fail("the run ended (exit %d) before %d rows:\n%s" % (p.returncode, a.rows, text[-3000:]))
    log = open(os.path.join(out, job + ".log"), errors="replace").read()
    m = re.search(r"SIGTERM received: stopped after increment (\d+)", log)
    if not m:
        fail("JOB.log does not report a stop by SIGTERM (killed before the stop ended? the run ended first?)\n"
             + log[-2000:] + text[-2000:])
    if "step 1 completed" in log:
        fail("the run completed its step: the SIGTERM came too late to test the stop")
    if not re.search(r"(?m)^energy balance", log):
        fail("no closing summary (energy balance line) after the stop")
    if "# stopped by SIGTERM" not in open(os.path.join(out, job + ".sta"), errors="replace").read():
        fail("JOB.sta does not note the stop by SIGTERM")
    for r in range(a.np):
        if not os.path.exists(os.path.join(out, job + ".rst.%dof%d" % (r, a.np))):
            fail("no restart file of process %d after the stop" % r)
    stop_inc = int(m.group(1))
    rows_end = csv_rows(csv)
    if rows_end <= rows_at_signal + 1:
        fail("the processes stopped %d rows after the SIGTERM to mpirun: not the delay of its kill sequence"
             % (rows_end - rows_at_signal))
    print("SIGTERM to mpirun at %d CSV rows; the processes got it %d rows later (mpirun's grace %d s) and stopped "
          "gracefully after increment %d: closing summary, JOB.sta note, restart files of all %d processes; mpirun "
          "exit %d" % (rows_at_signal, rows_end - rows_at_signal, a.grace, stop_inc, a.np, p.returncode))
    print("PASS")


if __name__ == "__main__":
    main()
