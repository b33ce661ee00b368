#!/usr/bin/env python3
"""Mutation testing: does the test suite notice a plausible bug?

Applies each mutant of mutants.toml alone to the source tree this script lives in, rebuilds,
runs ctest and records whether a test failed (killed) or none did (survived); the original file
is restored after each mutant, also on Ctrl-C. Run it in a clean checkout or a worktree, not in a
tree with work in progress:

    git worktree add ../geomint-mutation && cd ../geomint-mutation
    tests/mutation/run_mutants.py --build build-mutation

A rebuild and a ctest run per mutant take ten seconds to two and a half minutes on two cores, so it is run on demand,
not by `make test`. The build compiles each test file on its own (see configure). Before the
mutants, the unmodified tree must build and pass; its test times order the suite. For each mutant,
the library's test executables are built and run one after the other (LIBRARY_TESTS), then the
whole tree is built and its tests under --slow seconds run, then the slower ones, each step only
for a mutant the earlier ones did not kill. A test that waits on a fixture (a quick run) runs in the
phase of the fixture's setup (a fast test on a slow quick run runs late), and the fixtures' outputs
are removed before every mutant, so that no test reads what an earlier run left. The report (stdout and --report FILE, JSON, rewritten after
every mutant) gives each mutant's result and the failing tests, the kill rate, and the mutants
that change a published value (`affects`) but survived; the exit status is 1 if there is any
such mutant, 0 otherwise. With --resume, the mutants already in the report (of the same commit)
are not run again.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# The `*.figures` tests render plots and assert no number, the `faults.*` tests refusals and kills, the
# `mpi.*` tests compare a binary with itself on other rank counts: none can see a wrong formula. And
# `mutation.*` checks that every mutant's text is in the tree, which a mutated tree never passes: it
# would count every mutant killed.
DEFAULT_EXCLUDE = r"\.figures$|^faults\.|^mpi\.|^mutation\."


def refuse_modified_files(mutants):
    """A run killed outright (SIGKILL) cannot restore its mutated file: never mutate a mutant."""
    dirty = subprocess.run(["git", "status", "--porcelain", "--"] + sorted({m["file"] for m in mutants}),
                           cwd=ROOT, capture_output=True, text=True).stdout.strip()
    if dirty:
        sys.exit(f"files to mutate differ from the commit (a killed run?):\n{dirty}\nrestore them with git checkout")


def load_mutants(path, will_mutate):
    mutants = tomllib.loads(path.read_text())["mutant"]
    ids = [m["id"] for m in mutants]
    if len(ids) != len(set(ids)):
        sys.exit(f"{path}: duplicate mutant ids")
    for m in mutants:
        for key in ("id", "file", "old", "new", "affects"):
            if key not in m:
                sys.exit(f"{path}: mutant {m.get('id', '?')} has no '{key}'")
    if will_mutate:
        refuse_modified_files(mutants)
    for m in mutants:
        text = (ROOT / m["file"]).read_text()
        if text.count(m["old"]) != 1:
            sys.exit(f"mutant {m['id']}: `old` occurs {text.count(m['old'])} times in {m['file']} (must be once)")
        if m["old"] == m["new"]:
            sys.exit(f"mutant {m['id']}: `new` equals `old`")
        if "tests" in m:
            try:
                re.compile(m["tests"])
            except (re.error, TypeError) as e:
                sys.exit(f"mutant {m['id']}: `tests` is not a regex: {e}")
    return mutants


def run(cmd, log):
    """Runs cmd (its output to log) in a process group of its own, and returns its exit status. If this
    script is stopped meanwhile (Ctrl-C, SIGTERM), the group is sent SIGTERM, and SIGKILL if it has
    not ended 10 s later: ninja (which starts each compiler in a group of its own) stops its compilers
    on SIGTERM, not when it is killed; a SIGKILL alone would leave them running."""
    with open(log, "w") as out:
        child = subprocess.Popen(cmd, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            return child.wait()
        except BaseException:
            os.killpg(child.pid, signal.SIGTERM)
            try:
                child.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(child.pid, signal.SIGKILL)
                child.wait()
            raise


# The library's test executables, each built and then run before the next is built: most wrong
# formulas die in one of them, and the rest of the tree is built only for a mutant none kills. The
# smallest build first: the verification tests are one file, the unit tests twenty, and the stability
# tests reuse the unit tests' precompiled header (so they are built after them anyway).
LIBRARY_TESTS = ["geomint_verification_tests", "geomint_unit_tests", "geomint_stability_tests"]


def build(args, log, targets=None):
    return run(["cmake", "--build", str(args.build), "-j", str(args.jobs)] +
               (["--target"] + targets if targets else []), log) == 0


# ctest's closing lists name each test that did not pass with its status: "  12 - regression.X.y (Failed)". A test
# that did not run -- skipped (GTEST_SKIP, SKIP_RETURN_CODE, SKIP_REGULAR_EXPRESSION), disabled, or not run (its
# executable or a required file missing) -- saw nothing of a mutant: it neither kills nor lets one survive.
NOT_RUN = ("Skipped", "Disabled", "Not Run")


def ctest_outcome(text):
    """The names of the failing tests and of the tests that did not run, from ctest's output `text`."""
    failed, skipped = [], []
    for line in text.splitlines():
        s = line.strip()
        if " - " in s and s.endswith(")") and s.split(" - ", 1)[0].strip().isdigit():
            name, status = s.split(" - ", 1)[1].rsplit(" (", 1)
            (skipped if status[:-1] in NOT_RUN else failed).append(name)
    return failed, skipped


