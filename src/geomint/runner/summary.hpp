#pragma once
// What summary.json reports, in one shape in every experiment: a value that may not exist (null,
// never NaN), the range of a list, its spread, and the range of a scene's list of steps.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/methods/registry.hpp"

namespace geomint {

// The value, or null where there is none (an interpolation outside the measured range, say).
inline nlohmann::ordered_json or_null(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

// Adds the entries of `values` to summary[section] (other studies may have filled it already; an empty
// `values` adds nothing, not even the section).
inline void merge(nlohmann::ordered_json& summary, const char* section, const nlohmann::ordered_json& values) {
  for (const auto& [k, v] : values.items()) summary[section][k] = v;
}

// The labels of registered methods (their CSV columns and summary keys), for summary.methods.<study>.
inline nlohmann::ordered_json labels_of(const std::vector<std::string>& methods) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& m : methods) out.push_back(label_of(m));
  return out;
}

// {min, max} of a non-empty list.
inline nlohmann::ordered_json range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

// {min, max, mean} of a non-empty list.
inline nlohmann::ordered_json spread_of(const std::vector<double>& v) {
  nlohmann::ordered_json r = range_of(v);
  double sum = 0;
  for (double x : v) sum += x;
  r["mean"] = sum / static_cast<double>(v.size());
  return r;
}

// {min, max, count} of a scene's non-empty list of steps.
inline nlohmann::ordered_json h_range(const std::vector<double>& hs) {
  nlohmann::ordered_json r = range_of(hs);
  r["count"] = hs.size();
  return r;
}

}  // namespace geomint
