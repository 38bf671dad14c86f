#!/usr/bin/env python3
"""ldfcz's results of the published third-party decks against the Abaqus numbers their repositories hold.

  python3 benchmarks/third_party_results.py --work WORK --exe BIN [--tight] [--md FILE]

WORK is the --work folder of `benchmarks/abaqus_corpus.py third-party --manifest
benchmarks/abaqus_third_party_ran.json` (each deck runs in its repository's copy under WORK/NAME/src, writing its
outputs beside the deck, as an Abaqus job does; BIN the executable that run used, for the stamp). Compared where a repository holds Abaqus' own numbers:

  arruda_boyce            ArrudaBoyce/EngineeringStrainVsTrueStress.txt, an Abaqus/CAE X-Y export (engineering
                          strain, S22) of the single C3D8H element: against S22 of ldfcz's frames at the same
                          strains (U2 of the top face / 1 mm), where both have a point (the first and the last),
                          and elsewhere by linear interpolation between ldfcz's frames (which adds the
                          interpolation's own error: a bound, not the difference)
  hcp_crystal_plasticity  examples/one_element/abaqus.rpt (E11, S11 at element 1, point 1): its last row against
                          S11 of ldfcz's last frame (cell data, one element)

Each figure is printed with the digits the Abaqus file gives; a difference below those digits is "within the
printed digits". With --tight, arruda_boyce runs again (BIN, in WORK/arruda_boyce_tight) with the Newton tolerances
R_n = C_n = 1e-9 (`*CONTROLS, PARAMETERS=FIELD` after the `*STATIC` data line) and the shift of ldfcz's own values at
the shared strains is printed: the size of the difference the tolerance alone makes (Abaqus' run used its default
R_n = 0.005). numpy (Debian python3-numpy) reads the frames.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

import numpy as np

from abaqus_corpus import stamp  # the reports' stamp: commit, program, command, date, machine


def vtu_array(path, name):
    """A data array of an ldfcz VTU frame, one row per point or cell."""
    text = open(path).read()
    m = re.search(r'(<DataArray[^>]*Name="%s"[^>]*>)([^<]*)<' % re.escape(name), text)
    if m is None:
        return None
    nc = re.search(r'NumberOfComponents="(\d+)"', m.group(1))
    return np.array(m.group(2).split(), float).reshape(-1, int(nc.group(1)) if nc else 1)


def frames(folder, job):
    return sorted(glob.glob(os.path.join(folder, job + "_[0-9][0-9][0-9][0-9].vtu")))


def digits(text):
    """Relative resolution of a number as printed (one unit of its last digit)."""
    mant = re.split(r"[eE]", text)[0].lstrip("+-")
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return 10.0 ** (-decimals) / max(abs(float(mant)), 1e-300)


def stretch_stress(folder):
    """(engineering strain, S22) of each frame of the single-element run in folder."""
    got = []
    for f in frames(folder, "SingleElemExt"):
        u, s = vtu_array(f, "U"), vtu_array(f, "S")
        got.append((u[:, 1].max() / 1.0e-3, s[:, 1].mean()))
    return np.array(got)


def tight_run(work, exe, folder):
    """The arruda_boyce deck again with R_n = C_n = 1e-9, in its own copy; its frames' (strain, S22)."""
    tight = os.path.join(work, "arruda_boyce_tight")
    shutil.rmtree(tight, ignore_errors=True)
    shutil.copytree(folder, tight, ignore=shutil.ignore_patterns("*.vtu", "*.pvd", "*.odb"))
    deck = os.path.join(tight, "SingleElemExt.inp")
    text = open(deck).read()
    new = re.sub(r"(?im)^(\*Static\s*\n[^\n]*\n)", r"\1*Controls, parameters=field\n1e-9, 1e-9\n", text, count=1)
    if new == text:
        raise OSError("no *Static data line in " + deck)
    open(deck, "w").write(new)
    p = subprocess.run([os.path.abspath(exe), "-q", "--user", "ArrudaBoyce_f77.for", "SingleElemExt.inp"], cwd=tight,
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise OSError("the run with tight tolerances failed (exit %d)" % p.returncode)
    return stretch_stress(tight)


def arruda_boyce(work, exe=None):
    folder = os.path.join(work, "arruda_boyce", "src", "ArrudaBoyce")
    table = os.path.join(folder, "EngineeringStrainVsTrueStress.txt")
    rows = []
    for line in open(table):
        p = line.split()
        if len(p) == 2:
            try:
                rows.append((float(p[0]), float(p[1]), p[1]))
            except ValueError:
                pass
    got = stretch_stress(folder)
    tight = tight_run(work, exe, folder) if exe else None
    if len(got) < 2:
        return ["arruda_boyce: no ldfcz frames in " + folder]
    out = ["arruda_boyce (C3D8H read as C3D8, its UMAT, NLGEOM; %d Abaqus points, %d ldfcz frames):" % (
        len(rows) - 1, len(got))]
    worst = 0.0
    for e, s_ab, text in rows[1:]:
        hit = np.flatnonzero(np.abs(got[:, 0] - e) <= 1e-9 * max(1.0, e))
        if hit.size:
            s = got[hit[0], 1]
            rel = abs(s - s_ab) / abs(s_ab)
            out.append("  strain %-7g Abaqus S22 %-12s ldfcz %.9g: relative difference %.1e (%s the printed digits, "
                       "%.0e)" % (e, text, s, rel, "within" if rel <= digits(text) else "beyond", digits(text)))
            if tight is not None:
                k = np.flatnonzero(np.abs(tight[:, 0] - e) <= 1e-9 * max(1.0, e))
                if k.size:
                    out.append("    with R_n = C_n = 1e-9: ldfcz %.9g, moved by %.1e; difference to Abaqus %.1e" % (
                        tight[k[0], 1], abs(tight[k[0], 1] - s) / abs(s), abs(tight[k[0], 1] - s_ab) / abs(s_ab)))
        else:
            worst = max(worst, abs(np.interp(e, got[:, 0], got[:, 1]) - s_ab) / abs(s_ab))
    out.append("  the other points, against ldfcz interpolated linearly between its frames: at most %.1e "
               "(interpolation included)" % worst)
    return out


def hcp_crystal_plasticity(work):
    folder = os.path.join(work, "hcp_crystal_plasticity", "src", "examples", "one_element")
    rows = [line.split() for line in open(os.path.join(folder, "abaqus.rpt")) if re.match(r"\s*[-0-9.]", line)]
    rows = [r for r in rows if len(r) == 3]
    last = frames(folder, "HCP-UMAT")
    if not rows or not last:
        return ["hcp_crystal_plasticity: no Abaqus table or no ldfcz frames in " + folder]
    e11, s11 = rows[-1][1], rows[-1][2]
    s = vtu_array(last[-1], "S")[0, 0]
    rel = abs(s - float(s11)) / abs(float(s11))
    return ["hcp_crystal_plasticity (C3D8 crystal plasticity UMAT): E11 = %s, Abaqus S11 %s, ldfcz %.9g: relative "
            "difference %.1e (%s the printed digits, %.0e)" % (e11, s11, s, rel,
                                                                "within" if rel <= digits(s11) else "beyond",
                                                                digits(s11))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", required=True, help="the --work folder of abaqus_corpus.py third-party")
    ap.add_argument("--exe", required=True, help="the ldfcz executable the third-party run used (for the stamp)")
    ap.add_argument("--tight", action="store_true",
                    help="also rerun arruda_boyce with R_n = C_n = 1e-9 (the Newton tolerance's own effect)")
    ap.add_argument("--md", help="also write the lines to this file, stamped")
    a = ap.parse_args()
    lines = []
    missing = 0
    for check in (arruda_boyce, hcp_crystal_plasticity):
        try:
            got = check(a.work, a.exe) if (check is arruda_boyce and a.tight) else check(a.work)
        except OSError as e:
            got = ["%s: not found (%s)" % (check.__name__, e)]
        missing += any(": no " in x or ": not found" in x for x in got)
        lines += got
    print("\n".join(lines))
    if a.md:
        head = ["# ldfcz's results of published third-party decks against their Abaqus numbers", ""] + \
            stamp(sys.argv, a.exe) + ["", "The work folder came from `python3 benchmarks/abaqus_corpus.py third-party "
                                      "--manifest benchmarks/abaqus_third_party_ran.json --sources /work/.mirror "
                                      "--exe %s --work %s` at the same commit." % (a.exe, a.work), ""]
        with open(a.md, "w") as f:
            f.write("\n".join(head + ["    " + x for x in lines]) + "\n")
    return 1 if missing else 0


if __name__ == "__main__":
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
