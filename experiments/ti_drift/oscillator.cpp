// 004 Fig. 1: the methods of oscillator.methods (Stormer-Verlet, Takahashi-Imada (1.4), the simplified
// method (1.6), Forest-Ruth, processed where they have processing) on the harmonic oscillator, omega = 1,
// start q = 0, p = 1, at equal work: the largest global and energy errors over t <= t_omega / omega, their
// fitted orders, the closed forms of Sect. 1.4, and TI's stability bound 2 sqrt(3) by bisection.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::ti_drift {
namespace {

using Z1 = PhaseState<1>;
const HarmonicOscillator kOscillator{1.0, 1.0};  // Fig. 1: omega = 1

constexpr double kFitMaxOmegaH = 0.5;  // Fig. 1: the orders are fitted over omega h_eff <= 0.5

// Equal work: per unit time a method of e evaluations per step at h = h_eff e / 2
// does as many evaluations as Takahashi-Imada (2 per step) at h = h_eff.
double step_at_equal_work(double h_eff, std::int64_t evals) { return h_eff * static_cast<double>(evals) / 2; }

void check_oscillator(const Scene& s) {
  MethodsOn<Counting<HarmonicOscillator>>::check(s, "oscillator.methods", {kOscillator, nullptr});
  const auto omega_h = s.reals("oscillator.omega_h");
  std::vector<int> runs(omega_h.size(), 0);
  for (const auto& m : s.texts("oscillator.methods")) {
    const std::int64_t evals = evals_per_step(m);
    const double bound = method_info(m).oscillatory_bound;
    if (bound == 0.0) s.reject("oscillator.methods", m + " is unstable on the oscillator for every h > 0");
    int fit_points = 0;
    for (std::size_t i = 0; i < omega_h.size(); ++i) {
      if (beyond_bound(kOscillator.w * step_at_equal_work(omega_h[i], evals), bound)) continue;
      ++runs[i];
      fit_points += omega_h[i] <= kFitMaxOmegaH;
    }
    if (fit_points < 3)
      s.reject("oscillator.omega_h", "at least 3 values <= " + format_double(kFitMaxOmegaH) + " within the bound of " +
                                         m + " (its orders are fitted there)");
  }
  for (std::size_t i = 0; i < omega_h.size(); ++i)
    if (runs[i] == 0)
      s.reject("oscillator.omega_h", format_double(omega_h[i]) + " is beyond the stability bound of every named method");
}

// The closed form of Sect. 1.4 of a method at its own w h (start q_0 = 0), or NaN if it has none here.
double closed_form(const std::string& method, double wh) {
  const std::string name(method_info(method).name);
  if (name == "stormer_verlet") return sv_oscillator_max_rel_energy_error(wh);
  if (name == "takahashi_imada" || name == "simplified_takahashi_imada")
    return wh < method_info(name).oscillatory_bound ? ti_oscillator_max_rel_energy_error(wh) : std::nan("");
  return std::nan("");
}

// The largest sampled errors of a method's run at w h from z0 over t <= t_omega / w (processed where it has
// processing): the scaled global error against the exact solution and the relative error of H.
std::pair<double, double> oscillator_errors(const std::string& method, const Z1& z0, double h, double t_omega) {
  const HarmonicOscillator& osc = kOscillator;
  double gm = 0, em = 0;
  MethodsOn<HarmonicOscillator>::integrate(method, osc, z0, h, steps_within(t_omega, h),
                                           [&](std::int64_t j, const Z1& z) {
    const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
    gm = std::max(gm, std::hypot(z.p[0] - ex.p[0], z.q[0] - ex.q[0]));  // (|e_p|^2 + w^2 |e_q|^2)^(1/2)
    em = std::max(em, std::abs(osc.H(z) - osc.H(z0)) / osc.H(z0));
  });
  return std::pair{gm, em};
}

// The exponent of the growth of max_{m <= n} |z_m| with n along Stormer-Verlet on its stability bound
// w h = 2 (from q = 0, p = 1, over n <= t_omega / w steps, fitted over n >= n_max / 10): 0 for a bounded
// solution, 1 for the linear growth of the double root -1 of q_{n+1} + 2 q_n + q_{n-1} = 0 (004 Sect. 1.4).
double sv_growth_exponent_at_bound(double t_omega) {
  const double h = method_info("stormer_verlet").oscillatory_bound / kOscillator.w;
  const std::int64_t n = steps_within(t_omega, h);
  std::vector<double> steps, size;
  double largest = 0;
  MethodsOn<HarmonicOscillator>::integrate("stormer_verlet", kOscillator, make_state(0.0, 1.0), h, n,
                                           [&](std::int64_t j, const Z1& z) {
    largest = std::max(largest, std::hypot(z.p[0], kOscillator.w * z.q[0]));
    if (j > 0) steps.push_back(static_cast<double>(j)), size.push_back(largest);
  }, Bind::kernel);
  return power_law_exponent(steps, size, static_cast<double>(n) / 10);
}

constexpr double kClosedFormSplit = 1.0;  // the closed forms are compared apart below and above omega h_eff = 1
constexpr double kExampleOmegaH = 0.1;    // the report's example: the values at the omega h_eff nearest this
constexpr double kBisectionLo = 3.0, kBisectionHi = 3.9, kRadiusTolerance = 1e-12;  // TI's bound, bisected

// One run of a method: its effective step omega h_eff and largest errors (global, relative in H).
struct Pt {
  double h, g, e;
};
struct Method {
  std::string name, label;
  std::int64_t evals;
  double bound;
  std::vector<Pt> pts;
};

// Each method of oscillator.methods at each oscillator.omega_h within its bound, at equal work.
std::vector<Method> integrate_methods(const Scene& s, const Z1& z0, double T1) {
  std::vector<Method> methods;
  for (const auto& m : s.texts("oscillator.methods"))
    methods.push_back({m, label_of(m), evals_per_step(m), method_info(m).oscillatory_bound, {}});
  for (double wh : s.reals("oscillator.omega_h")) {
    for (auto& m : methods) {
      const double h = step_at_equal_work(wh, m.evals);
      if (beyond_bound(kOscillator.w * h, m.bound)) continue;  // (TI at h = h_eff: omega h_eff < 2 sqrt(3))
      const auto [g, e] = oscillator_errors(m.name, z0, h, T1);
      m.pts.push_back({wh, g, e});
    }
  }
  return methods;
}

// The closed forms of Sect. 1.4 (start q0 = 0), over omega h_eff up to SV's bound (it runs at h = h_eff/2);
// TI's is nan beyond its own bound 2 sqrt(3), where ti_beyond_bound = 1. Columns <label>_rel_H, their methods
// in the same order in summary methods.oscillator_closed_forms.
void write_closed_forms(Context& ctx) {
  const double sv_eff_bound = 2 * method_info("stormer_verlet").oscillatory_bound;
  const std::string sv = label_of("stormer_verlet"), ti = label_of("takahashi_imada");
  Csv cf({"omega_h", sv + "_rel_H", ti + "_rel_H", ti + "_beyond_bound"});
  cf.flags({ti + "_beyond_bound"});
  for (int i = 1; i <= 400; ++i) {
    const double y = sv_eff_bound * i / 401.0;
    const bool beyond = !(y < method_info("takahashi_imada").oscillatory_bound);
    cf.row(y, closed_form("stormer_verlet", y / 2), closed_form("takahashi_imada", y), static_cast<std::int64_t>(beyond));
  }
  ctx.write("oscillator_closed_forms.csv", cf);
  ctx.summary["methods"]["oscillator_closed_forms"] = labels_of({"stormer_verlet", "takahashi_imada"});
}

// The run of a method at omega h_eff = wh, or nullptr where it is beyond its bound (not run).
const Pt* run_at(const Method& m, double wh) {
  const auto p = std::find_if(m.pts.begin(), m.pts.end(), [&](const Pt& q) { return q.h == wh; });
  return p == m.pts.end() ? nullptr : &*p;
}

// Record: oscillator.csv (h = omega h_eff; per method <label>_solution, <label>_energy: the largest global and
// relative energy errors, NaN where <label>_beyond_bound), the orders fitted over omega h_eff <= 0.5 above
// round-off (orders.csv, summary orders), the equal work (summary equal_work); returns the summary of the study begun.
Value fit_orders(Context& ctx, const std::vector<Method>& methods, const Z1& z0, double T1) {
  const auto omega_h = ctx.scene.reals("oscillator.omega_h");
  // steps: the count of the Takahashi-Imada methods (h = h_eff, 2 evaluations per step), whose step is the
  // axis's; every method runs over the same t <= t_omega / omega, at its own h = h_eff e/2.
  std::vector<double> steps;
  for (double wh : omega_h) steps.push_back(static_cast<double>(steps_within(T1, step_at_equal_work(wh, 2))));
  ConvergenceStudy conv({.csv = "oscillator.csv", .h = omega_h, .steps = steps});
  const OrderFitRule rule{.floor = [](std::size_t) { return roundoff_floor(); }, .h_max = kFitMaxOmegaH};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& m : methods) {
    conv.column(m.label + "_solution", [&](std::size_t, std::size_t j) { const Pt* p = run_at(m, omega_h[j]); return p ? p->g : nan; })
        .column(m.label + "_energy", [&](std::size_t, std::size_t j) { const Pt* p = run_at(m, omega_h[j]); return p ? p->e : nan; })
        .flag(m.label + "_beyond_bound", [&](std::size_t, std::size_t j) { return run_at(m, omega_h[j]) == nullptr; })
        .fit(m.label + "_solution", m.label + "_solution", rule)
        .fit(m.label + "_energy", m.label + "_energy", rule);
  }
  conv.write(ctx);

