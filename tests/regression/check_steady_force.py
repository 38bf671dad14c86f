#!/usr/bin/python3
"""Unit checks of tools/ldfcz_tools/steady_force.py on synthetic peel curves with known answers (CTest steady_force).

Every curve: pull u in [0, 0.1] mm sampled unevenly (bunched samples imitate cutbacks, which must not weight the
mean), front history d(u) = 1.5 (u - 0.01) mm after a start-up of 10 um, l_e = 0.005 mm, fine region 0.2 mm.
Exit status 0 when every assertion holds.
"""
import math
import sys

from ldfcz_tools import steady_force as sf

LE, FINE, F0 = 0.005, 0.2, 1.2
BAD = []


def check(cond, text):
    print(('ok   ' if cond else 'FAIL ') + text)
    if not cond:
        BAD.append(text)


def samples(n=2000, u_end=0.1):
    """Uneven samples: a dense burst every 10th sample stretch (weights must come from the pull, not the count)."""
    u, x = [], 0.0
    k = 0
    while x < u_end:
        u.append(x)
        x += (u_end / n) * (0.1 if (k // 20) % 3 == 0 else 1.45)
        k += 1
    u.append(u_end)
    return u


def front(u, speed=1.5, u0=0.01):
    return [(x, max(0.0, speed * (x - u0))) for x in u[::25] + [u[-1]]]


def ramp(x, u1=0.015):
    return F0 * min(x / u1, 1.0)


u = samples()
fr = front(u)

# 1. ramp (up to 15 um) then plateau: the plateau value exactly, window after 3 elements crossed (20 um)
e = sf.estimate(u, [ramp(x) for x in u], fr, LE, FINE)
print('ramp:', sf.describe(e))
check(e['ok'] and abs(e['value'] / F0 - 1) < 1e-12, 'ramp: value = F0 to 1e-12 (%.3e)' % (e['value'] / F0 - 1))
check(e['window'][0] >= 0.02 - 1e-12, 'ramp: window starts after 3 elements crossed (%.4f mm)' % e['window'][0])
check(abs(e['drift']) < 1e-12 and e['uncertainty'] < 1e-12, 'ramp: no drift, no uncertainty on a flat plateau')
# the start: after the ramp and at the earliest the crossing of 3 elements (u = 0.01 + 3 l_e / 1.5 = 0.02 mm)
check(e['window'][0] <= 0.02 + 0.02 * (0.1 - 0.02) + 1e-12, 'ramp: window starts within one search step of 20 um')

# 2. ripple with the element period: F0 (1 + A sin(2 pi d / l_e)); value within its stated uncertainty; ripple A
A = 0.013
fr_r = [(x, max(0.0, 1.5 * (x - 0.01))) for x in u]   # dense front history (the ripple needs d(u) only here)
f = [ramp(x) * (1 + A * math.sin(2 * math.pi * max(0.0, 1.5 * (x - 0.01)) / LE)) for x in u]
e = sf.estimate(u, f, fr_r, LE, FINE)
print('ripple:', sf.describe(e))
err = abs(e['value'] / F0 - 1)
check(e['ok'] and err <= e['uncertainty'], 'ripple: |value/F0 - 1| = %.2e within the stated %.2e' % (
    err, e['uncertainty']))
# 5 %: over a window that is not a whole number of periods the fitted line takes up part of the sinusoid (its tilt
# is ~ A / cycles), which the residual's peak-to-peak then carries
check(abs(e['ripple'] / A - 1) < 0.05, 'ripple: amplitude %.4f = A = %.4f to 5 %%' % (e['ripple'], A))
w = e['window'][1] - e['window'][0]
cyc = 1.5 * w / LE
check(abs(e['cycles'] - cyc) <= 1.0, 'ripple: %.1f cycles counted, %.1f in the window' % (e['cycles'], cyc))
check(e['uncertainty'] < A / 5, 'ripple: uncertainty %.2e well below the amplitude (many cycles averaged)'
      % e['uncertainty'])

# 3. drift: F0 (1 + g u) after the ramp. g W above the tolerance: no plateau, flagged, drift = g W / (1 + g u_m)
g = 1.0   # 1 per mm: 8 % over the 80 um of the admissible interval
f = [ramp(x) * (1 + g * max(x - 0.015, 0.0)) for x in u]
e = sf.estimate(u, f, fr, LE, FINE)
print('drift:', sf.describe(e))
check(not e['ok'] and e['status'] == 'no-plateau', 'drift: refused as no-plateau')
um = 0.5 * (e['window'][0] + e['window'][1])
w = e['window'][1] - e['window'][0]
exact = g * w / (1 + g * (um - 0.015))
check(abs(e['drift'] / exact - 1) < 1e-6, 'drift: %.5f = g W / F(u_mid) = %.5f' % (e['drift'], exact))
# a small drift (below the tolerance over the window) is accepted and its value is the mid-window value
g = 0.05
f = [ramp(x) * (1 + g * max(x - 0.015, 0.0)) for x in u]
e = sf.estimate(u, f, fr, LE, FINE)
um = 0.5 * (e['window'][0] + e['window'][1])
mid = F0 * (1 + g * (um - 0.015))
print('small drift:', sf.describe(e))
check(e['ok'] and abs(e['value'] / mid - 1) < 1e-9, 'small drift: value = F at mid-window (%.2e)' % (
    e['value'] / mid - 1))
check(abs(e['value'] / F0 - 1 - g * (um - 0.015)) <= e['uncertainty'] + 1e-12,
      'small drift: the stated uncertainty covers half the drift')

# 4. front leaving the fine region: fine region 0.09 mm, front leaves it (minus 2 l_e) at
#    u = 0.01 + (0.09 - 0.01) / 1.5 = 0.0633 mm; beyond, the force rises 4 % over 10 um (coarse mesh) and stays
fine = 0.09
u_leave = 0.01 + (fine - 2 * LE) / 1.5
f = [ramp(x) * (1 + 0.04 * min(max(x - u_leave, 0.0) / 0.01, 1.0)) for x in u]
e = sf.estimate(u, f, fr, LE, fine)
print('leaving:', sf.describe(e), e['flags'])
check(abs(e['window'][1] - u_leave) < 1e-9, 'leaving: window ends where the front leaves (%.5f = %.5f mm)' % (
    e['window'][1], u_leave))
# 1e-6: the window's end value is interpolated between the two samples around the kink at u_leave
check(e['ok'] and abs(e['value'] / F0 - 1) < 1e-6, 'leaving: the value is the plateau in the fine region (%.2e)'
      % (e['value'] / F0 - 1))
check(any('left' in x for x in e['flags']), 'leaving: flagged')
# the front history ends before the run does (frames every n increments): extrapolated, flagged the same way
e2 = sf.estimate(u, f, [p for p in fr if p[0] <= 0.05], LE, fine)
check(abs(e2['window'][1] - u_leave) < 1e-9 and e2['ok'], 'leaving: found from the extrapolated front too')
# the front never crossed 3 elements: refused
e = sf.estimate(u, [ramp(x) for x in u], [(x, 0.004 * x / 0.1) for x in u[::50]], LE, FINE)
check(not e['ok'] and e['status'] == 'front-not-in-fine-region', 'no front advance: refused (%s)' % e['status'])
# without a front history: flagged front-unknown (no refusal)
e = sf.estimate(u, [ramp(x) for x in u])
check(any('front-unknown' in x for x in e['flags']) and abs(e['value'] / F0 - 1) < 0.005,
      'no front history: value within the settling tolerance 0.5 %%, flagged front-unknown (%.2e)' % (
          e['value'] / F0 - 1))

# 5. curvature: a U-shaped history F0 (1 + C ((u - 60 um) / 40 um)^2) has no straight-line drift over the
#    admissible 20-100 um but is no plateau (a test on the line alone accepted it); over whole element periods the
#    fitted parabola is exact: curvature = c W^2 / 4 / mean, c = C F0 / (40 um)^2
C = 0.02
f = [ramp(x) * (1 + C * ((x - 0.06) / 0.04) ** 2) for x in u]
e = sf.estimate(u, f, fr, LE, FINE)
print('U-shape:', sf.describe(e))
check(not e['ok'] and e['status'] == 'no-plateau', 'U-shape: refused as no-plateau (%s)' % e['status'])
period = LE / 1.5
wu, wf = sf._cut(u, f, 0.02, 0.1)
st = sf.window_stats(wu, wf, period)
w = st['window'][1] - st['window'][0]
exact = C * F0 / 0.04 ** 2 * w * w / 4 / st['value']
check(abs(st['curvature'] / exact - 1) < 1e-6, 'U-shape: curvature %.6f = c W^2 / 4 / mean = %.6f' % (
    st['curvature'], exact))
check(abs(st['drift']) < 0.1 * C, 'U-shape: the straight line alone sees almost no drift over 20-100 um (%.4f)'
      % st['drift'])

# 6. quarters (the plateau check): F0 (1 + g (u - 15 um)), g = 0.05 per mm, pulled 100 um: the whole periods of
#    the last quarter (75-100 um; n = 7 periods of 3.33 um, ending at 100 um) against those of 50-75 um: for a line
#    the mean of the cycle means is the value at the mean of their centres, the quarter's end minus n P / 2
g = 0.05
f = [ramp(x) * (1 + g * max(x - 0.015, 0.0)) for x in u]
e = sf.estimate(u, f, fr, LE, FINE)
nq = int(0.025 / period)
q_exact = (1 + g * (0.1 - nq * period / 2 - 0.015)) / (1 + g * (0.075 - nq * period / 2 - 0.015)) - 1
check(e['quarter_change'] is not None and abs(e['quarter_change'] / q_exact - 1) < 1e-6,
      'quarters: last quarter against the one before %.6f = %.6f' % (e['quarter_change'] or 0, q_exact))
# the element ripple, measured as a period: one element crossed per ripple cycle
f = [ramp(x) * (1 + A * math.sin(2 * math.pi * max(0.0, 1.5 * (x - 0.01)) / LE)) for x in u]
e = sf.estimate(u, f, fr_r, LE, FINE)
check(abs(e['ripple_elements'] - 1) < 0.05, 'ripple: observed period %.3f elements of front advance (1)'
      % e['ripple_elements'])
check(abs(e['quarter_change']) < 1e-6, 'ripple: whole-period quarter means agree (%.2e)' % e['quarter_change'])
# the discretisation band: the sum of the parts' absolute values
parts = {'element formulation': -0.01, 'n_z': 0.004, 'l_e': 0.002}
check(abs(sf.band(parts) - 0.016) < 1e-15 and '1.60 %' in sf.describe_band(e, parts),
      'band: %s' % sf.describe_band(e, parts))

# 7. Richardson: F = 1 + 0.3 h^2 (h = 4, 2, 1): p = 2, F_inf = 1; uneven ratio (3, 2, 1) with p = 1.5;
#    oscillating differences give no order
fi, p, why = sf.richardson([4, 2, 1], [1 + 0.3 * h * h for h in (4, 2, 1)])
check(abs(p - 2) < 1e-12 and abs(fi - 1) < 1e-12, 'Richardson constant ratio: p = %.6f, F_inf = %.9f' % (p, fi))
fi, p, why = sf.richardson([1, 3, 2], [1 - 0.2 * h ** 1.5 for h in (1, 3, 2)])
check(abs(p - 1.5) < 1e-8 and abs(fi - 1) < 1e-8, 'Richardson uneven ratio: p = %.8f, F_inf = %.9f' % (p, fi))
fi, p, why = sf.richardson([4, 2, 1], [1.01, 0.99, 1.005])
check(p is None and 'oscillat' in why, 'Richardson oscillating: no order (%s)' % why)

fi, p, why = sf.richardson([4, 2, 1], [1.0, 1.001, 1.003])
check(p is None and 'asymptotic' in why, 'Richardson growing differences: no order (%s)' % why)

print('%d failure(s)' % len(BAD))
sys.exit(1 if BAD else 0)
