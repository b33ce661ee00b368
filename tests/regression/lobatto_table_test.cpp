// Regression: the quick scene of lobatto_table reproduces 001 Table 1 and the
// claims around it (order 6, stability bound (10), symplecticity), and the
// nonlinear extension. Orders and the bound are the registry's (methods/registry.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "geomint/methods/registry.hpp"
#include "summary.hpp"

using json = nlohmann::json;
using geomint::method_info;

namespace {
const json& summary() { return summary_of("lobatto_table"); }
std::string label(const char* method) { return std::string(method_info(method).label); }
}  // namespace

// Table 1 and the growth rates of Fig. 2 against the published values: Published.LobattoTable
// (published_test.cpp), with the tolerances of experiments/lobatto_table/published.toml.

TEST(LobattoTable, DeclaredOrdersOnTheOscillatorAndNonlinearSystems) {
  const auto& o = summary()["orders"];
  const double lobatto = method_info("lobatto").order;  // 6
  for (const char* key : {"lobatto_p", "lobatto_q", "lobatto_H", "lobatto_nonlinear_pendulum", "lobatto_elastic_pendulum"})
    EXPECT_NEAR(o[key].get<double>(), lobatto, 0.3) << key;
  // Table 1's compared methods (the scene's table1.methods) and the same on the pendulum (nonlinear.methods).
  EXPECT_NEAR(o[label("simpson")].get<double>(), method_info("simpson").order, 0.2);
  EXPECT_NEAR(o[label("implicit_midpoint")].get<double>(), method_info("implicit_midpoint").order, 0.1);
  EXPECT_NEAR(o[label("simpson") + "_nonlinear_pendulum"].get<double>(), method_info("simpson").order, 0.2);
  EXPECT_NEAR(o[label("implicit_midpoint") + "_nonlinear_pendulum"].get<double>(), method_info("implicit_midpoint").order,
              0.1);
}

TEST(LobattoTable, StabilityBoundAndRunsAroundIt) {
  const auto& r = summary()["reproduced"];
  const double bound = method_info("lobatto").oscillatory_bound;  // 001 eq. (10)
  EXPECT_NEAR(r["stability_bound"].get<double>(), bound, 1e-9);
  EXPECT_EQ(summary()["published"]["stability_bound"].get<double>(), bound);
  EXPECT_EQ(r["bound_runs"]["0.98999999999999999"]["diverged_at_step"].get<long>(), -1);
  EXPECT_GT(r["bound_runs"]["1.01"]["diverged_at_step"].get<long>(), 0);
}

TEST(LobattoTable, NonlinearMapsAreSymplectic) {
  const auto& r = summary()["reproduced"];
  EXPECT_LT(r["symplecticity_defect_pendulum"].get<double>(), 1e-10);
  EXPECT_LT(r["symplecticity_defect_elastic"].get<double>(), 1e-10);
}

// 001 eq. (12) as printed (published.toml: eq12_printed_order, an erratum): iterated as a scheme,
// its state error over Table 1's meshes does not decrease at all (order about 0, not 6).
TEST(LobattoTable, Equation12AsPrintedDoesNotConverge) {
  EXPECT_LT(std::abs(summary()["orders"]["lobatto_printed_eq12_q"].get<double>()), 0.5);
}

// The scan's stable intervals are the exact stable set of (13)-(14) to the grid spacing.
TEST(LobattoTable, ScanFindsTheExactStableSet) {
  const auto& st = summary()["stability"];
  const auto& scan = summary()["reproduced"]["stable_set_h_omega"];
  const auto& exact = st["exact_set_h_omega"];
  const double step = st["grid_step"].get<double>();
  ASSERT_EQ(scan.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (int end : {0, 1}) EXPECT_NEAR(scan[i][end].get<double>(), exact[i][end].get<double>(), step) << i << " " << end;
}

// Table 1: every compared error of p, q and H rounds to the printed digits.
TEST(LobattoTable, Table1RoundsToThePrintedDigits) {
  const auto& printed = summary()["table1"]["printed"];
  EXPECT_GT(printed["compared"].get<int>(), 0);
  EXPECT_EQ(printed["round_to_printed_digits"].get<int>(), printed["compared"].get<int>());
}

// Fig. 2 at the first step size (N = 10): the measured growth rate is the exact-arithmetic rate of
// the closed-form orbit, up to the round-off drift of H_d seen in H.
TEST(LobattoTable, MeasuredGrowthIsTheExactGrowth) {
  const auto& r = summary()["long_run"]["rates"][0];
  const double exact = r["exact_rate"].get<double>(), measured = r["H_rate"].get<double>();
  EXPECT_GT(exact, 0);
  EXPECT_NEAR(measured, exact, 0.01 * exact);
  EXPECT_LT(std::abs(r["H_rate_minus_exact"].get<double>()), 10 * r["roundoff_in_H"].get<double>());
}