  Value evals, eff_bound, labels = Value::list(), points, fit_points, roundoff, largest, bounds;
  for (const auto& m : methods) {
    for (const std::string& name : {m.label + "_solution", m.label + "_energy"}) {
      const OrderFit& fit = conv.order(name);
      const auto& err = conv.values(name);
      fit_points[name] = fit.points;
      for (std::size_t j = 0; j < omega_h.size(); ++j)  // the largest step whose error is at the round-off plateau
        if (omega_h[j] <= kFitMaxOmegaH && std::isfinite(err[j]) && !fit.used[j] &&
            (!roundoff.contains(name) || omega_h[j] > roundoff.at(name).number()))
          roundoff[name] = omega_h[j];
    }
    evals[m.label] = m.evals;
    eff_bound[m.label] = m.bound * 2 / static_cast<double>(m.evals);  // in omega h_eff
    labels.push_back(m.label);
    points[m.label] = m.pts.size();
    bounds[m.label] = m.bound;
    const Pt& last = *std::max_element(m.pts.begin(), m.pts.end(), [](const Pt& a, const Pt& b) { return a.h < b.h; });
    largest[m.label] = {{"omega_h", last.h}, {"max_global_err", last.g}, {"max_rel_H_err", last.e}};
  }
  ctx.summary["equal_work"] = {{"evals_per_step", evals}, {"omega_h_eff_bound", eff_bound}, {"methods", labels}};

