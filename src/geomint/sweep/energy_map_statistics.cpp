#include "geomint/sweep/energy_map_statistics.hpp"

#include <array>
#include <map>

namespace geomint {

EnergyMapStatistics energy_map_statistics(const std::vector<EnergyMapRow>& rows, const ElasticPendulumParams& p,
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

Value to_value(const EnergyMapStatistics& s) {
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
          // the share of the starts at which the less often better system wins beyond round-off
          {"smaller_share_better_beyond_roundoff",
           frac(std::min(s.cartesian_better_beyond_roundoff, s.polar_better_beyond_roundoff), s.both_finite)},
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

SameEnergyWins same_energy_wins(const std::vector<EnergyMapRow>& rows, std::size_t nx, double roundoff_tie_tolerance) {
  SameEnergyWins s;
  std::vector<double> steps;  // |H_0 difference| of grid neighbours, along x and along y
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if ((i + 1) % nx != 0 && i + 1 < rows.size()) steps.push_back(std::abs(rows[i + 1].H0 - rows[i].H0));
    if (i + nx < rows.size()) steps.push_back(std::abs(rows[i + nx].H0 - rows[i].H0));
  }
  if (steps.empty()) return s;
  std::sort(steps.begin(), steps.end());
  s.band_width = nearest_rank_quantile(steps, 0.5);
  if (!(s.band_width > 0)) return s;
  double H_min = std::numeric_limits<double>::infinity();
  for (const EnergyMapRow& row : rows) H_min = std::min(H_min, row.H0);
  std::map<std::int64_t, std::array<std::int64_t, 2>> bands;  // band -> (Cartesian wins, polar wins)
  for (const EnergyMapRow& row : rows) {
    if (row.diverged_cartesian || row.diverged_polar || !std::isfinite(row.eps_cartesian) || !std::isfinite(row.eps_polar))
      continue;
    const double d = row.eps_cartesian - row.eps_polar;
    if (std::abs(d) <= roundoff_tie_tolerance * std::max(row.eps_cartesian, row.eps_polar)) continue;  // a tie
    ++s.wins, ++bands[static_cast<std::int64_t>(std::floor((row.H0 - H_min) / s.band_width))][d < 0 ? 0 : 1];
  }
  for (const auto& [band, w] : bands) {
    ++s.bands_with_wins;
    if (w[0] > 0 && w[1] > 0) ++s.mixed_bands, s.wins_in_mixed_bands += w[0] + w[1];
  }
  return s;
}

Value to_value(const SameEnergyWins& s) {
  const auto frac = [](std::int64_t a, std::int64_t b) { return b ? Value(static_cast<double>(a) / static_cast<double>(b)) : Value(); };
  return {{"band_width", s.band_width},
          {"bands_with_wins", s.bands_with_wins},
          {"mixed_bands", s.mixed_bands},
          {"share_mixed_bands", frac(s.mixed_bands, s.bands_with_wins)},
          {"wins", s.wins},
          {"share_wins_in_mixed_bands", frac(s.wins_in_mixed_bands, s.wins)}};
}

}  // namespace geomint
