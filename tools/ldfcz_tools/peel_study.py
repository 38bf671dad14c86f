#!/usr/bin/python3
"""Peel scenes and studies (paper sections 7-9): generate decks with tools/peel_deck.py, run bin/ldfcz on them,
collect JOB.csv, compute the steady peel force per unit width, and write reports/<study>/<study>.{csv,md,png}.

  peel_study.py main [--scene B]     the main plane-strain scene (reading A, the paper's text; --scene B the flap
                                     lifted at 90 degrees): prints the steady peel force per unit width with its
                                     averaging uncertainty and the discretisation band of the main-mesh study
  peel_study.py stmt-mesh-x|stmt-mesh-z|stmt-3d|...|mesh-x|mesh-z|simplifications|dofs|plastic-bound|
                app-settings|opening-bound|application [--quick]   (the whole list: docs/scenes.md)
  peel_study.py list                 the studies and their cases
  ... --ranks N --threads T --ldfcz build-mpi/bin/ldfcz    every case under `mpirun -np N` (the LDFCZ_MPI build),
                                     T threads per process; --reports DIR keeps these reports apart

Steady peel force: tools/ldfcz_tools/steady_force.py (the plateau window after the front has crossed 3 elements of the fine
region, its uncertainty, refused or flagged outside the fine region or before the plateau); the mean over the last
--plateau fraction of the pull (default 0.3) and its spread are kept as F_w_tail and spread. F/w = the reaction of
set LOAD along the pull (plane strain per unit thickness; 3D quarter model divided by b, the modelled width = half
the specimen width). Each study normalises by its reference case (per reading in the statement studies) and
reports |F/F_r - 1|, whether it is resolved, and the run time.
Python standard library only; matplotlib is used for the PNGs when it is installed.
"""
import argparse
import csv
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

THREADS = [2]  # set by main(), quoted in the reports
LDFCZ = ['']   # the ldfcz program (main()); material_point is looked for next to it
LAUNCH = []     # the launcher before ldfcz (--ranks: mpirun -np N), quoted in the reports
STAMP = ['']    # the reports' stamp, taken when the command starts (main())


def run_config():
    """How the runs were launched, for the reports: `-t N`, or `mpirun -np R` with `-t N` per process."""
    if LAUNCH:
        return '`%s`, `-t %d` per process' % (' '.join(LAUNCH), THREADS[0])
    return '`-t %d`' % THREADS[0]
from ldfcz_tools import outputs  # noqa: E402
from ldfcz_tools import peel_deck  # noqa: E402
from ldfcz_tools import steady_force as sfe  # noqa: E402
from ldfcz_tools.paths import ROOT  # noqa: E402

# The default plane-strain scene (the main job). Every study starts from these arguments. Pulled 0.1 mm with a fine
# region of 0.16 mm: the front (about 1.5 um per um of pull once steady) stays in the fine region, and the steady
# force is read over a plateau of 40-50 um of pull (tools/ldfcz_tools/steady_force.py; issue 17).
DEFAULT_PS = ['--rigid-substrate', '--u-total', '0.1', '--fine-length', '0.16']
DEFAULT_3D = ['--3d', '--rigid-substrate']
# Reading B of Fig. 10 (issue 17): the pre-delaminated flap (0.1 mm: a bend of radius 1.5 h_c to 90 degrees, then
# straight) lifted and pulled at 90 degrees, u_x free (carriage grip: the pull stays normal to the interface; a
# fixed grip would let the peel angle fall to about 55 degrees as the front runs 75 um away from it). Pulled
# 0.16 mm over a 0.2 mm fine region: the front advances about 0.8 um per um of pull, and the force settles slowly.
READING_B = ['--rigid-substrate', '--reading', 'peel', '--flap', '0.1', '--grip', 'carriage', '--u-total', '0.16',
             '--fine-length', '0.2']
# The main scene (issue 17: the reading the paper's statements favour): reading B pulled 0.2 mm over a 0.25 mm fine
# region, long enough for its plateau (from about 110-140 um of pull; stmt-3d-long pulls 0.32 mm for the same value
# within the uncertainties)
MAIN_B = READING_B + ['--u-total', '0.2', '--fine-length', '0.25', '--bonded', '0.35']
# Reading A as the scene of the studies of issue 35 (main-mesh): pulled 0.1 mm over a 0.2 mm fine region (the front,
# about 125 um delaminated at the end, stays 75 um, more than twice its process zone, inside the fine region).
SCENE_A = ['--rigid-substrate', '--u-total', '0.1', '--fine-length', '0.2']
# The main scene (issue 35): reading A, the paper's text (u_x on one end of the coating), on the mesh of the
# main-mesh study
MAIN_A_MESH = ['--le', '0.005', '--nz', '9']
MAIN_A = SCENE_A + MAIN_A_MESH
# Reading B pulled until every run reads its plateau (0.32 mm over a 0.4 mm fine region; issue 17)
LONG_B = READING_B + ['--u-total', '0.32', '--fine-length', '0.4', '--bonded', '0.5']


def studies(quick):
    """Cases per study: (label, generator arguments, is_reference). quick: fewer/cheaper cases (CI smoke)."""
    s = {}
    les = [0.02, 0.01, 0.005] if quick else [0.02, 0.01, 0.005, 0.0025, 0.002, 0.00125]
    s['mesh-x'] = [('le=%g' % le, DEFAULT_PS + ['--le', str(le)], le == les[-1]) for le in les]
    nzs = [1, 2, 3] if quick else [1, 2, 3, 5, 9]
    s['mesh-z'] = [('nz=%d' % nz, DEFAULT_PS + ['--nz', str(nz)], nz == nzs[-1]) for nz in nzs]
    # the PET model's accuracy bound PROPS(11) on the plastic strain increment (the UMAT's PNEWDT threshold) at the
    # section 8 discretisation through the thickness (l_e = 2 um, n_z = 3), plane strain, up to 1 um/inc; the
    # reference: the default bound 0.05 at 0.1 um/inc
    # pulled 0.1 mm over a 0.16 mm fine region (DEFAULT_PS): reading A's plateau from ~40 um (60 um were too short
    # for the plateau detection of tools/ldfcz_tools/steady_force.py)
    psb = DEFAULT_PS + ['--le', '0.002', '--nz', '3']
    gms = [0.05, 0.2, 1.0] if quick else [0.05, 0.1, 0.2, 0.5, 1.0]
    s['plastic-bound'] = [('reference: 0.05, 0.1 um/inc', psb + ['--du', '0.0001'], True,
                           ['--newton', 'auto', '--max-opening-increment', '0.33', '--max-plastic-increment', '0.05'])]
    s['plastic-bound'] += [('dgamma_max=%g' % g, psb + ['--du', '0.001', '--dgamma-max', str(g)], False,
                            ['--newton', 'auto', '--max-opening-increment', '0.33', '--max-plastic-increment', str(g)])
                           for g in gms]
    # the same without the linear extrapolation of the increment start (*STEP, EXTRAPOLATION=NO)
    s['plastic-bound'] += [('dgamma_max=%g, no extrapolation' % g, psb + ['--du', '0.001', '--dgamma-max', str(g),
                                                                         '--no-extrapolation'], False,
                            ['--newton', 'auto', '--max-opening-increment', '0.33', '--max-plastic-increment', str(g)])
                           for g in (0.05, 1.0)]
    # every case pulled as the default scene (0.1 mm over a 0.16 mm fine region: reading A's plateau from ~40 um)
    pull = ['--u-total', '0.1', '--fine-length', '0.16']
    s['simplifications'] = [
        ('full: steel, uniform mesh', pull + ['--no-coarse'], True),
        ('steel, coarse far field', pull, False),
        ('rigid, uniform mesh', pull + ['--rigid-substrate', '--no-coarse'], False),
        ('rigid, coarse far field (default)', DEFAULT_PS, False),
    ]
    # ---- the paper's statements against both readings of Fig. 10 (issue 17): A the 0-degree bridge (0.1 mm of pull
    # over a 0.16 mm fine region), B the flap lifted and pulled at 90 degrees (READING_B); plane strain unless said,
    # rigid substrate. Reference per reading (marked *).
    rd = {'A': DEFAULT_PS, 'B': READING_B}
    les = [0.02, 0.01, 0.005] if quick else [0.02, 0.01, 0.005, 0.0025]
    s['stmt-mesh-x'] = [('%s le=%g' % (k, le), a + ['--le', str(le)], le == les[-1]) for k, a in rd.items()
                        for le in les]
    nzs = [1, 2, 3] if quick else [1, 2, 3, 5, 9]
    s['stmt-mesh-z'] = [('%s nz=%d' % (k, nz), a + ['--nz', str(nz)], nz == nzs[-1]) for k, a in rd.items()
                        for nz in nzs]
    # plane strain against the 3D quarter (coarse: l_e = 20 um, n_z = 2), the width mesh n_y = 1, 2, 4 at
    # b = 0.04 mm and the narrower model b = 0.02 mm; reference: 3D n_y = 4, b = 0.04
    c3 = ['--le', '0.02', '--nz', '2']
    nys = [2] if quick else [1, 2, 4]
    s['stmt-3d'] = []
    for k, a in rd.items():
        s['stmt-3d'].append(('%s plane strain' % k, a + c3, False))
        for ny in nys:
            s['stmt-3d'].append(('%s 3D b=0.04 ny=%d' % (k, ny), a + c3 + ['--3d', '--width', '0.04', '--ny', str(ny)],
                                 ny == nys[-1], ['--newton', 'auto']))
        if not quick:
            s['stmt-3d'].append(('%s 3D b=0.02 ny=2' % k, a + c3 + ['--3d', '--width', '0.02', '--ny', '2'], False,
                                 ['--newton', 'auto']))
    # the same at the main discretisation (l_e = 10 um, n_z = 3; 3D with n_y = 2: the width mesh is converged to
    # within the uncertainties in stmt-3d)
    s['stmt-3d-fine'] = []
    for k, a in rd.items():
        s['stmt-3d-fine'] += [('%s plane strain' % k, a, False),
                              ('%s 3D b=0.04 ny=2' % k, a + ['--3d', '--width', '0.04', '--ny', '2'], True,
                               ['--newton', 'auto'])]
    # reading B pulled until its force settles (0.32 mm over a 0.4 mm fine region: plateau from about 110 um)
    bl = READING_B + ['--u-total', '0.32', '--fine-length', '0.4', '--bonded', '0.5']
    s['stmt-mesh-z-long'] = [('B nz=%d' % nz, bl + ['--nz', str(nz)], nz == nzs[-1]) for nz in nzs]
    s['stmt-3d-long'] = [('B plane strain', bl, False),
                         ('B 3D b=0.04 ny=2', bl + ['--3d', '--width', '0.04', '--ny', '2'], True, ['--newton', 'auto'])]
    # reading B's l_e, width and increment statements pulled 0.32 mm as well (the 0.16 mm pulls of stmt-mesh-x,
    # stmt-3d and stmt-increment end before B's plateau); same labels as the short studies, so that the statement
    # table takes them in their place when they have been run
    s['stmt-mesh-x-long'] = [('B le=%g' % le, bl + ['--le', str(le)], le == les[-1]) for le in les]
    # the same with the paper's nine elements through the thickness (n_z = 3 is 3.4 % off in reading B:
    # stmt-mesh-z-long), so that the l_e error is not mixed with the thickness error
    s['stmt-mesh-x-long-nz9'] = [('B le=%g nz=9' % le, bl + ['--le', str(le), '--nz', '9'], le == les[-1])
                                 for le in les[1:]]
    s['stmt-3d-width-long'] = [('B plane strain', bl + c3, False)]
    s['stmt-3d-width-long'] += [('B 3D b=0.04 ny=%d' % ny, bl + c3 + ['--3d', '--width', '0.04', '--ny', str(ny)],
                                 ny == nys[-1], ['--newton', 'auto']) for ny in nys]
    if not quick:
        s['stmt-3d-width-long'].append(('B 3D b=0.02 ny=2', bl + c3 + ['--3d', '--width', '0.02', '--ny', '2'], False,
                                        ['--newton', 'auto']))
    # increments: the PET accuracy bound off (PROPS(11) = 1e6) so that the requested pull per increment is what is
    # taken unless Newton cuts back; reference: the default bound 0.05 at 0.1 um/inc
    dus = [0.0003, 0.001] if quick else [0.0001, 0.0003, 0.001, 0.003, 0.01]
    s['stmt-increment'] = []
    for k, a in rd.items():
        s['stmt-increment'].append(('%s reference: bound 0.05, 0.1 um/inc' % k, a + ['--du', '0.0001'], True))
        s['stmt-increment'] += [('%s bound off, %g um/inc' % (k, 1e3 * du), a + ['--du', str(du), '--dgamma-max',
                                                                                '1e6', '--dt-min-ratio', '1e-4'],
                                 False) for du in dus]
    s['stmt-increment-long'] = [('B reference: bound 0.05, 0.1 um/inc', bl + ['--du', '0.0001'], True)]
    s['stmt-increment-long'] += [('B bound off, %g um/inc' % (1e3 * du), bl + ['--du', str(du), '--dgamma-max', '1e6',
                                                                             '--dt-min-ratio', '1e-4'], False)
                                 for du in dus]
    # reading B with the fixed grip at 90 degrees (the peel angle falls as the front runs away from the grip's line):
    # the l_e study of the regression test peel_readings' reference
    bf = ['--rigid-substrate', '--reading', 'peel', '--flap', '0.1', '--u-total', '0.1', '--fine-length', '0.16']
    s['stmt-mesh-x-fixed'] = [('B le=%g' % le, bf + ['--le', str(le)], le == les[-1]) for le in les]
    # Table 1 as printed against the alternative (--pet alt: S_a halved, same aged viscosity), both readings, plane
    # strain at the main mesh: T_max, phi and pull-rate sensitivities (reference: T_max 20 MPa, phi 0.2 N/mm, 1 um/s)
    s['table1'] = []
    for k, a in rd.items():
        for pet in ('table1', 'alt'):
            g = a + ['--pet', pet]
            s['table1'] += [('%s/%s base' % (k, pet), g, True),
                            ('%s/%s T_max=10' % (k, pet), g + ['--tmax', '10'], False),
                            ('%s/%s T_max=40' % (k, pet), g + ['--tmax', '40'], False),
                            ('%s/%s phi=0.1' % (k, pet), g + ['--phi', '0.1'], False),
                            ('%s/%s phi=0.4' % (k, pet), g + ['--phi', '0.4'], False),
                            ('%s/%s rate=1e-4' % (k, pet), g + ['--rate', '1e-4'], False),
                            ('%s/%s rate=1e-2' % (k, pet), g + ['--rate', '1e-2'], False)]
    # ---- issue 35: the main scene (reading A) without the ripple. Element length l_e x elements through the
    # thickness n_z x element formulation (CPE4: full integration, F-bar; CPE4I: incompatible modes, free of
    # shear locking in bending), so that the thickness error is separated from l_e; reference: the finest of each
    # formulation (marked *, one per formulation)
    mm_les = [0.01, 0.005] if quick else [0.01, 0.005, 0.0025]
    mm_nzs = [3, 5] if quick else [3, 5, 9]
    s['main-mesh'] = []
    for el, ea in (('CPE4', []), ('CPE4I', ['--incompatible'])):
        s['main-mesh'] += [('%s le=%g nz=%d' % (el, le, nz), SCENE_A + ['--le', str(le), '--nz', str(nz)] + ea,
                            le == mm_les[-1] and nz == mm_nzs[-1] and el == 'CPE4I') for nz in mm_nzs
                           for le in mm_les]
    if not quick:
        # beyond the grid, with the full-integration element: half the finest l_e at n_z = 9, and n_z = 13 at
        # l_e = 2.5 um (does the force settle when both are refined further?)
        s['main-mesh'] += [('CPE4 le=0.00125 nz=9', SCENE_A + ['--le', '0.00125', '--nz', '9'], False),
                           ('CPE4 le=0.0025 nz=13', SCENE_A + ['--le', '0.0025', '--nz', '13'], False)]
    # the three unloading behaviours of the cohesive law (paper Fig. 6, section 8: no noticeable influence) on the
    # main scene; reference: 2 (elastic damage, the decks' default)
    s['unloading'] = [('A unloading=%d' % k, MAIN_A + ['--unloading', str(k)], k == 2) for k in (1, 2, 3)]
    s['unloading'] += [('B unloading=%d' % k, LONG_B + ['--unloading', str(k)], k == 2)
                       for k in ((2,) if quick else (1, 2, 3))]
    # reading B on the elastic steel substrate against the rigid one (reading A: simplifications study)
    steel_b = [a for a in LONG_B if a != '--rigid-substrate']
    s['steel-b'] = [('B rigid substrate', LONG_B, True), ('B steel substrate', steel_b, False)]
    # the plane-strain/3D gap (section 9) and the lateral contraction: plane strain, 3D quarter models of growing
    # width b (element width 10 um), and the 3D quarter with its free edge y = b held in y (u_y = 0: no lateral
    # contraction at the edge); l_e = 10 um, n_z = 3. Reference: plane strain
    wb = [0.02, 0.04] if quick else [0.02, 0.04, 0.08, 0.16]
    s['width-3d'] = [('A plane strain', SCENE_A, True)]
    s['width-3d'] += [('A 3D b=%g ny=%d' % (b, round(b / 0.01)), SCENE_A + ['--3d', '--width', str(b), '--ny',
                                                                           str(round(b / 0.01))], False,
                       ['--newton', 'auto']) for b in wb]
    s['width-3d'] += [('A 3D b=0.04 ny=4 edge held in y', SCENE_A + ['--3d', '--width', '0.04', '--ny', '4',
                                                                     '--edge-fixed-y'], False, ['--newton', 'auto'])]
    if not quick:
        s['width-3d'] += [('B plane strain', LONG_B, True),
                          ('B 3D b=0.04 ny=2', LONG_B + ['--3d', '--width', '0.04', '--ny', '2'], False,
                           ['--newton', 'auto']),
                          ('B 3D b=0.04 ny=2 edge held in y', LONG_B + ['--3d', '--width', '0.04', '--ny', '2',
                                                                         '--edge-fixed-y'], False,
                           ['--newton', 'auto'])]
    # the alternative reading of Table 1 (--pet alt) on the plane-strain/3D statement, both readings (Table 1 as
    # printed: stmt-3d-fine and stmt-3d-long); reference per reading: 3D
    s['pet-alt'] = [('A plane strain', SCENE_A + ['--pet', 'alt'], False),
                    ('A 3D b=0.04 ny=2', SCENE_A + ['--pet', 'alt', '--3d', '--width', '0.04', '--ny', '2'], True,
                     ['--newton', 'auto']),
                    ('B plane strain', LONG_B + ['--pet', 'alt'], False),
                    ('B 3D b=0.04 ny=2', LONG_B + ['--pet', 'alt', '--3d', '--width', '0.04', '--ny', '2'], True,
                     ['--newton', 'auto'])]
    # Fig. 13: the main scene's reading and mesh pulled until 1.0 mm has delaminated (plane strain; the 3D quarter
    # of section 8 is the application study), with the Mises picture of the last frame
    s['fig13'] = [('A plane strain 1.0 mm', MAIN_A_MESH + ['--rigid-substrate', '--fine-length', '1.15', '--bonded',
                                                           '1.3', '--u-total', '0.7', '--field-frequency', '200'],
                   True)]
    s['dofs'] = [('le=%g nz=%d' % (le, nz), DEFAULT_PS + ['--le', str(le), '--nz', str(nz), '--u-total', '0.01'],
                  False) for le, nz in ((0.02, 2), (0.01, 3), (0.005, 3), (0.0025, 5))]
    # 3D members (short pulls): a wider range of DOFs, where the factorization begins to show.
    s['dofs'] += [('3D le=%g nz=%d ny=%d' % (le, nz, ny), DEFAULT_3D + ['--le', str(le), '--nz', str(nz), '--ny',
                                                                          str(ny), '--u-total', '0.005'], False)
                  for le, nz, ny in (((0.01, 3, 4), (0.005, 3, 8)) if quick else
                                     ((0.01, 3, 4), (0.005, 3, 8), (0.0025, 3, 10)))]
    # Section 8: 10 elements in y, 3 in z, l_e = 2 um (the paper's discretisation in the fine region), rigid
    # substrate (0.01 % effect, docs/scenes.md). Increment settings (study app-settings: 0.4 % from the reference
    # settings on the first 60 um of pull, 7.9x faster): up to 1 um of pull per increment, the opening increment
    # bound delta/3 of paper section 7, the PET accuracy bound PROPS(11) = 1.0 (plastic strain increment), linear
    # extrapolation (the default).
    app_solver = ['--newton', 'auto', '--max-opening-increment', '0.33', '--max-plastic-increment', '1.0']
    app_gen = DEFAULT_3D + ['--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.001', '--dgamma-max', '1.0']
    s60 = ['--fine-length', '0.07', '--bonded', '0.15', '--u-total', '0.06', '--field-frequency', '25']
    # the reference settings: the UMAT's default bound 0.05, 0.3 um/inc requested, no extrapolation
    ref_solver = ['--newton', 'auto', '--max-opening-increment', '0.33', '--max-plastic-increment', '0.05']
    ref_gen = DEFAULT_3D + ['--ny', '10', '--nz', '3', '--le', '0.002', '--du', '0.0003', '--no-extrapolation']
    s['app-settings'] = [('reference settings', ref_gen + s60, True, ref_solver),
                         ('application settings', app_gen + s60, False, app_solver)]
    # the cohesive opening increment bound of paper section 7 (delta/3 in the application) on the same 60 um: how far
    # can it be raised for an error below 0.5 % (issue 5), and what does that save (issue 4's one-hour goal)?
    # Reference: delta/10. In case the 1 um/inc cap of --du binds above delta/3, the two largest bounds also with
    # up to 3 um/inc.
    ob_solver = ['--newton', 'auto', '--max-plastic-increment', '1.0', '--max-opening-increment']
    k = app_gen.index('--du')
    app_gen3 = app_gen[:k + 1] + ['0.003'] + app_gen[k + 2:]
    s['opening-bound'] = [('delta/10', app_gen + s60, True, ob_solver + ['0.1']),
                          ('delta/3 (application)', app_gen + s60, False, ob_solver + ['0.33']),
                          ('delta/2', app_gen + s60, False, ob_solver + ['0.5']),
                          ('delta/1', app_gen + s60, False, ob_solver + ['1.0']),
                          ('delta/1, up to 3 um/inc', app_gen3 + s60, False, ob_solver + ['1.0']),
                          ('2 delta, up to 3 um/inc', app_gen3 + s60, False, ob_solver + ['2.0'])]
    if quick:
        s['application'] = [('section 8 mesh, short', app_gen + [
            '--fine-length', '0.02', '--bonded', '0.1', '--u-total', '0.01', '--field-frequency', '10'], True,
            app_solver)]
    else:
        # the paper's application: fine region over 1.05 mm, pulled until more than 1.0 mm has delaminated (the
        # front advances ~1.5 mm per mm of pull after the first 60 um: app-settings)
        # Linear algebra: LDL^T factors of the symmetric part in single precision as the GMRES preconditioner
        # (--factors symmetric-single; the Newton iterates hold within the GMRES tolerance): 28 % less time in
        # factorizations and solves on a window of this scene (benchmarks/bench_window.py, docs/performance.md)
        s['application'] = [('paper section 8', app_gen + [
            '--fine-length', '1.05', '--bonded', '1.2', '--u-total', '0.72', '--field-frequency', '40'], True,
            app_solver + ['--factors', 'symmetric-single'])]
    return s


