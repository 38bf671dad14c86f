#!/usr/bin/python3
"""Steady peel force that says how steady it is (issue 17, item 4), and Richardson extrapolation of mesh studies.

A peel run gives F/w against the pull u and, from the field frames, the delamination length d(u) (how far the front
has moved from its initial position into the fine region of length L_f with element length l_e). The steady force
is only meaningful while the front runs through the fine region, after the start-up transient:

  1. admissible pulls: d(u) >= n_cross l_e (the front has crossed n_cross elements of the fine region) and
     d(u) <= L_f - n_margin l_e (the front, with its process zone, is still inside the fine region). A value
     taken elsewhere is refused (status 'front-not-in-fine-region'); samples beyond the fine region are cut off and
     flagged ('front-left-fine-region').
  2. plateau: the earliest start s in the admissible interval [u_a, u_b] (tried in steps of 2 % of its length) such
     that the window [s, u_b] holds at least min_window of the admissible interval and the relative drift of a
     straight line fitted to F/w over it is below settle_tol; none: status 'no-plateau' (value and figures are
     still given, for the last min_window).
  3. over the window: value = mean of F/w weighted by the pull (trapezoidal integral / window length: cutbacks
     concentrate samples and must not weight the mean); drift = slope of the least-squares line (pull-weighted)
     times the window length, relative to the value; ripple = half the peak-to-peak of the residual about that line,
     relative; cycles = number of ripple periods in the window (half the sign changes of the residual); uncertainty
     (relative) = |drift|/2 + ripple/(pi max(cycles, 1)): the first term bounds the distance of the mean from the
     value at either end of a straight drift, the second the bias of averaging a sinusoid of that amplitude over a
     window that is not a whole number of periods (|mean of A sin| <= A P / (pi W)).

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


def estimate(u, fw, front=None, l_e=None, fine_length=None, n_cross=3, n_margin=2, settle_tol=0.005,
             min_window=0.3, step=0.02):
    """Steady force of one run. u, fw: pull (mm) and F/w (N/mm), u increasing; front: (u_k, d_k) pairs, the
    delamination length d_k (mm) at pull u_k (from the field frames), or None; l_e, fine_length (mm).
    Returns a dict: value, uncertainty (relative), drift, ripple, cycles, window (u0, u1), status, flags, ok."""
    out = {'value': float('nan'), 'uncertainty': float('nan'), 'drift': float('nan'), 'ripple': float('nan'),
           'cycles': 0.0, 'window': (float('nan'), float('nan')), 'status': OK, 'flags': [], 'ok': False}
    pts = [(x, y) for x, y in zip(u, fw) if x == x and y == y]
    if len(pts) < 3:
        out['status'] = 'too-few-samples'
        out['flags'].append(out['status'])
        return out
    u = [p[0] for p in pts]
    fw = [p[1] for p in pts]
    ua, ub = u[0], u[-1]
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
    # samples of the admissible interval (interpolated at its ends)
    chosen = None
    k = 0
    while True:
        s = ua + k * step * span
        if ub - s < min_window * span * (1.0 - 1e-12):
            break
        wu, wf = _cut(u, fw, s, ub)
        if len(wu) >= 3:
            st = window_stats(wu, wf)
            if abs(st['drift']) <= settle_tol:
                chosen = (s, st)
                break
        k += 1
    if chosen is None:
        s = ub - min_window * span
        wu, wf = _cut(u, fw, s, ub)
        st = window_stats(wu, wf) if len(wu) >= 3 else None
        out['status'] = 'no-plateau'
        out['flags'].append('no-plateau: drift over every window above %.3g' % settle_tol)
        if st is None:
            return out
        chosen = (s, st)
    s, st = chosen
    out.update(st)
    out['window'] = (s, ub)
    out['ok'] = out['status'] == OK
    return out


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
    """One line: value +- uncertainty, drift, ripple, window and status."""
    if est['value'] != est['value']:
        return 'no value (%s)' % est['status']
    return '%.4f N/mm +- %.2f %% (drift %+.2f %%, ripple +-%.2f %%, %.1f cycles, window %.1f-%.1f um) %s' % (
        est['value'], 100 * est['uncertainty'], 100 * est['drift'], 100 * est['ripple'], est['cycles'],
        1e3 * est['window'][0], 1e3 * est['window'][1], est['status'])
