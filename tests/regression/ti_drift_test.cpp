// Regression: the quick scene of ti_drift (004 Figs 1-6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/published.hpp"
#include "summary.hpp"

using json = nlohmann::json;

namespace {
const json& summary() { return summary_of("ti_drift"); }
}  // namespace

// The orders and the stability bound of Fig. 1 against the published values: Published.TiDrift
// (published_test.cpp), with the tolerances of experiments/ti_drift/published.toml.

TEST(TiDrift, ForestRuthAtEqualWork) {
  // Fig. 1 with Forest-Ruth (not in 004): order 4, at h = 3 h_eff / 2 (3 force evaluations per step,
  // TI 2: the gradient and a Hessian-vector product, SV 1).
  const auto& o = summary()["orders"];
  const double declared = geomint::method_info("forest_ruth").order;
  EXPECT_NEAR(o["forest_ruth_solution"].get<double>(), declared, 0.3);
  EXPECT_NEAR(o["forest_ruth_energy"].get<double>(), declared, 0.3);
  const auto& e = summary()["equal_work"]["evals_per_step"];
  EXPECT_EQ(e["sv"].get<int>(), 1);
  EXPECT_EQ(e["ti"].get<int>(), 2);
  EXPECT_EQ(e["sti"].get<int>(), 2);
  EXPECT_EQ(e["forest_ruth"].get<int>(), 3);
}

TEST(TiDrift, SimplifiedMethodCoincidesWithTiOnTheOscillator) {
  const auto& o = summary()["orders"];
  EXPECT_NEAR(o["sti_solution"].get<double>(), o["ti_solution"].get<double>(), 1e-9);
  EXPECT_NEAR(o["sti_energy"].get<double>(), o["ti_energy"].get<double>(), 1e-9);
}

TEST(TiDrift, StabilityBoundOfTakahashiImada) {
  // Bisection on the spectral radius against the registry's bound (the published one: Published.TiDrift).
  EXPECT_NEAR(summary()["reproduced"]["ti_stability_bound"].get<double>(),
              geomint::method_info("takahashi_imada").oscillatory_bound, 1e-9);
}

TEST(TiDrift, ShiftedEnergyDriftsAtThePredictedRate) {
  // Fig. 2: the rate of (4.3), averaged along the orbit, against the fitted slope.
  const auto& r = summary()["reproduced"];
  const double rate = r["unsym_pendulum_drift_rate"].get<double>(), pred = r["unsym_pendulum_drift_rate_predicted"].get<double>();
  EXPECT_LT(rate, 0.0);
  EXPECT_NEAR(rate, pred, 0.05 * std::abs(pred));
}

TEST(TiDrift, ModifiedEnergyHasNoDriftForCubicHenonHeiles) {
  // Fig. 3: bounded O(h^6) error, no drift over the run.
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["hh3_max_E_err"].get<double>(), 1e-7);
  EXPECT_LT(std::abs(r["hh3_drift_slope"].get<double>()) * 2000.0, 0.1 * r["hh3_max_E_err"].get<double>());
}

TEST(TiDrift, RandomWalkExponent) {
  // Fig. 4 on the quick scene's small ensemble (32 starts, t to 1e6): sigma ~ t^gamma with gamma
  // within 0.2 of the published 1/2 (the paper scene's comparison, with its tolerance, is in
  // published.toml).
  const auto entries = geomint::read_published(std::filesystem::path(GEOMINT_SOURCE_DIR) /
                                               "experiments/ti_drift/published.toml");
  const auto e = std::find_if(entries.begin(), entries.end(), [](const auto& p) { return p.key == "hh5_sigma_exponent"; });
  ASSERT_NE(e, entries.end());
  EXPECT_NEAR(summary()["reproduced"]["hh5_sigma_exponent"].get<double>(), e->value.get<double>(), 0.2);
}

TEST(TiDrift, SymplecticVersusVolumePreserving) {
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["ti_symplecticity_defect"].get<double>(), 1e-9);
  EXPECT_GT(r["sti_symplecticity_defect"].get<double>(), 1e-8);
  EXPECT_LT(std::abs(r["sti_det_minus_one"].get<double>()), 1e-9);
  EXPECT_LT(std::abs(r["ti_det_minus_one"].get<double>()), 1e-9);  // symplectic, so volume-preserving too
}

