// What the accuracy of 000 Figs 8-9's methods costs (study `cost`, formerly `timing`): one
// work-precision set (analysis/work_precision_set.hpp), "energy": per method and step of timing.h,
// the largest energy error of the run to convergence.t_end and its force evaluations, from separate
// (parallel) counting runs, and the wall time of the run (runner/timing.hpp; steps only: the
// transformation (41) applied once before and once after), serial. Beside the set, what the paper
// quotes: ns per step at oscillator.h over timing.steps steps, and where the first two methods'
// curves cross.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::euler_compensation {
namespace {


// The set "energy": counting runs in parallel, then every (h, method) timed together (runner/timing.hpp).
WorkPrecisionSet energy_set(const Scene& s, const PhaseState<1>& z0, int workers) {
  const double t_end = s.real("convergence.t_end"), k = s.real("oscillator.k");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods");
  const auto hs = s.reals("timing.h");
  const auto counted = distributed_map(hs.size(), [&](std::size_t i) {
    return oscillator_energy_errors(methods, k, z0, hs[i], steps_to(t_end, hs[i]));
  });
  WorkPrecisionSet energy("largest energy error |H(q_j, p_j) - H_0| over the run to convergence.t_end");
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const std::int64_t n = steps_to(t_end, hs[i]);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const OscillatorEnergyErrors& r = counted[i][m];
      energy.add({label_of(methods[m]), hs[i], static_cast<double>(n), {}, static_cast<double>(r.force_evals), r.max_err},
                 oscillator_timed(methods[m], k, z0, hs[i], n));
    }
  }
  energy.time(repeats, workers);
  return energy;
}

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const PhaseState<1> z0 = oscillator_start(s);
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods");
  ctx.progress("cost: work-precision runs");
  const WorkPrecisionSet energy = energy_set(s, z0, ctx.threads);
  ctx.write("cost_energy.csv", energy.csv());
  // (the paper quotes no target error: the set's wall_s_to and evals_to are empty)
  Value cost = {{"energy", energy.summary({})},
                {"method", timing_method_text(repeats) + "; the set's runs from (q0, p0) to convergence.t_end, the "
                                                         "transformation (41) once before and once after; ns_per_step "
                                                         "at oscillator.h over timing.steps steps"}};
  ctx.progress("cost: ns per step");
  const double h8 = s.real("oscillator.h"), k = s.real("oscillator.k");
  const std::int64_t n_ns = s.integer("timing.steps");
  InterleavedTiming timing(repeats, kTimingFloorS, ctx.threads);  // runs of their own, not the set's: the step of Fig 8 over timing.steps steps
  for (const auto& m : methods) timing.add(oscillator_timed(m, k, z0, h8, n_ns));
  const std::vector<RunTime> times = timing.run();
  std::vector<std::string> labels;
  std::vector<RunTime> per_step;
  std::vector<double> work;  // force evaluations per step, from the set's first run of the method
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string label = label_of(methods[i]);
    labels.push_back(label), per_step.push_back(times[i].scaled(1e9 / static_cast<double>(n_ns)));
    const auto& r = *std::ranges::find(energy.records(), label, &WorkPrecisionRecord::method);
    work.push_back(r.evals / r.steps);
    cost["ns_per_step"][label] = per_step.back().seconds();
    cost["ns_per_step_spread"][label] = per_step.back().spread();
  }
  // ns per step relative to the first method of timing.methods
  cost["relative_ns_per_step"] = relative_timings(labels, per_step, work);
  // Where the work-precision curves of the first two methods cross (null with one method).
  cost["crossover"] = labels.size() > 1 ? energy.crossing(labels[0], labels[1]) : Value(nullptr);
  ctx.summary["cost"] = cost;
  ctx.summary["h_range"]["timing"] = h_range(s.reals("timing.h"));
}

StudyPlan plan_cost(const Scene& s) {
  const auto methods = s.texts("timing.methods");
  const double counted = static_cast<double>(methods.size()) * steps_to_each(s.real("convergence.t_end"), s.reals("timing.h"));
  const PlanRate& rate = plan_rate("oscillator compensated symplectic euler");
  std::vector<TimedCall> calls;  // the set's runs, then a run of timing.steps per method
  for (double h : s.reals("timing.h")) calls.insert(calls.end(), methods.size(), TimedCall{s.real("convergence.t_end") / h, rate.ns_per_step});
  calls.insert(calls.end(), methods.size(), TimedCall{static_cast<double>(s.integer("timing.steps")), rate.ns_per_step});
  StudyPlan p;
  p.steps = counted, p.force_evals = counted * rate.evals_per_step();
  p.memory_bytes = static_cast<double>(calls.size()) * 8 * kCsvCellBytes, p.ns_per_step = rate.ns_per_step;
  p.note = "counting runs, then the timing protocol; " + rate.note;
  p.time(s, calls);
  return p;
}

}  // namespace

Study cost_study() {
  return {.name = "cost",
          .about = "cost of Figs 8-9's methods: error against wall time and force evaluations",
          .files = {"cost_energy.csv"},
          .keys = Schema()
                      .texts("timing.methods", compensated_oscillator_choices(), 1, "methods of the cost study (registry names or labels)")
                      .reals("timing.h", positive(), 3, "steps of the work-precision runs (to convergence.t_end)")
                      .integer("timing.steps", at_least(1), "steps of the run that measures ns per step"),
          .reads = {"timing.repeats", "convergence.t_end", "oscillator.q0", "oscillator.p0", "oscillator.k", "oscillator.h"},
          .run = run_cost,
          .validate = [](const Scene& s) { check_compensated_methods(s, "timing.h", "timing.methods", "convergence.t_end"); },
          .plan = plan_cost,
          .aliases = {"timing"}};
}

}  // namespace geomint::euler_compensation
