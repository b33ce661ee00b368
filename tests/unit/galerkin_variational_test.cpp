// The Lobatto and Simpson variational integrators built from their definition
// (001 Sec. 2-4), against the printed one-step matrix (13)-(14) and the system (12),
// symplecticity, stability bounds, and Newton's convergence on a nonlinear step; the closed
// forms of analysis/lobatto_oscillator.hpp (exact orbit, growth of Fig. 2, stable set); the
// work-precision interpolation of analysis/work_precision.hpp.
#include <gtest/gtest.h>

#include "../hard_case.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>

#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/drift.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

using namespace geomint;

namespace galerkin_variational_test {  // the file's scope (the tests build as one translation unit)

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
    const Mat<2> P = one_step_matrix(R, osc, h), printed = lobatto_map_13(h, m, w);
    EXPECT_NEAR(P(0, 0), printed(0, 0), 1e-13);
    EXPECT_NEAR(P(0, 1), printed(0, 1), 1e-13 * std::max(1.0, std::abs(printed(0, 1))));
    EXPECT_NEAR(P(1, 0), printed(1, 0), 1e-13);
    EXPECT_NEAR(P(1, 1), printed(1, 1), 1e-13);
    EXPECT_NEAR(P.determinant(), 1.0, 1e-13);  // symplectic
  }
}

// 001 eq. (12) gives (13)-(14) only with 12 (h^2 w^2 - 30) in the second equation; as printed
// (12 h^2 w^2 - 30) it is another map, inconsistent with the oscillator (its coefficient tends to 1/24).
TEST(Lobatto, Equation12GivesThe13And14OnlyWithTheCorrectedCoefficient) {
  const double m = 1.3, w = 2.1;
  for (double h : {0.05, 0.3, 1.0, 1.45}) {
    const Mat<2> corrected = lobatto_map_12(h, m, w, Eq12::corrected), printed = lobatto_map_12(h, m, w, Eq12::printed);
    const Mat<2> map = lobatto_map_13(h, m, w);
    EXPECT_LT((corrected - map).cwiseAbs().maxCoeff(), 1e-13 * std::max(1.0, map.cwiseAbs().maxCoeff())) << h;
    EXPECT_GT((printed - map).cwiseAbs().maxCoeff(), 1e-2) << h;
  }
  // the coefficient beta of (q_{j+1} - q_j)/h = beta (p_j + p_{j+1})/m from the step of (q, p) = (0, 1):
  // beta = m Phi_qp / (h (1 + Phi_pp)); as h -> 0 it tends to 1/2 (the oscillator), as printed to 1/24
  const double h = 1e-4;
  const auto beta = [&](const Mat<2>& P) { return P(1, 0) * m / (h * (1 + P(0, 0))); };
  EXPECT_NEAR(beta(lobatto_map_12(h, m, w, Eq12::corrected)), 0.5, 1e-6);
  EXPECT_NEAR(beta(lobatto_map_12(h, m, w, Eq12::printed)), 1.0 / 24, 1e-6);
}

TEST(Lobatto, StabilityBoundOfEquation10) {
  const HarmonicOscillator osc{1.0, 1.0};
  const auto R = lobatto_rule();
  const double bound = std::sqrt(42.0 - 6.0 * std::sqrt(29.0));
  // eigenvalues on the unit circle below the bound, one outside above it
  EXPECT_CASE_NEAR("Lobatto: spectral radius at 0.999 x the bound (10)", radius(one_step_matrix(R, osc, 0.999 * bound)),
                   1.0, 1e-12);
  EXPECT_CASE("Lobatto: spectral radius at 1.001 x the bound (10)", radius(one_step_matrix(R, osc, 1.001 * bound)), ">",
              1.0 + 1e-3);
  const auto S = simpson_rule();
  EXPECT_CASE_NEAR("Simpson: spectral radius at 0.999 sqrt 8", radius(one_step_matrix(S, osc, 0.999 * std::sqrt(8.0))),
                   1.0, 1e-12);
  EXPECT_CASE("Simpson: spectral radius at 1.001 sqrt 8", radius(one_step_matrix(S, osc, 1.001 * std::sqrt(8.0))), ">",
              1.0 + 1e-3);
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
  double c = 0;
  for (std::size_t k = 0; k + 1 < res.size() && res[k + 1] > 1e-13; ++k) c = std::max(c, res[k + 1] / (res[k] * res[k]));
  EXPECT_CASE("Newton on the Lobatto stage of the pendulum, h = 0.3: largest r_{k+1} / r_k^2 above round-off", c, "<",
              10);
  EXPECT_CASE("residual after 6 iterations", res.back(), "<", 1e-13);
}

