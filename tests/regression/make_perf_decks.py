#!/usr/bin/env python3
"""Writes two single-element decks of decks/single/ (run once; the decks are committed):

c3d8_umat_uniaxial.inp  one C3D8 unit cube with the Leonov UMAT (Table 1 PET) under homogeneous uniaxial stress:
    u1 of the face x = 1 follows ln(lambda_1) = rate * t (tabular amplitude at every increment time, DIRECT
    increments), lateral faces free; compared by check_perf_decks.py with bin/material_point (mode uniaxial, the
    same rate, increments and PROPS).
c3d8_rotation_uniaxial.inp  one C3D8 unit cube, built-in *ELASTIC (hypoelastic, Jaumann), every node prescribed
    by x = R(t) U(t) X: stretch lambda along the body's axis 1 with the lateral stretch lambda^-nu (zero lateral
    stress for log strains), superposed rotation about z up to 90 degrees. Closed form: Cauchy stress
    R diag(E ln lambda, 0, 0) R^T, so the reaction on the face X1 = 1 is E ln(lambda) lambda^(-2 nu) R e1.
"""
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, 'decks', 'single')

CUBE = """*NODE, NSET=ALL
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


def amplitude(name, times, values):
    lines = ['*AMPLITUDE, NAME=%s, DEFINITION=TABULAR' % name]
    pairs = ['%.10g, %.12g' % (t, v) for t, v in zip(times, values)]
    for k in range(0, len(pairs), 4):
        lines.append(', '.join(pairs[k:k + 4]))
    return '\n'.join(lines) + '\n'


def umat_deck(rate=1e-3, strain_end=0.3, steps=100):
    t_end = strain_end / rate
    times = [t_end * k / steps for k in range(steps + 1)]
    amp = amplitude('STRETCH', times, [math.exp(rate * t) - 1.0 for t in times])
    return ("""*HEADING
