#!/usr/bin/env python3
"""Fallback preprocessor for pFUnit test suites (.pf), used when no real pFUnit is installed.

It supports exactly the pFUnit syntax that ldfcz's suites use (see tests/pfunit_fallback/README.md):
@test, @before, @after on argument-free module subroutines, and the assertion macros
@assertEqual, @assertRelativelyEqual, @assertTrue, @assertFalse, @assertLessThan, @assertLessThanOrEqual,
@assertGreaterThan, @assertGreaterThanOrEqual, @assertIsFinite, each on one line (as pFUnit requires).
Anything else that starts with '@' is an error naming the file and line, so that a suite never silently
drops a check.

  pfpp.py module SUITE.pf OUT.F90     translate one suite
  pfpp.py driver OUT.F90 SUITE.pf...  write the test driver program for the given suites; the program runs
                                      every @test, or with -f PATTERN those whose name contains PATTERN
"""
import os
import re
import sys

ASSERTIONS = {
    "assertequal": "assertEqual",
    "assertrelativelyequal": "assertRelativelyEqual",
    "asserttrue": "assertTrue",
    "assertfalse": "assertFalse",
    "assertlessthan": "assertLessThan",
    "assertlessthanorequal": "assertLessThanOrEqual",
    "assertgreaterthan": "assertGreaterThan",
    "assertgreaterthanorequal": "assertGreaterThanOrEqual",
    "assertisfinite": "assertIsFinite",
}
ORDERING = ("assertlessthan", "assertlessthanorequal", "assertgreaterthan", "assertgreaterthanorequal")
ANNOTATIONS = ("test", "before", "after")
SUB_RE = re.compile(r"^\s*(?:(?:pure|impure|recursive|module)\s+)*subroutine\s+([a-z_][a-z0-9_]*)", re.I)
MODULE_RE = re.compile(r"^\s*module\s+([a-z_][a-z0-9_]*)\s*(?:!.*)?$", re.I)


class PfError(Exception):
    """A construct the fallback does not support, with its location."""


