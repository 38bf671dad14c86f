#!/usr/bin/python3
"""Short peel regression checks (CTest, registered by tests/studies.cmake): generate decks with tools/peel_deck.py,
run ldfcz on them and assert physical facts with stated tolerances.

  check_peel.py refinement LDFCZ WORKDIR   coarse plane-strain peel (rigid substrate) at l_e = 20 um and 10 um:
      both runs complete; a peel front advances (two fine cohesive elements opened past delta); the steady force
      per unit width is steady (spread over the averaging window below SPREAD_TOL) and stable under the refinement
      (|F_20/F_10 - 1| below REFINE_TOL), 3 elements over the coating; global energy balance of each run below ENERGY_TOL.
  check_peel.py symmetry LDFCZ WORKDIR     3D quarter model (YSYMM on the mid-width plane) against the same model
      over the full width without the symmetry plane: RF1_full = 2 RF1_quarter at every increment within SYM_TOL,
      mean U2 of the loaded face of the full model zero (no out-of-plane drift), and the quarter's loaded face
      contracts towards the symmetry plane (U2 < 0: the plane is active and the edge y = b free).
  check_peel.py readings LDFCZ WORKDIR     plane-strain peel of each reading of Fig. 10 (A: 0-degree bridge, B: flap
      lifted at 90 degrees): plateau found, pull work above phi times the delaminated length, value within the
      measured discretisation error of the mesh-converged plateau, energy balance (constants below).
Exit status 0 when every assertion holds, 1 otherwise (each failure printed).
"""
import os
import sys

from ldfcz_tools import peel_study

# Tolerances (measured values in docs/scenes.md, Release and Debug builds give the same numbers):
# - refinement: the steady force changes by 0.5-1 % from l_e = 20 to 10 um (and 0.2 % from 10 to 5 um); 3 % is
#   three times the measured change, and ten times smaller than the drop a broken tangent, a lost cohesive law or
#   a wrong width normalisation would produce (the force would fall to the flap's draw force, -35 %, or double).
REFINE_TOL = 0.03
# - spread of the force over the last 30 % of the pull: 2-3 % measured (one cohesive element passing the front at a
#   time modulates the force); 6 % allows the coarse mesh's larger ripple and fails on a force still rising.
SPREAD_TOL = 0.06
# - energy balance |W_ext - (stored + dissipated)| / W_ext: the host integrates the external work with the
#   trapezoidal rule, the UMAT its dissipation with the mid-point rule (second order, umat/umat.f); measured
#   0.2-0.3 % (the rest: the cohesive law's own integration and the model's J-dependent term, docs/umat.md).
#   1 %: a missing dissipation term (the cohesive phi per delaminated area alone is 15-20 % of W_ext here) or the
#   former first-order bookkeeping (1.1 % at 0.3 um/inc) fails it.
ENERGY_TOL = 0.01
# - quarter against full width: the full model's Newton iterates are the mirror extensions of the quarter's, so the
#   forces agree to round-off (1e-11 measured); 1e-6 leaves room for a different cutback sequence.
SYM_TOL = 1e-6
DRIFT_TOL = 1e-9   # mm: mean U2 of the full model's loaded face (1e-16 measured; quarter's contraction ~1e-3 mm)

COMMON = ['--rigid-substrate', '--u-total', '0.05', '--du', '0.0003']


def fail(msgs, text):
    print('FAIL: ' + text)
    msgs.append(text)