def stamp():
    """Provenance of a report: the source tree's commit (and whether tracked files differed from it), the ldfcz
    program's own `ldfcz -V` line (its commit at configure time and build type), the command, the date and the
    machine. Returned as (markdown line, dict)."""
    def git(*args):
        try:
            return subprocess.run(['git', '-C', ROOT] + list(args), capture_output=True, text=True,
                                  timeout=30).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            return ''
    commit = git('rev-parse', '--short=12', 'HEAD') or 'unknown'
    # the sources only: the reports being written are not what made them
    dirty = bool(git('status', '--porcelain', '--untracked-files=no', '--', '.', ':(exclude)reports')) \
        if commit != 'unknown' else False
    try:
        version = subprocess.run([LDFCZ[0], '-V'], capture_output=True, text=True,
                                 timeout=30).stdout.strip() if LDFCZ[0] else ''
    except (OSError, subprocess.SubprocessError):
        version = ''
    cpu = ''
    try:
        with open('/proc/cpuinfo') as fh:
            cpu = next((ln.split(':', 1)[1].strip() for ln in fh if ln.startswith('model name')), '')
    except OSError:
        pass
    d = {'commit': commit + (' with uncommitted changes to tracked source files' if dirty else ''),
         'ldfcz': version or 'unknown', 'command': '/usr/bin/python3 tools/peel_study.py ' + ' '.join(
             os.path.relpath(a, ROOT) if os.path.isabs(a) and a.startswith(ROOT) else a for a in sys.argv[1:]),
         'date': time.strftime('%Y-%m-%d %H:%M %Z'),
         'machine': '%s, %d cores visible%s' % (os.uname().nodename, os.cpu_count() or 1, ', ' + cpu if cpu else '')}
    line = ('Stamp: commit %s; program `%s`; command `%s`; %s; machine %s.' % (
        d['commit'], d['ldfcz'], d['command'], d['date'], d['machine']))
    return line, d


def find_ldfcz(path):
    if path:
        return path
    for cand in (os.path.join(ROOT, 'build', 'bin', 'ldfcz'), shutil.which('ldfcz')):
        if cand and os.path.exists(cand):
            return cand
    raise SystemExit('peel_study: bin/ldfcz not found: build first (tools/setup.sh) or pass --ldfcz')


def read_history(csv_path, info=None):
    """(pull, force) lists from JOB.csv: reading A (bridge) the columns LOAD.U1, LOAD.RF1; reading B (peel, info
    from peel_deck.build) the displacement and reaction of LOAD along the pull direction d (x, z plane)."""
    u, f = [], []
    d = info.get('pull_dir', (1.0, 0.0)) if info and info.get('reading') == 'peel' else None
    with open(csv_path) as fh:
        rows = csv.DictReader(fh)
        for r in rows:
            if d is None:
                u.append(float(r['LOAD.U1']))
                f.append(float(r['LOAD.RF1']))
            else:
                z = info['z_dof']
                u.append(d[0] * float(r['LOAD.U1']) + d[1] * float(r['LOAD.U%d' % z]))
                f.append(d[0] * float(r['LOAD.RF1']) + d[1] * float(r['LOAD.RF%d' % z]))
    return u, f


# the figures of the closing summary the reports keep, and where JOB.summary.json has them (docs/summary.md)
SUMMARY_FIGURES = {
    'increments': 'counters.increments', 'attempts': 'counters.attempts', 'cutbacks': 'counters.cutbacks',
    'iterations': 'counters.iterations', 'dofs': 'model.dofs', 'wall_s': 'times.wall_s',
    't_assembly_s': 'times.element_loop_s', 't_factor_s': 'times.factorization_s',
    'w_ext': 'energy.external_work', 'e_int': 'energy.stored_dissipated',
    'energy_rel_diff': 'energy.relative_difference', 'max_open_ratio': 'accuracy.max_opening_ratio',
}


def read_summary(outdir, job):
    """Numbers of the host's closing summary (JOB.summary.json; whatever of them are present)."""
    doc = outputs.read_summary(outdir, job)
    if doc is None:
        return {}
    out = {}
    for k, key in SUMMARY_FIGURES.items():
        v = outputs.get(doc, key)
        if v is not None:
            out[k] = float(v)
    return out


def read_sta(sta_path):
    """Increments, attempts, cutbacks and Newton iterations counted from JOB.sta (for runs stopped before their
    closing summary)."""
    out = {'increments': 0, 'attempts': 0, 'cutbacks': 0, 'iterations': 0}
    if not os.path.exists(sta_path):
        return out
    for line in open(sta_path):
        w = line.split()
        if not w or w[0].startswith('#') or len(w) < 7:
            continue
        out['attempts'] += 1
        out['iterations'] += int(w[3])
        if w[6] == 'converged':
            out['increments'] += 1
        else:
            out['cutbacks'] += 1
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
    with open(vtu_path) as fh:
        text = fh.read()

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


def read_vtu_arrays(vtu_path, names):
    """Reference points (flat x, y, z list) and the named DataArrays (None where absent) of a VTU frame."""
    with open(vtu_path) as fh:
        text = fh.read()
    pm = re.search(r'<Points><DataArray[^>]*>(.*?)</DataArray>', text, re.S)
    out = {}
    for name in names:
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        out[name] = [float(v) for v in m.group(1).split()] if m else None
    return [float(v) for v in pm.group(1).split()], out


def process_zone(files, delta, rows=1):
    """The softening part of the cohesive zone in a frame: the cohesive cells whose opening lies between delta
    (the peak traction) and 6 delta (4 % of it left), counted per row of cells along x (rows: elements over the
    width). Returns (number of cells per row, their extent along x in mm); (0, 0) when none."""
    n, xs = 0, []
    for v in with_interface_blocks(files):
        pts, a = read_vtu_arrays(v, ('connectivity', 'offsets', 'cohesive', 'opening'))
        if None in a.values():
            continue
        start = 0
        for i, o in enumerate(a['offsets']):
            o = int(o)
            if a['cohesive'][i] >= 1:
                d = math.sqrt(sum(c * c for c in a['opening'][3 * i:3 * i + 3]))
                if delta < d < 6.0 * delta:
                    ids = [int(c) for c in a['connectivity'][start:o]]
                    n += 1
                    xs.append(sum(pts[3 * j] for j in ids) / len(ids))
            start = o
    return (n / float(max(rows, 1)), (max(xs) - min(xs)) if xs else 0.0)


