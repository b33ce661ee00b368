// energy_map: 000 (Takacs & Fulop 2025) Fig. 6 -- the RMS energy error (50) of symplectic Euler
// (42)-(43) on the elastic pendulum in Cartesian (73) and polar (72) coordinates, over a grid of
// initial positions at rest; the analytic boundary of the polar runs' divergence; and the first
// integrals of Section 5.2 (free particle).
//   Fig 6    the map, with a checkpoint for --resume, and its statistics                map.cpp
//   Sec 5.2  p_x per step in polar coordinates, the angular momentum in Cartesian ones    first_integrals.cpp
// plus what the map costs: the batched kernel against the straightforward scalar
// loop, ns per step (study `kernel_timing`, formerly `timing`)                         kernel_timing.cpp
// and the energy error against wall time and force evaluations (work-precision of the
// two coordinate systems on a few starts, study `cost`)                                cost.cpp
// Here: the studies, in the order they run, and the scene keys that several of them read.
#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/energy_map_grid.hpp"

namespace geomint::energy_map {
Study map_study(EnergyMapCost& cost);                  // 000 Fig 6 (and --resume)             map.cpp
Study first_integrals_study();                         // 000 Sec 5.2                           first_integrals.cpp
Study kernel_timing_study(const EnergyMapCost& map);   // batched kernel against scalar loop    kernel_timing.cpp
Study cost_study();                                    // work-precision, Cartesian and polar   cost.cpp
}  // namespace geomint::energy_map

using namespace geomint;
using namespace geomint::energy_map;

namespace {

Schema shared_keys() {
  Schema s;
  s.integer("grid.nx", at_least(1), "initial x0 values (inclusive linspace)")
      .integer("grid.ny", at_least(1), "initial y0 values")
      .real("grid.x_min", any_finite(), "")
      .real("grid.x_max", any_finite(), "")
      .real("grid.y_min", any_finite(), "")
      .real("grid.y_max", any_finite(), "")
      .real("pendulum.l", positive(), "relaxed spring length l (000 eqs. (72)-(73))")
      .real("pendulum.m", positive(), "mass m")
      .real("pendulum.k", positive(), "spring stiffness k")
      .real("pendulum.g", non_negative(), "gravity g (y points down)")
      .real("dt", positive(),
            "step of symplectic Euler (000 Fig. 6: 0.2); dt sqrt(k/m) below its oscillatory bound (geomint-methods)")
      .real("t_max", positive(), "end time (000 Fig. 6: 50 000); a multiple of dt")
      .real("divergence.blowup", positive(), "|H_j - H_0| above this marks a run diverged");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  EnergyMapCost map_cost;  // the map study's kernel wall time, for the timing study of the same run
  ExperimentSpec spec{"energy_map",
                      "000 Fig. 6: RMS energy error of symplectic Euler in Cartesian and polar coordinates "
                      "over initial conditions; first integrals of Sec. 5.2",
                      shared_keys(),
                      {map_study(map_cost), first_integrals_study(), kernel_timing_study(map_cost), cost_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
