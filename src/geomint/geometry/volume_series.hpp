#pragma once
// Volume series of a point cloud under a flow (003 Figs 5.2, 5.4): the relative change
// V(t_j)/V(t_0) - 1 and its peak-to-peak range (and half of it, the amplitude) over a time window,
// of one series or of its difference from a reference series (which removes what both share, e.g.
// the convex-hull artefact of a cloud).
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace geomint {

// V_j / V_0 - 1 for the first `count` samples of a volume series V (all of them if there are fewer).
inline std::vector<double> relative_volumes(std::span<const double> v, std::size_t count) {
  std::vector<double> out;
  for (std::size_t j = 0; j < std::min(count, v.size()); ++j) out.push_back(v[j] / v[0] - 1);
  return out;
}

// max_j x_j - min_j x_j (0 for an empty series).
inline double peak_to_peak(std::span<const double> x) {
  if (x.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  return *hi - *lo;
}

// The peak-to-peak of V_j / V_0 - 1 over the first `count` samples.
inline double relative_peak_to_peak(std::span<const double> v, std::size_t count) {
  return peak_to_peak(relative_volumes(v, count));
}

// The amplitude of V_j / V_0 - 1 over the first `count` samples, half its peak-to-peak: the size
// that a plot shows as "the amplitude of the fluctuations" (003 Sec. 5.2.1), comparable with it.
inline double relative_amplitude(std::span<const double> v, std::size_t count) {
  return 0.5 * relative_peak_to_peak(v, count);
}

// The peak-to-peak over the first `count` samples of (V_j / V_0 - 1) - (R_j / R_0 - 1): the relative
// change of V less that of the reference series R.
inline double relative_peak_to_peak_minus(std::span<const double> v, std::span<const double> r, std::size_t count) {
  const std::vector<double> a = relative_volumes(v, count), b = relative_volumes(r, count);
  std::vector<double> d;
  for (std::size_t j = 0; j < std::min(a.size(), b.size()); ++j) d.push_back(a[j] - b[j]);
  return peak_to_peak(d);
}

}  // namespace geomint
