#pragma once
// Wall-clock timing for the cost figures and summary.json (never for pass/fail): one protocol for
// every cost and timing study and for the benchmarks' reporting.
//
// Each configuration (a method at a step, a kernel, ...) gets one untimed warm-up call, then its calls
// per timed run are calibrated from a probe run of an eighth of the floor so that a run lasts
// kTimingMargin times the floor (kTimingFloorS, 10 ms: well above the clock's resolution and a
// scheduler tick's jitter; below); a run that still ends below the floor is lengthened and run again. Then `repeats` rounds (at least
// kTimingRepeats in the paper scenes) each time one run of every configuration, in an order rotated
// by one per round (A B C, B C A, C A B, ...): a burst of load on a shared machine hits every
// configuration alike. A run's time is its wall time over its calls; a configuration reports the
// median of its runs (the estimate), their quartiles and minimum. Two configurations compare as a
// ratio with an interval from the quartiles (time_ratio); where the interval holds 1 they are
// indistinguishable.
// The machine's speed may drift during a measurement (another process, the clock frequency): every
// measurement of several configurations times a control, a loop bound by the throughput of the
// floating-point units, before and after its rounds (kControlRepeats runs each); the relative change of
// the control's median is the measurement's drift, and a ratio of two of its configurations tells one
// from the other only where its interval excludes 1 by more than that drift.
// With workers > 1 (the cost studies, whose runs are independent single-thread calls) up to that
// many configurations of a round run at a time, each on its own core, if the cores time alike
// (timing_concurrency: a throughput-bound loop runs as fast beside the others as alone, within
// kConcurrentSlowdown); otherwise, as on two hyperthreads of one core, one at a time.
// The floor comes from a measurement (bench/README.md, "The timing protocol's floor"): at 10 ms a configuration's
// time relative to the others of its measurement, what every comparison uses, reproduces between runs as well as
// at 20 ms, and a time itself about as well as the spread within one run, at 60 % of the time.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "geomint/runner/results.hpp"

#include "geomint/core/integrate.hpp"

namespace geomint {

inline constexpr double kTimingFloorS = 0.01;  // the shortest timed run
inline constexpr double kTimingMargin = 1.1;   // a run is calibrated to this times the floor
inline constexpr int kTimingRepeats = 7;       // the fewest rounds of the protocol (paper scenes)
inline constexpr int kControlRepeats = 3;      // runs of the control before and after a measurement
inline constexpr const char* kTimingRepeatsHelp =
    "rounds of the timing protocol (runner/timing.hpp): each configuration timed once per round in runs of at least "
    "its floor (run.json timing_protocol), interleaved; the median is the estimate, the interquartile range the spread "
    "(paper scenes: >= 7)";

// Keeps the compiler from discarding a computation whose result is unused.
template <class T>
inline void do_not_optimize(const T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}

// The wall time of one call of a timed configuration, over `repeats` timed runs of `inner` calls.
struct RunTime {
  double min_s = 0, q1_s = 0, median_s = 0, q3_s = 0, max_s = 0;  // seconds per call
  int repeats = 0;
  std::int64_t inner = 0;  // calls per timed run
  double drift = 0;        // |control after / control before - 1| of the measurement (0: not measured)
  double seconds() const { return median_s; }  // the estimate
  // the interquartile range relative to the median
  double spread() const { return median_s > 0 ? (q3_s - q1_s) / median_s : 0; }
  RunTime scaled(double factor) const;  // per 1/factor of a call (e.g. per step)
};

Value to_value(const RunTime& t);

// The quantile q of the sorted non-empty `v`, interpolated linearly between order statistics.
double sorted_quantile(const std::vector<double>& v, double q);

// The statistics of the per-call times of `repeats` runs (not sorted).
RunTime run_time_of(std::vector<double> per_call, std::int64_t inner);

// Whether `workers` configurations may be timed at a time: the median time of `workers` copies at once of
// a loop bound by the throughput of the floating-point units over the median time of one copy alone (the
// protocol, both interleaved, at least kTimingRepeats rounds). On two hyperthreads of one core the loop
// takes about twice as long beside the other; on separate cores as long. Measured once per process and
// worker count, or read from the file of share_timing_concurrency.
inline constexpr double kConcurrentSlowdown = 1.1;
struct TimingConcurrency {
  int workers = 1;        // those used: the requested count where slowdown <= kConcurrentSlowdown, else 1
  double slowdown = 1;    // the loop's time beside the others over its time alone
};
TimingConcurrency timing_concurrency(int workers, int repeats);
Value to_value(const TimingConcurrency& c);
// The runs of one make figures measure it once (--timing-concurrency FILE): timing_concurrency then takes it from
// FILE where FILE holds it for the requested workers, and otherwise measures it and adds it to FILE (one line
// "requested workers slowdown" each; a line of another form is an error). Empty: measured in this process only.
void share_timing_concurrency(const std::string& file);
// The measurements timing_concurrency used in this process, each with where it came from ("from": "this run" or
// the file it was read from) (run.json timing_concurrency; null if none).
Value timing_concurrency_record();
// The control of every measurement of several configurations in this process, in order: {configurations,
// before_s, after_s, drift} (run.json timing_control; null if none).
Value timing_control_record();

// The protocol's constants, as run.json records them (timing_protocol): floor_ms, margin, min_repeats,
// control_repeats.
Value timing_protocol_record();

// Times configurations under the protocol of the header comment.
class InterleavedTiming {
 public:
  explicit InterleavedTiming(int repeats, double floor_s = kTimingFloorS, int workers = 1)
      : repeats_(repeats), floor_s_(floor_s), workers_(workers) {}
  // A configuration; its index in run()'s result. f must stay callable until run() returns.
  std::size_t add(std::function<void()> f);
  std::vector<RunTime> run() const;
  std::size_t size() const { return configs_.size(); }

