// 003 Fig. 5.1: a large cloud on a 3-sphere (shape.points points of radius shape.radius around
// cloud.center) under the reference flow (odeint Bulirsch-Stoer on (3.8)), its snapshots and the
// areas of its shadows on the (x, px) and (y, py) planes; and whether the flow is symplectic: the
// defect max |Phi^T Omega Phi - Omega| of the Jacobian of the exact flow (3.8), of the flow of H with
// N = 1, and of Psi_{h,E}^j, with the measure identity det Phi(t) = N(y(t)) / N(y0) as a check.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "geomint/analysis/phi_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/convex_area.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"
#include "geomint/systems/nonholonomic_variational.hpp"

namespace geomint::measure_cloud {
namespace {

// ---- Fig. 5.1: is the flow symplectic? The defect max |Phi^T Omega Phi - Omega| of its Jacobian ----

// The linear symplectic map (x, y, px, py) -> (x + y, y, px, py - px): Omega-preserving, shadow-area changing.
Point4 linear_symplectic_shear(const Point4& z) { return {z[0] + z[1], z[1], z[2], z[3] - z[2]}; }

// Along the trajectory from z0, at t_j = j h <= t_end: the defect of the Jacobian of the exact flow
// (3.8), of the flow of H with N = 1 (symplectic: the same odeint variational equations, so its
// defect is what the integration itself contributes), and of Psi_{h,E}^j with E = H(z0) fixed
// (symplectic: round-off only), for each scene method; and, for (3.8), the measure identity
// det Phi(t) = N(y(t)) / N(y0) (mu = N^{-1} d^4 z preserved) as a check of Phi.
void run_symplecticity(Context& ctx, const NonholonomicParticle& sys, const Point4& z0a, double t_end, double rtol,
                       double atol) {
  const Scene& s = ctx.scene;
  const double h = s.real("h");
  const auto methods = scene_discretizations(s);
  put_run_facts(ctx, methods);
  const std::int64_t n = steps_within(t_end, h);
  ctx.progress("Fig. 5.1: symplecticity defect of the flow");
  const Vec<4> z0(z0a[0], z0a[1], z0a[2], z0a[3]);
  const auto flows = parallel_map(2, [&](std::size_t k) {
    return variational_flow(sys, z0, k == 0 ? ParticleFlow::conformal : ParticleFlow::hamiltonian, h, n, rtol, atol);
  });
  const double E = sys.H(from_array(z0a));
  const auto psi = psi_symplecticity_defects(methods, sys, z0a, h, E, n);
  std::vector<std::string> cols{"t", "conformal_flow", "hamiltonian_flow", "measure_identity_err"};
  for (Discretization d : methods) cols.push_back(std::string("psi_") + discretization_name(d));
  Csv csv(cols);
  double ham_max = 0, measure_max = 0;
  const double N0 = NonholonomicParticle::N(z0[1]);
  for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
    const double dc = symplecticity_defect<4>(flows[0][j].Phi), dh = symplecticity_defect<4>(flows[1][j].Phi);
    const double m = std::abs(flows[0][j].Phi.determinant() * N0 / NonholonomicParticle::N(flows[0][j].z[1]) - 1);
    ham_max = std::max(ham_max, dh), measure_max = std::max(measure_max, m);
    csv << static_cast<double>(j) * h << dc << dh << m;
    for (const auto& p : psi) csv << p[j];
    csv.end_row();
  }
  ctx.write("shape_symplecticity.csv", csv);
  Value& r = ctx.summary["reproduced"]["symplecticity"];
  r["t_end"] = static_cast<double>(n) * h;
  r["samples"] = n + 1;
  r["conformal_flow_at_t_end"] = symplecticity_defect<4>(flows[0].back().Phi);
  Value at_snapshots = Value::list();  // at the snapshot times of Fig. 5.1
  const double dt = s.real("shape.snapshot_dt");
  for (std::int64_t k = 0; k <= s.integer("shape.snapshots"); ++k) {
    const std::int64_t j = std::llround(static_cast<double>(k) * dt / h);
    if (j <= n && std::abs(static_cast<double>(j) * h - static_cast<double>(k) * dt) < 1e-9)
      at_snapshots.push_back(symplecticity_defect<4>(flows[0][static_cast<std::size_t>(j)].Phi));
  }
  r["conformal_flow_at_snapshots"] = at_snapshots;
  r["hamiltonian_flow_max"] = ham_max;
  // the defect of (3.8) at the last snapshot over the floor of the integration, the symplectic flow's largest
  // defect (at least the unit round-off)
  r["conformal_flow_over_floor"] = symplecticity_defect<4>(flows[0].back().Phi) /
                                   std::max(ham_max, std::numeric_limits<double>::epsilon());
  r["measure_identity_max_err"] = measure_max;
  Value psi_max;
  for (std::size_t k = 0; k < methods.size(); ++k)
    psi_max[discretization_name(methods[k])] = *std::max_element(psi[k].begin(), psi[k].end());
  put_methods(ctx, "psi_max", psi_max, "symplecticity");
}

// ---- Fig. 5.1: a large cloud on a 3-sphere under the reference flow ----

// The sum of the shadow areas describes the figure; it is not a symplectic invariant: the linear
// symplectic map S (x, y, px, py) = (x + y, y, px, py - px), the time-1 flow of the Hamiltonian y px,
// changes it (for a round ball from 2 pi r^2 to 2 sqrt(2) pi r^2), here applied to the cloud at t = 0
// (area sum `sum0`). Its relative change is set against the error of the hulls as areas of the shadows,
// known exactly for the ball before and after S: the sum of the two relative errors bounds the error of
// the change.
void put_shear(Context& ctx, const std::vector<std::vector<Point4>>& paths, double sum0, double radius) {
  std::vector<std::array<double, 2>> a, b;
  for (const auto& p : paths) {
    const Point4 z = linear_symplectic_shear(p.front());
    a.push_back({z[0], z[2]}), b.push_back({z[1], z[3]});
  }
  const double after = convex_area(a) + convex_area(b), ball = 2 * std::numbers::pi * radius * radius;
  ctx.summary["reproduced"]["shape_area_sum_after_shear"] = after;
  ctx.summary["reproduced"]["shape_area_sum_round_ball"] = ball;
  const double change = after / sum0 - 1;
  const double hull_error = std::abs(sum0 / ball - 1) + std::abs(after / (std::numbers::sqrt2 * ball) - 1);
  ctx.summary["reproduced"]["shape_area_sum_shear_change"] = change;
  ctx.summary["reproduced"]["shape_area_sum_hull_error"] = hull_error;
  ctx.summary["reproduced"]["shape_area_sum_shear_change_over_hull_error"] = hull_error > 0 ? Value(std::abs(change) / hull_error) : Value();
}

void run_shape(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = particle_setup(s);
  const auto [rtol, atol] = reference_tolerances(s);
  ctx.progress("Fig. 5.1: sphere cloud, reference flow");
  put_run_facts(ctx, {});
  SpherePoints gen(static_cast<std::uint64_t>(s.integer("seed")));
  std::vector<Point4> unit;
  for (std::int64_t i = 0; i < s.integer("shape.points"); ++i) unit.push_back(gen.next());
  const auto cloud = scaled_cloud(unit, z0, s.real("shape.radius"));
  const double dt = s.real("shape.snapshot_dt");
  const std::int64_t snaps = s.integer("shape.snapshots");
  const auto paths = reference_paths(sys, cloud, dt, snaps, rtol, atol);
  Csv pts({"t", "x", "y", "px", "py"}), areas({"t", "area_x_px", "area_y_py", "area_sum"});
  std::vector<double> sums;
  for (std::int64_t j = 0; j <= snaps; ++j) {
    std::vector<std::array<double, 2>> a, b;
    for (const auto& p : paths) {
      const Point4& z = p[static_cast<std::size_t>(j)];
      pts.row(static_cast<double>(j) * dt, z[0], z[1], z[2], z[3]);
      a.push_back({z[0], z[2]}), b.push_back({z[1], z[3]});
    }
    const double ax = convex_area(a), ay = convex_area(b);
    areas.row(static_cast<double>(j) * dt, ax, ay, ax + ay);
    sums.push_back(ax + ay);
  }
  ctx.write("shape.csv", pts);
  ctx.write("shape_areas.csv", areas);
  put_shear(ctx, paths, sums.front(), s.real("shape.radius"));
  ctx.summary["reproduced"]["shape_area_sum"] = sums;  // a description of the figure, not an invariant
  ctx.summary["reproduced"]["shape_area_sum_last"] = sums.back();
  ctx.summary["reproduced"]["shape_t_end"] = static_cast<double>(snaps) * dt;  // the time of the last snapshot
  run_symplecticity(ctx, sys, z0, static_cast<double>(snaps) * dt, rtol, atol);
}

StudyPlan plan_shape(const Scene& s) {
  const double snaps = static_cast<double>(s.integer("shape.snapshots")), points = static_cast<double>(s.integer("shape.points"));
  const double n = step_count_within(snaps * s.real("shape.snapshot_dt"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  return phi_plan(M * n + points * snaps + 2 * n, points * (snaps + 1) * kPointBytes * 2 + (2 + M) * (n + 1) * 20 * 8, plan_rate("cloud shape"));
}

}  // namespace

Study shape_study() {
  return {.name = "shape",
          .makes = {{"003", "Fig. 5.1"}},
          .about = "a large cloud on a 3-sphere under the reference flow: snapshots, shadow areas, symplecticity",
          .files = {"shape.csv", "shape_areas.csv", "shape_symplecticity.csv"},
          .keys = Schema()
                      .integer("seed", at_least(0), "seed of the random cloud of Fig. 5.1")
                      .integer("shape.points", at_least(5), "points on the 3-sphere of Fig. 5.1 (003: 5000)")
                      .real("shape.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxCloudRadius},
                            "radius of that sphere (003: 0.3)")
                      .real("shape.snapshot_dt", positive(), "time between snapshots (003: 2.75)")
                      .integer("shape.snapshots", at_least(1), "snapshots after t = 0 (003: 5)"),
          .reads = {"potential", "cloud.center", "h", "methods", "reference"},
          .run = run_shape,
          .validate = [](const Scene& s) { check_first_conformal_step(s, "h", {s.real("h")}); },
          .plan = plan_shape};
}

}  // namespace geomint::measure_cloud