def lateral_contraction(vtu_path, info):
    """3D quarter model: the lateral stretch of the coating's top face, lambda_y = 1 + (u_y(b) - u_y(0)) / b, and
    the axial stretch lambda_x = 1 + du_x/dx, per column of nodes along x (reference x, lambda_x, lambda_y mid-width,
    lambda_y at the edge), from the node numbering of tools/peel_deck.py (coating nodes first, x fastest, then y,
    then z). None for a plane-strain frame."""
    if info['dimension'] != 3:
        return None
    pts, a = read_vtu_arrays(vtu_path, ('U',))
    uu = a['U']
    nxt = info['n_far_x'] + info['n_fine_x'] + info['n_flap_x']
    nyn = info['ny'] + 1
    iz = info['nz_coating']

    def node(ix, iy):
        return ix + (nxt + 1) * (iy + nyn * iz)         # 0-based VTU point of coating node (ix, iy, top face)
    out = []
    for ix in range(nxt + 1):
        k0, kb, k1 = node(ix, 0), node(ix, nyn - 1), node(ix, 1)
        b = pts[3 * kb + 1] - pts[3 * k0 + 1]
        dy = pts[3 * k1 + 1] - pts[3 * k0 + 1]
        kb1 = node(ix, nyn - 2)
        lam_mid = 1.0 + (uu[3 * k1 + 1] - uu[3 * k0 + 1]) / dy
        lam_edge = 1.0 + (uu[3 * kb + 1] - uu[3 * kb1 + 1]) / (pts[3 * kb + 1] - pts[3 * kb1 + 1])
        lam_mean = 1.0 + (uu[3 * kb + 1] - uu[3 * k0 + 1]) / b
        if ix < nxt:
            j = node(ix + 1, 0)
            dx = math.dist(pts[3 * j:3 * j + 3], pts[3 * k0:3 * k0 + 3])
            lam_x = math.dist([pts[3 * j + c] + uu[3 * j + c] for c in range(3)],
                              [pts[3 * k0 + c] + uu[3 * k0 + c] for c in range(3)]) / dx
        else:
            lam_x = out[-1][1] if out else 1.0
        out.append((pts[3 * k0], lam_x, lam_mid, lam_edge, lam_mean))
    return out


def vtu_frames(outdir):
    """The ParaView frames of a run directory in order, each as the list of its files: JOB_NNNN.vtu of a serial
    run, or the pieces JOB_NNNN_R.vtu of a distributed one (one per process, each with its own elements)."""
    if not os.path.isdir(outdir):
        return []
    frames = {}
    for x in os.listdir(outdir):
        m = re.search(r'_(\d{4,})(_\d+)?\.vtu$', x)     # JOB_NNNN.vtu or JOB_NNNN_R.vtu
        if m:
            frames.setdefault(int(m.group(1)), []).append(os.path.join(outdir, x))
    return [sorted(frames[k]) for k in sorted(frames)]


def with_interface_blocks(files):
    """The pieces of a frame with their interface blocks: JOB_NNNN[_R].vtu and JOB_NNNN_interface[_R].vtu (the
    cohesive cells are written in a block of their own beside each piece)."""
    return files + [x for x in (re.sub(r'_(\d{4,})(_\d+)?\.vtu$', r'_\1_interface\2.vtu', v) for v in files)
                    if x not in files and os.path.exists(x)]


def frame_front(files, delta):
    """The delamination front of a frame: the smallest over its pieces (read_vtu_front); the cohesive cells are in
    the frame's interface block beside each piece (JOB_NNNN[_R].vtu: JOB_NNNN_interface[_R].vtu)."""
    files = with_interface_blocks(files)
    fronts = [f for f in (read_vtu_front(v, delta) for v in files) if f is not None]
    return min(fronts) if fronts else None


def last_u1(csv_path):
    """LOAD.U1 of the last complete row of JOB.csv (None when there is none yet)."""
    try:
        with open(csv_path) as fh:
            lines = fh.read().splitlines()
    except OSError:
        return None
    if len(lines) < 2:
        return None
    head = lines[0].split(',')
    try:
        return float(lines[-1].split(',')[head.index('LOAD.U1')])
    except (ValueError, IndexError):
        return float(lines[-2].split(',')[head.index('LOAD.U1')]) if len(lines) > 2 else None


def cpu_busy(dt=1.0):
    """Fraction of all cores busy over dt seconds (from /proc/stat; 0 where it is not readable)."""
    def sample():
        with open('/proc/stat') as fh:
            v = [int(x) for x in fh.readline().split()[1:]]
        return sum(v), v[3] + (v[4] if len(v) > 4 else 0)
    try:
        t0, i0 = sample()
        time.sleep(dt)
        t1, i1 = sample()
    except (OSError, ValueError):
        return 0.0
    return 1.0 - (i1 - i0) / float(max(t1 - t0, 1))


def wait_idle(max_wait, threshold=0.15):
    """Wait (at most max_wait s) until the cores are busy less than threshold; returns the last busy fraction."""
    t0 = time.time()
    busy = cpu_busy()
    while busy > threshold and time.time() - t0 < max_wait:
        busy = cpu_busy(2.0)
    return busy


def run_case(label, gen_args, workdir, ldfcz, threads, plateau, solver_args=(), time_limit=0.0, idle_wait=0.0,
             reuse=None):
    """Generate the deck, run ldfcz (stopped with SIGTERM after time_limit s when > 0: what converged is kept),
    and collect the results. progress: (wall s, U1 mm) sampled every second from JOB.csv."""
    os.makedirs(workdir, exist_ok=True)
    job = re.sub(r'[^A-Za-z0-9_.-]+', '_', label).strip('_') or 'case'
    deck = os.path.join(workdir, job + '.inp')
    p = peel_deck.parser().parse_args(gen_args + ['-o', deck])
    peel_deck.check(p)
    text, info = peel_deck.build(p)
    with open(deck, 'w') as fh:
        fh.write(text)
    outdir = os.path.join(workdir, job)
    if reuse is not None:
        return reuse_case(label, gen_args, solver_args, outdir, job, info, p, plateau, reuse)
    if os.path.isdir(outdir):
        shutil.rmtree(outdir)
    cmd = LAUNCH + [ldfcz, '-q', '-t', str(threads), '-o', outdir] + list(solver_args) + [deck]
    busy0 = wait_idle(idle_wait) if idle_wait > 0 else cpu_busy(0.5)
    load0 = os.getloadavg()[0]
    t0 = time.time()
    cpu0 = os.times().children_user + os.times().children_system
    proc = subprocess.Popen(cmd)
    progress, stopped = [(0.0, 0.0)], False
    csv_path = os.path.join(outdir, job + '.csv')
    while True:
        try:
            rc = proc.wait(timeout=1.0)
            break
        except subprocess.TimeoutExpired:
            pass
        now = time.time() - t0
        x = last_u1(csv_path)
        if x is not None and x > progress[-1][1]:
            progress.append((now, x))
        if time_limit > 0 and now > time_limit and not stopped:
            # OpenMPI's mpirun does not forward SIGTERM (it sends the processes SIGTERM a second later and SIGKILL a
            # second after that, too soon for an increment of this scene) but forwards SIGUSR1, the same graceful
            # stop (docs/host.md)
            proc.send_signal(signal.SIGUSR1 if LAUNCH else signal.SIGTERM)
            stopped = True
    wall = time.time() - t0
    res = {'label': label, 'job': job, 'exit': rc, 'run_time_s': wall, 'elements': info['elements'],
           'dofs': info['dofs'], 'l_e_mm': info['l_e_mm'], 'args': ' '.join(gen_args),
           'solver': ' '.join(solver_args), 'load_avg_start': load0, 'load_avg_end': os.getloadavg()[0],
           'stopped_at_limit': stopped, 'cpu_busy_before': busy0,
           'cpu_time_s': os.times().children_user + os.times().children_system - cpu0}
    summ = read_summary(outdir, job)
    if 'wall_s' not in summ:  # stopped: count from JOB.sta
        summ.update(read_sta(os.path.join(outdir, job + '.sta')))
        summ['wall_s'] = wall
    res.update({k: v for k, v in summ.items() if k != 'dofs'})
    return collect(res, outdir, job, info, p, plateau, progress)


def reuse_case(label, gen_args, solver_args, outdir, job, info, p, plateau, old):
    """The results of an earlier run in outdir (--reuse: rewrite the reports without running): run time from the
    closing summary, progress and load figures from the earlier report's rows when given."""
    summ = read_summary(outdir, job)
    if 'wall_s' not in summ:
        summ.update(read_sta(os.path.join(outdir, job + '.sta')))
    # the summary is written when ldfcz ended by itself or by a graceful stop (SIGTERM: exit 143) and gives the exit
    # status; older binaries wrote none
    doc = outputs.read_summary(outdir, job)
    res = {'label': label, 'job': job, 'exit': doc['exit_code'] if doc else int(old.get('exit') or 3),
           'run_time_s': float(old.get('run_time_s') or summ.get('wall_s', 0.0)), 'elements': info['elements'],
           'dofs': info['dofs'], 'l_e_mm': info['l_e_mm'], 'args': ' '.join(gen_args),
           'solver': ' '.join(solver_args), 'stopped_at_limit': old.get('stopped_at_limit') == 'True'}
    for k in ('load_avg_start', 'load_avg_end', 'cpu_busy_before', 'cpu_time_s'):
        if old.get(k):
            res[k] = float(old[k])
    res.update({k: v for k, v in summ.items() if k != 'dofs'})
    return collect(res, outdir, job, info, p, plateau, old.get('progress') or [(0.0, 0.0)])


