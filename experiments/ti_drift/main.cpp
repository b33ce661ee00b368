// ti_drift: 004 (On energy conservation of the simplified Takahashi-Imada
// method) Figs 1-6 -- the methods the scene names (Stormer-Verlet,
// Takahashi-Imada (1.4), the simplified method (1.6), Forest-Ruth) on the
// harmonic oscillator at equal work (Fig. 1), the drift of the shifted energy
// on the unsymmetric pendulum (Fig. 2), the modified energy E of (3.3) and
// (4.2) on Henon-Heiles k = 3 (Fig. 3) and its random walk over an ensemble
// for k = 5 (Fig. 4), Poincare cuts of one trajectory (Fig. 5), the
// Lennard-Jones cluster (Fig. 6: a step-size scan and the ensemble
// statistics), symplecticity against volume preservation, and the cost per step.
// One study per figure (or analysis); the scene's sections say which run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/growth_episodes.hpp"
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/orbit_average.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/published.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

using Z1 = PhaseState<1>;
using Z2 = PhaseState<2>;

constexpr double kFitMaxOmegaH = 0.5;  // Fig. 1: the orders are fitted over omega h_eff <= 0.5

double slope(const std::vector<double>& x, const std::vector<double>& y) { return linear_fit(x, y).slope; }

// Adds the entries of `values` to summary[section] (indexing the summary afresh for each).
void put(Context& ctx, const char* section, const json& values) {
  for (const auto& [k, v] : values.items()) ctx.summary[section][k] = v;
}

// {min, max} of a non-empty list.
json range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

// {min, max, mean} of a non-empty list.
json spread_of(const std::vector<double>& v) {
  json r = range_of(v);
  double sum = 0;
  for (double x : v) sum += x;
  r["mean"] = sum / static_cast<double>(v.size());
  return r;
}

// The entries of experiments/ti_drift/published.toml (read as the runner reads them): the report sets
// some reproduced values against the printed ones in ways the runner's comparisons do not (the signed
// difference of every comparison, standard scores, quantities derived from printed values).
const std::vector<Published>& published_entries() {
  static const std::vector<Published> entries =
      read_published(std::filesystem::path(GEOMINT_EXPERIMENT_DIR) / "published.toml");
  return entries;
}

const Published& published_entry(const std::string& key) {
  for (const Published& e : published_entries())
    if (e.key == key) return e;
  throw std::logic_error("published.toml has no entry " + key);
}

double published_value(const std::string& key) { return published_entry(key).value.get<double>(); }

// summary.difference_from_published.<key> = reproduced - published for every entry of the study with a
// number on both sides (the runner's comparisons give the difference relative where the comparison is
// relative, and none where the value is only reported).
void put_differences(Context& ctx, const std::string& study) {
  for (const Published& e : published_entries()) {
    const json* r = json_at(ctx.summary, e.summary);
    if (e.study == study && e.value.is_number() && r && r->is_number())
      ctx.summary["difference_from_published"][e.key] = r->get<double>() - e.value.get<double>();
  }
}


