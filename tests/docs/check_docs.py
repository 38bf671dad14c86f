#!/usr/bin/env python3
"""The documentation's own checks (CTest label `docs`; docs/testing.md).

  check_docs.py links ROOT                  every relative link of README.md, docs/*.md and reports/README.md
                                            resolves (file, and #anchor as MkDocs and GitHub slug the heading);
                                            every page of docs/ is reachable from README.md by links and listed in
                                            mkdocs.yml's nav, and every nav entry exists
  check_docs.py options ROOT --exe LDFCZ    every option of an `ldfcz ...` command line in README.md and docs/
                                            exists in `ldfcz --help`; docs/host.md's option table lists exactly
                                            the options of `ldfcz --help`
  check_docs.py mkdocs ROOT --out DIR       `mkdocs build --strict` into DIR (exit 77, skipped, without mkdocs)
  check_docs.py commands ROOT --exe LDFCZ --out DIR
                                            the README's install PATH line, first deck, worked user-UMAT example and
                                            picture run as written in DIR (repository folders linked in, build/bin
                                            the tested program's folder); their results against what the README
                                            says and against the closed forms

Prints PASS or FAIL lines; exit status 1 on any failure.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import unicodedata

LINK = re.compile(r'!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+"[^"]*")?\)')
FENCE = re.compile(r'^\s*(```|~~~)')


def fail(msg, bad):
    bad.append(msg)
    print('FAIL: ' + msg)


def prose_lines(text):
    """(line number, line) outside fenced code blocks, with inline code spans blanked."""
    fence = False
    for i, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            fence = not fence
            continue
        if not fence:
            yield i, re.sub(r'`[^`]*`', lambda m: ' ' * len(m.group(0)), line)


def code_segments(text):
    """The shell text of a page: every line of its fenced code blocks and every inline code span."""
    fence = False
    for line in text.splitlines():
        if FENCE.match(line):
            fence = not fence
            continue
        if fence:
            yield line
        else:
            for m in re.finditer(r'`([^`]+)`', line):
                yield m.group(1)


def heading_text(line):
    text = line.lstrip('#').strip()
    text = re.sub(r'!?\[([^\]]*)\]\([^)]*\)', r'\1', text)  # a link in a heading: its text
    return text.replace('`', '')


def slug_mkdocs(text):
    """Python-Markdown's toc slugify (MkDocs' default): ASCII, word characters, spaces and hyphens."""
    text = unicodedata.normalize('NFKD', text).encode('ascii', 'ignore').decode('ascii')
    text = re.sub(r'[^\w\s-]', '', text.replace('*', '')).strip().lower()
    return re.sub(r'[-\s]+', '-', text)


def slug_github(text):
    """GitHub's heading anchors: lower case, punctuation other than - and _ dropped, each space a hyphen."""
    text = text.replace('*', '').lower()
    text = re.sub(r'[^\w\- ]', '', text)
    return text.replace(' ', '-')


def anchors(path, cache):
    """{'mkdocs': set, 'github': set} of a Markdown file's heading anchors (duplicates numbered as each does)."""
    if path not in cache:
        out = {'mkdocs': set(), 'github': set()}
        seen = {'mkdocs': {}, 'github': {}}
        fence = False
        with open(path, encoding='utf-8') as fh:
            for line in fh:
                if FENCE.match(line):
                    fence = not fence
                    continue
                if fence or not re.match(r'#{1,6} ', line):
                    continue
                text = heading_text(line)
                for kind, slug, sep in (('mkdocs', slug_mkdocs(text), '_'), ('github', slug_github(text), '-')):
                    n = seen[kind].get(slug, 0)
                    seen[kind][slug] = n + 1
                    out[kind].add(slug if n == 0 else '%s%s%d' % (slug, sep, n))
        cache[path] = out
    return cache[path]


def md_links(root, rel):
    """(line, target) of the relative links of a Markdown file (URLs and mail addresses left out)."""
    with open(os.path.join(root, rel), encoding='utf-8') as fh:
        text = fh.read()
    for i, line in prose_lines(text):
        for m in LINK.finditer(line):
            target = m.group(1)
            if re.match(r'[A-Za-z][A-Za-z0-9+.-]*:', target):
                continue
            yield i, target


def resolve(root, rel, target):
    """(absolute path or None, fragment) of a link target of the file rel."""
    path, _, frag = target.partition('#')
    if not path:
        return os.path.join(root, rel), frag
    if path.startswith('/'):
        return None, frag
    return os.path.normpath(os.path.join(root, os.path.dirname(rel), path)), frag


