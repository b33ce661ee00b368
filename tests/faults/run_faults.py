#!/usr/bin/env python3
"""The fault suite of one experiment: hostile input never crashes it, hangs it or makes it lie.

    run_faults.py BIN WORK [--seed S] [--runs N] [--kills N] [--checkpoint-set KEY=VALUE ...]

1. Every scene key from `BIN --list-keys --json`, set to each hostile value of its type (0, -1, NaN,
   +-Inf, 1e300, 1e-300, 2^31, 2^63 - 1, 2^63, an empty list, a wrong type, a list of them), through
   `BIN --plan --json --set KEY=VALUE`. Allowed outcomes: exit 0 with a plan whose numbers are finite
   and non-negative; exit 2 with one line on stderr that names a scene key (the key itself, or, for a
   condition across keys, the one it conflicts with). Never a signal, exit 1, a hang, or more lines.
2. A seeded sample of the accepted hostile settings is run for real on the quick scene, restricted
   to the studies that read the key, where its plan is estimated under a few seconds: exit 0 with
   finite results (summary.json and every CSV; a CSV's nan only where its row says why, see
   non_finite_in), exit 2 naming a key, or exit 4 (numerical failure) with DIR left as it was.
3. Every study with a checkpoint (a key `checkpoint.stop_after` it reads), on the quick scene with a
   save after every round (checkpoint.interval = 0) and the --checkpoint-set values on top (to keep a
   long study short): killed (SIGKILL) at seeded random moments and resumed, the CSVs are byte-identical to an uninterrupted run; its checkpoint
   corrupted, truncated and tampered with, --resume exits 2 naming the file.
Prints one line per failure and a tally; exits 1 if anything failed.
"""
import argparse
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "regression"))
import same_csv  # noqa: E402

TIMEOUT_S = 30  # a --plan or a refused run that takes longer hangs
SCALARS = ["0", "-1", "nan", "inf", "-inf", "1e300", "1e-300", "2147483648", "9223372036854775807",
           "9223372036854775808", "0.5"]
NON_FINITE = re.compile(r"(?<![A-Za-z_])(-?nan|-?inf|infinity)(?![A-Za-z_])", re.IGNORECASE)

failures = []


def fail(what):
    failures.append(what)
    print("FAIL " + what, flush=True)


def run(cmd, timeout=TIMEOUT_S, cwd=None, env=None):
    """(returncode, stdout, stderr); returncode None on a timeout (the process group is killed)."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd, env=env,
                         start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
        return None, out, err
    return p.returncode, out, err


def hostile_values(k):
    """The hostile values of a key's type, as TOML text."""
    t = k["type"]
    wrong = ['"text"', "true", "[]", "[[1.0]]"]
    if t in ("real", "integer"):
        return SCALARS + wrong
    if t == "reals":
        n = max(1, k.get("min_len", 0))
        return ["[]", "1.0", '["a"]', "[[1.0]]"] + ["[" + ", ".join([v] * n) + "]" for v in SCALARS]
    if t == "real_rows":
        n, r = max(1, k.get("min_len", 0)), max(1, k.get("row_len", 1))
        rows = lambda v: "[" + ", ".join(["[" + ", ".join([v] * r) + "]"] * n) + "]"
        return ["[]", "1.0", "[1.0]", "[[]]"] + [rows(v) for v in SCALARS]
    if t == "boolean":
        return ["0", '"true"', "[]", "nan"]
    if t == "text":
        return ['""', '"no-such-choice"', "0", "[]", '"' + "x" * 10000 + '"']
    if t == "texts":
        return ["[]", '["no-such-choice"]', '"one"', "[0]", "[[]]"]
    raise SystemExit(f"unknown key type {t} of {k['key']}")


def names_a_key(err, key, keys):
    """A refusal names the key, or (a condition across keys) some scene key or section."""
    if key in err:
        return True
    return any(re.search(r"(?<![\w.])" + re.escape(k["key"]) + r"(?![\w])", err) for k in keys)


def finite_plan(plan):
    for st in plan["studies"]:
        for f in ("steps", "force_evals", "memory_bytes", "wall_s"):
            v = st.get(f)
            if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                return f"{st['study']}.{f} = {v}"
    return None


def check_plan_faults(binary, keys, scene_args):
    """Part 1; returns the accepted (key, value) settings."""
    accepted = []
    for k in keys:
        for v in hostile_values(k):
            setting = f"{k['key']}={v}"
            rc, out, err = run([binary, *scene_args, "--plan", "--json", "--set", setting])
            label = f"--plan --set {setting[:80]}"
            if rc is None:
                fail(f"{label}: hangs (> {TIMEOUT_S} s)")
            elif rc < 0:
                fail(f"{label}: killed by signal {-rc}: {err.strip()[-300:]}")
            elif rc == 0:
                try:
                    bad = finite_plan(json.loads(out))
                except (json.JSONDecodeError, KeyError) as e:
                    bad = f"unreadable plan ({e})"
                if bad:
                    fail(f"{label}: exit 0 with {bad}")
                else:
                    accepted.append((k["key"], v))
            elif rc == 2:
                lines = err.strip().splitlines()
                if len(lines) != 1:
                    fail(f"{label}: exit 2 with {len(lines)} lines on stderr: {err.strip()[:300]}")
                elif not names_a_key(err, k["key"], keys):
                    fail(f"{label}: exit 2 names no scene key: {err.strip()[:300]}")
            else:
                fail(f"{label}: exit {rc}: {err.strip()[:300]}")
    return accepted


