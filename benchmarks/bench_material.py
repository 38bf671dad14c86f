#!/usr/bin/env python3
"""Timing of the material and continuum-element routines (docs/performance.md, "Element loop").

  bench_material.py --bin BUILD/bin [--baseline OTHER/bin] [--repeat N] [--threads T] [--u-total U] [--md FILE]

1. Material point: runs every decks/material/*.txt with BIN/material_point (output to a scratch directory) and
   reports the wall time of each case (minimum over the repeats).
2. Element loop: generates the small 3D quarter peel deck `tools/peel_deck.py --3d --u-total U` (2388 equations,
   216 C3D8 Leonov + 320 C3D8 steel + 64 cohesive elements), runs `BIN/ldfcz -t T -q` on it and reads the run
   summary (JOB.summary.json): Newton iterations and the "assembly" wall time (element loop and sparse assembly), minimum
   over the repeats. OPENBLAS_NUM_THREADS=1 keeps MUMPS' BLAS threads from spinning on the shared cores.
With --baseline the same runs are made with the other build and the table gives the speed-up and the largest
difference of the results (material-point stress curves: max |sigma - sigma_baseline| in MPa; peel: max relative
difference of the reaction force history), so a change that alters the results shows up next to its timing.
Python standard library only.
"""
import argparse
import csv
import glob
import os
import subprocess
import sys
import tempfile
import time

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT


def run_material(binary, deck, out_csv):
    t0 = time.perf_counter()
    subprocess.run([binary, deck, "output=" + out_csv], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def read_column(path, name):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r[name]) for r in rows]


def run_peel(binary, deck, outdir, threads):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS=str(threads))
    t0 = time.perf_counter()
    subprocess.run([binary, "-t", str(threads), "-q", "-o", outdir, deck], check=True, env=env)
    wall = time.perf_counter() - t0
    doc = outputs.read_summary(outdir, os.path.splitext(os.path.basename(deck))[0])
    return wall, doc["counters"]["iterations"], doc["times"]["element_loop_s"]


def peel_force(outdir, deck):
    path = os.path.join(outdir, os.path.splitext(os.path.basename(deck))[0] + ".csv")
    return read_column(path, "LOAD.RF1")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True, help="directory with material_point and ldfcz")
    ap.add_argument("--baseline", help="directory with the baseline material_point and ldfcz")
    ap.add_argument("--repeat", type=int, default=3, help="runs per case, the minimum time is kept (default 3)")
    ap.add_argument("--threads", type=int, default=1, help="ldfcz --threads (default 1)")
    ap.add_argument("--u-total", default="0.002", help="pull of the peel deck (mm), default 0.002")
    ap.add_argument("--md", help="also write the tables to this markdown file")
    a = ap.parse_args()
    for d in [a.bin] + ([a.baseline] if a.baseline else []):
        for prog in ('material_point', 'ldfcz'):
            executable(os.path.join(d, prog), prog + ' program (--bin: the build\'s bin directory)')
    bins = [("new", os.path.abspath(a.bin))]
    if a.baseline:
        bins.append(("baseline", os.path.abspath(a.baseline)))
    lines = []
    with tempfile.TemporaryDirectory(prefix="bench_material_") as tmp:
        # ---- material point
        lines.append("| case | run time (s) |" + (" baseline (s) | speed-up | max abs stress difference (MPa) |"
                                                   if a.baseline else ""))
        lines.append("|---|---|" + ("---|---|---|" if a.baseline else ""))
        for deck in sorted(glob.glob(os.path.join(ROOT, "decks", "material", "*.txt"))):
            name = os.path.splitext(os.path.basename(deck))[0]
            times, curves = {}, {}
            for tag, d in bins:
                out = os.path.join(tmp, f"{name}_{tag}.csv")
                times[tag] = min(run_material(os.path.join(d, "material_point"), deck, out)
                                 for _ in range(a.repeat))
                curves[tag] = read_column(out, "stress")
            row = f"| {name} | {times['new']:.3f} |"
            if a.baseline:
                diff = max(abs(x - y) for x, y in zip(curves["new"], curves["baseline"]))
                row += f" {times['baseline']:.3f} | {times['baseline'] / times['new']:.1f} | {diff:.2e} |"
            lines.append(row)
        # ---- element loop on the small 3D peel deck
        deck = os.path.join(tmp, "peel3d.inp")
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "peel_deck.py"), "--3d", "--u-total",
                        a.u_total, "-o", deck], check=True)
        res = {}
        for tag, d in bins:
            out = os.path.join(tmp, "peel_" + tag)
            os.makedirs(out, exist_ok=True)
            runs = [run_peel(os.path.join(d, "ldfcz"), deck, out, a.threads) for _ in range(a.repeat)]
            best = min(runs, key=lambda r: r[2])
            res[tag] = (best, peel_force(out, deck))
        lines.append("")
        lines.append(f"Peel deck `tools/peel_deck.py --3d --u-total {a.u_total}`, `ldfcz -t {a.threads}` "
                     f"(minimum of {a.repeat} runs):")
        lines.append("")
        lines.append("| build | Newton iterations | assembly (s) | assembly per iteration (ms) | wall (s) |")
        lines.append("|---|---|---|---|---|")
        for tag, _ in bins:
            (wall, its, asm), _f = res[tag]
            lines.append(f"| {tag} | {its} | {asm:.3f} | {1000 * asm / its:.1f} | {wall:.2f} |")
        if a.baseline:
            fn, fb = res["new"][1], res["baseline"][1]
            scale = max(abs(x) for x in fb) or 1.0
            rel = max(abs(x - y) for x, y in zip(fn, fb)) / scale
            lines.append("")
            lines.append(f"Element loop speed-up (assembly per iteration): "
                         f"{(res['baseline'][0][2] / res['baseline'][0][1]) / (res['new'][0][2] / res['new'][0][1]):.1f}x;"
                         f" reaction force history max difference / max |RF1|: {rel:.1e}")
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if a.md:
        with open(a.md, "w") as f:
            f.write(text)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
