#!/usr/bin/env python3
"""Timing of the material and continuum-element routines (docs/performance.md, "Element loop").

  bench_material.py --bin BUILD/bin [--baseline OTHER/bin] [--repeat N] [--threads T] [--u-total U] [--md FILE]

1. Material point: runs every decks/material/*.txt with BIN/material_point (output to a scratch directory) and
   reports the CPU time of each case (user + system of the process; minimum over the repeats).
2. Element loop: generates the small 3D quarter peel deck `tools/peel_deck.py --3d --u-total U` (2388 equations,
   216 C3D8 Leonov + 320 C3D8 steel + 64 cohesive elements) and runs `BIN/ldfcz -t T -q` on it. Measured from
   outside, so that any build compares (e9cbdfd writes no JOB.summary.json): the process's CPU time and the Newton
   iterations of JOB.sta; where the build writes a run summary, also its element-loop ("assembly") wall time. With
   the same results the builds take the same iterations and factorizations, so the difference of the CPU times
   is the element loop's. OPENBLAS_NUM_THREADS=1 keeps MUMPS' BLAS threads from spinning on the shared cores.
The builds alternate within each repeat (new, baseline, new, ...), so that both meet the same load; the tables give
the minimum and the range of the repeats. With --baseline the table gives the speed-up and the largest difference
of the results (material-point stress curves: max |sigma - sigma_baseline| in MPa; peel: max relative difference
of the reaction force history), so a change that alters the results shows up next to its timing.
Python standard library only.
"""
import argparse
import csv
import glob
import os
import resource
import subprocess
import sys
import tempfile
import time

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT


def child_cpu():
    """User + system CPU seconds of the finished child processes so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_material(binary, deck, out_csv):
    c0 = child_cpu()
    subprocess.run([binary, deck, "output=" + out_csv], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    return child_cpu() - c0


def read_column(path, name):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r[name]) for r in rows]


def run_peel(binary, deck, outdir, threads):
    """(wall s, CPU s, Newton iterations, element-loop wall s or None) of one run."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS=str(threads))
    job = os.path.splitext(os.path.basename(deck))[0]
    for f in glob.glob(os.path.join(outdir, job + ".*")):
        os.remove(f)
    c0 = child_cpu()
    t0 = time.perf_counter()
    subprocess.run([binary, "-t", str(threads), "-q", "-o", outdir, deck], check=True, env=env,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    cpu = child_cpu() - c0
    its = outputs.sta_counts(os.path.join(outdir, job + ".sta"))["iterations"]
    loop = None
    if os.path.exists(outputs.summary_path(outdir, job)):
        loop = outputs.read_summary(outdir, job)["times"]["element_loop_s"]
    return wall, cpu, its, loop


def span(xs):
    """'min [min-max]' of a list of seconds."""
    return "%.3f [%.3f-%.3f]" % (min(xs), min(xs), max(xs))


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
        lines.append("| case | CPU (s) |" + (" baseline (s) | speed-up | max abs stress difference (MPa) |"
                                              if a.baseline else ""))
        lines.append("|---|---|" + ("---|---|---|" if a.baseline else ""))
        for deck in sorted(glob.glob(os.path.join(ROOT, "decks", "material", "*.txt"))):
            name = os.path.splitext(os.path.basename(deck))[0]
            times, curves = {tag: [] for tag, _ in bins}, {}
            for _ in range(a.repeat):
                for tag, d in bins:
                    out = os.path.join(tmp, f"{name}_{tag}.csv")
                    times[tag].append(run_material(os.path.join(d, "material_point"), deck, out))
                    curves[tag] = read_column(out, "stress")
            row = f"| {name} | {min(times['new']):.3f} |"
            if a.baseline:
                diff = max(abs(x - y) for x, y in zip(curves["new"], curves["baseline"]))
                row += (f" {min(times['baseline']):.3f} | {min(times['baseline']) / min(times['new']):.1f} |"
                        f" {diff:.2e} |")
            lines.append(row)
        # ---- element loop on the small 3D peel deck
        deck = os.path.join(tmp, "peel3d.inp")
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "peel_deck.py"), "--3d", "--u-total",
                        a.u_total, "-o", deck], check=True, stdout=subprocess.DEVNULL)
        runs = {tag: [] for tag, _ in bins}
        force = {}
        for _ in range(a.repeat):
            for tag, d in bins:
                out = os.path.join(tmp, "peel_" + tag)
                os.makedirs(out, exist_ok=True)
                runs[tag].append(run_peel(os.path.join(d, "ldfcz"), deck, out, a.threads))
                force[tag] = peel_force(out, deck)
        lines.append("")
        lines.append(f"Peel deck `tools/peel_deck.py --3d --u-total {a.u_total}`, `ldfcz -t {a.threads}`, "
                     f"{a.repeat} runs of each build alternating: minimum [range]")
        lines.append("")
        lines.append("| build | Newton iterations | process CPU (s) | CPU per iteration (ms) | wall (s) |"
                     " element loop, run summary (s) |")
        lines.append("|---|---|---|---|---|---|")
        for tag, _ in bins:
            rs = runs[tag]
            its = rs[0][2]
            loops = [r[3] for r in rs if r[3] is not None]
            lines.append(f"| {tag} | {its} | {span([r[1] for r in rs])} | "
                         f"{1000 * min(r[1] for r in rs) / its:.1f} | {span([r[0] for r in rs])} | "
                         f"{span(loops) if loops else 'not written'} |")
        if a.baseline:
            fn, fb = force["new"], force["baseline"]
            scale = max(abs(x) for x in fb) or 1.0
            rel = max(abs(x - y) for x, y in zip(fn, fb)) / scale
            cn, cb = min(r[1] for r in runs["new"]), min(r[1] for r in runs["baseline"])
            lines.append("")
            lines.append(f"Newton iterations {runs['new'][0][2]} and {runs['baseline'][0][2]}; process CPU "
                         f"{cb:.3f} -> {cn:.3f} s ({cb - cn:.3f} s less, {cb / cn:.2f}x); reaction force history "
                         f"max difference / max |RF1|: {rel:.1e}")
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if a.md:
        with open(a.md, "w") as f:
            f.write(text)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
