#!/usr/bin/env bash
# An MPI job gives the bytes of one process (issue 17): BIN with ARGS run as one process (2 threads)
# and under `mpirun -np NP` (1 thread per rank, more ranks than cores allowed) write the same CSV
# files and summary.json, timings aside. With --resume-np M the MPI run is first stopped after one
# round (checkpoint.stop_after = 1, exit 3) and then resumed with M ranks; with --usr1 as well, it is
# stopped instead by SIGUSR1 sent to mpirun once the first checkpoint is written (what a batch
# job's time-limit warning does: scripts/slurm_job.sh), with --term by SIGTERM (what `kill` does; the
# mpirun line forwards it as SIGUSR1), or with --term-rank by SIGTERM to one rank alone. With --reference DIR the one-process run is not made again: DIR holds
# what BIN with ARGS wrote with 2 threads (the scene's reference run).
#   check_mpi.sh BIN WORK NP [--reference DIR] [--resume-np M [--usr1 | --term | --term-rank]] -- ARGS...
set -euo pipefail
bin=$1 work=$2 np=$3
shift 3
reference=""
resume_np=""
usr1=""
if [[ ${1:-} == --reference ]]; then reference=$2; shift 2; fi
if [[ ${1:-} == --resume-np ]]; then resume_np=$2; shift 2; fi
if [[ ${1:-} == --usr1 ]]; then usr1=USR1; shift; fi
if [[ ${1:-} == --term ]]; then usr1=TERM; shift; fi
rank=""
if [[ ${1:-} == --term-rank ]]; then usr1=TERM rank=1; shift; fi
[[ ${1:-} == -- ]] && shift
# Open MPI refuses to run as root unless told; CI runs as root. The mpirun line is the project's
# (scripts/mpirun.sh, also the Slurm job's), with more ranks than cores allowed.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 GEOMINT_MPI_OVERSUBSCRIBE=1
mpi=("$(dirname "$0")/../../scripts/mpirun.sh")
rm -rf "$work" && mkdir -p "$work"
one=${reference:-$work/one}
if [[ -z $reference ]]; then
  "$bin" "$@" --threads 2 --out "$one" 2> "$work/one.stderr"
fi
[[ -f $one/summary.json ]] || { echo "FAIL: no one-process results in $one"; exit 1; }
if [[ -n $resume_np ]]; then
  set +e
  if [[ -n $usr1 ]]; then
    "${mpi[@]}" -np "$np" "$bin" "$@" --threads 1 --set checkpoint.interval=0 --out "$work/mpi" 2> "$work/stop.stderr" &
    pid=$!
    until compgen -G "$work/mpi.partial/*.checkpoint.json" > /dev/null || ! kill -0 "$pid" 2> /dev/null; do sleep 0.05; done
    if [[ -n $rank ]]; then
      # The newest rank of this run: a process whose command line starts with the binary and names this run's
      # --out (never mpirun, nor a rank of another test running beside this one: ctest -j).
      quote() { printf '%s' "$1" | sed 's/[][\.*^$+?(){}|]/\\&/g'; }
      pkill -TERM -n -f "^$(quote "$bin") .*--out $(quote "$work/mpi")( |\$)"
    else
      kill -"$usr1" "$pid" 2> /dev/null
    fi
    wait "$pid"
  else
    "${mpi[@]}" -np "$np" "$bin" "$@" --threads 1 --set checkpoint.stop_after=1 --out "$work/mpi" 2> "$work/stop.stderr"
  fi
  code=$?
  set -e
  [[ $code -eq 3 ]] || { echo "FAIL: the stopped MPI run exits $code, not 3"; cat "$work/stop.stderr"; exit 1; }
  ls "$work/mpi.partial/"*.checkpoint.json > /dev/null || { echo "FAIL: no checkpoint in $work/mpi.partial"; exit 1; }
  "${mpi[@]}" -np "$resume_np" "$bin" "$@" --threads 1 --resume --out "$work/mpi" 2> "$work/mpi.stderr"
  label="stopped with $np ranks, resumed with $resume_np"
else
  # (what the ranks of a killed job left in the temporary directory, of a process that no longer runs, goes;
  # nothing of this job's stays)
  exe=$(basename "$bin") dead=$(sh -c 'echo $$')
  mkdir -p "$work/tmp/$exe-rank1-$dead.partial" && touch "$work/tmp/$exe-rank1-$dead.lock"
  TMPDIR=$work/tmp "${mpi[@]}" -np "$np" "$bin" "$@" --threads 1 --out "$work/mpi" 2> "$work/mpi.stderr"
  left=$(ls "$work/tmp")
  [[ -z $left ]] || { echo "FAIL: left in TMPDIR: $left"; exit 1; }
  label="$np ranks"
fi
[[ ! -e "$work/mpi.partial" ]] || { echo "FAIL: $work/mpi.partial left"; exit 1; }
grep -q "\"ranks\": ${resume_np:-$np}" "$work/mpi/run.json" || { echo "FAIL: run.json does not count ${resume_np:-$np} ranks"; exit 1; }
files=0
for f in "$one/"*.csv; do
  name=$(basename "$f")
  [[ $name == timing* ]] && continue
  if [[ $name == cost_* ]]; then  # a work-precision set: every cell but its wall times
    "$(dirname "$0")/../regression/same_csv.py" "$f" "$work/mpi/$name" || { echo "FAIL: $name differs ($label)"; exit 1; }
  else
    cmp -s "$f" "$work/mpi/$name" || { echo "FAIL: $name differs ($label)"; exit 1; }
  fi
  files=$((files + 1))
done
"$(dirname "$0")/../regression/same_summary.py" "$one/summary.json" "$work/mpi/summary.json" ||
  { echo "FAIL: summary.json differs ($label)"; exit 1; }
echo "$files CSV files and summary.json identical: one process (2 threads) and $label (1 thread each)"
