#!/usr/bin/python3
"""Command: a field frame of a run rendered to a PNG, on a headless machine too (docs/tools.md).

The code and its options: tools/ldfcz_tools/render_frame.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('render_frame'))