def collect(res, outdir, job, info, p, plateau, progress):
    """Curves, steady force, front and timing figures of a finished (or stopped) run."""
    csv_path = os.path.join(outdir, job + '.csv')
    rc = res['exit']
    wall = res['run_time_s']
    u, f = read_history(csv_path, info) if os.path.exists(csv_path) else ([], [])
    if u and (not progress or u[-1] > progress[-1][1] * (1.0 + 1e-5)):  # (the samples are written to 6 digits)
        progress.append((wall, u[-1]))
    res['progress'] = progress
    fw = [v / info['width_mm'] for v in f]
    res['u_end_mm'] = u[-1] if u else 0.0
    res['u_total_mm'] = p.u_total
    res['completed'] = bool(u) and abs(u[-1] - p.u_total) <= 1e-6 * p.u_total and rc == 0
    res['F_w_tail'], res['spread'] = steady_force(u, fw, plateau)
    frames = vtu_frames(outdir)
    front = frame_front(frames[-1], info['delta_mm']) if frames else None
    res['delaminated_mm'] = (info['x_front_mm'] - front) if front is not None else 0.0
    res['vtus'] = [f[0] for f in frames]      # a frame's (first) file: the serial frame, or piece 0 of a .pvtu
    res['frames'] = frames
    res['info'] = info
    # the steady force with its plateau window and uncertainty (tools/ldfcz_tools/steady_force.py): the front history of the
    # field frames decides where the front is inside the fine region
    hist = front_history(res)
    est = sfe.estimate(u, fw, hist[1:] if len(hist) > 1 else None, info['l_e_mm'],
                                info.get('fine_length_mm'))
    res['steady'] = est
    res['F_w'] = est['value'] if est['value'] == est['value'] else res['F_w_tail']
    res['F_unc'] = est['uncertainty']
    res['F_drift'] = est['drift']
    res['F_ripple'] = est['ripple']
    res['F_status'] = est['status']
    res['F_window_um'] = '%.1f-%.1f' % (1e3 * est['window'][0], 1e3 * est['window'][1])
    res['F_curvature'] = est.get('curvature')
    res['F_sem'] = est.get('sem')
    res['F_ripple_period_um'] = 1e3 * est['period'] if est.get('period') else float('nan')
    res['F_ripple_elements'] = est.get('ripple_elements')
    res['F_cycles'] = len(est.get('cycle_means') or [])
    res['F_quarter_change'] = est['quarter_change'] if est.get('quarter_change') is not None else float('nan')
    res['F_vs_quarters'] = est['value_vs_quarters'] if est.get('value_vs_quarters') is not None else float('nan')
    res['front_speed'] = est.get('front_speed')
    # the fine region left ahead of the front at the end, and the softening part of the cohesive zone (delta to
    # 6 delta) in the frames of the plateau window (at most the last five), in cohesive elements along x
    res['fine_margin_um'] = 1e3 * (info['fine_length_mm'] - res['delaminated_mm'])
    times = [h[0] for h in hist[1:]]
    inwin = [k for k, t in enumerate(times) if est['window'][0] <= t <= est['window'][1] + 1e-9][-5:]
    pz = [process_zone(frames[k], info['delta_mm'], info.get('ny') or 1) for k in inwin if k < len(frames)]
    res['pz_cells'] = sum(p_[0] for p_ in pz) / len(pz) if pz else float('nan')
    res['pz_length_um'] = 1e3 * sum(p_[1] for p_ in pz) / len(pz) if pz else float('nan')
    res['lateral'] = lateral_contraction(frames[-1][0], info) if frames and info['dimension'] == 3 and \
        len(frames[-1]) == 1 and not p.full_width else None
    if res.get('increments') and res.get('wall_s'):
        res['t_inc_s'] = res['wall_s'] / res['attempts'] if res.get('attempts') else res['wall_s'] / res['increments']
    if res.get('iterations') and res.get('wall_s'):
        res['t_iter_s'] = res['wall_s'] / res['iterations']
    if res.get('attempts') and res.get('cpu_time_s'):
        res['t_inc_cpu_s'] = res['cpu_time_s'] / res['attempts']
    res['curve'] = (u, fw)
    # the pull per converged increment actually taken (JOB.sta increment column x rate), in um
    dus = sorted(1e3 * x * p.rate for x in sta_increments(os.path.join(outdir, job + '.sta')))
    if dus:
        res['du_min_um'], res['du_median_um'], res['du_max_um'] = dus[0], dus[len(dus) // 2], dus[-1]
    return res


def sta_increments(sta_path):
    """Time increments of the converged increments in JOB.sta."""
    out = []
    if not os.path.exists(sta_path):
        return out
    for line in open(sta_path):
        w = line.split()
        if len(w) >= 7 and not w[0].startswith('#') and w[6] == 'converged':
            out.append(float(w[5]))
    return out


def group(label):
    """The reading a statement-study case belongs to ('A' or 'B', the label's first word), '' otherwise."""
    w = label.split()
    return w[0] if w and (w[0] in ('A', 'B') or w[0].startswith(('A/', 'B/'))) else ''


def write_report(study, results, outdir):
    os.makedirs(outdir, exist_ok=True)
    for r in results:
        # the reference of the case's group (statement studies: one per reading), else the study's reference
        ref = [q for q in results if q.get('reference') and group(q['label']) == group(r['label'])]
        fref = ref[0]['F_w'] if ref else float('nan')
        r['F_over_Fr'] = r['F_w'] / fref if fref == fref and fref else float('nan')
        r['error'] = abs(r['F_over_Fr'] - 1.0) if r['F_over_Fr'] == r['F_over_Fr'] else float('nan')
        # an error is resolved when it exceeds the two steady-force uncertainties (tools/ldfcz_tools/steady_force.py)
        ur = ref[0].get('F_unc', float('nan')) if ref else float('nan')
        r['resolved'] = (r['error'] > ur + r.get('F_unc', float('nan'))) if not r.get('reference') else ''
    cols = ['label', 'reference', 'completed', 'exit', 'F_w', 'F_unc', 'F_status', 'F_window_um', 'F_drift',
            'F_curvature', 'F_sem', 'F_ripple', 'F_ripple_period_um', 'F_ripple_elements', 'F_cycles',
            'F_quarter_change', 'F_vs_quarters', 'front_speed', 'fine_margin_um', 'pz_cells', 'pz_length_um',
            'F_w_tail', 'F_over_Fr', 'error', 'resolved', 'spread', 'delaminated_mm', 'run_time_s',
            'increments', 'cutbacks', 'iterations', 'elements', 'dofs', 't_inc_s', 't_assembly_s', 't_factor_s',
            't_iter_s', 'attempts', 'energy_rel_diff', 'max_open_ratio', 'du_min_um', 'du_median_um', 'du_max_um',
            'cpu_busy_before', 'cpu_time_s',
            'load_avg_start', 'load_avg_end', 'u_end_mm', 'solver', 'args']
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
    loads = [r[k] for r in results for k in ('load_avg_start', 'load_avg_end') if k in r]
    solvers = sorted(set(r.get('solver', '') for r in results))
    cmd = ' '.join(sys.argv[1:2] + [x for x in sys.argv[2:] if x in ('--quick',)]
                   + (['--ranks', LAUNCH[-1]] if LAUNCH else [])) or study
    if loads:
        head = ('Generated by `tools/peel_study.py %s` on %s (%s, %d cores visible, %s; 1-min load average '
                '%.1f-%.1f at the starts and ends of the runs, which include the runs themselves).' % (
                    cmd, time.strftime('%Y-%m-%d %H:%M'), os.uname().nodename, os.cpu_count() or 1, run_config(),
                    min(loads), max(loads)))
        busy = 'Cores busy before each run (other jobs, 0-1): %s.' % ', '.join(
            '%.2f' % r['cpu_busy_before'] if 'cpu_busy_before' in r else '-' for r in results)
    else:
        head = ('Written by `tools/peel_study.py %s --reuse` on %s from the run files in out/peel/%s/ (the run '
                'times are the runs\' own closing summaries; no load figures were recorded for these runs).' % (
                    cmd, time.strftime('%Y-%m-%d %H:%M'), study))
        busy = 'Machine: %s, %d cores visible.' % (os.uname().nodename, os.cpu_count() or 1)
    st = STAMP[0] or stamp()[0]
    old_md = os.path.join(outdir, study + '.md')
    if '--reuse' in sys.argv or '--only' in sys.argv:
        # the report is rewritten from earlier runs (all, or all but the --only cases): keep their stamp
        prev = [ln.strip() for ln in open(old_md) if ln.startswith('Stamp:')][:1] if os.path.exists(old_md) else []
        if prev:
            st += ' Runs not made by this command: %s' % re.sub(r'^Stamp: (.*?)( Runs not made by this command: .*)?$',
                                                                 r'\1', prev[0])
    lines = ['# Study %s' % study, '', st, '', head, '', busy,
             '', 'ldfcz options: %s.' % '; '.join('`%s`' % (x or '(defaults: --newton full)') for x in solvers), '',
             'F/w: steady peel force per unit width (N/mm) by tools/ldfcz_tools/steady_force.py: the mean of the cycle means '
             '(the force averaged over whole ripple periods, one cohesive element crossed by the front each) over '
             'the plateau window (after the front has crossed 3 elements of the fine region, before it comes within 2 '
             'elements of its end, from where the cycle means drift and curve by less than 0.2 %), +- its relative '
             'uncertainty of the averaging (half the drift and the curvature plus the standard error of the cycle '
             'means); ripple: half the peak-to-peak oscillation about them, a resolution error of the cohesive '
             'discretisation; Q4/Q3: the cycle means of the last quarter of the pull against the quarter before; '
             'status: ok, or why the value is not a plateau (no-plateau, front-not-in-fine-region); error: '
             '|F/F_r - 1| against the reference case (marked *); resolved: the error exceeds the two uncertainties '
             'together. CPU time: the ldfcz process\'s user + system time.', '',
             '| case | F/w (N/mm) | +- | window (um of pull) | status | ripple | Q4/Q3 - 1 | F/F_r | error | resolved '
             '| delaminated (mm) | run time (s) | CPU time (s) | increments | cutbacks | elements | DOFs '
             '| energy balance |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in results:
        lines.append('| %s%s | %.4f | %.2f %% | %s | %s | %.2f %% | %s | %.4f | %.2e | %s | %.3f | %.1f | %s | %s | %s '
                     '| %d | %d | %s |' % (
                         r['label'], ' *' if r.get('reference') else '', r['F_w'],
                         100 * r.get('F_unc', float('nan')), r.get('F_window_um', '-'), r.get('F_status', '-'),
                         100 * r.get('F_ripple', float('nan')),
                         '%+.2f %%' % (100 * r['F_quarter_change']) if r.get('F_quarter_change') == r.get(
                             'F_quarter_change') and r.get('F_quarter_change') is not None else '-',
                         r['F_over_Fr'], r['error'], {True: 'yes', False: 'no'}.get(r['resolved'], '-'),
                         r['delaminated_mm'], r['run_time_s'], '%.1f' % r['cpu_time_s'] if r.get('cpu_time_s')
                         else '-', int(r.get('increments', 0)), int(r.get('cutbacks', 0)), r['elements'], r['dofs'],
                         '%.1e' % r['energy_rel_diff'] if 'energy_rel_diff' in r else '-'))
        if not r['completed']:
            lines[-1] += ' (not completed: %s, U = %.4g of %.4g mm%s)' % (
                stop_text(r), r['u_end_mm'], r['u_total_mm'], ', stopped at the time limit' if r.get('stopped_at_limit')
                else '')
    lines += study_extras(study, results, outdir)
    with open(os.path.join(outdir, study + '.md'), 'w') as fh:
        fh.write('\n'.join(lines) + '\n')
    plot(study, results, outdir)


def main_band(r, reports=os.path.join(ROOT, 'reports')):
    """The discretisation band of the main scene from the main-mesh study's report (no runs): the main mesh's value
    there against every mesh of the study at least as fine in l_e and n_z, in either element formulation. Returns
    a dict: band (the largest relative difference, the band's half-width), parts (relative differences of the
    single refinements: CPE4I on the same mesh, n_z = 9, the finest l_e), finer (label, relative difference) of
    every finer mesh, the main mesh's study value and its label, the report's stamp line; None without the
    report."""
    rows = load_rows(reports, 'main-mesh')
    le, nz = float(MAIN_A_MESH[1]), int(MAIN_A_MESH[3])
    key = 'CPE4 le=%g nz=%d' % (le, nz)
    if key not in rows:
        return None
    f_m = fnum(rows[key], 'F_w')
    mesh = {}
    for lab in rows:
        m = re.match(r'(CPE4I?) le=([0-9.e-]+) nz=(\d+)$', lab)
        if m and rows[lab].get('completed') == 'True':
            mesh[lab] = (m.group(1), float(m.group(2)), int(m.group(3)))
    finer = [(lab, fnum(rows[lab], 'F_w') / f_m - 1.0) for lab, (el, l_, n_) in sorted(mesh.items())
             if l_ <= le * (1 + 1e-9) and n_ >= nz and lab != key]
    cpe4 = {(l_, n_): lab for lab, (el, l_, n_) in mesh.items() if el == 'CPE4'}
    parts = {}
    if 'CPE4I le=%g nz=%d' % (le, nz) in mesh:
        parts['element formulation (CPE4I against CPE4, this mesh)'] = \
            fnum(rows['CPE4I le=%g nz=%d' % (le, nz)], 'F_w') / f_m - 1.0
    nz_big = max([n_ for (l_, n_) in cpe4 if n_ > nz] or [0])
    ls = sorted([l_ for (l_, n_) in cpe4 if n_ == nz_big and (l_, nz) in cpe4], key=lambda v: (v != le, v))
    if nz_big and ls:
        parts['elements through the thickness (n_z %d -> %d at l_e = %g um)' % (nz, nz_big, 1e3 * ls[0])] = \
            fnum(rows[cpe4[(ls[0], nz_big)]], 'F_w') / fnum(rows[cpe4[(ls[0], nz)]], 'F_w') - 1.0
    l_small = min([l_ for (l_, n_) in cpe4 if n_ == nz] or [le])
    if l_small < le:
        parts['element length (l_e %g -> %g um at n_z = %d)' % (1e3 * le, 1e3 * l_small, nz)] = \
            fnum(rows[cpe4[(l_small, nz)]], 'F_w') / f_m - 1.0
    ref = [lab for lab in mesh if rows[lab].get('reference') == 'True']
    md = os.path.join(reports, 'main-mesh', 'main-mesh.md')
    st = next((ln.strip() for ln in open(md) if ln.startswith('Stamp:')), '') if os.path.exists(md) else ''
    ds = [d for _, d in finer]
    return {'band': max([abs(d) for d in ds] or [float('nan')]), 'band_hi': max(ds + [0.0]),
            'band_lo': min(ds + [0.0]), 'parts': parts, 'finer': finer,
            'F_study': f_m, 'label': key, 'stamp': st,
            'finest': (ref[0], fnum(rows[ref[0]], 'F_w') / f_m - 1.0) if ref else ('-', float('nan'))}


def main_lines(r):
    """What the main job prints (and its report holds): the steady force with its averaging uncertainty and its
    discretisation band, what the band is made of, the ripple as resolution error, the plateau check."""
    est = r['steady']
    out = ['steady peel force per unit width: %s' % sfe.describe(est)]
    b = r.get('band')
    if b:
        out.append('F/w = %.4f N/mm +- %.2f %% (averaging), discretisation band %+.2f %% / %+.2f %% (%.4f to %.4f '
                   'N/mm; reports/main-mesh/)' % (est['value'], 100 * est['uncertainty'], 100 * b['band_hi'],
                                                  100 * b['band_lo'], est['value'] * (1 + b['band_lo']),
                                                  est['value'] * (1 + b['band_hi'])))
        out.append('  the band: from the lowest to the highest difference (zero included) between this mesh (%s, %.4f '
                   'N/mm in the study%s) and the %d meshes of the study at least as fine in l_e and n_z, in either '
                   'formulation: %s' % (
                       b['label'], b['F_study'], '' if abs(b['F_study'] / est['value'] - 1) < 1e-9 else
                       ' [this run: %+.2e]' % (est['value'] / b['F_study'] - 1), len(b['finer']),
                       ', '.join('%s %+.2f %%' % (lab, 100 * d) for lab, d in b['finer'])))
        out.append('  made of: %s; the finest CPE4I mesh (%s) %+.2f %%' % (
            ', '.join('%s %+.2f %%' % (k, 100 * v) for k, v in b['parts'].items()), b['finest'][0],
            100 * b['finest'][1]))
    elif r['info'].get('reading') != 'peel':
        out.append('  (no discretisation band: reports/main-mesh/main-mesh.csv not found; run tools/peel_study.py '
                   'main-mesh)')
    if est.get('period'):
        out.append('  ripple +-%.2f %% of the force with a period of %.2f um of pull = %.2f cohesive elements of front '
                   'advance: a resolution error of the cohesive discretisation (l_e = %g um), averaged out over '
                   'whole periods' % (100 * est['ripple'], 1e3 * est['period'] * est['ripple_elements'] if
                                      est['ripple_elements'] == est['ripple_elements'] else float('nan'),
                                      est['ripple_elements'], 1e3 * r['l_e_mm']))
    if est.get('quarter_change') is not None:
        out.append('  plateau check: cycle means of the last quarter of the pull %+.3f %% against the quarter before; '
                   'the value within %.3f %% of both' % (100 * est['quarter_change'], 100 * est['value_vs_quarters']))
    out.append('  delamination %.3f mm (the fine region reaches %.0f um beyond the front at the end; the softening '
               'zone spans %.1f cohesive elements = %.1f um), energy balance %s, run time %.1f s (CPU %.1f s)' % (
                   r['delaminated_mm'], r['fine_margin_um'], r['pz_cells'], r['pz_length_um'],
                   '%.2f %%' % (100 * r['energy_rel_diff']) if 'energy_rel_diff' in r else '-', r['run_time_s'],
                   r.get('cpu_time_s', float('nan'))))
    for fl in est['flags']:
        out.append('  flag: ' + fl)
    return out


def study_extras(study, results, outdir):
    """Study-specific lines under the table of STUDY.md."""
    out = []
    if study == 'main':
        out += [''] + ['    ' + ln for ln in main_lines(results[0])]
        if results[0].get('band') and results[0]['band']['stamp']:
            out += ['', 'The band comes from reports/main-mesh/main-mesh.csv (%s).' % results[0]['band']['stamp']]
    ok = [r for r in results if r['F_w'] == r['F_w']]
    if 'mesh-x' in study or 'mesh-z' in study:
        for g in sorted(set(group(r['label']) for r in ok)):
            out += richardson_lines(study, [r for r in ok if group(r['label']) == g])
    if study == 'dofs':
        out += ['', '| case | DOFs | attempts | Newton iterations | t/attempt (s) | t/iteration (s) | assembly | '
                'factorization |', '|---|---|---|---|---|---|---|---|']
        for r in results:
            if r.get('t_inc_s'):
                w = r.get('wall_s') or r['run_time_s']
                out.append('| %s | %d | %d | %d | %.4f | %.4f | %.0f %% | %.1f %% |' % (
                    r['label'], r['dofs'], r.get('attempts', 0), r.get('iterations', 0), r['t_inc_s'],
                    r.get('t_iter_s', float('nan')), 100 * r.get('t_assembly_s', 0) / w,
                    100 * r.get('t_factor_s', 0) / w))
        fits = []
        for name, sel in (('all', results), ('plane strain', [r for r in results if not r['label'].startswith('3D')]),
                          ('3D', [r for r in results if r['label'].startswith('3D')])):
            n_inc = fit_exponent([(r['dofs'], r['t_inc_s']) for r in sel if r.get('t_inc_s')])
            n_it = fit_exponent([(r['dofs'], r['t_iter_s']) for r in sel if r.get('t_iter_s')])
            n_as = fit_exponent([(r['dofs'], r['t_assembly_s'] / r['iterations']) for r in sel
                                 if r.get('t_assembly_s') and r.get('iterations')])
            n_fa = fit_exponent([(r['dofs'], r['t_factor_s'] / r['iterations']) for r in sel
                                 if r.get('t_factor_s') and r.get('iterations')])
            fits.append('| %s | %.2f | %.2f | %.2f | %.2f |' % (name, n_inc, n_it, n_as, n_fa))
        out += ['', 'Fitted exponents n of t = c DOFs^n (paper Fig. 11d: 1.34 for the time of an increment):', '',
                '| cases | t/attempt | t/iteration | assembly/iteration | factorization/iteration |',
                '|---|---|---|---|---|'] + fits
        out += ['', 'Fitted t_inc ~ DOFs^n (all cases): n = %.3f (paper Fig. 11d: 1.34).' %
                fit_exponent([(r['dofs'], r['t_inc_s']) for r in results if r.get('t_inc_s')])]
        # the CPU time of the process per attempt: on a shared machine the wall time of a run inflates with the
        # other jobs' load, its CPU time much less (with -t 1 the two agree on an idle machine)
        cp = [(r['dofs'], r['t_inc_cpu_s']) for r in results if r.get('t_inc_cpu_s')]
        if len(cp) >= 2:
            out += ['', 'The same fitted on the CPU time per attempt (all cases): n = %.3f; plane strain %.3f, 3D %.3f.'
                    % (fit_exponent(cp), fit_exponent([(r['dofs'], r['t_inc_cpu_s']) for r in results
                                                       if r.get('t_inc_cpu_s') and not r['label'].startswith('3D')]),
                       fit_exponent([(r['dofs'], r['t_inc_cpu_s']) for r in results
                                     if r.get('t_inc_cpu_s') and r['label'].startswith('3D')]))]
    elif study == 'opening-bound':
        out += ['', '| case | largest opening increment / delta | energy balance | Newton iterations |',
                '|---|---|---|---|']
        for r in results:
            out.append('| %s | %s | %s | %d |' % (
                r['label'], '%.3f' % r['max_open_ratio'] if 'max_open_ratio' in r else '-',
                '%.1e' % r['energy_rel_diff'] if 'energy_rel_diff' in r else '-', r.get('iterations', 0)))
        out += ['', 'Paper (section 7): opening increments below delta/3 dissipate more than 99 % of phi; '
                '0.1 um/inc was its stability limit for the PET model.']
    elif study == 'table1':
        out += table1_extras(ok, outdir)
    elif study == 'application':
        for r in results:
            out += application_extras(r, outdir)
    elif study == 'main-mesh':
        out += main_mesh_extras(ok, outdir)
    elif study == 'width-3d':
        out += width_extras(ok, outdir)
    elif study == 'pet-alt':
        out += pet_alt_extras(ok)
    elif study == 'fig13':
        for r in results:
            out += application_extras(r, outdir, 'fig13')
            # what the 3D quarter of the same mesh would be (generator only, no run)
            p3 = peel_deck.parser().parse_args(r['args'].split() + ['--3d', '--ny', '10', '--width', '0.04'])
            i3 = peel_deck.build(p3)[1]
            out += ['', 'The same scene as a 3D quarter (n_y = 10 over b = 0.04 mm, as section 8) would have %d '
                    'elements and %d DOFs (tools/peel_deck.py, not run): about the size of the section 8 '
                    'application (reports/application: 21660 elements, 89595 DOFs, 1.0 mm of delamination after '
                    '3550 s on the idle 2-core machine with `-t 2`).' % (i3['elements'], i3['dofs'])]
    return out


def main_mesh_extras(ok, outdir):
    """The l_e x n_z grid per element formulation (F/w, ripple, CPU time), the band of the main mesh, and every
    mesh's difference from the finest."""
    by = {r['label']: r for r in ok}
    les = sorted({r['l_e_mm'] for r in ok}, reverse=True)
    nzs = sorted({int(re.search(r'nz=(\d+)', r['label']).group(1)) for r in ok})
    out = []
    for el in ('CPE4', 'CPE4I'):
        out += ['', '%s: F/w (N/mm) +- averaging uncertainty, ripple, Q4/Q3 - 1, CPU time; rows l_e, columns n_z:' % el,
                '', '| l_e (um) | ' + ' | '.join('n_z = %d' % n for n in nzs) + ' |',
                '|---|' + '---|' * len(nzs)]
        for le in les:
            if not any(by.get('%s le=%g nz=%d' % (el, le, n)) for n in nzs):
                continue
            cells = []
            for n in nzs:
                r = by.get('%s le=%g nz=%d' % (el, le, n))
                cells.append('%.4f +- %.2f %%, ripple %.2f %%, %s, %.0f s' % (
                    r['F_w'], 100 * r['F_unc'], 100 * r['F_ripple'], '%+.2f %%' % (100 * r['F_quarter_change'])
                    if r.get('F_quarter_change') == r.get('F_quarter_change') else '-', r.get('cpu_time_s', 0))
                             if r else '-')
            out.append('| %g | %s |' % (1e3 * le, ' | '.join(cells)))
    pairs = [(le, n, by['CPE4I le=%g nz=%d' % (le, n)]['F_w'] / by['CPE4 le=%g nz=%d' % (le, n)]['F_w'] - 1)
             for le in les for n in nzs if 'CPE4I le=%g nz=%d' % (le, n) in by and 'CPE4 le=%g nz=%d' % (le, n) in by]
    out += ['', 'CPE4I against CPE4 on the same mesh: %s.' % ', '.join(
        'l_e = %g um, n_z = %d: %+.2f %%' % (1e3 * le, n, 100 * d) for le, n, d in pairs),
        '', 'Softening part of the cohesive zone (openings delta to 6 delta), cohesive elements along x (mean of the '
        'last frames of the window; column pz_cells of the CSV): %s.' % ', '.join(
            '%s: %.1f' % (r['label'], r['pz_cells']) for r in ok if r.get('pz_cells') == r.get('pz_cells'))]
    b = main_band({'label': ''}, os.path.dirname(outdir))
    if b:
        out += ['', 'The main scene\'s mesh (`MAIN_A_MESH` of tools/peel_study.py: %s) against every mesh at least as '
                'fine in l_e and n_z, in either formulation: %s; the band (from the lowest to the highest of them, '
                'zero included): **%+.2f %% / %+.2f %%**. Single refinements: %s. The reference (the finest CPE4I '
                'mesh, %s): %+.2f %%.' % (
                    b['label'], ', '.join('%s %+.2f %%' % (lab, 100 * d) for lab, d in b['finer']),
                    100 * b['band_hi'], 100 * b['band_lo'],
                    ', '.join('%s %+.2f %%' % (k, 100 * v) for k, v in b['parts'].items()), b['finest'][0],
                    100 * b['finest'][1])]
    return out


def width_extras(ok, outdir):
    """The plane-strain/3D gap per reading and the lateral contraction of the detached coating: the mean lateral
    stretch lambda_y of the top face in the peeled part (reference x between the initial front and half the
    delaminated length behind it) at mid-width and at the edge, its axial stretch lambda_x, and what uniaxial
    tension (lambda_y = lambda_x^-1/2, incompressible) and plane strain (lambda_y = 1) would give; a PNG of lambda_y
    along x."""
    out = ['', 'Lateral contraction of the peeled coating (top face, last frame; lambda = current / reference length):',
           '', '| case | F/F_ps - 1 | F_ps/F - 1 | lambda_x | lambda_y mid-width | lambda_y edge | lambda_y across b '
           '| uniaxial lambda_x^-1/2 |', '|---|---|---|---|---|---|---|---|']
    curves = []
    for g in ('A', 'B'):
        ps = next((r for r in ok if r['label'] == '%s plane strain' % g), None)
        for r in ok:
            if group(r['label']) != g or not r.get('lateral'):
                continue
            x0, d = r['info']['x_front_mm'], r['delaminated_mm']
            sel = [c for c in r['lateral'] if x0 - 0.5 * d <= c[0] <= x0]
            if not sel:
                continue
            mean = [sum(c[k] for c in sel) / len(sel) for k in range(1, 5)]
            out.append('| %s | %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f |' % (
                r['label'], '%+.2f %%' % (100 * (r['F_w'] / ps['F_w'] - 1)) if ps else '-',
                '%+.2f %%' % (100 * (ps['F_w'] / r['F_w'] - 1)) if ps else '-', mean[0], mean[1],
                mean[2], mean[3], mean[0] ** -0.5))
            curves.append((r['label'], r['lateral'], x0))
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(8, 4.2))
        for k, (lab, lat, x0) in enumerate(curves):
            col = plt.cm.tab10(k % 10)
            ax.plot([1e3 * (c[0] - x0) for c in lat], [c[2] for c in lat], '-', color=col, label=lab + ', mid-width')
            ax.plot([1e3 * (c[0] - x0) for c in lat], [c[3] for c in lat], ':', color=col, label=lab + ', edge')
        ax.set_xlabel('reference x - initial front (um)')
        ax.set_ylabel('lateral stretch lambda_y of the top face')
        ax.legend(fontsize=6)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, 'width-3d_lateral.png'), dpi=110)
        plt.close(fig)
        out += ['', '![lateral stretch](width-3d_lateral.png)']
    except ImportError:
        pass
    return out


