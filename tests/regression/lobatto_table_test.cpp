// Regression: the quick scene of lobatto_table reproduces 001 Table 1 and the
// claims around it (order 6, stability bound (10), symplecticity), and the
// nonlinear extension. Orders and the bound are the registry's (methods/registry.hpp).
#include <gtest/gtest.h>
#include <filesystem>
#include <sstream>
#include <cstdlib>
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/order_fit.hpp"
#include "summary.hpp"

namespace lobatto_table_test {  // the file's scope (the tests build as one translation unit)

using json = nlohmann::json;
namespace fs = std::filesystem;
using geomint::method_info;

namespace {
const json& summary() { return summary_of("lobatto_table"); }
std::string label(const char* method) { return std::string(method_info(method).label); }
}  // namespace

// Table 1 and the growth rates of Fig. 2 against the published values: Published.LobattoTable
// (published_test.cpp), with the tolerances of experiments/lobatto_table/published.toml.

// 001 Fig. 1 (published.toml fig1_close_at_three_meshes): at N = 3 Lobatto's q and p are closer to the
// exact q = A cos(w t), p = -A m w sin(w t) than those of the schemes drawn beside it; the errors
// again from fig1_N3.csv.
TEST(LobattoTable, LobattoIsTheClosestCurveOfFigureOneAtThreeMeshes) {
  const CsvFile f = read_csv(results_dir("lobatto_table") / "fig1_N3.csv");
  const auto& osc = scene_of("lobatto_table")["oscillator"];
  const double m = osc["m"], w = osc["omega"], A = osc["amplitude"];
  const auto errors = [&](const std::string& l) {
    double q = 0, p = 0;
    for (const auto& row : f.rows) {
      const double t = std::stod(row[f.column("t")]);
      q = std::max(q, std::abs(std::stod(row[f.column("q_" + l)]) - A * std::cos(w * t)));
      p = std::max(p, std::abs(std::stod(row[f.column("p_" + l)]) + A * m * w * std::sin(w * t)));
    }
    return std::pair{q, p};
  };
  const auto [q, p] = errors(label("lobatto"));
  const auto& ratios = summary()["figure1"]["closeness"]["error_ratio_to_lobatto"];
  ASSERT_EQ(ratios.size(), 2u);
  for (const char* other : {"simpson", "implicit_midpoint"}) {
    const auto [qo, po] = errors(label(other));
    EXPECT_NEAR(ratios[label(other)].get<double>(), std::min(qo / q, po / p), 1e-9 * std::min(qo / q, po / p)) << other;
  }
  const auto& c = summary()["comparisons"]["fig1_close_at_three_meshes"];
  EXPECT_EQ(c["verdict"], "reproduced") << c.dump(2);
}

TEST(LobattoTable, DeclaredOrdersOnTheOscillatorAndNonlinearSystems) {
  const auto& o = summary()["orders"];
  const double lobatto = method_info("lobatto").order;  // 6
  for (const char* key : {"lobatto_p", "lobatto_q", "lobatto_H", "lobatto_nonlinear_pendulum", "lobatto_elastic_pendulum"})
    EXPECT_NEAR(o[key].get<double>(), lobatto, 0.3) << key;
  // Table 1's compared methods (the scene's table1.methods) and the same on the pendulum (nonlinear.methods).
  EXPECT_NEAR(o[label("simpson")].get<double>(), method_info("simpson").order, 0.2);
  EXPECT_NEAR(o[label("implicit_midpoint")].get<double>(), method_info("implicit_midpoint").order, 0.1);
  EXPECT_NEAR(o[label("simpson") + "_nonlinear_pendulum"].get<double>(), method_info("simpson").order, 0.2);
  EXPECT_NEAR(o[label("implicit_midpoint") + "_nonlinear_pendulum"].get<double>(), method_info("implicit_midpoint").order,
              0.1);
}

TEST(LobattoTable, StabilityBoundAndRunsAroundIt) {
  const auto& r = summary()["reproduced"];
  const double bound = method_info("lobatto").oscillatory_bound;  // 001 eq. (10)
  EXPECT_CASE_NEAR("h omega at which the spectral radius leaves 1 (bisection), against (10)",
                   r["stability_bound"].get<double>(), bound, 1e-9);
  EXPECT_EQ(summary()["published"]["stability_bound"].get<double>(), bound);
  EXPECT_CASE("run at 0.99 x the bound: step of divergence (-1: none)",
              r["bound_runs"]["0.98999999999999999"]["diverged_at_step"].get<long>(), "==", -1);
  EXPECT_CASE("run at 1.01 x the bound: step of divergence", r["bound_runs"]["1.01"]["diverged_at_step"].get<long>(), ">", 0);
}

TEST(LobattoTable, NonlinearMapsAreSymplectic) {
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["symplecticity_defect_pendulum"].get<double>(), 1e-10);
  EXPECT_LT(r["symplecticity_defect_elastic"].get<double>(), 1e-10);
}

