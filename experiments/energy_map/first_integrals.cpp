// 000 Sec. 5.2, the free particle (m = 1): symplectic Euler (42)-(43) in polar coordinates changes
// p_x by O(h^2) per step (first_integrals.csv, its fitted order), while in Cartesian coordinates it
// keeps the angular momentum x p_y - y p_x, a quadratic invariant, up to round-off (with and without
// compensated summation: angular_momentum.csv).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/core/state.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/transforms/polar.hpp"

namespace geomint::energy_map {
namespace {

void check_first_integrals(const Scene& s) {
  for (const auto& row : s.real_rows("first_integrals.initial"))
    if (row[0] == 0.0 && row[1] == 0.0) s.reject("first_integrals.initial", "polar coordinates are singular at x = y = 0");
}

StudyPlan plan_first_integrals(const Scene& s) {
  const double polar = static_cast<double>(s.reals("first_integrals.h").size() * s.real_rows("first_integrals.initial").size());
  const double steps = polar + 2 * (static_cast<double>(s.integer("first_integrals.steps")) + 1);  // plain and compensated
  const PlanRate& rate = plan_rate("energy map scalar loop");
  return {steps, steps, 1001 * 100.0, rate.ns_per_step, rate.note};  // angular_momentum.csv: at most 1001 rows
}

// ---- Section 5.2, free particle (m = 1): polar symplectic Euler changes p_x by
// O(h^2) per step; Cartesian symplectic Euler keeps x p_y - y p_x ----

void run_first_integrals(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("first integrals");
  const FreeParticleCartesian free_cart{1.0, {}};
  const FreeParticlePolar free_polar{1.0, {}};
  const auto hs = s.reals("first_integrals.h");
  const auto starts = s.real_rows("first_integrals.initial");
  // Per step h: the max over the given states of |p_x^{j+1} - p_x^j| after one polar step.
  const std::vector<double> change = distributed_map(hs.size(), [&](std::size_t k) {
    double worst = 0;
    for (const auto& row : starts) {
      const auto z = make_state<2>(Vec<2>(row[0], row[1]), Vec<2>(row[2], row[3]));
      const auto next = cartesian_from_polar(symplectic_euler_pq(free_polar, polar_from_cartesian(z), hs[k]));
      worst = std::max(worst, std::abs(next.p[0] - z.p[0]));
    }
    return worst;
  });
  // first_integrals.csv (one step per h) and the order of the change over the changes above round-off.
  ConvergenceStudy conv({.csv = "first_integrals.csv", .h = hs, .steps = std::vector<double>(hs.size(), 1.0)});
  conv.column("px_change_per_step", change).fit("polar_px_change_per_step", "px_change_per_step", roundoff_floor());
  conv.write(ctx);

  // The angular momentum is a quadratic invariant of symplectic Euler (a P-series
  // method), preserved exactly in exact arithmetic; in floating point the
  // particle runs off to |q| ~ h |p| n and plain summation random-walks the
  // round-off, so the run is made with and without compensated summation.
  Csv lcsv({"j", "t", "L_rel_drift_plain", "L_rel_drift_compensated"});
  const auto zL = make_state<2>(Vec<2>(starts[0][0], starts[0][1]), Vec<2>(starts[0][2], starts[0][3]));
  const double L0 = angular_momentum(zL), hL = *std::min_element(hs.begin(), hs.end());
  const std::int64_t nL = s.integer("first_integrals.steps"), every = std::max<std::int64_t>(1, nL / 1000);
  double L_drift_plain = 0, L_drift = 0;
  PhaseState<2> zp = zL;
  CompensatedState<2> zc{zL};
  for (std::int64_t j = 0; j <= nL; ++j) {
    if (j > 0) zp = symplectic_euler_pq(free_cart, zp, hL), zc = symplectic_euler_pq(free_cart, zc, hL);
    const double dp = std::abs(angular_momentum(zp) - L0) / std::abs(L0);
    const double dc = std::abs(angular_momentum(zc.z) - L0) / std::abs(L0);
    L_drift_plain = std::max(L_drift_plain, dp), L_drift = std::max(L_drift, dc);
    if (j % every == 0) lcsv.row(j, static_cast<double>(j) * hL, dp, dc);
  }
  ctx.write("angular_momentum.csv", lcsv);

  ctx.summary["methods"]["first_integrals"] = labels_of({"symplectic_euler_pq"});  // (42)-(43), stepped above
  ctx.summary["reproduced"]["cartesian_L_max_rel_drift"] = L_drift;  // with compensated summation
  ctx.summary["reproduced"]["cartesian_L_max_rel_drift_plain"] = L_drift_plain;
  // |q_J| at the end of the angular-momentum run, and the round-off of evaluating L = x p_y - y p_x
  // there: eps |q_J| |p| / |L_0| (p is constant for the free particle).
  const double q_end = zc.z.q.norm();
  ctx.summary["first_integrals"] = {
      {"h", h_range(hs)},
      {"initial_conditions", starts.size()},
      {"px_local_order", local_order(hs, change)},  // (observables/order_fit.hpp)
      {"q_end", q_end},
      {"L_eval_roundoff", std::numeric_limits<double>::epsilon() * q_end * zL.p.norm() / std::abs(L0)}};
}

}  // namespace

Study first_integrals_study() {
  return {.name = "first_integrals",
          .makes = {{"000", "Sec. 5.2"}},
          .about = "polar symplectic Euler changes p_x by O(h^2) per step; Cartesian keeps the angular momentum",
          .files = {"first_integrals.csv", "orders.csv", "angular_momentum.csv"},
          .keys = Schema()
                      .reals("first_integrals.h", positive(), 3, "steps for the change of p_x per step in polar coordinates")
                      .real_rows("first_integrals.initial", 4, any_finite(), 1,
                                 "free-particle states [x, y, px, py], x, y not both 0")
                      .integer("first_integrals.steps", at_least(1), "steps of the Cartesian angular-momentum run"),
          .run = run_first_integrals,
          .validate = check_first_integrals,
          .plan = plan_first_integrals};
}

}  // namespace geomint::energy_map
