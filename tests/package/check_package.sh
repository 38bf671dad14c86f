#!/usr/bin/env bash
# Test package_find_ldfcz: install the build tree into a scratch prefix, build the consumer project of this folder
# against it with find_package(ldfcz REQUIRED), static and shared, run both (each checks a UEL and a UMAT closed
# form; the shared one must load lib*.so from the prefix), and check that pkg-config finds the same libraries, also
# after the prefix has been moved (the .pc file is relocatable).  check_package.sh BUILD_DIR OUT_DIR FORTRAN_COMPILER
set -euo pipefail
build=$1 out=$2 fc=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$out"
cmake --install "$build" --prefix "$out/prefix" > "$out.install.log"
cmake -S "$here" -B "$out/build" -DCMAKE_PREFIX_PATH="$out/prefix" -DCMAKE_Fortran_COMPILER="$fc" > "$out.configure.log"
cmake --build "$out/build" > "$out.build.log"
"$out/build/consumer"
"$out/build/consumer_shared"
# (ldd's output taken whole first: grep -q on a pipe would end ldd early with SIGPIPE, a failure under pipefail)
loaded=$(ldd "$out/build/consumer_shared")
case "$loaded" in
  *"$out/prefix/lib/libldfcz_umat.so"*) ;;
  *) echo "FAIL: consumer_shared does not load the installed libldfcz_umat.so"; echo "$loaded"; exit 1 ;;
esac
echo "shared libraries: consumer_shared loads them from the prefix: ok"
libs=$(PKG_CONFIG_PATH="$out/prefix/lib/pkgconfig" pkg-config --libs ldfcz)
echo "pkg-config --libs ldfcz: $libs"
for lib in ldfcz_uel ldfcz_umat ldfcz_kinds ldfcz_abaqus_utils; do
  [ -f "$out/prefix/lib/lib$lib.a" ] || { echo "FAIL: lib$lib.a not installed"; exit 1; }
  [ -f "$out/prefix/lib/lib$lib.so" ] || { echo "FAIL: lib$lib.so not installed"; exit 1; }
  case "$libs" in *"-l$lib"*) ;; *) echo "FAIL: pkg-config does not name $lib"; exit 1 ;; esac
done
mv "$out/prefix" "$out/moved"
moved=$(PKG_CONFIG_PATH="$out/moved/lib/pkgconfig" pkg-config --variable=libdir ldfcz)
[ "$(cd "$moved" && pwd)" = "$(cd "$out/moved/lib" && pwd)" ] \
  || { echo "FAIL: pkg-config libdir after moving the prefix: $moved"; exit 1; }
echo "pkg-config after moving the prefix: libdir $moved: ok"
mv "$out/moved" "$out/prefix"
for f in ldfcz_abaqus.f ldfcz_abaqus_uel.f ldfcz_abaqus_umat.f ldfcz_abaqus.f90 ldfcz_abaqus_uel.f90 \
         ldfcz_abaqus_umat.f90 ldfcz_marc_hypela2.f ldfcz_marc_uselem.f ldfcz_marc.f ldfcz_open_host_utils.f \
         ldfcz_open_host_utils.f90; do
  [ -f "$out/prefix/share/ldfcz/$f" ] || { echo "FAIL: drop-in $f not installed"; exit 1; }
done
[ -f "$out/prefix/include/ldfcz/SMAAspUserSubroutines.hdr" ] || { echo "FAIL: SMAAspUserSubroutines.hdr not installed"; exit 1; }
echo "package: ok"
