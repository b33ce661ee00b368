// What the accuracy of 000 Fig. 4's methods costs, against odeint's own steppers (study `timing`):
// wall time (runner/timing.hpp) of each method from initial[0] to t_end (pre once, post once, eq.
// (23)); force evaluations and phase errors (against the reference at initial[0]) from separate
// counting runs. Per method: the wall time and force evaluations to reach each target error.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "rowlands_convergence.hpp"

namespace geomint::rowlands_convergence {
namespace {

// What each method's accuracy costs (summary.json timing.cost.<label>): at the smallest h, the force
// evaluations per step; its smallest error; its error at the wall time of the most expensive run of
// the first method (`budget`, at which the methods are compared); and for every target error the wall time
// and the force evaluations at which its error first reaches it, or null (reaches: false) where the
// measured step sizes do not reach it (log-log interpolation, never extrapolated).
json cost_summary(const std::vector<std::string>& methods, const std::vector<std::vector<CostRun>>& all,
                  const std::vector<double>& targets, double budget) {
  json out;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::vector<CostRun> runs = by_decreasing_h(all[k]);
    if (runs.empty()) continue;
    json c{{"evals_per_step", runs.back().evals / runs.back().steps},
           {"min_err", std::min_element(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.err < b.err; })->err},
           {"err_at_equal_wall", or_null(error_at_wall(runs, budget))},
           {"wall_to", json::array()}, {"evals_to", json::array()}, {"reaches", json::array()}};
    for (double t : targets) {
      c["wall_to"].push_back(or_null(cost_to_reach(runs, t, &CostRun::wall_s)));
      c["evals_to"].push_back(or_null(cost_to_reach(runs, t, &CostRun::evals)));
      c["reaches"].push_back(cost_to_reach(runs, t, &CostRun::evals).has_value());
    }
    out[label_of(methods[k])] = c;
  }
  return out;
}

template <class Sys>
void timing_with(Context& ctx, const Sys& sys) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("h");
  const std::size_t nh = hs.size();
  const double t_end = s.real("t_end");
  const auto methods = s.texts("timing.methods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const State z0 = state_of(s.real_rows("initial")[0]);
  ctx.progress("cost: reference (odeint Bulirsch-Stoer)");
  const State z_ref = reference_solution(sys, z0, t_end, s.real("reference.rtol"), s.real("reference.atol"));

  ctx.progress("cost: timing");
  struct Count {
    std::int64_t evals = 0;
    double phase = 0;
    auto fields() { return std::tie(evals, phase); }
  };
  const auto counts = distributed_map(methods.size() * nh, [&](std::size_t task) {
    Count c;
    const Counting<Sys> counted{sys, &c.evals};
    const double h = hs[task % nh];
    const std::int64_t n = steps_to(t_end, h);
    const State zN = with_method(methods[task / nh], counted, [&](const auto& m) { return integrate(m, z0, h, n); });
    c.phase = phase_distance(zN, z_ref);
    return c;
  });
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "phase_err", "wall_spread"});
  json ns_per_step, ns_spread, timing;
  SpreadTally spreads;
  std::vector<std::vector<CostRun>> runs(methods.size());  // per method, its runs of `h`
  const double h_ns = *std::min_element(hs.begin(), hs.end());
  for (std::size_t task = 0; task < counts.size(); ++task) {
    const std::string label = label_of(methods[task / nh]);
    const double h = hs[task % nh];
    const std::int64_t n = steps_to(t_end, h);
    const RunTime t = with_method(methods[task / nh], sys, [&](const auto& m) {  // (the dispatch outside the clock)
      return time_runs(repeats, [&] { do_not_optimize(integrate_inlined(m, z0, h, n)); });
    });
    spreads.add(t);
    const double wall = t.seconds();
    cost.row(label, h, n, wall, 1e9 * wall / static_cast<double>(n), counts[task].evals, counts[task].phase, t.spread());
    runs[task / nh].push_back({h, static_cast<double>(n), wall, static_cast<double>(counts[task].evals), counts[task].phase});
    if (h == h_ns) ns_per_step[label] = 1e9 * wall / static_cast<double>(n), ns_spread[label] = t.spread();
  }
  ctx.write("timing.csv", cost);
  timing["ns_per_step"] = ns_per_step;
  timing["ns_per_step_spread"] = ns_spread;
  timing["spread"] = spreads.to_json();  // of every timed run of the study
  if (ns_per_step.contains("sv") && ns_per_step.contains("rowlands"))
    timing["ns_per_step_ratio_rowlands_over_sv"] = ns_per_step["rowlands"].get<double>() / ns_per_step["sv"].get<double>();
  timing["method"] = timing_method_text(repeats) + "; from initial[0] to t_end (pre- and postprocessing once, every "
                     "call inlined); ns_per_step at the smallest h";
  const double budget = largest_wall(by_decreasing_h(runs[0]));  // the most expensive run of the first method
  timing["cost"] = cost_summary(methods, runs, s.reals("timing.error_targets"), budget);
  timing["equal_wall_s"] = budget;
  for (const auto& m : methods)
    timing["relative_cost"][label_of(m)] = ns_per_step[label_of(m)].get<double>() / ns_per_step[label_of(methods[0])].get<double>();
  ctx.summary["timing"] = timing;
  ctx.summary["methods"]["timing"] = labels_of(methods);
  scene_summary(ctx);
}

void run_timing(Context& ctx) {
  with_elastic_pendulum(pendulum_of(ctx.scene), [&](const auto& sys) { timing_with(ctx, sys); });
}

StudyPlan plan_timing(const Scene& s) {
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double counted = methods * steps_per_run(s);
  return {counted * (1 + repeats), counted * kEvalsPerStep, methods * static_cast<double>(s.reals("h").size()) * 8 * kCellBytes,
          kNsPerStep, "timed runs of < 10 ms are repeated to 10 ms (not counted); ns per step: the processed Rowlands method "
          "(paper-scene summary timing)"};
}

void keys(Schema& s) {
  s.texts("timing.methods", pendulum_method_choices(), 1, "methods of the cost study (registry names or labels)")
      .integer("timing.repeats", at_least(1), "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .reals("timing.error_targets", positive(), 1,
             "phase errors for which the wall time and the force evaluations to reach them are reported");
}

}  // namespace

Study cost_study() {
  return {"timing", "cost: error against wall time and force evaluations, against odeint's steppers", {"timing.csv"},
          {"timing", "initial", "t_end", "h", "pendulum", "reference"},
          [](const Scene& s) {
            check_common(s);
            check_methods(s, "timing.methods");
          },
          run_timing, plan_timing, keys};
}

}  // namespace geomint::rowlands_convergence
