// The timing protocol (runner/timing.hpp): calibrated runs of at least the floor, rounds interleaved in a
// rotated order, medians and quartiles, and ratios whose verdict knows the noise and the work. (Counts,
// orders and synthetic timings are asserted, never a measured time.)
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/results_json.hpp"
#include "geomint/runner/timing.hpp"

using namespace geomint;

namespace timing_test {  // the file's scope (the tests build as one translation unit)

namespace {

// A synthetic timing: its median and quartiles.
RunTime timing(double q1, double median, double q3) {
  RunTime t;
  t.min_s = q1 * 0.9, t.q1_s = q1, t.median_s = median, t.q3_s = q3, t.max_s = q3 * 1.1, t.repeats = 7, t.inner = 1;
  return t;
}

}  // namespace

TEST(TimingProtocol, CalibratesEachRunToTheFloorAndOrdersTheStatistics) {
  long calls = 0;
  const auto busy = [&] {
    ++calls;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - start < std::chrono::microseconds(200)) {}
  };
  const RunTime t = time_runs(7, busy, 0.01);
  EXPECT_EQ(t.repeats, 7);
  EXPECT_GE(t.inner, 2);   // a 0.2 ms call is repeated towards 1.1 x 10 ms
  EXPECT_LE(t.inner, 55);  // ceil(1.1 x 10 ms / >= 0.2 ms)
  EXPECT_GE(t.min_s * static_cast<double>(t.inner), 0.01);  // no run below the floor (inner only grows)
  EXPECT_GE(calls, 1 + 7 * 2);  // a warm-up, a probe, the 7 timed runs
  EXPECT_GE(t.min_s, 200e-6);
  EXPECT_LE(t.min_s, t.q1_s);
  EXPECT_LE(t.q1_s, t.median_s);
  EXPECT_LE(t.median_s, t.q3_s);
  EXPECT_LE(t.q3_s, t.max_s);
  EXPECT_DOUBLE_EQ(t.seconds(), t.median_s);
  EXPECT_DOUBLE_EQ(t.spread(), (t.q3_s - t.q1_s) / t.median_s);
}

TEST(TimingProtocol, InterleavesTheConfigurationsInAnOrderRotatedEachRound) {
  std::string order;
  InterleavedTiming t(4, 0);  // (a floor of 0: one call per run)
  for (char c : std::string("ABC")) t.add([&order, c] { order += c; });
  const auto times = t.run();
  ASSERT_EQ(times.size(), 3u);
  // each: a warm-up call (no probe: the call is not shorter than the floor); then the rounds A B C, B C A,
  // C A B, A B C
  EXPECT_EQ(order, "ABC" "ABC" "BCA" "CAB" "ABC");
  for (const RunTime& r : times) {
    EXPECT_EQ(r.repeats, 4);
    EXPECT_EQ(r.inner, 1);
  }
}

TEST(TimingProtocol, ConcurrentRoundsTimeEachConfigurationOncePerRound) {
  // Two workers (two configurations at a time where the cores time alike, else one): whichever, every
  // configuration gets its warm-up call and one run per round, and a failing one fails the measurement.
  std::array<std::atomic<int>, 5> calls{};
  InterleavedTiming t(6, 0, 2);  // (a floor of 0: one call per run)
  for (std::size_t c = 0; c < calls.size(); ++c) t.add([&calls, c] { ++calls[c]; });
  const auto times = t.run();
  ASSERT_EQ(times.size(), calls.size());
  for (std::size_t c = 0; c < calls.size(); ++c) {
    EXPECT_EQ(calls[c].load(), 1 + 6) << "configuration " << c;
    EXPECT_EQ(times[c].repeats, 6);
  }
  const TimingConcurrency used = timing_concurrency(2, kTimingRepeats);
  EXPECT_TRUE(used.workers == 1 || used.workers == 2);
  EXPECT_EQ(used.workers == 2, used.slowdown <= kConcurrentSlowdown);
  EXPECT_EQ(timing_concurrency(1, kTimingRepeats).workers, 1);  // (nothing measured for one worker)

  InterleavedTiming failing(3, 0, 2);
  failing.add([] {});
  failing.add([] { throw std::runtime_error("Newton iteration left the domain"); });
  EXPECT_THROW(failing.run(), std::runtime_error);
}