def checked_files(root):
    docs = sorted('docs/' + f for f in os.listdir(os.path.join(root, 'docs')) if f.endswith('.md'))
    return ['README.md'] + docs + ['reports/README.md']


def check_links(root, bad):
    cache, n = {}, 0
    docs_dir = os.path.join(root, 'docs')
    for rel in checked_files(root):
        for line, target in md_links(root, rel):
            n += 1
            full, frag = resolve(root, rel, target)
            where = '%s:%d: link %s' % (rel, line, target)
            if full is None or not full.startswith(root + os.sep):
                fail(where + ': not a path inside the repository', bad)
                continue
            if not os.path.exists(full):
                fail(where + ': %s does not exist' % os.path.relpath(full, root), bad)
                continue
            if not frag:
                continue
            if os.path.isdir(full) or not full.endswith('.md'):
                fail(where + ': an anchor on a file that is not a Markdown page', bad)
                continue
            a = anchors(full, cache)
            # GitHub shows every page; MkDocs renders the pages of docs/ (it copies the others as they are)
            kinds = ('github', 'mkdocs') if full.startswith(docs_dir + os.sep) else ('github',)
            for kind in kinds:
                if frag not in a[kind]:
                    fail(where + ': no heading with the %s anchor #%s in %s' % (
                        'MkDocs' if kind == 'mkdocs' else 'GitHub', frag, os.path.relpath(full, root)), bad)
    print('links: %d relative links in %d files checked' % (n, len(checked_files(root))))


def nav_pages(root):
    """The pages mkdocs.yml's nav lists (its `- title: page.md` and `- page.md` entries)."""
    pages, in_nav = [], False
    with open(os.path.join(root, 'mkdocs.yml'), encoding='utf-8') as fh:
        for line in fh:
            if re.match(r'nav:\s*$', line):
                in_nav = True
                continue
            if in_nav and re.match(r'\S', line):
                break
            if in_nav:
                m = re.search(r'(?:^\s*-\s*|:\s*)"?([\w./-]+\.md)"?\s*$', line)
                if m:
                    pages.append(m.group(1))
    return pages


def check_reach(root, bad):
    """Every docs page reachable from README.md by relative links to Markdown files, and in the nav."""
    seen, todo = {'README.md'}, ['README.md']
    while todo:
        rel = todo.pop()
        for _, target in md_links(root, rel):
            full, _ = resolve(root, rel, target)
            if full and full.endswith('.md') and os.path.isfile(full) and full.startswith(root + os.sep):
                r = os.path.relpath(full, root)
                if r not in seen:
                    seen.add(r)
                    todo.append(r)
    docs = [f for f in checked_files(root) if f.startswith('docs/')]
    for d in docs:
        if d not in seen:
            fail('%s: not reachable from README.md by links' % d, bad)
    nav = nav_pages(root)
    if not nav:
        fail('mkdocs.yml: no nav found', bad)
    for p in nav:
        if not os.path.isfile(os.path.join(root, 'docs', p)):
            fail('mkdocs.yml: nav lists %s, which is not in docs/' % p, bad)
    for d in docs:
        if d[len('docs/'):] not in nav:
            fail('mkdocs.yml: %s is not in the nav' % d, bad)
    if len(set(nav)) != len(nav):
        fail('mkdocs.yml: a page is listed twice in the nav', bad)
    print('reach: %d docs pages, %d reachable from README.md, %d in the nav' % (
        len(docs), sum(d in seen for d in docs), len(nav)))


def help_options(exe):
    text = subprocess.run([exe, '--help'], capture_output=True, text=True, timeout=60).stdout
    longs = set(re.findall(r'(?<![\w-])(--[a-z][a-z0-9-]*)', text))
    shorts = set(re.findall(r'(?<![\w-])(-[a-zA-Z])(?=[,\s])', text))
    return longs | shorts


def command_options(segment):
    """The options of every `ldfcz ...` command line in a code segment (up to a shell separator or comment)."""
    out = []
    segment = re.sub(r'<[^>]*>', 'X', segment.split('#')[0])  # placeholders such as <build>/bin/ldfcz
    for part in re.split(r'[;|&()]+', segment):
        toks = part.split()
        # the program is the command: a word ending in ldfcz that is not the value of another program's option
        starts = [i for i, t in enumerate(toks) if re.match(r'(?:[\w.${}-]*/)*ldfcz$', t)
                  and (i == 0 or not toks[i - 1].startswith('-'))]
        for tok in toks[starts[0] + 1:] if starts else []:
            tok = tok.strip('[]')
            if re.match(r'--[a-z]', tok) or re.match(r'-[a-zA-Z]$', tok):
                out.append(tok.split('=')[0])
    return out


