#pragma once
// The summary.json and CSV files of an experiment's quick run (the ctest fixture <name>.quick_run).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../hard_case.hpp"

inline std::filesystem::path results_dir(const std::string& experiment) {
  return std::filesystem::path(GEOMINT_TEST_RESULTS) / experiment;
}

// A JSON file of an experiment's quick run, or a member of it, read once.
inline const nlohmann::json& json_of(const std::string& experiment, const std::string& file, const std::string& member = {}) {
  static std::map<std::string, nlohmann::json> cache;
  const std::string key = experiment + "/" + file + "#" + member;
  auto it = cache.find(key);
  if (it == cache.end()) {
    std::ifstream in(results_dir(experiment) / file);
    if (!in) throw std::runtime_error("no " + file + " in " + results_dir(experiment).string() + " (run the quick_run fixture)");
    const nlohmann::json j = nlohmann::json::parse(in);
    it = cache.emplace(key, member.empty() ? j : j.at(member)).first;
  }
  return it->second;
}

inline const nlohmann::json& summary_of(const std::string& experiment) { return json_of(experiment, "summary.json"); }
// The resolved scene of an experiment's quick run (run.json "scene").
inline const nlohmann::json& scene_of(const std::string& experiment) { return json_of(experiment, "run.json", "scene"); }

// A CSV file of a run: its header and its rows, as text (no quoted fields: the runs write none).
struct CsvFile {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;

  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return i;
    throw std::runtime_error("no column " + name);
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> v;
  for (std::size_t a = 0, b; a <= line.size(); a = b + 1) {
    b = line.find(',', a);
    if (b == std::string::npos) b = line.size();
    v.push_back(line.substr(a, b - a));
  }
  return v;
}

inline CsvFile read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  CsvFile csv;
  std::string line;
  std::getline(in, line);
  csv.names = split_csv_line(line);
  while (std::getline(in, line)) csv.rows.push_back(split_csv_line(line));
  return csv;
}

// Whether a row of a timing CSV is a measurement: not a run of fixed work per step whose time is
// interpolated between its method's timed runs (wall_timed 0, analysis/work_precision_set.hpp).
inline bool timed_row(const CsvFile& t, const std::vector<std::string>& row) {
  const auto c = std::find(t.names.begin(), t.names.end(), "wall_timed");
  return c == t.names.end() || row.at(static_cast<std::size_t>(c - t.names.begin())) != "0";
}
inline std::size_t timed_rows(const CsvFile& t) {
  return static_cast<std::size_t>(std::count_if(t.rows.begin(), t.rows.end(), [&](const auto& r) { return timed_row(t, r); }));
}

// The rows of a work-precision CSV whose time is interpolated (wall_timed 0) lie on the line, in the steps,
// through the timed rows of their method's fewest and most steps (WorkPrecisionSet::time), to round-off; those
// two are timed. Returns the count of interpolated rows.
inline std::size_t expect_interpolated_rows_affine(const CsvFile& t) {
  if (std::find(t.names.begin(), t.names.end(), "wall_timed") == t.names.end()) return 0;
  const std::size_t m = t.column("method"), n = t.column("steps"), w = t.column("wall_s");
  std::size_t interpolated = 0;
  for (const auto& row : t.rows) {
    if (timed_row(t, row)) continue;
    ++interpolated;
    const std::vector<std::string>*lo = nullptr, *hi = nullptr;
    for (const auto& r : t.rows)
      if (r[m] == row[m]) {
        if (!lo || std::stod(r[n]) < std::stod((*lo)[n])) lo = &r;
        if (!hi || std::stod(r[n]) > std::stod((*hi)[n])) hi = &r;
      }
    EXPECT_TRUE(timed_row(t, *lo) && timed_row(t, *hi)) << row[m];
    const double x = (std::stod(row[n]) - std::stod((*lo)[n])) / (std::stod((*hi)[n]) - std::stod((*lo)[n]));
    const double expect = std::stod((*lo)[w]) + x * (std::stod((*hi)[w]) - std::stod((*lo)[w]));
    EXPECT_NEAR(std::stod(row[w]) / expect, 1, 1e-12) << row[m] << " at " << row[n] << " steps";
  }
  return interpolated;
}

