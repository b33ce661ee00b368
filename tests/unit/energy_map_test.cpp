// The batched energy-map kernels (every instruction set this CPU runs)
// against the scalar reference loop, and the masking of diverging lanes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "../hard_case.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/observables/rms_energy_error.hpp"
#include "geomint/sweep/energy_map.hpp"
#include "geomint/sweep/energy_map_statistics.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/transforms/polar.hpp"

using namespace geomint;

namespace energy_map_test {  // the file's scope (the tests build as one translation unit)

namespace {
const EnergyMapParams P{1.0, 1.0, 1.0, 0.02, 0.2, 2000, 1e3};  // 000 Fig. 6 parameters, 400 time units

// Regular (non-chaotic) initial positions near the hanging point (0, 1.02).
void regular_batch(std::vector<double>& x, std::vector<double>& y) {
  x.resize(kEnergyMapBatch), y.resize(kEnergyMapBatch);
  for (int i = 0; i < kEnergyMapBatch; ++i) x[i] = -0.3 + 0.02 * i, y[i] = 0.9 + 0.01 * (i % 7);
}
}  // namespace

TEST(EnergyMapKernel, EveryInstructionSetMatchesTheScalarLoop) {
  std::vector<double> x, y;
  regular_batch(x, y);
  const auto kernels = energy_map_kernels();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(kernels.back().isa, "sse2");  // the portable fallback is always there
  for (const auto& k : kernels) {
    for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
      std::vector<EnergyMapPoint> out(kEnergyMapBatch);
      k.run(c, P, x.data(), y.data(), out.data());
      for (int i : {0, 9, 17, 31}) {
        const auto ref = energy_map_scalar(c, P, x[i], y[i]);
        ASSERT_EQ(ref.diverge_step, -1);
        EXPECT_EQ(out[i].diverge_step, -1);
        EXPECT_NEAR(out[i].eps, ref.eps, 1e-10 * ref.eps) << k.isa << " lane " << i;
      }
    }
  }
}

TEST(EnergyMapKernel, DivergingLanesAreMaskedAndDoNotPoisonOthers) {
  std::vector<double> x, y;
  regular_batch(x, y);
  const auto k = energy_map_kernels().front();
  std::vector<EnergyMapPoint> clean(kEnergyMapBatch), mixed(kEnergyMapBatch);
  k.run(Coordinates::polar, P, x.data(), y.data(), clean.data());
  x[3] = 1.5, y[3] = 1.5;  // r0 = 2.12 > 2l + (2mg/k) cos(theta0): passes through r = 0
  x[4] = 0.0, y[4] = 0.0;  // the origin: no polar initial condition
  k.run(Coordinates::polar, P, x.data(), y.data(), mixed.data());
  EXPECT_CASE("polar lane 3 through r = 0: step of divergence", mixed[3].diverge_step, ">", 0);
  EXPECT_TRUE(std::isnan(mixed[3].eps));
  EXPECT_CASE("polar lane 4 at the origin: step of divergence", mixed[4].diverge_step, "==", 0);
  int changed = 0;
  for (int i = 0; i < kEnergyMapBatch; ++i)
    if (i != 3 && i != 4) changed += mixed[i].eps != clean[i].eps;  // bit for bit
  EXPECT_CASE("other lanes of the batch whose energy error changed", changed, "==", 0);
  EXPECT_CASE("the scalar loop from lane 3's start: step of divergence",
              energy_map_scalar(Coordinates::polar, P, 1.5, 1.5).diverge_step, ">", 0);
}

