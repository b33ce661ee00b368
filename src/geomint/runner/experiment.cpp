#include "geomint/runner/experiment.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <filesystem>
#include <fstream>
#include <limits>
#include <iostream>
#include <optional>

#include <CLI/CLI.hpp>

#include "geomint/integrators/newton.hpp"
#include "geomint/io/run_info.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/published.hpp"
#include "geomint/runner/results_json.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/sweep/lanes_cap.hpp"
#include "geomint/sweep/mpi.hpp"

namespace geomint {

namespace {

double seconds_since_start() {
  static const auto t0 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "1 h 02 min", "3 min 05 s", "12 s".
std::string duration_text(double s) {
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%d h %02d min", int(s / 3600), int(std::fmod(s, 3600) / 60));
  else if (s >= 60) std::snprintf(buf, sizeof buf, "%d min %02d s", int(s / 60), int(std::fmod(s, 60)));
  else std::snprintf(buf, sizeof buf, "%.0f s", s);
  return buf;
}

std::string fmt_count(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, n < 1e6 ? "%.0f" : "%.3g", n);
  return buf;
}

std::string fmt_bytes(double b) {
  char buf[32];
  const char* unit[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (b >= 1024 && u < 4) b /= 1024, ++u;
  std::snprintf(buf, sizeof buf, "%.3g %s", b, unit[u]);
  return buf;
}

std::string fmt_seconds(double s) { return s < 1 ? fmt_count(s * 1e3) + " ms" : duration_text(s); }

// MemAvailable of /proc/meminfo in bytes (0 if unknown).
double available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kib = 0;
  while (in >> key) {
    if (key == "MemAvailable:" && in >> kib) return kib * 1024;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0;
}

}  // namespace

Context::Context(const Scene& s, OutputDir& o, int n_threads) : scene(s), out(o), threads(n_threads) {}
Context::~Context() = default;

namespace {
const Published& entry_named(const Context& ctx, const std::string& key) {
  for (const Published& e : ctx.published_entries)
    if (e.key == key) return e;
  throw std::logic_error("published.toml of " + ctx.experiment + " has no entry " + key);
}
}  // namespace

void StudyPlan::time(const Scene& s, const std::vector<TimedCall>& calls) {
  const TimedPlan timed = timing_plan(calls, static_cast<double>(s.integer("timing.repeats")));
  timed_seconds = timed.seconds, timed_steps = timed.steps;
}

double Context::published_value(const std::string& key) const {
  const Published& e = entry_named(*this, key);
  if (!e.value.is_number()) throw std::logic_error("published.toml of " + experiment + ": " + key + " is not a number");
  return e.value.get<double>();
}

Value Context::published_values(const std::string& key) const { return value_of(entry_named(*this, key).value); }

double Context::published_requirement(const std::string& key, const std::string& scene_key) const {
  const Published& e = entry_named(*this, key);
  if (!e.requires_.contains(scene_key) || !e.requires_.at(scene_key).is_number())
    throw std::logic_error("published.toml of " + experiment + ": " + key + " requires no number " + scene_key);
  return e.requires_.at(scene_key).get<double>();
}

std::optional<Value> Context::comparison(const Value& partial, const std::string& summary_key) const {
  const nlohmann::ordered_json j = to_json(partial);
  for (const Published& e : published_entries) {
    if (e.summary != summary_key) continue;
    auto c = compare_published(e, j, scene.to_json(), {e.study});
    if (c && (c->contains("difference") || c->contains("roundoff"))) return value_of(*c);  // (judged, or round-off)
  }
  return std::nullopt;
}

void Context::progress(std::string_view what) const {
  const double now = seconds_since_start();
  if (!::isatty(STDERR_FILENO) && now - last_line_ < 10) return;
  last_line_ = now;
  std::cerr << "  " << what << std::endl;
}

std::string progress_line(std::string_view what, double done, double total, std::string_view unit, double done_then,
                          double elapsed) {
  std::string line = "  " + std::string(what) + ": " + std::to_string(static_cast<long long>(done)) + " / " +
                     std::to_string(static_cast<long long>(total)) + " " + std::string(unit);
  const double rate = elapsed > 0 ? (done - done_then) / elapsed : 0;
  if (rate > 0 && done < total) {
    char buf[64];
    std::snprintf(buf, sizeof buf, ", %.3g %.*s/s, ", rate, static_cast<int>(unit.size()), unit.data());
    line += buf + duration_text(elapsed) + " elapsed, " + duration_text((total - done) / rate) + " left";
  }
  return line;
}

void Context::progress(std::string_view what, double done, double total, std::string_view unit) const {
  const double now = seconds_since_start();
  if (what != progress_what_ || done < progress_done_)
    progress_what_ = what, progress_start_ = now, progress_done_start_ = done;
  progress_done_ = done;
  const bool tty = ::isatty(STDERR_FILENO);
  if (done < total && now - last_line_ < (tty ? 0.1 : 10)) return;
  last_line_ = now;
  const std::string line = progress_line(what, done, total, unit, progress_done_start_, now - progress_start_);
  if (tty) std::cerr << '\r' << line << "\033[K" << (done >= total ? "\n" : "") << std::flush;
  else std::cerr << line << std::endl;
}

namespace {

volatile std::sig_atomic_t g_stop = 0;
volatile std::sig_atomic_t g_finishing = 0;  // the results are complete and being moved into DIR: no stop now
std::atomic<int> g_stop_points{0};
char g_stop_message[512], g_exit_message[512];  // composed before any signal can arrive
char g_lock_file[4200];                          // DIR.lock (atomic_file.hpp), removed by a stop at once

extern "C" void on_signal(int sig) {
  if (g_finishing) return;  // (the run ends with 0 in a moment; exit 3 would tell of a DIR left unchanged)
  if (sig == SIGUSR1 || (g_stop_points.load() > 0 && !g_stop)) {
    g_stop = 1;
    [[maybe_unused]] auto n = ::write(STDERR_FILENO, g_stop_message, std::strlen(g_stop_message));
    return;
  }
  // No checkpoint to stop at (or a second signal): stop at once, DIR untouched, with the exit code of a
  // stopped run (3: --resume runs the studies again from DIR.partial).
  [[maybe_unused]] auto n = ::write(STDERR_FILENO, g_exit_message, std::strlen(g_exit_message));
  if (g_lock_file[0] != '\0') ::unlink(g_lock_file);  // (held by this process: no other run has it)
  ::_exit(3);
}

void set_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGUSR1, &sa, nullptr);
  // A file over the size limit (ulimit -f) fails its write with EFBIG, which the writer reports (OutputError),
  // instead of SIGXFSZ killing the run with no message.
  std::signal(SIGXFSZ, SIG_IGN);
}

// From the start of the process: a signal before the results directory is prepared stops at once with the
// exit code of a stopped run (3), nothing written (its default action would end the run with 128 + the signal).
void install_early_signal_handlers(const std::string& name) {
  std::snprintf(g_exit_message, sizeof g_exit_message, "\n%s: interrupted before the run began: nothing written\n",
                name.c_str());
  if (!mpi::is_root()) g_exit_message[0] = '\0';
  set_handlers();
}

void install_signal_handlers(const std::string& name, const ResultsDir& results) {
  std::snprintf(g_stop_message, sizeof g_stop_message,
                "\n%s: interrupted: stopping at the next checkpoint (continue with --resume; a second "
                "signal stops at once)\n", name.c_str());
  std::snprintf(g_exit_message, sizeof g_exit_message,
                "\n%s: interrupted: stopped; %s is unchanged (--resume with the same arguments runs the studies again)\n",
                name.c_str(), results.final_path().c_str());
  std::snprintf(g_lock_file, sizeof g_lock_file, "%s.lock", results.final_path().c_str());
  if (!mpi::is_root()) g_stop_message[0] = g_exit_message[0] = '\0';  // (rank 0 speaks for the job)
  if (!mpi::is_root()) g_lock_file[0] = '\0';                           // (and holds DIR's lock)
  set_handlers();
}

}  // namespace