// The largest value of the wall_spread column of a timing CSV over its timed rows, interquartile range /
// median of each timed measurement (runner/timing.hpp); each one must be finite and >= 0.
inline double largest_spread(const CsvFile& t) {
  const std::size_t c = t.column("wall_spread");
  double largest = 0;
  for (const auto& row : t.rows) {
    const double s = std::stod(row[c]);
    if (!(std::isfinite(s) && s >= 0)) throw std::runtime_error("wall_spread " + row[c] + " is not finite and >= 0");
    if (timed_row(t, row)) largest = std::max(largest, s);
  }
  return largest;
}

// A work-precision set's CSV (cost_<set>.csv, analysis/work_precision_set.hpp) without its wall-time
// columns (wall_s, wall_q1_s, wall_q3_s, wall_spread), which differ from run to run: the cells to compare.
inline CsvFile without_wall_times(const CsvFile& t) {
  const auto wall = [](const std::string& c) { return c.starts_with("wall_"); };
  CsvFile out;
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < t.names.size(); ++i)
    if (!wall(t.names[i])) keep.push_back(i), out.names.push_back(t.names[i]);
  for (const auto& row : t.rows) {
    out.rows.emplace_back();
    for (std::size_t i : keep) out.rows.back().push_back(i < row.size() ? row[i] : std::string());
  }
  return out;
}

// ---- Running an experiment's binary (the command-line tests) ----

inline std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct BinaryOutcome {
  int code;  // the exit code; -1 if the process did not exit normally
  std::string out, err;
};

// Runs GEOMINT_BIN_DIR/<experiment> with `args` (shell words): its exit code, stdout and stderr.
inline BinaryOutcome run_binary(const std::string& experiment, const std::string& args) {
  namespace fs = std::filesystem;
  const fs::path work = fs::path(GEOMINT_TEST_RESULTS) / (experiment + "-cli-" + std::to_string(::getpid()));
  fs::create_directories(work);
  const fs::path out = work / "stdout.txt", err = work / "stderr.txt";
  const int status = std::system((std::string(GEOMINT_BIN_DIR) + "/" + experiment + " " + args + " >" + out.string() +
                                  " 2>" + err.string()).c_str());
  BinaryOutcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, file_text(out), file_text(err)};
  fs::remove_all(work);
  return r;
}

// The quick scene with `args` (e.g. "--set 'key=value'") ends with exit `code`: for 2 (refused before
// any work) exactly one line on stderr, otherwise (a numerical failure after some work) its last
// line, holding every needle; --out neither created nor DIR.partial left.
inline void expect_exit(const std::string& experiment, int code, const std::string& args,
                        const std::vector<std::string>& needles) {
  namespace fs = std::filesystem;
  const fs::path out = fs::path(GEOMINT_TEST_RESULTS) / (experiment + "-refused-" + std::to_string(::getpid()));
  fs::remove_all(out), fs::remove_all(out.string() + ".partial");
  const BinaryOutcome r = run_binary(experiment, "--quick --out " + out.string() + " " + args);
  EXPECT_RUN_REFUSED(experiment + " " + args, r.code, r.err, code, needles);
  if (code == 2) EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
  EXPECT_FALSE(fs::exists(out.string() + ".partial")) << args;
}

