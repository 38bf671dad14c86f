#!/usr/bin/env python3
"""Two runs of the paper's application scene in alternating segments, so that both meet the same machine speeds:
by default one process x T threads against N processes x 1 thread (docs/performance.md, "Serial against 2
processes, in alternating segments"), or any two commands (--run), e.g. two builds of ldfcz.

  bench_alternate.py [--deck DECK] [--work DIR] [--serial EXE] [--mpi EXE] [--ranks N] [--threads T]
                     [--segment K] [--until HH:MM | --budget S] [--options "..."] [--md FILE]
  bench_alternate.py --run LABEL=COMMAND --run LABEL=COMMAND [--options "..."] ...   (two commands: the launch
                     of ldfcz up to its options, e.g. --run "e9cbdfd=/path/e9cbdfd/ldfcz -q -t 2"
                     --run "now=build/bin/ldfcz -q -t 2"; --options are given to both)
  bench_alternate.py --resume --work DIR [--deck DECK] [--until HH:MM | --budget S] ...
                                                  (an earlier comparison continued from its restart files)
  bench_alternate.py --report DIR [--md FILE]     (the tables of an earlier or interrupted comparison)

On a shared or virtual machine the speed of the same run varies by 10-30 % between hours, more than the difference
between the two configurations; two whole runs one after the other compare hours as much as codes. Here both runs
start from the deck and advance by K converged increments at a time (default 100: `--restart-write K
--stop-after-increments K`, then `--restart-from` their own restart files), taking turns: serial then distributed,
then distributed then serial, and so on, until the time given (--until, a wall-clock time of today, or --budget
seconds from the start) has passed; the pair under way is completed. Each run keeps its own directory
(DIR/serial, DIR/mpi); a segment that fails ends the comparison and leaves no record that --resume would count
(its console file says why); restarting costs both the same (the restart file is read, MUMPS analyses again, GMRES
starts without factors).

Records per run: the wall time of its segments summed against the pull (LOAD.U1 of JOB.csv, sampled every 2 s:
DIR/progress_RUN.csv), what each segment's process used as measured from outside (wall, CPU time and peak
resident memory of the process and its children: DIR/RUN/segment_NN.json) and each segment's JOB.summary.json
(DIR/RUN/summary_NN.json) when the build writes one. The report: wall time at equal pull of the two runs and their
ratio; each run's counts (increments, attempts, cutbacks, Newton iterations from JOB.sta; factorizations and GMRES
iterations from the summaries), wall and CPU time and peak memory from outside, and its time split summed over
its segments (element loop, factorization, solve, the host's communication on rank 0) with its mean cost of a
Leonov element call from the summaries ('n/a' for a build that writes none, such as e9cbdfd: nothing is taken
from JOB.log); and, for the default deck, the pull and wall time at which each run's field frames show 1.0 mm of
delamination (the paper's application measure; the front found as tools/peel_study.py finds it, interpolated
between frames).

Defaults: the deck of `tools/peel_study.py application` generated into DIR (tools/peel_deck.py), its solver options
(`--newton auto --max-opening-increment 0.33 --max-plastic-increment 1.0 --factors symmetric-single`), serial
build/bin/ldfcz with 2 threads, build-mpi/bin/ldfcz under `mpirun -np 2 --bind-to none` with 1 thread each.
Each run continues from its own restart files, so builds that read only their own restart format compare alike.
Python standard library only (tools/ldfcz_tools: the run summary, peel_study's CSV and VTU front readers).
"""
import argparse
import csv
import glob
import json
import os
import shlex
import shutil
import subprocess
import sys
import time

from ldfcz_tools import outputs
from ldfcz_tools.paths import ROOT
from ldfcz_tools.peel_study import frame_front, last_u1  # a frame's front; LOAD.U1 of the last CSV row

GEN = ['--3d', '--rigid-substrate', '--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.001',
       '--dgamma-max', '1.0', '--fine-length', '1.05', '--bonded', '1.2', '--u-total', '0.72',
       '--field-frequency', '40']
