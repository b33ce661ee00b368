// measure_cloud: 003 (García-Naranjo & Vermeeren) Sec. 5, Figs 5.1-5.6 -- the
// nonholonomic particle as a conformally Hamiltonian system, discretized by
// the variational integrators Psi_{h,E} of the five discrete Lagrangians (5.1)
// with E = E^(ell)(z_0) per trajectory (the method Phi^(ell), (4.5)). Studies:
//   shape        Fig. 5.1   a large cloud on a 3-sphere under the reference flow
//   volumes      Figs 5.2, 5.4  measure-weighted convex-hull volumes of the 600-cell
//                cloud under Phi^(ell) and under the reference flow: the full cloud and,
//                beside it, the authors' cloud of the published figures (119 vertices)
//   energies     Figs 5.3, 5.5, 5.6  energies and errors along Phi^(4), Phi^(0)
//   long_run     beyond the paper: drift of H under Phi^(0) against Phi^(4)
//   order_study  beyond the paper: order of measure preservation on tiny clouds
//   cost         beyond the paper: error against wall time of each discretization
// The scene names the potential, the studies and the discretizations (registry
// names conformal_M ... or their labels M ...); nothing else is computed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/geometry/volume_series.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/nonholonomic_golden.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"
#include "geomint/systems/nonholonomic_variational.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;
namespace odeint = boost::numeric::odeint;

namespace {

using Z = PhaseState<2>;

// ---- the discretizations (5.1): the registry's conformal methods whose label names one ----

const MethodInfo* as_discretization(const MethodInfo& m) {
  return m.family == Family::conformal && parse_discretization(m.label) ? &m : nullptr;
}

// What `methods` admits: the registry names (conformal_M, ...) and, as an older spelling, the labels (M, ...).
std::vector<std::string> method_choices() {
  std::vector<std::string> names, labels;
  for (const MethodInfo& m : method_registry())
    if (as_discretization(m)) names.emplace_back(m.name), labels.emplace_back(m.label);
  names.insert(names.end(), labels.begin(), labels.end());
  return names;
}

// The scene's methods; the schema admits only the names and labels above.
std::vector<Discretization> scene_methods(const Scene& s) {
  std::vector<Discretization> out;
  for (const auto& m : s.texts("methods")) out.push_back(*parse_discretization(method_info(m).label));
  return out;
}

// The clouds are neighbourhoods of cloud.center (003: radius 0.01, 1e-5 and 0.3): from radius 3 on, the conformal
// step's Newton iteration fails at h = 0.25 and the reference flow of far points overflows, leaving no hull.
constexpr double kMaxRadius = 1.0;

Schema schema() {
  Schema s;
  s.text("potential", {"harmonic", "free"}, "U = (x^2 + y^2)/2 or U = 0 (003 Secs 5.2, 5.3)")
      .real("h", positive(), "time step (003: 0.25)")
      .real("t_end", positive(), "end time of the cloud runs (003 Figs 5.2, 5.4: 30)")
      .real("ptp_window", positive(), "peak-to-peak volume errors are taken over t <= ptp_window (the hull stays convex)")
      .texts("methods", method_choices(), 1,
             "discrete Lagrangians (5.1) by registry name (conformal_M, ...) or label (M, ...); CSV columns and "
             "summary keys use the label")
      .integer("seed", at_least(0), "seed of the random cloud of Fig. 5.1")
      .real("cloud.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxRadius}, "circumradius of the 600-cell cloud (003: 0.01)")
      .reals("cloud.center", any_finite(), 4, "centre [x, y, px, py] of every cloud and start of every trajectory")
      .boolean("cloud.authors_cloud",
               "also the cloud of the code of 003 (it drops the vertex (0, 0, r, 0): 119 vertices + centre), beside "
               "the full one: volumes_authors_phi*.csv, reproduced.authors_cloud")
      .reals("cloud.ells", at_least(0), 1, "truncation orders ell of the methods Phi^(ell) run on the cloud")
      .integer("shape.points", at_least(5), "points on the 3-sphere of Fig. 5.1 (003: 5000)")
      .real("shape.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxRadius}, "radius of that sphere (003: 0.3)")
      .real("shape.snapshot_dt", positive(), "time between snapshots (003: 2.75)")
      .integer("shape.snapshots", at_least(1), "snapshots after t = 0 (003: 5)")
      .real("energies.t_end", positive(), "end time of Figs 5.3, 5.5, 5.6 (003: 10) and of the cost runs")
      .real("long_run.t_end", positive(), "end time of the long run of Phi^(0) and Phi^(4)")
      .reals("order_study.h", positive(), 3, "steps of the order study and of the cost runs")
      .real("order_study.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxRadius}, "radius of its 600-cell clouds (small enough for no hull artefact)")
      .real("order_study.t_end", positive(), "its end time")
      .reals("order_study.ells", at_least(0), 1, "its truncation orders ell")
      .real("reference.rtol", tolerance(), "tolerances of the odeint Bulirsch-Stoer reference on (3.8)")
      .real("reference.atol", tolerance(), "")
      .integer("timing.repeats", at_least(1), "timed runs of >= 10 ms each (the minimum is the estimate)")
      .integer("checkpoint.stop_after", non_negative(),
               "volumes, order_study: stop after this many rounds of reference paths or cloud runs, leaving a "
               "checkpoint for --resume (0: run to the end)")
      .real("checkpoint.interval", non_negative(), "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work")
      .text("cost.discretization", method_choices(),
            "the discrete Lagrangian (5.1) of Phi^(4) and Phi^(0) in the comparison with RK4")
      .reals("cost.rk4_h", positive(), 3, "steps of the classical RK4 on (3.8), the baseline that preserves neither")
      .real("cost.target_err", positive(), "trajectory error at which the cost to reach it is reported")
      .real("cost.target_energy_err", positive(), "energy error max |H - H0| at which the cost to reach it is reported")
      .alias("observables", "studies");  // the older name of the studies list
  return s;
}

std::vector<int> ells(const Scene& s, const char* key) {
  std::vector<int> out;
  for (double e : s.reals(key)) out.push_back(static_cast<int>(e));
  return out;
}

// ---- checks across keys, per study ----

void check_ells(const Scene& s, const char* key) {
  for (double e : s.reals(key))
    if (e != std::floor(e) || static_cast<int>(e) % 2 || e > max_modified_order)
      s.reject(key, "every entry must be an even order between 0 and " + std::to_string(max_modified_order) +
                        " (the highest derived by scripts/derive_nonholonomic.py)");
}

// A run to s.real(key) takes at least one step of each length in `steps`.
void check_at_least_one_step(const Scene& s, const char* key, const std::vector<double>& steps, const char* what) {
  const double longest = *std::max_element(steps.begin(), steps.end());
  if (s.real(key) < longest) s.reject(key, std::string("must be at least one step ") + what + " = " + format_double(longest));
}

void check_first_step(const Scene& s, const char* key, const std::vector<double>& hs);

void check_volumes(const Scene& s) {
  check_ells(s, "cloud.ells");
  check_first_step(s, "h", {s.real("h")});
  check_at_least_one_step(s, "t_end", {s.real("h")}, "h");
  if (s.real("ptp_window") > s.real("t_end")) s.reject("ptp_window", "must not exceed t_end");
}

void check_order_study(const Scene& s) {
  check_ells(s, "order_study.ells");
  check_first_step(s, "order_study.h", s.reals("order_study.h"));
  if (s.real("order_study.t_end") < s.real("ptp_window")) s.reject("order_study.t_end", "must be at least ptp_window");
  check_at_least_one_step(s, "order_study.t_end", s.reals("order_study.h"), "max(order_study.h)");
}

// Number of steps of length h in [0, t].
std::int64_t steps_in(double t, double h) { return std::llround(std::floor(t / h + 1e-9)); }

Z as_state(const Point4& a) { return from_array(a); }

// ---- reference flow: odeint Bulirsch-Stoer on (3.8), sampled at t_j = j dt --------
std::vector<Point4> reference_samples(const NonholonomicParticle& sys, const Point4& z0, double dt, std::int64_t n,
                                      double rtol, double atol) {
  odeint::bulirsch_stoer<Point4> stepper(atol, rtol);
  const auto f = [&sys](const Point4& x, Point4& dxdt, double) { dxdt = sys.rhs(x); };
  std::vector<Point4> out{z0};
  Point4 x = z0;
  for (std::int64_t j = 1; j <= n; ++j) {
    reference_integrate(stepper, f, x, static_cast<double>(j - 1) * dt, static_cast<double>(j) * dt, 0.1 * dt);
    out.push_back(x);
  }
  return out;
}

// ---- the method Phi^(ell): Psi_{h,E*} with E* = E^(ell)(z0) (003 eq. (4.5), E fixed at z0) --
struct Trajectory {
  std::vector<Point4> z;        // z_0 .. z_n
  std::int64_t iterations = 0;  // Newton iterations, summed over the steps
  auto fields() { return std::tie(z, iterations); }  // (a record of runner/distributed_map.hpp)
};

Trajectory run_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell, const Point4& z0,
                   std::int64_t n) {
  const double E = ModifiedSeries(d, sys, h).E(ell, as_state(z0));
  Trajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  integrate(conformal_variational_method(d, sys, E, &t.iterations), as_state(z0), h, n,
            [&](std::int64_t, const Z& z) { t.z.push_back(to_array(z)); });
  return t;
}

// ---- clouds: snapshots[j][i] is point i at step j; point 0 is the image of the centre --
struct CloudRun {
  std::vector<std::vector<Point4>> snapshots;
  std::int64_t iterations = 0, steps = 0;
  auto fields() { return std::tie(snapshots, iterations, steps); }
};

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

// hull_facets(points, known); a cloud that left the domain of the hull (not finite, degenerate) is a
// NumericalFailure. `known`: the facets of another image of the same cloud, checked and taken
// without Qhull when they bound this one (bounds_hull).
std::vector<HullFacet> cloud_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& known = {}) {
  try {
    return hull_facets(points, known);
  } catch (const std::domain_error& e) {
    throw NumericalFailure(std::string("hull volume: ") + e.what());
  }
}

// Volume of conv(points), bounded by `facets`, for each density 1/N^(ell)_mod, ell in `measures` (0: mu itself, 1/N).
std::vector<double> hull_volumes(const std::vector<Point4>& points, const std::vector<HullFacet>& facets,
                                 const ModifiedSeries& ms, const std::vector<int>& measures) {
  std::vector<double> v;
  for (int m : measures)
    v.push_back(hull_integral(points, facets, points.front(), [&](const Point4& z) { return 1.0 / ms.N(m, as_state(z)); }));
  return v;
}

// hull_volumes of each snapshot of a run, its hulls checked against that of the first snapshot.
std::vector<std::vector<double>> snapshot_volumes(const CloudRun& run, const ModifiedSeries& ms, const std::vector<int>& measures) {
  const std::vector<HullFacet> first = cloud_hull(run.snapshots.front());
  return distributed_map(run.snapshots.size(), [&](std::size_t j) {
    return hull_volumes(run.snapshots[j], cloud_hull(run.snapshots[j], first), ms, measures);
  });
}

// The centre z0 and the vertices of a 600-cell of circumradius `radius` around it (the centre
// first: the apex of the hull triangulation).
std::vector<Point4> cloud_around(const Point4& z0, const std::vector<Point4>& vertices, double radius) {
  std::vector<Point4> unit{{0, 0, 0, 0}};
  unit.insert(unit.end(), vertices.begin(), vertices.end());
  return scaled_cloud(unit, z0, radius);
}

std::string measure_name(int m) { return m == 0 ? "mu" : "mu" + std::to_string(m); }

// 2-D convex-hull area (Andrew's monotone chain, then the shoelace formula).
double convex_area(std::vector<std::array<double, 2>> p) {
  std::sort(p.begin(), p.end());
  const auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<std::array<double, 2>> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); hull[k++] = p[i++])
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0; hull[k++] = p[i])
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
  double a = 0;
  for (std::size_t i = 0; i + 1 < k; ++i) a += hull[i][0] * hull[i + 1][1] - hull[i + 1][0] * hull[i][1];
  return 0.5 * std::abs(a);
}


