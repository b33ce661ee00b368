// lobatto_table: 001 (Dubois & Rojas-Quintero 2025) Table 1, Figs 1, 2 -- the
// Lobatto variational integrator built from its definition (P3 elements,
// quadrature (2), elimination of the internal values, momenta (11)), against
// the methods the scene names (001: Simpson's variational integrator and the
// implicit midpoint rule); its stability set; its extension to nonlinear
// Lagrangians (Newton); and what the accuracy costs.
//   Table 1  one period: errors of p, q, H and H_d (15), fitted orders         table1.cpp
//   Fig 1    trajectories over one period at N = 3, 10                        figure1.cpp
//   Fig 2    the energy error over 10^5 periods, plain and compensated        long_run.cpp
// plus the stability set beyond eq. (10), runs at 0.99 and 1.01 of the bound   stability.cpp
//      nonlinear Lagrangians (Newton): order 6, symplecticity                 nonlinear.cpp
//      cost (study cost): error against wall time, nonlinear pendulum        cost.cpp
//      cost over the long run of Fig 2: error against wall time               long_run_cost.cpp
// The compared methods are registry names (methods/registry.hpp); CSV columns and summary keys carry
// their labels. Here: the studies, in the order they run, and the scene keys that several of them read.
#include "geomint/runner/experiment.hpp"

namespace geomint::lobatto_table {
Study table1_study();         // 001 Table 1                                   table1.cpp
Study figure1_study();        // 001 Fig 1                                     figure1.cpp
Study long_run_study();       // 001 Fig 2                                     long_run.cpp
Study stability_study();      // the stability set beyond 001 eq. (10)         stability.cpp
Study nonlinear_study();      // nonlinear Lagrangians (Newton)                nonlinear.cpp
Study cost_study();           // cost on the nonlinear pendulum                cost.cpp
Study long_run_cost_study();  // cost over the long run of Fig 2               long_run_cost.cpp
}  // namespace geomint::lobatto_table

using namespace geomint;
using namespace geomint::lobatto_table;

namespace {

Schema shared_keys() {
  Schema s;
  s.real("oscillator.m", positive(), "mass m (001: 1)")
      .real("oscillator.omega", positive(), "angular frequency (001: 2 pi, period T = 1)")
      .real("oscillator.amplitude", positive(), "q(0); p(0) = 0 (001: pi/2)")
      .real("long_run.periods", at_least(1), "periods of Fig. 2 (001: 1e5)")
      .reals("nonlinear.h", positive(), 3, "steps of the nonlinear convergence study")
      .real("nonlinear.t_end", positive(), "end time of the nonlinear runs")
      .real("nonlinear.pendulum_q0", any_finite(), "initial angle of L = qdot^2/2 + cos q (p(0) = 0)");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"lobatto_table",
                      "001 Table 1, Figs 1, 2: the Lobatto variational integrator from its definition, "
                      "its stability set, nonlinear Lagrangians, and what the accuracy costs",
                      shared_keys(),
                      {table1_study(), figure1_study(), long_run_study(), stability_study(), nonlinear_study(),
                       cost_study(), long_run_cost_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
