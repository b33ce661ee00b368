// Regression: the quick scene of rowlands_convergence reproduces 000 Fig. 4
// (Stormer-Verlet order 2, Rowlands order 4) for every initial condition, and
// Forest-Ruth, the order-4 composition it is compared with, is of order 4.
#include <gtest/gtest.h>
#include <sstream>
#include <cstdlib>
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/published.hpp"
#include "summary.hpp"

namespace fs = std::filesystem;

namespace rowlands_convergence_test {  // the file's scope (the tests build as one translation unit)
using json = nlohmann::json;

namespace {

const fs::path dir = results_dir("rowlands_convergence");

const json& summary() { return summary_of("rowlands_convergence"); }

void expect_order(const char* key, double expected, double tol) {
  const auto& all = summary()["orders_by_initial"];
  ASSERT_GE(all.size(), 3u) << "the orders must hold for at least three initial conditions";
  for (std::size_t i = 0; i < all.size(); ++i)
    EXPECT_NEAR(all[i][key].get<double>(), expected, tol) << key << ", initial condition " << i;
}

// A published order (published.toml: value and tolerance) for every initial condition, not only
// the first (which summary.comparisons holds); a known discrepancy (expect = "differs") for each.
void expect_published_order(const std::string& key) {
  static const auto entries = geomint::read_published(std::filesystem::path(GEOMINT_SOURCE_DIR) /
                                                      "experiments/rowlands_convergence/published.toml");
  const auto e = std::find_if(entries.begin(), entries.end(), [&](const auto& p) { return p.key == key; });
  ASSERT_NE(e, entries.end()) << key;
  ASSERT_EQ(e->compare, "order") << key;
  const auto& all = summary()["orders_by_initial"];
  ASSERT_GE(all.size(), 3u) << "the orders must hold for at least three initial conditions";
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double order = all[i][key].get<double>(), published = e->value.get<double>();
    EXPECT_EQ(std::abs(order - published) <= e->tolerance ? "reproduced" : "differs", e->expect)
        << key << ", initial condition " << i << ": order " << order << ", published " << published << " +- "
        << e->tolerance;
  }
}

double declared(const char* method) { return geomint::method_info(method).order; }  // the registry's

}  // namespace

TEST(RowlandsConvergence, StormerVerletIsSecondOrder) {
  expect_published_order("sv_energy");
  expect_published_order("sv_phase");
}

TEST(RowlandsConvergence, RowlandsIsFourthOrderWithBothProcessors) {
  for (const char* key : {"rowlands_energy", "rowlands_phase", "rowlands_cheap_energy", "rowlands_cheap_phase"})
    expect_published_order(key);
}

TEST(RowlandsConvergence, KernelWithoutProcessingIsSecondOrder) {
  // Effective order 4 needs the processors: the kernel alone is of its declared order 2.
  expect_order("kernel_phase", declared("rowlands_kernel"), 0.15);
}

TEST(RowlandsConvergence, PrintedProcessorCoefficientGivesOrderTwo) {
  // (32)-(33) as printed (h^2/24) do not deliver the published order 4 (published.toml: expect
  // "differs"); they give the kernel's order 2, and h^2/12 gives 4.
  expect_published_order("rowlands_printed_phase");
  expect_order("rowlands_printed_phase", declared("rowlands_kernel"), 0.15);
}

TEST(RowlandsConvergence, ForestRuthIsFourthOrder) {
  // The standard fourth-order composition (not in 000), the order-4 peer of the processed method.
  expect_order("forest_ruth_energy", declared("forest_ruth"), 0.3);
  expect_order("forest_ruth_phase", declared("forest_ruth"), 0.3);
}