// ---- what every study reports through ctx.summary ----

// Sets summary[section][key], indexing ctx.summary afresh (no reference into it outlives an insertion).
void put(Context& ctx, const char* section, const std::string& key, json value) {
  ctx.summary[section][key] = std::move(value);
}

// {min, max, abs: {min, max}} of a non-empty list of numbers (abs: of their moduli).
json range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  double abs_lo = std::abs(v.front()), abs_hi = abs_lo;
  for (double x : v) abs_lo = std::min(abs_lo, std::abs(x)), abs_hi = std::max(abs_hi, std::abs(x));
  return {{"min", *lo}, {"max", *hi}, {"abs", {{"min", abs_lo}, {"max", abs_hi}}}};
}

// The ranges of a {label: number} object over the methods: "all", and those of each quadrature of N
// (003 (5.1), the first letter of the label): "N_midpoint" (M, MT) and "N_trapezoidal" (TM, TT, T).
// A group is left out if one of its values is not a finite number (an order without a fit).
json method_ranges(const json& per_method) {
  constexpr const char* groups[] = {"all", "N_midpoint", "N_trapezoidal"};
  json out = json::object();
  for (int g = 0; g < 3; ++g) {
    std::vector<double> v;
    bool complete = true;
    for (const auto& [label, x] : per_method.items()) {
      if (g > 0 && (g == 1) != n_midpoint(*parse_discretization(label))) continue;
      if (x.is_number() && std::isfinite(x.get<double>()))
        v.push_back(x.get<double>());
      else
        complete = false;
    }
    if (complete && !v.empty()) out[groups[g]] = range_of(v);
  }
  return out;
}

// Sets summary.reproduced.<key> (or summary.reproduced.<nest>.<key>) to a {label: number} object and
// summary.ranges.<key> (summary.ranges.<nest>.<key>) to its method_ranges.
void put_methods(Context& ctx, const std::string& key, json per_method, const std::string& nest = "") {
  json ranges = method_ranges(per_method);
  if (nest.empty()) {
    ctx.summary["reproduced"][key] = std::move(per_method);
    ctx.summary["ranges"][key] = std::move(ranges);
  } else {
    ctx.summary["reproduced"][nest][key] = std::move(per_method);
    ctx.summary["ranges"][nest][key] = std::move(ranges);
  }
}

// {label: a[label] / b[label]} over the labels of a.
json ratio_per_method(const json& a, const json& b) {
  json out;
  for (const auto& [label, x] : a.items()) out[label] = x.get<double>() / b[label].get<double>();
  return out;
}

