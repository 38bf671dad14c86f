#!/usr/bin/env python3
"""benchmarks/bench_mpi.py --refit on synthetic tables with a known answer (no solver needed): rows of two scenes of
N1, N2 DOFs on 1 to 16 processes whose memory per process follows m = m0 + m1 N / R + m2 N exactly on 2 or more
processes (the one-process rows off that line, as the serial path is) and whose element loop per iteration is
a N / R. The refit must read every row once (the table written twice, as a run prints it), fit the memory on the
distributed rows alone and recover m0, m1, m2 to the printed digits with a residual below 0.05 MB, leave the
one-process memory prediction out, and recover a. Usage: check_bench_refit.py TOOLS_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

M0, M1, M2, A = 35.0, 0.00625, 0.0015, 1.25e-5
HEADER = ('| scene | DOFs | run | increments / iterations | t/iteration (s) | element loop | communication | '
          'factorization | solve | factor entries (M) | element loop max/mean | element loop, slowest of each loop '
          'summed / mean | CPU/iteration rank 0 (s) | CPU/iteration all (s) | peak memory of a process (MB) | '
          'load average before |')


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def table(scene, n, ranks):
    rows = [HEADER, '|' + '---|' * 16]
    for r in ranks:
        mem = M0 + M1 * n / r + M2 * n + (120.0 if r == 1 else 0.0)   # the serial path off the line
        elem = A * n / r
        fact = 1e-9 * n ** 1.9 * (0.1 + 0.9 / r)
        name = '1 rank x 1 thread' if r == 1 else '%d ranks x 1 thread' % r
        rows.append('| %s | %d | %s | 8 / 29 | %.6f | %.6f | 0.000 | %.6f | 0.010 | 1.00 | - | - | 0 | 0 | %.4f | 0 |'
                    % (scene, n, name, elem + fact + 0.01, elem, fact, mem))
    return rows


def main():
    tools, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    a = os.path.join(work, 'a.md')
    b = os.path.join(work, 'b.md')
    ta = table('application', 90000, [1, 2, 4, 8, 16])
    with open(a, 'w') as f:
        f.write('Command: synthetic\n\n' + '\n'.join(ta) + '\n\n' + '\n'.join(ta) + '\n')   # printed twice
    with open(b, 'w') as f:
        f.write('\n'.join(table('application, full width', 170000, [1, 8, 16])) + '\n')
    p = subprocess.run([sys.executable, os.path.join(tools, 'bench_mpi.py'), '--refit', a, b, '--cluster-ranks', '1',
                        '32', '--out', work], capture_output=True, text=True, timeout=60)
    if p.returncode != 0:
        fail('bench_mpi.py --refit failed:\n' + p.stdout + p.stderr)
    out = p.stdout
    m = re.search(r'Rows read: (\d+)', out)
    if not m or int(m.group(1)) != 8:
        fail('rows read: %s, expected 8 (each row once)' % (m.group(1) if m else None))
    m = re.search(r'memory per process: m = (-?[\d.]+) MB \+ ([\d.e-]+) MB N / R \+ ([\d.e-]+) MB N \(fitted on (\d+) '
                  r'runs of 2 processes or more; largest residual ([\d.]+) MB\)', out)
    if not m:
        fail('no memory model fitted on the distributed runs:\n' + out)
    got = [float(x) for x in m.groups()[:3]]
    if abs(got[0] - M0) > 0.5 or abs(got[1] / M1 - 1) > 1e-3 or abs(got[2] / M2 - 1) > 1e-3:
        fail('memory model %s, expected %s' % (got, [M0, M1, M2]))
    if int(m.group(4)) != 6 or float(m.group(5)) > 0.05:
        fail('fitted on %s runs (expected 6), residual %s MB' % (m.group(4), m.group(5)))
    rows = dict(re.findall(r'^\| (\d+) \| [\d.]+ \| [\d.]+ \| [\d.]+ \| [\d.]+ \| (\S+) \|$', out, re.M))
    want32 = M0 + M1 * 170000 / 32 + M2 * 170000
    if rows.get('1') != '-' or abs(float(rows.get('32', 'nan')) - want32) > 1.0:
        fail('memory predictions %s, expected - on 1 process and %.0f MB on 32' % (rows, want32))
    m = re.search(r'element loop: t_e = ([\d.e-]+) N / R', out)
    if not m or abs(float(m.group(1)) / A - 1) > 1e-2:
        fail('element loop coefficient %s, expected %g' % (m.group(1) if m else None, A))
    print('refit: 8 rows, memory m = %s MB + %s N / R + %s N (residual %s MB), 32 processes %s MB, element loop %s N / R'
          % (got[0], got[1], got[2], float(re.search(r'residual ([\d.]+)', out).group(1)), rows['32'], A))
    print('PASS')


if __name__ == '__main__':
    main()