def refinement(ldfcz, work):
    bad = []
    res = {}
    for le, nz in ((0.02, 3), (0.01, 3)):
        label = 'ps_le%g' % (le * 1e3)
        r = peel_study.run_case(label, COMMON + ['--le', str(le), '--nz', str(nz)], work, ldfcz, 1, 0.3)
        res[le] = r
        print('%s: F/w = %.4f N/mm, spread %.3f, delaminated %.4f mm, energy balance %s, %.1f s' % (
            label, r['F_w_tail'], r['spread'], r['delaminated_mm'], r.get('energy_rel_diff'), r['run_time_s']))
        if not r['completed']:
            fail(bad, '%s did not complete (exit %d, U1 = %g mm)' % (label, r['exit'], r['u_end_mm']))
            continue
        # front = centre of the last cohesive element opened past delta: > l_e means two elements past the peak
        if not r['delaminated_mm'] > le:
            fail(bad, '%s: the front advanced %.4f mm, less than two elements: no peel' % (label, r['delaminated_mm']))
        if not r['spread'] < SPREAD_TOL:
            fail(bad, '%s: force not steady: spread %.3f >= %.3f' % (label, r['spread'], SPREAD_TOL))
        e = r.get('energy_rel_diff', float('nan'))
        if not e < ENERGY_TOL:
            fail(bad, '%s: energy balance %.3e >= %.3e' % (label, e, ENERGY_TOL))
    if all(r['completed'] for r in res.values()):
        # the mean over the last 30 % of the 50 um pull for both (too short a pull for the plateau estimator at
        # l_e = 20 um: the front crosses 3 elements only at its end; peel_readings checks the plateaus)
        d = abs(res[0.02]['F_w_tail'] / res[0.01]['F_w_tail'] - 1.0)
        print('refinement l_e 20 -> 10 um: |F_20/F_10 - 1| = %.4f (tolerance %.3f)' % (d, REFINE_TOL))
        if not d < REFINE_TOL:
            fail(bad, 'steady force not stable under refinement: %.4f >= %.3f' % (d, REFINE_TOL))
    return bad


# Readings of Fig. 10 (issue 17): plane strain, rigid substrate, l_e = 10 um, n_z = 3, 0.1 mm of pull over a 0.16 mm
# fine region. Reading A: the 0-degree bridge. Reading B: the flap lifted at 90 degrees and pulled by a fixed grip
# (the grip's line stays at x = const, so the peel angle falls towards ~55 degrees as the front runs away: a
# plateau within 0.1 mm of pull; the carriage grip, which keeps 90 degrees, has not settled within 0.16 mm and is
# a study case, not a regression). Asserted for each reading:
# - the steady-force estimator finds a plateau (status ok) with an uncertainty below UNC_TOL; reading B's fixed grip
#   keeps turning the peel angle, and by the cycle-mean test of issue 35 (drift and curvature below 0.2 %) its
#   0.1 mm pull has not settled (measured drift 0.85 % over the last 14 um): for B a 'no-plateau' is accepted while
#   the cycle means drift and curve by less than SETTLE_B (2 %: a force still rising by the 5-10 % of the
#   start-up, or a broken cohesive law, fails it);
# - energy: over the plateau window the work of the pull exceeds the interface's phi times the delaminated length
#   (F/w du >= phi da; the rest is the coating's plastic work); a lost cohesive law or a wrong width normalisation
#   breaks it;
# - the value agrees with the finest mesh of the l_e study (l_e = 2.5 um, same scene: A 1.1964 N/mm, reports/
#   stmt-mesh-x; B fixed grip 0.5167 N/mm, first pass of stmt-mesh-x, docs/scenes.md) within READ_TOL: the measured
#   l_e = 10 um discretisation error (A 0.28 %, B 0.7 %) plus three times the two runs' uncertainties (A 0.05 and
#   0.1 %, B 0.7 and 0.6 %), rounded up: A 1 %, B 5 %.
READINGS = {
    'A': (['--rigid-substrate', '--u-total', '0.1', '--fine-length', '0.16'], 1.1964, 0.01),
    'B': (['--rigid-substrate', '--reading', 'peel', '--flap', '0.1', '--u-total', '0.1', '--fine-length', '0.16'],
          0.5167, 0.05),
}
UNC_TOL = 0.02
SETTLE_B = 0.02