def non_finite_in(out_dir):
    """The first non-finite value of summary.json or a CSV (timing files aside). A CSV marks a value
    that does not exist as nan, with a flag in the same row that says why: column `<what>_<part>`
    beside `diverged_<part>` = 1 (energy_map's map.csv: eps_polar where diverged_polar = 1), or
    column `<method>_<what>` beside `<method>_beyond_bound` = 1 (ti_drift's closed forms)."""
    summary = Path(out_dir) / "summary.json"
    m = NON_FINITE.search(summary.read_text())
    if m:
        return f"summary.json: '{m.group(0)}'"
    for f in sorted(Path(out_dir).glob("*.csv")):
        if f.name.startswith("timing"):
            continue
        lines = f.read_text().splitlines()
        head = lines[0].split(",") if lines else []
        flags = lambda c: ["diverged_" + c.rsplit("_", 1)[-1], c.split("_", 1)[0] + "_beyond_bound"]
        flag = {i: [head.index(g) for g in flags(c) if g in head and g != c] for i, c in enumerate(head)}
        for n, line in enumerate(lines[1:], 2):
            cells = line.split(",")
            for i, cell in enumerate(cells):
                if NON_FINITE.search(cell):
                    if any(g < len(cells) and cells[g].strip() == "1" for g in flag.get(i, [])):
                        continue
                    return f"{f.name} line {n}, column {head[i] if i < len(head) else i}: '{cell.strip()}'"
    return None


def check_real_runs(binary, keys, accepted, work, rng, count):
    """Part 2: a sample of the accepted settings, run for real on the quick scene if short."""
    rng.shuffle(accepted)
    used_by = {k["key"]: k["used_by"] for k in keys}
    done = 0
    for key, v in accepted:
        if done == count:
            break
        setting = f"{key}={v}"
        studies = [a for st in used_by.get(key, []) for a in ("--study", st)]
        rc, out, _ = run([binary, "--quick", *studies, "--plan", "--json", "--set", setting])
        if rc != 0:
            continue  # refused for the quick scene: part 1 checks refusals
        plan = json.loads(out)
        if not plan["all_estimated"] or plan["wall_s"] > 3.0:
            continue
        done += 1
        out_dir = work / f"run-{done}"
        shutil.rmtree(out_dir, ignore_errors=True)
        label = f"--quick {' '.join(studies)} --set {setting[:80]}"
        t0 = time.monotonic()
        rc, _, err = run([binary, "--quick", *studies, "--threads", "2", "--set", setting, "--out", str(out_dir)], timeout=120)
        wall = time.monotonic() - t0
        if rc is None:
            fail(f"{label}: hangs (> 120 s; planned {plan['wall_s']:.2f} s)")
        elif rc == 0:
            bad = non_finite_in(out_dir)
            if bad:
                fail(f"{label}: exit 0 with a non-finite value in {bad}")
        elif rc == 2:
            if not names_a_key(err, key, keys):
                fail(f"{label}: exit 2 names no scene key: {err.strip()[:300]}")
        elif rc == 4:
            if out_dir.exists():
                fail(f"{label}: exit 4 but {out_dir} was written")
        else:
            fail(f"{label}: exit {rc}: {err.strip()[-300:]}")
        print(f"  real run {done}: {label} -> exit {rc} ({wall:.1f} s)", flush=True)
    return done


def csv_bytes(out_dir):
    """The CSVs of a run to compare: all but timing*.csv (wall times), and of a work-precision set
    cost_*.csv every cell but its wall times (tests/regression/same_csv.py)."""
    return {f.name: same_csv.cells(f) if f.name.startswith("cost_") else f.read_bytes()
            for f in sorted(Path(out_dir).glob("*.csv")) if not f.name.startswith("timing")}


def checkpointed_studies(keys):
    """(the key checkpoint.stop_after, study) for every study with a checkpoint: those that read that key."""
    return sorted({(k["key"], st) for k in keys if k["key"].endswith("checkpoint.stop_after") for st in k["used_by"]})