// Henon-Heiles start with q1 = 0 and p1 > 0 from H0 (004 Sect. 5).
template <class HH>
Z2 hh_start(const HH& hh, double q2, double p2, double H0) {
  const double p1 = std::sqrt(2 * (H0 - hh.U(Vec<2>(0.0, q2))) - p2 * p2);
  return make_state<2>(Vec<2>(0.0, q2), Vec<2>(p1, p2));
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Calls f with the Henon-Heiles system of Figs 4-5: exponent hh.k, coupling hh.coupling (compiled out if 0).
template <class F>
decltype(auto) with_ensemble_system(const Scene& s, F&& f) {
  return with_henon_heiles(static_cast<int>(s.integer("hh.k")), s.real("hh.coupling"), f);
}

// Start i of the Fig. 4 ensemble: (hh3.q2, hh3.p2) perturbed, each trajectory its own stream seeded by (seed, i).
template <class HH>
Z2 ensemble_start(const Scene& s, const HH& hhk, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("ensemble.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("ensemble.perturbation"), s.real("ensemble.perturbation"));
  const double dq = u(rng), dp = u(rng);
  return hh_start(hhk, s.real("hh3.q2") + dq, s.real("hh3.p2") + dp, s.real("hh.H0"));
}

// ---- Fig. 1: harmonic oscillator, omega = 1, start q = 0, p = 1, at equal work ----

const HarmonicOscillator kOscillator{1.0, 1.0};

// Force evaluations in one step of a method's kernel (a gradient, a force or a
// Hessian-vector product counts one: systems/counting.hpp).
std::int64_t evals_per_step(const std::string& method) {
  std::int64_t n = 0;
  const Counting<HarmonicOscillator> counted{kOscillator, &n};
  with_kernel(method, counted, [&](const auto& m) {
    const auto s = m.pre(make_state(1.0, 0.0), 0.1);
    n = 0;
    do_not_optimize(m.kernel(s, 0.1));
    return 0;
  });
  if (n < 1) throw std::logic_error(method + " evaluates no force in a step");
  return n;
}

// Equal work: per unit time a method of e evaluations per step at h = h_eff e / 2
// does as many evaluations as Takahashi-Imada (2 per step) at h = h_eff.
double step_at_equal_work(double h_eff, std::int64_t evals) { return h_eff * static_cast<double>(evals) / 2; }

void check_oscillator(const Scene& s) {
  check_methods(s, "oscillator.methods", Counting<HarmonicOscillator>{kOscillator, nullptr});
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
  return with_method(method, osc, [&](const auto& m) {
    double gm = 0, em = 0;
    integrate(m, z0, h, std::llround(std::floor(t_omega / h)), [&](std::int64_t j, const Z1& z) {
      const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
      gm = std::max(gm, std::hypot(z.p[0] - ex.p[0], z.q[0] - ex.q[0]));  // (|e_p|^2 + w^2 |e_q|^2)^(1/2)
      em = std::max(em, std::abs(osc.H(z) - osc.H(z0)) / osc.H(z0));
    });
    return std::pair{gm, em};
  });
}

// The exponent of the growth of max_{m <= n} |z_m| with n along Stormer-Verlet on its stability bound
// w h = 2 (from q = 0, p = 1, over n <= t_omega / w steps, fitted over n >= n_max / 10): 0 for a bounded
// solution, 1 for the linear growth of the double root -1 of q_{n+1} + 2 q_n + q_{n-1} = 0 (004 Sect. 1.4).
double sv_growth_exponent_at_bound(double t_omega) {
  const double h = method_info("stormer_verlet").oscillatory_bound / kOscillator.w;
  const std::int64_t n = std::llround(std::floor(t_omega / h));
  std::vector<double> steps, size;
  double largest = 0;
  with_kernel("stormer_verlet", kOscillator, [&](const auto& m) {
    integrate(m, make_state(0.0, 1.0), h, n, [&](std::int64_t j, const Z1& z) {
      largest = std::max(largest, std::hypot(z.p[0], kOscillator.w * z.q[0]));
      if (j > 0) steps.push_back(static_cast<double>(j)), size.push_back(largest);
    });
    return 0;
  });
  return power_law_exponent(steps, size, static_cast<double>(n) / 10);
}

constexpr double kClosedFormSplit = 1.0;  // the closed forms are compared apart below and above omega h_eff = 1
constexpr double kExampleOmegaH = 0.1;    // the report's example: the values at the omega h_eff nearest this
constexpr double kBisectionLo = 3.0, kBisectionHi = 3.9, kRadiusTolerance = 1e-12;  // TI's bound, bisected

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 1: oscillator");
  const Z1 z0 = make_state(0.0, 1.0);
  const double T1 = s.real("oscillator.t_omega");
  struct Pt {
    double h, g, e;
  };
  struct Method {
    std::string name, label;
    std::int64_t evals;
    double bound;
    std::vector<Pt> pts;
  };
  std::vector<Method> methods;
  for (const auto& m : s.texts("oscillator.methods"))
    methods.push_back({m, label_of(m), evals_per_step(m), method_info(m).oscillatory_bound, {}});

  Csv oc({"method", "omega_h", "h_eff", "max_global_err", "max_rel_H_err"});
  for (double wh : s.reals("oscillator.omega_h")) {
    for (auto& m : methods) {
      const double h = step_at_equal_work(wh, m.evals);
      if (beyond_bound(kOscillator.w * h, m.bound)) continue;  // (TI at h = h_eff: omega h_eff < 2 sqrt(3))
      const auto [g, e] = oscillator_errors(m.name, z0, h, T1);
      oc.row(m.label, wh, wh, g, e);
      m.pts.push_back({wh, g, e});
    }
  }
  ctx.write("oscillator.csv", oc);

  // The closed forms of Sect. 1.4 (start q0 = 0), over omega h_eff up to SV's bound (it runs at h = h_eff/2);
  // TI's is nan beyond its own bound 2 sqrt(3), where ti_beyond_bound = 1.
  const double sv_eff_bound = 2 * method_info("stormer_verlet").oscillatory_bound;
  Csv cf({"omega_h", "sv_rel_H", "ti_rel_H", "ti_beyond_bound"});
  for (int i = 1; i <= 400; ++i) {
    const double y = sv_eff_bound * i / 401.0;
    const bool beyond = !(y < method_info("takahashi_imada").oscillatory_bound);
    cf.row(y, closed_form("stormer_verlet", y / 2), closed_form("takahashi_imada", y), static_cast<std::int64_t>(beyond));
  }
  ctx.write("oscillator_closed_forms.csv", cf);

  json orders, evals, eff_bound, labels = json::array(), points, fit_points, roundoff, largest;
  for (const auto& m : methods) {
    for (const bool energy : {false, true}) {
      const std::string name = m.label + (energy ? "_energy" : "_solution");
      std::vector<double> h, e;
      for (const auto& p : m.pts)
        if (p.h <= kFitMaxOmegaH) h.push_back(p.h), e.push_back(energy ? p.e : p.g);
      const OrderFit fit = fit_order(h, e, roundoff_floor(), name.c_str());
      orders[name] = fit.order;
      fit_points[name] = fit.points;
      for (std::size_t i = 0; i < h.size(); ++i)  // the largest step whose error is at the round-off plateau
        if (!fit.used[i] && (!roundoff.contains(name) || h[i] > roundoff[name].get<double>())) roundoff[name] = h[i];
    }
    evals[m.label] = m.evals;
    eff_bound[m.label] = m.bound * 2 / static_cast<double>(m.evals);  // in omega h_eff
    labels.push_back(m.label);
    points[m.label] = m.pts.size();
    const Pt& last = *std::max_element(m.pts.begin(), m.pts.end(), [](const Pt& a, const Pt& b) { return a.h < b.h; });
    largest[m.label] = {{"omega_h", last.h}, {"max_global_err", last.g}, {"max_rel_H_err", last.e}};
  }
  put(ctx, "orders", orders);
  ctx.summary["equal_work"] = {{"evals_per_step", evals}, {"omega_h_eff_bound", eff_bound}, {"methods", labels}};

  const auto omega_h = s.reals("oscillator.omega_h");
  json bounds;
  for (const auto& m : methods) bounds[m.label] = m.bound;
  json o = {{"omega", kOscillator.w},
            {"start", {{"q", z0.q[0]}, {"p", z0.p[0]}}},
            {"omega_h_bound", bounds},  // each method's own bound in omega h (the registry's)
            {"omega_h_eff", range_of(omega_h)},
            {"points", points},
            {"fit", {{"max_omega_h", kFitMaxOmegaH}, {"floor", roundoff_floor()}, {"points", fit_points}}},
            {"roundoff_omega_h", roundoff},
            {"largest_step", largest}};
  o["omega_h_eff"]["count"] = omega_h.size();

  // The sampled maxima against the closed forms (each method at its own step w h = w h_eff e / 2).
  json closed;
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

  // TI against Stormer-Verlet at equal work, where both run; the report's example step.
  const auto of = [&](const std::string& label) {
    return std::find_if(methods.begin(), methods.end(), [&](const Method& m) { return m.label == label; });
  };
  if (const auto sv = of("sv"), ti = of("ti"); sv != methods.end() && ti != methods.end()) {
    int common = 0, better_energy = 0, better_global = 0;
    for (const auto& a : ti->pts)
      for (const auto& b : sv->pts)
        if (a.h == b.h) ++common, better_energy += a.e < b.e, better_global += a.g < b.g;
    o["ti_against_sv"] = {{"common", common}, {"ti_better_energy", better_energy}, {"ti_better_global", better_global}};
    const auto near = std::min_element(sv->pts.begin(), sv->pts.end(), [](const Pt& a, const Pt& b) {
      return std::abs(a.h - kExampleOmegaH) < std::abs(b.h - kExampleOmegaH);
    });
    json example = {{"omega_h", near->h}};
    for (const auto& m : methods)
      for (const auto& p : m.pts)
        if (p.h == near->h) example[m.label] = {{"max_global_err", p.g}, {"max_rel_H_err", p.e}};
    o["example"] = example;
  }

  // The stability bound of TI: where the spectral radius of its one-step matrix (the kernel's) leaves 1.
  const auto radius = [&](double wh) {
    return with_kernel("takahashi_imada", kOscillator, [&](const auto& m) { return spectral_radius(one_step_matrix(m, wh)); });
  };
  double lo = kBisectionLo, hi = kBisectionHi;
  for (int it = 0; it < 60; ++it) (radius(0.5 * (lo + hi)) <= 1 + kRadiusTolerance ? lo : hi) = 0.5 * (lo + hi);
  put(ctx, "reproduced", {{"ti_stability_bound", lo}});
  const double ti_bound = method_info("takahashi_imada").oscillatory_bound;
  o["stability_bound"] = {{"bisection", {{"lo", kBisectionLo}, {"hi", kBisectionHi}, {"radius_tolerance", kRadiusTolerance}}},
                          {"minus_closed_form", lo - ti_bound},  // the registry's 2 sqrt(3)
                          {"spacing_of_doubles", std::nextafter(ti_bound, 4.0) - ti_bound}};

  // 004 Sect. 1.4 as printed: SV "stable only for w h <= 2"; TI's error "remains bounded (converges to one)"
  // as w h -> 2 sqrt(3), which holds for the start q0 = 0 only: from p0 = 0, at the largest w h_eff TI runs.
  o["sv_growth_exponent_at_bound"] = sv_growth_exponent_at_bound(T1);
  if (const auto ti = of("ti"); ti != methods.end()) {
    const double wh = o["largest_step"]["ti"]["omega_h"];
    const Z1 rest = make_state(1.0, 0.0);
    o["from_rest"] = {{"start", {{"q", rest.q[0]}, {"p", rest.p[0]}}},
                      {"omega_h", wh},
                      {"max_rel_H_err", oscillator_errors(ti->name, rest, wh, T1).second},
                      {"closed_form", ti_oscillator_max_rel_energy_error_from_rest(wh)}};
  }
  ctx.summary["oscillator"] = o;
  put_differences(ctx, "oscillator");
}

// ---- Fig. 2: unsymmetric pendulum, the shifted energy H + h^2 H_3 along the simplified method ----

constexpr double kReferenceStep = 1e-3;       // Fig. 2: the exact orbit, RK4 at this step ...
constexpr std::int64_t kReferenceSteps = 2000000;  // ... over 2000 time units

void run_pendulum(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 2: unsymmetric pendulum");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const UnsymmetricPendulum up;
  const Z1 p0 = make_state(s.real("pendulum.q0"), s.real("pendulum.p0"));
  const std::int64_t n = steps_to(s.real("pendulum.t_end"), h), every = std::max<std::int64_t>(1, n / samples);
  const double E0 = shifted_energy(up, p0, h);
  Csv f2({"t", "shifted_energy_err", "H_err"});
  std::vector<double> ts, es, ts_all, es_all, Hs_all;
  // (4.3)'s rate averaged along the exact orbit (RK4 at step 1e-3 over 2000 time units).
  double predicted = 0;
  const Z1 ref_end = integrate(RungeKutta4::bind(up), p0, kReferenceStep, kReferenceSteps, [&](std::int64_t j, const Z1& z) {
    predicted += j > 0 ? simplified_ti_drift_rate(up, z, h) : 0.0;
  });
  integrate(simplified_ti_method(up, false), p0, h, n, [&](std::int64_t j, const Z1& z) {
    if (j % every) return;
    const double t = static_cast<double>(j) * h, e = shifted_energy(up, z, h) - E0;
    if (!std::isfinite(e))
      throw NumericalFailure("simplified_takahashi_imada: the shifted energy is not finite at step " +
                             std::to_string(j) + ", t = " + format_double(t));
    f2.row(t, e, up.H(z) - up.H(p0));
    ts_all.push_back(t), es_all.push_back(e), Hs_all.push_back(up.H(z) - up.H(p0));
    if (t <= s.real("pendulum.fit_t")) ts.push_back(t), es.push_back(e);
  });
  ctx.write("fig2_pendulum.csv", f2);
  const double rate = slope(ts, es), rate_predicted = predicted / static_cast<double>(kReferenceSteps);
  put(ctx, "reproduced",
      {{"unsym_pendulum_drift_rate", rate},                         // at the start's energy
       {"unsym_pendulum_drift_rate_whole", slope(ts_all, es_all)},  // over the whole span (the rate falls with H)
       {"unsym_pendulum_drift_rate_predicted", rate_predicted}});
  const double t_ref = kReferenceStep * static_cast<double>(kReferenceSteps);
  ctx.summary["pendulum"] = {
      {"H0", up.H(p0)},
      {"steps", n},
      {"sample_dt", static_cast<double>(every) * h},
      {"change", es_all.back()},               // of H + h^2 H_3 over the run
      {"H_drift_rate", slope(ts_all, Hs_all)},  // the slope of the error of H over the run
      {"peak_to_peak_about_trend", {{"shifted_energy", peak_to_peak_about_line(ts_all, es_all)},
                                    {"H", peak_to_peak_about_line(ts_all, Hs_all)}}},
      // the same about a least-squares quadratic, without the curvature of the drift (004 Fig. 2)
      {"peak_to_peak_about_quadratic", {{"shifted_energy", peak_to_peak_about_quadratic(ts_all, es_all)},
                                        {"H", peak_to_peak_about_quadratic(ts_all, Hs_all)}}},
      {"drift_rate_deviation", std::abs(rate - rate_predicted) / std::abs(rate_predicted)},
      {"U_max", UnsymmetricPendulum::U_max()},
      // the time the drift takes at the initial rate to bring H down to max U, where the pendulum stops turning over
      {"turnover_time", (up.H(p0) - UnsymmetricPendulum::U_max()) / std::abs(rate)},
      {"reference", {{"step", kReferenceStep},
                     {"t_end", t_ref},
                     {"periods", (ref_end.q[0] - p0.q[0]) / (2 * std::numbers::pi)}}}};  // turns of the rotating pendulum

  // The local drift over the whole run: the least-squares slope of H + h^2 H_3 in each of pendulum.slope_windows
  // consecutive windows, against (4.3) averaged over the rotating orbit of the window's mean energy H.
  const auto windows = static_cast<std::size_t>(s.integer("pendulum.slope_windows"));
  const auto rate_at = [&](double E) {
    return rotation_average(up, E, [&](double q, double p) { return simplified_ti_drift_rate(up, make_state(q, p), h); });
  };
  Csv ls({"t_start", "t_end", "t_mid", "H_mean", "local_slope", "predicted_slope", "rel_difference"});
  double worst = 0, worst_t = 0;
  const std::size_t per = ts_all.size() / windows;
  for (std::size_t w = 0; w < windows; ++w) {
    const std::size_t a = w * per, b = w + 1 == windows ? ts_all.size() : (w + 1) * per;
    const std::span<const double> tw(ts_all.data() + a, b - a), ew(es_all.data() + a, b - a);
    double H_mean = 0;
    for (std::size_t k = a; k < b; ++k) H_mean += up.H(p0) + Hs_all[k];
    H_mean /= static_cast<double>(b - a);
    const double local = linear_fit(tw, ew).slope, pred = rate_at(H_mean), rel = std::abs(local - pred) / std::abs(pred);
    ls.row(ts_all[a], ts_all[b - 1], 0.5 * (ts_all[a] + ts_all[b - 1]), H_mean, local, pred, rel);
    if (rel > worst) worst = rel, worst_t = 0.5 * (ts_all[a] + ts_all[b - 1]);
  }
  ctx.write("fig2_local_slope.csv", ls);
  ctx.summary["pendulum"]["local_slope"] = {
      {"windows", windows},
      {"window_length", ts_all[per] - ts_all[0]},
      {"max_rel_difference", worst},
      {"max_rel_difference_at", worst_t},
      // (4.3) over the orbit of the start's energy (quadrature) against its average along the RK4 orbit above
      {"predicted_at_start", rate_at(up.H(p0))},
      {"predicted_at_start_rel_difference", std::abs(rate_at(up.H(p0)) / rate_predicted - 1)}};
}

// ---- Fig. 3: Henon-Heiles k = 3, E along the simplified method: bounded, no drift ----

void run_hh3(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 3: Henon-Heiles k = 3");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const HenonHeiles hh{{}, 3};
  const Z2 start = hh_start(hh, s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"));
  const std::int64_t n = steps_to(s.real("hh3.t_end"), h), every = std::max<std::int64_t>(1, n / samples);
  const double E0 = simplified_ti_modified_energy(hh, start, h);
  Csv f3({"t", "E_err", "H_err"});
  std::vector<double> ts, es;
  double worst = 0, worst_H = 0;
  integrate(simplified_ti_method(hh, false), start, h, n, [&](std::int64_t j, const Z2& z) {
    if (j % every) return;
    const double t = static_cast<double>(j) * h, e = simplified_ti_modified_energy(hh, z, h) - E0;
    if (!std::isfinite(e))
      throw NumericalFailure("simplified_takahashi_imada: E is not finite at step " + std::to_string(j) +
                             ", t = " + format_double(t));
    f3.row(t, e, hh.H(z) - hh.H(start));
    ts.push_back(t), es.push_back(e), worst = std::max(worst, std::abs(e));
    worst_H = std::max(worst_H, std::abs(hh.H(z) - hh.H(start)));
  });
  ctx.write("fig3_hh3.csv", f3);
  const double drift = slope(ts, es);
  put(ctx, "reproduced", {{"hh3_drift_slope", drift}, {"hh3_max_E_err", worst}});
  const auto [e_lo, e_hi] = std::minmax_element(es.begin(), es.end());
  ctx.summary["hh3"] = {{"p1", start.p[0]},
                        {"steps", n},
                        {"sample_dt", static_cast<double>(every) * h},
                        {"E_err_peak_to_peak", *e_hi - *e_lo},
                        {"H_err_max", worst_H},
                        {"drift_over_run", drift * ts.back()},  // the fitted slope times the span
                        {"drift_over_run_share", std::abs(drift * ts.back()) / worst}};
  put_differences(ctx, "hh3");
}

// ---- Fig. 4: Henon-Heiles k, an ensemble: mean and standard deviation of the E error;
// Fig. 5: Poincare cuts of its trajectory with the largest error ----

// The column k of an ensemble's series, over the trajectories `which`.
std::vector<double> column(const std::vector<std::vector<double>>& series, const std::vector<std::size_t>& which,
                           std::size_t k) {
  std::vector<double> v;
  for (std::size_t i : which) v.push_back(series[i][k]);
  return v;
}

std::vector<std::size_t> all_of(std::size_t M) {
  std::vector<std::size_t> v(M);
  for (std::size_t i = 0; i < M; ++i) v[i] = i;
  return v;
}

constexpr std::size_t kPoincareWindows = 20;  // Fig. 5: the run of the trajectory is cut into this many windows
// The scene keys the ensemble's series depend on (its checkpoint).
const std::vector<std::string> kEnsembleKeys = {"h", "t_end", "samples", "hh", "ensemble.size", "ensemble.seed",
                                                "ensemble.perturbation", "hh3.q2", "hh3.p2"};

template <class HH>
void ensemble_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 4: ensemble");
  const double h = s.real("h"), t_end = s.real("t_end");
  const std::int64_t samples = s.integer("samples");
  const auto M = static_cast<std::size_t>(s.integer("ensemble.size"));
  const std::int64_t n4 = steps_to(t_end, h), every4 = std::max<std::int64_t>(1, n4 / samples);
  const auto time_of = [&](std::size_t k) { return static_cast<double>(k) * static_cast<double>(every4) * h; };
  std::vector<Z2> starts(M);
  for (std::size_t i = 0; i < M; ++i) starts[i] = ensemble_start(s, hhk, i);
  const auto t0 = std::chrono::steady_clock::now();  // (on --resume: the part run since)
  const auto lanes = simplified_ti_lanes_kernels<HH>().front().steps;  // (bit for bit the scalar method)
  const auto series = concatenate(checkpointed_map<std::vector<std::vector<double>>>(
      ctx, {"ensemble", kEnsembleKeys}, lane_batches(M), [&](std::size_t b) {
        const LaneBatch batch = lane_batch(b, M);
        std::vector<std::vector<double>> e(batch.count);
        std::vector<double> E0;
        for (std::size_t i = 0; i < batch.count; ++i) E0.push_back(simplified_ti_modified_energy(hhk, starts[batch.first + i], h));
        simplified_ti_lanes(hhk, lanes, std::span<const Z2>(starts).subspan(batch.first, batch.count), h, n4, every4,
                            [&](int i, std::int64_t, const Z2& z) { e[i].push_back(simplified_ti_modified_energy(hhk, z, h) - E0[i]); });
        return e;
      }));
  const double wall4 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < M; ++i)
    for (std::size_t k = 0; k < series[i].size(); ++k)
      if (!std::isfinite(series[i][k]))
        throw NumericalFailure("simplified_takahashi_imada: E of trajectory " + std::to_string(i) +
                               " is not finite at step " + std::to_string(static_cast<std::int64_t>(k) * every4) +
                               ", t = " + format_double(time_of(k)));
  const std::size_t ns = series[0].size();
  json reproduced;
  Csv f4s({"t", "mu", "sigma"});
  std::vector<double> ts, mus, sigmas;
  for (std::size_t k = 0; k < ns; ++k) {
    const auto [mu, sigma] = mean_and_deviation(column(series, all_of(M), k));
    f4s.row(time_of(k), mu, sigma);
    ts.push_back(time_of(k)), mus.push_back(mu), sigmas.push_back(sigma);
  }
  ctx.write("fig4_stats.csv", f4s);
  reproduced["hh5_mu_final"] = mus.back(), reproduced["hh5_sigma_final"] = sigmas.back();
  reproduced["hh5_sigma_exponent"] = power_law_exponent(ts, sigmas, t_end / 10);  // past the bounded part
  // Every trajectory's series (thinned to at most 200 times) and the outliers.
  Csv f4t({"trajectory", "outlier", "t", "E_err"});
  std::size_t worst_i = 0;
  double worst_e = 0;
  json outliers = json::array();
  std::vector<std::size_t> kept;
  const std::size_t stride = std::max<std::size_t>(1, ns / 200);
  for (std::size_t i = 0; i < M; ++i) {
    double mx = 0;
    for (double e : series[i]) mx = std::max(mx, std::abs(e));
    const bool out = mx > s.real("ensemble.outlier");
    if (out) outliers.push_back(i);
    else kept.push_back(i);
    if (mx > worst_e) worst_e = mx, worst_i = i;
    for (std::size_t k = 0; k < ns; k += stride)
      f4t.row(static_cast<std::int64_t>(i), static_cast<std::int64_t>(out), time_of(k), series[i][k]);
  }
  ctx.write("fig4_trajectories.csv", f4t);
  reproduced["hh5_outliers"] = outliers;

  // The statistics without the outliers, at the times of fig4_trajectories.csv.
  json ensemble = {{"p1", hh_start(hhk, s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0")).p[0]},  // unperturbed
                   {"steps", n4},
                   {"sample_dt", time_of(1)},
                   {"thinned_dt", time_of(stride)},
                   {"outliers", outliers.size()},
                   {"kept", kept.size()}};
  if (kept.size() >= 2) {
    std::vector<double> tk, sk;
    MeanDeviation last;
    for (std::size_t k = 0; k < ns; k += stride) {
      last = mean_and_deviation(column(series, kept, k));
      tk.push_back(time_of(k)), sk.push_back(last.sd);
    }
    ensemble["without_outliers"] = {{"mu_final", last.mean}, {"sigma_final", last.sd},
                                    {"sigma_exponent", power_law_exponent(tk, sk, t_end / 10)}};
  }
  // The mean: at the first output time after the start, and over [t_end/10, t_end].
  std::vector<double> mu_late, sigma2(sigmas.size());
  for (std::size_t k = 0; k < ns; ++k) {
    if (ts[k] >= t_end / 10) mu_late.push_back(mus[k]);
    sigma2[k] = sigmas[k] * sigmas[k];
  }
  ensemble["mu_first"] = {{"t", ts.at(1)}, {"mu", mus.at(1)}};
  ensemble["mu_late"] = spread_of(mu_late);
  ensemble["mu_final_stderr"] = standard_error_of_mean(sigmas.back(), static_cast<double>(M));
  ensemble["sigma_rel_stderr"] = standard_error_of_deviation(1.0, static_cast<double>(M));
  ensemble["sigma_exponent_from_hundredth"] = power_law_exponent(ts, sigmas, t_end / 100);
  // sigma^2 = c + D t of a random walk: D at t_end, and the slope of sigma^2 over [t_end/10, t_end].
  ensemble["sigma2_over_t"] = sigma2.back() / ts.back();
  ensemble["sigma2_slope"] = slope_from(ts, sigma2, t_end / 10);
  // The same from the printed sigma, at the printed time (published.toml: hh5_sigma_final).
  const Published& printed = published_entry("hh5_sigma_final");
  const double printed_sigma = printed.value.get<double>(), printed_t = printed.requires_.at("t_end").get<double>();
  ensemble["printed_sigma2_over_t"] = printed_sigma * printed_sigma / printed_t;
  ensemble["sigma2_over_t_minus_printed"] = ensemble["sigma2_over_t"].get<double>() - printed_sigma * printed_sigma / printed_t;
  // The printed sigma against ours carried to the printed time by the printed law sigma ~ t^gamma (published.toml:
  // hh5_sigma_exponent), in standard errors of ours (relative 1/sqrt(2(M-1))): a check that the quick scene can make.
  const double gamma_printed = published_value("hh5_sigma_exponent");
  const double carried = sigmas.back() * std::pow(printed_t / ts.back(), gamma_printed);
  ensemble["printed_sigma_check"] = {
      {"printed", printed_sigma},
      {"carried_to_printed_t", carried},
      {"exponent", gamma_printed},
      {"score", std::abs(carried - printed_sigma) / (carried * standard_error_of_deviation(1.0, static_cast<double>(M)))}};

  // Fig. 5: Poincare cuts (q1 = 0 upwards, p1 > 0) of the trajectory with the largest error,
  // on the window where its error grows fastest and on the one where it is flattest.
  ctx.progress("Fig. 5: Poincare cuts");
  const auto& e = series[worst_i];
  const std::size_t windows = kPoincareWindows, per = std::max<std::size_t>(2, ns / windows);
  std::size_t steep = 0, flat = 0, compared = 0;
  double smax = -1, smin = std::numeric_limits<double>::infinity();
  for (std::size_t w = 0; w < windows && (w + 1) * per <= ns; ++w, ++compared) {
    std::vector<double> x, y;
    for (std::size_t k = w * per; k < (w + 1) * per; ++k) x.push_back(static_cast<double>(k)), y.push_back(e[k]);
    const double sl_w = std::abs(slope(x, y));
    if (sl_w > smax) smax = sl_w, steep = w;
    if (sl_w < smin) smin = sl_w, flat = w;
  }
  const double tw = static_cast<double>(per) * static_cast<double>(every4) * h;
  Csv f5({"window", "t", "q2", "p2"});
  struct Cuts {
    std::size_t count = 0, negative = 0;
    double p2_sum = 0;
  };
  std::map<std::string, Cuts> cuts;
  // The growth episodes of its recorded error (analysis/growth_episodes.hpp; the scene's ensemble.episode_*).
  const double sample_dt = time_of(1);
  const auto half = static_cast<std::size_t>(std::max(1.0, std::round(s.real("ensemble.episode_half_width") / sample_dt)));
  const auto min_samples = static_cast<std::size_t>(std::max(1.0, std::round(s.real("ensemble.episode_min_length") / sample_dt)));
  std::vector<double> t_rec(ns);
  for (std::size_t k = 0; k < ns; ++k) t_rec[k] = time_of(k);
  const std::vector<double> run_slope = running_slope(t_rec, e, half);
  const SlopeNoise slope_sn = slope_noise(run_slope);
  const std::vector<Episode> episodes = growth_episodes(run_slope, s.real("ensemble.episode_threshold"), min_samples);
  std::vector<int> episode_of(ns, -1);  // the episode of the interval [t_k, t_{k+1}), or -1 (the complement)
  for (std::size_t i = 0; i < episodes.size(); ++i)
    for (std::size_t k = episodes[i].begin; k < episodes[i].end; ++k) episode_of[k] = static_cast<int>(i);
  Csv f5e({"t", "E_err", "running_slope", "episode", "sign"});
  for (std::size_t k = 0; k < ns; ++k)
    f5e.row(t_rec[k], e[k], run_slope[k], static_cast<std::int64_t>(episode_of[k]),
            static_cast<std::int64_t>(episode_of[k] >= 0 ? episodes[static_cast<std::size_t>(episode_of[k])].sign : 0));
  ctx.write("fig5_episodes.csv", f5e);
  // Per episode (the last entry: the complement): its cuts, and (4.3) integrated along the steps, h sum dE/dt.
  std::vector<Cuts> ep_cuts(episodes.size() + 1);
  std::vector<double> ep_predicted(episodes.size() + 1, 0.0);
  std::vector<std::int64_t> ep_steps(episodes.size() + 1, 0), ep_steps_negative(episodes.size() + 1, 0);
  Csv f5c({"episode", "sign", "t", "q2", "p2"});
  Z2 prev = starts[worst_i];
  integrate(simplified_ti_method(hhk, false), starts[worst_i], h, n4, [&](std::int64_t j, const Z2& z) {
    const double t = static_cast<double>(j) * h;
    const std::size_t k_prev = j > 0 ? static_cast<std::size_t>((j - 1) / every4) : 0;
    const int ep = k_prev < ns ? episode_of[k_prev] : -1;
    const std::size_t slot = ep >= 0 ? static_cast<std::size_t>(ep) : episodes.size();
    if (j > 0 && k_prev + 1 < ns) {
      ep_predicted[slot] += h * simplified_ti_drift_rate(hhk, prev, h);
      ++ep_steps[slot], ep_steps_negative[slot] += prev.p[1] < 0;
    }
    if (j > 0 && k_prev + 1 < ns && prev.q[0] < 0 && z.q[0] >= 0 && z.p[0] > 0) {
      const double a = -prev.q[0] / (z.q[0] - prev.q[0]);
      const double p2 = prev.p[1] + a * (z.p[1] - prev.p[1]);
      Cuts& c = ep_cuts[slot];
      ++c.count, c.negative += p2 < 0, c.p2_sum += p2;
      if (ep >= 0)
        f5c.row(static_cast<std::int64_t>(ep), static_cast<std::int64_t>(episodes[static_cast<std::size_t>(ep)].sign), t - (1 - a) * h,
                prev.q[1] + a * (z.q[1] - prev.q[1]), p2);
    }
    for (const auto& [label, w] : {std::pair{"growth", steep}, std::pair{"no_growth", flat}}) {
      if (j > 0 && t >= static_cast<double>(w) * tw && t < static_cast<double>(w + 1) * tw && prev.q[0] < 0 &&
          z.q[0] >= 0 && z.p[0] > 0) {
        const double a = -prev.q[0] / (z.q[0] - prev.q[0]);  // linear interpolation of the crossing
        const double p2 = prev.p[1] + a * (z.p[1] - prev.p[1]);
        f5.row(label, t - (1 - a) * h, prev.q[1] + a * (z.q[1] - prev.q[1]), p2);
        Cuts& c = cuts[label];
        ++c.count, c.negative += p2 < 0, c.p2_sum += p2;
      }
    }
    prev = z;
  });
  ctx.write("fig5_poincare.csv", f5);
  reproduced["poincare_trajectory"] = worst_i;
  reproduced["poincare_windows"] = {{"growth", {static_cast<double>(steep) * tw, static_cast<double>(steep + 1) * tw}},
                                    {"no_growth", {static_cast<double>(flat) * tw, static_cast<double>(flat + 1) * tw}}};
  put(ctx, "reproduced", reproduced);
  // Each window: its cuts, and the error of E of the trajectory at its ends (output times).
  json poincare = {{"windows", windows}, {"windows_compared", compared}};
  for (const auto& [label, w] : {std::pair{"growth", steep}, std::pair{"no_growth", flat}}) {
    const Cuts& c = cuts[label];
    const double E_lo = e[w * per], E_hi = e[(w + 1) * per < ns ? (w + 1) * per : ns - 1];
    poincare[label] = {{"t_start", static_cast<double>(w) * tw},
                       {"t_end", static_cast<double>(w + 1) * tw},
                       {"length", tw},
                       {"cuts", c.count},
                       {"cuts_per_time", static_cast<double>(c.count) / tw},
                       {"share_p2_negative", c.count ? static_cast<double>(c.negative) / static_cast<double>(c.count) : 0.0},
                       {"mean_p2", c.count ? c.p2_sum / static_cast<double>(c.count) : 0.0},
                       {"E_err_start", E_lo},
                       {"E_err_end", E_hi},
                       {"E_err_change", E_hi - E_lo},
                       {"E_err_slope", (E_hi - E_lo) / tw}};
    // The printed window (published.toml: poincare_<label>): its length and cuts per unit time.
    const json& printed_window = published_entry("poincare_" + std::string(label)).value;
    const double length = printed_window["t_end"].get<double>() - printed_window["t_start"].get<double>();
    poincare["printed"][label] = {{"length", length}, {"cuts_per_time", printed_window["cuts"].get<double>() / length}};
  }
  // The episodes against (4.3): dE/dt = -h^4/2880 U^(5)(p^5) = h^4/120 p2^5 for k = 5 (U_22222 = -24): E rises where
  // the time average of p2^5 over the episode is positive. The change (4.3) predicts, h sum_n dE/dt(p_n, q_n) over the
  // episode's steps, against the recorded change; and the share of the cuts, and of the steps, with p2 < 0.
  const auto share = [](const Cuts& c) { return c.count ? static_cast<double>(c.negative) / static_cast<double>(c.count) : 0.0; };
  const auto time_share = [&](std::size_t slot) {
    return ep_steps[slot] ? static_cast<double>(ep_steps_negative[slot]) / static_cast<double>(ep_steps[slot]) : 0.0;
  };
  double worst_rel = 0;
  int cut_sign_positive = 0;  // growths with a majority of cuts at p2 > 0 and declines with a majority at p2 < 0
  json eps = json::array();
  Cuts growth_all, decline_all;
  int agree = 0;
  double growth_time = 0;
  std::size_t longest = episodes.size();
  for (std::size_t i = 0; i < episodes.size(); ++i) {
    const Episode& ep = episodes[i];
    const std::size_t last = std::min(ep.end, ns - 1);
    const double ta = t_rec[ep.begin], tb = t_rec[last], change = e[last] - e[ep.begin];
    const Cuts& c = ep_cuts[i];
    (ep.sign > 0 ? growth_all : decline_all).count += c.count;
    (ep.sign > 0 ? growth_all : decline_all).negative += c.negative;
    const bool agrees = (ep_predicted[i] > 0) == (change > 0);
    agree += agrees;
    cut_sign_positive += c.count > 0 && (ep.sign > 0) == (share(c) < 0.5);
    worst_rel = std::max(worst_rel, std::abs(ep_predicted[i] / change - 1));
    if (ep.sign > 0) growth_time += tb - ta;
    if (ep.sign > 0 && (longest == episodes.size() || tb - ta > t_rec[std::min(episodes[longest].end, ns - 1)] -
                                                                    t_rec[episodes[longest].begin]))
      longest = i;
    eps.push_back({{"t_start", ta},
                   {"t_end", tb},
                   {"sign", ep.sign},
                   {"cuts", c.count},
                   {"share_p2_negative", share(c)},
                   {"mean_p2", c.count ? c.p2_sum / static_cast<double>(c.count) : 0.0},
                   {"share_time_p2_negative", time_share(i)},
                   {"E_err_change", change},
                   {"E_change_predicted", ep_predicted[i]},  // h sum of (4.3) over the episode's steps
                   {"predicted_over_recorded", ep_predicted[i] / change},
                   {"E_err_slope", change / (tb - ta)},
                   {"sign_agrees_with_43", agrees}});
  }
  const Cuts& rest = ep_cuts[episodes.size()];
  json ep_summary = {{"rule", {{"half_width", static_cast<double>(half) * sample_dt},
                               {"half_width_samples", half},
                               {"threshold", s.real("ensemble.episode_threshold")},
                               {"min_length", static_cast<double>(min_samples) * sample_dt},
                               {"slope_median", slope_sn.centre},
                               {"slope_noise", slope_sn.noise}}},
                     {"count", episodes.size()},
                     {"sign_agrees_with_43", agree},                 // episodes whose recorded change has the sign of (4.3)
                     {"max_rel_difference_from_43", worst_rel},       // max |predicted / recorded - 1| over the episodes
                     {"cut_majority_on_side_of_change", cut_sign_positive},
                     {"growth_time", growth_time},
                     {"list", eps},
                     {"growth", {{"cuts", growth_all.count}, {"share_p2_negative", share(growth_all)}}},
                     {"decline", {{"cuts", decline_all.count}, {"share_p2_negative", share(decline_all)}}},
                     {"complement", {{"cuts", rest.count}, {"share_p2_negative", share(rest)},
                                     {"share_time_p2_negative", time_share(episodes.size())},
                                     {"mean_p2", rest.count ? rest.p2_sum / static_cast<double>(rest.count) : 0.0},
                                     {"E_change_predicted", ep_predicted[episodes.size()]}}}};
  if (longest < episodes.size()) ep_summary["longest_growth"] = eps[longest];
  poincare["episodes"] = ep_summary;
  ctx.write("fig5_episode_cuts.csv", f5c);
  ctx.summary["ensemble"] = ensemble;
  ctx.summary["poincare"] = poincare;
  put(ctx, "timing",
      {{"fig4_wall_s", wall4},
       {"threads", ctx.threads},
       {"fig4_steps", static_cast<double>(M) * static_cast<double>(n4)},  // over the ensemble
       {"fig4_ns_per_step_thread",
        1e9 * wall4 * ctx.threads / (static_cast<double>(M) * static_cast<double>(n4))}});
  put_differences(ctx, "ensemble");
}

void run_ensemble(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { ensemble_with(ctx, hhk); });
}

// ---- Fig. 6: the Lennard-Jones cluster ----

using LJ = LennardJones<9>;
using Z18 = PhaseState<18>;

Vec<2> lj_grid(int k) { return Vec<2>(1 + k % 3, 1 + k / 3); }  // (i, j), i, j in {1, 2, 3}

// Start i of Fig. 6: the grid with each coordinate perturbed uniformly by at most lj.perturbation, p = 0, from the
// stream seeded by (lj.seed, i).
Z18 lj_start_of(const Scene& s, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("lj.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("lj.perturbation"), s.real("lj.perturbation"));
  Z18 z;
  for (int k = 0; k < 9; ++k) z.q[2 * k] = lj_grid(k)[0] + u(rng), z.q[2 * k + 1] = lj_grid(k)[1] + u(rng);
  return z;
}

constexpr std::size_t kLjShown = 50;          // Fig. 6: trajectories drawn (004: 50)
constexpr std::int64_t kStiffnessEvery = 10;   // Fig. 6: the stiffness along the scan starts, every this many steps of lj.h

void run_lj(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 6: Lennard-Jones cluster");
  const std::int64_t samples = s.integer("samples");
  const LJ lj;
  json reproduced;
  const auto grid = lj_grid;
  const auto lj_start = [&](std::size_t i) { return lj_start_of(s, i); };
  // The step-size scan: max |H - H0| over t <= lj.scan_t, diverged beyond lj.blowup or when not finite.
  const auto hs = s.reals("lj.h_scan");
  const auto scan_size = static_cast<std::size_t>(s.integer("lj.scan_size"));
  const auto scan = distributed_map(hs.size() * scan_size, [&](std::size_t task) {
    const double hh = hs[task / scan_size];
    const Z18 start = lj_start(task % scan_size);
    const double Hs = lj.H(start);
    double worst = 0;
    std::int64_t diverged = -1;
    integrate(simplified_ti_method(lj, false), start, hh, steps_to(s.real("lj.scan_t"), hh),
                        [&](std::int64_t j, const Z18& z) {
                          if (diverged >= 0) return;
                          const double e = std::abs(lj.H(z) - Hs);
                          if (!(e <= s.real("lj.blowup"))) diverged = j;
                          else worst = std::max(worst, e);
                        });
    return std::pair{worst, diverged};
  });
  // The stiffness omega_max^2 (largest eigenvalue of the Hessian): at the grid, at the starts of the
  // ensemble, and along the scan starts integrated at lj.h to lj.scan_t (its largest value on each).
  const double hl = s.real("lj.h");
  Vec<18> grid_q;
  for (int k = 0; k < 9; ++k) grid_q.segment<2>(2 * k) = grid(k);
  const double grid_stiffness = max_hessian_eigenvalue(lj, grid_q);
  const auto along = distributed_map(scan_size, [&](std::size_t i) {
    double largest = 0;
    integrate(simplified_ti_method(lj, false), lj_start(i), hl, steps_to(s.real("lj.scan_t"), hl),
              [&](std::int64_t j, const Z18& z) {
                if (j % kStiffnessEvery == 0) largest = std::max(largest, max_hessian_eigenvalue(lj, z.q));
              });
    return largest;
  });
  const auto [along_lo, along_hi] = std::minmax_element(along.begin(), along.end());
  Csv sc({"h", "trajectory", "max_H_err", "diverged", "diverge_step"});
  json stable_h = json::array(), scan_summary = json::array();
  std::vector<double> stable;
  for (std::size_t k = 0; k < hs.size(); ++k) {
    bool all_ok = true;
    std::vector<double> t_div, ok;
    for (std::size_t i = 0; i < scan_size; ++i) {
      const auto& [w, dv] = scan[k * scan_size + i];
      sc.row(hs[k], static_cast<std::int64_t>(i), w, static_cast<std::int64_t>(dv >= 0), dv);
      all_ok = all_ok && dv < 0;
      if (dv >= 0) t_div.push_back(static_cast<double>(dv) * hs[k]);
      else ok.push_back(w);
    }
    if (all_ok) stable_h.push_back(hs[k]), stable.push_back(hs[k]);
    json row = {{"h", hs[k]},
                {"runs", scan_size},
                {"diverged", t_div.size()},
                {"omega_max_h_at_grid", std::sqrt(grid_stiffness) * hs[k]},
                {"omega_max_h_along_starts", {{"min", std::sqrt(*along_lo) * hs[k]}, {"max", std::sqrt(*along_hi) * hs[k]}}}};
    if (!t_div.empty()) row["t_diverged"] = range_of(t_div);
    if (!ok.empty()) row["max_H_err"] = {{"median", median(ok)}, {"max", *std::max_element(ok.begin(), ok.end())}};
    scan_summary.push_back(row);
  }
  ctx.write("fig6_scan.csv", sc);
  reproduced["lj_stable_steps"] = stable_h;
  // The ensemble at lj.h: E error (3.3)+(4.2), H error, and H at the processed variables (1.5).
  const auto Ml = static_cast<std::size_t>(s.integer("lj.size"));
  const std::int64_t nl = steps_to(s.real("lj.t_end"), hl), every_l = std::max<std::int64_t>(1, nl / samples);
  const auto tl0 = std::chrono::steady_clock::now();  // (on --resume: the part run since)
  struct Series {
    std::vector<double> E, H, Hhat;
    auto fields() { return std::tie(E, H, Hhat); }
  };
  const std::vector<std::string> series_keys = {"samples", "lj.h", "lj.t_end", "lj.size", "lj.seed", "lj.perturbation"};
  const auto lanes = simplified_ti_lanes_kernels<LJ>().front().steps;  // (bit for bit the scalar method)
  const auto lj_series = concatenate(checkpointed_map<std::vector<Series>>(ctx, {"lj", series_keys}, lane_batches(Ml), [&](std::size_t b) {
    const LaneBatch batch = lane_batch(b, Ml);
    std::vector<Z18> starts;
    std::vector<double> E0, Hs;
    for (std::size_t i = batch.first; i < batch.first + batch.count; ++i)
      starts.push_back(lj_start(i)), E0.push_back(simplified_ti_modified_energy(lj, starts.back(), hl)), Hs.push_back(lj.H(starts.back()));
    std::vector<Series> r(batch.count);
    simplified_ti_lanes(lj, lanes, std::span<const Z18>(starts), hl, nl, every_l, [&](int i, std::int64_t, const Z18& z) {
      r[i].E.push_back(simplified_ti_modified_energy(lj, z, hl) - E0[i]);
      r[i].H.push_back(lj.H(z) - Hs[i]);
      r[i].Hhat.push_back(lj.H(ti_process(lj, z, hl, takahashi_imada_alpha)) - Hs[i]);
    });
    return r;
  }));
  const double wall6 = std::chrono::duration<double>(std::chrono::steady_clock::now() - tl0).count();
  for (std::size_t i = 0; i < Ml; ++i)  // diverged as the scan counts it (|H - H0| beyond lj.blowup), or not finite
    for (std::size_t k = 0; k < lj_series[i].E.size(); ++k)
      if (!std::isfinite(lj_series[i].E[k]) || !std::isfinite(lj_series[i].Hhat[k]) ||
          !(std::abs(lj_series[i].H[k]) <= s.real("lj.blowup")))
        throw NumericalFailure("simplified_takahashi_imada at lj.h = " + format_double(hl) + ": trajectory " +
                               std::to_string(i) + " diverged (|H - H0| = " + format_double(std::abs(lj_series[i].H[k])) +
                               " > lj.blowup) by step " + std::to_string(static_cast<std::int64_t>(k) * every_l) +
                               ", t = " + format_double(static_cast<double>(k) * static_cast<double>(every_l) * hl));
  Csv f6({"t", "mu", "sigma", "H_err_rms", "Hhat_err_rms", "Hhat_change_rms"});
  std::vector<double> ts, sigmas, H_rms, Hhat_rms, Hhat_change;
  const std::size_t nsl = lj_series[0].E.size();
  double mu_f = 0, sigma_f = 0, H_max = 0;
  for (std::size_t k = 0; k < nsl; ++k) {
    std::vector<double> E;
    double hr = 0, hhr = 0, hcr = 0;  // hcr: H(p^_n, q^_n) - H(p^_0, q^_0), what (1.5) makes random-walk
    for (const auto& r : lj_series) E.push_back(r.E[k]), hr += r.H[k] * r.H[k], hhr += r.Hhat[k] * r.Hhat[k];
    for (const auto& r : lj_series) hcr += (r.Hhat[k] - r.Hhat[0]) * (r.Hhat[k] - r.Hhat[0]);
    for (const auto& r : lj_series) H_max = std::max(H_max, std::abs(r.H[k]));
    const auto [mu, sigma] = mean_and_deviation(E);
    const double t = static_cast<double>(k) * static_cast<double>(every_l) * hl;
    const double H_rms_k = std::sqrt(hr / static_cast<double>(Ml)), Hhat_rms_k = std::sqrt(hhr / static_cast<double>(Ml));
    const double Hhat_change_k = std::sqrt(hcr / static_cast<double>(Ml));
    f6.row(t, mu, sigma, H_rms_k, Hhat_rms_k, Hhat_change_k);
    ts.push_back(t), sigmas.push_back(sigma), H_rms.push_back(H_rms_k), Hhat_rms.push_back(Hhat_rms_k);
    Hhat_change.push_back(Hhat_change_k);
    mu_f = mu, sigma_f = sigma;
  }
  ctx.write("fig6_stats.csv", f6);
  Csv f6t({"trajectory", "t", "E_err"});
  const std::size_t stride = std::max<std::size_t>(1, nsl / 200);
  for (std::size_t i = 0; i < std::min(Ml, kLjShown); ++i)
    for (std::size_t k = 0; k < nsl; k += stride)
      f6t.row(static_cast<std::int64_t>(i), static_cast<double>(k) * static_cast<double>(every_l) * hl, lj_series[i].E[k]);
  ctx.write("fig6_trajectories.csv", f6t);
  reproduced["lj_h"] = hl;
  reproduced["lj_mu_final"] = mu_f, reproduced["lj_sigma_final"] = sigma_f;
  const double mu_se = standard_error_of_mean(sigma_f, static_cast<double>(Ml));
  const double sigma_se = standard_error_of_deviation(sigma_f, static_cast<double>(Ml));
  reproduced["lj_mu_final_stderr"] = mu_se;
  reproduced["lj_sigma_final_stderr"] = sigma_se;
  reproduced["lj_sigma_exponent"] = power_law_exponent(ts, sigmas, s.real("lj.t_end") / 10);
  reproduced["lj_H_err_max"] = H_max;
  put(ctx, "reproduced", reproduced);

  // The ensemble's H errors after the start (t > 0): H at (p_n, q_n) and at the processed variables.
  std::vector<double> H_later(H_rms.begin() + 1, H_rms.end()), Hhat_later(Hhat_rms.begin() + 1, Hhat_rms.end());
  const json H_spread = spread_of(H_later), Hhat_spread = spread_of(Hhat_later);
  double Hhat_variation = 0;
  for (double b : Hhat_later) Hhat_variation = std::max(Hhat_variation, std::abs(b / Hhat_rms[0] - 1));
  std::vector<double> start_stiffness;
  for (std::size_t i = 0; i < Ml; ++i) start_stiffness.push_back(max_hessian_eigenvalue(lj, lj_start(i).q));
  ctx.summary["lj"] = {
      {"particles", LJ::D / 2},
      {"pairs", LJ::D / 2 * (LJ::D / 2 - 1) / 2},
      {"steps", nl},
      {"sample_dt", static_cast<double>(every_l) * hl},
      {"trajectories_shown", std::min(Ml, kLjShown)},
      {"scan", scan_summary},
      {"stable_step_count", stable.size()},
      {"stiffness", {{"grid", grid_stiffness},
                     {"starts", range_of(start_stiffness)},
                     {"along_scan_starts", {{"min", *along_lo}, {"max", *along_hi}}},
                     {"sample_dt", static_cast<double>(kStiffnessEvery) * hl}}},
      {"H_err_rms", H_spread},                       // over the output times t > 0
      {"Hhat_err_rms", Hhat_spread},
      {"Hhat_err_rms_start", Hhat_rms[0]},           // the offset H(chi_h(p_0, q_0)) - H_0
      {"Hhat_err_rms_variation", Hhat_variation},   // max |rms / its start - 1| over t > 0
      {"H_over_Hhat_err_rms", H_spread["mean"].get<double>() / Hhat_spread["mean"].get<double>()},
      // H(p^_n, q^_n) - H(p^_0, q^_0): its root mean square at t_end, against sigma of E, and its growth exponent
      {"Hhat_change_rms_final", Hhat_change.back()},
      {"Hhat_change_over_sigma_final", Hhat_change.back() / sigma_f},
      {"Hhat_change_exponent", power_law_exponent(ts, Hhat_change, s.real("lj.t_end") / 10)},
      // the published mean and standard deviation (published.toml) in standard errors of ours, and ours from zero
      {"standard_scores", {{"mu_from_printed", std::abs(mu_f - published_value("lj_mu_final")) / mu_se},
                           {"mu_from_zero", std::abs(mu_f) / mu_se},
                           {"sigma_from_printed", std::abs(sigma_f - published_value("lj_sigma_final")) / sigma_se}}}};
  if (!stable.empty()) ctx.summary["lj"]["stable_steps"] = range_of(stable);
  // the smallest step of the scan: the median of its largest errors of H
  const auto smallest = std::min_element(hs.begin(), hs.end()) - hs.begin();
  if (scan_summary[smallest].contains("max_H_err"))
    ctx.summary["lj"]["smallest_step"] = {{"h", hs[smallest]}, {"max_H_err_median", scan_summary[smallest]["max_H_err"]["median"]}};
  put(ctx, "timing",
      {{"fig6_wall_s", wall6},
       {"threads", ctx.threads},
       {"fig6_steps", static_cast<double>(Ml) * static_cast<double>(nl)},
       {"fig6_ns_per_step_thread", 1e9 * wall6 * ctx.threads / (static_cast<double>(Ml) * static_cast<double>(nl))}});
  put_differences(ctx, "lj");
}

// ---- Fig. 6, the printed step: sigma of the error of E against h (a small ensemble over a short span). The random
// walk of (4.3) gives sigma ~ h^4 t^(1/2); the fitted exponent in h, and the step at which the published sigma at the
// published time would be reached (carried there by the published t^(1/2)) ----

void run_lj_steps(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 6: sigma against h");
  const LJ lj;
  const auto hs = s.reals("lj_steps.h");
  const auto M = static_cast<std::size_t>(s.integer("lj_steps.size"));
  const double T = s.real("lj_steps.t_end");
  const auto lanes = simplified_ti_lanes_kernels<LJ>().front().steps;  // (bit for bit the scalar method)
  const std::size_t nb = lane_batches(M);  // per step h
  const auto err = concatenate(distributed_map(hs.size() * nb, [&](std::size_t task) {
    const double h = hs[task / nb];
    const LaneBatch batch = lane_batch(task % nb, M);
    std::vector<Z18> starts;
    for (std::size_t i = batch.first; i < batch.first + batch.count; ++i) starts.push_back(lj_start_of(s, i));
    const std::int64_t n = steps_to(T, h);
    const auto last = simplified_ti_lanes(lj, lanes, std::span<const Z18>(starts), h, n, n, [](int, std::int64_t, const Z18&) {});
    std::vector<double> e;
    for (std::size_t i = 0; i < batch.count; ++i)
      e.push_back(simplified_ti_modified_energy(lj, last[i], h) - simplified_ti_modified_energy(lj, starts[i], h));
    return e;
  }));
  for (std::size_t task = 0; task < err.size(); ++task)
    if (!std::isfinite(err[task]))
      throw NumericalFailure("simplified_takahashi_imada at h = " + format_double(hs[task / M]) +
                             ": E of trajectory " + std::to_string(task % M) + " is not finite at t = " + format_double(T));
  Csv out({"h", "mu", "sigma", "sigma_stderr"});
  std::vector<double> log_h, log_sigma;
  json per_h = json::array();
  for (std::size_t k = 0; k < hs.size(); ++k) {
    const MeanDeviation md = mean_and_deviation(std::span<const double>(err.data() + k * M, M));
    out.row(hs[k], md.mean, md.sd, standard_error_of_deviation(md.sd, static_cast<double>(M)));
    log_h.push_back(std::log(hs[k])), log_sigma.push_back(std::log(md.sd));
    per_h.push_back({{"h", hs[k]}, {"sigma", md.sd}, {"mu", md.mean}});
  }
  ctx.write("fig6_steps.csv", out);
  const LinearFit fit = linear_fit(log_h, log_sigma);
  // the standard error of the slope from the relative standard error 1/sqrt(2(M-1)) of each sigma (independent starts
  // per h are not assumed: the same starts are used at every h, so this is a scale, not a confidence bound)
  double sxx = 0, mean_log_h = 0;
  for (double x : log_h) mean_log_h += x / static_cast<double>(log_h.size());
  for (double x : log_h) sxx += (x - mean_log_h) * (x - mean_log_h);
  const double rel_se = standard_error_of_deviation(1.0, static_cast<double>(M));
  const double printed_sigma = published_value("lj_sigma_final"), printed_gamma = published_value("lj_sigma_exponent");
  const double printed_t = published_entry("lj_sigma_final").requires_.at("lj.t_end").get<double>();
  const double printed_h = published_value("lj_h");
  const double carry = std::pow(printed_t / T, printed_gamma);  // sigma(printed t) / sigma(T) of the random walk
  const double implied_h = std::exp((std::log(printed_sigma / carry) - fit.intercept) / fit.slope);
  ctx.summary["lj_steps"] = {
      {"t_end", T},
      {"size", M},
      {"sigma", per_h},
      {"exponent", fit.slope},
      {"exponent_stderr", rel_se / std::sqrt(sxx)},
      {"printed_sigma", printed_sigma},
      {"printed_t", printed_t},
      {"carry_to_printed_t", carry},
      {"implied_step", implied_h},  // the h at which the fit, carried to the printed t, gives the printed sigma
      {"implied_step_over_printed", implied_h / printed_h},
      {"sigma_at_printed_step", std::exp(fit.intercept + fit.slope * std::log(printed_h)) * carry}};
}

// ---- Cost: work-precision of the methods of work_precision.methods (processed where they have processing, as
// Fig. 1) on the harmonic oscillator of Fig. 1 (exact solution) and on Henon-Heiles k = 3 from the start of Fig. 3
// (odeint reference): the global error at work_precision.t_end against the wall time and the force evaluations ----

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
    with_method(method, counted, [&](const auto& m) { return integrate(m, z0, h, n); });
    const auto [err, rt] = with_method(method, sys, [&](const auto& m) {
      const RunTime t = time_runs(repeats, [&] { do_not_optimize(integrate_inlined(m, z0, h, n)); });
      return std::pair{error(integrate(m, z0, h, n)), t};
    });
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
  const auto or_null = [](std::optional<double> v) { return v ? json(*v) : json(nullptr); };
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

// ---- Symplecticity against volume preservation: the one-step Jacobian (central
// differences) of each named method's kernel on Henon-Heiles ----

HenonHeiles symplecticity_system(const Scene& s) { return {{}, static_cast<int>(s.integer("symplecticity.k"))}; }

// 004 Sect. 3.3 as printed: q_{n+1} of (1.6) = q_{n+1} of (1.4) + 1/4 h^6 alpha^2 f''(f, f)(q_{n+1/2}) + O(h^8),
// both from the same (p_n, q_n). The remainder after the printed term, one step at h / 2^j (j < 4) from z,
// with the term at q_{n+1/2} = (q_n + q_{n+1}) / 2 as printed, and at q_n.
json sect33_remainders(const HenonHeiles& hh, const Z2& z, double h) {
  std::vector<double> hs, at_mid, at_start;
  for (int j = 0; j < 4; ++j) {
    const double hj = h / std::pow(2.0, j);
    const Z2 ti = integrate(takahashi_imada_method(hh, false), z, hj, 1);
    const Z2 sti = integrate(simplified_ti_method(hh, false), z, hj, 1);
    const Vec<2> mid = (z.q + sti.q) / 2;
    hs.push_back(hj);
    at_mid.push_back((sti.q - ti.q - simplified_ti_q_correction(hh, mid, hj, takahashi_imada_alpha)).norm());
    at_start.push_back((sti.q - ti.q - simplified_ti_q_correction(hh, z.q, hj, takahashi_imada_alpha)).norm());
  }
  return {{"steps", range_of(hs)},
          {"order_at_midpoint", fit_order(hs, at_mid, 0.0, "Sect. 3.3 remainder").order},
          {"largest_at_q_n", *std::max_element(at_start.begin(), at_start.end())}};
}

void run_symplecticity(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("symplecticity");
  const HenonHeiles hh = symplecticity_system(s);
  const Z2 z = hh_start(hh, s.real("symplecticity.q2"), s.real("symplecticity.p2"), s.real("hh.H0"));
  const double h = s.real("h"), d = s.real("symplecticity.fd_step");
  json reproduced;
  for (const auto& m : s.texts("symplecticity.methods")) {
    const Mat<4> J = with_kernel(m, hh, [&](const auto& kernel) { return step_jacobian_fd(kernel, z, h, d); });
    reproduced[label_of(m) + "_symplecticity_defect"] = symplecticity_defect(J);
    reproduced[label_of(m) + "_det_minus_one"] = J.determinant() - 1.0;
  }
  put(ctx, "reproduced", reproduced);
  const json sect33 = sect33_remainders(hh, z, h);
  ctx.summary["sect33"] = sect33;
  ctx.summary["symplecticity"] = {{"p1", z.p[0]}};
}

// ---- Cost: ns per step of each named method's kernel (no processing, as Figs 2-6
// use them) on Henon-Heiles k, from the ensemble's first start ----

// The ensembles' lane kernels (sweep/ensemble_kernels.hpp) against the scalar method, simplified Takahashi-Imada
// unprocessed: ns per trajectory-step of the trajectories from `starts` (one batch), n steps, single thread.
template <class Sys>
json lanes_timing(const Sys& sys, const std::vector<typename Sys::State>& starts, double h, std::int64_t n, int repeats) {
  using Z = typename Sys::State;
  const double steps = static_cast<double>(starts.size()) * static_cast<double>(n);
  const auto method = simplified_ti_method(sys, false);
  const RunTime scalar = time_runs(repeats, [&] {
    for (const Z& z : starts) do_not_optimize(integrate_inlined(method, z, h, n));
  });
  json out = {{"trajectories", starts.size()}, {"steps", n}, {"scalar_ns_per_step", 1e9 * scalar.seconds() / steps},
              {"scalar_spread", scalar.spread()}};
  for (const auto& k : simplified_ti_lanes_kernels<Sys>()) {
    const RunTime t = time_runs(repeats, [&] {
      do_not_optimize(simplified_ti_lanes(sys, k.steps, std::span<const Z>(starts), h, n, n, [](int, std::int64_t, const Z&) {}));
    });
    out["kernels"][k.name] = {{"ns_per_step", 1e9 * t.seconds() / steps}, {"spread", t.spread()},
                              {"speedup_vs_scalar", scalar.seconds() / t.seconds()}};
    if (!out.contains("isa"))  // the one the ensembles use (the best)
      out["isa"] = k.name, out["ns_per_step"] = 1e9 * t.seconds() / steps, out["spread"] = t.spread(),
      out["speedup_vs_scalar"] = scalar.seconds() / t.seconds();
  }
  return out;
}

template <class HH>
void timing_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: ns per step");
  const Z2 z = ensemble_start(s, hhk, 0);
  const double h = s.real("h");
  const std::int64_t n = s.integer("timing.steps");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  json ns_per_step, runs, spread;
  for (const auto& m : s.texts("timing.methods")) {
    const RunTime t = with_kernel(m, hhk, [&](const auto& kernel) {
      return time_runs(repeats, [&] { do_not_optimize(integrate_inlined(kernel, z, h, n)); });
    });
    ns_per_step[label_of(m)] = 1e9 * t.seconds() / static_cast<double>(n);
    spread[label_of(m)] = t.spread();
    runs[label_of(m)] = to_json(t);
  }
  put(ctx, "timing",
      {{"ns_per_step", ns_per_step},
       {"spread", spread},  // (max - min) / min over the timed runs
       {"runs", runs},
       {"method", "minimum of " + std::to_string(repeats) + " timed runs (after a warm-up; each run repeats the " +
                      std::to_string(n) + " steps until it lasts at least 10 ms), single thread, every call inlined; "
                      "spread = (max - min) / min; fig4_wall_s, fig6_wall_s: the ensembles on --threads threads, one run"}});
  // The ensembles of Figs 4 and 6 in SIMD lanes against the scalar method: their first kEnsembleLanes starts.
  std::vector<Z2> hh_starts;
  std::vector<Z18> lj_starts;
  for (std::size_t i = 0; i < kEnsembleLanes; ++i) hh_starts.push_back(ensemble_start(s, hhk, i)), lj_starts.push_back(lj_start_of(s, i));
  put(ctx, "timing",
      {{"lanes", {{"fig4", lanes_timing(hhk, hh_starts, h, n, repeats)},
                  {"fig6", lanes_timing(LJ{}, lj_starts, s.real("lj.h"), s.integer("timing.lj_steps"), repeats)},
                  {"method", "ns per trajectory-step of " + std::to_string(kEnsembleLanes) + " trajectories (the first starts of "
                             "Figs 4 and 6), simplified Takahashi-Imada unprocessed: scalar, one trajectory after another "
                             "(integrate, every call inlined), against each lane kernel this CPU runs (all lanes at once, the "
                             "same bits); single thread, the timing method above"}}}});
  if (ns_per_step.contains("sv")) {  // per step, relative to Stormer-Verlet
    json relative;
    for (const auto& [label, ns] : ns_per_step.items()) relative[label] = double(ns) / double(ns_per_step["sv"]);
    put(ctx, "timing", {{"relative_to_sv", relative}});
  }
}

void run_timing(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { timing_with(ctx, hhk); });
}