TEST(TimingProtocol, QuartilesInterpolateBetweenOrderStatistics) {
  const RunTime r = run_time_of({7, 1, 6, 2, 5, 3, 4}, 3);
  EXPECT_DOUBLE_EQ(r.min_s, 1);
  EXPECT_DOUBLE_EQ(r.q1_s, 2.5);
  EXPECT_DOUBLE_EQ(r.median_s, 4);
  EXPECT_DOUBLE_EQ(r.q3_s, 5.5);
  EXPECT_DOUBLE_EQ(r.max_s, 7);
  EXPECT_DOUBLE_EQ(r.spread(), 0.75);
  EXPECT_EQ(r.inner, 3);
  const RunTime per_step = r.scaled(0.5);
  EXPECT_DOUBLE_EQ(per_step.q3_s, 2.75);
  EXPECT_DOUBLE_EQ(per_step.spread(), 0.75);  // (scaling keeps the spread)
}

TEST(TimingProtocol, ARatioIsIndistinguishableWhereTheQuartilesOverlap) {
  const TimeRatio overlap = time_ratio(timing(50, 60, 110), timing(40, 45.5, 70));  // 1.32 by medians, spreads of ~100 %
  EXPECT_NEAR(overlap.median, 60 / 45.5, 1e-15);
  EXPECT_NEAR(overlap.lo, 50.0 / 70, 1e-15);
  EXPECT_NEAR(overlap.hi, 110.0 / 40, 1e-15);
  EXPECT_TRUE(overlap.indistinguishable);
  EXPECT_EQ(timing_verdict(overlap, 1, 1), "indistinguishable");
  const TimeRatio apart = time_ratio(timing(58, 60, 62), timing(44, 45.5, 47));
  EXPECT_FALSE(apart.indistinguishable);
  EXPECT_EQ(timing_verdict(apart, 2, 1), "slower");
  EXPECT_EQ(timing_verdict(time_ratio(timing(44, 45.5, 47), timing(58, 60, 62)), 1, 2), "faster");
}

// A speed claim clears the measurement's drift: quartiles apart by 1.23 (58/47) are a claim under a drift of
// 10 %, not under one of 30 %; a ratio carried over to another cost keeps the interval's width and the drift.
TEST(TimingProtocol, ASpeedClaimInsideTheDriftIsIndistinguishable) {
  const auto drifting = [](RunTime t, double d) { return t.drift = d, t; };
  const TimeRatio steady = time_ratio(drifting(timing(58, 60, 62), 0.1), timing(44, 45.5, 47));
  EXPECT_DOUBLE_EQ(steady.drift, 0.1);
  EXPECT_EQ(timing_verdict(steady, 1, 1), "slower");
  const TimeRatio drifted = time_ratio(timing(58, 60, 62), drifting(timing(44, 45.5, 47), 0.3));
  EXPECT_DOUBLE_EQ(drifted.drift, 0.3);  // (the larger of the two measurements')
  EXPECT_TRUE(drifted.indistinguishable);
  EXPECT_EQ(timing_verdict(drifted, 1, 1), "indistinguishable");
  EXPECT_TRUE(time_ratio(drifting(timing(44, 45.5, 47), 0.3), timing(58, 60, 62)).indistinguishable);  // (faster side)
  const TimeRatio to_target = carried_over(steady, 2.0);  // e.g. twice the steps to an error target
  EXPECT_DOUBLE_EQ(to_target.median, 2.0);
  EXPECT_NEAR(to_target.lo / to_target.hi, steady.lo / steady.hi, 1e-15);
  EXPECT_EQ(timing_verdict(to_target, 1, 1), "slower");
  EXPECT_EQ(timing_verdict(carried_over(steady, 0.9), 1, 1), "indistinguishable");  // [0.84, 0.96] widened by 10 % holds 1
}

