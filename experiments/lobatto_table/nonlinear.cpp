// Nonlinear Lagrangians: the Lobatto variational integrator with Newton's method on the nonlinear
// pendulum L = qdot^2/2 + cos q and on a planar elastic pendulum, against odeint's Bulirsch-Stoer
// reference at nonlinear.t_end: the fitted orders (6), the Newton iterations per step, the compared
// methods' errors, and the symplecticity of the one-step maps.
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/galerkin_steps.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "lobatto_table.hpp"

namespace geomint::lobatto_table {
namespace {

// Errors of the nonlinear study below this many times the reference's absolute tolerance are not fitted.
constexpr double kReferenceFloorFactor = 100;

void check_nonlinear(const Scene& s) {
  check_distinct_methods(s, "nonlinear.methods");
  check_nonlinear_steps(s);
  const auto e = s.real_rows("nonlinear.elastic_initial")[0];
  if (std::hypot(e[0], e[1]) == 0.0) s.reject("nonlinear.elastic_initial", "the spring force is singular at x = y = 0");
  check_lobatto_steps(s, "nonlinear.h", kNonlinearOmega, ", frequency 1");
  for (const auto& m : s.texts("nonlinear.methods")) check_pendulum_steps(s, "nonlinear.methods", m);
}

// The planar elastic pendulum of the scene (y pointing down, systems/elastic_pendulum.hpp).
ElasticPendulumWithGravity elastic_pendulum(const Scene& s) {
  const ElasticPendulumParams p{s.real("nonlinear.elastic.l"), s.real("nonlinear.elastic.m"), s.real("nonlinear.elastic.k"),
                                s.real("nonlinear.elastic.g")};
  return {p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}};
}

void run_nonlinear(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("nonlinear");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  const auto methods = s.texts("nonlinear.methods");
  const auto lob = lobatto_rule();
  const auto [pend, pz0] = pendulum(s);
  const auto elastic = elastic_pendulum(s);
  const auto er = s.real_rows("nonlinear.elastic_initial")[0];
  const PhaseState<2> ez0 = make_state<2>(Vec<2>(er[0], er[1]), Vec<2>(er[2], er[3]));
  const Z1 pref = reference_solution(pend, pz0, t_end, rtol, atol);
  const PhaseState<2> eref = reference_solution(elastic, ez0, t_end, rtol, atol);
  struct Row {
    double pendulum_err, pendulum_iterations, elastic_err, elastic_iterations;
    std::vector<double> compared;  // the pendulum error of each of nonlinear.methods
    auto fields() { return std::tie(pendulum_err, pendulum_iterations, elastic_err, elastic_iterations, compared); }
  };
  const auto rows = distributed_map(nh.size(), [&](std::size_t i) {
    const double h = nh[i];
    const std::int64_t n = steps_to(t_end, h);
    int it = 0;
    double it_p = 0, it_e = 0;
    Z1 zp = pz0;
    PhaseState<2> ze = ez0;
    for (std::int64_t j = 0; j < n; ++j) {
      zp = galerkin_step(lob, pend, zp, h, &it), it_p += it;
      ze = galerkin_step(lob, elastic, ze, h, &it), it_e += it;
    }
    Row r{phase_distance(zp, pref), it_p / static_cast<double>(n), phase_distance(ze, eref),
          it_e / static_cast<double>(n), {}};
    for (const auto& m : methods)
      r.compared.push_back(phase_distance(
          MethodsOn<NonlinearPendulum>::integrate(m, pend, pz0, h, n), pref));
    return r;
  });
  for (std::size_t j = 0; j < nh.size(); ++j) {
    bool finite = std::isfinite(rows[j].pendulum_err) && std::isfinite(rows[j].elastic_err);
    for (double e : rows[j].compared) finite = finite && std::isfinite(e);
    if (!finite)
      throw NumericalFailure("study nonlinear: a non-finite error at h = " + format_double(nh[j]) + ", t = " +
                             format_double(t_end) + " (pendulum, elastic pendulum or one of nonlinear.methods)");
  }
  // nonlinear.csv and the orders fitted over the errors above the reference's accuracy.
  std::vector<double> steps;
  for (double h : nh) steps.push_back(static_cast<double>(steps_to(t_end, h)));
  ConvergenceStudy conv({.csv = "nonlinear.csv", .h = nh, .steps = steps, .orders_csv = "nonlinear_orders.csv"});
  conv.column("pendulum_err", [&](std::size_t, std::size_t j) { return rows[j].pendulum_err; })
      .column("pendulum_newton_iterations", [&](std::size_t, std::size_t j) { return rows[j].pendulum_iterations; })
      .column("elastic_err", [&](std::size_t, std::size_t j) { return rows[j].elastic_err; })
      .column("elastic_newton_iterations", [&](std::size_t, std::size_t j) { return rows[j].elastic_iterations; });
  for (std::size_t k = 0; k < methods.size(); ++k)
    conv.column(label_of(methods[k]) + "_pendulum_err", [&](std::size_t, std::size_t j) { return rows[j].compared[k]; });
  const double nfloor = kReferenceFloorFactor * atol;
  const std::string below = "at the reference's accuracy (" + format_double(kReferenceFloorFactor) + " reference.atol)";
  conv.fit("lobatto_nonlinear_pendulum", "pendulum_err", nfloor, below)
      .fit("lobatto_elastic_pendulum", "elastic_err", nfloor, below);
  for (const auto& m : methods) conv.fit(label_of(m) + "_nonlinear_pendulum", label_of(m) + "_pendulum_err", nfloor, below);
  conv.write(ctx);
  ctx.summary["methods"]["nonlinear"] = labels_of(methods);
  ctx.summary["nonlinear"] = {{"h_range", range_of(nh)},
                              {"error_floor", nfloor},
                              {"error_floor_over_atol", kReferenceFloorFactor},
                              {"newton_iterations", {{"pendulum", range_of(conv.values("pendulum_newton_iterations"))},
                                                     {"elastic", range_of(conv.values("elastic_newton_iterations"))}}},
                              {"fits", conv.fits()}};
  // Symplecticity of the nonlinear one-step maps: max |J^T Omega J - Omega|.
  merge(ctx.summary, "reproduced",
        {{"symplecticity_defect_pendulum", symplecticity_defect(galerkin_step_jacobian(lob, pend, pz0, nh.front()))},
         {"symplecticity_defect_elastic", symplecticity_defect(galerkin_step_jacobian(lob, elastic, ez0, nh.front()))}});
  ctx.summary["norms"]["nonlinear"] = "|z_N - z(t_end)|_2 against the odeint Bulirsch-Stoer reference";
}

StudyPlan plan_nonlinear(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const double runs = 2.0 + static_cast<double>(s.texts("nonlinear.methods").size());  // both pendulums, compared
  double steps = 0;
  for (double h : s.reals("nonlinear.h")) steps += runs * t_end / h;
  const PlanRate& rate = plan_rate("pendulum lobatto");
  return {steps, steps * kPendulumEvals, static_cast<double>(s.reals("nonlinear.h").size()) * runs * 4 * sizeof(double),
          rate.ns_per_step, "odeint reference steps not counted; " + rate.note};
}

}  // namespace

Study nonlinear_study() {
  return {.name = "nonlinear",
          .about = "nonlinear Lagrangians (Newton): order 6, symplecticity",
          .files = {"nonlinear.csv", "nonlinear_orders.csv"},
          .keys = Schema()
                      .real("nonlinear.elastic.l", positive(), "elastic pendulum: relaxed length of the spring")
                      .real("nonlinear.elastic.m", positive(), "elastic pendulum: mass")
                      .real("nonlinear.elastic.k", positive(), "elastic pendulum: spring stiffness")
                      .real("nonlinear.elastic.g", non_negative(), "elastic pendulum: gravity (y pointing down)")
                      .real_rows("nonlinear.elastic_initial", 4, any_finite(), 1, "elastic pendulum [x, y, px, py]")
                      .texts("nonlinear.methods", MethodsOn<NonlinearPendulum>::names(), 0,
                             "methods compared with Lobatto on the nonlinear pendulum"),
          .reads = {"nonlinear.h", "nonlinear.t_end", "nonlinear.pendulum_q0", "reference"},
          .run = run_nonlinear,
          .validate = check_nonlinear,
          .plan = plan_nonlinear};
}

}  // namespace geomint::lobatto_table
