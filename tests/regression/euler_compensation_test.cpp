// Regression: the quick scene of euler_compensation reproduces the published
// claims of 000 (Figs 2, 3, 8, 9). Runs on the outputs of the ctest fixture
// euler_compensation.quick_run.
#include <gtest/gtest.h>
#include <cstdlib>
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "summary.hpp"

namespace fs = std::filesystem;

namespace euler_compensation_test {  // the file's scope (the tests build as one translation unit)
using json = nlohmann::json;

namespace {

const fs::path dir = results_dir("euler_compensation");

const json& summary() { return summary_of("euler_compensation"); }

}  // namespace

// The published orders of Fig. 9 and the exactness of Figs 2-3: Published.EulerCompensation
// (published_test.cpp), with the tolerances of experiments/euler_compensation/published.toml.

TEST(EulerCompensation, EulerInTheOriginalCoordinateIsVisiblyOff) {
  // Figs 2-3: at the same steps, Euler in y is off by more than 10 % while Euler in ybar is exact.
  const auto& r = summary()["reproduced"];
  EXPECT_GT(r["decay_euler_max_rel_err"].get<double>(), 0.1);
  EXPECT_GT(r["gompertz_euler_max_rel_err"].get<double>(), 0.1);
}

TEST(EulerCompensation, CompensatedTrajectoryIsCloserToTheCircle) {
  // Fig 8: the compensated solution stays closer to H = 1/2.
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["fig8_max_energy_err_compensated"].get<double>(), r["fig8_max_energy_err_se"].get<double>());
  EXPECT_LT(r["fig8_max_abs_qhat"].get<double>(), 1.0);
  // 000 App. B (published.toml fig8_compensated_closer): the phase portrait with (82) lies closer to the
  // exact orbit, the circle through (q0, p0); the distances again from fig8_phase.csv
  const CsvFile phase = read_csv(dir / "fig8_phase.csv");
  const auto& osc = json_of("euler_compensation", "run.json", "scene")["oscillator"];
  const double radius = std::hypot(osc["q0"].get<double>(), osc["p0"].get<double>());
  double se = 0, compensated = 0;
  for (const auto& row : phase.rows) {
    const auto distance = [&](const char* q, const char* p) {
      return std::abs(std::hypot(std::stod(row[phase.column(q)]), std::stod(row[phase.column(p)])) - radius);
    };
    se = std::max(se, distance("q_se", "p_se")), compensated = std::max(compensated, distance("q_compensated", "p_compensated"));
  }
  EXPECT_DOUBLE_EQ(r["fig8_orbit_distance_ratio"].get<double>(), se / compensated);
  const auto& c = summary()["comparisons"]["fig8_compensated_closer"];
  EXPECT_EQ(c["verdict"], "reproduced") << c.dump(2);
}

TEST(EulerCompensation, Rk4EnergyErrorIsFifthOrderOnTheOscillator) {
  // |R(ih)|^2 = 1 - h^6/72 + O(h^8) for RK4, so after T/h steps |H - H0| ~ T h^5 / 144.
  EXPECT_NEAR(summary()["orders"]["rk4_energy"].get<double>(), 5.0, 0.1);
}

TEST(EulerCompensation, CostRunsHaveTheErrorsAndEvaluationsOfTheConvergenceRuns) {
  // The cost study's error and force evaluations at a step h (cost_energy.csv, the set "energy") are
  // those of the convergence run at the same h (fig9_convergence.csv), over t_end / h steps.
  const CsvFile cost = read_csv(dir / "cost_energy.csv"), conv = read_csv(dir / "fig9_convergence.csv");
  std::ifstream in(dir / "run.json");
  const double t_end = json::parse(in)["scene"]["convergence"]["t_end"];
  int matched = 0;
  for (const auto& row : cost.rows) {
    const std::string label = row[cost.column("method")];
    const double h = std::stod(row[cost.column("h")]);
    EXPECT_EQ(std::stoll(row[cost.column("steps")]), std::llround(t_end / h));
    for (const auto& c : conv.rows) {
      if (std::stod(c[conv.column("h")]) != h) continue;
      ++matched;
      EXPECT_EQ(row[cost.column("force_evals")], c[conv.column(label + "_evals")]) << label << " h = " << h;
      EXPECT_DOUBLE_EQ(std::stod(row[cost.column("err")]), std::stod(c[conv.column(label + "_max")]))
          << label << " h = " << h;
    }
  }
  EXPECT_GE(matched, 6);  // at least two common steps for each of the three methods
}

