#pragma once
// What summary.json reports, in one shape in every experiment (runner/results.hpp): the labels of a
// figure's methods, the range of a list, its spread, and the range of a scene's list of steps.
#include <algorithm>
#include <string>
#include <vector>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

// The labels of registered methods (their CSV columns and summary keys), for summary.methods.<study>.
inline Value labels_of(const std::vector<std::string>& methods) {
  Value out = Value::list();
  for (const auto& m : methods) out.push_back(label_of(m));
  return out;
}

// {min, max} of a non-empty list.
inline Value range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

// {min, max, mean} of a non-empty list.
inline Value spread_of(const std::vector<double>& v) {
  Value r = range_of(v);
  double sum = 0;
  for (double x : v) sum += x;
  r["mean"] = sum / static_cast<double>(v.size());
  return r;
}

// {min, max, count} of a scene's non-empty list of steps.
inline Value h_range(const std::vector<double>& hs) {
  Value r = range_of(hs);
  r["count"] = hs.size();
  return r;
}

}  // namespace geomint
