#pragma once
// The summary.json and CSV files of an experiment's quick run (the ctest fixture <name>.quick_run).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

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

// The largest value of the wall_spread column of a timing CSV, (max - min) / min of each timed
// measurement (runner/timing.hpp); each one must be finite and >= 0.
inline double largest_spread(const CsvFile& t) {
  const std::size_t c = t.column("wall_spread");
  double largest = 0;
  for (const auto& row : t.rows) {
    const double s = std::stod(row[c]);
    if (!(std::isfinite(s) && s >= 0)) throw std::runtime_error("wall_spread " + row[c] + " is not finite and >= 0");
    largest = std::max(largest, s);
  }
  return largest;
}