def check_checkpoints(binary, keys, work, rng, kills, settings):
    """Part 3: kill-and-resume and damaged checkpoints, for every study with a checkpoint."""
    studies = checkpointed_studies(keys)
    # a save after every round, so that a kill lands between saves
    settings = (["checkpoint.interval=0"] if any(k["key"] == "checkpoint.interval" for k in keys) else []) + settings
    for key, study in studies:
        base = [binary, "--quick", "--study", study] + [a for s in settings for a in ("--set", s)]
        ref = work / f"ckpt-{study}-ref"
        shutil.rmtree(ref, ignore_errors=True)
        t0 = time.monotonic()
        rc, _, err = run([*base, "--out", str(ref)], timeout=300)
        duration = time.monotonic() - t0
        if rc != 0:
            fail(f"{study}: the uninterrupted run exits {rc}: {err.strip()[-300:]}")
            continue
        want = csv_bytes(ref)
        for i in range(kills):
            out = work / f"ckpt-{study}-kill{i}"
            shutil.rmtree(out, ignore_errors=True), shutil.rmtree(str(out) + ".partial", ignore_errors=True)
            at = rng.uniform(0.1, 0.95) * duration
            p = subprocess.Popen([*base, "--threads", str(1 + i % 2), "--out", str(out)],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(at)
            p.send_signal(signal.SIGKILL)
            p.wait()
            if out.exists() and not (out / "run.json").exists():
                fail(f"{study}: killed at {at:.2f} s, {out} exists without run.json")
            rc, _, err = run([*base, "--threads", str(2 - i % 2), "--resume", "--out", str(out)], timeout=300)
            if rc != 0:
                fail(f"{study}: resumed after a kill at {at:.2f} s: exit {rc}: {err.strip()[-300:]}")
            elif csv_bytes(out) != want:
                fail(f"{study}: resumed after a kill at {at:.2f} s: the CSVs differ from the uninterrupted run")
            elif list(Path(str(out) + ".partial").glob("*")) or list(out.glob("*.tmp*")):
                fail(f"{study}: resumed after a kill at {at:.2f} s: leftover staging or temporary files")
            print(f"  {study}: killed at {at:.2f} s of {duration:.2f} s, resumed -> exit {rc}", flush=True)
        for damage, done in (("corrupt", "corrupted"), ("truncate", "truncated"), ("tamper", "tampered with")):
            out = work / f"ckpt-{study}-{damage}"
            partial = Path(str(out) + ".partial")
            shutil.rmtree(out, ignore_errors=True), shutil.rmtree(partial, ignore_errors=True)
            # (one thread: a round of one task, so that a quick scene of two tasks still stops after the first)
            rc, _, err = run([*base, "--threads", "1", "--set", f"{key}=1", "--out", str(out)], timeout=300)
            headers = sorted(partial.glob("*.checkpoint.json"))
            if rc != 3 or not headers:
                fail(f"{study}: --set {key}=1 exits {rc} with checkpoint(s) {headers}: {err.strip()[-300:]}")
                continue
            header = headers[0]
            logs = sorted(f for f in partial.glob(header.name.replace(".json", "") + ".*") if f != header)
            target = header
            if damage == "corrupt":
                header.write_text(header.read_text()[: len(header.read_text()) // 2])
            elif damage == "truncate":
                if not logs:
                    fail(f"{study}: a checkpoint without a record log beside {header.name}")
                    continue
                target = logs[0]
                os.truncate(target, max(0, target.stat().st_size // 2 - 3))
            else:  # a count beyond what the run has
                text = header.read_text()
                new = re.sub(r'("(?:tasks|batches)_done"\s*:\s*)\d+', r"\g<1>1000000000", text, count=1)
                if new == text:
                    fail(f"{study}: {header.name} has no tasks_done or batches_done to tamper with")
                    continue
                header.write_text(new)
            rc, _, err = run([*base, "--resume", "--out", str(out)], timeout=300)
            if rc != 2 or target.name not in err:
                fail(f"{study}: --resume with {target.name} {done}: exit {rc}, stderr: {err.strip()[-300:]}")
            print(f"  {study}: {target.name} {done} -> exit {rc}", flush=True)
    return len(studies)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("work", type=Path)
    ap.add_argument("--seed", type=int, default=20261125)
    ap.add_argument("--runs", type=int, default=6, help="real runs of accepted hostile settings")
    ap.add_argument("--kills", type=int, default=2, help="kill-and-resume runs per checkpointed study")
    ap.add_argument("--checkpoint-set", action="append", default=[], metavar="KEY=VALUE",
                    help="a --set for the checkpoint runs (part 3), to keep a long study short")
    args = ap.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    rng = random.Random(args.seed)
    rc, out, err = run([args.binary, "--list-keys", "--json"])
    if rc != 0:
        sys.exit(f"{args.binary} --list-keys --json: exit {rc}: {err}")
    keys = json.loads(out)
    t0 = time.monotonic()
    accepted = check_plan_faults(args.binary, keys, [])
    t1 = time.monotonic()
    runs = check_real_runs(args.binary, keys, accepted, args.work, rng, args.runs)
    t2 = time.monotonic()
    studies = check_checkpoints(args.binary, keys, args.work, rng, args.kills, args.checkpoint_set)
    t3 = time.monotonic()
    tried = sum(len(hostile_values(k)) for k in keys)
    print(f"{Path(args.binary).name}: {len(keys)} keys, {tried} hostile settings through --plan "
          f"({len(accepted)} accepted, {t1 - t0:.0f} s); {runs} real runs ({t2 - t1:.0f} s); "
          f"{studies} checkpointed studies killed, resumed and damaged ({t3 - t2:.0f} s); {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
