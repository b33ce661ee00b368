#pragma once
// energy_map: 000 (Takacs & Fulop 2025) Fig. 6, the first integrals of Sec. 5.2, and what the map
// costs. One study per file beside this one (main.cpp lists them); here what several of them share:
// the map's grid and parameters (map, timing), what the map study measured for the timing study of
// the same run, the names of the two coordinate systems, the checks of dt and t_max, and the --plan
// constants.
#include <cstddef>
#include <string>
#include <vector>

#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/energy_map.hpp"

namespace geomint::energy_map {

// What the map study measured, for the timing study of the same run.
struct MapCost {
  bool ran = false;
  double wall_cart = 0, wall_polar = 0;  // wall time of the batched kernel, per coordinate system
  double steps_cart = 0, steps_polar = 0;  // trajectory-steps computed in this run (a resumed run: the rest)
};

// The studies, in the order they run.
Study map_study(MapCost& cost);                  // 000 Fig 6 (and --resume)             map.cpp
Study first_integrals_study();                   // 000 Sec 5.2                           first_integrals.cpp
Study kernel_timing_study(const MapCost& map);   // batched kernel against scalar loop    kernel_timing.cpp
Study cost_study();                              // work-precision, Cartesian and polar   cost.cpp

// The scene keys the map depends on (the map study adds `checkpoint`, the timing study `timing`).
inline const std::vector<std::string> kMapKeys = {"dt", "t_max", "grid", "pendulum", "divergence"};

// The map's grid of initial positions at rest, padded to whole batches (x0 = y0 = 0 fills:
// marked dead at once), and its parameters.
struct MapSetup {
  std::vector<double> xs, ys;
  std::size_t npoints, nbatches;
  std::vector<double> x0, y0;  // nbatches * kEnergyMapBatch, x fastest
  EnergyMapParams P;
};

MapSetup map_setup(const Scene& s);

const char* coordinates_name(Coordinates c);
const char* coordinates_label(Coordinates c);  // its name in a figure, with its equation of 000: "polar (72)"
// sqrt(pendulum.k / pendulum.m), the spring's frequency that bounds the step; refuses one that is not finite and positive.
double spring_frequency(const Scene& s);

// The checks of the map's grid and step (the map and the timing study): x_max >= x_min, y_max >= y_min,
// symplectic Euler stable at dt, t_max a multiple of dt.
void check_map(const Scene& s);

// ---- plans (--plan, and the counts checked before any work): counts in double from the scene ----

// The batched kernel's own ceiling in cycles per trajectory-step: its multiplies and FMAs on two multiply
// pipes, counted in its compiled object (bench/README.md); 0 where not counted (SSE2).
inline double kernel_ceiling_cycles(const std::string& isa, Coordinates c) {
  const bool polar = c == Coordinates::polar;
  return isa == "avx512" ? (polar ? 2.7 : 1.5) : isa == "avx2" ? (polar ? 5.4 : 3.125) : 0.0;
}

// --plan's rates (experiments/plan_rates.toml): the batched kernel of the instruction set it runs on this CPU,
// and the scalar loop.
inline const PlanRate& kernel_rate() { return plan_rate("energy map kernel " + energy_map_kernels().front().isa); }
inline const PlanRate& scalar_rate() { return plan_rate("energy map scalar loop"); }

struct GridCount {
  double points, batches, steps;  // grid points, batches of 64 (padded), steps per trajectory (t_max / dt)
};
GridCount grid_count(const Scene& s);

}  // namespace geomint::energy_map
