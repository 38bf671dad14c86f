#!/usr/bin/env python3
"""Distributed against threaded on this machine: the 3D quarter peel scene of tools/peel_deck.py (the family of
bench_host.py: PET coating C3D8 + Leonov UMAT on a C3D8 steel substrate, LDF cohesive layer, l_e = 2 um, 10
elements over the width, 3 over the coating) and, with --application, the paper's application mesh (section 8:
rigid substrate, fine region over 1.05 mm; docs/performance.md), run for a few increments by the LDFCZ_MPI build
of ldfcz as

  1 rank x T threads          (mpirun -np 1 ldfcz --threads T: the serial code path, one MUMPS process)
  R ranks x 1 thread, central (right-hand side and solution through MUMPS' host, LDFCZ_MUMPS_CENTRAL_RHS=1: the
                               path before the distributed one, for the communication before/after)
  R ranks x 1 thread          (elements partitioned with the default weights, MUMPS distributed, distributed
                               right-hand side and solution)
  R ranks x 1 thread, measured weights  (--element-weights from the measured costs of the run above)
  R ranks, ORDERING           (--orderings: MUMPS' own PORD/AMF/... instead of the host's METIS; Debian's
                               MUMPS 5.5 links neither PT-Scotch nor ParMETIS, so no parallel ordering)

and, with --serial-exe, the default (sequential MUMPS) build with T threads. Prints per configuration the Newton
iterations and the wall time per iteration split into element loop (assembly), communication of the host
(reductions of forces and flags, gathers of solutions: rank 0's), factorization and solve (MUMPS' own
communication is inside those two), the element loop's balance over the processes (slowest / mean), rank 0's
CPU time per iteration, the CPU time of all processes per iteration (getrusage of the children), the largest
peak memory of a process and the load average before the run; writes the table and a fitted cost model (time and
memory per process against ranks and DOFs, with its prediction for the full-width specimen) to OUT/bench_mpi.md.

  cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DLDFCZ_MPI=ON && cmake --build build-mpi -j2 --target ldfcz
  benchmarks/bench_mpi.py --fine 0.02 0.05 --increments 3 --yield-idle --application --orderings pord amf

With --scaling R1 R2 ... instead (strong scaling, for a machine with more cores): 1 rank x 1 thread and R ranks x
1 thread for every R listed, plus --hybrid RxT runs (R ranks x T threads), on the same scenes; besides the table,
OUT/bench_mpi_scaling.md gives per scene the speedup and parallel efficiency of the element loop, the
factorization and the whole iteration, and compares every run with the prediction of the cost model fitted to
the 1- and 2-rank runs alone (what a 2-core machine can measure; the rest of an iteration's wall time, setup and
output included, is taken as not divided):

  benchmarks/bench_mpi.py --scaling 2 4 8 16 --hybrid 1x16 4x4 --fine 0.05 0.2 --application --out reports/bench/scaling

--pieces default 1 runs every R twice, with ldfcz's interleaved partition and with one part per process
(--partition-pieces 1); the tables then also give the element loop's balance loop by loop (the summary's "slowest
process of each loop summed", against the mean):

  benchmarks/bench_mpi.py --scaling 16 8 4 2 --pieces default 1 --fine --application --out reports/bench/scaling-interleaved

--full-width meshes the application scene over the specimen's full width (the cost model's prediction target);
`--fine` with no value leaves the peel members out:

  benchmarks/bench_mpi.py --scaling 2 8 16 --fine --application --full-width --out reports/bench/scaling

With --refit MD [MD ...] instead: nothing is run; the tables of earlier runs (their bench_mpi.md files, the rows of
1 rank x 1 thread and R ranks x 1 thread) are read back and the cost model and the scaling report are fitted to
them all, e.g. the application mesh and its full width measured in separate commands, so that the prediction for
the full-width specimen on a cluster uses both sizes (OUT/bench_mpi_refit.md):

  benchmarks/bench_mpi.py --refit reports/bench/scaling-memory/bench_mpi.md \
      reports/bench/scaling-memory/full_width_bench_mpi.md --cluster-ranks 1 2 8 16 32 128 --out DIR

With --ordering-study instead: the first increment of the peel member --fine (last value) and of the application
mesh, on 1 process with every ordering (the host's METIS, MUMPS' PORD, AMF, AMD, QAMD) and on R processes with
METIS and PORD: entries in the factors (deterministic), factorizations and their wall and rank-0 CPU seconds;
table to OUT/bench_mpi_orderings.md.
"""
import argparse
import json
import math
import os
import re
import resource
import time
import subprocess
import sys

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT, TOOLS

