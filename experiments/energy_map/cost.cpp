// What an energy error costs in either coordinate system (study `cost`): symplectic Euler (42)-(43) from
// a few starts of the map of 000 Fig. 6 (at rest, inside the polar runs' divergence boundary) at several
// steps to cost.t_end, the scalar loop (energy_map_scalar) in both systems. One work-precision set per
// start (sweep/energy_map_cost.hpp), "start_<i>", methods "cartesian" and "polar": the error is eq. (50)
// against H_0 = H(z_0), the wall time a start's share of one timed function (runner/timing.hpp) per system
// and step, one force evaluation per step. Per start besides (summary work_precision, not a
// cost): where it lies, the reference's own error, the fitted orders and the error target, the
// geometric middle of the error range both systems cover there.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/sweep/energy_map_cost.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::energy_map {
namespace {

// The two coordinate systems, as c = 0, 1 index the runs below.
constexpr Coordinates systems[] = {Coordinates::cartesian, Coordinates::polar};

void check_cost(const Scene& s) {
  check_oscillatory_bound(s, {"cost.dt", spring_frequency(s), false, ", omega = sqrt(k/m)"}, "cost.dt", "symplectic_euler_pq");
  check_whole_steps(s, "cost.dt", "cost.t_end", "cost.t_end");
  const ElasticPendulumParams p = elastic_pendulum_params(s);
  for (const auto& x : s.real_rows("cost.starts")) {
    const double r = std::hypot(x[0], x[1]);
    if (!(r > 0) || !(r < polar_boundary_radius(p, x[1] / r)))
      s.reject("cost.starts", "every start must lie inside the polar runs' divergence boundary r0 < 2l + (2mg/k) "
                              "cos(theta0), and not at the origin");
  }
}

StudyPlan plan_cost(const Scene& s) {
  const PlanRate& rate = plan_rate("energy map scalar loop");
  const double starts = static_cast<double>(s.real_rows("cost.starts").size());
  double steps = 0;
  std::vector<TimedCall> calls;  // per system and step: every start in turn
  for (double dt : s.reals("cost.dt")) {
    const double n = std::round(s.real("cost.t_end") / dt);
    steps += 2 * starts * n;  // (the untimed runs, both systems)
    calls.insert(calls.end(), 2, TimedCall{starts * n, rate.ns_per_step});
  }
  StudyPlan p;
  p.steps = steps, p.force_evals = steps, p.ns_per_step = rate.ns_per_step;
  p.memory_bytes = starts * static_cast<double>(s.reals("cost.dt").size()) * 2 * 200.0;
  p.note = "the untimed runs, then the timing protocol; " + rate.note;
  p.time(s, calls);
  return p;
}

// Per start: where it lies, the reference's own error, the fitted orders and the ranges of eps per
// system, and its error target (summary work_precision.starts; none where the ranges do not overlap).
// The fitted orders are recorded in `summary` (runner/fits.hpp) as start `i`'s.
Value start_facts(const std::vector<double>& x0, const ElasticPendulumParams& pendulum, const WorkPrecisionSet& set,
                  Value& summary, std::size_t i) {
  const double u = std::numeric_limits<double>::epsilon();
  const double x = x0[0], y = x0[1], r = std::hypot(x, y);
  const double spring = 0.5 * pendulum.k * (r - pendulum.l) * (r - pendulum.l), gravity = pendulum.m * pendulum.g * y;
  Value st = {{"x0", x}, {"y0", y}, {"r0", r}, {"H0", spring - gravity},
              {"r0_over_boundary", r / polar_boundary_radius(pendulum, y / r)},
              // H_0 is conserved by the flow: the reference is exact, its own error the round-off of
              // evaluating H, u (|k (r - l)^2 / 2| + |m g y|) at the start
              {"reference_error", u * (std::abs(spring) + std::abs(gravity))}};
  double lo = 0, hi = std::numeric_limits<double>::infinity();  // the error range both systems cover
  for (const Coordinates c : systems) {
    std::vector<double> h, e;  // in the order of cost.dt
    for (const WorkPrecisionRecord& rec : set.records())
      if (rec.method == coordinates_name(c)) h.push_back(rec.h), e.push_back(rec.err);
    const OrderFit fit = fit_order(h, e, roundoff_floor(), "cost");
    st["order"][coordinates_name(c)] = fit.order;
    record_order_fit(summary, "work_precision.starts." + std::to_string(i) + ".order." + coordinates_name(c),
                     {"cost_start_" + std::to_string(i) + ".csv", "h", "err", {{"method", coordinates_name(c)}}}, fit,
                     roundoff_floor());
    st["eps_range"][coordinates_name(c)] = range_of(e);
    lo = std::max(lo, *std::min_element(e.begin(), e.end())), hi = std::min(hi, *std::max_element(e.begin(), e.end()));
  }
  if (lo < hi) st["error_target"] = std::sqrt(lo * hi);
  return st;
}

// What the paper quotes of the sets (summary cost, beside cost.start_<i>): per start the polar cost to its
// target over the Cartesian one (wall time and evaluations) and which system is faster; over the starts,
// how often either was faster and the range of the ratios of evaluations; the ratio of ns per step.
void cost_ratios(Value& cost, std::size_t ns) {
  // ns per step: every start shares the timed function; the polar over the Cartesian, with the interval from
  // the quartiles (runner/timing.hpp), which carries over to each start's ratio of wall times (the set's
  // ratios_to, whose reference is the Cartesian system where both reach the target)
  const Value by0 = cost.at("start_0").at("by_method");
  const auto step = [&](const char* m, const char* q) { return by0.at(m).at(q).number(); };
  Value per_start = Value::list();
  int polar_faster = 0, cartesian_faster = 0, indistinguishable = 0, compared = 0;
  double evals_lo = std::numeric_limits<double>::infinity(), evals_hi = 0;
  for (std::size_t i = 0; i < ns; ++i) {
    const Value st = cost.at("start_" + std::to_string(i));  // (a copy: cost grows below)
    const auto to = [&](const char* c, const char* what) {
      const Value& v = st.at("by_method").at(c).at(what);
      return v.size() > 0 && v.at(0).is_number() ? std::optional<double>(v.at(0).number()) : std::nullopt;
    };
    const auto wc = to("cartesian", "wall_s_to"), wp = to("polar", "wall_s_to");
    const auto ec = to("cartesian", "evals_to"), ep = to("polar", "evals_to");
    Value faster;
    if (wc && wp) {  // (both reach it: the Cartesian system, first, is the reference)
      const std::string v = st.at("ratios_to").at(0).at("by_method").at("polar").at("verdict").text();
      faster = v == "faster" ? "polar" : v == "slower" ? "cartesian" : "indistinguishable";
      ++compared, (v == "faster" ? polar_faster : v == "slower" ? cartesian_faster : indistinguishable) += 1;
    }
    if (ec && ep) evals_lo = std::min(evals_lo, *ep / *ec), evals_hi = std::max(evals_hi, *ep / *ec);
    per_start.push_back({{"wall_ratio_polar_over_cartesian", wc && wp ? Value(*wp / *wc) : Value()},
                         {"evals_ratio_polar_over_cartesian", ec && ep ? Value(*ep / *ec) : Value()},
                         {"faster", faster}});
  }
  cost["ns_per_step_ratio_polar_over_cartesian"] = step("polar", "ns_per_step") / step("cartesian", "ns_per_step");
  cost["ns_per_step_ratio_interval"] = {{"min", step("polar", "ns_per_step_q1") / step("cartesian", "ns_per_step_q3")},
                                        {"max", step("polar", "ns_per_step_q3") / step("cartesian", "ns_per_step_q1")}};
  cost["timing_drift"] = std::max(step("polar", "ns_per_step_drift"), step("cartesian", "ns_per_step_drift"));
  cost["independent_timings"] = 1;  // (every start's wall ratio carries the one timed ratio per step: one claim)
  cost["per_start"] = per_start;
  cost["compared"] = compared, cost["polar_faster"] = polar_faster, cost["cartesian_faster"] = cartesian_faster;
  cost["indistinguishable"] = indistinguishable;
  cost["evals_ratio_range"] = evals_hi > 0 ? Value{{"min", evals_lo}, {"max", evals_hi}} : Value();
}

// The kernel_timing study of the same run times the same loop, energy_map_scalar, on other starts, another
// step and one configuration at a time: per system the ratio of its ns per step to this study's (at the
// smallest step), and whether the two agree, within the larger of the two measurements' drifts plus the
// larger of their spreads (interquartile range over median).
Value same_loop(const Value& cost, const Value& timing) {
  Value out;
  std::string verdict = "agree";
  for (const char* c : {"cartesian", "polar"}) {
    const Value& here = cost.at("start_0").at("by_method").at(c);
    const double ratio = timing.at("scalar_ns_per_step").at(c).number() / here.at("ns_per_step").number();
    const double allowance = std::max(here.at("ns_per_step_drift").number(), timing.at("scalar_drift").number()) +
                             std::max(here.at("ns_per_step_spread").number(), timing.at("scalar_ns_per_step_spread").at(c).number());
    out[c] = {{"ratio", ratio}, {"allowance", allowance}};
    if (std::abs(std::log(ratio)) > std::log1p(allowance)) verdict = "differ beyond the drift and spread";
  }
  out["verdict"] = verdict;
  return out;
}

// cost_start_<i>.csv and summary cost.start_<i> per start, its facts in summary work_precision.
void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: work-precision of the two coordinate systems");
  const auto starts = s.real_rows("cost.starts");
  const auto dts = s.reals("cost.dt");
  const double t_end = s.real("cost.t_end");
  const ElasticPendulumParams pendulum = elastic_pendulum_params(s);
  const auto sets = energy_map_cost_sets({pendulum.l, pendulum.m, pendulum.k, pendulum.g, 0, 0, s.real("divergence.blowup")}, t_end,
                                         dts, starts, static_cast<int>(s.integer("timing.repeats")), ctx.threads,
                                         "eq. (50) over [0, cost.t_end] against H_0 = H(z_0)");
  Value start_list = Value::list(), cost;
  double reference_error = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Value st = start_facts(starts[i], pendulum, sets[i], ctx.summary, i);
    reference_error = std::max(reference_error, st.at("reference_error").number());
    const std::string name = "start_" + std::to_string(i);
    ctx.write("cost_" + name + ".csv", sets[i].csv());
    cost[name] = sets[i].summary(st.contains("error_target") ? std::vector{st.at("error_target").number()} : std::vector<double>{});
    start_list.push_back(st);
  }
  Value labels;  // the sets' methods (coordinate systems) as a figure names them
  for (Coordinates c : systems) labels[coordinates_name(c)] = coordinates_label(c);
  ctx.summary["work_precision"] = {{"starts", start_list}, {"start_count", starts.size()}, {"t_end", t_end},
                                   {"labels", labels},
                                   {"reference_error_max", reference_error},
                                   {"dt_range", range_of(dts)},
                                   {"error", "eq. (50) over [0, cost.t_end] against H_0 = H(z_0), per start"}};
  cost["method"] = "the scalar loop energy_map_scalar in both systems (not the batched kernels); per system and step "
                   "one timed function runs every start of cost.starts in turn, a start's wall time is its share; " +
                   timing_method_text(static_cast<int>(s.integer("timing.repeats"))) +
                   "; force evaluations: one gradient of U per step; ns_per_step at the smallest h";
  cost_ratios(cost, starts.size());
  if (ctx.summary.contains("timing")) cost["scalar_loop_against_kernel_timing"] = same_loop(cost, ctx.summary.at("timing"));
  ctx.summary["cost"] = cost;
}


}  // namespace

Study cost_study() {
  return {.name = "cost",
          .about = "cost: energy error against wall time and force evaluations, Cartesian and polar",
          .files = {"cost_start_*.csv"},
          .keys = Schema()
                      .real_rows("cost.starts", 2, any_finite(), 1,
                                 "initial positions [x0, y0] (at rest) of the work-precision study, inside the polar "
                                 "runs' divergence boundary")
                      .reals("cost.dt", positive(), 3,
                             "steps of symplectic Euler in the work-precision study; each divides cost.t_end")
                      .real("cost.t_end", positive(), "end time of the work-precision runs (eq. (50) over [0, t_end])"),
          .reads = {"pendulum", "divergence", "timing.repeats"},
          .run = run_cost,
          .validate = check_cost,
          .plan = plan_cost};
}

}  // namespace geomint::energy_map
