#!/usr/bin/env python3
"""The first Newton iteration of an increment carries the prescribed increment through the tangent
(host/analysis/newton_iteration.f90; docs/host.md "Newton iteration"): it solves K_ff du_f = r_f - K_fp du_p at the
start of the increment, the prescribed dofs at their start values, instead of evaluating the elements with the
prescribed dofs already at their end values.

Deck: an 8x4x2 block of 1 mm C3D8 elements (tools/ldfcz_tools/block_deck.py, the benchmark block made small),
clamped at x = 0 and pulled by 0.1 mm per fixed increment at x = 8 (10 % strain of the element layer beside the
loaded face, were the increment applied to the boundary nodes alone), EXTRAPOLATION=NO so that every increment
starts from the converged state and carries its whole prescribed increment.

  linear: NLGEOM=NO, linear elasticity: the carried first iteration is the exact solution, so every increment
     converges in one iteration with its residual at round-off (r/q < 1e-11; measured ~1e-13, the linear criterion
     of convergence_check is 1e-8), and the reaction is linear in the pull (RF at increment k = k RF at increment 1,
     rtol 1e-9). A missing or wrong K_fp du_p leaves a residual of the order of the first one after the solve.
  nonlinear: NLGEOM=YES: the residual after the first correction is smaller than the carried prediction of the
     first iteration in every increment (it grew 6x when the increment was applied to the boundary nodes first:
     r/q 2.9 -> 16.6), and Newton, converging quadratically from there (r/q ~0.08 -> ~1e-3 < R_n = 5e-3), needs two
     iterations per increment (three before). The reactions agree with a run of 4x smaller increments within
     the Newton tolerance (R_n of the force scale, and the hypoelastic path dependence: rtol 5e-3).

  check_first_iteration.py --exe BIN --out DIR
"""
import argparse
import csv
import os
import subprocess
import sys

from ldfcz_tools.block_deck import block_deck


def fail(msg):
    print('FAIL: ' + msg)
    sys.exit(1)


def check(name, ok, detail):
    print('%-70s %s %s' % (name, detail, 'ok' if ok else 'FAIL'))
    if not ok:
        fail(name)


def run(exe, out, name, text):
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, name + '.inp')
    with open(deck, 'w') as f:
        f.write(text)
    res = subprocess.run([exe, '--quiet', '--threads', '1', '--out', out, deck], capture_output=True, text=True)
    if res.returncode != 0:
        fail('ldfcz exited %d on %s: %s' % (res.returncode, deck, res.stderr))
    incs = []
    for line in open(os.path.join(out, name + '.sta')):
        w = line.split()
        if len(w) >= 7 and not w[0].startswith('#') and w[6] == 'converged':
            ratios = [float(x) for x in line.split('r/q:')[1].split()]
            incs.append((int(w[3]), ratios))
    rows = list(csv.DictReader(open(os.path.join(out, name + '.csv'))))
    return incs, [float(r['LOAD.RF1']) for r in rows]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--exe', required=True)
    ap.add_argument('--out', required=True)
    a = ap.parse_args()
    size = dict(nx=8, ny=4, nz=2)

    incs, rf = run(a.exe, a.out, 'linear', block_deck(3, 0.1, nlgeom=False, extrapolation='NO', **size))
    print('linear: iterations and r/q per increment:', incs)
    check('linear: 3 increments of one iteration each', [n for n, _ in incs] == [1, 1, 1], str([n for n, _ in incs]))
    worst = max(r[1] for _, r in incs)
    check('linear: residual after the first iteration at round-off (r/q < 1e-11)', worst < 1e-11, '%.2e' % worst)
    dev = max(abs(rf[k] - (k + 1) * rf[0]) for k in range(3)) / abs(rf[2])
    check('linear: reaction proportional to the pull (rtol 1e-9)', dev < 1e-9, '%.2e' % dev)

    incs, rf = run(a.exe, a.out, 'nonlinear', block_deck(3, 0.1, extrapolation='NO', **size))
    print('nonlinear: iterations and r/q per increment:', incs)
    for k, (n, r) in enumerate(incs):
        check('nonlinear increment %d: residual after the first correction < the first' % (k + 1), r[1] < r[0],
              '%.3e vs %.3e' % (r[1], r[0]))
    check('nonlinear: two iterations per increment', [n for n, _ in incs] == [2, 2, 2], str([n for n, _ in incs]))
    _, rf_fine = run(a.exe, os.path.join(a.out, 'fine'), 'nonlinear_fine',
                     block_deck(12, 0.025, extrapolation='NO', **size))
    dev = max(abs(rf[k] - rf_fine[4 * k + 3]) / abs(rf_fine[4 * k + 3]) for k in range(3))
    check('nonlinear: reactions equal to those of 4x smaller increments (rtol 5e-3)', dev < 5e-3, '%.2e' % dev)
    print('PASS')


if __name__ == '__main__':
    main()
