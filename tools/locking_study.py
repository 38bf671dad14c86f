#!/usr/bin/env python3
"""Command: volumetric locking of the continuum elements against Lame (docs/elements.md).

The code and its options: tools/ldfcz_tools/locking_study.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('locking_study'))