  Value o = {{"omega", kOscillator.w},
             {"start", {{"q", z0.q[0]}, {"p", z0.p[0]}}},
             {"omega_h_bound", bounds},  // each method's own bound in omega h (the registry's)
             {"omega_h_eff", range_of(omega_h)},
             {"points", points},
             {"fit", {{"max_omega_h", kFitMaxOmegaH}, {"floor", roundoff_floor()}, {"points", fit_points}}},
             {"roundoff_omega_h", roundoff},
             {"largest_step", largest}};
  o["omega_h_eff"]["count"] = omega_h.size();
  return o;
}

// The sampled maxima against the closed forms (each method at its own step w h = w h_eff e / 2).
void compare_closed_forms(Value& o, const std::vector<Method>& methods) {
  Value closed;
  for (const auto& m : methods) {
    double deviation = 0, ratio = std::numeric_limits<double>::infinity(), at = 0;
    for (const auto& p : m.pts) {
      const double c = closed_form(m.name, step_at_equal_work(p.h, m.evals));
      if (!(c > 0)) continue;
      if (p.h <= kClosedFormSplit && p.e > roundoff_floor()) deviation = std::max(deviation, std::abs(p.e / c - 1));
      if (p.h > kClosedFormSplit && p.e / c < ratio) ratio = p.e / c, at = p.h;
    }
    if (std::isfinite(ratio))
      closed[m.label] = {{"max_deviation_below", deviation}, {"min_ratio_above", ratio}, {"min_ratio_above_at", at}};
  }
  o["closed_form"] = closed;
  o["closed_form"]["split_omega_h"] = kClosedFormSplit;
}

