#!/usr/bin/env python3
"""Mutation fuzzer of the ldfcz deck reader (issue 6).

  python3 tools/fuzz_decks.py [--exe BIN] [--count N] [--time SECONDS] [--seed S] [--timeout T] [--report FILE]

Takes the valid decks of decks/single, decks/patch and decks/cae, applies 1-3 random edits to one of them (delete, duplicate or
swap lines; replace a number by NaN, Inf, 1e999, -0, a huge integer, text or nothing; drop or add commas; misspell or
inject keywords and parameters; truncate; inject control/non-ASCII bytes, very long lines, a trailing comma), and
runs bin/ldfcz on the result with a short timeout. A crash is a signal, an exit status other than 0, 2 or 3, or a
Fortran runtime error / backtrace in the output. Crashing inputs are saved as decks/bad/fuzz_regressions/fuzz_<hash>.inp
(first line `** EXPECT exit=2`, checked by tests/regression/check_bad_cases.py). Prints the number of inputs tried,
the exit statuses, timeouts (a mutated deck may be a valid long analysis: not a crash) and crashes; exit status 1
when something crashed. Bounded by --count and --time (whichever comes first).
"""
import argparse
import collections
import glob
import hashlib
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT
CRASH = re.compile(r"Fortran runtime error|Backtrace|Segmentation fault|SIGSEGV|SIGABRT|core dumped|"
                   r"Program received signal|Error termination")
NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?")
SPECIAL = ["NaN", "Inf", "-Inf", "1e999", "-1e999", "1e-320", "-0", "0", "-1", "99999999999999999999", "2147483648",
           "-2147483649", "1.2.3", "abc", "", " ", "1e", "0x10", "1,5", "'", "\"", "*", "1d308", "3e38"]
KEYWORDS = ["*NODE", "*ELEMENT, TYPE=C3D8", "*NSET, NSET=A, GENERATE", "*ELSET, ELSET=B", "*MATERIAL, NAME=M",
            "*ELASTIC", "*STEP", "*STATIC", "*END STEP", "*BOUNDARY", "*INCLUDE, INPUT=", "*USER ELEMENT, TYPE=U1",
            "*UEL PROPERTY", "*AMPLITUDE, NAME=A", "*CONTROLS, PARAMETERS=FIELD", "*DEPVAR", "*USER MATERIAL",
            "*SOLID SECTION", "*OUTPUT, FIELD", "*NODE PRINT", "*HEADING", "**", "*", "*,", "*STEP, INC=",
            "*INCLUDE, INPUT=/dev/zero", "*INCLUDE, INPUT=/", "*PART, NAME=P", "*END PART", "*ASSEMBLY",
            "*END ASSEMBLY", "*INSTANCE, NAME=I, PART=P", "*END INSTANCE", "*PARAMETER", "<x>", "*NGEN", "*NFILL",
            "*NCOPY, OLD SET=A, CHANGE NUMBER=5, SHIFT", "*ELGEN", "*ORIENTATION, NAME=O", "*EL PRINT", "*MONITOR",
            "*FIELD, VARIABLE=1", "*TRANSFORM, NSET=A", "*TRANSFORM, NSET=A, TYPE=C", "*TRANSFORM, NSET=A, TYPE=S",
            "*SYSTEM", "*NGEN, LINE=C", "*NGEN, LINE=P", "*NFILL, BIAS=0.5", "*NCOPY, OLD SET=A, CHANGE NUMBER=5, REFLECT=LINE",
            "*NCOPY, OLD SET=A, CHANGE NUMBER=5, REFLECT=MIRROR", "*NCOPY, OLD SET=A, CHANGE NUMBER=5, REFLECT=POINT",
            "*ELASTIC, TYPE=ORTHOTROPIC", "*ELASTIC, TYPE=ENGINEERING CONSTANTS", "*ELASTIC, TYPE=LAMINA",
            "*ELASTIC, TYPE=ANISOTROPIC", "*EXPANSION, TYPE=ORTHO", "*EXPANSION, TYPE=ANISO, ZERO=20.",
            "**LDFCZ BUILTIN, UMAT=LEONOV", "**LDFCZ BUILTIN, UEL=LDF", "*SECTION CONTROLS, NAME=S, HOURGLASS=ENH",
            "*HOURGLASS STIFFNESS", "*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5",
            "*OUTPUT, FIELD, TIME INTERVAL=0.5", "*SOLIDSECTION", "*STEP, AMPLITUDE=RAM", "*DEPVAR\n2\n1, J, \"V\""]


