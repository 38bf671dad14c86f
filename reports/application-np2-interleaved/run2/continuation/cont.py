#!/usr/bin/env python3
"""Continue run 2 (work-pc32b, stopped at increment 838, 589.9 um) from its restart files to past 1.0 mm of
delamination; record wall time against pull and the front of every new frame."""
import glob, os, shutil, signal, subprocess, sys, time
sys.path.insert(0, '/work/main/tools')
import peel_study as ps
src = '/work/runs/work-pc32b/paper_section_8'
out = '/work/runs/cont2/paper_section_8'
if os.path.isdir(out):
    shutil.rmtree(out)
shutil.copytree(src, out)
delta = 3.6788e-03
d_last = 0.871   # run 2's last frame (frame 22, inc 838): application_front.csv
f22 = sorted(glob.glob(out + '/paper_section_8_0022_*.vtu'))
x_front = d_last + ps.frame_front(f22, delta)
print('x_front %.6f mm (from frame 22)' % x_front, flush=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')
cmd = ['mpirun', '-np', '2', '--bind-to', 'none', sys.argv[1], '-q', '-t', '1', '--newton', 'auto',
       '--max-opening-increment', '0.33', '--max-plastic-increment', '1.0', '--factors', 'symmetric-single',
       '--restart-write', '100', '--restart-from', out + '/paper_section_8.rst', '--out', out,
       '/work/runs/work-pc32b/paper_section_8.inp']
print(' '.join(cmd), flush=True)
t0 = time.time()
p = subprocess.Popen(cmd, env=env, stdout=open('/work/runs/cont2/mpirun.out', 'w'), stderr=subprocess.STDOUT)
prog = open('/work/runs/cont2/progress.csv', 'w'); prog.write('wall_s,U1_mm\n')
fronts = open('/work/runs/cont2/front.csv', 'w'); fronts.write('frame,U1_mm,delaminated_mm,wall_s\n')
seen = set(os.path.basename(f) for f in glob.glob(out + '/*.pvtu'))
last_u = None; stop_sent = False
while p.poll() is None:
    time.sleep(2)
    u = ps.last_u1(out + '/paper_section_8.csv')
    if u is not None and u != last_u:
        prog.write('%.2f,%.6g\n' % (time.time() - t0, u)); prog.flush(); last_u = u
    for f in sorted(glob.glob(out + '/*.pvtu')):
        b = os.path.basename(f)
        if b in seen:
            continue
        time.sleep(1)
        seen.add(b)
        k = b.split('_')[-1].split('.')[0]
        pieces = sorted(glob.glob(out + '/paper_section_8_%s_*.vtu' % k))
        d = x_front - ps.frame_front(pieces, delta)
        import re
        ts = re.findall(r'timestep="\s*([0-9.Ee+-]+)"[^>]*file="%s"' % b, open(out + '/paper_section_8.pvd').read())
        uu = float(ts[0]) * 1e-3 if ts else float('nan')
        fronts.write('%s,%.6g,%.6g,%.2f\n' % (k, uu, d, time.time() - t0)); fronts.flush()
        print('frame %s: U1 %.4f mm, delaminated %.4f mm, %.0f s' % (k, uu, d, time.time() - t0), flush=True)
        if d >= 1.0 and not stop_sent:
            p.send_signal(signal.SIGUSR1); stop_sent = True
print('exit', p.returncode, 'wall %.1f s' % (time.time() - t0), flush=True)
