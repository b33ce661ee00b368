#pragma once
// The summary.json of an experiment's quick run (the ctest fixture <name>.quick_run).
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

inline std::filesystem::path results_dir(const std::string& experiment) {
  return std::filesystem::path(GEOMINT_TEST_RESULTS) / experiment;
}

inline const nlohmann::json& summary_of(const std::string& experiment) {
  static std::map<std::string, nlohmann::json> cache;
  auto it = cache.find(experiment);
  if (it == cache.end()) {
    std::ifstream in(results_dir(experiment) / "summary.json");
    if (!in) throw std::runtime_error("no summary.json in " + results_dir(experiment).string() + " (run the quick_run fixture)");
    it = cache.emplace(experiment, nlohmann::json::parse(in)).first;
  }
  return it->second;
}
