// Hard cases: step sizes at a method's stability bound, 10^5-period runs, and
// the coordinate singularity |qhat| = 1 of the compensating transformation (82).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/observables/drift.hpp"
#include "geomint/systems/exponential_decay.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "../hard_case.hpp"

using namespace geomint;

namespace oscillator_stability_test {  // the file's scope (the tests build as one translation unit)

namespace {
constexpr double kPeriods = 1e5;
std::int64_t steps_for_periods(double h) { return std::llround(kPeriods * 2 * std::numbers::pi / h); }
}  // namespace

TEST(Stability, ExplicitEulerAtItsBoundOscillatesWithoutGrowth) {
  // h alpha = 2: y_{n+1} = -y_n exactly.
  double y = 1.0;
  for (int n = 0; n < 100000; ++n) y = explicit_euler(ExponentialDecay{1.0}, y, 2.0);
  EXPECT_EQ(y, 1.0);
  y = 1.0;
  for (int n = 0; n < 100; ++n) y = explicit_euler(ExponentialDecay{1.0}, y, 2.1);  // beyond: |1 - h| > 1
  EXPECT_CASE("|y| after 100 steps at h alpha = 2.1, y0 = 1", std::abs(y), ">", 1e3);
}

TEST(Stability, SymplecticEulerNearItsBoundFor1e5Periods) {
  // h = 1.9 (95 % of the bound h < 2): the quadratic q^2 - h q p + p^2 is an
  // exact invariant of (42)-(43) here, so the orbit stays on an ellipse and
  // the energy error neither grows nor drifts over 10^5 periods.
  const HarmonicOscillator osc;
  const double h = 1.9;
  const auto invariant = [h](const auto& z) { return z.q[0] * z.q[0] - h * z.q[0] * z.p[0] + z.p[0] * z.p[0]; };
  const auto z0 = make_state(1.0, 0.0);
  const std::int64_t n = steps_for_periods(h);
  WindowMaxima windows(n / 100);
  double worst_invariant = 0;
  const auto z = integrate(SymplecticEulerPQ::bind(osc), z0, h, n, [&](std::int64_t, const auto& x) {
    windows.add(osc.H(x) - osc.H(z0));
    worst_invariant = std::max(worst_invariant, std::abs(invariant(x) - invariant(z0)));
  });
  EXPECT_TRUE(std::isfinite(z.q[0]) && std::isfinite(z.p[0]));
  EXPECT_CASE("max change of the invariant q^2 - h q p + p^2 over 1e5 periods, h = 1.9", worst_invariant, "<", 1e-9);
  const auto& m = windows.maxima();
  EXPECT_CASE_NEAR("max |H - H0| of the last full window over that of the first", m[m.size() - 2] / m.front(), 1.0, 1e-3);
  EXPECT_CASE("fitted growth of max |H - H0| over the 100 windows, relative to the first",
              std::abs(windows.slope_per_window()) * 100 / m.front(), "<", 1e-3);
}

TEST(Stability, CompensatedSymplecticEulerFor1e5Periods) {
  // The paper's Fig 8 setting (h = 0.3, k = 2) over 10^5 periods: the orbit
  // keeps clear of the singularity |qhat| = 1 of (82), the energy error stays
  // bounded and shows no drift.
  const HarmonicOscillator osc;
  const double h = 0.3;
  const OscillatorCompensation compensation{2.0, h};
  const auto z0 = make_state(1.0, 0.0);
  const std::int64_t n = steps_for_periods(h);
  WindowMaxima windows(n / 100);
  double max_qhat = 0;
  integrate(CompensatedSymplecticEuler::bind(osc, compensation.k), z0, h, n, [&](std::int64_t, const auto& x) {
    windows.add(osc.H(x) - osc.H(z0));
    max_qhat = std::max(max_qhat, std::abs(compensation.qhat(x.q[0])));
  });
  EXPECT_CASE("max |qhat| over 1e5 periods, h = 0.3, k = 2 (the singularity is |qhat| = 1)", max_qhat, "<", 0.9);
  const auto& m = windows.maxima();
  EXPECT_TRUE(std::isfinite(m.back()));
  // Fig 8 setting: max |H - H0| = 0.054 over the first 1000 steps
  EXPECT_CASE("max |H - H0| of the last window of 1e5 periods", m.back(), "<", 0.06);
  EXPECT_CASE("fitted growth of max |H - H0| over the 100 windows, relative to the first",
              std::abs(windows.slope_per_window()) * 100 / m.front(), "<", 0.01);
}

TEST(Stability, CompensationWithTooSmallKFailsLoudly) {
  // With k = 0 the transformation is (81), defined only for |q| < 1; the
  // numerical orbit leaves that interval, and the next implicit stage must fail
  // with an IntegrationError, never return NaN or garbage silently.
  const HarmonicOscillator osc;
  const double h = 0.3;
  const PointTransformed sys{osc, OscillatorCompensation{0.0, h}};
  auto zb = sys.to_transformed(make_state(0.999, 0.0));
  // (a step that returns a non-finite state ends the loop: accepted, and the test fails)
  EXPECT_REFUSAL_OF(IntegrationError, "symplectic Euler on the chart (81), h = 0.3, from q = 0.999, up to 1000 steps",
                    for (int n = 0; n < 1000 && std::isfinite(zb.q[0]) && std::isfinite(zb.p[0]); ++n) zb =
                        symplectic_euler_pq(sys, zb, h),
                    {"Newton iteration"});
}

}  // namespace oscillator_stability_test
