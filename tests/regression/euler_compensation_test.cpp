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

TEST(EulerCompensation, FittedOrdersMatchThePaper) {
  const auto& o = summary()["orders"];
  EXPECT_NEAR(o["ee_decay"].get<double>(), 1.0, 0.1);               // explicit Euler: order 1
  EXPECT_NEAR(o["se_energy"].get<double>(), 1.0, 0.1);              // Fig 9, eq. (44)
  EXPECT_NEAR(o["se_compensated_energy"].get<double>(), 2.0, 0.1);  // Fig 9, Appendix B
}

TEST(EulerCompensation, PublishedValuesAreRecorded) {
  const auto& p = summary()["published"];
  EXPECT_EQ(p["se_energy"].get<double>(), 1.0);
  EXPECT_EQ(p["se_compensated_energy"].get<double>(), 2.0);
  EXPECT_EQ(p["ee_decay"].get<double>(), 1.0);
}

TEST(EulerCompensation, EulerInTheCompensatingCoordinateIsExact) {
  // Sections 2.3.1-2.3.2: exact up to round-off.
  const auto& r = summary()["reproduced"];
  EXPECT_LE(r["decay_compensated_max_rel_err"].get<double>(), 1e-12);
  EXPECT_LE(r["gompertz_compensated_max_rel_err"].get<double>(), 1e-12);
  EXPECT_GT(r["decay_euler_max_rel_err"].get<double>(), 0.1);  // ... while Euler in y is visibly off
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
