#!/usr/bin/env python3
"""Two or more builds of ldfcz on the same deck and options, run alternately from the start, timed from outside.

  bench_builds.py --exe LABEL=EXE [--exe LABEL=EXE ...] --deck DECK [--options "OPTIONS"] [--increments K]
                  [--threads T] [--rounds R] [--work DIR] [--md FILE]
  bench_builds.py --application ...     the deck of the paper's application scene (benchmarks/bench_window.py's
                                        generator arguments) with the application's options

Each round runs every build once, in turn (so that all meet the same machine speeds), for the first K increments
(`--stop-after-increments K`), and measures the process from outside: wall seconds and CPU seconds (user + system,
from wait4), and from the files every build writes (JOB.sta, JOB.csv) the increments, attempts and Newton
iterations and the last row of the CSV. Builds older than JOB.summary.json are measured the same way. Prints a
Markdown table of every run and the mean and spread per build, with a stamp (commit of this tree, command, date,
machine, load average before and after); --md writes it to a file too. Nothing here asserts a speed.
Python standard library only.
"""
import argparse
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time

from ldfcz_tools.paths import ROOT

APP_GEN = ['--3d', '--rigid-substrate', '--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.001',
           '--dgamma-max', '1.0', '--fine-length', '1.05', '--bonded', '1.2', '--u-total', '0.72',
           '--field-frequency', '40']
APP_OPTIONS = '--newton auto --max-opening-increment 0.33 --max-plastic-increment 1.0 --factors symmetric-single'


def sta_counts(path):
    """Converged increments, attempts and Newton iterations of a JOB.sta (the columns every build writes)."""
    inc = att = its = 0
    if not os.path.exists(path):
        return inc, att, its
    for line in open(path, errors='replace'):
        w = line.split()
        if len(w) < 7 or not w[0].isdigit():
            continue
        att += 1
        its += int(w[3])
        if w[6] == 'converged':
            inc += 1
    return inc, att, its


def last_row(path):
    if not os.path.exists(path):
        return ''
    rows = [ln.strip() for ln in open(path) if ln.strip()]
    return rows[-1] if len(rows) > 1 else ''


def run_once(exe, deck, options, k, threads, outdir):
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(outdir)
    cmd = [exe, '-q', '-t', str(threads)] + options.split() + ['--stop-after-increments', str(k), '-o', outdir, deck]
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(proc.pid, 0)
    wall = time.monotonic() - t0
    code = os.waitstatus_to_exitcode(status)
    job = os.path.splitext(os.path.basename(deck))[0]
    inc, att, its = sta_counts(os.path.join(outdir, job + '.sta'))
    return {'exit': code, 'wall': wall, 'cpu': ru.ru_utime + ru.ru_stime, 'inc': inc, 'att': att, 'its': its,
            'last': last_row(os.path.join(outdir, job + '.csv'))}


def stamp(argv):
    try:
        commit = subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short=12', 'HEAD'], capture_output=True,
                                text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = 'unknown'
    return 'Stamp: commit %s; command `%s`; %s; machine %s, %d cores visible.' % (
        commit, ' '.join(['benchmarks/bench_builds.py'] + argv), time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime()),
        platform.node(), os.cpu_count() or 1)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', action='append', required=True, help='LABEL=EXECUTABLE (two or more)')
    ap.add_argument('--deck', help='the deck (or --application)')
    ap.add_argument('--application', action='store_true', help="the application scene and its options")
    ap.add_argument('--options', help='ldfcz options (default: the application\'s with --application, else none)')
    ap.add_argument('--increments', type=int, default=60)
    ap.add_argument('--threads', type=int, default=1)
    ap.add_argument('--rounds', type=int, default=3)
    ap.add_argument('--work', default=os.path.join(ROOT, 'out', 'bench-builds'))
    ap.add_argument('--md', help='write the table to this file too')
    a = ap.parse_args(argv)
    exes = []
    for e in a.exe:
        if '=' not in e:
            ap.error('--exe needs LABEL=EXECUTABLE, got %r' % e)
        label, exe = e.split('=', 1)
        if not os.access(exe, os.X_OK):
            ap.error('%s is not an executable' % exe)
        exes.append((label, os.path.abspath(exe)))
    os.makedirs(a.work, exist_ok=True)
    if a.application:
        deck = os.path.join(a.work, 'app.inp')
        subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'peel_deck.py')] + APP_GEN + ['-o', deck],
                       check=True, stdout=subprocess.DEVNULL)
        options = APP_OPTIONS if a.options is None else a.options
    elif a.deck and os.path.isfile(a.deck):
        deck = os.path.abspath(a.deck)
        options = a.options or ''
    else:
        ap.error('give --deck FILE (an existing deck) or --application')
    load0 = os.getloadavg()[0]
    runs = []
    for r in range(a.rounds):
        for label, exe in exes:
            res = run_once(exe, deck, options, a.increments, a.threads, os.path.join(a.work, '%s_%d' % (label, r)))
            res.update(label=label, round=r + 1)
            runs.append(res)
            print('round %d %s: exit %d, %.1f s wall, %.1f s CPU, %d increments, %d attempts, %d iterations' % (
                r + 1, label, res['exit'], res['wall'], res['cpu'], res['inc'], res['att'], res['its']), flush=True)
    load1 = os.getloadavg()[0]
    out = ['# Builds on one deck, alternated', '', stamp(argv), '',
           'Deck `%s`, options `%s`, the first %d increments, `-t %d`, %d rounds; load average %.1f before, %.1f '
           'after.' % (os.path.basename(deck), options, a.increments, a.threads, a.rounds, load0, load1), '',
           '| round | build | exit | wall (s) | CPU (s) | increments | attempts | Newton iterations |',
           '|---|---|---|---|---|---|---|---|']
    for res in runs:
        out.append('| %d | %s | %d | %.1f | %.1f | %d | %d | %d |' % (
            res['round'], res['label'], res['exit'], res['wall'], res['cpu'], res['inc'], res['att'], res['its']))
    out += ['', '| build | wall mean (s) | spread | CPU mean (s) | spread | last CSV row |', '|---|---|---|---|---|---|']
    for label, _ in exes:
        mine = [x for x in runs if x['label'] == label]
        w = [x['wall'] for x in mine]
        c = [x['cpu'] for x in mine]
        out.append('| %s | %.1f | %.1f-%.1f | %.1f | %.1f-%.1f | `%s` |' % (
            label, statistics.mean(w), min(w), max(w), statistics.mean(c), min(c), max(c), mine[-1]['last'][:80]))
    text = '\n'.join(out) + '\n'
    print(text)
    if a.md:
        os.makedirs(os.path.dirname(os.path.abspath(a.md)), exist_ok=True)
        open(a.md, 'w').write(text)
    return 0 if all(x['exit'] in (0, 3) for x in runs) else 1


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
