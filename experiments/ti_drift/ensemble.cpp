// 004 Fig. 4: Henon-Heiles k (hh.k, 004: 5), an ensemble of perturbed starts along the simplified method (1.6)
// (in SIMD lanes, bit for bit the scalar method; checkpointed): the mean and standard deviation of the error of
// the modified energy E of (3.3) and (4.2), its random walk (sigma^2 against t) and the outliers. Its trajectory
// with the largest error goes to Fig. 5, the Poincare cuts and growth episodes (study poincare, poincare.cpp),
// when that study runs in the same process; alone, that study integrates the ensemble too
// (sweep/henon_heiles_ensemble.hpp: the ensemble, its starts, checkpoint and the hand-over).
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
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/henon_heiles_ensemble.hpp"

namespace geomint::ti_drift {
namespace {

// Fig. 4: the mean and standard deviation over the ensemble at each output time (fig4_stats.csv).
struct Stats {
  std::vector<double> ts, mus, sigmas;
};

Stats write_stats(Context& ctx, const HenonHeilesEnsemble& run, Value& reproduced) {
  const auto& series = run.series;
  const std::size_t ns = run.ns;
  const double t_end = run.t_end;
  const auto time_of = [&](std::size_t k) { return run.time_of(k); };
  Csv f4s({"t", "mu", "sigma"});
  std::vector<double> ts;
  const EnsembleMoments m = ensemble_moments(series);
  for (std::size_t k = 0; k < ns; ++k) {
    f4s.row(time_of(k), m.mean[k], m.sd[k]);
    ts.push_back(time_of(k));
  }
  ctx.write("fig4_stats.csv", f4s);
  reproduced["hh5_mu_final"] = m.mean.back(), reproduced["hh5_sigma_final"] = m.sd.back();
  const double t_fit = fit_window_start(ctx.scene, "ensemble", t_end);  // past the bounded part
  reproduced["hh5_sigma_exponent"] = power_law_exponent(ts, m.sd, t_fit);
  // its standard error over the ensemble (bootstrap over the trajectories: published.toml's tolerance)
  reproduced["hh5_sigma_exponent_stderr"] = bootstrap_exponent_stderr(
      series, ts, t_fit, kBootstrapResamples, static_cast<std::uint64_t>(ctx.scene.integer("ensemble.seed")));
  return {ts, m.mean, m.sd};
}

// Every trajectory's series (thinned to at most 200 times) and the outliers.
struct Outliers {
  Value outliers;
  std::vector<std::size_t> kept;
  std::size_t stride;  // of the thinned times
};

Outliers write_trajectories(Context& ctx, const HenonHeilesEnsemble& run, Value& reproduced) {
  const Scene& s = ctx.scene;
  const auto& series = run.series;
  const std::size_t M = run.M, ns = run.ns;
  const auto time_of = [&](std::size_t k) { return run.time_of(k); };
  Csv f4t({"trajectory", "outlier", "t", "E_err"});
  Value outliers = Value::list();
  std::vector<std::size_t> kept;
  const std::size_t stride = std::max<std::size_t>(1, ns / 200);
  for (std::size_t i = 0; i < M; ++i) {
    const bool out = largest_abs(series[i]) > s.real("ensemble.outlier");
    if (out) outliers.push_back(i);
    else kept.push_back(i);
    for (std::size_t k = 0; k < ns; k += stride)
      f4t.row(static_cast<std::int64_t>(i), static_cast<std::int64_t>(out), time_of(k), series[i][k]);
  }
  ctx.write("fig4_trajectories.csv", f4t);
  reproduced["hh5_outliers"] = outliers;
  return {outliers, kept, stride};
}

// The statistics without the outliers, at the times of fig4_trajectories.csv; p1: of the unperturbed start.
Value ensemble_summary(const Context& ctx, double p1, const HenonHeilesEnsemble& run, const Stats& st, const Outliers& out) {
  const Scene& s = ctx.scene;
  const std::vector<double>& ts = st.ts;
  const std::vector<double>& mus = st.mus;
  const std::vector<double>& sigmas = st.sigmas;
  const Value& outliers = out.outliers;
  const std::vector<std::size_t>& kept = out.kept;
  const std::size_t stride = out.stride;
  const auto& series = run.series;
  const std::size_t M = run.M, ns = run.ns;
  const double t_end = run.t_end;
  const double t_fit = fit_window_start(s, "ensemble", t_end);
  const std::int64_t n4 = run.n4;
  const auto time_of = [&](std::size_t k) { return run.time_of(k); };
  Value ensemble = {{"p1", p1},
                    {"steps", n4},
                    {"sample_dt", time_of(1)},
                    {"thinned_dt", time_of(stride)},
                    {"outliers", outliers.size()},
                    {"kept", kept.size()}};
  if (kept.size() >= 2) {
    const EnsembleMoments m = ensemble_moments(series, kept, stride);
    std::vector<double> tk;
    for (std::size_t k : m.k) tk.push_back(time_of(k));
    ensemble["without_outliers"] = {{"mu_final", m.mean.back()}, {"sigma_final", m.sd.back()},
                                    {"sigma_exponent", power_law_exponent(tk, m.sd, t_fit)}};
  }
  // The mean: at the first output time after the start, and over the fit window [t_fit, t_end].
  std::vector<double> mu_late, sigma2(sigmas.size());
  for (std::size_t k = 0; k < ns; ++k) {
    if (ts[k] >= t_fit) mu_late.push_back(mus[k]);
    sigma2[k] = sigmas[k] * sigmas[k];
  }
  ensemble["mu_first"] = {{"t", ts.at(1)}, {"mu", mus.at(1)}};
  ensemble["mu_late"] = spread_of(mu_late);
  ensemble["mu_final_stderr"] = standard_error_of_mean(sigmas.back(), static_cast<double>(M));
  ensemble["mu_final_in_stderr"] = mus.back() / ensemble.at("mu_final_stderr").number();  // how far from zero
  ensemble["sigma_rel_stderr"] = standard_error_of_deviation(1.0, static_cast<double>(M));
  ensemble["sigma_exponent_from_hundredth"] = power_law_exponent(ts, sigmas, t_fit / 10);  // a window ten times longer
  // sigma^2 = c + D t of a random walk: D at t_end, and the slope of sigma^2 over the fit window.
  ensemble["sigma2_over_t"] = sigma2.back() / ts.back();
  ensemble["sigma2_slope"] = slope_from(ts, sigma2, t_fit);
  ensemble["fit"] = {{"t_min", t_fit}, {"t_max", t_end}};
  // The same from the printed sigma, at the printed time (published.toml: hh5_sigma_final).
  const double printed_sigma = ctx.published_value("hh5_sigma_final");
  const double printed_t = ctx.published_requirement("hh5_sigma_final", "t_end");
  ensemble["printed_sigma2_over_t"] = printed_sigma * printed_sigma / printed_t;
  ensemble["sigma2_over_t_minus_printed"] = ensemble.at("sigma2_over_t").number() - printed_sigma * printed_sigma / printed_t;
  // The printed sigma against ours carried to the printed time by the printed law sigma ~ t^gamma (published.toml:
  // hh5_sigma_exponent), in standard errors of ours (relative 1/sqrt(2(M-1))): a check that the quick scene can make.
  const double gamma_printed = ctx.published_value("hh5_sigma_exponent");
  const double carried = sigmas.back() * std::pow(printed_t / ts.back(), gamma_printed);
  ensemble["printed_sigma_check"] = {
      {"printed", printed_sigma},
      {"carried_to_printed_t", carried},
      {"exponent", gamma_printed},
      {"score", std::abs(carried - printed_sigma) / (carried * standard_error_of_deviation(1.0, static_cast<double>(M)))}};
  return ensemble;
}

void run_ensemble(Context& ctx, LargestError& largest) {
  put_simplified_ti_method(ctx.summary, "ensemble");
  const Scene& s = ctx.scene;
  const HenonHeilesEnsemble run = integrate_ensemble(ctx);
  Value reproduced;
  const Stats stats = write_stats(ctx, run, reproduced);
  const Outliers out = write_trajectories(ctx, run, reproduced);
  const double p1 = with_ensemble_system(s, [&](const auto& hhk) {  // of the unperturbed start
    return hhk.start(s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0")).p[0];
  });
  const Value ensemble = ensemble_summary(ctx, p1, run, stats, out);
  merge(ctx.summary, "reproduced", reproduced);
  ctx.summary["ensemble"] = ensemble;
  largest = trajectory_of(run, largest_error(run));  // (Fig. 5: the poincare study of this process)
  const double t_fit = fit_window_start(ctx.scene, "ensemble", run.t_end), t_last = stats.ts.back();
  record_fit(ctx.summary, {"reproduced.hh5_sigma_exponent", {"fig4_stats.csv", "t", "sigma"}, "power_law", t_fit, t_last, "ensemble.fit_from"});
  record_fit(ctx.summary, {"ensemble.sigma_exponent_from_hundredth", {"fig4_stats.csv", "t", "sigma"}, "power_law", t_fit / 10,
                           t_last, "ensemble.fit_from", 0.1});
  record_fit(ctx.summary, {"ensemble.sigma2_slope", {"fig4_stats.csv", "t", "sigma^2"}, "slope", t_fit, t_last, "ensemble.fit_from"});
  record_unfittable(ctx.summary, "ensemble.without_outliers.sigma_exponent",
                    "the ensemble without its outliers at every output time: fig4_trajectories.csv holds the "
                    "trajectories at thinned times only");
  const double wall4 = run.wall4;
  const std::size_t M = run.M;
  const std::int64_t n4 = run.n4;
  merge(ctx.summary, "timing",
      {{"fig4_wall_s", wall4},
       {"threads", ctx.threads},
       {"fig4_steps", static_cast<double>(M) * static_cast<double>(n4)},  // over the ensemble
       {"fig4_ns_per_step_thread",
        1e9 * wall4 * ctx.threads / (static_cast<double>(M) * static_cast<double>(n4))}});
}

StudyPlan plan_ensemble(const Scene& s) {
  const double n = s.real("t_end") / s.real("h"), M = static_cast<double>(s.integer("ensemble.size"));
  const double rows = kept_samples(n, static_cast<double>(s.integer("samples")));
  const PlanRate& lanes = plan_rate("henon-heiles lanes");
  // M trajectories; the series of all M (and the copy of the one handed to Fig. 5), and the CSVs
  return {M * n, M * n * static_cast<double>(evals_per_step("simplified_takahashi_imada")),
          (M + 1) * rows * 8 + M * std::min(rows, 201.0) * 60, lanes.ns_per_step, lanes.note,
          static_cast<double>(lane_batches(static_cast<std::size_t>(M), kHenonHeilesLanes))};  // (tasks: batches of lanes)
}

}  // namespace

Study ensemble_study(LargestError& largest) {
  std::vector<std::string> reads = kEnsembleKeys;  // (main.cpp's shared keys: the poincare study reads them too)
  reads.emplace_back("checkpoint");
  return {.name = "ensemble",
          .makes = {{"004", "Fig. 4"}},
          .about = "the random walk of the error of E over an ensemble on Henon-Heiles k: mean, sigma, outliers",
          .files = {"fig4_stats.csv", "fig4_trajectories.csv"},
          .keys = Schema()
                      .real("ensemble.fit_from", {.gt = 0.0, .ge = {}, .lt = 1.0, .le = {}},
                            "Fig. 4: sigma ~ t^gamma, the late mean and the slope of sigma^2 are fitted over [fit_from "
                            "t_end, t_end] (summary ensemble.fit; 004: past the bounded part, 0.1)")
                      .real("ensemble.outlier", positive(),
                            "trajectories whose max |error| exceeds this go to Fig. 4's upper panel (004: 2e-6)"),
          .reads = reads,
          .run = [&largest](Context& ctx) { run_ensemble(ctx, largest); },
          .validate = check_ensemble_run,
          .plan = plan_ensemble};
}

}  // namespace geomint::ti_drift