def check_options(root, exe, bad):
    known = help_options(exe)
    n = 0
    for rel in [f for f in checked_files(root) if f != 'reports/README.md']:
        with open(os.path.join(root, rel), encoding='utf-8') as fh:
            text = fh.read()
        for seg in code_segments(text):
            for opt in command_options(seg):
                n += 1
                if opt not in known:
                    fail('%s: `ldfcz ... %s` (in `%s`): not an option of ldfcz --help' % (rel, opt, seg.strip()[:80]),
                         bad)
    # docs/host.md's option table against --help, both ways
    table = set()
    with open(os.path.join(root, 'docs', 'host.md'), encoding='utf-8') as fh:
        text = fh.read()
    sec = text.split('\n## Options\n', 1)
    if len(sec) != 2:
        fail('docs/host.md: no "## Options" section', bad)
    else:
        for line in sec[1].split('\n## ', 1)[0].splitlines():
            m = re.match(r'\|\s*([^|]+)\|', line)
            if m and '`' in m.group(1):
                for code in re.findall(r'`([^`]+)`', m.group(1)):
                    table.update(t for t in re.findall(r'(?<![\w-])(--?[a-zA-Z][a-z0-9-]*)', code))
        longs = {o for o in known if o.startswith('--')}
        for o in sorted(longs - table):
            fail('docs/host.md "Options": ldfcz --help has %s, the table does not' % o, bad)
        for o in sorted(table - known):
            fail('docs/host.md "Options": the table has %s, ldfcz --help does not' % o, bad)
    print('options: %d options on ldfcz command lines checked, %d options in --help, %d in docs/host.md\'s table' % (
        n, len(known), len(table)))


def find_mkdocs():
    """The command that runs MkDocs: this Python's module, else Debian's /usr/bin/mkdocs, else None."""
    try:
        import mkdocs  # noqa: F401
        return [sys.executable, '-m', 'mkdocs']
    except ImportError:
        exe = shutil.which('mkdocs')
        return [exe] if exe else None


def run_mkdocs(root, out):
    cmd = find_mkdocs()
    if not cmd:
        print('SKIP: mkdocs is not installed (Debian 12: apt-get install mkdocs; tools/setup.sh installs it)')
        return 77
    shutil.rmtree(out, ignore_errors=True)
    p = subprocess.run(cmd + ['build', '--strict', '--config-file', os.path.join(root, 'mkdocs.yml'),
                              '--site-dir', out], capture_output=True, text=True, timeout=300, cwd=root)
    print(p.stdout + p.stderr)
    if p.returncode != 0:
        print('FAIL: mkdocs build --strict: exit status %d' % p.returncode)
        return 1
    missing = [f for f in ('index.html', 'first-deck.html', 'host.html') if not os.path.isfile(os.path.join(out, f))]
    if missing:
        print('FAIL: mkdocs wrote no %s' % ', '.join(missing))
        return 1
    print('PASS: mkdocs build --strict (%s)' % out)
    return 0


def readme_blocks(root):
    """The fenced sh blocks of README.md, as lists of lines."""
    blocks, cur = [], None
    with open(os.path.join(root, 'README.md'), encoding='utf-8') as fh:
        for line in fh:
            if cur is None and re.match(r'```sh\s*$', line):
                cur = []
            elif cur is not None and line.startswith('```'):
                blocks.append(cur)
                cur = None
            elif cur is not None:
                cur.append(line.rstrip('\n'))
    return blocks


def block_with(blocks, needle, bad):
    found = [b for b in blocks if any(needle in ln for ln in b)]
    if not found:
        fail('README.md: no sh block with %s' % needle, bad)
        return []
    return found[0]


def last_row(path):
    with open(path) as fh:
        return list(csv.DictReader(fh))