OPTIONS = '--newton auto --max-opening-increment 0.33 --max-plastic-increment 1.0 --factors symmetric-single'
LEGACY_RUNS = ('serial', 'mpi')


def run_labels(work):
    """The two runs of a comparison: DIR/runs.json, else the legacy pair (serial, mpi)."""
    path = os.path.join(work, 'runs.json')
    if os.path.exists(path):
        with open(path) as fh:
            return [r['label'] for r in json.load(fh)]
    return list(LEGACY_RUNS)


def progress(work, run):
    """(wall s, pull mm) samples of a run."""
    with open(os.path.join(work, 'progress_%s.csv' % run)) as fh:
        return [(float(r['wall_s']), float(r['U1_mm'])) for r in csv.DictReader(fh)]


def wall_at(prog, u):
    """Wall time at pull u, interpolated in the samples (None beyond them)."""
    for k in range(1, len(prog)):
        if prog[k][1] >= u:
            (w0, a0), (w1, a1) = prog[k - 1], prog[k]
            return w0 + (u - a0) / (a1 - a0) * (w1 - w0) if a1 > a0 else w1
    return None


def segment_summary(path):
    """Times of one segment (the run summary of a run that started or restarted: its times are its own) and the
    counters at its end (they continue over a restart)."""
    doc = outputs.read_summary_file(path)
    c, t = doc['counters'], doc['times']
    umat = doc['element_cost']['umat_continuum']
    return {'inc': c['increments'], 'att': c['attempts'], 'cut': c['cutbacks'], 'its': c['iterations'],
            'fac': c['factorizations'], 'gmres': c['gmres_iterations'], 'wall': t['wall_s'],
            'asm': t['element_loop_s'], 'fact': t['factorization_s'], 'solve': t['solve_s'],
            'comm': t['communication_s'], 'umat_us': umat['us_per_call'] or 0.0, 'umat_calls': umat['calls']}


def outside_records(work, run):
    """What each segment's process used, measured from outside (segment_NN.json: wall, cpu, maxrss_kb)."""
    recs = []
    for f in sorted(glob.glob(os.path.join(work, run, 'segment_*.json'))):
        with open(f) as fh:
            recs.append(json.load(fh))
    return recs


def front_info():
    """tools/peel_deck.py's summary of the default deck (initial front x, delta, pull rate, nodes, elements)."""
    deck = os.path.join(os.environ.get('TMPDIR', '/tmp'), 'bench_alternate_%d.inp' % os.getpid())
    res = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'peel_deck.py')] + GEN + ['--info', '-o', deck],
                         capture_output=True, text=True, check=True)
    os.remove(deck)
    return json.loads(res.stderr.strip().splitlines()[-1])


def front_history(work, run, info):
    """(pull mm, delaminated mm) of every field frame of a run (JOB.pvd: a .vtu, or a .pvtu whose pieces are
    JOB_NNNN_R.vtu), the front found as tools/peel_study.py finds it, also written to DIR/front_RUN.csv; without
    the frames (a copy of the records only) that file is read instead. [] unless the run is of the default deck
    (its node and element counts in the first segment's summary, or the run's deck when it writes none)."""
    summaries = sorted(glob.glob(os.path.join(work, run, 'summary_*.json')))
    pvds = glob.glob(os.path.join(work, run, '*.pvd'))
    record = os.path.join(work, 'front_%s.csv' % run)
    if not pvds and os.path.exists(record):
        with open(record) as fh:
            return [(float(r['U1_mm']), float(r['delaminated_mm'])) for r in csv.DictReader(fh)]
    if summaries:
        model = outputs.read_summary_file(summaries[0])['model']
        default = (model.get('nodes'), model.get('elements')) == (info['nodes'], info['elements'])
    else:
        default = os.path.exists(os.path.join(work, 'default_deck'))
    if len(pvds) != 1 or not default:
        return []
    hist = []
    for t, f in outputs.pvd_frames(pvds[0]):
        path = os.path.join(work, run, f)
        pieces = sorted(x for files in outputs.frame_files(path).values() for x in files) \
            if os.path.exists(path) else []
        x = frame_front(pieces, info['delta_mm']) if pieces and all(map(os.path.exists, pieces)) else None
        if x is not None:
            hist.append((float(t) * info['rate_mm_s'], info['x_front_mm'] - x))
    with open(record, 'w') as fh:
        fh.write('U1_mm,delaminated_mm\n' + ''.join('%.6g,%.6g\n' % h for h in hist))
    return hist


