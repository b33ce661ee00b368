// Published values as data (runner/published.hpp): reading published.toml and the verdicts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../hard_case.hpp"
#include "geomint/runner/published.hpp"
#include "geomint/runner/results_json.hpp"
#include "temp_paths.hpp"

using namespace geomint;

namespace published_test {  // the file's scope (the tests build as one translation unit)
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

fs::path published_file(const std::string& text) {
  static int count = 0;
  const fs::path p = test::temp_path("geomint_published_test", "_" + std::to_string(count++) + ".toml");
  std::ofstream(p) << text;
  return p;
}

std::string error_of(const std::string& text) {
  try {
    read_published(published_file(text));
  } catch (const PublishedError& e) {
    return e.what();
  }
  return "";
}

const std::string kEntries = R"(
[p_err]
study = "table1"
value = 1.0e-6
where = "Table 1"
summary = "reproduced.p_err"
compare = { rel = 0.03 }
why = "the spread of the fixture"

[order]
study = "convergence"
value = 4
where = "Fig. 4"
summary = "orders.sv"
compare = { order = 0.1 }
why = "the curvature of the fixture's local slopes"

[growth]
study = "long_run"
value = { "0.1" = 3.0e-11, "0.05" = 5.0e-14 }
where = "Fig. 2"
summary = "reproduced.growth"
compare = { abs = "printed" }
roundoff = { floor = "reproduced.growth_floor", exact = "reproduced.growth_exact" }
requires = { "long_run.periods" = 100000.0 }
note = "round-off below h = 0.1"

[shown]
study = "table1"
value = 3
where = "text"
summary = "reproduced.shown"
)";

json verdict(const Published& e, const json& summary, const json& scene = json::object()) {
  const auto c = compare_published(e, summary, scene, {"table1", "convergence", "long_run"});
  return c ? (*c)["verdict"] : json(nullptr);
}

}  // namespace

TEST(Published, ReadsTheEntriesInFileOrder) {
  const auto entries = read_published(published_file(kEntries));
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].key, "p_err");
  EXPECT_EQ(entries[0].compare, "rel");
  EXPECT_EQ(entries[0].tolerance, 0.03);
  EXPECT_EQ(entries[1].key, "order");
  EXPECT_EQ(entries[2].key, "growth");
  EXPECT_EQ(entries[2].requires_["long_run.periods"], 100000.0);
  EXPECT_EQ(entries[3].compare, "");
}

