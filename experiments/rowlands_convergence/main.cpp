// rowlands_convergence: 000 (Takacs & Fulop 2025) Fig. 4 -- Stormer-Verlet
// (26)-(28) against the Rowlands method (30)-(37) on the elastic pendulum
// (73), and what the accuracy costs. The methods are named by the scene (any
// registered method that steps the pendulum); CSV columns and summary keys use
// their registry labels.
//   Fig 4  energy error (50) and phase-space error at t_max against h, for
//          several initial conditions; fitted orders (study `convergence`)    convergence.cpp
// plus what the accuracy costs, against odeint's own steppers: error against
//          wall time and force evaluations (study `cost`)                     cost.cpp
// Here: the studies, in the order they run, and the scene keys that both of them read.
#include "geomint/runner/experiment.hpp"

namespace geomint::rowlands_convergence {
Study convergence_study();  // 000 Fig 4                                                   convergence.cpp
Study cost_study();         // `timing`: error against wall time and force evaluations   cost.cpp
}  // namespace geomint::rowlands_convergence

using namespace geomint;
using namespace geomint::rowlands_convergence;

namespace {

Schema shared_keys() {
  Schema s;
  s.real("pendulum.l", positive(), "relaxed spring length l (000 eq. (73))")
      .real("pendulum.m", positive(), "mass m")
      .real("pendulum.k", positive(), "spring stiffness k")
      .real("pendulum.g", non_negative(), "gravitational acceleration g (0: no gravity term)")
      .real_rows("initial", 4, any_finite(), 1,
                 "initial conditions [x, y, px, py]; the first is drawn in Fig. 4 and timed, orders are fitted for each")
      .real("t_end", positive(), "t_max: end of every run (000 Fig. 4: 4)")
      .reals("h", positive(), 3,
             "step sizes; each divides t_end, and h sqrt(k/m) is below the oscillatory bound of every named method");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"rowlands_convergence",
                      "000 Fig. 4: Stormer-Verlet against the Rowlands method on the elastic pendulum, "
                      "with what the accuracy costs",
                      shared_keys(),
                      {convergence_study(), cost_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
