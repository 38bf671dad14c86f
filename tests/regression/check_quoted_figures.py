#!/usr/bin/python3
"""Every figure quoted in docs/scenes.md, docs/performance.md and in the README's main-job section is found in a
report it cites, and the reports index (reports/README.md) covers every report folder (CTest quoted_figures; no
simulation, about a second).

  check_quoted_figures.py ROOT

Blocks: a paragraph, a list item or a table row of the checked text. A block cites a report by naming
`reports/NAME` (a folder of reports/), by a study name in backticks that is such a folder (`stmt-3d`), or by an
HTML comment `<!-- reports: NAME NAME -->` (for a block whose citation is a sentence away). Every decimal number of
a block (integers are counts, dates, section numbers) must then be

  * found in the files of a cited report (its .md, .csv except the curves, .txt, .log; numbers compared at the
    quoted precision, also as a percentage of a fraction, in um of a value in mm, in mm of one in um, in hours or
    minutes of one in seconds), or
  * a model input: a default or a case argument of tools/peel_deck.py and tools/peel_study.py, a constant of
    Table 1 or of the steel, or
  * a figure of the paper (PAPER below: its sections 2 and 6-9, Table 1, Figs. 6-14).

A block that cites no report may hold inputs and paper figures only. So a measured figure without a report, or one
that no longer matches its report, fails this test with the block's first line.

The index: a table whose first column is the folder (`reports/NAME/`, bench folders included), the second its status
(`current`, `record`, or `superseded by NAME`), the third what it backs, the fourth its command; every folder with a
report file is listed, every listed folder exists, a superseded folder names an existing one, and a folder whose
status is current carries a stamp (a line starting `Stamp:` with commit, program, command, date and machine) in its
report, unless the index says `(not stamped: ...)`.
"""
import csv
import os
import re
import sys

# The paper's own figures (decimals only): coating 30 um on 210 um of steel, Table 1 (E 1.25 GPa, nu 0.4, S_a
# 28.4, eta_0r 0.486 MPa s, tau_0 0.95 MPa, mu 0.047, G_r 28.2 MPa, r0 0.990), steel 210 GPa / 0.3, errors 0.5 %,
# exponent 1.34, 0.1 um/inc (100 nm/inc), delta/3 and delta/2 as 0.33 / 0.5, 3.7 mm and 1.0 mm of delamination
# (Figs. 12, 13), the LDF's delta = phi / (e T_max) = 3.679e-3 mm
PAPER = {'0.5', '1.34', '0.1', '3.7', '1.0', '1.25', '0.4', '28.4', '0.486', '0.95', '0.047', '28.2', '0.990',
         '0.99', '0.3', '0.33', '0.2', '2.0', '0.03', '0.21', '0.030', '0.210', '3.679e-3', '3.679'}

NUM = re.compile(r'(?<![\w.])[-+]?\d+\.\d+(?:[eE][-+]?\d+)?(?![\w.]*\d)')


def blocks(text):
    """(first line number, text) of the paragraphs, list items and table rows of markdown text (code blocks and
    headings skipped)."""
    out, cur, start, code = [], [], 0, False
    for i, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        if s.startswith('```'):
            code = not code
            if cur:
                out.append((start, '\n'.join(cur)))
                cur = []
            continue
        if code or s.startswith('#') or s.startswith('!['):
            if cur:
                out.append((start, '\n'.join(cur)))
                cur = []
            continue
        new = not s or s.startswith('|') or re.match(r'[-*] |\d+\. ', s)
        if new and cur:
            out.append((start, '\n'.join(cur)))
            cur = []
        if s and not re.match(r'\|[-| ]+\|$', s):
            if not cur:
                start = i
            cur.append(s)
            if s.startswith('|'):
                out.append((start, '\n'.join(cur)))
                cur = []
    if cur:
        out.append((start, '\n'.join(cur)))
    return out


def report_numbers(root, name, cache):
    """Every number in the files of reports/NAME (recursively, the curves CSVs excepted)."""
    if name not in cache:
        vals = set()
        for dp, _, files in os.walk(os.path.join(root, 'reports', name)):
            for f in files:
                if f.endswith('_curves.csv') or not f.endswith(('.md', '.csv', '.txt', '.log')):
                    continue
                with open(os.path.join(dp, f), errors='replace') as fh:
                    for m in re.finditer(r'[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?', fh.read()):
                        try:
                            vals.add(abs(float(m.group(0))))
                        except ValueError:
                            pass
        cache[name] = vals
    return cache[name]


def matches(token, values):
    """The quoted token (its decimals give the precision) equals a value of the report, as is or scaled."""
    x = abs(float(token))
    if 'e' in token.lower():
        return any(abs(v - x) <= 5e-4 * x for v in values)
    d = len(token.split('.')[1])
    tol = 0.5 * 10 ** -d * (1 + 1e-9) + 1e-12
    for v in values:
        for k in (1.0, 100.0, 1e3, 1e-3, 1.0 / 3600, 1.0 / 60):
            if abs(v * k - x) <= tol:
                return True
    return False


def inputs(root):
    """Decimal inputs of the scenes: the generator's defaults, Table 1, the steel, and every number in the case
    arguments of the studies."""
    from ldfcz_tools import peel_deck, peel_study  # the package is on PYTHONPATH (tests/CMakeLists.txt)
    vals = set()
    for act in peel_deck.parser()._actions:
        if isinstance(act.default, float):
            vals.add(act.default)
    vals.update(peel_deck.PET_TABLE1 + peel_deck.PET_ALT + list(peel_deck.STEEL))
    for cases in peel_study.studies(False).values():
        for c in cases:
            for a in list(c[1]) + list(c[3] if len(c) > 3 else []):
                try:
                    vals.add(float(a))
                except ValueError:
                    pass
    return {abs(v) for v in vals}


