#!/usr/bin/env python3
"""Command: the stiff and extreme cases of decks/stability (docs/robustness.md).

The code and its options: tools/ldfcz_tools/stability_suite.py (--help).
"""
from ldfcz_tools.stability_suite import main

if __name__ == '__main__':
    main()
