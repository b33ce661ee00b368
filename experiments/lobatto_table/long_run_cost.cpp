// What the accuracy costs over the long run of 001 Fig. 2 (study `long_run_cost`): each method of
// long_run_cost.methods at the steps long_run_cost.h over long_run.periods periods of the oscillator,
// against its closed form; two work-precision sets (analysis/work_precision_set.hpp) of the same runs,
// "long_run_phase" (the phase error at the end) and "long_run_energy" (the largest energy error), from
// counting runs in parallel, checkpointed for --resume, and the wall time (runner/timing.hpp, serial,
// from a timed segment).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

using Z1 = PhaseState<1>;


void check_long_run_cost(const Scene& s) {
  check_distinct_methods(s, "long_run_cost.methods");
  check_oscillatory_bounds(s, {"long_run_cost.h", s.real("oscillator.omega")}, "long_run_cost.methods");
}

// The steps of a run of `periods` periods T at step h.
std::int64_t steps_of(double periods, double T, double h) { return std::llround(periods * T / h); }

// Errors and force evaluations: one counting run per method and step (in parallel): the largest
// |H(z_j) - H(z_0)| over the run (Fig. 2's quantity) and |z_N - z(t_N)|_2 at its end, both against
// the closed form of the oscillator.
struct Measured {
  std::int64_t evals = 0;
  double energy = 0, phase = 0;
  auto fields() { return std::tie(evals, energy, phase); }
};

// The counting runs: task = method index * (number of steps) + step index, the longest first (their steps
// times the method's force evaluations per step).
std::vector<Measured> measure(Context& ctx, const OscillatorFromRest& o, const std::vector<std::string>& methods,
                              const std::vector<double>& hs, double periods) {
  const auto& [osc, A, T, z0] = o;
  const std::size_t nh = hs.size();
  // (narrower than the study's reads: error_targets, timing_steps and timing.repeats do not change these runs)
  const std::vector<std::string> keys = {"oscillator", "long_run.periods", "long_run_cost.methods", "long_run_cost.h"};
  std::vector<double> work;
  for (const auto& m : methods) {
    const std::int64_t e = evals_per_step(m);
    for (double h : hs) work.push_back(static_cast<double>(steps_of(periods, T, h) * e));
  }
  return checkpointed_map<Measured>(ctx, {"long_run_cost", keys, 0, work}, methods.size() * nh, [&](std::size_t task) {
    Measured r;
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(periods, T, h);
    const double H0 = osc.H(z0);
    const Counting<HarmonicOscillator> counted{osc, &r.evals};
    const Z1 zN = MethodsOn<Counting<HarmonicOscillator>>::integrate(
        methods[task / nh], counted, z0, h, n,
        [&](std::int64_t, const Z1& z) { r.energy = std::max(r.energy, std::abs(osc.H(z) - H0)); });
    r.phase = phase_distance(zN, osc.exact(z0, static_cast<double>(n) * h));
    return r;
  });
}

// The two work-precision sets of the long runs: the same runs and wall times, two errors.
struct Sets {
  WorkPrecisionSet phase{"l2 phase-space error |z_N - z(t_N)|_2 at the end of the run, against the closed form"};
  WorkPrecisionSet energy{"largest energy error max_j |H(z_j) - H(z_0)| over the run, against H(z_0)"};
};

// Wall time of the same runs without observation, under the timing protocol (runner/timing.hpp). Writes
// cost_long_run_phase.csv and cost_long_run_energy.csv.
Sets time_and_write(Context& ctx, const OscillatorFromRest& o, const std::vector<std::string>& methods,
                    const std::vector<double>& hs, double periods, int repeats, const std::vector<Measured>& measured) {
  const auto& [osc, A, T, z0] = o;
  const std::size_t nh = hs.size();
  Sets sets;
  // The time per step on the oscillator does not depend on where the step is taken: it is measured on a
  // segment of long_run_cost.timing_steps steps (at most the run), all segments timed together, and the
  // run's wall time is its n steps at that rate (every time of the segment scaled by n / n_timed).
  InterleavedTiming timing(repeats, kTimingFloorS, ctx.threads);
  std::vector<double> scale;
  for (std::size_t task = 0; task < measured.size(); ++task) {
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(periods, T, h);
    const std::int64_t n_timed = std::min<std::int64_t>(n, ctx.scene.integer("long_run_cost.timing_steps"));
    timing.add(MethodsOn<HarmonicOscillator>::timed(methods[task / nh], osc, {z0}, h, n_timed));
    scale.push_back(static_cast<double>(n) / static_cast<double>(n_timed));
  }
  const std::vector<RunTime> times = timing.run();
  for (std::size_t task = 0; task < measured.size(); ++task) {
    const std::string& m = methods[task / nh];
    const double h = hs[task % nh];
    const double n = static_cast<double>(steps_of(periods, T, h));
    const RunTime t = times[task].scaled(scale[task]);
    const Measured& r = measured[task];
    sets.phase.add({label_of(m), h, n, t, static_cast<double>(r.evals), r.phase});
    sets.energy.add({label_of(m), h, n, t, static_cast<double>(r.evals), r.energy});
  }
  ctx.write("cost_long_run_phase.csv", sets.phase.csv());
  ctx.write("cost_long_run_energy.csv", sets.energy.csv());
  return sets;
}

