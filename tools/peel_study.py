#!/usr/bin/python3
"""Peel scenes and studies (paper sections 7-9): generate decks with tools/peel_deck.py, run bin/ldfcz on them,
collect JOB.csv, compute the steady peel force per unit width, and write reports/<study>/<study>.{csv,md,png}.

  peel_study.py main                 the default plane-strain scene: prints the steady peel force per unit width
  peel_study.py mesh-x|mesh-z|mesh-y|increment|simplifications|ps-vs-3d|dofs|application [--quick]
  peel_study.py list                 the studies and their cases

Steady peel force: the mean of F/w over the last --plateau fraction of the pulled displacement (default 0.3),
with its spread (max - min)/mean over the same window. F/w = RF1 of set LOAD (plane strain, unit thickness) or
RF1 / b (3D quarter model, b the modelled width = half the specimen width). Each study normalises by its reference
case (the finest or the full model, as the paper does with F_r) and reports |F/F_r - 1| against the run time.
Python standard library only; matplotlib is used for the PNGs when it is installed.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import peel_deck  # noqa: E402  (same directory)

# The default plane-strain scene (the main job). Every study starts from these arguments.
DEFAULT_PS = ['--rigid-substrate']
DEFAULT_3D = ['--3d', '--rigid-substrate']


def studies(quick):
    """Cases per study: (label, generator arguments, is_reference). quick: fewer/cheaper cases (CI smoke)."""
    s = {}
    les = [0.02, 0.01, 0.005] if quick else [0.02, 0.01, 0.005, 0.0025]
    s['mesh-x'] = [('le=%g' % le, DEFAULT_PS + ['--le', str(le)], le == les[-1]) for le in les]
    nzs = [1, 2, 3] if quick else [1, 2, 3, 5, 9]
    s['mesh-z'] = [('nz=%d' % nz, DEFAULT_PS + ['--nz', str(nz)], nz == nzs[-1]) for nz in nzs]
    base3 = DEFAULT_3D + ['--le', '0.02', '--nz', '2', '--u-total', '0.05']
    nys = [1, 2] if quick else [1, 2, 4, 8]
    cases = []
    for b in (0.02, 0.04):
        for ny in nys:
            cases.append(('b=%g ny=%d' % (b, ny), base3 + ['--width', str(b), '--ny', str(ny)],
                          b == 0.04 and ny == nys[-1]))
    s['mesh-y'] = cases
    dus = [0.0005, 0.0003, 0.0001] if not quick else [0.0005, 0.0003]
    s['increment'] = [('du=%g um' % (du * 1e3), DEFAULT_PS + ['--du', str(du)], du == dus[-1]) for du in dus]
    s['simplifications'] = [
        ('full: steel, uniform mesh', ['--no-coarse'], True),
        ('steel, coarse far field', [], False),
        ('rigid, uniform mesh', ['--rigid-substrate', '--no-coarse'], False),
        ('rigid, coarse far field (default)', DEFAULT_PS, False),
    ]
    ps3 = ['--le', '0.02', '--nz', '2', '--u-total', '0.05']
    s['ps-vs-3d'] = [('plane strain', DEFAULT_PS + ps3, False),
                     ('3D b=0.04 ny=2', DEFAULT_3D + ps3 + ['--width', '0.04', '--ny', '2'], True)]
    s['dofs'] = [('le=%g nz=%d' % (le, nz), DEFAULT_PS + ['--le', str(le), '--nz', str(nz), '--u-total', '0.01'],
                  False) for le, nz in ((0.02, 2), (0.01, 3), (0.005, 3), (0.0025, 5))]
    # Section 8: 10 elements in y, 3 in z, l_e = 2 um, 0.1 um/inc, to 1.0 mm delamination. In the main scene the
    # front advances about as fast as the pull once steady (0.045 mm for the last 0.03 mm), so 1.1 mm of pull.
    # About 18000 hexahedra with the UMAT: days on 2 cores with this host; not run yet.
    s['application'] = [('paper section 8', DEFAULT_3D + ['--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.0001',
                                                          '--fine-length', '1.15', '--bonded', '1.5',
                                                          '--u-total', '1.1', '--field-frequency', '200'], True)]
    return s


def find_ldfcz(path):
    if path:
        return path
    for cand in (os.path.join(ROOT, 'build', 'bin', 'ldfcz'), shutil.which('ldfcz')):
        if cand and os.path.exists(cand):
            return cand
    raise SystemExit('peel_study: bin/ldfcz not found: build first (tools/setup.sh) or pass --ldfcz')


def read_history(csv_path):
    """(U1, RF1) lists from JOB.csv (columns LOAD.U1, LOAD.RF1)."""
    u, f = [], []
    with open(csv_path) as fh:
        rows = csv.DictReader(fh)
        for r in rows:
            u.append(float(r['LOAD.U1']))
            f.append(float(r['LOAD.RF1']))
    return u, f


def read_summary(log_path):
    """Numbers of the host's closing summary in JOB.log (whatever of them are present)."""
    out = {}
    if not os.path.exists(log_path):
        return out
    text = open(log_path).read()
    pats = {
        'increments': r'increments\s+(\d+),', 'attempts': r'attempts\s+(\d+)', 'cutbacks': r'cutbacks\s+(\d+)',
        'iterations': r'Newton iterations\s+(\d+)', 'dofs': r'DOFs\s+(\d+)', 'wall_s': r'wall time\s+([0-9.Ee+-]+) s',
        't_assembly_s': r'assembly\s+([0-9.Ee+-]+) s', 't_factor_s': r'factorization\s+([0-9.Ee+-]+) s',
        'w_ext': r'external work\s+([0-9.Ee+-]+)', 'e_int': r'stored \+ dissipated\s+([0-9.Ee+-]+)',
        'energy_rel_diff': r'relative difference\s+([0-9.Ee+-]+)',
        'max_open_ratio': r'opening increment / delta\s+([0-9.Ee+-]+)',
    }
    for k, pat in pats.items():
        m = re.search(pat, text)
        if m:
            out[k] = float(m.group(1))
    return out


