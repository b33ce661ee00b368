// Verification of every registered method (src/geomint/methods/registry.hpp):
// its declared orders by the slope of the error (least squares on log-log,
// observables/order_fit.hpp), its declared linear-stability bounds and its
// declared properties. A method with a generic binding (methods/methods.hpp)
// is checked from its registry entry alone; the others have a case below.
// ctest runs one test per registered method, verification.<name>.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/unit_mass.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "../hard_case.hpp"

using namespace geomint;

namespace {

void report(const std::string& what, double value) { std::printf("  %-64s %.4g\n", what.c_str(), value); }

// ---- the problems ----

// The errors at these end times approach their leading terms without cancellations.
const HarmonicOscillator oscillator{1.0, 1.0};  // q'' = -q, closed form
const PhaseState<1> oscillator_z0 = make_state(1.0, 0.5);
constexpr double oscillator_T = 10.0;
const UnsymmetricPendulum pendulum;  // 004 Fig. 2: no symmetry that could raise an order
const PhaseState<1> pendulum_z0 = make_state(0.5, 1.0);  // a libration, H = -0.21
constexpr double pendulum_T = 4.0;
const HenonHeiles henon_heiles{{}, 3};  // 004 Fig. 3: two degrees of freedom
const PhaseState<2> generic_point = make_state<2>(Vec<2>(0.12, -0.21), Vec<2>(0.31, 0.17));
constexpr double property_h = 0.5;
const NonholonomicParticle particle{Potential::harmonic};  // 003 Sec. 5.2
const PhaseState<2> particle_z0 = make_state<2>(Vec<2>(0.0, 0.0), Vec<2>(1.0, 1.0));  // the centre of 003's clouds

// The saddle H = (p^2 - q^2)/2: along (1, -1) it is z' = -z, so a Runge-Kutta
// method maps (1, -1) to R(-h) (1, -1), R its stability function.
struct Saddle : UnitMassSeparable<1> {
  double U(const Vec<1>& q) const { return -0.5 * q[0] * q[0]; }
  Vec<1> U_q(const Vec<1>& q) const { return -q; }
  Mat<1> U_qq(const Vec<1>&) const { return Mat<1>::Constant(-1.0); }
  Vec<1> U_qq_times(const Vec<1>&, const Vec<1>& v) const { return -v; }
  Vec<1> force(const Vec<1>& q) const { return q; }
  Vec<1> H_q(const Vec<1>& q, const Vec<1>&) const { return U_q(q); }
};

// A reference to 100x its own error: the solution at tol against the one at tol/100.
struct Reference {
  PhaseState<1> z;
  double floor;
};
const Reference& pendulum_reference() {
  static const Reference r = [] {
    const auto a = reference_solution(pendulum, pendulum_z0, pendulum_T, 1e-14, 1e-14);
    return Reference{a, 100 * phase_distance(a, reference_solution(pendulum, pendulum_z0, pendulum_T, 1e-16, 1e-16))};
  }();
  return r;
}

// ---- orders ----

struct Steps {
  std::int64_t first = 8, last = 1 << 17;
};

// Errors e(n) after n = first 2^(k/2) steps to the time T (2^(k/4) above order 4,
// whose errors fall faster), while e(n) is above the floor (the reference's error,
// and the round-off floor of each of the n steps) and n <= last. The order is fitted
// over the errors in (floor, 10^-order], where the leading term dominates, up to
// the first that does not decrease.
template <class Error>
void expect_order(const std::string& what, int declared, double T, double floor, Error error, Steps steps = {},
                  double tolerance = 0.1) {
  std::vector<double> hs, es;
  const double per_octave = declared > 4 ? 4.0 : 2.0;
  std::int64_t previous = 0;
  for (int k = 0;; ++k) {
    const std::int64_t n = std::llround(static_cast<double>(steps.first) * std::pow(2.0, k / per_octave));
    if (n > steps.last) break;
    if (n == previous) continue;
    previous = n;
    const double e = error(n);
    if (!std::isfinite(e)) continue;  // beyond a stability bound
    if (e <= std::max(floor, roundoff_floor() * static_cast<double>(n))) break;
    if (e > std::pow(10.0, -declared)) continue;
    if (!es.empty() && e >= es.back()) break;
    hs.push_back(T / static_cast<double>(n)), es.push_back(e);
  }
  ASSERT_GE(es.size(), 3u) << what << ": fewer than 3 errors in (floor, 10^-order]";
  const OrderFit f = fit_order(hs, es, 0.0, what.c_str());
  EXPECT_CASE_NEAR(what + " (" + std::to_string(f.points) + " points)", f.order, declared, tolerance);
}

// |z_n - z(T)| of n steps of the method (or of its kernel alone) bound to sys by name.
template <class Sys, class Z>
double final_error(std::string_view name, bool kernel, const Sys& sys, const Z& z0, const Z& zT, double T, std::int64_t n) {
  const auto error = [&](const auto& m) { return phase_distance(integrate(m, z0, T / static_cast<double>(n), n), zT); };
  return kernel ? with_kernel(name, sys, error) : with_method(name, sys, error);
}

// On the oscillator (closed form) and the unsymmetric pendulum (reference); a processed method
// with its effective order, and its kernel alone with the kernel order.
void check_orders(const MethodInfo& m) {
  const bool processed = m.family == Family::processed;
  // Fehlberg's eighth-order formula shows slopes 8.9-9.8 on the pendulum over all the range above
  // the reference's error (its ninth-order terms dominate there): its order is fitted on the oscillator.
  const bool nonlinear = m.name != "odeint_rkf78";
  for (const bool kernel : {false, true}) {
    if (kernel && !processed) continue;
    const int order = kernel ? m.kernel_order : m.order;
    const std::string which = kernel ? "kernel order" : processed ? "effective order" : "order";
    const PhaseState<1> exact = oscillator.exact(oscillator_z0, oscillator_T);
    expect_order(which + " on the oscillator", order, oscillator_T, 0.0, [&](std::int64_t n) {
      return final_error(m.name, kernel, oscillator, oscillator_z0, exact, oscillator_T, n);
    });
    if (!nonlinear) continue;
    const Reference& ref = pendulum_reference();
    expect_order(which + " on the unsymmetric pendulum", order, pendulum_T, ref.floor, [&](std::int64_t n) {
      return final_error(m.name, kernel, pendulum, pendulum_z0, ref.z, pendulum_T, n);
    });
  }
}

// ---- linear stability ----

// Spectral radius of the kernel's one-step matrix on q'' = -q, and a run at 0.99x the bound over
// 1e4 periods; on the saddle, R(-h) along its stable direction.
void check_bounds(const MethodInfo& m) {
  const double b = m.oscillatory_bound;
  const auto radius = [&](double wh) {
    return with_kernel(m.name, oscillator, [&](const auto& k) { return spectral_radius(one_step_matrix(k, wh)); });
  };
  if (b == 0) {
    EXPECT_GT(radius(1e-2), 1.0) << "unstable for every h";
  } else if (std::isinf(b)) {
    for (double wh : {10.0, 100.0}) {
      EXPECT_LE(radius(wh), 1 + 1e-12) << "w h = " << wh;
    }
  } else if (std::isfinite(b)) {
    EXPECT_CASE("spectral radius at 0.99 x the oscillatory bound", radius(0.99 * b), "<=", 1 + 1e-12);
    EXPECT_CASE("spectral radius at 1.01 x the oscillatory bound", radius(1.01 * b), ">", 1 + 1e-6);
    // A run at 0.99 x the bound over 1e4 periods from |z0| = 1 stays within the condition number
    // of the eigenvectors (not small there: symplectic Euler's orbit p^2 + q^2 + h p q = 1 reaches |z| = 10).
    const double h = 0.99 * b;
    const auto n = static_cast<std::int64_t>(std::ceil(1e4 * 2 * std::numbers::pi / h));
    double largest = 0, kappa = 0;
    with_kernel(m.name, oscillator, [&](const auto& k) {
      kappa = eigenvector_condition(one_step_matrix(k, h));
      integrate(k, make_state(1.0, 0.0), h, n, [&](std::int64_t, const PhaseState<1>& z) {
        largest = std::max(largest, std::hypot(z.q[0], z.p[0]));
      });
    });
    EXPECT_CASE("max |z| over 1e4 periods at 0.99 x the oscillatory bound, |z0| = 1 (bound: the condition number "
                "of the eigenvectors)", largest, "<=", kappa * (1 + 1e-6));
  }

  const double r = m.real_bound;
  if (std::isnan(r)) return;
  const auto R = [&](double h) {  // z_1 = R(-h) (1, -1)
    const PhaseState<1> z = with_kernel(m.name, Saddle{}, [&](const auto& k) { return integrate(k, make_state(1.0, -1.0), h, 1); });
    EXPECT_NEAR(z.p[0], -z.q[0], 1e-12 * std::max(1.0, std::abs(z.q[0])));
    return std::abs(z.q[0]);
  };
  if (std::isinf(r)) {
    for (double h : {10.0, 100.0}) {
      EXPECT_LE(R(h), 1.0) << "h |lambda| = " << h;
    }
  } else {
    EXPECT_CASE("|R(-h)| at 0.99 x the real bound", R(0.99 * r), "<=", 1.0);
    EXPECT_CASE("|R(-h)| at 1.01 x the real bound", R(1.01 * r), ">", 1.0 + 1e-6);
  }
}

// ---- properties ----

// J of one kernel step at a generic point of a nonlinear problem, by
// Richardson-extrapolated central differences, d = 1e-3: truncation O(d^4) ~ 1e-12,
// round-off ~ eps/d ~ 1e-13, so the defects below are good to ~1e-11.
template <class Sys>
void check_properties(const MethodInfo& m, const Sys& sys, const PhaseState<2>& z, double h) {
  const Mat<4> J = with_kernel(m.name, sys, [&](const auto& k) { return step_jacobian_richardson(k, z, h, 1e-3); });
  const double defect = symplecticity_defect(J);
  if (m.has(property::symplectic)) {
    EXPECT_CASE("symplecticity defect max |J^T Omega J - Omega| of one step", defect, "<", 1e-10);
  } else {
    report("symplecticity defect max |J^T Omega J - Omega|", defect);
  }
  if (m.has(property::volume_preserving)) {
    EXPECT_CASE("|det J - 1| of one step", std::abs(J.determinant() - 1), "<", 1e-10);
    // 004 Sect. 1.3: volume preserving but, for two degrees of freedom, not symplectic.
    if (!m.has(property::symplectic)) {
      EXPECT_CASE("symplecticity defect of a volume-preserving, not symplectic method", defect, ">", 1e-6);
    }
  }
  if (m.has(property::time_reversible)) {
    const PhaseState<2> back = with_kernel(m.name, sys, [&](const auto& k) {
      return integrate(k, integrate(k, z, h, 1), -h, 1);
    });
    EXPECT_CASE("|kernel(kernel(z, h), -h) - z| / |z|", phase_distance(back, z) / phase_distance(z, PhaseState<2>{}),
                "<", 1e-13);
  }
}

void verify_bound_method(const MethodInfo& m) {
  check_orders(m);
  check_bounds(m);
  check_properties(m, henon_heiles, generic_point, property_h);
  if (m.family == Family::variational) {  // the exact Jacobian (implicit function theorem) as well
    const auto J = m.name == "lobatto" ? galerkin_step_jacobian(lobatto_rule(), henon_heiles, generic_point, property_h)
                                       : galerkin_step_jacobian(simpson_rule(), henon_heiles, generic_point, property_h);
    EXPECT_CASE("symplecticity defect of the exact Jacobian", symplecticity_defect(J), "<", 1e-12);
    const Mat<4> fd = with_method(m.name, henon_heiles, [&](const auto& k) {
      return step_jacobian_richardson(k, generic_point, property_h, 1e-3);
    });
    EXPECT_CASE("max |J_fd - J_exact|", (fd - J).cwiseAbs().maxCoeff(), "<", 1e-10);
  }
}

// ---- the methods without a generic binding ----

// 000 App. B, Fig. 9: symplectic Euler after the point transformation (82), k = 2, from q = 1, p = 0.
auto compensated_symplectic_euler(double k, double h) {
  const PointTransformed sys{oscillator, OscillatorCompensation{k, h}};
  return Processed{[sys](const PhaseState<1>& zb, double step) { return symplectic_euler_pq(sys, zb, step); },
                   [sys](const PhaseState<1>& z, double) { return sys.to_transformed(z); },
                   [sys](const PhaseState<1>& zb, double) { return sys.to_original(zb); }};
}

void verify_compensated_symplectic_euler(const MethodInfo& m) {
  // Fig. 9: max over [0, 20] of |H - H0|, with (order) and without (kernel alone) the transformation.
  const double T = 20, H0 = oscillator.H(make_state(1.0, 0.0));
  const auto energy_error = [&](const auto& method, double h, std::int64_t n) {
    double e = 0;
    integrate(method, make_state(1.0, 0.0), h, n, [&](std::int64_t, const PhaseState<1>& z) { e = std::max(e, std::abs(oscillator.H(z) - H0)); });
    return e;
  };
  expect_order("order of the energy error (000 Fig. 9)", m.order, T, roundoff_floor(), [&](std::int64_t n) {
    const double h = T / static_cast<double>(n);
    return energy_error(compensated_symplectic_euler(2.0, h), h, n);
  }, {100, 1 << 14});  // h from 0.2, as Fig. 9
  expect_order("kernel alone (symplectic Euler): order of the energy error", m.kernel_order, T, roundoff_floor(), [&](std::int64_t n) {
    const double h = T / static_cast<double>(n);
    return with_method("symplectic_euler_pq", oscillator, [&](const auto& se) { return energy_error(se, h, n); });
  }, {100, 1 << 14});
  // The transformed Hamiltonian is nonlinear: the step (pre, kernel, post) is symplectic (one degree of freedom: det J = 1).
  const Mat<2> J = step_jacobian_richardson(compensated_symplectic_euler(2.0, 0.1), make_state(0.6, 0.3), 0.1, 1e-3);
  EXPECT_CASE("symplecticity defect of one step", symplecticity_defect(J), "<", 1e-10);
}

// Psi_{h,E} (003 Sec. 4.2) with the discrete Lagrangian d, as a method on (q, p) at fixed E.
auto conformal_method(Discretization d, double E) { return conformal_variational_method(d, particle, E); }

// The error at T of Psi_{h,E(h)} from the centre of 003's clouds against the reference of (3.8).
template <class EnergyOf>
void expect_conformal_order(const std::string& what, Discretization d, EnergyOf E_of_h) {
  const double T = 2;
  const auto ref = reference_solution(particle, to_array(particle_z0), T, 1e-13, 1e-13);
  const auto ref_tight = reference_solution(particle, to_array(particle_z0), T, 1e-15, 1e-15);
  const double floor = 100 * phase_distance(from_array(ref), from_array(ref_tight));
  expect_order(what, 2, T, floor, [&](std::int64_t n) {
    const double h = T / static_cast<double>(n);
    return phase_distance(integrate(conformal_method(d, E_of_h(h)), particle_z0, h, n), from_array(ref));
  }, {8, 1 << 12});
}

void verify_conformal(const MethodInfo& m) {
  const Discretization d = *parse_discretization(m.label);
  expect_conformal_order("order with E = H(z0)", d, [](double) { return particle.H(particle_z0); });
  // Symplectic and symmetric for K_E at fixed E, at a generic point.
  const auto method = conformal_method(d, 0.8);
  const PhaseState<2> z = make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.9, 1.1));
  const double h = 0.25;
  const double defect = symplecticity_defect(step_jacobian_richardson(method, z, h, 1e-3));
  EXPECT_CASE("symplecticity defect at fixed E", defect, "<", 1e-10);
  const PhaseState<2> back = integrate(method, integrate(method, z, h, 1), -h, 1);
  EXPECT_CASE("|Psi_{-h}(Psi_h(z)) - z| / |z|", phase_distance(back, z) / phase_distance(z, PhaseState<2>{}), "<", 1e-13);
}

