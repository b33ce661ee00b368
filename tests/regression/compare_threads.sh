#!/usr/bin/env bash
# compare_threads.sh BIN WORKDIR [SCENE [ARGS...]]: run BIN's quick scene (or SCENE,
# with the further options ARGS) with 1 and with 2 threads and require every CSV except timing*.csv (wall
# times), and figure_values.gp (the numbers of the run but its timings), to be
# byte-identical.
set -euo pipefail
bin=$1 work=$2
scene=(--quick)
[ $# -ge 3 ] && scene=(--scene "$3" "${@:4}")
rm -rf "$work" && mkdir -p "$work"
"$bin" "${scene[@]}" --threads 1 --out "$work/t1" >/dev/null
"$bin" "${scene[@]}" --threads 2 --out "$work/t2" >/dev/null
n=0
for f in "$work"/t1/*.csv; do
  name=$(basename "$f")
  case "$name" in timing*.csv) continue ;; esac
  cmp "$f" "$work/t2/$name" || { echo "differs between --threads 1 and 2: $name" >&2; exit 1; }
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "no CSV written" >&2; exit 1; }
cmp "$work/t1/figure_values.gp" "$work/t2/figure_values.gp" || { echo "differs between --threads 1 and 2: figure_values.gp" >&2; exit 1; }
echo "$n CSV files identical for --threads 1 and 2"
