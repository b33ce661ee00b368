// The odeint reference against closed-form solutions of the elastic pendulum:
// radial oscillation without gravity, vertical oscillation with gravity.
#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace reference_test
