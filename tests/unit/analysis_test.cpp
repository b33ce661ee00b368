// The library's analysis helpers that experiments share: the stability-bound bisection and the
// scanned stable set (analysis/linear_stability.hpp), the area of a convex hull in the plane
// (geometry/convex_area.hpp), Poincare cuts (analysis/poincare.hpp) and the crossing of two
// work-precision curves, the rule of equal cost and the work-precision set of every cost study
// (analysis/work_precision.hpp, analysis/work_precision_set.hpp), and the convergence study of every
// order figure and table (analysis/convergence_study.hpp).
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../hard_case.hpp"

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/convergence_study.hpp"
#include "geomint/analysis/poincare.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/geometry/convex_area.hpp"
#include "geomint/runner/results_json.hpp"

using namespace geomint;

namespace analysis_test {  // the file's scope (the tests build as one translation unit)

// Stormer-Verlet on q'' = -q: |trace| of its one-step matrix is |2 - (w h)^2|, stable for w h < 2.
TEST(StabilityBoundary, BisectsStormerVerletToItsBoundOfTwo) {
  const auto stable = [](double wh) { return std::abs(2 - wh * wh) < 2; };
  const double b = stability_boundary(stable, 1.0, 3.0);
  EXPECT_TRUE(stable(b));
  EXPECT_FALSE(stable(std::nextafter(b, 4.0)) && stable(std::nextafter(std::nextafter(b, 4.0), 4.0)));
  EXPECT_CASE_NEAR("bisected bound of omega h for |2 - (omega h)^2| < 2 on [1, 3]", b, 2.0, 4e-16);
}

TEST(StabilityBoundary, ReturnsTheLastStablePointOfTheBracket) {
  // Stable below 0.3: 60 halvings of [0, 1] close in on the last double below it (the spacing there is 2^-54).
  // (measured and bound in units of the spacing of doubles below 0.3 from 0.3)
  const double ulp = 0.3 - std::nextafter(0.3, 0.0);
  EXPECT_CASE("last stable point of x < 0.3 on [0, 1], in ulps from 0.3",
              (stability_boundary([](double x) { return x < 0.3; }, 0.0, 1.0) - 0.3) / ulp, "==", -1);
  EXPECT_CASE("last stable point of x <= 0.3 on [0, 1], in ulps from 0.3",
              (stability_boundary([](double x) { return x <= 0.3; }, 0.0, 1.0) - 0.3) / ulp, "==", 0);
}

// A scan with two stable runs, one of them a single point at the end, and a radius one tolerance
// above 1 (stable) next to one just beyond it (not).
TEST(StableIntervals, AreTheMaximalRunsOfStableScanPoints) {
  const std::vector<double> x{0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
  const double tol = 1e-12;
  const std::vector<double> rho{1.0, 1.0 + tol, 1.0 + 2 * tol, 1.2, 0.9, 1.1, 1.0};
  const auto set = stable_intervals(x, rho, tol);
  ASSERT_EQ(set.size(), 3u);
  EXPECT_EQ(set[0].lo, 0.0);
  EXPECT_EQ(set[0].hi, 0.5);
  EXPECT_EQ(set[1].lo, 2.0);
  EXPECT_EQ(set[1].hi, 2.0);
  EXPECT_EQ(set[2].lo, 3.0);
  EXPECT_EQ(set[2].hi, 3.0);
  EXPECT_TRUE(stable_intervals(x, std::vector<double>(x.size(), 2.0), tol).empty());
  EXPECT_EQ(stable_intervals(x, std::vector<double>(x.size(), 1.0), tol).size(), 1u);
}

// The unit square with interior, repeated and edge points; a triangle in either orientation; a line.
TEST(ConvexArea, CountsOnlyTheHull) {
  EXPECT_DOUBLE_EQ(convex_area({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.5, 0}, {1, 1}, {0.2, 0.9}}), 1.0);
  EXPECT_DOUBLE_EQ(convex_area({{0, 0}, {2, 0}, {0, 3}}), 3.0);
  EXPECT_DOUBLE_EQ(convex_area({{0, 3}, {2, 0}, {0, 0}}), 3.0);
  EXPECT_EQ(convex_area({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), 0.0);
  EXPECT_EQ(convex_area({{1, 1}}), 0.0);
  // A regular 12-gon of radius 1, its vertices shuffled: area 3.
  std::vector<std::array<double, 2>> gon;
  for (int k : {5, 0, 7, 2, 11, 9, 1, 3, 10, 4, 8, 6})
    gon.push_back({std::cos(k * std::numbers::pi / 6), std::sin(k * std::numbers::pi / 6)});
  EXPECT_NEAR(convex_area(gon), 3.0, 1e-15);
}

// Two power laws err = c w^-p in wall time w: a (order 1) cheap at low accuracy, b (order 2) below it.
std::vector<CostRun> curve(double c, double p) {
  std::vector<CostRun> runs;
  for (double w : {1e-4, 1e-3, 1e-2, 1e-1}) runs.push_back({1 / w, 1 / w, w, 1 / w, c * std::pow(w, -p)});
  return runs;
}

TEST(WorkPrecision, CrossoverOfTwoPowerLawsIsWhereTheyAreEqual) {
  // 1e-4 / w = 1e-6 / w^2 at w = 1e-2, a break point of both curves.
  const auto at_break = crossover(curve(1e-4, 1), curve(1e-6, 2));
  ASSERT_TRUE(at_break.has_value());
  EXPECT_NEAR(at_break->wall_s, 1e-2, 1e-15);
  EXPECT_NEAR(at_break->err, 1e-2, 1e-15);
  // 1e-4 / w = 3e-7 / w^2 at w = 3e-3, between break points (exact: both curves are linear in log-log).
  const auto inside = crossover(curve(1e-4, 1), curve(3e-7, 2));
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->wall_s, 3e-3, 1e-15);
  EXPECT_NEAR(inside->err, 1e-4 / 3e-3, 1e-12);
}

TEST(WorkPrecision, CrossoverIsFoundInTheSegmentWhereTheCurvesChangeOrder) {
  // a falls by 10 per decade of wall time; b stays at 10, then drops: they cross between 1e-3 and 1e-2 s,
  // where log(a/b) goes from log(0.01) to log(10): at w = 1e-3 * 10^(2/3), error 0.1 / 10^(2/3).
  std::vector<CostRun> a = curve(1e-4, 1), b = a;
  const double b_err[] = {10, 10, 1e-3, 1e-4};
  for (std::size_t i = 0; i < b.size(); ++i) b[i].err = b_err[i];
  const auto c = crossover(a, b);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->wall_s, 1e-3 * std::pow(10.0, 2.0 / 3), 1e-15);
  EXPECT_NEAR(c->err, 0.1 / std::pow(10.0, 2.0 / 3), 1e-13);
}