// What every study reports besides its results: the thread count and the labels of the methods it
// runs (the CSV columns; figure_values.gp: summary_words('methods')).
void put_run_facts(Context& ctx, const std::vector<Discretization>& methods) {
  ctx.summary["timing"]["threads"] = ctx.threads;
  if (methods.empty()) return;
  json labels = json::array();
  for (Discretization d : methods) labels.push_back(discretization_name(d));
  ctx.summary["methods"] = labels;
}

// Newton iterations per step, over the studies of this run that ran Phi^(ell) (one run per process).
struct NewtonCount {
  std::int64_t iterations = 0, steps = 0;
} newton_count;

void count_newton(Context& ctx, std::int64_t iterations, std::int64_t steps) {
  newton_count.iterations += iterations, newton_count.steps += steps;
  put(ctx, "timing", "newton_iterations_mean",
      static_cast<double>(newton_count.iterations) / static_cast<double>(newton_count.steps));
}

// The generated modified quantities (E^(ell), N^(ell)_mod, K^(4)_mod) against independent
// reference values at h = 0.25, for this potential: every study that relies on them says so.
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

// What every study reads: the particle and the centre of the clouds (the start of every single trajectory).
struct Setup {
  NonholonomicParticle sys;
  Point4 z0;
};

Setup setup(const Scene& s) {
  const auto c = s.reals("cloud.center");
  return {NonholonomicParticle{parse_potential(s.text("potential"))}, Point4{c[0], c[1], c[2], c[3]}};
}

struct Tolerances {  // of the reference flow
  double rtol, atol;
};

Tolerances reference_tolerances(const Scene& s) { return {s.real("reference.rtol"), s.real("reference.atol")}; }

// The inputs of a study that runs the methods Phi^(ell) at the step h and compares them with the
// reference flow; reading them checks the modified series the methods rely on.
struct PhiStudy {
  NonholonomicParticle sys;
  Point4 z0;
  double rtol, atol, h;
  std::vector<Discretization> methods;
};

PhiStudy phi_study(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = setup(s);
  const auto [rtol, atol] = reference_tolerances(s);
  check_modified_series(ctx, sys);
  const double h = s.real("h");
  put_run_facts(ctx, scene_methods(s));
  json powers;  // Cor. 4.3 of 003: Phi^(ell) preserves mu^(ell)_mod to O(h^(ell + 2))
  for (int ell = 0; ell <= max_modified_order; ell += 2) powers["phi" + std::to_string(ell)] = std::pow(h, ell + 2);
  put(ctx, "reproduced", "h_pow_ell_plus_2", powers);
  return {sys, z0, rtol, atol, h, scene_methods(s)};
}

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
  const auto methods = scene_methods(s);
  put_run_facts(ctx, methods);
  const std::int64_t n = steps_in(t_end, h);
  ctx.progress("Fig. 5.1: symplecticity defect of the flow");
  const Vec<4> z0(z0a[0], z0a[1], z0a[2], z0a[3]);
  const auto flows = parallel_map(2, [&](std::size_t k) {
    return variational_flow(sys, z0, k == 0 ? ParticleFlow::conformal : ParticleFlow::hamiltonian, h, n, rtol, atol);
  });
  const double E = sys.H(as_state(z0a));
  const auto psi = distributed_map(methods.size(), [&](std::size_t k) {
    std::vector<double> defect{0.0};
    Mat<4> J = Mat<4>::Identity();
    Z z = as_state(z0a);
    for (std::int64_t j = 0; j < n; ++j) {
      const Z z1 = conformal_variational_step(methods[k], sys, z, h, E).z;
      J = psi_step_jacobian(methods[k], sys, z, z1, h, E) * J;
      defect.push_back(symplecticity_defect<4>(J));
      z = z1;
    }
    return defect;
  });
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
  json& r = ctx.summary["reproduced"]["symplecticity"];
  r["t_end"] = static_cast<double>(n) * h;
  r["samples"] = n + 1;
  r["conformal_flow_at_t_end"] = symplecticity_defect<4>(flows[0].back().Phi);
  json at_snapshots = json::array();  // at the snapshot times of Fig. 5.1
  const double dt = s.real("shape.snapshot_dt");
  for (std::int64_t k = 0; k <= s.integer("shape.snapshots"); ++k) {
    const std::int64_t j = std::llround(static_cast<double>(k) * dt / h);
    if (j <= n && std::abs(static_cast<double>(j) * h - static_cast<double>(k) * dt) < 1e-9)
      at_snapshots.push_back(symplecticity_defect<4>(flows[0][static_cast<std::size_t>(j)].Phi));
  }
  r["conformal_flow_at_snapshots"] = at_snapshots;
  r["hamiltonian_flow_max"] = ham_max;
  r["measure_identity_max_err"] = measure_max;
  json psi_max;
  for (std::size_t k = 0; k < methods.size(); ++k)
    psi_max[discretization_name(methods[k])] = *std::max_element(psi[k].begin(), psi[k].end());
  put_methods(ctx, "psi_max", psi_max, "symplecticity");
}

// ---- Fig. 5.1: a large cloud on a 3-sphere under the reference flow ----

void run_shape(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = setup(s);
  const auto [rtol, atol] = reference_tolerances(s);
  ctx.progress("Fig. 5.1: sphere cloud, reference flow");
  put_run_facts(ctx, {});
  SpherePoints gen(static_cast<std::uint64_t>(s.integer("seed")));
  std::vector<Point4> unit;
  for (std::int64_t i = 0; i < s.integer("shape.points"); ++i) unit.push_back(gen.next());
  const auto cloud = scaled_cloud(unit, z0, s.real("shape.radius"));
  const double dt = s.real("shape.snapshot_dt");
  const std::int64_t snaps = s.integer("shape.snapshots");
  const auto paths = distributed_map(cloud.size(), [&](std::size_t i) { return reference_samples(sys, cloud[i], dt, snaps, rtol, atol); });
  Csv pts({"t", "x", "y", "px", "py"}), areas({"t", "area_x_px", "area_y_py", "area_sum"});
  json sums = json::array();
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
  // The sum of the shadow areas describes the figure; it is not a symplectic invariant: the linear
  // symplectic map S (x, y, px, py) = (x + y, y, px, py - px) changes it (for a round ball from
  // 2 pi r^2 to 2 sqrt(2) pi r^2), here applied to the cloud at t = 0.
  {
    std::vector<std::array<double, 2>> a, b;
    for (const auto& p : paths) {
      const Point4 z = linear_symplectic_shear(p.front());
      a.push_back({z[0], z[2]}), b.push_back({z[1], z[3]});
    }
    put(ctx, "reproduced", "shape_area_sum_after_shear", convex_area(a) + convex_area(b));
    put(ctx, "reproduced", "shape_area_sum_round_ball", 2 * std::numbers::pi * std::pow(s.real("shape.radius"), 2));
  }
  put(ctx, "reproduced", "shape_area_sum", sums);  // a description of the figure, not an invariant
  put(ctx, "reproduced", "shape_area_sum_last", sums.back());
  put(ctx, "reproduced", "shape_t_end", static_cast<double>(snaps) * dt);  // the time of the last snapshot
  run_symplecticity(ctx, sys, z0, static_cast<double>(snaps) * dt, rtol, atol);
}

// ---- Figs 5.2 and 5.4: hull volumes of the 600-cell cloud under Phi^(ell) and the reference ----

// The scene keys the reference paths of the volumes study depend on (their checkpoints).
const std::vector<std::string> kReferencePathKeys = {"potential", "cloud.center", "cloud.radius", "h",
                                                     "t_end",     "ptp_window",   "reference"};