def pull_at_delamination(hist, d):
    """Pull at which the delaminated length first reaches d, interpolated between frames (None if it does not)."""
    for k in range(1, len(hist)):
        (u0, d0), (u1, d1) = hist[k - 1], hist[k]
        if d1 >= d > d0:
            return u0 + (d - d0) / (d1 - d0) * (u1 - u0)
    return None


def run_row(work, run):
    """One run's line of the report: counts from JOB.sta (and the summaries when there are), outside measures
    summed over the segments, the summaries' time split (None for what a build does not write)."""
    segs = [segment_summary(f) for f in sorted(glob.glob(os.path.join(work, run, 'summary_*.json')))]
    outside = outside_records(work, run)
    stas = glob.glob(os.path.join(work, run, '*.sta'))
    counts = outputs.sta_counts(stas[0]) if stas else {}
    row = {'segments': max(len(segs), len(outside)), 'inc': counts.get('increments'), 'att': counts.get('attempts'),
           'cut': counts.get('cutbacks'), 'its': counts.get('iterations'), 'fac': None, 'gmres': None,
           'wall': sum(o['wall'] for o in outside) if outside else None,
           'cpu': sum(o['cpu'] for o in outside) if outside else None,
           'rss': max(o['maxrss_kb'] for o in outside) / 1024.0 if outside else None}
    if segs:
        last = segs[-1]
        row.update({'inc': last['inc'], 'att': last['att'], 'cut': last['cut'], 'its': last['its'],
                    'fac': last['fac'], 'gmres': last['gmres']})
        for k in ('asm', 'fact', 'solve', 'comm'):
            row[k] = sum(s[k] for s in segs)
        if row['wall'] is None:
            row['wall'] = sum(s['wall'] for s in segs)
        calls = sum(s['umat_calls'] for s in segs)
        row['umat_us'] = sum(s['umat_us'] * s['umat_calls'] for s in segs) / calls if calls else None
    return row


def cell(v, fmt='%d'):
    return 'n/a' if v is None else fmt % v


