#!/usr/bin/env python3
"""ldfcz against CalculiX 2.20 on the same deck: a 40x40x10 C3D8 elastic NLGEOM block (issue 20).

The block is 40 x 40 x 10 mm with 1 mm elements (18 491 nodes, 16 000 C3D8); the face x = 0 is clamped, the face
x = 40 gets u1 = the pull, u2 = u3 = 0 (55 473 dofs, 52 767 equations); steel-like elasticity (E = 210 GPa,
nu = 0.3), NLGEOM, fixed increments (*STATIC, DIRECT) of 0.1 mm of pull, i.e. 10 % strain of the element layer
beside the loaded face if the increment were applied to the boundary nodes alone. The same deck text is read
by both programs (Abaqus keywords that CalculiX 2.20 reads alike).

Each configuration (program x threads) runs --repeat times, the configurations alternating within each repeat.
Per run: the wall time of each increment (the time at which the program appended the increment's line to
JOB.sta, polled every 10 ms), the Newton iterations per increment (JOB.sta), the program's CPU time (user + system
of the child), its peak resident memory (GNU time's %M, kB, where /usr/bin/time exists), the load average before
and after; for ldfcz also the closing summary's assembly / factorization / solve split (not for a build that
writes no JOB.summary.json, e.g. e9cbdfd: --ldfcz-exe LABEL=PATH runs another build). The report lists the median
and the spread of the repeats, so the noise of a shared machine shows.

  tools/setup.sh bench      (Release build and calculix-ccx)
  /usr/bin/python3 benchmarks/bench_calculix.py --exe build/bin/ldfcz --threads 1 2 --repeat 3 \\
      --md reports/bench/calculix.md

Not a test: a run takes minutes. Threads: ldfcz -t N, CalculiX OMP_NUM_THREADS=N (and CCX_NPROC_STIFFNESS /
CCX_NPROC_EQUATION_SOLVER, which ccx 2.20 reads before OMP_NUM_THREADS).
"""
import argparse
import json
import os
import shlex
import resource
import shutil
import statistics
import subprocess
import sys
import threading
import time

from ldfcz_tools import outputs
from ldfcz_tools.block_deck import block_deck
from ldfcz_tools.cli import executable


class StaWatch:
    """Polls a .sta file and stamps the wall time (since start) at which each line appeared."""

    def __init__(self, path, t0):
        self.path, self.t0, self.stamps, self.stop = path, t0, [], False
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        seen = 0
        while not self.stop:
            try:
                with open(self.path) as f:
                    lines = f.read().splitlines()
            except OSError:
                lines = []
            now = time.monotonic() - self.t0
            for ln in lines[seen:]:
                self.stamps.append((now, ln))
            seen = max(seen, len(lines))
            time.sleep(0.01)

    def finish(self):
        self.stop = True
        self.thread.join()


GNU_TIME = '/usr/bin/time'


def run_timed(cmd, cwd, env, sta):
    """Run cmd; returns (wall, cpu user+sys of the child, sta stamps, stdout, peak resident kB or None)."""
    if os.path.exists(sta):
        os.remove(sta)
    rss_file = os.path.abspath(os.path.join(cwd, 'maxrss.txt'))
    if os.path.exists(rss_file):
        os.remove(rss_file)
    if os.access(GNU_TIME, os.X_OK):
        cmd = [GNU_TIME, '-f', '%M', '-o', rss_file] + cmd
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    w = StaWatch(sta, t0)
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - t0
    time.sleep(0.05)
    w.finish()
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    if p.returncode != 0:
        sys.exit('bench_calculix: %s failed (exit %d):\n%s' % (' '.join(cmd), p.returncode, p.stdout[-3000:]))
    rss = None
    if os.path.exists(rss_file):
        with open(rss_file) as f:
            words = f.read().split()
        rss = int(words[-1]) if words and words[-1].isdigit() else None
    return wall, cpu, w.stamps, p.stdout, rss


def ldfcz_increments(stamps):
    """(time, iterations) of each converged increment from ldfcz's JOB.sta lines (attempts that failed are part of
    the next converged line's time)."""
    out = []
    for t, ln in stamps:
        f = ln.split()
        if len(f) >= 6 and f[0].isdigit() and 'converged' in ln:
            out.append((t, int(f[3])))
    return out


def ccx_increments(stamps):
    """(time, iterations) per increment from CalculiX's .sta lines: STEP INC ATT ITRS TOT TIME STEP TIME INC TIME."""
    out = []
    for t, ln in stamps:
        f = ln.split()
        if len(f) >= 7 and all(x.isdigit() for x in f[:4]):
            out.append((t, int(f[3])))
    return out