// Hull volumes in mu of the images of `cloud` under the reference flow at t_j = j h, j = 0..n; the
// paths kept in the checkpoint `name`.
std::vector<double> reference_volumes(Context& ctx, const std::string& name, const PhiStudy& p,
                                      const std::vector<Point4>& cloud, std::int64_t n) {
  const auto paths = checkpointed_map<std::vector<Point4>>(
      ctx, {name, kReferencePathKeys}, cloud.size(),
      [&](std::size_t i) { return reference_samples(p.sys, cloud[i], p.h, n, p.rtol, p.atol); });
  std::vector<Trajectory> per_point;
  for (const auto& z : paths) per_point.push_back(Trajectory{z, 0});
  const CloudRun ref = transpose(per_point);
  const ModifiedSeries plain(Discretization::M, p.sys, p.h);  // only its ell = 0 density 1/N is used
  std::vector<double> v;
  for (const auto& per_step : snapshot_volumes(ref, plain, {0})) v.push_back(per_step[0]);
  return v;
}

// Figs 5.2, 5.4 for one cloud: the hull volumes under the reference flow and under Phi^(ell) for each
// ell of cloud.ells, in every measure mu^(m)_mod, m = 0, 2, .., max_modified_order, to t_end; CSV
// <prefix>phi<ell>.csv; summary.reproduced.<nest> (the cloud's own object, or reproduced itself for nest
// ""): the peak-to-peak values over t <= ptp_window, that of each method in its own measure less
// that of the reference, and the reference's relative volume at the window and at t_end.
void cloud_volumes(Context& ctx, const PhiStudy& p, const std::vector<Point4>& cloud, const std::string& prefix,
                   const std::string& nest) {
  const Scene& s = ctx.scene;
  std::vector<int> all_measures;
  for (int m = 0; m <= max_modified_order; m += 2) all_measures.push_back(m);
  const std::int64_t n = steps_in(s.real("t_end"), p.h);
  const std::size_t window = static_cast<std::size_t>(steps_in(s.real("ptp_window"), p.h)) + 1;
  const auto put_here = [&](const std::string& key, json value) {
    if (nest.empty()) put(ctx, "reproduced", key, std::move(value));
    else ctx.summary["reproduced"][nest][key] = std::move(value);
  };
  ctx.progress("Figs 5.2, 5.4: reference, " + std::to_string(cloud.size()) + " points");
  const std::vector<double> ref_volumes = reference_volumes(ctx, nest.empty() ? "volumes.reference" : "volumes.reference_" + nest, p, cloud, n);
  const std::vector<double> ref_relative = relative_volumes(ref_volumes, ref_volumes.size());
  put_here("cloud_points", cloud.size());
  put_here("ptp_reference_mu", relative_peak_to_peak(ref_volumes, window));
  put_here("reference_rel_volume_at_window", ref_relative[window - 1]);
  put_here("reference_rel_volume_at_t_end", ref_relative.back());

  for (int ell : ells(s, "cloud.ells")) {
    ctx.progress("Figs 5.2, 5.4: Phi^(" + std::to_string(ell) + "), " + std::to_string(cloud.size()) + " points");
    const auto runs = distributed_map(p.methods.size(), [&](std::size_t k) { return cloud_phi(p.methods[k], p.sys, p.h, ell, cloud, n); });
    std::vector<std::string> cols{"t", "reference_mu"};
    for (Discretization d : p.methods)
      for (int m : all_measures) cols.push_back(std::string(discretization_name(d)) + "_" + measure_name(m));
    Csv csv(cols);
    std::vector<std::vector<std::vector<double>>> vols(p.methods.size());  // [method][measure][step]
    for (std::size_t k = 0; k < p.methods.size(); ++k) {
      const ModifiedSeries ms(p.methods[k], p.sys, p.h);
      const auto per_step = snapshot_volumes(runs[k], ms, all_measures);
      vols[k].assign(all_measures.size(), std::vector<double>(per_step.size()));
      for (std::size_t j = 0; j < per_step.size(); ++j)
        for (std::size_t m = 0; m < all_measures.size(); ++m) vols[k][m][j] = per_step[j][m];
      count_newton(ctx, runs[k].iterations, runs[k].steps);
    }
    for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
      csv << static_cast<double>(j) * p.h << ref_volumes[j];
      for (std::size_t k = 0; k < p.methods.size(); ++k)
        for (std::size_t m = 0; m < all_measures.size(); ++m) csv << vols[k][m][j];
      csv.end_row();
    }
    ctx.write(prefix + "phi" + std::to_string(ell) + ".csv", csv);
    const std::string phi = "ptp_phi" + std::to_string(ell) + "_";
    for (std::size_t m = 0; m < all_measures.size(); ++m) {
      json ptp;
      for (std::size_t k = 0; k < p.methods.size(); ++k) ptp[discretization_name(p.methods[k])] = relative_peak_to_peak(vols[k][m], window);
      put_methods(ctx, phi + measure_name(all_measures[m]), ptp, nest);
    }
    // the amplitude (half the ptp) in mu^(4)_mod, the quantity 003 reads off Fig. 5.2
    const auto mu4 = std::find(all_measures.begin(), all_measures.end(), 4);
    if (mu4 != all_measures.end()) {
      json amp;
      for (std::size_t k = 0; k < p.methods.size(); ++k)
        amp[discretization_name(p.methods[k])] =
            relative_amplitude(vols[k][static_cast<std::size_t>(mu4 - all_measures.begin())], window);
      put_methods(ctx, "amplitude_phi" + std::to_string(ell) + "_mu4", amp, nest);
    }
    // in its own measure mu^(ell)_mod, less the reference's relative volume (the hull artefact both share)
    const std::size_t own = static_cast<std::size_t>(std::find(all_measures.begin(), all_measures.end(), ell) - all_measures.begin());
    json corrected;
    for (std::size_t k = 0; k < p.methods.size(); ++k)
      corrected[discretization_name(p.methods[k])] = relative_peak_to_peak_minus(vols[k][own], ref_volumes, window);
    put_methods(ctx, phi + measure_name(ell) + "_minus_reference", corrected, nest);
  }
  const json& r = nest.empty() ? ctx.summary["reproduced"] : ctx.summary["reproduced"][nest];
  if (r.contains("ptp_phi0_mu4") && r.contains("ptp_phi4_mu4"))  // Fig. 5.4 against Fig. 5.2 in mu^(4)_mod
    put_methods(ctx, "ptp_mu4_phi0_over_phi4", ratio_per_method(r["ptp_phi0_mu4"], r["ptp_phi4_mu4"]), nest);
}

// The reference flow is run once more on the full cloud of this fraction of cloud.radius: the ratio
// of the two peak-to-peak values shows the order in r of the hull artefact (r^2: a factor 100).
constexpr double artefact_radius_fraction = 0.1;

