#pragma once
// The energy map of 000 Fig. 6 as a scene gives it (sweep/energy_map.hpp computes it): the grid of initial
// positions at rest (grid.*), padded to whole batches of the kernel, and the map's parameters (pendulum.*,
// dt, t_max, divergence.blowup); their checks; what --plan counts of them; and what the map's run measured
// of the batched kernel, which a study of the kernel's speed in the same process takes instead of timing it
// again (experiments/energy_map: the studies map and kernel_timing).
#include <cstddef>
#include <string>
#include <vector>

#include "geomint/runner/plan_rates.hpp"
#include "geomint/sweep/energy_map.hpp"

namespace geomint {

class Context;
class Scene;

// The scene keys the map's grid and parameters are read from.
inline const std::vector<std::string> kEnergyMapKeys = {"dt", "t_max", "grid", "pendulum", "divergence"};

// The map's grid of initial positions at rest, padded to whole batches (x0 = y0 = 0 fills: marked dead at
// once), and its parameters.
struct EnergyMapGrid {
  std::vector<double> xs, ys;  // inclusive linspaces of grid.nx and grid.ny values
  std::size_t npoints, nbatches;
  std::vector<double> x0, y0;  // nbatches * kEnergyMapBatch, x fastest
  EnergyMapParams P;
};
EnergyMapGrid energy_map_grid(const Scene& s);

// The map in one coordinate system: the best kernel this CPU runs (energy_map_kernels) on every batch of the grid, as
// a checkpointed map named `name` (runner/checkpoint.hpp: a stopped run continues with --resume), the points in the
// grid's order (padding included); `computed` counts the batches this run computed (not those of the checkpoint).
std::vector<EnergyMapPoint> energy_map_points(Context& ctx, const std::string& name, const EnergyMapGrid& g, Coordinates c,
                                              std::size_t& computed);

// The checks of the map's grid and step: x_max >= x_min, y_max >= y_min, symplectic Euler (42)-(43) stable
// at dt (the registry's bound on dt sqrt(k/m)), t_max a multiple of dt in at most 2^53 steps.
void check_energy_map(const Scene& s);

// --plan's counts, in double from the scene: grid points, batches of kEnergyMapBatch (padded), steps per
// trajectory (t_max / dt).
struct EnergyMapCount {
  double points, batches, steps;
};
EnergyMapCount energy_map_count(const Scene& s);

// --plan's rate of the batched kernel of the instruction set it runs on this CPU (experiments/plan_rates.toml).
const PlanRate& energy_map_kernel_rate();

// What the map's run measured of the batched kernel, per coordinate system: its wall time and the
// trajectory-steps it computed (a resumed run: the rest); `ran` only where both systems ran in this process.
struct EnergyMapCost {
  bool ran = false;
  double wall_cart = 0, wall_polar = 0;
  double steps_cart = 0, steps_polar = 0;
};

}  // namespace geomint
