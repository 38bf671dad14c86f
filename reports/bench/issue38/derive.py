#!/usr/bin/env python3
"""The derived figures of reports/bench/issue38/README.md from the window tables beside it (window_early.md,
window_late.md, written by benchmarks/bench_window.py --own-base) and the base runs' end points given below (the
step time = um of pull of each base run's last CSV row, printed by bench_window's runs in their base_LABEL/app.csv):
CPU and wall seconds per um of pull per run, their means per build and the ratio e9cbdfd / perf, and the estimate
of the time to 1.0 mm of delamination (e9cbdfd's measured 4288 s, reports/bench/alternate/report.md, divided by
the ratio). Python standard library only."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BASE_END = {'early': {'e9cbdfd': 34.53900165729291, 'perf': 33.30440803645892},
            'late': {'e9cbdfd': 422.2683188349310, 'perf': 425.1199072122456}}
E9_TO_1MM = 4288.0   # s, 1 process x 2 threads, reports/bench/alternate/report.md


def rows(path):
    out = []
    for line in open(path):
        c = [x.strip() for x in line.strip().strip('|').split('|')]
        if len(c) == 16 and c[1].isdigit():
            out.append({'label': c[0], 'round': int(c[1]), 'cpu': float(c[7]), 'wall': float(c[8]), 'end': float(c[14])})
    return out


def main():
    print('| window | build | round | pull (um) | CPU s per um | wall s per um |')
    print('|---|---|---|---|---|---|')
    ratios = {}
    for pos in ('early', 'late'):
        per = {}
        for r in rows(os.path.join(HERE, 'window_%s.md' % pos)):
            pull = r['end'] - BASE_END[pos][r['label']]
            per.setdefault(r['label'], []).append((r['cpu'] / pull, r['wall'] / pull))
            print('| %s | %s | %d | %.3f | %.3f | %.3f |' % (pos, r['label'], r['round'], pull, r['cpu'] / pull, r['wall'] / pull))
        mean = {k: (sum(x[0] for x in v) / len(v), sum(x[1] for x in v) / len(v)) for k, v in per.items()}
        ratios[pos] = (mean['e9cbdfd'][0] / mean['perf'][0], mean['e9cbdfd'][1] / mean['perf'][1])
        print('| %s | ratio e9cbdfd / perf (means) | | | %.2f | %.2f |' % (pos, ratios[pos][0], ratios[pos][1]))
    lo = min(r[0] for r in ratios.values())
    hi = max(r[0] for r in ratios.values())
    print()
    print('Estimate to 1.0 mm (CPU ratio %.2f-%.2f applied to e9cbdfd\'s %.0f s): %.0f-%.0f s = %.2f-%.2f h; '
          'the 2x goal needs %.0f s, the 3.6x goal %.0f s.' % (lo, hi, E9_TO_1MM, E9_TO_1MM / hi, E9_TO_1MM / lo,
                                                            E9_TO_1MM / hi / 3600, E9_TO_1MM / lo / 3600,
                                                            E9_TO_1MM / 2, E9_TO_1MM / 3.6))


if __name__ == '__main__':
    sys.exit(main())
