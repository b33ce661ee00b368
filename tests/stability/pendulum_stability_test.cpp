// Long runs of the elastic pendulum (000 eq. (73)): 10^5 periods of the
// spring mode with Stormer-Verlet and the processed Rowlands method. A
// symplectic method's energy error stays bounded and does not drift.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "geomint/observables/drift.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/transforms/rowlands_processors.hpp"
#include "../hard_case.hpp"

using namespace geomint;

namespace pendulum_stability_test {  // the file's scope (the tests build as one translation unit)

namespace {

const ElasticPendulumWithGravity sys{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.2}}};
const PhaseState<2> z0 = make_state<2>(Vec<2>(0.5, 1.0), Vec<2>(0.0, 0.0));

// Window maxima of |H - H0| over 10^5 periods 2 pi / sqrt(k/m) with step h.
WindowMaxima energy_windows(const auto& method, double h) {
  const auto n = std::llround(1e5 * 2 * std::numbers::pi / h);
  WindowMaxima w(n / 100);
  const double H0 = sys.H(z0);
  integrate(method, z0, h, n, [&](std::int64_t, const PhaseState<2>& z) { w.add(sys.H(z) - H0); });
  return w;
}

void expect_bounded_without_drift(const WindowMaxima& w, double bound) {
  const auto& m = w.maxima();
  EXPECT_TRUE(std::isfinite(m.back()));
  EXPECT_CASE("max |H - H0| over 1e5 periods", *std::max_element(m.begin(), m.end()), "<", bound);
  // Over the 100 windows the fitted growth is below 10 % of the typical maximum.
  EXPECT_CASE("fitted growth of max |H - H0| over the 100 windows, relative to the middle window's",
              std::abs(w.slope_per_window()) * 100 / m[m.size() / 2], "<", 0.1);
}

}  // namespace

TEST(Stability, PendulumEnergyDoesNotDriftStormerVerlet) {
  expect_bounded_without_drift(energy_windows(stormer_verlet_method(sys), 0.2), 1e-2);
}

TEST(Stability, PendulumEnergyDoesNotDriftRowlands) {
  // Fourth order: the same bound at a much smaller energy error.
  expect_bounded_without_drift(energy_windows(rowlands_cheap_method(sys), 0.2), 1e-4);
}

TEST(Stability, StormerVerletNearItsBoundOnThePendulum) {
  // h sqrt(k/m) = 1.8, 90 % of the linear stability bound 2 of the spring mode.
  expect_bounded_without_drift(energy_windows(stormer_verlet_method(sys), 1.8), 1.0);
}

}  // namespace pendulum_stability_test
