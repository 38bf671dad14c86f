#!/bin/bash
# The speed of each core (vCPU) of a machine, alone and with the others busy: benchmarks/bench_leonov_calls.f90 (the
# Leonov return, microseconds per plastic call, CPU time) pinned to one core with taskset, one at a time, then on
# 16, 8 and 2 cores at once. Equal figures: equal cores; figures that differ with the same work on every core: the
# machine gives its cores unequal speed (what an element loop split in equal parts then waits for).
#   reports/bench/scaling-memory/vcpu_speed.sh [BENCH]   (default build-mpi/bin/bench_leonov_calls; 16 cores)
set -u
B=${1:-build-mpi/bin/bench_leonov_calls}
pl() { grep plastic | head -1 | awk '{print $4}'; }
echo "== alone: plastic us/call on vCPU k"
for k in 0 1 5 8 11 15; do printf "cpu %2d %s\n" $k "$(taskset -c $k $B 1000000 | pl)"; done
run_set() {  # the cores to load at once
  for k in "$@"; do (taskset -c $k $B 3000000 | pl > /tmp/vcpu_speed_$k.txt) & done; wait
  for k in "$@"; do printf "%s " "$k:$(cat /tmp/vcpu_speed_$k.txt)"; done; echo
}
echo "== 16 at once"; run_set $(seq 0 15)
echo "== 8 at once on 0-7"; run_set $(seq 0 7)
echo "== 8 at once on even"; run_set 0 2 4 6 8 10 12 14
echo "== 2 at once: 0,1 then 0,8"; run_set 0 1; run_set 0 8