// A start straight below the pivot (x = 0, theta = 0) keeps p_theta = 0 exactly: the motion is radial, an
// oscillation about r* = 1.02 from r = 2.5 that crosses r = 0, where (72) stays finite (p_theta^2 / r^2 = 0).
// Only the test of r, the block's smallest r in the kernels, finds it; the step must be the scalar loop's.
TEST(EnergyMapKernel, RadialPassThroughTheOriginIsFoundByTheTestOfR) {
  std::vector<double> x, y;
  regular_batch(x, y);
  x[5] = 0.0, y[5] = 2.5;
  const auto ref = energy_map_scalar(Coordinates::polar, P, x[5], y[5]);
  EXPECT_CASE("the scalar loop from (0, 2.5): step of divergence", ref.diverge_step, ">", 0);
  for (const auto& k : energy_map_kernels()) {
    std::vector<EnergyMapPoint> out(kEnergyMapBatch);
    k.run(Coordinates::polar, P, x.data(), y.data(), out.data());
    EXPECT_EQ(out[5].diverge_step, ref.diverge_step) << k.isa;
    EXPECT_TRUE(std::isnan(out[5].eps)) << k.isa;
  }
}

// The kernels test for divergence once per block of steps and replay a suspect block
// step by step: with a threshold that some lanes cross mid-run, the step found must be
// the scalar loop's (round-off, and vector sin/cos, may move a marginal crossing by a step).
TEST(EnergyMapKernel, BlockReplayFindsTheStepOfDivergence) {
  std::vector<double> x, y;
  regular_batch(x, y);
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    EnergyMapParams Q = P;
    Q.blowup = 1.5 * energy_map_scalar(c, P, x[16], y[16]).eps;
    int crossed = 0;  // lanes that cross the threshold
    std::int64_t off = 0;  // the largest distance to the scalar loop's step
    for (const auto& k : energy_map_kernels()) {
      std::vector<EnergyMapPoint> out(kEnergyMapBatch);
      k.run(c, Q, x.data(), y.data(), out.data());
      for (int i = 0; i < kEnergyMapBatch; ++i) {
        const auto ref = energy_map_scalar(c, Q, x[i], y[i]);
        crossed += ref.diverge_step > 0;
        off = std::max(off, std::abs(out[i].diverge_step - ref.diverge_step));
        if (ref.diverge_step < 0) EXPECT_NEAR(out[i].eps, ref.eps, 1e-10 * ref.eps) << k.isa << " lane " << i;
      }
    }
    const std::string where = c == Coordinates::polar ? "polar" : "Cartesian";
    EXPECT_CASE(where + ", every kernel: largest |step found - scalar loop's step|", off, "<=", 1);
    const int lanes = static_cast<int>(energy_map_kernels().size()) * kEnergyMapBatch;
    EXPECT_CASE(where + ": lanes that cross the threshold (some ...", crossed, ">", 0);
    EXPECT_CASE(where + ": ... not all)", crossed, "<", lanes);
  }
}

TEST(EnergyMapScalar, MatchesTheGenericLibraryMethod) {
  // The written-out loop against symplectic_euler_pq on the library's systems
  // (Newton's method for the implicit stage in polar coordinates).
  const ElasticPendulumWithGravity cart{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.02}}};
  const ElasticPendulumPolarWithGravity polar{1.0, {SpringPolarTerm{1.0, 1.0}, GravityPolarTerm{1.0, 0.02}}};
  const double x0 = 0.4, y0 = 1.1;
  const auto eps_of = [&](const auto& sys, const PhaseState<2>& z) {
    return symplectic_euler_rms_energy_error(sys, z, P.h, P.steps);
  };
  const auto z0 = make_state<2>(Vec<2>(x0, y0), Vec<2>(0.0, 0.0));
  const double ec = eps_of(cart, z0), ep = eps_of(polar, polar_from_cartesian(z0));
  EXPECT_NEAR(energy_map_scalar(Coordinates::cartesian, P, x0, y0).eps, ec, 1e-11 * ec);
  EXPECT_NEAR(energy_map_scalar(Coordinates::polar, P, x0, y0).eps, ep, 1e-11 * ep);
}

