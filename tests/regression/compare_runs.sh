#!/usr/bin/env bash
# compare_runs.sh BIN WORKDIR SCENE REFERENCE [ARGS...]: run BIN's SCENE with the options ARGS (e.g. --threads 1),
# in the environment it is given (e.g. GEOMINT_LANES=sse2), and require every CSV except timing*.csv (wall times),
# and figure_values.gp (the numbers of the run but its timings), to be byte-identical to those in REFERENCE,
# written by a run with 2 threads in the default environment (the scene's quick run); a work-precision set
# cost_*.csv but its wall-time columns (same_csv.py); and summary.json but the fields README.md lists as
# timings (same_summary.py). The scene's run covers every study it asks for: the quick scenes, together,
# every study of every experiment.
set -euo pipefail
bin=$1 work=$2 scene=$3 reference=$4
shift 4
grep -q '"threads": 2,' "$reference/run.json" || { echo "$reference is not a run of 2 threads" >&2; exit 1; }
grep -q '"lanes_cap": null,' "$reference/run.json" || { echo "$reference is not a run of the CPU's own lanes" >&2; exit 1; }
what="$*${GEOMINT_LANES:+ GEOMINT_LANES=$GEOMINT_LANES}"
rm -rf "$work" && mkdir -p "$work"
"$bin" --scene "$scene" "$@" --out "$work/run" >/dev/null
[ -z "${GEOMINT_LANES:-}" ] || grep -q "\"lanes_cap\": \"$GEOMINT_LANES\"," "$work/run/run.json" ||
  { echo "the run did not record GEOMINT_LANES=$GEOMINT_LANES (run.json lanes_cap)" >&2; exit 1; }
n=0
for f in "$work"/run/*.csv; do
  name=$(basename "$f")
  case "$name" in
    timing*.csv) continue ;;
    cost_*.csv) "$(dirname "$0")/same_csv.py" "$f" "$reference/$name" ;;
    *) cmp "$f" "$reference/$name" ;;
  esac || { echo "differs between ($what) and the run of 2 threads: $name" >&2; exit 1; }
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "no CSV written" >&2; exit 1; }
cmp "$work/run/figure_values.gp" "$reference/figure_values.gp" ||
  { echo "differs between ($what) and the run of 2 threads: figure_values.gp" >&2; exit 1; }
"$(dirname "$0")/same_summary.py" "$work/run/summary.json" "$reference/summary.json" ||
  { echo "differs between ($what) and the run of 2 threads: summary.json" >&2; exit 1; }
echo "$n CSV files, figure_values.gp and summary.json (timings aside) identical for ($what) and 2 threads"
