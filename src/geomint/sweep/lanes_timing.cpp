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

template <class Sys>
LanesTiming time_lanes(const Sys& sys, const std::vector<typename Sys::State>& starts, double h, std::int64_t n,
                       int repeats) {
  using Z = typename Sys::State;
  const auto method = simplified_ti_method(sys, false);
  InterleavedTiming timing(repeats);  // the scalar method and each kernel, interleaved
  timing.add([&] {
    for (const Z& z : starts) do_not_optimize(integrate_inlined(method, z, h, n));
  });
  const auto kernels = simplified_ti_lanes_kernels<Sys>();
  for (const auto& k : kernels)
    timing.add([&] {
      do_not_optimize(simplified_ti_lanes(sys, k.steps, std::span<const Z>(starts), h, n, n, [](int, std::int64_t, const Z&) {}));
    });
  const std::vector<RunTime> t = timing.run();
  LanesTiming out{t.front(), {}};
  for (std::size_t i = 0; i < kernels.size(); ++i) out.kernels.push_back({kernels[i].name, t[i + 1]});
  return out;
}

template LanesTiming time_lanes(const LennardJones<9>&, const std::vector<LennardJones<9>::State>&, double, std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<true>&, const std::vector<HenonHeilesT<true>::State>&, double,
                                std::int64_t, int);
template LanesTiming time_lanes(const HenonHeilesT<false>&, const std::vector<HenonHeilesT<false>::State>&, double,
                                std::int64_t, int);

}  // namespace geomint
