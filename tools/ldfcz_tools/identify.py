#!/usr/bin/python3
"""Identify the interface parameters (phi, T_max; optionally PET constants) from a measured peel curve.

  identify.py synth -o curve.csv --phi 0.25 --tmax 15 --noise 0.005 [scene options]
      a synthetic "measured" curve: the plane-strain peel scene (tools/peel_deck.py) run at known parameters,
      sampled at --points pulls and perturbed by Gaussian noise (the true values are written into the header)
  identify.py fit curve.csv --force-unit N/mm --fit phi,tmax --start phi=0.2,tmax=20 [scene options]
      least-squares fit (scipy.optimize.least_squares, trust-region Levenberg-Marquardt type) of the plane-strain
      scene to the curve: best-fit values, 95 % confidence intervals from the Jacobian of the residual and the
      noise, correlations, identifiability from the sensitivities, which part of the curve informs which
      parameter, a plot (measured, fitted, residual) and a report (docs/identify.md explains every step)

The measured curve: CSV with two columns, the pull u_x (mm, or um with --pull-unit um) and the force; the force
unit must be stated: --force-unit N/mm (force per unit width) or --force-unit N with --width (the specimen width,
mm). Every evaluation is an `ldfcz` run of a generated deck (one thread each, --jobs in parallel), cached by the
deck's text in --cache. Units everywhere: mm, N, s, MPa.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

from ldfcz_tools import peel_deck  # noqa: E402
from ldfcz_tools.paths import ROOT  # noqa: E402

#: Python modules the command needs (ldfcz_tools.cli checks them before main: no traceback without NumPy)
REQUIRES = ('numpy', 'scipy')

# Parameters that can be fitted: name -> (unit, how it enters the generator). All are positive and fitted in ln p.
INTERFACE = {'phi': 'N/mm', 'tmax': 'MPa'}
PET_FITTABLE = {'E': 'MPa', 'S_a': '-', 'eta_0r': 'MPa s', 'tau_0': 'MPa', 'mu': '-', 'G_r': 'MPa'}
LN2 = math.log(2.0)
# A coating cannot carry a true stress above this (MPa): PET at the rates of a peel test draws at 40-70 MPa
# (docs/umat.md, Eq. 37 with Table 1); 200 MPa leaves a factor of about 3 for strain hardening and other grades.
MAX_COATING_STRESS = 200.0


class InputError(Exception):
    """Bad input: printed as 'identify: ...', exit status 2."""


class FitError(Exception):
    """The fit cannot proceed (e.g. the scene fails at the start values): exit status 3."""


# ----------------------------------------------------------------------------------------------------------------
# measured curve
# ----------------------------------------------------------------------------------------------------------------

def read_curve(path, pull_unit, force_unit, width, coating):
    """(pull mm, force per width N/mm, header comments) of a measured curve, checked. Raises InputError."""
    if not os.path.exists(path):
        raise InputError('%s: no such file' % path)
    if force_unit not in ('N', 'N/mm'):
        raise InputError('--force-unit must be N (force; needs --width) or N/mm (force per unit width)')
    if force_unit == 'N' and not (width and width > 0):
        raise InputError('--force-unit N needs --width, the specimen width in mm (the force is divided by it)')
    if force_unit == 'N/mm' and width:
        raise InputError('--width is given with --force-unit N/mm: the force is already per unit width '
                         '(give --force-unit N for a force in N)')
    u, f, comments = [], [], []
    with open(path, newline='') as fh:
        for lineno, line in enumerate(fh, 1):
            s = line.strip()
            if not s:
                continue
            if s.startswith('#'):
                comments.append(s)
                continue
            cells = [c.strip() for c in s.split(',')]
            if len(cells) < 2:
                raise InputError('%s:%d: two columns expected (pull, force), found %r' % (path, lineno, s))
            try:
                a, b = float(cells[0]), float(cells[1])
            except ValueError:
                if not u and lineno == len(comments) + 1:
                    continue          # a header line
                raise InputError('%s:%d: not a number: %r' % (path, lineno, s))
            for name, v in (('pull', a), ('force', b)):
                if not math.isfinite(v):
                    raise InputError('%s:%d: the %s is %s: remove or repair the point' % (path, lineno, name, v))
            if a < 0.0:
                raise InputError('%s:%d: negative pull %g' % (path, lineno, a))
            if u and a <= u[-1][0]:
                raise InputError('%s:%d: the pull does not increase (%g after %g at line %d): the fit needs a '
                                 'monotonic loading curve, sorted by pull' % (path, lineno, a, u[-1][0], u[-1][1]))
            u.append((a, lineno))
            f.append(b)
    scale_u = 1e-3 if pull_unit == 'um' else 1.0
    pull = [a * scale_u for a, _ in u]
    fw = [b / width for b in f] if force_unit == 'N' else list(f)
    if fw:
        peak = max(abs(v) for v in fw)
        stress = peak / coating
        if stress > MAX_COATING_STRESS:
            hint = ('is the force in N for the whole specimen? give --force-unit N --width W'
                    if force_unit == 'N/mm' else 'check --width (mm) and that the force is in N')
            raise InputError('%s: the force per unit width reaches %.4g N/mm, a mean stress of %.0f MPa in the '
                             '%.4g mm coating (a PET coating carries at most about %.0f MPa): %s'
                             % (path, peak, stress, coating, MAX_COATING_STRESS, hint))
    return pull, fw, comments


def noise_from_data(y):
    """Noise standard deviation of a sampled curve from its second differences, robust to a few sharp features:
    for independent noise of std s, y[i-1] - 2 y[i] + y[i+1] has std s sqrt(6); the median absolute deviation
    times 1.4826 estimates that std when the underlying curve is smooth at the sampling."""
    import numpy as np
    y = np.asarray(y)
    if len(y) < 5:
        return float('nan')
    d2 = y[:-2] - 2.0 * y[1:-1] + y[2:]
    mad = np.median(np.abs(d2 - np.median(d2)))
    return float(1.4826 * mad / math.sqrt(6.0))


def curve_parts(u, y, plateau):
    """Index masks of the parts of the curve: the initial rise up to the first force peak followed by a drop of at
    least 5 % (the yield peak of the flap; only when the curve starts below half that peak, i.e. at the rise), the
    peak and neck, and the plateau (the last `plateau` fraction of the pull). Without such a peak: the part before
    the plateau and the plateau."""
    import numpy as np
    u, y = np.asarray(u), np.asarray(y)
    n = len(y)
    u_pl = u[0] + (1.0 - plateau) * (u[-1] - u[0])
    ipk = None
    run_max, imax = -np.inf, 0
    for i in range(n):
        if y[i] > run_max:
            run_max, imax = y[i], i
        elif y[i] < 0.95 * run_max and u[imax] < u_pl:
            ipk = imax
            break
    if ipk is not None and y[0] > 0.5 * y[ipk]:
        ipk = None    # the window does not start at the rise from zero: a drop in it is ripple, not the yield peak
    parts = []
    if ipk is not None and ipk > 0:
        u_pk = u[ipk]
        parts.append(('initial rise', (u < 0.8 * u_pk) if u[0] < 0.8 * u_pk else np.zeros(n, bool)))
        parts.append(('peak and neck', (u >= 0.8 * u_pk) & (u < u_pl)))
    else:
        parts.append(('before the plateau', u < u_pl))
    parts.append(('plateau', u >= u_pl))
    return [(name, m) for name, m in parts if m.any()]


# ----------------------------------------------------------------------------------------------------------------
# the scene and its runs
# ----------------------------------------------------------------------------------------------------------------

def add_scene_options(ap):
    g = ap.add_argument_group('scene (tools/peel_deck.py, docs/scenes.md)')
    g.add_argument('--reading', choices=('bridge', 'peel'), default='bridge',
                   help='the reading of the paper\'s Fig. 10 (docs/scenes.md): bridge (A, default: the coating pulled '
                   'along the interface at 0 degrees) or peel (B: the pre-delaminated flap lifted and pulled at '
                   '--angle)')
    g.add_argument('--angle', type=float, default=None,
                   help='peel angle of --reading peel (degrees, (0, 180], default 90); the bridge pulls at 0')
    g.add_argument('--grip', choices=('fixed', 'carriage'), default='fixed',
                   help='--reading peel: fixed (the flap end moves along the peel direction) or carriage (90 degrees: '
                   'vertical pull, u_x free)')
    g.add_argument('--coating', type=float, default=0.030, help='coating thickness h_c (mm), default 0.030')
    g.add_argument('--steel', action='store_true', help='model the steel substrate (default: rigid, 0.01 %% effect)')
    g.add_argument('--substrate', type=float, default=0.210, help='steel thickness (mm) with --steel')
    g.add_argument('--bonded', type=float, default=0.30, help='bonded length L_b (mm), default 0.30')
    g.add_argument('--flap', type=float, default=None,
                   help='pre-delaminated flap a_0 (mm), default 0.020 (bridge) or 0.1 (peel: the bend and an arm)')
    g.add_argument('--fine-length', type=float, default=0.0,
                   help='fine mesh region ahead of the front (mm); default max(0.1, 2 x the largest pull), '
                        'at most --bonded')
    g.add_argument('--le', type=float, default=0.010, help='element length in the fine region (mm), default 0.010')
    g.add_argument('--nz', type=int, default=3, help='elements over the coating thickness, default 3')
    g.add_argument('--du', type=float, default=0.0003, help='pull per increment (mm), default 0.0003')
    g.add_argument('--rate', type=float, default=0.001, help='pull rate (mm/s), default 0.001')
    g.add_argument('--dgamma-max', type=float, default=0.0, help='PET accuracy bound PROPS(11); 0: UMAT default')
    g.add_argument('--pet', action='append', default=[], metavar='NAME=VALUE',
                   help='a Table 1 constant of the PET held at another value (repeatable)')
    g = ap.add_argument_group('runs')
    g.add_argument('--ldfcz', default='', help='the ldfcz program (default build/bin/ldfcz, build-debug/bin/ldfcz '
                   'or PATH)')
    g.add_argument('--jobs', type=int, default=os.cpu_count() or 2, help='parallel ldfcz runs (one thread each)')
    g.add_argument('--cache', default=os.path.join(ROOT, 'out', 'identify', 'cache'),
                   help='run cache directory (default out/identify/cache, ignored by git)')
    g.add_argument('--run-timeout', type=float, default=900.0, help='a run taking longer is stopped and failed (s)')


def check_scene(a):
    if a.reading == 'bridge':
        if a.angle not in (None, 0.0):
            raise InputError('--angle %g belongs to --reading peel (reading B, the flap lifted and pulled at an '
                             'angle); the bridge (reading A) pulls at 0 degrees (docs/scenes.md)' % a.angle)
        if a.grip != 'fixed':
            raise InputError('--grip belongs to --reading peel')
        a.angle = 0.0
    else:
        a.angle = 90.0 if a.angle is None else a.angle
        if not 0.0 < a.angle <= 180.0:
            raise InputError('--angle %g: the peel angle must be in (0, 180] degrees' % a.angle)
        if a.grip == 'carriage' and a.angle != 90.0:
            raise InputError('--grip carriage needs --angle 90')
    if a.flap is None:
        a.flap = 0.1 if a.reading == 'peel' else 0.020
    for name in ('coating', 'bonded', 'le', 'du', 'rate'):
        if getattr(a, name) <= 0.0:
            raise InputError('--%s must be positive' % name.replace('_', '-'))
    if a.nz < 1:
        raise InputError('--nz must be >= 1')


def find_ldfcz(path):
    if path:
        if not os.path.exists(path):
            raise InputError('--ldfcz %s: no such program' % path)
        return os.path.abspath(path)
    for cand in (os.path.join(ROOT, 'build', 'bin', 'ldfcz'), os.path.join(ROOT, 'build-debug', 'bin', 'ldfcz'),
                 shutil.which('ldfcz')):
        if cand and os.path.exists(cand):
            return cand
    raise InputError('bin/ldfcz not found: build first (tools/setup.sh) or pass --ldfcz')


class Scene:
    """The plane-strain (or 3D) peel scene at given parameters, run by ldfcz with a cache; counts the runs."""

    def __init__(self, a, u_max, three_d=False, extra_gen=()):
        self.a = a
        self.u_max = u_max
        self.three_d = three_d
        self.extra_gen = list(extra_gen)
        self.ldfcz = find_ldfcz(a.ldfcz)
        st = os.stat(self.ldfcz)
        self.ldfcz_id = '%s %d %d' % (os.path.realpath(self.ldfcz), st.st_size, int(st.st_mtime))
        self.cache = a.cache
        os.makedirs(self.cache, exist_ok=True)
        self.runs = 0            # ldfcz runs made
        self.hits = 0            # evaluations answered by the cache
        self.failed = []         # (params, reason) of failed runs
        self.run_seconds = 0.0   # wall time of the runs, summed
        fine = a.fine_length if a.fine_length > 0 else max(0.1, 2.0 * u_max)
        self.fine_length = min(fine, a.bonded)

    def gen_args(self, params):
        a = self.a
        g = ['--coating', repr(a.coating), '--bonded', repr(a.bonded), '--flap', repr(a.flap),
             '--fine-length', repr(self.fine_length), '--le', repr(a.le), '--nz', str(a.nz), '--du',
             repr(min(a.du, self.u_max)), '--rate', repr(a.rate), '--u-total', repr(self.u_max),
             '--field-frequency', '1000000']
        g += ['--substrate', repr(a.substrate)] if a.steel else ['--rigid-substrate']
        if a.reading == 'peel':
            g += ['--reading', 'peel', '--peel-angle', repr(a.angle), '--grip', a.grip]
        if a.dgamma_max > 0:
            g += ['--dgamma-max', repr(a.dgamma_max)]
        pet = dict(item.partition('=')[::2] for item in a.pet)
        for k, v in params.items():
            if k == 'phi':
                g += ['--phi', repr(v)]
            elif k == 'tmax':
                g += ['--tmax', repr(v)]
            else:
                pet[k] = repr(v)
        for k in sorted(pet):
            g += ['--pet', '%s=%s' % (k, pet[k])]
        if self.three_d:
            g += ['--3d']
        return g + self.extra_gen

    def deck(self, params):
        p = peel_deck.parser().parse_args(self.gen_args(params))
        peel_deck.check(p)
        return peel_deck.build(p)

    def evaluate_many(self, plist):
        """Curves (u, F/w) of several parameter sets, in parallel; None for a failed run (recorded)."""
        jobs = max(1, self.a.jobs)
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
            return list(ex.map(self.evaluate, plist))

    def evaluate(self, params):
        text, info = self.deck(params)
        cmd_opts = ['-q', '-t', '1']
        key = hashlib.sha1((text + '\n' + ' '.join(cmd_opts) + '\n' + self.ldfcz_id).encode()).hexdigest()[:20]
        d = os.path.join(self.cache, key)
        res_path = os.path.join(d, 'result.json')
        if os.path.exists(res_path):
            with open(res_path) as fh:
                r = json.load(fh)
            self.hits += 1
        else:
            r = self.run(text, d, cmd_opts, info)
            with open(res_path + '.tmp', 'w') as fh:
                json.dump(r, fh)
            os.replace(res_path + '.tmp', res_path)
        if not r['ok']:
            if (dict(params), r['reason']) not in self.failed:
                self.failed.append((dict(params), r['reason']))
            return None
        return r['u'], r['fw']

    def run(self, text, d, cmd_opts, info):
        if os.path.isdir(d):
            shutil.rmtree(d)
        os.makedirs(d)
        deck = os.path.join(d, 'peel.inp')
        with open(deck, 'w') as fh:
            fh.write(text)
        t0 = time.time()
        try:
            proc = subprocess.run([self.ldfcz] + cmd_opts + ['-o', d, deck], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.PIPE, timeout=self.a.run_timeout)
            rc, err = proc.returncode, proc.stderr.decode(errors='replace').strip()
        except subprocess.TimeoutExpired:
            rc, err = -1, 'stopped after %g s (--run-timeout)' % self.a.run_timeout
        wall = time.time() - t0
        self.runs += 1
        self.run_seconds += wall
        u, fw = [], []
        csv_path = os.path.join(d, 'peel.csv')
        if os.path.exists(csv_path):
            u, fw = read_pull_force(csv_path, info)
        reached = bool(u) and u[-1] >= self.u_max * (1.0 - 1e-6)
        ok = rc == 0 and reached
        reason = ''
        if not ok:
            why = {3: 'no convergence', 2: 'deck or option error', -1: 'timeout'}.get(rc, 'exit status %d' % rc)
            if rc < -1:
                try:
                    why = 'killed by signal %s' % signal.Signals(-rc).name
                except ValueError:
                    why = 'killed by signal %d' % -rc
            reason = '%s; run ended at u = %.4g mm of %.4g mm%s' % (
                why, u[-1] if u else 0.0, self.u_max, (': ' + err.splitlines()[-1]) if err else '')
        # keep the deck and the curve, drop the rest of the run files
        for x in os.listdir(d):
            if x not in ('peel.inp', 'peel.csv', 'peel.log'):
                p = os.path.join(d, x)
                if os.path.isfile(p):
                    os.remove(p)
        return {'ok': ok, 'reason': reason, 'u': u, 'fw': fw, 'wall_s': wall, 'rc': rc, 'dofs': info['dofs']}


def read_pull_force(csv_path, info):
    """(pull, F/w) of a run's JOB.csv: the displacement and reaction of LOAD along the pull direction d of the deck
    (reading A: x; reading B: (cos theta, sin theta) in the x, z plane, or z with the carriage grip)."""
    dx, dz = info.get('pull_dir', (1.0, 0.0))
    z = info.get('z_dof', 2)
    u, fw = [], []
    with open(csv_path) as fh:
        for row in csv.DictReader(fh):
            if info.get('reading') == 'peel':
                u.append(dx * float(row['LOAD.U1']) + dz * float(row['LOAD.U%d' % z]))
                fw.append((dx * float(row['LOAD.RF1']) + dz * float(row['LOAD.RF%d' % z])) / info['width_mm'])
            else:
                u.append(float(row['LOAD.U1']))
                fw.append(float(row['LOAD.RF1']) / info['width_mm'])
    return u, fw


# ----------------------------------------------------------------------------------------------------------------
# synth
# ----------------------------------------------------------------------------------------------------------------

def cmd_synth(a):
    import numpy as np
    check_scene(a)
    if a.points < 2:
        raise InputError('--points must be >= 2')
    u_min = a.u_min if a.u_min is not None else a.u_max / a.points
    if not 0 <= u_min < a.u_max:
        raise InputError('--u-min must lie in [0, --u-max)')
    params = {'phi': a.phi, 'tmax': a.tmax}
    scene = Scene(a, a.u_max, three_d=a.three_d,
                  extra_gen=(['--width', repr(a.model_width), '--ny', str(a.ny)] if a.three_d else []))
    curve = scene.evaluate(params)
    if curve is None:
        raise FitError('the scene failed at phi = %g, T_max = %g: %s' % (a.phi, a.tmax, scene.failed[-1][1]))
    u = np.linspace(u_min, a.u_max, a.points)
    f = np.interp(u, curve[0], curve[1])
    rng = np.random.default_rng(a.seed)
    sigma = a.noise * (np.max(np.abs(f)) if a.relative else 1.0)
    y = f + sigma * rng.standard_normal(len(u))
    scale = a.width if a.force_unit == 'N' else 1.0
    with open(a.output, 'w', newline='') as fh:
        fh.write('# synthetic peel curve (tools/identify.py synth): %s scene, phi = %g N/mm, T_max = %g MPa, '
                 'noise std %.4g N/mm (seed %d), coating %g mm, rate %g mm/s\n' % (
                     '3D' if a.three_d else 'plane-strain', a.phi, a.tmax, sigma, a.seed, a.coating, a.rate))
        fh.write('# generator: %s\n' % ' '.join(scene.gen_args(params)))
        fh.write('pull_mm,force_%s\n' % ('N' if a.force_unit == 'N' else 'N_per_mm'))
        for x, v in zip(u, y):
            fh.write('%.8g,%.8g\n' % (x, v * scale))
    print('synth: %d points to %s (phi = %g, T_max = %g, noise %.4g N/mm), %d run(s), %.1f s' % (
        len(u), a.output, a.phi, a.tmax, sigma, scene.runs, scene.run_seconds))
    return 0


# ----------------------------------------------------------------------------------------------------------------
# fit
# ----------------------------------------------------------------------------------------------------------------

def parse_start(text, names):
    start = {'phi': 0.2, 'tmax': 20.0}
    start.update({n: peel_deck.PET_TABLE1[peel_deck.PET_NAMES.index(n)] for n in PET_FITTABLE})
    for item in [x for x in text.split(',') if x.strip()]:
        k, _, v = item.partition('=')
        k = k.strip()
        if k not in start:
            raise InputError('--start %s: unknown parameter %r' % (item, k))
        try:
            start[k] = float(v)
        except ValueError:
            raise InputError('--start %s: %r is not a number' % (item, v))
        if not start[k] > 0:
            raise InputError('--start %s: the parameters are positive' % item)
    return {n: start[n] for n in names}


def unit_of(n):
    return INTERFACE.get(n) or PET_FITTABLE.get(n)


class Model:
    """Residuals r(x) = F_model(u_i; p) - F_measured(u_i), x = ln p of the free parameters."""

    def __init__(self, scene, u, y, names, fixed, h):
        import numpy as np
        self.scene, self.u, self.y = scene, np.asarray(u), np.asarray(y)
        self.names, self.fixed, self.h = list(names), dict(fixed), h
        self.penalty = 1e3 * (1.0 + float(np.max(np.abs(self.y))))
        self.evals = []     # (params, cost or None)

    def params(self, x):
        p = dict(self.fixed)
        p.update({n: float(math.exp(v)) for n, v in zip(self.names, x)})
        return p

    def curve_at(self, curve):
        import numpy as np
        return np.interp(self.u, curve[0], curve[1])

    def residual(self, x):
        import numpy as np
        c = self.scene.evaluate(self.params(x))
        if c is None:
            self.evals.append((self.params(x), None))
            return np.full(len(self.u), self.penalty)     # a failed run: the step is rejected
        r = self.curve_at(c) - self.y
        self.evals.append((self.params(x), float(r @ r)))
        return r

    def jacobian(self, x, names=None):
        """d r / d ln p by forward differences (step h in ln p; backward where the forward run fails), all runs of
        a Jacobian in parallel. names: columns for these parameters (default the free ones)."""
        import numpy as np
        names = names or self.names
        base_p = self.params(x)
        plist = [base_p]
        for n in names:
            q = dict(base_p)
            q[n] = base_p[n] * math.exp(self.h)
            plist.append(q)
        res = self.scene.evaluate_many(plist)
        if res[0] is None:
            raise FitError('the scene failed at %s' % fmt_params(base_p))
        f0 = self.curve_at(res[0])
        cols, redo = {}, []
        for n, c in zip(names, res[1:]):
            if c is None:
                redo.append(n)
            else:
                cols[n] = (self.curve_at(c) - f0) / self.h
        if redo:
            back = []
            for n in redo:
                q = dict(base_p)
                q[n] = base_p[n] * math.exp(-self.h)
                back.append(q)
            for n, c in zip(redo, self.scene.evaluate_many(back)):
                cols[n] = (f0 - self.curve_at(c)) / self.h if c is not None else np.zeros(len(self.u))
        return np.column_stack([cols[n] for n in names])


def fmt_params(p):
    return ', '.join('%s = %.5g %s' % (k, v, unit_of(k)) for k, v in p.items())


def factor_sensitivity(scene, model, params, names, parts, sigma):
    """Per parameter and direction (up: the parameter doubled, down: halved): the RMS change of the force over the
    curve and over each part, divided by the noise sigma, from runs at 2 p and p/2 (all in parallel). A direction
    whose run fails is None. A finite factor, not the derivative: the response of a discretised peel front ripples
    with the parameters (one element after the other fails), and only a change that moves the curve by more than
    the noise can be told from it."""
    import numpy as np
    f0 = model.curve_at(scene.evaluate(params))
    plist = []
    for n in names:
        for fac in (2.0, 0.5):
            q = dict(params)
            q[n] = params[n] * fac
            plist.append(q)
    res = scene.evaluate_many(plist)
    out = {}
    for k, n in enumerate(names):
        row = {}
        for d, c in zip(('up', 'down'), res[2 * k:2 * k + 2]):
            if c is None:
                row[d] = None
                continue
            diff = model.curve_at(c) - f0
            row['diff_' + d] = diff
            v = {'all': float(np.sqrt(np.mean(diff ** 2)) / sigma)}
            for pname, m in parts:
                v[pname] = float(np.sqrt(np.mean(diff[m] ** 2)) / sigma)
            row[d] = v
        out[n] = row
    return out


def sens_level(row, part='all'):
    """(smaller, larger) of the two directions' ratios; a failed direction is left out; (None, None) if both."""
    v = [row[d][part] for d in ('up', 'down') if row[d] is not None]
    return (min(v), max(v)) if v else (None, None)


