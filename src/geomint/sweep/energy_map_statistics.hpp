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
inline EnergyMapStatistics energy_map_statistics(const std::vector<EnergyMapRow>& rows, const ElasticPendulumParams& p,
                                                 double dt, std::int64_t steps, double ring_half_width) {
  EnergyMapStatistics s;
  s.roundoff_tie_tolerance = static_cast<double>(steps) * std::numeric_limits<double>::epsilon();
  s.points = static_cast<std::int64_t>(rows.size());
  s.ring_half_width = ring_half_width;
  std::vector<double> inner_r, inner_candidate_r, outer_d, outer_candidate_d, alive_outer_d, div_H0, alive_H0, ratios;
  std::vector<std::int64_t> inside_steps, outside_steps;
  std::int64_t ring[2] = {0, 0}, off_ring[2] = {0, 0};  // (polar better, runs)
  for (const EnergyMapRow& row : rows) {
    const bool dc = row.diverged_cartesian, dp = row.diverged_polar;
    s.diverged_polar += dp, s.diverged_cartesian += dc, s.diverged_any += dc || dp;
    if (!dc && !dp && std::isfinite(row.eps_cartesian) && std::isfinite(row.eps_polar)) {
      const double d = row.eps_cartesian - row.eps_polar;
      ++s.both_finite, s.cartesian_better += d < 0, s.polar_better += d > 0;
      s.eps_difference_min = std::min(s.eps_difference_min.value_or(d), d);
      s.eps_difference_max = std::max(s.eps_difference_max.value_or(d), d);
      const double scale = std::max(row.eps_cartesian, row.eps_polar);
      const auto tally = [&](double tolerance, std::int64_t& tied, std::int64_t& cartesian, std::int64_t& polar) {
        if (std::abs(d) <= tolerance * scale) ++tied;
        else (d < 0 ? cartesian : polar) += 1;
      };
      tally(s.roundoff_tie_tolerance, s.tied_roundoff, s.cartesian_better_beyond_roundoff, s.polar_better_beyond_roundoff);
      tally(kEnergyMapTiePercent, s.tied_percent, s.cartesian_better_beyond_percent, s.polar_better_beyond_percent);
    }
    const double r = std::hypot(row.x0, row.y0);
    if (r == 0) continue;  // the origin
    ++s.counted, s.cartesian_diverged_off_origin += dc;
    const double cos_phi = row.y0 / r, r_star = radial_rest_radius(p, cos_phi), b = polar_boundary_radius(p, cos_phi);
    const bool outside = r >= b;
    s.criterion += outside, s.disagree += dp != outside;
    (dp ? div_H0 : alive_H0).push_back(row.H0);
    if (outside) {
      if (dp) outside_steps.push_back(row.diverge_step_polar);
      else ++s.alive_outside;
    } else {
      if (r < r_star) {
        inner_candidate_r.push_back(r);
        if (dp) inner_r.push_back(r);
      } else {
        outer_candidate_d.push_back(b - r);
        (dp ? outer_d : alive_outer_d).push_back(b - r);
      }
      if (dp) inside_steps.push_back(row.diverge_step_polar);
    }
    if (!dc && !dp && std::isfinite(row.eps_cartesian) && std::isfinite(row.eps_polar)) {
      auto& tally = std::abs(r - p.l) < ring_half_width * p.l ? ring : off_ring;
      tally[0] += row.eps_polar < row.eps_cartesian, ++tally[1];
      if (row.eps_cartesian > 0) ratios.push_back(row.eps_polar / row.eps_cartesian);
    }
  }
  s.inner = static_cast<std::int64_t>(inner_r.size()), s.outer = static_cast<std::int64_t>(outer_d.size());
  s.diverged_inside = s.inner + s.outer;
  s.inner_r_max = detail::largest(inner_r);
  if (s.inner_r_max)
    s.inner_candidates = std::count_if(inner_candidate_r.begin(), inner_candidate_r.end(),
                                       [&](double r) { return r <= *s.inner_r_max; });
  s.outer_dist_max = detail::largest(outer_d);
  if (s.outer_dist_max)
    s.outer_candidates = std::count_if(outer_candidate_d.begin(), outer_candidate_d.end(),
                                       [&](double d) { return d <= *s.outer_dist_max; });
  if (s.outer_dist_max) s.outer_dist_all = detail::smallest(alive_outer_d);
  s.H0_min_diverged = detail::smallest(div_H0), s.H0_max_alive = detail::largest(alive_H0);
  if (!inside_steps.empty()) s.inside_steps = detail::step_statistics(inside_steps, dt);
  if (!outside_steps.empty()) s.outside_steps = detail::step_statistics(outside_steps, dt);
  s.ring_polar_better = detail::fraction(ring[0], ring[1]);
  s.off_ring_polar_better = detail::fraction(off_ring[0], off_ring[1]);
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    s.ratio_p05 = nearest_rank_quantile(ratios, 0.05), s.ratio_median = nearest_rank_quantile(ratios, 0.5),
    s.ratio_p95 = nearest_rank_quantile(ratios, 0.95);
  }
  return s;
}

