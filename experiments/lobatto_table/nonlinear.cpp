// Nonlinear Lagrangians: the Lobatto variational integrator with Newton's method on the nonlinear
// pendulum L = qdot^2/2 + cos q and on a planar elastic pendulum, against odeint's Bulirsch-Stoer
// reference at nonlinear.t_end: the fitted orders (6), the Newton iterations per step, the compared
// methods' errors, and the symplecticity of the one-step maps.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
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
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

using Z1 = PhaseState<1>;


// Errors of the nonlinear study below this many times the reference's absolute tolerance are not fitted.
constexpr double kReferenceFloorFactor = 100;

void check_nonlinear(const Scene& s) {
  check_distinct_methods(s, "nonlinear.methods");
  check_whole_steps(s, "nonlinear.h", "nonlinear.t_end");
  check_elastic_pendulum_states(s, "nonlinear.elastic_initial");
  check_lobatto_bound(s, {"nonlinear.h", NonlinearPendulum::max_frequency(), false, ", frequency 1"});
  check_oscillatory_bounds(s, {"nonlinear.h", NonlinearPendulum::max_frequency(), false, ", frequency 1"}, "nonlinear.methods");
}

// The planar elastic pendulum of the scene (y pointing down, systems/elastic_pendulum.hpp).
ElasticPendulumWithGravity elastic_pendulum(const Scene& s) {
  const ElasticPendulumParams p = elastic_pendulum_params(s, "nonlinear.elastic");
  return {p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}};
}

void run_nonlinear(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("nonlinear");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  const auto methods = s.texts("nonlinear.methods");
  const NonlinearPendulum pend;
  const Z1 pz0 = make_state(s.real("nonlinear.pendulum_q0"), 0.0);
  const auto elastic = elastic_pendulum(s);
  const PhaseState<2> ez0 = elastic_pendulum_state(s.real_rows("nonlinear.elastic_initial")[0]);
  const Z1 pref = reference_solution(pend, pz0, t_end, rtol, atol);
  const PhaseState<2> eref = reference_solution(elastic, ez0, t_end, rtol, atol);
  // Per step h: the columns of nonlinear.csv, the errors and Newton iterations per step of Lobatto on both pendulums,
  // then the pendulum error of each of nonlinear.methods.
  std::vector<std::string> columns = {"pendulum_err", "pendulum_newton_iterations", "elastic_err", "elastic_newton_iterations"};
  for (const auto& m : methods) columns.push_back(label_of(m) + "_pendulum_err");
  const auto rows = distributed_map(nh.size(), [&](std::size_t i) {
    const double h = nh[i];
    const std::int64_t n = steps_to(t_end, h);
    const auto p = lobatto_run(pend, pz0, h, n);
    const auto e = lobatto_run(elastic, ez0, h, n);
    std::vector<double> row = {phase_distance(p.z, pref), p.newton_iterations, phase_distance(e.z, eref), e.newton_iterations};
    for (const auto& m : methods) row.push_back(phase_distance(MethodsOn<NonlinearPendulum>::integrate(m, pend, pz0, h, n), pref));
    return row;
  });
  for (std::size_t j = 0; j < nh.size(); ++j)
    if (!std::all_of(rows[j].begin(), rows[j].end(), [](double v) { return std::isfinite(v); }))
      throw NumericalFailure("study nonlinear: a non-finite error at h = " + format_double(nh[j]) + ", t = " +
                             format_double(t_end) + " (pendulum, elastic pendulum or one of nonlinear.methods)");
  // nonlinear.csv and the orders fitted over the errors above the reference's accuracy.
  std::vector<double> steps;
  for (double h : nh) steps.push_back(static_cast<double>(steps_to(t_end, h)));
  ConvergenceStudy conv({.csv = "nonlinear.csv", .h = nh, .steps = steps, .orders_csv = "nonlinear_orders.csv"});
  for (std::size_t c = 0; c < columns.size(); ++c) conv.column(columns[c], [&rows, c](std::size_t, std::size_t j) { return rows[j][c]; });
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
        {{"symplecticity_defect_pendulum", symplecticity_defect(lobatto_step_jacobian(pend, pz0, nh.front()))},
         {"symplecticity_defect_elastic", symplecticity_defect(lobatto_step_jacobian(elastic, ez0, nh.front()))}});
  ctx.summary["norms"]["nonlinear"] = "|z_N - z(t_end)|_2 against the odeint Bulirsch-Stoer reference";
}

StudyPlan plan_nonlinear(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const double runs = 2.0 + static_cast<double>(s.texts("nonlinear.methods").size());  // both pendulums, compared
  double steps = 0;
  for (double h : s.reals("nonlinear.h")) steps += runs * t_end / h;
  const PlanRate& rate = plan_rate("pendulum lobatto");
  return {steps, steps * rate.evals_per_step(), static_cast<double>(s.reals("nonlinear.h").size()) * runs * 4 * sizeof(double),
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
