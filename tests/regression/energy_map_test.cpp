// Regression: the quick scene of energy_map (000 Fig. 6 and Sec. 5.2).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "summary.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const fs::path dir = results_dir("energy_map");

const json& summary() { return summary_of("energy_map"); }

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(EnergyMap, PolarDivergenceFollowsTheAnalyticBoundary) {
  EXPECT_GE(summary()["reproduced"]["boundary_agreement"].get<double>(), 0.95);
}

TEST(EnergyMap, EpsIsFiniteWhereverTheRunDidNotDiverge) {
  std::ifstream in(dir / "map.csv");
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line, "x0,y0,H0,eps_cartesian,eps_polar,diverged_cartesian,diverged_polar,diverge_step_polar");
  int rows = 0;
  while (std::getline(in, line)) {
    double v[8];
    std::stringstream ss(line);
    std::string cell;
    for (double& x : v) std::getline(ss, cell, ','), x = std::strtod(cell.c_str(), nullptr);
    EXPECT_EQ(std::isfinite(v[3]), v[5] == 0) << line;
    EXPECT_EQ(std::isfinite(v[4]), v[6] == 0) << line;
    ++rows;
  }
  EXPECT_EQ(rows, summary()["grid"]["points"].get<int>());
}

// Sec. 5.2.1 (p_x changes at O(h^2) per step in polar coordinates) and Sec. 5.2.2 (the angular
// momentum kept in Cartesian coordinates): Published.EnergyMap, with the tolerances of
// experiments/energy_map/published.toml.

TEST(EnergyMap, CompensatedSummationKeepsTheAngularMomentumWherePlainSummationDrifts) {
  // The exact preservation (69) shows only with compensated summation of the increments.
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["cartesian_L_max_rel_drift"].get<double>(), r["cartesian_L_max_rel_drift_plain"].get<double>());
}

TEST(EnergyMap, ResumeGivesTheSameMap) {
  // Stop after one round of batches, resume, and compare with an uninterrupted run (the map study alone).
  const std::string bin = std::string(GEOMINT_BIN_DIR) + "/energy_map --quick --study map --set grid.nx=48 --set grid.ny=48 ";
  const fs::path a = dir.parent_path() / "energy_map-resume", b = dir.parent_path() / "energy_map-straight";
  fs::remove_all(a), fs::remove_all(b);
  const int stopped = std::system((bin + "--set checkpoint.stop_after=1 --out " + a.string() + " 2>/dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(stopped));
  EXPECT_EQ(WEXITSTATUS(stopped), 3);
  EXPECT_TRUE(fs::exists(a / "energy_map.checkpoint.json"));
  EXPECT_FALSE(fs::exists(a / "map.csv"));
  ASSERT_EQ(std::system((bin + "--resume --out " + a.string() + " 2>/dev/null").c_str()), 0);
  ASSERT_EQ(std::system((bin + "--out " + b.string() + " 2>/dev/null").c_str()), 0);
  EXPECT_EQ(read(a / "map.csv"), read(b / "map.csv"));
  EXPECT_FALSE(fs::exists(a / "energy_map.checkpoint.json"));
}
