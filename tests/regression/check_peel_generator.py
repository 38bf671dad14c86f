#!/usr/bin/python3
"""Geometry checks of the decks tools/peel_deck.py writes (CTest peel_generator; needs no solver).

For each option family (plane strain / 3D quarter / 3D full width, steel / rigid substrate, graded / uniform mesh):
- every continuum element has a positive Jacobian at its 8 (4) corners (node order as C3D8 / CPE4 require);
- the element volumes add up to the geometry: coating h_c (L_b + a_0) w, steel h_s L_b w (relative 1e-9, exact
  for straight-sided elements up to round-off);
- the cohesive elements have zero initial thickness (top node k+4 on bottom node k, 2D: 3 on 2 and 4 on 1), their
  bottom->top normal points to +z, and their faces tile the bonded interface L_b w (relative 1e-9);
- PROPS of the UEL are phi and delta = phi/(e T_max) (Eq. 5), the UMAT's Table 1 constants and *DEPVAR 11;
- the LOAD set is the coating's end face x = L_b + a_0, the whole face (coating nodes only).
Reading B (--reading peel: the flap lifted at the peel angle theta, bottom face bent on radius R about
(L_b, R) then straight along d = (cos theta, sin theta)):
- every flap node lies where the bend puts it: at distance R - t from the bend centre while its arc length is
  within R theta, else on the straight arm at distance (s - R theta) from the bend's end along d (1e-9 mm);
- the end face (LOAD, the whole face, coating nodes only) is the segment of length h_c normal to d at arc length a_0;
- the coating area (volume) is h_c L_b w + (a_0 - R theta) h_c w + the bend's theta/2 (R^2 - (R - h_c)^2) w, the
  bend within the chord error of its elements (relative da^2/6 of the bend, da = largest angle of an element);
- *BOUNDARY of the step: fixed grip u_x = U cos theta and u_z = U sin theta on LOAD; carriage grip u_z = U alone.
"""
import math
import os
import subprocess
import sys


def parse(path):
    nodes, elems, sets, blocks = {}, {}, {}, []
    kw, etype, cur, params = None, None, None, {}
    for raw in open(path):
        line = raw.strip()
        if not line or line.startswith('**'):
            continue
        if line.startswith('*'):
            parts = [p.strip() for p in line.split(',')]
            kw = parts[0].upper()
            params = {}
            for p in parts[1:]:
                k, _, v = p.partition('=')
                params[k.strip().upper()] = v.strip()
            blocks.append((kw, params, []))
            if kw == '*ELEMENT':
                etype = params['TYPE']
                cur = params.get('ELSET')
            continue
        blocks[-1][2].append(line)
        f = [x.strip() for x in line.split(',') if x.strip()]
        if kw == '*NODE':
            nodes[int(f[0])] = [float(x) for x in f[1:]]
        elif kw == '*ELEMENT':
            elems[int(f[0])] = (etype, cur, [int(x) for x in f[1:]])
        elif kw == '*NSET':
            sets.setdefault(params['NSET'], []).extend(int(x) for x in f)
    return nodes, elems, sets, blocks


def det3(a):
    return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))


def hex_volume_and_min_jac(x):
    """Volume (2x2x2 Gauss) and the smallest corner Jacobian of a trilinear hexahedron."""
    sg = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]

    def jac(xi, et, ze):
        j = [[0.0] * 3 for _ in range(3)]
        for a, (s, t, u) in enumerate(sg):
            d = (s * (1 + t * et) * (1 + u * ze) / 8, t * (1 + s * xi) * (1 + u * ze) / 8,
                 u * (1 + s * xi) * (1 + t * et) / 8)
            for r in range(3):
                for c in range(3):
                    j[r][c] += d[r] * x[a][c]
        return det3(j)
    g = 1 / math.sqrt(3)
    vol = sum(jac(s * g, t * g, u * g) for s, t, u in sg)
    return vol, min(jac(s, t, u) for s, t, u in sg)


def quad_area_and_min_jac(x):
    area = 0.5 * sum(x[i][0] * x[(i + 1) % 4][1] - x[(i + 1) % 4][0] * x[i][1] for i in range(4))
    mins = []
    for i in range(4):   # corner Jacobian = cross product of the two edges at the corner
        a, b, c = x[i - 1], x[i], x[(i + 1) % 4]
        mins.append((c[0] - b[0]) * (a[1] - b[1]) - (c[1] - b[1]) * (a[0] - b[0]))
    return area, min(mins)


