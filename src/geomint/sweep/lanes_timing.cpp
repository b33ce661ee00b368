#include "geomint/sweep/lanes_timing.hpp"

#include <span>

#include "geomint/runner/timing_report.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {

Value LanesTiming::summary(std::size_t trajectories, std::int64_t n) const {
  const double steps = static_cast<double>(trajectories) * static_cast<double>(n);
  const RunTime per_step = scalar.scaled(1e9 / steps);  // ns per trajectory-step
  Value out = {{"trajectories", trajectories}, {"steps", n}, {"scalar_ns_per_step", per_step.seconds()},
               {"scalar", to_value(per_step)}, {"scalar_spread", per_step.spread()}};
  for (const auto& [name, k, own] : kernels) {
    const RunTime lanes = k.scaled(1e9 / steps);
    const TimeRatio speedup = time_ratio(per_step, lanes);
    out["kernels"][name] = {{"ns_per_step", lanes.seconds()},  {"spread", lanes.spread()}, {"time", to_value(lanes)},
                            {"speedup_vs_scalar", speedup.median}, {"speedup_interval", {{"min", speedup.lo}, {"max", speedup.hi}}},
                            {"against_scalar", timing_verdict(time_ratio(lanes, per_step), 1, 1)},
                            {"own_ceiling_ns", own ? Value(*own) : Value()},
                            {"own_ceiling_fraction", own ? Value(*own / lanes.seconds()) : Value()}};
    if (!out.contains("isa")) {  // the one the ensembles use (the widest lanes)
      out["isa"] = name, out["ns_per_step"] = lanes.seconds(), out["spread"] = lanes.spread(), out["speedup_vs_scalar"] = speedup.median;
      for (const char* key : {"speedup_interval", "against_scalar", "own_ceiling_ns", "own_ceiling_fraction"})
        out[key] = out.at("kernels").at(name).at(key);
    }
  }
  return out;
}

LanesTiming LanesConfigs::of(const std::vector<RunTime>& times) const {
  LanesTiming out{times.at(scalar).scaled(scalar_runs), {}};
  for (const Kernel& k : kernels)
    out.kernels.push_back({k.name, times.at(k.config),
                           k.arithmetic ? std::optional(1e9 * times.at(*k.arithmetic).seconds() / k.arithmetic_steps)
                                        : std::nullopt});
  return out;
}

template <class Sys>
LanesConfigs add_lanes(InterleavedTiming& timing, const Sys& sys, const std::vector<typename Sys::State>& starts,
                       double h, std::int64_t n, std::optional<std::size_t> scalar_on_first) {
  using Z = typename Sys::State;
  LanesConfigs out;
  if (scalar_on_first) {
    out.scalar = *scalar_on_first, out.scalar_runs = static_cast<double>(starts.size());
  } else {
    out.scalar = timing.add([&sys, &starts, h, n] {
      const auto method = simplified_ti_method(sys, false);
      for (const Z& z : starts) do_not_optimize(integrate_inlined(method, z, h, n));
    });
  }
  for (const auto& k : simplified_ti_lanes_kernels<Sys>()) {
    LanesConfigs::Kernel& c = out.kernels.emplace_back();
    c.name = k.name, c.config = timing.add([&sys, &starts, h, n, steps = k.steps] {
      do_not_optimize(simplified_ti_lanes(sys, steps, std::span<const Z>(starts), h, n, n, [](int, std::int64_t, const Z&) {}));
    });
    if (const KernelArithmetic a = k.arithmetic)
      c.arithmetic = timing.add([a] { do_not_optimize(a(kArithmeticRepeats)); }), c.arithmetic_steps = a.trajectory_steps(kArithmeticRepeats);
  }
  return out;
}

template <class Sys>
std::vector<TimedCall> lanes_calls(std::int64_t n, double scalar_ns, double lanes_ns, bool scalar_on_first) {
  const double steps = static_cast<double>(kLanes<Sys>) * static_cast<double>(n);
  std::vector<TimedCall> calls;
  if (!scalar_on_first) calls.push_back({steps, scalar_ns});
  for (const auto& k : simplified_ti_lanes_kernels<Sys>()) {
    calls.push_back({steps, lanes_ns});
    if (k.arithmetic) calls.push_back({k.arithmetic.trajectory_steps(kArithmeticRepeats), lanes_ns});
  }
  return calls;
}

#define GEOMINT_ADD_LANES(Sys)                                                                                   \
  template LanesConfigs add_lanes(InterleavedTiming&, const Sys&, const std::vector<Sys::State>&, double, std::int64_t, \
                                  std::optional<std::size_t>);                                                  \
  template std::vector<TimedCall> lanes_calls<Sys>(std::int64_t, double, double, bool);
GEOMINT_ADD_LANES(LennardJones<9>)
GEOMINT_ADD_LANES(HenonHeilesT<true>)
GEOMINT_ADD_LANES(HenonHeilesT<false>)
#undef GEOMINT_ADD_LANES

}  // namespace geomint
