#pragma once
// Error norms along a trajectory.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geomint/core/state.hpp"

namespace geomint {

// Accumulates e_j = value_j - value_0 (or any error sequence) over j = 0..J and
// reports the max norm and the root mean square of 000 eq. (50), which divides
// the sum of the J+1 squares by J.
class ErrorSeries {
 public:
  void add(double e) {
    // A NaN anywhere makes the max NaN: a failed run never reports a small error.
    max_ = (std::isnan(e) || std::isnan(max_)) ? e + max_ : std::max(max_, std::abs(e));
    sum_sq_ += e * e;
    ++count_;
  }
  double max_abs() const { return max_; }
  double rms50() const { return count_ > 1 ? std::sqrt(sum_sq_ / static_cast<double>(count_ - 1)) : 0.0; }  // (50)
  std::int64_t count() const { return count_; }

 private:
  double max_ = 0, sum_sq_ = 0;
  std::int64_t count_ = 0;
};

// max_j |e_j| of a recorded error sequence (0 for none).
inline double largest_abs(const std::vector<double>& e) {
  double mx = 0;
  for (double x : e) mx = std::max(mx, std::abs(x));
  return mx;
}

inline double relative_error(double approx, double exact) { return std::abs(approx - exact) / std::abs(exact); }

// The l2 distance of two phase-space points (all of q and p).
template <int D>
double phase_distance(const PhaseState<D>& a, const PhaseState<D>& b) {
  return std::sqrt((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm());
}

}  // namespace geomint
