#!/usr/bin/env bash
# compare_threads.sh BIN WORKDIR SCENE REFERENCE [ARGS...]: run BIN's SCENE with the further
# options ARGS and 1 thread, and require every CSV except timing*.csv (wall times), and
# figure_values.gp (the numbers of the run but its timings), to be byte-identical to those in
# REFERENCE, written by the same run with 2 threads (the scene's quick run); a work-precision set
# cost_*.csv but its wall-time columns (same_csv.py); and summary.json but the fields README.md lists as
# timings (same_summary.py). The scene's run covers every study it asks for: the quick scenes, together,
# every study of every experiment.
set -euo pipefail
bin=$1 work=$2 scene=$3 reference=$4
shift 4
grep -q '"threads": 2,' "$reference/run.json" || { echo "$reference is not a run of 2 threads" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
"$bin" --scene "$scene" "$@" --threads 1 --out "$work/t1" >/dev/null
n=0
for f in "$work"/t1/*.csv; do
  name=$(basename "$f")
  case "$name" in
    timing*.csv) continue ;;
    cost_*.csv) "$(dirname "$0")/same_csv.py" "$f" "$reference/$name" ;;
    *) cmp "$f" "$reference/$name" ;;
  esac || { echo "differs between --threads 1 and 2: $name" >&2; exit 1; }
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "no CSV written" >&2; exit 1; }
cmp "$work/t1/figure_values.gp" "$reference/figure_values.gp" || { echo "differs between --threads 1 and 2: figure_values.gp" >&2; exit 1; }
"$(dirname "$0")/same_summary.py" "$work/t1/summary.json" "$reference/summary.json" ||
  { echo "differs between --threads 1 and 2: summary.json" >&2; exit 1; }
echo "$n CSV files, figure_values.gp and summary.json (timings aside) identical for --threads 1 and 2"
