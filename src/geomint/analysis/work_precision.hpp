#pragma once
// What accuracy costs (work-precision, as DiffEqDevTools' WorkPrecisionSet): the runs of one
// method at decreasing step sizes, each with its wall time, force evaluations and error; the cost
// at which the error first reaches a target, and the error at a given wall time. Both interpolate
// linearly in log-log between two measured runs and are never extrapolated: outside the measured
// range there is no value (std::nullopt).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace geomint {

struct CostRun {
  double h = 0, steps = 0;
  double wall_s = 0;  // wall time of one run
  double evals = 0;   // force evaluations of one run
  double err = 0;     // its error
};

// A run enters the analysis if every quantity is finite and positive (a log-log scale needs it).
inline bool measurable(const CostRun& r) {
  for (double v : {r.h, r.steps, r.wall_s, r.evals, r.err})
    if (!(std::isfinite(v) && v > 0)) return false;
  return true;
}

// The measurable runs, by decreasing h.
inline std::vector<CostRun> by_decreasing_h(const std::vector<CostRun>& runs) {
  std::vector<CostRun> out;
  std::copy_if(runs.begin(), runs.end(), std::back_inserter(out), measurable);
  std::stable_sort(out.begin(), out.end(), [](const CostRun& a, const CostRun& b) { return a.h > b.h; });
  return out;
}

// The cost (`&CostRun::wall_s` or `&CostRun::evals`) at which the error first falls to `target`
// along `runs` (by decreasing h): log-log interpolation between the two runs that bracket it.
inline std::optional<double> cost_to_reach(const std::vector<CostRun>& runs, double target, double CostRun::*cost) {
  for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
    const CostRun &a = runs[i], &b = runs[i + 1];
    if (a.err >= target && target >= b.err && a.err > b.err) {
      const double s = std::log(a.err / target) / std::log(a.err / b.err);
      return std::exp(std::log(a.*cost) + s * (std::log(b.*cost) - std::log(a.*cost)));
    }
  }
  return std::nullopt;
}

// The error of a curve at a given cost (`&CostRun::wall_s` or `&CostRun::evals`): log-log
// interpolation on its runs ordered by that cost.
inline std::optional<double> error_at_cost(const std::vector<CostRun>& runs, double cost, double CostRun::*member) {
  std::vector<std::pair<double, double>> curve;  // (cost, err)
  for (const CostRun& r : runs) curve.emplace_back(r.*member, r.err);
  std::sort(curve.begin(), curve.end());
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto [c0, e0] = curve[i];
    const auto [c1, e1] = curve[i + 1];
    if (c0 <= cost && cost <= c1 && c1 > c0) {
      const double s = std::log(cost / c0) / std::log(c1 / c0);
      return std::exp(std::log(e0) + s * (std::log(e1) - std::log(e0)));
    }
  }
  return std::nullopt;
}

// The error at wall time `wall`.
inline std::optional<double> error_at_wall(const std::vector<CostRun>& runs, double wall) {
  return error_at_cost(runs, wall, &CostRun::wall_s);
}

// Equal cost, the one rule of every cost comparison: the largest cost (`&CostRun::wall_s` or
// `&CostRun::evals`) at which every curve is measured, the least of their largest costs; nullopt if
// it is below the smallest cost of some curve (the curves share no range) or a curve is empty.
inline std::optional<double> equal_cost(const std::vector<std::vector<CostRun>>& curves, double CostRun::*cost) {
  if (curves.empty()) return std::nullopt;
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  for (const auto& curve : curves) {
    if (curve.empty()) return std::nullopt;
    const auto [a, b] = std::minmax_element(curve.begin(), curve.end(),
                                            [cost](const CostRun& x, const CostRun& y) { return x.*cost < y.*cost; });
    lo = std::max(lo, (*a).*cost), hi = std::min(hi, (*b).*cost);
  }
  if (!(lo <= hi)) return std::nullopt;
  return hi;
}

// The wall time of the most expensive run (the common budget at which methods are compared).
inline double largest_wall(const std::vector<CostRun>& runs) {
  double w = 0;
  for (const CostRun& r : runs) w = std::max(w, r.wall_s);
  return w;
}

// The first wall time at which the work-precision curves of two methods cross (both interpolated
// linearly in log-log between their measured runs), and the error there; nullopt if they do not
// cross where both are measured. Between the merged break points the difference of the log errors
// is linear in log(wall), so a crossing is found exactly.
struct Crossing {
  double wall_s, err;
};
inline std::optional<Crossing> crossover(const std::vector<CostRun>& a, const std::vector<CostRun>& b) {
  const auto by_wall = [](const CostRun& x, const CostRun& y) { return x.wall_s < y.wall_s; };
  const double lo = std::max(std::min_element(a.begin(), a.end(), by_wall)->wall_s,
                             std::min_element(b.begin(), b.end(), by_wall)->wall_s);
  const double hi = std::min(std::max_element(a.begin(), a.end(), by_wall)->wall_s,
                             std::max_element(b.begin(), b.end(), by_wall)->wall_s);
  if (!(lo < hi)) return std::nullopt;
  std::vector<double> walls{lo, hi};
  for (const auto* runs : {&a, &b})
    for (const CostRun& r : *runs)
      if (lo <= r.wall_s && r.wall_s <= hi) walls.push_back(r.wall_s);
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  std::optional<std::tuple<double, double, double>> prev;  // (wall, log err_a - log err_b, log err_a)
  for (double w : walls) {
    const auto ea = error_at_wall(a, w), eb = error_at_wall(b, w);
    if (!ea || !eb) continue;
    const double la = std::log(*ea), d = la - std::log(*eb);
    if (prev) {
      const auto [w0, d0, la0] = *prev;
      if (d0 == 0) return Crossing{w0, std::exp(la0)};
      if (d0 * d < 0 || d == 0) {
        const double wc = std::exp(std::log(w0) + d0 / (d0 - d) * (std::log(w) - std::log(w0)));
        return Crossing{wc, *error_at_wall(a, wc)};
      }
    }
    prev = std::make_tuple(w, d, la);
  }
  return std::nullopt;
}

}  // namespace geomint
