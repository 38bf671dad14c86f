#!/usr/bin/env python3
"""Minimum and range of the repeats in run_micro.sh's outputs: us per call per case and way, the rate of the
counted flops at the minimum, and whether every repeat gave one fingerprint (element) or checksum (Leonov)."""
import re
import sys


def element(path):
    times, flops, prints = {}, {}, {}
    who = None
    for line in open(path):
        if line.startswith('## repeat'):
            who = line.split()[-1]
            continue
        m = re.match(r'^(.{25})(.{16})\s+([0-9.]+)\s+([0-9.]+)\.\s+[0-9.]+\s+\S+\s+([0-9A-F]{16})', line)
        if not m:
            continue
        key = (m.group(1).strip(), m.group(2).strip() if who == 'new' else 'e9cbdfd')
        times.setdefault(key, []).append(float(m.group(3)))
        flops[key] = float(m.group(4))
        prints.setdefault(m.group(1).strip(), set()).add(m.group(5))
    out = ['| case | build, way | us per call, min [range] | flops per call | GFLOP/s at the min |', '|---|---|---|---|---|']
    for (case, way), ts in times.items():
        out.append('| %s | %s | %.3f [%.3f-%.3f] | %.0f | %.2f |' % (case, way, min(ts), min(ts), max(ts),
                                                                     flops[(case, way)], flops[(case, way)] / min(ts) / 1e3))
    out.append('')
    out.append('Fingerprints per case over every build, way and repeat: ' + '; '.join(
        '%s %s' % (c, ' '.join(sorted(p))) for c, p in prints.items()))
    return out


def leonov(path):
    times, sums = {}, {}
    who = None
    for line in open(path):
        if line.startswith('## repeat'):
            who = line.split()[-1]
            continue
        m = re.match(r'^(\w+) .*?:\s+([0-9.]+) us per call, checksum\s+(\S+)', line)
        if m:
            times.setdefault((m.group(1), who), []).append(float(m.group(2)))
            sums.setdefault(m.group(1), set()).add(m.group(3))
    out = ['| increment | build | us per call, min [range] |', '|---|---|---|']
    for (case, who), ts in times.items():
        out.append('| %s | %s | %.3f [%.3f-%.3f] |' % (case, 'e9cbdfd' if who == 'old' else 'new', min(ts), min(ts),
                                                        max(ts)))
    out.append('')
    out.append('Checksums per increment over both builds and every repeat: ' + '; '.join(
        '%s %s' % (c, ' '.join(sorted(s))) for c, s in sums.items()))
    return out


print('\n'.join(element(sys.argv[1]) + [''] + leonov(sys.argv[2])))