void run_volumes(Context& ctx) {
  const Scene& s = ctx.scene;
  const PhiStudy p = phi_study(ctx);
  const double r = s.real("cloud.radius");
  const auto cloud = cloud_around(p.z0, six_hundred_cell_vertices(), r);
  cloud_volumes(ctx, p, cloud, "volumes_", "");
  const auto facets0 = hull_facets(cloud);
  put(ctx, "reproduced", "hull_volume_initial_over_r4",
      hull_integral(cloud, facets0, cloud.front(), [](const Point4&) { return 1.0; }) / std::pow(r, 4));
  put(ctx, "reproduced", "hull_volume_exact_over_r4", six_hundred_cell_volume(1.0));
  const auto small = cloud_around(p.z0, six_hundred_cell_vertices(), artefact_radius_fraction * r);
  const std::vector<double> small_volumes = reference_volumes(ctx, "volumes.reference_small", p, small, steps_in(s.real("ptp_window"), p.h));
  const double ptp_small = relative_peak_to_peak(small_volumes, small_volumes.size());
  put(ctx, "reproduced", "artefact_radius_fraction", artefact_radius_fraction);
  put(ctx, "reproduced", "ptp_reference_mu_small_radius", ptp_small);
  put(ctx, "reproduced", "ptp_reference_mu_ratio_to_small_radius",
      ctx.summary["reproduced"]["ptp_reference_mu"].get<double>() / ptp_small);
  if (s.boolean("cloud.authors_cloud"))  // the cloud of the published figures
    cloud_volumes(ctx, p, cloud_around(p.z0, authors_six_hundred_cell_vertices(), r), "volumes_authors_", "authors_cloud");
}

// ---- Figs 5.3, 5.5, 5.6: energies and errors along Phi^(4) and Phi^(0) from the centre ----

// The reference is checked against a second one with both tolerances multiplied by this factor.
constexpr double reference_check_factor = 1e-2;

void run_energies(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  const std::string pot = potential_name(sys.potential);
  ctx.progress("Figs 5.3, 5.5, 5.6: energies");
  const std::int64_t n = steps_in(s.real("energies.t_end"), h);
  const auto ref = reference_samples(sys, z0, h, n, rtol, atol);
  const auto ref_tight =
      reference_samples(sys, z0, h, n, reference_check_factor * rtol, reference_check_factor * atol);
  double self_check = 0;
  for (std::size_t j = 0; j < ref.size(); ++j) self_check = std::max(self_check, phase_distance(as_state(ref[j]), as_state(ref_tight[j])));
  put(ctx, "reproduced", "reference_self_check", self_check);
  put(ctx, "reproduced", "reference_check_factor", reference_check_factor);
  put(ctx, "reproduced", "energy_steps", n);
  const double H0 = sys.H(as_state(z0));
  put(ctx, "reproduced", "H0", H0);
  json H_end, err_end_of;
  for (int ell : {4, 0}) {
    const auto runs = distributed_map(methods.size(), [&](std::size_t k) { return run_phi(methods[k], sys, h, ell, z0, n); });
    std::vector<std::string> cols{"t", "reference_H"};
    for (Discretization d : methods)
      for (const char* q : {"H", "K_E", "K_mod", "E4", "err"}) cols.push_back(std::string(discretization_name(d)) + "_" + q);
    Csv csv(cols);
    const std::size_t M = methods.size();
    std::vector<ModifiedSeries> ms;
    std::vector<double> E_star, max_H(M, 0.0), max_K(M, 0.0), max_Kmod(M, 0.0), err_end(M), H_err_end(M);
    for (Discretization d : methods) ms.emplace_back(d, sys, h), E_star.push_back(ms.back().E(ell, as_state(z0)));
    for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
      csv << static_cast<double>(j) * h << sys.H(as_state(ref[j]));
      for (std::size_t k = 0; k < M; ++k) {
        const Z z = as_state(runs[k].z[j]);
        const double H = sys.H(z), K = sys.K(z, H0), Kmod = ms[k].K4(z, E_star[k]);
        const double err = phase_distance(z, as_state(ref[j]));
        csv << H << K << Kmod << ms[k].E(4, z) << err;
        max_H[k] = std::max(max_H[k], std::abs(H - H0)), max_K[k] = std::max(max_K[k], std::abs(K));
        max_Kmod[k] = std::max(max_Kmod[k], std::abs(Kmod));
        err_end[k] = err, H_err_end[k] = std::abs(H - H0);
      }
      csv.end_row();
    }
    json Estar, jmax_H, jmax_K, jmax_Kmod, jerr_end, jH_end;
    for (std::size_t k = 0; k < M; ++k) {
      const char* name = discretization_name(methods[k]);
      Estar[name] = E_star[k] - H0, jmax_H[name] = max_H[k], jmax_K[name] = max_K[k], jmax_Kmod[name] = max_Kmod[k];
      jerr_end[name] = err_end[k], jH_end[name] = H_err_end[k];
    }
    for (const auto& r : runs) count_newton(ctx, r.iterations, n);
    ctx.write("energies_phi" + std::to_string(ell) + ".csv", csv);
    const std::string p = "phi" + std::to_string(ell);
    put_methods(ctx, "Estar_minus_H0_" + p, Estar);
    put_methods(ctx, "max_abs_H_err_" + p, jmax_H);
    put_methods(ctx, "max_abs_K_E_" + p, jmax_K);
    put_methods(ctx, "max_abs_K_mod4_" + p, jmax_Kmod);
    put_methods(ctx, "err_at_t_end_" + p, jerr_end);
    put_methods(ctx, "H_err_at_t_end_" + p, jH_end);
    H_end[std::to_string(ell)] = jH_end, err_end_of[std::to_string(ell)] = jerr_end;
  }
  // |H(T) - H0| and the error at T under Phi^(0) over those under Phi^(4)
  put_methods(ctx, pot + "_H_drift_ratio", ratio_per_method(H_end["0"], H_end["4"]));
  put_methods(ctx, pot + "_err_ratio", ratio_per_method(err_end_of["0"], err_end_of["4"]));
}

// ---- long run: drift of H under Phi^(0) against Phi^(4) ----

void run_long_run(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  ctx.progress("long run");
  const std::int64_t n = steps_in(s.real("long_run.t_end"), h);
  const std::size_t M = methods.size();
  const auto runs = distributed_map(2 * M, [&](std::size_t k) { return run_phi(methods[k % M], sys, h, k < M ? 0 : 4, z0, n); });
  std::vector<std::string> cols{"t"};
  for (int ell : {0, 4})
    for (Discretization d : methods) cols.push_back(std::string(discretization_name(d)) + "_H_phi" + std::to_string(ell));
  Csv csv(cols);
  const double H0 = sys.H(as_state(z0));
  for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
    csv << static_cast<double>(j) * h;
    for (const auto& r : runs) csv << sys.H(as_state(r.z[j])) - H0;
    csv.end_row();
  }
  ctx.write("long_run.csv", csv);
  const auto ref = reference_samples(sys, z0, s.real("long_run.t_end"), 1, rtol, atol).back();
  json H0_end, H4_end, e0, e4;
  for (std::size_t k = 0; k < M; ++k) {
    const char* name = discretization_name(methods[k]);
    H0_end[name] = sys.H(as_state(runs[k].z.back())) - H0, H4_end[name] = sys.H(as_state(runs[M + k].z.back())) - H0;
    e0[name] = phase_distance(as_state(runs[k].z.back()), as_state(ref)),
    e4[name] = phase_distance(as_state(runs[M + k].z.back()), as_state(ref));
    count_newton(ctx, runs[k].iterations + runs[M + k].iterations, 2 * n);
  }
  put_methods(ctx, "long_H_err_phi0", H0_end), put_methods(ctx, "long_H_err_phi4", H4_end);
  put_methods(ctx, "long_err_phi0", e0), put_methods(ctx, "long_err_phi4", e4);
}

// ---- order of measure preservation: Phi^(ell) in its own mu^(ell)_mod on tiny clouds ----

