// What the accuracy costs on the nonlinear pendulum to nonlinear.t_end, against its own odeint
// reference: for each method of timing.methods at the steps nonlinear.h, the error, the force
// evaluations (a counting run) and the wall time (runner/timing.hpp, serial); per method the cost
// per step, the error at equal wall time and the cost of reaching each of timing.error_targets.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "lobatto_table.hpp"

namespace geomint::lobatto_table {
namespace {

void check_timing(const Scene& s) {
  check_distinct_methods(s, "timing.methods");
  check_nonlinear_steps(s);
  for (const auto& m : s.texts("timing.methods")) check_pendulum_steps(s, "timing.methods", m);
  const auto timed = s.texts("timing.methods");
  if (std::find(timed.begin(), timed.end(), s.text("timing.equal_wall")) == timed.end())
    s.reject("timing.equal_wall", "one of timing.methods");
}

// "%g" of an error target: the key of summary.timing.cost.<method>.wall_s_to and evals_to.
std::string target_key(double target) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", target);
  return b;
}

// What each method's runs cost: per step at the smallest h, relative to the first method; its
// smallest error; its error at the wall time `equal_wall`; the wall time and the force evaluations
// at which it first reaches each target (null where its measured runs do not reach it).
json cost_summary(const std::vector<std::string>& timed, const std::map<std::string, std::vector<CostRun>>& runs,
                  const json& ns_per_step, double equal_wall, const std::vector<double>& targets) {
  json cost = json::object();
  for (const auto& label : timed) {
    const auto r = by_decreasing_h(runs.at(label));
    if (r.empty()) continue;
    double min_err = r.front().err;
    for (const CostRun& x : r) min_err = std::min(min_err, x.err);
    json c = {{"relative_cost", ns_per_step[label].get<double>() / ns_per_step[timed.front()].get<double>()},
              {"evals_per_step", r.back().evals / r.back().steps},
              {"min_err", min_err},
              {"err_at_equal_wall", or_null(error_at_wall(r, equal_wall))}};
    for (double t : targets) {
      c["wall_s_to"][target_key(t)] = or_null(cost_to_reach(r, t, &CostRun::wall_s));
      c["evals_to"][target_key(t)] = or_null(cost_to_reach(r, t, &CostRun::evals));
    }
    cost[label] = c;
  }
  return cost;
}

void run_timing(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end");
  const auto [pend, pz0] = pendulum(s);
  const Z1 pref = reference_solution(pend, pz0, t_end, s.real("reference.rtol"), s.real("reference.atol"));
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "error", "wall_spread"});
  json ns = json::object(), ns_spread = json::object();
  SpreadTally spreads;
  std::map<std::string, std::vector<CostRun>> runs;
  for (const auto& m : s.texts("timing.methods")) {
    const std::string label = label_of(m);
    for (double h : nh) {
      const std::int64_t n = steps_to(t_end, h);
      std::int64_t evals = 0;
      const double err =
          phase_distance(MethodsOn<Counting<NonlinearPendulum>>::integrate(m, {pend, &evals}, pz0, h, n), pref);
      const RunTime t = MethodsOn<NonlinearPendulum>::time(m, pend, std::span(&pz0, 1), h, n, repeats);
      spreads.add(t);
      const double wall = t.seconds();
      cost << label << h << n << wall << 1e9 * wall / static_cast<double>(n) << evals << err << t.spread();
      cost.end_row();
      if (h == nh.back()) ns[label] = 1e9 * wall / static_cast<double>(n), ns_spread[label] = t.spread();
      runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(evals), err});
    }
  }
  ctx.write("timing.csv", cost);
  const json timed = labels_of(s.texts("timing.methods"));
  const double equal_wall = largest_wall(by_decreasing_h(runs[label_of(s.text("timing.equal_wall"))]));
  ctx.summary["methods"]["timing"] = timed;
  ctx.summary["timing"] = {
      {"ns_per_step", ns},
      {"ns_per_step_spread", ns_spread},
      {"spread", spreads.to_json()},
      {"method", "nonlinear pendulum to nonlinear.t_end; " + timing_method_text(repeats) +
                     "; ns_per_step at the smallest nonlinear.h; force evaluations count U_q and U_qq calls"},
      {"equal_wall_s", equal_wall},
      {"cost", cost_summary(timed.get<std::vector<std::string>>(), runs, ns, equal_wall,
                            s.reals("timing.error_targets"))}};
}

StudyPlan plan_timing(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  double steps = 0;
  for (double h : s.reals("nonlinear.h")) steps += methods * (1 + repeats) * t_end / h;  // a counting run, the timed runs
  return {steps, steps / (1 + repeats) * kPendulumEvals, methods * static_cast<double>(s.reals("nonlinear.h").size()) * 8 * kCellBytes,
          kPendulumNs, "timed runs of < 10 ms are repeated to 10 ms (not counted); ns per step: Lobatto on the pendulum (paper-scene summary timing)"};
}

void keys(Schema& s) {
  s.texts("timing.methods", MethodsOn<NonlinearPendulum>::names(), 1,
          "methods timed on the nonlinear pendulum at the steps nonlinear.h, against its reference")
      .reals("timing.error_targets", positive(), 1,
             "errors whose cost (wall time, force evaluations) each method's runs are asked for")
      .text("timing.equal_wall", MethodsOn<NonlinearPendulum>::names(),
            "the method of timing.methods whose most expensive run sets the wall time of the comparison at equal cost");
}

}  // namespace

Study timing_study() {
  return {"timing", "cost: error against wall time and force evaluations", {"timing.csv"},
          {"timing", "nonlinear.h", "nonlinear.t_end", "nonlinear.pendulum_q0", "reference"}, check_timing, run_timing,
          plan_timing, keys};
}

}  // namespace geomint::lobatto_table
