// Cost (study `cost`, formerly `work_precision`): work-precision of the methods of work_precision.methods
// (processed where they have processing, as Fig. 1) in two sets (analysis/work_precision_set.hpp):
// "henon_heiles", Henon-Heiles k = 3 from the start of Fig. 3 (odeint reference), and "oscillator", the
// harmonic oscillator of Fig. 1 (exact solution). Per method and step h of work_precision.h: the global
// error at work_precision.t_end, the wall time of one run (runner/timing.hpp) and the force evaluations
// of a counting run; the cost to reach work_precision.target, and the errors at equal cost (equal_cost).
#include <cmath>
#include <string>
#include <vector>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/methods/work_precision_runs.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint::ti_drift {
namespace {

const HarmonicOscillator kOscillator{1.0, 1.0};  // Fig. 1: omega = 1

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const double T = s.real("work_precision.t_end");
  const std::vector<double> targets{s.real("work_precision.target")};
  const auto methods = s.texts("work_precision.methods");
  // the reference of Henon-Heiles: odeint at rtol = atol = work_precision.reference_tol / 100, its error
  // estimated by the difference to the solution at work_precision.reference_tol
  ctx.progress("cost: Henon-Heiles reference (odeint Bulirsch-Stoer)");
  const HenonHeiles hh{{}, 3};
  const HenonHeiles::State hh0 = hh.start(s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"));
  const double tol = s.real("work_precision.reference_tol");
  const HenonHeiles::State ref = reference_solution(hh, hh0, T, tol / 100, tol / 100), ref_coarse = reference_solution(hh, hh0, T, tol, tol);
  const auto norm2 = [](const HenonHeiles::State& a, const HenonHeiles::State& b) { return std::sqrt((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm()); };
  const HarmonicOscillator::State osc0 = make_state(0.0, 1.0), osc_end = kOscillator.exact(osc0, T);
  ctx.progress("cost: work-precision");
  WorkPrecisionSet henon_heiles("l2 phase-space error |z_N - z(t_end)| against the odeint reference, Henon-Heiles k = 3");
  WorkPrecisionSet oscillator("sqrt((p_N - p(t_end))^2 + (omega (q_N - q(t_end)))^2) against the exact solution, omega = 1");
  const auto hs = s.reals("work_precision.h");
  for (const auto& m : methods) add_method_runs(henon_heiles, m, hh, hh0, hs, T, [&](const HenonHeiles::State& z) { return norm2(z, ref); });
  for (const auto& m : methods)
    add_method_runs(oscillator, m, kOscillator, osc0, hs, T, [&](const HarmonicOscillator::State& z) {
      return std::hypot(z.p[0] - osc_end.p[0], kOscillator.w * (z.q[0] - osc_end.q[0]));
    });
  ctx.progress("cost: timed runs");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  henon_heiles.time(repeats, ctx.threads), oscillator.time(repeats, ctx.threads);
  ctx.write("cost_henon_heiles.csv", henon_heiles.csv());
  ctx.write("cost_oscillator.csv", oscillator.csv());
  Value cost = {{"henon_heiles", henon_heiles.summary(targets)},
                {"oscillator", oscillator.summary(targets)},
                {"method", timing_method_text(repeats) + "; one run from the start to work_precision.t_end, processing included, every call inlined"},
                {"reference", {{"oscillator", "exact solution"}, {"henon_heiles_tol", tol / 100},
                               {"henon_heiles_error", norm2(ref, ref_coarse)}}}};  // estimate: against tol
  const std::string first = label_of(methods[0]);
  for (const char* set : {"henon_heiles", "oscillator"})
    cost["cost_ratio_to_" + first][set] = WorkPrecisionSet::cost_ratios(cost.at(set), first);
  ctx.summary["cost"] = cost;
}

void check_cost(const Scene& s) {
  MethodsOn<Counting<HenonHeiles>>::check(s, "work_precision.methods", {HenonHeiles{{}, 3}, nullptr});
  MethodsOn<Counting<HarmonicOscillator>>::check(s, "work_precision.methods", {kOscillator, nullptr});
  check_henon_heiles_starts(s, "hh3", HenonHeiles{{}, 3}, 0.0, false);
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h")) {
      check_oscillatory_bound(s, "work_precision.h", "work_precision.methods", m, kOscillator.w * h, "the oscillator");
      if (s.real("work_precision.t_end") / h < 1)
        s.reject("work_precision.t_end", "must be at least one step of every work_precision.h");
    }
}

StudyPlan plan_cost(const Scene& s) {
  // per method, problem and step: a counting run and an error run, then the timing protocol over the runs;
  // the odeint reference not counted
  const double T = s.real("work_precision.t_end");
  const PlanRate& rate = plan_rate("henon-heiles splitting");
  StudyPlan p;
  std::vector<TimedCall> calls;
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h")) {
      p.steps += 2 * 2 * T / h, p.force_evals += 2 * 2 * T / h * static_cast<double>(evals_per_step(m));
      calls.insert(calls.end(), 2, TimedCall{T / h, rate.ns_per_step});  // (Henon-Heiles and the oscillator)
    }
  p.memory_bytes = 1e5, p.ns_per_step = rate.ns_per_step;
  p.note = "counting and error runs, then the timing protocol; " + rate.note;
  p.time(s, calls);
  return p;
}

}  // namespace

Study cost_study() {
  return {.name = "cost",
          .about = "cost: error against wall time and force evaluations (Henon-Heiles k = 3, oscillator)",
          .files = {"cost_henon_heiles.csv", "cost_oscillator.csv"},
          .keys = Schema()
                      .texts("work_precision.methods", MethodsOn<Counting<HenonHeiles>>::choices(), 2,
                             "methods of the work-precision study (processed where they have processing; registry names or labels)")
                      .reals("work_precision.h", positive(), 3, "steps of the work-precision runs (every method)")
                      .real("work_precision.t_end", positive(), "the global error of a work-precision run is taken at this time")
                      .real("work_precision.target", positive(), "target error of the cost to reach it")
                      .real("work_precision.reference_tol", {.gt = {}, .ge = 1e-13, .lt = {}, .le = 1e-2},
                            "odeint tolerance of the Henon-Heiles reference error estimate (the reference itself: 100 times tighter, so in [1e-15, 1e-4])"),
          .reads = {"timing.repeats", "hh3.q2", "hh3.p2", "hh.H0"},
          .run = run_cost,
          .validate = check_cost,
          .plan = plan_cost,
          .aliases = {"work_precision"}};
}

}  // namespace geomint::ti_drift
