#!/usr/bin/env python3
"""The host's messages and Abaqus' command-line habits (issue 37 items 4-5; docs/host.md):

  check_messages.py --exe LDFCZ --decks DECKS --user-src DIR --reader SRC --out DIR

1. Misspelt keywords and parameters get the nearest name of the reader's tables ("*ELASTC: unknown keyword; did
   you mean *ELASTIC?", "TYPO; did you mean TYPE?"); a real Abaqus keyword ldfcz does not read is named as such, not
   taken for a slip (*PLASTIC is one edit from *ELASTIC); a word far from every keyword gets no suggestion. The
   keyword table (reader_keywords) holds exactly the keywords read_block dispatches (SRC: deck_reader.f90).
2. Abaqus' command line: `ldfcz job=NAME` runs NAME.inp into NAME.*, `ldfcz NAME` finds NAME.inp, `job=A input=B`
   names the job A, `user=FILE` without its extension finds FILE.f90, `cpus=2 interactive` run (interactive noted in
   JOB.log), abbreviations `j=` and `int` work; refused words (background, oldjob=, datacheck) and an ambiguous one
   exit 2 with a message saying what to do instead, and no traceback.
3. A --user file that does not compile (-q): exit 2, JOB.log with the compile command and the error, a JOB.sta
   status line, JOB.summary.json input_error, no empty JOB.csv/JOB.dat.
4. A CAE deck's boilerplate (*PREPRINT, history output, *DENSITY) is noted in JOB.log, not warned on the console;
   the deck's warnings that may change a result stay on the console and go to JOB.log too.
5. Every cutback is named in JOB.log: its own line, or counted in a "repeated N more times" line; the lines add up
   to the summary's cutback count (stab_peel_brittle: 9 cutbacks of 4 causes).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

CRASH = re.compile(r"Traceback|Fortran runtime error|Backtrace|Segmentation fault|Program received signal")


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(exe, args, cwd, expect):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True, timeout=300)
    text = p.stdout + p.stderr
    if p.returncode != expect or CRASH.search(text):
        fail("ldfcz %s: exit %d (expected %d)\n%s" % (" ".join(args), p.returncode, expect, text))
    return p


def expect_message(exe, out, name, deck_text, want, unwanted=None):
    deck = os.path.join(out, name + ".inp")
    with open(deck, "w") as f:
        f.write(deck_text)
    p = run(exe, ["-q", deck], out, 2)
    if want not in p.stderr or (unwanted and unwanted in p.stderr):
        fail("%s: message %r, expected %r%s" % (name, p.stderr.strip(), want,
                                                 " without %r" % unwanted if unwanted else ""))
    print("%-22s %s" % (name, p.stderr.strip().split(": ", 3)[-1][:100]))


def case_suggestions(a, base):
    out = os.path.join(a.out, "suggest")
    os.makedirs(out, exist_ok=True)
    expect_message(a.exe, out, "keyword_typo", base.replace("*ELASTIC", "*ELASTC", 1),
                   "*ELASTC: unknown keyword; did you mean *ELASTIC?")
    expect_message(a.exe, out, "keyword_transposed", base.replace("*BOUNDARY", "*BOUDNARY", 1),
                   "did you mean *BOUNDARY?")
    expect_message(a.exe, out, "parameter_typo", base.replace("*ELEMENT, TYPE=", "*ELEMENT, TYEP=", 1),
                   "unsupported parameter TYEP; did you mean TYPE?")
    expect_message(a.exe, out, "abaqus_keyword", base.replace("*ELASTIC", "*PLASTIC", 1),
                   "*PLASTIC: an Abaqus keyword that ldfcz does not support", unwanted="did you mean")
    expect_message(a.exe, out, "far_keyword", base.replace("*ELASTIC", "*FOOBARBAZ", 1),
                   "*FOOBARBAZ: unknown keyword (ldfcz never ignores", unwanted="did you mean")
    # the table and the dispatch hold the same keywords
    src = open(a.reader).read()
    block = re.search(r"recursive subroutine read_block.*?end subroutine read_block", src, re.S).group(0)
    dispatched = set(k for c in re.findall(r"case \((.*?)\)\n", block, re.S) for k in re.findall(r"'(\*[^']*)'", c))
    table = re.search(r"reader_keywords\(\*\) = \[character\(len=\d+\) ::(.*?)\]", src, re.S).group(1)
    listed = set(re.findall(r"'(\*[^']*)'", table))
    if dispatched != listed:
        fail("reader_keywords and read_block differ: only dispatched %s, only listed %s" % (
            sorted(dispatched - listed), sorted(listed - dispatched)))
    print("keyword table          the %d keywords of read_block" % len(listed))


def case_command_line(a):
    out = os.path.join(a.out, "words")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    shutil.copy(os.path.join(a.decks, "single", "c3d8_umat_uniaxial.inp"), os.path.join(out, "Job-1.inp"))
    shutil.copy(os.path.join(a.user_src, "user_umat_neohooke.f90"), os.path.join(out, "neohooke.f90"))
    run(a.exe, ["job=Job-1", "user=neohooke", "cpus=2", "interactive", "-q"], out, 0)
    with open(os.path.join(out, "Job-1.log")) as f:
        log = f.read()
    if "interactive: accepted without effect" not in log or "neohooke.f90" not in log:
        fail("job=Job-1 user=neohooke: JOB.log does not note interactive or compile neohooke.f90:\n" + log[:2000])
    print("job= user= cpus= interactive: Job-1.* written, neohooke.f90 compiled")
    os.remove(os.path.join(out, "Job-1.csv"))
    run(a.exe, ["Job-1", "-q"], out, 0)
    if not os.path.exists(os.path.join(out, "Job-1.csv")):
        fail("ldfcz Job-1: no Job-1.csv")
    run(a.exe, ["j=Run-2", "inp=Job-1", "int", "-q"], out, 0)
    if not os.path.exists(os.path.join(out, "Run-2.csv")):
        fail("j=Run-2 inp=Job-1: no Run-2.csv")
    print("ldfcz Job-1, j=Run-2 inp=Job-1 int: Job-1.inp found, job names Job-1 and Run-2")
    for args, want in ((["job=Job-1", "background"], "use the shell"),
                       (["job=Job-1", "oldjob=Job-0"], "--restart-from"),
                       (["job=Job-1", "datacheck"], "reads and checks the whole deck"),
                       (["job=Job-1", "a"], "ambiguous"),
                       (["job=Job-1", "cpus=two"], "cpus= needs a positive integer"),
                       (["job=Job-2"], "Job-2: file not found (nor Job-2.inp)"),
                       (["--user", "nothing", "Job-1"], "nor nothing.f, .for, .f90, .F or .o")):
        p = run(a.exe, args + ["-q"], out, 2)
        if want not in p.stderr:
            fail("%s: message %r, expected %r" % (" ".join(args), p.stderr.strip(), want))
        print("refused: %-34s %s" % (" ".join(args), p.stderr.strip()[:90]))


def case_user_error(a):
    out = os.path.join(a.out, "user_error")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    with open(os.path.join(out, "broken.f"), "w") as f:
        f.write("      subroutine umat(\n      not fortran\n")
    deck = os.path.join(a.decks, "single", "c3d8_umat_uniaxial.inp")
    run(a.exe, ["-q", "-o", "run", "--user", "broken", deck], out, 2)
    job = os.path.join(out, "run", "c3d8_umat_uniaxial")
    with open(job + ".log") as f:
        log = f.read()
    with open(job + ".sta") as f:
        sta = f.read()
    with open(job + ".summary.json") as f:
        doc = json.load(f)
    if "compiling user routines: " not in log or "compilation of broken.f failed" not in log:
        fail("JOB.log lacks the compile command or the error (-q):\n" + log)
    if "# input error (exit status 2): --user: compilation of broken.f failed" not in sta:
        fail("JOB.sta lacks the status line:\n" + sta)
    if doc["status"] != "input_error":
        fail("summary status %s" % doc["status"])
    empty = [x for x in os.listdir(os.path.join(out, "run")) if os.path.isfile(os.path.join(out, "run", x)) and
             os.path.getsize(os.path.join(out, "run", x)) == 0]
    if empty:
        fail("empty job files left after the --user error: %s" % empty)
    print("--user error (-q): compile command and error in JOB.log, JOB.sta line, input_error, no empty files")


def case_notes(a):
    out = os.path.join(a.out, "notes")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(a.decks, "cae", "cae_block_pressure.inp")
    p = run(a.exe, ["-q", "-o", out, deck], out, 0)
    log = open(os.path.join(out, "cae_block_pressure.log")).read()
    notes = [x for x in log.splitlines() if x.startswith("ldfcz: note: ")]
    if "warning" in p.stderr or len(notes) != 3:
        fail("CAE deck: console %r, notes %s" % (p.stderr, notes))
    # a warning that may change a result: on the console and in JOB.log (a *BOUNDARY range reaching the
    # rotations 4..6 of nodes that have none: it constrains nothing there)
    src = open(os.path.join(a.decks, "single", "c3d8_uniaxial.inp")).read()
    with open(os.path.join(out, "rotations.inp"), "w") as f:
        f.write(src.replace("TOP, 3, 3, 0.2", "TOP, 3, 3, 0.2\nBOTTOM, 4, 6", 1))
    p = run(a.exe, ["-q", "-o", out, os.path.join(out, "rotations.inp")], out, 0)
    log = open(os.path.join(out, "rotations.log")).read()
    if "warning" not in p.stderr or "ldfcz: warning: " not in log:
        fail("*BOUNDARY on dofs 4..6 without rotations: console %r; log without the warning" % p.stderr)
    # EXTRAPOLATION=PARABOLIC is carried out (the quadratic in time): no warning
    with open(os.path.join(out, "parabolic.inp"), "w") as f:
        f.write(src.replace("*STEP, NLGEOM=YES", "*STEP, NLGEOM=YES, EXTRAPOLATION=PARABOLIC", 1))
    p = run(a.exe, ["-q", "-o", out, os.path.join(out, "parabolic.inp")], out, 0)
    if "warning" in p.stderr or "ldfcz: warning: " in open(os.path.join(out, "parabolic.log")).read():
        fail("EXTRAPOLATION=PARABOLIC: warned %r" % p.stderr)
    # *RESTART, WRITE, NUMBER INTERVAL=n (restart data at n times of the step in Abaqus): accepted with a warning,
    # ldfcz's checkpoint written after every increment; with FREQUENCY= as well: refused at its line
    with open(os.path.join(out, "restart_interval.inp"), "w") as f:
        f.write(src.replace("*STATIC", "*RESTART, WRITE, NUMBER INTERVAL=2\n*STATIC", 1))
    p = run(a.exe, ["-q", "-o", out, os.path.join(out, "restart_interval.inp")], out, 0)
    if "NUMBER INTERVAL=2: ldfcz writes its checkpoint after every increment" not in p.stderr or \
            not os.path.exists(os.path.join(out, "restart_interval.rst")):
        fail("*RESTART, NUMBER INTERVAL: console %r, restart file %s" % (
            p.stderr, os.listdir(out)))
    expect_message(a.exe, out, "restart_both", src.replace(
        "*STATIC", "*RESTART, WRITE, FREQUENCY=1, NUMBER INTERVAL=2\n*STATIC", 1),
        "FREQUENCY and NUMBER INTERVAL are mutually exclusive")
    print("notes: 3 CAE boilerplate notes in JOB.log only; a boundary on missing rotations warned on the console "
          "and logged; EXTRAPOLATION=PARABOLIC without a warning; *RESTART NUMBER INTERVAL warned, checkpoint written")


def case_cutbacks(a):
    out = os.path.join(a.out, "cutbacks")
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(a.decks, "stability", "stab_peel_brittle.inp")
    run(a.exe, ["-q", "-t", "1", "-o", out, deck], out, 3)
    job = os.path.join(out, "stab_peel_brittle")
    log = open(job + ".log").read()
    doc = json.load(open(job + ".summary.json"))
    sta = [x for x in open(job + ".sta") if not x.startswith("#") and " cutback: " in x]
    own = re.findall(r"^  step \d+ increment \d+ attempt \d+: cutback: ", log, re.M)
    repeats = [int(n) for n in re.findall(r"^  cutback: .* repeated (\d+) more times? in step", log, re.M)]
    named = len(own) + sum(repeats)
    n = doc["counters"]["cutbacks"]
    print("cutbacks: %d in JOB.sta, %d in the summary, %d named in JOB.log (%d lines, %d summarised repeats)" % (
        len(sta), n, named, len(own), sum(repeats)))
    if not (named == n == len(sta)) or n < 2:
        fail("JOB.log names %d cutbacks, the summary counts %d, JOB.sta %d" % (named, n, len(sta)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--user-src", required=True)
    ap.add_argument("--reader", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    a.exe, a.out, a.decks = os.path.abspath(a.exe), os.path.abspath(a.out), os.path.abspath(a.decks)
    os.makedirs(a.out, exist_ok=True)
    base = open(os.path.join(a.decks, "single", "c3d8_uniaxial.inp")).read()
    case_suggestions(a, base)
    case_command_line(a)
    case_user_error(a)
    case_notes(a)
    case_cutbacks(a)
    print("PASS")


if __name__ == "__main__":
    main()
