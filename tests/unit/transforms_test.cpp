// The variable transformations (15), (18), the point transformation (82) and
// the canonical transformation (41) it induces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../hard_case.hpp"
#include "geomint/systems/exponential_decay.hpp"
#include "geomint/systems/gompertz.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "geomint/transforms/variable_transform.hpp"

using namespace geomint;

namespace transforms_test {  // the file's scope (the tests build as one translation unit)

namespace {
double central_difference(const auto& f, double x, double d) { return (f(x + d) - f(x - d)) / (2 * d); }
}  // namespace

TEST(DecayCompensation, InverseRoundTrip) {
  const DecayCompensation psi{1.7};
  // exp(alpha * ln(y) / alpha): relative round-off grows with |ln y|.
  for (double y : {1e-8, 0.01, 0.5, 1.0, 3.0, 1e6})
    EXPECT_NEAR(psi.inverse(psi(y)), y, 1e-15 * (1 + std::abs(std::log(y))) * y);
  for (double yb : {-10.0, -1.0, 0.0, 2.5}) EXPECT_NEAR(psi(psi.inverse(yb)), yb, 1e-15);
}

TEST(DecayCompensation, DerivativeAndConstantField) {
  const DecayCompensation psi{1.7};
  const TransformedODE t{ExponentialDecay{1.7}, psi};
  for (double y : {0.1, 1.0, 4.0}) {
    EXPECT_NEAR(psi.derivative(y), central_difference(psi, y, 1e-6 * y), 1e-7 * psi.derivative(y));
    EXPECT_NEAR(t.f(psi(y)), -1.0, 1e-15);  // (3) with (15): C1 = -1 (the paper's (16) prints -alpha)
  }
}

TEST(GompertzCompensation, InverseRoundTripAndConstantField) {
  const Gompertz g{2.0, 0.5};
  const GompertzCompensation psi{2.0, 0.5, 3.0};
  EXPECT_NEAR(psi(3.0), 0.0, 1e-16);  // C2 = 0
  const TransformedODE t{g, psi};
  for (double y : {0.5, 3.0, 20.0, 54.0}) {
    EXPECT_NEAR(psi.inverse(psi(y)), y, 1e-13 * y);
    EXPECT_NEAR(psi.derivative(y), central_difference(psi, y, 1e-6 * y), 1e-7 * std::abs(psi.derivative(y)));
    EXPECT_NEAR(t.f(psi(y)), 1.0, 1e-14);  // (13) with C1 = 1
  }
}

TEST(GompertzCompensation, TransformedCoordinateIsTime) {
  // Psi(y(t)) = t along the exact solution, so explicit Euler with f = 1 is exact.
  const Gompertz g{2.0, 0.5};
  const GompertzCompensation psi{2.0, 0.5, 3.0};
  for (double t : {0.0, 0.9, 5.0, 10.8}) EXPECT_NEAR(psi(g.exact(3.0, t)), t, 1e-13 * (1 + t));
}

TEST(OscillatorCompensation, DerivativesAgainstFiniteDifferences) {
  const OscillatorCompensation m{2.0, 0.3};
  const auto Q = [&](double q) { return m.Q(q); };
  const auto dQ = [&](double q) { return m.dQ(q); };
  for (double q : {-1.1, -0.7, 0.0, 0.4, 0.95, 1.15}) {
    EXPECT_NEAR(m.dQ(q), central_difference(Q, q, 1e-6), 1e-8) << "q = " << q;
    EXPECT_NEAR(m.d2Q(q), central_difference(dQ, q, 1e-6), 1e-6) << "q = " << q;
  }
}

TEST(OscillatorCompensation, InverseRoundTripUpToTheSingularity) {
  const OscillatorCompensation m{2.0, 0.3};
  double worst = 0;  // the largest |Q(Q^-1(qbar)) - qbar| over |qbar| <= 1
  for (double qb : {-1.0, -0.5, -1e-9, 0.0, 1e-12, 0.3, 0.9, 1.0}) worst = std::max(worst, std::abs(m.Q(m.inverse(qb)) - qb));
  EXPECT_CASE("(82), k = 2, h = 0.3: largest |Q(Q^-1(qbar)) - qbar| at 8 points of [-1, 1]", worst, "<=", 4e-16);
  // Near |qbar| = 1, Q'(q) -> 0: evaluating Q itself loses digits in 1 - qhat^2.
  worst = 0;
  for (double qb : {-0.999999, 0.99999999}) worst = std::max(worst, std::abs(m.Q(m.inverse(qb)) - qb));
  EXPECT_CASE("the same at qbar = -0.999999 and 0.99999999", worst, "<=", 1e-14);
  worst = 0;
  for (double q : {-1.17, -0.5, 0.0, 0.25, 1.0, 1.1799}) worst = std::max(worst, std::abs(m.inverse(m.Q(q)) - q));
  EXPECT_CASE("largest |Q^-1(Q(q)) - q| at 6 points of [-1.17, 1.1799]", worst, "<=", 1e-12);
  EXPECT_TRUE(std::isnan(m.inverse(1.0 + 1e-15)));
  EXPECT_FALSE(m.defined(1.18));
  EXPECT_TRUE(m.defined(1.1799));
}

TEST(OscillatorCompensation, SolvesTheCompensationOdeWhenKIsZero) {
  // (81) = (82) at k = 0 solves (80): (1 - q^2) Q''/Q' + q = 0.
  const OscillatorCompensation m{0.0, 0.3};
  for (double q : {-0.9, -0.3, 0.0, 0.5, 0.99}) EXPECT_NEAR((1 - q * q) * m.d2Q(q) / m.dQ(q) + q, 0.0, 1e-14);
}

TEST(PointTransformed, MomentumMapAndHamiltonian) {
  const PointTransformed sys{HarmonicOscillator{}, OscillatorCompensation{2.0, 0.3}};
  for (auto [q, p] : {std::pair{1.0, 0.0}, {0.3, -0.8}, {-1.1, 0.2}}) {
    const auto z = make_state(q, p);
    const auto zb = sys.to_transformed(z);
    EXPECT_NEAR(zb.p[0], p / sys.map.dQ(q), 1e-15);  // (41)
    const auto back = sys.to_original(zb);
    EXPECT_NEAR(back.q[0], q, 1e-13);
    EXPECT_NEAR(back.p[0], p, 1e-13);
    EXPECT_NEAR(sys.H(zb), HarmonicOscillator{}.H(z), 1e-13);  // (39)
  }
}

TEST(PointTransformed, GradientsAgainstFiniteDifferences) {
  // (46), (47) and the mixed derivative used by Newton's method.
  const PointTransformed sys{HarmonicOscillator{}, OscillatorCompensation{2.0, 0.3}};
  const auto zb = sys.to_transformed(make_state(0.6, 0.7));
  const double qb = zb.q[0], pb = zb.p[0], d = 1e-6;
  const auto H = [&](double x, double y) { return sys.H(make_state(x, y)); };
  EXPECT_NEAR(sys.H_q(Vec<1>(qb), Vec<1>(pb))[0], (H(qb + d, pb) - H(qb - d, pb)) / (2 * d), 1e-7);
  EXPECT_NEAR(sys.H_p(Vec<1>(qb), Vec<1>(pb))[0], (H(qb, pb + d) - H(qb, pb - d)) / (2 * d), 1e-7);
  const auto Hq = [&](double y) { return sys.H_q(Vec<1>(qb), Vec<1>(y))[0]; };
  EXPECT_NEAR(sys.H_qp(Vec<1>(qb), Vec<1>(pb))(0, 0), (Hq(pb + d) - Hq(pb - d)) / (2 * d), 1e-7);
}

}  // namespace transforms_test
