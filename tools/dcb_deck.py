#!/usr/bin/env python3
"""Command: a double-cantilever-beam deck bonded by the LDF cohesive element.

The code and its options: tools/ldfcz_tools/dcb_deck.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('dcb_deck'))