def pet_alt_extras(ok):
    """Plane strain against 3D with the alternative PET set, beside the same with Table 1 as printed (stmt-3d-fine
    for reading A is the 0.16 mm fine region, stmt-3d-long for reading B)."""
    by = {r['label']: r for r in ok}
    out = ['', '| reading | plane strain / 3D - 1, --pet alt | the same, Table 1 as printed (report) |', '|---|---|---|']
    for g, rep in (('A', 'stmt-3d-fine'), ('B', 'stmt-3d-long')):
        ps, d3 = by.get('%s plane strain' % g), by.get('%s 3D b=0.04 ny=2' % g)
        old = load_rows(os.path.join(ROOT, 'reports'), rep)
        o_ps, o_3 = old.get('%s plane strain' % g), old.get('%s 3D b=0.04 ny=2' % g)
        out.append('| %s | %s | %s |' % (
            g, '%+.2f %% (+-%.2f)' % (100 * (ps['F_w'] / d3['F_w'] - 1), 100 * (ps['F_unc'] + d3['F_unc']))
            if ps and d3 else '-',
            '%+.2f %% (+-%.2f) (%s)' % (100 * (fnum(o_ps, 'F_w') / fnum(o_3, 'F_w') - 1),
                                        100 * (fnum(o_ps, 'F_unc') + fnum(o_3, 'F_unc')), rep) if o_ps and o_3 else '-'))
    return out


def table1_extras(ok, outdir):
    """Sensitivities per reading and PET set, and the PET material curves of both sets (material_point)."""
    out = ['', 'F/w (N/mm) +- its uncertainty (status when not a plateau); base: T_max 20 MPa, phi 0.2 N/mm, 1 um/s.',
           '', '| reading / PET | base | T_max 10 / 40 MPa | phi 0.1 / 0.4 N/mm | '
           'F/w per decade of pull rate (1e-4 / 1e-2 mm/s) |', '|---|---|---|---|---|']
    by = {r['label']: r for r in ok}
    for g in sorted(set(group(r['label']) for r in ok)):
        def f(tag):
            r = by.get('%s %s' % (g, tag))
            return r['F_w'] if r else float('nan')

        def m(tag):
            # the value, +- its uncertainty, marked when it is not a plateau
            r = by.get('%s %s' % (g, tag))
            if not r:
                return '-'
            return '%.4f (+-%.1f %%%s)' % (r['F_w'], 100 * r.get('F_unc', float('nan')),
                                          '' if r.get('F_status') == 'ok' else ', ' + str(r.get('F_status')))
        dec = (f('rate=1e-2') / f('rate=1e-4')) ** 0.5 - 1.0
        out.append('| %s | %s | %s / %s | %s / %s | %+.1f %% (%s / %s) |' % (
            g, m('base'), m('T_max=10'), m('T_max=40'), m('phi=0.1'), m('phi=0.4'), 100 * dec, m('rate=1e-4'),
            m('rate=1e-2')))
    out += material_curves(outdir)
    return out


def material_curves(outdir):
    """Uniaxial PET curves of Table 1 and the alternative at 1e-3, 1e-2, 1e-1 /s (bin/material_point next to
    ldfcz): yield (first maximum), softened minimum, stress at true strain 1, yield per decade; PNG."""
    mp = os.path.join(os.path.dirname(LDFCZ[0]), 'material_point')
    if not os.path.exists(mp):
        return ['', '(material_point not built: no PET curves)']
    rows, curves = [], {}
    for name, props in (('table1', peel_deck.PET_TABLE1), ('alt', peel_deck.PET_ALT)):
        for rate in (1e-3, 1e-2, 1e-1):
            csvp = os.path.join(outdir, 'pet_%s_%g.csv' % (name, rate))
            subprocess.run([mp, 'mode=uniaxial', 'rate=%g' % rate, 'strain_end=1.2', 'steps=600',
                            'props=' + ' '.join('%.12g' % v for v in props), 'output=' + csvp], check=True,
                           stdout=subprocess.DEVNULL)
            with open(csvp) as fh:
                rr = list(csv.DictReader(fh))
            e = [float(x['strain']) for x in rr]
            sg = [float(x['stress']) for x in rr]
            k = next((i for i in range(1, len(sg) - 1) if sg[i] >= sg[i - 1] and sg[i] > sg[i + 1]), None)
            y = sg[k] if k is not None else float('nan')
            mn = min(sg[k:]) if k is not None else float('nan')
            s1 = interp(e, sg, 1.0)
            rows.append((name, rate, y, mn, s1))
            curves[(name, rate)] = (e, sg)
            os.remove(csvp)
    out = ['', 'PET in uniaxial tension (bin/material_point, true strain rate; the same commands the study runs):',
           '', '| PET | rate (1/s) | yield (MPa) | softened minimum (MPa) | stress at true strain 1 (MPa) |',
           '|---|---|---|---|---|']
    for name, rate, y, mn, s1 in rows:
        out.append('| %s | %g | %.1f | %.1f | %.1f |' % (name, rate, y, mn, s1))
    for name in ('table1', 'alt'):
        ys = {rt: y for n, rt, y, mn, s1 in rows if n == name}
        ss = {rt: s1 for n, rt, y, mn, s1 in rows if n == name}
        out.append('')
        out.append('%s: yield stress +%.1f %% per decade of strain rate (%.2f MPa), stress at strain 1 +%.1f %% per '
                   'decade (1e-3 -> 1e-1 /s).' % (name, 100 * ((ys[1e-1] / ys[1e-3]) ** 0.5 - 1),
                                                 (ys[1e-1] - ys[1e-3]) / 2, 100 * ((ss[1e-1] / ss[1e-3]) ** 0.5 - 1)))
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for (name, rate), (e, sg) in sorted(curves.items()):
            ax.plot(e, sg, ('-' if name == 'table1' else '--'), label='%s %g/s' % (name, rate))
        ax.set_xlabel('true strain (-)')
        ax.set_ylabel('true stress (MPa)')
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        ax.set_title('PET uniaxial: Table 1 as printed (solid) and the alternative (dashed)')
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, 'table1_pet.png'), dpi=110)
        plt.close(fig)
        out += ['', '![PET curves](table1_pet.png)']
    except ImportError:
        pass
    return out