void run_long_run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: long runs on the oscillator");
  const OscillatorFromRest o = oscillator_from_rest(s);
  const auto& [osc, A, T, z0] = o;
  const auto methods = s.texts("long_run_cost.methods");
  const auto hs = s.reals("long_run_cost.h");
  const double periods = s.real("long_run.periods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto measured = measure(ctx, o, methods, hs, periods);
  const Sets sets = time_and_write(ctx, o, methods, hs, periods, repeats, measured);
  // The closed form's own error at t_N = periods T: the round-off of cos and sin of omega t_N, about
  // u omega t_N in the phase, i.e. u omega t_N |(A, m omega A)| in z (A and m omega A: the amplitudes
  // of q and p).
  const double t_N = periods * T;
  const double reference_error = std::numeric_limits<double>::epsilon() * osc.w * t_N * std::hypot(A, osc.m * osc.w * A);
  Value errors = Value::record();
  for (const auto& m : methods) {
    const std::string label = label_of(m);
    double phase_min = std::numeric_limits<double>::infinity(), energy_max = 0, energy_min = phase_min;
    for (const auto& r : sets.phase.records())
      if (r.method == label) phase_min = std::min(phase_min, r.err);
    for (const auto& r : sets.energy.records())
      if (r.method == label) energy_min = std::min(energy_min, r.err), energy_max = std::max(energy_max, r.err);
    errors[label] = {{"phase_min", phase_min}, {"energy_min", energy_min}, {"energy_max", energy_max}};
  }
  ctx.summary["methods"]["long_run_cost"] = labels_of(methods);
  ctx.summary["long_run_cost"] = {{"t_end", t_N}, {"h_range", range_of(hs)}, {"reference_error", reference_error},
                                  {"errors", errors},
                                  {"norms", "phase: |z_N - z(t_N)|_2 against the closed form; energy: max over the "
                                            "steps of |H(z_j) - H(z_0)|"}};
  // (long_run_cost.error_targets are phase errors: the energy set has none)
  merge(ctx.summary, "cost", {{"long_run_phase", sets.phase.summary(s.reals("long_run_cost.error_targets"))},
                              {"long_run_energy", sets.energy.summary({})},
                              {"method", segmented_timing_method_text(repeats, "long_run_*", "long_run_cost.timing_steps")}});
}

StudyPlan plan_long_run_cost(const Scene& s) {
  const double periods = s.real("long_run.periods"), T = oscillator_from_rest(s).T;
  const double methods = static_cast<double>(s.texts("long_run_cost.methods").size());
  const double timed = static_cast<double>(s.integer("long_run_cost.timing_steps"));
  const PlanRate& rate = plan_rate("oscillator lobatto");
  double counted = 0;
  std::vector<TimedCall> calls;
  for (double h : s.reals("long_run_cost.h")) {
    const double n = periods * T / h;
    counted += methods * n;
    calls.insert(calls.end(), s.texts("long_run_cost.methods").size(), TimedCall{std::min(n, timed), rate.ns_per_step});
  }
  StudyPlan p{counted, counted * rate.evals_per_step(),
              methods * static_cast<double>(s.reals("long_run_cost.h").size()) * 9 * kCsvCellBytes, rate.ns_per_step,
              "the runs, then the timing protocol on their segments; " + rate.note};
  p.time(s, calls);
  return p;
}

}  // namespace

Study long_run_cost_study() {
  return {.name = "long_run_cost",
          .about = "cost over the long run of Fig 2: error against wall time and force evaluations",
          .files = {"cost_long_run_phase.csv", "cost_long_run_energy.csv"},
          .keys = Schema()
                      .texts("long_run_cost.methods", MethodsOn<HarmonicOscillator>::names(), 1,
                             "methods whose cost is measured on the oscillator of Fig. 2 over long_run.periods periods "
                             "(001: lobatto, simpson, implicit_midpoint)")
                      .reals("long_run_cost.h", positive(), 3, "steps of the long-run work-precision study")
                      .reals("long_run_cost.error_targets", positive(), 1,
                             "phase errors at the end of the long run whose cost (wall time, force evaluations) each "
                             "method is asked for")
                      .integer("long_run_cost.timing_steps", at_least(1),
                               "steps of the timed segment; a long run's wall time is its steps times the time per "
                               "step measured on it"),
          .reads = {"long_run.periods", "oscillator", "timing.repeats", "checkpoint"},
          .run = run_long_run_cost,
          .validate = check_long_run_cost,
          .plan = plan_long_run_cost};
}

}  // namespace geomint::lobatto_table
