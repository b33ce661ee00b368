// Scene loading: overrides, validation, and the messages a user sees.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <stdlib.h>  // mkdtemp

#include "../hard_case.hpp"
#include "geomint/scene/scene.hpp"

using namespace geomint;
namespace fs = std::filesystem;

namespace scene_test {  // the file's scope (the tests build as one translation unit)

namespace {

Schema schema() {
  Schema s;
  s.real("decay.h", positive()).integer("decay.steps", at_least(1)).reals("convergence.h", positive(), 3);
  s.real_rows("initial", 2, any_finite(), 1).boolean("flags.fast").text("method", {"se", "rk4"});
  return s;
}

// A fresh directory under the system's temporary directory, removed with everything in it at exit.
struct TemporaryDirectory {
  fs::path path;
  TemporaryDirectory() {
    std::string name = (fs::temp_directory_path() / "geomint_scene_test_XXXXXX").string();
    if (!::mkdtemp(name.data())) throw std::runtime_error("mkdtemp failed for " + name);
    path = name;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
};

const fs::path& scene_dir() {
  static const TemporaryDirectory dir;
  return dir.path;
}

fs::path scene_file(const std::string& text) {
  static int counter = 0;
  const fs::path p = scene_dir() / ("scene_" + std::to_string(counter++) + ".toml");
  std::ofstream(p) << text;
  return p;
}

const std::string valid = R"(
initial = [[1.0, 0.0], [0.5, 0.5]]
method = "se"
[decay]
h = 0.3
steps = 20
[convergence]
h = [0.1, 0.05, 0.025]
[flags]
fast = true
)";

std::string error_of_file(const fs::path& file, const std::vector<std::string>& overrides = {}) {
  try {
    Scene::load(file, overrides, schema());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return error_of_file(scene_file(text), overrides);
}

// A hard case: the scene `text` with `overrides` is refused with a message that names every needle.
void expect_refused(const std::string& what, const std::string& text, const std::vector<std::string>& overrides,
                    const std::vector<std::string>& needles) {
  const fs::path file = scene_file(text);
  EXPECT_REFUSAL_OF(SceneError, what, Scene::load(file, overrides, schema()), needles);
}

}  // namespace

TEST(Scene, LoadsValidScene) {
  const auto s = Scene::load(scene_file(valid), {}, schema());
  EXPECT_DOUBLE_EQ(s.real("decay.h"), 0.3);
  EXPECT_EQ(s.integer("decay.steps"), 20);
  EXPECT_EQ(s.reals("convergence.h").size(), 3u);
  EXPECT_EQ(s.real_rows("initial")[1][1], 0.5);
  EXPECT_TRUE(s.boolean("flags.fast"));
  EXPECT_EQ(s.text("method"), "se");
  EXPECT_EQ(s.to_json()["decay"]["steps"], 20);
}

TEST(Scene, IntegerIsAcceptedAsReal) {
  std::string text = valid;
  text.replace(text.find("h = 0.3"), 7, "h = 1");
  EXPECT_DOUBLE_EQ(Scene::load(scene_file(text), {}, schema()).real("decay.h"), 1.0);
}

TEST(Scene, OverridesApply) {
  const auto s = Scene::load(scene_file(valid), {"decay.h=0.01", "convergence.h=[1, 0.5, 0.25, 0.125]", "method=\"rk4\""},
                             schema());
  EXPECT_DOUBLE_EQ(s.real("decay.h"), 0.01);
  EXPECT_EQ(s.reals("convergence.h").size(), 4u);
  EXPECT_EQ(s.text("method"), "rk4");
}

TEST(Scene, RejectsOutOfRangeNanAndNegative) {
  expect_refused("a negative step", valid, {"decay.h=-1"}, {"decay.h = -1 (from --set): must be a finite number > 0"});
  expect_refused("a NaN step", valid, {"decay.h=nan"}, {"decay.h = nan (from --set): must be a finite number > 0"});
  expect_refused("an infinite step", valid, {"decay.h=inf"}, {"decay.h = inf (from --set): must be a finite number > 0"});
  expect_refused("zero steps", valid, {"decay.steps=0"}, {"decay.steps = 0"});
  expect_refused("a negative step in a list", valid, {"convergence.h=[0.1, -0.05, 0.025]"}, {"each a finite number > 0"});
  expect_refused("a list shorter than its minimum", valid, {"convergence.h=[0.1, 0.05]"}, {"a list of 3 to"});
  // An integer key declared without an upper bound still fits an int: 2^31 is refused, 2^31 - 1 is not.
  expect_refused("an integer of 2^31", valid, {"decay.steps=2147483648"},
                 {"decay.steps = 2147483648 (from --set): must be an integer, a finite number >= 1 and <= 2147483647"});
  EXPECT_EQ(error_of(valid, {"decay.steps=2147483647"}), "");
}

TEST(Scene, RejectsUnknownKeys) {
  expect_refused("an unknown key in --set", valid, {"nosuch.key=1"},
                 {"--set nosuch.key=1: unknown key 'nosuch.key' (see --help for the keys)"});
  expect_refused("an unknown table in the scene", valid + "\n[extra]\nthing = 2\n", {}, {"unknown key 'extra.thing'"});
  // a key with a control character is named escaped, on one line
  const std::string nl = error_of(valid + "\n\"a\\nb\" = 1\n");
  EXPECT_NE(nl.find("unknown key 'flags.a\\nb'"), std::string::npos) << nl;
  EXPECT_EQ(nl.find('\n'), std::string::npos) << nl;
}

// A file the system says is regular but that cannot be read (/proc/self/mem: 0 bytes, an I/O error on reading)
// is a refusal naming it, not an abort.
TEST(Scene, AFileThatCannotBeReadIsRefused) {
  EXPECT_REFUSAL_OF(SceneError, "--scene /proc/self/mem", Scene::load("/proc/self/mem", {}, schema()),
                    {"/proc/self/mem", "cannot be read"});
}

TEST(Scene, RejectsTypeErrors) {
  std::string text = valid;
  text.replace(text.find("h = 0.3"), 7, "h = \"fast\"");
  expect_refused("a string for a number", text, {}, {"decay.h = \"fast\"", "must be a finite number > 0"});
  expect_refused("2.5 for an integer", valid, {"decay.steps=2.5"}, {"must be an integer"});
  expect_refused("1 for a boolean", valid, {"flags.fast=1"}, {"true or false"});
  expect_refused("a name not in the list", valid, {"method=\"euler\""}, {"one of \"se\", \"rk4\""});
  expect_refused("a row of 3 numbers for rows of 2", valid, {"initial=[[1, 2, 3]]"}, {"lists of 2 numbers"});
}

// A list longer than a study can use is refused before any work: max_list_entries numbers or rows, and a
// list of choices at most as long as its choices.
TEST(Scene, RefusesListsLongerThanAStudyCanUse) {
  const auto list_of = [](std::size_t n, const std::string& entry) {
    std::string v = "[";
    for (std::size_t i = 0; i < n; ++i) v += (i ? ", " : "") + entry;
    return v + "]";
  };
  EXPECT_EQ(error_of(valid, {"convergence.h=" + list_of(max_list_entries, "0.1")}), "");
  expect_refused("a list of steps one entry too long", valid, {"convergence.h=" + list_of(max_list_entries + 1, "0.1")},
                 {"convergence.h = [0.1, 0.1, 0.1, ... (1001 entries), 0.1, 0.1]",
                  "must be a list of 3 to " + std::to_string(max_list_entries) + " numbers"});
  expect_refused("rows one too many", valid, {"initial=" + list_of(max_list_entries + 1, "[1.0, 2.0]")},
                 {"initial", "1 to " + std::to_string(max_list_entries) + " lists of 2 numbers"});
  Schema choices;
  choices.texts("methods", {"se", "rk4"}, 1);
  EXPECT_NO_THROW(Scene::load(scene_file("methods = [\"se\", \"rk4\"]\n"), {}, choices));
  EXPECT_REFUSAL_OF(SceneError, "three names from two choices",
                    Scene::load(scene_file("methods = [\"se\", \"rk4\", \"se\"]\n"), {}, choices),
                    {"methods", "must be a list of 1 to 2 strings"});
}

// A path or value of any length is shown in a refusal on a line or two: by its start and end.
TEST(Scene, ARefusalShowsALongPathByItsEnds) {
  std::string long_path;
  for (int i = 0; i < 500; ++i) long_path += "abcdefghi/";
  long_path += "x.toml";
  const std::string e = error_of_file(long_path);
  EXPECT_NE(e.find("(5006 characters)"), std::string::npos) << e;
  EXPECT_LT(e.size(), 2 * kShownChars) << e;
  EXPECT_EQ(printable(std::string(kShownChars, 'a')), std::string(kShownChars, 'a'));  // (no longer: as it is)
}

TEST(Scene, RejectsUnparsableValuesAndMissingKeys) {
  expect_refused("a word for a number", valid, {"decay.h=abc"}, {"cannot read 'abc' as a number"});
  expect_refused("--set without a value", valid, {"decay.h"}, {"expected key=value"});
  expect_refused("a scene that is not TOML", "decay = [", {}, {"not valid TOML"});
}

TEST(Scene, KeysAreRequiredOnlyByTheStudiesThatRun) {
  std::string text = valid;
  text.erase(text.find("steps = 20"), 10);
  const auto s = Scene::load(scene_file(text), {}, schema());  // loading needs no key
  EXPECT_NO_THROW(s.require({"convergence", "decay.h"}, "study c", schema()));
  try {
    s.require({"decay"}, "study d", schema());
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("missing key 'decay.steps' (an integer), needed by study d"), std::string::npos)
        << e.what();
  }
}

TEST(Scene, ReadsOutsideTheDeclaredKeysFail) {
  const auto s = Scene::load(scene_file(valid), {}, schema());
  s.restrict_reads({"decay"}, "study d");
  EXPECT_DOUBLE_EQ(s.real("decay.h"), 0.3);
  EXPECT_THROW(s.reals("convergence.h"), std::logic_error);
  s.restrict_reads({});
  EXPECT_EQ(s.reals("convergence.h").size(), 3u);
}

TEST(Scene, AnOverlayChangesOnlyWhatItNames) {
  const fs::path base = scene_file(valid);
  const auto s = Scene::load(scene_file("base = \"" + base.filename().string() + "\"\n[decay]\nh = 0.1\n"), {}, schema());
  EXPECT_DOUBLE_EQ(s.real("decay.h"), 0.1);                 // from the overlay
  EXPECT_EQ(s.integer("decay.steps"), 20);                  // the rest of [decay] from the base
  EXPECT_EQ(s.reals("convergence.h").size(), 3u);           // other sections from the base
  ASSERT_EQ(s.bases().size(), 1u);
  EXPECT_FALSE(s.to_json().contains("base"));
  // A value the base gave names the base file when rejected; one the overlay gave, the overlay.
  try {
    s.reject("decay.steps", "x");
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(base.string()), std::string::npos) << e.what();
  }
}

