// A study of the methods Phi^(ell) of 003 (analysis/phi_study.hpp), compiled once.
#include "geomint/analysis/phi_study.hpp"

#include <cmath>

#include "geomint/io/csv.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_variational.hpp"

namespace geomint {
namespace {

// Newton iterations per step, over the studies of this run that ran Phi^(ell) (one run per process).
struct NewtonCount {
  std::int64_t iterations = 0, steps = 0;
} newton_count;

constexpr double kNewtonPerStep = 3.86;  // force evaluations per step of phi_plan

}  // namespace

std::vector<int> modified_orders(const Scene& s, const char* key) {
  std::vector<int> out;
  for (double e : s.reals(key)) out.push_back(static_cast<int>(e));
  return out;
}

void check_modified_orders(const Scene& s, const char* key) {
  for (double e : s.reals(key))
    if (e != std::floor(e) || static_cast<int>(e) % 2 || e > max_modified_order)
      s.reject(key, "every entry must be an even order between 0 and " + std::to_string(max_modified_order) +
                        " (the highest derived by scripts/derive_nonholonomic.py)");
}

ParticleSetup particle_setup(const Scene& s) {
  const auto c = s.reals("cloud.center");
  return {NonholonomicParticle{parse_potential(s.text("potential"))}, std::array<double, 4>{c[0], c[1], c[2], c[3]}};
}

ReferenceTolerances reference_tolerances(const Scene& s) { return {s.real("reference.rtol"), s.real("reference.atol")}; }

void check_first_conformal_step(const Scene& s, const char* key, const std::vector<double>& hs) {
  const auto [sys, z0] = particle_setup(s);
  for (Discretization d : scene_discretizations(s))
    for (double h : hs) {
      try {
        const PhaseState<2> z1 = conformal_variational_step(d, sys, from_array(z0), h, sys.H(from_array(z0))).z;
        if (!std::isfinite(z1.q.squaredNorm() + z1.p.squaredNorm())) throw IntegrationError("non-finite step");
      } catch (const IntegrationError&) {
        s.reject(key, std::string("a step at which the Newton iteration of the conformal step ") + discretization_name(d) +
                          " converges from cloud.center (here it does not at h = " + format_double(h) + "; 003: 0.25)");
      }
    }
}

void count_newton(Context& ctx, std::int64_t iterations, std::int64_t steps) {
  newton_count.iterations += iterations, newton_count.steps += steps;
  ctx.summary["timing"]["newton_iterations_mean"] =
      static_cast<double>(newton_count.iterations) / static_cast<double>(newton_count.steps);
}

void check_modified_series(Context& ctx, const NonholonomicParticle& sys) {
  ctx.summary["reproduced"]["golden_max_rel_err"] = modified_series_golden_error(sys);
  ctx.summary["reproduced"]["max_modified_order"] = max_modified_order;
}

PhiStudy phi_study(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = particle_setup(s);
  const auto [rtol, atol] = reference_tolerances(s);
  check_modified_series(ctx, sys);
  const double h = s.real("h");
  put_run_facts(ctx, scene_discretizations(s));
  Value powers;  // Cor. 4.3 of 003: Phi^(ell) preserves mu^(ell)_mod to O(h^(ell + 2))
  for (int ell = 0; ell <= max_modified_order; ell += 2) powers["phi" + std::to_string(ell)] = std::pow(h, ell + 2);
  ctx.summary["reproduced"]["h_pow_ell_plus_2"] = powers;
  return {sys, z0, rtol, atol, h, scene_discretizations(s)};
}

std::vector<double> hull_volumes(const std::vector<Point4>& points, const std::vector<HullFacet>& facets,
                                 const ModifiedSeries& ms, const std::vector<int>& measures) {
  std::vector<double> v;
  for (int m : measures)
    v.push_back(hull_integral(points, facets, points.front(), [&](const Point4& z) { return 1.0 / ms.N(m, from_array(z)); }));
  return v;
}

std::vector<CloudRun> cloud_phi_runs(const PhiStudy& p, const std::vector<Point4>& cloud, int ell, std::int64_t n) {
  return distributed_map(p.methods.size(), [&](std::size_t k) { return cloud_phi(p.methods[k], p.sys, p.h, ell, cloud, n); });
}

std::vector<std::vector<double>> snapshot_volumes(const CloudRun& run, const ModifiedSeries& ms, const std::vector<int>& measures) {
  const std::vector<HullFacet> first = cloud_hull(run.snapshots.front());
  return distributed_map(run.snapshots.size(), [&](std::size_t j) {
    return hull_volumes(run.snapshots[j], cloud_hull(run.snapshots[j], first), ms, measures);
  });
}

std::vector<std::vector<Point4>> reference_paths(const NonholonomicParticle& sys, const std::vector<Point4>& cloud, double dt,
                                                 std::int64_t n, double rtol, double atol) {
  return distributed_map(cloud.size(), [&](std::size_t i) { return reference_samples(sys, cloud[i], dt, n, rtol, atol); });
}

std::vector<double> reference_volumes(Context& ctx, const std::string& name, const std::vector<std::string>& keys,
                                      const PhiStudy& p, const std::vector<Point4>& cloud, std::int64_t n) {
  const auto paths = checkpointed_map<std::vector<Point4>>(
      ctx, {name, keys}, cloud.size(), [&](std::size_t i) { return reference_samples(p.sys, cloud[i], p.h, n, p.rtol, p.atol); });
  std::vector<PointTrajectory> per_point;
  for (const auto& z : paths) per_point.push_back(PointTrajectory{z, 0});
  const CloudRun ref = transpose(per_point);
  const ModifiedSeries plain(Discretization::M, p.sys, p.h);  // only its ell = 0 density 1/N is used
  std::vector<double> v;
  for (const auto& per_step : snapshot_volumes(ref, plain, {0})) v.push_back(per_step[0]);
  return v;
}

std::vector<std::vector<double>> psi_symplecticity_defects(const std::vector<Discretization>& methods,
                                                           const NonholonomicParticle& sys, const Point4& z0, double h,
                                                           double E, std::int64_t n) {
  return distributed_map(methods.size(), [&](std::size_t k) {
    std::vector<double> defect{0.0};
    Mat<4> J = Mat<4>::Identity();
    PhaseState<2> z = from_array(z0);
    for (std::int64_t j = 0; j < n; ++j) {
      const PhaseState<2> z1 = conformal_variational_step(methods[k], sys, z, h, E).z;
      J = psi_step_jacobian(methods[k], sys, z, z1, h, E) * J;
      defect.push_back(symplecticity_defect<4>(J));
      z = z1;
    }
    return defect;
  });
}

StudyPlan phi_plan(double steps, double memory, const PlanRate& rate, const std::string& extra) {
  return {steps, kNewtonPerStep * steps, memory, rate.ns_per_step, extra.empty() ? rate.note : extra + "; " + rate.note};
}

}  // namespace geomint