TEST(EulerCompensation, OutputsAreComplete) {
  for (const char* f : {"fig2_decay.csv", "fig2_decay_exact.csv", "fig3_gompertz.csv", "fig3_gompertz_exact.csv",
                        "fig8_phase.csv", "fig8_exact.csv", "fig9_convergence.csv", "orders.csv", "cost_energy.csv",
                        "summary.json", "run.json"}) {
    ASSERT_TRUE(fs::is_regular_file(dir / f)) << f;
    EXPECT_GT(fs::file_size(dir / f), 20u) << f;
  }
  std::ifstream in(dir / "run.json");
  const json run = json::parse(in);
  EXPECT_FALSE(run["build"]["git_commit"].get<std::string>().empty());
  // Fig 8 used the k and h that run.json records: max |qhat| = max |q| / (1 + k h^2), (82).
  const double k = run["scene"]["oscillator"]["k"], h = run["scene"]["oscillator"]["h"];
  const CsvFile phase = read_csv(dir / "fig8_phase.csv");
  double max_q = 0;
  for (const auto& row : phase.rows) max_q = std::max(max_q, std::abs(std::stod(row[phase.column("q_compensated")])));
  EXPECT_NEAR(summary()["reproduced"]["fig8_max_abs_qhat"].get<double>(), max_q / (1 + k * h * h), 1e-15);
}

TEST(EulerCompensation, CompensatedEulerAgreesWithAnIndependentSolution) {
  // Figs 2-3: Euler in ybar mapped back by Psi^{-1} against odeint's Bulirsch-Stoer on y' = f(y), not
  // against the closed form (built from the same expression as Psi^{-1}); the reference's own error
  // against the closed form is stated beside it.
  const auto& r = summary()["reproduced"];
  for (const std::string key : {"decay", "gompertz"}) {
    EXPECT_LT(r[key + "_odeint_max_rel_err"].get<double>(), 1e-12) << key;
    EXPECT_LT(r[key + "_compensated_max_rel_err_odeint"].get<double>(), 1e-12) << key;
    EXPECT_GT(r[key + "_euler_max_rel_err"].get<double>(), 0.1) << key;
  }
}

TEST(EulerCompensation, PrintedFieldSixteenIsExactOnlyForAlphaOne) {
  // 000 (16) prints ybar' = -alpha; with Psi of (15) the field is -1 (3). Mapped back by (15), Euler
  // on the printed field misses the exact solution at alpha != 1 (published.toml: decay_printed_field) ...
  const auto& r = summary()["reproduced"];
  EXPECT_EQ(summary()["comparisons"]["decay_printed_field"]["verdict"], "differs");
  EXPECT_GT(r["decay_printed_field_max_rel_err"].get<double>(), 0.1);
  // ... while on the field -1 it is exact to round-off (Fig. 2).
  EXPECT_LT(r["decay_compensated_max_rel_err"].get<double>(), 1e-12);
}

TEST(EulerCompensation, CostSummaryOfTheCostStudy) {
  // Time per step relative to the first method, and the crossover of the first two methods' work-precision
  // curves: a point inside the wall times both measure, where both interpolated errors agree.
  const auto& c = summary()["cost"];
  const auto& ns = c["ns_per_step"];
  for (const auto& [m, v] : ns.items())
    EXPECT_DOUBLE_EQ(c["relative_ns_per_step"]["by_method"][m]["ratio"].get<double>(), v.get<double>() / ns["se"].get<double>())
        << m;
  const auto& h = summary()["h_range"];
  EXPECT_LT(h["timing"]["min"].get<double>(), h["timing"]["max"].get<double>());
  EXPECT_EQ(h["convergence"]["count"].get<int>(), summary()["fits"]["se_energy"]["points"].get<int>());
  ASSERT_EQ(c["crossover"]["methods"], json({"se", "se_compensated"}));  // (always: the keys do not depend on timings)
  if (c["crossover"]["wall_s"].is_null()) return;  // the curves do not cross within the measured wall times
  EXPECT_GT(c["crossover"]["err"].get<double>(), 0.0);
  const CsvFile t = read_csv(dir / "cost_energy.csv");
  std::map<std::string, std::pair<double, double>> range;  // per method: its smallest and largest wall time
  for (const auto& r : t.rows) {
    const double w = std::stod(r[t.column("wall_s")]);
    const auto it = range.try_emplace(r[t.column("method")], w, w).first;
    it->second = {std::min(it->second.first, w), std::max(it->second.second, w)};
  }
  const double wall = c["crossover"]["wall_s"].get<double>();
  for (const char* m : {"se", "se_compensated"}) {
    EXPECT_GE(wall, range[m].first) << m;
    EXPECT_LE(wall, range[m].second) << m;
  }
}

