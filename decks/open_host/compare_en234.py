#!/usr/bin/env python3
"""The LDF element in an open host against ldfcz: EN234_FEA running en234_two_blocks.in with the UEL drop-in and
ldfcz_open_host_utils.f, and ldfcz running its twin two_blocks_force.inp (docs/uel.md, "Open hosts").

  compare_en234.py LDFCZ_OUT/two_blocks_force.csv EN234_RUN/en234_two_blocks_dof.dat

At each of the 10 force levels F (0.1 .. 1.0 of 18 N = 0.9 T_max on the unit area) prints the interface opening
(glue top minus glue bottom U3) and the top face's U3 of both runs, and the closed-form opening of T(Delta) = F/A
(Eq. 20, Newton on the branch before the peak); then the largest relative differences.
"""
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
lines = open(sys.argv[2]).read().splitlines()
en = []
i = 0
while i < len(lines):
    if lines[i].startswith(' ZONE') and 'I=   16' in lines[i]:
        en.append([list(map(float, l.split())) for l in lines[i + 1:i + 17]])
        i += 17
    else:
        i += 1
phi, d = 0.2, 3.679e-3
k = phi / d ** 2
def delta_of(T):
    x = 1e-4
    for _ in range(60):
        x -= (k * x * math.exp(-x / d) - T) / (k * (1 - x / d) * math.exp(-x / d))
    return x
u3 = lambda v, n: v[n - 1][5] + v[n - 1][8]     # EN234 prints the increment (DU3) and the start value (U3)
wo = wt = wc = wl = 0
for r, v in zip(rows, en):
    t = float(r['total_time']); F = 18 * t
    op_l = float(r['GLUE_TOP.U3']) - float(r['GLUE_BOTTOM.U3'])
    op_e = u3(v, 9) - u3(v, 5)
    top_l, top_e = float(r['TOP.U3']), u3(v, 13)
    ex = delta_of(F)
    wo = max(wo, abs(op_e - op_l) / op_l); wt = max(wt, abs(top_e - top_l) / top_l)
    wc = max(wc, abs(op_e - ex) / ex); wl = max(wl, abs(op_l - ex) / ex)
    print("%.1f F=%5.2f N  opening ldfcz %.10e  EN234 %.10e  closed form %.10e  top U3 ldfcz %.10e  EN234 %.10e"
          % (t, F, op_l, op_e, ex, top_l, top_e))
print("%d states; largest relative difference: opening EN234 vs ldfcz %.2e, top U3 %.2e; opening vs closed form:"
      " EN234 %.2e, ldfcz %.2e" % (len(en), wo, wt, wc, wl))