TEST(Published, RejectsMalformedEntries) {
  const auto refused = [](const std::string& what, const std::string& text, const std::string& needle) {
    EXPECT_REFUSAL_OF(PublishedError, what, read_published(published_file(text)), {needle});
  };
  const std::string entry = "[a]\nstudy = \"s\"\nvalue = 1\nwhere = \"w\"\n";
  refused("an entry without a summary key", entry, "missing 'summary'");
  refused("an unknown field", entry + "summary = \"x\"\ncolour = 1\n", "unknown field");
  refused("a relative tolerance on a published 0",
          "[a]\nstudy = \"s\"\nvalue = 0\nwhere = \"w\"\nsummary = \"x\"\ncompare = { rel = 0.1 }\n", "!= 0");
  refused("an unknown comparison", entry + "summary = \"x\"\ncompare = { near = 0.1 }\n", "compare is");
  refused("an unknown expectation", entry + "summary = \"x\"\nexpect = \"maybe\"\n", "expect");
  // a known discrepancy names the test that shows it
  refused("a discrepancy without its test", entry + "summary = \"x\"\nexpect = \"differs\"\nnote = \"n\"\n", "ctest test");
  refused("a file that is not TOML", "[a\n", "not valid TOML");
  // an erratum quotes the paper's words it contradicts
  const std::string differs = entry + "summary = \"x\"\nexpect = \"differs\"\nnote = \"n\"\ntest = \"t\"\n";
  refused("a printed statement that differs, without quotes", differs, "needs quotes");
  refused("a quotation without its place", differs + "quotes = [{ text = \"words\" }]\n", "quotes is a list");
  refused("quotes that are not a list", differs + "quotes = \"words\"\n", "quotes is a list");
  EXPECT_EQ(error_of(differs + "quotes = [{ at = \"004 Sect. 1.4\", text = \"words\" }]\n"), "");
  // a convention quotes the passage whose assumption it holds under
  const std::string convention = entry + "summary = \"x\"\nkind = \"convention\"\nexpect = \"differs\"\nnote = \"n\"\ntest = \"t\"\n";
  refused("a convention without the passage it holds under", convention, "a convention needs quotes");
  EXPECT_EQ(error_of(convention + "quotes = [{ at = \"004 Sect. 1.4\", text = \"attained when p_n = 0\" }]\n"), "");
  // a typed tolerance states its origin; a derived or an exact one has none to state
  refused("a typed tolerance without its origin", entry + "summary = \"x\"\ncompare = { rel = 0.1 }\n", "needs why");
  refused("a claim's bound without its origin", "[a]\nstudy = \"s\"\nwhere = \"w\"\nsummary = \"x\"\ncompare = { above = 0.8 }\n",
          "needs why");
  refused("an origin for a derived tolerance", entry + "summary = \"x\"\ncompare = { abs = \"printed\" }\nwhy = \"w\"\n",
          "has none");
  EXPECT_EQ(error_of(entry + "summary = \"x\"\ncompare = { abs = 0 }\n"), "");  // (exact: 0 has no origin to state)
  EXPECT_EQ(error_of(entry + "summary = \"x\"\ncompare = { rel = 0.1 }\nwhy = \"the spread of 100 samples\"\n"), "");
}

TEST(Published, VerdictsByTolerance) {
  const auto e = read_published(published_file(kEntries));
  EXPECT_EQ(verdict(e[0], {{"reproduced", {{"p_err", 1.02e-6}}}}), "reproduced");
  EXPECT_EQ(verdict(e[0], {{"reproduced", {{"p_err", 1.04e-6}}}}), "differs");
  EXPECT_EQ(verdict(e[0], {{"reproduced", {{"p_err", nullptr}}}}), "differs");  // NaN written as null: never within
  EXPECT_EQ(verdict(e[1], {{"orders", {{"sv", 4.08}}}}), "reproduced");
  EXPECT_EQ(verdict(e[1], {{"orders", {{"sv", 3.85}}}}), "differs");
  EXPECT_EQ(verdict(e[3], {{"reproduced", {{"shown", 7}}}}), "reported");
}

TEST(Published, ValueTablesMatchTheReproducedKeysByNumberOrName) {
  const auto e = read_published(published_file(kEntries));
  const json scene = {{"long_run", {{"periods", 100000}}}};
  // (its round-off floor and exact value by h, as the run writes them: at h = 0.05 the entry is round-off)
  const auto with_floor = [](json summary) {
    summary["reproduced"]["growth_floor"] = {{"0.10000000000000001", 1e-14}, {"0.050000000000000003", 3e-13}};
    summary["reproduced"]["growth_exact"] = {{"0.10000000000000001", 3e-11}, {"0.050000000000000003", 1e-17}};
    return summary;
  };
  const json summary =
      with_floor({{"reproduced", {{"growth", {{"0.10000000000000001", 3.01e-11}, {"0.050000000000000003", -3e-13}}}}}});
  const auto c = compare_published(e[2], summary, scene, {"long_run"});
  ASSERT_TRUE(c);
  EXPECT_EQ((*c)["verdict"], "reproduced");
  EXPECT_EQ((*c)["published"]["0.10000000000000001"], 3.0e-11);  // keyed as the reproduced values
  EXPECT_EQ((*c)["note"], "round-off below h = 0.1");
  const json far =
      with_floor({{"reproduced", {{"growth", {{"0.10000000000000001", 3.06e-11}, {"0.050000000000000003", 2e-12}}}}}});
  EXPECT_EQ(verdict(e[2], far, scene), "differs");
  // A parameter the run did not compute is listed and left out; none computed: not computed.
  const json partial = with_floor({{"reproduced", {{"growth", {{"0.10000000000000001", 3.0e-11}}}}}});
  const auto p = compare_published(e[2], partial, scene, {"long_run"});
  EXPECT_EQ((*p)["verdict"], "reproduced");
  EXPECT_EQ((*p)["not_computed"], json::array({"0.05"}));
  EXPECT_EQ(verdict(e[2], {{"reproduced", {{"growth", json::object()}}}}, scene), "not computed");
}