// Peak-to-peak over t <= 20 of V(t)/V(0) - 1, V the mu^(ell)_mod volume of the convex hull of
// a 600-cell cloud of radius 1e-5 around the centre (plus the centre) under Phi^(ell).
double measure_ptp(Discretization d, int ell, double h) {
  std::vector<Point4> unit{{0, 0, 0, 0}};
  for (const Point4& v : six_hundred_cell_vertices()) unit.push_back(v);
  const ModifiedSeries series(d, particle, h);
  std::vector<PhaseState<2>> cloud;
  std::vector<double> E;
  for (const Point4& p : scaled_cloud(unit, to_array(particle_z0), 1e-5)) {
    cloud.push_back(from_array(p));
    E.push_back(series.E(ell, cloud.back()));  // 003 (4.5): E = E^(ell)(z_0) per trajectory
  }
  double V0 = 0, lo = 0, hi = 0;
  const auto n = static_cast<std::int64_t>(std::floor(20 / h + 1e-9));
  for (std::int64_t j = 0; j <= n; ++j) {
    std::vector<Point4> points;
    for (const auto& z : cloud) points.push_back(to_array(z));
    const double V = hull_integral(points, hull_facets(points), points.front(),
                                   [&](const Point4& x) { return 1.0 / series.N(ell, from_array(x)); });
    if (j == 0) V0 = V;
    lo = std::min(lo, V / V0 - 1), hi = std::max(hi, V / V0 - 1);
    for (std::size_t i = 0; i < cloud.size(); ++i) cloud[i] = conformal_variational_step(d, particle, cloud[i], h, E[i]).z;
  }
  return hi - lo;
}

