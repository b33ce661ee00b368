// The analyses of ti_drift (004): growth episodes of a recorded series (Fig. 5) and the time average over a
// rotating orbit (the rate (4.3) at the current energy, Fig. 2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "../hard_case.hpp"
#include "geomint/analysis/claim_share.hpp"
#include "geomint/analysis/episode_cuts.hpp"
#include "geomint/analysis/growth_episodes.hpp"
#include "geomint/analysis/sample_windows.hpp"
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

// ---- The windows, pinned where the answer depends on the boundary sample (an off-by-one fails) ----

TEST(GrowthEpisodes, RunningSlopeWindowEndsAtKPlusHalf) {
  // y = t on t = 0..49, then slope 3 from the kink at K = 30: y = 30 + 3 (t - 30). The window [k - 4, k + 4] of
  // k <= K - 4 = 26 holds no sample past the kink: slope 1 exactly. That of k = 27 holds one, t = K + 1 = k + 4,
  // where y is 2 above the line: slope 1 + 2 * 4 / sum_{u=-4..4} u^2 = 1 + 8 / 60. With the window one sample
  // shorter at either end (k + 3 or k - 3), k = 27 has slope 1, or k = 26 a slope above 1.
  const std::size_t K = 30, half = 4;
  std::vector<double> t, y;
  for (std::size_t k = 0; k < 50; ++k) {
    const double x = static_cast<double>(k);
    t.push_back(x), y.push_back(k <= K ? x : 30.0 + 3.0 * (x - 30.0));
  }
  const std::vector<double> s = running_slope(t, y, half);
  for (std::size_t k = half; k + half <= K; ++k) EXPECT_NEAR(s[k], 1.0, 1e-12) << "k = " << k;
  EXPECT_NEAR(s[K - half + 1], 1.0 + 8.0 / 60.0, 1e-12);
  // k = 28: t = 31, 32 lie 2 and 4 above the line, at u = 3 and 4: 1 + (2 * 3 + 4 * 4) / 60
  EXPECT_NEAR(s[K - half + 2], 1.0 + 22.0 / 60.0, 1e-12);
  // mirrored: k >= K + 4 sees only slope 3; k = K + 3 = 33 has t = 29 .. 37, u = -4 at t = 29 is 2 above the
  // line of slope 3 through the others (y = 30 + 3 (t - 30) at t = 29 is 27, y is 29): 3 - 2 * 4 / 60
  for (std::size_t k = K + half; k + half < 50; ++k) EXPECT_NEAR(s[k], 3.0, 1e-12) << "k = " << k;
  EXPECT_NEAR(s[K + half - 1], 3.0 - 8.0 / 60.0, 1e-12);
}

TEST(GrowthEpisodes, RunningSlopeWindowIsClippedAtTheEndsOfTheRecord) {
  // y = t^2 at t = 0..n-1: the least-squares slope over the consecutive samples [a, b] is a + b (t^2 is even about
  // the midpoint (a + b) / 2 up to its linear part), so s_k names both ends of its clipped window [k - half, k + half]
  const std::size_t n = 20, half = 3;
  std::vector<double> t, y;
  for (std::size_t k = 0; k < n; ++k) t.push_back(static_cast<double>(k)), y.push_back(static_cast<double>(k * k));
  const std::vector<double> s = running_slope(t, y, half);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k >= half ? k - half : 0, b = std::min(n - 1, k + half);
    EXPECT_NEAR(s[k], static_cast<double>(a + b), 1e-9) << "k = " << k;
  }
  EXPECT_NEAR(s[0], 3.0, 1e-9);        // [0, 3]
  EXPECT_NEAR(s[n - 1], 35.0, 1e-9);   // [16, 19]
}

TEST(GrowthEpisodes, AnEpisodeIsTheRunOfSlopesBeyondTheThresholdAndAtLeastMinSamplesLong) {
  // running slopes -1, +1 alternating (median 0, robust deviation 1.4826) with 10 on samples [40, 70) and -10 on
  // [170, 200): a growth [40, 70) and a decline [170, 200) to the end of the record, each exactly min_samples = 30
  // long; with 31 needed, neither
  std::vector<double> s(200);
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = k % 2 ? 1.0 : -1.0;
  for (std::size_t k = 40; k < 70; ++k) s[k] = 10.0;
  for (std::size_t k = 170; k < 200; ++k) s[k] = -10.0;
  ASSERT_DOUBLE_EQ(slope_noise(s).noise, 1.4826);
  const auto ep = growth_episodes(s, 4.0, 30);
  ASSERT_EQ(ep.size(), 2u);
  EXPECT_EQ(ep[0].begin, 40u);
  EXPECT_EQ(ep[0].end, 70u);
  EXPECT_EQ(ep[0].sign, 1);
  EXPECT_EQ(ep[1].begin, 170u);
  EXPECT_EQ(ep[1].end, 200u);
  EXPECT_EQ(ep[1].sign, -1);
  EXPECT_TRUE(growth_episodes(s, 4.0, 31).empty());
  std::vector<double> t(200);
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k);
  EXPECT_FALSE(first_growth_episode(t, std::vector<double>(200, 0.0), {1, 4.0, 1}));  // a flat record: none
}

