#!/usr/bin/python3
"""Command: the peel scenes' decks of van den Bosch, Schreurs, Geers (2007), sections 7-9.

The code and its options: tools/ldfcz_tools/peel_deck.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('peel_deck'))
