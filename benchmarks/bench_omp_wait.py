#!/usr/bin/env python3
"""Do the element loop's idle OpenMP workers take CPU during the (sequential) MUMPS factorization? (issue 20)

Runs ldfcz on a deck (default: the benchmark block of bench_calculix.py, tools/ldfcz_tools/block_deck.py, with 2
increments of 0.1 mm, 52 767 equations) in several configurations (threads and OpenMP environment), and samples every thread's CPU time from
/proc/PID/task/TID/stat every 0.1 s. Reported per run: wall and CPU time of the run, the closing summary's
assembly / factorization / solve wall times, and the CPU time of each thread (main thread first). A worker that
spins beside the factorization shows a CPU time near assembly + factorization; one that sleeps, near assembly
(its share of the element loop).

  /usr/bin/python3 benchmarks/bench_omp_wait.py --exe build/bin/ldfcz --repeat 2 \\
      --config "t1=-t 1" --config "t2=-t 2" --config "t2-active=-t 2" --env t2-active=OMP_WAIT_POLICY=active \\
      --config "t2-passive=-t 2" --env t2-passive=OMP_WAIT_POLICY=passive

Not a test (minutes); the figures are in docs/performance.md.
"""
import argparse
import os
import shlex
import statistics
import subprocess
import sys
import threading
import time

from bench_calculix import summary_split
from ldfcz_tools import outputs
from ldfcz_tools.block_deck import block_deck
from ldfcz_tools.cli import executable

TICK = os.sysconf('SC_CLK_TCK')


def thread_cpu(pid):
    """{tid: (name, cpu seconds)} of the threads of pid."""
    out = {}
    try:
        tids = os.listdir('/proc/%d/task' % pid)
    except OSError:
        return out
    for tid in tids:
        try:
            with open('/proc/%d/task/%s/stat' % (pid, tid)) as f:
                st = f.read()
        except OSError:
            continue
        name = st[st.index('(') + 1:st.rindex(')')]
        fields = st[st.rindex(')') + 2:].split()
        out[int(tid)] = (name, (int(fields[11]) + int(fields[12])) / TICK)  # utime, stime
    return out


def run(exe, args, env, wd, deck):
    p = subprocess.Popen([exe, '-q'] + args + [deck], cwd=wd, env=env)
    last = {}
    t0 = time.monotonic()

    def sample():
        while p.poll() is None:
            cur = thread_cpu(p.pid)
            if cur:
                last.update(cur)
            time.sleep(0.1)
    th = threading.Thread(target=sample, daemon=True)
    th.start()
    rc = p.wait()
    wall = time.monotonic() - t0
    th.join()
    if rc != 0:
        sys.exit('bench_omp_wait: ldfcz exited %d' % rc)
    job = os.path.splitext(os.path.basename(deck))[0]
    doc = outputs.read_summary(wd, job)
    split = summary_split(doc)
    split['wall'], split['cpu'] = doc['times']['wall_s'], doc['times']['cpu_s']
    threads = [last[t][1] for t in sorted(last)]   # the main thread has the lowest id
    return wall, split, threads


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', default='build/bin/ldfcz')
    ap.add_argument('--deck', default='', help='deck (default: the benchmark block, 2 increments)')
    ap.add_argument('--config', action='append', required=True, help='LABEL=ldfcz options')
    ap.add_argument('--env', action='append', default=[], help='LABEL=VAR=VALUE (several allowed)')
    ap.add_argument('--repeat', type=int, default=2)
    ap.add_argument('--work', default='out/bench-omp-wait')
    ap.add_argument('--md', default='')
    a = ap.parse_args()
    executable(a.exe, 'ldfcz program')
    os.makedirs(a.work, exist_ok=True)
    deck = os.path.abspath(a.deck) if a.deck else os.path.join(os.path.abspath(a.work), 'block.inp')
    if not a.deck:
        with open(deck, 'w') as f:
            f.write(block_deck(2, 0.1))
    configs = [c.split('=', 1) for c in a.config]
    envs = {}
    for e in a.env:
        label, kv = e.split('=', 1)
        k, v = kv.split('=', 1)
        envs.setdefault(label, {})[k] = v
    rows = []
    for rep in range(a.repeat):
        for label, opts in configs:
            env = dict(os.environ)
            for k in ('OMP_WAIT_POLICY', 'GOMP_SPINCOUNT'):
                env.pop(k, None)
            env.update(envs.get(label, {}))
            wd = os.path.join(a.work, '%s_r%d' % (label, rep))
            os.makedirs(wd, exist_ok=True)
            load0 = os.getloadavg()[0]
            wall, s, thr = run(os.path.abspath(a.exe), opts.split(), env, wd, deck)
            load1 = os.getloadavg()[0]
            rows.append(dict(label=label, rep=rep, opts=opts, env=envs.get(label, {}), load=(load0 + load1) / 2,
                             threads=thr, **s))
            print('%-12s rep %d: wall %.1f s, CPU %.1f s, assembly %.2f, factorization %.2f (%d), solve %.2f, '
                  'thread CPU %s, load %.1f' % (label, rep, s['wall'], s['cpu'], s['assembly'], s['factorization'],
                                                s['factorizations'], s['solve'],
                                                ' '.join('%.1f' % t for t in thr), rows[-1]['load']), flush=True)
    if a.md:
        out = ['# Idle OpenMP workers beside the MUMPS factorization', '',
               '`/usr/bin/python3 benchmarks/bench_omp_wait.py %s`' % shlex.join(sys.argv[1:]), '',
               'Median of %d repeats [min-max]. Thread CPU: seconds of each thread of the process (main first; '
               'OpenBLAS and MUMPS run on the main thread, the element loop on all OpenMP threads).' % a.repeat, '',
               '| configuration | options | environment | wall (s) | CPU (s) | assembly (s) | factorization (s) | '
               'factorizations | thread CPU (s) | load average |', '|---|---|---|---|---|---|---|---|---|---|']
        for label, opts in configs:
            rs = [r for r in rows if r['label'] == label]

            def med(k):
                xs = [r[k] for r in rs]
                return '%.1f [%.1f-%.1f]' % (statistics.median(xs), min(xs), max(xs))
            thr = ' / '.join(' '.join('%.1f' % t for t in r['threads']) for r in rs)
            out.append('| %s | `%s` | %s | %s | %s | %s | %s | %d | %s | %.1f-%.1f |' % (
                label, opts, ' '.join('%s=%s' % kv for kv in rs[0]['env'].items()) or '-', med('wall'), med('cpu'),
                med('assembly'), med('factorization'), rs[0]['factorizations'], thr,
                min(r['load'] for r in rs), max(r['load'] for r in rs)))
        os.makedirs(os.path.dirname(a.md) or '.', exist_ok=True)
        with open(a.md, 'w') as f:
            f.write('\n'.join(out) + '\n')
        print('wrote', a.md)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
