#pragma once
// What the map of 000 Fig. 6 shows, in numbers: where the polar runs diverge, compared with the
// analytic boundary of Sec. 4.1 (r(0) >= 2l + (2mg/k) cos(phi(0)), cos(phi(0)) = y(0)/r(0), y
// pointing down); how early they diverge; where the polar run has the smaller energy error (50);
// and how the two errors compare, ties apart from wins.
//
// A release from rest oscillates radially about r* = l + (mg/k) cos(phi(0)) between r(0) and
// 2r* - r(0) (systems/elastic_pendulum.hpp). A polar run that diverges inside the boundary is
// "inner" if r(0) < r* (its inner turning point is r(0) itself, next to the pivot), else "outer"
// (inner turning point 2r* - r(0), at the radial distance b - r(0) inside the boundary b).
// The origin is no initial condition of the polar problem: it enters only the counts of diverged
// runs over the whole grid.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>


#include "geomint/runner/results.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint {

// One initial position of the map and what the two runs from it gave (a row of map.csv).
struct EnergyMapRow {
  double x0, y0, H0;
  double eps_cartesian, eps_polar;  // (50); NaN where the run diverged
  bool diverged_cartesian, diverged_polar;
  std::int64_t diverge_step_polar;  // -1: did not diverge
};

// Nearest-rank quantile of a sorted non-empty list: sorted[round(q (n - 1))], halves to even.
template <class T>
T nearest_rank_quantile(const std::vector<T>& sorted, double q) {
  return sorted[static_cast<std::size_t>(std::nearbyint(q * static_cast<double>(sorted.size() - 1)))];
}

struct StepStatistics {  // of the steps at which polar runs diverged
  std::int64_t median = 0, max = 0;
  double time_max = 0;  // max * dt
};

struct EnergyMapStatistics {
  // the whole grid (the origin included)
  std::int64_t points = 0, diverged_polar = 0, diverged_cartesian = 0, diverged_any = 0;
  // the grid without the origin, against the boundary
  std::int64_t counted = 0;                        // points other than the origin
  std::int64_t criterion = 0;                      // on or outside the boundary
  std::int64_t disagree = 0;                       // polar run diverged != outside the boundary
  std::int64_t diverged_inside = 0, alive_outside = 0, cartesian_diverged_off_origin = 0;
  std::int64_t inner = 0, inner_candidates = 0;    // diverged with r(0) < r*; points with r(0) <= inner_r_max
  std::int64_t outer = 0, outer_candidates = 0;    // diverged with r(0) >= r*; points at most outer_dist_max inside
  std::optional<double> inner_r_max, outer_dist_max;
  std::optional<double> outer_dist_all;            // every point closer than this to the boundary diverged
  std::optional<double> H0_min_diverged, H0_max_alive;
  std::optional<StepStatistics> inside_steps, outside_steps;
  // runs finite in both coordinate systems: which energy error is smaller
  std::int64_t both_finite = 0, cartesian_better = 0, polar_better = 0;
  std::optional<double> eps_difference_min, eps_difference_max;  // eps_cartesian - eps_polar
  // ties: |eps_cartesian - eps_polar| <= tolerance * max(eps_cartesian, eps_polar), at round-off (the
  // tolerance J eps_mach of a sum of J squared errors (50)) and within 1 %; the wins beyond each
  double roundoff_tie_tolerance = 0;
  std::int64_t tied_roundoff = 0, cartesian_better_beyond_roundoff = 0, polar_better_beyond_roundoff = 0;
  std::int64_t tied_percent = 0, cartesian_better_beyond_percent = 0, polar_better_beyond_percent = 0;
  double ring_half_width = 0;                      // |r(0) - l| < ring_half_width * l: near the rest length
  std::optional<double> ring_polar_better, off_ring_polar_better;  // fraction of the points there
  std::optional<double> ratio_p05, ratio_median, ratio_p95;        // of eps_polar / eps_cartesian
};

namespace detail {
inline StepStatistics step_statistics(std::vector<std::int64_t> steps, double dt) {
  std::sort(steps.begin(), steps.end());
  return {nearest_rank_quantile(steps, 0.5), steps.back(), static_cast<double>(steps.back()) * dt};
}
inline std::optional<double> largest(const std::vector<double>& v) {
  return v.empty() ? std::nullopt : std::optional(*std::max_element(v.begin(), v.end()));
}
inline std::optional<double> smallest(const std::vector<double>& v) {
  return v.empty() ? std::nullopt : std::optional(*std::min_element(v.begin(), v.end()));
}
inline std::optional<double> fraction(std::int64_t a, std::int64_t b) {
  return b ? std::optional(static_cast<double>(a) / static_cast<double>(b)) : std::nullopt;
}
}  // namespace detail

inline constexpr double kEnergyMapTiePercent = 0.01;  // |delta eps| within 1 % of the larger eps: a tie

// steps: J of (50), for the round-off tolerance of the ties.
EnergyMapStatistics energy_map_statistics(const std::vector<EnergyMapRow>& rows, const ElasticPendulumParams& p,
                                          double dt, std::int64_t steps, double ring_half_width);

// The statistics as summary.json reports them (null where there is nothing to count, e.g. no
// polar run diverged inside the boundary).
Value to_value(const EnergyMapStatistics& s);

// Which coordinate system wins at the same total energy (000 Sec. 4.1: "even if we only consider initial
// conditions corresponding the same total energy"): the starts finite in both systems whose energy errors
// differ beyond the round-off tie tolerance (a win), grouped in bands of H_0 as wide as the map's energy
// resolution, the median |H_0 difference| of two neighbouring grid points (rows: the grid, x fastest, nx per
// row). A band is mixed if both systems win in it.
struct SameEnergyWins {
  double band_width = 0;
  std::int64_t bands_with_wins = 0, mixed_bands = 0;  // bands holding a win; those holding wins of both
  std::int64_t wins = 0, wins_in_mixed_bands = 0;
};
SameEnergyWins same_energy_wins(const std::vector<EnergyMapRow>& rows, std::size_t nx, double roundoff_tie_tolerance);
Value to_value(const SameEnergyWins& s);

}  // namespace geomint