TEST(Published, PrintedDigitsGiveHalfAUnitInTheLast) {
  EXPECT_DOUBLE_EQ(half_unit_in_last_digit("2.50e-11"), 5e-14);
  EXPECT_DOUBLE_EQ(half_unit_in_last_digit("0.603"), 5e-4);
  EXPECT_DOUBLE_EQ(half_unit_in_last_digit("6"), 0.5);
  EXPECT_DOUBLE_EQ(half_unit_in_last_digit("-3.0E2"), 5.0);
  EXPECT_DOUBLE_EQ(half_unit_in_last_digit("1_000.5"), 0.05);
}

// A tolerance from the printed digits is the rounding of each printed value; an entry whose value in exact
// arithmetic lies below the run's round-off floor is not comparable, the others are judged (001 Fig. 2).
TEST(Published, ToleranceFromThePrintedDigitsAndEntriesAtRoundOff) {
  const auto e = read_published(published_file(R"(
[growth]
study = "long_run"
value = { "0.1" = 2.50e-11, "0.05" = 5.45e-14 }
where = "Fig. 2"
summary = "reproduced.growth"
compare = { abs = "printed" }
roundoff = { floor = "reproduced.floor", exact = "reproduced.exact" }
)"));
  const auto run = [&](double at_01, double exact_005) {
    const json summary = {{"reproduced", {{"growth", {{"0.1", at_01}, {"0.05", -3.1e-13}}},
                                          {"floor", {{"0.1", 1.5e-14}, {"0.05", 3.1e-13}}},
                                          {"exact", {{"0.1", 2.5e-11}, {"0.05", exact_005}}}}}};
    return *compare_published(e[0], summary, json::object(), {"long_run"});
  };
  EXPECT_EQ(run(2.5049e-11, 1e-17)["verdict"], "reproduced");  // within 5e-14 of 2.50e-11
  EXPECT_EQ(run(2.5049e-11, 1e-17)["roundoff"], json::array({"0.05"}));
  EXPECT_EQ(run(2.5051e-11, 1e-17)["verdict"], "differs");     // rounds to 2.51e-11
  EXPECT_EQ(run(2.5049e-11, 1e-12)["verdict"], "differs");     // 0.05 comparable: -3.1e-13 against 5.45e-14
  const auto all = read_published(published_file(R"(
[Hd]
study = "table1"
value = { "10" = 2.66e-15 }
where = "Table 1"
summary = "reproduced.Hd"
compare = { abs = "printed" }
roundoff = { floor = "reproduced.floor" }
)"));
  const json summary = {{"reproduced", {{"Hd", {{"10", 1.4e-14}}}, {"floor", {{"10", 1e-11}}}}}};
  EXPECT_EQ((*compare_published(all[0], summary, json::object(), {"table1"}))["verdict"], "not comparable");
}

// A tolerance from the run's statistics: kStandardErrors of the standard error the run wrote.
TEST(Published, ToleranceFromTheRunsStandardError) {
  const auto e = read_published(published_file(R"(
[gamma]
study = "ensemble"
value = 0.5
where = "Fig. 4"
summary = "reproduced.gamma"
compare = { abs = "stderr" }
stderr = "reproduced.gamma_stderr"
)"));
  const auto verdict_at = [&](double gamma, double se) {
    const json summary = {{"reproduced", {{"gamma", gamma}, {"gamma_stderr", se}}}};
    return (*compare_published(e[0], summary, json::object(), {"ensemble"}))["verdict"];
  };
  EXPECT_EQ(verdict_at(0.6, 0.06), "reproduced");  // 0.1 <= 2 x 0.06
  EXPECT_EQ(verdict_at(0.6, 0.04), "differs");     // 0.1 > 2 x 0.04
  EXPECT_NE(error_of("[g]\nstudy = \"e\"\nvalue = 0.5\nwhere = \"F\"\nsummary = \"r.g\"\ncompare = { abs = \"stderr\" }\n")
                .find("needs stderr"), std::string::npos);
}

TEST(Published, PrintedDigitsNeedADecimalLiteral) {
  EXPECT_NE(error_of("[n]\nstudy = \"s\"\nvalue = 0x1F\nwhere = \"F\"\nsummary = \"r.n\"\ncompare = { abs = \"printed\" }\n")
                .find("written in decimal"), std::string::npos);
}

TEST(Published, ATypedToleranceNotSmallerThanItsValueIsALoadError) {
  EXPECT_NE(error_of(R"(
[growth]
study = "long_run"
value = { "0.1" = 2.5e-11, "0.05" = 5.45e-14 }
where = "Fig. 2"
summary = "reproduced.growth"
compare = { abs = 1e-12 }
why = "w"
)").find("is not smaller than the value 5.45e-14"), std::string::npos);
}

TEST(Published, OtherSceneParametersAreNotComparable) {
  const auto e = read_published(published_file(kEntries));
  const json scene = {{"long_run", {{"periods", 1000}}}};
  const auto c = compare_published(e[2], json::object(), scene, {"long_run"});
  ASSERT_TRUE(c);
  EXPECT_EQ((*c)["verdict"], "not comparable");
  EXPECT_NE((*c)["reason"].get<std::string>().find("long_run.periods = 1000, published at 100000"), std::string::npos);
}

TEST(Published, OnlyStudiesThatRanAndOnlyWhatTheyComputed) {
  const auto e = read_published(published_file(kEntries));
  EXPECT_FALSE(compare_published(e[0], json::object(), json::object(), {"convergence"}));
  EXPECT_EQ((*compare_published(e[0], json::object(), json::object(), {"table1"}))["verdict"], "not computed");
  json summary = {{"reproduced", {{"p_err", 1.0e-6}, {"shown", 3}}}};
  apply_published(e, summary, json::object(), {"table1"});
  EXPECT_EQ(summary["published"]["p_err"], 1.0e-6);
  EXPECT_EQ(summary["comparisons"]["p_err"]["verdict"], "reproduced");
  EXPECT_FALSE(summary["comparisons"].contains("order"));
  apply_published(e, summary, {{"long_run", {{"periods", 1000}}}}, {"long_run"});  // not comparable:
  EXPECT_EQ(summary["comparisons"]["growth"]["verdict"], "not comparable");      // compared, not published
  EXPECT_FALSE(summary["published"].contains("growth"));
}

TEST(Published, ValueTablesKeyedByMethod) {
  const auto e = read_published(published_file(R"(
[order]
study = "s"
value = { M = 2, T = 2 }
where = "w"
summary = "orders.o"
compare = { order = 0.3 }
why = "w"
)"));
  EXPECT_EQ(verdict(e[0], {{"orders", {{"o", {{"M", 2.05}, {"T", 1.9}}}}}}), nullptr);  // study s did not run
  const auto c = compare_published(e[0], {{"orders", {{"o", {{"M", 2.05}, {"T", 1.6}}}}}}, json::object(), {"s"});
  EXPECT_EQ((*c)["verdict"], "differs");
  EXPECT_NEAR((*c)["difference"]["T"].get<double>(), -0.4, 1e-12);
}

// Every entry belongs to one item of the paper its study makes: given where the study makes several,
// taken from the study where it makes one; the comparison carries it (the ledger's verdict per figure).
TEST(Published, EachEntryBelongsToAFigureItsStudyMakes) {
  using V = std::vector<std::string>;
  const auto makes = [](const std::string& study) {
    return study == "table1" ? V{"001 Table 1"} : study == "convergence" ? V{"000 Fig. 4"} : study == "long_run" ? V{"001 Fig. 2"}
                                                                                                             : V{"003 Fig. 5.2", "003 Fig. 5.4"};
  };
  auto entries = read_published(published_file(kEntries));
  resolve_figures(entries, "published.toml", makes);
  EXPECT_EQ(entries[0].figure, "001 Table 1");
  EXPECT_EQ(entries[1].figure, "000 Fig. 4");
  const auto c = compare_published(entries[1], {{"orders", {{"sv", 4.05}}}}, json::object(), {"convergence"});
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ((*c)["figure"], "000 Fig. 4");
  const auto resolved = [&](const std::string& figure_line) {
    auto e = read_published(published_file("[a]\nstudy = \"volumes\"\nvalue = 1\nwhere = \"w\"\nsummary = \"x\"\n" + figure_line));
    try {
      resolve_figures(e, "published.toml", makes);
    } catch (const PublishedError& err) {
      return std::string(err.what());
    }
    return e[0].figure;
  };
  EXPECT_EQ(resolved("figure = \"003 Fig. 5.4\"\n"), "003 Fig. 5.4");
  EXPECT_EQ(resolved("figure = \"004 Sec. 1.4\"\n"), "004 Sec. 1.4");  // a statement of the text
  EXPECT_EQ(resolved("figure = \"000 eq. (16)\"\n"), "000 eq. (16)");
  EXPECT_NE(resolved("").find("figure = ?"), std::string::npos) << resolved("");
  EXPECT_NE(resolved("figure = \"003 Fig. 5.3\"\n").find("not one the study volumes makes"), std::string::npos);
}

TEST(Published, ClaimsAreComparedAboveOrBelowTheirThreshold) {
  const auto e = read_published(published_file(R"(
[side]
study = "table1"
where = "the cuts lie in p2 < 0"
summary = "share"
compare = { above = 0.5 }
why = "a majority"

[each]
study = "table1"
where = "less drift than the other, for every method"
summary = "ratio"
compare = { below = 1 }
why = "less than the other"
)"));
  EXPECT_EQ(e[0].value, "> 0.5");
  EXPECT_EQ(verdict(e[0], {{"share", 0.93}}), "reproduced");
  EXPECT_EQ(verdict(e[0], {{"share", 0.07}}), "differs");
  EXPECT_EQ(verdict(e[0], {{"share", 0.5}}), "differs");  // on the bound: the claim does not hold
  EXPECT_EQ(verdict(e[1], {{"ratio", {{"M", 0.2}, {"T", 0.9}}}}), "reproduced");
  EXPECT_EQ(verdict(e[1], {{"ratio", {{"M", 0.2}, {"T", 1.1}}}}), "differs");  // every value of a table
  EXPECT_EQ(verdict(e[1], {{"ratio", json::object()}}), "differs");           // nothing measured: no claim holds
  EXPECT_NE(error_of("[a]\nstudy = \"s\"\nvalue = 1\nwhere = \"w\"\nsummary = \"x\"\ncompare = { above = 0.5 }\n")
                .find("no 'value'"),
            std::string::npos);
}

TEST(Published, AClaimWithAStandardErrorHoldsOnlyThatManyStandardErrorsPastItsLimit) {
  // a share of random samples above one half (a coin flip) by kStandardErrors of its binomial standard error
  const auto e = read_published(published_file(R"(
[typical]
study = "table1"
where = "the claim holds for most starts"
summary = "share"
compare = { above = 0.5 }
stderr = "share_stderr"
why = "one half: a coin flip"
)"));
  ASSERT_EQ(e[0].tolerance_origin, "stderr");
  EXPECT_EQ(verdict(e[0], {{"share", 0.8}, {"share_stderr", 0.1}}), "reproduced");  // 0.3 above, 2 x 0.1 needed
  EXPECT_EQ(verdict(e[0], {{"share", 0.65}, {"share_stderr", 0.1}}), "differs");   // above, but within 2 x 0.1
  EXPECT_EQ(verdict(e[0], {{"share", 0.65}}), "differs");                          // no standard error: not held
  const auto c = compare_published(e[0], {{"share", 0.8}, {"share_stderr", 0.1}}, json::object(), {"table1"});
  ASSERT_TRUE(c);
  EXPECT_EQ((*c)["compare"], json({{"above", 0.5}}));  // the bound as typed, the margin in tolerances
  EXPECT_DOUBLE_EQ((*c)["tolerances"]["of"].get<double>(), kStandardErrors * 0.1);
}

TEST(Published, KindsAndChosenParameters) {
  EXPECT_NE(error_of("[a]\nstudy = \"s\"\nvalue = 1\nwhere = \"w\"\nsummary = \"x\"\nkind = \"rumour\"\n").find("kind is"),
            std::string::npos);
  EXPECT_NE(error_of("[a]\nstudy = \"s\"\nvalue = 1\nwhere = \"w\"\nsummary = \"x\"\nkind = \"convention\"\n")
                .find("needs its note"),
            std::string::npos);
  EXPECT_NE(error_of("[a]\nstudy = \"s\"\nvalue = 1\nwhere = \"w\"\nsummary = \"x\"\nchosen = { h = 0.2 }\n")
                .find("needs its note"),
            std::string::npos);
  const auto e = read_published(published_file(
      "[a]\nstudy = \"table1\"\nvalue = 3.0\nwhere = \"w\"\nsummary = \"x\"\ncompare = { rel = 0.1 }\nwhy = \"w\"\n"
      "kind = \"authors_code\"\nchosen = { \"lj.h\" = 0.2 }\nnote = \"the printed step diverges\"\n"));
  const auto c = compare_published(e[0], {{"x", 3.1}}, {{"lj", {{"h", 0.01}}}}, {"table1"});
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ((*c)["kind"], "authors_code");
  EXPECT_EQ((*c)["chosen"]["lj.h"]["printed"], 0.2);
  EXPECT_EQ((*c)["chosen"]["lj.h"]["used"], 0.01);
}

TEST(Published, EachFigureHasOneVerdictFromItsOwnComparisons) {
  const auto comparison = [](const char* figure, const char* verdict, json extra = json::object()) {
    json c = {{"figure", figure}, {"verdict", verdict}};
    for (const auto& [k, v] : extra.items()) c[k] = v;
    return c;
  };
  const json chosen = {{"chosen", {{"lj.h", {{"printed", 0.2}, {"used", 0.01}}}}}};
  const json comparisons = {
      {"sigma4", comparison("004 Fig. 4", "reproduced")},
      {"side", comparison("004 Fig. 5", "differs", {{"expect", "differs"}})},
      {"symmetric", comparison("004 Fig. 5", "reproduced")},
      {"sigma6", comparison("004 Fig. 6", "reproduced", chosen)},
      {"mu6", comparison("004 Fig. 6", "reported", chosen)},
      {"printed_step", comparison("004 Sec. 5.3", "differs", {{"expect", "differs"}})},
      {"norm", comparison("000 Fig. 9", "differs", {{"kind", "convention"}})},
      {"max_norm", comparison("000 Fig. 9", "reproduced")},
      {"eq12", comparison("001 Table 1", "differs")},
      {"other_scene", comparison("003 Fig. 5.3", "not comparable")},
      {"rowlands", comparison("000 Fig. 4", "reproduced",
                              {{"corrected", {{"what", "the coefficient of (32)-(33)"}, {"printed", "h^2/24"},
                                              {"used", "h^2/12"}, {"printed_gives", "printed"}}}})},
  };
  const auto verdict_of = [&](const char* figure) { return figure_verdict(comparisons, figure)["verdict"]; };
  EXPECT_EQ(verdict_of("004 Fig. 4"), "reproduced");
  EXPECT_EQ(verdict_of("004 Fig. 5"), "partly reproduced");  // never Fig. 4's values
  EXPECT_EQ(verdict_of("004 Fig. 6"), "reproduced with a corrected parameter");  // the text's erratum is not Fig. 6's
  EXPECT_EQ(verdict_of("000 Fig. 9"), "reproduced");          // a convention is listed, not judged
  EXPECT_EQ(verdict_of("000 Fig. 4"), "reproduced with a corrected coefficient");  // one policy with Fig. 6's
  EXPECT_EQ(verdict_of("001 Table 1"), "differs");
  EXPECT_EQ(verdict_of("003 Fig. 5.3"), "not comparable");
  EXPECT_EQ(verdict_of("003 Fig. 5.1"), "no printed value");
  const json f5 = figure_verdict(comparisons, "004 Fig. 5");
  EXPECT_EQ(f5["reproduced"], json::array({"symmetric"}));
  EXPECT_EQ(f5["differs"], json::array({"side"}));
  EXPECT_FALSE(f5.contains("unexpected"));  // expected to differ: an erratum, not a regression
  EXPECT_EQ(figure_verdict(comparisons, "001 Table 1")["unexpected"], json::array({"eq12"}));
  EXPECT_EQ(figure_verdict(comparisons, "004 Fig. 6")["chosen"]["lj.h"]["printed"], 0.2);
  EXPECT_EQ(figure_verdict(comparisons, "000 Fig. 9")["conventions"], json::array({"norm"}));
  json summary = {{"comparisons", comparisons}};
  apply_figure_verdicts(summary, {"004 Fig. 4", "004 Fig. 5"});
  EXPECT_EQ(summary["figures"].size(), 2u);
  EXPECT_EQ(summary["figures"]["004 Fig. 5"]["verdict"], "partly reproduced");
}

// What a study reports (runner/results.hpp) reaches summary.json as nlohmann wrote it before: members in
// the order added, integers as integers (3) and reals as reals (3.0), null for a missing value.
TEST(Results, WrittenAsJsonWritesIt) {
  Value v;
  v["reproduced"]["order"] = 3.0;
  v["count"] = std::size_t{3};
  v["shift"] = -2;
  v["h"] = {{"min", 0.01}, {"max", 0.1}};
  v["methods"] = std::vector<std::string>{"sv", "ti"};
  v["none"] = std::optional<double>();
  v["list"].push_back(1.5);
  EXPECT_EQ(to_json(v).dump(),
            R"({"reproduced":{"order":3.0},"count":3,"shift":-2,"h":{"min":0.01,"max":0.1},"methods":["sv","ti"],)"
            R"("none":null,"list":[1.5]})");
  EXPECT_EQ(value_of(to_json(v)), v);  // and back, kinds included
  EXPECT_EQ(v.at("h").at("max").number(), 0.1);
  EXPECT_EQ(v.at("count").integer(), 3);
  EXPECT_EQ(v.at("methods").at(1).text(), "ti");
  EXPECT_TRUE(v.at("none").is_null());
  EXPECT_THROW(v.at("missing"), std::out_of_range);
  EXPECT_THROW(v.at("methods").number(), std::logic_error);
  EXPECT_THROW(v["count"]["x"] = 1, std::logic_error);  // a number is not a record
}

TEST(Results, MergeAddsMembersAndNothingForNone) {
  Value summary;
  merge(summary, "reproduced", {{"a", 1.0}});
  merge(summary, "reproduced", {{"b", 2.0}, {"a", 3.0}});
  merge(summary, "orders", Value::record());
  EXPECT_EQ(to_json(summary).dump(), R"({"reproduced":{"a":3.0,"b":2.0}})");
}

}  // namespace published_test
