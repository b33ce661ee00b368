#pragma once
// The common front door of every experiment executable (the interface
// contract of ARCHITECTURE.md section 3): --scene, --quick, --study,
// --list-studies, --out, --threads, --set, --resume, --help; exit 0 on
// success, 2 on bad input (before any work), 1 on a failure during the run,
// 3 when stopped with a checkpoint, 4 on a numerical failure. --out DIR is
// replaced as a whole, only when the run succeeds (io/atomic_file.hpp ResultsDir).
//
// An experiment is a set of studies, one per figure, table or analysis. The
// scene says which run: the studies listed in its top-level `studies`, or, if
// it has none, every study whose section is present; `--study NAME` narrows
// that set. Only the scene keys the running studies declare are required, and
// a study may read only those.
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/core/numerical_failure.hpp"
#include "geomint/io/atomic_file.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {

struct Published;  // an entry of published.toml (runner/published.hpp)

class Context {
 public:
  Context(const Scene& s, OutputDir& o, int n_threads);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  const Scene& scene;
  OutputDir& out;
  int threads;
  bool resume = false;  // --resume: continue from the checkpoint in the output directory, if any
  std::string experiment, study;  // the experiment, and the study that runs
  std::vector<std::string> reads;  // the scene keys the study that runs reads (Study::uses)
  std::string resume_command;     // the command line of the run with --resume (for a stopped run's message)
  // What summary.json reports besides "experiment", "studies" and the wall
  // times: "published", "reproduced", "orders", "timing", ... (runner/results.hpp)
  Value summary = Value::record();

  // (a value that is not finite in a row no flag column marks: NumericalFailure, nothing written)
  void write(const std::string& name, const Csv& csv) {
    if (!csv.unflagged_non_finite().empty())
      throw NumericalFailure(name + ", " + csv.unflagged_non_finite() + ": not finite, in a row no flag column marks");
    out.write(name, csv.str());
  }
  // The entries of the experiment's published.toml, as the runner read and checked them before any
  // study ran (it sets them against the summary after the run: runner/published.hpp). A study reads
  // an entry's printed value (a number: published_value; a record of numbers keyed by a parameter:
  // published_values) and the scene value it was printed for (published_requirement); each throws
  // std::logic_error if there is no such entry or value.
  std::vector<Published> published_entries;
  double published_value(const std::string& key) const;
  Value published_values(const std::string& key) const;
  double published_requirement(const std::string& key, const std::string& scene_key) const;
  // The comparison the runner will make (runner/published.hpp) of the entry whose reproduced value is
  // at `summary_key` of `partial` (the summary, or a study's part of it), for a study's own text;
  // nullopt if there is none or if this scene cannot make it (no difference, no entry at round-off).
  std::optional<Value> comparison(const Value& partial, const std::string& summary_key) const;
  // Progress on stderr: on a terminal every call, otherwise at most one line every 10 s.
  void progress(std::string_view what) const;
  // The same with `done` of `total` units (e.g. "batches"), the rate since the first call for
  // `what`, the time elapsed since then and the time left at that rate (progress_line).
  void progress(std::string_view what, double done, double total, std::string_view unit) const;

 private:
  mutable std::string progress_what_;
  mutable double progress_start_ = 0, progress_done_start_ = 0, progress_done_ = 0;
  mutable double last_line_ = -1e9;  // seconds since the run began
};

// A progress line: "  what: done / total unit", and while not done, with the rate since `elapsed` seconds
// ago, when `done_then` were done, "R unit/s, E elapsed, L left".
std::string progress_line(std::string_view what, double done, double total, std::string_view unit, double done_then,
                          double elapsed);

// SIGINT and SIGTERM. While a StopPoint exists, the first signal only sets stop_requested(): the
// study stops at its next checkpoint (Interrupted, exit 3); a second one ends the process. With no
// StopPoint, a signal ends the process at once (the results directory stays as it was: the run
// writes into its staging directory). SIGUSR1 (which mpirun passes on to every rank, and a batch
// job's time-limit warning: scripts/slurm_job.sh) only ever sets stop_requested(): the run stops at
// the next checkpoint, or finishes if none comes. Either way a line on stderr says what happens. Once
// the run has written run.json and only moves its complete results into DIR, a signal is ignored (exit 0).
bool stop_requested();
struct StopPoint {
  StopPoint();
  ~StopPoint();
  StopPoint(const StopPoint&) = delete;
  StopPoint& operator=(const StopPoint&) = delete;
};

// Thrown by an experiment that stops early on purpose, leaving a checkpoint
// for --resume; the run exits with code 3.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// NumericalFailure (core/numerical_failure.hpp), thrown by a study or what it calls (Newton's
// IntegrationError, an order fit, an odeint reference): what() names the method, step and time
// where it can; the runner adds the study. The run exits with code 4 and writes no results.

// What a study would cost (--plan), derived from the scene before any work: its counts are also
// checked then (a count beyond 2^53, or memory beyond what the machine has, is refused: exit 2).
// The plan's fixed cost of a study, besides its steps: its threads started, its CSVs and checkpoint written
// and synced to disk (measured: energy_map's quick map, 4.6 ms of steps, takes 15-22 ms).
inline constexpr double kStudyOverheadS = 0.01;

