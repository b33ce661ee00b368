#pragma once
// rowlands_convergence: 000 (Takacs & Fulop 2025) Fig. 4 -- Stormer-Verlet (26)-(28) against the
// Rowlands method (30)-(37) on the elastic pendulum (73), and what the accuracy costs.
// One study per file beside this one (main.cpp lists them); here what both of them share: the
// pendulum and the initial conditions of the scene, the checks of its steps and methods, what both
// report about the scene, and the --plan constants.
#include <string>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::rowlands_convergence {

using State = PhaseState<2>;

// The studies, in the order they run.
Study convergence_study();  // 000 Fig 4                                                   convergence.cpp
Study cost_study();         // `timing`: error against wall time and force evaluations   cost.cpp

// A row [x, y, px, py] of the scene's `initial`.
State state_of(const std::vector<double>& row);

// The scene's pendulum.l, pendulum.m, pendulum.k, pendulum.g.
ElasticPendulumParams pendulum_of(const Scene& s);

// What `methods` and `timing.methods` may name: the methods that step the pendulum.
std::vector<std::string> pendulum_method_choices();

// What both studies report about the scene: the step sizes and the initial conditions.
void scene_summary(Context& ctx);

// The methods named under `key`: each once, each able to step the pendulum,
// and every h sqrt(k/m) below each one's oscillatory bound (the registry's).
void check_methods(const Scene& s, const char* key);

// Each h divides t_end (at most 2^53 steps); no initial condition at the pivot x = y = 0.
void check_common(const Scene& s);

// ---- What each study would cost (--plan), from the scene before any work ----
// Steps in double (t_end / h summed over the runs); ns per step from experiments/plan_rates.toml; force
// evaluations per step measured on the paper scene (results/rowlands_convergence, summary
// timing.cost.*.evals_per_step: the most evaluations per step, odeint_rkn_sb3a).

inline const PlanRate& step_rate() { return plan_rate("elastic pendulum rowlands"); }
constexpr double kEvalsPerStep = 6; // the most of the paper scene's methods (odeint_rkn_sb3a)
constexpr double kCellBytes = 24;   // one CSV cell held in memory

}  // namespace geomint::rowlands_convergence
