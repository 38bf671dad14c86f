#!/usr/bin/env bash
# Install what is missing, build the Debug configuration (bounds checks, floating-point traps) and run every test;
# then the same tests on the Release configuration (the optimised code the main job and the studies run: a
# failure that only optimisation or uninitialised memory brings out shows here).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc 2>/dev/null || echo 2)
# LLVM flang: the user routines must also compile with a second compiler (tests/portability).
LDFCZ_EXTRA_PACKAGES="flang-16 ${LDFCZ_EXTRA_PACKAGES:-}" bash "$root/tools/setup.sh" Debug
build_dir=${LDFCZ_BUILD_DIR:-$root/build-debug}
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "$@"
release_dir=${LDFCZ_RELEASE_BUILD_DIR:-$root/build}
LDFCZ_BUILD_DIR="$release_dir" bash "$root/tools/setup.sh" Release
ctest --test-dir "$release_dir" --output-on-failure -j "$jobs" "$@"