def steady_force(u, fw, plateau):
    """Mean and relative spread of fw over u >= (1 - plateau) max(u)."""
    if not u:
        return float('nan'), float('nan')
    u0 = (1.0 - plateau) * max(u)
    win = [f for x, f in zip(u, fw) if x >= u0]
    if not win:
        return float('nan'), float('nan')
    mean = sum(win) / len(win)
    spread = (max(win) - min(win)) / abs(mean) if mean else float('nan')
    return mean, spread


def read_vtu_front(vtu_path, delta):
    """x of the delamination front in a VTU frame: the smallest cell-centre x among cohesive cells whose opening
    magnitude exceeds delta (past the peak traction). None when no cell qualifies."""
    text = open(vtu_path).read()

    def array(name):
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return [float(v) for v in m.group(1).split()] if m else None
    pm = re.search(r'<Points><DataArray[^>]*>(.*?)</DataArray>', text, re.S)
    pts = [float(v) for v in pm.group(1).split()]
    conn, offs, coh, op = array('connectivity'), array('offsets'), array('cohesive'), array('opening')
    if None in (conn, offs, coh, op):
        return None
    xs, start = [], 0
    for i, o in enumerate(offs):
        o = int(o)
        if coh[i] >= 1:
            ids = [int(c) for c in conn[start:o]]
            d = math.sqrt(sum(v * v for v in op[3 * i:3 * i + 3]))
            if d > delta:
                xs.append(sum(pts[3 * j] for j in ids) / len(ids))
        start = o
    return min(xs) if xs else None