TEST(RowlandsConvergence, ForestRuthCostsThreeForcesPerStep) {
  // At equal h Forest-Ruth evaluates the force 3 times per step (plus once at the start), and its
  // phase error is larger than that of the processed Rowlands method, which costs less (000 Sec. 3.3).
  const CsvFile csv = read_csv(dir / "fig4_convergence.csv");
  const std::size_t steps = csv.column("steps"), evals = csv.column("forest_ruth_evals"),
                    fr = csv.column("forest_ruth_phase"), row_phase = csv.column("rowlands_phase");
  for (const auto& v : csv.rows) {
    EXPECT_EQ(std::stoll(v[evals]), 3 * std::stoll(v[steps]) + 1) << v[steps];
    EXPECT_GT(std::stod(v[fr]), std::stod(v[row_phase])) << v[steps];
  }
  EXPECT_GT(csv.rows.size(), 0u);
}

TEST(RowlandsConvergence, EveryOrderIsTheSlopeOfThePlottedErrors) {
  // Each order of summary.json (and orders.csv) is the least-squares slope of log err against log h
  // of the Fig. 4 errors (fig4_convergence.csv) of its initial condition over the fitted h range.
  const CsvFile orders = read_csv(dir / "orders.csv"), conv = read_csv(dir / "fig4_convergence.csv");
  const std::size_t initial = orders.column("initial"), name = orders.column("name"), order = orders.column("order"),
                    h_min = orders.column("h_min"), h_max = orders.column("h_max");
  const std::size_t conv_initial = conv.column("initial"), conv_h = conv.column("h");
  for (const auto& o : orders.rows) {
    // order name -> CSV column: the energy norm's RMS is "_energy_rms".
    std::string col = o[name];
    if (col.size() > 7 && col.compare(col.size() - 7, 7, "_energy") == 0) col += "_rms";
    const std::size_t c = conv.column(col);
    const double lo = std::stod(o[h_min]), hi = std::stod(o[h_max]);
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& r : conv.rows) {
      const double h = std::stod(r[conv_h]);
      if (r[conv_initial] != o[initial] || h < lo || h > hi) continue;
      const double x = std::log(h), y = std::log(std::stod(r[c]));
      n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    ASSERT_GE(n, 3) << o[name] << ", initial condition " << o[initial];
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_NEAR(std::stod(o[order]), slope, 1e-9) << o[name] << ", initial condition " << o[initial];
    EXPECT_EQ(summary()["orders_by_initial"][std::stoul(o[initial])][o[name]].get<double>(), std::stod(o[order]))
        << o[name] << ", initial condition " << o[initial];
  }
  EXPECT_EQ(summary()["orders"], summary()["orders_by_initial"][0]);
}

TEST(RowlandsConvergence, ReferenceIsAHundredTimesBelowEveryFittedError) {
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["reference_self_check"].get<double>(), 1e-12);
  EXPECT_GE(r["reference_margin"].get<double>(), 100.0);
}

TEST(RowlandsConvergence, OrderRangesHoldTheOrdersOfEveryInitialCondition) {
  // order_ranges: over all initial conditions and norms, the methods with a second-order kernel by
  // their declared order (order 2: Stormer-Verlet, the kernel alone, (32)-(33) as printed; order 4:
  // the processed Rowlands methods).
  const auto& ranges = summary()["order_ranges"];
  const std::vector<std::pair<const char*, std::vector<std::string>>> groups = {
      {"order_2", {"sv", "kernel", "rowlands_printed"}}, {"order_4", {"rowlands", "rowlands_cheap"}}};
  for (const auto& [group, methods] : groups) {
    const double lo = ranges[group]["min"].get<double>(), hi = ranges[group]["max"].get<double>();
    double seen_lo = 1e300, seen_hi = -1e300;
    for (const auto& o : summary()["orders_by_initial"])
      for (const auto& m : methods)
        for (const char* suffix : {"_energy", "_energy_max", "_phase"}) {
          const double v = o[m + suffix].get<double>();
          seen_lo = std::min(seen_lo, v), seen_hi = std::max(seen_hi, v);
        }
    EXPECT_EQ(lo, seen_lo) << group;
    EXPECT_EQ(hi, seen_hi) << group;
  }
}