// Polar kernels turn sin and cos of theta by the angle-addition formula with Taylor
// sin and cos of the turn h p_theta / (m r^2), and take the full sin and cos where the
// turn exceeds kEnergyMapMaxTurn. These starts pass close to r = 0 within 30 steps, with
// turns of ~2.5 per step, where the series would be off by ~1e-6: the kernels must match
// the scalar loop all the same. (The passes make the motion chaotic: a short run.)
TEST(EnergyMapKernel, LargeTurnsMatchTheScalarLoop) {
  EnergyMapParams Q = P;
  Q.steps = 40;
  const std::vector<std::pair<double, double>> starts{{1.4225, -1.485}, {-1.4075, -1.495}, {1.4825, 1.5}, {-1.44, -1.47}};
  const ElasticPendulumPolarWithGravity polar{1.0, {SpringPolarTerm{1.0, 1.0}, GravityPolarTerm{1.0, 0.02}}};
  std::vector<double> x, y;
  regular_batch(x, y);
  for (std::size_t s = 0; s < starts.size(); ++s) {
    std::tie(x[8 * s], y[8 * s]) = starts[s];
    double max_turn = 0;  // max |theta_{j+1} - theta_j| along the library's symplectic Euler
    auto z = polar_from_cartesian(make_state<2>(Vec<2>(starts[s].first, starts[s].second), Vec<2>(0.0, 0.0)));
    for (std::int64_t j = 1; j <= Q.steps; ++j) {
      const auto zn = symplectic_euler_pq(polar, z, Q.h);
      max_turn = std::max(max_turn, std::fabs(zn.q[1] - z.q[1])), z = zn;
    }
    EXPECT_GT(max_turn, 4 * kEnergyMapMaxTurn) << s;
  }
  for (const auto& k : energy_map_kernels()) {
    std::vector<EnergyMapPoint> out(kEnergyMapBatch);
    k.run(Coordinates::polar, Q, x.data(), y.data(), out.data());
    for (std::size_t s = 0; s < starts.size(); ++s) {
      const auto ref = energy_map_scalar(Coordinates::polar, Q, x[8 * s], y[8 * s]);
      ASSERT_EQ(ref.diverge_step, -1) << s;
      EXPECT_EQ(out[8 * s].diverge_step, -1) << k.isa << " start " << s;
      EXPECT_NEAR(out[8 * s].eps, ref.eps, 1e-10 * ref.eps) << k.isa << " start " << s;
    }
  }
}

// energy_map_turn: one turn from theta = 0 is Taylor sin d, cos d, within 2 ulp on |d| <= 0.5.
TEST(EnergyMapTurn, GivesSinAndCosOfTheTurn) {
  const double eps = std::numeric_limits<double>::epsilon();
  for (int i = -1000; i <= 1000; ++i) {
    const double d = kEnergyMapMaxTurn * i / 1000.0;
    double s = 0.0, c = 1.0;
    energy_map_turn(d, s, c);
    EXPECT_NEAR(s, std::sin(d), 2 * eps * std::fabs(std::sin(d))) << d;
    EXPECT_NEAR(c, std::cos(d), 2 * eps) << d;
  }
}

