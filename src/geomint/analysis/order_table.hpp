#pragma once
// The order table of every convergence study (000 Figs 4 and 9): the least-squares order of each
// named error series against h (observables/order_fit.hpp: only errors above a floor, at least 3
// points), per initial condition, in one shape: orders.csv (initial, name, order, log10_c, r2,
// points, h_min, h_max; read by figures/common.gp getfit) and summary.json's orders.<name> (the
// order) and fits.<name> (the whole fit), of one initial condition.
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/io/csv.hpp"
#include "geomint/observables/order_fit.hpp"

namespace geomint {

class OrderTable {
 public:
  // Fits err(h) above `floor` and records it. If fewer than 3 points are above the floor, throws
  // NumericalFailure naming the series, the initial condition, the floor and `floor_is` (what errors
  // below the floor are, e.g. "round-off").
  const OrderFit& fit(const std::string& name, std::span<const double> h, std::span<const double> err, double floor,
                      int initial = 0, const std::string& floor_is = "round-off");

  Csv csv() const;                                    // orders.csv: one row per fit, in the order fitted
  nlohmann::ordered_json orders(int initial = 0) const;  // {name: order}
  nlohmann::ordered_json fits(int initial = 0) const;    // {name: to_json(fit)}

 private:
  struct Row {
    int initial;
    std::string name;
    OrderFit fit;
  };
  std::vector<Row> rows_;
};

}  // namespace geomint