void verify_phi(const MethodInfo& m) {
  const int ell = m.measure_order - 2;
  for (const Discretization d : all_discretizations)
    expect_conformal_order(std::string("order, discretization ") + discretization_name(d), d,
                           [&](double h) { return ModifiedSeries(d, particle, h).E(ell, particle_z0); });
  // The measure order on the discretization TM, whose constants are the largest, so that its asymptotic
  // range lies farthest above the hull volumes' round-off (~1e-9 at radius 1e-5), over h = 0.25 2^(-k/4),
  // k = 4..8. ell = 6: the h^(ell+4) term still shows at h = 0.25 (local slopes 8.5 there) and the
  // round-off is reached by h = 0.07, so k = 2..6 is the cleanest range and the tolerance is 0.25.
  const int k0 = ell == 6 ? 2 : 4;
  std::vector<double> hs, ptp;
  for (int k = k0; k <= k0 + 4; ++k) {
    hs.push_back(0.25 * std::pow(2.0, -k / 4.0));
    ptp.push_back(measure_ptp(Discretization::TM, ell, hs.back()));
  }
  const OrderFit f = fit_order(hs, ptp, 0.0, "measure order");
  EXPECT_CASE_NEAR("order of mu^(ell)_mod preservation (TM, " + std::to_string(f.points) + " points)", f.order,
                   m.measure_order, ell == 6 ? 0.25 : 0.1);
}

