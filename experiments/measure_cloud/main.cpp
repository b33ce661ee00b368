// measure_cloud: 003 (García-Naranjo & Vermeeren) Sec. 5, Figs 5.1-5.6 -- the
// nonholonomic particle as a conformally Hamiltonian system, discretized by
// the variational integrators Psi_{h,E} of the five discrete Lagrangians (5.1)
// with E = E^(ell)(z_0) per trajectory (the method Phi^(ell), (4.5)). Studies:
//   shape        Fig. 5.1   a large cloud on a 3-sphere under the reference flow        shape.cpp
//   volumes      Figs 5.2, 5.4  measure-weighted convex-hull volumes of the 600-cell    volumes.cpp
//                cloud under Phi^(ell) and under the reference flow: the full cloud and,
//                beside it, the authors' cloud of the published figures (119 vertices)
//   energies     Figs 5.3, 5.5, 5.6  energies and errors along Phi^(4), Phi^(0)        energies.cpp
//   long_run     beyond the paper: drift of H under Phi^(0) against Phi^(4)             long_run.cpp
//   order_study  beyond the paper: order of measure preservation on tiny clouds         order_study.cpp
//   cost         beyond the paper: error against wall time of each discretization       cost.cpp
// The scene names the potential, the studies and the discretizations (registry
// names conformal_M ... or their labels M ...); nothing else is computed.
// Every study reads the potential and the centre cloud.center; all but order_study the reference
// flow. Here: the studies, and the scene keys that several of them read (the runner declares reference.*,
// checkpoint.* and timing.repeats: common_keys(); what else they share is the library's: analysis/phi_study.hpp).
#include <utility>

#include "geomint/methods/discretizations.hpp"
#include "geomint/runner/experiment.hpp"

namespace geomint::measure_cloud {

// The studies, in the order they run (each in the file of its name).
Study shape_study();
Study volumes_study();
Study energies_study();
Study long_run_study();
Study order_study_study();
Study cost_study();

}  // namespace geomint::measure_cloud

using namespace geomint;
using namespace geomint::measure_cloud;

namespace {

Schema shared_keys() {
  Schema s;
  s.text("potential", {"harmonic", "free"}, "U = (x^2 + y^2)/2 or U = 0 (003 Secs 5.2, 5.3)")
      .real("h", positive(), "time step (003: 0.25)")
      .real("ptp_window", positive(), "peak-to-peak volume errors are taken over t <= ptp_window (the hull stays convex)")
      .texts("methods", discretization_choices(), 1,
             "discrete Lagrangians (5.1) by registry name (conformal_M, ...) or label (M, ...); CSV columns and "
             "summary keys use the label")
      .reals("cloud.center", any_finite(), 4, "centre [x, y, px, py] of every cloud and start of every trajectory")
      .real("energies.t_end", positive(), "end time of Figs 5.3, 5.5, 5.6 (003: 10) and of the cost runs")
      .reals("order_study.h", positive(), 3, "steps of the order study and of the cost runs")
      .alias("observables", "studies");  // the older name of the studies list
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"measure_cloud", "003 Figs 5.1-5.6: measure-preserving discretization of the nonholonomic particle",
                      shared_keys(),
                      {shape_study(), volumes_study(), energies_study(), long_run_study(), order_study_study(),
                       cost_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