// The method of a label, or methods.end().
std::vector<Method>::const_iterator find_label(const std::vector<Method>& methods, const std::string& label) {
  return std::find_if(methods.begin(), methods.end(), [&](const Method& m) { return m.label == label; });
}

// TI against Stormer-Verlet at equal work, where both run; the report's example step.
void compare_ti_sv(Value& o, const std::vector<Method>& methods) {
  if (const auto sv = find_label(methods, "sv"), ti = find_label(methods, "ti"); sv != methods.end() && ti != methods.end()) {
    int common = 0, better_energy = 0, better_global = 0;
    for (const auto& a : ti->pts)
      for (const auto& b : sv->pts)
        if (a.h == b.h) ++common, better_energy += a.e < b.e, better_global += a.g < b.g;
    o["ti_against_sv"] = {{"common", common}, {"ti_better_energy", better_energy}, {"ti_better_global", better_global}};
    const auto near = std::min_element(sv->pts.begin(), sv->pts.end(), [](const Pt& a, const Pt& b) {
      return std::abs(a.h - kExampleOmegaH) < std::abs(b.h - kExampleOmegaH);
    });
    Value example = {{"omega_h", near->h}};
    for (const auto& m : methods)
      for (const auto& p : m.pts)
        if (p.h == near->h) example[m.label] = {{"max_global_err", p.g}, {"max_rel_H_err", p.e}};
    o["example"] = example;
  }
}

// The stability bound of TI: where the spectral radius of its one-step matrix (the kernel's) leaves 1.
void bisect_ti_bound(Context& ctx, Value& o) {
  const auto radius = [&](double wh) {
    return spectral_radius(one_step_matrix(one_step_by_name("takahashi_imada", kOscillator, Bind::kernel), wh));
  };
  const double lo =
      stability_boundary([&](double wh) { return radius(wh) <= 1 + kRadiusTolerance; }, kBisectionLo, kBisectionHi);
  merge(ctx.summary, "reproduced", {{"ti_stability_bound", lo}});
  const double ti_bound = method_info("takahashi_imada").oscillatory_bound;
  o["stability_bound"] = {{"bisection", {{"lo", kBisectionLo}, {"hi", kBisectionHi}, {"radius_tolerance", kRadiusTolerance}}},
                          {"minus_closed_form", lo - ti_bound},  // the registry's 2 sqrt(3)
                          {"spacing_of_doubles", std::nextafter(ti_bound, 4.0) - ti_bound}};
}

