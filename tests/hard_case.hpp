#pragma once
// One measured quantity of a hard case and the bound it is held to: asserted, and written as a line
//   HARDCASE {"what": "...", "measured": x, "relation": "<=", "bound": b}
// of the test's output (relation <, <=, >, >= or ==; {"relation": "near", "bound": target, "tolerance": t}
// for |x - target| <= t).
// ctest's JUnit report (make paper: paper/generated/hardcases.xml) keeps the output, and the report's
// hard-cases chapter shows each case's bound and measured value from these lines.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace geomint::test {

inline ::testing::AssertionResult hard_case(const std::string& what, double measured, const std::string& relation,
                                            double bound, double tolerance = 0) {
  nlohmann::ordered_json line = {{"what", what},
                                 {"measured", std::isfinite(measured) ? nlohmann::ordered_json(measured) : nullptr},
                                 {"relation", relation},
                                 {"bound", bound}};
  if (relation == "near") line["tolerance"] = tolerance;
  std::printf("HARDCASE %s\n", line.dump().c_str());
  std::fflush(stdout);
  const bool holds = relation == "=="   ? measured == bound
                     : relation == "<"  ? measured < bound
                     : relation == "<=" ? measured <= bound
                     : relation == ">"  ? measured > bound
                     : relation == ">=" ? measured >= bound
                     : relation == "near" && std::abs(measured - bound) <= tolerance;
  if (holds) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": measured " << measured << ", not " << relation << " " << bound
                                       << (relation == "near" ? " within " + std::to_string(tolerance) : "");
}

}  // namespace geomint::test

// EXPECT_CASE("what", measured, "<=", bound) and EXPECT_CASE_NEAR("what", measured, target, tolerance)
#define EXPECT_CASE(what, measured, relation, bound) \
  EXPECT_TRUE(::geomint::test::hard_case((what), (measured), (relation), (bound)))
#define EXPECT_CASE_NEAR(what, measured, target, tolerance) \
  EXPECT_TRUE(::geomint::test::hard_case((what), (measured), "near", (target), (tolerance)))
