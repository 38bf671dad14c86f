#!/usr/bin/env python3
"""Step-size study of the Leonov UMAT: uniaxial tension of PET at 1e-3 /s to true strain 1.0, driven by
`material_point` with strain increments 1e-2 ... 1e-4, against a converged reference: Richardson extrapolation
(first order, the order of backward Euler) of runs with strain increments 5e-5 and 2.5e-5, sigma_ref = 2 s(h/2) - s(h).

  /usr/bin/python3 tools/umat_step_study.py BIN [--root DIR]

Error of a run = max over the true strains 0.01, 0.02, ..., 1.00 of |sigma - sigma_ref| (MPa); observed order
p = ln(e_i/e_j) / ln(h_i/h_j) between successive increments. Also reported: the error of the 2.5e-5 run itself
against the extrapolated reference (what a plain fine-step reference would have carried).
Writes reports/umat/step_study.csv, step_study.md, step_study.png (PNG only with matplotlib).
"""
import csv
import math
import os
import subprocess
import sys
import time

from ldfcz_tools.cli import executable

INCREMENTS = [1.0e-2, 5.0e-3, 2.0e-3, 1.0e-3, 5.0e-4, 2.0e-4, 1.0e-4]
H_REF = 2.5e-5
RATE = 1.0e-3
STRAIN_END = 1.0
POINTS = 100


def run(binary, root, h, outdir):
    steps = int(round(STRAIN_END / h))
    out = os.path.join(outdir, f"step_{steps}.csv")
    every = steps // POINTS
    t0 = time.perf_counter()
    subprocess.run([binary, "mode=uniaxial", f"rate={RATE}", f"strain_end={STRAIN_END}", f"steps={steps}",
                    f"output_every={every}", f"output={out}"], cwd=root, check=True, stdout=subprocess.DEVNULL)
    elapsed = time.perf_counter() - t0
    with open(out, newline="") as fh:
        rows = list(csv.DictReader(fh))
    curve = {round(float(r["strain"]), 6): float(r["stress"]) for r in rows}
    os.remove(out)
    return curve, elapsed


def main(argv):
    if not argv:
        print(__doc__)
        return 1
    binary = executable(os.path.abspath(argv[0]), 'material_point driver')
    root = os.path.abspath(argv[argv.index("--root") + 1]) if "--root" in argv else os.getcwd()
    outdir = os.path.join(root, "reports", "umat")
    os.makedirs(outdir, exist_ok=True)
    fine2, t_ref2 = run(binary, root, 2.0 * H_REF, outdir)
    fine1, t_ref = run(binary, root, H_REF, outdir)
    keys = [round(k / POINTS, 6) for k in range(1, POINTS + 1)]
    ref = {k: 2.0 * fine1[k] - fine2[k] for k in keys}
    e_ref = max(abs(fine1[k] - ref[k]) for k in keys)
    smax = max(abs(ref[k]) for k in keys)
    table = []
    for h in INCREMENTS:
        curve, elapsed = run(binary, root, h, outdir)
        err = max(abs(curve[k] - ref[k]) for k in keys)
        table.append([h, err, err / smax, elapsed])
    for i, row in enumerate(table):
        if i == 0:
            row.append(float("nan"))
        else:
            h0, e0 = table[i - 1][0], table[i - 1][1]
            row.append(math.log(e0 / row[1]) / math.log(h0 / row[0]) if row[1] > 0 else float("nan"))
    with open(os.path.join(outdir, "step_study.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["strain_increment", "max_abs_error_MPa", "relative_error", "run_time_s", "observed_order"])
        for row in table:
            w.writerow([f"{row[0]:.1e}", f"{row[1]:.4e}", f"{row[2]:.4e}", f"{row[3]:.3f}", f"{row[4]:.3f}"])
        w.writerow([f"{H_REF:.1e}", "reference", f"{e_ref:.3e} (error of the h = 2.5e-5 run)", f"{t_ref:.3f}", ""])
    with open(os.path.join(outdir, "step_study.md"), "w") as fh:
        fh.write("# Step-size study: PET uniaxial tension, 1e-3 /s, to true strain 1.0\n\n")
        fh.write(f"Reference: Richardson extrapolation 2 s(h) - s(2h) of runs with strain increments {H_REF:.1e} "
                 f"({int(round(STRAIN_END / H_REF))} increments, {t_ref:.2f} s) and {2 * H_REF:.1e} ({t_ref2:.2f} s); "
                 f"the {H_REF:.1e} run differs from it by {e_ref:.2e} MPa.\n")
        fh.write(f"Error: max over strains 0.01..1.00 of |sigma - sigma_ref|; peak stress {smax:.1f} MPa.\n")
        fh.write("Produced by `/usr/bin/python3 tools/umat_step_study.py <build>/bin/material_point`.\n\n")
        fh.write("| strain increment | max error (MPa) | relative | run time (s) | observed order |\n")
        fh.write("|---|---|---|---|---|\n")
        for row in table:
            fh.write(f"| {row[0]:.1e} | {row[1]:.3e} | {row[2]:.2e} | {row[3]:.3f} | {row[4]:.2f} |\n")
    print(f"umat_step_study: wrote {outdir}/step_study.csv and step_study.md")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("umat_step_study: matplotlib not available, step_study.png not written")
        return 0
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.2))
    a1.loglog([r[0] for r in table], [r[1] for r in table], "o-", label="max |error|")
    h = [r[0] for r in table]
    a1.loglog(h, [table[0][1] * (x / h[0]) for x in h], "k--", label="order 1")
    a1.set_xlabel("strain increment")
    a1.set_ylabel("max |sigma - sigma_ref| (MPa)")
    a1.grid(True, which="both", alpha=0.3)
    a1.legend()
    a2.loglog([r[3] for r in table], [r[1] for r in table], "s-")
    a2.set_xlabel("run time (s)")
    a2.set_ylabel("max |sigma - sigma_ref| (MPa)")
    a2.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "step_study.png"), dpi=120)
    plt.close(fig)
    print(f"umat_step_study: wrote {outdir}/step_study.png")
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('umat_step_study'))