void run_order_study(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = setup(s);
  check_modified_series(ctx, sys);
  const auto methods = scene_methods(s);
  put_run_facts(ctx, methods);
  const auto hs = s.reals("order_study.h");
  const auto es = ells(s, "order_study.ells");
  const auto cloud = cloud_around(z0, six_hundred_cell_vertices(), s.real("order_study.radius"));
  // Task (k, e, i): method k, order es[e], step hs[i]; e == es.size() is the noise probe of
  // method k: Phi^(max order) at half the smallest step, whose true volume error
  // C (h/2)^(max order + 2) is negligible, so that what it shows is round-off.
  struct Task {
    std::size_t k, e, i;
  };
  std::vector<Task> tasks;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    for (std::size_t e = 0; e < es.size(); ++e)
      for (std::size_t i = 0; i < hs.size(); ++i) tasks.push_back({k, e, i});
    tasks.push_back({k, es.size(), 0});
  }
  const double h_probe = 0.5 * *std::min_element(hs.begin(), hs.end());
  ctx.progress("order study: " + std::to_string(tasks.size()) + " cloud runs");
  struct Result {
    double ptp;
    std::int64_t iterations, steps;
    auto fields() { return std::tie(ptp, iterations, steps); }
  };
  const std::vector<std::string> keys = {"potential", "cloud.center", "methods", "order_study", "ptp_window"};
  const auto results = checkpointed_map<Result>(ctx, {"order_study", keys}, tasks.size(), [&](std::size_t t) {
    const Task& T = tasks[t];
    const bool probe = T.e == es.size();
    const double hh = probe ? h_probe : hs[T.i];
    const int ell = probe ? max_modified_order : es[T.e];
    const std::int64_t n = steps_in(s.real("order_study.t_end"), hh);
    const CloudRun run = cloud_phi(methods[T.k], sys, hh, ell, cloud, n);
    const ModifiedSeries ms(methods[T.k], sys, hh);
    std::vector<double> v;
    std::vector<HullFacet> facets;  // those of the previous snapshot, checked before they are taken
    for (const auto& snap : run.snapshots) {
      facets = cloud_hull(snap, facets);
      v.push_back(hull_volumes(snap, facets, ms, {ell})[0]);
    }
    return Result{relative_peak_to_peak(v, static_cast<std::size_t>(steps_in(s.real("ptp_window"), hh)) + 1), run.iterations,
                  run.steps};
  });
  Csv csv({"method", "ell", "h", "ptp"});
  double noise = 0;
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    const bool probe = tasks[t].e == es.size();
    if (probe) noise = std::max(noise, results[t].ptp);
    csv.row(discretization_name(methods[tasks[t].k]), probe ? max_modified_order : es[tasks[t].e],
            probe ? h_probe : hs[tasks[t].i], results[t].ptp);
    count_newton(ctx, results[t].iterations, results[t].steps);
  }
  ctx.write("order_study.csv", csv);
  // Points within a factor 2 of the measured round-off noise are left out of the fits.
  const double floor = 2 * noise;
  put(ctx, "reproduced", "order_study_noise", noise);
  put(ctx, "reproduced", "order_study_noise_floor", floor);
  put(ctx, "reproduced", "order_study_h_probe", h_probe);
  put(ctx, "reproduced", "order_study_h",
      {{"min", *std::min_element(hs.begin(), hs.end())}, {"max", *std::max_element(hs.begin(), hs.end())}});
  put(ctx, "reproduced", "order_study_h_count", hs.size());
  const std::size_t i_max = static_cast<std::size_t>(std::max_element(hs.begin(), hs.end()) - hs.begin());
  json fits;
  for (std::size_t e = 0; e < es.size(); ++e) {
    const std::string key = "measure_ell" + std::to_string(es[e]);
    json o, f, points, at_h_max;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      std::vector<double> ptp;
      for (std::size_t i = 0; i < hs.size(); ++i) ptp.push_back(results[k * (es.size() * hs.size() + 1) + e * hs.size() + i].ptp);
      const char* name = discretization_name(methods[k]);
      at_h_max[name] = ptp[i_max];
      try {
        const OrderFit fit = fit_order(hs, ptp, floor, "order study");
        o[name] = fit.order, f[name] = to_json(fit), points[name] = fit.points;
      } catch (const NumericalFailure&) {
        o[name] = nullptr, points[name] = nullptr;  // fewer than 3 steps above the noise: no order is claimed
      }
    }
    ctx.summary["orders"][key] = o;
    ctx.summary["ranges"][key] = method_ranges(o);
    ctx.summary["ranges"]["fit_points_" + key] = method_ranges(points);
    put_methods(ctx, "order_study_ptp_phi" + std::to_string(es[e]) + "_at_h_max", at_h_max);
    if (!f.empty()) fits[key] = f;
  }
  if (!fits.empty()) ctx.summary["fits"] = fits;
}

// ---- work-precision: Phi^(4) against Phi^(0) and RK4 ----

// One timed run: its step, its trajectory (z_0 .. z_n; Newton iterations for Phi^(ell)) and its time.
struct TimedRun {
  double h;
  Trajectory tr;
  RunTime time;
};

// (3.8) as z' = f(z) on Vec<4>, for runge_kutta4; `evals` counts the evaluations of f.
struct ParticleField {
  const NonholonomicParticle& sys;
  std::int64_t* evals;
  Vec<4> f(const Vec<4>& z) const {
    ++*evals;
    const Point4 d = sys.rhs({z[0], z[1], z[2], z[3]});
    return {d[0], d[1], d[2], d[3]};
  }
};

Trajectory run_rk4(const NonholonomicParticle& sys, double h, const Point4& z0, std::int64_t n, std::int64_t* evals) {
  const ParticleField field{sys, evals};
  Trajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  Vec<4> y(z0[0], z0[1], z0[2], z0[3]);
  t.z.push_back(z0);
  for (std::int64_t j = 0; j < n; ++j) {
    y = runge_kutta4(field, y, h);
    t.z.push_back({y[0], y[1], y[2], y[3]});
  }
  return t;
}

json or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