// ---- Checks before any work, and what each study costs (--plan) ----

// The step of the simplified method (and of the timed kernels) below the oscillatory bound the registry declares,
// at the highest frequency omega of the motion linearised where the study runs (observables/stiffness.hpp).
void check_step_bound(const Scene& s, const char* step_key, double h, double omega, const std::string& where) {
  check_oscillatory_bound(s, step_key, step_key, "simplified_takahashi_imada", h * omega, where, "2 sqrt(3)");
}

// Fig. 2: the rotating pendulum passes every q, so omega^2 = max_q U''(q) (on a grid of 3600 angles).
double pendulum_omega() {
  const UnsymmetricPendulum up;
  double w2 = 0;
  for (int i = 0; i < 3600; ++i) w2 = std::max(w2, max_hessian_eigenvalue(up, Vec<1>(2 * std::numbers::pi * i / 3600)));
  return std::sqrt(w2);
}

// The escape energy of U = (q1^2 + q2^2)/2 + c q1^2 q2 - q2^k/k: the lowest of its saddles, on the axis
// (q1 = 0, |q2| = 1: U = 1/2 - 1/k) and, for c != 0, at q2 = -1/(2c), q1^2 = (q2^(k-1) - q2)/c where that is
// positive (1/6 for k = 3, c = 1, the triangle of 004 Fig. 3). Below it the motion from a start inside stays bounded.
template <class HH>
double hh_escape_energy(const HH& hh) {
  double e = 0.5 - 1.0 / hh.k;
  if (hh.c != 0.0) {
    const double q2 = -1 / (2 * hh.c), q1sq = (int_pow(q2, hh.k - 1) - q2) / hh.c;
    if (q1sq > 0) e = std::min(e, hh.U(Vec<2>(std::sqrt(q1sq), q2)));
  }
  return e;
}