def failed_tests(args, log, stop_on_failure=True, select=None):
    """Runs ctest on the tests matching `select` (-R; every test if None), less --exclude's; returns the
    names of the failing tests ([] if all pass) and of those that did not run (ctest_outcome). A mutant is
    killed by its first failing test: with `stop_on_failure` ctest stops there (the names are those that
    failed by then)."""
    cmd = ["ctest", "--test-dir", str(args.build), "-j", str(args.jobs), "--timeout", str(args.timeout),
           "-E", args.exclude] + (["--stop-on-failure"] if stop_on_failure else [])
    if select:
        cmd += ["-R", select]
    code = run(cmd, log)
    failed, skipped = ctest_outcome(Path(log).read_text())
    if code != 0 and not failed and not skipped:
        failed = ["(ctest failed)"]
    return failed, skipped


def verdict(compiled, failed, skipped, guard=None):
    """A mutant's result: "does not compile"; "killed" by a failing test; "skipped" when no test failed and a test
    that guards it did not run (those matching the mutant's `tests` regex, or without one any test: then the run
    did not see the whole suite); else "survived". A skipped test is never counted as a kill or a survival."""
    if not compiled:
        return "does not compile"
    if failed:
        return "killed"
    if any(guard is None or re.search(guard, name) for name in skipped):
        return "skipped"
    return "survived"


def split_phases(tests, durations, slow):
    """The tests (ctest --show-only=json-v1 `tests`) in phases of names: those under `slow` seconds
    in `durations` (or not timed), then the others. A test runs in the phase of the setups of the
    fixtures it requires (FIXTURES_REQUIRED, and for a cleanup test FIXTURES_CLEANUP), transitively,
    when that is later than its own: a fast test that reads a slow quick run's output must run after
    that quick run of the same mutant, not in a phase before it."""
    props = {t["name"]: {p["name"]: p["value"] for p in t.get("properties", [])} for t in tests}
    setups = {}
    for name, p in props.items():
        for fixture in p.get("FIXTURES_SETUP", []):
            setups.setdefault(fixture, []).append(name)
    phase = {}

    def phase_of(name, path=()):
        if name in path:
            raise ValueError(f"fixture cycle: {' -> '.join(path + (name,))}")
        if name not in phase:
            needs = props[name].get("FIXTURES_REQUIRED", []) + props[name].get("FIXTURES_CLEANUP", [])
            phase[name] = max([int(durations.get(name, 0.0) >= slow)] +
                              [phase_of(setup, path + (name,)) for f in needs for setup in setups.get(f, [])])
        return phase[name]

    phases = [[], []]
    for t in tests:
        phases[phase_of(t["name"])].append(t["name"])
    return [p for p in phases if p]


def ctest_tests(args, *selection):
    """ctest's list of tests (with their properties) of `selection` (ctest options), none run."""
    out = subprocess.run(["ctest", "--test-dir", str(args.build), "--show-only=json-v1", *selection],
                         cwd=ROOT, capture_output=True, text=True, check=True).stdout
    return json.loads(out)["tests"]


def names_pattern(names):
    return "^(" + "|".join(re.escape(n) for n in names) + ")$"


