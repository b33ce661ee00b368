// What an energy error costs in either coordinate system (work-precision): symplectic Euler (42)-(43)
// from a few starts of the map of 000 Fig. 6 (at rest, inside the polar runs' divergence boundary) at
// several steps to cost.t_end, the scalar loop (energy_map_scalar) in both systems; the error is
// eq. (50) against H_0 = H(z_0), the wall time a start's share of one timed function (runner/timing.hpp)
// per system and step. timing_cost.csv, and per start the fitted orders and what an error target costs.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "energy_map.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::energy_map {
namespace {

// The two coordinate systems, as c = 0, 1 index the runs below.
constexpr Coordinates systems[] = {Coordinates::cartesian, Coordinates::polar};

void check_cost(const Scene& s) {
  const ElasticPendulumParams p{s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
  const double bound = method_info("symplectic_euler_pq").oscillatory_bound, omega = std::sqrt(p.k / p.m);
  const double t_end = s.real("cost.t_end");
  for (double dt : s.reals("cost.dt")) {
    if (!(dt * omega < bound))
      s.reject("cost.dt", "symplectic Euler is unstable for dt sqrt(k/m) >= " + format_double(bound) +
                              " (methods/registry.hpp): dt < " + format_double(bound / omega));
    const double n = std::round(t_end / dt);
    if (n < 1 || std::abs(n * dt - t_end) > 1e-9 * t_end)
      s.reject("cost.t_end", "must be a positive multiple of every cost.dt, here " + format_double(dt));
    if (!(n <= max_exact_count))  // steps are counted in int64 and t = j dt
      s.reject("cost.t_end", "cost.t_end / cost.dt must be at most 2^53 steps, here cost.dt = " + format_double(dt));
  }
  for (const auto& x : s.real_rows("cost.starts")) {
    const double r = std::hypot(x[0], x[1]);
    if (!(r > 0) || !(r < polar_boundary_radius(p, x[1] / r)))
      s.reject("cost.starts", "every start must lie inside the polar runs' divergence boundary r0 < 2l + (2mg/k) "
                              "cos(theta0), and not at the origin");
  }
}

StudyPlan plan_cost(const Scene& s) {
  double per_start = 0;  // steps of one start at every step size
  for (double dt : s.reals("cost.dt")) per_start += std::round(s.real("cost.t_end") / dt);
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double starts = static_cast<double>(s.real_rows("cost.starts").size());
  const double steps = 2 * starts * per_start * (1 + repeats);  // both systems: the untimed run and the timed ones
  return {steps, steps, starts * static_cast<double>(s.reals("cost.dt").size()) * 2 * 200.0, kScalarNsPerStep,
          std::string("one call per timed run (runs lengthened to >= 10 ms not counted); ") + kNsNote};
}

// Per start its record and what an error target costs there; over the starts, how often either system
// reached the target first, and the range of the ratios of force evaluations (polar over Cartesian).
struct StartCosts {
  json start_list, cost_list;
  int polar_faster, cartesian_faster, compared;
  double evals_ratio_min, evals_ratio_max;
};
StartCosts start_costs(const std::vector<std::vector<double>>& starts, const ElasticPendulumParams& pendulum,
                       const std::vector<std::vector<std::vector<CostRun>>>& curves) {
  const std::size_t ns = starts.size();
  const double u = std::numeric_limits<double>::epsilon();
  json start_list = json::array(), cost_list = json::array();
  int polar_faster = 0, cartesian_faster = 0, compared = 0;
  double evals_ratio_min = std::numeric_limits<double>::infinity(), evals_ratio_max = 0;
  for (std::size_t i = 0; i < ns; ++i) {
    const double x = starts[i][0], y = starts[i][1], r = std::hypot(x, y);
    const double spring = 0.5 * pendulum.k * (r - pendulum.l) * (r - pendulum.l), gravity = pendulum.m * pendulum.g * y;
    json st = {{"x0", x}, {"y0", y}, {"r0", r}, {"H0", spring - gravity},
               {"r0_over_boundary", r / polar_boundary_radius(pendulum, y / r)},
               // H_0 is conserved by the flow: the reference is exact, its own error the round-off of
               // evaluating H, u (|k (r - l)^2 / 2| + |m g y|) at the start
               {"reference_error", u * (std::abs(spring) + std::abs(gravity))}};
    for (std::size_t c = 0; c < 2; ++c) {
      std::vector<double> h, e;
      for (const CostRun& run : curves[c][i]) h.push_back(run.h), e.push_back(run.err);
      st["order"][coordinates_name(systems[c])] = fit_order(h, e, roundoff_floor(), "cost").order;
      st["eps_range"][coordinates_name(systems[c])] = range_of(e);
    }
    // The target: the geometric middle of the error range both systems cover at this start.
    const auto range = [&](std::size_t c) {
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (const CostRun& run : curves[c][i]) lo = std::min(lo, run.err), hi = std::max(hi, run.err);
      return std::pair{lo, hi};
    };
    const double lo = std::max(range(0).first, range(1).first), hi = std::min(range(0).second, range(1).second);
    json cost_i = {{"start", i}};
    if (lo < hi) {
      const double target = std::sqrt(lo * hi);
      st["error_target"] = target;
      const auto cart = by_decreasing_h(curves[0][i]), polar = by_decreasing_h(curves[1][i]);
      const auto wc = cost_to_reach(cart, target, &CostRun::wall_s), wp = cost_to_reach(polar, target, &CostRun::wall_s);
      const auto ec = cost_to_reach(cart, target, &CostRun::evals), ep = cost_to_reach(polar, target, &CostRun::evals);
      json t = {{"target", target},
                {"wall_s", {{"cartesian", or_null(wc)}, {"polar", or_null(wp)}}},
                {"evals", {{"cartesian", or_null(ec)}, {"polar", or_null(ep)}}},
                {"wall_ratio_polar_over_cartesian", wc && wp ? json(*wp / *wc) : json(nullptr)},
                {"evals_ratio_polar_over_cartesian", ec && ep ? json(*ep / *ec) : json(nullptr)},
                {"faster", wc && wp ? json(*wp < *wc ? "polar" : "cartesian") : json(nullptr)}};
      if (wc && wp) ++compared, (*wp < *wc ? polar_faster : cartesian_faster) += 1;
      if (ec && ep) evals_ratio_min = std::min(evals_ratio_min, *ep / *ec), evals_ratio_max = std::max(evals_ratio_max, *ep / *ec);
      cost_i.update(t);
    }
    start_list.push_back(st);
    cost_list.push_back(cost_i);
  }
  return {start_list, cost_list, polar_faster, cartesian_faster, compared, evals_ratio_min, evals_ratio_max};
}

// The energy errors and the timed runs (timing_cost.csv), then per start and over the starts (summary
// work_precision and timing.work_precision).
void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: work-precision of the two coordinate systems");
  const auto starts = s.real_rows("cost.starts");
  const auto dts = s.reals("cost.dt");
  const double t_end = s.real("cost.t_end");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const ElasticPendulumParams pendulum{s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
  const auto params = [&](double dt) {
    return EnergyMapParams{pendulum.l, pendulum.m, pendulum.k, pendulum.g, dt, steps_to(t_end, dt), s.real("divergence.blowup")};
  };
  const std::size_t ns = starts.size(), nd = dts.size();
  // The energy errors (50): one untimed run per system, step and start (split across threads and ranks).
  const auto eps = distributed_map(2 * nd * ns, [&](std::size_t task) {
    const std::size_t c = task / (nd * ns), d = task / ns % nd, i = task % ns;
    return energy_map_scalar(systems[c], params(dts[d]), starts[i][0], starts[i][1]);
  });
  // The wall time: per system and step one timed function integrates every start in turn (serial, one
  // thread); a start's share is the minimum over the repeats divided by the number of starts (the loop's
  // time per step does not depend on the start: its only branch is the divergence test).
  Csv csv({"coordinates", "start", "x0", "y0", "h", "steps", "wall_s", "force_evals", "eps", "wall_spread"});
  std::vector<std::vector<std::vector<CostRun>>> curves(2, std::vector<std::vector<CostRun>>(ns));
  SpreadTally spreads;
  json ns_per_step, ns_spread;
  for (std::size_t d = 0; d < nd; ++d) {  // (both systems at one step back to back: a busy spell hits both alike)
    for (std::size_t c = 0; c < 2; ++c) {
      const EnergyMapParams P = params(dts[d]);
      const RunTime t = time_runs(repeats, [&] {
        for (const auto& x : starts) do_not_optimize(energy_map_scalar(systems[c], P, x[0], x[1]).eps);
      });
      spreads.add(t);
      const double wall = t.seconds() / static_cast<double>(ns);
      const double evals = static_cast<double>(P.steps);  // symplectic Euler (42): one gradient of U per step
      for (std::size_t i = 0; i < ns; ++i) {
        const EnergyMapPoint& e = eps[(c * nd + d) * ns + i];
        csv.row(coordinates_name(systems[c]), static_cast<std::int64_t>(i), starts[i][0], starts[i][1], dts[d], P.steps,
                wall, P.steps, e.eps, t.spread());
        curves[c][i].push_back({dts[d], static_cast<double>(P.steps), wall, evals, e.eps});
      }
      if (dts[d] == *std::min_element(dts.begin(), dts.end())) {  // time per step at the smallest step
        ns_per_step[coordinates_name(systems[c])] = 1e9 * wall / static_cast<double>(P.steps);
        ns_spread[coordinates_name(systems[c])] = t.spread();
      }
    }
  }
  ctx.write("timing_cost.csv", csv);

  // Per start: where it lies, the reference's own error, the fitted orders; what each target costs.
  const auto [start_list, cost_list, polar_faster, cartesian_faster, compared, evals_ratio_min, evals_ratio_max] =
      start_costs(starts, pendulum, curves);
  double reference_error = 0;
  for (const auto& st : start_list) reference_error = std::max(reference_error, st["reference_error"].get<double>());
  ctx.summary["work_precision"] = {{"starts", start_list}, {"start_count", ns}, {"t_end", t_end},
                                   {"reference_error_max", reference_error},
                                   {"dt_range", range_of(dts)},
                                   {"error", "eq. (50) over [0, cost.t_end] against H_0 = H(z_0), per start"}};
  json& timing = ctx.summary["timing"]["work_precision"];
  timing = {{"ns_per_step", ns_per_step},
            {"ns_per_step_spread", ns_spread},
            {"ns_per_step_ratio_polar_over_cartesian",
             ns_per_step["polar"].get<double>() / ns_per_step["cartesian"].get<double>()},
            {"spread", spreads.to_json()},
            {"per_start", cost_list},
            {"compared", compared},
            {"evals_ratio_range", evals_ratio_max > 0 ? json{{"min", evals_ratio_min}, {"max", evals_ratio_max}} : json(nullptr)},
            {"polar_faster", polar_faster},
            {"cartesian_faster", cartesian_faster},
            {"method", "the scalar loop energy_map_scalar in both systems (not the batched kernels); per system and "
                       "step one timed function runs every start of cost.starts in turn, a start's wall time is its "
                       "share; " + timing_method_text(repeats) + "; force evaluations: one gradient of U per step"}};
}

void keys(Schema& s) {
  s.real_rows("cost.starts", 2, any_finite(), 1,
              "initial positions [x0, y0] (at rest) of the work-precision study, inside the polar runs' "
              "divergence boundary")
      .reals("cost.dt", positive(), 3, "steps of symplectic Euler in the work-precision study; each divides cost.t_end")
      .real("cost.t_end", positive(), "end time of the work-precision runs (eq. (50) over [0, t_end])");
}

}  // namespace

Study cost_study() {
  return {"cost", "cost: energy error against wall time and force evaluations, Cartesian and polar",
          {"timing_cost.csv"}, {"cost", "pendulum", "divergence", "timing.repeats"}, check_cost, run_cost, plan_cost,
          keys};
}

}  // namespace geomint::energy_map