// The Henon-Heiles starts q1 = 0, q2 in [q2 - d, q2 + d], p2 in [p2 - d, p2 + d] (d: the ensemble's
// perturbation, 0 for one start) lie in the bounded well below the escape energy: hh.H0 below it, every q2 between
// the saddles on the axis (q2 < 1, and q2 > -1 for even k: U(0, .) is monotone on either side of 0 there, so
// p1^2 = 2 (H0 - U(0, q2)) - p2^2 > 0 at the corners of the box holds on all of it), and the step h below the
// bound at the frequency of the linearisation at the start, max eig U''(0, q2) (a necessary condition).
template <class HH>
void check_hh_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h) {
  const double H0 = s.real("hh.H0"), q2 = s.real(section + ".q2"), p2 = s.real(section + ".p2");
  const double escape = hh_escape_energy(hh);
  if (!(H0 < escape))
    s.reject("hh.H0", "must be below the escape energy " + format_double(escape) + " of U (k = " + std::to_string(hh.k) +
                          ", c = " + format_double(hh.c) + ": its lowest saddle); here " + format_double(H0));
  // the unperturbed start is blamed on its keys, a perturbed one on ensemble.perturbation
  const auto inside = [&](double a) { return a < 1 && (hh.k % 2 == 1 || a > -1); };
  const auto exists = [&](double a, double b) { return 2 * (H0 - hh.U(Vec<2>(0.0, a))) - b * b > 0; };
  if (!inside(q2))
    s.reject(section + ".q2", "the start must lie between the saddles of U on q1 = 0 (q2 < 1" +
                                  std::string(hh.k % 2 ? "" : ", q2 > -1") + "); here q2 = " + format_double(q2));
  if (!exists(q2, p2))
    s.reject(section + ".p2", "the start q1 = 0, q2 = " + short_num(q2) + ", p2 = " + short_num(p2) + " (k = " +
                                  std::to_string(hh.k) + ") needs U(0, q2) + p2^2/2 < hh.H0 = " + short_num(H0));
  for (const double a : {q2 - d, q2 + d})
    for (const double b : {p2 - d, p2 + d})
      if (!inside(a) || !exists(a, b))
        s.reject("ensemble.perturbation", "the perturbed start q1 = 0, q2 = " + short_num(a) + ", p2 = " + short_num(b) +
                                              " must lie between the saddles of U on q1 = 0 with U(0, q2) + p2^2/2 < "
                                              "hh.H0 = " + short_num(H0) + "; here " + format_double(d));
  if (check_h)
    check_step_bound(s, "h", s.real("h"), std::sqrt(max_hessian_eigenvalue(hh, Vec<2>(0.0, q2))),
                     "omega^2 = max eig U''(0, " + section + ".q2), Henon-Heiles k = " + std::to_string(hh.k));
}

