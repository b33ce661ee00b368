#!/bin/sh
# Energy-map throughput, all implementations in one table (000 Fig. 6 workload:
# symplectic Euler p first, elastic pendulum l = m = k = 1, g = 0.02, h = 0.2).
#
#   bench/run_energy_map_bench.sh [BUILD_DIR]      (default: build)
#
# Runs BUILD_DIR/bin/geomint_energy_map_bench (batch kernels per ISA, the
# straightforward scalar loop, Boost.Odeint; median of BENCH_REPS repetitions of at least
# BENCH_MIN_TIME seconds each) and bench/peers/energy_map_numpy.py (median of
# NUMPY_REPEAT runs of NUMPY_N trajectories x 20000 steps) under Debian's
# /usr/bin/python3, then prints per implementation and coordinate system: ns per
# trajectory-step on one core and in cycles (the repetitions of all benchmarks interleaved in random order; the
# clock calibrated in the same run by a dependent chain of
# integer additions), the ratio to the best batch kernel, the fraction of each kernel's own ceiling on
# this core (the time of its step's vector arithmetic alone, measured in the same run:
# src/geomint/sweep/arithmetic_ceiling.hpp, the counts in arithmetic_counts.hpp;
# not counted for SSE2) and of its ceiling counted for Zen 5 in cycles (its multiplies and FMAs on two
# pipes: AVX-512 1.5 cycles Cartesian, 2.625 polar, AVX2 3.25 and 5.25; bench/README.md), and the eps of
# the check points from every implementation. Build first:
#   cmake --build build --target geomint_energy_map_bench
# QUICK=1 shortens everything (a smoke run, ~6 s; numpy keeps 4096 trajectories,
# below which its per-step interpreter overhead dominates).
set -eu

BUILD=${1:-build}
HERE=$(cd "$(dirname "$0")" && pwd)
BIN=$BUILD/bin/geomint_energy_map_bench
PY=/usr/bin/python3   # Debian's interpreter: python3-numpy (the PATH python3 may lack numpy)

if [ "${QUICK:-0}" = 1 ]; then
  : "${BENCH_MIN_TIME:=0.05}" "${BENCH_REPS:=1}" "${NUMPY_N:=4096}" "${NUMPY_REPEAT:=1}"
else
  : "${BENCH_MIN_TIME:=0.2}" "${BENCH_REPS:=3}" "${NUMPY_N:=4096}" "${NUMPY_REPEAT:=3}"
fi

[ -x "$BIN" ] || { echo "$0: $BIN not found; build it: cmake --build $BUILD --target geomint_energy_map_bench" >&2; exit 2; }
[ -x "$PY" ] && "$PY" -c 'import numpy' 2>/dev/null ||
  { echo "$0: $PY with numpy not found (Debian: apt-get install python3-numpy)" >&2; exit 2; }

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT INT TERM

echo "== C++: $BIN (min time ${BENCH_MIN_TIME} s, ${BENCH_REPS} repetitions)" >&2
"$BIN" --benchmark_min_time="$BENCH_MIN_TIME" --benchmark_repetitions="$BENCH_REPS" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$TMP/cpp.json" 2>"$TMP/cpp.err" ||
  { cat "$TMP/cpp.err" >&2; exit 1; }
echo "== numpy: $HERE/peers/energy_map_numpy.py (${NUMPY_N} trajectories, median of ${NUMPY_REPEAT})" >&2
"$PY" "$HERE/peers/energy_map_numpy.py" --n "$NUMPY_N" --steps 20000 --repeat "$NUMPY_REPEAT" --json >"$TMP/numpy.json"

"$PY" - "$TMP/cpp.json" "$TMP/cpp.err" "$TMP/numpy.json" <<'EOF'
import json, sys

# Cycles per trajectory-step that each kernel's multiplies and FMAs need on the two multiply pipes of Zen 5,
# counted in its compiled object (bench/README.md); None where not counted.
CEILING_CYCLES = {("avx512", "cartesian"): 1.5, ("avx512", "polar"): 2.625,
                  ("avx2", "cartesian"): 3.25, ("avx2", "polar"): 5.25}
cpp = json.load(open(sys.argv[1]))
numpy = json.load(open(sys.argv[3]))

