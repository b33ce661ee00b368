// Regression: the quick scene of euler_compensation reproduces the published
// claims of 000 (Figs 2, 3, 8, 9). Runs on the outputs of the ctest fixture
// euler_compensation.quick_run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "summary.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const fs::path dir = results_dir("euler_compensation");

const json& summary() { return summary_of("euler_compensation"); }

}  // namespace

// The published orders of Fig. 9 and the exactness of Figs 2-3: Published.EulerCompensation
// (published_test.cpp), with the tolerances of experiments/euler_compensation/published.toml.

TEST(EulerCompensation, EulerInTheOriginalCoordinateIsVisiblyOff) {
  // Figs 2-3: at the same steps, Euler in y is off by more than 10 % while Euler in ybar is exact.
  const auto& r = summary()["reproduced"];
  EXPECT_GT(r["decay_euler_max_rel_err"].get<double>(), 0.1);
  EXPECT_GT(r["gompertz_euler_max_rel_err"].get<double>(), 0.1);
}

TEST(EulerCompensation, CompensatedTrajectoryIsCloserToTheCircle) {
  // Fig 8: the compensated solution stays closer to H = 1/2.
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["fig8_max_energy_err_compensated"].get<double>(), r["fig8_max_energy_err_se"].get<double>());
  EXPECT_LT(r["fig8_max_abs_qhat"].get<double>(), 1.0);
}

TEST(EulerCompensation, Rk4EnergyErrorIsFifthOrderOnTheOscillator) {
  // |R(ih)|^2 = 1 - h^6/72 + O(h^8) for RK4, so after T/h steps |H - H0| ~ T h^5 / 144.
  EXPECT_NEAR(summary()["orders"]["rk4_energy"].get<double>(), 5.0, 0.1);
}

TEST(EulerCompensation, TimingIsReportedNotAsserted) {
  const auto& t = summary()["timing"]["ns_per_step"];
  EXPECT_GT(t["se"].get<double>(), 0.0);
  EXPECT_GT(t["se_compensated"].get<double>(), 0.0);
}

TEST(EulerCompensation, OutputsAreComplete) {
  for (const char* f : {"fig2_decay.csv", "fig2_decay_exact.csv", "fig3_gompertz.csv", "fig3_gompertz_exact.csv",
                        "fig8_phase.csv", "fig8_exact.csv", "fig9_convergence.csv", "orders.csv", "timing.csv",
                        "summary.json", "run.json"}) {
    ASSERT_TRUE(fs::is_regular_file(dir / f)) << f;
    EXPECT_GT(fs::file_size(dir / f), 20u) << f;
  }
  std::ifstream in(dir / "run.json");
  const json run = json::parse(in);
  EXPECT_EQ(run["scene"]["oscillator"]["k"].get<double>(), 2.0);
  EXPECT_FALSE(run["build"]["git_commit"].get<std::string>().empty());
  EXPECT_EQ(run["threads"].get<int>(), 2);
}
