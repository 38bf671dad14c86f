#!/usr/bin/env python3
"""Command: C3D8R's hourglass control on coarse cantilever meshes against C3D8I, C3D8 and beam theory.

The code and its options: tools/ldfcz_tools/hourglass_study.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('hourglass_study'))
