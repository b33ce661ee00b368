// What the accuracy of 000 Figs 8-9's methods costs: wall time (runner/timing.hpp) of each method to
// convergence.t_end over the steps timing.h (steps only: the transformation (41) applied once before
// and once after), serial; errors and force evaluations from separate (parallel) counting runs.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include "euler_compensation.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"

namespace geomint::euler_compensation {
namespace {

void run_timing(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: timing");
  const State z0 = initial_state(s);
  const double t_end = s.real("convergence.t_end"), k = s.real("oscillator.k");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods");
  SpreadTally spreads;
  const auto timed = [&](const std::string& method, double h, std::int64_t n) {
    const RunTime t = oscillator_method_time(method, k, z0, h, n, repeats);
    spreads.add(t);
    return t;
  };
  const auto timing_hs = s.reals("timing.h");
  const auto timing_runs = distributed_map(timing_hs.size(), [&](std::size_t i) {
    return oscillator_runs(methods, z0, timing_hs[i], k, steps_to(t_end, timing_hs[i]));
  });
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "energy_err_max", "wall_spread"});
  std::vector<std::vector<CostRun>> curves(methods.size());  // per method: the runs of timing.h
  for (std::size_t i = 0; i < timing_hs.size(); ++i) {
    const double h = timing_hs[i];
    const std::int64_t n = steps_to(t_end, h);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const RunTime t = timed(methods[m], h, n);
      const double wall = t.seconds();
      const EnergyRun& r = timing_runs[i][m];
      cost.row(label_of(methods[m]), h, n, wall, 1e9 * wall / static_cast<double>(n), r.force_evals, r.max_err,
               t.spread());
      curves[m].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.force_evals), r.max_err});
    }
  }
  ctx.write("timing.csv", cost);

  json& timing = ctx.summary["timing"];
  const double h8 = s.real("oscillator.h");
  const std::int64_t n_timing = s.integer("timing.steps");
  json ns_per_step, ns_spread;
  for (const auto& m : methods) {
    const RunTime t = timed(m, h8, n_timing);
    ns_per_step[label_of(m)] = 1e9 * t.seconds() / static_cast<double>(n_timing);
    ns_spread[label_of(m)] = t.spread();
  }
  timing["ns_per_step"] = ns_per_step;
  timing["ns_per_step_spread"] = ns_spread;
  json relative;  // ns per step relative to the first method of timing.methods
  for (const auto& m : methods)
    relative[label_of(m)] = ns_per_step[label_of(m)].get<double>() / ns_per_step[label_of(methods[0])].get<double>();
  timing["relative_cost"] = relative;
  if (ns_per_step.contains("se") && ns_per_step.contains("se_compensated"))
    timing["ns_per_step_ratio_compensated_over_se"] =
        ns_per_step["se_compensated"].get<double>() / ns_per_step["se"].get<double>();
  timing["method"] = timing_method_text(repeats) + "; ns_per_step at oscillator.h over timing.steps steps";
  timing["spread"] = spreads.to_json();  // of every timed measurement of the study
  // Error at equal wall time: at the geometric middle of the wall-time range
  // that all methods cover.
  double w_lo = 0, w_hi = std::numeric_limits<double>::infinity();
  for (const auto& curve : curves) {
    const auto [lo, hi] = std::minmax_element(curve.begin(), curve.end(),
                                              [](const CostRun& a, const CostRun& b) { return a.wall_s < b.wall_s; });
    w_lo = std::max(w_lo, lo->wall_s), w_hi = std::min(w_hi, hi->wall_s);
  }
  if (w_lo < w_hi) {
    const double w_star = std::sqrt(w_lo * w_hi);
    json at_wall{{"wall_s", w_star}};
    for (std::size_t m = 0; m < methods.size(); ++m) at_wall[label_of(methods[m])] = or_null(error_at_wall(curves[m], w_star));
    timing["error_at_equal_wall_time"] = at_wall;
  } else {
    timing["error_at_equal_wall_time"] = nullptr;  // timing.h gives no common wall-time range
  }
  // Where the work-precision curves of the first two methods cross (null: not in the measured range).
  const auto cross = methods.size() > 1 ? crossover(curves[0], curves[1]) : std::nullopt;
  timing["crossover"] = cross ? json{{"methods", {label_of(methods[0]), label_of(methods[1])}},
                                     {"wall_s", cross->wall_s}, {"err", cross->err}}
                              : json(nullptr);
  ctx.summary["h_range"]["timing"] = h_range(timing_hs);
}

StudyPlan plan_timing(const Scene& s) {
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double counted = methods * steps_to_t_end(s, "timing.h");
  const double steps = counted * (1 + repeats) + methods * repeats * static_cast<double>(s.integer("timing.steps"));
  return {steps, counted * kEvalsPerStep, methods * static_cast<double>(s.reals("timing.h").size()) * 8 * kCellBytes,
          kOscillatorNs, std::string("timed runs of < 10 ms are repeated to 10 ms (not counted); ") + kOscillatorNsNote};
}

void keys(Schema& s) {
  s.texts("timing.methods", oscillator_method_choices(), 1, "methods of the cost study (registry names or labels)")
      .reals("timing.h", positive(), 3, "steps of the work-precision runs (to convergence.t_end)")
      .integer("timing.repeats", at_least(1), "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .integer("timing.steps", at_least(1), "steps of the run that measures ns per step");
}

}  // namespace

Study cost_study() {
  return {"timing", "cost: error against wall time and force evaluations", {"timing.csv"},
          {"timing", "convergence.t_end", "oscillator.q0", "oscillator.p0", "oscillator.k", "oscillator.h"},
          [](const Scene& s) { check_steps(s, "timing.h", "timing.methods"); }, run_timing, plan_timing, keys};
}

}  // namespace geomint::euler_compensation
