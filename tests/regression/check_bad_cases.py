#!/usr/bin/env python3
"""Bad-input cases that check_run.py --bad does not cover (registered by tests/robustness.cmake):

  check_bad_cases.py --exe BIN --case FILE --out DIR

FILE is one of
  decks/bad/options/NAME.args   a bad command line: line 1 `# EXPECT exit=2 message=TEXT`, line 2 the arguments
                                ({deck} = a valid deck, {dir} = DIR, {src} = the directory of FILE)
  decks/bad/runtime/NAME.inp    a deck that parses but whose user routine rejects its properties (XIT):
                                line 1 `** EXPECT exit=2 message=TEXT`
  decks/bad/fuzz_regressions/NAME.inp   a deck that once crashed ldfcz (tools/fuzz_decks.py): `** EXPECT exit=2`
Each must end with the expected exit status, the message text in stdout/stderr/JOB.log, and no crash (no signal,
no Fortran runtime error or backtrace), and must not claim completion ("completed" for every step).
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
VALID_DECK = os.path.join(os.path.abspath(HERE), "..", "..", "decks", "single", "c3d8_uniaxial.inp")
CRASH = re.compile(r"Fortran runtime error|Backtrace|Segmentation fault|SIGSEGV|SIGABRT|core dumped|"
                   r"Program received signal")


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--case", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    with open(a.case, errors="replace") as f:
        first = f.readline()
        second = f.readline()
    m = re.match(r"(?:#|\*\*) EXPECT exit=(\d+)(?: message=(.*))?$", first.strip())
    if not m:
        fail("no EXPECT first line in " + a.case)
    want_exit, message = int(m.group(1)), (m.group(2) or "").strip()
    a.case = os.path.abspath(a.case)
    a.out = os.path.abspath(a.out)
    if a.case.endswith(".args"):
        args = [x.format(deck=VALID_DECK, dir=a.out, src=os.path.dirname(os.path.abspath(a.case)))
                for x in shlex.split(second)]
        cmd = [a.exe] + args
        job = None
    else:
        cmd = [a.exe, "--quiet", "--threads", "1", "--out", a.out, a.case]
        job = os.path.splitext(os.path.basename(a.case))[0]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, errors="replace", cwd=a.out)
    print(" ".join(cmd))
    print("exit status", p.returncode)
    text = p.stdout + p.stderr
    log = ""
    if job and os.path.exists(os.path.join(a.out, job + ".log")):
        log = open(os.path.join(a.out, job + ".log"), errors="replace").read()
        text += log
    print(text.strip()[-2000:])
    if p.returncode < 0:
        fail("killed by signal %d" % -p.returncode)
    if CRASH.search(p.stderr):
        fail("crash (runtime error/backtrace) in stderr")
    if p.returncode != want_exit:
        fail("exit status %d, expected %d" % (p.returncode, want_exit))
    if message and message not in text:
        fail("the output does not contain '%s'" % message)
    if want_exit != 0 and re.search(r"step \d+ completed", log) and "error" not in log:
        fail("the log presents the run as complete")
    print("ok")


if __name__ == "__main__":
    main()
