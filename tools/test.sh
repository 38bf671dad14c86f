#!/usr/bin/env bash
# Install what is missing, build the Debug configuration (bounds checks, floating-point traps) and run every test;
# then the same tests on the Release configuration (the optimised code the main job and the studies run: a
# failure that only optimisation or uninitialised memory brings out shows here).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
jobs=$(nproc 2>/dev/null || echo 2)
# The project's sources build without a warning: here (and so in CI) a new warning fails the build
# (LDFCZ_WERROR, off for users: cmake/LdfczCompilerFlags.cmake).
export LDFCZ_CMAKE_ARGS="-DLDFCZ_WERROR=ON ${LDFCZ_CMAKE_ARGS:-}"
# LLVM flang: the user routines must also compile with a second compiler (tests/portability).
LDFCZ_EXTRA_PACKAGES="flang-16 ${LDFCZ_EXTRA_PACKAGES:-}" bash "$root/tools/setup.sh" Debug
build_dir=${LDFCZ_BUILD_DIR:-$root/build-debug}
ctest --test-dir "$build_dir" --output-on-failure -j "$jobs" "$@"
release_dir=${LDFCZ_RELEASE_BUILD_DIR:-$root/build}
LDFCZ_BUILD_DIR="$release_dir" bash "$root/tools/setup.sh" Release
ctest --test-dir "$release_dir" --output-on-failure -j "$jobs" "$@"
# The distributed build (-DLDFCZ_MPI=ON: OpenMPI and the parallel MUMPS, installed by setup.sh): ldfcz and the partition
# test only, Release, and the tests labelled mpi (tests/mpi.cmake) one at a time (each runs up to 3 processes).
mpi_dir=${LDFCZ_MPI_BUILD_DIR:-$root/build-mpi}
if command -v mpirun > /dev/null 2>&1; then
  # shellcheck disable=SC2086
  cmake -S "$root" -B "$mpi_dir" -DCMAKE_BUILD_TYPE=Release -DLDFCZ_MPI=ON -DPython3_EXECUTABLE=/usr/bin/python3 \
        ${LDFCZ_CMAKE_ARGS:-} > "$mpi_dir.configure.log" 2>&1 || { cat "$mpi_dir.configure.log" >&2; exit 1; }
  cmake --build "$mpi_dir" -j "$jobs" --target ldfcz partition_check > "$mpi_dir.build.log" 2>&1 || \
    { tail -n 60 "$mpi_dir.build.log" >&2; exit 1; }
  ctest --test-dir "$mpi_dir" -L mpi --output-on-failure "$@"
else
  echo "test.sh: MPI tests skipped: mpirun not found (tools/setup.sh installs openmpi-bin on Debian)"
fi
