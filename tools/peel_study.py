#!/usr/bin/python3
"""Command: the peel scenes and studies (paper sections 7-9) and their reports.

The code and its options: tools/ldfcz_tools/peel_study.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('peel_study'))