def report(work, delamination=1.0):
    """Markdown tables of a comparison in work."""
    runs = run_labels(work)
    progs = [progress(work, r) for r in runs]
    if any(len(p) < 2 for p in progs):
        return 'bench_alternate.py: no progress recorded yet in %s\n' % work
    ps, pm = progs
    umax = min(ps[-1][1], pm[-1][1])
    out = ['| pull (um) | %s (s) | %s (s) | %s / %s |' % (runs[0], runs[1], runs[0], runs[1]), '|---|---|---|---|']
    marks = [u for u in (25, 50, 100, 150, 200, 250, 300, 350, 400, 450, 500, 550, 600, 650, 700)
             if u * 1e-3 < umax]
    for k, u in enumerate(marks + [umax * 1e3]):
        um = umax if k == len(marks) else u * 1e-3      # the common end exactly as recorded (mm)
        a, b = wall_at(ps, um), wall_at(pm, um)
        out.append('| %s | %.0f | %.0f | %.3f |' % ('%.1f (common end)' % u if k == len(marks) else '%g' % u,
                                                  a, b, a / b))
    out += ['', '| run | segments | increments | attempts | cutbacks | Newton iterations | iterations per increment '
            '| factorizations | GMRES iterations | wall (s) | CPU (s) | peak memory (MiB) | element loop (s) '
            '| factorization (s) | solve (s) | host communication (s) | Leonov call (us, mean) |',
            '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for run in runs:
        r = run_row(work, run)
        per = r['its'] / r['inc'] if r['its'] is not None and r['inc'] else None
        out.append('| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            run, r['segments'], cell(r['inc']), cell(r['att']), cell(r['cut']), cell(r['its']), cell(per, '%.2f'),
            cell(r['fac']), cell(r['gmres']), cell(r['wall'], '%.0f'), cell(r['cpu'], '%.0f'),
            cell(r['rss'], '%.0f'), cell(r.get('asm'), '%.0f'), cell(r.get('fact'), '%.0f'),
            cell(r.get('solve'), '%.0f'), cell(r.get('comm'), '%.0f'), cell(r.get('umat_us'), '%.1f')))
    info = front_info()
    rows = []
    for run, prog in zip(runs, progs):
        u = pull_at_delamination(front_history(work, run, info), delamination)
        w = wall_at(prog, u) if u is not None else None
        if w is not None:
            rows.append('| %s | %.1f | %.0f | %.3f |' % (run, 1e3 * u, w, w / 3600))
    if rows:
        out += ['', 'Delamination of %g mm (front of each run\'s field frames as tools/peel_study.py finds it, pull '
                'interpolated between the frames that bracket it, wall time at that pull):' % delamination, '',
                '| run | pull (um) | wall (s) | wall (h) |', '|---|---|---|---|'] + rows
    per_seg = []
    for run in runs:
        segs = sorted(glob.glob(os.path.join(work, run, 'summary_*.json')))
        if segs:
            per_seg.append('%s %s' % (run, ', '.join('%.1f' % segment_summary(f)['umat_us'] for f in segs)))
    if per_seg:
        out += ['', 'Leonov call per segment (us; the machine speed each segment met): ' + '; '.join(per_seg)]
    out += ['', 'Wall time per segment (s, from outside): ' + '; '.join(
        '%s %s' % (run, ', '.join('%.0f' % o['wall'] for o in outside_records(work, run))) for run in runs)]
    return '\n'.join(out) + '\n'


def ranks_of(work):
    path = os.path.join(work, 'ranks.txt')
    return open(path).read().strip() if os.path.exists(path) else 'N'


