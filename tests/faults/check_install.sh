#!/usr/bin/env bash
# An installed build finds its scenes: cmake --install BUILD --prefix WORK/prefix, then, from another
# working directory and with GEOMINT_EXPERIMENTS unset, every installed executable lists its keys and
# plans its paper scene, --help names the installed scene directory, and a quick run reads its scene
# from there (run.json).
#   check_install.sh BUILD WORK
set -euo pipefail
build=$1 work=$2
prefix=$work/prefix
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
unset GEOMINT_EXPERIMENTS
cd /
scenes=$prefix/share/geomint/experiments
for exe in euler_compensation rowlands_convergence energy_map lobatto_table ti_drift measure_cloud; do
  bin=$prefix/bin/$exe
  [[ -x $bin ]] || { echo "FAIL: $bin not installed"; exit 1; }
  [[ -f $scenes/$exe/$exe.toml && -f $scenes/$exe/quick.toml ]] || { echo "FAIL: $exe's scenes not installed"; exit 1; }
  help=$("$bin" --help)  # (not piped into grep -q, whose early exit would make pipefail report --help's SIGPIPE)
  grep -qF "$scenes/$exe/$exe.toml" <<< "$help" || { echo "FAIL: $exe --help does not name $scenes/$exe"; exit 1; }
  "$bin" --list-keys --json > /dev/null || { echo "FAIL: $exe --list-keys --json"; exit 1; }
  "$bin" --plan > /dev/null || { echo "FAIL: $exe --plan on the installed paper scene"; exit 1; }
done
"$prefix/bin/euler_compensation" --quick --out "$work/out" 2> /dev/null
grep -qF "\"scene_file\": \"$scenes/euler_compensation/quick.toml\"" "$work/out/run.json" ||
  { echo "FAIL: the installed euler_compensation did not read $scenes/euler_compensation/quick.toml"; exit 1; }
echo "installed in $prefix: every executable finds its scenes in $scenes"
