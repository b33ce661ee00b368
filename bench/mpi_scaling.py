#!/usr/bin/env python3
"""Strong scaling of the energy map (000 Fig. 6) under MPI, and its projection to a cluster.

    bench/mpi_scaling.py BUILD OUT [--t-max T]

Runs the map study of the paper scene (the 201 x 201 grid, t_max shortened to T: the same work per
trajectory-step, a fifth of the time) with 1 and 2 ranks of 1 and 2 threads, back to back in one
invocation (scripts/mpirun.sh, the project's mpirun line), so that the times compare as ratios.
It checks that every run wrote the same map.csv, and writes OUT/summary.json: per configuration
the map's wall time, each rank's busy time (its share of the batches) and exchange time (waiting
for, gathering and decoding the other ranks' results), rank 0's checkpoint writes, the speed-up
against 1 rank x 1 thread; then, from these measurements, the projected wall time of the cluster
scene experiments/energy_map/fine.toml on 64 and 1024 cores:

    wall(P) = S c / P / e + R x + W

S: the fine scene's trajectory-steps (its --plan); c: the measured time per trajectory-step and
core (1 rank x 1 thread); e: the parallel efficiency measured with 2 ranks x 1 thread (busy time
only: what the split itself costs); R x: its rounds times the measured exchange time per gathered
byte (the fastest exchange of the 2-rank run, i.e. without waiting) times the bytes it gathers per
round and rank; W: the checkpoint writes, at the measured time per byte. The exchange here goes
through shared memory; on a cluster's network it is slower, so the summary also gives the
exchange term at 100 times the measured cost per byte. OUT/run.json records the machine and the
commands. Timings are measurements of this machine, never asserted.
"""
import argparse
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = [(1, 1), (1, 2), (2, 1), (2, 2)]  # (ranks, threads)
BATCH = 64  # kEnergyMapBatch: trajectories per task
RECORD_DOUBLES = 1 + 2 * BATCH  # a batch's record in the exchange: its length, then (eps, diverge_step) per point


def run_map(build, out, ranks, threads, t_max, log):
    args = [str(build / "bin" / "energy_map"), "--study", "map", "--set", f"t_max={t_max}",
            "--threads", str(threads), "--out", str(out)]
    cmd = ([str(ROOT / "scripts" / "mpirun.sh"), "-np", str(ranks)] + args) if ranks > 1 else args
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               GEOMINT_MPI_OVERSUBSCRIBE="1")
    with open(log, "w") as err:
        subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=err, check=True)
    return cmd, json.loads((out / "run.json").read_text())


def plan_steps(build, scene):
    out = subprocess.run([str(build / "bin" / "energy_map"), "--scene", str(ROOT / scene), "--plan", "--json"],
                         capture_output=True, text=True, check=True).stdout
    return next(s for s in json.loads(out)["studies"] if s["study"] == "map")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build", type=Path)
    ap.add_argument("out", type=Path)
    ap.add_argument("--t-max", type=float, default=10000.0)
    args = ap.parse_args()
    work = args.out.with_name(args.out.name + ".runs")
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)

    runs, commands, maps = [], [], []
    for ranks, threads in CONFIGS:
        tag = f"{ranks}x{threads}"
        print(f"mpi_scaling: map with {ranks} rank(s) x {threads} thread(s)", file=sys.stderr, flush=True)
        cmd, run = run_map(args.build, work / tag, ranks, threads, args.t_max, work / f"{tag}.stderr")
        commands.append(" ".join(cmd))
        maps.append((work / tag / "map.csv").read_bytes())
        runs.append({"ranks": ranks, "threads": threads, "cores": ranks * threads, "wall_s": run["study_wall_s"]["map"],
                     "rank_busy_s": run["rank_busy_s"], "rank_exchange_s": run["rank_exchange_s"],
                     "checkpoint_write_s": run["checkpoint_write_s"]})
    if any(m != maps[0] for m in maps):
        sys.exit("mpi_scaling: the configurations wrote different map.csv files")
    base = runs[0]["wall_s"]
    for r in runs:
        r["speedup"] = base / r["wall_s"]
        r["efficiency"] = r["speedup"] / r["cores"]

    # The measured constants.
    quick = plan_steps(args.build, "experiments/energy_map/energy_map.toml")
    steps_here = quick["steps"] * args.t_max / 50000.0  # (the paper scene's plan is for t_max = 50 000)
    batches_here = quick["tasks"]
    c = base / steps_here  # s per trajectory-step and core, 1 rank x 1 thread
    two = next(r for r in runs if (r["ranks"], r["threads"]) == (2, 1))
    e = (base / 2) / max(two["rank_busy_s"])  # the split's own efficiency (busy time of the slower rank)
    rounds_here = 2 * 32  # checkpointed_map: 32 rounds per coordinate system (round = batches / 32)
    exchanged_here = batches_here * RECORD_DOUBLES * 8  # bytes every rank receives over the map
    x_per_byte = min(two["rank_exchange_s"]) / exchanged_here
    write_per_byte = runs[0]["checkpoint_write_s"] / exchanged_here  # rank 0 writes each record once

    fine = plan_steps(args.build, "experiments/energy_map/fine.toml")
    fine_bytes = fine["tasks"] * RECORD_DOUBLES * 8
    projection = []
    for cores in (64, 1024):
        compute = fine["steps"] * c / cores / e
        exchange = fine_bytes * x_per_byte
        projection.append({"cores": cores, "wall_s": compute + exchange + fine_bytes * write_per_byte,
                           "compute_s": compute, "exchange_s": exchange, "exchange_s_at_100x": 100 * exchange,
                           "checkpoint_write_s": fine_bytes * write_per_byte,
                           "core_hours": cores * (compute + exchange) / 3600})
    summary = {
        "experiment": "mpi_scaling",
        "map": {"scene": "experiments/energy_map/energy_map.toml", "t_max": args.t_max, "trajectory_steps": steps_here,
                "batches": batches_here, "rounds": rounds_here, "exchanged_bytes": exchanged_here},
        "runs": runs,
        "measured": {"ns_per_trajectory_step_core": c * 1e9, "split_efficiency_2_ranks": e,
                     "exchange_ns_per_byte": x_per_byte * 1e9, "checkpoint_write_ns_per_byte": write_per_byte * 1e9,
                     "imbalance_2_ranks": max(two["rank_busy_s"]) / (sum(two["rank_busy_s"]) / 2) - 1},
        "fine": {"scene": "experiments/energy_map/fine.toml", "trajectory_steps": fine["steps"], "batches": fine["tasks"],
                 "exchanged_bytes": fine_bytes, "core_hours_1_core": fine["steps"] * c / 3600,
                 "projection": projection},
    }
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    cpu = next((l.split(":", 1)[1].strip() for l in Path("/proc/cpuinfo").read_text().splitlines()
                if l.startswith("model name")), platform.processor())
    (args.out / "run.json").write_text(json.dumps({"commands": commands, "cpu": cpu, "cores": os.cpu_count(),
                                                   "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())},
                                                  indent=2) + "\n")
    shutil.rmtree(work)
    for r in runs:
        print(f"{r['ranks']} x {r['threads']}: map {r['wall_s']:.3g} s, speed-up {r['speedup']:.2f}, "
              f"busy {', '.join(f'{b:.3g}' for b in r['rank_busy_s'])} s")
    for p in projection:
        print(f"fine scene on {p['cores']} cores: {p['wall_s'] / 60:.3g} min ({p['core_hours']:.3g} core-hours)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