def define_runs(a, work):
    """[(label, launch command)] of the comparison: --run, or the legacy serial/mpi pair; kept in DIR/runs.json
    (read back by --resume)."""
    path = os.path.join(work, 'runs.json')
    if a.resume and os.path.exists(path):
        with open(path) as fh:
            return [(r['label'], r['command']) for r in json.load(fh)]
    if a.run:
        if len(a.run) != 2:
            sys.exit('bench_alternate.py: give --run twice (two runs are compared)')
        runs = [(lab, shlex.split(cmd)) for lab, cmd in (r.split('=', 1) for r in a.run)]
        if runs[0][0] == runs[1][0] or any(not lab.replace('-', '').replace('_', '').isalnum() for lab, _ in runs):
            sys.exit('bench_alternate.py: --run labels must differ and be letters, digits, - or _')
    else:
        runs = [('serial', [os.path.abspath(a.serial), '-q', '-t', str(a.threads)]),
                ('mpi', ['mpirun', '-np', str(a.ranks), '--bind-to', 'none', os.path.abspath(a.mpi), '-q', '-t', '1'])]
    with open(path, 'w') as fh:
        json.dump([{'label': lab, 'command': cmd} for lab, cmd in runs], fh, indent=1)
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--deck', help='the deck (default: the application deck, generated into --work)')
    ap.add_argument('--work', default=os.path.join(ROOT, 'out', 'bench-alternate'))
    ap.add_argument('--serial', default=os.path.join(ROOT, 'build', 'bin', 'ldfcz'))
    ap.add_argument('--mpi', default=os.path.join(ROOT, 'build-mpi', 'bin', 'ldfcz'))
    ap.add_argument('--ranks', type=int, default=2)
    ap.add_argument('--threads', type=int, default=2, help='threads of the one-process run')
    ap.add_argument('--run', action='append', default=[], help='LABEL=COMMAND (twice): compare these two launches '
                    'instead of --serial/--mpi')
    ap.add_argument('--segment', type=int, default=100, help='converged increments per segment')
    ap.add_argument('--until', help='start no new pair of segments after this time of today (HH:MM)')
    ap.add_argument('--budget', type=float, help='start no new pair after this many seconds')
    ap.add_argument('--options', default=OPTIONS, help='ldfcz options of both runs')
    ap.add_argument('--report', help='only print the tables of the comparison in this directory')
    ap.add_argument('--resume', action='store_true', help='continue the comparison in --work: each run from its '
                    'last restart files, its wall time summed on from its progress file, the turns in order')
    ap.add_argument('--md', help='also write the tables to this file')
    a = ap.parse_args()
    if a.report:
        text = report(a.report)
        print(text, end='')
        if a.md:
            open(a.md, 'w').write(text)
        return
    if a.until:
        hh, mm = map(int, a.until.split(':'))
        now = time.localtime()
        deadline = time.mktime((now.tm_year, now.tm_mon, now.tm_mday, hh, mm, 0, 0, 0, -1))
    elif a.budget is not None:
        deadline = time.time() + a.budget
    else:
        sys.exit('bench_alternate.py: give --until HH:MM or --budget SECONDS')
    os.makedirs(a.work, exist_ok=True)
    runs = define_runs(a, a.work)
    labels = [lab for lab, _ in runs]
    for lab, cmd in runs:
        exe = next((w for w in cmd if os.path.basename(w).startswith('ldfcz')), cmd[0])
        if not os.access(exe, os.X_OK):
            sys.exit('bench_alternate.py: %s (run %s) is not an executable (build first)' % (exe, lab))
    deck = a.deck
    if not deck:
        deck = os.path.join(a.work, 'app.inp')
        open(os.path.join(a.work, 'default_deck'), 'w').write('the deck of tools/peel_study.py application\n')
    if not a.deck and not (a.resume and os.path.exists(deck)):
        subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'peel_deck.py')] + GEN + ['-o', deck],
                       check=True, stdout=subprocess.DEVNULL)
    deck = os.path.abspath(deck)
    job = os.path.splitext(os.path.basename(deck))[0]
    opts = a.options.split() + ['--restart-write', str(a.segment), '--stop-after-increments', str(a.segment)]
    launch = dict(runs)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')
    state = {}
    for run in labels:
        d = os.path.join(a.work, run)
        if a.resume:
            # the segments so far (one record each) and the wall time summed over them
            segs = max(len(glob.glob(os.path.join(d, 'summary_*.json'))),
                       len(glob.glob(os.path.join(d, 'segment_*.json'))))
            if segs == 0 or not glob.glob(os.path.join(d, job + '.rst*')):     # JOB.rst, or JOB.rst.KofN per rank
                sys.exit('bench_alternate.py: nothing to resume in %s (no segment records or no %s.rst)' % (d, job))
            state[run] = {'wall': progress(a.work, run)[-1][0], 'seg': segs}
            continue
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        with open(os.path.join(a.work, 'progress_%s.csv' % run), 'w') as fh:
            fh.write('wall_s,U1_mm\n')
        state[run] = {'wall': 0.0, 'seg': 0}
    if a.resume and (state[labels[0]]['seg'] != state[labels[1]]['seg'] or
                     (not a.run and labels == list(LEGACY_RUNS) and ranks_of(a.work) != str(a.ranks))):
        sys.exit('bench_alternate.py: %s holds %d and %d segments: resume needs whole pairs (and the same --ranks)' % (
            a.work, state[labels[0]]['seg'], state[labels[1]]['seg']))
    open(os.path.join(a.work, 'ranks.txt'), 'w').write(str(a.ranks))
    with open(os.path.join(a.work, 'commands.txt'), 'a' if a.resume else 'w') as fh:
        for run in labels:
            fh.write('%s: %s\n' % (run, ' '.join(launch[run] + ['-o', os.path.join(a.work, run)] + opts +
                                                ['[--restart-from DIR/%s.rst]' % job, deck])))
    log = open(os.path.join(a.work, 'segments.txt'), 'a' if a.resume else 'w')

    def segment(run):
        st, d = state[run], os.path.join(a.work, run)
        cmd = launch[run] + ['-o', d] + opts
        if st['seg'] > 0:
            cmd += ['--restart-from', os.path.join(d, job + '.rst')]
        t0 = time.time()
        prog_path = os.path.join(a.work, 'progress_%s.csv' % run)
        prog_size = os.path.getsize(prog_path)
        with open(os.path.join(d, 'console_%02d.txt' % st['seg']), 'w') as con, open(prog_path, 'a') as prog:
            p = subprocess.Popen(cmd + [deck], env=env, stdout=con, stderr=subprocess.STDOUT)
            last = None
            while True:
                # the process's own resources (and its waited-for children's: mpirun's ranks) at its end
                pid, status, usage = os.wait4(p.pid, os.WNOHANG)
                if pid == p.pid:
                    break
                time.sleep(2)
                u = last_u1(os.path.join(d, job + '.csv'))
                if u is not None and u != last:
                    prog.write('%.2f,%.6g\n' % (st['wall'] + time.time() - t0, u))
                    prog.flush()
                    last = u
            wall = time.time() - t0
            rc = os.waitstatus_to_exitcode(status)
            p.returncode = rc
            u = last_u1(os.path.join(d, job + '.csv'))
            if rc in (0, 3):
                st['wall'] += wall
                if u is not None:
                    prog.write('%.2f,%.6g\n' % (st['wall'], u))
        if rc not in (0, 3):
            # a failed segment leaves no trace that a --resume would count: its progress rows are dropped, its
            # records are not kept as a segment (the console file says why it failed)
            with open(prog_path, 'r+') as prog:
                prog.truncate(prog_size)
            log.write('%s %s segment %d: failed, exit %d (not counted)\n' % (time.strftime('%H:%M:%S'), run,
                                                                            st['seg'], rc))
            log.flush()
            return rc
        with open(os.path.join(d, 'segment_%02d.json' % st['seg']), 'w') as fh:
            json.dump({'wall': wall, 'cpu': usage.ru_utime + usage.ru_stime, 'maxrss_kb': usage.ru_maxrss,
                       'exit': rc, 'load': os.getloadavg()[0], 'end': time.strftime('%Y-%m-%d %H:%M:%S')}, fh)
        if os.path.exists(outputs.summary_path(d, job)):
            shutil.copy(outputs.summary_path(d, job), os.path.join(d, 'summary_%02d.json' % st['seg']))
        log.write('%s %s segment %d: exit %d, %.1f s, %.1f s in all, pull %.6g mm, load %.2f\n' % (
            time.strftime('%H:%M:%S'), run, st['seg'], rc, wall, st['wall'], u, os.getloadavg()[0]))
        log.flush()
        st['seg'] += 1
        return rc

    pair, ended = state[labels[0]]['seg'], False     # the turns go on in order after a resume
    while time.time() < deadline and not ended:
        for run in (labels if pair % 2 == 0 else labels[::-1]):
            rc = segment(run)
            if rc == 0:
                ended = True        # the analysis is complete (the other run completes in its turn)
            elif rc != 3:
                sys.exit('bench_alternate.py: the %s run failed (exit %d; %s)' % (run, rc, os.path.join(
                    a.work, run, 'console_%02d.txt' % state[run]['seg'])))
        pair += 1
    text = report(a.work)
    print(text, end='')
    if a.md:
        open(a.md, 'w').write(text)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