TEST(ImplicitMidpoint, IsTheCayleyMapOnTheOscillator) {
  // On q'' = -q the midpoint rule is (I - hA/2)^{-1} (I + hA/2): q1 = ((1 - h^2/4) q + h p) / (1 + h^2/4).
  const HarmonicOscillator osc;
  const double h = 0.3;
  const auto z = implicit_midpoint(osc, make_state(1.0, 0.5), h);
  EXPECT_NEAR(z.q[0], ((1 - h * h / 4) * 1.0 + h * 0.5) / (1 + h * h / 4), 1e-15);
  EXPECT_NEAR(z.p[0], ((1 - h * h / 4) * 0.5 - h * 1.0) / (1 + h * h / 4), 1e-15);
}

// The orbit of (13)-(14) from (q, p) = (A, 0) in closed form against the iterated map.
TEST(Lobatto, ExactOrbitIsTheIteratedMap) {
  const double m = 1.0, w = 2 * std::numbers::pi, A = std::numbers::pi / 2, h = 0.1;
  const auto orbit = lobatto_exact_orbit(h, m, w, A);
  ASSERT_TRUE(orbit.has_value());
  const LobattoCoefficients k = lobatto_coefficients(h, m, w);
  const Mat<2> Phi = lobatto_map_13(h, m, w);
  Vec<2> x(0.0, A);  // (p, q)
  for (int j = 1; j <= 200; ++j) {
    x = Phi * x;
    EXPECT_NEAR(x[1], A * std::cos(j * orbit->theta), 1e-12) << j;
    EXPECT_NEAR(x[0], -std::sqrt(-k.b / k.c) * A * std::sin(j * orbit->theta), 1e-11) << j;
    const double H = 0.5 * x[0] * x[0] / m + 0.5 * m * w * w * x[1] * x[1];
    EXPECT_NEAR(H - orbit->H0, orbit->K * std::pow(std::sin(j * orbit->theta), 2), 1e-12) << j;
  }
  EXPECT_NEAR(orbit->H0, 0.5 * m * w * w * A * A, 1e-14);
  EXPECT_NEAR(orbit->Hd0, -0.5 * Phi(0, 1) * A * A, 1e-13);  // (15) at p = 0
  EXPECT_FALSE(lobatto_exact_orbit(4.0 / w, m, w, A).has_value());  // h w = 4: second interval, c < 0 < b
}

// Fig. 2's growth in exact arithmetic against a run of the map: the same window maxima of
// |H_j - H_0|, and so the same slope, up to the round-off of the run. N = 3 (Fig. 1's mesh): the
// samples pass the peak of sin^2 within the run; N = 10: they approach it; N = 20: one starts on it.
TEST(Lobatto, ExactGrowthEqualsTheSimulatedGrowth) {
  const double m = 1.0, w = 2 * std::numbers::pi, A = std::numbers::pi / 2, T = 1.0, periods = 2000;
  const std::int64_t windows = 50;
  for (const int N : {3, 10, 20}) {
    const double h = T / N;
    const auto g = lobatto_exact_growth(h, m, w, A, periods, windows);
    ASSERT_TRUE(g.has_value());
    const Mat<2> Phi = lobatto_map_13(h, m, w);
    const std::int64_t n = std::llround(periods * T / h), W = n / windows;
    WindowMaxima wm(W);
    Vec<2> x(0.0, A);
    const double H0 = 0.5 * m * w * w * A * A;
    double largest = 0;
    for (std::int64_t j = 1; j <= n; ++j) {
      x = Phi * x;
      const double dH = 0.5 * x[0] * x[0] / m + 0.5 * m * w * w * x[1] * x[1] - H0;
      wm.add(dH), largest = std::max(largest, std::abs(dH));
    }
    ASSERT_EQ(wm.maxima().size(), g->maxima.size());
    // (the run drifts by the round-off of H_d, Fig. 2 (c): relative to |K|, most at N = 20)
    const double tol = (N == 20 ? 1e-2 : 1e-5) * g->bound;
    for (std::size_t i = 0; i < g->maxima.size(); ++i) EXPECT_NEAR(wm.maxima()[i], g->maxima[i], tol) << N << " " << i;
    EXPECT_LE(largest, g->bound + tol);
    const double largest_maximum = *std::max_element(g->maxima.begin(), g->maxima.end());
    ASSERT_TRUE(g->periods_to_peak.has_value());
    if (N == 20) {  // a sample starts on the peak, the maxima stay at |K|
      EXPECT_EQ(*g->periods_to_peak, 0.0);
      EXPECT_LT(std::abs(g->slope_per_period) * periods, 1e-6 * g->bound);
    } else {        // the samples approach the peak: the maxima grow, as measured
      EXPECT_GT(g->slope_per_period, 0);
      EXPECT_NEAR(wm.slope_per_window() / (static_cast<double>(W) * h / T), g->slope_per_period, 0.02 * g->slope_per_period);
      EXPECT_EQ(largest_maximum == g->bound, *g->periods_to_peak < periods) << N;  // reached |K| within the run
    }
  }
}

