// What the accuracy costs on the nonlinear pendulum to nonlinear.t_end, against its own odeint
// reference (study `cost`, formerly `timing`): one work-precision set (analysis/work_precision_set.hpp),
// "pendulum": per method of timing.methods and step of nonlinear.h, the phase-space error at t_end and
// the force evaluations (a counting run) and the wall time of the run (runner/timing.hpp, serial).
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

using Z1 = PhaseState<1>;


void check_cost(const Scene& s) {
  check_distinct_methods(s, "timing.methods");
  check_whole_steps(s, "nonlinear.h", "nonlinear.t_end");
  check_oscillatory_bounds(s, {"nonlinear.h", NonlinearPendulum::max_frequency(), false, ", frequency 1"}, "timing.methods");
}

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end");
  const NonlinearPendulum pend;
  const Z1 pz0 = make_state(s.real("nonlinear.pendulum_q0"), 0.0);
  const Z1 pref = reference_solution(pend, pz0, t_end, s.real("reference.rtol"), s.real("reference.atol"));
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods");
  WorkPrecisionSet set("l2 phase-space error |z_N - z(t_end)|_2 at nonlinear.t_end against the odeint reference");
  for (const auto& m : methods)
    for (double h : nh) {
      const std::int64_t n = steps_to(t_end, h);
      std::int64_t evals = 0;
      const double err =
          phase_distance(MethodsOn<Counting<NonlinearPendulum>>::integrate(m, {pend, &evals}, pz0, h, n), pref);
      set.add({label_of(m), h, static_cast<double>(n), {}, static_cast<double>(evals), err},
              MethodsOn<NonlinearPendulum>::timed(m, pend, {pz0}, h, n));
    }
  set.time(repeats, ctx.threads);
  ctx.write("cost_pendulum.csv", set.csv());
  Value cost = {{"pendulum", set.summary(s.reals("timing.error_targets"))}, {"method", segmented_timing_method_text(repeats, "long_run_*", "long_run_cost.timing_steps")}};
  // ns per step on the pendulum relative to the first of timing.methods
  cost["relative_ns_per_step"] = set.relative_ns_per_step();
  merge(ctx.summary, "cost", cost);  // (long_run_cost adds its sets beside, in either order, or alone)
}

StudyPlan plan_cost(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const auto methods = s.texts("timing.methods");
  const PlanRate& rate = plan_rate("pendulum lobatto");
  double steps = 0;
  std::vector<TimedCall> calls;
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (double h : s.reals("nonlinear.h")) steps += t_end / h, calls.push_back(TimedCall{t_end / h, rate.ns_per_step});
  StudyPlan p{steps, steps * rate.evals_per_step(), static_cast<double>(calls.size()) * 8 * kCsvCellBytes, rate.ns_per_step,
              "a counting run per method and h, then the timing protocol; " + rate.note};
  p.time(s, calls);
  return p;
}

}  // namespace

Study cost_study() {
  return {.name = "cost",
          .about = "cost: error against wall time and force evaluations",
          .files = {"cost_pendulum.csv"},
          .keys = Schema()
                      .texts("timing.methods", MethodsOn<NonlinearPendulum>::names(), 1,
                             "methods timed on the nonlinear pendulum at the steps nonlinear.h, against its reference")
                      .reals("timing.error_targets", positive(), 1,
                             "errors whose cost (wall time, force evaluations) each method's runs are asked for")
                      // (declared so that scenes which set it are still read; equal wall time is the one rule of
                      // equal_cost)
                      .text("timing.equal_wall", MethodsOn<NonlinearPendulum>::names(),
                            "unused: the errors at equal wall time are at the largest wall time every method's runs "
                            "reach (analysis/work_precision.hpp equal_cost), whatever this names"),
          .reads = {"timing.repeats", "nonlinear.h", "nonlinear.t_end", "nonlinear.pendulum_q0", "reference"},
          .run = run_cost,
          .validate = check_cost,
          .plan = plan_cost,
          .aliases = {"timing"}};
}

}  // namespace geomint::lobatto_table
