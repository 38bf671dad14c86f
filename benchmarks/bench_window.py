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

--own-base: builds whose restart files differ (e.g. a commit against e9cbdfd, whose format is older) each run
their own base run with their own executable (DIR/base_LABEL) and restart from it (--generator LABEL=PATH: with
the deck that build's own tools/peel_deck.py writes, DIR/deck_LABEL/app.inp); --repeat R runs the
configurations R times, in turn and in reverse order every other round (A B, B A, ...), so that they meet the same
machine speeds. Every run is measured from outside, so that builds that write no JOB.summary.json compare: CPU
seconds of the process (user + system, wait4), wall seconds, peak resident set (ru_maxrss), and from the closing
summary every build prints on its console (captured to RUNDIR/console.txt; builds older than
JOB.summary.json have nothing else) the Newton iterations, factorizations, GMRES iterations, the time split and
the measured microseconds per continuum UMAT element call; LOAD.RF1 and the step time of the window's last
CSV row. Prints one row per run, then the mean (min-max) per configuration.
Python standard library only.
"""
import argparse
import os
import platform
import re
import shutil
import subprocess
import sys
import time

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT

GEN = ['--3d', '--rigid-substrate', '--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.001',
       '--dgamma-max', '1.0', '--fine-length', '1.05', '--bonded', '1.2', '--u-total', '0.72',
       '--field-frequency', '40']
COMMON = ['--max-opening-increment', '0.33', '--max-plastic-increment', '1.0']
JOB = 'app'
CONSOLE = 'console.txt'  # a run's console (stdout and stderr), as bench_window captured it


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


LOG_PATTERNS = {
    'inc': r'^increments (\d+), attempts (\d+), cutbacks (\d+), Newton iterations (\d+), factorizations (\d+)',
    'gmres': r'GMRES solves \d+ \((\d+) GMRES iterations',
    'split': r'^wall time split: assembly\s+([\d.]+) s, factorization\s+([\d.]+) s, solve\s+([\d.]+) s',
    'umat': r'^element cost measured \(us per call, calls\): UMAT continuum\s+([\d.]+)',
}


def console_summary(path):
    """The closing summary of a run's captured console (every build prints it; its counters continue over
    restarts, its times are the run's own): increments, attempts, cutbacks, iterations, factorizations, GMRES iterations,
    assembly / factorization / solve seconds, us per UMAT continuum element call."""
    out = {}
    for line in open(path, errors='replace'):
        line = line.strip()
        m = re.match(LOG_PATTERNS['inc'], line)
        if m:
            out.update(dict(zip(('inc', 'att', 'cut', 'its', 'fac'), map(int, m.groups()))))
        m = re.search(LOG_PATTERNS['gmres'], line)
        if m:
            out['gmres'] = int(m.group(1))
        m = re.match(LOG_PATTERNS['split'], line)
        if m:
            out.update(dict(zip(('asm', 'fact', 'solve'), map(float, m.groups()))))
        m = re.match(LOG_PATTERNS['umat'], line)
        if m:
            out['umat_us'] = float(m.group(1))
    return out


def timed(cmd, console, env=None):
    """Run cmd, its console into the file console; (exit status, wall s, CPU s of the process and its children,
    peak resident set MiB)."""
    t0 = time.monotonic()
    with open(console, 'w') as out:
        p = subprocess.Popen(cmd, env=env, stdout=out, stderr=subprocess.STDOUT)
        _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    return p.returncode, time.monotonic() - t0, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0


def own_base_main(a, deck, configs, exes, envs, exe):
    """--own-base: each executable's base run and restart files; the configurations alternated --repeat times."""
    bases, decks = {}, {}
    gens = dict(g.split('=', 1) for g in a.generator)
    for label, _ in configs:
        x = exes.get(label, exe)
        if x in bases:
            continue
        tag = re.sub(r'[^A-Za-z0-9_.-]', '_', label)
        if label in gens:
            # the deck as that build's own generator writes it (an older build may not read today's deck)
            os.makedirs(os.path.join(a.work, 'deck_' + tag), exist_ok=True)
            decks[x] = os.path.join(a.work, 'deck_' + tag, JOB + '.inp')
            subprocess.run([sys.executable, gens[label]] + GEN + a.gen_args.split() + ['-o', decks[x]], check=True,
                           stdout=subprocess.DEVNULL)
        else:
            decks[x] = deck
        base = os.path.join(a.work, 'base_' + tag)
        stamp = os.path.join(base, 'start.txt')
        key = '%d %s %s' % (a.start, x, os.path.getmtime(x))
        if not (os.path.exists(stamp) and open(stamp).read() == key and
                open(os.path.join(base, 'deck.inp')).read() == open(decks[x]).read()):
            shutil.rmtree(base, ignore_errors=True)
            os.makedirs(base)
            shutil.copy(decks[x], os.path.join(base, 'deck.inp'))
            print('base run of %s: the first %d increments ...' % (x, a.start), flush=True)
            rc, wall, cpu, rss = timed([x, '-t', str(a.threads)] + COMMON + configs[0][1].split() +
                                       ['--restart-write', str(a.start), '--stop-after-increments', str(a.start),
                                        '-o', base, decks[x]], os.path.join(base, CONSOLE))
            if rc not in (0, 3) or not os.path.exists(os.path.join(base, JOB + '.rst')):
                sys.exit('bench_window.py: the base run of %s failed (exit %d)' % (x, rc))
            open(os.path.join(base, 'outside.txt'), 'w').write('%.3f %.3f %.1f\n' % (wall, cpu, rss))
            open(stamp, 'w').write(key)
        bases[x] = base
    rows = []
    order = list(configs)
    for r in range(a.repeat):
        for label, opts in (order if r % 2 == 0 else order[::-1]):
            x = exes.get(label, exe)
            b = console_summary(os.path.join(bases[x], CONSOLE))
            d = os.path.join(a.work, 'w_%s_%d' % (re.sub(r'[^A-Za-z0-9_.-]', '_', label), r + 1))
            shutil.rmtree(d, ignore_errors=True)
            shutil.copytree(bases[x], d)
            env = dict(os.environ)
            for k, v in envs.get(label, []):
                env[k] = v
            cmd = [x, '-t', str(a.threads)] + COMMON + opts.split() + \
                ['--restart-from', os.path.join(d, JOB + '.rst'), '--stop-after-increments', str(a.window), '-o', d,
                 decks[x]]
            print('%s round %d: %s' % (label, r + 1, ' '.join(cmd)), flush=True)
            load0 = os.getloadavg()[0]
            rc, wall, cpu, rss = timed(cmd, os.path.join(d, CONSOLE), env)
            if rc not in (0, 3):
                sys.exit('bench_window.py: configuration %s failed (exit %d)' % (label, rc))
            s = console_summary(os.path.join(d, CONSOLE))
            w = {k: s[k] - b[k] for k in ('inc', 'att', 'cut', 'its', 'fac', 'gmres')}
            w.update({k: s.get(k, 0.0) for k in ('asm', 'fact', 'solve', 'umat_us')})
            w.update(wall=wall, cpu=cpu, rss=rss, load=load0)
            t, rf = last_row(os.path.join(d, JOB + '.csv'))
            rows.append((label, r + 1, w, t, rf))
    head = ('Window of the application scene%s: increments %d-%d, each build from its own restart file '
            '(base runs of %d increments), `-t %d`, %s; options: %s.' % (
                (' (generator options added: `%s`)' % a.gen_args) if a.gen_args else '', a.start + 1,
                a.start + a.window, a.start, a.threads, ' '.join(COMMON),
                '; '.join('%s `%s`%s' % (lb, op, (' exe ' + exes[lb]) if lb in exes else '') for lb, op in configs)))
    out = [head, '', '| configuration | round | increments (attempts) | Newton iterations | per increment | '
           'factorizations | GMRES iterations | CPU (s) | wall (s) | load | assembly / factorization / solve (s) | '
           'us per UMAT element call | s per factorization | peak RSS (MiB) | step time at the end | '
           'LOAD.RF1 at the end (N) |', '|' + '---|' * 16]
    for label, r, w, t, rf in rows:
        out.append('| %s | %d | %d (%d) | %d | %.2f | %d | %d | %.1f | %.1f | %.2f | %.1f / %.1f / %.1f | %.2f | '
                   '%.3f | %.0f | %.4f | %.9e |' % (
                       label, r, w['inc'], w['att'], w['its'], w['its'] / max(w['inc'], 1), w['fac'], w['gmres'],
                       w['cpu'], w['wall'], w['load'], w['asm'], w['fact'], w['solve'], w['umat_us'],
                       w['fact'] / max(w['fac'], 1), w['rss'], t, rf))
    out += ['', '| configuration | CPU (s) mean (min-max) | wall (s) mean (min-max) | Newton iterations per '
            'increment | LOAD.RF1 at the end (N) | step time at the end |', '|---|---|---|---|---|---|']
    for label, _ in configs:
        rr = [x for x in rows if x[0] == label]
        cpu = [x[2]['cpu'] for x in rr]
        wall = [x[2]['wall'] for x in rr]
        out.append('| %s | %.1f (%.1f-%.1f) | %.1f (%.1f-%.1f) | %.2f | %s | %s |' % (
            label, sum(cpu) / len(cpu), min(cpu), max(cpu), sum(wall) / len(wall), min(wall), max(wall),
            rr[0][2]['its'] / max(rr[0][2]['inc'], 1), ' '.join('%.9e' % x[4] for x in rr),
            ' '.join('%.4f' % x[3] for x in rr)))
    for x, base in bases.items():
        wall, cpu, rss = open(os.path.join(base, 'outside.txt')).read().split()
        bs = console_summary(os.path.join(base, CONSOLE))
        out.append('')
        out.append('Base run of %s: %d increments (%d attempts), %d Newton iterations, %d factorizations, '
                   '%s s CPU, %s s wall, peak RSS %s MiB.' % (x, bs['inc'], bs['att'], bs['its'], bs['fac'], cpu,
                                                              wall, rss))
    out += ['', 'Stamp: commit %s, `%s`, %s, %s.' % (
        subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                       text=True).stdout.strip(), ' '.join(sys.argv), time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime()),
        '%s, %d CPUs' % (platform.node(), os.cpu_count()))]
    text = '\n'.join(out) + '\n'
    print(text)
    if a.md:
        os.makedirs(os.path.dirname(os.path.abspath(a.md)), exist_ok=True)
        open(a.md, 'w').write(text)


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
    ap.add_argument('--own-base', action='store_true', help='each executable restarts from its own base run')
    ap.add_argument('--generator', action='append', default=[],
                    help='LABEL=PATH: that configuration\'s deck from this tools/peel_deck.py (with --own-base)')
    ap.add_argument('--repeat', type=int, default=1, help='rounds of the configurations (with --own-base)')
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
    if a.own_base:
        return own_base_main(a, deck, configs, exes, envs, exe)
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
