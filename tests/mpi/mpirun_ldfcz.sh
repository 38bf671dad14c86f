#!/bin/sh
# ldfcz under mpirun: `mpirun_ldfcz.sh NP EXE ARGS...` runs `mpirun -np NP EXE ARGS...`, so that the serial test
# scripts that take --exe (tests/regression/check_loads.py: closed-form answers) check the distributed run.
np=$1
exe=$2
shift 2
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 exec mpirun -np "$np" --oversubscribe --bind-to none "$exe" "$@"
