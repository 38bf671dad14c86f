#!/usr/bin/python3
"""Command: identification of the interface parameters from a measured peel curve (docs/identify.md).

The code and its options: tools/ldfcz_tools/identify.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('identify'))
