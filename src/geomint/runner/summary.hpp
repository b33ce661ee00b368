#pragma once
// What summary.json reports, in one shape in every experiment: a value that may not exist (null,
// never NaN), the range of a list, its spread, and the range of a scene's list of steps.
#include <algorithm>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

namespace geomint {

// The value, or null where there is none (an interpolation outside the measured range, say).
inline nlohmann::ordered_json or_null(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
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
