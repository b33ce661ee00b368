// Beyond 003: what accuracy costs on the harmonic particle (study `cost`): two work-precision sets
// (analysis/work_precision_set.hpp) of the same runs, one per error: "trajectory", the l2 phase-space
// error |z_N - z_ref(t_N)|_2 at t_N = N h <= T against the reference there, and "energy", the energy
// error max_j |H(z_j) - H_0| over the run. Methods: Phi^(4) of each scene discretization (phi4_<label>)
// and Phi^(0) of cost.discretization (phi0_<label>) over order_study.h, and the classical RK4 on (3.8)
// (rk4) over cost.rk4_h; every run from cloud.center with N = floor(T/h) steps, T = energies.t_end.
// Costs: wall time (WorkPrecisionSet::time: the timing protocol of runner/timing.hpp, every run together;
// RK4, of fixed work per step, timed at its fewest and most steps) and evaluations (Newton
// iterations of Psi_{h,E}, each the discrete momentum with its 2x2 Jacobian; 4 evaluations of (3.8)
// per RK4 step). Besides, what is not a cost (reproduced, orders, ranges): per discretization the
// Newton iterations per step at h, the errors at T for the steps that end there and the order of the
// trajectory error; the orders of the compared runs and the reference's own error.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geomint/analysis/phi_study.hpp"
#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint::measure_cloud {
namespace {

// One run: its label in the sets, its step, its trajectory (z_0 .. z_n; Newton iterations for Phi^(ell)),
// its evaluations, and the run again (to time).
struct TimedRun {
  std::string method;
  double h;
  PointTrajectory tr;
  double evals;
  std::function<void()> again;
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

PointTrajectory run_rk4(const NonholonomicParticle& sys, double h, const Point4& z0, std::int64_t n, std::int64_t* evals) {
  const ParticleField field{sys, evals};
  PointTrajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  Vec<4> y(z0[0], z0[1], z0[2], z0[3]);
  t.z.push_back(z0);
  for (std::int64_t j = 0; j < n; ++j) {
    y = runge_kutta4(field, y, h);
    t.z.push_back({y[0], y[1], y[2], y[3]});
  }
  return t;
}

std::string phi_label(int ell, Discretization d) { return "phi" + std::to_string(ell) + "_" + discretization_name(d); }

// Phi^(ell) of d at the step h to T = energies.t_end (timed by timed_runs).
TimedRun timed_phi(const Scene& s, const PhiStudy& p, Discretization d, int ell, double h) {
  const std::int64_t n = steps_within(s.real("energies.t_end"), h);  // n h <= T: the error is taken there
  PointTrajectory tr = run_phi(d, p.sys, h, ell, p.z0, n);
  const double evals = static_cast<double>(tr.iterations);
  return {phi_label(ell, d), h, std::move(tr), evals, [&p, d, h, ell, n] {
            do_not_optimize(run_phi(d, p.sys, h, ell, p.z0, n).z.back());
          }};
}

// The classical RK4 on (3.8) at the step h to T = energies.t_end (timed by timed_runs); its evaluations of
// (3.8) counted.
TimedRun timed_rk4(const Scene& s, const PhiStudy& p, double h) {
  const std::int64_t n = steps_within(s.real("energies.t_end"), h);
  std::int64_t evals = 0;
  PointTrajectory tr = run_rk4(p.sys, h, p.z0, n, &evals);
  return {"rk4", h, std::move(tr), static_cast<double>(evals), [&p, h, n] {
            std::int64_t uncounted = 0;
            do_not_optimize(run_rk4(p.sys, h, p.z0, n, &uncounted).z.back());
          }};
}

// Every run, in the order of the sets' rows: Phi^(4) of each discretization, Phi^(0) of cmp, RK4.
std::vector<TimedRun> cost_runs(Context& ctx, const PhiStudy& p, Discretization cmp) {
  const Scene& s = ctx.scene;
  std::vector<TimedRun> runs;
  ctx.progress("cost: Phi^(4) of each discretization");
  for (Discretization d : p.methods)
    for (double h : s.reals("order_study.h")) runs.push_back(timed_phi(s, p, d, 4, h));
  ctx.progress("cost: Phi^(0) and RK4");
  for (double h : s.reals("order_study.h")) runs.push_back(timed_phi(s, p, cmp, 0, h));
  for (double h : s.reals("cost.rk4_h")) runs.push_back(timed_rk4(s, p, h));
  return runs;
}

struct Sets {
  WorkPrecisionSet trajectory{"l2 phase-space error |z_N - z_ref(t_N)|_2 at t_N = N h <= energies.t_end from cloud.center"};
  WorkPrecisionSet energy{"energy error max_j |H(z_j) - H_0| over the run from cloud.center to t_N = N h <= energies.t_end"};
  double reference_error = 0;  // of the references at every t_N, against references at 100x tighter tolerances
};

// The errors of every run against the reference at its t_N (one reference per t_N, and its own error), and
// the wall times: the trajectory set times the runs (every run together), the energy set has the same.
Sets errors_of(Context& ctx, const PhiStudy& p, const std::vector<TimedRun>& runs) {
  Sets out;
  const double H0 = p.sys.H(from_array(p.z0));
  std::map<double, Point4> refs;  // by t_N
  for (const TimedRun& r : runs) {
    const auto n = static_cast<std::int64_t>(r.tr.z.size()) - 1;
    const double tN = static_cast<double>(n) * r.h;
    if (!refs.contains(tN)) {
      const auto ref = reference_samples(p.sys, p.z0, tN, 1, p.rtol, p.atol).back();
      const auto tight = reference_samples(p.sys, p.z0, tN, 1, reference_check_factor * p.rtol, reference_check_factor * p.atol).back();
      out.reference_error = std::max(out.reference_error, phase_distance(from_array(ref), from_array(tight)));
      refs.emplace(tN, ref);
    }
    double e_energy = 0;
    for (const Point4& z : r.tr.z) e_energy = std::max(e_energy, std::abs(p.sys.H(from_array(z)) - H0));
    const double err = phase_distance(from_array(r.tr.z.back()), from_array(refs.at(tN)));
    out.trajectory.add({r.method, r.h, static_cast<double>(n), {}, r.evals, err}, r.again);
    out.energy.add({r.method, r.h, static_cast<double>(n), {}, r.evals, e_energy});
  }
  ctx.progress("cost: timed runs");
  out.trajectory.time(static_cast<int>(ctx.scene.integer("timing.repeats")), ctx.threads);
  out.energy.times_of(out.trajectory);
  return out;
}

// Per discretization, from its Phi^(4) runs: the Newton iterations per step at h, the errors at T for
// the steps whose runs end at T itself (n h = T), and the order of the error against h over all the
// steps (reproduced, ranges, orders). Returns the ns per step at h (the step of 003's figures), by label.
Value report_discretizations(Context& ctx, const PhiStudy& p, const WorkPrecisionSet& trajectory) {
  const Scene& s = ctx.scene;
  const double T = s.real("energies.t_end");
  const auto hs = s.reals("order_study.h");
  std::vector<double> h_at_T;
  for (double hh : hs)
    if (std::abs(static_cast<double>(steps_within(T, hh)) * hh / T - 1) < 1e-9) h_at_T.push_back(hh);
  Value ns_per_step, newton_at_h, err_at_T, order;
  std::vector<std::string> names;  // Phi^(4) at h: each discretization's time per step against the first's
  std::vector<RunTime> per_step;
  std::vector<double> work;  // (Newton iterations per step)
  for (Discretization d : p.methods) {
    const char* name = discretization_name(d);
    std::vector<double> errs;  // in the order of hs
    for (const WorkPrecisionRecord& r : trajectory.records()) {
      if (r.method != phi_label(4, d)) continue;
      errs.push_back(r.err);
      if (std::find(h_at_T.begin(), h_at_T.end(), r.h) != h_at_T.end()) err_at_T[name].push_back(r.err);
      if (r.h == p.h) {
        ns_per_step[name] = 1e9 * r.wall.seconds() / r.steps, newton_at_h[name] = r.evals / r.steps;
        names.push_back(name), per_step.push_back(r.wall.scaled(1e9 / r.steps)), work.push_back(r.evals / r.steps);
      }
    }
    const OrderFit fit = fit_order(hs, errs, 0.0, "cost");
    order[name] = fit.order;
    record_order_fit(ctx.summary, std::string("orders.cost_error_phi4.") + name,
                     {"cost_trajectory.csv", "h", "err", {{"method", phi_label(4, d)}}}, fit, 0.0);
  }
  put_methods(ctx, "newton_iterations_per_step_phi4", newton_at_h);
  if (!names.empty()) ctx.summary["cost"]["relative_ns_per_step_at_h"] = relative_timings(names, per_step, work);
  ctx.summary["reproduced"]["cost_h_at_t_end"] = h_at_T;
  ctx.summary["reproduced"]["cost_err_at_t_end"] = err_at_T;
  ctx.summary["orders"]["cost_error_phi4"] = order;
  ctx.summary["ranges"]["cost_error_phi4"] = method_ranges(order);
  return ns_per_step;
}

// The comparison of Phi^(4), Phi^(0) (of cmp) and RK4 that is not a cost (summary.reproduced.work_precision):
// the fitted order of each one's trajectory error against h and the reference's own error.
void report_compared(Context& ctx, Discretization cmp, const Sets& sets) {
  const Scene& s = ctx.scene;
  Value w;
  w["discretization"] = discretization_name(cmp);
  w["methods"] = std::vector<std::string>{"phi4", "phi0", "rk4"};
  w["reference_error"] = sets.reference_error;
  w["reference_check_factor"] = reference_check_factor;
  w["target_err"] = s.real("cost.target_err");
  w["target_energy_err"] = s.real("cost.target_energy_err");
  for (const std::string m : {"phi4", "phi0", "rk4"}) {
    std::vector<double> hs, errs;
    for (const CostRun& r : sets.trajectory.runs(m == "rk4" ? m : m + "_" + discretization_name(cmp)))
      hs.push_back(r.h), errs.push_back(r.err);
    const std::string method = m == "rk4" ? m : m + "_" + discretization_name(cmp);
    const OrderFit fit = fit_order(hs, errs, 0.0, "work precision");  // trajectory error against h
    w[m]["order"] = fit.order;
    record_order_fit(ctx.summary, "reproduced.work_precision." + m + ".order",
                     {"cost_trajectory.csv", "h", "err", {{"method", method}}}, fit, 0.0);
  }
  ctx.summary["reproduced"]["work_precision"] = w;
}

// summary.cost: the two sets, the timing method, the ns per step of Phi^(4) at h (by label, and its
// ranges), and per set the wall time of each method to its target over that of RK4
// (wall_s_to_target_over_rk4; null where either does not reach it).
void report_cost(Context& ctx, const Sets& sets, const Value& ns_per_step_at_h) {
  const Scene& s = ctx.scene;
  Value& cost = ctx.summary["cost"];
  cost["trajectory"] = sets.trajectory.summary({s.real("cost.target_err")});
  cost["energy"] = sets.energy.summary({s.real("cost.target_energy_err")});
  cost["method"] = timing_method_text(static_cast<int>(s.integer("timing.repeats"))) +
                   "; one run from cloud.center to energies.t_end; ns_per_step at the smallest h (by_method) and, "
                   "for Phi^(4), at the scene's h (ns_per_step_at_h)";
  cost["ns_per_step_at_h"] = ns_per_step_at_h;
  cost["ns_per_step_at_h_ranges"] = method_ranges(ns_per_step_at_h);
  for (const char* set : {"trajectory", "energy"}) {
    const Value by = cost.at(set).at("by_method");  // (a copy: cost grows below)
    const Value& rk4 = by.at("rk4").at("wall_s_to").at(0);
    for (std::size_t i = 0; i < by.size(); ++i) {
      const std::string& m = by.keys()[i];
      const Value& x = by.at(i).at("wall_s_to").at(0);
      if (m != "rk4")
        cost["wall_s_to_target_over_rk4"][set][m] = x.is_number() && rk4.is_number() ? Value(x.number() / rk4.number()) : Value();
    }
  }
}

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const PhiStudy p = phi_study(ctx);
  const Discretization cmp = *parse_discretization(method_info(s.text("cost.discretization")).label);
  const std::vector<TimedRun> runs = cost_runs(ctx, p, cmp);
  ctx.progress("cost: errors against the reference");
  const Sets sets = errors_of(ctx, p, runs);
  ctx.write("cost_trajectory.csv", sets.trajectory.csv());
  ctx.write("cost_energy.csv", sets.energy.csv());
  const Value ns_at_h = report_discretizations(ctx, p, sets.trajectory);
  report_compared(ctx, cmp, sets);
  report_cost(ctx, sets, ns_at_h);
}
StudyPlan plan_cost(const Scene& s) {
  const double T = s.real("energies.t_end");
  const double M = static_cast<double>(s.texts("methods").size());
  const PlanRate& rate = plan_rate("cloud cost");
  double steps = 0, kept = 0;
  std::vector<TimedCall> calls;  // the timed runs: Phi^(4) of each method and Phi^(0) at each h, RK4 at each of its steps
  for (double h : s.reals("order_study.h")) {
    steps += (M + 1) * step_count_within(T, h), kept += 2 * (step_count_within(T, h) + 1);
    calls.insert(calls.end(), static_cast<std::size_t>(M) + 1, TimedCall{step_count_within(T, h), rate.ns_per_step});
  }
  for (double h : s.reals("cost.rk4_h")) {
    steps += step_count_within(T, h), kept += step_count_within(T, h) + 1;
    calls.push_back(TimedCall{step_count_within(T, h), rate.ns_per_step});
  }
  StudyPlan p = phi_plan(steps, kept * kPointBytes, rate, "the runs, then the timing protocol");
  p.time(s, calls);
  return p;
}

void check_cost(const Scene& s) {
  check_at_least_one_step(s, "energies.t_end", s.reals("order_study.h"), "max(order_study.h)");
  check_at_least_one_step(s, "energies.t_end", s.reals("cost.rk4_h"), "max(cost.rk4_h)");
  const auto ms = scene_discretizations(s);
  if (std::find(ms.begin(), ms.end(), *parse_discretization(method_info(s.text("cost.discretization")).label)) == ms.end())
    s.reject("cost.discretization", "must be one of the scene's methods (its Phi^(4) runs are reused)");
  check_first_conformal_step(s, "h", {s.real("h")});
  check_first_conformal_step(s, "order_study.h", s.reals("order_study.h"));
}

}  // namespace

// the cost runs take the steps of the order study to the end time of the energies
Study cost_study() {
  return {.name = "cost",
          .about = "work precision: Phi^(4) of each discretization, Phi^(0) and RK4; trajectory and energy errors",
          .files = {"cost_trajectory.csv", "cost_energy.csv"},
          .keys = Schema()
                      .text("cost.discretization", discretization_choices(),
                            "the discrete Lagrangian (5.1) of Phi^(4) and Phi^(0) in the comparison with RK4")
                      .reals("cost.rk4_h", positive(), 3,
                             "steps of the classical RK4 on (3.8), the baseline that preserves neither")
                      .real("cost.target_err", positive(), "trajectory error at which the cost to reach it is reported")
                      .real("cost.target_energy_err", positive(),
                            "energy error max |H - H0| at which the cost to reach it is reported"),
          .reads = {"potential", "cloud.center", "h", "methods", "energies.t_end", "order_study.h", "timing.repeats",
                    "reference"},
          .run = run_cost,
          .validate = check_cost,
          .plan = plan_cost};
}

}  // namespace geomint::measure_cloud