def is_input(token, ins):
    x = abs(float(token))
    if 'e' in token.lower():
        return any(abs(v * k - x) <= 5e-4 * x for v in ins for k in (1.0, 1e3))
    tol = 0.5 * 10 ** -len(token.split('.')[1]) * (1 + 1e-9)
    return any(abs(v * k - x) <= tol for v in ins for k in (1.0, 1e3))


def cited(block, folders):
    names = set(re.findall(r'reports/([A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.-]+)?)', block))
    for m in re.finditer(r'<!-- reports: ([^>]*)-->', block):
        names.update(m.group(1).split())
    names.update(n for n in re.findall(r'`([a-z0-9-]+)`', block) if n in folders)
    out = set()
    for n in names:
        n = n.rstrip('/.')
        parts = n.split('/')
        # reports/NAME/file or reports/bench/NAME/...: the deepest folder that exists
        for k in range(len(parts), 0, -1):
            if '/'.join(parts[:k]) in folders:
                out.add('/'.join(parts[:k]))
                break
    return out


def check_text(root, label, text, folders, ins, cache, bad):
    n_blocks = n_numbers = 0
    for line, b in blocks(text):
        toks = [m.group(0) for m in NUM.finditer(re.sub(r'<!--.*?-->', '', b))]
        if not toks:
            continue
        n_blocks += 1
        refs = cited(b, folders)
        values = set()
        for r in refs:
            values |= report_numbers(root, r, cache)
        for t in toks:
            n_numbers += 1
            t0 = t.lstrip('+-')
            if t0 in PAPER or is_input(t0, ins) or (refs and matches(t0, values)):
                continue
            bad.append('%s:%d: %s not found in %s (block: %s)' % (
                label, line, t, ', '.join('reports/' + r for r in sorted(refs)) or 'no cited report',
                b.splitlines()[0][:100]))
    return n_blocks, n_numbers


def readme_sections(text):
    """The README's main-job and peel sections (the rest is not this test's)."""
    keep, out = False, []
    for line in text.splitlines():
        if line.startswith('## '):
            keep = line.startswith('## The main job') or line.startswith('## Peel studies')
        if keep:
            out.append(line)
    return '\n'.join(out)


def report_folders(root):
    """Folders under reports/ that hold a file (top level and one level below bench/)."""
    out = set()
    base = os.path.join(root, 'reports')
    for d in sorted(os.listdir(base)):
        p = os.path.join(base, d)
        if not os.path.isdir(p):
            continue
        out.add(d)
        if d == 'bench':
            for e in sorted(os.listdir(p)):
                if os.path.isdir(os.path.join(p, e)):
                    out.add('bench/' + e)
    return out


def check_index(root, folders, bad):
    path = os.path.join(root, 'reports', 'README.md')
    if not os.path.exists(path):
        bad.append('reports/README.md: no index')
        return
    listed = {}
    for line in open(path):
        m = re.match(r'\|\s*`?reports/([^`|]+?)/?`?\s*\|\s*([^|]*)\|\s*([^|]*)\|\s*([^|]*)\|', line)
        if m:
            listed[m.group(1).strip().rstrip('/')] = (m.group(2).strip(), m.group(3).strip(), m.group(4).strip())
    for f in sorted(folders - set(listed)):
        bad.append('reports/README.md: folder reports/%s/ not in the index' % f)
    for f, (status, backs, cmd) in sorted(listed.items()):
        if f not in folders:
            bad.append('reports/README.md: reports/%s/ listed but absent' % f)
            continue
        m = re.match(r'superseded by `?reports/([A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.-]+)?)', status)
        if not (status.startswith(('current', 'record')) or m):
            bad.append('reports/README.md: reports/%s/: status %r is not current, record or superseded by NAME'
                       % (f, status))
        if m and m.group(1).rstrip('/') not in folders:
            bad.append('reports/README.md: reports/%s/ superseded by an absent folder %s' % (f, m.group(1)))
        if not backs or not cmd:
            bad.append('reports/README.md: reports/%s/: what it backs and its command are required' % f)
        if status.startswith('current') and 'not stamped' not in status:
            stamped = False
            for dp, _, files in os.walk(os.path.join(root, 'reports', f)):
                for x in files:
                    if x.endswith('.md'):
                        for ln in open(os.path.join(dp, x), errors='replace'):
                            if ln.startswith('Stamp:') and all(k in ln for k in ('commit', 'program', 'command',
                                                                                  'machine')):
                                stamped = True
            if not stamped:
                bad.append('reports/README.md: reports/%s/ is current but its report has no Stamp: line' % f)


def main(argv):
    root = os.path.abspath(argv[1])
    folders = report_folders(root)
    ins = inputs(root)
    cache, bad = {}, []
    nb = nn = 0
    for doc in ('scenes.md', 'performance.md'):
        with open(os.path.join(root, 'docs', doc)) as fh:
            b, n = check_text(root, 'docs/' + doc, fh.read(), folders, ins, cache, bad)
            nb, nn = nb + b, nn + n
    with open(os.path.join(root, 'README.md')) as fh:
        b, n = check_text(root, 'README.md', readme_sections(fh.read()), folders, ins, cache, bad)
        nb, nn = nb + b, nn + n
    check_index(root, folders, bad)
    for x in bad:
        print('FAIL: ' + x)
    print('check_quoted_figures: %d numbers in %d blocks, %d report folders: %s' % (
        nn, nb, len(folders), 'FAILED (%d)' % len(bad) if bad else 'passed'))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
