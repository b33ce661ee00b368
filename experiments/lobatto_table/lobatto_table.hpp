#pragma once
// lobatto_table: 001 (Dubois & Rojas-Quintero 2025) Table 1, Figs 1, 2 -- the Lobatto variational
// integrator built from its definition, against the methods the scene names; its stability set; its
// extension to nonlinear Lagrangians (Newton); and what the accuracy costs.
// One study per file beside this one (main.cpp lists them); here what several of them share: the
// oscillator of Table 1 and Figs 1, 2 and its one-step matrix, the nonlinear pendulum, the checks
// on steps and meshes, summary helpers, the comparison with published.toml and the --plan constants.
#include <optional>
#include <string>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {

// 001's scheme (13)-(14), by its registry name: the method of Table 1, Fig. 2 and the stability scan.
inline constexpr const char* kScheme = "lobatto";

using Z1 = PhaseState<1>;

// The studies, in the order they run.
Study table1_study();         // 001 Table 1                                   table1.cpp
Study figure1_study();        // 001 Fig 1                                     figure1.cpp
Study long_run_study();       // 001 Fig 2                                     long_run.cpp
Study stability_study();      // the stability set beyond 001 eq. (10)         stability.cpp
Study nonlinear_study();      // nonlinear Lagrangians (Newton)                nonlinear.cpp
Study cost_study();           // cost on the nonlinear pendulum                cost.cpp
Study long_run_cost_study();  // cost over the long run of Fig 2               long_run_cost.cpp

// The largest linear frequency of the nonlinear pendulum (U'' = cos q <= 1) and of the elastic
// pendulum of the paper scene (sqrt(k/m) = 1): the h omega at which the registry's bounds apply.
constexpr double kNonlinearOmega = 1.0;

// 001 eq. (15) from the computed map: H_d = (Phi_qp p^2 - Phi_pq q^2) / 2, i.e. c/(2 delta) p^2 - b/(2 delta) q^2.
double discrete_energy(const Mat<2>& Phi, const Z1& z);

// The one-step matrix of (the kernel of) a registered method on the oscillator at step h,
// in 001's order (p, q) of eq. (13): Phi of the Lobatto scheme, with which (15) and (13) are written.
Mat<2> pq_matrix(const std::string& method, const HarmonicOscillator& osc, double h);

Mat<2> lobatto_matrix(const HarmonicOscillator& osc, double h);

// ---- checks across keys, shared by studies ----

// The Lobatto scheme at h omega = hw (001 eq. (10)).
void check_lobatto(const Scene& s, const char* key, double hw, const std::string& what);
// The Lobatto scheme at every step h of `key` at frequency omega (`at`: said of the frequency, e.g. ", frequency 1").
void check_lobatto_steps(const Scene& s, const char* key, double omega, const std::string& at = "");

// Whole numbers of steps per period N at `key`; Lobatto (the subject, if `lobatto`) and the
// methods of `methods_key` stable at h omega = 2 pi / N.
void check_meshes(const Scene& s, const char* key, const char* methods_key, bool lobatto);

// `method` (of `methods_key`) stable at every step of nonlinear.h, at the pendulums' linear frequency 1.
void check_pendulum_steps(const Scene& s, const char* methods_key, const std::string& method);

// Every step of nonlinear.h divides nonlinear.t_end (the runs end at t_end, where the reference is),
// checked in double before the step count is rounded to an integer.
void check_nonlinear_steps(const Scene& s);

// ---- the oscillator of Table 1 and Figs 1, 2 ----

struct Oscillator {
  HarmonicOscillator osc;
  double A, T;  // amplitude q(0), period 2 pi / omega
  Z1 z0;        // (q, p) = (A, 0)
};

Oscillator oscillator(const Scene& s);

// ---- the nonlinear pendulum of the nonlinear and cost studies ----

struct Pendulum {
  NonlinearPendulum pend;
  Z1 z0;  // (q, p) = (nonlinear.pendulum_q0, 0)
};

Pendulum pendulum(const Scene& s);

// ---- What each study would cost (--plan), from the scene before any work ----
//
// Steps are counted in double (t_end = 1e300 gives a huge count, refused by the runner, not an overflowed
// integer). The ns per step are experiments/plan_rates.toml's; force evaluations per step are the largest
// of summary cost.pendulum.by_method.*.evals_per_step.

constexpr double kCellBytes = 24;            // one CSV cell held in memory (text and separator)
constexpr double kStateBytes = sizeof(Z1);   // one stored (q, p)
constexpr double kOscillatorEvals = 11;      // force evaluations per step on the oscillator (Lobatto, the most)
constexpr double kPendulumEvals = 16;        // per step on the nonlinear pendulum (Lobatto's Newton, the most)

double period_of(const Scene& s);

// summary.cost.method: how the runs of both cost studies (cost, long_run_cost) are timed; the same text
// from either, so that each may run alone or after the other (merge of runner/results.hpp).
std::string cost_method_text(int repeats);

}  // namespace geomint::lobatto_table
