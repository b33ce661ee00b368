#!/usr/bin/env bash
# A Slurm batch job for one experiment scene under MPI (README: Running on a cluster), e.g. the
# cluster scenes:
#   sbatch --nodes=8 --ntasks-per-node=4 --cpus-per-task=16 --time=02:00:00 \
#     scripts/slurm_job.sh energy_map experiments/energy_map/fine.toml results/energy_map-fine
#   sbatch --nodes=4 --ntasks-per-node=4 --cpus-per-task=16 --time=04:00:00 \
#     scripts/slurm_job.sh ti_drift experiments/ti_drift/ensembles.toml results/ti_drift-ensembles
# Run from the repository root after `make build` (on a file system every node sees). One rank per
# task with --cpus-per-task OpenMP threads; the mpirun line is scripts/mpirun.sh, the one the tests
# run. The job always passes --resume: a job that ran out of time or was requeued continues from its
# last checkpoint in OUT.partial (on any number of nodes), a first run starts from the beginning.
# Before submitting, `build/bin/NAME --scene SCENE --plan --ranks N --threads T` estimates the wall time.
#SBATCH --job-name=geomint
#SBATCH --output=geomint-%j.log
#SBATCH --signal=B:USR1@300
set -uo pipefail
usage="usage: sbatch [options] scripts/slurm_job.sh NAME SCENE OUT"
name=${1:?$usage} scene=${2:?$usage} out=${3:?$usage}
: "${SLURM_NTASKS:?not inside a Slurm job ($usage)}"
export OMP_PROC_BIND=false
scripts/mpirun.sh -np "$SLURM_NTASKS" "build/bin/$name" --scene "$scene" --threads "${SLURM_CPUS_PER_TASK:-1}" \
  --out "$out" --resume &
pid=$!
# Five minutes before the time limit (--signal=B:USR1@300) this shell gets SIGUSR1; mpirun passes it
# on to every rank, and the run stops at its next checkpoint (exit 3).
trap 'kill -USR1 "$pid"' USR1
code=0
wait "$pid" || code=$?
while ((code > 128)) && kill -0 "$pid" 2>/dev/null; do  # (wait returned for the trap: the run goes on)
  code=0
  wait "$pid" || code=$?
done
((code == 3)) && echo "stopped at a checkpoint in $out.partial: submit the same job again to continue"
exit "$code"