def run_case(label, gen_args, workdir, ldfcz, threads, plateau):
    os.makedirs(workdir, exist_ok=True)
    job = re.sub(r'[^A-Za-z0-9_.-]+', '_', label).strip('_') or 'case'
    deck = os.path.join(workdir, job + '.inp')
    p = peel_deck.parser().parse_args(gen_args + ['-o', deck])
    peel_deck.check(p)
    text, info = peel_deck.build(p)
    with open(deck, 'w') as fh:
        fh.write(text)
    outdir = os.path.join(workdir, job)
    cmd = [ldfcz, '-q', '-t', str(threads), '-o', outdir, deck]
    t0 = time.time()
    rc = subprocess.call(cmd)
    wall = time.time() - t0
    res = {'label': label, 'job': job, 'exit': rc, 'run_time_s': wall, 'elements': info['elements'],
           'dofs': info['dofs'], 'l_e_mm': info['l_e_mm'], 'args': ' '.join(gen_args)}
    res.update({k: v for k, v in read_summary(os.path.join(outdir, job + '.log')).items() if k != 'dofs'})
    csv_path = os.path.join(outdir, job + '.csv')
    u, f = read_history(csv_path) if os.path.exists(csv_path) else ([], [])
    fw = [v / info['width_mm'] for v in f]
    res['u_end_mm'] = u[-1] if u else 0.0
    res['completed'] = bool(u) and abs(u[-1] - p.u_total) <= 1e-6 * p.u_total and rc == 0
    res['F_w'], res['spread'] = steady_force(u, fw, plateau)
    vtus = sorted(x for x in os.listdir(outdir) if x.endswith('.vtu')) if os.path.isdir(outdir) else []
    front = read_vtu_front(os.path.join(outdir, vtus[-1]), info['delta_mm']) if vtus else None
    res['delaminated_mm'] = (info['x_front_mm'] - front) if front is not None else 0.0
    if res.get('increments') and res.get('wall_s'):
        res['t_inc_s'] = res['wall_s'] / res['attempts'] if res.get('attempts') else res['wall_s'] / res['increments']
    res['curve'] = (u, fw)
    return res