def readings(ldfcz, work):
    bad = []
    for k, (args, f_conv, tol) in READINGS.items():
        r = peel_study.run_case('reading_' + k, args, work, ldfcz, 1, 0.3)
        est = r['steady']
        print('reading %s: %s; delaminated %.4f mm; energy balance %s; %.1f s' % (
            k, peel_study.sfe.describe(est), r['delaminated_mm'], r.get('energy_rel_diff'), r['run_time_s']))
        if not r['completed']:
            fail(bad, 'reading %s did not complete (exit %d)' % (k, r['exit']))
            continue
        settled = est['status'] == 'ok' or (k == 'B' and est['status'] == 'no-plateau' and
                                            abs(est['drift']) < SETTLE_B and abs(est['curvature']) < SETTLE_B)
        if not settled or not est['uncertainty'] < UNC_TOL:
            fail(bad, 'reading %s: no plateau (%s, drift %.3g, curvature %.3g, uncertainty %.3g)' % (
                k, est['status'], est['drift'], est['curvature'], est['uncertainty']))
        hist = peel_study.front_history(r)
        u0, u1 = est['window']
        da = interp(u1, [h[0] for h in hist], [h[1] for h in hist]) - interp(u0, [h[0] for h in hist],
                                                                           [h[1] for h in hist])
        work_pull = est['value'] * (u1 - u0)
        phi = 0.2
        print('  plateau window %.1f-%.1f um: F/w du = %.4e N/mm, phi da = %.4e N/mm' % (1e3 * u0, 1e3 * u1,
                                                                                        work_pull, phi * da))
        if not work_pull > phi * da:
            fail(bad, 'reading %s: pull work %.4e below the interface energy %.4e' % (k, work_pull, phi * da))
        dev = abs(est['value'] / f_conv - 1)
        print('  against the converged %.4f N/mm: %.2f %% (tolerance %.1f %%)' % (f_conv, 100 * dev, 100 * tol))
        if not dev < tol:
            fail(bad, 'reading %s: F/w %.4f differs from the converged %.4f by %.2f %%' % (k, est['value'], f_conv,
                                                                                       100 * dev))
        e = r.get('energy_rel_diff', float('nan'))
        if not e < ENERGY_TOL:
            fail(bad, 'reading %s: energy balance %.3e >= %.3e' % (k, e, ENERGY_TOL))
    return bad


def interp(x, xs, ys):
    for i in range(1, len(xs)):
        if xs[i] >= x:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] > xs[i - 1] else 0.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return ys[-1]


def read_cols(path, names):
    import csv
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    return [[float(r[n]) for r in rows] for n in names]


def symmetry(ldfcz, work):
    bad = []
    args = ['--3d', '--rigid-substrate', '--le', '0.02', '--nz', '1', '--ny', '1', '--width', '0.02',
            '--bonded', '0.2', '--u-total', '0.006', '--du', '0.0005']
    rq = peel_study.run_case('quarter', args, work, ldfcz, 1, 0.3)
    rf = peel_study.run_case('full', args + ['--full-width'], work, ldfcz, 1, 0.3)
    for r in (rq, rf):
        if not r['completed']:
            fail(bad, '%s model did not complete (exit %d)' % (r['label'], r['exit']))
    if bad:
        return bad
    uq, fq, vq = read_cols(os.path.join(work, 'quarter', 'quarter.csv'), ['LOAD.U1', 'LOAD.RF1', 'LOAD.U2'])
    uf, ff, vf = read_cols(os.path.join(work, 'full', 'full.csv'), ['LOAD.U1', 'LOAD.RF1', 'LOAD.U2'])
    worst = max(abs(interp(u, uf, ff) - 2.0 * f) / abs(2.0 * f) for u, f in zip(uq, fq) if f != 0.0)
    drift = max(abs(v) for v in vf)
    print('quarter vs full width: max |RF1_full - 2 RF1_quarter| / |2 RF1_quarter| = %.2e (tolerance %.1e); '
          'max |mean U2| full = %.2e mm; quarter mean U2 at the end = %.3e mm' % (worst, SYM_TOL, drift, vq[-1]))
    if not worst < SYM_TOL:
        fail(bad, 'quarter model differs from the full-width model: %.2e' % worst)
    if not drift < DRIFT_TOL:
        fail(bad, 'out-of-plane drift of the full-width model: %.2e mm' % drift)
    if not vq[-1] < -1e-6:
        fail(bad, 'quarter model: the loaded face does not contract towards the symmetry plane (U2 = %.3e)' % vq[-1])
    return bad


def main(argv):
    if len(argv) != 4 or argv[1] not in ('refinement', 'symmetry', 'readings'):
        print(__doc__)
        return 2
    ldfcz, work = argv[2], argv[3]
    os.makedirs(work, exist_ok=True)
    bad = {'refinement': refinement, 'symmetry': symmetry, 'readings': readings}[argv[1]](ldfcz, work)
    print('check_peel %s: %s' % (argv[1], 'FAILED (%d)' % len(bad) if bad else 'passed'))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