bool stop_requested() { return g_stop != 0; }
StopPoint::StopPoint() { ++g_stop_points; }
StopPoint::~StopPoint() { --g_stop_points; }

bool file_matches(std::string_view pattern, std::string_view name) {
  const auto star = pattern.find('*');
  if (star == std::string_view::npos) return pattern == name;
  const auto head = pattern.substr(0, star), tail = pattern.substr(star + 1);
  return name.size() >= head.size() + tail.size() && name.starts_with(head) && name.ends_with(tail);
}

namespace {

// The dotted key of the first number in `j` that is not finite, if any.
std::optional<std::string> first_non_finite(const nlohmann::ordered_json& j, const std::string& at = "") {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return at.empty() ? std::string("(root)") : at;
  if (j.is_object())
    for (const auto& [k, v] : j.items())
      if (auto bad = first_non_finite(v, at.empty() ? k : at + "." + k)) return bad;
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      if (auto bad = first_non_finite(j[i], at + "." + std::to_string(i))) return bad;
  return std::nullopt;
}

constexpr const char* kStudiesKey = "studies";

// DIR/figure_values.gp: the numbers of the resolved scene and of summary.json (timings aside), and
// the scene's texts, for the figure scripts (figures/common.gp: scene_num, summary_num). Gnuplot
// has no maps and truncates long names, so they are two arrays, FV_KEY (the dotted key, prefixed
// "scene." or "summary."; array elements by index from 0) and FV_VAL; integers are written with
// ".0" (gnuplot would divide them as integers). A list of texts is also one text under its own key,
// its words separated by spaces (scene_words, summary_words); of the summary's texts, those under a key
// "labels" (a figure's names of a study's curves, e.g. work_precision.labels.polar). And the papers' items
// each study that ran made under the scene, "made.<study>" (made_by: a figure's title names its item as the
// study does), and each item by its script's spelling, "item.fig52" (made_item).
using Entry = std::pair<std::string, std::string>;  // (key, gnuplot literal)

std::string gnuplot_quoted(const std::string& s) {  // '...' with '' for ' and no newlines
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : c == '\n' ? std::string(" ") : std::string(1, c);
  return q + "'";
}

void collect_values(const nlohmann::ordered_json& j, const std::string& key, bool texts, std::vector<Entry>& out) {
  if (j.is_array() && !j.empty() && std::all_of(j.begin(), j.end(), [](const auto& e) { return e.is_string(); })) {
    std::string words;  // a list of names (e.g. methods) also as one text, space-separated, for `for [m in ...]`
    for (const auto& e : j) words += (words.empty() ? "" : " ") + e.get<std::string>();
    out.emplace_back(key, gnuplot_quoted(words));
  }
  if (j.is_object() || j.is_array()) {
    std::size_t i = 0;
    for (const auto& [k, v] : j.items())
      collect_values(v, key + "." + (j.is_array() ? std::to_string(i++) : k), texts || k == "labels", out);
  } else if (j.is_number() && std::isfinite(j.get<double>())) {
    std::string v = format_double(j.get<double>());
    if (v.find_first_of(".e") == std::string::npos) v += ".0";
    out.emplace_back(key, v);
  } else if (j.is_string() && texts) {
    out.emplace_back(key, gnuplot_quoted(j.get<std::string>()));
  }
}

// The numbers of a subtree dropped (nulls, which collect_values skips), its texts kept.
void drop_numbers(nlohmann::ordered_json& j) {
  if (j.is_number()) j = nullptr;
  if (j.is_object() || j.is_array())
    for (auto& v : j) drop_numbers(v);
}

std::string figure_values(const nlohmann::ordered_json& scene, nlohmann::ordered_json summary,
                          const std::vector<Entry>& made) {
  // (wall times differ from run to run; this file does not): the run's timing, and the numbers of the
  // cost studies' work-precision sets (analysis/work_precision_set.hpp), whose method lists the figures read
  summary.erase("timing");
  if (summary.contains("cost")) drop_numbers(summary["cost"]);
  std::vector<Entry> values;
  collect_values(scene, "scene", true, values);
  collect_values(summary, "summary", false, values);
  values.insert(values.end(), made.begin(), made.end());
  std::set<std::string> seen;
  for (const auto& [k, v] : values)
    if (!seen.insert(k).second) throw std::logic_error("figure_values.gp: the key " + k + " twice");
  std::string out =
      "# The numbers of this run for its figures (figures/common.gp: scene_num, summary_num): the resolved\n"
      "# scene (numbers and texts), the numbers of summary.json without its timings, and the items each study\n"
      "# made (made.<study>: \"000 Fig. 9\", for a figure's title: made_by).\n";
  const std::string n = std::to_string(values.size());
  out += "array FV_KEY[" + n + "]\narray FV_VAL[" + n + "]\n";
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string at = "[" + std::to_string(i + 1) + "] = ";
    out += "FV_KEY" + at + gnuplot_quoted(values[i].first) + "; FV_VAL" + at + values[i].second + "\n";
  }
  return out;
}

