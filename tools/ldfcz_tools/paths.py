"""Where things are in the source tree, for the tools' defaults (build/bin/ldfcz, reports/, out/)."""
import os

PACKAGE = os.path.dirname(os.path.realpath(__file__))   # (benchmarks/ldfcz_tools is a link to it)
TOOLS = os.path.dirname(PACKAGE)   # tools/: the command scripts
ROOT = os.path.dirname(TOOLS)      # the source tree
