#!/usr/bin/env python3
"""Command: a double-cantilever-beam deck bonded by the LDF cohesive element.

The code and its options: tools/ldfcz_tools/dcb_deck.py (--help).
"""
from ldfcz_tools.dcb_deck import main

if __name__ == '__main__':
    main()
