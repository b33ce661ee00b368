// Stormer-Verlet, the Rowlands kernel and its processors (000 eq. (26)-(37)),
// and the generic processing driver (000 eq. (23)).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geomint/integrators/rowlands.hpp"
#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/transforms/rowlands_processors.hpp"

using namespace geomint;

namespace rowlands_test {  // the file's scope (the tests build as one translation unit)

namespace {
const ElasticPendulumWithGravity sys{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.2}}};
const PhaseState<2> z0 = make_state<2>(Vec<2>(0.5, 1.0), Vec<2>(0.3, 0.2));  // p not along q: the spring is nonlinear across q

double distance(const PhaseState<2>& a, const PhaseState<2>& b) {
  return std::sqrt((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm());
}

// Order of e(h) from h = 0.2 down by halving.
double order_of(const auto& e) {
  std::vector<double> hs, es;
  for (double h = 0.2; h > 0.01; h /= 2) hs.push_back(h), es.push_back(e(h));
  return fit_order(hs, es, 1e-14).order;
}
}  // namespace

TEST(StormerVerlet, CachedForceEqualsTheTwoEvaluationForm) {
  // Two steps with the cached force against (26)-(28) written out.
  const double h = 0.1;
  auto s = stormer_verlet_method(sys).pre(z0, h);
  s = stormer_verlet(sys, stormer_verlet(sys, s, h), h);
  PhaseState<2> z = z0;
  for (int j = 0; j < 2; ++j) {
    const Vec<2> p_half = z.p - 0.5 * h * sys.U_q(z.q);  // (26)
    z.q = z.q + h * p_half;                              // (27), M = I
    z.p = p_half - 0.5 * h * sys.U_q(z.q);               // (28)
  }
  EXPECT_LT(distance(s.z, z), 1e-15);
  EXPECT_EQ(s.F, sys.force(s.z.q));
}

TEST(Rowlands, KernelForceIsMinusTheGradientOfTheEffectivePotential) {
  // (30): Uhat = U - h^2/24 U_q M^{-1} U_q.
  const double h = 0.3, d = 1e-6;
  const auto Uhat = [&](const Vec<2>& q) { return sys.U(q) - h * h / 24 * sys.U_q(q).squaredNorm(); };
  const Vec<2> q(0.7, -0.9);
  Vec<2> grad;
  for (int i = 0; i < 2; ++i) {
    Vec<2> e = Vec<2>::Zero();
    e[i] = d;
    grad[i] = (Uhat(q + e) - Uhat(q - e)) / (2 * d);
  }
  EXPECT_LT((rowlands_force(sys, q, h) + grad).norm(), 1e-8);
}

TEST(Rowlands, ProcessedMethodIsFourthOrderOnlyWithTheDerivedCoefficient) {
  // 000 eq. (23) with (31)-(33): the processors remove the h^2 error of the kernel only for c = 1/12;
  // with the printed c = 1/24 half of it stays (order 2). Order from the difference of runs at h and h/2 to T.
  constexpr double T = 1.6;  // a multiple of every h of order_of
  const auto err = [](double c) {
    return [c](double h) {
      const auto m = rowlands_method(sys, c);
      const int n = static_cast<int>(std::lround(T / h));
      return distance(integrate(m, z0, h, n), integrate(m, z0, h / 2, 2 * n));
    };
  };
  EXPECT_NEAR(order_of(err(rowlands_processor_coefficient)), 4.0, 0.15);
  EXPECT_NEAR(order_of(err(rowlands_processor_coefficient_printed)), 2.0, 0.15);
}

TEST(Rowlands, CheapPostAfterPreIsIdentityToFourthOrder) {
  // (36)-(37) read the kernel states next to the preprocessed one (34)-(35).
  const auto err = [](double h) {
    const auto m = rowlands_cheap_method(sys);
    const auto s = m.pre(z0, h);
    return distance(m.post(m.kernel(s, -h), s, m.kernel(s, h), h), z0);
  };
  EXPECT_NEAR(order_of(err), 4.0, 0.15);
}

TEST(Rowlands, CheapAndExactPreprocessorsAgreeToFourthOrder) {
  // (34)-(35) approximate (32)-(33) with the derived coefficient h^2/12, not the printed h^2/24.
  const auto err = [](double h, double c) {
    return distance(rowlands_pre_cheap(sys, z0, h), rowlands_pre_exact(sys, z0, h, c));
  };
  EXPECT_NEAR(order_of([&](double h) { return err(h, rowlands_processor_coefficient); }), 4.0, 0.15);
  EXPECT_NEAR(order_of([&](double h) { return err(h, rowlands_processor_coefficient_printed); }), 2.0, 0.15);
}

TEST(Processing, FinalOnlyRunEqualsTheObservedRun) {
  // eq. (23): post o kernel^n o pre, whether or not every step is postprocessed.
  const double h = 0.05;
  for (int n : {0, 1, 7}) {
    const auto m = rowlands_cheap_method(sys);
    const auto observed = integrate(m, z0, h, n, [](auto, const auto&) {});
    EXPECT_EQ(distance(observed, integrate(m, z0, h, n)), 0.0) << n;
    const auto e = rowlands_method(sys);
    EXPECT_EQ(distance(integrate(e, z0, h, n, [](auto, const auto&) {}), integrate(e, z0, h, n)),
              0.0);
  }
}

}  // namespace rowlands_test
