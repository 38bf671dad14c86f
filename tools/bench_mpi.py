#!/usr/bin/env python3
"""Distributed against threaded on this machine: the 3D quarter peel scene of tools/peel_deck.py (the family of
tools/bench_host.py: PET coating C3D8 + Leonov UMAT on a C3D8 steel substrate, LDF cohesive layer, l_e = 2 um, 10
elements over the width, 3 over the coating) run for a few increments by the LDFCZ_MPI build of ldfcz as

  1 rank x T threads   (mpirun -np 1 ldfcz --threads T: the serial code path, one MUMPS process)
  R ranks x 1 thread   (mpirun -np R ldfcz --threads 1: elements partitioned, MUMPS distributed)

and, with --serial-exe, the default (sequential MUMPS) build with T threads. Prints per configuration the Newton
iterations and the wall time per iteration split into element loop (assembly), communication of the host
(reductions of forces and flags, broadcasts of solutions: rank 0's), factorization and solve (MUMPS' own
communication is inside those two), rank 0's CPU time per iteration (less sensitive than the wall time to other
jobs on the machine) and the largest peak memory of a process; writes the table to OUT/bench_mpi.md.

  cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DLDFCZ_MPI=ON && cmake --build build-mpi -j2 --target ldfcz
  tools/bench_mpi.py --exe build-mpi/bin/ldfcz --serial-exe build/bin/ldfcz --fine 0.02 0.05 --increments 3
"""
import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

PATTERNS = {
    'counts': r'^increments (\d+), attempts (\d+), cutbacks (\d+), Newton iterations (\d+), factorizations (\d+)',
    'dofs': r'^DOFs (\d+), free equations (\d+)',
    'wall': r'^wall time\s+([\d.]+) s, CPU time\s+([\d.]+) s',
    'split': r'^wall time split: assembly\s+([\d.]+) s, factorization\s+([\d.]+) s, solve\s+([\d.]+) s, '
             r'output\s+([\d.]+) s',
    'setup': r'^solver setup \(pattern, METIS ordering, MUMPS analysis\)\s+([\d.]+) s',
    'comm': r'^MPI processes (\d+), communication of the host\s+([\d.]+) s.*peak memory of a process (\d+) kB',
    'memory': r'^peak memory \(VmHWM\) (\d+) kB',
}


def deck(args, fine, out):
    cmd = [sys.executable, os.path.join(HERE, 'peel_deck.py'), '--3d', '--le', str(args.le), '--ny', str(args.ny),
           '--nz', str(args.nz), '--fine-length', str(fine), '--bonded', str(fine + args.margin), '--du',
           str(args.du), '--u-total', str(args.du * args.increments), '--field-frequency', '0', '--info', '-o', out]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit('bench_mpi.py: peel_deck.py failed: ' + res.stderr)
    return json.loads(res.stderr.strip().splitlines()[-1])   # the mesh summary (--info)


def parse(path):
    text = open(path).read()
    r = {}
    for key, pat in PATTERNS.items():
        m = re.search(pat, text, re.M)
        r[key] = [float(g) for g in m.groups()] if m else None
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--exe', default=os.path.join(ROOT, 'build-mpi', 'bin', 'ldfcz'), help='LDFCZ_MPI ldfcz')
    ap.add_argument('--serial-exe', default=None, help='default-build ldfcz (sequential MUMPS) to compare too')
    ap.add_argument('--fine', type=float, nargs='+', default=[0.02, 0.05], help='fine-region lengths (mm)')
    ap.add_argument('--ranks', type=int, default=2, help='R of R ranks x 1 thread')
    ap.add_argument('--threads', type=int, default=2, help='T of 1 rank x T threads')
    ap.add_argument('--newton', default='full')
    ap.add_argument('--le', type=float, default=0.002)
    ap.add_argument('--ny', type=int, default=10)
    ap.add_argument('--nz', type=int, default=3)
    ap.add_argument('--margin', type=float, default=0.1)
    ap.add_argument('--du', type=float, default=0.0003)
    ap.add_argument('--increments', type=int, default=3)
    ap.add_argument('--out', default=os.path.join(ROOT, 'reports', 'bench'))
    ap.add_argument('--yield-idle', action='store_true', help='OMPI_MCA_mpi_yield_when_idle=1: a waiting process '
                    'gives its core away instead of polling (a machine shared with other jobs)')
    args = ap.parse_args()
    work = os.path.join(args.out, 'work_mpi')
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1',
               OMPI_MCA_rmaps_base_oversubscribe='1')
    if args.yield_idle:
        env['OMPI_MCA_mpi_yield_when_idle'] = '1'
    mpirun = ['mpirun', '--oversubscribe', '--bind-to', 'none']
    configs = [('1 rank x %d threads' % args.threads, mpirun + ['-np', '1', args.exe, '--threads', str(args.threads)]),
               ('%d ranks x 1 thread' % args.ranks, mpirun + ['-np', str(args.ranks), args.exe, '--threads', '1'])]
    if args.serial_exe:
        configs.insert(0, ('serial build, %d threads' % args.threads, [args.serial_exe, '--threads', str(args.threads)]))
    lines = ['| fine (mm) | DOFs | run | increments / iterations | t/iteration (s) | element loop | communication | '
             'factorization | solve | CPU/iteration rank 0 (s) | peak memory of a process (MB) |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for fine in args.fine:
        path = os.path.join(work, 'peel_%g.inp' % fine)
        deck(args, fine, path)
        for k, (name, cmd) in enumerate(configs):
            rdir = os.path.join(work, 'run_%g_%d' % (fine, k))
            os.makedirs(rdir, exist_ok=True)
            full = cmd + ['-q', '--newton', args.newton, '--out', rdir, path]
            res = subprocess.run(full, capture_output=True, text=True, env=env)
            if res.returncode != 0:
                sys.exit('bench_mpi.py: %s failed (exit %d):\n%s' % (' '.join(full), res.returncode,
                                                                    (res.stdout + res.stderr)[-2000:]))
            s = parse(os.path.join(rdir, 'peel_%g.log' % fine))
            inc, its = int(s['counts'][0]), int(s['counts'][3])
            asm, fact, solve = s['split'][0], s['split'][1], s['split'][2]
            comm = s['comm'][1] if s['comm'] else 0.0
            per = s['wall'][0] / its
            row = '| %g | %d | %s | %d / %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.0f |' % (
                fine, int(s['dofs'][0]), name, inc, its, per, asm / its, comm / its, fact / its, solve / its,
                s['wall'][1] / its, (s['comm'][2] if s['comm'] else s['memory'][0]) / 1024.0)
            lines.append(row)
            print(row, flush=True)
    load = open('/proc/loadavg').read().split()[:3] if os.path.exists('/proc/loadavg') else ['?']
    with open(os.path.join(args.out, 'bench_mpi.md'), 'w') as f:
        f.write('Command: tools/bench_mpi.py ' + ' '.join(sys.argv[1:]) + '\n\nLoad average at the end: ' +
                ' '.join(load) + ' (other jobs share the cores: wall times inflate, CPU time does not)\n\n' +
                '\n'.join(lines) + '\n')
    print('\n'.join(lines))


if __name__ == '__main__':
    main()
