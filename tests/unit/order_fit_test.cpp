#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"

using namespace geomint;

namespace order_fit_test {  // the file's scope (the tests build as one translation unit)

TEST(OrderFit, ExactPowerLaw) {
  std::vector<double> h, e;
  for (double x = 0.2; x > 1e-3; x /= 2) h.push_back(x), e.push_back(3.0 * x * x);
  const auto f = fit_order(h, e, 1e-13);
  EXPECT_NEAR(f.order, 2.0, 1e-12);
  EXPECT_NEAR(f.log10_c, std::log10(3.0), 1e-12);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  EXPECT_EQ(f.points, static_cast<int>(h.size()));
}

TEST(OrderFit, LeavesOutTheRoundoffPlateau) {
  // err = h^4 down to a round-off plateau at 5e-14: the plateau would pull the slope down.
  std::vector<double> h = {0.1, 0.05, 0.025, 0.0125, 1e-4, 5e-5}, e;
  for (double x : h) e.push_back(std::max(x * x * x * x, 5e-14));
  const auto f = fit_order(h, e, 1e-13);
  EXPECT_NEAR(f.order, 4.0, 1e-12);
  EXPECT_EQ(f.points, 4);
  EXPECT_FALSE(f.used[4]);
  EXPECT_LT(fit_order(h, e, 0.0).order, 3.0);  // what a threshold-free fit would report
}

TEST(OrderFit, DropsNonFiniteAndNeedsThreePoints) {
  const std::vector<double> h = {0.1, 0.05, 0.025, 0.0125}, e = {NAN, 1e-2, 5e-3, INFINITY};
  EXPECT_THROW(fit_order(h, e, 0.0), NumericalFailure);
  EXPECT_THROW(fit_order(std::vector<double>{0.1}, std::vector<double>{1.0, 2.0}, 0.0), std::invalid_argument);
}

TEST(OrderFit, NoisyFirstOrder) {
  std::vector<double> h, e;
  int i = 0;
  for (double x = 0.1; x > 1e-4; x /= 2, ++i) h.push_back(x), e.push_back(x * (1 + 0.05 * ((i % 2) ? 1 : -1)));
  EXPECT_NEAR(fit_order(h, e, 1e-13).order, 1.0, 0.02);
}

TEST(ErrorSeries, MaxAndRmsOfEquation50) {
  ErrorSeries s;
  for (double e : {0.0, 3.0, -4.0}) s.add(e);  // J = 2: sqrt((0 + 9 + 16) / 2)
  EXPECT_DOUBLE_EQ(s.max_abs(), 4.0);
  EXPECT_DOUBLE_EQ(s.rms50(), std::sqrt(12.5));
  s.add(NAN);
  s.add(1.0);
  EXPECT_TRUE(std::isnan(s.max_abs()));  // a failed run never reports a small error
}

}  // namespace order_fit_test
