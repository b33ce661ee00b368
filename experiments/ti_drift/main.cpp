// ti_drift: 004 (On energy conservation of the simplified Takahashi-Imada method) Figs 1-6 -- the
// methods the scene names (Stormer-Verlet, Takahashi-Imada (1.4), the simplified method (1.6),
// Forest-Ruth) and the energy behaviour of the simplified method:
//   Fig 1      the harmonic oscillator at equal work: errors, orders, closed forms    oscillator.cpp
//   Fig 2      the drift of the shifted energy on the unsymmetric pendulum            pendulum.cpp
//   Fig 3      the modified energy E of (3.3) and (4.2) on Henon-Heiles k = 3         hh3.cpp
//   Fig 4      its random walk over an ensemble for k = 5                             ensemble.cpp
//   Fig 5      Poincare cuts and growth episodes of the ensemble's trajectory with
//              the largest error (from the ensemble study of the same run, or the
//              ensemble integrated again: sweep/henon_heiles_ensemble.hpp)            poincare.cpp
//   Fig 5      the printed side of the cuts over the growth episodes of many starts   episode_sides.cpp
//   Fig 6      the Lennard-Jones cluster: a step-size scan and the ensemble statistics lj.cpp
//   Fig 6      sigma against h (the printed step)                                     lj_steps.cpp
//   Sect. 1.3  symplecticity against volume preservation                              symplecticity.cpp
// plus the cost: error against wall time and force evaluations (study `cost`)         cost.cpp
//            and ns per step of each method's kernel (study `kernel_timing`)          kernel_timing.cpp
// One study per figure (or analysis); the scene's sections say which run. Here: the studies, and the
// scene keys that several of them read (what they share otherwise is the library's).
#include <utility>

#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/henon_heiles_ensemble.hpp"

namespace geomint::ti_drift {

// The studies, in the order they run (each in the file of its name).
Study oscillator_study();
Study pendulum_study();
Study hh3_study();
Study ensemble_study(LargestError& largest);  // hands its trajectory with the largest error to ...
Study poincare_study(const LargestError& largest);  // ... this study of the same process
Study episode_sides_study();
Study lj_study();
Study lj_steps_study();
Study cost_study();
Study symplecticity_study();
Study kernel_timing_study();

}  // namespace geomint::ti_drift

using namespace geomint;
using namespace geomint::ti_drift;

namespace {

Schema shared_keys() {
  Schema s;
  s.real("h", positive(), "step of Figs 2-5 (004: 0.2), of the symplecticity check and of the cost runs")
      .real("t_end", positive(), "Fig. 4 time span (004: 2.5e6)")
      .real("hh3.q2", any_finite(), "Fig. 3 start q2 (q1 = 0, p1 > 0 from hh.H0); the centre of the Fig. 4 starts")
      .real("hh3.p2", any_finite(), "Fig. 3 start p2")
      .integer("hh.k", at_least(3), "exponent k of Fig. 4 (004: 5)")
      .real("hh.H0", positive(), "energy of the Henon-Heiles starts (004: 1/8)")
      .real("hh.coupling", any_finite(),
            "coefficient c of c q1^2 q2 in the potential of Figs 4-5 (004: 1); c = 0 removes the term from the "
            "compiled step")
      .integer("ensemble.size", at_least(2), "Fig. 4 trajectories (004: 100)")
      .integer("ensemble.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("ensemble.perturbation", non_negative(), "q2 and p2 of each start perturbed uniformly by at most this")
      .integer("samples", at_least(10), "output times per long run")
      .real("lj.h", positive(), "Fig. 6: the step used for the statistics")
      .integer("lj.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("lj.perturbation", non_negative(), "each coordinate of the 3 x 3 grid perturbed uniformly by at most this (004: 0.01)");
  // (checkpoint.* and timing.repeats are the runner's, common_keys(). A checkpoint's rounds are rounds of
  // trajectories: ensemble, lj, and poincare, which integrates the ensemble when the ensemble study does not run.)
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  LargestError largest;  // the ensemble study's trajectory with the largest error, for the poincare study of the same run
  ExperimentSpec spec{"ti_drift", "004 Figs 1-6: energy behaviour of the (simplified) Takahashi-Imada method",
                      shared_keys(),
                      {oscillator_study(), pendulum_study(), hh3_study(), ensemble_study(largest), poincare_study(largest),
                       episode_sides_study(), lj_study(), lj_steps_study(), cost_study(), symplecticity_study(), kernel_timing_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
