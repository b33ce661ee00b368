// measure_cloud: what its studies share (measure_cloud.hpp).
#include "measure_cloud.hpp"

#include <algorithm>
#include <cmath>

#include "geomint/core/integrate.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/nonholonomic_golden.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"

namespace geomint::measure_cloud {

namespace {

const MethodInfo* as_discretization(const MethodInfo& m) {
  return m.family == Family::conformal && parse_discretization(m.label) ? &m : nullptr;
}

// {min, max, abs: {min, max}} of a non-empty list of numbers (abs: of their moduli).
Value signed_range_of(const std::vector<double>& v) {
  Value r = range_of(v);
  double abs_lo = std::abs(v.front()), abs_hi = abs_lo;
  for (double x : v) abs_lo = std::min(abs_lo, std::abs(x)), abs_hi = std::max(abs_hi, std::abs(x));
  r["abs"] = {{"min", abs_lo}, {"max", abs_hi}};
  return r;
}

// Newton iterations per step, over the studies of this run that ran Phi^(ell) (one run per process).
struct NewtonCount {
  std::int64_t iterations = 0, steps = 0;
} newton_count;

constexpr double kNewtonPerStep = 3.86;  // force evaluations per step of make_plan (measure_cloud.hpp)

}  // namespace

std::vector<std::string> method_choices() {
  std::vector<std::string> names, labels;
  for (const MethodInfo& m : method_registry())
    if (as_discretization(m)) names.emplace_back(m.name), labels.emplace_back(m.label);
  names.insert(names.end(), labels.begin(), labels.end());
  return names;
}

std::vector<Discretization> scene_methods(const Scene& s) {
  std::vector<Discretization> out;
  for (const auto& m : s.texts("methods")) out.push_back(*parse_discretization(method_info(m).label));
  return out;
}

std::vector<int> ells(const Scene& s, const char* key) {
  std::vector<int> out;
  for (double e : s.reals(key)) out.push_back(static_cast<int>(e));
  return out;
}

void check_ells(const Scene& s, const char* key) {
  for (double e : s.reals(key))
    if (e != std::floor(e) || static_cast<int>(e) % 2 || e > max_modified_order)
      s.reject(key, "every entry must be an even order between 0 and " + std::to_string(max_modified_order) +
                        " (the highest derived by scripts/derive_nonholonomic.py)");
}

void check_at_least_one_step(const Scene& s, const char* key, const std::vector<double>& steps, const char* what) {
  const double longest = *std::max_element(steps.begin(), steps.end());
  if (s.real(key) < longest) s.reject(key, std::string("must be at least one step ") + what + " = " + format_double(longest));
}

void check_first_step(const Scene& s, const char* key, const std::vector<double>& hs) {
  const auto [sys, z0] = setup(s);
  for (Discretization d : scene_methods(s))
    for (double h : hs) {
      try {
        const Z z1 = conformal_variational_step(d, sys, as_state(z0), h, sys.H(as_state(z0))).z;
        if (!std::isfinite(z1.q.squaredNorm() + z1.p.squaredNorm())) throw IntegrationError("non-finite step");
      } catch (const IntegrationError&) {
        s.reject(key, std::string("a step at which the Newton iteration of the conformal step ") + discretization_name(d) +
                          " converges from cloud.center (here it does not at h = " + format_double(h) + "; 003: 0.25)");
      }
    }
}

Z as_state(const Point4& a) { return from_array(a); }

std::vector<Point4> reference_samples(const NonholonomicParticle& sys, const Point4& z0, double dt, std::int64_t n,
                                      double rtol, double atol) {
  ReferenceIntegrator reference(4, array_field<4>(sys), rtol, atol);
  std::vector<Point4> out{z0};
  Point4 x = z0;
  for (std::int64_t j = 1; j <= n; ++j) {
    reference.integrate(x, static_cast<double>(j - 1) * dt, static_cast<double>(j) * dt, 0.1 * dt);
    out.push_back(x);
  }
  return out;
}

Trajectory run_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell, const Point4& z0,
                   std::int64_t n) {
  const double E = ModifiedSeries(d, sys, h).E(ell, as_state(z0));
  Trajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  integrate(conformal_variational_method(d, sys, E, &t.iterations), as_state(z0), h, n,
            [&](std::int64_t, const Z& z) { t.z.push_back(to_array(z)); });
  return t;
}

CloudRun transpose(const std::vector<Trajectory>& per_point) {
  CloudRun c;
  const std::size_t n = per_point.front().z.size();
  c.snapshots.assign(n, std::vector<Point4>(per_point.size()));
  for (std::size_t i = 0; i < per_point.size(); ++i) {
    for (std::size_t j = 0; j < n; ++j) c.snapshots[j][i] = per_point[i].z[j];
    c.iterations += per_point[i].iterations, c.steps += static_cast<std::int64_t>(n - 1);
  }
  return c;
}

CloudRun cloud_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                   const std::vector<Point4>& cloud, std::int64_t n) {
  std::vector<Trajectory> per_point;
  for (const Point4& z0 : cloud) per_point.push_back(run_phi(d, sys, h, ell, z0, n));
  return transpose(per_point);
}

std::vector<HullFacet> cloud_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& known) {
  try {
    return hull_facets(points, known);
  } catch (const std::domain_error& e) {
    throw NumericalFailure(std::string("hull volume: ") + e.what());
  }
}