std::string join(const std::vector<std::string>& v, const char* sep = ", ") {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

std::vector<std::string> study_names(const ExperimentSpec& spec) {
  std::vector<std::string> names;
  for (const auto& st : spec.studies) names.push_back(st.name);
  return names;
}

// The study called `name`, by its name or a former name (Study::aliases); nullptr if none.
const Study* find_study(const ExperimentSpec& spec, std::string_view name) {
  for (const auto& st : spec.studies)
    if (st.name == name || std::find(st.aliases.begin(), st.aliases.end(), name) != st.aliases.end()) return &st;
  return nullptr;
}

// An item's name as its figure script spells it (figures/<run>_<slug>*.gp; scripts/report.py item_slug):
// "003 Fig. 5.2" -> "fig52", "001 Table 1" -> "table1".
std::string item_slug(const std::string& id) {
  std::string slug;
  for (char c : id.substr(id.find(' ') + 1)) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) slug += static_cast<char>(std::tolower(u));
  }
  return slug;
}

// The ids of the items a study makes under a scene (Study::makes_under): a part of those it declares.
std::vector<std::string> made_here(const Study& st, const Scene& scene) {
  const std::vector<Item> here = st.makes_under ? st.makes_under(scene) : st.makes;
  std::vector<std::string> ids;
  for (const Item& item : here) {
    if (std::find(st.makes.begin(), st.makes.end(), item) == st.makes.end())
      throw std::logic_error("study " + st.name + " makes " + item.id() + " under this scene, not one of its makes");
    ids.push_back(item.id());
  }
  return ids;
}

// The ids of every item a study makes.

// Every name a scene or --study may use: the studies' names and their former names.
std::vector<std::string> accepted_study_names(const ExperimentSpec& spec) {
  std::vector<std::string> names = study_names(spec);
  for (const auto& st : spec.studies) names.insert(names.end(), st.aliases.begin(), st.aliases.end());
  return names;
}

// The current name of a study named in `where` by `name` (known to find_study); a former name gets a note.
std::string current_name(const ExperimentSpec& spec, const std::string& name, const std::string& where) {
  const std::string& now = find_study(spec, name)->name;
  if (now != name)
    std::cerr << spec.name << ": note: " << where << ": study '" << name << "' is now called '" << now
              << "' (the former name is accepted for one release)\n";
  return now;
}

// The studies the scene asks for (its `studies` list, else the studies whose
// section it has), narrowed by --study; in the experiment's order.
std::vector<const Study*> select_studies(const ExperimentSpec& spec, const Scene& scene,
                                         const std::vector<std::string>& on_command_line) {
  const std::string valid = " (the studies of " + spec.name + ": " + join(study_names(spec)) + ")";
  std::vector<std::string> asked;
  if (scene.has(kStudiesKey)) {
    for (const auto& name : scene.texts(kStudiesKey))  // the schema admits only study names (and former names)
      asked.push_back(current_name(spec, name, scene.file().string() + ": studies"));
  } else {
    for (const auto& st : spec.studies)
      if (scene.has(st.name) || std::any_of(st.aliases.begin(), st.aliases.end(), [&](const auto& a) { return scene.has(a); }))
        asked.push_back(st.name);
  }
  std::vector<std::string> named;  // --study, by current names
  for (const auto& given : on_command_line) {
    if (!find_study(spec, given)) throw SceneError("--study " + given + ": no such study" + valid);
    const std::string name = current_name(spec, given, "--study");
    named.push_back(name);
    if (std::find(asked.begin(), asked.end(), name) == asked.end())
      throw SceneError("--study " + name + ": the scene " + scene.file().string() + " does not ask for it (it asks for: " +
                       (asked.empty() ? std::string("none") : join(asked)) + "; add it to the scene's studies list)");
  }
  std::vector<const Study*> out;
  for (const auto& st : spec.studies) {
    const bool in_scene = std::find(asked.begin(), asked.end(), st.name) != asked.end();
    const bool on_line = named.empty() || std::find(named.begin(), named.end(), st.name) != named.end();
    if (in_scene && on_line) out.push_back(&st);
  }
  if (out.empty()) throw SceneError(scene.file().string() + ": the scene asks for no study" + valid);
  return out;
}