// At equal cost (003, harmonic scene, not in the paper): Phi^(4) and Phi^(0) with the discretization
// cmp over order_study.h (the Phi^(4) runs are those of the cost study) and the classical RK4 on
// (3.8) over cost.rk4_h, each from z0 with N = floor(T/h) steps, T = energies.t_end. Two errors:
// the trajectory error |z_N - z(t_N)|_2 against the reference at t_N (whose own error, against a
// reference at 100x tighter tolerances, is reported), and the energy error max_j |H(z_j) - H0|
// (bounded for the conformal methods, drifting for RK4). Costs: wall time (time_runs: the minimum
// of timing.repeats runs of >= 10 ms) and evaluations (Newton iterations of Psi_{h,E}, each the
// discrete momentum with its 2x2 Jacobian; 4 evaluations of (3.8) per RK4 step).
void work_precision(Context& ctx, const NonholonomicParticle& sys, const Point4& z0, double rtol, double atol,
                    Discretization cmp, const std::vector<TimedRun>& phi4_runs) {
  const Scene& s = ctx.scene;
  const double T = s.real("energies.t_end"), H0 = sys.H(as_state(z0));
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  ctx.progress("cost: Phi^(4), Phi^(0) and RK4 at equal cost");
  std::vector<TimedRun> phi0_runs, rk4_runs;
  std::vector<std::int64_t> rk4_evals;
  for (double hh : s.reals("order_study.h")) {
    const std::int64_t n = steps_in(T, hh);
    Trajectory tr;
    const RunTime rt = time_runs(repeats, [&] {
      tr = run_phi(cmp, sys, hh, 0, z0, n);
      do_not_optimize(tr.z.back());
    });
    phi0_runs.push_back({hh, tr, rt});
  }
  for (double hh : s.reals("cost.rk4_h")) {
    const std::int64_t n = steps_in(T, hh);
    Trajectory tr;
    std::int64_t evals = 0;
    const RunTime rt = time_runs(repeats, [&] {
      evals = 0;
      tr = run_rk4(sys, hh, z0, n, &evals);
      do_not_optimize(tr.z.back());
    });
    rk4_runs.push_back({hh, tr, rt}), rk4_evals.push_back(evals);
  }
  const char* names[] = {"phi4", "phi0", "rk4"};
  const std::vector<TimedRun>* all[] = {&phi4_runs, &phi0_runs, &rk4_runs};
  Csv csv({"method", "h", "steps", "t_end", "err", "energy_err", "evals", "wall_s", "wall_spread"});
  std::vector<CostRun> traj[3], energy[3];
  double ref_err = 0, spread_max = 0;
  for (int m = 0; m < 3; ++m)
    for (std::size_t i = 0; i < all[m]->size(); ++i) {
      const TimedRun& r = (*all[m])[i];
      const std::int64_t n = static_cast<std::int64_t>(r.tr.z.size()) - 1;
      const double tN = static_cast<double>(n) * r.h;
      const auto ref = reference_samples(sys, z0, tN, 1, rtol, atol).back();
      const auto tight = reference_samples(sys, z0, tN, 1, reference_check_factor * rtol, reference_check_factor * atol).back();
      ref_err = std::max(ref_err, phase_distance(as_state(ref), as_state(tight)));
      double e_energy = 0;
      for (const Point4& z : r.tr.z) e_energy = std::max(e_energy, std::abs(sys.H(as_state(z)) - H0));
      const double err = phase_distance(as_state(r.tr.z.back()), as_state(ref));
      const double evals = m == 2 ? static_cast<double>(rk4_evals[i]) : static_cast<double>(r.tr.iterations);
      spread_max = std::max(spread_max, r.time.spread());
      csv.row(names[m], r.h, n, tN, err, e_energy, evals, r.time.seconds(), r.time.spread());
      traj[m].push_back({r.h, static_cast<double>(n), r.time.seconds(), evals, err});
      energy[m].push_back({r.h, static_cast<double>(n), r.time.seconds(), evals, e_energy});
    }
  ctx.write("timing_work_precision.csv", csv);
  // the common budget: the largest wall time that every method reaches
  double budget = std::numeric_limits<double>::infinity();
  for (int m = 0; m < 3; ++m) budget = std::min(budget, largest_wall(traj[m]));
  const double target = s.real("cost.target_err"), target_energy = s.real("cost.target_energy_err");
  json w, wt;  // w: what does not depend on the clock (deterministic); wt: wall-time quantities (timing)
  w["discretization"] = discretization_name(cmp);
  w["methods"] = {"phi4", "phi0", "rk4"};
  w["reference_error"] = ref_err;
  w["reference_check_factor"] = reference_check_factor;
  w["target_err"] = target;
  w["target_energy_err"] = target_energy;
  wt["budget_s"] = budget;
  for (int m = 0; m < 3; ++m) {
    const auto t = by_decreasing_h(traj[m]), e = by_decreasing_h(energy[m]);
    json c, ct;
    ct["err_at_budget"] = or_null(error_at_wall(t, budget));
    ct["energy_err_at_budget"] = or_null(error_at_wall(e, budget));
    ct["wall_s_to_target"] = or_null(cost_to_reach(t, target, &CostRun::wall_s));
    c["evals_to_target"] = or_null(cost_to_reach(t, target, &CostRun::evals));
    ct["wall_s_to_target_energy"] = or_null(cost_to_reach(e, target_energy, &CostRun::wall_s));
    c["evals_to_target_energy"] = or_null(cost_to_reach(e, target_energy, &CostRun::evals));
    std::vector<double> hs, errs;
    for (const CostRun& r : t) hs.push_back(r.h), errs.push_back(r.err);
    c["order"] = fit_order(hs, errs, 0.0, "work precision").order;  // trajectory error against h
    ct["ns_per_step_at_h_max"] = 1e9 * t.front().wall_s / t.front().steps;
    w[names[m]] = c, wt[names[m]] = ct;
  }
  // speeds as ratios measured in this run: the cost of each method to reach the target over that of RK4
  for (const char* key : {"wall_s_to_target", "wall_s_to_target_energy"}) {
    const json r = wt["rk4"][key];  // copies: inserting into wt (an ordered_json) moves its elements
    for (const char* m : {"phi4", "phi0"}) {
      const json x = wt[m][key];
      wt["ratio_to_rk4"][m][key] = x.is_number() && r.is_number() ? json(x.get<double>() / r.get<double>()) : json(nullptr);
    }
  }
  ctx.summary["timing"]["work_precision"] = wt;
  ctx.summary["reproduced"]["work_precision"] = w;
  put(ctx, "timing", "work_precision_spread_max", spread_max);
}

// ---- cost: error at energies.t_end against wall time, per method (Phi^(4)), over order_study.h ----

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  ctx.progress("cost");
  const double T = s.real("energies.t_end");
  const auto hs = s.reals("order_study.h");
  // the steps whose runs end at T itself (n h = T), for which the errors are also reported by step
  json h_at_T = json::array();
  for (double hh : hs)
    if (std::abs(static_cast<double>(steps_in(T, hh)) * hh / T - 1) < 1e-9) h_at_T.push_back(hh);
  Csv csv({"method", "h", "steps", "t_end", "err", "wall_s", "ns_per_step", "newton_iterations_per_step"});
  json ns_per_step, newton_at_h, err_at_T, order, time_at_h;
  double spread_max = 0;
  const Discretization cmp = *parse_discretization(method_info(s.text("cost.discretization")).label);
  std::vector<TimedRun> phi4_runs;  // the runs of Phi^(4) with the compared discretization, reused below
  for (Discretization d : methods) {
    const char* name = discretization_name(d);
    std::vector<double> errs;
    for (double hh : hs) {
      const std::int64_t n = steps_in(T, hh);  // the error is taken at n h <= T, against the reference there
      const auto ref = reference_samples(sys, z0, static_cast<double>(n) * hh, 1, rtol, atol).back();
      Trajectory tr;
      const RunTime rt = time_runs(static_cast<int>(s.integer("timing.repeats")), [&] {
        tr = run_phi(d, sys, hh, 4, z0, n);
        do_not_optimize(tr.z.back());
      });
      const double sec = rt.seconds();
      spread_max = std::max(spread_max, rt.spread());
      if (d == cmp) phi4_runs.push_back({hh, tr, rt});
      const double ns = 1e9 * sec / static_cast<double>(n), err = phase_distance(as_state(tr.z.back()), as_state(ref));
      const double newton = static_cast<double>(tr.iterations) / static_cast<double>(n);
      csv.row(name, hh, n, static_cast<double>(n) * hh, err, sec, ns, newton);
      errs.push_back(err);
      if (std::find(h_at_T.begin(), h_at_T.end(), hh) != h_at_T.end()) err_at_T[name].push_back(err);
      if (hh == h) ns_per_step[name] = ns, newton_at_h[name] = newton, time_at_h[name] = to_json(rt);
    }
    order[name] = fit_order(hs, errs, 0.0, "cost").order;  // error against h over all the steps
  }
  ctx.write("timing_cost.csv", csv);
  put(ctx, "timing", "cost_at_h", time_at_h);
  put(ctx, "timing", "cost_spread_max", spread_max);
  put(ctx, "timing", "ns_per_step", ns_per_step);
  put(ctx, "timing", "ns_per_step_ranges", method_ranges(ns_per_step));
  put_methods(ctx, "newton_iterations_per_step_phi4", newton_at_h);
  put(ctx, "reproduced", "cost_h_at_t_end", h_at_T);
  put(ctx, "reproduced", "cost_err_at_t_end", err_at_T);
  ctx.summary["orders"]["cost_error_phi4"] = order;
  ctx.summary["ranges"]["cost_error_phi4"] = method_ranges(order);
  work_precision(ctx, sys, z0, rtol, atol, cmp, phi4_runs);
}