def check_commands(root, exe, out, bad):
    """Run the README's commands as a reader would, in a scratch copy of the repository's layout."""
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(os.path.join(out, 'build'))
    for d in ('decks', 'tests', 'tools'):
        os.symlink(os.path.join(root, d), os.path.join(out, d))
    os.symlink(os.path.dirname(os.path.abspath(exe)), os.path.join(out, 'build', 'bin'))
    blocks = readme_blocks(root)
    path_line = [ln for ln in block_with(blocks, 'export PATH=', bad) if ln.startswith('export PATH=')]
    script = path_line[:1] + block_with(blocks, 'decks/first/two_blocks.inp', bad) + \
        block_with(blocks, 'decks/first/block_umat.inp', bad)
    picture = block_with(blocks, 'render_frame.py', bad)
    with open(os.path.join(root, 'README.md'), encoding='utf-8') as fh:
        readme = fh.read()
    env = dict(os.environ, PATH=os.environ.get('PATH', '/usr/bin:/bin'))
    print('running in %s:\n  %s' % (out, '\n  '.join(script)))
    p = subprocess.run(['bash', '-e', '-c', '\n'.join(script)], cwd=out, env=env, capture_output=True, text=True,
                       timeout=300)
    if p.returncode != 0:
        fail('README commands: exit status %d\n%s' % (p.returncode, (p.stdout + p.stderr)[-3000:]), bad)
        return
    # the first deck: the largest force T_max A = 20 N (paper Eq. 20), as many digits as the README quotes
    m = re.search(r'this run: ([0-9.]+) N in `run/two_blocks.csv`', readme)
    rows = last_row(os.path.join(out, 'run', 'two_blocks.csv'))
    fmax = max(float(r['TOP.RF3']) for r in rows)
    if not m:
        fail('README.md: the first deck\'s quoted peak force ("this run: X N in `run/two_blocks.csv`") not found', bad)
    else:
        q = m.group(1)
        tol = 0.5 * 10 ** -len(q.split('.')[1])
        if abs(fmax - float(q)) > tol:
            fail('first deck: largest TOP.RF3 %.6f N, the README says %s' % (fmax, q), bad)
    # the discretisation of the LDF law reaches its peak within the load step: T_max = 20 MPa on 1 mm^2 to 0.1 %
    if abs(fmax - 20.0) > 0.02:
        fail('first deck: largest force %.5f N, T_max A = 20 N' % fmax, bad)
    # the user UMAT: neo-Hooke with lambda = 0 keeps the width, F = mu (l^2 - 1)/l at l = 1.1, mu = 100 MPa; the
    # tangent is exact and Newton converges to the residual tolerance, far below 1e-6 relative
    rows = last_row(os.path.join(out, 'run', 'block_umat.csv'))
    f, u = float(rows[-1]['X1.RF1']), float(rows[-1]['X1.U1'])
    lam = 1.0 + u
    exact = 100.0 * (lam * lam - 1.0) / lam
    if abs(u - 0.1) > 1e-12 or abs(f - exact) > 1e-6 * exact:
        fail('user UMAT example: X1.RF1 = %.8f N at u = %g, closed form %.8f N' % (f, u, exact), bad)
    m = re.search(r'mu \(l\^2 - 1\)/l, ([0-9.]+) N at l = 1\.1', readme)
    if not m or abs(float(m.group(1)) - f) > 0.5 * 10 ** -len(m.group(1).split('.')[1]):
        fail('README.md: the user UMAT example\'s quoted force (%s) is not the run\'s %.6f N' % (
            m.group(1) if m else 'not found', f), bad)
    log = open(os.path.join(out, 'run', 'block_umat.log'), errors='replace').read()
    if 'user_umat_neohooke' not in log:
        fail('user UMAT example: run/block_umat.log does not name the user routine', bad)
    print('README commands: first deck peak %.4f N, user UMAT %.6f N (closed form %.6f)' % (fmax, f, exact))
    # the picture, where VTK is there (test deck_frames checks pictures in depth)
    vtk = subprocess.run(['/usr/bin/python3', '-c', 'import vtk'], capture_output=True).returncode == 0
    if not vtk:
        print('SKIP: the README\'s picture: /usr/bin/python3 has no VTK (python3-vtk9)')
        return
    for line in picture:
        cmd = line.split('#')[0].strip()
        if not cmd:
            continue
        p = subprocess.run(['bash', '-e', '-c', cmd], cwd=out, capture_output=True, text=True, timeout=120)
        png = re.search(r'# (run/\S+\.png)', line)
        if p.returncode != 0:
            fail('README picture `%s`: exit status %d: %s' % (cmd, p.returncode, (p.stdout + p.stderr)[-500:]), bad)
        elif png and not os.path.getsize(os.path.join(out, png.group(1))) > 1000:
            fail('README picture `%s`: %s missing or empty' % (cmd, png.group(1)), bad)
    print('README picture commands: %d run' % len([ln for ln in picture if ln.split('#')[0].strip()]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('what', choices=('links', 'options', 'mkdocs', 'commands'))
    ap.add_argument('root')
    ap.add_argument('--exe')
    ap.add_argument('--out')
    a = ap.parse_args()
    root = os.path.realpath(a.root)
    bad = []
    if a.what == 'links':
        check_links(root, bad)
        check_reach(root, bad)
    elif a.what == 'options':
        check_options(root, a.exe, bad)
    elif a.what == 'mkdocs':
        return run_mkdocs(root, a.out)
    else:
        check_commands(root, a.exe, a.out, bad)
    print('FAIL (%d)' % len(bad) if bad else 'PASS')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
