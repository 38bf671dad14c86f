#!/usr/bin/env python3
"""Plot material-point curves written by the `material_point` driver (CSV), and run the PET cases.

  plot_material.py OUT.png A.csv [B.csv ...]      stress-strain plot of the given driver outputs
  plot_material.py --run BIN [--root DIR]         run every decks/material/*.txt with the driver BIN (from the
                                                  repository root DIR), then write reports/umat/:
                                                  pet_uniaxial.png, pet_shear.png, yield.csv, yield.md
  plot_material.py --history BIN [--root DIR]     run the segment histories decks/material/history/pet_*.txt
                                                  (relaxation, creep) and plot stress and strain against time:
                                                  reports/umat/<case>.png

Uses the standard library; matplotlib only for the PNG (skipped with a note if it is missing).
Columns used: 'strain' (ln lambda_1 or shear) and 'stress' (material-frame sigma_11 or sigma_12), SDV7 (gamma_p).
"""
import csv
import glob
import os
import subprocess
import sys
import time

from ldfcz_tools.cli import ToolError, executable


def read_curve(path):
    """Return (strain, stress, rows) from a driver CSV (ToolError naming the file when it is not one)."""
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    if not rows:
        raise ToolError("%s: no data rows (a material_point CSV expected)" % path)
    missing = [c for c in ("strain", "stress") if c not in rows[0]]
    if missing:
        raise ToolError("%s: no column %s (a material_point CSV has time, F.., S.., SDV.., strain, stress, J)"
                        % (path, ", ".join(missing)))
    try:
        strain = [float(r["strain"]) for r in rows]
        stress = [float(r["stress"]) for r in rows]
    except (TypeError, ValueError):
        raise ToolError("%s: a strain or stress value is not a number" % path) from None
    return strain, stress, rows


def plot(out_png, paths, title=None, xlabel="true strain (-)", ylabel="true stress (MPa)"):
    """Plot each CSV as one curve; return False when matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"plot_material: matplotlib not available, {out_png} not written")
        return False
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for p in paths:
        x, y, _ = read_curve(p)
        ax.plot(x, y, label=os.path.splitext(os.path.basename(p))[0])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_png, dpi=120)
    plt.close(fig)
    print(f"plot_material: wrote {out_png}")
    return True


def yield_point(strain, stress):
    """First local extremum of |stress| (the upper yield point) and the following minimum (softened)."""
    mag = [abs(s) for s in stress]
    i_peak = max(range(len(mag)), key=lambda i: mag[i] if abs(strain[i]) < 0.3 else -1.0)
    after = range(i_peak, len(mag))
    i_low = min(after, key=lambda i: mag[i] if abs(strain[i]) < 0.6 else float("inf"))
    return i_peak, i_low


def run_cases(binary, root):
    executable(binary, "material_point driver")
    decks = sorted(glob.glob(os.path.join(root, "decks", "material", "*.txt")))
    if not decks:
        raise ToolError("%s: no cases decks/material/*.txt under this root (--root: the repository)" % root)
    outdir = os.path.join(root, "reports", "umat")
    os.makedirs(outdir, exist_ok=True)
    results = []
    for deck in decks:
        t0 = time.perf_counter()
        subprocess.run([binary, deck], cwd=root, check=True)
        elapsed = time.perf_counter() - t0
        name = os.path.splitext(os.path.basename(deck))[0]
        results.append((name, os.path.join(outdir, name + ".csv"), elapsed))
    uni = [r[1] for r in results if "tension" in r[0] or "compression" in r[0]]
    plot(os.path.join(outdir, "pet_uniaxial.png"), uni,
         title="PET (Table 1): uniaxial tension and compression")
    shear = [r[1] for r in results if "shear" in r[0]]
    if shear:
        plot(os.path.join(outdir, "pet_shear.png"), shear, title="PET (Table 1): simple shear",
             xlabel="shear gamma (-)", ylabel="shear stress sigma_12 (MPa)")
    lines = []
    with open(os.path.join(outdir, "yield.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["case", "yield_strain", "yield_stress_MPa", "softened_strain", "softened_stress_MPa",
                    "stress_at_end_MPa", "gamma_p_end", "run_time_s"])
        for name, path, elapsed in results:
            x, y, rows = read_curve(path)
            ip, il = yield_point(x, y)
            row = [name, f"{x[ip]:.4f}", f"{y[ip]:.3f}", f"{x[il]:.4f}", f"{y[il]:.3f}", f"{y[-1]:.3f}",
                   f"{float(rows[-1]['SDV7']):.4f}", f"{elapsed:.3f}"]
            w.writerow(row)
            lines.append("| " + " | ".join(row) + " |")
    with open(os.path.join(outdir, "yield.md"), "w") as fh:
        fh.write("# PET material-point cases (driver `material_point`, Table 1 properties)\n\n")
        fh.write("Yield = first maximum of |stress| (|strain| < 0.3); softened = following minimum.\n")
        fh.write("Produced by `/usr/bin/python3 tools/plot_material.py --run <build>/bin/material_point`.\n\n")
        fh.write("| case | yield strain | yield stress (MPa) | softened strain | softened stress (MPa) | "
                 "stress at end (MPa) | gamma_p at end | run time (s) |\n")
        fh.write("|---|---|---|---|---|---|---|---|\n")
        fh.write("\n".join(lines) + "\n")
    print(f"plot_material: wrote {outdir}/yield.csv and yield.md")


def run_histories(binary, root):
    """Run the PET segment histories and plot strain and stress against time, one PNG per case."""
    executable(binary, "material_point driver")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_material: matplotlib not available, no plots")
        return
    outdir = os.path.join(root, "reports", "umat")
    os.makedirs(outdir, exist_ok=True)
    for case in sorted(glob.glob(os.path.join(root, "decks", "material", "history", "pet_*.txt"))):
        subprocess.run([binary, case], cwd=root, check=True)
        name = os.path.splitext(os.path.basename(case))[0]
        with open(os.path.join(outdir, name + ".csv"), newline="") as fh:
            rows = list(csv.DictReader(fh))
        t = [float(r["time"]) for r in rows]
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.4, 6.0), sharex=True)
        a1.plot(t, [float(r["strain"]) for r in rows])
        a1.set_ylabel("true strain ln(lambda_1) (-)")
        a2.plot(t, [float(r["stress"]) for r in rows])
        a2.set_ylabel("true stress sigma_11 (MPa)")
        a2.set_xlabel("time (s)")
        a1.set_title("PET (Table 1): " + name.replace("pet_", "").replace("_", " "))
        for a in (a1, a2):
            a.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, name + ".png"), dpi=120)
        plt.close(fig)
        print(f"plot_material: wrote {outdir}/{name}.png")


def main(argv):
    if len(argv) >= 2 and argv[0] == "--history":
        root = os.getcwd()
        if "--root" in argv:
            root = argv[argv.index("--root") + 1]
        run_histories(os.path.abspath(argv[1]), os.path.abspath(root))
        return 0
    if len(argv) >= 2 and argv[0] == "--run":
        root = os.getcwd()
        if "--root" in argv:
            root = argv[argv.index("--root") + 1]
        run_cases(os.path.abspath(argv[1]), os.path.abspath(root))
        return 0
    if len(argv) < 2:
        print(__doc__)
        return 1
    plot(argv[0], argv[1:])
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('plot_material'))
