#!/usr/bin/env python3
"""Which routine a *USER MATERIAL / *USER ELEMENT runs (docs/host.md, "User routines: the user's or a clear stop").

  check_routines.py --exe BIN --out DIR --umat-deck decks/single/c3d8_umat_uniaxial.inp
                    --uel-deck decks/single/cohesive_block.inp --user tests/regression/user_umat_neohooke.f90
                    --user-deck decks/single/quadratic_rotation.inp

  stop      the project's Leonov and cohesive decks without their '**LDFCZ BUILTIN' line and without --user: exit 2
            and one message naming the file and line of the *MATERIAL (*USER ELEMENT), the material (type), and
            both fixes (--user FILE, and the declaration with the one built-in routine's name)
  builtin   the decks as committed (with the declaration): they run, and JOB.log says for the material (type)
            which routine runs and from which file (the built-in LEONOV from umat/umat.f, LDF from uel/uel.f)
  user      a user UMAT (--user) on a deck that also declares the built-in one: the user's runs (JOB.log names its
            file and that the declaration does not apply) and JOB.csv is the bit-identical twin of the run of the
            deck without the declaration
"""
import argparse
import filecmp
import os
import re
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def without_declaration(src, dst, what):
    """A copy of deck src (and the files it includes) without the '**LDFCZ BUILTIN, what=' lines; returns the
    line number of each keyword line named in the copy (for the expected messages)."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    with open(src) as f:
        lines = f.read().split("\n")
    out = []
    for line in lines:
        if line.upper().startswith("**LDFCZ BUILTIN, %s=" % what):
            continue
        m = re.match(r"\*INCLUDE, INPUT=(\S+)", line, re.I)
        if m:
            inc = os.path.join(os.path.dirname(src), m.group(1))
            without_declaration(inc, os.path.join(os.path.dirname(dst), m.group(1)), what)
        out.append(line)
    with open(dst, "w") as f:
        f.write("\n".join(out))


def find_line(path, prefix):
    """(file, line) of the first line of path or its includes starting with prefix (case-insensitive)."""
    with open(path) as f:
        lines = f.read().split("\n")
    for k, line in enumerate(lines):
        if line.upper().startswith(prefix.upper()):
            return os.path.basename(path), k + 1
        m = re.match(r"\*INCLUDE, INPUT=(\S+)", line, re.I)
        if m:
            hit = find_line(os.path.join(os.path.dirname(path), m.group(1)), prefix)
            if hit:
                return hit
    return None


def run(exe, deck, out, user=None):
    cmd = [exe, "-q", "--threads", "1", "--out", out] + (["--user", user] if user else []) + [deck]
    return subprocess.run(cmd, capture_output=True, text=True)


def case_stop(a):
    for deck, what, kw, who, fix in ((a.umat_deck, "UMAT", "*MATERIAL, NAME=", "material PET", "UMAT=LEONOV"),
                                     (a.uel_deck, "UEL", "*USER ELEMENT", "user element type U1", "UEL=LDF")):
        copy = os.path.join(a.out, "stop_" + what.lower(), os.path.basename(deck))
        without_declaration(deck, copy, what)
        p = run(a.exe, copy, os.path.join(a.out, "stop_" + what.lower(), "run"))
        fname, line = find_line(copy, kw)
        print("%s without declaration, no --user: exit %d: %s" % (what, p.returncode, p.stderr.strip()))
        if p.returncode != 2:
            fail("exit %d, expected 2" % p.returncode)
        for needle in ("%s:%d:" % (fname, line), who, "--user FILE", "**LDFCZ BUILTIN, " + fix):
            if needle not in p.stderr:
                fail("the message does not name '%s'" % needle)


def case_builtin(a):
    for deck, note in ((a.umat_deck, r"material PET \(\S+:\d+\): \*USER MATERIAL runs the built-in UMAT LEONOV "
                                     r"\(umat/umat.f\), declared at \S+:\d+"),
                       (a.uel_deck, r"user element type U1 \(\S+:\d+\): \*USER ELEMENT runs the built-in UEL LDF "
                                    r"\(uel/uel.f\), declared at \S+:\d+")):
        out = os.path.join(a.out, "builtin_" + os.path.splitext(os.path.basename(deck))[0])
        p = run(a.exe, deck, out)
        if p.returncode != 0:
            fail("%s: exit %d: %s" % (deck, p.returncode, p.stderr))
        job = os.path.splitext(os.path.basename(deck))[0]
        with open(os.path.join(out, job + ".log")) as f:
            head = f.read().split("\n")[:4]
        print("\n".join(head))
        if not any(re.search(note, line) for line in head):
            fail("JOB.log's first lines do not say '%s'" % note)


def case_user(a):
    job = os.path.splitext(os.path.basename(a.user_deck))[0]
    with open(a.user_deck) as f:
        text = f.read()
    k = text.upper().index("*USER MATERIAL")
    declared = os.path.join(a.out, "user_declared", job + ".inp")
    os.makedirs(os.path.dirname(declared), exist_ok=True)
    with open(declared, "w") as f:
        f.write(text[:k] + "**LDFCZ BUILTIN, UMAT=LEONOV\n" + text[k:])
    p1 = run(a.exe, a.user_deck, os.path.join(a.out, "user_plain"), a.user)
    p2 = run(a.exe, declared, os.path.join(a.out, "user_declared", "run"), a.user)
    if p1.returncode != 0 or p2.returncode != 0:
        fail("exit %d / %d: %s %s" % (p1.returncode, p2.returncode, p1.stderr, p2.stderr))
    with open(os.path.join(a.out, "user_declared", "run", job + ".log")) as f:
        head = "\n".join(f.read().split("\n")[:6])
    print(head)
    want = "runs the UMAT of %s (--user); its **LDFCZ BUILTIN, UMAT=LEONOV" % a.user
    if want not in head or "does not apply: the user's routine runs" not in head:
        fail("JOB.log does not say that the user's UMAT runs and the declaration does not apply")
    same = filecmp.cmp(os.path.join(a.out, "user_plain", job + ".csv"),
                       os.path.join(a.out, "user_declared", "run", job + ".csv"), shallow=False)
    print("JOB.csv with and without the declaration identical: %s" % same)
    if not same:
        fail("the declaration changed the results of the user's UMAT")


def main():
    ap = argparse.ArgumentParser()
    for name in ("--exe", "--out", "--umat-deck", "--uel-deck", "--user", "--user-deck"):
        ap.add_argument(name, required=True)
    ap.add_argument("--case", required=True, choices=["stop", "builtin", "user"])
    a = ap.parse_args()
    for k in ("exe", "out", "umat_deck", "uel_deck", "user", "user_deck"):
        setattr(a, k, os.path.abspath(getattr(a, k)))
    globals()["case_" + a.case](a)
    print("PASS")


if __name__ == "__main__":
    main()