TEST(Scene, BasesChainAndCyclesAreRefused) {
  const fs::path a = scene_file(valid);
  const fs::path b = scene_file("base = \"" + a.filename().string() + "\"\n[decay]\nsteps = 7\n");
  const auto s = Scene::load(scene_file("base = \"" + b.filename().string() + "\"\n[decay]\nh = 0.2\n"), {}, schema());
  EXPECT_EQ(s.integer("decay.steps"), 7);
  EXPECT_DOUBLE_EQ(s.real("decay.h"), 0.2);
  EXPECT_EQ(s.bases().size(), 2u);
  const fs::path self = scene_dir() / "self.toml";
  std::ofstream(self) << "base = \"" << self.filename().string() << "\"\n";
  EXPECT_REFUSAL_OF(SceneError, "a scene that is its own base", Scene::load(self, {}, schema()), {"already in the chain"});
  expect_refused("a base that does not exist", "base = \"no-such-file.toml\"\n", {}, {"no such file"});
}

TEST(Scene, AnAliasReadsAsItsKey) {
  Schema sc = schema();
  sc.alias("how", "method");
  const auto s = Scene::load(scene_file("how = \"rk4\"\n"), {}, sc);
  EXPECT_EQ(s.text("method"), "rk4");
  EXPECT_EQ(Scene::load(scene_file(valid), {"how=\"rk4\""}, sc).text("method"), "rk4");
}

TEST(Scene, CrossKeyRejectNamesTheKeyAndValue) {
  const auto s = Scene::load(scene_file(valid), {}, schema());
  EXPECT_REFUSAL_OF(SceneError, "a value that another key rules out", s.reject("decay.h", "must be below 0.2"),
                    {"decay.h = 0.3 (in ", "must be below 0.2"});
}

TEST(Scene, AnErrorInAnOlderSpellingNamesIt) {
  Schema aliased;
  aliased.texts("studies", {"a", "b"}, 0, "studies").alias("observables", "studies");
  const auto error = [&](const std::string& text, const std::vector<std::string>& overrides) {
    try {
      Scene::load(scene_file(text), overrides, aliased);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("observables = [\"c\"]\n", {}).find("as 'observables', the older name of 'studies'"),
            std::string::npos);
  EXPECT_EQ(error("studies = []\n", {"observables=[\"c\"]"}),
            "studies = [\"c\"] (from --set as 'observables', the older name of 'studies'): must be a list of 0 to 2 strings, "
            "each one of \"a\", \"b\"");
}

}  // namespace scene_test
