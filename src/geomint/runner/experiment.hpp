#pragma once
// The common front door of every experiment executable (the interface
// contract of ARCHITECTURE.md section 3): --scene, --quick, --study,
// --list-studies, --out, --threads, --set, --resume, --help; exit 0 on
// success, 2 on bad input (before any work), 1 on a failure during the run,
// 3 when stopped with a checkpoint.
//
// An experiment is a set of studies, one per figure, table or analysis. The
// scene says which run: the studies listed in its top-level `studies`, or, if
// it has none, every study whose section is present; `--study NAME` narrows
// that set. Only the scene keys the running studies declare are required, and
// a study may read only those.
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/io/atomic_file.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {

class Context {
 public:
  Context(const Scene& s, OutputDir& o, int n_threads) : scene(s), out(o), threads(n_threads) {}
  const Scene& scene;
  OutputDir& out;
  int threads;
  bool resume = false;  // --resume: continue from the checkpoint in the output directory, if any
  // What summary.json reports besides "experiment", "studies" and the wall
  // times: "published", "reproduced", "orders", "timing", ...
  nlohmann::ordered_json summary = nlohmann::ordered_json::object();

  void write(const std::string& name, const Csv& csv) { out.write(name, csv.str()); }
  // A line on stderr when it is a terminal.
  void progress(std::string_view what) const;
};

// Thrown by an experiment that stops early on purpose, leaving a checkpoint
// for --resume; the run exits with code 3.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Study {
  std::string name;                // as in scenes, --study and summary.json
  std::string makes;               // the figure or table, e.g. "000 Fig 9"
  std::vector<std::string> files;  // the CSV files it writes ('*' stands for a scene-dependent part)
  std::vector<std::string> uses;   // the scene keys or sections it reads (required when it runs)
  std::function<void(const Scene&)> validate;  // checks across keys; calls scene.reject(...)
  std::function<void(Context&)> run;
};

struct ExperimentSpec {
  std::string name;
  std::string description;
  Schema schema;
  std::vector<Study> studies;  // in the order they run
};

int run_experiment(int argc, char** argv, ExperimentSpec spec, const std::string& experiment_dir);

// Does a file name match a Study::files pattern ('*' matches any run of characters)?
bool file_matches(std::string_view pattern, std::string_view name);

}  // namespace geomint
