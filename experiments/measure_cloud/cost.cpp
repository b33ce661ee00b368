// Beyond 003: what each discretization costs -- the error at energies.t_end of Phi^(4) against wall
// time (time_runs: the minimum of timing.repeats runs of >= 10 ms) over the steps order_study.h, with
// ns and Newton iterations per step at h -- and, at equal cost, Phi^(4) and Phi^(0) of
// cost.discretization against the classical RK4 on (3.8) over cost.rk4_h: trajectory and energy
// errors against wall time and evaluations (the runs take the steps of the order study to the end
// time of the energies).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/timing.hpp"
#include "measure_cloud.hpp"

namespace geomint::measure_cloud {
namespace {

// ---- work-precision: Phi^(4) against Phi^(0) and RK4 ----

// One timed run: its step, its trajectory (z_0 .. z_n; Newton iterations for Phi^(ell)) and its time.
struct TimedRun {
  double h;
  Trajectory tr;
  RunTime time;
};

// (3.8) as z' = f(z) on Vec<4>, for runge_kutta4; `evals` counts the evaluations of f.
struct ParticleField {
  const NonholonomicParticle& sys;
  std::int64_t* evals;
  Vec<4> f(const Vec<4>& z) const {
    ++*evals;
    const Point4 d = sys.rhs({z[0], z[1], z[2], z[3]});
    return {d[0], d[1], d[2], d[3]};
  }
};

Trajectory run_rk4(const NonholonomicParticle& sys, double h, const Point4& z0, std::int64_t n, std::int64_t* evals) {
  const ParticleField field{sys, evals};
  Trajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  Vec<4> y(z0[0], z0[1], z0[2], z0[3]);
  t.z.push_back(z0);
  for (std::int64_t j = 0; j < n; ++j) {
    y = runge_kutta4(field, y, h);
    t.z.push_back({y[0], y[1], y[2], y[3]});
  }
  return t;
}

// The runs compared at equal cost, in the order of the CSV rows.
constexpr const char* kCompared[] = {"phi4", "phi0", "rk4"};

// The common budget and the errors and costs at the targets of the runs of work_precision (traj:
// trajectory errors, energy: energy errors; per run of kCompared): summary.reproduced.work_precision
// what does not depend on the clock, summary.timing.work_precision the wall-time quantities.
void report_work_precision(Context& ctx, Discretization cmp, const std::vector<CostRun> (&traj)[3],
                           const std::vector<CostRun> (&energy)[3], double ref_err, double spread_max) {
  const Scene& s = ctx.scene;
  // the common budget: the largest wall time that every method reaches
  double budget = std::numeric_limits<double>::infinity();
  for (int m = 0; m < 3; ++m) budget = std::min(budget, largest_wall(traj[m]));
  const double target = s.real("cost.target_err"), target_energy = s.real("cost.target_energy_err");
  json w, wt;  // w: what does not depend on the clock (deterministic); wt: wall-time quantities (timing)
  w["discretization"] = discretization_name(cmp);
  w["methods"] = {"phi4", "phi0", "rk4"};
  w["reference_error"] = ref_err;
  w["reference_check_factor"] = reference_check_factor;
  w["target_err"] = target;
  w["target_energy_err"] = target_energy;
  wt["budget_s"] = budget;
  for (int m = 0; m < 3; ++m) {
    const auto t = by_decreasing_h(traj[m]), e = by_decreasing_h(energy[m]);
    json c, ct;
    ct["err_at_budget"] = or_null(error_at_wall(t, budget));
    ct["energy_err_at_budget"] = or_null(error_at_wall(e, budget));
    ct["wall_s_to_target"] = or_null(cost_to_reach(t, target, &CostRun::wall_s));
    c["evals_to_target"] = or_null(cost_to_reach(t, target, &CostRun::evals));
    ct["wall_s_to_target_energy"] = or_null(cost_to_reach(e, target_energy, &CostRun::wall_s));
    c["evals_to_target_energy"] = or_null(cost_to_reach(e, target_energy, &CostRun::evals));
    std::vector<double> hs, errs;
    for (const CostRun& r : t) hs.push_back(r.h), errs.push_back(r.err);
    c["order"] = fit_order(hs, errs, 0.0, "work precision").order;  // trajectory error against h
    ct["ns_per_step_at_h_max"] = 1e9 * t.front().wall_s / t.front().steps;
    w[kCompared[m]] = c, wt[kCompared[m]] = ct;
  }
  // speeds as ratios measured in this run: the cost of each method to reach the target over that of RK4
  for (const char* key : {"wall_s_to_target", "wall_s_to_target_energy"}) {
    const json r = wt["rk4"][key];  // copies: inserting into wt (an ordered_json) moves its elements
    for (const char* m : {"phi4", "phi0"}) {
      const json x = wt[m][key];
      wt["ratio_to_rk4"][m][key] = x.is_number() && r.is_number() ? json(x.get<double>() / r.get<double>()) : json(nullptr);
    }
  }
  ctx.summary["timing"]["work_precision"] = wt;
  ctx.summary["reproduced"]["work_precision"] = w;
  put(ctx, "timing", "work_precision_spread_max", spread_max);
}

// At equal cost (003, harmonic scene, not in the paper): Phi^(4) and Phi^(0) with the discretization
// cmp over order_study.h (the Phi^(4) runs are those of the cost study) and the classical RK4 on
// (3.8) over cost.rk4_h, each from z0 with N = floor(T/h) steps, T = energies.t_end. Two errors:
// the trajectory error |z_N - z(t_N)|_2 against the reference at t_N (whose own error, against a
// reference at 100x tighter tolerances, is reported), and the energy error max_j |H(z_j) - H0|
// (bounded for the conformal methods, drifting for RK4). Costs: wall time (time_runs: the minimum
// of timing.repeats runs of >= 10 ms) and evaluations (Newton iterations of Psi_{h,E}, each the
// discrete momentum with its 2x2 Jacobian; 4 evaluations of (3.8) per RK4 step).
void work_precision(Context& ctx, const NonholonomicParticle& sys, const Point4& z0, double rtol, double atol,
                    Discretization cmp, const std::vector<TimedRun>& phi4_runs) {
  const Scene& s = ctx.scene;
  const double T = s.real("energies.t_end"), H0 = sys.H(as_state(z0));
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  ctx.progress("cost: Phi^(4), Phi^(0) and RK4 at equal cost");
  std::vector<TimedRun> phi0_runs, rk4_runs;
  std::vector<std::int64_t> rk4_evals;
  for (double hh : s.reals("order_study.h")) {
    const std::int64_t n = steps_in(T, hh);
    Trajectory tr;
    const RunTime rt = time_runs(repeats, [&] {
      tr = run_phi(cmp, sys, hh, 0, z0, n);
      do_not_optimize(tr.z.back());
    });
    phi0_runs.push_back({hh, tr, rt});
  }
  for (double hh : s.reals("cost.rk4_h")) {
    const std::int64_t n = steps_in(T, hh);
    Trajectory tr;
    std::int64_t evals = 0;
    const RunTime rt = time_runs(repeats, [&] {
      evals = 0;
      tr = run_rk4(sys, hh, z0, n, &evals);
      do_not_optimize(tr.z.back());
    });
    rk4_runs.push_back({hh, tr, rt}), rk4_evals.push_back(evals);
  }
  const std::vector<TimedRun>* all[] = {&phi4_runs, &phi0_runs, &rk4_runs};
  Csv csv({"method", "h", "steps", "t_end", "err", "energy_err", "evals", "wall_s", "wall_spread"});
  std::vector<CostRun> traj[3], energy[3];
  double ref_err = 0, spread_max = 0;
  for (int m = 0; m < 3; ++m)
    for (std::size_t i = 0; i < all[m]->size(); ++i) {
      const TimedRun& r = (*all[m])[i];
      const std::int64_t n = static_cast<std::int64_t>(r.tr.z.size()) - 1;
      const double tN = static_cast<double>(n) * r.h;
      const auto ref = reference_samples(sys, z0, tN, 1, rtol, atol).back();
      const auto tight = reference_samples(sys, z0, tN, 1, reference_check_factor * rtol, reference_check_factor * atol).back();
      ref_err = std::max(ref_err, phase_distance(as_state(ref), as_state(tight)));
      double e_energy = 0;
      for (const Point4& z : r.tr.z) e_energy = std::max(e_energy, std::abs(sys.H(as_state(z)) - H0));
      const double err = phase_distance(as_state(r.tr.z.back()), as_state(ref));
      const double evals = m == 2 ? static_cast<double>(rk4_evals[i]) : static_cast<double>(r.tr.iterations);
      spread_max = std::max(spread_max, r.time.spread());
      csv.row(kCompared[m], r.h, n, tN, err, e_energy, evals, r.time.seconds(), r.time.spread());
      traj[m].push_back({r.h, static_cast<double>(n), r.time.seconds(), evals, err});
      energy[m].push_back({r.h, static_cast<double>(n), r.time.seconds(), evals, e_energy});
    }
  ctx.write("timing_work_precision.csv", csv);
  report_work_precision(ctx, cmp, traj, energy, ref_err, spread_max);
}

// ---- cost: error at energies.t_end against wall time, per method (Phi^(4)), over order_study.h ----

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  ctx.progress("cost");
  const double T = s.real("energies.t_end");
  const auto hs = s.reals("order_study.h");
  // the steps whose runs end at T itself (n h = T), for which the errors are also reported by step
  json h_at_T = json::array();
  for (double hh : hs)
    if (std::abs(static_cast<double>(steps_in(T, hh)) * hh / T - 1) < 1e-9) h_at_T.push_back(hh);
  Csv csv({"method", "h", "steps", "t_end", "err", "wall_s", "ns_per_step", "newton_iterations_per_step"});
  json ns_per_step, newton_at_h, err_at_T, order, time_at_h;
  double spread_max = 0;
  const Discretization cmp = *parse_discretization(method_info(s.text("cost.discretization")).label);
  std::vector<TimedRun> phi4_runs;  // the runs of Phi^(4) with the compared discretization, reused below
  for (Discretization d : methods) {
    const char* name = discretization_name(d);
    std::vector<double> errs;
    for (double hh : hs) {
      const std::int64_t n = steps_in(T, hh);  // the error is taken at n h <= T, against the reference there
      const auto ref = reference_samples(sys, z0, static_cast<double>(n) * hh, 1, rtol, atol).back();
      Trajectory tr;
      const RunTime rt = time_runs(static_cast<int>(s.integer("timing.repeats")), [&] {
        tr = run_phi(d, sys, hh, 4, z0, n);
        do_not_optimize(tr.z.back());
      });
      const double sec = rt.seconds();
      spread_max = std::max(spread_max, rt.spread());
      if (d == cmp) phi4_runs.push_back({hh, tr, rt});
      const double ns = 1e9 * sec / static_cast<double>(n), err = phase_distance(as_state(tr.z.back()), as_state(ref));
      const double newton = static_cast<double>(tr.iterations) / static_cast<double>(n);
      csv.row(name, hh, n, static_cast<double>(n) * hh, err, sec, ns, newton);
      errs.push_back(err);
      if (std::find(h_at_T.begin(), h_at_T.end(), hh) != h_at_T.end()) err_at_T[name].push_back(err);
      if (hh == h) ns_per_step[name] = ns, newton_at_h[name] = newton, time_at_h[name] = to_json(rt);
    }
    order[name] = fit_order(hs, errs, 0.0, "cost").order;  // error against h over all the steps
  }
  ctx.write("timing_cost.csv", csv);
  put(ctx, "timing", "cost_at_h", time_at_h);
  put(ctx, "timing", "cost_spread_max", spread_max);
  put(ctx, "timing", "ns_per_step", ns_per_step);
  put(ctx, "timing", "ns_per_step_ranges", method_ranges(ns_per_step));
  put_methods(ctx, "newton_iterations_per_step_phi4", newton_at_h);
  put(ctx, "reproduced", "cost_h_at_t_end", h_at_T);
  put(ctx, "reproduced", "cost_err_at_t_end", err_at_T);
  ctx.summary["orders"]["cost_error_phi4"] = order;
  ctx.summary["ranges"]["cost_error_phi4"] = method_ranges(order);
  work_precision(ctx, sys, z0, rtol, atol, cmp, phi4_runs);
}

StudyPlan plan_cost(const Scene& s) {
  const double T = s.real("energies.t_end"), runs = static_cast<double>(s.integer("timing.repeats")) + 1;
  const double M = static_cast<double>(s.texts("methods").size());
  double steps = 0, kept = 0;
  for (double h : s.reals("order_study.h")) steps += (M + 1) * runs * steps_of(T, h), kept += 2 * (steps_of(T, h) + 1);
  for (double h : s.reals("cost.rk4_h")) steps += runs * steps_of(T, h), kept += steps_of(T, h) + 1;
  return make_plan(steps, kept * kPointBytes, 119000, "steps: a lower bound (timed runs last at least 10 ms each)");
}

void check_cost(const Scene& s) {
  check_at_least_one_step(s, "energies.t_end", s.reals("order_study.h"), "max(order_study.h)");
  check_at_least_one_step(s, "energies.t_end", s.reals("cost.rk4_h"), "max(cost.rk4_h)");
  const auto ms = scene_methods(s);
  if (std::find(ms.begin(), ms.end(), *parse_discretization(method_info(s.text("cost.discretization")).label)) == ms.end())
    s.reject("cost.discretization", "must be one of the scene's methods (its Phi^(4) runs are reused)");
  check_first_step(s, "h", {s.real("h")});
  check_first_step(s, "order_study.h", s.reals("order_study.h"));
}

void keys(Schema& s) {
  s.integer("timing.repeats", at_least(1), "timed runs of >= 10 ms each (the minimum is the estimate)")
      .text("cost.discretization", method_choices(),
            "the discrete Lagrangian (5.1) of Phi^(4) and Phi^(0) in the comparison with RK4")
      .reals("cost.rk4_h", positive(), 3, "steps of the classical RK4 on (3.8), the baseline that preserves neither")
      .real("cost.target_err", positive(), "trajectory error at which the cost to reach it is reported")
      .real("cost.target_energy_err", positive(), "energy error max |H - H0| at which the cost to reach it is reported");
}

}  // namespace

// the cost runs take the steps of the order study to the end time of the energies
Study cost_study() {
  return {"cost", "error against wall time of each discretization; Phi^(4) against Phi^(0) and RK4 at equal cost",
          {"timing_cost.csv", "timing_work_precision.csv"},
          {"potential", "cloud.center", "h", "methods", "energies.t_end", "order_study.h", "timing", "cost", "reference"},
          check_cost, run_cost, plan_cost, keys};
}

}  // namespace geomint::measure_cloud
