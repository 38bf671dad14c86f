#!/usr/bin/env python3
"""Command: Newton convergence of a UMAT with and without *ORIENTATION (docs/host.md).

The code and its options: tools/ldfcz_tools/orientation_newton_study.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('orientation_newton_study'))