// The samples a run of n steps keeps: every max(1, floor(n / samples)) steps, from step 0.
double kept_samples(double n, double samples) { return std::floor(n / std::max(1.0, std::floor(n / samples))) + 1; }

void check_pendulum(const Scene& s) {
  const double h = s.real("h"), t_end = s.real("pendulum.t_end");
  check_step_bound(s, "h", h, pendulum_omega(), "omega^2 = max_q U''(q) of the pendulum of Fig. 2");
  const double H0 = UnsymmetricPendulum().H(make_state(s.real("pendulum.q0"), s.real("pendulum.p0")));
  if (!(std::isfinite(H0) && H0 > UnsymmetricPendulum::U_max()))  // Fig. 2 and (4.3) averaged over the orbit need a pendulum that turns over
    s.reject("pendulum.p0", "the start must turn over: H(q0, p0) = " + format_double(H0) + " must exceed max U = " +
                                format_double(UnsymmetricPendulum::U_max()));
  if (t_end / h < 1) s.reject("pendulum.t_end", "must be at least one step h = " + format_double(h));
  if (!(t_end / h <= max_exact_count))  // before the windows below, which would blame fit_t
    s.reject("pendulum.t_end", "at most 2^53 steps h = " + format_double(h) + " (here " + format_double(t_end / h) + ")");
  const double n = std::round(t_end / h), every = std::max(1.0, std::floor(n / static_cast<double>(s.integer("samples"))));
  if (!(s.real("pendulum.fit_t") <= t_end && s.real("pendulum.fit_t") >= 2 * every * h))
    s.reject("pendulum.fit_t", "must lie in [2 sample intervals, pendulum.t_end] = [" + format_double(2 * every * h) + ", " +
                                   format_double(t_end) + "] (the drift rate is fitted over t <= fit_t)");
  const double rows = kept_samples(n, static_cast<double>(s.integer("samples")));
  if (static_cast<double>(s.integer("pendulum.slope_windows")) * 2 > rows)
    s.reject("pendulum.slope_windows", "must be at most half the " + format_double(rows) +
                                           " samples of the run (each window fits a slope through at least 2)");
}