 private:
  int repeats_;
  double floor_s_;
  int workers_;
  std::vector<std::function<void()>> configs_;
};

// A configuration to plan: the steps of one call and their time per step.
struct TimedCall {
  double steps = 0, ns_per_step = 0;
};
// What timing configurations under the protocol with `repeats` rounds takes: each a warm-up call, then
// (a call shorter than the floor) a probe of an eighth of the floor and its rounds of kTimingMargin
// times the floor, or (a longer call) its rounds of one call; several of them, the control before and after.
struct TimedPlan {
  double seconds = 0, steps = 0;
};
inline TimedPlan timing_plan(const std::vector<TimedCall>& calls, double repeats) {
  TimedPlan p;
  for (const TimedCall& c : calls) {
    const double call_s = c.steps * c.ns_per_step * 1e-9;
    const double rest_s = call_s >= kTimingFloorS ? repeats * call_s : kTimingFloorS / 8 + repeats * kTimingMargin * kTimingFloorS;
    p.seconds += call_s + rest_s;
    p.steps += c.steps + (call_s > 0 ? rest_s / call_s * c.steps : 0);
  }
  if (calls.size() > 1)  // the control before and after (InterleavedTiming::run)
    p.seconds += 2 * (kTimingFloorS / 8 + kControlRepeats * kTimingMargin * kTimingFloorS);
  return p;
}

// One configuration alone under the protocol.
RunTime time_runs(int repeats, const std::function<void()>& f, double floor_s = kTimingFloorS);

// The ratio a / b of two timings: the ratio of the medians, and an interval [q1_a / q3_b, q3_a / q1_b]
// from the quartiles. `indistinguishable` when the interval, widened by the drift of the measurements
// (the larger of the two) to [lo / (1 + drift), hi (1 + drift)], holds 1.
struct TimeRatio {
  double median = 0, lo = 0, hi = 0, drift = 0;
  bool indistinguishable = true;
};
TimeRatio time_ratio(const RunTime& a, const RunTime& b);
// A ratio of two costs made of the timed calls (e.g. the wall times to an error target, from the times per
// step): `ratio`, with the relative interval and the drift of `timed` carried over.
TimeRatio carried_over(const TimeRatio& timed, double ratio);
Value to_value(const TimeRatio& r);

// What a timing says of a configuration a against b, given the work per step of each (force evaluations,
// or operations): "faster" or "slower" where the interval excludes 1 by more than the drift,
// "indistinguishable" where it does not, and "contradicts the work" where a does strictly more work than b and yet times faster (or less and
// slower): a measurement error until shown otherwise, never a finding.
std::string timing_verdict(const TimeRatio& a_over_b, double work_a, double work_b);

// Each timing against the reference, labels[ref] (the first by default): {reference, by_method: {label: {ratio
// (of the medians), interval: {min, max} (time_ratio), verdict (timing_verdict, with work[k] the work per
// call)}}}. Labels, times and work are parallel lists.
Value relative_timings(const std::vector<std::string>& labels, const std::vector<RunTime>& times,
                       const std::vector<double>& work, std::size_t ref = 0);

// n steps of eq. (23) (pre once, post once) with every call in the loop inlined: each method is
// timed with its step inlined, however many other methods the executable instantiates.
template <class M, class Z>
[[gnu::flatten, gnu::noinline]] Z integrate_inlined(const M& m, const Z& z0, double h, std::int64_t n) {
  return integrate(m, z0, h, n);
}

}  // namespace geomint
