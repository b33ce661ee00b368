// The stability set beyond 001 eq. (10): the spectral radius of the Lobatto one-step matrix (13)
// (and of each compared method's) over a scan of h omega, the first loss of stability refined by
// bisection, runs of long_run.periods periods just below and just above that bound, and the exact
// stable set of (13)-(14).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

// A scan point of the stability study is stable if the spectral radius is at most 1 + this.
constexpr double kRadiusTolerance = 1e-12;
// A run at the stability bound counts as diverged when |(p, q)| exceeds this many times q(0).
constexpr double kDivergedFactor = 1e6;
// The runs around the first loss of stability: these multiples of the bound.
constexpr double kBoundFactors[] = {0.99, 1.01};

void check_stability(const Scene& s) {
  check_distinct_methods(s, "stability.methods");
  if (!(s.real("stability.hw_max") > s.real("stability.hw_min"))) s.reject("stability.hw_max", "must exceed stability.hw_min");
}

bool stable(double rho) { return rho <= 1.0 + kRadiusTolerance; }

// The scanned stable set: the intervals [lo, hi] of h omega (analysis/linear_stability.hpp), as [[lo, hi], ...].
Value stable_set_of(const std::vector<double>& hw, const std::vector<double>& rho) {
  Value set = Value::list();
  for (const StableInterval& i : stable_intervals(hw, rho, kRadiusTolerance)) set.push_back(std::vector<double>{i.lo, i.hi});
  return set;
}

// Runs of long_run.periods periods at kBoundFactors times the bound `lo`: by factor, and as a list.
std::pair<Value, Value> bound_runs(const Scene& s, const OscillatorFromRest& o, double lo) {
  const auto& [osc, A, T, z0] = o;
  Value runs, run_list = Value::list();
  for (double factor : kBoundFactors) {
    const double h = factor * lo / osc.w;
    const Mat<2> Phi = one_step_pq_matrix("lobatto", osc, h);
    Vec<2> x(0.0, A);
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / h);
    std::int64_t diverged_at = -1;
    double max_norm = 0;
    for (std::int64_t j = 1; j <= n && diverged_at < 0; ++j) {
      x = Phi * x;
      max_norm = std::max(max_norm, x.norm());
      if (!(x.norm() <= kDivergedFactor * A)) diverged_at = j;
    }
    const Value run = {{"h_omega", factor * lo}, {"steps", n}, {"diverged_at_step", diverged_at},
                       {"max_norm_over_initial", max_norm / A}};
    runs[format_double(factor)] = run;
    Value r = {{"factor", factor}};  // the factor, then the run's members
    for (std::size_t i = 0; i < run.size(); ++i) r[run.keys()[i]] = run.at(i);
    run_list.push_back(r);
  }
  return {runs, run_list};
}