// Carried through a block of 128 steps along polar symplectic Euler, sin and cos stay within
// a few ulp of those of theta_j: the rounding of each turn (~1 ulp) adds up like a random walk,
// sqrt(128) ~ 11 ulp; the test allows twice that. Starts at rest on the circle r = 1.6 (inside
// the divergence boundary r = 2 + 0.04 cos theta) swing widely, with turns up to about 0.18.
TEST(EnergyMapTurn, CarriedThroughABlockStaysWithinAFewUlpOfSinAndCosOfTheta) {
  const ElasticPendulumPolarWithGravity polar{1.0, {SpringPolarTerm{1.0, 1.0}, GravityPolarTerm{1.0, 0.02}}};
  const double eps = std::numeric_limits<double>::epsilon();
  double worst = 0, max_turn = 0;
  for (int i = 0; i < 16; ++i) {
    const double phi = std::numbers::pi * (i + 0.5) / 16;
    auto z = polar_from_cartesian(make_state<2>(Vec<2>(1.6 * std::sin(phi), 1.6 * std::cos(phi)), Vec<2>(0.0, 0.0)));
    double s = 0, c = 0;
    for (std::int64_t j = 0; j < P.steps; ++j) {
      if (j % 128 == 0) s = std::sin(z.q[1]), c = std::cos(z.q[1]);
      const auto zn = symplectic_euler_pq(polar, z, P.h);
      const double turn = zn.q[1] - z.q[1];
      ASSERT_LE(std::fabs(turn), kEnergyMapMaxTurn);
      energy_map_turn(turn, s, c);
      max_turn = std::max(max_turn, std::fabs(turn));
      worst = std::max({worst, std::fabs(s - std::sin(zn.q[1])), std::fabs(c - std::cos(zn.q[1]))});
      z = zn;
    }
  }
  EXPECT_GT(max_turn, 0.15);
  EXPECT_LT(worst, 2 * std::sqrt(128.0) * eps);
}

TEST(EnergyMapStatistics, CountsInsideAndOutsideTheRegionOfSection41) {
  // l = m = k = 1, g = 0.5: r* = 1 + cos(phi) / 2, boundary b = 2 + cos(phi) (cos(phi) = y/r).
  const ElasticPendulumParams p{1.0, 1.0, 1.0, 0.5};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<EnergyMapRow> rows = {
      {0.0, 0.0, 0.0, nan, nan, true, true, 0},          // the origin
      {0.0, 3.5, 0.2, 1e-3, nan, false, true, 10},       // outside (b = 3), diverged
      {0.0, -1.5, 0.3, 1e-3, nan, false, true, 30},      // outside (b = 1), diverged
      {0.0, 0.2, 0.4, 1e-3, nan, false, true, 1000},     // inside, r < r* = 1.5: inner, diverged
      {0.3, 0.0, 0.5, 2e-3, 1e-3, false, false, -1},     // inside, r < r* = 1: polar better, off the ring
      {0.0, 2.9, 0.6, 1e-3, nan, false, true, 5000},     // inside, r >= r*: outer, 0.1 inside b, diverged
      {0.0, 2.7, 0.7, 1e-3, 3e-3, false, false, -1},     // outer candidate 0.3 inside b: Cartesian better
      {1.05, 0.0, 0.8, 1e-3, 0.5e-3, false, false, -1},  // outer candidate, on the ring: polar better
      {0.0, 1.0, 0.9, 2e-3, 1e-3, false, false, -1},     // inner candidate, on the ring: polar better
  };
  const EnergyMapStatistics s = energy_map_statistics(rows, p, 0.2, 1000, 0.2);
  EXPECT_EQ(s.points, 9);
  EXPECT_EQ(s.diverged_polar, 5);
  EXPECT_EQ(s.diverged_cartesian, 1);
  EXPECT_EQ(s.diverged_any, 5);
  EXPECT_EQ(s.counted, 8);
  EXPECT_EQ(s.criterion, 2);
  EXPECT_EQ(s.disagree, 2);
  EXPECT_EQ(s.diverged_inside, 2);
  EXPECT_EQ(s.alive_outside, 0);
  EXPECT_EQ(s.cartesian_diverged_off_origin, 0);
  EXPECT_EQ(s.inner, 1);
  EXPECT_DOUBLE_EQ(*s.inner_r_max, 0.2);
  EXPECT_EQ(s.inner_candidates, 1);
  EXPECT_EQ(s.outer, 1);
  EXPECT_NEAR(*s.outer_dist_max, 0.1, 1e-15);
  EXPECT_EQ(s.outer_candidates, 1);
  EXPECT_NEAR(*s.outer_dist_all, 0.3, 1e-15);
  EXPECT_DOUBLE_EQ(*s.H0_min_diverged, 0.2);
  EXPECT_DOUBLE_EQ(*s.H0_max_alive, 0.9);
  EXPECT_EQ(s.inside_steps->median, 1000);  // nearest rank, halves to even
  EXPECT_EQ(s.inside_steps->max, 5000);
  EXPECT_DOUBLE_EQ(s.inside_steps->time_max, 1000.0);
  EXPECT_EQ(s.outside_steps->median, 10);
  EXPECT_EQ(s.outside_steps->max, 30);
  EXPECT_EQ(s.both_finite, 4);
  EXPECT_EQ(s.cartesian_better, 1);
  EXPECT_EQ(s.polar_better, 3);
  EXPECT_DOUBLE_EQ(*s.eps_difference_min, -2e-3);
  EXPECT_DOUBLE_EQ(*s.eps_difference_max, 1e-3);
  EXPECT_DOUBLE_EQ(*s.ring_polar_better, 1.0);
  EXPECT_DOUBLE_EQ(*s.off_ring_polar_better, 0.5);
  EXPECT_DOUBLE_EQ(*s.ratio_p05, 0.5);
  EXPECT_DOUBLE_EQ(*s.ratio_median, 0.5);
  EXPECT_DOUBLE_EQ(*s.ratio_p95, 3.0);
}

