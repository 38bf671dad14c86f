#!/usr/bin/python3
"""Steady peel force that says how steady it is (issue 17, item 4), and Richardson extrapolation of mesh studies.

A peel run gives F/w against the pull u and, from the field frames, the delamination length d(u) (how far the front
has moved from its initial position into the fine region of length L_f with element length l_e). The steady force
is only meaningful while the front runs through the fine region, after the start-up transient:

  1. admissible pulls: d(u) >= n_cross l_e (the front has crossed n_cross elements of the fine region) and
     d(u) <= L_f - n_margin l_e (the front, with its process zone, is still inside the fine region). A value
     taken elsewhere is refused (status 'front-not-in-fine-region'); samples beyond the fine region are cut off and
     flagged ('front-left-fine-region').
  2. the ripple period: while the front runs through the fine region the force oscillates with the time the front
     takes to cross one cohesive element, P = l_e / v (v: the front's advance per unit pull over the admissible
     interval, from the front history); the force is averaged over whole periods ("cycle means"), which removes
     the ripple from the value and from the drift test. Without a front history (or v <= 0) P is taken from the
     residual's sign changes, and without at least MIN_CYCLES whole periods the samples themselves are used.
  3. plateau: the earliest start s in the admissible interval [u_a, u_b] (tried in steps of 2 % of its length) such
     that the window [s, u_b] holds at least min_window of the admissible interval and the cycle means over it
     have a relative drift (slope of a straight line times the window length) and a relative curvature (the
     quadratic term of a parabola fitted to them: its end value minus its mid value, c W^2 / 4) both below
     settle_tol: a U-shaped or arched history is not a plateau even when its straight line is flat. None: status
     'no-plateau' (value and figures are still given, for the last min_window).
  4. over the window (whole periods ending at u_b): value = the mean of the cycle means (without whole periods:
     the pull-weighted trapezoidal mean); drift, curvature as above; ripple = half the peak-to-peak of the
     residual of the samples about the cycle means' line, relative: the force's oscillation at the element
     period, a resolution error of the cohesive discretisation (it shrinks with l_e), not noise; ripple_elements =
     the observed period (window / half the residual's sign changes) in elements crossed by the front (1: the
     element period); uncertainty (relative, of the averaging only) = |drift|/2 + |curvature|/2 + the standard
     error of the cycle means (their standard deviation / sqrt(n)); without whole periods the former bound
     |drift|/2 + ripple/(pi max(cycles, 1)) (|mean of A sin| <= A P / (pi W) over a window of partial periods).
  5. quarters (the plateau check of a referee): the mean of the cycle means whose centres lie in the last quarter
     of the run's pull against those of the quarter before: quarter_change = Q4/Q3 - 1, and value_vs_quarters =
     the larger of |value/Q3 - 1|, |value/Q4 - 1| (None when the quarters are not both inside the admissible
     interval with whole periods).

The uncertainty above is that of reading the steady force from one run. The discretisation error (element
formulation, elements through the thickness, element length) is a separate band measured by mesh studies;
band() adds its parts (their absolute values: the errors are not independent random draws) and describe_band()
prints the value with both.

Without a front history (d(u) unknown) the admissible interval is the whole run and the status says so
('front-unknown'); nothing is then refused, only flagged.

Richardson (three meshes h1 > h2 > h3, values F1, F2, F3): observed order p from
(F1 - F2)/(F2 - F3) = (h1^p - h2^p)/(h2^p - h3^p) (bisection; closed form ln(.)/ln(r) for a constant ratio r),
F_inf = F3 + (F3 - F2)/((h2/h3)^p - 1). Oscillating differences (opposite signs) have no order: returned as None
with the reason.

Python standard library only.
"""
import math

OK = 'ok'


def _trapz_mean(u, f):
    w = u[-1] - u[0]
    if w <= 0.0:
        return sum(f) / len(f)
    return sum(0.5 * (f[i] + f[i - 1]) * (u[i] - u[i - 1]) for i in range(1, len(u))) / w