// The statistics as summary.json reports them (null where there is nothing to count, e.g. no
// polar run diverged inside the boundary).
inline Value to_value(const EnergyMapStatistics& s) {
  const auto opt = [](const std::optional<double>& v) { return Value(v); };
  const auto steps = [](const std::optional<StepStatistics>& v) {
    return v ? Value{{"median", v->median}, {"max", v->max}, {"time_max", v->time_max}} : Value();
  };
  const auto frac = [](std::int64_t a, std::int64_t b) { return b ? Value(static_cast<double>(a) / static_cast<double>(b)) : Value(); };
  return {{"points", s.points},
          {"diverged_polar", s.diverged_polar},
          {"diverged_cartesian", s.diverged_cartesian},
          {"diverged_any", s.diverged_any},
          {"fraction_diverged_any", frac(s.diverged_any, s.points)},
          {"counted", s.counted},
          {"criterion", s.criterion},
          {"disagree", s.disagree},
          {"diverged_inside", s.diverged_inside},
          {"alive_outside", s.alive_outside},
          {"cartesian_diverged_off_origin", s.cartesian_diverged_off_origin},
          {"cartesian_diverged_at_origin", s.diverged_cartesian - s.cartesian_diverged_off_origin},
          {"inner", s.inner},
          {"inner_r_max", opt(s.inner_r_max)},
          {"inner_candidates", s.inner_candidates},
          {"outer", s.outer},
          {"outer_dist_max", opt(s.outer_dist_max)},
          {"outer_dist_all", opt(s.outer_dist_all)},
          {"outer_candidates", s.outer_candidates},
          {"H0_min_diverged", opt(s.H0_min_diverged)},
          {"H0_max_alive", opt(s.H0_max_alive)},
          {"inside_steps", steps(s.inside_steps)},
          {"outside_steps", steps(s.outside_steps)},
          {"both_finite", s.both_finite},
          {"cartesian_better", s.cartesian_better},
          {"polar_better", s.polar_better},
          {"equal", s.both_finite - s.cartesian_better - s.polar_better},
          {"fraction_cartesian_better", frac(s.cartesian_better, s.both_finite)},
          {"ties",
           {{"roundoff_tolerance", s.roundoff_tie_tolerance},
            {"roundoff", s.tied_roundoff},
            {"cartesian_better_beyond_roundoff", s.cartesian_better_beyond_roundoff},
            {"polar_better_beyond_roundoff", s.polar_better_beyond_roundoff},
            {"percent_tolerance", kEnergyMapTiePercent},
            {"percent", s.tied_percent},
            {"cartesian_better_beyond_percent", s.cartesian_better_beyond_percent},
            {"polar_better_beyond_percent", s.polar_better_beyond_percent}}},
          {"eps_difference", s.eps_difference_min
                                 ? Value{{"min", *s.eps_difference_min}, {"max", *s.eps_difference_max}}
                                 : Value()},
          {"ring_polar_better", opt(s.ring_polar_better)},
          {"off_ring_polar_better", opt(s.off_ring_polar_better)},
          {"ratio_polar_over_cartesian",
           s.ratio_median ? Value{{"p05", *s.ratio_p05}, {"median", *s.ratio_median}, {"p95", *s.ratio_p95}} : Value()}};
}

}  // namespace geomint