def summary_split(doc):
    """Assembly, factorization, solve and set-up seconds and the factorizations of ldfcz's run summary
    (JOB.summary.json)."""
    t = doc['times']
    return {'assembly': t['element_loop_s'], 'factorization': t['factorization_s'], 'solve': t['solve_s'],
            'setup': t['solver_setup_s'], 'factorizations': doc['counters']['factorizations']}


def load_avg():
    return os.getloadavg()[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', default='build/bin/ldfcz', help='ldfcz executable (a Release build)')
    ap.add_argument('--ccx', default='ccx', help='CalculiX executable')
    ap.add_argument('--threads', type=int, nargs='+', default=[1, 2])
    ap.add_argument('--repeat', type=int, default=3)
    ap.add_argument('--increments', type=int, default=4)
    ap.add_argument('--du', type=float, default=0.1, help='pull per increment (mm)')
    ap.add_argument('--work', default='out/bench-calculix')
    ap.add_argument('--programs', nargs='+', default=['ldfcz', 'ccx'],
                    help="ccx, ldfcz, or the label of an --ldfcz-config")
    ap.add_argument('--ldfcz-config', action='append', default=[],
                    help="LABEL=ldfcz options: a further ldfcz configuration, run when LABEL is in --programs "
                         "(e.g. 'auto=--newton auto')")
    ap.add_argument('--ldfcz-exe', action='append', default=[],
                    help="LABEL=PATH: the ldfcz executable of configuration LABEL (another build; default --exe; "
                         "a LABEL without --ldfcz-config runs with no options), e.g. 'e9cbdfd=/path/bin/ldfcz'")
    ap.add_argument('--md', default='', help='write the report here (markdown)')
    a = ap.parse_args()
    if 'ldfcz' in a.programs:
        executable(a.exe, 'ldfcz program')
    a.ldfcz = dict(ldfcz='')
    for c in a.ldfcz_config:
        label, opts = c.split('=', 1)
        a.ldfcz[label] = opts
    a.exes = {}
    for c in a.ldfcz_exe:
        label, path = c.split('=', 1)
        a.exes[label] = os.path.abspath(path)
        a.ldfcz.setdefault(label, '')
    os.makedirs(a.work, exist_ok=True)
    deck = os.path.join(a.work, 'block.inp')
    with open(deck, 'w') as f:
        f.write(block_deck(a.increments, a.du))
    exe = os.path.abspath(a.exe)
    ccx = shutil.which(a.ccx) if 'ccx' in a.programs else None
    if 'ccx' in a.programs and not ccx:
        sys.exit('bench_calculix: %s not found (tools/setup.sh bench installs calculix-ccx)' % a.ccx)
    rows = []
    for rep in range(a.repeat):
        for nt in a.threads:
            for prog in a.programs:
                wd = os.path.join(a.work, '%s_t%d_r%d' % (prog, nt, rep))
                os.makedirs(wd, exist_ok=True)
                shutil.copy(deck, os.path.join(wd, 'block.inp'))
                env = dict(os.environ, OMP_NUM_THREADS=str(nt))
                la0 = load_avg()
                if prog in a.ldfcz:
                    cmd = [a.exes.get(prog, exe), '-q', '-t', str(nt)] + a.ldfcz[prog].split() + ['block.inp']
                    summary = outputs.summary_path(wd, 'block')
                    if os.path.exists(summary):
                        os.remove(summary)
                    wall, cpu, stamps, _, rss = run_timed(cmd, wd, env, os.path.join(wd, 'block.sta'))
                    incs = ldfcz_increments(stamps)
                    split = summary_split(outputs.read_summary(wd, 'block')) if os.path.exists(summary) else {}
                else:
                    env.update(CCX_NPROC_STIFFNESS=str(nt), CCX_NPROC_EQUATION_SOLVER=str(nt),
                               CCX_NPROC_RESULTS=str(nt))
                    wall, cpu, stamps, _, rss = run_timed([ccx, '-i', 'block'], wd, env,
                                                          os.path.join(wd, 'block.sta'))
                    incs = ccx_increments(stamps)
                    split = {}
                la1 = load_avg()
                if len(incs) != a.increments:
                    sys.exit('bench_calculix: %s -t %d: %d increments seen in the .sta file, %d expected'
                             % (prog, nt, len(incs), a.increments))
                tinc = [incs[0][0]] + [incs[i][0] - incs[i - 1][0] for i in range(1, len(incs))]
                row = dict(prog=prog, threads=nt, rep=rep, wall=wall, cpu=cpu, load=(la0 + la1) / 2,
                           t_inc=tinc, its=[i for _, i in incs], maxrss_kb=rss, **split)
                rows.append(row)
                print('%-5s -t %d rep %d: wall %.1f s, cpu %.1f s, %s kB, load %.1f, per increment %s s, iterations %s '
                      '%s' % (prog, nt, rep, wall, cpu, rss, row['load'], ' '.join('%.2f' % x for x in tinc),
                              row['its'], ' '.join('%s %.1f' % kv for kv in split.items())), flush=True)
    with open(os.path.join(a.work, 'runs.json'), 'w') as f:
        json.dump(rows, f, indent=1)
    if a.md:
        write_md(a, rows)


def write_md(a, rows):
    def med(xs):
        return statistics.median(xs)
    out = ['# ldfcz against CalculiX 2.20: the 40x40x10 C3D8 elastic NLGEOM block', '',
           'Written by `/usr/bin/python3 benchmarks/bench_calculix.py %s` (see the tool\'s docstring for the deck).'
           % shlex.join(sys.argv[1:]), '',
           'Per increment: the wall time between the increment\'s line in JOB.sta and the previous one (the first '
           'increment from the program\'s start: it includes reading the deck and the set-up). "later" is the median '
           'over increments 2..n. Median of %d repeats, [min-max] in brackets. CPU: user + system of the whole run.'
           % a.repeat, '',
           '| program | threads | iterations per increment | wall (s) | CPU (s) | first increment (s) | later increment (s) | '
           'assembly / factorization / solve (s) | peak resident memory (MiB) | load average |',
           '|---|---|---|---|---|---|---|---|---|---|']
    summary = {}
    for nt in a.threads:
        for prog in a.programs:
            rs = [r for r in rows if r['prog'] == prog and r['threads'] == nt]
            if not rs:
                continue
            first = [r['t_inc'][0] for r in rs]
            later = [med(r['t_inc'][1:]) if len(r['t_inc']) > 1 else float('nan') for r in rs]
            walls = [r['wall'] for r in rs]
            rss = [r['maxrss_kb'] / 1024 for r in rs if r.get('maxrss_kb')]
            summary[(prog, nt)] = (med(walls), med(later), med([r['cpu'] for r in rs]), med(rss) if rss else None)
            split = ''
            if prog in a.ldfcz and all('assembly' in r for r in rs):
                split = '%.1f / %.1f / %.1f' % tuple(med([r[k] for r in rs]) for k in ('assembly', 'factorization', 'solve'))
            out.append('| %s | %d | %s | %.1f [%.1f-%.1f] | %.1f | %.2f [%.2f-%.2f] | %.2f [%.2f-%.2f] | %s | %s | %.1f-%.1f |' % (
                prog, nt, ' '.join(map(str, rs[0]['its'])), med(walls), min(walls), max(walls),
                med([r['cpu'] for r in rs]), med(first), min(first), max(first), med(later), min(later), max(later),
                split, '%.0f [%.0f-%.0f]' % (med(rss), min(rss), max(rss)) if rss else '', min(r['load'] for r in rs),
                max(r['load'] for r in rs)))
    out += ['', 'ldfcz configurations: ' + ', '.join('%s = `%s -q -t N %s`' % (k, a.exes.get(k, 'ldfcz'), v)
                                                  for k, v in a.ldfcz.items() if k in a.programs), '',
            '| threads | CalculiX / ldfcz, wall of the run | CalculiX / ldfcz, later increment | CalculiX / ldfcz, CPU '
            'of the run | ldfcz / CalculiX, peak memory |', '|---|---|---|---|---|']
    for nt in a.threads:
        for prog in a.programs:
            if prog in a.ldfcz and (prog, nt) in summary and ('ccx', nt) in summary:
                l, c = summary[(prog, nt)], summary[('ccx', nt)]
                mem = '%.2f' % (l[3] / c[3]) if l[3] and c[3] else ''
                what = '%d' % nt if prog == 'ldfcz' else '%d, ldfcz %s (%s)' % (nt, prog, ', '.join(
                    x for x in ['`%s`' % a.ldfcz[prog] if a.ldfcz[prog] else '',
                                a.exes.get(prog, '')] if x))
                out.append('| %s | %.2f | %.2f | %.2f | %s |' % (what, c[0] / l[0], c[1] / l[1], c[2] / l[2], mem))
    out += ['', 'Every run, in the order run:', '', '| program | threads | repeat | wall (s) | CPU (s) | per increment '
            '(s) | iterations | peak resident (kB) | load average |', '|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        out.append('| %s | %d | %d | %.1f | %.1f | %s | %s | %s | %.1f |' % (
            r['prog'], r['threads'], r['rep'], r['wall'], r['cpu'], ' '.join('%.2f' % x for x in r['t_inc']),
            ' '.join(map(str, r['its'])), r.get('maxrss_kb') or '', r['load']))
    os.makedirs(os.path.dirname(a.md) or '.', exist_ok=True)
    with open(a.md, 'w') as f:
        f.write('\n'.join(out) + '\n')
    print('wrote', a.md)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
