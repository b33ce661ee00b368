// 004 Fig. 6, the printed step: sigma of the error of the modified energy E against h (a small ensemble of the starts
// of Fig. 6 over a short span). The random walk of (4.3) gives sigma ~ h^4 t^(1/2); the fitted exponent in h, and the
// step at which the published sigma at the published time would be reached (carried there by the published t^(1/2)).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/lennard_jones_ensemble.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint::ti_drift {
namespace {

using LJ = LennardJones<9>;  // 004 Fig. 6
void run_lj_steps(Context& ctx) {
  put_simplified_ti_method(ctx.summary, "lj_steps");
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 6: sigma against h");
  const LJ lj;
  const auto hs = s.reals("lj_steps.h");
  const auto M = static_cast<std::size_t>(s.integer("lj_steps.size"));
  const double T = s.real("lj_steps.t_end");
  const auto lanes = simplified_ti_lanes_kernels<LJ>().front().steps;  // (bit for bit the scalar method)
  const std::size_t nb = lane_batches(M, kLennardJonesLanes);  // per step h
  const auto err = concatenate(distributed_map(hs.size() * nb, [&](std::size_t task) {
    const double h = hs[task / nb];
    const LaneBatch batch = lane_batch(task % nb, M, kLennardJonesLanes);
    std::vector<LJ::State> starts;
    for (std::size_t i = batch.first; i < batch.first + batch.count; ++i) starts.push_back(lennard_jones_start(s, i));
    const std::int64_t n = steps_to(T, h);
    const auto last = simplified_ti_lanes(lj, lanes, std::span<const LJ::State>(starts), h, n, n, [](int, std::int64_t, const LJ::State&) {});
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
  Value per_h = Value::list();
  for (std::size_t k = 0; k < hs.size(); ++k) {
    const MeanDeviation md = mean_and_deviation(std::span<const double>(err.data() + k * M, M));
    out.row(hs[k], md.mean, md.sd, standard_error_of_deviation(md.sd, static_cast<double>(M)));
    log_h.push_back(std::log(hs[k])), log_sigma.push_back(std::log(md.sd));
    per_h.push_back({{"h", hs[k]}, {"sigma", md.sd}, {"mu", md.mean}});
  }
  ctx.write("fig6_steps.csv", out);
  const LinearFit fit = linear_fit(log_h, log_sigma);
  record_fit(ctx.summary, {"lj_steps.exponent", {"fig6_steps.csv", "h", "sigma"}, "power_law", *std::min_element(hs.begin(), hs.end()),
                           *std::max_element(hs.begin(), hs.end())});
  const double printed_sigma = ctx.published_value("lj_sigma_final"), printed_gamma = ctx.published_value("lj_sigma_exponent");
  const double printed_t = ctx.published_requirement("lj_sigma_final", "lj.t_end"), printed_h = ctx.published_value("lj_h");
  const double carry = std::pow(printed_t / T, printed_gamma);  // sigma(printed t) / sigma(T) of the random walk
  const double implied_h = std::exp((std::log(printed_sigma / carry) - fit.intercept) / fit.slope);
  ctx.summary["lj_steps"] = {
      {"t_end", T},
      {"size", M},
      {"sigma", per_h},
      {"exponent", fit.slope},
      // the slope's standard error from the relative standard error 1/sqrt(2(M-1)) of each sigma (the same starts
      // at every h, not independent ones: a scale, not a confidence bound)
      {"exponent_stderr", standard_error_of_deviation(1.0, static_cast<double>(M)) / std::sqrt(fit.sxx)},
      {"printed_sigma", printed_sigma},
      {"printed_t", printed_t},
      {"carry_to_printed_t", carry},
      {"implied_step", implied_h},  // the h at which the fit, carried to the printed t, gives the printed sigma
      {"implied_step_over_printed", implied_h / printed_h},
      {"sigma_at_printed_step", std::exp(fit.intercept + fit.slope * std::log(printed_h)) * carry}};
}

void check_lj_steps(const Scene& s) {
  for (double h : s.reals("lj_steps.h")) {
    check_lennard_jones_step(s, "lj_steps.h", h);
    if (s.real("lj_steps.t_end") / h < 1) s.reject("lj_steps.t_end", "must be at least one step of every lj_steps.h");
  }
}

StudyPlan plan_lj_steps(const Scene& s) {
  const double M = static_cast<double>(s.integer("lj_steps.size")), hs = static_cast<double>(s.reals("lj_steps.h").size());
  double steps = 0;
  for (double h : s.reals("lj_steps.h")) steps += M * s.real("lj_steps.t_end") / h;
  const double evals = steps * static_cast<double>(evals_per_step("simplified_takahashi_imada"));
  return {steps, evals, M * hs * 8, plan_rate("lennard-jones lanes").ns_per_step, plan_rate("lennard-jones lanes").note,
          static_cast<double>(lane_batches(static_cast<std::size_t>(M), kLennardJonesLanes)) * hs};
}

}  // namespace

Study lj_steps_study() {
  return {.name = "lj_steps",
          .makes = {{"004", "Fig. 6"}},
          .about = "sigma against h (the printed step)",
          .files = {"fig6_steps.csv"},
          .keys = Schema()
                      .reals("lj_steps.h", positive(), 3, "Fig. 6: steps at which sigma of the error of E is measured (its power of h)")
                      .integer("lj_steps.size", at_least(2), "trajectories per step of lj_steps (the starts of Fig. 6: lj.seed)")
                      .real("lj_steps.t_end", positive(), "time at which sigma is measured in lj_steps"),
          .reads = {"lj.seed", "lj.perturbation"},
          .run = run_lj_steps,
          .validate = check_lj_steps,
          .plan = plan_lj_steps};
}

}  // namespace geomint::ti_drift
