#!/usr/bin/env python3
"""Strong scaling of the energy map (000 Fig. 6) under MPI, and its projection to a cluster.

    bench/mpi_scaling.py BUILD OUT [--t-max T]

Runs the map study of the paper scene (the 201 x 201 grid, t_max shortened to T: the same work per
trajectory-step, a fifth of the time) with 1 and 2 ranks of 1 and 2 threads, each --repeats times (3),
the configurations interleaved in one invocation (scripts/mpirun.sh, the project's mpirun line), so
that the times compare as ratios of medians with their range, and checks that every run wrote the same
map.csv with the same kernel (instruction set). A configuration with more workers than the machine
has cores is marked oversubscribed. Then the cluster scene
experiments/energy_map/fine.toml with 2 ranks for 2 steps (t_max = 2 dt): every exchange and
checkpoint of the fine map at its full size (the same batches, rounds and records), almost no
computation. OUT/summary.json gives per run the map's wall time, each rank's busy time (its share
of the batches) and exchange time (waiting for, gathering and decoding the other ranks' results),
rank 0's checkpoint writes and the speed-up against 1 rank x 1 thread; and the projected wall
time of the fine scene on N ranks x 4 threads, 64 and 1024 cores:

    wall = rounds x ceil(ceil(round / N) / 4) x t_batch / e + X + W

with the rounds of checkpointed_map (runner/checkpoint.hpp: default_round, repeated here), t_batch
= 64 trajectories x J steps x c, c the measured time per trajectory-step and core (1 rank x 1
thread), e the efficiency of 2 ranks x 1 thread (busy time only: what the split itself costs), X
and W the exchange (the rank that waited least) and checkpoint writes measured at the fine map's
size. busy_fraction is (steps x c / cores) / (rounds' depth x t_batch) = (steps x c / cores) / (compute x e): the
share of the workers' batch slots that hold a batch, what the rounds lose to whole batches per thread (not the
split, the exchange or the checkpoints). The exchange went through shared memory here; on a cluster network it is slower, roughly
in proportion to the bytes each rank receives, which the summary gives. OUT/run.json records the
machine and the commands. Timings are measurements of this machine, never asserted.
"""
import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = [(1, 1), (1, 2), (2, 1), (2, 2)]  # (ranks, threads)
BATCH = 64  # kEnergyMapBatch: trajectories per task
RECORD_DOUBLES = 1 + 2 * BATCH  # a batch's record in the exchange: its length, then (eps, diverge_step) per point


def run_map(build, out, ranks, threads, t_max, log, scene="experiments/energy_map/energy_map.toml"):
    args = [str(build / "bin" / "energy_map"), "--scene", str(ROOT / scene), "--study", "map",
            "--set", f"t_max={t_max}", "--threads", str(threads), "--out", str(out)]
    cmd = ([str(ROOT / "scripts" / "mpirun.sh"), "-np", str(ranks)] + args) if ranks > 1 else args
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               GEOMINT_MPI_OVERSUBSCRIBE="1")
    with open(log, "w") as err:
        subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=err, check=True)
    return cmd, json.loads((out / "run.json").read_text())


