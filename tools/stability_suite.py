#!/usr/bin/env python3
"""Command: the stiff and extreme cases of decks/stability (docs/robustness.md).

The code and its options: tools/ldfcz_tools/stability_suite.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('stability_suite'))