def deck(args, fine, out, application=False):
    cmd = [sys.executable, os.path.join(TOOLS, 'peel_deck.py'), '--3d', '--le', str(args.le), '--ny', str(args.ny),
           '--nz', str(args.nz), '--fine-length', str(fine), '--bonded', str(fine + args.margin), '--du',
           str(args.du), '--u-total', str(args.du * args.increments), '--field-frequency', '0', '--info', '-o', out]
    if application:
        # tools/peel_study.py application (paper section 8): rigid substrate, fine region 1.05 mm, bonded 1.2 mm,
        # up to 1 um per increment, PET accuracy bound 1.0
        cmd = [sys.executable, os.path.join(TOOLS, 'peel_deck.py'), '--3d', '--rigid-substrate', '--le', '0.002',
               '--ny', '10', '--nz', '3', '--fine-length', '1.05', '--bonded', '1.2', '--du', '0.001',
               '--dgamma-max', '1.0', '--u-total', str(0.001 * args.increments), '--field-frequency', '0',
               '--info', '-o', out] + (['--full-width'] if args.full_width else [])
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit('bench_mpi.py: peel_deck.py failed: ' + res.stderr)
    return json.loads(res.stderr.strip().splitlines()[-1])   # the mesh summary (--info)


def parse(outdir, job):
    """The figures of a run's summary (JOB.summary.json) in the groups this benchmark tabulates: counts (increments,
    attempts, cutbacks, iterations, factorizations), dofs (DOFs, equations), wall (wall, CPU), split (element loop,
    factorization, solve, output), setup, entries, memory (kB); for a distributed run comm (processes, host
    communication, largest process memory in kB), balance (max, mean, max/mean of the element loop), slowest (the
    slowest process of each loop summed, over the mean); weights (the measured partition weights)."""
    doc = outputs.read_summary(outdir, job)
    c, t, m, mpi = doc['counters'], doc['times'], doc['model'], doc['mpi']
    return {'counts': [c['increments'], c['attempts'], c['cutbacks'], c['iterations'], c['factorizations']],
            'dofs': [m['dofs'], m['equations']], 'wall': [t['wall_s'], t['cpu_s']],
            'split': [t['element_loop_s'], t['factorization_s'], t['solve_s'], t['output_s']],
            'setup': [t['solver_setup_s']], 'entries': [doc['factors']['entries']] if doc['factors']['entries'] else None,
            'memory': [doc['memory']['peak_kb']],
            'comm': [mpi['processes'], mpi['communication_s'], doc['memory']['peak_kb_largest_process']] if mpi else None,
            'balance': [mpi['element_loop_max_s'], mpi['element_loop_mean_s'], mpi['element_loop_max_over_mean']]
            if mpi else None,
            'slowest': [mpi['element_loop_slowest_summed_s'], mpi['element_loop_slowest_over_mean']] if mpi else None,
            'weights': [e['weight'] for e in doc['element_cost'].values()]}