def verdict(row):
    """'identifiable' (a halving and a doubling both move the curve by more than the noise), 'lower bound' /
    'upper bound' (only a halving / only a doubling does: the data bound the parameter on one side), 'none'."""
    up = row['up']['all'] if row['up'] is not None else None
    down = row['down']['all'] if row['down'] is not None else None
    if up is None and down is None:
        return 'unknown'
    if up is None or down is None:      # one direction failed: the other decides
        return 'identifiable' if (up if up is not None else down) >= 1.0 else 'none'
    if up >= 1.0 and down >= 1.0:
        return 'identifiable'
    if down >= 1.0:
        return 'lower bound'
    if up >= 1.0:
        return 'upper bound'
    return 'none'


def cmd_fit(a):
    import numpy as np
    from scipy import optimize, stats
    t_start = time.time()
    check_scene(a)
    names = [n.strip() for n in a.fit.split(',') if n.strip()]
    if not names:
        raise InputError('--fit: no parameter named')
    for n in names:
        if n not in INTERFACE and n not in PET_FITTABLE:
            raise InputError('--fit %s: not a fittable parameter (phi, tmax, or a PET constant: %s)'
                             % (n, ', '.join(PET_FITTABLE)))
    if len(set(names)) != len(names):
        raise InputError('--fit: a parameter is named twice')
    for item in a.pet:
        if item.partition('=')[0] in names:
            raise InputError('--pet %s: that constant is fitted (--fit); give its start value with --start' % item)
    start = parse_start(a.start, names + [n for n in ('phi', 'tmax') if n not in names])
    fixed = {n: v for n, v in start.items() if n not in names}
    u, y, comments = read_curve(a.curve, a.pull_unit, a.force_unit, a.width, a.coating)
    n_min = max(10, 5 * len(names))
    if len(u) < n_min:
        raise InputError('%s: %d points; fitting %d parameter(s) needs at least %d' % (a.curve, len(u), len(names),
                                                                                       n_min))
    if a.ps3d_ratio is not None and not a.ps3d_ratio > 0:
        raise InputError('--ps3d-ratio must be positive (plane-strain force / 3D force of the same geometry)')
    u_max = u[-1]
    if u_max > a.bonded:
        raise InputError('%s: the measured pull reaches %.4g mm, more than the scene\'s bonded length %.4g mm: the '
                         'front advances at least 1 mm per mm of pull (the detached coating stretches less than '
                         '100 %%), so the scene would be debonded before the end; give --bonded (and mind the run '
                         'time)' % (a.curve, u_max, a.bonded))
    u_arr, y_meas = np.asarray(u), np.asarray(y)
    ratio = a.ps3d_ratio or 1.0
    y_ps = y_meas * ratio               # the plane-strain equivalent of the measured (3D) force
    scene = Scene(a, u_max)
    model = Model(scene, u_arr, y_ps, names, fixed, a.fd_step)
    x0 = np.array([math.log(start[n]) for n in names])
    parts = curve_parts(u_arr, y_ps, a.plateau)
    sigma_data = noise_from_data(y_ps)
    log = []

    def say(msg):
        log.append(msg)
        if not a.quiet:
            print(msg)
            sys.stdout.flush()

    say('identify: %d points, pull %.4g-%.4g mm, force per width up to %.4g N/mm%s; fitting %s from %s' % (
        len(u), u[0], u_max, float(np.max(y_meas)), (' (x %.4g: plane-strain equivalent)' % ratio) if a.ps3d_ratio
        else '', ', '.join(names), fmt_params(start)))
    # ---- the start point: units plausible, the scene reaches the measured pull, sensitivities
    c_start = scene.evaluate(start)
    if c_start is None:
        raise FitError('the scene cannot reach the measured pull %.4g mm at the start values (%s): %s; start '
                       'elsewhere or change the scene (--du, --bonded, the mesh)' % (u_max, fmt_params(start),
                                                                                   scene.failed[-1][1]))
    f_start = model.curve_at(c_start)
    ratio_units = float(np.sqrt(np.mean(y_ps ** 2)) / max(np.sqrt(np.mean(f_start ** 2)), 1e-300))
    if not 0.2 <= ratio_units <= 5.0:
        raise InputError('%s: the measured force is %.3g times the scene\'s at the start values (RMS over the '
                         'curve): check --force-unit and --width (a force in N for a whole specimen given as N/mm, '
                         'or the reverse), --coating, or start closer' % (a.curve, ratio_units))
    sigma0 = a.noise if a.noise else sigma_data
    if not sigma0 > 0:
        sigma0 = 1e-3 * float(np.max(np.abs(y_ps)))
    sens0 = factor_sensitivity(scene, model, start, names, parts, sigma0)
    # a parameter that the curve bounds on one side only is held too: the fit would drift along its flat side
    free = [n for n in names if verdict(sens0[n]) in ('identifiable', 'unknown')]
    held = [n for n in names if n not in free]
    for n in held:
        say('  %s at the start: %s (doubled / halved: %s x the noise): held at %.5g %s' % (
            n, VERDICT_TEXT[verdict(sens0[n])], fmt_sens(sens0[n], 'all'), start[n], unit_of(n)))
    # ---- the fit of the identifiable parameters; a held parameter that is identifiable at the result is added and
    # the fit repeated from there (once)
    result = None
    span = math.log(a.bound_factor)
    x_from = dict(start)
    for attempt in range(2):
        if free:
            fixed2 = dict(fixed)
            fixed2.update({n: x_from[n] for n in held})
            model = Model(scene, u_arr, y_ps, free, fixed2, a.fd_step)
            xf0 = np.array([math.log(x_from[n]) for n in free])
            lb = np.array([math.log(start[n]) - span for n in free])
            ub = np.array([math.log(start[n]) + span for n in free])
            result = optimize.least_squares(model.residual, np.clip(xf0, lb, ub), jac=model.jacobian,
                                            method='trf', bounds=(lb, ub), x_scale=1.0, xtol=a.xtol, ftol=1e-8,
                                            gtol=1e-10, max_nfev=a.max_evals)
            x_best = result.x
            say('  least_squares (%s): %s after %d residual and %d Jacobian evaluations (%s)' % (
                ', '.join(free), 'converged' if result.success else 'NOT converged', result.nfev, result.njev,
                result.message))
        else:
            x_best = np.array([])
            model = Model(scene, u_arr, y_ps, [], dict(start), a.fd_step)
        best = model.params(x_best)
        # ---- statistics at the optimum: residual, noise, sensitivities of every parameter (fitted and held)
        c_best = scene.evaluate(best)
        if c_best is None:
            raise FitError('the scene failed at the fitted values %s' % fmt_params(best))
        f_best = model.curve_at(c_best)
        r = f_best - y_ps
        dof = max(len(u) - len(free), 1)
        s_res = float(math.sqrt(r @ r / dof))
        sigma = a.noise if a.noise else s_res
        sens = factor_sensitivity(scene, model, best, names, parts, sigma)
        verdicts = {n: verdict(sens[n]) for n in names}
        newly = [n for n in held if verdicts[n] == 'identifiable']
        if not newly or attempt == 1:
            break
        for n in newly:
            say('  %s: identifiable at the result (doubled / halved: %s x the noise): fitted too, from there' % (
                n, fmt_sens(sens[n], 'all')))
        free += newly
        held = [n for n in held if n not in newly]
        x_from = dict(best)
    ident = [n for n in free if verdicts[n] in ('identifiable', 'unknown')]
    out = {'parameters': {}, 'correlation': {}, 'parts': [p for p, _ in parts]}
    tq = float(stats.t.ppf(0.975, dof)) if ident else float('nan')
    cov = None
    if ident:
        # covariance of ln p of the identifiable parameters from the Jacobian of the residual at the optimum
        mod_i = Model(scene, u_arr, y_ps, ident, {k: v for k, v in best.items() if k not in ident}, a.fd_step)
        Ji = mod_i.jacobian(np.array([math.log(best[n]) for n in ident]))
        JTJ = Ji.T @ Ji
        try:
            cov = sigma ** 2 * np.linalg.inv(JTJ)
        except np.linalg.LinAlgError:
            cov = sigma ** 2 * np.linalg.pinv(JTJ)
    # the effect of the parameters that are not identified (held or ended where the curve does not pin them) on the
    # identified ones: re-fitting the latter (linearised) after the former is doubled or halved moves them by
    # delta = -(J^T J)^-1 J^T dF; the interval 'ci95_with_held' adds the largest such moves to the 95 % interval
    moves = {n: [] for n in ident}
    if cov is not None:
        for h in [n for n in names if n not in ident]:
            for d in ('up', 'down'):
                dF = sens[h].get('diff_' + d)
                if dF is None:
                    continue
                delta = -np.linalg.solve(Ji.T @ Ji, Ji.T @ dF) if len(ident) else []
                for k, n in enumerate(ident):
                    moves[n].append((h, d, float(delta[k])))
    for n in names:
        sens[n] = {k: v for k, v in sens[n].items() if not k.startswith('diff_')}
        sens0[n] = {k: v for k, v in sens0[n].items() if not k.startswith('diff_')}
    for n in names:
        e = {'unit': unit_of(n), 'start': start[n], 'sensitivity': sens[n], 'sensitivity_start': sens0[n],
             'verdict': verdicts[n], 'fitted': n in free}
        if n in ident:
            k = ident.index(n)
            half = tq * math.sqrt(max(cov[k, k], 0.0))
            e.update({'status': 'identified', 'value': best[n], 'ci95': [best[n] * math.exp(-half),
                                                                         best[n] * math.exp(half)],
                      'ci95_rel': math.exp(half) - 1.0})
            if moves[n]:
                lo = min([0.0] + [m[2] for m in moves[n]])
                hi = max([0.0] + [m[2] for m in moves[n]])
                e['held_moves'] = [{'parameter': h, 'factor': 2.0 if d == 'up' else 0.5, 'relative_move':
                                    math.exp(v) - 1.0} for h, d, v in moves[n]]
                e['ci95_with_held'] = [best[n] * math.exp(lo - half), best[n] * math.exp(hi + half)]
        else:
            e.update({'status': 'not identifiable', 'value': None,
                      'held_at': best[n]})
        out['parameters'][n] = e
    if cov is not None and len(ident) > 1:
        d = np.sqrt(np.diag(cov))
        corr = cov / np.outer(d, d)
        out['correlation'] = {'names': ident, 'matrix': corr.tolist()}
    t_total = time.time() - t_start
    out.update({
        'curve': os.path.relpath(os.path.abspath(a.curve), ROOT), 'points': len(u), 'force_unit': a.force_unit, 'width_mm': a.width,
        'ps3d_ratio': a.ps3d_ratio, 'noise_given': a.noise, 'noise_from_data': sigma_data, 'residual_std': s_res,
        'sigma_used': sigma, 'rms_residual': float(math.sqrt(r @ r / len(r))), 'runs': scene.runs,
        'cache_hits': scene.hits, 'failed_runs': [{'params': p, 'reason': why} for p, why in scene.failed],
        'run_seconds': scene.run_seconds, 'total_seconds': t_total, 'jobs': a.jobs, 'ldfcz': os.path.relpath(scene.ldfcz, ROOT),
        'generator': ' '.join(scene.gen_args(best)), 'fd_step': a.fd_step,
        'least_squares': ({'success': bool(result.success), 'nfev': int(result.nfev), 'njev': int(result.njev),
                           'message': result.message} if result is not None else None),
        'held_at_start': held, 'best': best, 'dofs': scene.deck(best)[1]['dofs'],
    })
    # ---- optional 3D confirmation at the fitted values
    if a.confirm_3d:
        s3 = Scene(a, u_max, three_d=True, extra_gen=['--width', repr(a.model_width), '--ny', str(a.ny)])
        t3 = time.time()
        c3 = s3.evaluate(best)
        if c3 is None:
            out['confirm_3d'] = {'ok': False, 'reason': s3.failed[-1][1]}
            say('  3D confirmation run FAILED: %s' % s3.failed[-1][1])
        else:
            f3 = np.interp(u_arr, c3[0], c3[1])
            pl = parts[-1][1]
            d_pl = float(np.mean(f3[pl]) / np.mean(y_meas[pl]) - 1.0)
            ps_over_3d = float(np.mean(f_best[pl]) / np.mean(f3[pl]))
            out['confirm_3d'] = {'ok': True, 'rms_vs_measured': float(np.sqrt(np.mean((f3 - y_meas) ** 2))),
                                 'plateau_rel_diff': d_pl, 'ps_over_3d_plateau': ps_over_3d,
                                 'seconds': time.time() - t3, 'runs': s3.runs, 'width_mm': a.model_width,
                                 'ny': a.ny, 'curve': [c3[0], c3[1]]}
            say('  3D confirmation (quarter model, b = %g mm, n_y = %d): plateau %+.2f %% against the measured, RMS '
                'difference %.4g N/mm; plane-strain/3D plateau ratio at the fitted values %.4f (%d run, %.1f s)' % (
                    a.model_width, a.ny, 100 * d_pl, out['confirm_3d']['rms_vs_measured'], ps_over_3d, s3.runs,
                    out['confirm_3d']['seconds']))
        out['runs'] += s3.runs
        out['cache_hits'] += s3.hits
        out['total_seconds'] = time.time() - t_start
    report(a, out, u_arr, y_meas, y_ps, f_start, f_best, r, parts, log, comments)
    return 0 if (result is None or result.success) else 3


