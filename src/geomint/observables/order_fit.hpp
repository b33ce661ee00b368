#pragma once
// Convergence orders: least-squares slope of log(error) against log(h).
#include <limits>
#include <span>
#include <vector>

#include "geomint/core/numerical_failure.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

struct OrderFit {
  double order = 0;       // fitted slope p in err ~ C h^p
  double log10_c = 0;     // fitted log10 C
  double r2 = 0;          // coefficient of determination of the log-log fit
  int points = 0;         // how many points entered the fit
  double h_min = 0, h_max = 0;
  std::vector<bool> used; // per input point: inside the fit?
};

// The round-off floor of an error of a quantity of size `scale`: 1000 ulp. Errors
// below it are at the round-off plateau and are left out of order fits.
inline double roundoff_floor(double scale = 1.0) { return 1e3 * std::numeric_limits<double>::epsilon() * scale; }

// Fits over the points whose error is finite and above `min_err`
// (points at the round-off plateau would flatten the slope). Throws
// NumericalFailure if fewer than 3 points remain (nothing to fit: the study fails, exit 4).
OrderFit fit_order(std::span<const double> h, std::span<const double> err, double min_err,
                  const char* what = "fit_order");

// The local order between the two smallest step sizes with a finite positive error: the slope of log(err)
// against log(h) there (NaN with fewer than two such distinct h). The end of the asymptotic range, where
// a fit over a window would mix in the larger steps.
double local_order(std::span<const double> h, std::span<const double> err);

// The fit as summary.json reports it: order, log10_c, r2, points, h_min, h_max.
Value to_value(const OrderFit& f);

}  // namespace geomint
