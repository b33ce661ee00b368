#!/usr/bin/env python3
"""run_mutants.split_phases on made-up ctest test lists: a test never runs in a phase before the setup
of a fixture it requires, so it cannot read outputs that an earlier run left; and library_stages
gives each library test executable exactly the tests that run it; BaselineOutputs puts back the
baseline's outputs that a mutant changed or removed, with their mtimes, and leaves the others alone; a test that
did not run (skipped, disabled, not run; ctest's own output included) neither kills a mutant nor lets it survive."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run_mutants import (LIBRARY_TESTS, BaselineOutputs, ctest_outcome, library_stages, split_phases,  # noqa: E402
                         verdict)


def entry(name, setup=(), requires=(), cleanup=(), command="/build/bin/geomint_regression_tests"):
    """One entry of `ctest --show-only=json-v1`'s tests."""
    props = [{"name": key, "value": list(value)} for key, value in
             (("FIXTURES_SETUP", setup), ("FIXTURES_REQUIRED", requires), ("FIXTURES_CLEANUP", cleanup)) if value]
    return {"name": name, "command": [command, f"--gtest_filter={name}"],
            "properties": props + [{"name": "LABELS", "value": ["regression"]}]}


def phase_index(phases, name):
    return next(i for i, phase in enumerate(phases) if name in phase)


class SplitPhases(unittest.TestCase):
    def check_each_once(self, tests, phases):
        self.assertEqual(sorted(n for phase in phases for n in phase), sorted(t["name"] for t in tests))

    def test_a_fast_test_runs_with_the_slow_setup_it_requires(self):
        # S (slow) sets up F, which A needs; T (fast) sets up G, which C needs; X cleans up F.
        tests = [entry("A", requires=["F"]), entry("S", setup=["F"]), entry("B"), entry("C", requires=["G"]),
                 entry("T", setup=["G"]), entry("X", cleanup=["F"])]
        durations = {"A": 0.1, "S": 30.0, "B": 0.1, "T": 1.0, "X": 0.1}  # C not timed: fast
        phases = split_phases(tests, durations, slow=15.0)
        self.check_each_once(tests, phases)
        self.assertEqual(len(phases), 2)
        self.assertEqual(phase_index(phases, "A"), phase_index(phases, "S"))
        self.assertEqual(phase_index(phases, "X"), phase_index(phases, "S"))
        for name in ("B", "C", "T"):
            self.assertIn(name, phases[0])
        self.assertLessEqual(phase_index(phases, "T"), phase_index(phases, "C"))

    def test_the_closure_is_transitive(self):
        # A needs F; F's setup S (fast) needs H, whose setup U is slow: A and S run with U, after B.
        tests = [entry("A", requires=["F"]), entry("S", setup=["F"], requires=["H"]), entry("U", setup=["H"]),
                 entry("B")]
        phases = split_phases(tests, {"A": 0.1, "S": 0.1, "U": 30.0, "B": 0.1}, slow=15.0)
        self.check_each_once(tests, phases)
        self.assertEqual(phases, [["B"], ["A", "S", "U"]])

    def test_a_fixture_with_several_setups_waits_for_the_slowest(self):
        # quick_runs: every experiment's quick run sets it up; one of them is slow.
        tests = [entry("P", requires=["quick_runs"]), entry("q1", setup=["quick_runs"]), entry("q2", setup=["quick_runs"])]
        phases = split_phases(tests, {"P": 0.1, "q1": 0.5, "q2": 23.0}, slow=15.0)
        self.check_each_once(tests, phases)
        self.assertEqual(phase_index(phases, "P"), phase_index(phases, "q2"))
        self.assertEqual(phase_index(phases, "q1"), 0)

    def test_no_slow_test_gives_one_phase(self):
        tests = [entry("A", requires=["F"]), entry("S", setup=["F"]), entry("B")]
        self.assertEqual(split_phases(tests, {"S": 3.0}, slow=15.0), [["A", "S", "B"]])

    def test_a_fixture_cycle_is_refused(self):
        tests = [entry("S", setup=["F"], requires=["G"]), entry("T", setup=["G"], requires=["F"])]
        with self.assertRaises(ValueError):
            split_phases(tests, {}, slow=15.0)


class LibraryStages(unittest.TestCase):
    def test_each_executable_gets_the_tests_that_run_it(self):
        tests = [entry("V.a", command="/b/bin/geomint_verification_tests"), entry("U.a", command="/b/bin/geomint_unit_tests"),
                 entry("mutation.mutants_apply", command="/usr/bin/python3"), entry("R.a"),
                 entry("U.b", command="/b/bin/geomint_unit_tests"), entry("S.a", command="/b/bin/geomint_stability_tests"),
                 entry("U.excluded", command="/b/bin/geomint_unit_tests")]
        stages = library_stages(tests, exclude=r"^mutation\.|excluded")
        self.assertEqual([target for target, _ in stages], LIBRARY_TESTS)
        self.assertEqual(dict(stages), {"geomint_verification_tests": ["V.a"], "geomint_unit_tests": ["U.a", "U.b"],
                                        "geomint_stability_tests": ["S.a"]})

    def test_an_executable_without_tests_is_refused(self):
        with self.assertRaises(ValueError):
            library_stages([entry("U.a", command="/b/bin/geomint_unit_tests")], exclude="^$")



