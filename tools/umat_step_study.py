#!/usr/bin/env python3
"""Command: step-size study of the Leonov UMAT on the material_point driver.

The code and its options: tools/ldfcz_tools/umat_step_study.py (--help).
"""
import sys

from ldfcz_tools.cli import run

if __name__ == '__main__':
    sys.exit(run('umat_step_study'))
