// 004 Fig. 6: the Lennard-Jones cluster of 9 particles on a perturbed 3 x 3 grid along the simplified method
// (1.6): a step-size scan for stability (with the stiffness of the cluster), and at lj.h the ensemble's mean
// and standard deviation of the error of the modified energy E of (3.3) and (4.2), the error of H, and of H
// at the processed variables (1.5).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/lennard_jones_ensemble.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint::ti_drift {
namespace {

using Z18 = PhaseState<18>;
using LJ = LennardJones<9>;  // 004 Fig. 6

constexpr std::size_t kLjShown = 50;          // Fig. 6: trajectories drawn (004: 50)
constexpr std::int64_t kStiffnessEvery = 10;   // Fig. 6: the stiffness along the scan starts, every this many steps of lj.h

// The step-size scan and the stiffness of the cluster, as the summary reports them.
struct Scan {
  Value scan_summary;          // per step of lj.h_scan
  std::vector<double> stable;  // the steps at which no run diverged
  double grid_stiffness, along_lo, along_hi;
};

// The step-size scan (fig6_scan.csv) and the stiffness of the cluster.
Scan scan_steps(Context& ctx, Value& reproduced) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("lj.h_scan");
  const auto scan_size = static_cast<std::size_t>(s.integer("lj.scan_size"));
  const auto scan = lennard_jones_step_scan(s);
  // The stiffness omega_max^2 (largest eigenvalue of the Hessian): at the grid, at the starts of the
  // ensemble, and along the scan starts integrated at lj.h to lj.scan_t (its largest value on each).
  const double grid_stiffness = lennard_jones_grid_stiffness();
  const auto along = lennard_jones_stiffness_along(s, kStiffnessEvery);
  const auto [along_lo, along_hi] = std::minmax_element(along.begin(), along.end());
  Csv sc({"h", "trajectory", "max_H_err", "diverged", "diverge_step"});
  sc.flags({"diverged"});
  Value stable_h = Value::list(), scan_summary = Value::list();
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
    Value row = {{"h", hs[k]},
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
  return {scan_summary, stable, grid_stiffness, *along_lo, *along_hi};
}

// The ensemble's statistics at each output time (fig6_stats.csv), its first trajectories (fig6_trajectories.csv),
// and the reproduced values of Fig. 6.
struct Stats {
  std::vector<double> ts, H_rms, Hhat_rms, Hhat_change;
  double mu_f, sigma_f, mu_se, sigma_se;
};

Stats write_stats(Context& ctx, const LennardJonesEnsemble& en, Value& reproduced) {
  const Scene& s = ctx.scene;
  const double hl = en.hl;
  const std::size_t Ml = en.Ml;
  const std::int64_t every_l = en.every_l;
  const std::vector<LennardJonesSeries>& lj_series = en.lj_series;
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
  reproduced["lj_sigma_exponent"] = power_law_exponent(ts, sigmas, fit_window_start(s, "lj", s.real("lj.t_end")));
  std::vector<std::vector<double>> E_series;  // its standard error over the ensemble (bootstrap: published.toml)
  for (const auto& r : lj_series) E_series.push_back(r.E);
  reproduced["lj_sigma_exponent_stderr"] = bootstrap_exponent_stderr(
      E_series, ts, fit_window_start(s, "lj", s.real("lj.t_end")), kBootstrapResamples, static_cast<std::uint64_t>(s.integer("lj.seed")));
  reproduced["lj_H_err_max"] = H_max;
  return {ts, H_rms, Hhat_rms, Hhat_change, mu_f, sigma_f, mu_se, sigma_se};
}

// summary.lj: the scan, the stiffness, the errors of H and of H at the processed variables, and the standard
// scores of the published mean and standard deviation.
void put_summary(Context& ctx, const LJ& lj, const Scan& scan, const LennardJonesEnsemble& en, const Stats& st) {
  const Scene& s = ctx.scene;
  const double hl = en.hl;
  const std::size_t Ml = en.Ml;
  const std::int64_t nl = en.nl, every_l = en.every_l;
  const Value& scan_summary = scan.scan_summary;
  const std::vector<double>& stable = scan.stable;
  const double grid_stiffness = scan.grid_stiffness;
  const std::vector<double>& ts = st.ts;
  const std::vector<double>& H_rms = st.H_rms;
  const std::vector<double>& Hhat_rms = st.Hhat_rms;
  const std::vector<double>& Hhat_change = st.Hhat_change;
  const double mu_f = st.mu_f, sigma_f = st.sigma_f, mu_se = st.mu_se, sigma_se = st.sigma_se;
  // The ensemble's H errors after the start (t > 0): H at (p_n, q_n) and at the processed variables.
  std::vector<double> H_later(H_rms.begin() + 1, H_rms.end()), Hhat_later(Hhat_rms.begin() + 1, Hhat_rms.end());
  const Value H_spread = spread_of(H_later), Hhat_spread = spread_of(Hhat_later);
  double Hhat_variation = 0;
  for (double b : Hhat_later) Hhat_variation = std::max(Hhat_variation, std::abs(b / Hhat_rms[0] - 1));
  std::vector<double> start_stiffness;
  for (std::size_t i = 0; i < Ml; ++i) start_stiffness.push_back(max_hessian_eigenvalue(lj, lennard_jones_start(s, i).q));
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
                     {"along_scan_starts", {{"min", scan.along_lo}, {"max", scan.along_hi}}},
                     {"sample_dt", static_cast<double>(kStiffnessEvery) * hl}}},
      {"H_err_rms", H_spread},                       // over the output times t > 0
      {"Hhat_err_rms", Hhat_spread},
      {"Hhat_err_rms_start", Hhat_rms[0]},           // the offset H(chi_h(p_0, q_0)) - H_0
      {"Hhat_err_rms_variation", Hhat_variation},   // max |rms / its start - 1| over t > 0
      {"H_over_Hhat_err_rms", H_spread.at("mean").number() / Hhat_spread.at("mean").number()},
      // H(p^_n, q^_n) - H(p^_0, q^_0): its root mean square at t_end, against sigma of E, and its growth exponent
      {"Hhat_change_rms_final", Hhat_change.back()},
      {"Hhat_change_over_sigma_final", Hhat_change.back() / sigma_f},
      {"Hhat_change_exponent", power_law_exponent(ts, Hhat_change, fit_window_start(s, "lj", s.real("lj.t_end")))},
      {"fit", {{"t_min", fit_window_start(s, "lj", s.real("lj.t_end"))}, {"t_max", s.real("lj.t_end")}}},
      // the published mean and standard deviation (published.toml) in standard errors of ours, and ours from zero
      {"standard_scores", {{"mu_from_printed", std::abs(mu_f - ctx.published_value("lj_mu_final")) / mu_se},
                           {"mu_from_zero", std::abs(mu_f) / mu_se},
                           {"sigma_from_printed", std::abs(sigma_f - ctx.published_value("lj_sigma_final")) / sigma_se}}}};
  if (!stable.empty()) ctx.summary["lj"]["stable_steps"] = range_of(stable);
  const double t_fit = fit_window_start(s, "lj", s.real("lj.t_end"));
  record_fit(ctx.summary, {"reproduced.lj_sigma_exponent", {"fig6_stats.csv", "t", "sigma"}, "power_law", t_fit, ts.back(), "lj.fit_from"});
  record_fit(ctx.summary, {"lj.Hhat_change_exponent", {"fig6_stats.csv", "t", "Hhat_change_rms"}, "power_law", t_fit, ts.back(), "lj.fit_from"});
  // the smallest step of the scan: the median of its largest errors of H
  const auto hs = s.reals("lj.h_scan");
  const auto smallest = static_cast<std::size_t>(std::min_element(hs.begin(), hs.end()) - hs.begin());
  if (scan_summary.at(smallest).contains("max_H_err"))
    ctx.summary["lj"]["smallest_step"] = {{"h", hs[smallest]},
                                          {"max_H_err_median", scan_summary.at(smallest).at("max_H_err").at("median")}};
}

