#!/usr/bin/env python3
"""Snapshot and compare the outputs of a test run: the proof that a behaviour-preserving change preserved behaviour.

  outputs_snapshot.py save BUILD_DIR DEST     copy every JOB.csv and JOB.dat that the tests wrote under
                                              BUILD_DIR/tests into DEST (same relative paths)
  outputs_snapshot.py compare OLD NEW [--rtol R] [--atol A]
                                              compare two snapshots file by file, number by number

The comparison splits each line into words; words that parse as numbers are compared with |a - b| <= atol +
rtol max(|a|, |b|) (default rtol 1e-9, atol 1e-300: round-off of the printed digits and of reordered sums), other
words exactly. Timings are not in CSV or JOB.dat, so no word is skipped. Exit status 0 when every file of OLD is in
NEW and matches, 1 otherwise (each difference listed: file, line, first differing word, relative difference); files
only in NEW are listed, not failures. Runs whose path takes wall times into account (none should: docs/host.md
"Reproducible runs") would show here as differences.
"""
import argparse
import math
import os
import shutil
import sys


def _outputs(root):
    """Relative paths of the CSV and JOB.dat files under root, sorted."""
    found = []
    for d, dirs, files in os.walk(root):
        # identify.py's run caches are named by a hash of each run's inputs, which differs between runs of the
        # failure tests: their CSVs are compared through the tests' own outputs instead
        dirs[:] = [x for x in dirs if x != 'cache']
        for f in files:
            if f.endswith(('.csv', '.dat')):
                found.append(os.path.relpath(os.path.join(d, f), root))
    return sorted(found)


def save(build, dest):
    src = os.path.join(build, 'tests')
    if not os.path.isdir(src):
        print(f'outputs_snapshot: {src}: no such folder (run the tests of that build first)', file=sys.stderr)
        return 2
    files = _outputs(src)
    for rel in files:
        os.makedirs(os.path.join(dest, os.path.dirname(rel)), exist_ok=True)
        shutil.copy2(os.path.join(src, rel), os.path.join(dest, rel))
    print(f'outputs_snapshot: {len(files)} files saved in {dest}')
    return 0


def _number(word):
    try:
        v = float(word)
    except ValueError:
        return None
    return v


def _compare_file(a, b, rtol, atol):
    """First difference of two files as text, None if they match; worst relative difference of the numbers."""
    with open(a, errors='replace') as fa, open(b, errors='replace') as fb:
        la, lb = fa.read().splitlines(), fb.read().splitlines()
    worst = 0.0
    if len(la) != len(lb):
        return f'{len(la)} lines against {len(lb)}', worst
    for i, (x, y) in enumerate(zip(la, lb), 1):
        if x == y:
            continue
        wx, wy = x.replace(',', ' ').split(), y.replace(',', ' ').split()
        if len(wx) != len(wy):
            return f'line {i}: {len(wx)} words against {len(wy)}', worst
        for u, v in zip(wx, wy):
            if u == v:
                continue
            nu, nv = _number(u), _number(v)
            if nu is None or nv is None:
                return f'line {i}: {u!r} against {v!r}', worst
            if math.isnan(nu) and math.isnan(nv):
                continue
            d = abs(nu - nv)
            scale = max(abs(nu), abs(nv))
            rel = d / scale if scale > 0 else 0.0
            worst = max(worst, rel)
            if d > atol + rtol * scale:
                return f'line {i}: {u} against {v} (relative {rel:.2e})', worst
    return None, worst


def compare(old, new, rtol, atol):
    fa, fb = _outputs(old), set(_outputs(new))
    bad = 0
    worst_all = 0.0
    for rel in fa:
        if rel not in fb:
            print(f'MISSING {rel}')
            bad += 1
            continue
        diff, worst = _compare_file(os.path.join(old, rel), os.path.join(new, rel), rtol, atol)
        worst_all = max(worst_all, worst)
        if diff:
            print(f'DIFFERS {rel}: {diff}')
            bad += 1
    for rel in sorted(fb - set(fa)):
        print(f'NEW     {rel}')
    print(f'outputs_snapshot: {len(fa)} files compared, {bad} differ or are missing; largest relative difference '
          f'of a number within tolerance {worst_all:.2e}')
    return 1 if bad else 0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest='cmd', required=True)
    s = sub.add_parser('save')
    s.add_argument('build')
    s.add_argument('dest')
    c = sub.add_parser('compare')
    c.add_argument('old')
    c.add_argument('new')
    c.add_argument('--rtol', type=float, default=1e-9)
    c.add_argument('--atol', type=float, default=1e-300)
    a = p.parse_args(argv)
    if a.cmd == 'save':
        return save(a.build, a.dest)
    return compare(a.old, a.new, a.rtol, a.atol)


if __name__ == '__main__':
    sys.exit(main())