TEST(TimingProtocol, AMethodDoingMoreWorkTimedFasterIsFlagged) {
  const TimeRatio faster = time_ratio(timing(44, 45.5, 47), timing(58, 60, 62));
  EXPECT_EQ(timing_verdict(faster, 2, 1), "contradicts the work");  // twice the force evaluations, yet faster
  EXPECT_EQ(timing_verdict(time_ratio(timing(58, 60, 62), timing(44, 45.5, 47)), 1, 2), "contradicts the work");
  EXPECT_EQ(timing_verdict(faster, 1, 1), "faster");  // the same work: a finding
}

TEST(TimingProtocol, RelativeTimingsAgainstTheFirst) {
  const auto r = to_json(relative_timings({"sv", "ti"}, {timing(44, 45.5, 47), timing(40, 60, 110)}, {1, 2}));
  EXPECT_EQ(r["reference"], "sv");
  EXPECT_EQ(r["by_method"]["sv"]["verdict"], "reference");
  EXPECT_NEAR(r["by_method"]["ti"]["ratio"].get<double>(), 60 / 45.5, 1e-15);
  EXPECT_EQ(r["by_method"]["ti"]["verdict"], "indistinguishable");
  EXPECT_NEAR(r["by_method"]["ti"]["interval"]["min"].get<double>(), 40.0 / 47, 1e-15);
  EXPECT_EQ(relative_timings({"sv", "ti"}, {timing(44, 45.5, 47), timing(50, 60, 110)}, {1, 2})["by_method"]["ti"]["verdict"].text(),
            "slower");
  EXPECT_THROW(relative_timings({"sv"}, {}, {1}), std::invalid_argument);
  // The reference where it is not the first: the same ratios, keys in the given order.
  const auto s = to_json(relative_timings({"ti", "sv"}, {timing(40, 60, 110), timing(44, 45.5, 47)}, {2, 1}, 1));
  EXPECT_EQ(s["reference"], "sv");
  EXPECT_EQ(s["by_method"]["sv"]["verdict"], "reference");
  EXPECT_NEAR(s["by_method"]["ti"]["ratio"].get<double>(), 60 / 45.5, 1e-15);
  EXPECT_THROW(relative_timings({"sv", "ti"}, {timing(44, 45.5, 47), timing(40, 60, 110)}, {1, 2}, 2), std::invalid_argument);
}

TEST(TimingProtocol, PlansItsOwnTime) {
  // 3 configurations, 7 rounds, each after its warm-up call: calls shorter than the floor (1 ms: 1000 steps of
  // 1 us; 1 us) a probe of floor / 8 and 7 runs of 1.1 x the floor; a longer call (50 ms) 7 runs of one call; and
  // the control loop before and after, a probe and 3 runs each
  const TimedPlan p = timing_plan({{1000, 1000}, {1, 1000}, {50000, 1000}}, 7);
  const double f = kTimingFloorS, short_runs = f / 8 + 7 * 1.1 * f, control = 2 * (f / 8 + 3 * 1.1 * f);
  EXPECT_NEAR(p.seconds, (1e-3 + short_runs) + (1e-6 + short_runs) + 8 * 0.05 + control, 1e-15);
  EXPECT_NEAR(p.steps, (1000 + short_runs / 1e-6) + (1 + short_runs / 1e-6) + 8 * 50000, 1e-6);
  EXPECT_NEAR(timing_plan({{1000, 1000}}, 7).seconds, 1e-3 + short_runs, 1e-15);  // (one alone: no ratio, no control)
}

// --plan's rates come from experiments/plan_rates.toml, compiled in: a rate names what it is and the CPU it was
// measured on, and a name the table lacks is a study's error, not a silent 0.
TEST(PlanRates, ComeFromTheTableWithWhereTheyWereMeasured) {
  const geomint::PlanRate& r = geomint::plan_rate("pendulum lobatto");
  EXPECT_GT(r.ns_per_step, 0);
  EXPECT_NE(r.note.find("Lobatto"), std::string::npos) << r.note;
  EXPECT_NE(r.note.find(" ns on "), std::string::npos) << r.note;
  EXPECT_THROW(geomint::plan_rate("pendulum no such method"), std::logic_error);
}

}  // namespace timing_test
