"""MkDocs hook of the documentation site (mkdocs.yml): links from docs/ to the repository's other files.

The pages link to files outside docs/ (README.md, reports/, decks/, tools/, tests/), which MkDocs 1.4 cannot resolve
and warns about (so `mkdocs build --strict` would fail). This hook adds every such file that exists to the site as a
static file under _repo/ (a folder's link goes to its README.md) and points the links there. A link whose target
does not exist is left alone, so MkDocs still warns about it and --strict fails; tests/docs/check_docs.py checks
every link of the README, docs/ and reports/README.md, anchors included, with or without MkDocs.
"""
import os
import re

from mkdocs.structure.files import File

LINK = re.compile(r'(!?\[[^\]]*\]\()([^)\s]+)(\))')


class RepoFile(File):
    """A file of the repository outside docs/, copied as it is (a Markdown file too: it is not a page)."""

    def __init__(self, rel, root, config):
        super().__init__('_repo/' + rel, config['docs_dir'], config['site_dir'], config['use_directory_urls'])
        self.abs_src_path = os.path.join(root, rel)

    def is_documentation_page(self):
        return False


def _outside(target, page_dir, docs, root):
    """The target's path relative to the repository's root when it is an existing file outside docs/, else None."""
    if re.match(r'[A-Za-z][A-Za-z0-9+.-]*:', target) or target.startswith(('#', '/')):
        return None
    full = os.path.normpath(os.path.join(page_dir, target.partition('#')[0]))
    if full == docs or full.startswith(docs + os.sep) or not full.startswith(root + os.sep):
        return None
    if os.path.isdir(full) and os.path.isfile(os.path.join(full, 'README.md')):
        full = os.path.join(full, 'README.md')
    return os.path.relpath(full, root).replace(os.sep, '/') if os.path.isfile(full) else None


def _links(markdown):
    """(line index, match) of the links outside fenced code blocks."""
    fence = False
    for i, line in enumerate(markdown.split('\n')):
        if line.lstrip().startswith('```'):
            fence = not fence
        elif not fence:
            for m in LINK.finditer(line):
                yield i, m


def _dirs(config):
    docs = os.path.realpath(config['docs_dir'])
    return docs, os.path.dirname(docs)


def on_files(files, config, **kwargs):
    docs, root = _dirs(config)
    wanted = set()
    for f in files.documentation_pages():
        with open(f.abs_src_path, encoding='utf-8') as fh:
            text = fh.read()
        page_dir = os.path.dirname(f.abs_src_path)
        for _, m in _links(text):
            rel = _outside(m.group(2), page_dir, docs, root)
            if rel:
                wanted.add(rel)
    for rel in sorted(wanted):
        files.append(RepoFile(rel, root, config))
    return files


def on_page_markdown(markdown, page, config, files, **kwargs):
    docs, root = _dirs(config)
    page_dir = os.path.dirname(page.file.abs_src_path)
    depth = page.file.src_path.replace(os.sep, '/').count('/')
    lines = markdown.split('\n')
    for i, m in reversed(list(_links(markdown))):
        rel = _outside(m.group(2), page_dir, docs, root)
        if rel:
            frag = m.group(2).partition('#')[2]
            new = m.group(1) + '../' * depth + '_repo/' + rel + ('#' + frag if frag else '') + m.group(3)
            lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
    return '\n'.join(lines)
