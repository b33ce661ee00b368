#include "geomint/analysis/order_table.hpp"

#include <cstdint>

#include "geomint/core/numerical_failure.hpp"

namespace geomint {

const OrderFit& OrderTable::fit(const std::string& name, std::span<const double> h, std::span<const double> err,
                                double floor, int initial, const std::string& floor_is) {
  try {
    rows_.push_back({initial, name, fit_order(h, err, floor, name.c_str())});
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(std::string(e.what()) + " (initial condition " + std::to_string(initial) + ", floor " +
                           format_double(floor) + ": below it the errors are " + floor_is + "; add larger h)");
  }
  return rows_.back().fit;
}

Csv OrderTable::csv() const {
  Csv out({"initial", "name", "order", "log10_c", "r2", "points", "h_min", "h_max"});
  for (const auto& [initial, name, f] : rows_)
    out.row(static_cast<std::int64_t>(initial), name, f.order, f.log10_c, f.r2, f.points, f.h_min, f.h_max);
  return out;
}

nlohmann::ordered_json OrderTable::orders(int initial) const {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& r : rows_)
    if (r.initial == initial) out[r.name] = r.fit.order;
  return out;
}

nlohmann::ordered_json OrderTable::fits(int initial) const {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& r : rows_)
    if (r.initial == initial) out[r.name] = to_json(r.fit);
  return out;
}

}  // namespace geomint
