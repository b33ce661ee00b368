#!/usr/bin/env bash
# The mpirun line of every MPI run of the project: the ctest label mpi (tests/mpi/check_mpi.sh) and
# the Slurm job (scripts/slurm_job.sh) run their experiments through it.
#   scripts/mpirun.sh -np N BIN ARGS...
# --bind-to none: a rank's OpenMP threads (--threads T) may use every core the scheduler gave it
# (Open MPI's default binds a rank to one core, which would put all T threads on it). With
# GEOMINT_MPI_OVERSUBSCRIBE=1 more ranks than cores are allowed (the tests' 3 ranks on 2 cores).
set -euo pipefail
exec mpirun --bind-to none ${GEOMINT_MPI_OVERSUBSCRIBE:+--oversubscribe} "$@"
