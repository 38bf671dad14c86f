#!/usr/bin/env python3
"""Solver settings compared on a window of the paper's application scene (docs/performance.md).

  bench_window.py [--ldfcz EXE] [--work DIR] [--start N] [--window K] [--threads T] [--gen-args ARGS]
                  [--config LABEL=OPTIONS ...] [--exe LABEL=EXE ...] [--env LABEL=VAR=VALUE ...] [--md FILE]

1. Generates the application deck of `tools/peel_study.py application` (tools/peel_deck.py: 3D quarter, rigid
   substrate, 10 x 3 elements, l_e = 2 um over 1.05 mm; 89595 DOFs) into DIR and runs its first N increments
   (default 62: about 30 um of pull, the front is moving) once, writing the restart file (reused when present
   and the deck is unchanged). --gen-args appends generator options (they override the defaults), e.g.
   "--ny 2" for a narrower proxy of the same scene whose late stage (--start 600: the peeled arm flows) is
   cheap to reach.
2. Runs every configuration from that restart file for K increments (default 25) in its own copy of the run
   directory: `ldfcz -t T --max-opening-increment 0.33 --max-plastic-increment 1.0 OPTIONS --restart-from ...
   --stop-after-increments K` (OPTIONS default `--newton auto`), optionally with another executable (--exe, e.g.
   a build of an older commit; the restart file format must match) or an environment variable (--env).
3. Prints a Markdown table (and writes it to --md if given): Newton iterations, factorizations, GMRES
   iterations, wall time split as in the closing summary, assembly per iteration, and the reaction force at the
   end of the window (differences between configurations must stay within the Newton tolerance; the increments
   may differ, so compare it at equal step time only when the step times agree).
Counts are those of the window (the closing summary after a restart counts from the start of the analysis: the
restart run's figures minus the base run's). Wall times depend on what else runs on the machine: run it idle.
Python standard library only.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT

GEN = ['--3d', '--rigid-substrate', '--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.001',
       '--dgamma-max', '1.0', '--fine-length', '1.05', '--bonded', '1.2', '--u-total', '0.72',
       '--field-frequency', '40']
COMMON = ['--max-opening-increment', '0.33', '--max-plastic-increment', '1.0']
JOB = 'app'


def summary(outdir):
    """Counters (continued over restarts) and times (of the last run) of JOB.summary.json."""
    doc = outputs.read_summary(outdir, JOB)
    c, t = doc['counters'], doc['times']
    return {'inc': c['increments'], 'cut': c['cutbacks'], 'its': c['iterations'], 'fac': c['factorizations'],
            'gmres': c['gmres_iterations'], 'wall': t['wall_s'], 'asm': t['element_loop_s'],
            'fact': t['factorization_s'], 'solve': t['solve_s']}


def last_row(csv_path):
    lines = open(csv_path).read().strip().split('\n')
    head = lines[0].split(',')
    row = lines[-1].split(',')
    return float(row[head.index('step_time')]), float(row[head.index('LOAD.RF1')])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--ldfcz', default=os.path.join(ROOT, 'build', 'bin', 'ldfcz'))
    ap.add_argument('--work', default=os.path.join(ROOT, 'out', 'bench-window'))
    ap.add_argument('--start', type=int, default=62, help='increments before the window (base run)')
    ap.add_argument('--window', type=int, default=25, help='increments of each configuration')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--config', action='append', default=[], help='LABEL=ldfcz options (repeatable)')
    ap.add_argument('--exe', action='append', default=[], help='LABEL=executable for that configuration')
    ap.add_argument('--env', action='append', default=[], help='LABEL=VAR=VALUE for that configuration')
    ap.add_argument('--md', help='also write the table to this file')
    ap.add_argument('--gen-args', default='', help='extra tools/peel_deck.py options (override the defaults)')
    a = ap.parse_args()
    executable(a.ldfcz, 'ldfcz program')
    configs = [c.split('=', 1) for c in a.config] or [['auto', '--newton auto']]
    exes = dict(e.split('=', 1) for e in a.exe)
    envs = {}
    for e in a.env:
        label, kv = e.split('=', 1)
        envs.setdefault(label, []).append(kv.split('=', 1))
    exe = os.path.abspath(a.ldfcz)
    if not os.access(exe, os.X_OK):
        sys.exit('bench_window.py: %s is not an executable (build first, or --ldfcz)' % exe)
    os.makedirs(a.work, exist_ok=True)
    deck = os.path.join(a.work, JOB + '.inp')
    new_deck = deck + '.new'
    subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'peel_deck.py')] + GEN + a.gen_args.split() +
                   ['-o', new_deck],
                   check=True, stdout=subprocess.DEVNULL)
    base = os.path.join(a.work, 'base')
    rst = os.path.join(base, JOB + '.rst')
    same = os.path.exists(deck) and open(deck).read() == open(new_deck).read()
    os.replace(new_deck, deck)
    stamp = os.path.join(base, 'start.txt')
    if not (same and os.path.exists(rst) and os.path.exists(stamp) and open(stamp).read() == str(a.start)):
        shutil.rmtree(base, ignore_errors=True)
        print('base run: the first %d increments (restart file) ...' % a.start, flush=True)
        r = subprocess.run([exe, '-q', '-t', str(a.threads), '--newton', 'auto'] + COMMON +
                           ['--restart-write', str(a.start), '--stop-after-increments', str(a.start), '-o', base,
                            deck])
        if r.returncode not in (0, 3) or not os.path.exists(rst):
            sys.exit('bench_window.py: the base run failed (exit %d)' % r.returncode)
        open(stamp, 'w').write(str(a.start))
    b = summary(base)
    rows = []
    for label, opts in configs:
        d = os.path.join(a.work, 'w_' + re.sub(r'[^A-Za-z0-9_.-]', '_', label))
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(base, d)
        env = dict(os.environ)
        for k, v in envs.get(label, []):
            env[k] = v
        cmd = [exes.get(label, exe), '-q', '-t', str(a.threads)] + COMMON + opts.split() + \
            ['--restart-from', os.path.join(d, JOB + '.rst'), '--stop-after-increments', str(a.window), '-o', d,
             deck]
        print('%s: %s' % (label, ' '.join(cmd)), flush=True)
        r = subprocess.run(cmd, env=env)
        if r.returncode not in (0, 3):
            sys.exit('bench_window.py: configuration %s failed (exit %d)' % (label, r.returncode))
        s = summary(d)
        t, rf = last_row(os.path.join(d, JOB + '.csv'))
        w = {k: s[k] - b[k] for k in ('inc', 'cut', 'its', 'fac', 'gmres')}
        w.update({k: s[k] for k in ('wall', 'asm', 'fact', 'solve')})
        rows.append((label, opts, w, t, rf))
    out = ['Window of the application scene%s: increments %d-%d from the restart file, `-t %d`, %s.' % (
        (' (generator options added: `%s`)' % a.gen_args) if a.gen_args else '',
        a.start + 1, a.start + a.window, a.threads, ' '.join(COMMON)), '',
        '| configuration | options | increments | Newton iterations | factorizations | GMRES iterations | wall (s) '
        '| assembly / factorization / solve (s) | assembly per iteration (s) | '
        'step time at the end (s = um of pull) | LOAD.RF1 at the end (N) |',
        '|---|---|---|---|---|---|---|---|---|---|---|']
    for label, opts, w, t, rf in rows:
        extra = ' '.join(['%s=%s' % tuple(kv) for kv in envs.get(label, [])] +
                         (['exe ' + exes[label]] if label in exes else []))
        out.append('| %s | `%s`%s | %d | %d | %d | %d | %.1f | %.1f / %.1f / %.1f | %.3f | %.4f | %.9e |' % (
            label, opts, (' ' + extra) if extra else '', w['inc'], w['its'], w['fac'], w['gmres'], w['wall'],
            w['asm'], w['fact'], w['solve'], w['asm'] / max(w['its'], 1), t, rf))
    text = '\n'.join(out) + '\n'
    print(text)
    if a.md:
        os.makedirs(os.path.dirname(os.path.abspath(a.md)), exist_ok=True)
        open(a.md, 'w').write(text)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