def _line_fit(u, f):
    """Least-squares line f = a + b (u - um) with weights = the pull each sample represents (trapezoidal)."""
    n = len(u)
    if n < 2 or u[-1] <= u[0]:
        return (sum(f) / n if n else float('nan')), 0.0, (u[0] if n else 0.0)
    wt = []
    for i in range(n):
        lo = u[i] - u[i - 1] if i > 0 else 0.0
        hi = u[i + 1] - u[i] if i < n - 1 else 0.0
        wt.append(0.5 * (lo + hi))
    sw = sum(wt)
    um = sum(w * x for w, x in zip(wt, u)) / sw
    fm = sum(w * y for w, y in zip(wt, f)) / sw
    sxx = sum(w * (x - um) ** 2 for w, x in zip(wt, u))
    sxy = sum(w * (x - um) * (y - fm) for w, x, y in zip(wt, u, f))
    return fm, (sxy / sxx if sxx > 0.0 else 0.0), um


def _interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 1.0
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]


def _crossing(us, ds, level):
    """First pull at which the (piecewise linear) delamination history reaches level; None if never."""
    if ds[0] >= level:
        return us[0]
    for k in range(1, len(us)):
        if ds[k] >= level > ds[k - 1]:
            return us[k - 1] + (level - ds[k - 1]) / (ds[k] - ds[k - 1]) * (us[k] - us[k - 1])
    return None


def window_stats(u, f):
    """value, drift, ripple, cycles, uncertainty (relative) of F/w samples f at pulls u (one window)."""
    mean = _trapz_mean(u, f)
    a, b, um = _line_fit(u, f)
    w = u[-1] - u[0]
    drift = b * w / mean if mean else float('nan')
    res = [y - (a + b * (x - um)) for x, y in zip(u, f)]
    ripple = 0.5 * (max(res) - min(res)) / abs(mean) if mean else float('nan')
    signs = [1 if r > 0 else -1 for r in res if r != 0.0]
    changes = sum(1 for i in range(1, len(signs)) if signs[i] != signs[i - 1])
    cycles = 0.5 * changes
    unc = 0.5 * abs(drift) + ripple / (math.pi * max(cycles, 1.0))
    return {'value': mean, 'drift': drift, 'ripple': ripple, 'cycles': cycles, 'uncertainty': unc}


MIN_CYCLES = 3


def _front_speed(fu, fd, a, b):
    """Mean front advance per unit pull over [a, b] from the (monotone, piecewise linear) front history."""
    return (_interp(fu, fd, b) - _interp(fu, fd, a)) / (b - a) if b > a else 0.0


def cycle_means(u, f, a, b, period):
    """Means of f (trapezoidal, over the pull) over the whole periods [b - k P, b - (k - 1) P] inside [a, b], oldest
    first, as (centre, mean) pairs; [] when the period is unknown or longer than the interval."""
    if not period or period <= 0.0:
        return []
    n = int((b - a) / period * (1.0 + 1e-9))
    out = []
    for k in range(n, 0, -1):
        lo, hi = b - k * period, b - (k - 1) * period
        cu, cf = _cut(u, f, lo, hi)
        out.append((0.5 * (lo + hi), _trapz_mean(cu, cf)))
    return out


def _poly_trend(cm):
    """Relative drift (line slope x span) and curvature (c W^2 / 4 of a parabola) of cycle means cm."""
    n = len(cm)
    x = [c[0] for c in cm]
    y = [c[1] for c in cm]
    mean = sum(y) / n
    w = (x[-1] - x[0]) * n / (n - 1) if n > 1 else 0.0     # the span of the whole periods
    xm = sum(x) / n
    sxx = sum((t - xm) ** 2 for t in x)
    slope = sum((t - xm) * (v - mean) for t, v in zip(x, y)) / sxx if sxx > 0 else 0.0
    curv = 0.0
    if n >= 4 and sxx > 0:
        # least squares on (1, t, t^2 - mean(t^2)) with t = x - xm: the t^2 column made orthogonal to 1 and t
        q = [(t - xm) ** 2 for t in x]
        qm = sum(q) / n
        t3 = sum((t - xm) * (qq - qm) for t, qq in zip(x, q)) / sxx
        qq_ = [qq - qm - t3 * (t - xm) for t, qq in zip(x, q)]
        sqq = sum(v * v for v in qq_)
        c = sum(v * (yy - mean) for v, yy in zip(qq_, y)) / sqq if sqq > 0 else 0.0
        curv = c * w * w / 4.0 / mean if mean else float('nan')
    return (slope * w / mean if mean else float('nan')), curv