void run_lj(Context& ctx) {
  put_simplified_ti_method(ctx.summary, "lj");
  ctx.progress("Fig. 6: Lennard-Jones cluster");
  const LJ lj;
  Value reproduced;
  const Scan scan = scan_steps(ctx, reproduced);
  const LennardJonesEnsemble en = integrate_lennard_jones_ensemble(ctx);
  const Stats st = write_stats(ctx, en, reproduced);
  merge(ctx.summary, "reproduced", reproduced);
  put_summary(ctx, lj, scan, en, st);
  const double wall6 = en.wall6;
  const std::size_t Ml = en.Ml;
  const std::int64_t nl = en.nl;
  merge(ctx.summary, "timing",
      {{"fig6_wall_s", wall6},
       {"threads", ctx.threads},
       {"fig6_steps", static_cast<double>(Ml) * static_cast<double>(nl)},
       {"fig6_ns_per_step_thread", 1e9 * wall6 * ctx.threads / (static_cast<double>(Ml) * static_cast<double>(nl))}});
}

void check_lj(const Scene& s) {
  check_lennard_jones_step(s, "lj.h", s.real("lj.h"));
  if (s.real("lj.t_end") / s.real("lj.h") < 2) s.reject("lj.t_end", "must be at least two steps lj.h");
  for (double h : s.reals("lj.h_scan"))
    if (s.real("lj.scan_t") / h < 1) s.reject("lj.scan_t", "must be at least one step of every lj.h_scan");
}