TEST(WorkPrecision, NoCrossoverWhereTheCurvesDoNotMeetOrDoNotOverlap) {
  EXPECT_FALSE(crossover(curve(1e-4, 1), curve(1e-9, 1)).has_value());  // parallel, apart
  std::vector<CostRun> late = curve(1e-6, 2);
  for (auto& r : late) r.wall_s *= 1e6;  // no common wall-time range
  EXPECT_FALSE(crossover(curve(1e-4, 1), late).has_value());
}

// The section q1 = 0 upwards: a step from q1 = -1 to q1 = 3 crosses at a quarter of the step.
TEST(WorkPrecision, EqualCostIsTheLargestCostEveryCurveReaches) {
  std::vector<CostRun> a = curve(1e-4, 1), b = curve(1e-6, 2);
  b.pop_back();  // b measured to wall 1e-2 only
  EXPECT_EQ(equal_cost({a, b}, &CostRun::wall_s), 1e-2);
  EXPECT_EQ(equal_cost({a, b}, &CostRun::evals), 1e4);  // evals = 1 / w: the largest b reaches is 1e4
  std::vector<CostRun> late = curve(1, 1);
  for (CostRun& r : late) r.wall_s *= 1e4;  // walls 1 .. 1e3: no range shared with a
  EXPECT_FALSE(equal_cost({a, late}, &CostRun::wall_s).has_value());
  EXPECT_FALSE(equal_cost({a, {}}, &CostRun::wall_s).has_value());
}

