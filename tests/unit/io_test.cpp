#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../hard_case.hpp"
#include "geomint/io/atomic_file.hpp"
#include "geomint/io/crc32c.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/sweep/parallel_map.hpp"

using namespace geomint;
namespace fs = std::filesystem;

namespace io_test {  // the file's scope (the tests build as one translation unit)

// CRC-32C against its published check value (RFC 3720, B.4: "123456789" -> 0xE3069283) and the
// iSCSI test vectors of 32 zero and 32 0xFF bytes; in pieces as in one.
TEST(Crc32c, MatchesTheCheckValuesOfRfc3720) {
  EXPECT_EQ(crc32c("123456789", 9), 0xE3069283u);
  const std::string zeros(32, '\0'), ones(32, '\xFF');
  EXPECT_EQ(crc32c(zeros.data(), 32), 0x8A9136AAu);
  EXPECT_EQ(crc32c(ones.data(), 32), 0x62A8AB43u);
  EXPECT_EQ(crc32c("6789", 4, crc32c("12345", 5)), 0xE3069283u);
  EXPECT_EQ(crc32c(nullptr, 0), 0u);
}

TEST(Csv, HeaderRowsAndFullPrecision) {
  Csv csv({"name", "h", "n"});
  csv.row("se", 0.1, 10);
  csv.row("rk4", 1.0 / 3.0, std::int64_t{1} << 40);
  EXPECT_EQ(csv.str(), "name,h,n\nse,0.10000000000000001,10\nrk4,0.33333333333333331,1099511627776\n");
  EXPECT_EQ(std::strtod(format_double(1.0 / 3.0).c_str(), nullptr), 1.0 / 3.0);  // reads back bit for bit
  EXPECT_EQ(csv.rows(), 2u);
  EXPECT_EQ(format_double(-std::nan("")), "nan");
}

// format_double is printf's "%.17g" byte for byte (the CSVs of every earlier run stay comparable):
// on random bit patterns (every exponent, subnormals), powers of ten, integers and the specials.
TEST(Csv, NumbersAreWrittenAsPrintfWrites) {
  const auto printf17 = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.1, 1e-5, 1e-4, 1e16, 1e17, 123456789012345678.0,
                                5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int e = -320; e <= 308; ++e) values.push_back(std::pow(10.0, e));
  std::mt19937_64 rng(17);
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isnan(v)) values.push_back(v);
  }
  for (double v : values) ASSERT_EQ(format_double(v), printf17(v)) << std::hexfloat << v;
}

// A value that is not finite is kept only in a row a flag column marks; the first that is not is named.
TEST(Csv, NonFiniteValuesOnlyInFlaggedRows) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Csv flagged({"x", "eps", "diverged"});
  flagged.flags({"diverged"});
  flagged.row(1.0, 0.5, std::int64_t{0});
  flagged.row(2.0, nan, std::int64_t{1});
  flagged.row(3.0, -inf, 1.0);
  EXPECT_EQ(flagged.unflagged_non_finite(), "");
  flagged.row(4.0, inf, std::int64_t{0});
  flagged.row(5.0, nan, std::int64_t{0});
  EXPECT_EQ(flagged.unflagged_non_finite(), "row 4, column eps");  // (the first)
  Csv plain({"t", "ybar"});
  plain.row(0.0, 1.0);
  plain.row(1.0, -inf);
  EXPECT_EQ(plain.unflagged_non_finite(), "row 2, column ybar");
  EXPECT_THROW(plain.flags({"nosuch"}), std::logic_error);
}

TEST(Csv, RejectsRowsOfTheWrongWidth) {
  Csv csv({"a", "b"});
  EXPECT_REFUSAL_OF(std::logic_error, "one cell for two columns", csv.row(1.0), {"fewer cells"});
  Csv csv2({"a"});
  EXPECT_REFUSAL_OF(std::logic_error, "two cells for one column", csv2.row(1.0, 2.0), {"more cells"});
  EXPECT_REFUSAL_OF(std::logic_error, "a cell with a comma", csv2.row("x,y"), {"quoting"});
}

