#!/usr/bin/env python3
"""plan_rates.py RESULTS BUILD [--check]: --plan's rates (experiments/plan_rates.toml) measured on the paper
scenes' runs in RESULTS (make figure-runs) by the binaries in BUILD, and the table rewritten with them.

A rate with `summary = "<results> <key>"` is the time that run's summary.json holds under the key (`*`
matches any name: the largest of the matches, or their mean with combine = "mean"); `when = "<results> <key>
<value>"` takes it only from a run whose key has that value (a kernel of the CPU's instruction set). A rate with
`study = "<results> <study>"` is the one at which that study's plan of the same scene and threads
(`--plan --json`) takes as long as the study ran: the plan's wall time less its fixed overhead is linear in the
rate. A study that ran under 50 ms (tests/regression/check_plans.py's bound) keeps its rate, too short to
measure. With --check, nothing is written: every source must resolve (key, study, run) and the script exits 1
naming those that do not (the table's test on the quick runs)."""
import json
import pathlib
import subprocess
import sys
import tomllib

TABLE = pathlib.Path(__file__).resolve().parent.parent / "experiments" / "plan_rates.toml"
SHORTEST_S = 0.05


def lookup(tree, parts):
    """The values under the dotted key parts, `*` matching every name of a record."""
    if not parts:
        return [tree]
    if not isinstance(tree, dict):
        return []
    names = tree.keys() if parts[0] == "*" else [parts[0]] if parts[0] in tree else []
    return [v for n in names for v in lookup(tree[n], parts[1:])]


def from_summary(results, source, combine):
    run, key = source.split(" ", 1)
    values = [v for v in lookup(json.loads((results / run / "summary.json").read_text()), key.split("."))
              if isinstance(v, (int, float)) and v > 0]
    if not values:
        raise LookupError(f"no positive value under {key} in {run}/summary.json")
    return max(values) if combine == "largest" else sum(values) / len(values)


def from_study(results, build, source, ns_now):
    run_dir, study = source.split(" ")
    run = json.loads((results / run_dir / "run.json").read_text())
    if study not in run["study_wall_s"]:
        raise LookupError(f"{run_dir}/run.json has no study {study}")
    argv = run["command"].split()  # the run's command without its --out and --threads
    dropped = {i + d for i, a in enumerate(argv) if a in ("--out", "--threads") for d in (0, 1)}
    argv = [str(build / "bin" / run["experiment"])] + [a for i, a in enumerate(argv) if i and i not in dropped]
    plan = json.loads(subprocess.run(argv + ["--threads", str(run["threads"]), "--plan", "--json"],
                                     capture_output=True, text=True, check=True).stdout)
    planned = next(s for s in plan["studies"] if s["study"] == study)
    if f"({ns_now:.3g} ns on " not in planned["note"]:  # (runner/plan_rates.cpp's note)
        raise LookupError(f"the binary's plan of {study} does not use {ns_now:.3g} ns: rebuild {build} from this table")
    planned = planned["wall_s"] - plan["study_overhead_s"]
    ran = run["study_wall_s"][study]
    if ran < SHORTEST_S:
        return None  # too short to measure: the rate stays
    return ns_now * (ran - plan["study_overhead_s"]) / planned


def when_holds(results, when):
    run, key, value = when.split(" ")
    found = lookup(json.loads((results / run / "summary.json").read_text()), key.split("."))
    return bool(found) and str(found[0]) == value


def machine(results, run):
    """The CPU of a run, with the widest instruction set its energy-map kernel found (when that run is there)."""
    isa = lookup(json.loads((results / "energy_map" / "summary.json").read_text()), ["timing", "kernel_isa_name"]) \
        if (results / "energy_map" / "summary.json").exists() else []
    return f"{run['machine']['cpu']}{f' ({isa[0]})' if isa else ''}, {run['machine']['logical_cores']} logical cores"


def quoted(text):
    return json.dumps(text, ensure_ascii=False)


def main():
    results, build = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    check = "--check" in sys.argv[3:]
    text = TABLE.read_text(encoding="utf-8")
    header = text[:text.index("[rates.")]
    rates = tomllib.loads(text)["rates"]
    problems, lines = [], [header.rstrip("\n")]
    for name, r in rates.items():
        try:
            if r.get("when") and not when_holds(results, r["when"]):
                value, why = None, "another instruction set ran"
            elif "summary" in r:
                value, why = from_summary(results, r["summary"], r.get("combine", "largest")), "measured"
            else:
                value = from_study(results, build, r["study"], r["ns_per_step"])
                why = "measured" if value is not None else "study under 50 ms: kept"
        except (LookupError, OSError, subprocess.CalledProcessError, ValueError) as e:
            problems.append(f"{name}: {e}")
            value, why = None, "source missing"
        print(f"plan_rates: {name:42s} {r['ns_per_step']:>10.4g} -> "
              f"{'' if value is None else f'{value:.3g}':>10s}  ({why})")
        if value is not None:
            run = json.loads((results / (r.get("summary") or r["study"]).split(" ")[0] / "run.json").read_text())
            rounded = float(f"{value:.3g}")
            r["ns_per_step"] = int(rounded) if rounded == int(rounded) else rounded
            r["cpu"] = machine(results, run)
            r["measured"] = run["end_utc"][:10]
        lines.append(f"\n[rates.{quoted(name)}]")
        lines += [f"{k} = {v if isinstance(v, (int, float)) else quoted(v)}" for k, v in r.items()]
    for p in problems:
        print("plan_rates: cannot measure", p)
    if not check and not problems:
        TABLE.write_text("\n".join(lines) + "\n", encoding="utf-8")
        print(f"plan_rates: wrote {TABLE}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
