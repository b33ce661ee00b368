// Each experiment's published.toml against its quick run: every published quantity of a study that
// ran is in summary.json with the published value of the file, and each comparison the quick scene
// allows comes out as the file expects ("reproduced" unless it names a known discrepancy). The
// tolerances are the file's: changing a published value there makes this test fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "geomint/runner/published.hpp"
#include "summary.hpp"

using namespace geomint;

namespace published_test {  // the file's scope (the tests build as one translation unit)

namespace {

void expect_published(const std::string& experiment) {
  const auto entries =
      read_published(std::filesystem::path(GEOMINT_SOURCE_DIR) / "experiments" / experiment / "published.toml");
  const auto& summary = summary_of(experiment);
  const auto& ran = summary["studies"];
  int compared = 0;
  for (const Published& e : entries) {
    if (std::find(ran.begin(), ran.end(), e.study) == ran.end()) continue;
    ASSERT_TRUE(summary["comparisons"].contains(e.key)) << e.key;
    const auto& c = summary["comparisons"][e.key];
    const std::string verdict = c["verdict"];
    if (e.value.is_number() && verdict != "not comparable") EXPECT_EQ(summary["published"][e.key], e.value) << e.key;
    EXPECT_NE(verdict, "not computed") << e.key << ": " << c["reason"];
    if (verdict == "not comparable" || verdict == "reported" || verdict == "not computed") continue;
    ++compared;
    EXPECT_EQ(verdict, e.expect) << e.key << " (" << e.where << "): published " << e.value.dump() << ", reproduced "
                                 << c["reproduced"].dump() << ", difference " << c["difference"].dump();
  }
  EXPECT_GT(compared, 0) << "the quick scene of " << experiment << " compares no published value";
}

}  // namespace

#include "published_tests.inc"  // TEST(Published, <Name>) { expect_published("<name>"); } per experiment

}  // namespace published_test