void check_hh3(const Scene& s) {
  check_hh_starts(s, "hh3", HenonHeiles{{}, 3}, 0.0, true);
  if (s.real("hh3.t_end") / s.real("h") < 2) s.reject("hh3.t_end", "must be at least two steps h");
}

void check_ensemble(const Scene& s) {
  with_ensemble_system(s, [&](const auto& hh) { check_hh_starts(s, "hh3", hh, s.real("ensemble.perturbation"), true); });
  const double h = s.real("h"), t_end = s.real("t_end");
  if (t_end / h < 2) s.reject("t_end", "must be at least two steps h");
  for (const char* key : {"ensemble.episode_half_width", "ensemble.episode_min_length"})
    if (s.real(key) > t_end) s.reject(key, "must not exceed t_end = " + format_double(t_end));
}

void check_work_precision(const Scene& s) {
  check_methods(s, "work_precision.methods", Counting<HenonHeiles>{HenonHeiles{{}, 3}, nullptr});
  check_methods(s, "work_precision.methods", Counting<HarmonicOscillator>{kOscillator, nullptr});
  check_hh_starts(s, "hh3", HenonHeiles{{}, 3}, 0.0, false);
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h")) {
      check_oscillatory_bound(s, "work_precision.h", "work_precision.methods", m, kOscillator.w * h, "the oscillator");
      if (s.real("work_precision.t_end") / h < 1)
        s.reject("work_precision.t_end", "must be at least one step of every work_precision.h");
    }
}