def load_rows(reports, study):
    """Rows of reports/STUDY/STUDY.csv by label ({} when the study has not been run)."""
    path = os.path.join(reports, study, study + '.csv')
    if not os.path.exists(path):
        return {}
    with open(path) as fh:
        return {r['label']: r for r in csv.DictReader(fh)}


def fnum(r, k):
    try:
        return float(r.get(k, '')) if r else float('nan')
    except ValueError:
        return float('nan')


def statements(reports):
    """The paper's statements (sections 7-9) against readings A and B of Fig. 10, from the stmt-* and table1
    reports (no runs): reports/statements/statements.md."""
    mx, mz, m3, mi = (load_rows(reports, x) for x in ('stmt-mesh-x', 'stmt-mesh-z', 'stmt-3d', 'stmt-increment'))
    # reading B pulled 0.32 mm (on its plateau) replaces B's 0.16 mm rows where that study's reference completed
    longer = {}
    for short, rows, lng, ref in (('x', mx, 'stmt-mesh-x-long', 'B le=0.0025'),
                                  ('3', m3, 'stmt-3d-width-long', 'B 3D b=0.04 ny=4'),
                                  ('i', mi, 'stmt-increment-long', 'B reference: bound 0.05, 0.1 um/inc')):
        ml_ = load_rows(reports, lng)
        if ml_.get(ref, {}).get('completed') == 'True':
            for lab in [lab for lab in rows if lab.startswith('B ')]:
                del rows[lab]
            rows.update(ml_)
            longer[short] = True
    nm = 'not measured'

    def val(rows, label):
        r = rows.get(label)
        if not r or r.get('completed') != 'True':
            return float('nan'), ''
        return fnum(r, 'F_w'), '' if r.get('F_status') == 'ok' else ' (%s)' % r.get('F_status')

    def pct(x, unc=None):
        if x != x:
            return nm
        return '%+.2f %%' % (100 * x) + (' (+-%.2f)' % (100 * unc) if unc is not None and unc == unc else '')
    rows = []
    cells = {}
    for k in ('A', 'B'):
        c = {}
        fps, f1 = val(m3, '%s plane strain' % k)
        f3, f2 = val(m3, '%s 3D b=0.04 ny=4' % k)
        u = fnum(m3.get('%s plane strain' % k), 'F_unc') + fnum(m3.get('%s 3D b=0.04 ny=4' % k), 'F_unc')
        c['ps3d'] = 'l_e = 20 um, n_z = 2, n_y = 4: ' + pct(fps / f3 - 1, u) + f1 + f2
        mf = load_rows(reports, 'stmt-3d-fine')
        if mf:
            gp, g1 = val(mf, '%s plane strain' % k)
            g3, g2 = val(mf, '%s 3D b=0.04 ny=2' % k)
            uf = fnum(mf.get('%s plane strain' % k), 'F_unc') + fnum(mf.get('%s 3D b=0.04 ny=2' % k), 'F_unc')
            c['ps3d'] += '; l_e = 10 um, n_z = 3, n_y = 2: ' + pct(gp / g3 - 1, uf) + g1 + g2
        ml = load_rows(reports, 'stmt-3d-long')
        if '%s plane strain' % k in ml:
            gp, g1 = val(ml, '%s plane strain' % k)
            g3, g2 = val(ml, '%s 3D b=0.04 ny=2' % k)
            uf = fnum(ml.get('%s plane strain' % k), 'F_unc') + fnum(ml.get('%s 3D b=0.04 ny=2' % k), 'F_unc')
            c['ps3d'] += '; the same pulled 0.32 mm: ' + pct(gp / g3 - 1, uf) + g1 + g2
        # CPU time of the single-threaded runs (-t 1): the wall time on a shared machine says little
        tps = fnum(m3.get('%s plane strain' % k), 'cpu_time_s')
        t3 = [fnum(m3.get('%s 3D b=0.04 ny=%d' % (k, n)), 'cpu_time_s') for n in (1, 2, 4)]
        c['speed'] = ', '.join('%.1f' % (t / tps) for t in t3 if t == t) + ' (n_y = 1, 2, 4; CPU time)' \
            if tps == tps else nm
        # reading B: the 0.32 mm pulls (stmt-mesh-z-long, on their plateaus) when they have been run
        mzl = load_rows(reports, 'stmt-mesh-z-long')
        mzk, zlong = (mzl, ' (pulled 0.32 mm)') if k == 'B' and mzl.get('B nz=9', {}).get('completed') == 'True' \
            else (mz, '')
        fz = {n: val(mzk, '%s nz=%d' % (k, n))[0] for n in (1, 2, 3, 5, 9)}
        uz = {n: fnum(mzk.get('%s nz=%d' % (k, n)), 'F_unc') for n in (1, 2, 3, 5, 9)}
        c['nz1'] = pct(fz[1] / fz[9] - 1, uz[1] + uz[9]) + zlong
        ok_n = [n for n in (1, 2, 3, 5) if fz[n] == fz[n] and abs(fz[n] / fz[9] - 1) < 0.005]
        errs = ', '.join('%d: %.2f %% (+-%.2f)' % (n, 100 * abs(fz[n] / fz[9] - 1), 100 * (uz[n] + uz[9]))
                         for n in (1, 2, 3, 5) if fz[n] == fz[n])
        c['nz05'] = ('n_z = %d (errors %s against n_z = 9)' % (ok_n[0], errs) if ok_n else
                     (nm if fz[9] != fz[9] else 'none below 9 (errors %s)' % errs)) + zlong
        les = [0.02, 0.01, 0.005, 0.0025]
        fx = {le: val(mx, '%s le=%g' % (k, le))[0] for le in les}
        ux = {le: fnum(mx.get('%s le=%g' % (k, le)), 'F_unc') for le in les}
        good = [le for le in les if fx[le] == fx[le]]
        f_inf, p, why = (sfe.richardson(good[-3:], [fx[le] for le in good[-3:]]) if len(good) >= 3
                         else (None, None, 'fewer than 3 meshes'))
        ref = f_inf if f_inf is not None else fx[0.0025]
        c['le'] = '; '.join('%g um: %.2f %%' % (1e3 * le, 100 * abs(fx[le] / ref - 1)) for le in good) + \
            (' against Richardson F_inf = %.4f (p = %.2f)' % (f_inf, p) if f_inf is not None else
             ' against l_e = 2.5 um (%s)' % why) + '; uncertainties %s' % ', '.join(
                 '%.2f %%' % (100 * ux[le]) for le in good) if good else nm
        fy = {n: val(m3, '%s 3D b=0.04 ny=%d' % (k, n))[0] for n in (1, 2, 4)}
        uy = {n: fnum(m3.get('%s 3D b=0.04 ny=%d' % (k, n)), 'F_unc') for n in (1, 2, 4)}
        c['ny'] = ', '.join('n_y = %d: %.2f %% (+-%.2f)' % (n, 100 * abs(fy[n] / fy[4] - 1), 100 * (uy[n] + uy[4]))
                            for n in (1, 2) if fy[n] == fy[n]) + ' against n_y = 4' if fy[4] == fy[4] else nm
        fb, _ = val(m3, '%s 3D b=0.02 ny=2' % k)
        ub = fnum(m3.get('%s 3D b=0.02 ny=2' % k), 'F_unc')
        c['widths'] = ('b = 0.02 against 0.04 mm (n_y = 2): %s' % pct(fb / fy[2] - 1, ub + uy[2])) \
            if fb == fb and fy[2] == fy[2] else nm
        # CPU time of the ldfcz process (-t 1) per increment attempt: less sensitive to the other jobs on the
        # machine than the wall time
        pts = [(fnum(r, 'dofs'), fnum(r, 'cpu_time_s') / fnum(r, 'attempts')) for rows_ in (mx, mz, m3)
               for lab, r in rows_.items() if group(lab) == k and fnum(r, 'attempts') > 0
               and fnum(r, 'cpu_time_s') > 0]
        c['dofs'] = ('%.2f (%d runs, %d-%d DOFs)' % (fit_exponent(pts), len(pts), min(p_[0] for p_ in pts),
                                                     max(p_[0] for p_ in pts)) if len(pts) >= 2 else nm)
        inc = [(lab, r) for lab, r in mi.items() if group(lab) == k]
        fr = [fnum(r, 'F_w') for lab, r in inc if 'reference' in lab]
        ufr = [fnum(r, 'F_unc') for lab, r in inc if 'reference' in lab]
        desc = []
        for lab, r in inc:
            if 'reference' in lab:
                continue
            done = r.get('completed') == 'True'
            desc.append('%s um/inc requested: %s' % (lab.split(',')[-1].split('um')[0].strip(), (
                'taken %.3g/%.3g/%.3g um (min/median/max), error %.2f %% (+-%.2f)' % (
                    fnum(r, 'du_min_um'), fnum(r, 'du_median_um'), fnum(r, 'du_max_um'),
                    100 * abs(fnum(r, 'F_w') / fr[0] - 1) if fr else float('nan'),
                    100 * (fnum(r, 'F_unc') + ufr[0]) if ufr else float('nan'))) if done else 'not completed'))
        c['inc'] = '; '.join(desc) if desc else nm
        m9 = load_rows(reports, 'stmt-mesh-x-long-nz9')
        if k == 'B' and m9.get('B le=0.0025 nz=9', {}).get('completed') == 'True':
            l9 = [0.01, 0.005, 0.0025]
            f9 = {le: val(m9, 'B le=%g nz=9' % le)[0] for le in l9}
            u9 = {le: fnum(m9.get('B le=%g nz=9' % le), 'F_unc') for le in l9}
            f9_inf, p9, why9 = sfe.richardson(l9, [f9[le] for le in l9])
            if f9_inf is not None:
                c['le'] += ' (n_z = 3); with n_z = 9: ' + '; '.join(
                    '%g um: %.2f %%' % (1e3 * le, 100 * abs(f9[le] / f9_inf - 1)) for le in l9) + \
                    ' against Richardson F_inf = %.4f N/mm (observed order %.2f); uncertainties %s' % (
                        f9_inf, p9, ', '.join('%.2f %%' % (100 * u9[le]) for le in l9))
            else:
                c['le'] += ' (n_z = 3); with n_z = 9: ' + '; '.join(
                    '%g um: %.2f %% (+-%.2f)' % (1e3 * le, 100 * abs(f9[le] / f9[0.0025] - 1),
                                                 100 * (u9[le] + u9[0.0025])) for le in l9[:-1]) + \
                    ' against l_e = 2.5 um (%s)' % why9
        if k == 'B':
            for key, short in (('le', 'x'), ('ny', '3'), ('widths', '3'), ('inc', 'i'), ('speed', '3')):
                if longer.get(short) and c[key] != nm:
                    c[key] += ' (pulled 0.32 mm)'
            if longer.get('3'):
                c['ps3d'] = c['ps3d'].replace('n_y = 4: ', 'n_y = 4, pulled 0.32 mm: ', 1)
        cells[k] = c
    more_rows = statement_rows_35(reports, cells, nm)
    refs = {'ps3d': ('stmt-3d stmt-3d-fine', 'stmt-3d-width-long stmt-3d-fine stmt-3d-long'),
            'speed': ('stmt-3d', 'stmt-3d-width-long'), 'nz1': ('stmt-mesh-z', 'stmt-mesh-z-long'),
            'nz05': ('stmt-mesh-z main-mesh', 'stmt-mesh-z-long'),
            'le': ('stmt-mesh-x main-mesh', 'stmt-mesh-x-long stmt-mesh-x-long-nz9'),
            'ny': ('stmt-3d', 'stmt-3d-width-long'), 'widths': ('stmt-3d', 'stmt-3d-width-long'),
            'dofs': ('stmt-mesh-x stmt-mesh-z stmt-3d', 'stmt-mesh-x stmt-mesh-z stmt-3d'),
            'inc': ('stmt-increment', 'stmt-increment-long')}
    for k in ('A', 'B'):
        for key, (ra, rb) in refs.items():
            cells[k][key] += ' (%s)' % ', '.join('`%s`' % x for x in (ra if k == 'A' else rb).split())
    table = more_rows[:4] + [
        ('plane strain against 3D (section 9, Fig. 14)', 'plane strain +4 %', 'ps3d'),
        ('speed-up of plane strain (section 9)', '15-50x', 'speed'),
        ('one element through the thickness (Fig. 11b)', '2 % error', 'nz1'),
        ('elements through the thickness for < 0.5 % (Fig. 11b)', '9', 'nz05'),
        ('element length l_e (Fig. 11c)', '0.5 % at 2 um', 'le'),
        ('elements over the width (Fig. 11a)', '0.5 % with 4', 'ny'),
        ('two model widths (Fig. 11a)', 'almost identical', 'widths'),
        ('CPU time per increment attempt against DOFs (Fig. 11d)', 'exponent 1.34', 'dofs'),
        ('load step (section 7)', 'error < 1 % for all steps; stable up to 100 nm/inc (PET model)', 'inc'),
    ] + more_rows[4:]
    out = ['# The paper\'s statements against the two readings of Fig. 10', '', STAMP[0] or stamp()[0], '',
           'The reports behind each cell are named in it (reports/NAME/NAME.md). '
           'Written by `tools/peel_study.py statements` on %s from reports/stmt-mesh-x(-long), stmt-mesh-z(-long), '
           'stmt-3d, stmt-3d-width-long, stmt-3d-fine, stmt-3d-long and stmt-increment(-long) (reading B from the '
           '0.32 mm pulls of the -long studies where they have been run; each made by `tools/peel_study.py STUDY --threads 1`; their .md files hold every case, '
           'run times and the machine load). Reading A: the 0-degree bridge (the coating drawn along x); reading B: '
           'the pre-delaminated flap lifted and pulled at 90 degrees (carriage grip, u_x free). Plane strain, rigid substrate, '
           'l_e = 10 um, n_z = 3 unless the statement varies them; 3D: the quarter model at l_e = 20 um, n_z = 2. '
           'Percentages with +-: the steady-force uncertainties of the two runs added (tools/ldfcz_tools/steady_force.py). '
           '"%s": the runs were not made (or did not complete) in this pass.' % (time.strftime('%Y-%m-%d %H:%M'), nm),
           '', '| statement | paper | reading A (bridge) | reading B (90-degree peel) |', '|---|---|---|---|']
    for name, paper, key in table:
        out.append('| %s | %s | %s | %s |' % (name, paper, cells['A'][key], cells['B'][key]))
    os.makedirs(os.path.join(reports, 'statements'), exist_ok=True)
    with open(os.path.join(reports, 'statements', 'statements.md'), 'w') as fh:
        fh.write('\n'.join(out) + '\n')
    print('\n'.join(out))
    return 0


