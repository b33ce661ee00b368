#pragma once
// 000 eq. (14): exponential decay y' = -alpha*y.
#include <cmath>

namespace geomint {

struct ExponentialDecay {
  double alpha;

  double f(double y) const { return -alpha * y; }                      // 000 eq. (14)
  double exact(double y0, double t) const { return y0 * std::exp(-alpha * t); }
  double linear_rate() const { return alpha; }                          // |lambda| of f'(y)
};

}  // namespace geomint