# ----------------------------------------------------------------------------------------------------------------
# report
# ----------------------------------------------------------------------------------------------------------------

VERDICT_TEXT = {
    'identifiable': 'identifiable',
    'unknown': 'sensitivity unknown: both runs at 2 p and p/2 failed',
    'none': 'halving or doubling it moves the curve by less than the noise',
    'lower bound': 'only bounded from below: halving it moves the curve by more than the noise, doubling it does not',
    'upper bound': 'only bounded from above: doubling it moves the curve by more than the noise, halving it does not',
}


def verdict_text(e):
    if e['verdict'] in ('identifiable', 'unknown') and not e['fitted']:
        return 'held at the start, where it was not identifiable, and sensitive at the result: start from there'
    return VERDICT_TEXT[e['verdict']]


def fmt_sens(row, part):
    return ' / '.join('%.3g' % row[d][part] if row[d] is not None else 'failed' for d in ('up', 'down'))


def part_info(row, part):
    lo, hi = sens_level(row, part)
    if hi is None:
        return '?'
    return 'yes' if lo >= 1.0 else 'one-sided' if hi >= 1.0 else 'no'


def report(a, out, u, y_meas, y_ps, f_start, f_best, r, parts, log, comments):
    import numpy as np
    os.makedirs(a.report_dir, exist_ok=True)
    base = os.path.join(a.report_dir, a.name)
    lines = []
    w = lines.append
    w('# Identification: %s' % a.name)
    w('')
    args = ' '.join(x.replace(ROOT + os.sep, '') for x in sys.argv[1:])
    w('Command: `tools/identify.py %s` (%s, %s; 1-min load average %.1f at the end).' % (
        args, time.strftime('%Y-%m-%d %H:%M'), os.uname().nodename, os.getloadavg()[0]))
    for c in comments:
        w('Curve header: `%s`' % c.lstrip('# '))
    w('')
    w('Scene: plane strain, %s, `tools/peel_deck.py %s` (%d DOFs).' % (
        'reading A (the coating pulled along the interface at 0 degrees)' if a.reading == 'bridge' else
        'reading B (the flap lifted and pulled at %g degrees, %s grip)' % (a.angle, a.grip), out['generator'],
        out['dofs']))
    w('')
    w('| parameter | start | result | 95 % CI | change of the curve / noise: doubled, halved (RMS) |')
    w('|---|---|---|---|---|')
    for n, e in out['parameters'].items():
        if e['status'] == 'identified':
            res = '%.5g %s' % (e['value'], e['unit'])
            ci = '%.5g - %.5g (+-%.2f %%)' % (e['ci95'][0], e['ci95'][1], 100 * e['ci95_rel'])
            if e.get('held_moves'):
                ci += '; with the unidentified parameters doubled or halved: %.5g - %.5g (%s)' % (
                    e['ci95_with_held'][0], e['ci95_with_held'][1], ', '.join(
                        '%s x %g: %+.2f %%' % (m['parameter'], m['factor'], 100 * m['relative_move'])
                        for m in e['held_moves']))
        else:
            res = '**not identifiable** (%s; %s %.5g)' % (verdict_text(e),
                                                          'ended at' if e['fitted'] else 'held at', e['held_at'])
            ci = '-'
        w('| %s | %.5g | %s | %s | %s |' % (n, e['start'], res, ci, fmt_sens(e['sensitivity'], 'all')))
    w('')
    if out['correlation']:
        nm = out['correlation']['names']
        w('Correlation of the identified parameters (ln p):')
        w('')
        w('| | ' + ' | '.join(nm) + ' |')
        w('|---' * (len(nm) + 1) + '|')
        for i, n in enumerate(nm):
            w('| %s | %s |' % (n, ' | '.join('%.3f' % v for v in out['correlation']['matrix'][i])))
        w('')
    w('Which part of the curve carries information: RMS change of the force over that part when the parameter is '
      'doubled / halved (runs at the result), divided by the noise; both >= 1: informative, one: one-sided:')
    w('')
    pn = [p for p, _ in parts]
    w('| parameter | ' + ' | '.join('%s (%d pts, u %.3g-%.3g mm)' % (
        p, int(m.sum()), float(u[m][0]), float(u[m][-1])) for p, m in parts) + ' |')
    w('|---' * (len(pn) + 1) + '|')
    for n, e in out['parameters'].items():
        w('| %s | %s |' % (n, ' | '.join('%s (%s)' % (fmt_sens(e['sensitivity'], p), part_info(e['sensitivity'], p))
                                         for p in pn)))
    w('')
    w('Noise: %s; residual std after the fit %.4g N/mm (%d points, RMS residual %.4g N/mm); the data\'s own '
      'estimate (second differences) %.4g N/mm.' % (
          ('given %.4g N/mm' % out['noise_given']) if out['noise_given'] else 'from the residual',
          out['residual_std'], out['points'], out['rms_residual'], out['noise_from_data']))
    if out['ps3d_ratio']:
        w('')
        w('3D correction: the measured force was multiplied by the plane-strain/3D ratio %.4g before the fit.'
          % out['ps3d_ratio'])
    c3 = out.get('confirm_3d')
    if c3:
        w('')
        if c3['ok']:
            w('3D confirmation at the fitted values (quarter model, b = %g mm, n_y = %d, %.1f s): plateau %+.2f %% '
              'against the measured; RMS difference over the curve %.4g N/mm; plane-strain/3D plateau ratio %.4f.'
              % (c3['width_mm'], c3['ny'], c3['seconds'], 100 * c3['plateau_rel_diff'], c3['rms_vs_measured'],
                 c3['ps_over_3d_plateau']))
        else:
            w('3D confirmation run failed: %s' % c3['reason'])
    w('')
    ls = out['least_squares']
    w('Run time: **%.1f s** in all, **%d ldfcz runs** (%d cache hits; %.1f s of runs, %d in parallel); '
      'least_squares: %s.' % (out['total_seconds'], out['runs'], out['cache_hits'], out['run_seconds'], out['jobs'],
                              ('%s, %d residual and %d Jacobian evaluations' % (
                                  'converged' if ls['success'] else 'not converged', ls['nfev'], ls['njev']))
                              if ls else 'no parameter to fit'))
    if out['failed_runs']:
        w('')
        w('Failed runs (skipped; a failed trial point counts as a rejected step):')
        for fr in out['failed_runs']:
            w('- %s: %s' % (fmt_params(fr['params']), fr['reason']))
    w('')
    w('![measured and fitted curve](%s.png)' % a.name)
    w('')
    w('Log:')
    w('```')
    lines.extend(log)
    w('```')
    with open(base + '.md', 'w') as fh:
        fh.write('\n'.join(lines) + '\n')
    js = {k: v for k, v in out.items() if k != 'confirm_3d'}
    if c3:
        js['confirm_3d'] = {k: v for k, v in c3.items() if k != 'curve'}
    with open(base + '.json', 'w') as fh:
        json.dump(js, fh, indent=1, sort_keys=True)
    with open(base + '_curves.csv', 'w', newline='') as fh:
        wr = csv.writer(fh)
        wr.writerow(['pull_mm', 'measured_N_per_mm', 'plane_strain_equivalent', 'start', 'fitted', 'residual'])
        for row in zip(u, y_meas, y_ps, f_start, f_best, r):
            wr.writerow(['%.8g' % v for v in row])
    plot(base + '.png', a, out, u, y_meas, y_ps, f_start, f_best, r, parts)
    print('identify: results')
    for n, e in out['parameters'].items():
        if e['status'] == 'identified':
            print('  %-7s = %.5g %s  (95 %% CI %.5g - %.5g, +-%.2f %%)' % (
                n, e['value'], e['unit'], e['ci95'][0], e['ci95'][1], 100 * e['ci95_rel']))
            if e.get('held_moves'):
                print('          with the unidentified parameters doubled or halved: %.5g - %.5g (%s)' % (
                    e['ci95_with_held'][0], e['ci95_with_held'][1], ', '.join(
                        '%s x %g: %+.2f %%' % (m['parameter'], m['factor'], 100 * m['relative_move'])
                        for m in e['held_moves'])))
        else:
            print('  %-7s   not identifiable: %s (%s %.5g %s)' % (
                n, verdict_text(e), 'ended at' if e['fitted'] else 'held at', e['held_at'], e['unit']))
        print('          doubled / halved: %s x the noise; informative parts: %s' % (
            fmt_sens(e['sensitivity'], 'all'),
            ', '.join('%s%s' % (p, '' if part_info(e['sensitivity'], p) == 'yes' else ' (one-sided)')
                      for p in pn if part_info(e['sensitivity'], p) != 'no') or 'none'))
    if out['correlation']:
        nm = out['correlation']['names']
        for i in range(len(nm)):
            for j in range(i + 1, len(nm)):
                print('  correlation(%s, %s) = %.3f' % (nm[i], nm[j], out['correlation']['matrix'][i][j]))
    print('  residual std %.4g N/mm; %d runs (%d cached), %d failed; total %.1f s' % (
        out['residual_std'], out['runs'], out['cache_hits'], len(out['failed_runs']), out['total_seconds']))
    print('  report: %s.md' % base)


