// The polar elastic pendulum (000 eq. (72)) against the Cartesian one (73)
// through the point transformation and its momentum map (41).
#include <gtest/gtest.h>

#include <cmath>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/transforms/polar.hpp"

using namespace geomint;

namespace polar_test {  // the file's scope (the tests build as one translation unit)

namespace {
const double l = 1.0, m = 1.3, k = 0.9, g = 0.02;
const ElasticPendulumWithGravity cart{m, {SpringTerm{k, l}, GravityTerm{m, g}}};
const ElasticPendulumPolarWithGravity polar{m, {SpringPolarTerm{k, l}, GravityPolarTerm{m, g}}};
const PhaseState<2> z0 = make_state<2>(Vec<2>(0.7, 1.1), Vec<2>(0.3, -0.2));

double distance(const PhaseState<2>& a, const PhaseState<2>& b) {
  return std::sqrt((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm());
}
}  // namespace

TEST(Polar, TransformationRoundTripAndSameHamiltonian) {
  const auto zp = polar_from_cartesian(z0);
  EXPECT_NEAR(zp.q[0], std::hypot(0.7, 1.1), 1e-15);
  EXPECT_LT(distance(cartesian_from_polar(zp), z0), 1e-15);
  EXPECT_NEAR(polar.H(zp), cart.H(z0), 1e-15);
  EXPECT_NEAR(angular_momentum(z0), -zp.p[1], 1e-15);
  // Hanging at rest: x = 0, y = l + m g / k is theta = 0.
  EXPECT_EQ(polar_from_cartesian(make_state<2>(Vec<2>(0.0, 1.2), Vec<2>(0.0, 0.0))).q[1], 0.0);
}

TEST(Polar, GradientsAgainstFiniteDifferences) {
  const auto zp = polar_from_cartesian(z0);
  const double d = 1e-6;
  for (int i = 0; i < 2; ++i) {
    auto a = zp, b = zp;
    a.q[i] += d, b.q[i] -= d;
    EXPECT_NEAR(polar.H_q(zp.q, zp.p)[i], (polar.H(a) - polar.H(b)) / (2 * d), 1e-8);
    a = zp, b = zp;
    a.p[i] += d, b.p[i] -= d;
    EXPECT_NEAR(polar.H_p(zp.q, zp.p)[i], (polar.H(a) - polar.H(b)) / (2 * d), 1e-8);
  }
  auto a = zp, b = zp;
  a.p[1] += d, b.p[1] -= d;
  EXPECT_NEAR(polar.H_qp(zp.q, zp.p)(0, 1), (polar.H_q(a.q, a.p)[0] - polar.H_q(b.q, b.p)[0]) / (2 * d), 1e-8);
}

TEST(Polar, SameExactTrajectory) {
  // The same motion in both coordinates (odeint references), mapped by (41).
  const auto zc = reference_solution(cart, z0, 5.0, 1e-13, 1e-13);
  const auto zp = reference_solution(polar, polar_from_cartesian(z0), 5.0, 1e-13, 1e-13);
  EXPECT_LT(distance(cartesian_from_polar(zp), zc), 1e-10);
}

TEST(Polar, SymplecticEulerTrajectoriesAgreeAsHTendsToZero) {
  // Symplectic Euler differs between the coordinate systems (Sec. 4) by O(h): the gap halves with h.
  double previous = 0;
  for (double h : {0.01, 0.005, 0.0025}) {
    const auto n = std::llround(2.0 / h);
    const auto step = [](const auto& sys) {
      return one_step_method([&sys](const auto& z, double dt) { return symplectic_euler_pq(sys, z, dt); });
    };
    const auto zc = integrate(step(cart), z0, h, n);
    const auto zp = integrate(step(polar), polar_from_cartesian(z0), h, n);
    const double gap = distance(cartesian_from_polar(zp), zc);
    if (previous > 0) EXPECT_NEAR(previous / gap, 2.0, 0.1);
    previous = gap;
  }
}

TEST(Polar, PrintedInverseOf63GivesAnotherPendulum) {
  // (72) and (73) are one pendulum only with theta = atan2(x, y), the first half of (63); with the
  // second half as printed (x = r cos(theta), y = r sin(theta)) gravity -m g y turns into
  // -m g r sin(theta), and H differs by m g (y - x) at rest.
  for (const Vec<2> q : {Vec<2>(0.7, 1.1), Vec<2>(-1.2, 0.4), Vec<2>(0.3, -0.9)}) {
    const auto at_rest = [](const Vec<2>& position) { return make_state<2>(position, Vec<2>(0.0, 0.0)); };
    EXPECT_NEAR(polar.H(at_rest(polar_from_cartesian(at_rest(q)).q)), cart.H(at_rest(q)), 1e-15);
    const double printed = polar.H(at_rest(polar_position_as_printed_63(q)));
    EXPECT_NEAR(printed - cart.H(at_rest(q)), m * g * (q[1] - q[0]), 1e-15);
    EXPECT_GT(std::abs(printed - cart.H(at_rest(q))), 1e-3);
  }
}

}  // namespace polar_test
