#pragma once
// euler_compensation: 000 (Takacs & Fulop 2025) Figs 2, 3, 8 and 9, and what their accuracy costs.
// One study per file beside this one (main.cpp lists them); here what several of them share: the
// oscillator of Figs 8-9 with and without the compensating transformation (82), its checks and its
// --plan constants.
#include <cstdint>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::euler_compensation {

using Oscillator = HarmonicOscillator;
using State = Oscillator::State;

// The studies, in the order they run.
Study decay_study();        // 000 Fig 2      decay.cpp
Study gompertz_study();     // 000 Fig 3      gompertz.cpp
Study oscillator_study();   // 000 Fig 8      oscillator.cpp
Study convergence_study();  // 000 Fig 9      convergence.cpp
Study cost_study();         // cost of Figs 8-9's methods   cost.cpp

constexpr int kExactCurvePoints = 400;  // resolution of the exact curves in the figures

// The scene's (oscillator.q0, oscillator.p0).
State initial_state(const Scene& s);

// A non-finite state is (82) left undefined (|qhat| >= 1): say where.
void check_finite(const State& z, const std::string& method, std::int64_t j, double h);

struct EnergyRun {
  double max_err = 0, rms_err = 0;  // of H(q_j, p_j) - H(q_0, p_0), j = 0..N
  std::int64_t force_evals = 0;
  auto fields() { return std::tie(max_err, rms_err, force_evals); }  // (a record of runner/distributed_map.hpp)
};

// One convergence run of each method to t = N h, counting force evaluations.
// A call that runs n steps of a method of Figs 8-9 from z0, every call inlined: a configuration to time
// (runner/timing.hpp).
std::function<void()> oscillator_method_timed(const std::string& method, double k, const State& z0, double h,
                                              std::int64_t n);
std::vector<EnergyRun> oscillator_runs(const std::vector<std::string>& methods, const State& z0, double h, double k,
                                       std::int64_t n);

// What Figs 8-9 and the cost study may name: the methods that step the oscillator, and (82).
std::vector<std::string> oscillator_method_choices();

// A step h of Fig 8: symplectic Euler stable, the transformation (82) defined at q0.
void check_oscillator_step(const Scene& s, const char* key, double h);

// The methods of `methods_key` at the steps of `key` (runs to convergence.t_end): each method
// once, every step below its bound (and (82) defined, if named), and each h dividing t_end.
void check_steps(const Scene& s, const char* key, const char* methods_key);

// ---- --plan: steps in double; ns per step from experiments/plan_rates.toml
constexpr double kCellBytes = 24;      // one CSV cell held in memory
inline const PlanRate& oscillator_rate() { return plan_rate("oscillator compensated symplectic euler"); }
constexpr double kEvalsPerStep = 4;    // the most of the paper scene's methods (rk4)

}  // namespace geomint::euler_compensation
