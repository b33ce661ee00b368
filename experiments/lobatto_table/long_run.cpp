// 001 Fig. 2: the discrete energy H_d of (15) and the energy H over long_run.periods periods of the oscillator,
// iterating the Lobatto one-step matrix (13) with plain and with compensated summation; the window maxima of their
// errors, their growth rates per period, and the growth in exact arithmetic (the closed-form orbit of (13)-(14)).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/core/compensated_sum.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/drift.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

// One run of Fig. 2 (a record of runner/distributed_map.hpp).
struct Long {
  std::vector<double> plain, comp, H;       // window maxima
  double slope_plain, slope_comp, slope_H, per_window;  // per period; the periods of a window
  auto fields() { return std::tie(plain, comp, H, slope_plain, slope_comp, slope_H, per_window); }
};

// One run at step h: the window maxima of |H_d - H_d(0)| (plain and compensated) and of |H - H(0)|.
Long long_run(const Scene& s, const OscillatorFromRest& o, double h, std::int64_t windows) {
  const auto& [osc, A, T, z0] = o;
  const std::int64_t n = std::llround(s.real("long_run.periods") * T / h), per = std::max<std::int64_t>(1, n / windows);
  const Mat<2> Phi = one_step_pq_matrix("lobatto", osc, h), PhiI = Phi - Mat<2>::Identity();
  const double Hd0 = discrete_energy(Phi, z0), H0 = osc.H(z0);
  WindowMaxima wp(per), wc(per), wH(per);
  Vec<2> x(z0.p[0], z0.q[0]), y = x, c = Vec<2>::Zero();
  for (std::int64_t j = 1; j <= n; ++j) {
    x = Phi * x;                              // (13)
    compensated_add(y, c, Vec<2>(PhiI * y));  // (13) as y + (Phi - I) y, compensated
    wp.add(discrete_energy(Phi, make_state(x[1], x[0])) - Hd0);
    wc.add(discrete_energy(Phi, make_state(y[1], y[0])) - Hd0);
    wH.add(osc.H(make_state(x[1], x[0])) - H0);
  }
  const double per_window = static_cast<double>(per) * h / T;
  return Long{wp.maxima(), wc.maxima(), wH.maxima(), wp.slope_per_window() / per_window,
              wc.slope_per_window() / per_window, wH.slope_per_window() / per_window, per_window};
}