def window_stats(u, f, period=None):
    """value, drift, curvature, ripple, cycles, uncertainty (relative) of F/w samples f at pulls u over one window;
    with a ripple period, over the whole periods ending at the window's end (its start moved to theirs)."""
    cm = cycle_means(u, f, u[0], u[-1], period) if period else []
    if len(cm) >= MIN_CYCLES:
        a = u[-1] - len(cm) * period
        u, f = _cut(u, f, a, u[-1]) if a > u[0] else (u, f)
        mean = sum(c[1] for c in cm) / len(cm)
        drift, curv = _poly_trend(cm)
        sem = (math.sqrt(sum((c[1] - mean) ** 2 for c in cm) / (len(cm) - 1) / len(cm)) / abs(mean)
               if mean else float('nan'))
    else:
        cm = []
        mean = _trapz_mean(u, f)
        curv, sem = 0.0, 0.0
    a0, b, um = _line_fit(u, f)
    w = u[-1] - u[0]
    if not cm:
        drift = b * w / mean if mean else float('nan')
    else:
        # the residual about the cycle means' line (their mean and drift)
        um = 0.5 * (u[0] + u[-1])
        a0, b = mean, drift * mean / w if w > 0 else 0.0
    res = [y - (a0 + b * (x - um)) for x, y in zip(u, f)]
    ripple = 0.5 * (max(res) - min(res)) / abs(mean) if mean else float('nan')
    signs = [1 if r > 0 else -1 for r in res if r != 0.0]
    changes = sum(1 for i in range(1, len(signs)) if signs[i] != signs[i - 1])
    cycles = 0.5 * changes
    if cm:
        unc = 0.5 * abs(drift) + 0.5 * abs(curv) + sem
    else:
        unc = 0.5 * abs(drift) + ripple / (math.pi * max(cycles, 1.0))
    return {'value': mean, 'drift': drift, 'curvature': curv, 'ripple': ripple, 'cycles': cycles,
            'uncertainty': unc, 'sem': sem, 'cycle_means': cm, 'window': (u[0], u[-1])}


