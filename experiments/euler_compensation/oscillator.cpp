// 000 Fig 8: symplectic Euler (42)-(43) on the oscillator (74), with and without the compensating
// point transformation (82): phase portraits over oscillator.steps steps and their energy errors.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"

namespace geomint::euler_compensation {
namespace {

using State = PhaseState<1>;

constexpr int kExactCurvePoints = 400;  // resolution of the exact curve

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 8: phase portraits");
  const HarmonicOscillator osc;  // (74)
  const State z0 = oscillator_start(s);
  const double H0 = osc.H(z0);
  const double h = s.real("oscillator.h"), k = s.real("oscillator.k");
  const auto se = SymplecticEulerPQ::bind(osc);
  const auto compensated = CompensatedSymplecticEuler::bind(osc, k);
  Csv phase({"j", "t", "q_se", "p_se", "q_compensated", "p_compensated", "energy_err_se", "energy_err_compensated"});
  const std::int64_t n = s.integer("oscillator.steps");
  std::vector<State> zs;
  integrate(se, z0, h, n, [&](std::int64_t, const State& z) { zs.push_back(z); });
  ErrorSeries err_se, err_comp;
  double max_qhat = 0, dist_se = 0, dist_comp = 0;  // largest distance from the exact orbit, the circle through z0
  const double radius = std::hypot(z0.q[0], z0.p[0]);
  integrate(compensated, z0, h, n, [&](std::int64_t j, const State& zc) {
    check_compensated_state(zc, "compensated_symplectic_euler", j, h);
    const State& z = zs[static_cast<std::size_t>(j)];
    const double e_se = osc.H(z) - H0, e_comp = osc.H(zc) - H0;
    err_se.add(e_se), err_comp.add(e_comp);
    dist_se = std::max(dist_se, std::abs(std::hypot(z.q[0], z.p[0]) - radius));
    dist_comp = std::max(dist_comp, std::abs(std::hypot(zc.q[0], zc.p[0]) - radius));
    max_qhat = std::max(max_qhat, std::abs(OscillatorCompensation{k, h}.qhat(zc.q[0])));
    phase.row(j, static_cast<double>(j) * h, z.q[0], z.p[0], zc.q[0], zc.p[0], e_se, e_comp);
  });
  ctx.write("fig8_phase.csv", phase);
  Csv exact({"t", "q", "p"});
  for (int i = 0; i <= kExactCurvePoints; ++i) {
    const double t = 2 * std::numbers::pi * i / kExactCurvePoints;
    const State e = osc.exact(z0, t);
    exact.row(t, e.q[0], e.p[0]);
  }
  ctx.write("fig8_exact.csv", exact);
  auto& reproduced = ctx.summary["reproduced"];
  reproduced["fig8_max_energy_err_se"] = err_se.max_abs();
  reproduced["fig8_max_energy_err_compensated"] = err_comp.max_abs();
  reproduced["fig8_max_abs_qhat"] = max_qhat;
  // the phase portrait's distance from the exact solution's orbit: without (82) over with it
  reproduced["fig8_max_orbit_distance_se"] = dist_se;
  reproduced["fig8_max_orbit_distance_compensated"] = dist_comp;
  reproduced["fig8_orbit_distance_ratio"] = dist_comp > 0 ? Value(dist_se / dist_comp) : Value();  // (null: on the orbit)
  // (Fig 8's curves: the columns *_se, then *_compensated)
  ctx.summary["methods"]["oscillator"] = labels_of({"symplectic_euler_pq", "compensated_symplectic_euler"});
}

StudyPlan plan_oscillator(const Scene& s) {
  const double n = static_cast<double>(s.integer("oscillator.steps"));
  const PlanRate& rate = plan_rate("oscillator compensated symplectic euler");
  return {2 * n, 2 * n, (n + 1) * (sizeof(State) + 8 * kCsvCellBytes), rate.ns_per_step, rate.note};
}

}  // namespace

Study oscillator_study() {
  return {.name = "oscillator",
          .makes = {{"000", "Fig. 8"}},
          .about = "symplectic Euler (42)-(43) on the oscillator (74), with and without the transformation (82)",
          .files = {"fig8_phase.csv", "fig8_exact.csv"},
          .keys = Schema().integer("oscillator.steps", at_least(1), "number of steps in Fig 8"),
          .reads = {"oscillator"},
          .run = run_oscillator,
          .validate = [](const Scene& s) { check_compensated_step(s, "oscillator.h", s.real("oscillator.h")); },
          .plan = plan_oscillator};
}

}  // namespace geomint::euler_compensation
