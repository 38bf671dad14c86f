#!/bin/bash
# One MPI process under heaptrack, its file named by its rank: ht.R.zst in $HEAPTRACK_DIR (default: the current
# directory). Used as: mpirun -np N reports/bench/memory/heaptrack_rank.sh build-mpi/bin/ldfcz [options] JOB.inp
exec heaptrack -o "${HEAPTRACK_DIR:-$PWD}/ht.${OMPI_COMM_WORLD_RANK:-0}" "$@"
