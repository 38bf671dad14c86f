#!/usr/bin/python3
"""Command: the peel scenes and studies (paper sections 7-9) and their reports.

The code and its options: tools/ldfcz_tools/peel_study.py (--help).
"""
import sys

from ldfcz_tools.peel_study import main

if __name__ == '__main__':
    sys.exit(main())
