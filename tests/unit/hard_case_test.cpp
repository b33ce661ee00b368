// The hard-case helper (tests/hard_case.hpp): it holds a measured value to its bound by the relation it
// names, and writes the line the report's hard-cases chapter reads.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "../hard_case.hpp"

namespace hard_case_test {  // the file's scope (the tests build as one translation unit)

TEST(HardCase, HoldsOnlyOnTheSideOfItsBoundThatItNames) {
  using geomint::test::hard_case;
  EXPECT_TRUE(hard_case("a", 0.5, "<", 1.0));
  EXPECT_FALSE(hard_case("a", 1.0, "<", 1.0));
  EXPECT_TRUE(hard_case("a", 1.0, "<=", 1.0));
  EXPECT_FALSE(hard_case("a", 1.5, "<=", 1.0));
  EXPECT_TRUE(hard_case("a", 1.5, ">", 1.0));
  EXPECT_FALSE(hard_case("a", 1.0, ">", 1.0));
  EXPECT_TRUE(hard_case("a", 1.0, ">=", 1.0));
  EXPECT_TRUE(hard_case("exit code", 2, "==", 2));
  EXPECT_FALSE(hard_case("exit code", 1, "==", 2));
  EXPECT_TRUE(hard_case("order", 3.95, "near", 4.0, 0.1));
  EXPECT_FALSE(hard_case("order", 3.85, "near", 4.0, 0.1));
  EXPECT_FALSE(hard_case("a", std::nan(""), "<", 1.0));  // a NaN never holds
  EXPECT_FALSE(hard_case("a", 0.5, "~", 1.0));           // nor does an unknown relation
}

TEST(HardCase, WritesTheLineTheReportReads) {
  testing::internal::CaptureStdout();
  (void)geomint::test::hard_case("spectral radius at 0.99 x the bound", 0.93, "<=", 1.0);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(out, "HARDCASE {\"what\":\"spectral radius at 0.99 x the bound\",\"measured\":0.93,\"relation\":\"<=\","
                 "\"bound\":1.0}\n");
}

TEST(HardCase, ARefusalHoldsOnlyWhenRefusedWithAMessageNamingEveryNeedle) {
  using geomint::test::refusal_case;
  using geomint::test::refusal_of;
  const auto refuse = [] { throw std::invalid_argument("dt = -1: the step must be positive"); };
  EXPECT_TRUE(refusal_case("a negative step", refusal_of(refuse), {"dt", "positive"}));
  EXPECT_FALSE(refusal_case("a negative step", refusal_of(refuse), {"dt", "finite"}));  // a needle it does not name
  EXPECT_FALSE(refusal_case("a negative step", refusal_of([] {}), {"dt"}));             // accepted
  EXPECT_EQ(refusal_of<std::invalid_argument>(refuse), "dt = -1: the step must be positive");
  EXPECT_THROW(refusal_of<std::out_of_range>(refuse), std::invalid_argument);  // another type is not a refusal
}

TEST(HardCase, WritesTheRefusalLineTheReportReads) {
  testing::internal::CaptureStdout();
  (void)geomint::test::refusal_case("a NaN step", std::string("dt = nan"), {"dt"});
  (void)geomint::test::refusal_case("a NaN step", std::nullopt, {"dt"});
  EXPECT_EQ(testing::internal::GetCapturedStdout(),
            "HARDCASE {\"what\":\"a NaN step\",\"measured\":\"dt = nan\",\"relation\":\"names\",\"bound\":[\"dt\"]}\n"
            "HARDCASE {\"what\":\"a NaN step\",\"measured\":null,\"relation\":\"names\",\"bound\":[\"dt\"]}\n");
}

}  // namespace hard_case_test