TEST(RowlandsConvergence, PrintedCoefficientHalvesTheKernelsError) {
  // To leading order the error of the processed method is proportional to 1/12 - c: with the printed
  // c = 1/24 it is half that of the kernel alone (c = 0), at the smallest h, in both norms.
  const auto& r = summary()["printed_over_kernel"];
  EXPECT_NEAR(r["min"].get<double>(), 0.5, 0.01);
  EXPECT_NEAR(r["max"].get<double>(), 0.5, 0.01);
}

TEST(RowlandsConvergence, CostSummaryOfTheCostStudy) {
  // Force evaluations per step: one gradient for Stormer-Verlet, a gradient and a Hessian-vector
  // product for the Rowlands kernel (31) (Sec. 3.3 counts only the one-time processing as overhead).
  const auto& phase = summary()["cost"]["phase"];
  const auto& by = phase["by_method"];
  EXPECT_NEAR(by["sv"]["evals_per_step"].get<double>(), 1.0, 0.05);
  EXPECT_NEAR(by["rowlands"]["evals_per_step"].get<double>(), 2.0, 0.05);
  const auto targets = phase["targets"].size();
  for (const auto& [m, c] : by.items()) {  // a target is reached in wall time exactly where in evaluations
    ASSERT_EQ(c["wall_s_to"].size(), targets) << m;
    for (std::size_t i = 0; i < targets; ++i) EXPECT_EQ(c["wall_s_to"][i].is_null(), c["evals_to"][i].is_null()) << m;
  }
  EXPECT_EQ(phase["methods"].size(), by.size());
}

// The timing method (runner/timing.hpp, runner/timing_report.hpp): every timed measurement of the cost
// study reports its spread (max - min) / min beside its minimum: one per row of cost_phase.csv, and
// summary.json's cost.phase.spread is over all of them. (Structure only: no timing value is asserted.)
TEST(RowlandsConvergence, EveryTimedMeasurementReportsItsSpread) {
  const CsvFile t = read_csv(results_dir("rowlands_convergence") / "cost_phase.csv");
  const double largest = largest_spread(t);
  const auto& spread = summary_of("rowlands_convergence")["cost"]["phase"]["spread"];
  ASSERT_TRUE(spread.is_object());
  EXPECT_EQ(spread["measurements"].get<std::size_t>(), timed_rows(t));
  EXPECT_GT(expect_interpolated_rows_affine(t), 0u);  // the explicit methods: timed at their fewest and most steps
  EXPECT_GE(spread["max"].get<double>(), largest);
  EXPECT_DOUBLE_EQ(spread["max"].get<double>(), largest);
}

// ---- Bad input (the interface contract): exit 2 before any work, one stderr line naming the key,
// the value and what is allowed, no results directory; --plan of the paper scene (tests/regression/summary.hpp: expect_exit, expect_plan). ----

TEST(RowlandsConvergence, RefuseReferenceToleranceOutsideRange) {
  expect_exit("rowlands_convergence", 2, "--set reference.rtol=1e300", {"reference.rtol", "1e+300", "<= 0.01"});
  expect_exit("rowlands_convergence", 2, "--set reference.rtol=1e-300", {"reference.rtol", "1e-300", ">= 1e-15"});
}
TEST(RowlandsConvergence, RefuseStepCountBeyond2To53) {
  expect_exit("rowlands_convergence", 2, "--set t_end=1e300", {"h", "2^53"});
}
TEST(RowlandsConvergence, RefuseRepeatsBeyondInt) {
  expect_exit("rowlands_convergence", 2, "--set timing.repeats=2147483648", {"timing.repeats", "2147483648"});
}
TEST(RowlandsConvergence, PlanOfThePaperSceneHasFiniteStepCounts) {
  expect_plan("rowlands_convergence", {"convergence", "cost"});
}

}  // namespace rowlands_convergence_test
