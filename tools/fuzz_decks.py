#!/usr/bin/env python3
"""Command: the mutation fuzzer of the deck reader (docs/robustness.md).

The code and its options: tools/ldfcz_tools/fuzz_decks.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('fuzz_decks'))
