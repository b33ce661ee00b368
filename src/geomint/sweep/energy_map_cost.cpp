// The energy map's scalar loop as work-precision sets (sweep/energy_map_cost.hpp).
#include "geomint/sweep/energy_map_cost.hpp"

#include <cstddef>

#include "geomint/core/integrate.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/timing.hpp"

namespace geomint {

std::vector<WorkPrecisionSet> energy_map_cost_sets(const EnergyMapParams& p, double t_end, const std::vector<double>& dts,
                                                   const std::vector<std::vector<double>>& starts, int repeats,
                                                   int workers, const std::string& error) {
  constexpr Coordinates systems[] = {Coordinates::cartesian, Coordinates::polar};
  const std::size_t ns = starts.size(), nd = dts.size();
  std::vector<EnergyMapParams> P;  // per step
  for (double dt : dts) P.push_back({p.l, p.m, p.k, p.g, dt, steps_to(t_end, dt), p.blowup});
  const auto eps = distributed_map(2 * nd * ns, [&](std::size_t task) {
    const std::size_t c = task / (nd * ns), d = task / ns % nd, i = task % ns;
    return energy_map_scalar(systems[c], P[d], starts[i][0], starts[i][1]);
  });
  std::vector<WorkPrecisionSet> sets(ns, WorkPrecisionSet(error));
  InterleavedTiming timing(repeats, kTimingFloorS, workers);  // every system and step together
  for (std::size_t d = 0; d < nd; ++d)
    for (std::size_t c = 0; c < 2; ++c)
      timing.add([&, c, d] {
        for (const auto& x : starts) do_not_optimize(energy_map_scalar(systems[c], P[d], x[0], x[1]).eps);
      });
  const std::vector<RunTime> times = timing.run();
  for (std::size_t d = 0; d < nd; ++d)
    for (std::size_t c = 0; c < 2; ++c) {
      const RunTime share = times[2 * d + c].scaled(1 / static_cast<double>(ns));  // (the same spread)
      for (std::size_t i = 0; i < ns; ++i)  // symplectic Euler (42): one gradient of U per step
        sets[i].add({coordinates_name(systems[c]), dts[d], static_cast<double>(P[d].steps), share,
                     static_cast<double>(P[d].steps), eps[(c * nd + d) * ns + i].eps});
    }
  return sets;
}

}  // namespace geomint