// The reference of every experiment: within 100x its tolerance of the closed form.
void verify_bulirsch_stoer(const MethodInfo&) {
  for (double tol : {1e-8, 1e-10, 1e-12}) {
    const double e = phase_distance(reference_solution(oscillator, oscillator_z0, 10.0, tol, tol), oscillator.exact(oscillator_z0, 10.0));
    char what[80];
    std::snprintf(what, sizeof what, "error on the oscillator at t = 10 / tolerance, tolerance %.0e", tol);
    EXPECT_CASE(what, e / tol, "<", 100.0);
  }
}

using Case = void (*)(const MethodInfo&);
const std::map<std::string_view, Case> cases = {
    {"compensated_symplectic_euler", verify_compensated_symplectic_euler},
    {"conformal_M", verify_conformal}, {"conformal_MT", verify_conformal}, {"conformal_TM", verify_conformal},
    {"conformal_TT", verify_conformal}, {"conformal_T", verify_conformal},
    {"phi0", verify_phi}, {"phi2", verify_phi}, {"phi4", verify_phi}, {"phi6", verify_phi},
    {"odeint_bulirsch_stoer", verify_bulirsch_stoer}};

std::vector<std::string> registered_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : method_registry()) names.emplace_back(m.name);
  return names;
}

}  // namespace

class Verification : public testing::TestWithParam<std::string> {};

TEST_P(Verification, DeclaredOrdersBoundsAndProperties) {
  const MethodInfo& m = method_info(GetParam());
  const auto bound = methods_for<UnsymmetricPendulum>();
  if (std::find(bound.begin(), bound.end(), m.name) != bound.end()) {
    verify_bound_method(m);
  } else if (const auto c = cases.find(m.name); c != cases.end()) {
    c->second(m);
  } else {
    FAIL() << "registered method " << m.name << " has no verification case: give it a generic binding "
           << "(src/geomint/methods/methods.hpp) or a case in tests/verification/verification_test.cpp";
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, Verification, testing::ValuesIn(registered_names()),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });
