// The analyses of ti_drift (004): growth episodes of a recorded series (Fig. 5) and the time average over a
// rotating orbit (the rate (4.3) at the current energy, Fig. 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "../hard_case.hpp"
#include "geomint/analysis/growth_episodes.hpp"
#include "geomint/analysis/orbit_average.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"

using namespace geomint;

namespace ti_drift_analysis_test {  // the file's scope (the tests build as one translation unit)

namespace {

// A random walk of n steps (unit variance per step, fixed seed) plus a ramp of `rate` per sample on [a, b).
struct Series {
  std::vector<double> t, y;
};
Series walk_with_ramp(std::size_t n, std::size_t a, std::size_t b, double rate) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-std::sqrt(3.0), std::sqrt(3.0));  // variance 1
  Series s;
  double y = 0;
  for (std::size_t k = 0; k < n; ++k) {
    s.t.push_back(static_cast<double>(k));
    s.y.push_back(y);
    y += u(rng) + (k >= a && k < b ? rate : 0.0);
  }
  return s;
}

}  // namespace

// Three trajectories of five output times: at time k they are k - 1, k and k + 1 (mean k, sd 1),
// but trajectory 2 is an outlier from k = 3 on.
TEST(EnsembleMoments, AreTakenAcrossTheTrajectoriesAtEveryStrideThTime) {
  const std::vector<std::vector<double>> series{{-1, 0, 1, 2, 3}, {0, 1, 2, 3, 4}, {1, 2, 3, 40, 50}};
  const EnsembleMoments all = ensemble_moments(series);
  ASSERT_EQ(all.k, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(all.mean[k], static_cast<double>(k));
    EXPECT_DOUBLE_EQ(all.sd[k], 1.0);  // the sample deviation (denominator M - 1)
  }
  EXPECT_DOUBLE_EQ(all.mean[4], 19.0);
  const std::vector<std::size_t> which{0, 2};  // trajectories 0 and 2, every second time
  const EnsembleMoments thinned = ensemble_moments(series, which, 2);
  ASSERT_EQ(thinned.k, (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_DOUBLE_EQ(thinned.mean[1], 2.0);
  EXPECT_DOUBLE_EQ(thinned.sd[1], std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(thinned.mean[2], 26.5);
  EXPECT_DOUBLE_EQ(thinned.sd[2], 47 / std::sqrt(2.0));
}

TEST(GrowthEpisodes, RunningSlopeOfALineIsItsSlope) {
  std::vector<double> t, y;
  for (int k = 0; k < 50; ++k) t.push_back(0.5 * k), y.push_back(3.0 - 2.0 * 0.5 * k);
  for (double s : running_slope(t, y, 4)) EXPECT_NEAR(s, -2.0, 1e-12);
}

TEST(GrowthEpisodes, FindsARampInARandomWalk) {
  // a ramp of 2 per sample over 200 samples (a rise of 400, against a walk of about sqrt(200) = 14 there)
  const Series s = walk_with_ramp(3000, 1200, 1400, 2.0);
  const std::size_t half = 20;
  const auto ep = growth_episodes(running_slope(s.t, s.y, half), 4.0, 20);
  ASSERT_EQ(ep.size(), 1u);
  EXPECT_EQ(ep[0].sign, 1);
  EXPECT_NEAR(static_cast<double>(ep[0].begin), 1200.0, static_cast<double>(half));  // the window smears by <= half
  EXPECT_NEAR(static_cast<double>(ep[0].end), 1400.0, static_cast<double>(half));
}

TEST(GrowthEpisodes, ADeclineHasSignMinusOne) {
  const Series s = walk_with_ramp(3000, 500, 700, -2.0);
  const auto ep = growth_episodes(running_slope(s.t, s.y, 20), 4.0, 20);
  ASSERT_EQ(ep.size(), 1u);
  EXPECT_EQ(ep[0].sign, -1);
  EXPECT_NEAR(static_cast<double>(ep[0].begin), 500.0, 20.0);
}

TEST(GrowthEpisodes, NoneInAPlainRandomWalk) {
  const Series s = walk_with_ramp(3000, 0, 0, 0.0);
  EXPECT_TRUE(growth_episodes(running_slope(s.t, s.y, 20), 4.0, 20).empty());
}

TEST(GrowthEpisodes, NoiseIsTheRobustDeviation) {
  // for slopes +-1 around 0 (half each) the MAD is 1
  const SlopeNoise n = slope_noise({-1.0, 1.0, -1.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(n.centre, 0.0);
  EXPECT_DOUBLE_EQ(n.noise, 1.4826);
}

TEST(OrbitAverage, RateOfEq43AgainstTheTimeAverageAlongTheOrbit) {
  // 004 Fig. 2's pendulum from q = 0, p = 2.5: the quadrature over the orbit of its energy against the time
  // average along an RK4 orbit (step 1e-3) over a whole number of turns (the partial turn would bias it).
  const UnsymmetricPendulum up;
  const double h = 0.2;
  const auto z0 = make_state(0.0, 2.5);
  const auto rate = [&](double q, double p) { return simplified_ti_drift_rate(up, make_state(q, p), h); };
  const double quad = rotation_average(up, up.H(z0), rate);
  double sum = 0, turns_t = 0, sum_at_turn = 0;
  std::int64_t n_at_turn = 0;
  const double dt = 1e-3;
  int turns = 0;
  PhaseState<1> prev = z0;
  integrate(RungeKutta4::bind(up), z0, dt, 400000, [&](std::int64_t j, const PhaseState<1>& z) {
    if (j == 0) return;
    sum += simplified_ti_drift_rate(up, z, h);
    if (std::floor(z.q[0] / (2 * std::numbers::pi)) > std::floor(prev.q[0] / (2 * std::numbers::pi)))
      ++turns, sum_at_turn = sum, n_at_turn = j, turns_t = static_cast<double>(j) * dt;
    prev = z;
  });
  ASSERT_GT(turns, 10);
  (void)turns_t;
  EXPECT_NEAR(quad, sum_at_turn / static_cast<double>(n_at_turn), 1e-3 * std::abs(quad));
  // and the mean of p over time is 2 pi / period
  const double period = turns_t / turns;
  EXPECT_NEAR(rotation_average(up, up.H(z0), [](double, double p) { return p; }), 2 * std::numbers::pi / period,
              1e-3 * 2 * std::numbers::pi / period);
}

TEST(OrbitAverage, RefusesAnOrbitThatDoesNotRotate) {
  const UnsymmetricPendulum up;
  EXPECT_REFUSAL_OF(NumericalFailure, "an orbit average at E = 0 of the unsymmetric pendulum",
                    rotation_average(up, 0.0, [](double, double) { return 1.0; }), {"does not rotate"});
}

}  // namespace ti_drift_analysis_test
