#!/usr/bin/env python3
"""Every CTest test of a build carries exactly one area label and otherwise only speed labels, both from the sets
that docs/testing.md defines ("Labels": a table row per label, `| `name` | area |` or `| `name` | speed |`).

  check_labels.py --ctest CTEST --build BUILD_DIR --doc docs/testing.md

Reads the tests with `ctest --show-only=json-v1` (nothing runs). Fails naming each test without an area label, with
two, or with a label the documentation does not define, and when the documentation defines no label of a kind.
Python standard library only.
"""
import argparse
import json
import re
import subprocess
import sys


def documented_labels(doc):
    """{'area': set, 'speed': set} from the table rows of docs/testing.md."""
    kinds = {'area': set(), 'speed': set()}
    with open(doc, encoding='utf-8') as f:
        for line in f:
            m = re.match(r'\|\s*`([a-z0-9_-]+)`\s*\|\s*(area|speed)\s*\|', line)
            if m:
                kinds[m.group(2)].add(m.group(1))
    return kinds


def test_labels(ctest, build):
    """[(test name, [labels])] of the build."""
    p = subprocess.run([ctest, '--test-dir', build, '--show-only=json-v1'], capture_output=True, text=True,
                       timeout=120)
    if p.returncode != 0:
        sys.exit('FAIL: ctest --show-only failed:\n' + p.stdout + p.stderr)
    tests = []
    for t in json.loads(p.stdout)['tests']:
        labels = []
        for prop in t.get('properties', []):
            if prop['name'] == 'LABELS':
                labels = prop['value']
        tests.append((t['name'], labels))
    return tests


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--ctest', default='ctest')
    ap.add_argument('--build', required=True)
    ap.add_argument('--doc', required=True)
    a = ap.parse_args()
    kinds = documented_labels(a.doc)
    if not kinds['area'] or not kinds['speed']:
        sys.exit('FAIL: %s defines no %s labels (rows "| `name` | area |" / "| `name` | speed |")' %
                 (a.doc, 'area' if not kinds['area'] else 'speed'))
    problems = []
    tests = test_labels(a.ctest, a.build)
    for name, labels in tests:
        areas = [x for x in labels if x in kinds['area']]
        unknown = [x for x in labels if x not in kinds['area'] and x not in kinds['speed']]
        if len(areas) != 1:
            problems.append('%s: %d area labels %s (exactly one of %s)' % (
                name, len(areas), areas, ', '.join(sorted(kinds['area']))))
        if unknown:
            problems.append('%s: labels not defined in %s: %s' % (name, a.doc, ', '.join(unknown)))
    if problems:
        print('FAIL: %d of %d tests:\n  ' % (len(problems), len(tests)) + '\n  '.join(problems))
        sys.exit(1)
    used = sorted({x for _, labels in tests for x in labels})
    print('PASS: %d tests, each with one area label; labels used: %s' % (len(tests), ', '.join(used)))


if __name__ == '__main__':
    main()
