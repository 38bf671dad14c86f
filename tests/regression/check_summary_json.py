#!/usr/bin/env python3
"""JOB.summary.json (docs/summary.md) for every way a run ends: valid JSON with exactly the documented keys, a status
and exit code that match the program's, counters consistent with JOB.sta and with each other, and a restart that
continues the counters to the uninterrupted run's.

  check_summary_json.py --exe BIN --decks DECKS_DIR --doc docs/summary.md --out DIR [--np N]

Runs (decks/single unless said): cohesive_block completed; nonconvergence (exit 3); cohesive_block stopped after 5 increments
(--stop-after-increments, restart data written) and restarted from them to the end; a restart from another deck's
restart file (input error found after the deck was read); a deck error in a directory holding an earlier summary
(the summary goes); a UEL that calls XIT (decks/bad/runtime/uel_phi_zero.inp). With --np N every run is under mpirun -np N (the LDFCZ_MPI build) and the summary must carry the
processes' balance (key mpi).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from ldfcz_tools import outputs


def fail(msg):
    print('FAIL: ' + msg)
    sys.exit(1)


def documented_keys(doc_path):
    """The keys of docs/summary.md's table (first column, in backquotes)."""
    keys = set()
    with open(doc_path) as f:
        for line in f:
            m = re.match(r'^\| `([^`]+)` \|', line)
            if m:
                keys.add(m.group(1))
    if len(keys) < 50:
        fail('%s: only %d keys found in its table' % (doc_path, len(keys)))
    return keys


def run(a, deck, out, *opts):
    cmd = [a.exe, '-q', '-t', '1', '-o', out, *opts, deck]
    if a.np > 1:
        cmd = ['mpirun', '-np', str(a.np), '--oversubscribe', '--bind-to', 'none'] + cmd
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if re.search(r'Fortran runtime error|Backtrace|Program received signal', p.stderr):
        fail('%s crashed:\n%s' % (' '.join(cmd), p.stderr[-2000:]))
    return p.returncode


def check_keys(doc, documented, what):
    """Every documented key present (unless its parent is null), none undocumented."""
    got = outputs.summary_keys(doc)
    extra = sorted(got - documented)
    if extra:
        fail('%s: keys not in docs/summary.md: %s' % (what, extra))
    missing = []
    for k in sorted(documented - got):
        parent = k.rsplit('.', 1)[0] if '.' in k else None
        if parent and '[]' not in parent and outputs.get(doc, parent) is None and parent in got:
            continue   # a member of a null object (restart, mpi)
        if parent and parent.endswith('[]') and not doc.get(parent[:-2]):
            continue   # a member of the records of an empty array
        missing.append(k)
    if missing:
        fail('%s: documented keys missing: %s' % (what, missing))


def summary_of(out, job, what, documented, status, exit_code, procs, stopped_attempt=0):
    """The run's summary, checked for the keys, the status and the consistency of its counters."""
    path = outputs.summary_path(out, job)
    if os.path.exists(path + '.tmp'):
        fail('%s: the temporary %s.tmp is left' % (what, path))
    doc = outputs.read_summary(out, job)
    if doc is None:
        fail('%s: no %s' % (what, path))
    check_keys(doc, documented, what)
    if doc['status'] != status or doc['exit_code'] != exit_code:
        fail('%s: status %s, exit code %s; expected %s, %d' % (what, doc['status'], doc['exit_code'], status,
                                                              exit_code))
    # the processes' balance is measured by a run that reached its first step (times known)
    if doc['processes'] != procs or (procs > 1 and doc['times']['wall_s'] is not None) != (doc['mpi'] is not None):
        fail('%s: processes %s, mpi %s with %d processes' % (what, doc['processes'], doc['mpi'], procs))
    c = doc['counters']
    # every failed attempt has one cause; an attempt converges or is cut back (or is the one a user routine stopped)
    if sum(doc['cutbacks_by_cause'].values()) != c['cutbacks']:
        fail('%s: cutbacks by cause %s do not sum to %d' % (what, doc['cutbacks_by_cause'], c['cutbacks']))
    if c['attempts'] != c['increments'] + c['cutbacks'] + stopped_attempt:
        fail('%s: attempts %d != increments %d + cutbacks %d' % (what, c['attempts'], c['increments'],
                                                                c['cutbacks']))
    if sum(s['increments'] for s in doc['steps']) != c['increments'] or \
            sum(s['cutbacks'] for s in doc['steps']) != c['cutbacks']:
        fail('%s: the steps %s do not add up to the counters %s' % (what, doc['steps'], c))
    if outputs.summary_nonfinite(doc):
        fail('%s: figures null: %s' % (what, outputs.summary_nonfinite(doc)))
    print('%-28s %-25s exit %d, %d increments, %d attempts, cutbacks %s' % (
        what, doc['status'], doc['exit_code'], c['increments'], c['attempts'],
        {k: v for k, v in doc['cutbacks_by_cause'].items() if v}))
    return doc


