#pragma once
// The common front door of every experiment executable (the interface
// contract of ARCHITECTURE.md section 3): --scene, --quick, --out, --threads,
// --set, --help; exit 0 on success, 2 on bad input (before any work), 1 on a
// failure during the run.
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

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
  // What summary.json reports besides "experiment" and the total wall time:
  // "published", "reproduced", "orders", "timing", ...
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

struct ExperimentSpec {
  std::string name;
  std::string description;
  Schema schema;
  std::function<void(const Scene&)> validate;  // checks across keys; calls scene.reject(...)
  std::function<void(Context&)> run;
};

int run_experiment(int argc, char** argv, const ExperimentSpec& spec, const std::string& experiment_dir);

}  // namespace geomint
