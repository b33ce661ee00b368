#!/usr/bin/env bash
# The mpirun line of every MPI run of the project: the ctest label mpi (tests/mpi/check_mpi.sh) and
# the Slurm job (scripts/slurm_job.sh) run their experiments through it.
#   scripts/mpirun.sh -np N BIN ARGS...
# --bind-to none: a rank's OpenMP threads (--threads T) may use every core the scheduler gave it
# (Open MPI's default binds a rank to one core, which would put all T threads on it). With
# GEOMINT_MPI_OVERSUBSCRIBE=1 more ranks than cores are allowed (the tests' 3 ranks on 2 cores).
# A first SIGTERM or SIGINT to this script reaches the ranks as SIGUSR1 (stop at the next checkpoint, exit
# 3: mpirun itself would end the job on SIGTERM and exit 1); a second one as SIGTERM (stop at once, exit 3).
set -uo pipefail
mpirun --bind-to none ${GEOMINT_MPI_OVERSUBSCRIBE:+--oversubscribe} "$@" &
job=$!
signals=0
forward() {
  signals=$((signals + 1))
  if [[ $signals -eq 1 ]]; then kill -USR1 "$job" 2> /dev/null; else kill -TERM "$job" 2> /dev/null; fi
}
trap forward TERM INT
trap 'kill -USR1 "$job" 2> /dev/null' USR1
while :; do
  wait "$job"
  code=$?
  kill -0 "$job" 2> /dev/null || exit "$code"  # (a trapped signal ends wait early: wait again)
done
