#pragma once
// Statistics of an ensemble of trajectories and of a recorded time series (004 Figs 2-6): the mean
// and sample standard deviation across the trajectories, their standard errors, the exponent of a
// power law fitted in log-log coordinates and its bootstrap standard error, the peak-to-peak amplitude about a least-squares line or
// quadratic,
// and the median.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "geomint/observables/linear_fit.hpp"
#include "geomint/sweep/parallel_map.hpp"

namespace geomint {

struct MeanDeviation {
  double mean = 0, sd = 0;
};

// The mean and the sample standard deviation (denominator M - 1) of M >= 2 values.
inline MeanDeviation mean_and_deviation(std::span<const double> v) {
  const double M = static_cast<double>(v.size());
  double mean = 0, var = 0;
  for (double x : v) mean += x;
  mean /= M;
  for (double x : v) var += (x - mean) * (x - mean);
  return {mean, std::sqrt(var / (M - 1))};
}

// The mean and sample standard deviation across the trajectories `which` (M >= 2) of an ensemble's
// series (series[i][k]: trajectory i at its k-th output time, all of one length), at every stride-th
// output time k = 0, stride, 2 stride, ...: the moments of 004 Fig. 4 against t.
struct EnsembleMoments {
  std::vector<std::size_t> k;  // the output times taken
  std::vector<double> mean, sd;
};
inline EnsembleMoments ensemble_moments(const std::vector<std::vector<double>>& series,
                                        std::span<const std::size_t> which, std::size_t stride = 1) {
  EnsembleMoments out;
  std::vector<double> column(which.size());
  for (std::size_t k = 0; k < series.at(which[0]).size(); k += stride) {
    for (std::size_t j = 0; j < which.size(); ++j) column[j] = series[which[j]][k];
    const MeanDeviation md = mean_and_deviation(column);
    out.k.push_back(k), out.mean.push_back(md.mean), out.sd.push_back(md.sd);
  }
  return out;
}
// The same over every trajectory.
inline EnsembleMoments ensemble_moments(const std::vector<std::vector<double>>& series, std::size_t stride = 1) {
  std::vector<std::size_t> all(series.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  return ensemble_moments(series, all, stride);
}

// Standard errors of the mean and of the standard deviation sd of M samples (normal
// approximation): sd / sqrt(M) and sd / sqrt(2 (M - 1)).
inline double standard_error_of_mean(double sd, double M) { return sd / std::sqrt(M); }
inline double standard_error_of_deviation(double sd, double M) { return sd / std::sqrt(2 * (M - 1)); }

// The exponent gamma of s ~ t^gamma: the least-squares slope of log s against log t over the
// points with t >= t0 and s > 0 (NaN if fewer than two).
inline double power_law_exponent(std::span<const double> t, std::span<const double> s, double t0) {
  std::vector<double> lt, ls;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && s[i] > 0) lt.push_back(std::log(t[i])), ls.push_back(std::log(s[i]));
  return lt.size() >= 2 ? linear_fit(lt, ls).slope : std::numeric_limits<double>::quiet_NaN();
}

// Bootstrap resamples of an ensemble: enough for a standard error to about 5 % (1/sqrt(2 (200 - 1))).
inline constexpr int kBootstrapResamples = 200;

// The bootstrap standard error of gamma in sd ~ t^gamma (power_law_exponent over t >= t0 of the sample standard
// deviation across the trajectories at the times t[k]; series[i][k]: trajectory i at t[k]): the sample standard
// deviation of gamma over `resamples` ensembles of the same size drawn from the trajectories with replacement, from
// the stream seeded by `seed` (the same bits at any thread count). It carries the sampling error of the finite
// ensemble, each trajectory's correlation over time included, which a formula for independent points would miss.
inline double bootstrap_exponent_stderr(const std::vector<std::vector<double>>& series, std::span<const double> t,
                                        double t0, int resamples, std::uint64_t seed) {
  const std::size_t M = series.size(), K = t.size();
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, M - 1);
  std::vector<std::vector<std::size_t>> which(static_cast<std::size_t>(resamples), std::vector<std::size_t>(M));
  for (auto& w : which)  // (every draw first, in the stream's order; the resamples then on the threads)
    for (auto& i : w) i = pick(rng);
  std::vector<double> by_time(K * M);  // by_time[k M + i] = series[i][k]: a resample gathers within one time's row
  for (std::size_t i = 0; i < M; ++i)
    for (std::size_t k = 0; k < K; ++k) by_time[k * M + i] = series[i][k];
  const std::vector<double> gammas = parallel_map(which.size(), [&](std::size_t r) {
    std::vector<double> column(M), sd(K, 0.0);
    for (std::size_t k = 0; k < K; ++k) {
      if (t[k] < t0) continue;  // (outside the fit)
      for (std::size_t j = 0; j < M; ++j) column[j] = by_time[k * M + which[r][j]];
      sd[k] = mean_and_deviation(column).sd;
    }
    return power_law_exponent(t, sd, t0);
  });
  return mean_and_deviation(gammas).sd;
}

// The least-squares slope of y against x over the points with x >= x0.
inline double slope_from(std::span<const double> x, std::span<const double> y, double x0) {
  std::vector<double> a, b;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] >= x0) a.push_back(x[i]), b.push_back(y[i]);
  return linear_fit(a, b).slope;
}

// max - min of y - trend(x): the size of an oscillation about a fitted trend.
inline double peak_to_peak_about(std::span<const double> x, std::span<const double> y, const auto& trend) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - trend(x[i]);
    lo = std::min(lo, r), hi = std::max(hi, r);
  }
  return hi - lo;
}

// The size of the oscillation about a linear trend (least-squares line in x).
inline double peak_to_peak_about_line(std::span<const double> x, std::span<const double> y) {
  const LinearFit line = linear_fit(x, y);
  return peak_to_peak_about(x, y, [&](double t) { return line.intercept + line.slope * t; });
}

// The same about a least-squares quadratic: without the curvature of a drift whose rate changes (004 Fig. 2).
inline double peak_to_peak_about_quadratic(std::span<const double> x, std::span<const double> y) {
  return peak_to_peak_about(x, y, quadratic_fit(x, y));
}

// The median of v (the mean of the two middle values for an even count; NaN if v is empty).
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace geomint