StudyPlan plan_lj(const Scene& s) {
  const double scan_t = s.real("lj.scan_t"), scan_size = static_cast<double>(s.integer("lj.scan_size"));
  const double hl = s.real("lj.h"), n = s.real("lj.t_end") / hl, M = static_cast<double>(s.integer("lj.size"));
  StudyPlan p;
  for (double h : s.reals("lj.h_scan")) p.steps += scan_size * scan_t / h;
  p.steps += scan_size * scan_t / hl + M * n;
  p.force_evals = p.steps * static_cast<double>(evals_per_step("simplified_takahashi_imada"));
  p.memory_bytes = M * kept_samples(n, static_cast<double>(s.integer("samples"))) * 3 * 8;  // E, H, H^ of each trajectory
  const PlanRate& rate = plan_rate("lennard-jones lanes");
  p.ns_per_step = rate.ns_per_step;
  p.note = rate.note;
  p.tasks = static_cast<double>(lane_batches(static_cast<std::size_t>(M), kLennardJonesLanes));  // the ensemble's batches of lanes (the scan before it: a small part)
  return p;
}

}  // namespace

Study lj_study() {
  return {.name = "lj",
          .makes = {{"004", "Fig. 6"}},
          .about = "the Lennard-Jones cluster: a step-size scan and the ensemble statistics at lj.h",
          .files = {"fig6_*.csv"},
          .keys = Schema()
                      .reals("lj.h_scan", positive(), 1, "Fig. 6: steps scanned for stability (004 prints h = 0.2)")
                      .real("lj.scan_t", positive(), "time span of the step-size scan")
                      .integer("lj.scan_size", at_least(1), "trajectories of the scan")
                      .real("lj.t_end", positive(), "Fig. 6 time span (004: 2e4)")
                      .real("lj.fit_from", {.gt = 0.0, .ge = {}, .lt = 1.0, .le = {}},
                            "Fig. 6: sigma ~ t^gamma and the growth of H(p^, q^) are fitted over [fit_from t_end, "
                            "t_end] (summary lj.fit)")
                      .integer("lj.size", at_least(2), "Fig. 6 trajectories (004: 400)")
                      .real("lj.blowup", positive(), "|H - H0| above this marks a scan run diverged"),
          .reads = {"lj.h", "lj.seed", "lj.perturbation", "samples", "checkpoint"},
          .run = run_lj,
          .validate = check_lj,
          .plan = plan_lj};
}

}  // namespace geomint::ti_drift
