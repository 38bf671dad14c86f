#!/usr/bin/env python3
"""LOAD.RF1 of two window runs at the same step time (the earlier end of the two), interpolated linearly between
the CSV rows that bracket it; prints both and the relative difference."""
import sys
def rows(p):
    L = open(p).read().strip().split('\n')
    h = L[0].split(',')
    it, ir = h.index('step_time'), h.index('LOAD.RF1')
    return [(float(x.split(',')[it]), float(x.split(',')[ir])) for x in L[1:]]
def at(r, t):
    for k in range(1, len(r)):
        if r[k - 1][0] <= t <= r[k][0]:
            (t0, f0), (t1, f1) = r[k - 1], r[k]
            return f0 + (t - t0) / (t1 - t0) * (f1 - f0) if t1 > t0 else f1
a, b = rows(sys.argv[1]), rows(sys.argv[2])
t = min(a[-1][0], b[-1][0])
fa, fb = at(a, t), at(b, t)
print('step time %.4f: RF1 %.9e (%s) %.9e (%s), relative difference %.2e' % (t, fa, sys.argv[1], fb, sys.argv[2], (fb - fa) / fa))