def plot(png, a, out, u, y_meas, y_ps, f_start, f_best, r, parts):
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write('identify: matplotlib not installed: no plot\n')
        return
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True, gridspec_kw={'height_ratios': [3, 1.3]})
    um = 1e3 * u
    ax.plot(um, y_meas, 'k.', ms=4, label='measured')
    if out['ps3d_ratio']:
        ax.plot(um, y_ps, '.', color='0.6', ms=3, label='measured x %.4g (plane-strain equivalent)'
                % out['ps3d_ratio'])
    ax.plot(um, f_start, ':', color='tab:gray', label='start')
    ident = ', '.join('%s = %.4g' % (n, e['value']) for n, e in out['parameters'].items()
                      if e['status'] == 'identified')
    ax.plot(um, f_best, '-', color='tab:red', label='fitted (plane strain): ' + (ident or 'nothing identified'))
    c3 = out.get('confirm_3d')
    if c3 and c3['ok']:
        ax.plot([1e3 * v for v in c3['curve'][0]], c3['curve'][1], '--', color='tab:blue',
                label='3D quarter model at the fitted values')
    ax.set_ylabel('peel force per unit width (N/mm)')
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc='lower right')
    for name, m in parts[1:]:
        ax.axvline(float(um[m][0]), color='0.7', lw=0.6)
        ax2.axvline(float(um[m][0]), color='0.7', lw=0.6)
    ax2.plot(um, r, '.-', color='tab:red', ms=3, lw=0.5)
    ax2.axhline(0, color='k', lw=0.5)
    ax2.set_ylabel('residual (N/mm)')
    ax2.set_xlabel('pull u_x (um)')
    ax2.grid(alpha=0.3)
    fig.suptitle('tools/identify.py: %s (%d runs, %.0f s)' % (a.name, out['runs'], out['total_seconds']),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


# ----------------------------------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest='command', required=True)
    s = sub.add_parser('synth', help='a synthetic measured curve from the scene at known parameters')
    s.add_argument('-o', '--output', required=True, help='CSV to write')
    s.add_argument('--phi', type=float, default=0.2, help='work of separation (N/mm)')
    s.add_argument('--tmax', type=float, default=20.0, help='T_max (MPa)')
    s.add_argument('--noise', type=float, default=0.0, help='Gaussian noise std (N/mm; with --relative: fraction '
                   'of the largest force)')
    s.add_argument('--relative', action='store_true')
    s.add_argument('--seed', type=int, default=1)
    s.add_argument('--points', type=int, default=60)
    s.add_argument('--u-max', type=float, default=0.05, help='largest pull (mm)')
    s.add_argument('--u-min', type=float, default=None, help='first pull (mm), default u_max/points')
    s.add_argument('--force-unit', choices=('N', 'N/mm'), default='N/mm')
    s.add_argument('--width', type=float, default=0.0, help='specimen width (mm) for --force-unit N')
    s.add_argument('--3d', dest='three_d', action='store_true', help='the 3D quarter model instead')
    add_scene_options(s)
    add_3d_options(s)
    f = sub.add_parser('fit', help='fit the scene to a measured curve')
    f.add_argument('curve', help='CSV: pull, force (comment lines #, one header line allowed)')
    f.add_argument('--force-unit', required=True, choices=('N', 'N/mm'),
                   help='unit of the force column: N (divided by --width) or N/mm (per unit width)')
    f.add_argument('--width', type=float, default=0.0, help='specimen width (mm), with --force-unit N')
    f.add_argument('--pull-unit', choices=('mm', 'um'), default='mm')
    f.add_argument('--fit', default='phi,tmax', help='parameters to fit: phi, tmax, PET constants (%s)'
                   % ', '.join(PET_FITTABLE))
    f.add_argument('--start', default='', help='start values, e.g. phi=0.15,tmax=25 (default phi 0.2, T_max 20, '
                   'Table 1)')
    f.add_argument('--noise', type=float, default=0.0,
                   help='measurement noise std (N/mm); default: estimated (data, then the fit residual)')
    f.add_argument('--plateau', type=float, default=0.3, help='fraction of the pull taken as the plateau')
    f.add_argument('--fd-step', type=float, default=0.02, help='finite-difference step in ln p (default 0.02)')
    f.add_argument('--xtol', type=float, default=1e-3, help='convergence: step in ln p (default 1e-3)')
    f.add_argument('--max-evals', type=int, default=30, help='most residual evaluations of least_squares')
    f.add_argument('--bound-factor', type=float, default=10.0,
                   help='the parameters stay within this factor of their start values')
    f.add_argument('--ps3d-ratio', type=float, default=None,
                   help='measured plane-strain/3D force ratio of this geometry (reports/stmt-3d-fine): the measured '
                   'force is multiplied by it and fitted with the plane-strain scene')
    f.add_argument('--confirm-3d', action='store_true', help='one 3D quarter-model run at the fitted values')
    f.add_argument('--report-dir', default=os.path.join(ROOT, 'reports', 'identify'))
    f.add_argument('--name', default='', help='report name (default: the curve file\'s base name)')
    f.add_argument('--quiet', action='store_true')
    add_scene_options(f)
    add_3d_options(f)
    a = ap.parse_args(argv)
    try:
        if a.command == 'synth':
            return cmd_synth(a)
        a.name = a.name or os.path.splitext(os.path.basename(a.curve))[0]
        return cmd_fit(a)
    except InputError as e:
        sys.stderr.write('identify: %s\n' % e)
        return 2
    except FitError as e:
        sys.stderr.write('identify: fit failed: %s\n' % e)
        return 3


def add_3d_options(ap):
    g = ap.add_argument_group('3D quarter model (synth --3d, fit --confirm-3d)')
    g.add_argument('--model-width', type=float, default=0.040, help='modelled width b (mm), default 0.040')
    g.add_argument('--ny', type=int, default=2, help='elements over b, default 2 (mesh-y study: within 0.05 %%)')


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('identify'))