// 001 eq. (12) as printed (published.toml: eq12_printed_order, an erratum): iterated as a scheme,
// its state error over Table 1's meshes does not decrease at all (order about 0, not 6).
TEST(LobattoTable, Equation12AsPrintedDoesNotConverge) {
  EXPECT_LT(std::abs(summary()["orders"]["lobatto_printed_eq12_q"].get<double>()), 0.5);
}

// The scan's stable intervals are the exact stable set of (13)-(14) to the grid spacing.
TEST(LobattoTable, ScanFindsTheExactStableSet) {
  const auto& st = summary()["stability"];
  const auto& scan = summary()["reproduced"]["stable_set_h_omega"];
  const auto& exact = st["exact_set_h_omega"];
  const double step = st["grid_step"].get<double>();
  ASSERT_EQ(scan.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (int end : {0, 1}) EXPECT_NEAR(scan[i][end].get<double>(), exact[i][end].get<double>(), step) << i << " " << end;
}

// Table 1: every compared error of p, q and H rounds to the printed digits.
TEST(LobattoTable, Table1RoundsToThePrintedDigits) {
  const auto& printed = summary()["table1"]["printed"];
  EXPECT_GT(printed["compared"].get<int>(), 0);
  EXPECT_EQ(printed["round_to_printed_digits"].get<int>(), printed["compared"].get<int>());
}

// Fig. 2 at the first step size (N = 10): the measured growth rate is the exact-arithmetic rate of
// the closed-form orbit, up to the round-off drift of H_d seen in H.
TEST(LobattoTable, MeasuredGrowthIsTheExactGrowth) {
  const auto& r = summary()["long_run"]["rates"][0];
  const double exact = r["exact_rate"].get<double>(), measured = r["H_rate"].get<double>();
  EXPECT_GT(exact, 0);
  EXPECT_NEAR(measured, exact, 0.01 * exact);
  EXPECT_LT(std::abs(r["H_rate_minus_exact"].get<double>()), 10 * r["roundoff_in_H"].get<double>());
}

// The work-precision runs over the long run of Fig. 2 (the sets long_run_phase and long_run_energy of the
// same runs: cost_long_run_phase.csv, cost_long_run_energy.csv) against closed forms in
// exact arithmetic: the Lobatto scheme is the rotation by theta of 001 (13)-(14) (q_N = A cos(N theta),
// p_N = -sqrt(-b/c) A sin(N theta)), the implicit midpoint rule on the oscillator the rotation by
// 2 atan(h omega / 2) (it conserves H); the phase error at t_N against the exact flow from either.
// The Lobatto phase errors fall as h^6 (N steps of a phase error O(h^7)), fitted from the CSV.
TEST(LobattoTable, LongRunCostErrorsMatchTheClosedForms) {
  const json run = json::parse(std::ifstream(results_dir("lobatto_table") / "run.json"));
  const auto& sc = run["scene"];
  const double m = sc["oscillator"]["m"], w = sc["oscillator"]["omega"], A = sc["oscillator"]["amplitude"];
  const double periods = sc["long_run"]["periods"], T = 2 * std::numbers::pi / w;
  const CsvFile csv = read_csv(results_dir("lobatto_table") / "cost_long_run_phase.csv");
  const CsvFile energy = read_csv(results_dir("lobatto_table") / "cost_long_run_energy.csv");
  const std::size_t cm = csv.column("method"), ch = csv.column("h"), cs = csv.column("steps"),
                    cp = csv.column("err"), ce = energy.column("err"), cf = csv.column("force_evals");
  ASSERT_EQ(energy.rows.size(), csv.rows.size());
  std::map<std::string, std::vector<double>> hs, phase;
  std::map<std::string, double> evals_per_step;
  int checked = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const auto& row = csv.rows[i];
    for (const char* c : {"method", "h", "steps", "force_evals"})  // the same run in both sets
      EXPECT_EQ(energy.rows[i][energy.column(c)], row[csv.column(c)]) << c << " row " << i;
    const std::string method = row[cm];
    const double h = std::stod(row[ch]), err = std::stod(row[cp]);
    const std::int64_t n = std::stoll(row[cs]);
    EXPECT_EQ(n, std::llround(periods * T / h)) << method;
    const double per_step = std::stod(row[cf]) / static_cast<double>(n);  // a linear problem: the same every step
    if (evals_per_step.count(method)) EXPECT_DOUBLE_EQ(per_step, evals_per_step[method]) << method;
    evals_per_step[method] = per_step;
    hs[method].push_back(h), phase[method].push_back(err);
    const double t = static_cast<double>(n) * h, N = static_cast<double>(n);
    const auto distance = [&](double q, double p) {  // to the exact flow at t_N
      return std::hypot(q - A * std::cos(w * t), p + m * w * A * std::sin(w * t));
    };
    if (method == label("lobatto")) {
      const auto orbit = geomint::lobatto_exact_orbit(h, m, w, A);
      ASSERT_TRUE(orbit);
      const auto k = geomint::lobatto_coefficients(h, m, w);
      const double exact = distance(A * std::cos(N * orbit->theta), -std::sqrt(-k.b / k.c) * A * std::sin(N * orbit->theta));
      EXPECT_NEAR(err, exact, 1e-6 * exact + 1e-9) << "h = " << h;
      // |H_j - H_0| <= |K| in exact arithmetic; in floating point up to the round-off of N steps, N u H_0
      EXPECT_LE(std::stod(energy.rows[i][ce]), std::abs(orbit->K) + N * std::numeric_limits<double>::epsilon() * orbit->H0) << "h = " << h;
      EXPECT_GE(std::stod(energy.rows[i][ce]), 0.5 * std::abs(orbit->K)) << "h = " << h;  // sin^2(j theta) comes near 1 in a period
      ++checked;
    } else if (method == label("implicit_midpoint")) {
      const double theta = 2 * std::atan(h * w / 2);
      const double exact = distance(A * std::cos(N * theta), -m * w * A * std::sin(N * theta));
      EXPECT_NEAR(err, exact, 1e-6 * exact + 1e-9) << "h = " << h;
      EXPECT_LT(std::stod(energy.rows[i][ce]), 1e-9 * 0.5 * m * w * w * A * A) << "h = " << h;  // H conserved up to round-off
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * static_cast<int>(sc["long_run_cost"]["h"].size()));
  EXPECT_NEAR(geomint::fit_order(hs[label("lobatto")], phase[label("lobatto")], geomint::roundoff_floor()).order,
              method_info("lobatto").order, 0.3);
  EXPECT_NEAR(summary()["long_run_cost"]["reference_error"].get<double>(),
              std::numeric_limits<double>::epsilon() * w * periods * T * std::hypot(A, m * w * A), 1e-20);
}

// The timing method (runner/timing.hpp, runner/timing_report.hpp): every timed measurement of the cost
// studies reports its spread (max - min) / min beside its minimum: one per row of each set's cost_<set>.csv
// (the pendulum runs; the long runs of Fig. 2, the same in both long-run sets), and summary.json's
// cost.<set>.spread is over all of them. (Structure only: no timing value is asserted.)
TEST(LobattoTable, EveryTimedMeasurementReportsItsSpread) {
  for (const char* set : {"pendulum", "long_run_phase", "long_run_energy"}) {
    const CsvFile t = read_csv(results_dir("lobatto_table") / ("cost_" + std::string(set) + ".csv"));
    const double largest = largest_spread(t);
    const auto& spread = summary()["cost"][set]["spread"];
    ASSERT_TRUE(spread.is_object()) << set;
    expect_interpolated_rows_affine(t);
    EXPECT_EQ(spread["measurements"].get<std::size_t>(), timed_rows(t)) << set;
    EXPECT_DOUBLE_EQ(spread["max"].get<double>(), largest) << set;
  }
}

// Both cost studies merge into summary.cost (either may run alone); equal wall time is the one rule
// (analysis/work_precision.hpp equal_cost): the least of the methods' largest wall times in the set's CSV,
// whatever the scene's (unused) timing.equal_wall names.
TEST(LobattoTable, CostSetsFollowTheOneRuleOfEqualCost) {
  const auto& cost = summary()["cost"];
  EXPECT_TRUE(cost["method"].is_string());
  for (const char* set : {"pendulum", "long_run_phase", "long_run_energy"}) {
    const CsvFile t = read_csv(results_dir("lobatto_table") / ("cost_" + std::string(set) + ".csv"));
    std::map<std::string, std::pair<double, double>> range;  // per method: its smallest and largest wall time
    for (const auto& r : t.rows) {
      const double w = std::stod(r[t.column("wall_s")]);
      const auto it = range.try_emplace(r[t.column("method")], w, w).first;
      it->second = {std::min(it->second.first, w), std::max(it->second.second, w)};
    }
    double least = std::numeric_limits<double>::infinity(), lo = 0;
    for (const auto& [m, w] : range) least = std::min(least, w.second), lo = std::max(lo, w.first);
    if (lo <= least) EXPECT_DOUBLE_EQ(cost[set]["equal_wall_s"].get<double>(), least) << set;
    else EXPECT_TRUE(cost[set]["equal_wall_s"].is_null()) << set;  // (the ranges share no wall time)
    EXPECT_EQ(cost[set]["methods"].size(), range.size()) << set;
  }
  const auto& by = cost["pendulum"]["by_method"];
  for (const auto& [m, c] : by.items())  // ns per step relative to the first of timing.methods
    EXPECT_DOUBLE_EQ(cost["relative_ns_per_step"]["by_method"][m]["ratio"].get<double>(),
                     c["ns_per_step"].get<double>() / by[label("lobatto")]["ns_per_step"].get<double>()) << m;
}

// ---- Bad input (the interface contract): exit 2 before any work, one stderr line naming the key,
// the value and what is allowed, no results directory; --plan of the paper scene (tests/regression/summary.hpp: expect_exit, expect_plan). ----

TEST(LobattoTable, RefuseStepCountBeyond2To53) {
  expect_exit("lobatto_table", 2, "--set long_run.periods=1e300", {"long_run", "2^53"});
}
TEST(LobattoTable, RefuseNonlinearStepThatDoesNotDivideTEnd) {
  expect_exit("lobatto_table", 2, "--set nonlinear.t_end=20.03", {"nonlinear.h", "divide nonlinear.t_end", "20.03"});
}
TEST(LobattoTable, RefuseNonlinearStepsBeyondTheStabilityBound) {
  expect_exit("lobatto_table", 2, "--set 'nonlinear.h=[10,5,2.5]'", {"nonlinear.h", "unstable", "h omega"});
}
TEST(LobattoTable, RefuseRepeatsBeyondInt) {
  expect_exit("lobatto_table", 2, "--set timing.repeats=2147483648", {"timing.repeats", "2147483648"});
}
TEST(LobattoTable, RefuseReferenceToleranceOutsideRange) {
  expect_exit("lobatto_table", 2, "--set reference.rtol=1e300", {"reference.rtol", "1e+300", "<= 0.01"});
  expect_exit("lobatto_table", 2, "--set reference.atol=1e-300", {"reference.atol", ">= 1e-15"});
}
TEST(LobattoTable, RefuseSingularElasticInitialCondition) {
  expect_exit("lobatto_table", 2, "--set 'nonlinear.elastic_initial=[[0.0, 0.0, 0.1, 0.0]]'", {"nonlinear.elastic_initial", "singular"});
}
TEST(LobattoTable, PlanOfThePaperSceneHasFiniteStepCounts) {
  expect_plan("lobatto_table", {"table1", "figure1", "long_run", "stability", "nonlinear", "cost", "long_run_cost"});
}

// Checkpoints (runner/checkpoint.hpp): the long runs of the cost study, stopped after one round and resumed (on 1
// thread), give the files of a run straight through (the sets' wall times aside: every other cell of
// cost_long_run_*.csv, and summary.json but its timing and cost).
TEST(LobattoTable, ResumedLongRunCostGivesTheSameResults) {
  expect_resume_identical("lobatto_table", "--quick --study long_run_cost", 1, "long_run_cost");
}

// A resumed run reruns its studies: a run stopped after table1 (of another amplitude) and resumed with
// long_run_cost alone commits the files run.json lists, not the stopped run's table1.csv beside them.
TEST(LobattoTable, ResumedRunHoldsOnlyItsOwnFiles) {
  namespace fs = std::filesystem;
  const fs::path out = results_dir("lobatto_table-resume-fewer");
  fs::remove_all(out), fs::remove_all(out.string() + ".partial");
  const BinaryOutcome stopped = run_binary("lobatto_table", "--quick --study table1 --study long_run_cost --set "
                                           "oscillator.amplitude=0.5 --set checkpoint.stop_after=1 --out " + out.string());
  ASSERT_EQ(stopped.code, 3) << stopped.err;
  ASSERT_TRUE(fs::exists(out.string() + ".partial/table1.csv"));
  const BinaryOutcome resumed = run_binary("lobatto_table", "--quick --study long_run_cost --resume --out " + out.string());
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const auto run = nlohmann::json::parse(file_text(out / "run.json"));
  std::vector<std::string> listed = run["files"].get<std::vector<std::string>>(), held;
  listed.push_back("run.json");
  for (const auto& e : fs::directory_iterator(out)) held.push_back(e.path().filename().string());
  std::sort(listed.begin(), listed.end()), std::sort(held.begin(), held.end());
  EXPECT_EQ(held, listed);
}

}  // namespace lobatto_table_test
