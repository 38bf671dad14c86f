#!/usr/bin/env python3
"""Command: plots of material-point curves and the PET cases.

The code and its options: tools/ldfcz_tools/plot_material.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('plot_material'))