TEST(WorkPrecision, ErrorAtCostInterpolatesPowerLawsExactly) {
  const auto b = curve(1e-6, 2);  // err = 1e-6 w^-2 = 1e-6 evals^2
  EXPECT_NEAR(*error_at_cost(b, std::sqrt(1e-3 * 1e-2), &CostRun::wall_s) / (1e-6 / (1e-3 * 1e-2)), 1, 1e-13);
  EXPECT_NEAR(*error_at_cost(b, 300.0, &CostRun::evals) / (1e-6 * 300.0 * 300.0), 1, 1e-13);
  EXPECT_FALSE(error_at_cost(b, 1.0, &CostRun::wall_s).has_value());  // beyond the largest run: never extrapolated
}

// Two methods, four steps each: a of order 1 in wall time (err = 1e-4 / w), b of order 2, b timed at half a's rate.
WorkPrecisionSet two_methods() {
  WorkPrecisionSet set("the error of a run");
  for (const char* m : {"a", "b"})
    for (double w : {1e-4, 1e-3, 1e-2, 1e-1}) {
      const bool is_a = m == std::string("a");
      RunTime t;  // the estimate (the median) w or w / 2, its interquartile range once the median
      t.median_s = is_a ? w : w / 2, t.q1_s = 0.75 * t.median_s, t.q3_s = 1.75 * t.median_s;
      t.min_s = 0.5 * t.median_s, t.max_s = 2 * t.median_s, t.repeats = 7, t.inner = 1;
      set.add({m, 1 / w, 1e3 * w, t, (is_a ? 2 : 4) * 1e3 * w, is_a ? 1e-4 / w : 1e-6 / (w * w)});
    }
  return set;
}

