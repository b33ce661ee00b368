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
  // Fig. 6: the printed h = 0.2 blows up for the 3 x 3 cluster; h = 0.01 is stable, |H - H0| ~ 1e-3.
  const auto& r = summary()["reproduced"];
  bool has_02 = false, has_001 = false;
  for (const auto& h : r["lj_stable_steps"]) has_02 |= h.get<double>() == 0.2, has_001 |= h.get<double>() == 0.01;
  EXPECT_FALSE(has_02);
  EXPECT_TRUE(has_001);
  EXPECT_LT(r["lj_H_err_max"].get<double>(), 2e-2);
  EXPECT_GT(r["lj_sigma_final"].get<double>(), 0.0);
}
