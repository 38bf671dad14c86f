#!/usr/bin/env python3
"""Command: the mutation fuzzer of the deck reader (docs/robustness.md).

The code and its options: tools/ldfcz_tools/fuzz_decks.py (--help).
"""
from ldfcz_tools.fuzz_decks import main

if __name__ == '__main__':
    main()
