#pragma once
// ti_drift: 004 (On energy conservation of the simplified Takahashi-Imada method) Figs 1-6, the
// symplecticity check and the cost of the methods. One study per file beside this one (main.cpp lists
// them); here what several of them share: the phase-space types, the summary helper, the oscillator
// of Fig. 1 (whose force evaluations per step every --plan counts), the Lennard-Jones starts of Fig. 6,
// the step checks and the --plan constants. The Henon-Heiles starts and their checks:
// henon_heiles_starts.hpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint::ti_drift {

using Z1 = PhaseState<1>;
using Z2 = PhaseState<2>;

// The ensemble study's trajectory with the largest error (ensemble.hpp), for the poincare study of the same
// process: empty until the ensemble study has run in it (the poincare study then integrates the ensemble itself).
struct Trajectory;
using LargestError = std::optional<Trajectory>;

// The studies, in the order they run.
Study oscillator_study();      // 004 Fig 1                                            oscillator.cpp
Study pendulum_study();        // 004 Fig 2                                            pendulum.cpp
Study hh3_study();             // 004 Fig 3                                            hh3.cpp
Study ensemble_study(LargestError& largest);         // 004 Fig 4                      ensemble.cpp
Study poincare_study(const LargestError& largest);   // 004 Fig 5                      poincare.cpp
Study lj_study();              // 004 Fig 6                                            lj.cpp
Study lj_steps_study();        // 004 Fig 6: sigma against h (the printed step)        lj_steps.cpp
Study cost_study();            // cost: error against wall time and force evaluations  cost.cpp
Study symplecticity_study();   // 004 Sect. 1.3: symplectic against volume-preserving  symplecticity.cpp
Study kernel_timing_study();   // cost: ns per step of each method                     kernel_timing.cpp

// ---- summary.json

// The method a figure's trajectories are stepped with, the simplified method (1.6) unprocessed at the alpha of
// (1.4): summary methods.<study> (its label) and ti_alpha, which the figure's title names.
void put_trajectory_method(Context& ctx, const std::string& study);

// The slope of the least-squares line through (x, y).
double slope(const std::vector<double>& x, const std::vector<double>& y);

// ---- The systems

// Fig. 1 (and the cost study): the harmonic oscillator, omega = 1.
inline const HarmonicOscillator kOscillator{1.0, 1.0};

// Force evaluations in one step of a method's kernel (a gradient, a force or a
// Hessian-vector product counts one: systems/counting.hpp).
std::int64_t evals_per_step(const std::string& method);
// The start of a figure's fit window (power laws and drifts over [t_min, t_end]): <section>.fit_from of t_end.
double fit_t_min(const Scene& s, const std::string& section, double t_end);

// Fig. 6: the Lennard-Jones cluster.
using LJ = LennardJones<9>;
using Z18 = PhaseState<18>;

Vec<2> lj_grid(int k);  // (i, j), i, j in {1, 2, 3}

// Start i of Fig. 6: the grid with each coordinate perturbed uniformly by at most lj.perturbation, p = 0, from the
// stream seeded by (lj.seed, i).
Z18 lj_start_of(const Scene& s, std::size_t i);

// ---- Checks before any work, and --plan

// The step of the simplified method (and of the timed kernels) below the oscillatory bound the registry declares,
// at the highest frequency omega of the motion linearised where the study runs (observables/stiffness.hpp).
void check_step_bound(const Scene& s, const char* step_key, double h, double omega, const std::string& where);

// The samples a run of n steps keeps: every max(1, floor(n / samples)) steps, from step 0.
double kept_samples(double n, double samples);

// --plan's rates (experiments/plan_rates.toml): a Henon-Heiles trajectory by a scalar method, and the
// ensembles in SIMD lanes (Henon-Heiles; Lennard-Jones with its processing every sample).
inline const PlanRate& hh_rate() { return plan_rate("henon-heiles splitting"); }
inline const PlanRate& hh_lanes_rate() { return plan_rate("henon-heiles lanes"); }
inline const PlanRate& lj_lanes_rate() { return plan_rate("lennard-jones lanes"); }

}  // namespace geomint::ti_drift