TEST(EnergyMapStatistics, TiesAtRoundOffAndWithinOnePercentApartFromWins) {
  // J = 1000 steps: a round-off tie is |delta eps| <= 1000 eps_mach max(eps); a 1 % tie, within 0.01 max(eps).
  const ElasticPendulumParams p{1.0, 1.0, 1.0, 0.02};
  const std::vector<EnergyMapRow> rows = {
      {0.0, 1.0, 0.5, 1e-3, 1e-3 * (1 + 1e-14), false, false, -1},  // round-off tie (and 1 % tie)
      {0.0, 1.1, 0.5, 1e-3 * (1 + 1e-10), 1e-3, false, false, -1},  // 1 % tie, polar wins beyond round-off
      {0.0, 1.2, 0.5, 1e-3, 1.008e-3, false, false, -1},            // 1 % tie, Cartesian wins beyond round-off
      {0.0, 1.3, 0.5, 1e-3, 1.02e-3, false, false, -1},             // Cartesian wins beyond 1 %
      {0.0, 1.4, 0.5, 1.03e-3, 1e-3, false, false, -1},             // polar wins beyond 1 %
  };
  const EnergyMapStatistics s = energy_map_statistics(rows, p, 0.2, 1000, 0.2);
  EXPECT_DOUBLE_EQ(s.roundoff_tie_tolerance, 1000 * std::numeric_limits<double>::epsilon());
  EXPECT_EQ(s.tied_roundoff, 1);
  EXPECT_EQ(s.cartesian_better_beyond_roundoff, 2);
  EXPECT_EQ(s.polar_better_beyond_roundoff, 2);
  EXPECT_EQ(s.tied_percent, 3);
  EXPECT_EQ(s.cartesian_better_beyond_percent, 1);
  EXPECT_EQ(s.polar_better_beyond_percent, 1);
}

TEST(EnergyMapStatistics, NearestRankQuantile) {
  const std::vector<int> v = {1, 2, 3, 4, 5};
  EXPECT_EQ(nearest_rank_quantile(v, 0.0), 1);
  EXPECT_EQ(nearest_rank_quantile(v, 0.5), 3);
  EXPECT_EQ(nearest_rank_quantile(v, 0.95), 5);  // round(3.8)
  EXPECT_EQ(nearest_rank_quantile(std::vector<int>{1, 2, 3, 4}, 0.5), 3);  // round(1.5) = 2, to even
  EXPECT_EQ(nearest_rank_quantile(std::vector<int>{1, 2, 3, 4, 5, 6}, 0.5), 3);  // round(2.5) = 2
}

}  // namespace energy_map_test
