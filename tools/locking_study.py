#!/usr/bin/env python3
"""Command: volumetric locking of the continuum elements against Lame (docs/elements.md).

The code and its options: tools/ldfcz_tools/locking_study.py (--help).
"""
from ldfcz_tools.locking_study import main

if __name__ == '__main__':
    main()