def statement_rows_35(reports, cells, nm):
    """The statements of sections 7-9 that issue 35 added to the table, for both readings (cells[k][key], from the
    reports named in each cell; nm where a report is missing). Returns the rows (name, paper, key): the first four
    go before the mesh statements."""
    def rows(study):
        return load_rows(reports, study)

    def pct(r1, r2, unc=True):
        if not r1 or not r2 or r1.get('completed') != 'True' or r2.get('completed') != 'True':
            return nm
        d = fnum(r1, 'F_w') / fnum(r2, 'F_w') - 1
        return '%+.2f %%' % (100 * d) + (' (+-%.2f)' % (100 * (fnum(r1, 'F_unc') + fnum(r2, 'F_unc'))) if unc else '')
    a, b = cells['A'], cells['B']
    mmr = rows('main-mesh')

    def series(fmt, keys, scale=1.0):
        got = [(k_, mmr.get(fmt % k_)) for k_ in keys]
        return ', '.join('%g: %.4f' % (scale * float(k_), fnum(r_, 'F_w')) for k_, r_ in got if r_)
    if mmr:
        a['nz05'] += ('; at l_e = 2.5 um (`main-mesh`, 0.2 mm fine region, CPE4) n_z = %s N/mm' %
                      series('CPE4 le=0.0025 nz=%s', ('3', '5', '9', '13')))
        a['le'] += ('; at n_z = 9 (`main-mesh`, CPE4) l_e (um) = %s N/mm, not monotone' %
                    series('CPE4 le=%s nz=9', ('0.01', '0.005', '0.0025', '0.00125'), 1e3))
    a['loading'] = 'u_x prescribed on the coating\'s end face (u_y, u_z free): as the text says'
    b['loading'] = 'u_z prescribed on the lifted flap\'s end face, u_x free (carriage grip): not a u_x'
    a['quarter'] = ('a quarter: the mid-width plane (YSYMM) and the mid-length plane, where the coating bridges the '
                    'broken substrate (the uniform u_x of the end face)')
    b['quarter'] = ('half the width: one symmetry plane (a single arm peeled at 90 degrees has no mid-length '
                    'symmetry), so not a quarter')
    # stretch of the detached coating from the front's advance v per unit pull: A the drawn length grows by the
    # pull, (d + u) / d - 1 = 1/v; B (carriage) the pull lifts the peeled length and stretches it, u / d - 1
    mm = rows('main').get('peel_main') or next(iter(rows('main').values()), None)
    sb = rows('steel-b').get('B rigid substrate')
    v_a = fnum(mm, 'front_speed')
    v_b = fnum(sb, 'front_speed')
    a['stretch'] = ('%.0f %% (1/v, the front advancing v = %.2f um per um of pull over the plateau; `main`)' % (
        100 / v_a, v_a) if v_a == v_a and v_a > 0 else nm)
    b['stretch'] = ('%.0f %% (1/v - 1, v = %.2f um per um of pull; `steel-b`)' % (100 * (1 / v_b - 1), v_b)
                    if v_b == v_b and v_b > 0 else nm)
    sim = rows('simplifications')
    a['steel'] = ('rigid against elastic steel: %s (`simplifications`, l_e = 10 um)' % pct(
        sim.get('rigid, coarse far field (default)'), sim.get('steel, coarse far field')) if sim else nm)
    b['steel'] = ('steel against rigid: %s (`steel-b`, pulled 0.32 mm)' % pct(
        rows('steel-b').get('B steel substrate'), sb) if sb else nm)
    un = rows('unloading')
    for k, c in (('A', a), ('B', b)):
        ref = un.get('%s unloading=2' % k)
        vals = ['%d: %s' % (n, pct(un.get('%s unloading=%d' % (k, n)), ref)) for n in (1, 3)
                if un.get('%s unloading=%d' % (k, n))]
        c['unloading'] = ('%s against 2 (`unloading`%s)' % ('; '.join(vals), ', the main mesh' if k == 'A' else
                                                             ', pulled 0.32 mm') if vals and ref else nm)
    app = rows('application')
    ra = next(iter(app.values()), None)
    a['app'] = ('3D quarter, n_y = 10, n_z = 3, l_e = 2 um, 1 um/inc at most: F/w = %.3f N/mm (`application`)'
                % fnum(ra, 'F_w') if ra else nm)
    b['app'] = 'not run'
    f13 = rows('fig13')
    r13 = next(iter(f13.values()), None)
    a['fig13'] = ('plane strain, the main mesh: %.3f mm delaminated at %.0f um of pull, F/w = %.4f N/mm '
                  '(`fig13`, Mises picture there); 3D quarter, section 8 mesh: %.3f mm (`application`)' % (
                      fnum(r13, 'delaminated_mm'), 1e3 * fnum(r13, 'u_end_mm'), fnum(r13, 'F_w'),
                      fnum(ra, 'delaminated_mm')) if r13 and ra else nm)
    b['fig13'] = 'not run'
    wd = rows('width-3d')
    for k, c in (('A', a), ('B', b)):
        ps = wd.get('%s plane strain' % k)
        b4 = 'b=0.04 ny=4' if k == 'A' else 'b=0.04 ny=2'
        free, held = wd.get('%s 3D %s' % (k, b4)), wd.get('%s 3D %s edge held in y' % (k, b4))
        widths = ', '.join('b = %s mm: %s' % (lab.split('b=')[1].split()[0], pct(ps, r, False))
                           for lab, r in sorted(wd.items(), key=lambda t: float(t[0].split('b=')[1].split()[0])
                                                if 'b=' in t[0] else 0.0)
                           if group(lab) == k and '3D' in lab and 'edge' not in lab)
        c['ycontr'] = ('plane strain against the 3D quarter: %s; the 3D quarter with its free edge held in y '
                       'against plane strain: %s (`width-3d`, l_e = 10 um, n_z = 3; the lateral stretch of the '
                       'peeled coating there)' % (
                           widths, pct(held, ps)) if ps and free and held else nm)
    pa = rows('pet-alt')
    for k, c in (('A', a), ('B', b)):
        c['petalt'] = ('plane strain against 3D: %s (`pet-alt`, n_y = 2)' % pct(
            pa.get('%s plane strain' % k), pa.get('%s 3D b=0.04 ny=2' % k)) if pa else nm)
    return [
        ('loading (section 7): "a displacement u_x on one end of the polymer coating"', 'u_x', 'loading'),
        ('model extent (section 7): "only encompasses a quarter of the specimen"', 'a quarter', 'quarter'),
        ('stretch of the detached coating (section 7): "the coating stretches at least 50 %"', '>= 50 %',
         'stretch'),
        ('substrate (section 7): elastic steel, 210 GPa, 0.3', 'elastic steel', 'steel'),
        ('plane strain against 3D with the alternative Table 1 (`--pet alt`)', '-', 'petalt'),
        ('the cause of the plane-strain excess (section 9): "prevents deformations in y-direction"',
         'the y-contraction', 'ycontr'),
        ('the three unloading behaviours (section 8, Fig. 6)', 'no noticeable influence', 'unloading'),
        ('the application (section 8)', '3D, n_y = 10, n_z = 3, l_e = 2 um', 'app'),
        ('deformed geometry after 1.0 mm of delamination (Fig. 13)', 'agrees qualitatively with Fig. 12', 'fig13'),
    ]


def mesh_size(r, study):
    """The mesh parameter h of a case for Richardson: l_e (mm) for mesh-x, 1/n_z for mesh-z."""
    if 'mesh-z' in study:
        m = re.search(r'nz=(\d+)', r['label'])
        return 1.0 / int(m.group(1)) if m else None
    return r['l_e_mm']


def richardson_lines(study, ok):
    """Richardson estimate and observed order from every three consecutive meshes whose values are plateaus."""
    rows = sorted([(mesh_size(r, study), r) for r in ok if mesh_size(r, study)], key=lambda t: -t[0])
    out = ['', 'Richardson extrapolation (tools/ldfcz_tools/steady_force.py) from three consecutive meshes (h = %s):' % (
        '1/n_z' if 'mesh-z' in study else 'l_e'), '',
        '| meshes | F/w (N/mm) | all plateaus | observed order p | F_inf (N/mm) | finest against F_inf |',
        '|---|---|---|---|---|---|']
    for k in range(len(rows) - 2):
        tri = rows[k:k + 3]
        hs = [t[0] for t in tri]
        fs = [t[1]['F_w'] for t in tri]
        plate = all(t[1].get('F_status') == 'ok' for t in tri)
        f_inf, p, why = sfe.richardson(hs, fs)
        # differences below the uncertainties are not resolved: no order from them
        unc = max(t[1].get('F_unc', 0.0) for t in tri) * fs[-1]
        if f_inf is not None and min(abs(fs[0] - fs[1]), abs(fs[1] - fs[2])) < unc:
            why = 'differences (%.2g, %.2g N/mm) below the uncertainty %.2g N/mm' % (
                fs[0] - fs[1], fs[1] - fs[2], unc)
            f_inf = None
        out.append('| %s | %s | %s | %s | %s | %s |' % (
            ', '.join(t[1]['label'] for t in tri), ', '.join('%.4f' % f for f in fs), 'yes' if plate else 'no',
            '%.2f' % p if f_inf is not None else '- (%s)' % why, '%.4f' % f_inf if f_inf is not None else '-',
            '%.2f %%' % (100 * abs(fs[-1] / f_inf - 1)) if f_inf is not None else '-'))
    return out


def stop_text(r):
    """How an incomplete run ended: ldfcz's exit status, or the signal that ended it (negative status)."""
    if r['exit'] == 128 + signal.SIGTERM:
        return 'stopped by SIGTERM after the increment under way (exit 143, closing summary written)'
    return 'ended by signal %d' % -r['exit'] if r['exit'] < 0 else 'exit %d' % r['exit']


def interp(xs, ys, x):
    """Linear interpolation of y(x) in increasing xs (clamped at the ends)."""
    if not xs:
        return float('nan')
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 1.0
            return ys[k - 1] + w * (ys[k] - ys[k - 1])
    return ys[-1]


def front_history(r):
    """(pull U1 mm, delaminated length mm) of every VTU frame (U1 = rate x frame time)."""
    info, hist = r['info'], [(0.0, 0.0)]
    pvd = [x for x in r['vtus'][:1]]
    if not pvd:
        return hist
    pvd_path = re.sub(r'_\d{4,}(_\d+)?\.vtu$', '.pvd', pvd[0])
    times = [float(t) for t in re.findall(r'timestep="\s*([0-9.Ee+-]+)"', open(pvd_path).read())] \
        if os.path.exists(pvd_path) else []
    for t, v in zip(times, r.get('frames') or [[x] for x in r['vtus']]):
        fr = frame_front(v, info['delta_mm'])
        hist.append((t * info['rate_mm_s'], info['x_front_mm'] - fr if fr is not None else 0.0))
    return hist