C3D8 + Leonov UMAT (Table 1 PET), homogeneous uniaxial stress at true strain rate %g /s to %g: against bin/material_point
** Units: mm, N, s, MPa. Unit cube; face x = 1 pulled with u1 = exp(rate t) - 1; faces x = 0, y = 0, z = 0 symmetric.
** tests/regression/make_perf_decks.py writes this deck; tests/regression/check_perf_decks.py checks it.
""" % (rate, strain_end) + CUBE + """*NSET, NSET=X0
1, 4, 5, 8
*NSET, NSET=X1
2, 3, 6, 7
*NSET, NSET=Y0
1, 2, 5, 6
*NSET, NSET=Z0
1, 2, 3, 4
*NSET, NSET=CORNER
7
*SOLID SECTION, ELSET=CUBE, MATERIAL=PET
*MATERIAL, NAME=PET
**LDFCZ BUILTIN, UMAT=LEONOV
*USER MATERIAL, CONSTANTS=10, UNSYMM
1250., 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.990
200., -4.
*DEPVAR
11
**LDFCZ STATEV, MATERIAL=PET, PLASTIC STRAIN=7
""" + amp + """*BOUNDARY
X0, XSYMM
Y0, YSYMM
Z0, ZSYMM
*STEP, NLGEOM=YES, INC=1000
*STATIC, DIRECT
%.10g, %.10g
** lateral equilibrium far tighter than Abaqus' default R_n = 0.005 (the comparison is with a tight driver)
*CONTROLS, PARAMETERS=FIELD
1e-7, 1e-6
*BOUNDARY, AMPLITUDE=STRETCH
X1, 1, 1, 1.
*NODE PRINT, NSET=X1, TOTALS=YES
RF1
*NODE PRINT, NSET=CORNER, TOTALS=YES
U1, U2, U3
*END STEP
""" % (t_end / steps, t_end))


def rotation_deck(young=1000.0, nu=0.3, lam_end=1.2, theta_end_deg=90.0, steps=60):
    times = [k / steps for k in range(steps + 1)]
    lam = [1.0 + (lam_end - 1.0) * t for t in times]
    lat = [v ** (-nu) for v in lam]
    th = [math.radians(theta_end_deg) * t for t in times]
    # x = R U X: columns R U e1 = lam (c, s, 0), R U e2 = lat (-s, c, 0), R U e3 = lat e3
    a = {
        'A1': [l * math.cos(t) - 1.0 for l, t in zip(lam, th)],            # u1 of X = e1
        'A2': [l * math.sin(t) for l, t in zip(lam, th)],                  # u2 of X = e1
        'A3': [-m * math.sin(t) for m, t in zip(lat, th)],                 # u1 of X = e2
        'A4': [m * math.cos(t) - 1.0 for m, t in zip(lat, th)],            # u2 of X = e2
        'A5': [m - 1.0 for m in lat],                                      # u3 of X = e3
    }
    a['A13'] = [p + q for p, q in zip(a['A1'], a['A3'])]                  # X = e1 + e2
    a['A24'] = [p + q for p, q in zip(a['A2'], a['A4'])]
    amps = ''.join(amplitude(k, times, v) for k, v in a.items())
    # node: (X1, X2, X3); u1, u2 from the in-plane position, u3 from X3
    nodes = {1: (0, 0, 0), 2: (1, 0, 0), 3: (1, 1, 0), 4: (0, 1, 0), 5: (0, 0, 1), 6: (1, 0, 1), 7: (1, 1, 1),
             8: (0, 1, 1)}
    bcs = ['*BOUNDARY\n1, 1, 3\n2, 3, 3\n3, 3, 3\n4, 3, 3\n5, 1, 2\n']
    for n, (x1, x2, x3) in nodes.items():
        key = {(1, 0): ('A1', 'A2'), (0, 1): ('A3', 'A4'), (1, 1): ('A13', 'A24')}.get((x1, x2))
        if key:
            bcs.append('*BOUNDARY, AMPLITUDE=%s\n%d, 1, 1, 1.\n' % (key[0], n))
            bcs.append('*BOUNDARY, AMPLITUDE=%s\n%d, 2, 2, 1.\n' % (key[1], n))
        if x3 == 1:
            bcs.append('*BOUNDARY, AMPLITUDE=A5\n%d, 3, 3, 1.\n' % n)
    return ("""*HEADING
C3D8 *ELASTIC under NLGEOM: uniaxial stress along the body axis while the body rotates 90 degrees about z
** Units: mm, N, MPa. x = R(t) U(t) X on every node: U = diag(lambda, lambda^-nu, lambda^-nu), lambda 1 -> %g,
** R about z, 0 -> %g degrees, both linear in time. Closed form: sigma = R diag(E ln lambda, 0, 0) R^T; reaction of the
** face X1 = 1: E ln(lambda) lambda^(-2 nu) (cos, sin, 0).
** tests/regression/make_perf_decks.py writes this deck; tests/regression/check_perf_decks.py checks it.
""" % (lam_end, theta_end_deg) + CUBE + """*NSET, NSET=FACE
2, 3, 6, 7
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
%g, %g
""" % (young, nu) + amps + """*STEP, NLGEOM=YES, INC=1000
*STATIC, DIRECT
%.10g, 1.
""" % (1.0 / steps) + ''.join(bcs[1:]) + """*NODE PRINT, NSET=FACE, TOTALS=YES
RF1, RF2, RF3
*END STEP
""").replace('*NSET, NSET=FACE', bcs[0] + '*NSET, NSET=FACE', 1)


if __name__ == '__main__':
    with open(os.path.join(OUT, 'c3d8_umat_uniaxial.inp'), 'w') as f:
        f.write(umat_deck())
    with open(os.path.join(OUT, 'c3d8_rotation_uniaxial.inp'), 'w') as f:
        f.write(rotation_deck())
    print('wrote decks/single/c3d8_umat_uniaxial.inp, decks/single/c3d8_rotation_uniaxial.inp')