def check_case(gen, work, args, bad):
    deck = os.path.join(work, 'gen_%d.inp' % abs(hash(' '.join(args))))
    subprocess.check_call([sys.executable, gen, '-o', deck] + args)
    nodes, elems, sets, blocks = parse(deck)
    three_d = '--3d' in args
    val = {a.lstrip('-'): args[i + 1] for i, a in enumerate(args[:-1]) if a.startswith('--') and
           not args[i + 1].startswith('--')}
    hc, hs = float(val.get('coating', 0.030)), float(val.get('substrate', 0.210))
    lb, a0 = float(val.get('bonded', 0.30)), float(val.get('flap', 0.020))
    b = float(val.get('width', 0.040)) if three_d else 1.0
    w = 2 * b if '--full-width' in args else b
    vol = {'COATING': 0.0, 'SUBSTRATE': 0.0}
    coh_area = 0.0
    tag = ' '.join(args)
    for eid, (et, es, conn) in elems.items():
        x = [nodes[n] for n in conn]
        if et in ('C3D8', 'CPE4', 'C3D8I', 'CPE4I'):
            # the coating's formulation: incompatible modes with --incompatible, the steel always the plain element
            want = ('C3D8' if three_d else 'CPE4') + ('I' if es == 'COATING' and '--incompatible' in args else '')
            if et != want:
                bad.append('%s: %s element %d is %s, expected %s' % (tag, es, eid, et, want))
            v, jmin = hex_volume_and_min_jac(x) if et.startswith('C3D8') else quad_area_and_min_jac(x)
            if not jmin > 0:
                bad.append('%s: element %d has a corner Jacobian %.3e <= 0' % (tag, eid, jmin))
            vol[es] += v
        else:
            k = len(conn) // 2
            top = [conn[k:][i] for i in range(k)] if three_d else [conn[3], conn[2]]
            bot = conn[:k]
            gap = max(abs(p - q) for t, s in zip(top, bot) for p, q in zip(nodes[t], nodes[s]))
            if gap > 1e-12:
                bad.append('%s: cohesive element %d is not of zero thickness (%.2e)' % (tag, eid, gap))
            xb = [nodes[n] for n in bot]
            if three_d:
                d1 = [xb[2][i] - xb[0][i] for i in range(3)]
                d2 = [xb[3][i] - xb[1][i] for i in range(3)]
                nz = 0.5 * (d1[0] * d2[1] - d1[1] * d2[0])       # area times normal z (planar face)
            else:
                nz = xb[1][0] - xb[0][0]                       # n = e_z x t: +z when 1 -> 2 runs along +x
            if not nz > 0:
                bad.append('%s: cohesive element %d normal does not point bottom -> top (+z)' % (tag, eid))
            coh_area += nz
    exp_c = hc * (lb + a0) * w
    peel = val.get('reading') == 'peel'
    if peel:
        exp_c, chord_tol = peel_checks(args, val, nodes, elems, sets, blocks, hc, lb, a0, w, three_d, tag, bad)
    exp_s = 0.0 if '--rigid-substrate' in args else hs * lb * w
    for name, got, exp in (('coating', vol['COATING'], exp_c), ('substrate', vol['SUBSTRATE'], exp_s),
                           ('interface', coh_area, lb * w)):
        tol = 1e-9 * max(exp, 1e-30) + (1e-15 if exp == 0 else 0) + (chord_tol if peel and name == 'coating' else 0)
        if abs(got - exp) > tol:
            bad.append('%s: %s volume/area %.9e, expected %.9e' % (tag, name, got, exp))
    for kw, params, data in blocks:
        if kw == '*UEL PROPERTY':
            f = [float(x) for x in data[0].split(',')]
            phi = float(val.get('phi', 0.2))
            delta = phi / (math.e * float(val.get('tmax', 20.0)))
            if abs(f[0] - phi) > 1e-9 or abs(f[1] - delta) > 1e-9 * delta:
                bad.append('%s: UEL PROPS %s, expected phi %g delta %.6e' % (tag, f[:2], phi, delta))
        if kw == '*USER MATERIAL':
            f = [float(x) for line in data for x in line.split(',')]
            exp = [1250.0, 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.990, 200.0, -4.0]
            if val.get('pet') == 'alt':
                # the alternative: S_a halved, the aged viscosity eta_0r exp(S_a) kept (docs/scenes.md)
                exp[2], exp[3] = 14.2, 0.486 * math.exp(14.2)
            if '--dgamma-max' in args:
                exp.append(float(val['dgamma-max']))   # PROPS(11): the accuracy bound dgamma_max
            # the deck writes 9 significant digits
            if len(f) != len(exp) or any(abs(a - b) > 1e-8 * abs(b) for a, b in zip(f, exp)):
                bad.append('%s: UMAT constants %s are not Table 1%s' % (tag, f, ' + dgamma_max' if len(exp) > 10
                                                                         else ''))
            n = int(params.get('CONSTANTS', '0'))
            if n != len(exp):
                bad.append('%s: *USER MATERIAL, CONSTANTS=%d for %d constants' % (tag, n, len(exp)))
        if kw == '*STEP':
            has_no = params.get('EXTRAPOLATION', '') == 'NO'
            if has_no != ('--no-extrapolation' in args):
                bad.append('%s: *STEP EXTRAPOLATION=NO %s' % (tag, 'missing' if not has_no else 'unexpected'))
        if kw == '*DEPVAR' and int(data[0]) != 11:
            bad.append('%s: *DEPVAR %s, the UMAT needs 11' % (tag, data[0]))
    # --edge-fixed-y: YEDGE is every coating (and steel) node on the free edge y = b, held in y in the model data
    edge = sorted(n for n in {n for et, es, conn in elems.values() if es in ('COATING', 'SUBSTRATE') for n in conn}
                  if three_d and abs(nodes[n][1] - b) < 1e-12)
    held = [data for kw, params, data in blocks if kw == '*BOUNDARY' and any(
        [x.strip() for x in line.split(',')][:3] == ['YEDGE', '2', '2'] for line in data)]
    if '--edge-fixed-y' in args and (sorted(sets.get('YEDGE', [])) != edge or not edge or not held):
        bad.append('%s: YEDGE (%d nodes) is not the edge y = b (%d nodes) held in y (%s)' % (
            tag, len(sets.get('YEDGE', [])), len(edge), 'boundary written' if held else 'no boundary'))
    if '--edge-fixed-y' not in args and ('YEDGE' in sets or held):
        bad.append('%s: YEDGE written without --edge-fixed-y' % tag)
    xload = lb + a0
    load = sets.get('LOAD', [])
    if peel:
        print('%-70s %5d elements: checked' % (tag[:70], len(elems)))
        return
    coat_nodes = {n for et, es, conn in elems.values() if es == 'COATING' for n in conn}
    face = [n for n in coat_nodes if abs(nodes[n][0] - xload) < 1e-12]
    if sorted(load) != sorted(face):
        bad.append('%s: LOAD is not the end face x = %g (%d nodes, face %d)' % (tag, xload, len(load), len(face)))
    print('%-70s %5d elements: checked' % (tag[:70], len(elems)))


