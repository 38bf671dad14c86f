#!/usr/bin/env bash
# Install what is missing (Debian 12 packages), then configure and build ldfcz.
#   tools/setup.sh [Release|Debug]     build directory: build/ (Release) or build-debug/ (Debug), or $LDFCZ_BUILD_DIR
#   tools/setup.sh bench               the Release build and what the benchmarks compare against (CalculiX 2.20,
#                                      Debian's calculix-ccx: benchmarks/bench_calculix.py) or measure with (heaptrack:
#                                      reports/bench/memory/); the tests never need them
# Extra CMake options may be passed in $LDFCZ_CMAKE_ARGS (e.g. -DCMAKE_PREFIX_PATH=/path/to/pfunit).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_type=${1:-Release}
bench_packages=()
if [ "$build_type" = bench ]; then
  build_type=Release
  bench_packages=(calculix-ccx heaptrack)
fi
case "$build_type" in
  Release) default_dir="$root/build" ;;
  Debug) default_dir="$root/build-debug" ;;
  *) echo "setup.sh: unknown build type '$build_type' (Release or Debug)" >&2; exit 2 ;;
esac
build_dir=${LDFCZ_BUILD_DIR:-$default_dir}

packages=(gfortran gcc make cmake pkg-config python3 python3-matplotlib python3-numpy python3-scipy python3-vtk9
          libmumps-seq-dev libmetis-dev liblapack-dev libopenblas-dev)
# Pictures of the frames on a machine without a display (tools/render_frame.py, test deck_frames): Debian's VTK
# renders off-screen through an X server, which xvfb-run provides (it needs xauth)
packages+=(xvfb xauth)
# The documentation site and its test (mkdocs.yml, test docs_mkdocs: mkdocs build --strict): Debian 12's MkDocs 1.4
packages+=(mkdocs)
# The LDFCZ_MPI build (mpirun -np N ldfcz; its tests run in tools/test.sh): OpenMPI and the parallel MUMPS. The default
# build does not use them; they are installed always so that the MPI tests never lack them on Debian.
packages+=(openmpi-bin libopenmpi-dev libmumps-dev)
# More packages for a particular use (tools/test.sh adds LLVM flang for the portability check).
read -r -a extra <<< "${LDFCZ_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}" "${bench_packages[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup.sh: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs=$(nproc 2>/dev/null || echo 2)
# shellcheck disable=SC2086
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" -DPython3_EXECUTABLE=/usr/bin/python3 \
      ${LDFCZ_CMAKE_ARGS:-} > "$build_dir.configure.log" 2>&1 || { cat "$build_dir.configure.log" >&2; exit 1; }
cmake --build "$build_dir" -j "$jobs" > "$build_dir.build.log" 2>&1 || { tail -n 60 "$build_dir.build.log" >&2; exit 1; }
echo "setup.sh: built ldfcz ($build_type) in $build_dir"
