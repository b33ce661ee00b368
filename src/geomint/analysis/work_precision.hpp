#pragma once
// What accuracy costs (work-precision, as DiffEqDevTools' WorkPrecisionSet): the runs of one
// method at decreasing step sizes, each with its wall time, force evaluations and error; the cost
// at which the error first reaches a target, and the error at a given wall time. Both interpolate
// linearly in log-log between two measured runs and are never extrapolated: outside the measured
// range there is no value (std::nullopt).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
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

// The error at wall time `wall`: log-log interpolation on the runs ordered by wall time.
inline std::optional<double> error_at_wall(const std::vector<CostRun>& runs, double wall) {
  std::vector<std::pair<double, double>> curve;  // (wall_s, err)
  for (const CostRun& r : runs) curve.emplace_back(r.wall_s, r.err);
  std::sort(curve.begin(), curve.end());
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto [w0, e0] = curve[i];
    const auto [w1, e1] = curve[i + 1];
    if (w0 <= wall && wall <= w1 && w1 > w0) {
      const double s = std::log(wall / w0) / std::log(w1 / w0);
      return std::exp(std::log(e0) + s * (std::log(e1) - std::log(e0)));
    }
  }
  return std::nullopt;
}

// The wall time of the most expensive run (the common budget at which methods are compared).
inline double largest_wall(const std::vector<CostRun>& runs) {
  double w = 0;
  for (const CostRun& r : runs) w = std::max(w, r.wall_s);
  return w;
}

}  // namespace geomint
