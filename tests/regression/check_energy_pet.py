#!/usr/bin/python3
"""Energy balance of the Leonov UMAT on one C3D8 element (issue 17, item 6): loading, holding, unloading.

  check_energy_pet.py LDFCZ WORKDIR

The host integrates the external work of the reactions with the trapezoidal rule; the UMAT returns
SSE = psi / J and SPD (the viscoplastic dissipation accumulated with the mid-point rule on tau_bar dgamma_p/dt),
per unit current volume (umat/umat.f, docs/umat.md). Two histories of PET (Table 1):

1. simple shear u_1 = gamma(t) X_3 on every node (J = 1 exactly, rotations included): gamma 0 -> 1 in 50 s, held
   50 s, back to 0.5 in 20 s (strain rates 0.02-0.025 /s: the material yields, relaxes in the hold and unloads
   elastically then flows in reverse). With J = 1 the model's stress derives from psi, so the balance must close
   up to the time integration: |W - (E + D)| / W below CLOSE_TOL at 1 s increments, and falling at least
   ORDER_RATIO times when the increments are 4 times smaller (second order: 16). The former end-of-increment
   dissipation tau_bar_(n+1) dgamma_p gave 3.4e-2 and 9.3e-3 (first order): this check fails on it.
2. uniaxial tension (faces x, y, z = 0 symmetric, u_1 on x = 1: 0 -> 0.5 -> held -> 0.3, J varies by ~1 %):
   the Cauchy form of the model (sigma = G dev Be~ + ..., Eqs. 31-33) has no exact stored energy when J varies
   (the Kirchhoff stress of J psi_dev would carry an extra pressure J psi_dev, a few MPa against kappa (J-1));
   psi_ref = J psi_dev + psi_vol leaves a model-intrinsic residual of ~3e-4 that does not depend on the increment.
   Asserted: below UNIAXIAL_TOL at 1 s and 0.25 s increments, and the two differ by less than UNIAXIAL_DT_TOL
   (no first-order bookkeeping term left: the former rule gave 2.9e-2 and 7.9e-3).
Exit status 0 when every assertion holds.
"""
import os
import subprocess
import sys

from ldfcz_tools import outputs

CLOSE_TOL = 1e-4        # measured 1.6e-5 at 1 s increments
ORDER_RATIO = 8.0       # measured 14 (second order gives 16)
UNIAXIAL_TOL = 1e-3     # measured 2.6e-4 (model-intrinsic, see above)
UNIAXIAL_DT_TOL = 5e-5  # measured < 1e-6 change between 1 s and 0.25 s increments

MAT = """*SOLID SECTION, ELSET=CUBE, MATERIAL=PET
*MATERIAL, NAME=PET
**LDFCZ BUILTIN, UMAT=LEONOV
*USER MATERIAL, CONSTANTS=10, UNSYMM
1250., 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.990
200., -4.
*DEPVAR
11
"""
NODES = """*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
"""


def deck(kind, dt):
    s = '*HEADING\nPET energy balance, %s, %g s increments (tests/regression/check_energy_pet.py)\n' % (kind, dt)
    s += NODES
    if kind == 'shear':
        s += '*NSET, NSET=BOT\n1, 2, 3, 4\n*NSET, NSET=TOP\n5, 6, 7, 8\n*NSET, NSET=ALL8\n1, 2, 3, 4, 5, 6, 7, 8\n'
        s += MAT + '*BOUNDARY\nALL8, 2, 3, 0.\nBOT, 1, 1, 0.\n'
        load, hist = 'TOP, 1, 1, %g', (('load', 50, 1.0), ('hold', 50, 1.0), ('unload', 20, 0.5))
    else:
        s += ('*NSET, NSET=X0\n1, 4, 5, 8\n*NSET, NSET=TOP\n2, 3, 6, 7\n*NSET, NSET=Y0\n1, 2, 5, 6\n'
              '*NSET, NSET=Z0\n1, 2, 3, 4\n')
        s += MAT + '*BOUNDARY\nX0, XSYMM\nY0, YSYMM\nZ0, ZSYMM\n'
        load, hist = 'TOP, 1, 1, %g', (('load', 50, 0.5), ('hold', 50, 0.5), ('unload', 20, 0.3))
    for name, period, target in hist:
        s += ('*STEP, NLGEOM=YES, INC=100000\n%s\n*STATIC, DIRECT\n%g, %g\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-9\n'
              '*BOUNDARY\n' + load + '\n*NODE PRINT, NSET=TOP, TOTALS=YES\nRF1, U1\n*END STEP\n') % (
                  name, dt, period, target)
    return s


def balance(ldfcz, work, kind, dt):
    job = '%s_%g' % (kind, dt)
    path = os.path.join(work, job + '.inp')
    with open(path, 'w') as fh:
        fh.write(deck(kind, dt))
    out = os.path.join(work, job)
    subprocess.run([ldfcz, '-q', '-t', '1', '-o', out, path], check=True)
    # the run summary's energy balance (JOB.summary.json)
    energy = outputs.read_summary(out, job)['energy']
    w, e, rel = energy['external_work'], energy['stored_dissipated'], energy['relative_difference']
    print('%-8s dt = %-5g W = %.4e N mm, E + D = %.4e N mm, relative difference %.2e' % (kind, dt, w, e, rel))
    return rel


def main():
    ldfcz, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    bad = []
    s1, s4 = balance(ldfcz, work, 'shear', 1.0), balance(ldfcz, work, 'shear', 0.25)
    if not s1 < CLOSE_TOL:
        bad.append('simple shear: balance %.2e >= %.0e at 1 s increments' % (s1, CLOSE_TOL))
    if not s1 > ORDER_RATIO * s4:
        bad.append('simple shear: balance %.2e -> %.2e with 4x smaller increments, not second order' % (s1, s4))
    u1, u4 = balance(ldfcz, work, 'uniaxial', 1.0), balance(ldfcz, work, 'uniaxial', 0.25)
    if not (u1 < UNIAXIAL_TOL and u4 < UNIAXIAL_TOL):
        bad.append('uniaxial: balance %.2e, %.2e >= %.0e' % (u1, u4, UNIAXIAL_TOL))
    if not abs(u1 - u4) < UNIAXIAL_DT_TOL:
        bad.append('uniaxial: balance depends on the increment (%.2e vs %.2e)' % (u1, u4))
    for b in bad:
        print('FAIL: ' + b)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
