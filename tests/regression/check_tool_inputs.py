#!/usr/bin/env python3
"""No traceback from any tool on bad input or a missing dependency (issue 37 item 5):

  check_tool_inputs.py --root SRC --bin BIN --out DIR [--only TEXT]

Every command (tools/NAME.py, python3 -m ldfcz_tools.NAME, benchmarks/*.py, the Fortran drivers in BIN) is fed, in
place of its input file (a curve, a case file, a trace, a frame, a source, an executable, a directory of sources),
each of: a binary file (the first 4 kB of an executable), a folder, an empty file and a CSV with a column missing;
a generator gets a folder where its output file goes. Each must end with a non-zero exit status, no "Traceback"
(nor a Fortran runtime error or backtrace), and its last line on standard error naming the command (`NAME: ...`)
or argparse's usage error. Then identify.py and render_frame.py are run by a Python that cannot import NumPy / VTK
(`python3 -S`: no site packages; LDFCZ_NO_REEXEC=1 so that the command does not restart itself under
/usr/bin/python3): one line naming the module and the Debian package, exit 2.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

CRASH = re.compile(r"Traceback \(most recent call last\)|Fortran runtime error|Backtrace|Error termination|"
                   r"Segmentation fault|Program received signal")
KINDS = ('binary', 'folder', 'empty', 'column')


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def make_inputs(out, exe):
    """The four bad inputs (and the name each goes under: some commands find their input by its name)."""
    d = os.path.join(out, 'inputs')
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(os.path.join(d, 'folder'))
    with open(exe, 'rb') as f:
        head = f.read(4096)
    paths = {'folder': os.path.join(d, 'folder')}
    for kind, data in (('binary', head), ('empty', b''), ('column', b'u_mm\n0.0\n0.1\n0.2\n')):
        paths[kind] = os.path.join(d, kind + '.csv')
        with open(paths[kind], 'wb') as f:
            f.write(data)
    # loop_trace.py reads PREFIX.rank0.csv
    for kind in KINDS:
        target = os.path.join(d, 'trace_%s.rank0.csv' % kind)
        if kind == 'folder':
            os.makedirs(target)
        else:
            shutil.copy(paths[kind], target)
    paths.update({'trace_' + k: os.path.join(d, 'trace_' + k) for k in KINDS})
    return paths


def commands(root, bin_dir, work):
    """(label, argv with {f} for the bad input, kinds it applies to). Executables and inputs of every command."""
    py = [sys.executable]
    t = lambda name: py + [os.path.join(root, 'tools', name)]        # noqa: E731
    b = lambda name: py + [os.path.join(root, 'benchmarks', name)]   # noqa: E731
    w = lambda name: os.path.join(work, name)                        # noqa: E731
    mp = os.path.join(bin_dir, 'material_point')
    return [
        ('identify fit', t('identify.py') + ['fit', '{f}', '--force-unit', 'N/mm', '--report-dir', w('identify')],
         KINDS),
        ('python3 -m ldfcz_tools.identify', py + ['-m', 'ldfcz_tools.identify', 'fit', '{f}', '--force-unit', 'N/mm',
                                                  '--report-dir', w('identify_m')], KINDS),
        ('plot_material curve', t('plot_material.py') + [w('plot.png'), '{f}'], KINDS),
        ('plot_material --run', t('plot_material.py') + ['--run', '{f}', '--root', w('pm_root')], KINDS),
        ('umat_step_study', t('umat_step_study.py') + ['{f}', '--root', w('uss_root')], KINDS),
        ('stability_suite', t('stability_suite.py') + ['--exe', '{f}', '--out', w('stab'), '--no-report', '--only',
                                                       'penetration_10'], KINDS),
        ('fuzz_decks', t('fuzz_decks.py') + ['--exe', '{f}', '--count', '2', '--time', '5', '--no-save'], KINDS),
        ('locking_study', t('locking_study.py') + ['--exe', '{f}', '--out', w('locking')], KINDS),
        ('orientation_newton_study', t('orientation_newton_study.py') + ['--exe', '{f}', '--out', w('orient')],
         KINDS),
        # (an empty folder as --work is a study whose runs are not done: reported as such, exit 0)
        ('peel_study --reuse', t('peel_study.py') + ['mesh-z', '--reuse', '--only', 'nz=1', '--work', '{f}',
                                                     '--reports', w('reports')], ('binary', 'empty', 'column')),
        ('peel_deck output', t('peel_deck.py') + ['-o', '{f}'], ('folder',)),
        ('dcb_deck output', t('dcb_deck.py') + ['--out', '{f}'], ('folder',)),
        ('make_dropin', t('make_dropin.py') + ['--out', w('dropin.f'), '--tag', 'x', '{f}'], KINDS),
        ('routine_lengths', t('routine_lengths.py') + ['{f}'], KINDS),
        ('render_frame', t('render_frame.py') + ['{f}', '-o', w('frame.png')], KINDS),
        ('loop_trace', b('loop_trace.py') + ['{trace}'], KINDS),
        ('bench_alternate --report', b('bench_alternate.py') + ['--report', '{f}'], KINDS),
        ('bench_calculix', b('bench_calculix.py') + ['--exe', '{f}', '--programs', 'ldfcz', '--threads', '1',
                                                     '--repeat', '1', '--increments', '1', '--work', w('ccx')],
         KINDS),
        ('bench_host', b('bench_host.py') + ['--exe', '{f}', '--fine', '0.02', '--increments', '1', '--modes', 'full',
                                             '--out', w('bench_host')], KINDS),
        ('bench_material', b('bench_material.py') + ['--bin', '{f}', '--repeat', '1'], KINDS),
        ('bench_mpi', b('bench_mpi.py') + ['--exe', '{f}', '--fine', '0.02', '--increments', '1', '--out',
                                           w('bench_mpi')], KINDS),
        ('bench_omp_wait', b('bench_omp_wait.py') + ['--exe', '{f}', '--config', 'a=', '--repeat', '1', '--work',
                                                     w('omp')], KINDS),
        ('bench_window', b('bench_window.py') + ['--ldfcz', '{f}', '--work', w('window'), '--start', '1',
                                                 '--window', '1'], KINDS),
        ('material_point', [mp, '{f}'], KINDS),
        ('material_point output', [mp, 'steps=2', 'output={f}'], ('folder',)),
    ]


def check(label, argv, kind, env, cwd):
    p = subprocess.run(argv, capture_output=True, text=True, errors='replace', env=env, cwd=cwd, timeout=300)
    text = p.stdout + p.stderr
    err = [x for x in p.stderr.strip().splitlines() if x.strip()]
    last = err[-1] if err else ''
    prog = os.path.basename(argv[1] if argv[0] == sys.executable and argv[1] != '-m' else argv[0])
    if argv[1:2] == ['-m']:
        prog = '__main__.py|' + argv[2].split('.')[-1]
    bases = [n[:-3] if n.endswith('.py') else n for n in prog.split('|')]
    named = any(last.startswith(n + ': ') or last.startswith(n + '.py: ') for n in bases) or 'usage:' in p.stderr
    ok = p.returncode != 0 and not CRASH.search(text) and named
    print('%-34s %-7s exit %3d  %s' % (label, kind, p.returncode, last[:110]))
    if not ok:
        print(text[-3000:])
        fail('%s on a %s input: exit %d, %s' % (label, kind, p.returncode,
                                                 'a traceback' if CRASH.search(text) else 'no line naming it'))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--root', required=True, help='the source tree')
    ap.add_argument('--bin', required=True, help='the build\'s bin directory (ldfcz, material_point)')
    ap.add_argument('--out', required=True)
    ap.add_argument('--only', default='')
    a = ap.parse_args()
    root, out = os.path.abspath(a.root), os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    paths = make_inputs(out, os.path.join(a.bin, 'ldfcz'))
    env = dict(os.environ, PYTHONPATH=os.path.join(root, 'tools'), LDFCZ_NO_REEXEC='1')
    env.pop('LDFCZ_TRACEBACK', None)
    work = os.path.join(out, 'work')
    os.makedirs(work, exist_ok=True)
    n = 0
    for label, argv, kinds in commands(root, os.path.abspath(a.bin), work):
        if a.only not in label:
            continue
        for kind in kinds:
            args = [x.replace('{f}', paths[kind]).replace('{trace}', paths['trace_' + kind]) for x in argv]
            check(label, args, kind, env, work)
            n += 1
    # a Python without NumPy / VTK (python3 -S has no site packages): one line naming the module, exit 2
    curve = os.path.join(work, 'curve.csv')
    with open(curve, 'w') as f:
        f.write('u_mm,F_N_per_mm\n0.01,0.1\n0.02,0.2\n')
    for label, argv, module in (
            ('identify without NumPy', [sys.executable, '-S', os.path.join(root, 'tools', 'identify.py'), 'fit', curve,
                                        '--force-unit', 'N/mm'], 'numpy'),
            ('render_frame without VTK', [sys.executable, '-S', os.path.join(root, 'tools', 'render_frame.py'),
                                          curve], 'vtk')):
        p = subprocess.run(argv, capture_output=True, text=True, env=env, cwd=work, timeout=120)
        lines = p.stderr.strip().splitlines()
        print('%-34s exit %d  %s' % (label, p.returncode, lines[-1][:120] if lines else ''))
        if p.returncode != 2 or CRASH.search(p.stdout + p.stderr) or len(lines) != 1 or module not in lines[0] or \
                'python3-' not in lines[0]:
            fail('%s: exit %d, stderr %r' % (label, p.returncode, p.stderr))
        n += 1
    print('%d bad inputs: every command ended with a message and a non-zero exit, no traceback' % n)
    print('PASS')


if __name__ == '__main__':
    main()