def strip_comment(line):
    """The code part of a free-form line (a '!' outside quotes starts a comment)."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i]
    return line


def split_macro(text, path, lineno):
    """Split '@name(args)' into (name, args) using the matching closing parenthesis."""
    m = re.match(r"\s*@([A-Za-z]+)\s*(\(.*)?$", text, re.S)
    if not m:
        raise PfError(f"{path}:{lineno}: cannot read the annotation '{text.strip()}'")
    name, rest = m.group(1), (m.group(2) or "")
    if not rest:
        return name, None
    depth, quote = 0, None
    for i, ch in enumerate(rest):
        if quote:
            if ch == quote:
                quote = None
            continue
        if ch in "'\"":
            quote = ch
        elif ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                tail = strip_comment(rest[i + 1:]).strip()
                if tail:
                    raise PfError(f"{path}:{lineno}: text after @{name}(...): '{tail}'")
                return name, rest[1:i]
    raise PfError(f"{path}:{lineno}: unbalanced parentheses in @{name}")


def read_suite(path):
    """Translate a .pf file: returns (fortran text, module name, tests, befores, afters)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    out, tests, befores, afters = [], [], [], []
    module = None
    pending = None
    rel = os.path.abspath(path)
    i = 0
    while i < len(lines):
        line = lines[i]
        lineno = i + 1
        stripped = line.strip()
        if module is None:
            m = MODULE_RE.match(line)
            if m and m.group(1).lower() != "procedure":
                module = m.group(1)
        if stripped.startswith("@"):
            text = strip_comment(line).rstrip()
            j = i
            if text.endswith("&"):
                # pFUnit 4's preprocessor reads an annotation or assertion from a single line only.
                raise PfError(f"{path}:{lineno}: @-lines cannot be continued with '&' (pFUnit reads them on one "
                              f"line): compute the values first, or write the assertion on one line")
            name, args = split_macro(text, path, lineno)
            key = name.lower()
            if key in ANNOTATIONS:
                if args is not None and key != "test":
                    raise PfError(f"{path}:{lineno}: @{name} takes no arguments in this fallback")
                if args is not None and args.strip():
                    raise PfError(f"{path}:{lineno}: @test arguments are not supported by the fallback")
                pending = (key, lineno)
                out.append(f"! pFUnit annotation @{name}")
            elif key in ASSERTIONS:
                if args is None or not args.strip():
                    raise PfError(f"{path}:{lineno}: @{name} needs arguments")
                if key in ORDERING:
                    # one generic with the pairs of kinds pFUnit accepts (funit.f90): the name goes first
                    call = (f"call pf_ordering('{ASSERTIONS[key]}', {args.strip()}, "
                            f"pf_file='{os.path.basename(path)}', pf_line={lineno})")
                else:
                    call = (f"call {ASSERTIONS[key]}({args.strip()}, pf_file='{os.path.basename(path)}', "
                            f"pf_line={lineno})")
                out.append(call)
                out.append("if (anyExceptions()) return")
                out.append(f'#line {j + 2} "{rel}"')
            else:
                raise PfError(f"{path}:{lineno}: @{name} is not supported by the pFUnit fallback "
                              f"(supported: @test, @before, @after, " + ", ".join("@" + v for v in ASSERTIONS.values()) + ")")
            i = j + 1
            continue
        if pending is not None and stripped and not stripped.startswith("!"):
            m = SUB_RE.match(line)
            if not m:
                raise PfError(f"{path}:{pending[1]}: @{pending[0]} must precede a subroutine")
            if m.group(1).lower() in ("initialize", "finalize"):
                raise PfError(f"{path}:{lineno}: a pFUnit procedure must not be called '{m.group(1)}' "
                              f"(it clashes with funit's own)")
            {"test": tests, "before": befores, "after": afters}[pending[0]].append(m.group(1))
            pending = None
        out.append(line)
        i += 1
    if module is None:
        raise PfError(f"{path}:1: no module found")
    base = os.path.splitext(os.path.basename(path))[0]
    if module.lower() != base.lower():
        raise PfError(f"{path}: the module is '{module}' but pFUnit requires it to be named like the file ('{base}')")
    if len(befores) > 1 or len(afters) > 1:
        raise PfError(f"{path}: at most one @before and one @after per suite")
    if not tests:
        raise PfError(f"{path}: no @test found")
    text = f'#line 1 "{rel}"\n' + "\n".join(out) + "\n"
    return text, module, tests, befores, afters


def write_if_changed(path, text):
    """Write the file only when its content changes (keeps builds incremental)."""
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv):
    try:
        if len(argv) == 4 and argv[1] == "module":
            text, _, _, _, _ = read_suite(argv[2])
            write_if_changed(argv[3], text)
            return 0
        if len(argv) >= 4 and argv[1] == "driver":
            body = ["! Generated by tests/pfunit_fallback/pfpp.py: runs every @test of the suites below (or those",
                    "! whose name contains the PATTERN of -f PATTERN, as pFUnit's driver).",
                    "program pf_driver",
                    "  use funit, only: pf_selected, pf_begin_test, pf_end_test, pf_summary, anyExceptions"]
            calls = []
            for pf in argv[3:]:
                _, module, tests, befores, afters = read_suite(pf)
                body.append(f"  use {module}, only: " + ", ".join(tests + befores + afters))
                for t in tests:
                    calls.append(f"  if (pf_selected('{t}')) then")
                    calls.append(f"    call pf_begin_test('{module}.{t}')")
                    for b in befores:
                        calls.append(f"    call {b}()")
                    calls.append(f"    if (.not. anyExceptions()) call {t}()")
                    for a in afters:
                        calls.append(f"    call {a}()")
                    calls.append("    call pf_end_test()")
                    calls.append("  end if")
            body.append("  implicit none")
            body.extend(calls)
            body.append("  call pf_summary()")
            body.append("end program pf_driver")
            write_if_changed(argv[2], "\n".join(body) + "\n")
            return 0
    except PfError as err:
        print(f"pfpp: error: {err}", file=sys.stderr)
        return 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