class SkippedTests(unittest.TestCase):
    """A test that did not run (GTEST_SKIP, ctest "Skipped" or "Not Run") neither kills a mutant nor lets it survive."""

    CTEST_OUTPUT = """
90% tests passed, 1 tests failed out of 10

The following tests did not run:
\t  4 - regression.TiDrift.Skipped (Skipped)
\t  5 - unit.Disabled (Disabled)

The following tests FAILED:
\t  7 - regression.Published.TiDrift (Failed)
\t  8 - unit.MissingExecutable (Not Run)
\t  9 - stability.Long (Timeout)
Errors while running CTest
"""

    def test_the_closing_lists_are_read_by_status(self):
        failed, skipped = ctest_outcome(self.CTEST_OUTPUT)
        self.assertEqual(failed, ["regression.Published.TiDrift", "stability.Long"])
        self.assertEqual(skipped, ["regression.TiDrift.Skipped", "unit.Disabled", "unit.MissingExecutable"])

    def test_a_mutant_whose_guarding_test_is_skipped_is_skipped(self):
        skipped = ["regression.TiDrift.Skipped"]
        self.assertEqual(verdict(True, [], skipped, guard=r"^regression\.TiDrift\."), "skipped")
        self.assertEqual(verdict(True, [], skipped, guard=None), "skipped")  # no guard named: any test that did not run
        self.assertEqual(verdict(True, [], skipped, guard=r"^unit\."), "survived")  # its own tests ran
        self.assertEqual(verdict(True, [], [], guard=None), "survived")
        self.assertEqual(verdict(True, ["unit.X"], skipped), "killed")  # a failure kills, a skip never does
        self.assertEqual(verdict(False, [], skipped), "does not compile")

    @unittest.skipUnless(shutil.which("cmake") and shutil.which("ctest"), "needs cmake and ctest")
    def test_real_ctest_output_of_a_skipped_and_a_failing_test(self):
        with tempfile.TemporaryDirectory() as d:
            src, build = Path(d) / "src", Path(d) / "build"
            src.mkdir()
            (src / "CMakeLists.txt").write_text(
                "cmake_minimum_required(VERSION 3.16)\nproject(p NONE)\nenable_testing()\n"
                "add_test(NAME skips COMMAND ${CMAKE_COMMAND} -E echo \"[  SKIPPED ] 1 test\")\n"
                "set_tests_properties(skips PROPERTIES SKIP_REGULAR_EXPRESSION \"\\\\[  SKIPPED \\\\]\")\n"
                "add_test(NAME fails COMMAND ${CMAKE_COMMAND} -E false)\n"
                "add_test(NAME passes COMMAND ${CMAKE_COMMAND} -E true)\n"
                "add_test(NAME missing COMMAND /nonexistent/test-binary)\n")
            subprocess.run(["cmake", "-S", str(src), "-B", str(build)], check=True, capture_output=True)
            out = subprocess.run(["ctest", "--test-dir", str(build)], capture_output=True, text=True).stdout
            failed, skipped = ctest_outcome(out)
            self.assertEqual(failed, ["fails"], out)
            self.assertEqual(sorted(skipped), ["missing", "skips"], out)


class KeptOutputs(unittest.TestCase):
    def test_changed_and_removed_outputs_come_back_with_their_mtimes(self):
        with tempfile.TemporaryDirectory() as d:
            build = Path(d)
            files = {Path("a.o"): b"baseline a", Path("sub/b.o"): b"baseline b", Path("bin/c"): b"baseline c"}
            for rel, text in files.items():
                (build / rel).parent.mkdir(parents=True, exist_ok=True)
                (build / rel).write_bytes(text)
                os.utime(build / rel, ns=(1_000_000_000, 1_000_000_000 + len(text)))
            kept = BaselineOutputs(build)
            kept.keep(sorted(files))
            before = {rel: (build / rel).stat().st_mtime_ns for rel in files}
            (build / "a.o").write_bytes(b"mutant a, longer")    # rebuilt from the mutant
            (build / "sub/b.o").unlink()                        # removed (an interrupted build)
            (build / "new.o").write_bytes(b"not an output of the baseline")
            self.assertEqual(kept.restore(), 2)
            for rel, text in files.items():
                self.assertEqual((build / rel).read_bytes(), text)
                self.assertEqual((build / rel).stat().st_mtime_ns, before[rel])
            self.assertTrue((build / "new.o").exists())
            self.assertEqual(kept.restore(), 0)  # nothing differs any more

    def test_an_output_rewritten_with_the_same_size_is_restored(self):
        with tempfile.TemporaryDirectory() as d:
            build = Path(d)
            (build / "x.o").write_bytes(b"12345")
            os.utime(build / "x.o", ns=(5_000_000_000, 5_000_000_000))
            kept = BaselineOutputs(build)
            kept.keep([Path("x.o")])
            (build / "x.o").write_bytes(b"54321")  # same size, a newer mtime
            self.assertEqual(kept.restore(), 1)
            self.assertEqual((build / "x.o").read_bytes(), b"12345")


if __name__ == "__main__":
    unittest.main()
