// The elastic pendulum (000 eq. (73)): gradient and Hessian-vector product
// against finite differences, and the term assembly.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

#include "geomint/systems/elastic_pendulum.hpp"

using namespace geomint;

namespace elastic_pendulum_test {  // the file's scope (the tests build as one translation unit)

namespace {
const ElasticPendulumWithGravity pendulum{1.3, {SpringTerm{0.7, 1.1}, GravityTerm{1.3, 0.2}}};

Vec<2> fd_gradient(const auto& f, const Vec<2>& q, double d) {
  Vec<2> g;
  for (int i = 0; i < 2; ++i) {
    Vec<2> e = Vec<2>::Zero();
    e[i] = d;
    g[i] = (f((q + e).eval()) - f((q - e).eval())) / (2 * d);
  }
  return g;
}
}  // namespace

TEST(ElasticPendulum, HamiltonianOfEquation73) {
  const auto z = make_state<2>(Vec<2>(0.6, -0.8), Vec<2>(0.3, -0.4));  // |q| = 1
  const double expected = 0.25 / (2 * 1.3) + 0.5 * 0.7 * (1.0 - 1.1) * (1.0 - 1.1) + 1.3 * 0.2 * 0.8;
  EXPECT_NEAR(pendulum.H(z), expected, 1e-15);
}

TEST(ElasticPendulum, GradientAgainstFiniteDifferences) {
  for (const Vec<2> q : {Vec<2>(0.5, -1.0), Vec<2>(-1.4, 0.3), Vec<2>(0.01, 0.02)}) {
    const Vec<2> fd = fd_gradient([](const Vec<2>& x) { return pendulum.U(x); }, q, 1e-6);
    EXPECT_LT((pendulum.U_q(q) - fd).norm(), 1e-7 * (1 + fd.norm()));
    EXPECT_EQ(pendulum.force(q), -pendulum.U_q(q));
  }
}

TEST(ElasticPendulum, HessianVectorProductAgainstFiniteDifferences) {
  const double d = 1e-6;
  for (const Vec<2> q : {Vec<2>(0.5, -1.0), Vec<2>(-1.4, 0.3)}) {
    for (const Vec<2> v : {Vec<2>(1.0, 0.0), Vec<2>(0.3, -2.0)}) {
      const Vec<2> fd = (pendulum.U_q(q + d * v) - pendulum.U_q(q - d * v)) / (2 * d);
      EXPECT_LT((pendulum.U_qq_times(q, v) - fd).norm(), 1e-8 * (1 + fd.norm()));
    }
  }
}

TEST(ElasticPendulum, TermsTheSceneCallsFor) {
  with_elastic_pendulum({1.0, 1.0, 1.0, 0.0}, [](const auto& sys) {
    EXPECT_TRUE((std::is_same_v<std::decay_t<decltype(sys)>, ElasticPendulumWithoutGravity>));
  });
  with_elastic_pendulum({1.0, 1.0, 1.0, 0.2}, [](const auto& sys) {
    EXPECT_TRUE((std::is_same_v<std::decay_t<decltype(sys)>, ElasticPendulumWithGravity>));
    EXPECT_DOUBLE_EQ(sys.U_q(Vec<2>(0.0, -1.0))[1], -0.2);  // spring relaxed at |q| = l: gravity only
  });
}

TEST(ElasticPendulum, RadialOscillationOfSection41) {
  // 000 Sec. 4.1: from rest, with the angle frozen, m r'' = -k (r - l) + m g cos(phi): at r* the
  // radial force vanishes, and the turning point 2 r* - r(0) reaches 0 on the boundary.
  const ElasticPendulumParams p{1.1, 1.3, 0.7, 0.2};
  for (double c : {1.0, 0.3, -0.8}) {
    const double r_star = radial_rest_radius(p, c);
    EXPECT_NEAR(-p.k * (r_star - p.l) + p.m * p.g * c, 0.0, 1e-15);
    EXPECT_NEAR(2 * r_star - polar_boundary_radius(p, c), 0.0, 1e-15);
  }
  // The boundary is the isoline H_0 = U(r = 0) = k l^2 / 2 for a release from rest at (x, y) = r (sin, cos).
  const ElasticPendulumWithGravity cart{p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}};
  for (double phi : {0.0, 0.9, 2.5}) {
    const double b = polar_boundary_radius(p, std::cos(phi));
    EXPECT_NEAR(cart.H(make_state<2>(Vec<2>(b * std::sin(phi), b * std::cos(phi)), Vec<2>(0.0, 0.0))), pivot_energy(p),
                1e-14);
  }
  // Hanging at rest: no force at x = 0, y = l + m g / k.
  EXPECT_LT(cart.U_q(Vec<2>(0.0, hanging_equilibrium_y(p))).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(spring_frequency(p), std::sqrt(0.7 / 1.3));
}

}  // namespace elastic_pendulum_test
