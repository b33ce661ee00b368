// What the accuracy of 000 Fig. 4's methods costs, against odeint's own steppers (study `cost`, formerly
// `timing`): one work-precision set (analysis/work_precision_set.hpp), "phase": per method and step h
// of Fig. 4, the l2 phase-space error at t_end from initial[0] against the reference, from a counting
// run that also counts the force evaluations, and the wall time of the run (pre once, post once, eq.
// (23); runner/timing.hpp).
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::rowlands_convergence {
namespace {

using State = PhaseState<2>;


void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const ElasticPendulumRuns sys(elastic_pendulum_params(s));
  const auto hs = s.reals("h");
  const std::size_t nh = hs.size();
  const double t_end = s.real("t_end");
  const auto methods = s.texts("timing.methods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const State z0 = elastic_pendulum_state(s.real_rows("initial")[0]);
  ctx.progress("cost: reference (odeint Bulirsch-Stoer)");
  const State z_ref = sys.reference(z0, t_end, s.real("reference.rtol"), s.real("reference.atol"));

  ctx.progress("cost: counting runs");
  struct Count {
    std::int64_t evals = 0;
    double phase = 0;
    auto fields() { return std::tie(evals, phase); }
  };
  const auto counts = distributed_map(methods.size() * nh, [&](std::size_t task) {
    Count c;
    const double h = hs[task % nh];
    const State zN = sys.integrate(methods[task / nh], z0, h, steps_to(t_end, h), &c.evals);
    c.phase = phase_distance(zN, z_ref);
    return c;
  });
  ctx.progress("cost: timed runs");
  WorkPrecisionSet phase("l2 phase-space error at t_end from initial[0]");
  for (std::size_t task = 0; task < counts.size(); ++task) {
    const double h = hs[task % nh];
    const std::int64_t n = steps_to(t_end, h);
    phase.add({label_of(methods[task / nh]), h, static_cast<double>(n), {}, static_cast<double>(counts[task].evals),
               counts[task].phase},
              sys.timed(methods[task / nh], z0, h, n));  // (the dispatch outside the clock)
  }
  phase.time(repeats, ctx.threads);
  ctx.write("cost_phase.csv", phase.csv());
  Value cost = {{"phase", phase.summary(s.reals("timing.error_targets"))},
                {"method", timing_method_text(repeats) + "; from initial[0] to t_end (pre- and postprocessing once, every "
                                                         "call inlined); ns_per_step at the smallest h"}};
  // ns per step relative to the first method of timing.methods
  cost["relative_ns_per_step"] = phase.relative_ns_per_step();
  ctx.summary["cost"] = cost;
  record_steps_and_starts(ctx.summary, s, "h", "initial");
}

StudyPlan plan_cost(const Scene& s) {
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double counted = methods * steps_to_each(s.real("t_end"), s.reals("h"));
  std::vector<TimedCall> calls;  // the timed configurations: a run per method and h
  const PlanRate& rate = plan_rate("elastic pendulum rowlands");
  for (std::size_t m = 0; m < s.texts("timing.methods").size(); ++m)
    for (double h : s.reals("h")) calls.push_back(TimedCall{s.real("t_end") / h, rate.ns_per_step});
  StudyPlan p{counted, counted * rate.evals_per_step(), methods * static_cast<double>(s.reals("h").size()) * 8 * kCsvCellBytes,
              rate.ns_per_step, "a counting run per method and h, then the timing protocol; " + rate.note};
  p.time(s, calls);
  return p;
}


}  // namespace

Study cost_study() {
  return {.name = "cost",
          .about = "cost of Fig 4's methods: error against wall time and force evaluations, against odeint's steppers",
          .files = {"cost_phase.csv"},
          .keys = Schema()
                      .texts("timing.methods", ElasticPendulumRuns::choices(), 1, "methods of the cost study (registry names or labels)")
                      .reals("timing.error_targets", positive(), 1,
                             "phase errors for which the wall time and the force evaluations to reach them are reported"),
          .reads = {"timing.repeats", "initial", "t_end", "h", "pendulum", "reference"},
          .run = run_cost,
          .validate =
              [](const Scene& s) {
                check_whole_steps(s, "h", "t_end");
                check_elastic_pendulum_states(s, "initial");
                ElasticPendulumRuns(elastic_pendulum_params(s)).check(s, "timing.methods", "h");
              },
          .plan = plan_cost,
          .aliases = {"timing"}};
}

}  // namespace geomint::rowlands_convergence
