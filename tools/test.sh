#!/usr/bin/env bash
# Install what is missing, build the Debug configuration (bounds checks, floating-point traps) and run every test.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# LLVM flang: the user routines must also compile with a second compiler (tests/portability).
LDFCZ_EXTRA_PACKAGES="flang-16 ${LDFCZ_EXTRA_PACKAGES:-}" bash "$root/tools/setup.sh" Debug
build_dir=${LDFCZ_BUILD_DIR:-$root/build-debug}
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
