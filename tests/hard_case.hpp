#pragma once
// One measured quantity of a hard case and the bound it is held to: asserted, and written as a line
//   HARDCASE {"what": "...", "measured": x, "relation": "<=", "bound": b}
// of the test's output (relation <, <=, >, >= or ==; {"relation": "near", "bound": target, "tolerance": t}
// for |x - target| <= t); or, for a refusal, a line
//   HARDCASE {"what": "...", "measured": "the refusal's message" (null: accepted), "relation": "names", "bound": [needles]}
// that holds when the input was refused with a message naming every needle.
// ctest's JUnit report (make paper: paper/generated/hardcases.xml) keeps the output, and the report's
// hard-cases chapter shows each case's bound and measured value from these lines.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

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

// The message with which `statement` was refused (an exception of type E), or nothing if it was accepted.
template <class E = std::exception, class F>
std::optional<std::string> refusal_of(F&& statement) {
  try {
    statement();
  } catch (const E& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

inline ::testing::AssertionResult refusal_case(const std::string& what, const std::optional<std::string>& message,
                                               const std::vector<std::string>& needles) {
  nlohmann::ordered_json line = {{"what", what},
                                 {"measured", message ? nlohmann::ordered_json(*message) : nullptr},
                                 {"relation", "names"},
                                 {"bound", needles}};
  std::printf("HARDCASE %s\n", line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
  std::fflush(stdout);
  if (!message) return ::testing::AssertionFailure() << what << ": accepted, not refused";
  for (const auto& n : needles)
    if (message->find(n) == std::string::npos)
      return ::testing::AssertionFailure() << what << ": the refusal does not name '" << n << "': " << *message;
  return ::testing::AssertionSuccess();
}

// The last line of a process's stderr (its refusal or failure), or nothing if it ended with exit 0.
inline std::optional<std::string> last_error_line(int exit_code, const std::string& err) {
  if (exit_code == 0) return std::nullopt;
  std::string e = err;
  while (!e.empty() && e.back() == '\n') e.pop_back();
  return e.substr(e.rfind('\n') == std::string::npos ? 0 : e.rfind('\n') + 1);
}

}  // namespace geomint::test

// EXPECT_CASE("what", measured, "<=", bound) and EXPECT_CASE_NEAR("what", measured, target, tolerance)
#define EXPECT_CASE(what, measured, relation, bound) \
  EXPECT_TRUE(::geomint::test::hard_case((what), (measured), (relation), (bound)))
#define EXPECT_CASE_NEAR(what, measured, target, tolerance) \
  EXPECT_TRUE(::geomint::test::hard_case((what), (measured), "near", (target), (tolerance)))
// EXPECT_REFUSAL("what", statement, {"needle", ...}): `statement` throws a std::exception whose message
// names each needle; EXPECT_REFUSAL_OF(E, ...) for an exception of type E.
#define EXPECT_REFUSAL_OF(E, what, statement, ...) \
  EXPECT_TRUE(::geomint::test::refusal_case((what), ::geomint::test::refusal_of<E>([&] { statement; }), __VA_ARGS__))
#define EXPECT_REFUSAL(what, statement, ...) EXPECT_REFUSAL_OF(std::exception, what, statement, __VA_ARGS__)
// EXPECT_RUN_REFUSED("what", exit_code, stderr, code, {"needle", ...}): a run ended with exit `code` and the last
// line of its stderr names each needle (two hard-case lines: the exit code, the message).
#define EXPECT_RUN_REFUSED(what, exit_code, err, code, ...)                                                        \
  do {                                                                                                           \
    EXPECT_CASE(std::string(what) + ": exit code", (exit_code), "==", (code)) << (err);                          \
    EXPECT_TRUE(::geomint::test::refusal_case((what), ::geomint::test::last_error_line((exit_code), (err)),     \
                                              __VA_ARGS__));                                                     \
  } while (false)
