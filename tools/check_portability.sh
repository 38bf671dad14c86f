#!/usr/bin/env bash
# Compile the user routines (uel/, umat/ and the kinds module) with a second compiler, LLVM flang, as a commercial
# host would compile a user file with its own compiler. Prints the diagnostics; exits non-zero on any error.
#   tools/check_portability.sh [flang executable]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fc=${1:-}
if [ -z "$fc" ]; then
  for c in flang-new-16 flang-new flang; do command -v "$c" >/dev/null 2>&1 && { fc=$c; break; }; done
fi
[ -n "$fc" ] || { echo "check_portability: no flang compiler found" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# Dependency order: kinds and the finiteness test (common/), then each area's modules in the order its CMakeLists
# lists them, then the adapters.
sources=("$root/common/ldfcz_kinds.f90" "$root/common/ldfcz_finite.f90")
for area in uel umat; do
  [ -f "$root/$area/CMakeLists.txt" ] || continue
  while read -r f; do sources+=("$root/$area/$f"); done < <(
    sed -n '/add_library(ldfcz_'"$area"'/,/)/p' "$root/$area/CMakeLists.txt" | grep -oE '[A-Za-z0-9_]+\.(f90|f|F90)')
done
status=0
for src in "${sources[@]}"; do
  if ! out=$("$fc" -c -I"$root/host/abaqus" -I"$work" "$src" 2>&1); then
    echo "FAIL $src"; echo "$out"; status=1
  else
    [ -n "$out" ] && { echo "WARN $src"; echo "$out"; }
    echo "ok   ${src#"$root"/}"
  fi
done
exit $status
