#include "geomint/observables/order_fit.hpp"

#include "geomint/observables/linear_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace geomint {

OrderFit fit_order(std::span<const double> h, std::span<const double> err, double min_err, const char* what) {
  if (h.size() != err.size()) throw std::invalid_argument("fit_order: h and err differ in length");
  OrderFit fit;
  fit.used.assign(h.size(), false);
  std::vector<double> x, y;
  fit.h_min = std::numeric_limits<double>::infinity();
  fit.h_max = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!(std::isfinite(err[i]) && err[i] > min_err && h[i] > 0)) continue;
    fit.used[i] = true;
    x.push_back(std::log10(h[i]));
    y.push_back(std::log10(err[i]));
    fit.h_min = std::min(fit.h_min, h[i]);
    fit.h_max = std::max(fit.h_max, h[i]);
  }
  fit.points = static_cast<int>(x.size());
  if (fit.points < 3) {
    throw NumericalFailure(std::string(what) + ": only " + std::to_string(fit.points) +
                                " points above the round-off floor; at least 3 are needed");
  }
  const LinearFit line = linear_fit(x, y);
  fit.order = line.slope;
  fit.log10_c = line.intercept;
  fit.r2 = line.r2;
  return fit;
}

Value to_value(const OrderFit& f) {
  return {{"order", f.order}, {"log10_c", f.log10_c}, {"r2", f.r2}, {"points", f.points},
          {"h_min", f.h_min}, {"h_max", f.h_max}};
}

double local_order(std::span<const double> h, std::span<const double> err) {
  std::vector<std::pair<double, double>> pts;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] > 0 && err[i] > 0 && std::isfinite(h[i]) && std::isfinite(err[i])) pts.emplace_back(h[i], err[i]);
  std::sort(pts.begin(), pts.end());
  if (pts.size() < 2 || pts[0].first == pts[1].first) return std::nan("");
  return std::log(pts[1].second / pts[0].second) / std::log(pts[1].first / pts[0].first);
}

}  // namespace geomint