def estimate(u, fw, front=None, l_e=None, fine_length=None, n_cross=3, n_margin=2, settle_tol=0.002,
             min_window=0.3, step=0.02):
    """Steady force of one run. u, fw: pull (mm) and F/w (N/mm), u increasing; front: (u_k, d_k) pairs, the
    delamination length d_k (mm) at pull u_k (from the field frames), or None; l_e, fine_length (mm).
    Returns a dict: value, uncertainty (relative, of the averaging), drift, curvature, ripple, ripple_elements,
    cycles, period (mm of pull), cycle_means, quarter_change, value_vs_quarters, window (u0, u1), status, flags,
    ok."""
    out = {'value': float('nan'), 'uncertainty': float('nan'), 'drift': float('nan'), 'ripple': float('nan'),
           'curvature': float('nan'), 'cycles': 0.0, 'window': (float('nan'), float('nan')), 'status': OK,
           'flags': [], 'ok': False, 'period': None, 'ripple_elements': float('nan'), 'cycle_means': [],
           'quarter_change': None, 'value_vs_quarters': None, 'front_speed': float('nan')}
    pts = [(x, y) for x, y in zip(u, fw) if x == x and y == y]
    if len(pts) < 3:
        out['status'] = 'too-few-samples'
        out['flags'].append(out['status'])
        return out
    u = [p[0] for p in pts]
    fw = [p[1] for p in pts]
    ua, ub = u[0], u[-1]
    fu = fd = None
    if front and l_e and fine_length:
        fu = [0.0] + [p[0] for p in front]
        fd = [0.0] + [p[1] for p in front]
        # the front history only resolves d(u) between frames: d is monotone (damage does not heal)
        for k in range(1, len(fd)):
            fd[k] = max(fd[k], fd[k - 1])
        start = _crossing(fu, fd, n_cross * l_e)
        leave = _crossing(fu, fd, fine_length - n_margin * l_e)
        if start is None:
            out['status'] = 'front-not-in-fine-region'
            out['flags'].append('front crossed fewer than %d elements (%.4g mm delaminated at %.4g mm of pull)'
                                % (n_cross, fd[-1], fu[-1]))
            return _fill_last(out, u, fw, min_window)
        ua = max(ua, start)
        if leave is not None:
            out['flags'].append('front-left-fine-region at %.4g mm of pull: samples beyond it not used' % leave)
            ub = min(ub, leave)
        elif fu[-1] < u[-1] * (1.0 - 1e-9):
            # after the last frame the front is extrapolated at its last speed: flag if it may have left
            spd = (fd[-1] - fd[-2]) / (fu[-1] - fu[-2]) if len(fu) > 1 and fu[-1] > fu[-2] else 0.0
            d_end = fd[-1] + spd * (u[-1] - fu[-1])
            if d_end > fine_length - n_margin * l_e:
                ub = min(ub, fu[-1] + (fine_length - n_margin * l_e - fd[-1]) / spd)
                out['flags'].append('front-left-fine-region (extrapolated from the last frame) at %.4g mm' % ub)
        if ub <= ua:
            out['status'] = 'front-not-in-fine-region'
            out['flags'].append('no pull with the front inside the fine region')
            return _fill_last(out, u, fw, min_window)
    else:
        out['flags'].append('front-unknown: the whole run is admissible')
    span = ub - ua
    # the ripple period: one cohesive element crossed by the front (its speed over the admissible interval), else
    # the residual's sign changes over the admissible interval
    period = None
    if fu is not None:
        v = _front_speed(fu, fd, ua, ub) if fu[-1] >= ub * (1.0 - 1e-9) else _front_speed(fu, fd, ua, fu[-1])
        out['front_speed'] = v
        if v > 0.0:
            period = l_e / v
    if period is None:
        wu, wf = _cut(u, fw, ua, ub)
        st = window_stats(wu, wf)
        if st['cycles'] >= MIN_CYCLES:
            period = span / st['cycles']
    out['period'] = period
    chosen = None
    k = 0
    while True:
        s = ua + k * step * span
        if ub - s < min_window * span * (1.0 - 1e-12):
            break
        wu, wf = _cut(u, fw, s, ub)
        if len(wu) >= 3:
            st = window_stats(wu, wf, period)
            if abs(st['drift']) <= settle_tol and abs(st['curvature']) <= settle_tol:
                chosen = st
                break
        k += 1
    if chosen is None:
        s = ub - min_window * span
        wu, wf = _cut(u, fw, s, ub)
        st = window_stats(wu, wf, period) if len(wu) >= 3 else None
        out['status'] = 'no-plateau'
        out['flags'].append('no-plateau: drift or curvature of the cycle means above %.3g over every window'
                            % settle_tol)
        if st is None:
            return out
        chosen = st
    out.update(chosen)
    if period and out['cycles'] > 0 and l_e and out['front_speed'] == out['front_speed']:
        w = out['window'][1] - out['window'][0]
        out['ripple_elements'] = (w / out['cycles']) * out['front_speed'] / l_e
    _quarters(out, u, fw, ua, ub, period)
    out['ok'] = out['status'] == OK
    return out


def _quarters(out, u, fw, ua, ub, period):
    """The plateau check: cycle means in the last quarter of the run's pull against the quarter before."""
    u_end = u[-1]
    q3, q4 = (0.5 * u_end, 0.75 * u_end), (0.75 * u_end, u_end)
    if not period or q3[0] < ua - 1e-12 or q4[1] > ub + 1e-12:
        out['flags'].append('quarters: the last two quarters of the pull are not both inside the admissible '
                            'interval with whole ripple periods: no plateau check')
        return
    m = []
    for a, b in (q3, q4):
        cm = cycle_means(u, fw, a, b, period)
        if not cm:
            return
        m.append(sum(c[1] for c in cm) / len(cm))
    out['quarter_means'] = tuple(m)
    out['quarter_change'] = m[1] / m[0] - 1.0
    out['value_vs_quarters'] = max(abs(out['value'] / m[0] - 1.0), abs(out['value'] / m[1] - 1.0))