TEST(WorkPrecisionSet, SummaryInTheOneShape) {
  const auto s = to_json(two_methods().summary({1e-3, 1e-9}));
  EXPECT_EQ(s["methods"], nlohmann::ordered_json({"a", "b"}));
  EXPECT_EQ(s["equal_wall_s"].get<double>(), 0.05);  // b's largest wall time 1e-1 / 2
  EXPECT_EQ(s["equal_evals"].get<double>(), 200.0);  // a's largest: 2 evaluations per step, 100 steps
  const auto& a = s["by_method"]["a"];
  const auto& b = s["by_method"]["b"];
  EXPECT_EQ(a["runs"], 4);
  EXPECT_NEAR(a["err_at_equal_wall"].get<double>() / (1e-4 / 0.05), 1, 1e-13);
  EXPECT_NEAR(b["err_at_equal_wall"].get<double>() / (1e-6 / (0.1 * 0.1)), 1, 1e-13);
  EXPECT_NEAR(b["err_at_equal_evals"].get<double>() / (1e-6 / (0.05 * 0.05)), 1, 1e-13);  // 200 evals: w = 0.05
  EXPECT_NEAR(a["wall_s_to"][0].get<double>() / 0.1, 1, 1e-13);  // 1e-4 / w = 1e-3 at w = 0.1
  EXPECT_NEAR(b["wall_s_to"][0].get<double>() / (std::sqrt(1e-3) / 2), 1, 1e-13);  // timed at half a's rate
  EXPECT_TRUE(a["wall_s_to"][1].is_null());  // 1e-9 is beyond the measured steps
  EXPECT_NEAR(a["evals_to"][0].get<double>() / 200, 1, 1e-13);
  EXPECT_EQ(a["min_err"].get<double>(), 1e-4 / 1e-1);
  EXPECT_NEAR(a["ns_per_step"].get<double>() / (1e9 * 1e-1 / 100), 1, 1e-13);  // at the smallest h (largest w)
  EXPECT_EQ(b["evals_per_step"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(b["ns_per_step_spread"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["spread"]["max"].get<double>(), 1.0);
  EXPECT_EQ(s["spread"]["measurements"], 8);
}

TEST(WorkPrecisionSet, CsvHasOneRowPerRecord) {
  const Csv csv = two_methods().csv();
  EXPECT_EQ(csv.rows(), 8u);
  EXPECT_EQ(csv.str().substr(0, csv.str().find('\n')),
            "method,h,steps,wall_s,wall_q1_s,wall_q3_s,wall_spread,wall_timed,force_evals,err");
}

// Each method's time per step at its smallest h against the first's, with the force evaluations per
// step as the work: b at half a's time per step but spreads of 100 %: indistinguishable.
TEST(WorkPrecisionSet, RelativeTimePerStepKnowsTheNoise) {
  const auto r = to_json(two_methods().relative_ns_per_step());
  EXPECT_EQ(r["reference"], "a");
  EXPECT_DOUBLE_EQ(r["by_method"]["b"]["ratio"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(r["by_method"]["b"]["interval"]["min"].get<double>(), 0.75 * 0.5 / 1.75);
  EXPECT_EQ(r["by_method"]["b"]["verdict"], "indistinguishable");
}

// Each method's wall time to a target against the first method that reaches it, with the interval of the times
// per step carried over (b: half a's time per step, spreads of 100 %, indistinguishable per step, but of order 2:
// to 1e-3 in a sixth of a's time, faster beyond that interval), and nothing for a target no method reaches.
TEST(WorkPrecisionSet, TimeToATargetCarriesTheIntervalOfTheTimesPerStep) {
  const auto r = to_json(two_methods().summary({1e-3, 1e-9}))["ratios_to"];
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0]["reference"], "a");
  const auto& b = r[0]["by_method"]["b"];
  const double ratio = (std::sqrt(1e-3) / 2) / 0.1;  // (b's and a's wall times to 1e-3, SummaryInTheOneShape)
  EXPECT_NEAR(b["wall_ratio"].get<double>() / ratio, 1, 1e-13);
  EXPECT_NEAR(b["min"].get<double>() / (ratio * (0.75 / 1.75)), 1, 1e-13);  // q1_b / q3_a over median_b / median_a
  EXPECT_NEAR(b["max"].get<double>() / (ratio * (1.75 / 0.75)), 1, 1e-13);
  EXPECT_EQ(b["verdict"], "faster");
  EXPECT_TRUE(r[1]["reference"].is_null());
  EXPECT_TRUE(r[1]["by_method"].empty());
}

// A method of fixed work per step (force evaluations 2 n + 1 at every h) is timed at its fewest and most
// steps, its other runs interpolated affinely in the steps; one whose evaluations are not affine in the steps
// (a Newton iteration count that changes with h) and one of two runs are timed at every run.
TEST(WorkPrecisionSet, TimesAMethodOfFixedWorkPerStepAtItsEnds) {
  WorkPrecisionSet set("e");
  std::map<std::string, int> calls;
  const auto add = [&](const std::string& m, double n, double evals) {
    set.add({m, 1 / n, n, {}, evals, 1 / n}, [&calls, key = m + std::to_string(static_cast<int>(n))] { ++calls[key]; });
  };
  for (double n : {100, 10, 1000, 300}) add("fixed", n, 2 * n + 1), add("newton", n, n < 500 ? 3 * n : 4 * n);
  for (double n : {10, 20}) add("two", n, 2 * n);
  set.time(7);
  for (const char* k : {"fixed10", "fixed1000", "newton10", "newton100", "newton300", "newton1000", "two10", "two20"})
    EXPECT_GE(calls[k], 7) << k;
  EXPECT_EQ(calls["fixed100"], 0);
  EXPECT_EQ(calls["fixed300"], 0);
  const auto& r = set.records();  // in the order added: fixed and newton alternate, n = 100, 10, 1000, 300
  EXPECT_FALSE(r[0].wall_timed);
  EXPECT_TRUE(r[2].wall_timed && r[4].wall_timed && r[1].wall_timed);
  const RunTime expect = affine_in_steps(r[2].wall, 10, r[4].wall, 1000, 300);
  EXPECT_EQ(r[6].wall.median_s, expect.median_s);
  EXPECT_EQ(r[6].wall.q3_s, expect.q3_s);
  EXPECT_EQ(set.summary({})["by_method"]["fixed"]["timed_runs"].integer(), 2);
  EXPECT_EQ(set.summary({})["spread"]["measurements"].integer(), 8);  // the timed runs only
  const Csv csv = set.csv();
  EXPECT_NE(csv.str().find("\nfixed,0.01,100,"), std::string::npos);
}

// A second set of the same runs with another error takes the first's wall times (timed once); a set of
// other runs is refused.
TEST(WorkPrecisionSet, TakesTheTimesOfASetOfTheSameRuns) {
  WorkPrecisionSet timed("trajectory"), energy("energy"), other("energy");
  for (double n : {10, 100, 1000}) {
    timed.add({"fixed", 1 / n, n, {}, 2 * n, 1 / n}, [] {});
    energy.add({"fixed", 1 / n, n, {}, 2 * n, 1 / (n * n)});
    other.add({"fixed", 2 / n, n, {}, 2 * n, 1 / (n * n)});
  }
  timed.time(7);
  energy.times_of(timed);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(energy.records()[k].wall.median_s, timed.records()[k].wall.median_s);
    EXPECT_EQ(energy.records()[k].wall_timed, timed.records()[k].wall_timed);
    EXPECT_EQ(energy.records()[k].err, 1 / std::pow(timed.records()[k].steps, 2));
  }
  EXPECT_FALSE(energy.records()[1].wall_timed);  // (the middle run of fixed work per step, interpolated)
  EXPECT_THROW(other.times_of(timed), std::logic_error);
}

// t(n) = t0 + n t1 through two runs, every statistic.
TEST(WorkPrecisionSet, AffineInStepsThroughTwoRuns) {
  RunTime a, b;
  a.min_s = 1, a.q1_s = 2, a.median_s = 3, a.q3_s = 4, a.max_s = 5;
  b.min_s = 11, b.q1_s = 22, b.median_s = 33, b.q3_s = 44, b.max_s = 55;
  const RunTime m = affine_in_steps(a, 10, b, 110, 60);
  EXPECT_DOUBLE_EQ(m.min_s, 6);
  EXPECT_DOUBLE_EQ(m.q1_s, 12);
  EXPECT_DOUBLE_EQ(m.median_s, 18);
  EXPECT_DOUBLE_EQ(m.q3_s, 24);
  EXPECT_DOUBLE_EQ(m.max_s, 30);
  EXPECT_EQ(m.repeats, 0);
}

// Records added with a run are timed together by time(); a record timed by its caller keeps its time.
TEST(WorkPrecisionSet, TimesTheRecordsAddedWithARun) {
  WorkPrecisionSet set("e");
  int calls = 0;
  RunTime given;
  given.median_s = 42;
  set.add({"a", 0.1, 10, given, 10, 1e-3});
  set.add({"b", 0.1, 10, {}, 10, 1e-3}, [&] { ++calls; });
  set.time(7);
  EXPECT_EQ(set.records()[0].wall.median_s, 42);
  EXPECT_EQ(set.records()[1].wall.repeats, 7);
  EXPECT_GE(calls, 1 + 1 + 7);  // a warm-up, a calibration run, the rounds
}

// Two initial conditions, four steps: err = 3 h^2 (condition 0) and h^4 (condition 1), and a
// column that is not fitted.
ConvergenceStudy two_conditions() {
  ConvergenceStudy conv({.csv = "conv.csv", .h = {0.1, 0.05, 0.025, 0.0125}, .steps = {10, 20, 40, 80}, .initials = 2});
  conv.column("a_err", [](std::size_t i, std::size_t j) {
        const double h = 0.1 / std::pow(2.0, static_cast<double>(j));
        return i == 0 ? 3 * h * h : h * h * h * h;
      })
      .column("a_evals", [](std::size_t i, std::size_t j) { return static_cast<double>(10 * (i + 1) << j); });
  return conv;
}

TEST(ConvergenceStudy, FitsEachColumnPerInitialConditionInOneShape) {
  ConvergenceStudy conv = two_conditions();
  conv.fit("a_energy", "a_err", 1e-13).fit("a_energy_high", "a_err", [](std::size_t i) { return i == 0 ? 1e-13 : 1e-7; });
  EXPECT_NEAR(conv.orders().at("a_energy").number(), 2.0, 1e-12);
  EXPECT_NEAR(conv.orders(1).at("a_energy").number(), 4.0, 1e-12);
  EXPECT_NEAR(conv.fits().at("a_energy").at("log10_c").number(), std::log10(3.0), 1e-12);
  EXPECT_EQ(conv.fits(1).at("a_energy").at("points").integer(), 4);
  EXPECT_EQ(conv.order("a_energy_high", 1).points, 3);  // h^4 = 2.4e-8 < 1e-7 at the smallest h: left out
  EXPECT_EQ(conv.order("a_energy_high", 1).h_min, 0.025);
  EXPECT_EQ(conv.values("a_evals", 1), (std::vector<double>{20, 40, 80, 160}));
  // The runs' CSV: initial, h, steps, the columns; one row per (initial condition, h).
  const std::string runs = conv.csv().str();
  EXPECT_EQ(runs.substr(0, runs.find('\n')), "initial,h,steps,a_err,a_evals");
  EXPECT_EQ(conv.csv().rows(), 8u);
  EXPECT_NE(runs.find("\n1,0.012500000000000001,80,2.4414062500000008e-08,160\n"), std::string::npos) << runs;
  // orders.csv: by initial condition, then in the order fitted.
  const std::string orders = conv.orders_csv().str();
  EXPECT_EQ(orders.substr(0, orders.find('\n')), "initial,name,order,log10_c,r2,points,h_min,h_max");
  std::vector<std::string> keys;
  for (std::size_t at = orders.find('\n') + 1; at < orders.size(); at = orders.find('\n', at) + 1)
    keys.push_back(orders.substr(at, orders.find(',', orders.find(',', at) + 1) - at));
  EXPECT_EQ(keys, (std::vector<std::string>{"0,a_energy", "0,a_energy_high", "1,a_energy", "1,a_energy_high"}));
}

TEST(ConvergenceStudy, OneInitialConditionHasNoInitialColumn) {
  ConvergenceStudy conv({.csv = "conv.csv", .h = {0.1, 0.05, 0.025}, .steps = {10, 20, 40}});
  conv.column("e", [](std::size_t, std::size_t j) { return 1.0 / static_cast<double>(1 << j); }).fit("e", "e", 0.0);
  EXPECT_EQ(conv.csv().str(), "h,steps,e\n0.10000000000000001,10,1\n0.050000000000000003,20,0.5\n0.025000000000000001,40,0.25\n");
  EXPECT_NEAR(conv.orders().at("e").number(), 1.0, 1e-12);
}

TEST(ConvergenceStudy, RefusesASeriesWithFewerThanThreePointsAboveItsFloorNamingIt) {
  ConvergenceStudy conv = two_conditions();
  EXPECT_REFUSAL_OF(NumericalFailure, "an order fit with two of four points above the floor 1e-6 (condition 1)",
                    conv.fit("sv_phase", "a_err", 1e-6, "round-off or the reference's accuracy"),
                    {"sv_phase", "initial condition 1", "reference's accuracy"});
  EXPECT_REFUSAL_OF(std::logic_error, "a fit of a column that was not added", conv.fit("b", "b_err", 0.0), {"no column b_err"});
}

// The rule of a fit: a window h <= h_max leaves the larger steps out; a fit that is not required has "no
// order" where fewer than 3 points remain (null in the summary, no row in orders.csv, nothing to recompute).
TEST(ConvergenceStudy, FitsInsideItsWindowAndMayHaveNoOrder) {
  ConvergenceStudy conv = two_conditions();
  conv.fit("windowed", "a_err", OrderFitRule{.floor = [](std::size_t) { return 0.0; }, .h_max = 0.05});
  EXPECT_EQ(conv.order("windowed").points, 3);
  EXPECT_EQ(conv.order("windowed").h_max, 0.05);
  conv.fit("optional", "a_err", OrderFitRule{.floor = [](std::size_t i) { return i == 0 ? 0.0 : 1e-6; }, .required = false});
  EXPECT_TRUE(conv.has_order("optional", 0));
  EXPECT_FALSE(conv.has_order("optional", 1));
  EXPECT_TRUE(conv.orders(1).at("optional").is_null());
  EXPECT_FALSE(conv.fits(1).contains("optional"));
  EXPECT_EQ(conv.orders_csv().rows(), 3u);  // windowed at 0 and 1, optional at 0
  EXPECT_THROW(conv.order("optional", 1), std::logic_error);
}

// A run that was not made (beyond a method's stability bound) is NaN in a row its flag column marks: the
// CSV may hold it, and the fit leaves it out.
TEST(ConvergenceStudy, RunsNotMadeAreNaNInFlaggedRows) {
  ConvergenceStudy conv({.csv = "conv.csv", .h = {0.4, 0.2, 0.1, 0.05}, .steps = {10, 20, 40, 80}});
  const auto beyond = [](std::size_t, std::size_t j) { return j == 0; };  // (h = 0.4 beyond the bound)
  conv.column("e", [&](std::size_t i, std::size_t j) {
        return beyond(i, j) ? std::numeric_limits<double>::quiet_NaN() : std::pow(0.4 / std::pow(2.0, static_cast<double>(j)), 2);
      })
      .flag("e_beyond_bound", beyond)
      .fit("e", "e", 0.0);
  EXPECT_EQ(conv.csv().unflagged_non_finite(), "");
  EXPECT_NE(conv.csv().str().find("0.40000000000000002,10,nan,1\n"), std::string::npos) << conv.csv().str();
  EXPECT_EQ(conv.order("e").points, 3);
  EXPECT_NEAR(conv.order("e").order, 2.0, 1e-12);
  ConvergenceStudy unflagged({.csv = "conv.csv", .h = {0.4, 0.2}, .steps = {10, 20}});
  unflagged.column("e", [](std::size_t, std::size_t j) { return j == 0 ? std::numeric_limits<double>::quiet_NaN() : 1.0; });
  EXPECT_NE(unflagged.csv().unflagged_non_finite(), "");  // (the runner refuses to write it)
}

TEST(PoincareSection, UpwardCutInterpolatesTheStepLinearly) {
  const auto z = [](double q1, double q2, double p1, double p2) {
    PhaseState<2> s;
    s.q << q1, q2;
    s.p << p1, p2;
    return s;
  };
  const auto cut = upward_cut(z(-1, 2, 1, -4), z(3, 6, 1, 4));
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->a, 0.25);
  EXPECT_EQ(cut->q2, 3.0);
  EXPECT_EQ(cut->p2, -2.0);
  EXPECT_FALSE(upward_cut(z(3, 0, -1, 0), z(-1, 0, -1, 0)).has_value());  // downwards
  EXPECT_FALSE(upward_cut(z(-1, 0, -1, 0), z(3, 0, -1, 0)).has_value());  // upwards in q1 but p1 < 0 at the end
  EXPECT_FALSE(upward_cut(z(1, 0, 1, 0), z(3, 0, 1, 0)).has_value());     // no crossing
  EXPECT_TRUE(upward_cut(z(-1, 0, 1, 0), z(0, 0, 1, 0)).has_value());     // ends on the section
}

}  // namespace analysis_test
