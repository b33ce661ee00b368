#pragma once
// ti_drift: 004 (On energy conservation of the simplified Takahashi-Imada method) Figs 1-6, the
// symplecticity check and the cost of the methods. One study per file beside this one (main.cpp lists
// them); here what several of them share: the phase-space types, the summary helper, the oscillator
// of Fig. 1 (whose force evaluations per step every --plan counts), the Lennard-Jones starts of Fig. 6,
// the step checks and the --plan rates, the Henon-Heiles starts of Figs 3-5 and their checks, and the ensemble
// of Figs 4-5.
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint {
struct EpisodeRule;  // (analysis/episode_cuts.hpp)
}  // namespace geomint

namespace geomint::ti_drift {

using Z1 = PhaseState<1>;
using Z2 = PhaseState<2>;

// The ensemble study's trajectory with the largest error (Trajectory, below), for the poincare study of the same
// process: empty until the ensemble study has run in it (the poincare study then integrates the ensemble itself).
struct Trajectory;
using LargestError = std::optional<Trajectory>;

// The studies, in the order they run.
Study oscillator_study();      // 004 Fig 1                                            oscillator.cpp
Study pendulum_study();        // 004 Fig 2                                            pendulum.cpp
Study hh3_study();             // 004 Fig 3                                            hh3.cpp
Study ensemble_study(LargestError& largest);         // 004 Fig 4                      ensemble.cpp
Study poincare_study(const LargestError& largest);   // 004 Fig 5                      poincare.cpp
Study episode_sides_study();                         // 004 Fig 5 over many starts     episode_sides.cpp
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
double lj_grid_stiffness();  // omega_max^2 = max eig U'' at the grid (observables/stiffness.hpp)

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

// ---- Figs 3-5: the Henon-Heiles system and its starts

// Calls f with the Henon-Heiles system of Figs 4-5: exponent hh.k, coupling hh.coupling (compiled out if 0).
template <class F>
decltype(auto) with_ensemble_system(const Scene& s, F&& f) {
  return with_henon_heiles(static_cast<int>(s.integer("hh.k")), s.real("hh.coupling"), f);
}

// Start i of the Fig. 4 ensemble: (hh3.q2, hh3.p2) perturbed, each trajectory its own stream seeded by (seed, i).
template <class HH>
Z2 ensemble_start(const Scene& s, const HH& hhk, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("ensemble.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("ensemble.perturbation"), s.real("ensemble.perturbation"));
  const double dq = u(rng), dp = u(rng);
  return hhk.start(s.real("hh3.q2") + dq, s.real("hh3.p2") + dp, s.real("hh.H0"));
}

// The scene's rule for the growth episodes of Fig. 5 (ensemble.episode_*) in samples of sample_dt
// (analysis/episode_cuts.hpp).
EpisodeRule episode_rule(const Scene& s, double sample_dt);
void check_episode_rule(const Scene& s);  // its widths do not exceed t_end

// The Henon-Heiles starts q1 = 0, q2 in [q2 - d, q2 + d], p2 in [p2 - d, p2 + d] (d: the ensemble's
// perturbation, 0 for one start) lie in the bounded well below the escape energy (the lowest saddle of
// U): hh.H0 below it, every q2 between the saddles on the axis (q2 < 1, and q2 > -1 for even k: U(0, .)
// is monotone on either side of 0 there, so p1^2 = 2 (H0 - U(0, q2)) - p2^2 > 0 at the corners of the
// box holds on all of it), and the step h below the bound at the frequency of the linearisation at the
// start, max eig U''(0, q2) (a necessary condition).
// Compiled once, in ti_drift.cpp, for HenonHeilesT<true> and HenonHeilesT<false>.
template <class HH>
void check_hh_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h);

// ---- Figs 4-5: the ensemble, which Fig. 4 (study ensemble, ensemble.cpp) and Fig. 5 (study poincare,
// poincare.cpp) read: the error of the modified energy E of (3.3) and (4.2) of every trajectory at its output times,
// and the trajectory with the largest error, which Fig. 5 cuts. The poincare study takes that trajectory from the
// ensemble study when both run in one process, and integrates the ensemble itself otherwise (integrate_ensemble:
// the same starts, checkpoint and numbers).

// The ensemble as run: the error of E of each trajectory at its ns output times, every4 steps apart.
struct Run {
  double h, t_end;
  std::size_t M;
  std::int64_t n4, every4;
  std::vector<Z2> starts;
  std::vector<std::vector<double>> series;  // per trajectory
  std::size_t ns;
  double wall4;  // (on --resume: the part run since)
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

// The scene keys the ensemble depends on (its checkpoint "ensemble"): both studies read them.
const std::vector<std::string> kEnsembleKeys = {"h", "t_end", "samples", "hh", "ensemble.size", "ensemble.seed",
                                                "ensemble.perturbation", "hh3.q2", "hh3.p2"};

// The ensemble of the scene along the simplified method (1.6), in SIMD lanes (bit for bit the scalar method),
// checkpointed (checkpoint "ensemble"; --resume), whichever study runs it (ensemble.cpp).
Run integrate_ensemble(Context& ctx);

// The checks of the ensemble's scene values before any work: the starts in the bounded well, two steps at least.
void check_ensemble_run(const Scene& s);

// The trajectory with the largest max_k |E_k - E_0| (the first of equal ones).
std::size_t largest_error(const Run& run);

// One trajectory of a run: its index in the ensemble, its start and recorded error, and the run's steps and
// output times (LargestError: the one the ensemble study hands to the poincare study).
struct Trajectory {
  std::size_t index;
  Z2 start;
  std::vector<double> e;
  double h, t_end;
  std::int64_t n4, every4;
  std::size_t ns;
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

inline Trajectory trajectory_of(const Run& run, std::size_t i) {
  return {i, run.starts[i], run.series[i], run.h, run.t_end, run.n4, run.every4, run.ns};
}

}  // namespace geomint::ti_drift
