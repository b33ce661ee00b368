#!/usr/bin/env bash
# tools/new_study writes a skeleton that builds, runs, reproduces what its published.toml states (the verdict
# of its figure) and renders:
# into a temporary directory, a new experiment with a new system, built against this build tree's library
# (BUILD/geomint-config.cmake: nothing of the library is rebuilt), run on its paper scene, its figure
# rendered and checked. Also: the generator refuses a name that is not snake_case and a file that exists.
#   tests/tools/new_study_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 build=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/new_study.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
gen() { "$src/tools/new_study" "$@" --root "$tmp/proj"; }

gen demo_paper energy --paper 999 --item "Fig. 7" --system demo_system
# five files, no more: the study, its scene, its published values, its figure, its system
written=$(cd "$tmp/proj" && find . -type f | sort | tr '\n' ' ')
[ "$written" = "./experiments/demo_paper/demo_paper.toml ./experiments/demo_paper/energy.cpp ./experiments/demo_paper/published.toml ./figures/demo_paper_fig7.gp ./src/geomint/systems/demo_system.hpp " ] ||
  { echo "new_study_test: wrote $written" >&2; exit 1; }
for f in experiments/demo_paper/energy.cpp experiments/demo_paper/demo_paper.toml \
         experiments/demo_paper/published.toml figures/demo_paper_fig7.gp src/geomint/systems/demo_system.hpp; do
  [ -s "$tmp/proj/$f" ] || { echo "new_study_test: $f not written" >&2; exit 1; }
done
# it never overwrites, and it refuses names that are not snake_case (exit 2)
set +e
gen demo_paper energy --paper 999 --item "Fig. 7" 2>/dev/null; rc_exists=$?
gen Demo energy --paper 999 --item "Fig. 7" 2>/dev/null; rc_name=$?
set -e
[ "$rc_exists" = 2 ] && [ "$rc_name" = 2 ] || { echo "new_study_test: exits $rc_exists, $rc_name (want 2, 2)" >&2; exit 1; }

cat > "$tmp/proj/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(demo LANGUAGES CXX)
find_package(geomint CONFIG REQUIRED)
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY \${CMAKE_BINARY_DIR}/bin)
geomint_methods_on(on_demo_system \${CMAKE_SOURCE_DIR}/src/geomint/systems/demo_system.hpp)
geomint_add_experiment(demo_paper \${CMAKE_SOURCE_DIR}/experiments/demo_paper \${on_demo_system})
target_include_directories(demo_paper BEFORE PRIVATE \${CMAKE_SOURCE_DIR}/src)
CMAKE
cmake -S "$tmp/proj" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release -Dgeomint_DIR="$build" >/dev/null
cmake --build "$tmp/build" -j 2 >/dev/null
"$tmp/build/bin/demo_paper" --out "$tmp/out" >/dev/null
python3 - "$tmp/out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
order, verdict = s["orders"]["forest_ruth_energy"], s["figures"]["999 Fig. 7"]["verdict"]
print(f"new_study_test: the skeleton's order {order:.3f}, 999 Fig. 7 {verdict}")
sys.exit(0 if verdict == "reproduced" else 1)  # (its published.toml's comparison, copied from the worked example)
PY
"$src/tests/figures/render_figures.sh" "$tmp/out" "$tmp/figs" "$tmp/proj/figures/demo_paper_fig7.gp"