TEST(GrowthEpisodes, AnEpisodesStepsEndAtTheLastOutputTime) {
  // samples every 5 steps, 10 output times (steps 0 .. 45): the episode [3, 7) spans the intervals 3 .. 6, 20 steps
  // from step 15; [6, 10) reaches the end of the record, whose last output time closes it: intervals 6 .. 8, 15 steps
  EXPECT_EQ(episode_steps({3, 7, 1}, 10, 5), 20);
  EXPECT_EQ(episode_steps({6, 10, 1}, 10, 5), 15);
  EXPECT_EQ(episode_steps({9, 10, 1}, 10, 5), 0);
}

TEST(SampleWindows, ConsecutiveWindowsSplitTheRecordAndTheLastRunsToItsEnd) {
  // 23 samples in 5 windows of 4 (per = floor(23 / 5)); the last takes the remaining 7
  const std::size_t n = 23;
  for (std::size_t w = 0; w < 4; ++w) {
    EXPECT_EQ(consecutive_window(n, 5, w).begin, 4 * w);
    EXPECT_EQ(consecutive_window(n, 5, w).end, 4 * w + 4);
  }
  EXPECT_EQ(consecutive_window(n, 5, 4).begin, 16u);
  EXPECT_EQ(consecutive_window(n, 5, 4).end, 23u);
  // a fit over window w of a series whose slope changes at sample 8 (the first sample of window 2): window 1 sees
  // slope 1, window 2 slope 2; a window one sample longer (or shifted) mixes them
  std::vector<double> t, y;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = static_cast<double>(k);
    t.push_back(x), y.push_back(k < 8 ? x : 8.0 + 2.0 * (x - 8.0));
  }
  const auto slope_in = [&](std::size_t w) {
    const SampleWindow sw = consecutive_window(n, 5, w);
    return linear_fit(std::span<const double>(t).subspan(sw.begin, sw.end - sw.begin),
                      std::span<const double>(y).subspan(sw.begin, sw.end - sw.begin)).slope;
  };
  EXPECT_NEAR(slope_in(1), 1.0, 1e-12);
  EXPECT_NEAR(slope_in(2), 2.0, 1e-12);
}

TEST(ClaimShare, ShareOfSamplesWithItsBinomialStandardErrorAndQuartiles) {
  // 5 samples, the claim (value > 1/2) holds in 3: share 0.6, standard error sqrt(0.6 * 0.4 / 5), coin flip 0.5 / sqrt(5)
  const ClaimShare c = claim_share({0.9, 0.1, 0.7, 0.5, 0.8}, 0.5);
  EXPECT_EQ(c.samples, 5u);
  EXPECT_EQ(c.holds, 3u);  // 0.5 itself is not above
  EXPECT_DOUBLE_EQ(c.share, 0.6);
  EXPECT_DOUBLE_EQ(c.standard_error, std::sqrt(0.6 * 0.4 / 5));
  EXPECT_DOUBLE_EQ(c.coin_flip_standard_error, 0.5 / std::sqrt(5.0));
  const Quartiles q = quartiles_of({0.9, 0.1, 0.7, 0.5, 0.8});  // sorted 0.1 0.5 0.7 0.8 0.9
  EXPECT_DOUBLE_EQ(q.min, 0.1);
  EXPECT_DOUBLE_EQ(q.q1, 0.5);
  EXPECT_DOUBLE_EQ(q.median, 0.7);
  EXPECT_DOUBLE_EQ(q.q3, 0.8);
  EXPECT_DOUBLE_EQ(q.max, 0.9);
  EXPECT_DOUBLE_EQ(quartiles_of({0.0, 1.0}).q1, 0.25);  // between order statistics
  EXPECT_TRUE(std::isnan(claim_share({}, 0.5).share));
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
