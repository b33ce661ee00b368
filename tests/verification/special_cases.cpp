// Verification (verification.hpp): the registered methods without a generic binding.
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/methods/dispatch.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "verification.hpp"

namespace geomint::verification {

// 000 App. B, Fig. 9: symplectic Euler after the point transformation (82), k = 2, from q = 1, p = 0.
namespace {

auto compensated_symplectic_euler(double k, double h) {
  const PointTransformed sys{oscillator, OscillatorCompensation{k, h}};
  return Processed{[sys](const PhaseState<1>& zb, double step) { return symplectic_euler_pq(sys, zb, step); },
                   [sys](const PhaseState<1>& z, double) { return sys.to_transformed(z); },
                   [sys](const PhaseState<1>& zb, double) { return sys.to_original(zb); }};
}

}  // namespace

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
namespace {

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

}  // namespace

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
namespace {

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

}  // namespace

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

}  // namespace geomint::verification
