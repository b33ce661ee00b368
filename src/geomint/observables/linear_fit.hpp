#pragma once
// The least-squares line y = intercept + slope x (the one implementation used by
// order fits, drift slopes and growth rates).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace geomint {

struct LinearFit {
  double slope = 0, intercept = 0;
  double r2 = 1;  // coefficient of determination (1 when y is constant)
  double sxx = 0;  // sum of (x_i - mean x)^2: with errors of standard deviation s in y, the slope's is s / sqrt(sxx)
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
  f.sxx = sxx;
  f.slope = sxx > 0 ? sxy / sxx : 0.0;
  f.intercept = my - f.slope * mx;
  f.r2 = syy > 0 && sxx > 0 ? sxy * sxy / (sxx * syy) : 1.0;
  return f;
}

// The least-squares parabola y = c0 + c1 u + c2 u^2 in u = (x - x0) / w, x0 the mean of x and w the largest
// |x - x0| (for the curvature of a drift, 004 Fig. 2); needs at least three distinct x.
struct QuadraticFit {
  double x0 = 0, w = 1, c0 = 0, c1 = 0, c2 = 0;
  double operator()(double x) const {
    const double u = (x - x0) / w;
    return c0 + (c1 + c2 * u) * u;
  }
};

inline QuadraticFit quadratic_fit(std::span<const double> x, std::span<const double> y) {
  QuadraticFit f;
  const double n = static_cast<double>(x.size());
  for (double v : x) f.x0 += v / n;
  f.w = 0;
  for (double v : x) f.w = std::max(f.w, std::abs(v - f.x0));
  double s[5] = {}, b[3] = {};  // sums of u^k (k <= 4) and of y u^k (k <= 2)
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double u = (x[i] - f.x0) / f.w;
    double uk = 1;
    for (int k = 0; k < 5; ++k, uk *= u) {
      s[k] += uk;
      if (k < 3) b[k] += y[i] * uk;
    }
  }
  // the normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = b by Cramer's rule
  const auto det = [](double a, double b_, double c, double d, double e, double g, double p, double q, double r) {
    return a * (e * r - g * q) - b_ * (d * r - g * p) + c * (d * q - e * p);
  };
  const double D = det(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
  f.c0 = det(b[0], s[1], s[2], b[1], s[2], s[3], b[2], s[3], s[4]) / D;
  f.c1 = det(s[0], b[0], s[2], s[1], b[1], s[3], s[2], b[2], s[4]) / D;
  f.c2 = det(s[0], s[1], b[0], s[1], s[2], b[1], s[2], s[3], b[2]) / D;
  return f;
}

}  // namespace geomint
