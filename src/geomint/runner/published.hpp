#pragma once
// What the papers printed, as data: experiments/<name>/published.toml holds
// one table per published quantity,
//
//   [p_err]
//   study = "table1"                      # the study that reproduces it
//   value = { "10" = 8.95e-6, "20" = 1.39e-7 }   # a table keyed by a parameter (here N), or one number
//   where = "001 Table 1, N = 10, 20"     # seed, figure / table / equation
//   figure = "001 Table 1"                # the figure, table or section of the paper it belongs to: one
//                                         # the study makes (Study::makes), or a statement of the text
//                                         # ("004 Sec. 1.4", "000 eq. (16)"); may be left out where the
//                                         # study makes exactly one (or none: a quantity beyond the figures)
//   summary = "reproduced.p_err"          # the reproduced value in summary.json (dotted path; for a
//                                         # table, an object with the parameters as keys)
//   compare = { rel = 0.03 }              # or { abs = 1e-13 }, { order = 0.1 } (|difference| <= 0.1);
//                                         # { rel = "printed" } or { abs = "printed" }: half a unit in the
//                                         # last digit of each value as printed (its TOML literal: 2.50e-11
//                                         # gives 5e-14, 0.603 gives 5e-4), the rounding of the print;
//                                         # { abs = "stderr" } with stderr = "summary path": kStandardErrors
//                                         # standard errors of the reproduced value, from the run's own data;
//                                         # without compare the value is reported, not compared;
//                                         # a printed qualitative claim ("the cuts lie in p2 < 0") is
//                                         # { above = x } or { below = x }: the measured quantity
//                                         # (every value of a table) lies above or below x; no `value`;
//                                         # with stderr = "summary path": beyond x by kStandardErrors
//                                         # standard errors of the measured quantity, from the run's data
//                                         # (a claim about a share of random samples)
//   why = "..."                           # where a typed tolerance comes from (required with one, unless
//                                         # it is 0: an exact comparison); the report lists them in one table
//   kind = "printed"                      # where the value comes from: "printed" (default), "scanning"
//                                         # (printed, but the scanned text may have garbled it),
//                                         # "authors_code" (not printed: the code published with the
//                                         # paper gives it), "convention" (a convention the paper leaves
//                                         # open, computed beside the one compared: never an erratum),
//                                         # "sample" (printed of one random sample the paper does not
//                                         # give, e.g. the trajectory of a random start: the reproduction's
//                                         # sample may differ without contradicting the paper)
//   chosen = { "lj.h" = 0.2 }             # a parameter the reproduction sets otherwise than printed
//                                         # (scene key = the printed value; the note says why)
//   corrected = { what = "the coefficient of (32)-(33)", printed = "h^2/24", used = "h^2/12",
//                 printed_gives = "rowlands_printed_phase" }
//                                         # a printed coefficient or formula the reproduction replaces by a
//                                         # derived one; printed_gives: the entry that shows what the printed
//                                         # one gives (the note says why)
//   roundoff = { floor = "reproduced.x_roundoff", exact = "reproduced.x_exact" }
//                                         # the run's round-off floor of the quantity and its value in exact
//                                         # arithmetic (summary paths, keyed as the value table): an entry
//                                         # whose exact value lies at or below the floor measures round-off,
//                                         # printed and reproduced alike, and is "not comparable (round-off)"
//                                         # (without exact: where printed and reproduced both lie at or below)
//   requires = { "long_run.periods" = 100000.0 }   # scene values under which it is comparable
//   expect = "differs"                    # a known discrepancy (default: "reproduced")
//   note = "..."                          # why the reproduction differs, if it does
//   test = "regression.X.Y"               # the ctest test that demonstrates it (required with expect)
//
// After the studies ran, every entry of a study that ran is set against the
// summary: summary.comparisons.<key> holds figure, where, published, reproduced, difference,
// compare, verdict and note. The verdict is "reproduced" or "differs" (by the
// tolerance, or the claim's bound), "reported" (no compare), "not comparable" (the scene differs
// from `requires`) or "not computed" (the study ran without computing it, e.g.
// for other methods); a value table with a parameter the run did not compute
// is an internal error. summary.published.<key> is the published value of every
// entry but those not comparable or not computed. The regression tests require
// every comparison of the quick scenes to be made.
//
// Then each figure or table a study made under the run's scene gets one verdict from its own
// comparisons only (figure_verdict), in summary.figures."<item>".
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace geomint {

struct PublishedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Published {
  std::string key, study, where, summary, note, test;
  std::string why;                  // a typed tolerance's origin (required with one)
  std::string figure;                // "004 Fig. 5": the item of the paper (paper/papers.toml) it belongs to
  std::string expect = "reproduced";
  nlohmann::ordered_json value;     // a number, or an object of numbers keyed by a parameter
  std::string compare;              // "rel", "abs", "order", "above", "below" (a claim) or "" (reported only)
  double tolerance = 0;             // (the bound of a claim)
  std::string tolerance_origin = "typed";  // "typed" (the number in compare), "printed" (the print's rounding) or
                                           // "stderr" (kStandardErrors standard errors, from the run)
  nlohmann::ordered_json tolerances;       // "printed": per value (a number, or an object keyed as the value)
  std::string roundoff_floor, roundoff_exact;  // summary paths of the round-off floor and the exact value
  std::string stderr_path;                     // "stderr": the summary path of the reproduced value's standard error
  std::string kind = "printed";     // "printed", "scanning", "authors_code", "convention" or "sample"
  nlohmann::ordered_json chosen = nlohmann::ordered_json::object();  // scene key -> the printed value
  nlohmann::ordered_json corrected;  // {what, printed, used, printed_gives}, or null
  nlohmann::ordered_json requires_ = nlohmann::ordered_json::object();  // dotted scene key -> value
  nlohmann::ordered_json quotes = nlohmann::ordered_json::array();  // [{"at", "text"}]: the paper's words, verbatim
};

// A tolerance from the run's statistics is this many standard errors of what it judges.
inline constexpr double kStandardErrors = 2;

// Half a unit in the last digit of a number as printed: "2.50e-11" -> 5e-14, "0.603" -> 5e-4, "6" -> 0.5.
double half_unit_in_last_digit(std::string literal);

// The entries of a published.toml, in file order; throws PublishedError naming the file and the entry.
std::vector<Published> read_published(const std::filesystem::path& file);

// The verdict of one entry against a summary and a resolved scene (Scene::to_json()); nullopt if the
// entry's study did not run.
std::optional<nlohmann::ordered_json> compare_published(const Published& entry, const nlohmann::ordered_json& summary,
                                                        const nlohmann::ordered_json& scene,
                                                        const std::vector<std::string>& studies_ran);

// Sets summary.published and summary.comparisons from every entry of a study that ran.
void apply_published(const std::vector<Published>& entries, nlohmann::ordered_json& summary,
                     const nlohmann::ordered_json& scene, const std::vector<std::string>& studies_ran);

// The verdict of one figure or table from its comparisons (summary.comparisons entries whose figure
// it is), in the report's vocabulary:
//   "reproduced"                 every compared value (a number, an order or a claim) within tolerance;
//   "reproduced with a corrected parameter", "... coefficient", "... parameter and coefficient"
//                                so, but at least one with a printed parameter (`chosen`) or coefficient
//                                (`corrected`) replaced: one policy wherever the paper's input is corrected;
//   "partly reproduced"          some within tolerance, some not;
//   "differs"                    none within tolerance (each explained in the errata, or a regression);
//   "not comparable"             nothing compared, something not comparable under this scene;
//   "no printed value"           nothing compared: the paper prints no number or claim for it (its
//                                shape is compared by eye), only reported values if any.
// Conventions (kind = "convention") are listed, never judged. The object holds the verdict and the
// keys by outcome: reproduced, differs (unexpected: those expected to reproduce), reported,
// not_comparable, conventions, chosen (scene key -> {printed, used}), corrected (what -> {printed, used,
// printed_gives}).
nlohmann::ordered_json figure_verdict(const nlohmann::ordered_json& comparisons, const std::string& figure);

// summary.figures: figure_verdict of every item in `made` (the items the studies that ran made under
// the scene, in order).
void apply_figure_verdicts(nlohmann::ordered_json& summary, const std::vector<std::string>& made);

// Each entry's figure checked against, or taken from, the ids of the items its study makes (`items_of(study)`,
// Study::makes); throws PublishedError naming the file and the entry.
void resolve_figures(std::vector<Published>& entries, const std::filesystem::path& file,
                     const std::function<std::vector<std::string>(const std::string&)>& items_of);

// The value at a dotted path ("reproduced.p_err.10", "initial.0.1"), or nullptr if there is none.
const nlohmann::ordered_json* json_at(const nlohmann::ordered_json& j, const std::string& dotted);

}  // namespace geomint
