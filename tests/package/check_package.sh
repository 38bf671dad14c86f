#!/usr/bin/env bash
# Test package_find_ldfcz: install the build tree into a scratch prefix, build the consumer project of this folder
# against it with find_package(ldfcz REQUIRED), run it (it checks a UEL and a UMAT closed form), and check that
# pkg-config finds the same libraries.  check_package.sh BUILD_DIR OUT_DIR FORTRAN_COMPILER
set -euo pipefail
build=$1 out=$2 fc=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$out"
cmake --install "$build" --prefix "$out/prefix" > "$out.install.log"
cmake -S "$here" -B "$out/build" -DCMAKE_PREFIX_PATH="$out/prefix" -DCMAKE_Fortran_COMPILER="$fc" > "$out.configure.log"
cmake --build "$out/build" > "$out.build.log"
"$out/build/consumer"
libs=$(PKG_CONFIG_PATH="$out/prefix/lib/pkgconfig" pkg-config --libs ldfcz)
echo "pkg-config --libs ldfcz: $libs"
for lib in ldfcz_uel ldfcz_umat ldfcz_kinds; do
  [ -f "$out/prefix/lib/lib$lib.a" ] || { echo "FAIL: lib$lib.a not installed"; exit 1; }
  case "$libs" in *"-l$lib"*) ;; *) echo "FAIL: pkg-config does not name $lib"; exit 1 ;; esac
done
for f in ldfcz_abaqus.f ldfcz_abaqus_uel.f ldfcz_abaqus_umat.f; do
  [ -f "$out/prefix/share/ldfcz/$f" ] || { echo "FAIL: drop-in $f not installed"; exit 1; }
done
echo "package: ok"
