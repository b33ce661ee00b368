// Regression: the quick scene of ti_drift (004 Figs 1-6).
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "summary.hpp"

using json = nlohmann::json;

namespace {
const json& summary() { return summary_of("ti_drift"); }
}  // namespace

TEST(TiDrift, OrdersOnTheOscillator) {
  const auto& o = summary()["orders"];
  EXPECT_NEAR(o["ti_energy"].get<double>(), 6.0, 0.4);
  EXPECT_NEAR(o["ti_solution"].get<double>(), 4.0, 0.3);
  EXPECT_NEAR(o["sv_energy"].get<double>(), 2.0, 0.15);
}

TEST(TiDrift, ForestRuthAtEqualWork) {
  // Fig. 1 with Forest-Ruth (not in 004): order 4, at h = 3 h_eff / 2 (3 force evaluations per step,
  // TI 2: the gradient and a Hessian-vector product, SV 1).
  const auto& o = summary()["orders"];
  EXPECT_NEAR(o["forest_ruth_solution"].get<double>(), 4.0, 0.3);
  EXPECT_NEAR(o["forest_ruth_energy"].get<double>(), 4.0, 0.3);
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
  // Bisection on the spectral radius against the registry's bound (004 Sect. 1.4: 2 sqrt(3)).
  EXPECT_NEAR(summary()["reproduced"]["ti_stability_bound"].get<double>(),
              summary()["published"]["ti_stability_bound"].get<double>(), 1e-9);
  EXPECT_NEAR(summary()["published"]["ti_stability_bound"].get<double>(), 2 * std::sqrt(3.0), 1e-15);
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
  // Fig. 4 on a small ensemble: sigma ~ t^gamma with gamma near 1/2.
  const double g = summary()["reproduced"]["hh5_sigma_exponent"].get<double>();
  EXPECT_GE(g, 0.3);
  EXPECT_LE(g, 0.7);
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