void run_stability(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("stability scan");
  const OscillatorFromRest o = oscillator_from_rest(s);
  const HarmonicOscillator& osc = o.osc;
  const double hw0 = s.real("stability.hw_min"), hw1 = s.real("stability.hw_max");
  const auto npts = s.integer("stability.points");
  const auto methods = s.texts("stability.methods");
  const auto radius_at = [&](double hw) { return spectral_radius(one_step_pq_matrix("lobatto", osc, hw / osc.w)); };
  std::vector<std::string> columns = {"h_omega", "spectral_radius"};
  for (const auto& m : methods) columns.push_back("spectral_radius_" + label_of(m));
  Csv st(columns);
  std::vector<double> hws, rhos;
  std::vector<std::vector<double>> rho_m(methods.size());
  for (std::int64_t i = 0; i < npts; ++i) {
    const double hw = hw0 + (hw1 - hw0) * static_cast<double>(i) / static_cast<double>(npts - 1);
    const double rho = radius_at(hw);
    st << hw << rho;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      rho_m[k].push_back(spectral_radius(one_step_pq_matrix(methods[k], osc, hw / osc.w)));
      st << rho_m[k].back();
    }
    st.end_row();
    hws.push_back(hw), rhos.push_back(rho);
  }
  ctx.write("stability.csv", st);
  // The first loss of stability, refined by bisection.
  double lo = hw0, hi = hw1;
  for (std::size_t i = 0; i < hws.size(); ++i) {
    if (!stable(rhos[i])) {
      hi = hws[i];
      break;
    }
    lo = hws[i];
  }
  lo = stability_boundary([&](double hw) { return stable(radius_at(hw)); }, lo, hi);
  // Runs of long_run.periods periods at kBoundFactors times the bound: bounded below it, diverged above.
  const auto [runs, run_list] = bound_runs(s, o, lo);
  const Value stable_set = stable_set_of(hws, rhos);
  ctx.summary["reproduced"]["stability_bound"] = lo;
  ctx.summary["reproduced"]["stable_set_h_omega"] = stable_set;
  ctx.summary["reproduced"]["bound_runs"] = runs;
  // The scan of each compared method; the exact stable set of (13)-(14); the bound as h/T and steps
  // per period; the scan point nearest h omega = pi (h = T/2, the paper's remark after (10)).
  Value compared = Value::record();
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const Value set = stable_set_of(hws, rho_m[k]);
    compared[label_of(methods[k])] = {{"stable_set_h_omega", set}, {"intervals", set.size()}};
  }
  Value exact_set = Value::list();  // as [[lo, hi], ...]
  for (const auto& [a, b] : lobatto_stable_set()) exact_set.push_back(std::vector<double>{a, b});
  std::size_t near_pi = 0;
  for (std::size_t i = 1; i < hws.size(); ++i)
    if (std::abs(hws[i] - std::numbers::pi) < std::abs(hws[near_pi] - std::numbers::pi)) near_pi = i;
  const double steps_per_period = 2 * std::numbers::pi / lo;  // N = T/h = 2 pi / (h omega)
  ctx.summary["methods"]["stability"] = labels_of(methods);
  ctx.summary["methods"]["stability_scheme"] = labels_of({"lobatto"});  // (the spectral_radius column's method)
  ctx.summary["stability"] = {
      {"grid_step", (hw1 - hw0) / static_cast<double>(npts - 1)},
      {"radius_tolerance", kRadiusTolerance},
      {"diverged_factor", kDivergedFactor},
      {"intervals", stable_set.size()},
      {"exact_set_h_omega", exact_set},
      {"compared", compared},
      {"bound_h_over_T", lo / (2 * std::numbers::pi)},
      {"bound_steps_per_period", steps_per_period},
      {"least_whole_steps_per_period", std::floor(steps_per_period) + 1},
      {"near_pi", {{"h_omega", hws[near_pi]}, {"spectral_radius", rhos[near_pi]}}},
      {"bound_runs", run_list}};
}

StudyPlan plan_stability(const Scene& s) {
  const double points = static_cast<double>(s.integer("stability.points"));
  const double methods = static_cast<double>(s.texts("stability.methods").size());
  const double periods = s.real("long_run.periods");
  double steps = points * (1 + methods);  // one one-step matrix per point and method
  for (double factor : kBoundFactors) steps += periods * 2 * std::numbers::pi / (factor * method_info("lobatto").oscillatory_bound);
  const PlanRate& rate = plan_rate("oscillator one-step matrix");
  return {steps, 0, points * (2 + methods) * (sizeof(double) + kCsvCellBytes), rate.ns_per_step,
          "runs at the bound iterate the one-step matrix (13); " + rate.note};
}

}  // namespace

Study stability_study() {
  return {.name = "stability",
          .about = "stability set beyond 001 eq. (10); runs at 0.99 and 1.01 of the bound",
          .files = {"stability.csv"},
          .keys = Schema()
                      .real("stability.hw_min", positive(), "scan of the spectral radius over h omega")
                      .real("stability.hw_max", positive(), "")
                      .integer("stability.points", at_least(2), "")
                      .texts("stability.methods", MethodsOn<HarmonicOscillator>::names(), 0,
                             "methods whose kernel's spectral radius is scanned with Lobatto's"),
          .reads = {"oscillator", "long_run.periods"},
          .run = run_stability,
          .validate = check_stability,
          .plan = plan_stability};
}

}  // namespace geomint::lobatto_table
