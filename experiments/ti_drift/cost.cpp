// Cost: work-precision of the methods of work_precision.methods (processed where they have processing, as
// Fig. 1) on the harmonic oscillator of Fig. 1 (exact solution) and on Henon-Heiles k = 3 from the start of
// Fig. 3 (odeint reference): the global error at work_precision.t_end against the wall time
// (runner/timing.hpp) and the force evaluations, and the cost to reach work_precision.target.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/systems/counting.hpp"
#include "henon_heiles_starts.hpp"
#include "ti_drift.hpp"

namespace geomint::ti_drift {
namespace {

struct WpRow {
  std::string method;
  CostRun run;
  double spread = 0;
};

// The runs of one method on one problem: error(z_end) of the processed end state, evals by a counting run.
template <class Sys, class Err>
std::vector<WpRow> wp_runs(const Scene& s, const std::string& method, const Sys& sys, const typename Sys::State& z0,
                           const Err& error) {
  const double T = s.real("work_precision.t_end");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  std::vector<WpRow> rows;
  for (double h : s.reals("work_precision.h")) {
    const std::int64_t n = steps_to(T, h);
    std::int64_t evals = 0;
    const Counting<Sys> counted{sys, &evals};
    MethodsOn<Counting<Sys>>::integrate(method, counted, z0, h, n);
    const RunTime rt = MethodsOn<Sys>::time(method, sys, std::span(&z0, 1), h, n, repeats);
    const double err = error(MethodsOn<Sys>::integrate(method, sys, z0, h, n));
    if (!std::isfinite(err))
      throw NumericalFailure(method + " at h = " + format_double(h) + ": the error at t = " +
                             format_double(T) + " is not finite");
    rows.push_back({label_of(method), {h, static_cast<double>(n), rt.seconds(), static_cast<double>(evals), err}, rt.spread()});
  }
  return rows;
}

void run_work_precision(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: work-precision");
  const double T = s.real("work_precision.t_end"), target = s.real("work_precision.target");
  const auto methods = s.texts("work_precision.methods");
  // the reference of Henon-Heiles: odeint at rtol = atol = work_precision.reference_tol, its error estimated by the
  // difference to the solution at a 100 times tighter tolerance
  const HenonHeiles hh{{}, 3};
  const Z2 hh0 = hh_start(hh, s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"));
  const double tol = s.real("work_precision.reference_tol");
  const Z2 ref = reference_solution(hh, hh0, T, tol / 100, tol / 100);
  const Z2 ref_coarse = reference_solution(hh, hh0, T, tol, tol);
  const auto norm2 = [](const Z2& a, const Z2& b) { return std::sqrt((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm()); };
  const Z1 osc0 = make_state(0.0, 1.0);
  const Z1 osc_end = kOscillator.exact(osc0, T);
  Csv out({"problem", "method", "h", "steps", "wall_s", "wall_spread", "force_evals", "error"});
  json wp = {{"t_end", T}, {"target", target}, {"repeats", s.integer("timing.repeats")},
             {"reference", {{"oscillator", "exact solution"},
                            {"henon_heiles_tol", tol / 100},
                            {"henon_heiles_error", norm2(ref, ref_coarse)}}}};  // estimate: against tol
  for (const std::string problem : {"oscillator", "henon_heiles"}) {
    std::vector<std::vector<CostRun>> curves;
    json to_reach, evals_to_reach, spread_max;
    for (const auto& m : methods) {
      const auto rows = problem == "oscillator"
                            ? wp_runs(s, m, kOscillator, osc0, [&](const Z1& z) {
                                return std::hypot(z.p[0] - osc_end.p[0], kOscillator.w * (z.q[0] - osc_end.q[0]));
                              })
                            : wp_runs(s, m, hh, hh0, [&](const Z2& z) { return norm2(z, ref); });
      std::vector<CostRun> c;
      double sp = 0;
      for (const auto& r : rows) {
        out.row(problem, r.method, r.run.h, r.run.steps, r.run.wall_s, r.spread, r.run.evals, r.run.err);
        c.push_back(r.run), sp = std::max(sp, r.spread);
      }
      c = by_decreasing_h(c);
      to_reach[label_of(m)] = {{"wall_s", or_null(cost_to_reach(c, target, &CostRun::wall_s))},
                               {"evals", or_null(cost_to_reach(c, target, &CostRun::evals))},
                               {"ns_per_eval", 1e9 * rows.back().run.wall_s / rows.back().run.evals}};
      evals_to_reach[label_of(m)] = or_null(cost_to_reach(c, target, &CostRun::evals));
      spread_max[label_of(m)] = sp;
      curves.push_back(c);
    }
    double w_lo = 0, w_hi = std::numeric_limits<double>::infinity();
    for (const auto& c : curves) {
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (const auto& r : c) lo = std::min(lo, r.wall_s), hi = std::max(hi, r.wall_s);
      w_lo = std::max(w_lo, lo), w_hi = std::min(w_hi, hi);
    }
    json at_wall = nullptr;
    if (w_lo < w_hi) {
      const double w_star = std::sqrt(w_lo * w_hi);
      at_wall = {{"wall_s", w_star}};
      for (std::size_t m = 0; m < methods.size(); ++m) at_wall[label_of(methods[m])] = or_null(error_at_wall(curves[m], w_star));
    }
    // (wall times: summary.timing.work_precision, which figure_values.gp and the thread check leave out)
    wp[problem] = {{"evals_to_reach", evals_to_reach}};
    json& wt = ctx.summary["timing"]["work_precision"][problem];
    wt = {{"cost_to_reach", to_reach}, {"error_at_equal_wall_time", at_wall}, {"largest_spread", spread_max}};
    // the ratios of the costs to reach the target, relative to the first method, in wall time and in force evaluations
    json ratio;
    const std::string first = label_of(methods[0]);
    for (const auto& m : methods) {
      const auto& a = to_reach[label_of(m)];
      const auto& b = to_reach[first];
      if (!a["wall_s"].is_null() && !b["wall_s"].is_null())
        ratio[label_of(m)] = {{"wall_s", a["wall_s"].get<double>() / b["wall_s"].get<double>()},
                              {"evals", a["evals"].get<double>() / b["evals"].get<double>()}};
    }
    wt["cost_ratio_to_" + first] = ratio;
  }
  ctx.write("timing_work_precision.csv", out);
  ctx.summary["work_precision"] = wp;
}

void check_work_precision(const Scene& s) {
  MethodsOn<Counting<HenonHeiles>>::check(s, "work_precision.methods", {HenonHeiles{{}, 3}, nullptr});
  MethodsOn<Counting<HarmonicOscillator>>::check(s, "work_precision.methods", {kOscillator, nullptr});
  check_hh_starts(s, "hh3", HenonHeiles{{}, 3}, 0.0, false);
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h")) {
      check_oscillatory_bound(s, "work_precision.h", "work_precision.methods", m, kOscillator.w * h, "the oscillator");
      if (s.real("work_precision.t_end") / h < 1)
        s.reject("work_precision.t_end", "must be at least one step of every work_precision.h");
    }
}

StudyPlan plan_work_precision(const Scene& s) {
  // per method, problem and step: a counting run, an error run and timing.repeats timed runs (each repeated up to
  // 10 ms: the steps here are a lower bound); the odeint reference not counted
  const double T = s.real("work_precision.t_end"), runs = 2 + static_cast<double>(s.integer("timing.repeats"));
  StudyPlan p;
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h"))
      p.steps += 2 * runs * T / h, p.force_evals += 2 * runs * T / h * static_cast<double>(evals_per_step(m));
  p.memory_bytes = 1e5;
  p.ns_per_step = kNsPerStepHH;
  p.note = "a lower bound (timed runs last at least 10 ms each); " + std::string(kNsNote);
  return p;
}

void keys(Schema& s) {
  s.texts("work_precision.methods", MethodsOn<Counting<HenonHeiles>>::choices(), 2,
          "methods of the work-precision study (processed where they have processing; registry names or labels)")
      .reals("work_precision.h", positive(), 3, "steps of the work-precision runs (every method)")
      .real("work_precision.t_end", positive(), "the global error of a work-precision run is taken at this time")
      .real("work_precision.target", positive(), "target error of the cost to reach it")
      .real("work_precision.reference_tol", {.gt = {}, .ge = 1e-13, .lt = {}, .le = 1e-2},
            "odeint tolerance of the Henon-Heiles reference error estimate (the reference itself: 100 times tighter, so in [1e-15, 1e-4])");
}

}  // namespace

Study work_precision_study() {
  return {"work_precision", "cost: error against wall time and force evaluations (oscillator, Henon-Heiles k = 3)",
          {"timing_work_precision.csv"},
          {"work_precision", "timing.repeats", "hh3.q2", "hh3.p2", "hh.H0"},
          check_work_precision, run_work_precision, plan_work_precision, keys};
}

}  // namespace geomint::ti_drift
