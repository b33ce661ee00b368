#pragma once
// 000 eq. (17): Gompertz growth y' = y*(a - b*ln y).
#include <cmath>

namespace geomint {

struct Gompertz {
  double a;
  double b;

  double f(double y) const { return y * (a - b * std::log(y)); }       // 000 eq. (17)
  // Closed form: ln y(t) = a/b + (ln y0 - a/b) e^{-b t}.
  double exact(double y0, double t) const {
    return std::exp(a / b + (std::log(y0) - a / b) * std::exp(-b * t));
  }
  double equilibrium() const { return std::exp(a / b); }
  // |f'(y*)| = b at the equilibrium y* = e^{a/b}: the rate that bounds
  // the explicit Euler step near the equilibrium.
  double linear_rate() const { return b; }
};

}  // namespace geomint
