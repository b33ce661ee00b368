#pragma once
// The harmonic oscillator H(q, p) = p^2/(2m) + m w^2 q^2/2: with m = w = 1 the
// dimensionless form 000 eq. (74); with m = 1, w = 2 pi the oscillator of 001. And the
// nonlinear pendulum of 001 Sec. 5. Below them, what the studies take of them: 001's oscillator
// released from rest and its one-step matrices, and 000's oscillator (74) with and without the
// compensating transformation (82).
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<HarmonicOscillator>
// geomint: MethodsOn<Counting<HarmonicOscillator>>
// geomint: MethodsOn<NonlinearPendulum>
// geomint: MethodsOn<Counting<NonlinearPendulum>>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/reference/odeint_reference.hpp"

namespace geomint {

class Scene;
struct OscillatorSteps;  // (methods/scene_methods.hpp)

struct HarmonicOscillator {
  using State = PhaseState<1>;
  static constexpr bool separable = true;  // H = T(p) + U(q)

  double m = 1.0;  // mass
  double w = 1.0;  // angular frequency omega

  double H(const State& z) const { return 0.5 * z.p[0] * z.p[0] / m + U(z.q); }  // (74) for m = w = 1
  Vec<1> H_q(const Vec<1>& q, const Vec<1>& /*p*/) const { return U_q(q); }   // (75): p' = -m w^2 q
  Vec<1> H_p(const Vec<1>& /*q*/, const Vec<1>& p) const { return p / m; }    // (76): q' = p/m
  Mat<1> H_qp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Zero(); }
  Mat<1> H_pp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Constant(1.0 / m); }
  double omega() const { return w; }

  // The mechanical form L = m qdot^2/2 - U(q), for variational integrators.
  double mass() const { return m; }
  Vec<1> inv_mass(const Vec<1>& p) const { return p / m; }
  double U(const Vec<1>& q) const { return 0.5 * m * w * w * q[0] * q[0]; }
  Vec<1> U_q(const Vec<1>& q) const { return m * w * w * q; }
  Mat<1> U_qq(const Vec<1>&) const { return Mat<1>::Constant(m * w * w); }
  Vec<1> U_qq_times(const Vec<1>&, const Vec<1>& v) const { return m * w * w * v; }
  Vec<1> force(const Vec<1>& q) const { return -U_q(q); }

  // Exact flow: q = q0 cos wt + p0/(m w) sin wt, p = -m w q0 sin wt + p0 cos wt.
  State exact(const State& z0, double t) const {
    const double c = std::cos(w * t), s = std::sin(w * t);
    State z;
    z.q[0] = c * z0.q[0] + s * z0.p[0] / (m * w);
    z.p[0] = -s * m * w * z0.q[0] + c * z0.p[0];
    return z;
  }
};

// 001 Sec. 5: L = qdot^2/2 + cos q, the nonlinear pendulum (m = 1, V = -cos q).
struct NonlinearPendulum {
  using State = PhaseState<1>;
  static constexpr bool separable = true;

  double H(const State& z) const { return 0.5 * z.p[0] * z.p[0] + U(z.q); }
  Vec<1> H_q(const Vec<1>& q, const Vec<1>&) const { return U_q(q); }
  Vec<1> H_p(const Vec<1>&, const Vec<1>& p) const { return p; }
  Mat<1> H_qp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Zero(); }
  Mat<1> H_pp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Identity(); }
  double mass() const { return 1.0; }
  Vec<1> inv_mass(const Vec<1>& p) const { return p; }
  double U(const Vec<1>& q) const { return -std::cos(q[0]); }
  Vec<1> U_q(const Vec<1>& q) const { return Vec<1>(std::sin(q[0])); }
  Mat<1> U_qq(const Vec<1>& q) const { return Mat<1>::Constant(std::cos(q[0])); }
  Vec<1> U_qq_times(const Vec<1>& q, const Vec<1>& v) const { return U_qq(q) * v; }
  Vec<1> force(const Vec<1>& q) const { return -U_q(q); }
  // The largest linear frequency: sqrt of the largest U'' = cos q, at the bottom.
  static double max_frequency() { return 1.0; }
};

// Its odeint reference (reference/odeint_reference.hpp), compiled once (harmonic_oscillator.cpp).
extern template PhaseState<1> reference_solution<NonlinearPendulum>(const NonlinearPendulum&, const PhaseState<1>&, double,
                                                                    double, double);