// The paper scene, for the defaults --help shows (nullopt if it cannot be read).
std::optional<Scene> paper_scene(const ExperimentSpec& spec, const std::string& dir) {
  try {
    return Scene::load(dir + "/" + spec.name + ".toml", {}, spec.schema);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string studies_help(const ExperimentSpec& spec) {
  std::string s = "\nStudies (a scene runs those in its `studies` list, else those whose section it has;\n"
                  "--study NAME runs only NAME):\n";
  for (const auto& st : spec.studies) s += "  " + st.name + "  " + st.description() + "  [" + join(st.files, " ") + "]\n";
  return s;
}

// Every scene key: its type, what it admits, its default (the paper scene's value; null where the paper
// scene has none), its meaning and the studies that read it (--list-keys --json, and --help).
nlohmann::ordered_json keys_json(const ExperimentSpec& spec, const std::string& dir) {
  const auto paper = paper_scene(spec, dir);
  const auto scene = paper ? paper->to_json() : nlohmann::ordered_json();
  const auto schema_type = [](Schema::Type t) {
    switch (t) {
      case Schema::Type::real: return "real";
      case Schema::Type::integer: return "integer";
      case Schema::Type::reals: return "reals";
      case Schema::Type::real_rows: return "real_rows";
      case Schema::Type::boolean: return "boolean";
      case Schema::Type::text: return "text";
      case Schema::Type::texts: return "texts";
    }
    return "?";
  };
  auto keys = nlohmann::ordered_json::array();
  for (const auto& e : spec.schema.entries()) {
    nlohmann::ordered_json k = {{"key", e.key}, {"type", schema_type(e.type)}, {"type_name", type_name(e.type)},
                                {"allowed", allowed_values(e)}};
    const bool numeric = e.type == Schema::Type::real || e.type == Schema::Type::integer ||
                         e.type == Schema::Type::reals || e.type == Schema::Type::real_rows;
    if (numeric) {
      auto b = nlohmann::ordered_json::object();
      for (const auto& [name, v] : {std::pair{"gt", e.bound.gt}, {"ge", e.bound.ge}, {"lt", e.bound.lt}, {"le", e.bound.le}})
        if (v) b[name] = *v;
      k["bound"] = b;
    }
    if (e.type == Schema::Type::reals || e.type == Schema::Type::texts || e.type == Schema::Type::real_rows)
      k["min_len"] = e.min_len;
    if (e.type == Schema::Type::real_rows) k["row_len"] = e.row_len;
    if (!e.choices.empty()) k["choices"] = e.choices;
    k["default"] = nullptr;
    if (paper && paper->has(e.key)) {
      std::string p = "/" + e.key;
      std::replace(p.begin(), p.end(), '.', '/');
      k["default"] = scene.at(nlohmann::ordered_json::json_pointer(p));
    }
    k["doc"] = e.doc;
    auto users = nlohmann::ordered_json::array();
    for (const auto& st : spec.studies)
      if (e.key != kStudiesKey && key_under(e.key, st.uses())) users.push_back(st.name);
    k["used_by"] = users;
    keys.push_back(k);
  }
  return keys;
}

std::string keys_help(const ExperimentSpec& spec, const std::string& dir) {
  std::string s = "\nScene keys (default: the paper scene " + dir + "/" + spec.name +
                  ".toml; override any with --set key=value; --list-keys --json lists them as JSON):\n";
  for (const auto& k : keys_json(spec, dir)) {
    const std::string allowed = k["allowed"];
    s += "  " + k["key"].get<std::string>() + "  (" + k["type_name"].get<std::string>() +
         (allowed.empty() ? "" : "; " + allowed) + ")  default " + (k["default"].is_null() ? "(none)" : k["default"].dump()) + "\n";
    if (!k["doc"].get<std::string>().empty()) s += "      " + k["doc"].get<std::string>() + "\n";
    if (!k["used_by"].empty()) {
      std::vector<std::string> users = k["used_by"];
      s += "      used by: " + join(users) + "\n";
    }
  }
  for (const auto& [from, to] : spec.schema.aliases()) s += "  " + from + "  older spelling of " + to + "\n";
  s += "\nExit codes: 0 done; 1 internal error; 2 bad input (before any work); 3 stopped with a checkpoint "
       "(--resume continues); 4 numerical failure (a NaN or Inf, Newton's method not converged, a trajectory "
       "outside its chart)\n"
       "Output: the run writes into DIR.partial and replaces --out DIR by it only when it succeeds; a DIR that "
       "is not a results directory of this experiment is never replaced.\n"
       "Scenes and published values: " + dir + " (a moved build looks for experiments/" + spec.name +
       " above its own directory and the working directory; GEOMINT_EXPERIMENTS=DIR reads DIR/" + spec.name + ").\n";
  return s;
}

// The command line of this run with --resume, each argument quoted for the shell where it needs it, less
// a --set checkpoint.stop_after (the resumed run goes on to the end).
std::string resume_command(int argc, char** argv) {
  std::string command;
  bool has_resume = false;
  const auto stop_after = [](std::string_view a) { return a.starts_with("checkpoint.stop_after="); };
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--set" && i + 1 < argc && stop_after(argv[i + 1])) {
      ++i;
      continue;
    }
    if (a.starts_with("--set=") && stop_after(std::string_view(a).substr(6))) continue;
    has_resume = has_resume || a == "--resume";
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                         "_-+=.,/:@%") == std::string::npos;
    std::string quoted = "'";
    for (char c : a) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    command += (i ? " " : "") + (plain ? a : quoted + "'");
  }
  return has_resume ? command : command + " --resume";
}

// The results directory of a rank other than 0 in an MPI job: a scratch directory, removed at the end. What
// ranks of earlier jobs that were killed left there (<name>-rank<N>-<pid>, .partial, .lock, of a process that
// no longer runs) is removed first.
std::filesystem::path rank_scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path tmp = fs::temp_directory_path();
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(tmp, ec)) {
    std::string f = e.path().filename().string();
    if (!f.starts_with(name + "-rank")) continue;
    for (const std::string suffix : {".partial", ".lock"})
      if (f.ends_with(suffix)) f.resize(f.size() - suffix.size());
    const std::string pid = f.substr(f.rfind('-') + 1);
    if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) stale.push_back(e.path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);  // (another rank may remove it first)
  return tmp / (name + "-rank" + std::to_string(mpi::rank()) + "-" + std::to_string(::getpid()));
}

// A study's counts, checked before any work: exactly representable as doubles (steps are
// counted in 64-bit integers and t = n h), and memory the machine has. `read`: the scene keys
// the plan was computed from, named in the refusal.
void check_plan(const Study& st, const StudyPlan& p, const std::vector<std::string>& read) {
  const std::string from = read.empty() ? "" : " (from " + join(read) + ")";
  if (!(p.steps <= max_exact_count) || !(p.force_evals <= max_exact_count))
    throw SceneError("study " + st.name + ": " + fmt_count(p.steps) + " steps (" + fmt_count(p.force_evals) +
                     " force evaluations) exceed 2^53" + from + "; shorten the run or enlarge the step");
  const double available = available_memory_bytes();
  if (available > 0 && p.memory_bytes > available)
    throw SceneError("study " + st.name + " needs about " + fmt_bytes(p.memory_bytes) + " of memory, more than the " +
                     fmt_bytes(available) + " available" + from + "; make the grid, ensemble or record smaller");
}