// Fig. 6: lj.h below the bound at the stiffness of the unperturbed grid (omega^2 = 86.8; the perturbed starts and
// the motion are stiffer: a run that diverges anyway ends with a numerical failure, exit 4).
void check_lj(const Scene& s) {
  const LJ lj;
  Vec<18> grid_q;
  for (int k = 0; k < 9; ++k) grid_q.segment<2>(2 * k) = lj_grid(k);
  check_step_bound(s, "lj.h", s.real("lj.h"), std::sqrt(max_hessian_eigenvalue(lj, grid_q)),
                   "omega^2 = max eig U'' at the 3 x 3 grid of Fig. 6");
  if (s.real("lj.t_end") / s.real("lj.h") < 2) s.reject("lj.t_end", "must be at least two steps lj.h");
  for (double h : s.reals("lj.h_scan"))
    if (s.real("lj.scan_t") / h < 1) s.reject("lj.scan_t", "must be at least one step of every lj.h_scan");
}

void check_lj_steps(const Scene& s) {
  const LJ lj;
  Vec<18> grid_q;
  for (int k = 0; k < 9; ++k) grid_q.segment<2>(2 * k) = lj_grid(k);
  const double omega = std::sqrt(max_hessian_eigenvalue(lj, grid_q));
  for (double h : s.reals("lj_steps.h")) {
    check_step_bound(s, "lj_steps.h", h, omega, "omega^2 = max eig U'' at the 3 x 3 grid of Fig. 6");
    if (s.real("lj_steps.t_end") / h < 1) s.reject("lj_steps.t_end", "must be at least one step of every lj_steps.h");
  }
}

// ns per (trajectory-)step and thread, measured (the paper scene's summary.json, timing): one Henon-Heiles
// trajectory (24.3, the scalar method, before the ensembles ran in lanes); the ensembles in SIMD lanes on a 2-core
// AVX2 machine (fig4_ns_per_step_thread 5.6, Henon-Heiles, its registers of lanes stepped together;
// fig6_ns_per_step_thread 158, Lennard-Jones with its processing every sample).
constexpr double kNsPerStepHH = 24.3, kNsPerStepLanesHH = 5.6, kNsPerStepLanesLJ = 158.0;
const char* const kNsNote = "ns per step: measured (paper scene, summary.json timing.fig4_ns_per_step_thread before the lanes)";
const char* const kNsLanesNote = "ns per trajectory-step: measured (paper scene, summary.json timing.fig4/fig6_ns_per_step_thread, "
                                 "the ensembles in SIMD lanes; 2-core AVX2 machine)";

std::int64_t evals_of(const std::string& m) { return evals_per_step(m); }

StudyPlan plan_oscillator(const Scene& s) {
  const double T = s.real("oscillator.t_omega") / kOscillator.w;
  StudyPlan p;
  double largest_ti = 0;
  for (const auto& m : s.texts("oscillator.methods")) {
    const double e = static_cast<double>(evals_of(m));
    for (double wh : s.reals("oscillator.omega_h")) {
      const double h = step_at_equal_work(wh, evals_of(m));
      if (beyond_bound(kOscillator.w * h, method_info(m).oscillatory_bound)) continue;
      p.steps += T / h, p.force_evals += e * T / h;
      if (label_of(m) == "ti") largest_ti = std::max(largest_ti, wh);
    }
  }
  const double sv_steps = T * kOscillator.w / method_info("stormer_verlet").oscillatory_bound;
  p.steps += sv_steps + (largest_ti > 0 ? T / largest_ti : 0.0);
  p.force_evals += sv_steps + (largest_ti > 0 ? 2 * T / largest_ti : 0.0);
  p.memory_bytes = 16 * sv_steps + 1e5;  // the sampled growth of SV at its bound: 2 doubles per step
  p.ns_per_step = 10.8;
  p.note = "ns per step: Stormer-Verlet's (summary.json timing.ns_per_step.sv of the paper scene)";
  return p;
}

StudyPlan plan_pendulum(const Scene& s) {
  const double n = s.real("pendulum.t_end") / s.real("h"), e = static_cast<double>(evals_of("simplified_takahashi_imada"));
  StudyPlan p;
  p.steps = n + static_cast<double>(kReferenceSteps);
  p.force_evals = e * n + 4 * static_cast<double>(kReferenceSteps);
  p.memory_bytes = kept_samples(n, static_cast<double>(s.integer("samples"))) * (3 * 8 + 80);  // 3 series + the CSV rows
  p.ns_per_step = kNsPerStepHH;
  p.note = kNsNote;
  return p;
}

StudyPlan plan_hh3(const Scene& s) {
  const double n = s.real("hh3.t_end") / s.real("h");
  return {n, n * static_cast<double>(evals_of("simplified_takahashi_imada")),
          kept_samples(n, static_cast<double>(s.integer("samples"))) * (2 * 8 + 80), kNsPerStepHH, kNsNote};
}

StudyPlan plan_ensemble(const Scene& s) {
  const double n = s.real("t_end") / s.real("h"), M = static_cast<double>(s.integer("ensemble.size"));
  const double rows = kept_samples(n, static_cast<double>(s.integer("samples")));
  // M trajectories and the rerun of the one with the largest error (Fig. 5); the series of all M, and the CSVs
  return {(M + 1) * n, (M + 1) * n * static_cast<double>(evals_of("simplified_takahashi_imada")),
          M * rows * 8 + rows * 200 + M * std::min(rows, 201.0) * 60, kNsPerStepLanesHH, kNsLanesNote,
          static_cast<double>(lane_batches(static_cast<std::size_t>(M)))};  // (tasks: batches of lanes)
}