def mutate(lines, rng):
    lines = list(lines)
    op = rng.randrange(16)
    if not lines:
        return ["*NODE"]
    i = rng.randrange(len(lines))
    if op == 0:
        del lines[i]
    elif op == 1:
        lines.insert(i, lines[i])
    elif op == 2:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif op in (3, 4, 5):
        nums = list(NUM.finditer(lines[i]))
        if nums:
            m = rng.choice(nums)
            lines[i] = lines[i][:m.start()] + rng.choice(SPECIAL) + lines[i][m.end():]
    elif op == 6:
        lines[i] = lines[i].replace(",", "", 1) if rng.random() < 0.5 else lines[i].replace(",", ",,", 1)
    elif op == 7:
        lines[i] = lines[i] + ","
    elif op == 8:
        lines.insert(i, rng.choice(KEYWORDS))
    elif op == 9:
        if lines[i].startswith("*"):
            k = lines[i].split(",")
            if len(k) > 1 and rng.random() < 0.5:
                del k[rng.randrange(1, len(k))]
            else:
                k[0] = k[0][:-1] if rng.random() < 0.5 else k[0] + "X"
            lines[i] = ",".join(k)
    elif op == 10:
        cut = rng.randrange(len(lines))
        lines = lines[:cut] + ([lines[cut][:rng.randrange(len(lines[cut]) + 1)]] if rng.random() < 0.5 else [])
    elif op == 11:
        pos = rng.randrange(len(lines[i]) + 1)
        junk = "".join(chr(rng.choice([0, 1, 7, 9, 11, 12, 27, 127, 0xe9, 0xff, 0x2028])) for _ in range(rng.randint(1, 4)))
        lines[i] = lines[i][:pos] + junk + lines[i][pos:]
    elif op == 12:
        lines[i] = lines[i] + ", " + ", ".join(["1.0"] * rng.choice([3, 100, 5000]))
    elif op == 13:
        lines[i] = lines[i].lower() if rng.random() < 0.5 else lines[i].upper()
    elif op == 14:
        lines[i] = re.sub(r"=\s*[^,]*", "=" + rng.choice(["", "0", "-1", "YES", "NO", "X" * 300, "1e9"]), lines[i], 1)
    else:
        lines.insert(i, "")
    return lines


def run(exe, text, tmp, timeout):
    path = os.path.join(tmp, "fuzz.inp")
    with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write(text)
    out = os.path.join(tmp, "out")
    shutil.rmtree(out, ignore_errors=True)
    try:
        p = subprocess.run([exe, "--quiet", "--threads", "1", "--out", out, path], capture_output=True,
                           timeout=timeout, errors="replace")
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return "timeout", ""
    except OSError as x:       # the executable is being rebuilt: not an input's fault
        time.sleep(1.0)
        return "exec-error", str(x)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "..", "build-robust", "bin", "ldfcz"))
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--time", type=float, default=300.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=5.0)
    ap.add_argument("--save", default=os.path.join(ROOT, "decks", "bad", "fuzz_regressions"))
    ap.add_argument("--no-save", action="store_true")
    ap.add_argument("--report")
    a = ap.parse_args()
    executable(a.exe, 'ldfcz program')
    rng = random.Random(a.seed)
    seeds = sorted(glob.glob(os.path.join(ROOT, "decks", "single", "*.inp")) +
                   glob.glob(os.path.join(ROOT, "decks", "patch", "*.inp")) +
                   glob.glob(os.path.join(ROOT, "decks", "cae", "*.inp")))
    texts = {s: open(s).read().split("\n") for s in seeds}
    tmp = tempfile.mkdtemp(prefix="ldfcz_fuzz_")
    for inc in glob.glob(os.path.join(ROOT, "decks", "single", "*.inc")):
        shutil.copy(inc, tmp)   # decks that *INCLUDE a mesh find it next to the mutated deck
    stats = collections.Counter()
    crashes = []
    t0 = time.time()
    n = 0
    while n < a.count and time.time() - t0 < a.time:
        seed = rng.choice(seeds)
        lines = texts[seed]
        for _ in range(rng.randint(1, 3)):
            lines = mutate(lines, rng)
        text = "\n".join(lines)
        rc, out = run(a.exe, text, tmp, a.timeout)
        n += 1
        crash = rc not in (0, 2, 3, "timeout", "exec-error") and not isinstance(rc, str) or bool(CRASH.search(out))
        stats[rc] += 1
        if crash:
            h = hashlib.sha1(text.encode("utf-8", "surrogateescape")).hexdigest()[:10]
            first = [l for l in out.splitlines() if l.strip()][:3]
            crashes.append((h, os.path.basename(seed), rc, " / ".join(first)[:200]))
            if not a.no_save:
                os.makedirs(a.save, exist_ok=True)
                with open(os.path.join(a.save, "fuzz_%s.inp" % h), "w", encoding="utf-8",
                          errors="surrogateescape") as f:
                    # an *INCLUDE of the seed's mesh file is found from decks/bad/fuzz_regressions as well
                    saved = re.sub(r"(?i)INPUT=cohesive_mesh\.inc", "INPUT=../../single/cohesive_mesh.inc", text)
                    f.write("** EXPECT exit=2\n** from %s by tools/fuzz_decks.py --seed %d\n" % (
                        os.path.basename(seed), a.seed) + saved)
    shutil.rmtree(tmp, ignore_errors=True)
    wall = time.time() - t0
    lines = ["fuzz_decks: %d inputs tried in %.0f s (seed %d, %d seed decks, timeout %.0f s per run)" % (
                 n, wall, a.seed, len(seeds), a.timeout),
             "exit statuses: " + ", ".join("%s: %d" % (k, v) for k, v in sorted(stats.items(), key=str)),
             "crashes: %d" % len(crashes)]
    for h, seed, rc, msg in crashes:
        lines.append("  fuzz_%s.inp (from %s): exit %s: %s" % (h, seed, rc, msg))
    print("\n".join(lines))
    if a.report:
        with open(a.report, "w") as f:
            f.write("# Deck fuzzing (tools/fuzz_decks.py)\n\n```\n%s\n```\n" % "\n".join(lines))
    sys.exit(1 if crashes else 0)


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('fuzz_decks'))
