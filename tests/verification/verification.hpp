#pragma once
// Verification of every registered method (src/geomint/methods/registry.hpp):
// its declared orders by the slope of the error (least squares on log-log,
// observables/order_fit.hpp), its declared linear-stability bounds and its
// declared properties. A method with a generic binding (methods/methods.hpp)
// is checked from its registry entry alone; the others have a case (special_cases.cpp).
// ctest runs one test per registered method, verification.<name>.
//
// The files: this header (the problems, the order fit), orders.cpp, stability.cpp and properties.cpp
// (the checks of a method with a generic binding), special_cases.cpp (the methods without one), and
// verification_test.cpp (the test of each registered method). Each check instantiates every method on
// its problems in a file of its own: the files compile in parallel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"
#include "geomint/systems/unit_mass.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"
#include "../hard_case.hpp"

namespace geomint::verification {

inline void report(const std::string& what, double value) { std::printf("  %-64s %.4g\n", what.c_str(), value); }

// The errors at these end times approach their leading terms without cancellations.
inline const HarmonicOscillator oscillator{1.0, 1.0};  // q'' = -q, closed form
inline const PhaseState<1> oscillator_z0 = make_state(1.0, 0.5);
inline constexpr double oscillator_T = 10.0;
inline const UnsymmetricPendulum pendulum;  // 004 Fig. 2: no symmetry that could raise an order
inline const PhaseState<1> pendulum_z0 = make_state(0.5, 1.0);  // a libration, H = -0.21
inline constexpr double pendulum_T = 4.0;
inline const HenonHeiles henon_heiles{{}, 3};  // 004 Fig. 3: two degrees of freedom
inline const PhaseState<2> generic_point = make_state<2>(Vec<2>(0.12, -0.21), Vec<2>(0.31, 0.17));
inline constexpr double property_h = 0.5;
inline const NonholonomicParticle particle{Potential::harmonic};  // 003 Sec. 5.2
inline const PhaseState<2> particle_z0 = make_state<2>(Vec<2>(0.0, 0.0), Vec<2>(1.0, 1.0));  // the centre of 003's clouds

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
inline const Reference& pendulum_reference() {
  static const Reference r = [] {
    const auto a = reference_solution(pendulum, pendulum_z0, pendulum_T, 1e-14, 1e-14);
    return Reference{a, 100 * phase_distance(a, reference_solution(pendulum, pendulum_z0, pendulum_T, 1e-16, 1e-16))};
  }();
  return r;
}

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

// The checks of a method with a generic binding (methods/methods.hpp).
void check_orders(const MethodInfo& m);      // orders.cpp
void check_bounds(const MethodInfo& m);      // stability.cpp
void check_properties(const MethodInfo& m);  // properties.cpp

// The methods without one (special_cases.cpp).
void verify_compensated_symplectic_euler(const MethodInfo& m);
void verify_conformal(const MethodInfo& m);
void verify_phi(const MethodInfo& m);
void verify_bulirsch_stoer(const MethodInfo& m);

}  // namespace geomint::verification