// 004 Sect. 1.4 as printed: SV "stable only for w h <= 2"; TI's error "remains bounded (converges to one)"
// as w h -> 2 sqrt(3), which holds for the start q0 = 0 only: from p0 = 0, at the largest w h_eff TI runs.
void sect14_as_printed(Value& o, const std::vector<Method>& methods, double T1) {
  o["sv_growth_exponent_at_bound"] = sv_growth_exponent_at_bound(T1);
  if (const auto ti = find_label(methods, "ti"); ti != methods.end()) {
    const double wh = o.at("largest_step").at("ti").at("omega_h").number();
    const Z1 rest = make_state(1.0, 0.0);
    o["from_rest"] = {{"start", {{"q", rest.q[0]}, {"p", rest.p[0]}}},
                      {"omega_h", wh},
                      {"max_rel_H_err", oscillator_errors(ti->name, rest, wh, T1).second},
                      {"closed_form", ti_oscillator_max_rel_energy_error_from_rest(wh)}};
  }
}

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 1: oscillator");
  const Z1 z0 = make_state(0.0, 1.0);
  const double T1 = s.real("oscillator.t_omega");
  const std::vector<Method> methods = integrate_methods(s, z0, T1);
  write_closed_forms(ctx);
  Value o = fit_orders(ctx, methods, z0, T1);
  compare_closed_forms(o, methods);
  compare_ti_sv(o, methods);
  bisect_ti_bound(ctx, o);
  sect14_as_printed(o, methods, T1);
  ctx.summary["oscillator"] = o;
  record_unfittable(ctx.summary, "oscillator.sv_growth_exponent_at_bound",
                    "the run of Stormer-Verlet on its bound is not written to a CSV (only its growth exponent is reported)");
}

StudyPlan plan_oscillator(const Scene& s) {
  const double T = s.real("oscillator.t_omega") / kOscillator.w;
  StudyPlan p;
  double largest_ti = 0;
  for (const auto& m : s.texts("oscillator.methods")) {
    const double e = static_cast<double>(evals_per_step(m));
    for (double wh : s.reals("oscillator.omega_h")) {
      const double h = step_at_equal_work(wh, evals_per_step(m));
      if (beyond_bound(kOscillator.w * h, method_info(m).oscillatory_bound)) continue;
      p.steps += T / h, p.force_evals += e * T / h;
      if (label_of(m) == "ti") largest_ti = std::max(largest_ti, wh);
    }
  }
  const double sv_steps = T * kOscillator.w / method_info("stormer_verlet").oscillatory_bound;
  p.steps += sv_steps + (largest_ti > 0 ? T / largest_ti : 0.0);
  p.force_evals += sv_steps + (largest_ti > 0 ? 2 * T / largest_ti : 0.0);
  p.memory_bytes = 16 * sv_steps + 1e5;  // the sampled growth of SV at its bound: 2 doubles per step
  const PlanRate& rate = plan_rate("oscillator splitting");
  p.ns_per_step = rate.ns_per_step, p.note = rate.note;
  return p;
}

}  // namespace

Study oscillator_study() {
  return {.name = "oscillator",
          .makes = {{"004", "Fig. 1"}},
          .about = "the harmonic oscillator at equal work: global and energy errors, their orders, the closed forms",
          .files = {"oscillator.csv", "orders.csv", "oscillator_closed_forms.csv"},
          .keys = Schema()
                      .reals("oscillator.omega_h", positive(), 3,
                             "effective steps omega h_eff of Fig. 1 (equal work: h = h_eff e/2 for e force evaluations "
                             "per step)")
                      .texts("oscillator.methods", MethodsOn<Counting<HarmonicOscillator>>::choices(), 1,
                             "methods of Fig. 1, processed where they have processing (registry names or labels)")
                      .real("oscillator.t_omega", positive(), "errors are maxima over t <= t_omega / omega (004: 50)"),
          .run = run_oscillator,
          .validate = check_oscillator,
          .plan = plan_oscillator};
}

}  // namespace geomint::ti_drift
