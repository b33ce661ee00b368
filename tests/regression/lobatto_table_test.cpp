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