def application_extras(r, outdir, name='application'):
    """Cost per um of pull over the second half of the run, delamination against pull, the wall time to the
    paper's 1.0 mm of delamination (measured, or estimated when not reached), and the rendered Mises PNG of the
    last frame."""
    out = ['', '## %s' % r['label'], '']
    out.append('Run: `%s` generator arguments `%s`; ldfcz `%s`; %d elements, %d DOFs; pulled %.1f of %.1f um in '
               '%.0f s (%s).' % (r['job'], r['args'], r['solver'], r['elements'], r['dofs'], 1e3 * r['u_end_mm'],
                                 1e3 * r['u_total_mm'], r['run_time_s'],
                                 'completed' if r['completed'] else 'stopped at the time limit'
                                 if r.get('stopped_at_limit') else 'not completed, ' + stop_text(r)))
    prog = r['progress']
    u_end = prog[-1][1]
    half = [pt for pt in prog if pt[1] >= 0.5 * u_end]
    cost = (half[-1][0] - half[0][0]) / (1e3 * (half[-1][1] - half[0][1])) \
        if len(half) > 1 and half[-1][1] > half[0][1] else float('nan')
    hist = front_history(r)
    with open(os.path.join(outdir, name + '_front.csv'), 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(['U1_mm', 'delaminated_mm'])
        for a, b in hist:
            wr.writerow(['%.6g' % a, '%.6g' % b])
    with open(os.path.join(outdir, name + '_progress.csv'), 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(['wall_s', 'U1_mm'])
        for a, b in prog:
            wr.writerow(['%.2f' % a, '%.6g' % b])
    d_end = hist[-1][1]
    late = [h for h in hist if h[0] >= 0.5 * hist[-1][0]]
    rate = (late[-1][1] - late[0][1]) / (late[-1][0] - late[0][0]) if len(late) > 1 and late[-1][0] > late[0][0] \
        else float('nan')
    out.append('')
    out.append('Delamination %.1f um at %.1f um of pull; over the second half of the run the front advanced %.2f um '
               'per um of pull. Wall time per um of pull over the second half of the pull: **%.1f s/um** '
               '(%s_progress.csv: wall time against pull).' % (1e3 * d_end, 1e3 * hist[-1][0], rate, cost, name))
    # the paper's 1.0 mm of delamination: when the run reached it, the wall time at which it did (pull at 1.0 mm
    # interpolated in the front history, wall time at that pull in the progress record); otherwise the time to
    # reach it at the measured cost per um of pull and front advance per um of pull (same model, same DOFs)
    target = 1.0
    reached = [k for k in range(1, len(hist)) if hist[k][1] >= target > hist[k - 1][1]]
    if reached:
        k = reached[0]
        (u0, d0), (u1, d1) = hist[k - 1], hist[k]
        u_t = u0 + (target - d0) / (d1 - d0) * (u1 - u0) if d1 > d0 else u1
        t_t = interp([b for _, b in prog], [a for a, _ in prog], u_t)
        r['time_to_1mm_s'] = t_t
        out += ['', '**1.0 mm of delamination reached** at %.1f um of pull, after **%.0f s = %.2f h** of wall time on '
                'this machine with %s (front history of the VTU frames, %s_front.csv, interpolated; '
                'wall time against pull, %s_progress.csv).' % (1e3 * u_t, t_t, t_t / 3600, run_config(), name,
                                                              name)]
        if not r['completed']:
            out[-1] += (' The run was ended (%s) at %.1f um of pull, %.1f um after that point: the rest of the '
                        'planned pull was not needed.' % (stop_text(r), 1e3 * u_end, 1e3 * (u_end - u_t)))
    else:
        adv = rate if rate == rate and rate > 0.2 else 1.0
        u_full = hist[-1][0] + max(target - d_end, 0.0) / adv
        # from the wall time at the last frame's pull (where the front is known) at the measured cost per um
        t_full = interp([b for _, b in prog], [a for a, _ in prog], hist[-1][0]) + cost * 1e3 * (u_full - hist[-1][0])
        r['time_to_1mm_s'] = float('nan')
        out += ['', 'Not reached in this run: 1.0 mm of delamination would need %.3f mm of pull (last frame: %.1f um '
                'delaminated at %.1f um of pull, then the measured %.2f mm of front per mm of pull); at the measured '
                'cost per um that is **%.0f s = %.2f h** in all on this machine with %s (an estimate).' % (
                    u_full, 1e3 * d_end, 1e3 * hist[-1][0], adv, t_full, t_full / 3600, run_config())]
    if r['vtus'] and len((r.get('frames') or [[None]])[-1]) > 1:
        out += ['', 'No Mises picture: the frames of a distributed run are pieces (open JOB.pvd in ParaView).']
    elif r['vtus']:
        png = os.path.join(outdir, name + '_mises.png')
        if render_mises(r['vtus'][-1], r['info'], png, hist[-1]):
            out += ['', '![deformed coating, von Mises stress](%s_mises.png)' % name, '',
                    name + '_mises.png: the last ParaView frame (`%s`), deformed (scale 1), coating coloured by '
                    'the von Mises stress (cell values), side views of the free edge y = b and of the symmetry '
                    'plane y = 0, and the top view.' % os.path.relpath(r['vtus'][-1], ROOT)]
    return out


def render_mises(vtu_path, info, png, last):
    """Side views (free edge y = b, mid-plane y = 0) and top view of the deformed coating, coloured by Mises."""
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        from matplotlib.collections import PolyCollection
    except ImportError:
        return False
    with open(vtu_path) as fh:
        text = fh.read()

    def array(name, typ=float):
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return [typ(float(v)) for v in m.group(1).split()] if m else None
    pm = re.search(r'<Points><DataArray[^>]*>(.*?)</DataArray>', text, re.S)
    x0 = [float(v) for v in pm.group(1).split()]
    uu = array('U')
    xd = [a + b for a, b in zip(x0, uu)]
    conn, offs, coh, mises = array('connectivity', int), array('offsets', int), array('cohesive', int), \
        array('Mises')
    cells, start = [], 0
    for i, o in enumerate(offs):
        if coh[i] == 0:
            cells.append((conn[start:o], mises[i]))
        start = o
    three_d = info['dimension'] == 3
    b = info['width_mm']
    xmin = info['x_front_mm'] - 1.5 * max(last[1], 0.01)

    def face(ids, axis, val):
        """The 4 nodes of hexahedron ids whose reference coordinate `axis` is val (None when not on that plane)."""
        f = [j for j in ids if abs(x0[3 * j + axis] - val) < 1e-9]
        return f if len(f) == 4 else None

    def poly(f, ax_h, ax_v):
        pts = [(xd[3 * j + ax_h], xd[3 * j + ax_v]) for j in f]
        cx = sum(p[0] for p in pts) / 4
        cy = sum(p[1] for p in pts) / 4
        return sorted(pts, key=lambda p: math.atan2(p[1] - cy, p[0] - cx))
    views = []
    ztop = max(x0[2::3])
    if three_d:
        for title, axis, val, ah, av in (('side view, free edge y = b', 1, b, 0, 2),
                                         ('side view, symmetry plane y = 0', 1, 0.0, 0, 2),
                                         ('top view, coating surface z = h_c', 2, None, 0, 1)):
            polys, vals = [], []
            for ids, m in cells:
                v = val
                if v is None:
                    v = max(x0[3 * j + 2] for j in ids)
                    if abs(v - ztop) > 1e-9:
                        continue
                f = face(ids, axis, v)
                if f is None:
                    continue
                pp = poly(f, ah, av)
                if max(p[0] for p in pp) < xmin:
                    continue
                polys.append(pp)
                vals.append(m)
            views.append((title, polys, vals, ah, av))
    else:
        polys, vals = [], []
        for ids, m in cells:
            pts = [(xd[3 * j], xd[3 * j + 1]) for j in ids]
            if max(p[0] for p in pts) >= xmin:
                polys.append(pts)
                vals.append(m)
        views.append(('plane strain, the whole coating', polys, vals, 0, 1))
        # the drawing front at true scale: from 60 um ahead of the current front to 150 um behind it
        xf = info['x_front_mm'] - last[1]
        zp, zv = [], []
        for pp, m in zip(polys, vals):
            if any(xf - 0.06 <= p[0] <= xf + 0.15 for p in pp):
                zp.append(pp)
                zv.append(m)
        views.append(('plane strain, the delamination front (current front at x = %.0f um)' % (1e3 * xf), zp, zv,
                      0, 1))
    allv = [v for vw in views for v in vw[2]]
    if not allv:
        return False
    spans = []
    for vw in views:
        hs = [p[0] for pp in vw[1] for p in pp] or [0.0, 1.0]
        vs = [p[1] for pp in vw[1] for p in pp] or [0.0, 1.0]
        spans.append((max(hs) - min(hs), max(vs) - min(vs)))
    lx = max(sp[0] for sp in spans)
    heights = [min(4.0, max(1.0, 8.0 * sp[1] / max(sp[0], 1e-12))) + 0.9 for sp in spans]
    fig, axs = plt.subplots(len(views), 1, figsize=(10, sum(heights) + 0.5), squeeze=False,
                            gridspec_kw={'height_ratios': heights})
    for (title, polys, vals, ah, av), ax in zip(views, axs[:, 0]):
        pc = PolyCollection([[(1e3 * p[0], 1e3 * p[1]) for p in pp] for pp in polys], array=vals, cmap='jet',
                            edgecolors='none')
        pc.set_clim(0, max(allv))
        ax.add_collection(pc)
        ax.autoscale_view()
        ax.set_aspect('equal')
        ax.set_title(title, fontsize=9)
        ax.set_xlabel('x (um)')
        ax.set_ylabel(('y' if av == 1 and three_d else 'z') + ' (um)')
        hs = [1e3 * p[0] for pp in polys for p in pp]
        if hs and 1e3 * info['x_front_mm'] > max(hs):
            ax.set_xlim(min(hs) - 2.0, max(hs) + 2.0)       # the zoomed front: the initial front is off the view
        else:
            ax.axvline(1e3 * info['x_front_mm'], color='k', lw=0.6, ls='--')
        fig.colorbar(pc, ax=ax, label='von Mises (MPa)', fraction=0.03, pad=0.01)
    fig.suptitle('ldfcz %s: pull %.1f um, delaminated %.1f um (dashed: initial front)' % (
        'application (section 8 mesh)' if three_d else 'plane strain, l_e = %g um, n_z = %d' % (
            1e3 * info['l_e_mm'], info['nz_coating']), 1e3 * last[0], 1e3 * last[1]), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return True


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
        cm = (r.get('steady') or {}).get('cycle_means') or []
        if study == 'main' and cm:
            ax[0].plot([1e3 * c[0] for c in cm], [c[1] for c in cm], 'k.', ms=3, label='cycle means (plateau window)')
            b = r.get('band')
            if b:
                v = r['steady']['value']
                ax[0].axhspan(v * (1 + b['band_lo']), v * (1 + b['band_hi']), color='0.85', zorder=0,
                              label='discretisation band (main-mesh)')
    ax[0].set_xlabel('pulled displacement u_x (um)')
    ax[0].set_ylabel('peel force per unit width F/w (N/mm)')
    ax[0].legend(fontsize=7)
    ax[0].grid(alpha=0.3)
    if pts:
        pts.sort()
        ax[1].loglog([p[0] for p in pts], [p[1] for p in pts], 'o:')
        for t, e, lab in pts:
            ax[1].annotate(lab, (t, e), fontsize=7)
        ax[1].set_xlabel('run time (s)')
        ax[1].set_ylabel('|F/F_r - 1|')
        ax[1].grid(alpha=0.3, which='both')
    fig.suptitle('ldfcz peel study: ' + study)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, study + '.png'), dpi=110)
    plt.close(fig)


def old_rows(outdir, study):
    """Rows of an existing STUDY.csv by label (and the application's progress samples)."""
    rows = {}
    path = os.path.join(outdir, study + '.csv')
    if os.path.exists(path):
        with open(path) as fh:
            for r in csv.DictReader(fh):
                rows[r['label']] = r
    prog = os.path.join(outdir, study + '_progress.csv')
    if study in ('application', 'fig13') and os.path.exists(prog) and len(rows) == 1:
        with open(prog) as fh:
            pts = [(float(r['wall_s']), float(r['U1_mm'])) for r in csv.DictReader(fh)]
        for r in rows.values():
            r['progress'] = pts
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('study')
    ap.add_argument('--ldfcz', default='', help='path of the ldfcz program (default build/bin/ldfcz or PATH)')
    ap.add_argument('--reports', default=os.path.join(ROOT, 'reports'), help='report root (default reports/)')
    ap.add_argument('--work', default='', help='run directory: decks, JOB.csv/log/sta, ParaView frames '
                    '(default out/peel/<study>, ignored by git)')
    ap.add_argument('--threads', type=int, default=2)
    ap.add_argument('--ranks', type=int, default=0,
                    help='run each case on this many MPI processes (mpirun -np N; --ldfcz must be the LDFCZ_MPI '
                    'build, e.g. build-mpi/bin/ldfcz; --threads then counts per process)')
    ap.add_argument('--plateau', type=float, default=0.3, help='fraction of the pull averaged for the steady force')
    ap.add_argument('--quick', action='store_true', help='fewer, cheaper cases')
    ap.add_argument('--scene', choices=('A', 'B'), default='A',
                    help='main: reading A (default: the paper\'s text, u_x on one end of the coating, the 0-degree '
                    'bridge) or B (the flap lifted and pulled at 90 degrees, u_x free)')
    ap.add_argument('--only', default='', help='run only cases whose label contains this text (the report keeps '
                    'the other cases from their last run files, as --reuse)')
    ap.add_argument('--ldfcz-args', default='', help='extra ldfcz options for every case, e.g. "--newton auto"')
    ap.add_argument('--wait-idle', type=float, default=0.0,
                    help='before each case wait up to this many seconds for the cores to be idle (< 15 %% busy)')
    ap.add_argument('--reuse', action='store_true', help='do not run: rewrite the report from the run files of the '
                    'last run (out/peel/STUDY) and the run times of the existing report')
    ap.add_argument('--gen-args', default='', help='extra generator options for every case (they override the '
                    'case\'s), e.g. "--u-total 0.08 --fine-length 0.09"')
    ap.add_argument('--time-limit', type=float, default=0.0,
                    help='stop a case (SIGTERM) after this many seconds and keep what converged (0: no limit)')
    a = ap.parse_args(argv)
    THREADS[0] = a.threads
    if a.ranks > 0:
        LAUNCH[:] = ['mpirun', '-np', str(a.ranks)]
        os.environ.setdefault('OMPI_ALLOW_RUN_AS_ROOT', '1')
        os.environ.setdefault('OMPI_ALLOW_RUN_AS_ROOT_CONFIRM', '1')
    extra = a.ldfcz_args.split()
    all_studies = studies(a.quick)
    if a.study == 'list':
        for k, v in all_studies.items():
            if k.startswith('_'):
                continue
            print(k + ': ' + '; '.join('%s%s [%s]' % (c[0], ' *' if c[2] else '', ' '.join(c[1])) for c in v))
        return 0
    ldfcz = find_ldfcz(a.ldfcz)
    LDFCZ[0] = ldfcz
    STAMP[0] = stamp()[0]
    if a.study == 'statements':
        return statements(a.reports)
    if a.study == 'main' and not a.reuse:
        outdir = os.path.join(a.reports, 'main')
        work = a.work or os.path.join(ROOT, 'out', 'peel', 'main')
        job, gen = ('peel_ps_flap90', MAIN_B) if a.scene == 'B' else ('peel_main', MAIN_A)
        r = run_case(job, gen, work, ldfcz, a.threads, a.plateau, extra, a.time_limit, a.wait_idle)
        r['reference'] = True
        if a.scene == 'A':
            r['band'] = main_band(r)
        write_report('main', [r], outdir)
        for line in main_lines(r):
            print(line)
        print('force-displacement: %s; plot: %s; ParaView frames: %s' % (
            os.path.join(outdir, 'main_curves.csv'), os.path.join(outdir, 'main.png'),
            os.path.join(work, r['job'], r['job'] + '.pvd')))
        return 0 if r['completed'] else 3
    if a.study not in all_studies or a.study.startswith('_'):
        raise SystemExit('peel_study: unknown study %s (peel_study.py list)' % a.study)
    outdir = os.path.join(a.reports, a.study)
    work = a.work or os.path.join(ROOT, 'out', 'peel', a.study)
    results = []
    before = old_rows(outdir, a.study)
    for case in all_studies[a.study]:
        label, args, is_ref = case[:3]
        reuse = a.reuse
        if a.only and a.only not in label:
            # the other cases stay in the report from their last run (as --reuse), when their run files exist
            job = re.sub(r'[^A-Za-z0-9_.-]+', '_', label).strip('_') or 'case'
            if label not in before or not os.path.isdir(os.path.join(work, job)):
                continue
            reuse = True
        r = run_case(label, args + a.gen_args.split(), work, ldfcz, a.threads, a.plateau,
                     list(case[3] if len(case) > 3 else []) + extra, a.time_limit, a.wait_idle,
                     before.get(label, {}) if reuse else None)
        r['reference'] = is_ref
        results.append(r)
        print('%-36s F/w = %.4f N/mm  spread %.1e  %.1f s  %s' % (label, r['F_w'], r['spread'], r['run_time_s'],
                                                                  'ok' if r['completed'] else 'NOT COMPLETED'))
        sys.stdout.flush()
    write_report(a.study, results, outdir)
    print('report: ' + os.path.join(outdir, a.study + '.md'))
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('peel_study'))