def test_phases(args):
    """The ctest -R pattern of each phase (split_phases of the baseline's test times, without
    --exclude's tests); one phase with --tests. A phase is selected by its names (-R), not by leaving
    the others out (-E alone): ctest then drops the left-out tests before it adds the setups of the
    fixtures the selected tests require, and a test would read a quick run that did not run. With -R,
    ctest adds those setups (split_phases has put them in the phase or an earlier one; a setup that a
    later phase needs again runs again there)."""
    if args.tests:
        return [args.tests]
    cost_file = args.build / "Testing" / "Temporary" / "CTestCostData.txt"
    durations = {parts[0]: float(parts[2]) for parts in map(str.split, cost_file.read_text().splitlines())
                 if len(parts) == 3}
    phases = [[n for n in phase if not re.search(args.exclude, n)]
              for phase in split_phases(ctest_tests(args), durations, args.slow)]
    return [checked_pattern(args, phase, "a phase") for phase in phases if phase]


def checked_pattern(args, names, what):
    """The ctest -R pattern selecting exactly `names`. A regex too long for ctest (with 3.25, one of
    69 kB) matches no test, and says nothing; ctest and Python could also read --exclude differently:
    each selection is checked before a mutant relies on it."""
    pattern = names_pattern(names)
    missing = set(names) - {t["name"] for t in ctest_tests(args, "-R", pattern, "-E", args.exclude)}
    if missing:
        sys.exit(f"ctest does not select {len(missing)} of the {len(names)} tests of {what} "
                 f"(e.g. {min(missing)}; its -R pattern has {len(pattern)} characters)")
    return pattern


def library_stages(tests, exclude):
    """(target, names of the tests that run its executable) for each of LIBRARY_TESTS, in that order;
    `tests` is ctest's list (--show-only=json-v1), and tests matching `exclude` are left out."""
    stages = []
    for target in LIBRARY_TESTS:
        names = [t["name"] for t in tests if t.get("command") and Path(t["command"][0]).name == target
                 and not re.search(exclude, t["name"])]
        if not names:
            raise ValueError(f"no test runs {target}")
        stages.append((target, names))
    return stages


class BaselineOutputs:
    """The baseline's build outputs, kept aside in <build>/mutation-baseline, so that after a mutant the
    build is the baseline's again without a recompile. A mutated file gets a new mtime, so that its
    dependents rebuild; restored to its text alone, it would keep a newer one, and the next mutant would
    recompile every file that includes it, whether that mutant changes them or not (30 % of the
    compile time of a whole run). So the restore puts back its text and its mtime, and every output that
    differs from the baseline's (built from the mutant, or removed) is copied back from this store with its
    mtime: every output then holds what the baseline built from the same text, and is newer than its
    inputs. Only under Ninja, whose outputs `ninja -t targets all` lists; under make a mutated file's
    dependents rebuild after it, as before."""

    def __init__(self, build):
        self.build, self.store, self.files = build, build / "mutation-baseline", {}

    @staticmethod
    def ninja_outputs(build):
        """The files the build writes: the outputs of every non-phony edge under the build directory."""
        out = subprocess.run(["ninja", "-C", str(build), "-t", "targets", "all"], capture_output=True, text=True,
                             check=True).stdout
        root, paths = build.resolve(), set()
        for line in out.splitlines():
            target, _, rule = line.rpartition(": ")
            path = (root / target).resolve()
            if rule != "phony" and path.is_relative_to(root) and path.is_file():
                paths.add(path.relative_to(root))
        return sorted(paths)

    def keep(self, outputs):
        """Copies `outputs` (paths relative to the build directory) into the store, with their mtimes."""
        shutil.rmtree(self.store, ignore_errors=True)
        self.files = {}
        for rel in outputs:
            src, dst = self.build / rel, self.store / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dst)
            st = src.stat()
            self.files[rel] = (st.st_mtime_ns, st.st_size)

    def restore(self):
        """Copies back every kept output that is missing or differs in mtime or size; returns how many."""
        changed = 0
        for rel, (mtime, size) in self.files.items():
            path = self.build / rel
            try:
                st = path.stat()
                if (st.st_mtime_ns, st.st_size) == (mtime, size):
                    continue
            except FileNotFoundError:
                path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_name(path.name + ".mutation-restore")
            shutil.copy2(self.store / rel, tmp)
            os.replace(tmp, path)  # (an executable being replaced is never half written)
            changed += 1
        return changed


