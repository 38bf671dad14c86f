#!/usr/bin/env python3
"""Where a run's memory goes, per component, for one or more builds (docs/performance.md "Memory").

  memory_breakdown.py --exe LABEL=BUILD/bin/ldfcz [--exe ...] [--deck block|FILE] [--threads T] [--work DIR]
                      [--md FILE]

Each build runs the deck twice: under heaptrack (tools/setup.sh bench installs it), whose peak-memory consumers
(`heaptrack_print --print-peaks`: the heap each allocation site held at the moment of the peak of the whole heap)
are summed per component, and alone under GNU time for the peak resident set (%M: what the CalculiX comparison
reports; MUMPS reserves work space that it does not touch, so the heap's peak exceeds it). A site is put in a
component by its function and, for the host's allocations, by the text of its source line (read from the file
heaptrack names, so a build with line information is needed: RelWithDebInfo, `-g`):

  MUMPS factors and work space    dmumps_* and mumps_* of the factorization and solve
  MUMPS input and analysis        mumps_analyse (MUMPS' copy of the entries, IRN/JCN/A) and dmumps_ana*
  matrix: element slot maps       build_slot_map (where each element matrix entry goes)
  matrix: pattern and values      sparse_setup, build_pattern (the host's entries: row/column indices, values)
  element reference geometry      solid_element_geometry, solid_compact_geometry and analysis_init's geo arrays
  element states                  element_state_allocate, analysis_init's conv/trial arrays (converged and trial)
  dof vectors, element forces     analysis_init's dof vectors (u, u_conv, fint, fext, fdl) and element forces
  model and the rest              everything else (deck, boundaries, loads, output, Newton vectors, ...)

The deck `block` is the CalculiX comparison's (benchmarks/bench_calculix.py: 40x40x10 C3D8, *ELASTIC, NLGEOM) with
one increment: the peak is its first factorization. Prints (and with --md writes) the table in MiB.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from ldfcz_tools.block_deck import block_deck

COMPONENTS = ['MUMPS factors and work space', 'MUMPS input and analysis', 'matrix: element slot maps',
              'matrix: pattern and values', 'element reference geometry', 'element states',
              'dof vectors, element forces', 'model and the rest']
UNITS = {'B': 1.0, 'K': 1e3, 'M': 1e6, 'G': 1e9}


def size_bytes(text):
    m = re.match(r'([0-9.]+)([KMG]?)', text)
    return float(m.group(1)) * UNITS[m.group(2) or 'B']


def source_line(path, line):
    try:
        with open(path, errors='replace') as f:
            for k, text in enumerate(f, 1):
                if k == line:
                    return text
    except OSError:
        pass
    return ''


def component(function, where):
    """The component of an allocation site (function name, 'file:line' or '')."""
    f = function.lower()
    text = ''
    if where:
        path, _, line = where.rpartition(':')
        text = source_line(path, int(line)) if line.isdigit() else ''
    if 'mumps_analyse' in f or 'dmumps_ana' in f or 'smumps_ana' in f:
        return 'MUMPS input and analysis'
    if 'mumps' in f:
        return 'MUMPS factors and work space'
    if 'build_slot_map' in f:
        return 'matrix: element slot maps'
    if 'sparse_setup' in f or 'build_pattern' in f:
        return 'matrix: pattern and values'
    if 'solid_element_geometry' in f or 'compact_geometry' in f or ('analysis_init' in f and 'geo' in text):
        return 'element reference geometry'
    if 'analysis_init' in f and re.search(r'%(u|u_conv|fint|fe|fext|fdl|fdle)\s*\(', text):
        return 'dof vectors, element forces'
    if 'element_state_allocate' in f or ('analysis_init' in f and ('conv' in text or 'trial' in text)):
        return 'element states'
    return 'model and the rest'


def peaks(zst):
    """(bytes, function, 'file:line') of every peak-memory consumer heaptrack_print lists."""
    out = subprocess.run(['heaptrack_print', '-f', zst, '--print-peaks', '1', '--print-allocators', '0',
                          '--print-temporary', '0', '--print-leaks', '0', '--peak-limit', '1000'],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout.splitlines()
    found = []
    for k, line in enumerate(out):
        m = re.match(r'^([0-9.]+[KMG]?) peak memory consumed over', line)
        if not m:
            continue
        function = out[k + 1].strip() if k + 1 < len(out) else ''
        where = ''
        if k + 2 < len(out) and out[k + 2].strip().startswith('at '):
            where = out[k + 2].strip()[3:]
        found.append((size_bytes(m.group(1)), function, where))
    summary = subprocess.run(['heaptrack_print', '-f', zst], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             text=True).stdout
    m = re.search(r'peak heap memory consumption: ([0-9.]+[KMG]?)', summary)
    return found, size_bytes(m.group(1)) if m else float('nan')


def run(label, exe, deck, threads, work):
    wd = os.path.join(work, label)
    os.makedirs(wd, exist_ok=True)
    shutil.copy(deck, os.path.join(wd, 'job.inp'))
    env = dict(os.environ, OPENBLAS_NUM_THREADS='1', OMP_NUM_THREADS=str(threads))
    rss_file = os.path.abspath(os.path.join(wd, 'maxrss.txt'))
    subprocess.run(['/usr/bin/time', '-f', '%M', '-o', rss_file, exe, '-q', '-t', str(threads), 'job.inp'], cwd=wd,
                   env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(rss_file) as f:
        rss = int(f.read().split()[-1]) * 1024
    zst = os.path.join(os.path.abspath(wd), 'heaptrack')
    for old in os.listdir(wd):
        if old.startswith('heaptrack.'):
            os.remove(os.path.join(wd, old))
    subprocess.run(['heaptrack', '-o', zst, exe, '-q', '-t', str(threads), 'job.inp'], cwd=wd, env=env, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    zfile = [os.path.join(wd, f) for f in os.listdir(wd) if f.startswith('heaptrack.')][0]
    sites, heap = peaks(zfile)
    per = dict.fromkeys(COMPONENTS, 0.0)
    for size, function, where in sites:
        per[component(function, where)] += size
    per['model and the rest'] += max(0.0, heap - sum(per.values()))
    return per, heap, rss


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', action='append', required=True, help='LABEL=PATH of an ldfcz build (with -g)')
    ap.add_argument('--deck', default='block', help="'block' (the CalculiX comparison's, 1 increment) or a deck file")
    ap.add_argument('--threads', type=int, default=1)
    ap.add_argument('--work', default='out/memory-breakdown')
    ap.add_argument('--md', default='')
    a = ap.parse_args()
    if not shutil.which('heaptrack'):
        sys.exit('memory_breakdown: heaptrack not found (tools/setup.sh bench installs it)')
    os.makedirs(a.work, exist_ok=True)
    deck = a.deck
    if deck == 'block':
        deck = os.path.join(a.work, 'block.inp')
        with open(deck, 'w') as f:
            f.write(block_deck(1, 0.1))
    results = []
    for spec in a.exe:
        label, path = spec.split('=', 1)
        results.append((label,) + run(label, os.path.abspath(path), deck, a.threads, a.work))
    mib = 1024.0 * 1024.0
    lines = ['| component (MiB at the heap\'s peak) | ' + ' | '.join(r[0] for r in results) + ' |',
             '|---|' + '---|' * len(results)]
    for c in COMPONENTS:
        lines.append('| %s | %s |' % (c, ' | '.join('%.1f' % (r[1][c] / mib) for r in results)))
    lines.append('| **heap at its peak (heaptrack)** | %s |' % ' | '.join('%.1f' % (r[2] / mib) for r in results))
    lines.append('| **peak resident set (GNU time %%M)** | %s |' % ' | '.join('%.1f' % (r[3] / mib)
                                                                             for r in results))
    text = '\n'.join(lines) + '\n'
    sys.stdout.write(text)
    if a.md:
        with open(a.md, 'w') as f:
            f.write(text)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