struct TimedCall;  // (runner/timing.hpp)
struct StudyPlan {
  double steps = 0;         // integration steps, all trajectories and runs together
  double force_evals = 0;   // force (gradient) evaluations
  double memory_bytes = 0;  // the largest memory the study holds at once
  double ns_per_step = 0;   // estimated time per step and thread (0: no estimate)
  std::string note = {};    // what the estimate rests on
  double tasks = 0;         // independent tasks of about equal cost, split across MPI ranks and threads
                            // (distributed_map, checkpointed_map); 0: the study runs alike on every rank
  // The wall time and the steps of the runs it times under the timing protocol (runner/timing.hpp,
  // timing_plan), one after another on one thread; their steps are not in `steps`.
  double timed_seconds = 0, timed_steps = 0;
  // The part of those runs that the study skips when the study `reuses` runs in the same process (it then
  // takes that study's measurement instead; plan_json leaves the part out).
  std::string reuses = {};
  double reused_seconds = 0, reused_steps = 0;
  // A study that takes the results of the study `reuses` when that one runs in the same process, and computes
  // them itself otherwise: its whole plan in the first case, which plan_json takes instead of this one (null:
  // the two differ only by the timed part above).
  std::shared_ptr<const StudyPlan> when_reusing = {};
  // The timing protocol over `calls` at the scene's timing.repeats (timing_plan, runner/timing.hpp): sets
  // timed_seconds and timed_steps.
  void time(const Scene& s, const std::vector<TimedCall>& calls);
};

// A figure, table or statement of a paper (paper/papers.toml): `paper` its number ("000"), `item` as the
// paper names it ("Fig. 9", "Table 1", "Sec. 5.2", "energy error"); "<paper> <item>" (id()) is its one
// spelling in published.toml, summary.json "figures", run.json and the report.
struct Item {
  std::string paper, item;
  std::string id() const { return paper + " " + item; }
  bool operator==(const Item&) const = default;
};

// A study: one figure, table or analysis, declared in one expression (designated initialisers). What it
// reads is `keys` (the keys only it reads, declared there once: type, range, meaning) and `reads` (the
// other keys or sections it reads: the experiment's shared keys, ExperimentSpec::schema, and the
// runner's, common_keys()); every key under them is required when it runs, and it may read no other.
struct Study {
  std::string name;                // as in scenes, --study and summary.json
  std::vector<Item> makes = {};    // the papers' items it makes (none: an analysis beyond them)
  std::string about = {};          // what it makes or computes, in words (--list-studies, --plan)
  std::vector<std::string> files = {};  // the CSV files it writes ('*' stands for a scene-dependent part)
  Schema keys = {};                     // the scene keys only this study reads
  std::vector<std::string> reads = {};  // the shared keys or sections it reads besides
  std::function<void(Context&)> run = {};
  std::function<void(const Scene&)> validate = {};   // checks across keys; calls scene.reject(...)
  std::function<StudyPlan(const Scene&)> plan = {};  // --plan and the count checks (none: not estimated)
  std::vector<std::string> aliases = {};  // former names, still accepted (with a note on stderr) for one release
  // Where the items it makes depend on the scene (003: Fig 5.3 is the harmonic scene's energies, Figs 5.5
  // and 5.6 the free particle's): those of `makes` this scene makes.
  std::function<std::vector<Item>(const Scene&)> makes_under = {};

  std::vector<std::string> uses() const;  // the prefixes of every key it reads: those of `keys`, and `reads`
  std::vector<std::string> item_ids() const;  // the ids of `makes`: "000 Fig. 9"
  std::string description() const;       // its items' ids and `about`: "000 Fig. 9: error in H against h"
};

// The scene keys the runner itself declares, once for every experiment, read by the studies that name them
// in Study::reads: "timing.repeats" (runner/timing.hpp), "checkpoint" (.stop_after, .interval:
// runner/checkpoint.hpp), "reference" (.rtol, .atol: the odeint reference solutions).
const Schema& common_keys();

struct ExperimentSpec {
  std::string name;
  std::string description = {};
  Schema schema = {};  // the keys several studies read (each study declares its own: Study::keys)
  std::vector<Study> studies = {};  // in the order they run
};

// `built_from`: the experiment's source directory when the binary was built (its scenes and
// published.toml); a moved build finds them as find_experiment_dir (experiment.cpp) says.
int run_experiment(int argc, char** argv, ExperimentSpec spec, const std::string& built_from);

// An experiment whose studies share no keys needs no main.cpp (README "Adding a figure"): each study file
// registers its study at namespace scope,
//   const RegisteredStudy registered{order_study};   // Study order_study() { return {.name = "order", ...}; }
// and the executable CMake generates for a directory without main.cpp (cmake/geomint_experiment.cmake) runs
// them, in the order of their names, as the experiment `name`, described by its studies' items.
struct RegisteredStudy {
  explicit RegisteredStudy(Study (*make)());
};
int run_registered_experiment(int argc, char** argv, const std::string& name, const std::string& built_from);

// Does a file name match a Study::files pattern ('*' matches any run of characters)?
bool file_matches(std::string_view pattern, std::string_view name);

}  // namespace geomint