TEST(TiDrift, LennardJonesPrintedStepIsUnstable) {
  // Fig. 6 (erratum lj_printed_step_stable of published.toml): every run of the step-size scan at the
  // printed step (lj_h) blows up for the 3 x 3 cluster; the step of the run (lj.h) is stable there, with
  // |H - H0| of the size 004 reports.
  const auto& r = summary()["reproduced"];
  const double printed = summary()["comparisons"]["lj_h"]["published"].get<double>();
  bool scanned = false;
  for (const auto& row : summary()["lj"]["scan"])
    if (row["h"].get<double>() == printed) {
      scanned = true;
      EXPECT_EQ(row["diverged"].get<int>(), row["runs"].get<int>());
      EXPECT_GT(row["runs"].get<int>(), 0);
    }
  EXPECT_TRUE(scanned) << "the scan does not include the printed step";
  bool run_step_stable = false;
  for (const auto& h : r["lj_stable_steps"]) run_step_stable |= h.get<double>() == r["lj_h"].get<double>();
  EXPECT_TRUE(run_step_stable);
  EXPECT_LT(r["lj_H_err_max"].get<double>(), 2e-2);
  // the error of E of (4.2) random-walks, sigma ~ t^(1/2) (0.42 on the quick scene's 8 runs); with a wrong
  // coefficient of U^(4) in (4.2) a bounded O(h^4) oscillation flattens it (0.24)
  EXPECT_NEAR(r["lj_sigma_exponent"].get<double>(), 0.5, 0.15);
}

TEST(TiDrift, ShiftedEnergyRemovesTheOscillationOfH) {
  // Fig. 2: about a least-squares quadratic (without the curvature of the drift) H + h^2 H_3 oscillates far less
  // than H; with half the H_3 of (3.3) it would keep half of the O(h^2) oscillation.
  const auto& q = summary()["pendulum"]["peak_to_peak_about_quadratic"];
  EXPECT_LT(q["shifted_energy"].get<double>(), 0.1 * q["H"].get<double>());
}

TEST(TiDrift, StormerVerletGrowsLinearlyOnItsBound) {
  // 004 Sect. 1.4 prints "stable only for omega h <= 2" (erratum sv_stable_at_bound): at omega h = 2 the
  // double root -1 makes the solution grow linearly, max |z_n| ~ n.
  EXPECT_NEAR(summary()["oscillator"]["sv_growth_exponent_at_bound"].get<double>(), 1.0, 0.1);
}

TEST(TiDrift, TiEnergyErrorFromRestIsUnbounded) {
  // 004 Sect. 1.4: the error "converges to one" as omega h -> 2 sqrt(3) only from q0 = 0 (erratum
  // ti_energy_error_bounded); from p0 = 0 the sampled maximum (over the span of Fig. 1) is far above one and
  // below its closed form x^3 / (12 - x)^3 (the unit test TakahashiImada.FromRestTheEnergyErrorIsUnbounded
  // follows it to the closed form over a longer run).
  const auto& f = summary()["oscillator"]["from_rest"];
  EXPECT_LE(f["max_rel_H_err"].get<double>(), f["closed_form"].get<double>() * (1 + 1e-9));
  EXPECT_GT(f["max_rel_H_err"].get<double>(), 10.0);
  EXPECT_LT(summary()["oscillator"]["largest_step"]["ti"]["max_rel_H_err"].get<double>(), 1.0);  // from q0 = 0
}

TEST(TiDrift, Sect33RemainderIsOrderSeven) {
  // 004 Sect. 3.3 prints O(h^8) for the remainder of q_{n+1} with f''(f, f) at q_{n+1/2} (erratum
  // sect33_q_remainder): it is O(h^7); with the term at q_n it vanishes on the cubic problem.
  EXPECT_NEAR(summary()["sect33"]["order_at_midpoint"].get<double>(), 7.0, 0.2);
  EXPECT_LT(summary()["sect33"]["largest_at_q_n"].get<double>(), 1e-15);
}

TEST(TiDrift, SampledMaximaAgreeWithTheClosedForms) {
  // Fig. 1: below omega h_eff = 1 the sampled largest energy errors follow the closed forms of Sect. 1.4.
  const auto& c = summary()["oscillator"]["closed_form"];
  EXPECT_LT(c["sv"]["max_deviation_below"].get<double>(), 1e-3);
  EXPECT_LT(c["ti"]["max_deviation_below"].get<double>(), 1e-2);
  EXPECT_LE(c["sv"]["min_ratio_above"].get<double>(), 1.0 + 1e-9);  // sampled maxima never exceed the closed form
}
