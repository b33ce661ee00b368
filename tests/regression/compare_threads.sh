#!/usr/bin/env bash
# compare_threads.sh BIN WORKDIR: run BIN's quick scene with 1 and with 2
# threads and require every CSV except timing*.csv (wall times) to be
# byte-identical.
set -euo pipefail
bin=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
"$bin" --quick --threads 1 --out "$work/t1" >/dev/null
"$bin" --quick --threads 2 --out "$work/t2" >/dev/null
n=0
for f in "$work"/t1/*.csv; do
  name=$(basename "$f")
  case "$name" in timing*.csv) continue ;; esac
  cmp "$f" "$work/t2/$name" || { echo "differs between --threads 1 and 2: $name" >&2; exit 1; }
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "no CSV written" >&2; exit 1; }
echo "$n CSV files identical for --threads 1 and 2"
