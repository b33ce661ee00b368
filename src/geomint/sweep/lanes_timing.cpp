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
  for (const auto& [name, k] : kernels) {
    const RunTime lanes = k.scaled(1e9 / steps);
    const TimeRatio speedup = time_ratio(per_step, lanes);
    out["kernels"][name] = {{"ns_per_step", lanes.seconds()},  {"spread", lanes.spread()}, {"time", to_value(lanes)},
                            {"speedup_vs_scalar", speedup.median}, {"speedup_interval", {{"min", speedup.lo}, {"max", speedup.hi}}},
                            {"against_scalar", timing_verdict(time_ratio(lanes, per_step), 1, 1)}};
    if (!out.contains("isa"))  // the one the ensembles use (the widest lanes)
      out["isa"] = name, out["ns_per_step"] = lanes.seconds(), out["spread"] = lanes.spread(),
      out["speedup_vs_scalar"] = speedup.median, out["speedup_interval"] = out.at("kernels").at(name).at("speedup_interval"),
      out["against_scalar"] = out.at("kernels").at(name).at("against_scalar");
  }
  return out;
}

LanesTiming LanesConfigs::of(const std::vector<RunTime>& times) const {
  LanesTiming out{times.at(scalar).scaled(scalar_runs), {}};
  for (const auto& [name, i] : kernels) out.kernels.push_back({name, times.at(i)});
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
  for (const auto& k : simplified_ti_lanes_kernels<Sys>())
    out.kernels.emplace_back(k.name, timing.add([&sys, &starts, h, n, steps = k.steps] {
      do_not_optimize(simplified_ti_lanes(sys, steps, std::span<const Z>(starts), h, n, n, [](int, std::int64_t, const Z&) {}));
    }));
  return out;
}

#define GEOMINT_ADD_LANES(Sys)                                                                                   \
  template LanesConfigs add_lanes(InterleavedTiming&, const Sys&, const std::vector<Sys::State>&, double, std::int64_t, \
                                  std::optional<std::size_t>);
GEOMINT_ADD_LANES(LennardJones<9>)
GEOMINT_ADD_LANES(HenonHeilesT<true>)
GEOMINT_ADD_LANES(HenonHeilesT<false>)
#undef GEOMINT_ADD_LANES

}  // namespace geomint
