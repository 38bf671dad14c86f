#!/usr/bin/env python3
"""Sizes of the host's Fortran procedures and derived types (a code-structure measure, not a test).

  routine_lengths.py [--top N] [--types] [DIR ...]      (default DIR: host)

Procedures: own lines of every subroutine and function, from its first line to its `end` line, minus the lines of
the procedures it contains (a `contains` section's lines count for the contained procedures only). Types: the
components of every derived type (one per name: `real :: a, b` is two), components of a nested type counted once.
Prints the N longest procedures and, with --types, the N types with the most components.
"""
import argparse
import os
import re
import sys

START = re.compile(r"^\s*(?:(?:pure|elemental|recursive|impure|module)\s+)*"
                   r"(?:(?:integer|real|logical|character|complex|type)\b[^!]*?\s+)?"
                   r"(subroutine|function)\s+(\w+)", re.I)
END = re.compile(r"^\s*end\s+(subroutine|function)\b", re.I)
TYPE_START = re.compile(r"^\s*type\s*(?:,[^:]*)?::\s*(\w+)\s*$", re.I)
TYPE_END = re.compile(r"^\s*end\s+type\b", re.I)


def procedures(path):
    """(name, own lines) of every procedure in a free-form file."""
    out = []
    stack = []   # [name, first line, lines of contained procedures]
    with open(path, errors="replace") as f:
        lines = f.read().split("\n")
    for k, line in enumerate(lines, 1):
        code = line.split("!", 1)[0]
        if re.match(r"^\s*end\s+interface\b", code, re.I) or re.match(r"^\s*(abstract\s+)?interface\b", code, re.I):
            stack.append(None) if re.match(r"^\s*(abstract\s+)?interface\b", code, re.I) else stack.pop()
            continue
        if stack and stack[-1] is None:
            continue   # an interface block's declarations
        if END.match(code):
            name, first, inner = stack.pop()
            total = k - first + 1
            out.append((name, total - inner, path, first))
            if stack and stack[-1] is not None:
                stack[-1][2] += total
            continue
        m = START.match(code)
        if m and not re.match(r"^\s*end\b", code, re.I) and "procedure" not in code.lower().split("(")[0]:
            stack.append([m.group(2), k, 0])
    return out


def type_components(path):
    """(type name, components) of every derived type in a file."""
    out = []
    name = None
    count = 0
    with open(path, errors="replace") as f:
        for line in f:
            code = line.split("!", 1)[0]
            if name is None:
                m = TYPE_START.match(code)
                if m:
                    name, count = m.group(1), 0
                continue
            if TYPE_END.match(code):
                out.append((name, count, path))
                name = None
                continue
            if "::" in code and not re.match(r"^\s*(procedure|generic|final)\b", code, re.I):
                names = code.split("::", 1)[1]
                names = re.sub(r"\([^()]*\)", "", re.sub(r"\([^()]*\)", "", names))   # array specs
                names = re.sub(r"=.*", "", names) if "[" not in names else re.sub(r"=\s*\[.*?\]", "", names)
                count += len([n for n in names.split(",") if n.strip()])
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dirs", nargs="*", default=["host"])
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--types", action="store_true")
    a = ap.parse_args()
    files = []
    for d in a.dirs:
        if not os.path.isdir(d):
            sys.exit("routine_lengths.py: %s: not a directory (the arguments are source directories)" % d)
        for root, _, names in os.walk(d):
            files += [os.path.join(root, n) for n in sorted(names) if n.endswith((".f90", ".F90", ".f90.in"))]
    if not files:
        sys.exit("routine_lengths.py: no Fortran sources (.f90, .F90) under %s" % " ".join(a.dirs))
    procs = [p for f in files for p in procedures(f)]
    procs.sort(key=lambda p: -p[1])
    print("longest procedures (own lines):")
    for name, n, path, first in procs[:a.top]:
        print("  %5d  %s  (%s:%d)" % (n, name, path, first))
    if a.types:
        types = [t for f in files for t in type_components(f)]
        types.sort(key=lambda t: -t[1])
        print("derived types with the most components:")
        for name, n, path in types[:a.top]:
            print("  %5d  %s  (%s)" % (n, name, path))


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