// --plan (with `args`, e.g. a --scene; default the paper scene): exit 0, a line per study with a step
// count in (0, 2^53], and --out not created (nothing runs).
inline void expect_plan(const std::string& experiment, const std::vector<std::string>& studies,
                        const std::string& args = {}) {
  namespace fs = std::filesystem;
  const fs::path never = fs::path(GEOMINT_TEST_RESULTS) / (experiment + "-plan-never-written");
  const BinaryOutcome r = run_binary(experiment, "--plan " + args + " --out " + never.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const auto& st : studies) {
    std::istringstream lines(r.out);
    std::string line;
    bool found = false;
    while (std::getline(lines, line)) {
      std::istringstream words(line);
      std::string name, steps;
      if (!(words >> name >> steps) || name != st) continue;
      found = true;
      char* end = nullptr;
      const double n = std::strtod(steps.c_str(), &end);
      EXPECT_TRUE(end != steps.c_str() && *end == '\0' && std::isfinite(n) && n > 0 && n <= 9007199254740992.0)
          << st << ": " << line;
    }
    EXPECT_TRUE(found) << "no plan line for " << st << " in:\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(never));
}

// Checkpoints (runner/checkpoint.hpp): `experiment` with `args` (a scene, a study, small --set values) stopped
// after one round (checkpoint.stop_after = 1: exit 3, the results directory DIR as it was, a *.checkpoint.json in
// DIR.partial), resumed with --threads `resume_threads`, gives the CSV files and summary.json (its timing aside)
// of a run straight through on 2 threads; DIR then holds no checkpoint and DIR.partial is gone.
inline void expect_resume_identical(const std::string& experiment, const std::string& args, int resume_threads,
                                    const std::string& tag) {
  namespace fs = std::filesystem;
  const auto read = file_text;
  const auto run = [&](const std::string& more, const fs::path& out) {
    const int status = std::system((std::string(GEOMINT_BIN_DIR) + "/" + experiment + " " + args + " " + more +
                                    " --out " + out.string() + " >/dev/null 2>" + out.string() + ".stderr").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  const fs::path a = results_dir(experiment + "-resume-" + tag), b = results_dir(experiment + "-straight-" + tag);
  const fs::path partial = a.string() + ".partial";
  fs::remove_all(a), fs::remove_all(partial), fs::remove_all(b);
  fs::create_directories(a);  // an earlier result, which a stopped run leaves as it was
  std::ofstream(a / "run.json") << "{\"experiment\": \"" << experiment << "\"}\n";
  ASSERT_EQ(run("--threads 2 --set checkpoint.stop_after=1", a), 3) << read(a.string() + ".stderr");
  const std::string stopped = read(a.string() + ".stderr");
  const auto command = stopped.find("continue with: ");
  ASSERT_NE(command, std::string::npos) << stopped;
  EXPECT_NE(stopped.find("--resume", command), std::string::npos) << stopped;
  EXPECT_EQ(stopped.find("stop_after", command), std::string::npos) << "the resume command stops again: " << stopped;
  EXPECT_EQ(std::distance(fs::directory_iterator(a), fs::directory_iterator{}), 1);
  int checkpoints = 0;
  for (const auto& e : fs::directory_iterator(partial)) checkpoints += e.path().string().ends_with(".checkpoint.json");
  EXPECT_GE(checkpoints, 1);
  ASSERT_EQ(run("--threads " + std::to_string(resume_threads) + " --resume", a), 0) << read(a.string() + ".stderr");
  ASSERT_EQ(run("--threads 2", b), 0) << read(b.string() + ".stderr");
  EXPECT_FALSE(fs::exists(partial));
  for (const auto& e : fs::directory_iterator(b)) {
    const std::string f = e.path().filename().string();
    if (!f.ends_with(".csv") || f.starts_with("timing")) continue;
    if (f.starts_with("cost_")) {  // a work-precision set: every cell but its wall times
      const CsvFile ca = without_wall_times(read_csv(a / f)), cb = without_wall_times(read_csv(e.path()));
      EXPECT_EQ(ca.names, cb.names) << f;
      EXPECT_EQ(ca.rows, cb.rows) << f;
      continue;
    }
    EXPECT_EQ(read(a / f), read(e.path())) << f;
  }
  for (const auto& e : fs::directory_iterator(a)) EXPECT_EQ(e.path().string().find(".checkpoint."), std::string::npos) << e.path();
  auto sa = nlohmann::json::parse(read(a / "summary.json")), sb = nlohmann::json::parse(read(b / "summary.json"));
  sa.erase("timing"), sb.erase("timing");
  sa.erase("cost"), sb.erase("cost");  // (wall times and what follows from them; the sets' other cells: their CSVs)
  EXPECT_EQ(sa, sb);
}
