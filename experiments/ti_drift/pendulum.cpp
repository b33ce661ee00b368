// 004 Fig. 2: the unsymmetric pendulum, the shifted energy H + h^2 H_3 along the simplified method (1.6):
// its drift, fitted over the start and over the run, against the rate (4.3) averaged along the exact orbit;
// and the local drift in consecutive windows against (4.3) at each window's energy.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "geomint/analysis/orbit_average.hpp"
#include "geomint/analysis/sample_windows.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"

namespace geomint::ti_drift {
namespace {

using Z1 = PhaseState<1>;

constexpr double kReferenceStep = 1e-3;       // Fig. 2: the exact orbit, RK4 at this step ...
constexpr std::int64_t kReferenceSteps = 2000000;  // ... over 2000 time units

// The local drift over the whole run: the least-squares slope of H + h^2 H_3 in each of pendulum.slope_windows
// consecutive windows, against (4.3) averaged over the rotating orbit of the window's mean energy H.
void write_local_slopes(Context& ctx, const UnsymmetricPendulum& up, const Z1& p0, double h,
                        const std::vector<double>& ts_all, const std::vector<double>& es_all,
                        const std::vector<double>& Hs_all, double rate_predicted) {
  const Scene& s = ctx.scene;
  const auto windows = static_cast<std::size_t>(s.integer("pendulum.slope_windows"));
  const auto rate_at = [&](double E) {
    return rotation_average(up, E, [&](double q, double p) { return simplified_ti_drift_rate(up, make_state(q, p), h); });
  };
  Csv ls({"t_start", "t_end", "t_mid", "H_mean", "local_slope", "predicted_slope", "rel_difference"});
  double worst = 0, worst_t = 0;
  const std::size_t per = ts_all.size() / windows;
  for (std::size_t w = 0; w < windows; ++w) {
    const auto [a, b] = consecutive_window(ts_all.size(), windows, w);
    const std::span<const double> tw(ts_all.data() + a, b - a), ew(es_all.data() + a, b - a);
    double H_mean = 0;
    for (std::size_t k = a; k < b; ++k) H_mean += up.H(p0) + Hs_all[k];
    H_mean /= static_cast<double>(b - a);
    const double local = linear_fit(tw, ew).slope, pred = rate_at(H_mean), rel = std::abs(local - pred) / std::abs(pred);
    ls.row(ts_all[a], ts_all[b - 1], 0.5 * (ts_all[a] + ts_all[b - 1]), H_mean, local, pred, rel);
    record_fit(ctx.summary, {"fig2_local_slope.csv#local_slope#" + std::to_string(w), {"fig2_pendulum.csv", "t", "shifted_energy_err"},
                             "slope", ts_all[a], ts_all[b - 1]});
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

void run_pendulum(Context& ctx) {
  put_simplified_ti_method(ctx.summary, "pendulum");
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
  const Z1 ref_end = integrate(one_step_method([f = HamiltonianField<UnsymmetricPendulum>{up}](const Z1& z, double dt) { return runge_kutta4(f, z, dt); }), p0, kReferenceStep, kReferenceSteps, [&](std::int64_t j, const Z1& z) {
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
  const double rate = linear_fit(ts, es).slope, rate_predicted = predicted / static_cast<double>(kReferenceSteps);
  record_fit(ctx.summary, {"reproduced.unsym_pendulum_drift_rate", {"fig2_pendulum.csv", "t", "shifted_energy_err"}, "slope", 0,
                           s.real("pendulum.fit_t"), "", 1, 0, "pendulum.fit_t"});
  record_fit(ctx.summary, {"reproduced.unsym_pendulum_drift_rate_whole", {"fig2_pendulum.csv", "t", "shifted_energy_err"}, "slope",
                           0, ts_all.back()});
  record_fit(ctx.summary, {"pendulum.H_drift_rate", {"fig2_pendulum.csv", "t", "H_err"}, "slope", 0, ts_all.back()});
  for (const auto& [trend, kind] : {std::pair{"trend", "ptp_about_line"}, std::pair{"quadratic", "ptp_about_quadratic"}})
    for (const auto& [name, column] : {std::pair{"shifted_energy", "shifted_energy_err"}, std::pair{"H", "H_err"}})
      record_fit(ctx.summary, {std::string("pendulum.peak_to_peak_about_") + trend + "." + name, {"fig2_pendulum.csv", "t", column},
                               kind, 0, ts_all.back()});
  merge(ctx.summary, "reproduced",
      {{"unsym_pendulum_drift_rate", rate},                         // at the start's energy
       {"unsym_pendulum_drift_rate_whole", linear_fit(ts_all, es_all).slope},  // over the whole span (the rate falls with H)
       {"unsym_pendulum_drift_rate_predicted", rate_predicted}});
  const double t_ref = kReferenceStep * static_cast<double>(kReferenceSteps);
  ctx.summary["pendulum"] = {
      {"H0", up.H(p0)},
      {"steps", n},
      {"sample_dt", static_cast<double>(every) * h},
      {"change", es_all.back()},               // of H + h^2 H_3 over the run
      {"change_relative_to_H0", es_all.back() / up.H(p0)},
      {"H_drift_rate", linear_fit(ts_all, Hs_all).slope},  // the slope of the error of H over the run
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
  write_local_slopes(ctx, up, p0, h, ts_all, es_all, Hs_all, rate_predicted);
}

// Fig. 2: the rotating pendulum passes every q, so omega^2 = max_q U''(q) (on a grid of 3600 angles).
double pendulum_omega() {
  const UnsymmetricPendulum up;
  double w2 = 0;
  for (int i = 0; i < 3600; ++i) w2 = std::max(w2, max_hessian_eigenvalue(up, Vec<1>(2 * std::numbers::pi * i / 3600)));
  return std::sqrt(w2);
}

void check_pendulum(const Scene& s) {
  const double h = s.real("h"), t_end = s.real("pendulum.t_end");
  check_step_bound(s, "h", "simplified_takahashi_imada", h * pendulum_omega(),
                   "omega^2 = max_q U''(q) of the pendulum of Fig. 2", "2 sqrt(3)");
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

StudyPlan plan_pendulum(const Scene& s) {
  const double n = s.real("pendulum.t_end") / s.real("h"), e = static_cast<double>(evals_per_step("simplified_takahashi_imada"));
  StudyPlan p;
  p.steps = n + static_cast<double>(kReferenceSteps);
  p.force_evals = e * n + 4 * static_cast<double>(kReferenceSteps);
  const PlanRate& reference = plan_rate("pendulum odeint reference");
  p.memory_bytes = kept_samples(n, static_cast<double>(s.integer("samples"))) * (3 * 8 + 80);  // 3 series + the CSV rows
  const PlanRate& rate = plan_rate("henon-heiles splitting");
  p.ns_per_step = (n * rate.ns_per_step + static_cast<double>(kReferenceSteps) * reference.ns_per_step) / p.steps;
  p.note = rate.note + "; " + reference.note;
  return p;
}

}  // namespace

Study pendulum_study() {
  return {.name = "pendulum",
          .makes = {{"004", "Fig. 2"}},
          .about = "the drift of the shifted energy on the unsymmetric pendulum, against the rate (4.3)",
          .files = {"fig2_pendulum.csv", "fig2_local_slope.csv"},
          .keys = Schema()
                      .real("pendulum.q0", any_finite(), "Fig. 2 start (004: q = 0, p = 2.5)")
                      .real("pendulum.p0", any_finite(), "")
                      .real("pendulum.t_end", positive(), "Fig. 2 time span")
                      .real("pendulum.fit_t", positive(),
                            "the drift rate is fitted over t <= fit_t, where the energy has not yet fallen")
                      .integer("pendulum.slope_windows", at_least(2),
                               "the local drift: least-squares slopes over this many consecutive windows of the run, "
                               "against (4.3) at each window's energy"),
          .reads = {"h", "samples"},
          .run = run_pendulum,
          .validate = check_pendulum,
          .plan = plan_pendulum};
}

}  // namespace geomint::ti_drift