def band(parts):
    """The discretisation band (relative) from its parts {name: relative difference}: the sum of their absolute
    values (the errors of element formulation, thickness mesh and element length are not independent random
    draws, so they are not added in quadrature)."""
    return sum(abs(v) for v in parts.values())


def describe_band(est, parts):
    """Value +- averaging uncertainty, and the discretisation band with its parts."""
    b = band(parts)
    return ('%.4f N/mm +- %.2f %% (averaging) +- %.2f %% (discretisation: %s)' % (
        est['value'], 100 * est['uncertainty'], 100 * b,
        ', '.join('%s %.2f %%' % (k, 100 * abs(v)) for k, v in parts.items())))


def _fill_last(out, u, fw, min_window):
    """Figures of the last min_window of the run, for the record of a refused value (ok stays False)."""
    s = u[-1] - min_window * (u[-1] - u[0])
    wu, wf = _cut(u, fw, s, u[-1])
    if len(wu) >= 3:
        out.update(window_stats(wu, wf))
        out['window'] = (s, u[-1])
    out['ok'] = False
    return out


def _cut(u, f, a, b):
    """Samples with a < u < b plus the interpolated values at a and b."""
    wu, wf = [a], [_interp(u, f, a)]
    for x, y in zip(u, f):
        if a < x < b:
            wu.append(x)
            wf.append(y)
    wu.append(b)
    wf.append(_interp(u, f, b))
    return wu, wf


def observed_order(h, F, tol=1e-12):
    """Observed order p of F(h) = F_inf + C h^p from three meshes h[0] > h[1] > h[2]. None (with a reason) when the
    differences oscillate or vanish."""
    (h1, h2, h3), (f1, f2, f3) = h, F
    d12, d23 = f1 - f2, f2 - f3
    if abs(d23) <= tol * max(abs(f3), 1.0) or abs(d12) <= tol * max(abs(f3), 1.0):
        return None, 'differences below round-off: converged or no resolution'
    if d12 * d23 < 0.0:
        return None, 'oscillating convergence (F1 - F2 and F2 - F3 of opposite signs)'
    ratio = d12 / d23
    r12, r23 = h1 / h2, h2 / h3
    if abs(r12 - r23) < 1e-9 * r23:
        p = math.log(ratio) / math.log(r23)
        if p <= 0.0:
            return None, 'differences growing with refinement (p = %.2f <= 0): not in the asymptotic range' % p
        return p, ''

    def g(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - ratio
    lo, hi = 1e-3, 20.0
    if g(lo) * g(hi) > 0:
        return None, 'no order in (0, 20]: not in the asymptotic range'
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi), ''


def richardson(h, F):
    """(F_inf, p, reason) from three meshes (any order of h; sorted coarse to fine here)."""
    pairs = sorted(zip(h, F), key=lambda t: -t[0])
    hs = [p[0] for p in pairs]
    fs = [p[1] for p in pairs]
    p, why = observed_order(hs, fs)
    if p is None:
        return None, None, why
    f_inf = fs[2] + (fs[2] - fs[1]) / ((hs[1] / hs[2]) ** p - 1.0)
    return f_inf, p, ''


def describe(est):
    """One line: value +- uncertainty, drift, curvature, ripple, window and status."""
    if est['value'] != est['value']:
        return 'no value (%s)' % est['status']
    q = est.get('quarter_change')
    return ('%.4f N/mm +- %.2f %% (drift %+.2f %%, curvature %+.2f %%, ripple +-%.2f %%, %.1f cycles, window '
            '%.1f-%.1f um%s) %s' % (
                est['value'], 100 * est['uncertainty'], 100 * est['drift'], 100 * (est.get('curvature') or 0.0),
                100 * est['ripple'], est['cycles'], 1e3 * est['window'][0], 1e3 * est['window'][1],
                ', last quarter %+.2f %% against the one before' % (100 * q) if q is not None else '',
                est['status']))