void run_long_run(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 2: long runs");
  const OscillatorFromRest o = oscillator_from_rest(s);
  const auto& [osc, A, T, z0] = o;
  const auto long_h = s.reals("long_run.h");
  const std::int64_t windows = s.integer("long_run.windows");
  const auto longs = distributed_map(long_h.size(), [&](std::size_t i) { return long_run(s, o, long_h[i], windows); });
  Csv f2({"h", "period", "Hd_err_plain", "Hd_err_compensated", "H_err"});
  Value growth, growth_comp, growth_H;
  for (std::size_t i = 0; i < long_h.size(); ++i) {
    const Long& l = longs[i];
    for (std::size_t k = 0; k < l.plain.size(); ++k)
      f2.row(long_h[i], static_cast<double>(k + 1) * l.per_window, l.plain[k], l.comp[k], l.H[k]);
    const std::string h = format_double(long_h[i]);
    growth[h] = l.slope_plain, growth_comp[h] = l.slope_comp, growth_H[h] = l.slope_H;
  }
  ctx.write("fig2_energy.csv", f2);
  // Growth rates: least-squares slope, per period, of the window maxima of |H - H(0)| (Fig. 2's quantity, compared
  // in published.toml), and of |H_d - H_d(0)| with plain and with compensated summation (the round-off of (15)).
  merge(ctx.summary, "reproduced", {{"energy_growth_rate", growth_H}, {"energy_growth_rate_Hd", growth},
                                    {"energy_growth_rate_Hd_compensated", growth_comp}});
  // Per step size (by index): the rates again; the largest H_d errors; the growth rate of the same window maxima in
  // exact arithmetic (the orbit of (13)-(14)), with what the drift of H_d explains of it; and the printed rate.
  Value rates = Value::list(), exact_by_h, roundoff_by_h;  // (the last two: published.toml's roundoff of Fig. 2)
  for (std::size_t i = 0; i < long_h.size(); ++i) {
    const double h = long_h[i];
    const Long& l = longs[i];
    Value r = {{"h", h}, {"steps_per_period", T / h}, {"H_rate", l.slope_H}, {"Hd_rate", l.slope_plain},
               {"Hd_rate_compensated", l.slope_comp}, {"Hd_err_max", *std::max_element(l.plain.begin(), l.plain.end())},
               {"Hd_err_max_compensated", *std::max_element(l.comp.begin(), l.comp.end())}};
    const auto exact = lobatto_exact_growth(h, osc.m, osc.w, A, s.real("long_run.periods"), windows);
    if (const auto orbit = lobatto_exact_orbit(h, osc.m, osc.w, A); exact && orbit) {
      r["exact_rate"] = exact->slope_per_period;
      r["H_rate_minus_exact"] = l.slope_H - exact->slope_per_period;
      r["bound"] = exact->bound;  // |K|
      r["periods_to_peak"] = Value(exact->periods_to_peak);  // (null: none)
      r["roundoff_in_H"] = orbit->H0 / orbit->Hd0 * std::abs(l.slope_plain);  // a drift of H_d seen in H
      r["Hd_drift_per_step"] = std::abs(l.slope_plain) * h / T / orbit->Hd0;  // relative, per step
      exact_by_h[format_double(h)] = exact->slope_per_period, roundoff_by_h[format_double(h)] = r.at("roundoff_in_H");
    }
    rates.push_back(r);
  }
  merge(ctx.summary, "reproduced", {{"energy_growth_rate_exact", exact_by_h}, {"energy_growth_rate_roundoff", roundoff_by_h}});
  if (const auto published = ctx.comparison(ctx.summary, "reproduced.energy_growth_rate"))  // 001 Fig. 2, per h
    for (std::size_t i = 0; i < long_h.size(); ++i)
      if (const Value* rate = published->at("published").find(format_double(long_h[i]))) rates.at(i)["published_rate"] = *rate;
  ctx.summary["long_run"] = {{"window_periods", s.real("long_run.periods") / static_cast<double>(windows)}, {"rates", rates}};
}

StudyPlan plan_long_run(const Scene& s) {
  const double periods = s.real("long_run.periods"), T = oscillator_from_rest(s).T;
  const double windows = static_cast<double>(s.integer("long_run.windows")), runs = static_cast<double>(s.reals("long_run.h").size());
  const double steps = steps_to_each(periods * T, s.reals("long_run.h"));
  const PlanRate& rate = plan_rate("oscillator one-step matrix");
  return {steps, 0, runs * windows * (3 * sizeof(double) + 5 * kCsvCellBytes), rate.ns_per_step,
          "iterates the one-step matrix (13), no force evaluations; " + rate.note};
}

}  // namespace

Study long_run_study() {
  return {.name = "long_run",
          .makes = {{"001", "Fig. 2"}},
          .about = "Lobatto's errors of H and H_d (15) over long_run.periods periods, plain and compensated summation",
          .files = {"fig2_energy.csv"},
          .keys = Schema()
                      .reals("long_run.h", positive(), 1, "steps of Fig. 2 (001: 0.1, 0.05, 0.025)")
                      .integer("long_run.windows", at_least(2), "windows for the maxima of the energy error"),
          .reads = {"long_run.periods", "oscillator"},
          .run = run_long_run,
          .validate = [](const Scene& s) { check_lobatto_bound(s, {"long_run.h", s.real("oscillator.omega")}); },
          .plan = plan_long_run};
}

}  // namespace geomint::lobatto_table