TEST(OutputDir, WritesAtomicallyAndLeavesNoTemporaries) {
  const fs::path dir = fs::temp_directory_path() / ("geomint_io_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  OutputDir out(dir);
  out.write("a.csv", "x\n1\n");
  out.write("a.csv", "x\n2\n");
  std::ifstream in(dir / "a.csv");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "x\n2\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  EXPECT_EQ(out.written(), std::vector<std::string>{"a.csv"});
  fs::remove_all(dir);
}

TEST(OutputDir, RejectsUnwritableDirectories) {
  EXPECT_REFUSAL_OF(OutputError, "--out under /proc/self", OutputDir("/proc/self/geomint-out"),
                    {"/proc/self/geomint-out", "cannot create"});
  const fs::path file = fs::temp_directory_path() / ("geomint_io_file_" + std::to_string(::getpid()));
  std::ofstream(file) << "x";
  EXPECT_REFUSAL_OF(OutputError, "--out under a file", OutputDir(file / "sub"), {"cannot create"});
  fs::remove(file);
  if (::geteuid() != 0) {  // permission bits do not stop root
    const fs::path ro = fs::temp_directory_path() / ("geomint_io_ro_" + std::to_string(::getpid()));
    fs::create_directories(ro);
    ::chmod(ro.c_str(), 0555);
    EXPECT_REFUSAL_OF(OutputError, "--out a read-only directory", OutputDir{ro}, {"not writable"});
    ::chmod(ro.c_str(), 0755);
    fs::remove_all(ro);
  }
}

namespace {

std::string read_text(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch directory, removed with everything in it.
struct Scratch {
  fs::path root = fs::temp_directory_path() / ("geomint_results_test_" + std::to_string(::getpid()));
  Scratch() { fs::remove_all(root), fs::create_directories(root); }
  ~Scratch() { fs::remove_all(root); }
};

// A finished run of `experiment` writing `files` into DIR.
void finished_run(const fs::path& dir, const std::string& experiment, const std::vector<std::string>& files) {
  ResultsDir results(dir, experiment, false);
  OutputDir out(results.staging_path());
  for (const auto& f : files) out.write(f, f + "\n");
  out.write("run.json", "{\"experiment\": \"" + experiment + "\"}\n");
  results.commit(out.written());
}

}  // namespace

TEST(ResultsDir, ReplacesTheDirectoryAsAWholeOnlyOnCommit) {
  Scratch t;
  const fs::path dir = t.root / "res";
  finished_run(dir, "exp", {"old.csv", "both.csv"});
  EXPECT_TRUE(fs::exists(dir / "old.csv"));
  EXPECT_FALSE(fs::exists(t.root / "res.partial"));
  {  // a failed run: DIR is exactly as it was
    ResultsDir failed(dir, "exp", false);
    OutputDir(failed.staging_path()).write("both.csv", "new\n");
    failed.discard();
  }
  EXPECT_EQ(read_text(dir / "both.csv"), "both.csv\n");
  EXPECT_FALSE(fs::exists(t.root / "res.partial"));
  {  // a killed run (neither commit nor discard) leaves DIR as it was, too
    ResultsDir killed(dir, "exp", false);
    OutputDir(killed.staging_path()).write("both.csv", "new\n");
  }
  EXPECT_EQ(read_text(dir / "both.csv"), "both.csv\n");
  finished_run(dir, "exp", {"new.csv", "both.csv"});  // the next run empties the killed one's staging
  EXPECT_FALSE(fs::exists(dir / "old.csv"));  // replaced as a whole, not merged
  EXPECT_TRUE(fs::exists(dir / "new.csv"));
  EXPECT_EQ(read_text(dir / "both.csv"), "both.csv\n");
  EXPECT_FALSE(fs::exists(t.root / "res.partial"));
  EXPECT_FALSE(fs::exists(dir / ".geomint-staging"));
}

TEST(ResultsDir, RefusesToReplaceWhatIsNotAResultsDirectoryOfTheExperiment) {
  Scratch t;
  const fs::path home = t.root / "home";
  fs::create_directories(home);
  std::ofstream(home / "precious.txt") << "x";
  EXPECT_REFUSAL_OF(OutputError, "--out a directory of a user's files", ResultsDir(home, "exp", false),
                    {"not a results directory"});
  EXPECT_REFUSAL_OF(OutputError, "the same with a trailing slash", ResultsDir(t.root / "home/", "exp", false),
                    {"not a results directory"});
  EXPECT_TRUE(fs::exists(home / "precious.txt"));
  EXPECT_FALSE(fs::exists(t.root / "home.partial"));
  finished_run(t.root / "other", "other_exp", {"a.csv"});
  EXPECT_REFUSAL_OF(OutputError, "--out another experiment's results", ResultsDir(t.root / "other", "exp", false),
                    {"not a results directory of exp"});
  EXPECT_REFUSAL_OF(OutputError, "--out /", ResultsDir("/", "exp", false), {"root directory"});
  fs::create_directories(t.root / "empty");
  EXPECT_NO_THROW(ResultsDir(t.root / "empty", "exp", false).discard());  // an empty directory may be replaced
  fs::create_directories(t.root / "x.partial");  // a staging name holding a user's files
  std::ofstream(t.root / "x.partial" / "notes.txt") << "x";
  EXPECT_REFUSAL_OF(OutputError, "a staging directory x.partial holding a user's file", ResultsDir(t.root / "x", "exp", false),
                    {"x.partial"});
}

TEST(ResultsDir, ResumeKeepsTheInterruptedRunAndDropsItsTemporaries) {
  Scratch t;
  const fs::path dir = t.root / "res";
  {
    ResultsDir stopped(dir, "exp", false);
    OutputDir(stopped.staging_path()).write("checkpoint.json", "{}\n");
    std::ofstream(stopped.staging_path() / ".checkpoint.json.tmp-12345") << "half";  // a killed writer's temporary
  }
  {
    const ResultsDir resumed(dir, "exp", true);
    EXPECT_TRUE(resumed.resumed());
    EXPECT_TRUE(fs::exists(resumed.staging_path() / "checkpoint.json"));
    EXPECT_FALSE(fs::exists(resumed.staging_path() / ".checkpoint.json.tmp-12345"));
    // (while it holds DIR, no second ResultsDir on it: runner's one run per results directory)
    EXPECT_REFUSAL_OF(OutputError, "a second run on a results directory in use", ResultsDir(dir, "exp", false),
                      {"another run (process", "res.lock"});
  }
  ResultsDir fresh(dir, "exp", false);  // without --resume the interrupted run is dropped
  EXPECT_FALSE(fresh.resumed());
  EXPECT_FALSE(fs::exists(fresh.staging_path() / "checkpoint.json"));
  EXPECT_FALSE(ResultsDir(t.root / "new", "exp", true).resumed());  // nothing to resume
}

// A run killed before its staging directory got its marker leaves only a temporary there: the next run, with
// --resume or without, empties it and runs (it was refused, and every later run with it, until a person
// deleted it); a staging directory with a user's file beside the temporary is still refused.
TEST(ResultsDir, AStagingDirectoryOfATemporaryAloneIsNoObstacle) {
  Scratch t;
  for (const bool resume : {false, true}) {
    const fs::path dir = t.root / (resume ? "resumed" : "fresh");
    fs::create_directories(t.root / (dir.filename().string() + ".partial"));
    std::ofstream(t.root / (dir.filename().string() + ".partial") / "..geomint-staging.tmp-4242") << "exp";
    ResultsDir run(dir, "exp", resume);
    EXPECT_FALSE(run.resumed());
    run.discard();
  }
  fs::create_directories(t.root / "y.partial");
  std::ofstream(t.root / "y.partial" / "..geomint-staging.tmp-4242") << "exp";
  std::ofstream(t.root / "y.partial" / "notes.txt") << "x";
  EXPECT_REFUSAL_OF(OutputError, "a staging directory holding a user's file beside a temporary",
                    ResultsDir(t.root / "y", "exp", false), {"y.partial"});
}

// A results directory is never nested in another: --out inside one is refused (a run of its experiment would
// replace it, and the nested one with it), and so is --out on one that holds another.
TEST(ResultsDir, ResultsDirectoriesAreNeverNested) {
  Scratch t;
  finished_run(t.root / "outer", "ti_drift", {"a.csv"});
  EXPECT_REFUSAL_OF(OutputError, "--out inside a complete result", ResultsDir(t.root / "outer" / "inner", "energy_map", false),
                    {"inside the results directory", "outer"});
  EXPECT_REFUSAL_OF(OutputError, "--out two levels inside", ResultsDir(t.root / "outer" / "a" / "b", "energy_map", false),
                    {"inside the results directory"});
  finished_run(t.root / "other", "energy_map", {"b.csv"});
  fs::rename(t.root / "other", t.root / "outer" / "moved");  // (one moved in by hand)
  EXPECT_REFUSAL_OF(OutputError, "--out on a result that holds another", ResultsDir(t.root / "outer", "ti_drift", false),
                    {"holds the results directory", "moved"});
  EXPECT_TRUE(fs::exists(t.root / "outer" / "moved" / "b.csv"));
  finished_run(t.root / "plain2", "exp", {"c.csv"});
  fs::create_directories(t.root / "plain2" / "figures");
  EXPECT_NO_THROW(finished_run(t.root / "plain2", "exp", {"c.csv"}));
}

// A resumed run reruns its studies: what the interrupted run wrote and this one did not (a study it
// does not run, perhaps of other scene values) must not reach DIR beside this run's run.json.
TEST(ResultsDir, CommitKeepsExactlyTheFilesOfThisRun) {
  Scratch t;
  const fs::path dir = t.root / "res";
  {
    ResultsDir stopped(dir, "exp", false);
    OutputDir out(stopped.staging_path());
    out.write("table1.csv", "of the stopped run\n"), out.write("long.checkpoint.json", "{}\n");
    fs::create_directories(stopped.staging_path() / "sub");
    std::ofstream(stopped.staging_path() / ".long.checkpoint.json.tmp-12345") << "half";
  }
  ResultsDir resumed(dir, "exp", true);
  ASSERT_TRUE(resumed.resumed());
  OutputDir out(resumed.staging_path());
  out.write("long.csv", "long\n"), out.write("run.json", "{\"experiment\": \"exp\"}\n");
  resumed.commit(out.written());
  std::vector<std::string> in_dir;
  for (const auto& e : fs::directory_iterator(dir)) in_dir.push_back(e.path().filename().string());
  std::sort(in_dir.begin(), in_dir.end());
  EXPECT_EQ(in_dir, (std::vector<std::string>{"long.csv", "run.json"}));
  EXPECT_FALSE(fs::exists(t.root / "res.partial"));
}

TEST(ParallelMap, ResultsByIndexAndLowestIndexErrorWins) {
  const auto v = parallel_map(100, [](std::size_t i) { return static_cast<double>(i) * 0.5; });
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], 0.5 * static_cast<double>(i));
  try {
    parallel_map(50, [](std::size_t i) -> int {
      if (i % 7 == 3) throw std::runtime_error("bad " + std::to_string(i));
      return 0;
    });
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "bad 3");
  }
}

}  // namespace io_test