rows = []  # (implementation, coordinates, ns per step)
arithmetic = {}  # (isa, coordinates): ns per trajectory-step of the kernel's arithmetic alone, on this core
ns_per_cycle = None  # the calibrated clock: ns per dependent integer addition, one cycle each
for b in cpp["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    if b["run_name"] == "BM_ClockCalibration":
        ns_per_cycle = b["time_per_add"] * 1e9
        continue
    parts = b["run_name"].split("/")  # BM_{EnergyMapKernel,KernelArithmetic}/<isa>/<coords>, BM_EnergyMap{Scalar,Odeint}/<coords>
    kind, coords = parts[0], parts[-1]
    if kind == "BM_KernelArithmetic":
        arithmetic[(parts[1], coords)] = b["time_per_step"] * 1e9
        continue
    impl = {"BM_EnergyMapKernel": "batch kernel " + parts[1] if len(parts) == 3 else kind,
            "BM_EnergyMapScalar": "straightforward scalar loop",
            "BM_EnergyMapOdeint": "Boost.Odeint symplectic_euler"}.get(kind, kind)
    rows.append((impl, coords, b["time_per_step"] * 1e9))
for coords, ns in numpy["ns_per_step"].items():
    rows.append(("numpy (vectorised over trajectories)", coords, ns))

COORDS = ("cartesian", "polar")
best = {c: min(ns for impl, cc, ns in rows if cc == c and impl.startswith("batch kernel"))
        for c in COORDS if any(cc == c and impl.startswith("batch kernel") for impl, cc, ns in rows)}
ctx = cpp["context"]
print(f"# {ctx.get('workload', '')}; {ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, "
      f"load average {' '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))}")
print(f"# numpy {numpy['numpy']}: {numpy['trajectories']} trajectories x {numpy['steps']} steps, "
      f"median of {numpy['repeat']}; C++: median of repetitions, CPU time, one thread")
w = max(len(r[0]) for r in rows)
print(f"# clock: {1 / ns_per_cycle:.3f} GHz, calibrated in this run (a dependent chain of integer additions, "
      f"one cycle each: {ns_per_cycle:.4f} ns per addition)")
print(f"{'implementation':{w}s}  {'coordinates':11s}  {'ns/step/core':>12s}  {'cycles/step':>11s}  "
      f"{'x best kernel':>13s}  {'of own ceiling':>14s}  {'of Zen 5 count':>14s}")
for c in COORDS:
    for impl, cc, ns in sorted((r for r in rows if r[1] == c), key=lambda r: r[2]):
        ratio = f"{ns / best[c]:12.2f}x" if c in best else f"{'-':>13s}"
        cycles = ns / ns_per_cycle
        isa = impl.split()[-1] if impl.startswith("batch kernel") else None
        here, zen5 = arithmetic.get((isa, c)), CEILING_CYCLES.get((isa, c))
        own = f"{here / ns:14.1%}" if here else f"{'not counted' if isa else '':>14s}"
        counted = f"{zen5 / cycles:14.1%}" if zen5 else f"{'not counted' if isa else '':>14s}"
        print(f"{impl:{w}s}  {cc:11s}  {ns:12.3f}  {cycles:11.2f}  {ratio}  {own}  {counted}")
print("# own ceiling: the time of the kernel's vector arithmetic alone on this core, measured in this run "
      "(" + ", ".join(f"{isa} {c} {ns:.3f} ns" for (isa, c), ns in sorted(arithmetic.items())) + ")")

# eps of the check points: C++ lines "eps <coords> <impl> <x0> <y0> <eps>", numpy's JSON
print(f"\n# eps (000 eq. (50)) after {numpy['steps']} steps at the check points")
eps = {}
for line in open(sys.argv[2]):
    f = line.split()
    if len(f) == 6 and f[0] == "eps":
        eps.setdefault((f[1], float(f[3]), float(f[4])), []).append((f[2], float(f[5])))
for c, pts in numpy["eps"].items():
    for x, y, e in pts:
        eps.setdefault((c, x, y), []).append(("numpy", e))
for (c, x, y), vals in eps.items():
    ref = dict(vals).get("scalar")
    diffs = "  ".join(f"{impl} {v:.15g}" + (f" ({abs(v - ref) / abs(ref):.1e})" if ref and impl != "scalar" else "")
                      for impl, v in vals)
    print(f"{c:9s} ({x:g}, {y:g}): {diffs}")
print("# (relative difference to energy_map_scalar in parentheses; numpy sums without compensation)")
EOF
