// 004 Fig. 3: Henon-Heiles k = 3 from one start, the modified energy E of (3.3) and (4.2) along the
// simplified method (1.6): bounded, no drift (the fitted slope over the run against the largest error).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint::ti_drift {
namespace {

using Z2 = PhaseState<2>;

void run_hh3(Context& ctx) {
  put_simplified_ti_method(ctx.summary, "hh3");
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 3: Henon-Heiles k = 3");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const HenonHeiles hh{{}, 3};
  const Z2 start = hh.start(s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"));
  const std::int64_t n = steps_to(s.real("hh3.t_end"), h), every = std::max<std::int64_t>(1, n / samples);
  const double E0 = simplified_ti_modified_energy(hh, start, h);
  Csv f3({"t", "E_err", "H_err"});
  std::vector<double> ts, es;
  double worst = 0, worst_H = 0;
  simplified_ti_integrate(hh, start, h, n, [&](std::int64_t j, const Z2& z) {
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
  const double drift = linear_fit(ts, es).slope;
  record_fit(ctx.summary, {"reproduced.hh3_drift_slope", {"fig3_hh3.csv", "t", "E_err"}, "slope", 0, ts.back()});
  record_fit(ctx.summary, {"hh3.E_err_peak_to_peak", {"fig3_hh3.csv", "t", "E_err"}, "ptp", 0, ts.back()});
  merge(ctx.summary, "reproduced", {{"hh3_drift_slope", drift}, {"hh3_max_E_err", worst}});
  const auto [e_lo, e_hi] = std::minmax_element(es.begin(), es.end());
  ctx.summary["hh3"] = {{"p1", start.p[0]},
                        {"steps", n},
                        {"sample_dt", static_cast<double>(every) * h},
                        {"E_err_peak_to_peak", *e_hi - *e_lo},
                        {"H_err_max", worst_H},
                        {"drift_over_run", drift * ts.back()},  // the fitted slope times the span
                        {"drift_over_run_share", std::abs(drift * ts.back()) / worst}};
}

void check_hh3(const Scene& s) {
  check_henon_heiles_starts(s, "hh3", HenonHeiles{{}, 3}, 0.0, true);
  if (s.real("hh3.t_end") / s.real("h") < 2) s.reject("hh3.t_end", "must be at least two steps h");
}

StudyPlan plan_hh3(const Scene& s) {
  const double n = s.real("hh3.t_end") / s.real("h");
  const PlanRate& rate = plan_rate("henon-heiles splitting");
  return {n, n * static_cast<double>(evals_per_step("simplified_takahashi_imada")),
          kept_samples(n, static_cast<double>(s.integer("samples"))) * (2 * 8 + 80), rate.ns_per_step, rate.note};
}

}  // namespace

Study hh3_study() {
  return {.name = "hh3",
          .makes = {{"004", "Fig. 3"}},
          .about = "the modified energy E of (3.3) and (4.2) on Henon-Heiles k = 3: bounded, no drift",
          .files = {"fig3_hh3.csv"},
          .keys = Schema().real("hh3.t_end", positive(), "Fig. 3 time span"),
          .reads = {"h", "samples", "hh3.q2", "hh3.p2", "hh.H0"},
          .run = run_hh3,
          .validate = check_hh3,
          .plan = plan_hh3};
}

}  // namespace geomint::ti_drift