StudyPlan plan_lj(const Scene& s) {
  const double scan_t = s.real("lj.scan_t"), scan_size = static_cast<double>(s.integer("lj.scan_size"));
  const double hl = s.real("lj.h"), n = s.real("lj.t_end") / hl, M = static_cast<double>(s.integer("lj.size"));
  StudyPlan p;
  for (double h : s.reals("lj.h_scan")) p.steps += scan_size * scan_t / h;
  p.steps += scan_size * scan_t / hl + M * n;
  p.force_evals = p.steps * static_cast<double>(evals_of("simplified_takahashi_imada"));
  p.memory_bytes = M * kept_samples(n, static_cast<double>(s.integer("samples"))) * 3 * 8;  // E, H, H^ of each trajectory
  p.ns_per_step = kNsPerStepLanesLJ;
  p.note = kNsLanesNote;
  p.tasks = static_cast<double>(lane_batches(static_cast<std::size_t>(M)));  // the ensemble's batches of lanes (the scan before it: a small part)
  return p;
}

StudyPlan plan_lj_steps(const Scene& s) {
  const double M = static_cast<double>(s.integer("lj_steps.size"));
  StudyPlan p;
  for (double h : s.reals("lj_steps.h")) p.steps += M * s.real("lj_steps.t_end") / h;
  p.force_evals = p.steps * static_cast<double>(evals_of("simplified_takahashi_imada"));
  p.memory_bytes = M * static_cast<double>(s.reals("lj_steps.h").size()) * 8;
  p.ns_per_step = kNsPerStepLanesLJ;
  p.note = kNsLanesNote;
  p.tasks = static_cast<double>(lane_batches(static_cast<std::size_t>(M)) * s.reals("lj_steps.h").size());
  return p;
}

StudyPlan plan_work_precision(const Scene& s) {
  // per method, problem and step: a counting run, an error run and timing.repeats timed runs (each repeated up to
  // 10 ms: the steps here are a lower bound); the odeint reference not counted
  const double T = s.real("work_precision.t_end"), runs = 2 + static_cast<double>(s.integer("timing.repeats"));
  StudyPlan p;
  for (const auto& m : s.texts("work_precision.methods"))
    for (double h : s.reals("work_precision.h"))
      p.steps += 2 * runs * T / h, p.force_evals += 2 * runs * T / h * static_cast<double>(evals_of(m));
  p.memory_bytes = 1e5;
  p.ns_per_step = kNsPerStepHH;
  p.note = "a lower bound (timed runs last at least 10 ms each); " + std::string(kNsNote);
  return p;
}

StudyPlan plan_symplecticity(const Scene& s) {
  // per method: 16 central differences of one step; Sect. 3.3: 4 steps of each of two methods
  const double m = static_cast<double>(s.texts("symplecticity.methods").size());
  return {16 * m + 8, 2 * (16 * m + 8), 1e4, kNsPerStepHH, kNsNote};
}

StudyPlan plan_timing(const Scene& s) {
  const double n = static_cast<double>(s.integer("timing.steps")), r = static_cast<double>(s.integer("timing.repeats"));
  StudyPlan p;
  for (const auto& m : s.texts("timing.methods"))
    p.steps += (r + 1) * n, p.force_evals += (r + 1) * n * static_cast<double>(evals_of(m));
  p.memory_bytes = 1e4;
  p.ns_per_step = kNsPerStepHH;
  p.note = "a lower bound (each timed run lasts at least 10 ms); " + std::string(kNsNote);
  return p;
}

Schema schema() {
  Schema s;
  s.reals("oscillator.omega_h", positive(), 3,
          "effective steps omega h_eff of Fig. 1 (equal work: h = h_eff e/2 for e force evaluations per step)")
      .texts("oscillator.methods", method_choices<Counting<HarmonicOscillator>>(), 1,
             "methods of Fig. 1, processed where they have processing (registry names or labels)")
      .real("oscillator.t_omega", positive(), "errors are maxima over t <= t_omega / omega (004: 50)")
      .real("h", positive(), "step of Figs 2-5 (004: 0.2), of the symplecticity check and of the cost runs")
      .real("pendulum.q0", any_finite(), "Fig. 2 start (004: q = 0, p = 2.5)")
      .real("pendulum.p0", any_finite(), "")
      .real("pendulum.t_end", positive(), "Fig. 2 time span")
      .real("pendulum.fit_t", positive(), "the drift rate is fitted over t <= fit_t, where the energy has not yet fallen")
      .integer("pendulum.slope_windows", at_least(2),
               "the local drift: least-squares slopes over this many consecutive windows of the run, against (4.3) at "
               "each window's energy")
      .real("hh3.q2", any_finite(), "Fig. 3 start q2 (q1 = 0, p1 > 0 from hh.H0); the centre of the Fig. 4 starts")
      .real("hh3.p2", any_finite(), "Fig. 3 start p2")
      .real("hh3.t_end", positive(), "Fig. 3 time span")
      .integer("hh.k", at_least(3), "exponent k of Fig. 4 (004: 5)")
      .real("hh.H0", positive(), "energy of the Henon-Heiles starts (004: 1/8)")
      .real("hh.coupling", any_finite(),
            "coefficient c of c q1^2 q2 in the potential of Figs 4-5 (004: 1); c = 0 removes the term from the "
            "compiled step")
      .real("t_end", positive(), "Fig. 4 time span (004: 2.5e6)")
      .integer("ensemble.size", at_least(2), "Fig. 4 trajectories (004: 100)")
      .integer("ensemble.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("ensemble.perturbation", non_negative(), "q2 and p2 of each start perturbed uniformly by at most this")
      .real("ensemble.episode_half_width", positive(),
            "Fig. 5 episodes: the running slope of the error of E of the trajectory is fitted over +- this time")
      .real("ensemble.episode_threshold", positive(),
            "Fig. 5 episodes: a sample belongs to an episode where its running slope differs from their median by more "
            "than this many robust standard deviations (1.4826 MAD) of the running slopes")
      .real("ensemble.episode_min_length", positive(), "Fig. 5 episodes: the shortest episode (time units)")
      .real("ensemble.outlier", positive(), "trajectories whose max |error| exceeds this go to Fig. 4's upper panel (004: 2e-6)")
      .integer("samples", at_least(10), "output times per long run")
      .reals("lj.h_scan", positive(), 1, "Fig. 6: steps scanned for stability (004 prints h = 0.2)")
      .real("lj.scan_t", positive(), "time span of the step-size scan")
      .integer("lj.scan_size", at_least(1), "trajectories of the scan")
      .real("lj.h", positive(), "Fig. 6: the step used for the statistics")
      .real("lj.t_end", positive(), "Fig. 6 time span (004: 2e4)")
      .integer("lj.size", at_least(2), "Fig. 6 trajectories (004: 400)")
      .integer("checkpoint.stop_after", non_negative(),
               "ensemble, lj: stop after this many rounds of trajectories, leaving a checkpoint for --resume (0: run to "
               "the end)")
      .real("checkpoint.interval", non_negative(), "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work")
      .integer("lj.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("lj.perturbation", non_negative(), "each coordinate of the 3 x 3 grid perturbed uniformly by at most this (004: 0.01)")
      .real("lj.blowup", positive(), "|H - H0| above this marks a scan run diverged")
      .texts("symplecticity.methods", method_choices<HenonHeiles>(), 1,
             "methods whose one-step Jacobian (of the kernel) is checked (registry names or labels)")
      .integer("symplecticity.k", at_least(3), "exponent k of the Henon-Heiles system of the check")
      .real("symplecticity.q2", any_finite(), "start q2 of the check (q1 = 0, p1 > 0 from hh.H0)")
      .real("symplecticity.p2", any_finite(), "start p2 of the check")
      .real("symplecticity.fd_step", positive(), "step of the central differences of the Jacobian")
      .reals("lj_steps.h", positive(), 3, "Fig. 6: steps at which sigma of the error of E is measured (its power of h)")
      .integer("lj_steps.size", at_least(2), "trajectories per step of lj_steps (the starts of Fig. 6: lj.seed)")
      .real("lj_steps.t_end", positive(), "time at which sigma is measured in lj_steps")
      .texts("work_precision.methods", method_choices<Counting<HenonHeiles>>(), 2,
             "methods of the work-precision study (processed where they have processing; registry names or labels)")
      .reals("work_precision.h", positive(), 3, "steps of the work-precision runs (every method)")
      .real("work_precision.t_end", positive(), "the global error of a work-precision run is taken at this time")
      .real("work_precision.target", positive(), "target error of the cost to reach it")
      .real("work_precision.reference_tol", {.gt = {}, .ge = 1e-13, .lt = {}, .le = 1e-2},
            "odeint tolerance of the Henon-Heiles reference error estimate (the reference itself: 100 times tighter, so in [1e-15, 1e-4])")
      .texts("timing.methods", method_choices<HenonHeiles>(), 1,
             "methods timed (their kernels, on the Fig. 4 system; registry names or labels)")
      .integer("timing.steps", at_least(1), "steps of each timed run")
      .integer("timing.lj_steps", at_least(1), "steps of each timed run of the Lennard-Jones lanes (Fig. 6 cluster, lj.h)")
      .integer("timing.repeats", at_least(1),
               "timed runs per method and step, each of at least 10 ms (the minimum is the estimate, the spread reported)");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"ti_drift", "004 Figs 1-6: energy behaviour of the (simplified) Takahashi-Imada method",
                      schema(), {}};
  spec.studies = {
      {"oscillator", "004 Fig 1", {"oscillator.csv", "oscillator_closed_forms.csv"}, {"oscillator"}, check_oscillator,
       run_oscillator, plan_oscillator},
      {"pendulum", "004 Fig 2", {"fig2_pendulum.csv", "fig2_local_slope.csv"}, {"h", "samples", "pendulum"}, check_pendulum, run_pendulum,
       plan_pendulum},
      {"hh3", "004 Fig 3", {"fig3_hh3.csv"}, {"h", "samples", "hh3", "hh.H0"},
       check_hh3, run_hh3, plan_hh3},
      {"ensemble", "004 Figs 4, 5", {"fig4_stats.csv", "fig4_trajectories.csv", "fig5_poincare.csv", "fig5_episodes.csv", "fig5_episode_cuts.csv"},
       {"h", "t_end", "samples", "hh", "ensemble", "hh3.q2", "hh3.p2", "checkpoint"},
       check_ensemble, run_ensemble, plan_ensemble},
      {"lj", "004 Fig 6", {"fig6_*.csv"}, {"lj", "samples", "checkpoint"}, check_lj, run_lj, plan_lj},
      {"lj_steps", "004 Fig 6: sigma against h (the printed step)", {"fig6_steps.csv"}, {"lj_steps", "lj.seed", "lj.perturbation"},
       check_lj_steps, run_lj_steps, plan_lj_steps},
      {"work_precision", "cost: error against wall time and force evaluations (oscillator, Henon-Heiles k = 3)",
       {"timing_work_precision.csv"},
       {"work_precision", "timing.repeats", "hh3.q2", "hh3.p2", "hh.H0"},
       check_work_precision, run_work_precision, plan_work_precision},
      {"symplecticity", "004 Sect. 1.3: TI symplectic, the simplified TI only volume-preserving", {},
       {"symplecticity", "h", "hh.H0"},
       [](const Scene& s) {
         check_methods(s, "symplecticity.methods", symplecticity_system(s));
         check_hh_starts(s, "symplecticity", symplecticity_system(s), 0.0, true);
       },
       run_symplecticity, plan_symplecticity},
      {"timing", "cost: ns per step of each method", {},
       {"timing", "h", "hh", "hh3.q2", "hh3.p2", "ensemble.seed", "ensemble.perturbation", "lj.h", "lj.seed", "lj.perturbation"},
       [](const Scene& s) {
         with_ensemble_system(s, [&](const auto& hh) {
           check_methods(s, "timing.methods", hh);
           check_hh_starts(s, "hh3", hh, s.real("ensemble.perturbation"), true);
         });
       },
       run_timing, plan_timing},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
