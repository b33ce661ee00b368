#pragma once
// A work-precision set (DiffEqDevTools' WorkPrecisionSet): what accuracy costs, in the one shape of
// every cost study. One record per (method, step h): the error of one run, its wall time (the timed
// repeats of runner/timing.hpp), its force evaluations (a separate counting run) and its steps. A
// method whose force evaluations are affine in the steps (e = a n + c at every h: fixed work per
// step) is timed at its fewest and its most steps only, and its other runs' times are interpolated
// affinely in the steps between those two (time(); `wall_timed` says which).
// One CSV (csv()), one summary (summary()) and one rule for "at equal cost" (equal_cost()), drawn by
// figures/cost.gpi. Costs and errors are interpolated in log-log between measured runs, never
// extrapolated (analysis/work_precision.hpp).
#include <functional>
#include <string>
#include <vector>


#include "geomint/analysis/work_precision.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/runner/timing.hpp"

namespace geomint {

struct WorkPrecisionRecord {
  std::string method;  // registry label
  double h = 0, steps = 0;
  RunTime wall;        // of one run; its estimate (RunTime::seconds, the median) is the run's wall time
  double evals = 0;    // force evaluations of one run
  double err = 0;      // the error of the run
  bool wall_timed = true;  // false: `wall` interpolated in the steps between the method's timed runs (time())
};

// The affine interpolation in the steps n of every statistic of two timed runs a (na steps) and b (nb):
// the time of a run of fixed work per step, t(n) = t0 + n t1 (repeats and inner 0: not a measurement).
RunTime affine_in_steps(const RunTime& a, double na, const RunTime& b, double nb, double n);

class WorkPrecisionSet {
 public:
  // `error`: what the error of a run is, in words (summary "error").
  explicit WorkPrecisionSet(std::string error) : error_(std::move(error)) {}

  void add(WorkPrecisionRecord r) { records_.push_back(std::move(r)), timed_.emplace_back(); }
  // A record whose wall time is measured by time(): `run` is one run of it (MethodsOn<Sys>::timed).
  void add(WorkPrecisionRecord r, std::function<void()> run) { records_.push_back(std::move(r)), timed_.push_back(std::move(run)); }
  // Times the records added with a run, all in one interleaved measurement (runner/timing.hpp), up to
  // `workers` runs at a time where the cores time alike; of a method with more than two such records
  // whose force evaluations are affine in the steps, only those of its fewest and most steps (the
  // others interpolated: affine_in_steps).
  void time(int repeats, int workers = 1);
  // The wall times of `timed`, a set of the same runs (method, h and steps, in the same order) with
  // another error: its records' wall and wall_timed.
  void times_of(const WorkPrecisionSet& timed);
  const std::vector<WorkPrecisionRecord>& records() const { return records_; }
  std::vector<std::string> methods() const;                    // in the order first added
  std::vector<CostRun> runs(const std::string& method) const;  // its measurable runs, by decreasing h

  // One row per record: method,h,steps,wall_s,wall_q1_s,wall_q3_s,wall_spread,wall_timed,force_evals,err
  // (wall_s the median; wall_timed 1 where timed, 0 where interpolated).
  Csv csv() const;
  // {error, methods, targets, equal_wall_s, equal_evals (equal_cost), by_method: {label: {runs, min_err,
  // ns_per_step, ns_per_step_q1, ns_per_step_q3, ns_per_step_spread, evals_per_step (of its run at the
  // smallest h), err_at_equal_wall,
  // err_at_equal_evals, wall_s_to, evals_to (per target; null where the measured steps do not reach it)}},
  // timed_runs (of its runs, those timed)}}, spread (of every timed run: runner/timing_report.hpp),
  // ratios_to (ratios_to)}.
  Value summary(const std::vector<double>& targets) const;
  // Per target: each method's wall time to reach it over that of the first method that reaches it (the
  // reference), with the interval and drift of the ratio of their times per step at the smallest h
  // (time_ratio) carried over, and its verdict (timing_verdict: faster, slower or indistinguishable; the force
  // evaluations to a target are no measure of work across systems or methods whose evaluations cost unlike):
  // [{target, reference, by_method: {label: {wall_ratio, min, max, drift, verdict}}}].
  Value ratios_to(const Value& by_method, const std::vector<double>& targets) const;
  // Each method's time per step at its smallest h against the first method's (relative_timings,
  // runner/timing_report.hpp), the force evaluations per step as the work.
  Value relative_ns_per_step() const;
  // Where the work-precision curves (error against wall time) of methods a and b cross (crossover,
  // analysis/work_precision.hpp): {methods, wall_s, err}, wall_s and err null where they do not cross in the
  // measured range or a method has no measurable run (the keys the same whatever the timings).
  Value crossing(const std::string& a, const std::string& b) const;
  // Of a set's summary(): each method's wall time and force evaluations to reach the (first) target relative to
  // method `first`'s, where both reach it: {label: {wall_s, evals}}.
  static Value cost_ratios(const Value& summary, const std::string& first);

 private:
  std::string error_;
  std::vector<WorkPrecisionRecord> records_;
  std::vector<std::function<void()>> timed_;  // (empty for a record timed by its caller)
  const WorkPrecisionRecord& finest_run(const std::string& method) const;  // its run at the smallest h
};

}  // namespace geomint
