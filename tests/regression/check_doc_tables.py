#!/usr/bin/env python3
"""The documentation's generated tables against the declarations they come from.

  check_doc_tables.py --tables LDFCZ_DOC_TABLES --docs DOCS_DIR [--write]

docs/elements.md holds the element type table and docs/host.md the output-variable table between the lines
  <!-- ldfcz_doc_tables WHAT: ... -->   and   <!-- end ldfcz_doc_tables WHAT -->
The text between them must be what `ldfcz_doc_tables WHAT` writes from the element catalogue
(host/elements/element_catalog.f90) and the output registry (host/output/output_registry.f90), line for line: a
type or variable added, removed or changed on one side only fails the test. --write puts the program's tables
into the documents instead (after a change of the catalogue or the registry).
"""
import argparse
import os
import subprocess
import sys

TABLES = (("elements", "elements.md"), ("outputs", "host.md"))


def block(text, what, path):
    """Start and end line indices of the generated block of `what` in the document's lines."""
    begin = [i for i, line in enumerate(text) if line.startswith("<!-- ldfcz_doc_tables %s:" % what)]
    end = [i for i, line in enumerate(text) if line.strip() == "<!-- end ldfcz_doc_tables %s -->" % what]
    if len(begin) != 1 or len(end) != 1 or end[0] < begin[0]:
        print("FAIL: %s: no single block '<!-- ldfcz_doc_tables %s: ... -->' ... '<!-- end ldfcz_doc_tables %s -->'"
              % (path, what, what))
        sys.exit(1)
    return begin[0], end[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tables", required=True)
    ap.add_argument("--docs", required=True)
    ap.add_argument("--write", action="store_true")
    a = ap.parse_args()
    bad = 0
    for what, doc in TABLES:
        path = os.path.join(a.docs, doc)
        want = subprocess.run([a.tables, what], capture_output=True, text=True, check=True).stdout.splitlines()
        with open(path) as f:
            text = f.read().splitlines()
        b, e = block(text, what, path)
        got = text[b + 1:e]
        if a.write:
            text[b + 1:e] = want
            with open(path, "w") as f:
                f.write("\n".join(text) + "\n")
            print("%s: %s table written (%d rows)" % (path, what, len(want) - 2))
            continue
        if got == want:
            print("%s: %s table as generated (%d rows): ok" % (path, what, len(want) - 2))
            continue
        bad += 1
        print("FAIL: %s: the %s table differs from `ldfcz_doc_tables %s`:" % (path, what, what))
        for k in range(max(len(got), len(want))):
            g = got[k] if k < len(got) else "(none)"
            w = want[k] if k < len(want) else "(none)"
            if g != w:
                print("  line %d\n    docs:      %s\n    generated: %s" % (b + 2 + k, g, w))
    if bad:
        print("FAIL: rerun with --write after a change of the catalogue or the registry")
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    main()
