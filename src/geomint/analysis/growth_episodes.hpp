#pragma once
// Growth episodes of a recorded series y(t_k) (004 Fig. 5: the intervals on which the modified energy
// of one trajectory changes linearly). The rule:
//   1. the running slope s_k: the least-squares slope of y over the samples [k - half, k + half]
//      (clipped at the ends of the record);
//   2. its noise: the robust standard deviation of the running slopes over the whole record,
//      1.4826 x the median absolute deviation of s_k from their median (unaffected by the episodes
//      themselves as long as they cover less than half of the record);
//   3. an episode: a maximal run of consecutive samples with s_k - median(s) above `threshold` times
//      the noise (a growth, sign +1) or below minus that (a decline, sign -1), of at least
//      `min_samples` samples. Its interval is [t_begin, t_last] of those samples.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/linear_fit.hpp"

namespace geomint {

struct Episode {
  std::size_t begin = 0, end = 0;  // samples [begin, end)
  int sign = 0;                    // +1 growth, -1 decline
};

// Step 1: the running least-squares slope over the samples [k - half, k + half] (clipped); half >= 1.
inline std::vector<double> running_slope(std::span<const double> t, std::span<const double> y, std::size_t half) {
  const std::size_t n = t.size();
  std::vector<double> s(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k >= half ? k - half : 0, b = std::min(n, k + half + 1);
    s[k] = linear_fit(t.subspan(a, b - a), y.subspan(a, b - a)).slope;
  }
  return s;
}

struct SlopeNoise {
  double centre = 0;  // median of the running slopes
  double noise = 0;   // 1.4826 x their median absolute deviation from it
};

// Step 2.
inline SlopeNoise slope_noise(const std::vector<double>& s) {
  SlopeNoise r;
  r.centre = median(s);
  std::vector<double> dev;
  for (double v : s) dev.push_back(std::abs(v - r.centre));
  r.noise = 1.4826 * median(std::move(dev));
  return r;
}

// Step 3 on the running slopes s.
inline std::vector<Episode> growth_episodes(const std::vector<double>& s, double threshold, std::size_t min_samples) {
  const SlopeNoise sn = slope_noise(s);
  const auto sign_at = [&](std::size_t k) {
    const double z = s[k] - sn.centre;
    return z > threshold * sn.noise ? 1 : z < -threshold * sn.noise ? -1 : 0;
  };
  std::vector<Episode> out;
  std::size_t k = 0;
  while (k < s.size()) {
    const int sg = sign_at(k);
    std::size_t e = k + 1;
    while (e < s.size() && sign_at(e) == sg) ++e;
    if (sg != 0 && e - k >= min_samples) out.push_back({k, e, sg});
    k = e;
  }
  return out;
}

}  // namespace geomint
