#!/usr/bin/env bash
# The micro-benchmarks of reports/bench/kernel/README.md, the two builds alternating in the same minutes:
#   reports/bench/kernel/run_micro.sh OLD_BUILD NEW_BUILD [N] [REPEATS]   (build directories, e.g. a build of e9cbdfd
#                                                                         and build/; writes micro_*.txt here)
# The element benchmark is compiled against OLD_BUILD's modules and libraries (benchmarks/bench_element_calls.F90,
# LDFCZ_BASELINE_API); bench_leonov_calls is each build's own (the Leonov core is the same source in both).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
n=${3:-50000}
reps=${4:-5}
tmp=$(mktemp -d)
gfortran -O2 -cpp -fopenmp -DLDFCZ_BASELINE_API -J "$tmp" -I "$old/modules" "$root/benchmarks/bench_element_calls.F90" \
  "$old/lib/libldfcz_elements.a" "$old/lib/libldfcz_umat.a" "$old/lib/libldfcz_abaqus_utils.a" \
  "$old/lib/libldfcz_kinds.a" -o "$tmp/bench_element_calls_old"
{
  echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(uname -n), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
  echo "# commit $(git -C "$root" rev-parse --short HEAD), old $old, new $new, N = $n, load $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$here/micro_element.txt"
cp "$here/micro_element.txt" "$here/micro_leonov.txt"
for r in $(seq 1 "$reps"); do
  echo "## repeat $r old" >> "$here/micro_element.txt"
  "$tmp/bench_element_calls_old" "$n" >> "$here/micro_element.txt"
  echo "## repeat $r new" >> "$here/micro_element.txt"
  "$new/bin/bench_element_calls" "$n" >> "$here/micro_element.txt"
  echo "## repeat $r old" >> "$here/micro_leonov.txt"
  "$old/bin/bench_leonov_calls" $((20 * n)) >> "$here/micro_leonov.txt"
  echo "## repeat $r new" >> "$here/micro_leonov.txt"
  "$new/bin/bench_leonov_calls" $((20 * n)) >> "$here/micro_leonov.txt"
done
echo "# end $(date -u '+%H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)" >> "$here/micro_element.txt"
rm -rf "$tmp"
python3 "$here/summarise_micro.py" "$here/micro_element.txt" "$here/micro_leonov.txt" > "$here/micro_summary.md"
cat "$here/micro_summary.md"