def peel_checks(args, val, nodes, elems, sets, blocks, hc, lb, a0, w, three_d, tag, bad):
    """Reading B: flap geometry, LOAD face, loads. Returns the expected coating volume and its chord tolerance."""
    theta = math.radians(float(val.get('peel-angle', 90.0)))
    r = float(val.get('bend-radius', 1.5 * hc))
    zc = 2 if three_d else 1                      # index of z in a node's coordinates
    d = (math.cos(theta), math.sin(theta))
    sb = r * theta
    coat = {n for et, es, conn in elems.values() if es == 'COATING' for n in conn}
    flap = [n for n in coat if nodes[n][0] > lb + 1e-12 or nodes[n][zc] > hc + 1e-12]
    da = 0.0
    end_face = []
    arcs = {}
    for n in flap:
        x, z = nodes[n][0], nodes[n][zc]
        # distance from the bend centre and angle: in the bend part the node lies on the circle of radius R - t
        cx, cz = lb, r
        rho = math.hypot(x - cx, z - cz)
        ang = math.atan2(x - cx, cz - z)           # 0 at the front, theta at the end of the bend
        if ang <= theta + 1e-9 and (ang >= -1e-12):
            t = r - rho
            if -1e-9 <= t <= hc + 1e-9:
                arcs[n] = (r * ang, t)
                continue
        # straight arm: P - C = (R - t) (sin theta, -cos theta) + l d (the two directions are orthogonal)
        t = r - ((x - cx) * math.sin(theta) - (z - cz) * math.cos(theta))
        ll = (x - cx) * d[0] + (z - cz) * d[1]
        if -1e-9 <= t <= hc + 1e-9 and ll >= -1e-9:
            arcs[n] = (sb + ll, t)
        else:
            bad.append('%s: flap node %d at (%.6g, %.6g) is neither on the bend nor on the arm' % (tag, n, x, z))
    for n, (sa, t) in arcs.items():
        if abs(sa - a0) < 1e-9:
            end_face.append(n)
    load = sets.get('LOAD', [])
    if sorted(load) != sorted(end_face) or not end_face:
        bad.append('%s: LOAD (%d nodes) is not the end face at arc length a_0 (%d nodes)' % (tag, len(load),
                                                                                             len(end_face)))
    ts = sorted(set(round(arcs[n][1], 9) for n in end_face))
    if end_face and abs(ts[-1] - ts[0] - hc) > 1e-9:
        bad.append('%s: end face spans %.6g mm of thickness, not h_c' % (tag, ts[-1] - ts[0]))
    # largest angle of a bend element: from the bottom-face nodes' arc lengths
    # (the element across the bend's end included: its chord spans the kink)
    sbot = sorted(set(round(sa, 12) for sa, t in arcs.values() if abs(t) < 1e-9))
    for a, b in zip(sbot, sbot[1:]):
        if a < sb - 1e-12:
            da = max(da, (b - a) / r)
    bend = 0.5 * theta * (r * r - (r - hc) ** 2)
    exp = hc * lb * w + (a0 - sb) * hc * w + bend * w
    # loads
    u_total = float(val.get('u-total', 0.05))
    grip = val.get('grip', 'fixed')
    zdof = 3 if three_d else 2
    step = False
    got = {}
    for kw, params, data in blocks:
        if kw == '*STEP':
            step = True
        if kw == '*BOUNDARY' and step:
            for line in data:
                f = [x.strip() for x in line.split(',')]
                if f[0] == 'LOAD':
                    got[int(f[1])] = float(f[3])
    want = {zdof: u_total} if grip == 'carriage' else {1: u_total * d[0], zdof: u_total * d[1]}
    if set(got) != set(want) or any(abs(got[k] - want[k]) > 1e-9 * u_total + 1e-15 for k in want):
        bad.append('%s: LOAD boundary %s, expected %s' % (tag, got, want))
    # polygon against arc: a sector of angle da loses the fraction 1 - sin(da)/da < da^2/6 of its area; twice that
    # for the element across the bend's end (chord deviations on both sides of the kink)
    return exp, 2.0 * bend * w * da * da / 6.0 + 1e-12