TEST(EulerCompensation, EnergyNormFiftyIsPreAsymptoticOverFigureNine) {
  // With (82) the energy error is second order in the max norm (Fig. 9), but in the l2 norm (50) the
  // fit over these step sizes is steeper (published.toml: se_compensated_energy_rms): the local slopes
  // of fig9_convergence.csv come down towards 2 only at the smallest h.
  const auto& o = summary()["orders"];
  EXPECT_EQ(summary()["comparisons"]["se_compensated_energy_rms"]["verdict"], "differs");
  EXPECT_NEAR(o["se_compensated_energy"].get<double>(), 2.0, 0.1);
  EXPECT_GT(o["se_compensated_energy_rms"].get<double>(), 2.1);
  std::ifstream in(dir / "fig9_convergence.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream ss(line); std::getline(ss, line, ',');) names.push_back(line);
  const auto col = static_cast<std::size_t>(std::find(names.begin(), names.end(), "se_compensated_rms") - names.begin());
  ASSERT_LT(col, names.size());
  std::vector<double> h, e;
  while (std::getline(in, line)) {
    std::vector<double> v;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) v.push_back(std::stod(line));
    h.push_back(v[0]), e.push_back(v[col]);
  }
  ASSERT_GE(h.size(), 3u);
  std::vector<double> slopes;
  for (std::size_t i = 0; i + 1 < h.size(); ++i) slopes.push_back(std::log(e[i] / e[i + 1]) / std::log(h[i] / h[i + 1]));
  EXPECT_LT(slopes.back(), *std::max_element(slopes.begin(), slopes.end()));
  EXPECT_GT(slopes.back(), 2.0);
}

// The timing method (runner/timing.hpp, runner/timing_report.hpp): every timed measurement of the cost
// study reports its spread (max - min) / min beside its minimum: one per row of cost_energy.csv, over
// which summary.json's cost.energy.spread is, and one per method for ns_per_step (cost.ns_per_step_spread).
// (Structure only: no timing value is asserted.)
TEST(EulerCompensation, EveryTimedMeasurementReportsItsSpread) {
  const CsvFile t = read_csv(results_dir("euler_compensation") / "cost_energy.csv");
  const double largest = largest_spread(t);
  const auto& cost = summary_of("euler_compensation")["cost"];
  const auto& spread = cost["energy"]["spread"];
  ASSERT_TRUE(spread.is_object());
  expect_interpolated_rows_affine(t);
  EXPECT_EQ(spread["measurements"].get<std::size_t>(), timed_rows(t));
  EXPECT_GE(spread["max"].get<double>(), largest);
  ASSERT_EQ(cost["ns_per_step_spread"].size(), cost["ns_per_step"].size());
  for (const auto& [m, ns] : cost["ns_per_step"].items()) EXPECT_TRUE(cost["ns_per_step_spread"][m].is_number()) << m;
}

// Equal wall time is the one rule (analysis/work_precision.hpp equal_cost): the least of the methods'
// largest wall times in cost_energy.csv; the crossover is of the first two methods' curves.
TEST(EulerCompensation, EqualWallTimeIsTheLeastLargestWallTime) {
  const CsvFile t = read_csv(dir / "cost_energy.csv");
  std::map<std::string, double> largest;
  for (const auto& r : t.rows) {
    double& w = largest[r[t.column("method")]];
    w = std::max(w, std::stod(r[t.column("wall_s")]));
  }
  double least = largest.begin()->second;
  for (const auto& [m, w] : largest) least = std::min(least, w);
  const auto& cost = summary()["cost"];
  EXPECT_DOUBLE_EQ(cost["energy"]["equal_wall_s"].get<double>(), least);
  for (const auto& [m, w] : largest) EXPECT_TRUE(cost["energy"]["by_method"][m]["err_at_equal_wall"].is_number()) << m;
  EXPECT_EQ(cost["crossover"]["methods"], json({"se", "se_compensated"}));
}

// ---- Bad input (the interface contract): exit 2 before any work, one stderr line naming the key,
// the value and what is allowed, no results directory; --plan of the paper scene (tests/regression/summary.hpp: expect_exit, expect_plan). ----

TEST(EulerCompensation, RefuseStepCountBeyond2To53) {
  expect_exit("euler_compensation", 2, "--set convergence.t_end=1e300", {"convergence.h", "2^53"});
}
TEST(EulerCompensation, RefuseRepeatsBeyondInt) {
  expect_exit("euler_compensation", 2, "--set timing.repeats=2147483648", {"timing.repeats", "2147483648"});
}
TEST(EulerCompensation, RefuseFigureLongerThanMemory) {
  expect_exit("euler_compensation", 2, "--set oscillator.steps=2000000000", {"oscillator", "memory"});
}
TEST(EulerCompensation, PlanOfThePaperSceneHasFiniteStepCounts) {
  expect_plan("euler_compensation", {"decay", "gompertz", "oscillator", "convergence", "cost"});
}

}  // namespace euler_compensation_test