// ---- 001 Table 1, Figs 1, 2: the oscillator released from rest, and its one-step matrices ----

// The scene's oscillator (oscillator.m, oscillator.omega) released from rest at q = A = oscillator.amplitude:
// z0 = (q, p) = (A, 0); its period T = 2 pi / omega (harmonic_oscillator.cpp).
struct OscillatorFromRest {
  HarmonicOscillator osc;
  double A, T;
  PhaseState<1> z0;
};
OscillatorFromRest oscillator_from_rest(const Scene& s);

// The largest errors |q_j - q(t_j)| and |p_j - p(t_j)| of a trajectory z_0..z_N at step h from z0, against the
// exact flow (harmonic_oscillator.cpp).
struct PhaseErrors {
  double q, p;
};
PhaseErrors max_errors(const HarmonicOscillator& osc, const PhaseState<1>& z0, const std::vector<PhaseState<1>>& zs,
                       double h);

// The one-step matrix of (the kernel of) a registered method on the oscillator at step h, in 001's order (p, q)
// of eq. (13) (harmonic_oscillator_runs.cpp).
Mat<2> one_step_pq_matrix(std::string_view method, const HarmonicOscillator& osc, double h);

// 001 eq. (10): the Lobatto scheme below its oscillatory bound, sqrt(42 - 6 sqrt(29)), at every step of `steps`.
void check_lobatto_bound(const Scene& s, const OscillatorSteps& steps);

// 001 eq. (15), the discrete energy of a one-step matrix Phi on (p, q): H_d = (Phi_qp p^2 - Phi_pq q^2) / 2.
inline double discrete_energy(const Mat<2>& Phi, const PhaseState<1>& z) {
  return 0.5 * (Phi(1, 0) * z.p[0] * z.p[0] - Phi(0, 1) * z.q[0] * z.q[0]);
}

// ---- 000 Figs 8, 9: the oscillator (74), m = w = 1, with and without the compensating transformation (82) ----
// (harmonic_oscillator.cpp; the runs: harmonic_oscillator_runs.cpp)

// The scene's start (oscillator.q0, oscillator.p0).
PhaseState<1> oscillator_start(const Scene& s);

// What a scene may name: the registered methods that step the oscillator, their labels, and
// compensated_symplectic_euler, symplectic Euler after (82), which takes the k of (82) (oscillator.k):
// outside the registry's dispatch by name.
std::vector<std::string> compensated_oscillator_choices();

// A run's energy errors, of H(q_j, p_j) - H(q_0, p_0), j = 0..N: the largest and eq. (50); its force evaluations.
struct OscillatorEnergyErrors {
  double max_err = 0, rms_err = 0;
  std::int64_t force_evals = 0;
  auto fields() { return std::tie(max_err, rms_err, force_evals); }  // (a record of runner/distributed_map.hpp)
};

// One run of each method to t = n h from z0 on (74) (compensated_symplectic_euler with k), counting force
// evaluations; a non-finite state throws (check_compensated_state).
std::vector<OscillatorEnergyErrors> oscillator_energy_errors(const std::vector<std::string>& methods, double k,
                                                             const PhaseState<1>& z0, double h, std::int64_t n);

// A call that runs n steps of `method` on (74) from z0, every call inlined: a configuration to time
// (runner/timing.hpp).
std::function<void()> oscillator_timed(std::string_view method, double k, const PhaseState<1>& z0, double h,
                                       std::int64_t n);

// A non-finite state is (82) left undefined (|qhat| >= 1): IntegrationError, saying where.
void check_compensated_state(const PhaseState<1>& z, const std::string& method, std::int64_t j, double h);

// A step h of `key`: symplectic Euler stable on (74) (omega = 1), and (82) defined at oscillator.q0 with oscillator.k.
void check_compensated_step(const Scene& s, const char* key, double h);

// The methods of `methods_key` on (74) at the steps of `step_key` of runs to `end_key`: each method named once, each
// step dividing the run (check_whole_steps), each method below its oscillatory bound (omega = 1), and
// check_compensated_step where compensated_symplectic_euler is named.
void check_compensated_methods(const Scene& s, const char* step_key, const char* methods_key, const char* end_key);

}  // namespace geomint