def main(argv):
    gen, work = argv[1], argv[2]
    os.makedirs(work, exist_ok=True)
    bad = []
    cases = [[], ['--rigid-substrate'], ['--no-coarse', '--le', '0.02'], ['--nz', '5', '--flap', '0.03'],
             ['--3d', '--ny', '2', '--le', '0.02'], ['--3d', '--rigid-substrate', '--ny', '3', '--width', '0.03'],
             ['--3d', '--full-width', '--ny', '2', '--le', '0.02', '--nz', '2'],
             ['--tmax', '10', '--phi', '0.1', '--bonded', '0.5', '--coating', '0.02'], ['--flap', '0', '--rigid-substrate'],
             ['--rigid-substrate', '--dgamma-max', '1.0', '--no-extrapolation'],
             # reading B: the lifted flap (90 degrees fixed and carriage grip, small angle, 3D quarter, steel)
             ['--reading', 'peel', '--flap', '0.1', '--rigid-substrate'],
             ['--reading', 'peel', '--flap', '0.1', '--grip', 'carriage', '--rigid-substrate', '--nz', '4'],
             ['--reading', 'peel', '--flap', '0.05', '--peel-angle', '10', '--le', '0.005', '--rigid-substrate'],
             ['--reading', 'peel', '--flap', '0.12', '--peel-angle', '135', '--bend-radius', '0.04'],
             ['--reading', 'peel', '--flap', '0.1', '--3d', '--ny', '2', '--le', '0.02', '--rigid-substrate'],
             ['--reading', 'peel', '--flap', '0.1', '--3d', '--ny', '2', '--le', '0.02'],
             ['--pet', 'alt', '--rigid-substrate'], ['--incompatible', '--nz', '4'],
             ['--3d', '--incompatible', '--ny', '2', '--le', '0.02'],
             ['--3d', '--rigid-substrate', '--edge-fixed-y', '--ny', '3', '--le', '0.02'],
             ['--3d', '--edge-fixed-y', '--ny', '2', '--le', '0.02']]
    for c in cases:
        check_case(gen, work, c, bad)
    # the committed main-scene deck is what the main job (tools/peel_study.py main, MAIN_A) generates
    root = os.path.dirname(os.path.dirname(os.path.abspath(gen)))
    from ldfcz_tools import peel_study  # the package is on PYTHONPATH (tests/CMakeLists.txt)
    main_deck = os.path.join(work, 'main_scene.inp')
    subprocess.check_call([sys.executable, gen, '-o', main_deck] + peel_study.MAIN_A)
    with open(main_deck) as fh, open(os.path.join(root, 'decks', 'peel', 'peel_main.inp')) as fc:
        if fh.read() != fc.read():
            bad.append('decks/peel/peel_main.inp is not the main job\'s deck: regenerate it with tools/peel_deck.py '
                       '%s -o decks/peel/peel_main.inp' % ' '.join(peel_study.MAIN_A))
    check_case(gen, work, peel_study.MAIN_A, bad)
    for b in bad:
        print('FAIL: ' + b)
    print('check_peel_generator: %s' % ('FAILED (%d)' % len(bad) if bad else 'passed'))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