std::vector<double> hull_volumes(const std::vector<Point4>& points, const std::vector<HullFacet>& facets,
                                 const ModifiedSeries& ms, const std::vector<int>& measures) {
  std::vector<double> v;
  for (int m : measures)
    v.push_back(hull_integral(points, facets, points.front(), [&](const Point4& z) { return 1.0 / ms.N(m, as_state(z)); }));
  return v;
}

std::vector<Point4> cloud_around(const Point4& z0, const std::vector<Point4>& vertices, double radius) {
  std::vector<Point4> unit{{0, 0, 0, 0}};
  unit.insert(unit.end(), vertices.begin(), vertices.end());
  return scaled_cloud(unit, z0, radius);
}

void put(Context& ctx, const char* section, const std::string& key, Value value) {
  ctx.summary[section][key] = std::move(value);
}

Value method_ranges(const Value& per_method) {
  constexpr const char* groups[] = {"all", "N_midpoint", "N_trapezoidal"};
  Value out = Value::record();
  for (int g = 0; g < 3; ++g) {
    std::vector<double> v;
    bool complete = true;
    for (std::size_t i = 0; i < per_method.size(); ++i) {
      const std::string& label = per_method.keys()[i];
      const Value& x = per_method.at(i);
      if (g > 0 && (g == 1) != n_midpoint(*parse_discretization(label))) continue;
      if (x.is_number() && std::isfinite(x.number()))
        v.push_back(x.number());
      else
        complete = false;
    }
    if (complete && !v.empty()) out[groups[g]] = signed_range_of(v);
  }
  return out;
}

void put_methods(Context& ctx, const std::string& key, Value per_method, const std::string& nest) {
  Value ranges = method_ranges(per_method);
  if (nest.empty()) {
    ctx.summary["reproduced"][key] = std::move(per_method);
    ctx.summary["ranges"][key] = std::move(ranges);
  } else {
    ctx.summary["reproduced"][nest][key] = std::move(per_method);
    ctx.summary["ranges"][nest][key] = std::move(ranges);
  }
}

Value ratio_per_method(const Value& a, const Value& b) {
  Value out;
  for (const std::string& label : a.keys()) out[label] = a.at(label).number() / b.at(label).number();
  return out;
}

void put_run_facts(Context& ctx, const std::vector<Discretization>& methods) {
  ctx.summary["timing"]["threads"] = ctx.threads;
  if (methods.empty()) return;
  Value labels = Value::list();
  for (Discretization d : methods) labels.push_back(discretization_name(d));
  ctx.summary["methods"] = labels;
}

void count_newton(Context& ctx, std::int64_t iterations, std::int64_t steps) {
  newton_count.iterations += iterations, newton_count.steps += steps;
  put(ctx, "timing", "newton_iterations_mean",
      static_cast<double>(newton_count.iterations) / static_cast<double>(newton_count.steps));
}

void check_modified_series(Context& ctx, const NonholonomicParticle& sys) {
  const std::string pot = potential_name(sys.potential);
  double worst = 0;
  for (const auto& g : nonholonomic::golden_cases) {
    if (g.potential != pot) continue;
    const ModifiedSeries ms(*parse_discretization(g.discretization), sys, nonholonomic::golden_h);
    for (const auto* p : {&g.a, &g.b}) {
      const Z z = as_state(p->z);
      const double got[] = {ms.E(2, z), ms.E(4, z), ms.N(2, z), ms.N(4, z), ms.K4(z, 1.0)};
      const double want[] = {p->E2, p->E4, p->N2, p->N4, p->K4_at_E1};
      for (int k = 0; k < 5; ++k) worst = std::max(worst, std::abs(got[k] - want[k]) / std::abs(want[k]));
    }
  }
  put(ctx, "reproduced", "golden_max_rel_err", worst);
  put(ctx, "reproduced", "max_modified_order", max_modified_order);
}

Setup setup(const Scene& s) {
  const auto c = s.reals("cloud.center");
  return {NonholonomicParticle{parse_potential(s.text("potential"))}, Point4{c[0], c[1], c[2], c[3]}};
}

Tolerances reference_tolerances(const Scene& s) { return {s.real("reference.rtol"), s.real("reference.atol")}; }

PhiStudy phi_study(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = setup(s);
  const auto [rtol, atol] = reference_tolerances(s);
  check_modified_series(ctx, sys);
  const double h = s.real("h");
  put_run_facts(ctx, scene_methods(s));
  Value powers;  // Cor. 4.3 of 003: Phi^(ell) preserves mu^(ell)_mod to O(h^(ell + 2))
  for (int ell = 0; ell <= max_modified_order; ell += 2) powers["phi" + std::to_string(ell)] = std::pow(h, ell + 2);
  put(ctx, "reproduced", "h_pow_ell_plus_2", powers);
  return {sys, z0, rtol, atol, h, scene_methods(s)};
}

StudyPlan make_plan(double steps, double memory, const PlanRate& rate, const std::string& extra) {
  return {steps, kNewtonPerStep * steps, memory, rate.ns_per_step, extra.empty() ? rate.note : extra + "; " + rate.note};
}

}  // namespace geomint::measure_cloud