def fit_power(xs, ys):
    """y = a x^b by least squares on logarithms (two or more points)."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-12)) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((x - mx) ** 2 for x in lx)
    b = sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / sxx if sxx > 0 else 1.0
    return math.exp(my - b * mx), b


def lstsq3(rows, ys):
    """Least squares for y = c0 r0 + c1 r1 + c2 r2 (normal equations, Gauss elimination)."""
    a = [[sum(r[i] * r[j] for r in rows) for j in range(3)] for i in range(3)]
    v = [sum(r[i] * y for r, y in zip(rows, ys)) for i in range(3)]
    for k in range(3):
        p = max(range(k, 3), key=lambda i: abs(a[i][k]))
        a[k], a[p], v[k], v[p] = a[p], a[k], v[p], v[k]
        if abs(a[k][k]) < 1e-30:
            return None
        for i in range(k + 1, 3):
            f = a[i][k] / a[k][k]
            a[i] = [x - f * y for x, y in zip(a[i], a[k])]
            v[i] -= f * v[k]
    c = [0.0] * 3
    for k in (2, 1, 0):
        c[k] = (v[k] - sum(a[k][j] * c[j] for j in range(k + 1, 3))) / a[k][k]
    return c


def cost_model(results, ranks, full_dofs, cluster_ranks):
    """Per Newton iteration: element loop t_e = a_e N / R (N DOFs, R cores: ranks, or threads of one rank),
    factorization t_f(N, 1) = a_f N^b_f (fitted on the 1-rank runs) and t_f(N, R) = t_f(N, 1) (s + (1 - s) / R)
    with the serial fraction s from the measured R-rank/1-rank ratio (Amdahl), solve likewise; memory per process
    m = m_0 + m_1 N / R + m_2 N (the model and whole dof vectors are on every process). Returns text lines."""
    one = [r for r in results if r['ranks'] == 1 and r['kind'] == 'base']
    many = [r for r in results if r['ranks'] == ranks and r['kind'] == 'dist']
    if len(one) < 2 or not many:
        return ['(cost model: needs 1-rank runs at two sizes or more and the %d-rank runs)' % ranks]
    a_e = sum(r['elem'] * r['cores'] / r['dofs'] for r in one + many) / len(one + many)
    af, bf = fit_power([r['dofs'] for r in one], [r['fact'] for r in one])
    asv, bsv = fit_power([r['dofs'] for r in one], [r['solve'] for r in one])
    ratios = []
    for r in many:
        base = [o for o in one if o['dofs'] == r['dofs']]
        if base and base[0]['fact'] > 0:
            ratios.append(r['fact'] / base[0]['fact'])
    s_f = amdahl_fraction([(ranks, y) for y in ratios]) if ratios else 1.0
    # memory: on the distributed runs alone where they span two sizes and two numbers of processes (a one-process
    # run takes the serial path, whose structures the linear form does not describe: its residual was 52 MB against
    # 2.5 MB for the others on reports/bench/scaling-memory), else on every run
    dist = [r for r in results if r['kind'] == 'dist']
    spans = len({r['dofs'] for r in dist}) >= 2 and len({r['ranks'] for r in dist}) >= 2
    mem_runs = dist if len(dist) >= 3 and spans else [r for r in results if r['kind'] in ('base', 'dist')]
    mem_from_dist = mem_runs is dist
    mem = lstsq3([[1.0, r['dofs'] / r['ranks'], r['dofs']] for r in mem_runs], [r['mem_mb'] for r in mem_runs])
    out = ['Cost model per Newton iteration, fitted to the runs above (N: DOFs, R: ranks; the fit is as noisy as '
           'the wall times it comes from):', '',
           '- element loop: t_e = %.3g N / R s (R cores: ranks, or the threads of the 1-rank run; mean over the '
           'runs of t_e R / N)' % a_e,
           '- factorization on one rank: t_f = %.3g N^%.2f s; on R ranks t_f (s + (1 - s)/R) with the serial fraction '
           's = %.2f from the measured %d-rank/1-rank ratio (%s)' % (af, bf, s_f, ranks,
                                                                   ', '.join('%.2f' % x for x in ratios)),
           '- solve: t_s = %.3g N^%.2f s' % (asv, bsv)]
    if mem:
        worst = max(abs(mem[0] + mem[1] * r['dofs'] / r['ranks'] + mem[2] * r['dofs'] - r['mem_mb'])
                    for r in mem_runs)
        out.append('- memory per process: m = %.0f MB + %.3g MB N / R + %.3g MB N (fitted on %d runs%s; largest '
                   'residual %.1f MB)' % (tuple(mem) + (len(mem_runs), ' of 2 processes or more' if mem_from_dist
                                                        else '', worst)))
    out.append('')
    out.append('Prediction for the full-width specimen (`--full-width`: twice the quarter model\'s width, about %d '
               'DOFs) per Newton iteration:' % full_dofs)
    out.append('')
    out.append('| ranks | element loop (s) | factorization (s) | solve (s) | total (s) | memory per process (MB) |')
    out.append('|---|---|---|---|---|---|')
    for R in cluster_ranks:
        te = a_e * full_dofs / R
        tf = af * full_dofs ** bf * (s_f + (1 - s_f) / R)
        ts = asv * full_dofs ** bsv * (s_f + (1 - s_f) / R)
        m = (mem[0] + mem[1] * full_dofs / R + mem[2] * full_dofs) if mem else float('nan')
        mcol = '-' if (mem_from_dist and R == 1) else '%.0f' % m
        out.append('| %d | %.2f | %.2f | %.2f | %.2f | %s |' % (R, te, tf, ts, te + tf + ts, mcol))
    return out


def amdahl_fraction(pairs):
    """Serial fraction s of t(R) = t(1) (s + (1 - s) / R) by least squares over (R, t(R)/t(1)) pairs with R > 1."""
    num = sum((y - 1.0 / r) * (1 - 1.0 / r) for r, y in pairs)
    den = sum((1 - 1.0 / r) ** 2 for r, y in pairs)
    return min(1.0, max(0.0, num / den)) if den > 0 else 1.0


def scaling_report(results, full_dofs, cluster_ranks):
    """Per scene: speedups against 1 rank x 1 thread, and every run against the prediction from the 1- and
    2-rank runs alone (element loop / R, factorization and solve by Amdahl with the 2-rank serial fraction,
    communication as measured on 2 ranks); then the serial fraction fitted over all ranks and its prediction for
    the full-width specimen."""
    out = []
    fits = []
    for scene in dict.fromkeys(r['scene'] for r in results):
        rs = [r for r in results if r['scene'] == scene]
        one = [r for r in rs if r['kind'] == 'base']
        two = [r for r in rs if r['kind'] == 'dist' and r['ranks'] == 2]
        if not one:
            continue
        b = one[0]
        s2 = amdahl_fraction([(2, two[0]['fact'] / b['fact'])]) if two else 1.0
        other = b['per'] - b['elem'] - b['fact'] - b['solve']   # setup, output, Newton's own work: not divided
        comm2 = two[0]['comm'] if two else 0.0
        dist = [r for r in rs if r['kind'] == 'dist']
        s_all = amdahl_fraction([(r['ranks'], r['fact'] / b['fact']) for r in dist])
        fits.append(dict(dofs=b['dofs'], elem=b['elem'], fact=b['fact'], solve=b['solve'], s=s_all, scene=scene))
        out += ['## %s (%d DOFs, %d Newton iterations)' % (scene, b['dofs'], b['its']), '',
                'Serial fraction of the factorization: %.2f from 2 ranks, %.2f fitted over all ranks.' % (s2, s_all),
                '', '| run | cores | t/iteration (s) | speedup | efficiency | element loop speedup | factorization '
                'speedup | element loop max/mean | slowest of each loop / mean | communication (s) | predicted '
                't/iteration from 1-2 ranks (s) | measured/predicted | peak memory of a process (MB) |',
                '|---|---|---|---|---|---|---|---|---|---|---|---|---|']
        for r in rs:
            if r['kind'] in ('base', 'dist'):
                R = r['ranks']
                pred = (other + b['elem'] / R + (b['fact'] + b['solve']) * (s2 + (1 - s2) / R) +
                        (comm2 if R > 1 else 0.0))
                pcol = '%.3f | %.2f' % (pred, r['per'] / pred)
            else:
                pcol = '- | -'
            sp = b['per'] / r['per']
            out.append('| %s | %d | %.3f | %.2f | %.2f | %.2f | %.2f | %s | %s | %.3f | %s | %.0f |' % (
                r['name'], r['cores'], r['per'], sp, sp / r['cores'], b['elem'] / max(r['elem'], 1e-12),
                b['fact'] / max(r['fact'], 1e-12), r['balance'], r['slowest'], r['comm'], pcol, r['mem_mb']))
        out.append('')
    if len(fits) >= 2:
        af, bf = fit_power([f['dofs'] for f in fits], [f['fact'] for f in fits])
        a_e = sum(f['elem'] / f['dofs'] for f in fits) / len(fits)
        big = max(fits, key=lambda f: f['dofs'])
        s = big['s']
        out += ['## Prediction for the full-width specimen (%d DOFs)' % full_dofs, '',
                'From the 1-rank runs (element loop %.3g N s, factorization %.3g N^%.2f s per iteration) and the '
                'serial fraction %.2f fitted on the largest scene (%s):' % (a_e, af, bf, s, big['scene']), '',
                '| ranks | element loop (s) | factorization (s) | total (s) |', '|---|---|---|---|']
        for R in cluster_ranks:
            te = a_e * full_dofs / R
            tf = af * full_dofs ** bf * (s + (1 - s) / R)
            out.append('| %d | %.2f | %.2f | %.2f |' % (R, te, tf, te + tf))
    return out


def ordering_study(args, env, work):
    mpirun = ['mpirun', '--oversubscribe', '--bind-to', 'none']
    lines = ['| scene | DOFs | processes | ordering | factorizations | entries in the factors (M) | factorization '
             '(s, wall) | per factorization (s) | CPU rank 0 (s) | load average before |',
             '|---|---|---|---|---|---|---|---|---|---|']
    for label, fine, application in (('peel %g' % args.fine[-1], args.fine[-1], False), ('application', 1.05, True)):
        tag = 'app' if application else '%g' % fine
        path = os.path.join(work, 'order_%s.inp' % tag)
        deck(args, fine, path, application)
        for np_, orders in ((1, ['metis', 'pord', 'amf', 'amd', 'qamd']), (args.ranks, ['metis', 'pord'])):
            for o in orders:
                rdir = os.path.join(work, 'order_%s_%d_%s' % (tag, np_, o))
                os.makedirs(rdir, exist_ok=True)
                cmd = mpirun + ['-np', str(np_), args.exe, '--threads', '1', '-q', '--newton', 'full',
                                '--stop-after-increments', '1', '--out', rdir, path]
                load = open('/proc/loadavg').read().split()[0]
                extra = {} if o == 'metis' else {'LDFCZ_MUMPS_ORDERING': o}
                res = subprocess.run(cmd, capture_output=True, text=True, env=dict(env, **extra))
                if res.returncode not in (0, 3):
                    sys.exit('bench_mpi.py: %s failed (exit %d)' % (' '.join(cmd), res.returncode))
                s = parse(rdir, 'order_%s' % tag)
                nf = int(s['counts'][4])
                row = '| %s | %d | %d | %s | %d | %.2f | %.2f | %.2f | %.2f | %s |' % (
                    label, int(s['dofs'][0]), np_, 'host METIS' if o == 'metis' else 'MUMPS ' + o.upper(), nf,
                    s['entries'][0] / 1e6, s['split'][1], s['split'][1] / max(nf, 1), s['wall'][1], load)
                lines.append(row)
                print(row, flush=True)
    with open(os.path.join(args.out, 'bench_mpi_orderings.md'), 'w') as f:
        f.write('Command: benchmarks/bench_mpi.py ' + ' '.join(sys.argv[1:]) + '\n\n' + '\n'.join(lines) + '\n')


def read_tables(paths):
    """The rows of earlier runs' bench_mpi.md tables as this script's results (1 rank x 1 thread: 'base'; R ranks
    x 1 thread: 'dist'; R ranks x T threads: 'hybrid'; the variants with a suffix, other partitions, weights or
    orderings, left out), each row once."""
    results, seen = [], set()
    for path in paths:
        header = None
        for line in open(path):
            cells = [c.strip() for c in line.strip().strip('|').split('|')]
            if not line.startswith('|') or len(cells) < 5:
                continue
            if cells[0] == 'scene':
                header = cells
                continue
            if header is None or set(cells[0]) <= set('-') or tuple(cells) in seen:
                continue
            seen.add(tuple(cells))
            c = dict(zip(header, cells))
            name = c['run']
            m = re.match(r'^(\d+) ranks? x (\d+) threads?$', name)
            ranks, threads = (int(m.group(1)), int(m.group(2))) if m else (0, 0)
            kind = ('base' if (ranks, threads) == (1, 1) else 'dist' if m and threads == 1 else
                    'hybrid' if m else 'other')
            if kind == 'other':
                continue
            results.append(dict(scene=c['scene'], kind=kind, ranks=ranks, cores=ranks * threads,
                                dofs=int(c['DOFs']), elem=float(c['element loop']), comm=float(c['communication']),
                                fact=float(c['factorization']), solve=float(c['solve']),
                                mem_mb=float(c['peak memory of a process (MB)']), per=float(c['t/iteration (s)']),
                                name=name, its=int(c['increments / iterations'].split('/')[1]),
                                balance=c.get('element loop max/mean', '-'),
                                slowest=c.get('element loop, slowest of each loop summed / mean', '-')))
    if not results:
        sys.exit('bench_mpi.py: --refit: no rows of 1 rank x 1 thread or R ranks x 1 thread in ' + ' '.join(paths))
    return results


def refit(args):
    """--refit: the cost model and scaling report fitted to the rows of earlier tables."""
    results = read_tables(args.refit)
    # the scaling report's per-scene tables: the 1-process row first
    results.sort(key=lambda r: (r['scene'], r['ranks'] != 1, r['ranks']))
    wide = [r['dofs'] for r in results if 'full width' in r['scene']]
    app = [r['dofs'] for r in results if r['scene'] == 'application']
    full_dofs = wide[0] if wide else 2 * (app[0] if app else max(r['dofs'] for r in results))
    text = (['Command: benchmarks/bench_mpi.py ' + ' '.join(sys.argv[1:]), '',
             'Rows read: %d from %s' % (len(results), ', '.join(args.refit)), ''] +
            cost_model(results, 2, full_dofs, args.cluster_ranks) + [''] +
            scaling_report(results, full_dofs, args.cluster_ranks))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, 'bench_mpi_refit.md'), 'w') as f:
        f.write('\n'.join(text) + '\n')
    print('\n'.join(text))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', default=os.path.join(ROOT, 'build-mpi', 'bin', 'ldfcz'), help='LDFCZ_MPI ldfcz')
    ap.add_argument('--serial-exe', default=None, help='default-build ldfcz (sequential MUMPS) to compare too')
    ap.add_argument('--fine', type=float, nargs='*', default=[0.02, 0.05], help='fine-region lengths (mm)')
    ap.add_argument('--ranks', type=int, default=2, help='R of R ranks x 1 thread')
    ap.add_argument('--threads', type=int, default=2, help='T of 1 rank x T threads')
    ap.add_argument('--newton', default='full')
    ap.add_argument('--le', type=float, default=0.002)
    ap.add_argument('--ny', type=int, default=10)
    ap.add_argument('--nz', type=int, default=3)
    ap.add_argument('--margin', type=float, default=0.1)
    ap.add_argument('--du', type=float, default=0.0003)
    ap.add_argument('--increments', type=int, default=3)
    ap.add_argument('--out', default=os.path.join(ROOT, 'reports', 'bench'))
    ap.add_argument('--application', action='store_true', help='also the paper\'s application mesh (section 8)')
    ap.add_argument('--orderings', nargs='*', default=[], help='MUMPS built-in orderings to compare with the host\'s '
                    'METIS on R ranks (pord, amd, amf, qamd)')
    ap.add_argument('--full-width', action='store_true', help='the application mesh over the specimen\'s full width '
                    '(peel_deck.py --full-width: twice the DOFs; what the cost model predicts)')
    ap.add_argument('--ordering-study', action='store_true', help='first increment per ordering (see above)')
    ap.add_argument('--cluster-ranks', type=int, nargs='+', default=[1, 2, 8, 32, 128])
    ap.add_argument('--scaling', type=int, nargs='+', default=[], help='strong scaling: R ranks x 1 thread for each '
                    'R (and 1 rank x 1 thread), see above')
    ap.add_argument('--hybrid', nargs='*', default=[], help='with --scaling: RxT runs, R ranks x T threads each')
    ap.add_argument('--pieces', nargs='+', default=['default'],
                    help='with --scaling: the partitions of the R-rank runs, each R run once per value: "default" '
                    '(ldfcz\'s own interleaved partition) or P (--partition-pieces P; 1: one part per process). '
                    'The cost model uses the first value\'s runs')
    ap.add_argument('--yield-idle', action='store_true', help='OMPI_MCA_mpi_yield_when_idle=1: a waiting process '
                    'gives its core away instead of polling (a machine shared with other jobs)')
    ap.add_argument('--refit', nargs='+', default=[], metavar='MD', help='fit the cost model to earlier tables '
                    '(bench_mpi.md files) instead of running, see above')
    args = ap.parse_args()
    if args.refit:
        refit(args)
        return
    executable(args.exe, 'ldfcz program (an LDFCZ_MPI build)')
    work = os.path.join(args.out, 'work_mpi')
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1',
               OMPI_MCA_rmaps_base_oversubscribe='1')
    if args.yield_idle:
        env['OMPI_MCA_mpi_yield_when_idle'] = '1'
    if args.ordering_study:
        ordering_study(args, env, work)
        return
    mpirun = ['mpirun', '--oversubscribe', '--bind-to', 'none']
    R = str(args.ranks)
    # (name, kind, ranks, command, extra environment)
    configs = [('1 rank x %d threads' % args.threads, 'base', 1,
                mpirun + ['-np', '1', args.exe, '--threads', str(args.threads)], {}),
               ('%s ranks x 1 thread, central RHS' % R, 'central', args.ranks,
                mpirun + ['-np', R, args.exe, '--threads', '1'], {'LDFCZ_MUMPS_CENTRAL_RHS': '1'}),
               ('%s ranks x 1 thread' % R, 'dist', args.ranks, mpirun + ['-np', R, args.exe, '--threads', '1'], {}),
               ('%s ranks x 1 thread, measured weights' % R, 'weights', args.ranks,
                mpirun + ['-np', R, args.exe, '--threads', '1'], {})]
    for o in args.orderings:
        configs.append(('%s ranks x 1 thread, MUMPS %s ordering' % (R, o.upper()), 'order', args.ranks,
                        mpirun + ['-np', R, args.exe, '--threads', '1'], {'LDFCZ_MUMPS_ORDERING': o}))
    if args.scaling:
        configs = [('1 rank x 1 thread', 'base', 1, mpirun + ['-np', '1', args.exe, '--threads', '1'], {})]
        for nr in args.scaling:
            if nr > 1:
                for k, pieces in enumerate(args.pieces):
                    opt = [] if pieces == 'default' else ['--partition-pieces', str(int(pieces))]
                    label = '' if pieces == 'default' else ', %s piece%s per process' % (pieces,
                                                                                      '' if pieces == '1' else 's')
                    configs.append(('%d ranks x 1 thread%s' % (nr, label), 'dist' if k == 0 else 'pieces', nr,
                                    mpirun + ['-np', str(nr), args.exe, '--threads', '1'] + opt, {}))
        for h in args.hybrid:
            nr, nt = (int(x) for x in h.lower().split('x'))
            configs.append(('%d rank%s x %d threads' % (nr, 's' if nr > 1 else '', nt), 'hybrid', nr,
                            mpirun + ['-np', str(nr), args.exe, '--threads', str(nt)], {}, nt))
    if args.serial_exe:
        configs.insert(0, ('serial build, %d threads' % args.threads, 'serial', 1,
                           [args.serial_exe, '--threads', str(args.threads)], {}))
    lines = ['| scene | DOFs | run | increments / iterations | t/iteration (s) | element loop | communication | '
             'factorization | solve | factor entries (M) | element loop max/mean | element loop, slowest of each loop '
             'summed / mean | CPU/iteration rank 0 (s) | CPU/iteration all (s) | peak memory of a process (MB) | '
             'load average before |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    scenes = [('peel %g' % f, f, False) for f in args.fine]
    if args.application:
        # with --scaling the application mesh first: the scene that matters most, should a time limit cut the rest
        scenes.insert(0 if args.scaling else len(scenes),
                      ('application, full width' if args.full_width else 'application', 1.05, True))
    results = []
    app_dofs = None
    for label, fine, application in scenes:
        tag = 'app' if application else '%g' % fine
        path = os.path.join(work, 'peel_%s.inp' % tag)
        deck(args, fine, path, application)
        measured = None
        for k, config in enumerate(configs):
            name, kind, nranks, cmd, extra_env = config[:5]
            rdir = os.path.join(work, 'run_%s_%d' % (tag, k))
            os.makedirs(rdir, exist_ok=True)
            full = list(cmd)
            if kind == 'weights':
                if not measured:
                    continue
                full += ['--element-weights', ','.join(measured)]
                name += ' (%s)' % ','.join(measured)
            full += ['-q', '--newton', args.newton, '--out', rdir, path]
            load = open('/proc/loadavg').read().split()[0] if os.path.exists('/proc/loadavg') else '?'
            ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            res = subprocess.run(full, capture_output=True, text=True, env=dict(env, **extra_env))
            ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            if res.returncode != 0:
                sys.exit('bench_mpi.py: %s failed (exit %d):\n%s' % (' '.join(full), res.returncode,
                                                                    (res.stdout + res.stderr)[-2000:]))
            s = parse(rdir, 'peel_%s' % tag)
            inc, its = int(s['counts'][0]), int(s['counts'][3])
            asm, fact, solve = s['split'][0], s['split'][1], s['split'][2]
            comm = s['comm'][1] if s['comm'] else 0.0
            per = s['wall'][0] / its
            cpu_all = (ru1.ru_utime + ru1.ru_stime - ru0.ru_utime - ru0.ru_stime) / its
            mem_mb = (s['comm'][2] if s['comm'] else s['memory'][0]) / 1024.0
            balance = '%.3f' % s['balance'][2] if s['balance'] else '-'
            slowest = '%.3f' % s['slowest'][1] if s['slowest'] else '-'
            if kind == 'dist' and s['weights']:
                measured = ['%d' % w for w in s['weights']]
            if application:
                app_dofs = int(s['dofs'][0])
            cores = args.threads if kind in ('base', 'serial') else nranks
            if args.scaling:
                cores = nranks * (config[5] if len(config) > 5 else 1)
            results.append(dict(scene=label, kind=kind, ranks=nranks, cores=cores, dofs=int(s['dofs'][0]),
                                elem=asm / its, comm=comm / its, fact=fact / its, solve=solve / its, mem_mb=mem_mb,
                                per=per, name=name, its=its, balance=balance, slowest=slowest))
            entries = '%.2f' % (s['entries'][0] / 1e6) if s['entries'] else '-'
            row = ('| %s | %d | %s | %d / %d | %.3f | %.3f | %.3f | %.3f | %.3f | %s | %s | %s | %.3f | %.3f | '
                   '%.0f | %s |') % (
                label, int(s['dofs'][0]), name, inc, its, per, asm / its, comm / its, fact / its, solve / its,
                entries, balance, slowest, s['wall'][1] / its, cpu_all, mem_mb, load)
            lines.append(row)
            print(row, flush=True)
    full_dofs = (app_dofs if args.full_width else 2 * app_dofs) if app_dofs else 2 * max(r['dofs'] for r in results)
    model = cost_model(results, 2 if args.scaling else args.ranks, full_dofs,
                       args.cluster_ranks)
    if args.scaling:
        with open(os.path.join(args.out, 'bench_mpi_scaling.md'), 'w') as f:
            f.write('Command: benchmarks/bench_mpi.py ' + ' '.join(sys.argv[1:]) + '\n\n' +
                    '\n'.join(scaling_report(results, full_dofs, args.cluster_ranks)) + '\n')
    load = open('/proc/loadavg').read().split()[:3] if os.path.exists('/proc/loadavg') else ['?']
    with open(os.path.join(args.out, 'bench_mpi.md'), 'w') as f:
        f.write('Command: benchmarks/bench_mpi.py ' + ' '.join(sys.argv[1:]) + '\n\nLoad average at the end: ' +
                ' '.join(load) + ' (other jobs share the cores: wall times inflate, CPU time does not)\n\n' +
                '\n'.join(lines) + '\n\n' + '\n'.join(model) + '\n')
    print('\n'.join(lines))
    print('\n'.join(model))


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
