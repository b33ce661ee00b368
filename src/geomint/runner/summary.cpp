#include "geomint/runner/summary.hpp"

#include <algorithm>

namespace geomint {

Value labels_of(const std::vector<std::string>& methods) {
  Value out = Value::list();
  for (const auto& m : methods) out.push_back(label_of(m));
  return out;
}

Value range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

Value spread_of(const std::vector<double>& v) {
  Value r = range_of(v);
  double sum = 0;
  for (double x : v) sum += x;
  r["mean"] = sum / static_cast<double>(v.size());
  return r;
}

Value h_range(const std::vector<double>& hs) {
  Value r = range_of(hs);
  r["count"] = hs.size();
  return r;
}

}  // namespace geomint
