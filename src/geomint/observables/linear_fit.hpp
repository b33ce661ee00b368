#pragma once
// The least-squares line y = intercept + slope x (the one implementation used by
// order fits, drift slopes and growth rates).
#include <cstddef>
#include <span>

namespace geomint {

struct LinearFit {
  double slope = 0, intercept = 0;
  double r2 = 1;  // coefficient of determination (1 when y is constant)
};

// Needs at least two distinct x; with all x equal the slope is reported as 0.
inline LinearFit linear_fit(std::span<const double> x, std::span<const double> y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= n, my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  LinearFit f;
  f.slope = sxx > 0 ? sxy / sxx : 0.0;
  f.intercept = my - f.slope * mx;
  f.r2 = syy > 0 && sxx > 0 ? sxy * sxy / (sxx * syy) : 1.0;
  return f;
}

}  // namespace geomint