def remove_fixture_outputs(args):
    """The quick runs write into <build>/test-results (GEOMINT_TEST_RESULTS, tests/CMakeLists.txt), and
    the regression tests read them there. Without this, a test of one mutant could read files that an
    earlier run (the baseline, another mutant) wrote and this one's run did not rewrite."""
    shutil.rmtree(args.build / "test-results", ignore_errors=True)


def commit_of_tree():
    out = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True)
    return out.stdout.strip() if out.returncode == 0 else None


def summarize(results, commit):
    """The counts; the kill rate over the mutants whose tests ran (killed or survived: a skipped one is neither)."""
    valid = [r for r in results if r["result"] != "does not compile"]
    killed = [r for r in valid if r["result"] == "killed"]
    judged = [r for r in valid if r["result"] in ("killed", "survived")]
    return {"commit": commit, "mutants": len(results), "compiled": len(valid), "killed": len(killed),
            "skipped": [r["id"] for r in valid if r["result"] == "skipped"],
            "kill_rate": len(killed) / len(judged) if judged else None,
            "published_survivors": [r["id"] for r in valid if r["result"] == "survived" and r["affects"]],
            "results": results}


def configure(args):
    """A mutation build compiles each test file on its own (GEOMINT_UNITY_TESTS=OFF): a mutant then
    recompiles the test files that include its header, not every batch one of them is in. Ninja, when
    there is one, is used: under make a test file waits for the whole library, under ninja it
    compiles beside the library's files (and BaselineOutputs can restore the build after a mutant)."""
    cmd = ["cmake", "-S", str(ROOT), "-B", str(args.build), "-DGEOMINT_UNITY_TESTS=OFF"]
    if not (args.build / "CMakeCache.txt").exists():
        cmd.append("-DCMAKE_BUILD_TYPE=Release")
        if shutil.which("ninja"):
            cmd += ["-G", "Ninja"]
        if shutil.which("ccache"):
            cmd.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mutants", type=Path, default=Path(__file__).with_name("mutants.toml"))
    ap.add_argument("--build", type=Path, default=ROOT / "build-mutation")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--only", help="comma-separated mutant ids")
    ap.add_argument("--tests", help="ctest -R regex (default: every test)")
    ap.add_argument("--exclude", default=DEFAULT_EXCLUDE, help="ctest -E regex")
    ap.add_argument("--timeout", type=int, default=600, help="seconds per test (a hang counts as a kill)")
    ap.add_argument("--slow", type=float, default=15.0,
                    help="tests that took at least this many seconds in the baseline run last")
    ap.add_argument("--report", type=Path, help="write the results as JSON (after every mutant)")
    ap.add_argument("--resume", action="store_true", help="keep the results of --report, run the other mutants")
    ap.add_argument("--list", action="store_true", help="check and list the mutants, run nothing")
    args = ap.parse_args()
    args.build = args.build if args.build.is_absolute() else ROOT / args.build

    mutants = load_mutants(args.mutants, will_mutate=not args.list)
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {m["id"] for m in mutants}
        if unknown:
            sys.exit(f"unknown mutant ids: {', '.join(sorted(unknown))}")
        mutants = [m for m in mutants if m["id"] in wanted]
    if args.list:
        for m in mutants:
            print(f"{m['id']:32} {m['file']}  [{m['affects'] or 'no published value'}]")
        print(f"{len(mutants)} mutants")
        return 0

    commit = commit_of_tree()
    results = []
    if args.resume:
        if not args.report or not args.report.exists():
            sys.exit("--resume needs an existing --report FILE")
        previous = json.loads(args.report.read_text())
        if previous.get("commit") != commit:
            sys.exit(f"{args.report} is of commit {previous.get('commit')}, this tree is {commit}: run afresh")
        ids = {m["id"] for m in mutants}
        results = [r for r in previous["results"] if r["id"] in ids]
    done = {r["id"] for r in results}

    logs = args.build / "mutation-logs"
    configure(args)
    logs.mkdir(parents=True, exist_ok=True)
    print("baseline: building and testing the unmodified tree", flush=True)
    if not build(args, logs / "baseline-build.log"):
        sys.exit(f"the unmodified tree does not build: {logs / 'baseline-build.log'}")
    remove_fixture_outputs(args)
    base_failed, base_skipped = failed_tests(args, logs / "baseline-ctest.log", stop_on_failure=False)
    if base_failed:
        sys.exit(f"the unmodified tree fails tests ({', '.join(base_failed)}): nothing can be measured")
    if base_skipped:
        print(f"baseline: {len(base_skipped)} tests did not run ({', '.join(base_skipped[:3])}); a mutant they guard "
              "is reported skipped", flush=True)
    phases = test_phases(args)
    baseline = BaselineOutputs(args.build) if (args.build / "build.ninja").exists() else None
    if baseline:
        baseline.keep(BaselineOutputs.ninja_outputs(args.build))
    try:
        stages = [(target, checked_pattern(args, names, target))
                  for target, names in library_stages(ctest_tests(args), args.exclude)]
    except ValueError as e:
        sys.exit(f"cannot stage the library's tests: {e}")

    for i, m in enumerate(mutants, 1):
        if m["id"] in done:
            continue
        path = ROOT / m["file"]
        original, original_stat = path.read_bytes(), path.stat()
        start = time.monotonic()
        interrupted = None
        try:
            remove_fixture_outputs(args)
            path.write_text(original.decode().replace(m["old"], m["new"], 1))
            failed, skipped, compiled = [], [], True
            for target, select in [] if args.tests else stages:
                compiled = build(args, logs / f"{m['id']}-build-{target}.log", [target])
                if not compiled:
                    break
                failed, not_run = failed_tests(args, logs / f"{m['id']}-ctest-{target}.log", select=select)
                skipped += not_run
                if failed:
                    break
            if compiled and not failed:
                compiled = build(args, logs / f"{m['id']}-build.log")
            for k, select in enumerate(phases if compiled and not failed else []):
                failed, not_run = failed_tests(args, logs / f"{m['id']}-ctest{k}.log", select=select)
                skipped += not_run
                if failed:
                    break
            result = verdict(compiled, failed, skipped, m.get("tests"))
        except KeyboardInterrupt:
            interrupted = True
        finally:
            signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM, signal.SIGINT})  # (a restore is never cut short)
            path.write_bytes(original)
            if baseline:  # the baseline's text, mtime and outputs (BaselineOutputs)
                os.utime(path, ns=(original_stat.st_atime_ns, original_stat.st_mtime_ns))
                baseline.restore()
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM, signal.SIGINT})
        if interrupted:
            print("interrupted; the mutated file is restored", file=sys.stderr)
            return 130
        results.append({"id": m["id"], "file": m["file"], "affects": m["affects"], "result": result,
                        "failed_tests": failed, "skipped_tests": skipped, "seconds": round(time.monotonic() - start, 1)})
        shown = ", ".join(failed[:3]) + (f" (+{len(failed) - 3})" if len(failed) > 3 else "")
        print(f"[{i}/{len(mutants)}] {m['id']:32} {result:16} {shown}", flush=True)
        if args.report:
            args.report.write_text(json.dumps(summarize(results, commit), indent=2) + "\n")
    # Leave the build matching the unmodified tree, without the last mutant's outputs.
    build(args, logs / "final-build.log")
    remove_fixture_outputs(args)

    summary = summarize(results, commit)
    valid = [r for r in results if r["result"] != "does not compile"]
    killed = [r for r in valid if r["result"] == "killed"]
    judged = len(valid) - len(summary["skipped"])
    rate = f"{summary['kill_rate']:.0%}" if judged else "n/a"
    print(f"\nkilled {len(killed)} of {judged} mutants that compile and whose tests ran ({rate}); "
          f"{len(summary['skipped'])} skipped (a test that guards them did not run); "
          f"{len(results) - len(valid)} do not compile")
    for r in valid:
        if r["result"] in ("survived", "skipped"):
            print(f"  {r['result']}: {r['id']} ({r['affects'] or 'changes no published value'})")
    if args.report:
        args.report.write_text(json.dumps(summary, indent=2) + "\n")
    return 1 if summary["published_survivors"] else 0


def stop(_signum, _frame):
    raise KeyboardInterrupt


if __name__ == "__main__":
    # SIGTERM unwinds as Ctrl-C does: run() stops the build or ctest it waits on, a mutated file is restored.
    signal.signal(signal.SIGTERM, stop)
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        sys.exit("interrupted")