def write_report(study, results, outdir):
    os.makedirs(outdir, exist_ok=True)
    ref = [r for r in results if r.get('reference')]
    fref = ref[0]['F_w'] if ref else float('nan')
    for r in results:
        r['F_over_Fr'] = r['F_w'] / fref if fref == fref and fref else float('nan')
        r['error'] = abs(r['F_over_Fr'] - 1.0) if r['F_over_Fr'] == r['F_over_Fr'] else float('nan')
    cols = ['label', 'reference', 'completed', 'F_w', 'F_over_Fr', 'error', 'spread', 'delaminated_mm', 'run_time_s',
            'increments', 'cutbacks', 'iterations', 'elements', 'dofs', 't_inc_s', 't_assembly_s', 't_factor_s',
            'energy_rel_diff', 'max_open_ratio', 'args']
    with open(os.path.join(outdir, study + '.csv'), 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(cols)
        for r in results:
            wr.writerow([r.get(c, '') for c in cols])
    with open(os.path.join(outdir, study + '_curves.csv'), 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(['label', 'U1_mm', 'F_per_width_N_per_mm'])
        for r in results:
            for x, y in zip(*r['curve']):
                wr.writerow([r['label'], '%.9g' % x, '%.9g' % y])
    lines = ['# Study %s' % study, '',
             'Generated by `tools/peel_study.py %s` on %s (%s, %d cores visible, other jobs may have shared them: '
             'compare run times within one table).' % (' '.join(sys.argv[1:2] + [x for x in sys.argv[2:] if x in (
                 '--quick',)]) or study, time.strftime('%Y-%m-%d %H:%M'), os.uname().nodename, os.cpu_count() or 1),
             '',
             'F/w: steady peel force per unit width (N/mm), mean over the last part of the pull; spread: (max-min)/mean '
             'there; error: |F/F_r - 1| against the reference case (marked *).', '',
             '| case | F/w (N/mm) | F/F_r | error | spread | delaminated (mm) | run time (s) | increments | cutbacks '
             '| elements | DOFs | energy balance |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in results:
        lines.append('| %s%s | %.4f | %.4f | %.2e | %.1e | %.3f | %.1f | %s | %s | %d | %d | %s |' % (
            r['label'], ' *' if r.get('reference') else '', r['F_w'], r['F_over_Fr'], r['error'], r['spread'],
            r['delaminated_mm'], r['run_time_s'], int(r.get('increments', 0)), int(r.get('cutbacks', 0)),
            r['elements'], r['dofs'], '%.1e' % r['energy_rel_diff'] if 'energy_rel_diff' in r else '-'))
        if not r['completed']:
            lines[-1] += ' (not completed: exit %d, U = %.4g mm)' % (r['exit'], r['u_end_mm'])
    if study == 'dofs':
        pts = [(r['dofs'], r['t_inc_s']) for r in results if r.get('t_inc_s')]
        n = fit_exponent(pts)
        lines += ['', 'Fitted t_inc ~ DOFs^n: n = %.3f (paper Fig. 11d: 1.34).' % n]
    with open(os.path.join(outdir, study + '.md'), 'w') as fh:
        fh.write('\n'.join(lines) + '\n')
    plot(study, results, outdir)


def fit_exponent(pts):
    pts = [(math.log(a), math.log(b)) for a, b in pts if a > 0 and b > 0]
    if len(pts) < 2:
        return float('nan')
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx else float('nan')


def plot(study, results, outdir):
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write('peel_study: matplotlib not installed: no PNG written\n')
        return
    pts = [(r['run_time_s'], r['error'], r['label']) for r in results if not r.get('reference') and r['error'] > 0]
    fig, ax = plt.subplots(1, 2 if pts else 1, figsize=(11, 4.2) if pts else (6.5, 4.2))
    if not pts:
        ax = [ax]
    for r in results:
        u, fw = r['curve']
        ax[0].plot([1e3 * x for x in u], fw, label=r['label'] + (' *' if r.get('reference') else ''))
    ax[0].set_xlabel('pulled displacement u_x (um)')
    ax[0].set_ylabel('peel force per unit width F/w (N/mm)')
    ax[0].legend(fontsize=7)
    ax[0].grid(alpha=0.3)
    if pts:
        ax[1].loglog([p[0] for p in pts], [p[1] for p in pts], 'o-')
        for t, e, lab in pts:
            ax[1].annotate(lab, (t, e), fontsize=7)
        ax[1].set_xlabel('run time (s)')
        ax[1].set_ylabel('|F/F_r - 1|')
        ax[1].grid(alpha=0.3, which='both')
    fig.suptitle('ldfcz peel study: ' + study)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, study + '.png'), dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('study')
    ap.add_argument('--ldfcz', default='', help='path of the ldfcz program (default build/bin/ldfcz or PATH)')
    ap.add_argument('--reports', default=os.path.join(ROOT, 'reports'), help='report root (default reports/)')
    ap.add_argument('--work', default='', help='run directory: decks, JOB.csv/log/sta, ParaView frames '
                    '(default out/peel/<study>, ignored by git)')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--plateau', type=float, default=0.3, help='fraction of the pull averaged for the steady force')
    ap.add_argument('--quick', action='store_true', help='fewer, cheaper cases')
    ap.add_argument('--only', default='', help='run only cases whose label contains this text')
    a = ap.parse_args(argv)
    all_studies = studies(a.quick)
    if a.study == 'list':
        for k, v in all_studies.items():
            print(k + ': ' + '; '.join('%s%s [%s]' % (c[0], ' *' if c[2] else '', ' '.join(c[1])) for c in v))
        return 0
    ldfcz = find_ldfcz(a.ldfcz)
    if a.study == 'main':
        outdir = os.path.join(a.reports, 'main')
        work = a.work or os.path.join(ROOT, 'out', 'peel', 'main')
        r = run_case('peel_ps', DEFAULT_PS, work, ldfcz, a.threads, a.plateau)
        r['reference'] = True
        write_report('main', [r], outdir)
        print('steady peel force per unit width: %.4f N/mm (plane strain, mean over the last %d%% of the pull, '
              'spread %.1f%%), delamination %.3f mm, run time %.1f s' % (
                  r['F_w'], round(100 * a.plateau), 100 * r['spread'], r['delaminated_mm'], r['run_time_s']))
        print('force-displacement: %s; plot: %s; ParaView frames: %s' % (
            os.path.join(outdir, 'main_curves.csv'), os.path.join(outdir, 'main.png'),
            os.path.join(work, r['job'], r['job'] + '.pvd')))
        return 0 if r['completed'] else 3
    if a.study not in all_studies:
        raise SystemExit('peel_study: unknown study %s (peel_study.py list)' % a.study)
    outdir = os.path.join(a.reports, a.study)
    work = a.work or os.path.join(ROOT, 'out', 'peel', a.study)
    results = []
    for label, args, is_ref in all_studies[a.study]:
        if a.only and a.only not in label:
            continue
        r = run_case(label, args, work, ldfcz, a.threads, a.plateau)
        r['reference'] = is_ref
        results.append(r)
        print('%-36s F/w = %.4f N/mm  spread %.1e  %.1f s  %s' % (label, r['F_w'], r['spread'], r['run_time_s'],
                                                                  'ok' if r['completed'] else 'NOT COMPLETED'))
        sys.stdout.flush()
    write_report(a.study, results, outdir)
    print('report: ' + os.path.join(outdir, a.study + '.md'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
