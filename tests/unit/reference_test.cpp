// The odeint reference against closed-form solutions of the elastic pendulum:
// radial oscillation without gravity, vertical oscillation with gravity.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "geomint/reference/odeint_reference.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

using namespace geomint;

namespace reference_test {  // the file's scope (the tests build as one translation unit)

TEST(Reference, RadialOscillationWithoutGravity) {
  // q = (x, 0), p = (px, 0), x > 0: x(t) = l + (x0 - l) cos wt + px0/(m w) sin wt, w = sqrt(k/m).
  const double l = 1.0, m = 2.0, k = 3.0, w = std::sqrt(k / m), t = 4.0;
  const ElasticPendulumWithoutGravity sys{m, {SpringTerm{k, l}}};
  const auto z0 = make_state<2>(Vec<2>(1.3, 0.0), Vec<2>(0.4, 0.0));
  const auto z = reference_solution(sys, z0, t, 1e-13, 1e-13);
  const double x = l + 0.3 * std::cos(w * t) + 0.4 / (m * w) * std::sin(w * t);
  const double px = m * (-0.3 * w * std::sin(w * t) + 0.4 / m * std::cos(w * t));
  EXPECT_NEAR(z.q[0], x, 1e-12);
  EXPECT_NEAR(z.p[0], px, 1e-12);
  EXPECT_EQ(z.q[1], 0.0);
}

TEST(Reference, VerticalOscillationWithGravity) {
  // (73) has U = -m g y: y points down. x = 0, y > 0: y'' = -(k/m)(y - l) + g, about y* = l + m g / k.
  const double l = 1.0, m = 1.0, k = 1.0, g = 0.2, w = 1.0, t = 4.0, ys = l + m * g / k;
  const ElasticPendulumWithGravity sys{m, {SpringTerm{k, l}, GravityTerm{m, g}}};
  const auto z0 = make_state<2>(Vec<2>(0.0, 1.5), Vec<2>(0.0, 0.1));
  const auto z = reference_solution(sys, z0, t, 1e-13, 1e-13);
  EXPECT_NEAR(z.q[1], ys + (1.5 - ys) * std::cos(w * t) + 0.1 * std::sin(w * t), 1e-12);
  EXPECT_NEAR(z.p[1], -(1.5 - ys) * std::sin(w * t) + 0.1 * std::cos(w * t), 1e-12);
  EXPECT_EQ(z.q[0], 0.0);
}

// The integrator kept across calls lands on every sample time: x' = -x sampled at t = 0.5, 1, ..., 3.
TEST(Reference, IntegratorKeptAcrossSamplesLandsOnEachTime) {
  ReferenceIntegrator reference(1, [](const double* x, double* dxdt) { dxdt[0] = -x[0]; }, 1e-13, 1e-13);
  std::array<double, 1> x{1.0};
  for (int j = 1; j <= 6; ++j) {
    reference.integrate(x, 0.5 * (j - 1), 0.5 * j, 0.05);
    EXPECT_NEAR(x[0], std::exp(-0.5 * j), 1e-12) << "t = " << 0.5 * j;
  }
}

TEST(Reference, FailuresAreReportedNotReturned) {
  ReferenceIntegrator blow_up(1, [](const double* x, double* dxdt) { dxdt[0] = x[0] * x[0]; }, 1e-10, 1e-10);
  std::array<double, 1> x{1.0};  // x = 1/(1 - t): infinite at t = 1
  EXPECT_THROW(blow_up.integrate(x, 0.0, 2.0, 1e-3), NumericalFailure);
  std::array<double, 2> wrong{1.0, 2.0};
  EXPECT_THROW(blow_up.integrate(wrong, 0.0, 1.0, 1e-3), std::invalid_argument);
}

}  // namespace reference_test
