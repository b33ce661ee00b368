#pragma once
// A yes/no claim judged on n independent samples (004 Fig. 5: "the Poincare cuts of a growth episode lie in
// the region p2 < 0", one growth episode per random start): how often it holds, with the binomial standard
// error of that share, and the spread of the per-sample quantity the claim reads (its quartiles).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace geomint {

// The q-quantile (0 <= q <= 1) of the values v, sorted ascending, by linear interpolation between the
// order statistics at q (n - 1); NaN if v is empty.
inline double quantile_of_sorted(const std::vector<double>& v, double q) {
  if (v.empty()) return std::nan("");
  const double at = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

struct Quartiles {
  double min, q1, median, q3, max;
};

inline Quartiles quartiles_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {quantile_of_sorted(v, 0), quantile_of_sorted(v, 0.25), quantile_of_sorted(v, 0.5), quantile_of_sorted(v, 0.75),
          quantile_of_sorted(v, 1)};
}

// The claim "value > bound" over the samples `values`: holds in `holds` of `samples`; share = holds / samples,
// its binomial standard error sqrt(share (1 - share) / samples), and the standard error a share would have if
// the claim held by a coin flip, sqrt(1/4 / samples) = 1 / (2 sqrt(samples)). NaN shares for no sample.
struct ClaimShare {
  std::size_t samples = 0, holds = 0;
  double share = std::nan(""), standard_error = std::nan(""), coin_flip_standard_error = std::nan("");
};

inline ClaimShare claim_share(const std::vector<double>& values, double bound) {
  ClaimShare c;
  c.samples = values.size();
  c.holds = static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [&](double v) { return v > bound; }));
  if (c.samples == 0) return c;
  const double n = static_cast<double>(c.samples);
  c.share = static_cast<double>(c.holds) / n;
  c.standard_error = std::sqrt(c.share * (1 - c.share) / n);
  c.coin_flip_standard_error = 0.5 / std::sqrt(n);
  return c;
}

}  // namespace geomint