def default_round(n, workers):  # runner/checkpoint.hpp: default_round
    return max(1, (n + 31) // 32, min(4 * workers, (n + 7) // 8))


def plan_steps(build, scene):
    out = subprocess.run([str(build / "bin" / "energy_map"), "--scene", str(ROOT / scene), "--plan", "--json"],
                         capture_output=True, text=True, check=True).stdout
    return next(s for s in json.loads(out)["studies"] if s["study"] == "map")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build", type=Path)
    ap.add_argument("out", type=Path)
    ap.add_argument("--t-max", type=float, default=10000.0)
    ap.add_argument("--repeats", type=int, default=3, help="runs of each configuration, interleaved (default 3)")
    args = ap.parse_args()
    work = args.out.with_name(args.out.name + ".runs")
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)

    # Every configuration args.repeats times, the configurations interleaved in an order rotated each round (as
    # the timing protocol of runner/timing.hpp), so that a burst of load hits all of them alike.
    measured, commands, maps, isas = {c: [] for c in CONFIGS}, [], [], set()
    for k in range(args.repeats):
        for ranks, threads in CONFIGS[k % len(CONFIGS):] + CONFIGS[:k % len(CONFIGS)]:
            tag = f"{ranks}x{threads}"
            print(f"mpi_scaling: round {k + 1}: map with {ranks} rank(s) x {threads} thread(s)", file=sys.stderr, flush=True)
            cmd, run = run_map(args.build, work / tag, ranks, threads, args.t_max, work / f"{tag}.stderr")
            if k == 0:
                commands.append(" ".join(cmd))
            maps.append((work / tag / "map.csv").read_bytes())
            isas.add(json.loads((work / tag / "summary.json").read_text())["timing"]["kernel_isa"])
            measured[(ranks, threads)].append(run)
    if any(m != maps[0] for m in maps):
        sys.exit("mpi_scaling: the configurations wrote different map.csv files")
    if len(isas) != 1:
        sys.exit(f"mpi_scaling: the runs used different kernels ({', '.join(sorted(isas))})")
    runs = []
    for (ranks, threads), rs in measured.items():
        walls = sorted(r["study_wall_s"]["map"] for r in rs)
        typical = min(rs, key=lambda r: abs(r["study_wall_s"]["map"] - statistics.median(walls)))  # (its busy times)
        runs.append({"ranks": ranks, "threads": threads, "cores": ranks * threads, "wall_s": statistics.median(walls),
                     "wall_s_range": {"min": walls[0], "max": walls[-1]}, "repeats": len(walls),
                     "oversubscribed": True if ranks * threads > os.cpu_count() else None,  # (null: not)
                     "rank_busy_s": typical["rank_busy_s"], "rank_exchange_s": typical["rank_exchange_s"],
                     "checkpoint_write_s": typical["checkpoint_write_s"]})
    base, base_range = runs[0]["wall_s"], runs[0]["wall_s_range"]
    for r in runs:
        r["speedup"] = base / r["wall_s"]
        r["speedup_range"] = {"min": base_range["min"] / r["wall_s_range"]["max"],
                              "max": base_range["max"] / r["wall_s_range"]["min"]}
        r["efficiency"] = r["speedup"] / r["cores"]

    # The measured constants.
    paper = plan_steps(args.build, "experiments/energy_map/energy_map.toml")
    steps_here = paper["steps"] * args.t_max / 50000.0  # (the paper scene's plan is for t_max = 50 000)
    c = base / steps_here  # s per trajectory-step and core, 1 rank x 1 thread (the median run)
    c_range = {k: v / steps_here for k, v in base_range.items()}
    two = next(r for r in runs if (r["ranks"], r["threads"]) == (2, 1))
    e = (base / 2) / max(two["rank_busy_s"])  # the split's own efficiency (busy time of the slower rank)

    print("mpi_scaling: the fine map's exchanges and checkpoints, 2 ranks x 1 thread, 2 steps", file=sys.stderr, flush=True)
    cmd, fine_run = run_map(args.build, work / "fine", 2, 1, 0.4, work / "fine.stderr", "experiments/energy_map/fine.toml")
    commands.append(" ".join(cmd))
    X, W = min(fine_run["rank_exchange_s"]), fine_run["checkpoint_write_s"]
    fine = plan_steps(args.build, "experiments/energy_map/fine.toml")
    per_map = int(fine["tasks"]) // 2
    t_batch = fine["steps"] / fine["tasks"] * c
    projection = []
    for ranks, threads in ((16, 4), (256, 4)):
        r = default_round(per_map, ranks * threads)
        depth = 0
        for first in range(0, per_map, r):  # the rounds of one map: each rank's share, ceil(share / T) deep
            depth += math.ceil(math.ceil(min(r, per_map - first) / ranks) / threads)
        compute = 2 * depth * t_batch / e
        projection.append({"ranks": ranks, "threads": threads, "cores": ranks * threads, "round": r,
                           "wall_s": compute + X + W, "compute_s": compute, "exchange_s": X, "checkpoint_write_s": W,
                           "overhead_s": X + W,
                           "busy_fraction": fine["steps"] * c / (ranks * threads) / (2 * depth * t_batch),
                           "wall_s_range": {k: compute * v / c + X + W for k, v in c_range.items()},
                           "core_hours": ranks * threads * (compute + X + W) / 3600})
    summary = {
        "experiment": "mpi_scaling",
        "machine_cores": os.cpu_count(),
        "map": {"scene": "experiments/energy_map/energy_map.toml", "t_max": args.t_max, "trajectory_steps": steps_here,
                "batches": paper["tasks"]},
        "runs": runs,
        "repeats": args.repeats,
        "kernel_isa": isas.pop(),
        "measured": {"ns_per_trajectory_step_core": c * 1e9,
                     "ns_per_trajectory_step_core_range": {k: v * 1e9 for k, v in c_range.items()},
                     "split_efficiency_2_ranks": e,
                     "imbalance_2_ranks": max(two["rank_busy_s"]) / (sum(two["rank_busy_s"]) / 2) - 1,
                     "fine_exchange_s": X, "fine_checkpoint_write_s": W,
                     "fine_exchange_rank_s": fine_run["rank_exchange_s"]},
        "fine": {"scene": "experiments/energy_map/fine.toml", "trajectory_steps": fine["steps"], "batches": fine["tasks"],
                 "received_bytes_per_rank": fine["tasks"] * RECORD_DOUBLES * 8,
                 "core_hours_1_core": fine["steps"] * c / 3600, "plan_memory_bytes_per_rank": fine["memory_bytes"],
                 "projection": projection},
    }
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    first = json.loads((work / "1x1" / "run.json").read_text())  # the binary and machine of every run here
    (args.out / "run.json").write_text(json.dumps({"build": first["build"], "machine": first["machine"],
                                                   "threads": "1 and 2", "ranks": "1 and 2", "commands": commands,
                                                   "end_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())},
                                                  indent=2) + "\n")
    shutil.rmtree(work)
    for r in runs:
        print(f"{r['ranks']} x {r['threads']}: map {r['wall_s']:.3g} s (median of {r['repeats']}), speed-up {r['speedup']:.2f}"
              f" ({r['speedup_range']['min']:.2f}-{r['speedup_range']['max']:.2f})"
              f"{', oversubscribed' if r['oversubscribed'] else ''}, "
              f"busy {', '.join(f'{b:.3g}' for b in r['rank_busy_s'])} s")
    for p in projection:
        print(f"fine scene on {p['cores']} cores: {p['wall_s'] / 60:.3g} min ({p['core_hours']:.3g} core-hours)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
