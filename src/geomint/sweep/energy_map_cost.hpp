#pragma once
// What an energy error of the energy map's scalar loop (energy_map_scalar, sweep/energy_map.hpp) costs in either
// coordinate system, from a few starts at rest: one work-precision set (analysis/work_precision_set.hpp) per start,
// its methods the coordinate systems ("cartesian", "polar": coordinates_name), compiled once (energy_map_cost.cpp).
#include <string>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/sweep/energy_map.hpp"

namespace geomint {

// At every step dt of `dts` to t_end, from each start [x0, y0] of `starts`, with the pendulum and blow-up of `p`
// (its h and steps aside): the error eq. (50) of one untimed run per system, step and start (split across threads
// and ranks: distributed_map), and the wall time, a start's share of one timed function per system and step that
// integrates every start in turn (runner/timing.hpp: all of them timed together over `repeats` rounds, up to
// `workers` at a time; the loop's time per step does not depend on the start: its only branch is the divergence
// test); one force evaluation (a gradient of U) per step. `error` says what the error is (the sets' summary).
std::vector<WorkPrecisionSet> energy_map_cost_sets(const EnergyMapParams& p, double t_end, const std::vector<double>& dts,
                                                   const std::vector<std::vector<double>>& starts, int repeats,
                                                   int workers, const std::string& error);

}  // namespace geomint
