#include "geomint/runner/experiment.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "geomint/io/run_info.hpp"

namespace geomint {

void Context::progress(std::string_view what) const {
  if (::isatty(STDERR_FILENO)) std::cerr << "  " << what << '\n';
}

namespace {

std::string keys_help(const Schema& schema) {
  std::string s = "\nScene keys (all required in the scene file; override any with --set key=value):\n";
  for (const auto& e : schema.entries()) s += "  " + e.key + (e.doc.empty() ? "" : "  " + e.doc) + "\n";
  return s;
}

}  // namespace

int run_experiment(int argc, char** argv, const ExperimentSpec& spec, const std::string& experiment_dir) {
  const auto start = std::chrono::system_clock::now();
  const auto t0 = std::chrono::steady_clock::now();
  const std::string name = spec.name;

  CLI::App app{spec.description, name};
  std::string scene_file;
  bool quick = false;
  std::string out_dir = "results/" + name;
  int threads = omp_get_max_threads();
  std::vector<std::string> overrides;
  auto* scene_opt = app.add_option("--scene", scene_file, "Scene file (default: " + experiment_dir + "/" + name + ".toml)");
  app.add_flag("--quick", quick, "Use the quick scene " + experiment_dir + "/quick.toml (seconds; for CI)")
      ->excludes(scene_opt);
  app.add_option("--out", out_dir, "Output directory")->capture_default_str();
  app.add_option("--threads", threads, "Threads (results do not depend on it)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--set", overrides, "Override a scene key: --set key=value (repeatable)");
  bool resume = false;
  app.add_flag("--resume", resume,
               "Continue an interrupted run from the checkpoint in --out (experiments that write checkpoints)");
  app.footer(keys_help(spec.schema));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << name << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  if (scene_file.empty()) scene_file = experiment_dir + "/" + (quick ? std::string("quick") : name) + ".toml";

  std::optional<Scene> scene;
  std::optional<OutputDir> out;
  try {
    scene = Scene::load(scene_file, overrides, spec.schema);
    if (spec.validate) spec.validate(*scene);
    out.emplace(out_dir);
  } catch (const SceneError& e) {
    std::cerr << name << ": scene error: " << e.what() << '\n';
    return 2;
  } catch (const OutputError& e) {
    std::cerr << name << ": output error: " << e.what() << '\n';
    return 2;
  }

  omp_set_num_threads(threads);
  Context ctx(*scene, *out, threads);
  ctx.resume = resume;
  try {
    spec.run(ctx);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    nlohmann::ordered_json summary = {{"experiment", name}};
    for (auto& [k, v] : ctx.summary.items()) summary[k] = v;
    summary["timing"]["wall_s"] = wall;
    out->write("summary.json", summary.dump(2) + "\n");

    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    nlohmann::ordered_json run = {{"experiment", name}, {"build", build_info()}};
    run["command"] = command;
    run["scene_file"] = scene->file().string();
    run["overrides"] = overrides;
    run["scene"] = scene->to_json();
    run["threads"] = threads;
    run["start_utc"] = utc_iso8601(start);
    run["end_utc"] = utc_iso8601(std::chrono::system_clock::now());
    run["wall_s"] = wall;
    run["files"] = out->written();
    out->write("run.json", run.dump(2) + "\n");
  } catch (const Interrupted& e) {
    std::cerr << name << ": stopped: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace geomint
