#!/usr/bin/env python3
"""C3D8R's hourglass control on coarse meshes: a cantilever under a tip shear, C3D8R against C3D8I and C3D8 and
against beam theory (docs/elements.md, "One point with hourglass stiffness").

  python3 tools/hourglass_study.py --exe build/bin/ldfcz [--out DIR]

The cantilever: L = 10, section h x b = 1 x 1, *ELASTIC E = 1000, nu = 0, clamped at x = 0 (every node of the
face), a tip shear P = 1 along y as consistent nodal loads of the bilinear tip faces (*CLOAD), small strain. Meshes
of square elements, n_t = 1, 2, 4 through the thickness (10 n_t along the length, one across the width). Printed:
the mean tip deflection over Timoshenko's PL^3/(3EI) + PL/(kappa G A) (kappa = 5/6), and C3D8R's over C3D8I's. The
clamped face's local stiffening (about 1 % here) is the same for every type. A study command, not a test.
"""
import argparse
import os
import subprocess
import sys

from ldfcz_tools import outputs
from ldfcz_tools.cli import ToolError, executable

L, H, B, E, NU, P = 10.0, 1.0, 1.0, 1000.0, 0.0, 1.0
TYPES = ('C3D8R', 'C3D8I', 'C3D8')


def deck(etype, nt):
    """The deck text of the cantilever with nt elements through the thickness."""
    nx, nw = 10 * nt, 1
    nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (nt + 1) * k)   # noqa: E731
    out = ['*HEADING', 'cantilever %s %dx%dx%d (tools/hourglass_study.py)' % (etype, nx, nt, nw), '*NODE']
    for k in range(nw + 1):
        for j in range(nt + 1):
            for i in range(nx + 1):
                out.append('%d, %.15g, %.15g, %.15g' % (nid(i, j, k), L * i / nx, H * j / nt, B * k / nw))
    out.append('*ELEMENT, TYPE=%s, ELSET=BEAM' % etype)
    e = 0
    for k in range(nw):
        for j in range(nt):
            for i in range(nx):
                e += 1
                out.append('%d, %s' % (e, ', '.join(str(n) for n in (
                    nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                    nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)))))
    root = [nid(0, j, k) for k in range(nw + 1) for j in range(nt + 1)]
    tip = [(nid(nx, j, k), j, k) for k in range(nw + 1) for j in range(nt + 1)]
    out += ['*NSET, NSET=ROOT'] + [', '.join(str(n) for n in root)]
    out += ['*NSET, NSET=TIP'] + [', '.join(str(n) for n, _, _ in tip)]
    out += ['*SOLID SECTION, ELSET=BEAM, MATERIAL=M', '*MATERIAL, NAME=M', '*ELASTIC', '%g, %g' % (E, NU),
            '*BOUNDARY', 'ROOT, 1, 3, 0.', '*STEP', '*STATIC', '1., 1.', '*CLOAD']
    for n, j, k in tip:
        # consistent loads of a uniform shear traction on the bilinear tip faces: the product of 1D trapezoid weights
        wj = (0.5 if j in (0, nt) else 1.0) / nt
        wk = (0.5 if k in (0, nw) else 1.0) / nw
        out.append('%d, 2, %.15g' % (n, P * wj * wk))
    out += ['*NODE PRINT, NSET=TIP, TOTALS=YES', 'U2', '*END STEP']
    return '\n'.join(out) + '\n'


def tip_deflection(exe, out, etype, nt):
    job = '%s_nt%d' % (etype.lower(), nt)
    path = os.path.join(out, job + '.inp')
    with open(path, 'w') as f:
        f.write(deck(etype, nt))
    p = subprocess.run([exe, '-q', '-t', '1', '-o', out, path], capture_output=True, text=True)
    if p.returncode != 0:
        raise ToolError('%s: ldfcz exit %d: %s' % (job, p.returncode, p.stderr.strip()[-300:]))
    rows = outputs.read_csv(os.path.join(out, job + '.csv'))
    return float(rows[-1]['TIP.U2'])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--exe', required=True)
    ap.add_argument('--out', default=os.path.join('out', 'hourglass_study'))
    a = ap.parse_args()
    executable(a.exe, 'ldfcz program')
    os.makedirs(a.out, exist_ok=True)
    inertia, area, g = B * H ** 3 / 12, B * H, E / (2 * (1 + NU))
    exact = P * L ** 3 / (3 * E * inertia) + P * L / (5.0 / 6.0 * g * area)
    print('cantilever L = %g, h = b = 1, E = %g, nu = %g, tip shear %g: Timoshenko %.6g' % (L, E, NU, P, exact))
    print('%-8s %-12s %-12s %-12s %s' % ('n_t', 'C3D8R', 'C3D8I', 'C3D8', 'C3D8R / C3D8I'))
    for nt in (1, 2, 4):
        d = {t: tip_deflection(a.exe, a.out, t, nt) for t in TYPES}
        print('%-8s %-12.4f %-12.4f %-12.4f %.4f' % ('%dx%dx1' % (10 * nt, nt), d['C3D8R'] / exact,
                                                    d['C3D8I'] / exact, d['C3D8'] / exact, d['C3D8R'] / d['C3D8I']))
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('hourglass_study'))
