#!/usr/bin/python3
"""Benchmark of the ldfcz host on a family of 3D peel meshes (not a test).

Each member is the 3D quarter peel scene of tools/peel_deck.py (PET coating C3D8 + Leonov UMAT on a steel
substrate C3D8 *ELASTIC, LDF cohesive layer U1 between them) with the paper's application discretisation (section 8:
l_e = 2 um, 10 elements over the width, 3 over the coating thickness) and a growing fine region. A few increments of
each are run with bin/ldfcz for every requested Newton variant; the figures come from JOB.summary.json.

Prints and writes (reports/bench/ by default): bench.csv (one row per run), bench.md (table, fitted exponents, the
estimate of the paper's application scene), bench.png (times per Newton iteration against DOFs; matplotlib through
/usr/bin/python3 when present).

  benchmarks/bench_host.py --exe build-perf/bin/ldfcz [--fine 0.02 0.05 0.1 0.2] [--modes full krylov] [--threads 2]

Time per Newton iteration = (assembly + factorization + solve) / iterations; the fitted exponent n of
t = c DOF^n is the paper's Fig. 11d quantity (paper: n = 1.34 for the time of an increment).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT, TOOLS

def peel_deck(args, fine, out, extra=()):
    """Write the deck of one family member with tools/peel_deck.py; returns its --info dictionary."""
    gen = os.path.join(TOOLS, 'peel_deck.py')
    if not os.path.exists(gen):
        sys.exit('bench_host.py: tools/peel_deck.py is needed to generate the peel meshes')
    cmd = [sys.executable, gen, '--3d', '--le', str(args.le), '--ny', str(args.ny), '--nz', str(args.nz),
           '--fine-length', str(fine), '--bonded', str(fine + args.margin), '--du', str(args.du),
           '--u-total', str(args.du * args.increments), '--field-frequency', '0', '--info', '-o', out] + list(extra)
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        # older generators: no field output switch
        cmd = [c for c in cmd if c not in ('--field-frequency',)]
        i = cmd.index('--info')
        cmd = cmd[:i - 1] + cmd[i:] if cmd[i - 1] == '0' else cmd
        res = subprocess.run(cmd, capture_output=True, text=True)
        if res.returncode != 0:
            sys.exit('bench_host.py: peel_deck.py failed: ' + res.stderr)
    return json.loads(res.stderr.strip().splitlines()[-1])


def fit_exponent(xs, ys):
    """Least-squares slope and factor of log y = log c + n log x."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float('nan'), float('nan')
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    n = sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx
    return n, math.exp(my - n * mx)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', default=os.path.join(ROOT, 'build-perf', 'bin', 'ldfcz'), help='bin/ldfcz')
    ap.add_argument('--fine', type=float, nargs='+', default=[0.02, 0.05, 0.1, 0.2],
                    help='fine-region lengths (mm) of the family')
    ap.add_argument('--modes', nargs='+', default=['full', 'krylov'], help='Newton variants to run')
    ap.add_argument('--le', type=float, default=0.002, help='element length (mm), paper: 0.002')
    ap.add_argument('--ny', type=int, default=10, help='elements over the width, paper: 10')
    ap.add_argument('--nz', type=int, default=3, help='elements over the coating, paper: 3')
    ap.add_argument('--margin', type=float, default=0.1, help='bonded length beyond the fine region (mm)')
    ap.add_argument('--du', type=float, default=0.0003, help='pull per increment (mm)')
    ap.add_argument('--increments', type=int, default=3, help='increments per run')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--out', default=os.path.join(ROOT, 'reports', 'bench'))
    ap.add_argument('--work', default=None, help='run directory (default OUT/work)')
    ap.add_argument('--reuse', action='store_true', help='parse the logs of earlier runs in the work directory '
                    'instead of running again (only regenerates the tables and the plot)')
    ap.add_argument('--paper-fine', type=float, default=1.0, help='fine length of the paper scene (mm)')
    ap.add_argument('--paper-pull', type=float, default=1.5,
                    help='pull (mm) to delaminate the paper length: 1.0 mm x 1.5 (coating stretch >= 50%%, section 7)')
    ap.add_argument('--paper-dofs', type=int, default=80000,
                    help='DOFs of the paper scene: n_DOF = 4 (1 + n_z) n_x n_y = 4*4*500*10 (section 7)')
    ap.add_argument('--iters-per-inc', type=float, default=4.0,
                    help='Newton iterations per increment of a peel run (measured: decks/peel 3D, about 4)')
    args = ap.parse_args()
    if not args.reuse:
        executable(args.exe, 'ldfcz program')

    work = args.work or os.path.join(args.out, 'work')
    os.makedirs(work, exist_ok=True)
    rows = []
    for fine in args.fine:
        deck = os.path.join(work, 'bench_%g.inp' % fine)
        info = peel_deck(args, fine, deck)
        for mode in args.modes:
            rdir = os.path.join(work, 'run_%g_%s' % (fine, mode))
            t0 = time.time()
            job = os.path.splitext(os.path.basename(deck))[0]
            if args.reuse and os.path.exists(outputs.summary_path(rdir, job)):
                res = subprocess.CompletedProcess([], 0, '', '')
            else:
                res = subprocess.run([args.exe, '--quiet', '--threads', str(args.threads), '--newton', mode,
                                      '--out', rdir, deck], capture_output=True, text=True)
            wall = time.time() - t0
            s = outputs.read_summary(rdir, job)
            if s is None or s['times']['wall_s'] is None:
                print('run failed (exit %d): %s' % (res.returncode, res.stderr), file=sys.stderr)
                continue
            c, t = s['counters'], s['times']
            inc, its, fac = c['increments'], c['iterations'], c['factorizations']
            asm, fct, sol, outp = t['element_loop_s'], t['factorization_s'], t['solve_s'], t['output_s']
            row = dict(fine_mm=fine, mode=mode, dofs=s['model']['dofs'], equations=s['model']['equations'],
                       elements=info['elements'], exit=s['exit_code'], increments=inc, iterations=its,
                       factorizations=fac, gmres_iterations=c['gmres_iterations'], wall_s=t['wall_s'],
                       cpu_s=t['cpu_s'], assembly_s=asm, factor_s=fct, solve_s=sol, output_s=outp,
                       setup_s=t['solver_setup_s'], peak_mb=(s['memory']['peak_kb'] or 0) / 1024.0, run_s=wall)
            it = max(its, 1)
            row['t_iter_s'] = (asm + fct + sol) / it
            row['asm_iter_s'] = asm / it
            row['fact_iter_s'] = fct / it
            row['solve_iter_s'] = sol / it
            row['cpu_iter_s'] = s['wall'][1] / it
            row['t_inc_s'] = (asm + fct + sol + outp) / max(inc, 1)
            rows.append(row)
            print('fine %-5g %-8s DOFs %6d  inc %d  iter %2d  fact %2d  t/iter %7.3f s (asm %7.3f fact %7.3f '
                  'solve %6.3f)  t/inc %7.2f s  output %.3f s' % (fine, mode, row['dofs'], inc, its, fac,
                                                                    row['t_iter_s'], row['asm_iter_s'],
                                                                    row['fact_iter_s'], row['solve_iter_s'],
                                                                    row['t_inc_s'], outp), flush=True)
    if not rows:
        sys.exit('bench_host.py: no successful run')
    os.makedirs(args.out, exist_ok=True)
    keys = list(rows[0].keys())
    with open(os.path.join(args.out, 'bench.csv'), 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)

    # fits per mode, and the paper scene estimate
    paper = peel_deck(args, args.paper_fine, os.path.join(work, 'paper_scene.inp'))
    ndof_mesh = paper['dofs']
    ndof_paper = args.paper_dofs
    lines = ['# ldfcz host benchmark (benchmarks/bench_host.py)', '',
             'Command: `%s`' % ' '.join(['benchmarks/bench_host.py'] + sys.argv[1:]), '',
             'Family: 3D quarter peel scene of tools/peel_deck.py, l_e = %g mm, n_y = %d, n_z = %d, fine region '
             '%s mm; %d increments of %g mm each, `--threads %d`; times are wall seconds from the run summary (JOB.summary.json).'
             % (args.le, args.ny, args.nz, ', '.join('%g' % v for v in args.fine), args.increments, args.du,
                args.threads), '',
             '| fine (mm) | Newton | DOFs | increments | iterations | factorizations | GMRES its | t/iteration (s) '
             '| assembly/it | factorization/it | solve/it | output (s) | peak MB |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        lines.append('| %g | %s | %d | %d | %d | %d | %d | %.3f | %.3f | %.3f | %.4f | %.3f | %.0f |' % (
            r['fine_mm'], r['mode'], r['dofs'], r['increments'], r['iterations'], r['factorizations'],
            r['gmres_iterations'], r['t_iter_s'], r['asm_iter_s'], r['fact_iter_s'], r['solve_iter_s'],
            r['output_s'], r['peak_mb']))
    lines += ['', '| Newton | exponent n of t/iteration = c DOF^n | assembly n | factorization n | CPU-time n | '
              't/iteration at the paper scene (%d DOFs) |' % ndof_paper, '|---|---|---|---|---|---|']
    fits = {}
    for mode in args.modes:
        rs = [r for r in rows if r['mode'] == mode]
        n, c = fit_exponent([r['dofs'] for r in rs], [r['t_iter_s'] for r in rs])
        na, _ = fit_exponent([r['dofs'] for r in rs], [r['asm_iter_s'] for r in rs])
        nf, cf = fit_exponent([r['dofs'] for r in rs], [r['fact_iter_s'] for r in rs])
        nc, _ = fit_exponent([r['dofs'] for r in rs], [r['cpu_iter_s'] for r in rs])
        fits[mode] = (n, c)
        lines.append('| %s | %.2f | %.2f | %.2f | %.2f | %.2f s |' % (mode, n, na, nf, nc, c * ndof_paper ** n))
    lines += ['', '## The paper\'s application scene (section 8)', '',
              'The paper counts n_DOF = 4 n_elem = 4 (1 + n_z) n_x n_y = %d DOFs (the estimate below uses it); '
              'our mesh of it, `tools/peel_deck.py --3d --le %g --ny %d --nz %d --fine-length %g --bonded %g`, has '
              '%d DOFs (%d elements: the steel is meshed through its thickness). Pull needed for %g mm of delamination: about %g mm (coating stretch >= 50%%, '
              'section 7). Newton iterations per increment: %g.' % (
                  ndof_paper, args.le, args.ny, args.nz, args.paper_fine, args.paper_fine + args.margin, ndof_mesh,
                  paper['elements'], args.paper_fine, args.paper_pull, args.iters_per_inc), '',
              '| Newton | pull per increment (um) | increments | estimated run time (h), %d DOFs | (h), %d DOFs |'
              % (ndof_paper, ndof_mesh), '|---|---|---|---|---|']
    for mode, (n, c) in fits.items():
        for du_um in (0.1, 0.5, 1.0, 1.8):
            ninc = args.paper_pull * 1000.0 / du_um
            lines.append('| %s | %g | %.0f | %.1f | %.1f |' % (
                mode, du_um, ninc, ninc * args.iters_per_inc * c * ndof_paper ** n / 3600.0,
                ninc * args.iters_per_inc * c * ndof_mesh ** n / 3600.0))
    with open(os.path.join(args.out, 'bench.md'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines[-(len(fits) * 4 + 6):]))
    print('wrote', os.path.join(args.out, 'bench.csv'), os.path.join(args.out, 'bench.md'))

    # plot with the system python's matplotlib when available
    plot = r'''
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6, 4.5))
for mode, mk in (("full", "o"), ("modified", "s"), ("krylov", "^"), ("auto", "v")):
    rs = [r for r in rows if r["mode"] == mode]
    if not rs:
        continue
    d = [float(r["dofs"]) for r in rs]
    ax.loglog(d, [float(r["t_iter_s"]) for r in rs], mk + "-", label=mode + ": total / iteration")
    ax.loglog(d, [max(float(r["fact_iter_s"]), 1e-4) for r in rs], mk + ":", label=mode + ": factorization / iteration")
    if mode == "full":
        ax.loglog(d, [float(r["asm_iter_s"]) for r in rs], mk + "--", label="element loop / iteration")
ax.set_xlabel("DOFs")
ax.set_ylabel("wall time per Newton iteration (s)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
'''
    if os.path.exists('/usr/bin/python3'):
        res = subprocess.run(['/usr/bin/python3', '-c', plot, os.path.join(args.out, 'bench.csv'),
                              os.path.join(args.out, 'bench.png')], capture_output=True, text=True)
        if res.returncode == 0:
            print('wrote', os.path.join(args.out, 'bench.png'))
        else:
            print('no plot (matplotlib):', res.stderr.strip().splitlines()[-1:], file=sys.stderr)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
