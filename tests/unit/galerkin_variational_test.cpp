// The Lobatto and Simpson variational integrators built from their definition
// (001 Sec. 2-4), against the printed one-step matrix (13)-(14), symplecticity,
// stability bounds, and Newton's convergence on a nonlinear step.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>

#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

using namespace geomint;

namespace {
Mat<2> one_step_matrix(const auto& R, const HarmonicOscillator& osc, double h) {  // (p, q) ordering
  const auto ep = galerkin_step(R, osc, make_state(0.0, 1.0), h), eq = galerkin_step(R, osc, make_state(1.0, 0.0), h);
  Mat<2> P;
  P << ep.p[0], eq.p[0], ep.q[0], eq.q[0];
  return P;
}
double radius(const Mat<2>& P) { return Eigen::EigenSolver<Mat<2>>(P).eigenvalues().cwiseAbs().maxCoeff(); }
}  // namespace

TEST(GalerkinRule, LobattoQuadratureIsExactToDegreeFive) {
  const auto R = lobatto_rule();
  for (int d = 0; d <= 6; ++d) {
    double q = 0;
    for (int k = 0; k < 4; ++k) q += R.w[k] * std::pow(R.c[k], d);
    if (d <= 5) EXPECT_NEAR(q, 1.0 / (d + 1), 1e-15) << d;
    else EXPECT_GT(std::abs(q - 1.0 / (d + 1)), 1e-4);  // (2) is exact to degree 5 only
  }
  // D differentiates cubics exactly: phi_m'(c_k) applied to t^3 gives 3 c_k^2.
  for (int k = 0; k < 4; ++k) {
    double d = 0;
    for (int m = 0; m < 4; ++m) d += R.D(k, m) * std::pow(R.c[m], 3);
    EXPECT_NEAR(d, 3 * R.c[k] * R.c[k], 1e-13);
  }
}

TEST(Lobatto, OneStepMatrixEqualsThePrinted13And14) {
  const double m = 1.3, w = 2.1;
  const HarmonicOscillator osc{m, w};
  const auto R = lobatto_rule();
  for (double h : {0.05, 0.3, 1.0, 1.45}) {
    const double x = h * w, x2 = x * x;
    const double dt = 1 + x2 / 30 + x2 * x2 / 1800;                                   // (14)
    const double a = 1 - 7.0 / 15 * x2 + 23.0 / 900 * x2 * x2 - x2 * x2 * x2 / 3600;
    const double b = m * h * w * w / 43200 * (x2 - 60) * (x2 * x2 - 84 * x2 + 720);
    const double c = h / m * (1 - 2.0 / 15 * x2 + x2 * x2 / 300);
    const Mat<2> P = one_step_matrix(R, osc, h);
    EXPECT_NEAR(P(0, 0), a / dt, 1e-13);
    EXPECT_NEAR(P(0, 1), b / dt, 1e-13 * std::max(1.0, std::abs(b / dt)));
    EXPECT_NEAR(P(1, 0), c / dt, 1e-13);
    EXPECT_NEAR(P(1, 1), a / dt, 1e-13);
    EXPECT_NEAR(P.determinant(), 1.0, 1e-13);  // symplectic
  }
}

TEST(Lobatto, StabilityBoundOfEquation10) {
  const HarmonicOscillator osc{1.0, 1.0};
  const auto R = lobatto_rule();
  const double bound = std::sqrt(42.0 - 6.0 * std::sqrt(29.0));
  EXPECT_NEAR(radius(one_step_matrix(R, osc, 0.999 * bound)), 1.0, 1e-12);  // eigenvalues on the unit circle
  EXPECT_GT(radius(one_step_matrix(R, osc, 1.001 * bound)), 1.0 + 1e-3);
  const auto S = simpson_rule();
  EXPECT_NEAR(radius(one_step_matrix(S, osc, 0.999 * std::sqrt(8.0))), 1.0, 1e-12);
  EXPECT_GT(radius(one_step_matrix(S, osc, 1.001 * std::sqrt(8.0))), 1.0 + 1e-3);
}

TEST(Lobatto, NonlinearStepIsSymplectic) {
  const ElasticPendulumWithGravity ep{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.2}}};
  const auto J = galerkin_step_jacobian(lobatto_rule(), ep, make_state<2>(Vec<2>(1.2, 0.6), Vec<2>(0.3, -0.1)), 0.2);
  EXPECT_LT(symplecticity_defect(J), 1e-10);
  // and the Jacobian is that of the step (central differences)
  const auto z = make_state<2>(Vec<2>(1.2, 0.6), Vec<2>(0.3, -0.1));
  auto a = z, b = z;
  a.q[0] += 1e-6, b.q[0] -= 1e-6;
  const auto za = galerkin_step(lobatto_rule(), ep, a, 0.2), zb = galerkin_step(lobatto_rule(), ep, b, 0.2);
  EXPECT_NEAR(J(0, 0), (za.q[0] - zb.q[0]) / 2e-6, 1e-7);
  EXPECT_NEAR(J(2, 0), (za.p[0] - zb.p[0]) / 2e-6, 1e-7);
}

TEST(Lobatto, NewtonConvergesQuadraticallyOnANonlinearStep) {
  const NonlinearPendulum pend;
  const auto R = lobatto_rule();
  const GalerkinStage<3, NonlinearPendulum> stage{R, pend, Vec<1>(1.0), Vec<1>(0.4), 0.3};
  auto x = stage.guess();
  std::vector<double> res;
  for (int it = 0; it < 6; ++it) {
    res.push_back(stage.residual(x).norm());
    x -= stage.jacobian(x).partialPivLu().solve(stage.residual(x));
  }
  // r_{k+1} <= C r_k^2 while above round-off
  for (std::size_t k = 0; k + 1 < res.size() && res[k + 1] > 1e-13; ++k)
    EXPECT_LT(res[k + 1], 10 * res[k] * res[k]) << k;
  EXPECT_LT(res.back(), 1e-13);
}

TEST(ImplicitMidpoint, IsTheCayleyMapOnTheOscillator) {
  // On q'' = -q the midpoint rule is (I - hA/2)^{-1} (I + hA/2): q1 = ((1 - h^2/4) q + h p) / (1 + h^2/4).
  const HarmonicOscillator osc;
  const double h = 0.3;
  const auto z = implicit_midpoint(osc, make_state(1.0, 0.5), h);
  EXPECT_NEAR(z.q[0], ((1 - h * h / 4) * 1.0 + h * 0.5) / (1 + h * h / 4), 1e-15);
  EXPECT_NEAR(z.p[0], ((1 - h * h / 4) * 0.5 - h * 1.0) / (1 + h * h / 4), 1e-15);
}
