// The elastic pendulum (000 eq. (73)): gradient and Hessian-vector product
// against finite differences, and the term assembly.
#include <gtest/gtest.h>

#include <type_traits>

#include "geomint/systems/elastic_pendulum.hpp"

using namespace geomint;

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
