#!/usr/bin/env python3
"""The same deck run several times gives the same results to the bit: no decision that changes the solution path
depends on a clock, a thread count or the order in which processes finish (docs/testing.md, "Reproducibility").

  check_reproducible.py --exe BIN --deck DECK --out DIR [--np N] [--expect-exit K] [-- LDFCZ OPTIONS]

Without --np: the deck runs three times, on 1 thread, again on 1 thread and on 2 threads (-t). With --np N: twice
under mpirun -np N (1 thread each), the distributed run. Every run must exit alike and write the same JOB.csv,
JOB.dat and JOB.sta, byte for byte (they hold no times; JOB.log does and is not compared), and the closing summary's
counts (increments, attempts, cutbacks, Newton iterations, factorizations, GMRES solves and iterations) must agree.
A difference is reported with the first differing line of each file. With --newton auto the GMRES budget is part
of the path: the check also requires GMRES to have run (the summary's GMRES iterations > 0), so that the budget was
exercised.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys


def fail(msg):
    print('FAIL: ' + msg)
    sys.exit(1)


def run(a, label, threads, extra):
    d = os.path.join(a.out, label)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    cmd = [a.exe, '-q', '-t', str(threads), '-o', d] + extra + [a.deck]
    env = dict(os.environ)
    if a.np:
        cmd = ['mpirun', '-np', str(a.np), '--oversubscribe', '--bind-to', 'none'] + cmd
        env.update(OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1',
                   OMPI_MCA_rmaps_base_oversubscribe='1', OMPI_MCA_mpi_yield_when_idle='1')
    p = subprocess.run(cmd, capture_output=True, text=True, errors='replace', env=env, timeout=600)
    if p.returncode != a.expect_exit:
        fail('%s: exit %d (expected %d)\n%s' % (label, p.returncode, a.expect_exit, (p.stdout + p.stderr)[-3000:]))
    return d


def counts(d, job):
    with open(os.path.join(d, job + '.log'), errors='replace') as f:
        text = f.read().split('=== ldfcz summary ===')[-1]
    m = re.search(r'increments (\d+), attempts (\d+), cutbacks (\d+), Newton iterations (\d+), factorizations (\d+)',
                  text)
    if not m:
        fail('%s: no closing summary in JOB.log' % d)
    g = re.search(r'GMRES solves (\d+) \((\d+) GMRES iterations', text)
    return tuple(int(x) for x in m.groups()) + (tuple(int(x) for x in g.groups()) if g else (0, 0))


def first_difference(p, q):
    with open(p, errors='replace') as f:
        a = f.read().split('\n')
    with open(q, errors='replace') as f:
        b = f.read().split('\n')
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return 'line %d:\n  %s\n  %s' % (i + 1, x[:200], y[:200])
    return 'lengths %d and %d lines' % (len(a), len(b))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', required=True)
    ap.add_argument('--deck', required=True)
    ap.add_argument('--out', required=True)
    ap.add_argument('--np', type=int, default=0, help='processes (mpirun); default: serial runs on 1, 1 and 2 threads')
    ap.add_argument('--expect-exit', type=int, default=0)
    ap.add_argument('extra', nargs='*', help='ldfcz options (after --)')
    a = ap.parse_args()
    job = os.path.splitext(os.path.basename(a.deck))[0]
    if a.np:
        runs = [('np%d_a' % a.np, 1), ('np%d_b' % a.np, 1)]
    else:
        runs = [('t1_a', 1), ('t1_b', 1), ('t2', 2)]
    dirs = [(label, run(a, label, t, a.extra)) for label, t in runs]
    ref_label, ref = dirs[0]
    ref_counts = counts(ref, job)
    if '--newton' in a.extra and 'auto' in a.extra and ref_counts[6] == 0:
        fail('%s: no GMRES iteration: the budget of --newton auto was not exercised' % ref_label)
    for label, d in dirs[1:]:
        for ext in ('csv', 'dat', 'sta'):
            p, q = os.path.join(ref, job + '.' + ext), os.path.join(d, job + '.' + ext)
            if not os.path.exists(p) or not os.path.exists(q):
                fail('%s or %s missing' % (p, q))
            with open(p, 'rb') as f1, open(q, 'rb') as f2:
                if f1.read() != f2.read():
                    fail('JOB.%s of %s differs from %s\'s: %s' % (ext, label, ref_label, first_difference(p, q)))
        c = counts(d, job)
        if c != ref_counts:
            fail('%s: summary counts %s, %s: %s' % (label, c, ref_label, ref_counts))
    print('increments, attempts, cutbacks, Newton iterations, factorizations, GMRES solves, GMRES iterations: %s'
          % (ref_counts,))
    print('PASS: %s: JOB.csv, JOB.dat and JOB.sta identical to the bit' % ', '.join(label for label, _ in dirs))


if __name__ == '__main__':
    main()