// The stable set of (13)-(14): bounded by the roots of a -+ delta~, whose factored forms equal (14);
// its first interval ends at the printed bound (10); the map built from the definition is stable
// inside each interval and unstable between them; H_d (15) is definite on each.
TEST(Lobatto, StableSetAgainstThePrintedBoundOf10) {
  for (double x : {0.5, 7.0, 25.0, 44.0, 70.0, 90.0}) {
    const LobattoCoefficients k = lobatto_coefficients(std::sqrt(x), 1.0, 1.0);
    EXPECT_NEAR(k.a - k.delta_tilde, -x * (x - 30) * (x - 60) / 3600, 1e-12 * (1 + x * x * x / 3600)) << x;
    EXPECT_NEAR(k.a + k.delta_tilde, -(x - 10) * (x * x - 84 * x + 720) / 3600, 1e-12 * (1 + x * x * x / 3600)) << x;
  }
  const auto set = lobatto_stable_set();
  ASSERT_EQ(set.size(), 3u);
  EXPECT_EQ(set[0][0], 0.0);
  EXPECT_NEAR(set[0][1], method_info("lobatto").oscillatory_bound, 1e-14);  // 001 eq. (10)
  const HarmonicOscillator osc{1.0, 1.0};
  const auto R = lobatto_rule();
  double inside = 0, gaps = std::numeric_limits<double>::infinity();  // largest radius in the set, smallest between
  for (std::size_t i = 0; i < set.size(); ++i) {
    const auto [lo, hi] = set[i];
    for (int k = 1; k < 10; ++k) {
      const double hw = lo + (hi - lo) * k / 10.0;
      inside = std::max(inside, radius(one_step_matrix(R, osc, hw)));
      const LobattoCoefficients c = lobatto_coefficients(hw, 1.0, 1.0);
      EXPECT_TRUE(i == 1 ? (c.c < 0 && 0 < c.b) : (c.b < 0 && 0 < c.c)) << hw;  // H_d definite
    }
    if (i + 1 < set.size()) gaps = std::min(gaps, radius(one_step_matrix(R, osc, 0.5 * (hi + set[i + 1][0]))));
  }
  gaps = std::min(gaps, radius(one_step_matrix(R, osc, set.back()[1] + 0.1)));
  EXPECT_CASE("Lobatto: largest spectral radius at 9 points inside each of the 3 stable intervals", inside, "<=",
              1 + 1e-12);
  EXPECT_CASE("smallest spectral radius between the intervals and beyond the last", gaps, ">", 1 + 1e-6);
}

// Work-precision on a power law err = h^4 with wall time and evaluations proportional to 1/h:
// log-log interpolation is exact there, and nothing is extrapolated.
TEST(WorkPrecision, InterpolatesInLogLogAndNeverExtrapolates) {
  std::vector<CostRun> runs;
  for (double h : {0.05, 0.4, 0.1, 0.2}) runs.push_back({h, 1 / h, 1e-6 / h, 10 / h, std::pow(h, 4)});
  runs.push_back({0.3, 1 / 0.3, 0.0, 1.0, 1.0});  // not measurable (no wall time): left out
  const auto r = by_decreasing_h(runs);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r.front().h, 0.4);
  const double target = 1e-3, h = std::pow(target, 0.25);  // reached between h = 0.2 and 0.1
  EXPECT_NEAR(cost_to_reach(r, target, &CostRun::wall_s).value(), 1e-6 / h, 1e-12 * 1e-6 / h);
  EXPECT_NEAR(cost_to_reach(r, target, &CostRun::evals).value(), 10 / h, 1e-12 * 10 / h);
  EXPECT_FALSE(cost_to_reach(r, 1e-8, &CostRun::wall_s).has_value());  // below the smallest error
  EXPECT_FALSE(cost_to_reach(r, 1.0, &CostRun::wall_s).has_value());   // above the largest
  const double wall = 1.5e-5;
  EXPECT_NEAR(error_at_wall(r, wall).value(), std::pow(1e-6 / wall, 4), 1e-12 * std::pow(1e-6 / wall, 4));
  EXPECT_FALSE(error_at_wall(r, 1e-3).has_value());
  EXPECT_EQ(largest_wall(r), 1e-6 / 0.05);
}

}  // namespace galerkin_variational_test