// ---- what each study costs (--plan), from the scene before any work ----
// ns per step and thread of each study: its wall time in the paper scenes on 2 threads (summary.json
// timing.study_wall_s) times 2 over its steps below -- the hull volumes, references and timed repeats included;
// force evaluations: Newton iterations, 3.86 per step (timing.newton_iterations_mean there). The odeint
// reference samples count as steps.
constexpr double kNewtonPerStep = 3.86, kPointBytes = 4 * 8;
const char* const kPlanNote = "ns per step: the paper scene's study wall time on 2 threads over its steps (summary.json)";

double steps_of(double t, double h) { return std::floor(t / h + 1e-9); }  // steps_in in double, before any cast

StudyPlan make_plan(double steps, double memory, double ns_per_step, const std::string& extra = {}) {
  return {steps, kNewtonPerStep * steps, memory, ns_per_step, extra.empty() ? kPlanNote : extra + "; " + kPlanNote};
}

StudyPlan plan_shape(const Scene& s) {
  const double snaps = static_cast<double>(s.integer("shape.snapshots")), points = static_cast<double>(s.integer("shape.points"));
  const double n = steps_of(snaps * s.real("shape.snapshot_dt"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  return make_plan(M * n + points * snaps + 2 * n, points * (snaps + 1) * kPointBytes * 2 + (2 + M) * (n + 1) * 20 * 8, 15700);
}

StudyPlan plan_volumes(const Scene& s) {
  const double n = steps_of(s.real("t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  const double runs = M * static_cast<double>(s.reals("cloud.ells").size()) + 1;  // + the reference
  const double points = 2 * 121.0;  // the full cloud and the authors' (at most)
  return make_plan(runs * points * n, runs * (n + 1) * 121 * kPointBytes, 9500);
}

StudyPlan plan_energies(const Scene& s) {
  const double n = steps_of(s.real("energies.t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  const double runs = M * (max_modified_order / 2 + 1) + 2;
  return make_plan(runs * n, runs * (n + 1) * kPointBytes, 7500);
}

StudyPlan plan_long_run(const Scene& s) {
  const double n = steps_of(s.real("long_run.t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  return make_plan(2 * M * n, 2 * M * (n + 1) * kPointBytes, 1800);
}

StudyPlan plan_order_study(const Scene& s) {
  const auto hs = s.reals("order_study.h");
  const double T = s.real("order_study.t_end"), M = static_cast<double>(s.texts("methods").size());
  const double ells_n = static_cast<double>(s.reals("order_study.ells").size()), h_min = *std::min_element(hs.begin(), hs.end());
  double steps = M * 120 * steps_of(T, h_min / 2);  // the round-off probes
  for (double h : hs) steps += M * ells_n * 120 * steps_of(T, h);
  StudyPlan p = make_plan(steps, 2 * (steps_of(T, h_min / 2) + 1) * 121 * kPointBytes, 8100, "the snapshots of two runs at once");
  p.tasks = M * (ells_n * static_cast<double>(hs.size()) + 1);  // (a cloud run each)
  return p;
}

StudyPlan plan_cost(const Scene& s) {
  const double T = s.real("energies.t_end"), runs = static_cast<double>(s.integer("timing.repeats")) + 1;
  const double M = static_cast<double>(s.texts("methods").size());
  double steps = 0, kept = 0;
  for (double h : s.reals("order_study.h")) steps += (M + 1) * runs * steps_of(T, h), kept += 2 * (steps_of(T, h) + 1);
  for (double h : s.reals("cost.rk4_h")) steps += runs * steps_of(T, h), kept += steps_of(T, h) + 1;
  return make_plan(steps, kept * kPointBytes, 119000, "steps: a lower bound (timed runs last at least 10 ms each)");
}

// The conformal step's Newton iteration converges at each step of `key` from the centre cloud.center (one step of each
// scene method, E = H(z0)): where it does not, every run of the study would fail in its first step.
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

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"measure_cloud", "003 Figs 5.1-5.6: measure-preserving discretization of the nonholonomic particle",
                      schema(), {}};
  // every study reads the potential and the centre cloud.center; all but order_study the reference flow
  const auto with = [](std::vector<std::string> keys, bool reference = true) {
    keys.insert(keys.begin(), {"potential", "cloud.center"});
    if (reference) keys.push_back("reference");
    return keys;
  };
  spec.studies = {
      {"shape", "003 Fig 5.1", {"shape.csv", "shape_areas.csv", "shape_symplecticity.csv"},
       with({"seed", "shape", "h", "methods"}),
       [](const Scene& s) { check_first_step(s, "h", {s.real("h")}); }, run_shape, plan_shape},
      {"volumes", "003 Figs 5.2, 5.4", {"volumes_phi*.csv", "volumes_authors_phi*.csv"},
       with({"h", "methods", "t_end", "ptp_window", "cloud", "checkpoint"}),
       check_volumes, run_volumes, plan_volumes},
      {"energies", "003 Figs 5.3, 5.5, 5.6", {"energies_phi*.csv"}, with({"h", "methods", "energies"}),
       [](const Scene& s) {
         check_at_least_one_step(s, "energies.t_end", {s.real("h")}, "h");
         check_first_step(s, "h", {s.real("h")});
       },
       run_energies, plan_energies},
      {"long_run", "H under Phi^(0) and Phi^(4) to long_run.t_end", {"long_run.csv"},
       with({"h", "methods", "long_run"}),
       [](const Scene& s) {
         check_at_least_one_step(s, "long_run.t_end", {s.real("h")}, "h");
         check_first_step(s, "h", {s.real("h")});
       },
       run_long_run, plan_long_run},
      {"order_study", "order of measure preservation (003 Cor. 4.3)", {"order_study.csv"},
       with({"methods", "order_study", "ptp_window", "checkpoint"}, false), check_order_study, run_order_study,
       plan_order_study},
      // the cost runs take the steps of the order study to the end time of the energies
      {"cost", "error against wall time of each discretization; Phi^(4) against Phi^(0) and RK4 at equal cost",
       {"timing_cost.csv", "timing_work_precision.csv"},
       with({"h", "methods", "energies.t_end", "order_study.h", "timing", "cost"}),
       [](const Scene& s) {
         check_at_least_one_step(s, "energies.t_end", s.reals("order_study.h"), "max(order_study.h)");
         check_at_least_one_step(s, "energies.t_end", s.reals("cost.rk4_h"), "max(cost.rk4_h)");
         const auto ms = scene_methods(s);
         if (std::find(ms.begin(), ms.end(), *parse_discretization(method_info(s.text("cost.discretization")).label)) == ms.end())
           s.reject("cost.discretization", "must be one of the scene's methods (its Phi^(4) runs are reused)");
         check_first_step(s, "h", {s.real("h")});
         check_first_step(s, "order_study.h", s.reals("order_study.h"));
       },
       run_cost, plan_cost},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