// The plan as JSON (--plan --json) for `ranks` MPI ranks of `threads` threads: counts null for a
// study without a plan, estimated wall times in seconds, null where there is no estimate. A study of
// n tasks gives each rank ceil(n / ranks) of them (distributed_map's cyclic split), run ceil(share /
// threads) deep on its threads: wall = (steps / n) ns_per_step ceil(share / threads). A study without
// tasks runs on every rank alike: steps ns_per_step / threads. Every rank holds every result: the
// memory is per rank. Timed runs add their own time (StudyPlan::timed_seconds, less the part a study
// skips when the study it reuses runs too), and every study the fixed cost of running at all (kStudyOverheadS).
// A study whose plan has another plan for when the study it reuses runs too (StudyPlan::when_reusing) is
// planned by that one then.
nlohmann::ordered_json plan_json(const std::vector<const Study*>& studies, const std::vector<StudyPlan>& plans, int ranks,
                                 int threads) {
  nlohmann::ordered_json j = {{"ranks", ranks},
                              {"threads", threads},
                              {"study_overhead_s", kStudyOverheadS},
                              {"studies", nlohmann::ordered_json::array()}};
  double total = 0;
  bool all = true;
  for (std::size_t i = 0; i < studies.size(); ++i) {
    StudyPlan p = plans[i];
    if (!p.reuses.empty() &&
        std::any_of(studies.begin(), studies.end(), [&](const Study* other) { return other->name == p.reuses; })) {
      if (p.when_reusing) p = StudyPlan(*p.when_reusing);
      else p.timed_seconds -= p.reused_seconds, p.timed_steps -= p.reused_steps;
    }
    const bool has = static_cast<bool>(studies[i]->plan), estimated = has && p.ns_per_step > 0, split = has && p.tasks > 0;
    const double share = split ? std::ceil(p.tasks / ranks) : 0;
    const double wall = (split ? p.steps / p.tasks * p.ns_per_step * 1e-9 * std::ceil(share / threads)
                               : p.steps * p.ns_per_step * 1e-9 / threads) +
                        p.timed_seconds + kStudyOverheadS;
    total += estimated ? wall : 0, all = all && estimated;
    const auto value = [](bool known, double v) { return known ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
    j["studies"].push_back({{"study", studies[i]->name}, {"makes", studies[i]->description()}, {"steps", value(has, p.steps + p.timed_steps)},
                            {"force_evals", value(has, p.force_evals)}, {"memory_bytes", value(has, p.memory_bytes)},
                            {"tasks", value(split, p.tasks)}, {"tasks_per_rank", value(split, share)},
                            {"wall_s", value(estimated, wall)}, {"note", p.note}});
  }
  j["wall_s"] = total;
  j["all_estimated"] = all;
  return j;
}

// The same plan as a table (--plan).
void print_plan(std::ostream& os, const nlohmann::ordered_json& plan) {
  char line[256];
  const auto row = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d,
                       const std::string& e, const std::string& f) {
    std::snprintf(line, sizeof line, "%-18s %12s %12s %10s %12s %14s", a.c_str(), b.c_str(), c.c_str(), d.c_str(),
                  e.c_str(), f.c_str());
    os << line;
  };
  const auto shown = [](const nlohmann::ordered_json& v, std::string (*fmt)(double), const char* none) {
    return v.is_null() ? std::string(none) : fmt(v.get<double>());
  };
  const int ranks = plan["ranks"].get<int>();
  row("study", "steps", "force evals", "memory", "tasks/rank", "wall time");
  os << "   (estimated, " << (ranks > 1 ? std::to_string(ranks) + " ranks x " : std::string()) << plan["threads"].get<int>()
     << " threads)\n";
  for (const auto& st : plan["studies"]) {
    row(st["study"], shown(st["steps"], fmt_count, "-"), shown(st["force_evals"], fmt_count, "-"),
        shown(st["memory_bytes"], fmt_bytes, "-"), shown(st["tasks_per_rank"], fmt_count, "-"),
        shown(st["wall_s"], fmt_seconds, "no estimate"));
    const std::string note = st["note"];
    os << "   " << st["makes"].get<std::string>() << (note.empty() ? "" : "; " + note) << '\n';
  }
  row("total", "", "", "", "", fmt_seconds(plan["wall_s"].get<double>()));
  os << (plan["all_estimated"].get<bool>() ? "" : "   (studies without an estimate not counted)") << '\n';
}

}  // namespace

// The directory of the experiment's scenes and published.toml: $GEOMINT_EXPERIMENTS/<name> if that
// variable is set; else, for an installed binary (cmake --install), <prefix>/share/geomint/experiments/<name>
// beside its bin directory; else the source directory the binary was built from, if it still exists; else
// experiments/<name> in the nearest ancestor of the binary's directory or of the working directory that
// has one (a build moved with its sources, or run from the repository). The first candidate is returned
// if none exists, so that the error names it.
std::string find_experiment_dir(const std::string& name, const std::string& built_from) {
  namespace fs = std::filesystem;
  const auto has_scene = [&](const fs::path& d) {
    std::error_code ec;
    return fs::is_regular_file(d / (name + ".toml"), ec);
  };
  if (const char* env = std::getenv("GEOMINT_EXPERIMENTS"); env && *env) return (fs::path(env) / name).string();
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (const fs::path installed = exe_dir.parent_path() / "share" / "geomint" / "experiments" / name;
      !exe_dir.empty() && has_scene(installed))
    return installed.string();
  if (has_scene(built_from)) return built_from;
  for (fs::path start : {exe_dir, fs::current_path(ec)})
    for (fs::path d = start; !d.empty(); d = d.parent_path()) {
      if (has_scene(d / "experiments" / name)) return (d / "experiments" / name).string();
      if (d == d.root_path()) break;
    }
  return built_from;
}

