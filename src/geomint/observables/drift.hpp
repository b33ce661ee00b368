#pragma once
// Drift of an error along a long run: the maxima of |e| over consecutive
// windows and the least-squares slope of those maxima against time. A
// symplectic method shows bounded, non-drifting maxima (slope ~ 0); a
// non-symplectic one grows linearly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "geomint/observables/linear_fit.hpp"

namespace geomint {

class WindowMaxima {
 public:
  explicit WindowMaxima(std::int64_t window_steps) : window_(window_steps) {}
  void add(double e) {
    if (count_++ % window_ == 0) maxima_.push_back(0.0);
    const double a = std::abs(e);
    maxima_.back() = std::isnan(a) ? a : std::max(maxima_.back(), a);
  }
  const std::vector<double>& maxima() const { return maxima_; }
  // Least-squares slope of the window maxima per window (over complete windows).
  double slope_per_window() const {
    const std::size_t n = count_ % window_ == 0 ? maxima_.size() : maxima_.size() - 1;
    std::vector<double> index(n);
    for (std::size_t i = 0; i < n; ++i) index[i] = static_cast<double>(i);
    return linear_fit(index, std::span<const double>(maxima_.data(), n)).slope;
  }

 private:
  std::int64_t window_, count_ = 0;
  std::vector<double> maxima_;
};

}  // namespace geomint