def against_sta(doc, out, job, what):
    """The counters equal JOB.sta's count of its attempts (a fresh run: the file holds every attempt)."""
    n = outputs.sta_counts(os.path.join(out, job + '.sta'))
    c = doc['counters']
    got = {k: c[k] for k in n}
    if got != n:
        fail('%s: counters %s, JOB.sta %s' % (what, got, n))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--exe', required=True)
    ap.add_argument('--decks', required=True, help='decks/single')
    ap.add_argument('--doc', required=True, help='docs/summary.md')
    ap.add_argument('--out', required=True)
    ap.add_argument('--np', type=int, default=1)
    a = ap.parse_args()
    documented = documented_keys(a.doc)
    shutil.rmtree(a.out, ignore_errors=True)
    blk = os.path.join(a.decks, 'cohesive_block.inp')

    full = os.path.join(a.out, 'completed')
    rc = run(a, blk, full)
    ref = summary_of(full, 'cohesive_block', 'completed', documented, 'completed', 0, a.np)
    against_sta(ref, full, 'cohesive_block', 'completed')
    if rc != 0 or not ref['steps'][-1]['completed'] or ref['restart'] is not None:
        fail('completed: exit %d, steps %s, restart %s' % (rc, ref['steps'], ref['restart']))
    # the energy balance closes to the trapezoidal rule's error on this smooth path (JOB.log prints 2.13E-03)
    if not 0 <= ref['energy']['relative_difference'] < 1e-2:
        fail('completed: energy relative difference %s' % ref['energy']['relative_difference'])

    nc = os.path.join(a.out, 'no_convergence')
    rc = run(a, os.path.join(a.decks, 'nonconvergence.inp'), nc)
    doc = summary_of(nc, 'nonconvergence', 'no convergence', documented, 'no_convergence', 3, a.np)
    against_sta(doc, nc, 'nonconvergence', 'no convergence')
    if rc != 3 or doc['steps'][-1]['completed'] or doc['cutbacks_by_cause']['iteration_limit'] < 1:
        fail('no convergence: exit %d, steps %s, causes %s' % (rc, doc['steps'], doc['cutbacks_by_cause']))

    cut = os.path.join(a.out, 'stopped')
    rc = run(a, blk, cut, '--restart-write', '1', '--stop-after-increments', '5')
    doc = summary_of(cut, 'cohesive_block', 'stopped after 5 increments', documented, 'stopped_after_increments', 3,
                     a.np)
    if rc != 3 or doc['counters']['increments'] != 5 or doc['stop_after_increments'] != 5:
        fail('stopped: exit %d, counters %s' % (rc, doc['counters']))
    rst = os.path.join(cut, 'cohesive_block.rst')
    rc = run(a, blk, cut, '--restart-from', rst)
    doc = summary_of(cut, 'cohesive_block', 'restarted', documented, 'completed', 0, a.np)
    if rc != 0 or doc['restart'] is None or doc['restart']['increments_before'] != 5:
        fail('restarted: exit %d, restart %s' % (rc, doc['restart']))
    # the counters continue to the uninterrupted run's; the energies too, bit for bit on one process (the restart
    # repeats the arithmetic), within 1e-9 on several (MUMPS sums in message arrival order: tests/mpi.cmake)
    rel = 0.0 if a.np == 1 else 1e-9
    for k in ('counters', 'cutbacks_by_cause'):
        if doc[k] != ref[k]:
            fail('restarted: %s %s against the uninterrupted %s' % (k, doc[k], ref[k]))
    got = [(s['increments'], s['cutbacks'], s['completed'], s['total_time'], s['external_work']) for s in doc['steps']]
    want = [(s['increments'], s['cutbacks'], s['completed'], s['total_time'], s['external_work']) for s in ref['steps']]
    pairs = [(doc['energy'][k], ref['energy'][k]) for k in ('external_work', 'stored_dissipated')]
    pairs += [(x[4], y[4]) for x, y in zip(got, want)]
    if [x[:4] for x in got] != [y[:4] for y in want] or any(abs(x - y) > rel * abs(y) for x, y in pairs):
        fail('restarted: steps %s, energies %s against the uninterrupted run' % (got, pairs))

    # an error found after the deck was read: a restart file of another deck
    bad = os.path.join(a.out, 'input_error')
    rc = run(a, os.path.join(a.decks, 'nonconvergence.inp'), bad, '--restart-from', rst)
    doc = summary_of(bad, 'nonconvergence', 'restart of another deck', documented, 'input_error', 2, a.np)
    if rc != 2 or doc['times']['wall_s'] is not None or doc['counters']['increments'] != 0:
        fail('input error: exit %d, times %s, counters %s' % (rc, doc['times'], doc['counters']))

    # a user routine's XIT in the first increment (its properties rejected): stopped, the attempt counted
    xit = os.path.join(a.out, 'user_routine')
    rc = run(a, os.path.join(a.decks, '..', 'bad', 'runtime', 'uel_phi_zero.inp'), xit)
    doc = summary_of(xit, 'uel_phi_zero', 'XIT in a UEL', documented, 'stopped_by_user_routine', 2, a.np,
                     stopped_attempt=1)
    if rc != 2 or doc['counters']['increments'] != 0 or doc['times']['wall_s'] is None:
        fail('XIT: exit %d, counters %s, times %s' % (rc, doc['counters'], doc['times']))

    # a deck error in a directory with an earlier run's summary: that summary goes, and the deck error's own is
    # written (status input_error, no model size: the deck was not read)
    with open(os.path.join(full, 'cohesive_block.inp'), 'w') as f:
        f.write('*HEADING\nbroken\n*NODE\n1, 0., 0., x\n')
    rc = run(a, os.path.join(full, 'cohesive_block.inp'), full)
    doc = summary_of(full, 'cohesive_block', 'deck error', documented, 'input_error', 2, a.np)
    if rc != 2 or doc['model']['nodes'] != 0 or doc['counters']['increments'] != 0 or \
            doc['times']['wall_s'] is not None:
        fail('deck error: exit %d, model %s, counters %s, times %s' % (rc, doc['model'], doc['counters'],
                                                                        doc['times']))
    print('deck error                   its own summary (input_error, no model), exit 2')
    print('PASS')


if __name__ == '__main__':
    main()