std::vector<std::string> Study::uses() const {
  std::vector<std::string> prefixes;
  for (const auto& e : keys.entries()) prefixes.push_back(e.key);
  prefixes.insert(prefixes.end(), reads.begin(), reads.end());
  return prefixes;
}

std::vector<std::string> Study::item_ids() const {
  std::vector<std::string> ids;
  for (const Item& item : makes) ids.push_back(item.id());
  return ids;
}

std::string Study::description() const {
  const std::string items = join(item_ids());
  return items.empty() ? about : about.empty() ? items : items + ": " + about;
}

const Schema& common_keys() {
  static const Schema keys = [] {
    Schema s;
    s.integer("timing.repeats", at_least(1), kTimingRepeatsHelp)
        .integer("checkpoint.stop_after", non_negative(),
                 "stop after this many rounds of tasks, leaving a checkpoint for --resume (0: run to the end)")
        .real("checkpoint.interval", non_negative(),
              "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work")
        .real("reference.rtol", tolerance(), "relative tolerance of the odeint Bulirsch-Stoer reference solutions")
        .real("reference.atol", tolerance(), "absolute tolerance of the odeint Bulirsch-Stoer reference solutions");
    return s;
  }();
  return keys;
}

int run_experiment(int argc, char** argv, ExperimentSpec spec, const std::string& built_from) {
  const mpi::Session mpi_session(argc, argv);  // (one process without mpirun)
  if (!mpi::is_root()) std::cout.rdbuf(nullptr), std::cerr.rdbuf(nullptr);  // rank 0 speaks for the job
  const std::string experiment_dir = find_experiment_dir(spec.name, built_from);
  const auto start = std::chrono::system_clock::now();
  const nlohmann::ordered_json load_before = load_average();  // (timings on a shared machine: its load, run.json)
  const auto t0 = std::chrono::steady_clock::now();
  const std::string name = spec.name;
  install_early_signal_handlers(name);
  for (const Study& st : spec.studies) spec.schema.merge(st.keys);
  for (const Schema::Entry& e : common_keys().entries())  // the runner's keys that a study reads
    if (std::any_of(spec.studies.begin(), spec.studies.end(), [&](const Study& st) { return key_under(e.key, st.reads); }))
      spec.schema.declare(e);
  spec.schema.texts(kStudiesKey, accepted_study_names(spec), 0,
                    "the studies this scene runs (default: every study whose section the scene has)");

  CLI::App app{spec.description, name};
  std::string scene_file;
  bool quick = false, list_studies = false, list_keys = false, as_json = false;
  std::string out_dir = "results/" + name;
  int threads = omp_get_max_threads();
  std::vector<std::string> overrides, only;
  auto* scene_opt = app.add_option("--scene", scene_file, "Scene file (default: " + experiment_dir + "/" + name + ".toml)");
  app.add_flag("--quick", quick, "Use the quick scene " + experiment_dir + "/quick.toml (the paper scene, shortened; for CI; the paper scene where there is none)")
      ->excludes(scene_opt);
  app.add_option("--study", only, "Run only this study of the scene (repeatable; see --list-studies)");
  app.add_flag("--list-studies", list_studies, "Print each study: name, the figure or table it makes, its CSV files");
  app.add_flag("--list-keys", list_keys,
                                     "Print every scene key: type, allowed values, default, meaning, the studies that read it");
  app.add_flag("--json", as_json, "With --list-keys or --plan: print JSON");
  app.add_option("--out", out_dir, "Output directory")->capture_default_str();
  app.add_option("--threads", threads, "Threads (results do not depend on it)")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  app.add_option("--set", overrides, "Override a scene key: --set key=value (repeatable)");
  bool plan_only = false;
  app.add_flag("--plan", plan_only,
               "Validate, print what each study would run (steps, force evaluations, memory, tasks per MPI rank, "
               "estimated wall time) and exit without running");
  int plan_ranks = 0;
  auto* ranks_opt = app.add_option("--ranks", plan_ranks,
                                   "With --plan: the estimate for this many MPI ranks of --threads threads each "
                                   "(default: the ranks of this job; 1 without mpirun)")
                        ->check(CLI::Range(1, 1 << 24));
  double max_seconds = 0;
  app.add_option("--max-seconds", max_seconds,
                 "Refuse, before any work, a run whose --plan estimates more wall time than this (0: no limit)")
      ->check(CLI::Range(0.0, 1e12));
  std::string concurrency_file;
  app.add_option("--timing-concurrency", concurrency_file,
                 "Share the measurement of whether the cores time alike (run.json timing_concurrency) through this "
                 "file: read it there if the file holds it, else measure it and add it (make figures: one measurement "
                 "for all its runs)");
  bool resume = false;
  app.add_flag("--resume", resume,
               "Continue an interrupted run from the checkpoint in --out (experiments that write checkpoints)");
  app.footer(studies_help(spec) + keys_help(spec, experiment_dir));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << name << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  // Arguments are shown in one line: one with a control character (a newline, a carriage return, a tab...)
  // is refused, shown with the character escaped (a --set of two lines would otherwise set one key).
  for (const auto& [option, values] : {std::pair<const char*, std::vector<std::string>>{"--set", overrides},
                                       {"--study", only}, {"--scene", {scene_file}}, {"--out", {out_dir}},
                                       {"--timing-concurrency", {concurrency_file}}})
    for (const auto& v : values)
      if (std::any_of(v.begin(), v.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) {
        std::cerr << name << ": " << option << " " << printable(v)
                  << ": holds a control character (shown escaped); give one value per option, on one line\n";
        return 2;
      }
  for (const auto& given : only)  // (also with --list-keys and --list-studies, which run nothing)
    if (!find_study(spec, given)) {
      std::cerr << name << ": --study " << given << ": no such study (the studies of " << name << ": "
                << join(study_names(spec)) << ")\n";
      return 2;
    }
  if (as_json && !list_keys && !plan_only) {
    std::cerr << name << ": --json goes with --list-keys or --plan (see --help)\n";
    return 2;
  }
  if (ranks_opt->count() > 0 && !plan_only) {
    std::cerr << name << ": --ranks goes with --plan (an MPI job's ranks are mpirun's -np; see --help)\n";
    return 2;
  }
  if (list_studies) {
    for (const auto& st : spec.studies) std::cout << st.name << '\t' << st.description() << '\t' << join(st.files, " ") << '\n';
    return 0;
  }
  if (list_keys) {
    const auto keys = keys_json(spec, experiment_dir);
    if (as_json) {
      std::cout << keys.dump(2) << '\n';
    } else {
      for (const auto& k : keys)
        std::cout << k["key"].get<std::string>() << '\t' << k["type_name"].get<std::string>() << '\t'
                  << k["allowed"].get<std::string>() << '\t' << (k["default"].is_null() ? "" : k["default"].dump())
                  << '\t' << k["doc"].get<std::string>() << '\n';
    }
    return 0;
  }
  std::string lanes;  // GEOMINT_LANES, the lane kernels' widest instruction set ("": the CPU's)
  try {
    if (!concurrency_file.empty()) share_timing_concurrency(concurrency_file);
    lanes = lanes_cap();
  } catch (const std::exception& e) {  // (a file of another form, or GEOMINT_LANES of none: before any work)
    std::cerr << name << ": " << e.what() << '\n';
    return 2;
  }
  // (--quick: quick.toml, or the paper scene where the experiment has none: its paper scene is quick)
  if (scene_file.empty())
    scene_file = experiment_dir + "/" +
                 (quick && std::filesystem::exists(experiment_dir + "/quick.toml") ? std::string("quick") : name) + ".toml";

  std::optional<Scene> scene;
  std::optional<ResultsDir> results;
  std::optional<OutputDir> out;
  int refused = 0;
  std::vector<const Study*> studies;
  const std::filesystem::path published_file = std::filesystem::path(experiment_dir) / "published.toml";
  std::vector<Published> published;
  try {
    if (std::filesystem::exists(published_file)) published = read_published(published_file);
    for (const Published& p : published) {
      const Study* st = find_study(spec, p.study);
      if (!st || st->name != p.study)  // published.toml names studies by their current names
        throw PublishedError(published_file.string() + ": [" + p.key + "]: no study '" + p.study + "' (studies: " +
                             join(study_names(spec)) + ")");
    }
    resolve_figures(published, published_file, [&](const std::string& study) { return find_study(spec, study)->item_ids(); });
  } catch (const PublishedError& e) {
    std::cerr << name << ": published values: " << e.what() << '\n';
    return 2;
  }
  try {
    scene = Scene::load(scene_file, overrides, spec.schema);
    studies = select_studies(spec, *scene, only);
    for (const Study* st : studies) {
      scene->require(st->uses(), "study " + st->name, spec.schema);
      scene->restrict_reads(st->uses(), "study " + st->name);
      if (st->validate) st->validate(*scene);
    }
    scene->restrict_reads({});
    std::vector<StudyPlan> plans;
    for (const Study* st : studies) {
      scene->restrict_reads(st->uses(), "study " + st->name);
      std::vector<std::string> read;
      scene->log_reads(&read);
      plans.push_back(st->plan ? st->plan(*scene) : StudyPlan{});
      scene->log_reads(nullptr);
      check_plan(*st, plans.back(), read);
    }
    scene->restrict_reads({});
    const nlohmann::ordered_json plan = plan_json(studies, plans, plan_ranks > 0 ? plan_ranks : mpi::size(), threads);
    if (max_seconds > 0 && plan["wall_s"].get<double>() > max_seconds)
      throw SceneError("the plan estimates " + fmt_seconds(plan["wall_s"].get<double>()) + " of wall time, over --max-seconds " +
                       format_double(max_seconds) + " (see --plan)");
    if (plan_only) {
      if (as_json)
        std::cout << plan.dump(2) << '\n';
      else
        print_plan(std::cout, plan);
      return 0;
    }
    // Rank 0 writes DIR; another rank of an MPI job writes into a scratch directory it removes.
    results.emplace(mpi::is_root() ? std::filesystem::path(out_dir) : rank_scratch_dir(name), name, resume);
    out.emplace(results->staging_path());
  } catch (const SceneError& e) {
    std::cerr << name << ": scene error: " << e.what() << '\n';
    refused = 2;
  } catch (const OutputError& e) {
    std::cerr << name << ": output error: " << e.what() << '\n';
    refused = 2;
  } catch (const std::filesystem::filesystem_error& e) {  // (a path the checks above did not foresee)
    std::cerr << name << ": path error: " << e.what() << '\n';
    refused = 2;
  }
  if (mpi::all_max(refused) != 0) {  // (DIR is rank 0's alone: the other ranks learn of its refusal here)
    if (!mpi::is_root() && results) results->discard();  // (a rank's scratch directory, not DIR.partial)
    return 2;
  }

  if (resume && !results->resumed())
    std::cerr << name << ": --resume: no interrupted run in " << results->staging_path().string()
              << "; starting from the beginning\n";
  install_signal_handlers(name, *results);
  omp_set_num_threads(threads);
  Context ctx(*scene, *out, threads);
  ctx.resume = mpi::all_max(results->resumed()) != 0;  // (rank 0's staging directory decides)
  ctx.experiment = name;
  ctx.published_entries = published;
  ctx.resume_command = (mpi::size() > 1 ? "mpirun -np " + std::to_string(mpi::size()) + " " : std::string()) +
                       resume_command(argc, argv);  // (any -np resumes)
  try {
    std::vector<std::string> ran;
    nlohmann::ordered_json study_wall = nlohmann::ordered_json::object();
    for (const Study* st : studies) {
      const auto ts = std::chrono::steady_clock::now();
      const std::size_t files_before = out->written().size();
      scene->restrict_reads(st->uses(), "study " + st->name);
      ctx.study = st->name, ctx.reads = st->uses();
      try {
        st->run(ctx);
      } catch (const NumericalFailure& e) {  // also Newton's IntegrationError (integrators/newton.hpp)
        throw NumericalFailure("study " + st->name + ": " + e.what());
      }
      scene->restrict_reads({});
      for (std::size_t i = files_before; i < out->written().size(); ++i) {
        const std::string& f = out->written()[i];
        if (std::none_of(st->files.begin(), st->files.end(), [&](const std::string& p) { return file_matches(p, f); }))
          throw std::logic_error("study " + st->name + " wrote " + f + ", which it does not declare");
      }
      study_wall[st->name] = std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();
      ran.push_back(st->name);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const nlohmann::ordered_json reported = to_json(ctx.summary);
    if (const auto bad = first_non_finite(reported))
      throw NumericalFailure("summary value " + *bad + " is not finite");
    nlohmann::ordered_json summary = {{"experiment", name}, {"studies", ran}};
    for (auto& [k, v] : reported.items()) summary[k] = v;
    apply_published(published, summary, scene->to_json(), ran);
    std::vector<std::string> made;  // the papers' items the studies that ran made under this scene
    for (const std::string& r : ran)
      for (const auto& item : made_here(*find_study(spec, r), *scene)) made.push_back(item);
    apply_figure_verdicts(summary, made);
    summary["timing"]["wall_s"] = wall;
    summary["timing"]["study_wall_s"] = study_wall;
    out->write("summary.json", summary.dump(2) + "\n");
    std::vector<Entry> made_by;  // (the papers' items of each study that ran, for the figures' titles)
    for (const std::string& r : ran)
      made_by.emplace_back("made." + r, gnuplot_quoted(join(made_here(*find_study(spec, r), *scene), ", ")));
    for (const std::string& item : std::set<std::string>(made.begin(), made.end()))  // (two studies' item once)
      made_by.emplace_back("item." + item_slug(item), gnuplot_quoted(item));
    out->write("figure_values.gp", figure_values(scene->to_json(), summary, made_by));

    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    nlohmann::ordered_json run = {{"experiment", name}, {"build", build_info()}, {"machine", machine_info()}};
    run["command"] = command;
    run["scene_file"] = scene->file().string();
    if (!published.empty()) run["published_file"] = published_file.string();
    std::vector<std::string> bases;
    for (const auto& b : scene->bases()) bases.push_back(b.string());
    run["scene_bases"] = bases;
    run["overrides"] = overrides;
    run["scene"] = scene->to_json();
    run["studies"] = ran;
    run["study_list"] = nlohmann::ordered_json::array();  // every study of the experiment: what it makes, its files
    for (const auto& st : spec.studies)
      run["study_list"].push_back({{"name", st.name}, {"makes", st.description()}, {"made", made_here(st, *scene)},
                                   {"files", st.files},
                                   {"ran", std::find(ran.begin(), ran.end(), st.name) != ran.end()}});
    run["threads"] = threads;
    run["lanes_cap"] = lanes.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(lanes);  // (GEOMINT_LANES)
    run["ranks"] = mpi::size();
    const double busy = mpi::busy_seconds();
    const double exchange = mpi::exchange_seconds();
    run["rank_busy_s"] = mpi::all_gather(std::span<const double>(&busy, 1));  // each rank's time in distributed tasks
    run["rank_exchange_s"] = mpi::all_gather(std::span<const double>(&exchange, 1));  // and in exchanging their results
    run["checkpoint_write_s"] = checkpoint_write_seconds();
    run["load_average"] = {{"before", load_before}, {"after", load_average()}};  // 1, 5, 15 minutes
    run["timing_protocol"] = to_json(timing_protocol_record());  // (runner/timing.hpp: its floor and rounds)
    run["timing_concurrency"] = to_json(timing_concurrency_record());  // (runner/timing.hpp; null: no cost study timed)
    run["timing_control"] = to_json(timing_control_record());  // (runner/timing.hpp: each measurement's drift)
    run["start_utc"] = utc_iso8601(start);
    run["end_utc"] = utc_iso8601(std::chrono::system_clock::now());
    run["wall_s"] = wall;
    run["study_wall_s"] = study_wall;
    run["files"] = out->written();
    out->write("run.json", run.dump(2) + "\n");
    g_finishing = 1;  // (from here a signal lets the run end: exit 0, DIR replaced)
    remove_checkpoints(out->path());
    if (mpi::is_root()) results->commit(out->written());
    else results->discard();
  } catch (const Interrupted& e) {
    if (!mpi::is_root()) results->discard();
    std::cerr << name << ": stopped: " << e.what() << " (kept in " << results->staging_path().string()
              << "; " << results->final_path().string() << " is unchanged)\n";
    return 3;
  } catch (const SceneError& e) {  // bad input found once the run has begun (e.g. a corrupt checkpoint)
    if (!mpi::is_root()) results->discard();
    std::cerr << name << ": bad input: " << e.what() << " (kept in " << results->staging_path().string() << "; "
              << results->final_path().string() << " is unchanged)\n";
    return 2;
  } catch (const NumericalFailure& e) {
    results->discard();
    std::cerr << name << ": numerical failure: " << e.what() << " (" << results->final_path().string()
              << " is unchanged)\n";
    return 4;
  } catch (const std::exception& e) {
    results->discard();
    std::cerr << name << ": error: " << e.what() << " (" << results->final_path().string() << " is unchanged)\n";
    return 1;
  }
  return 0;
}

namespace {
std::vector<Study (*)()>& registered_studies() {
  static std::vector<Study (*)()> makers;
  return makers;
}
}  // namespace

RegisteredStudy::RegisteredStudy(Study (*make)()) { registered_studies().push_back(make); }

int run_registered_experiment(int argc, char** argv, const std::string& name, const std::string& built_from) {
  ExperimentSpec spec{.name = name};
  for (const auto make : registered_studies()) spec.studies.push_back(make());
  std::sort(spec.studies.begin(), spec.studies.end(), [](const Study& a, const Study& b) { return a.name < b.name; });
  std::vector<std::string> described;
  for (const Study& st : spec.studies) described.push_back(st.description());
  spec.description = join(described, "; ");
  return run_experiment(argc, argv, std::move(spec), built_from);
}

}  // namespace geomint
