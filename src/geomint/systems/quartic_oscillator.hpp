#pragma once
// The quartic oscillator H(q, p) = p^2/2 + q^4/4 (m = 1): an anharmonic oscillator whose period depends on
// its energy, the system of the worked example (experiments/triple_jump).
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<QuarticOscillator>
#include <cmath>

#include "geomint/core/state.hpp"

namespace geomint {

struct QuarticOscillator {
  using State = PhaseState<1>;
  static constexpr bool separable = true;  // H = T(p) + U(q)

  double H(const State& z) const { return 0.5 * z.p[0] * z.p[0] + U(z.q); }
  Vec<1> H_q(const Vec<1>& q, const Vec<1>& /*p*/) const { return U_q(q); }  // p' = -q^3
  Vec<1> H_p(const Vec<1>& /*q*/, const Vec<1>& p) const { return p; }       // q' = p
  Mat<1> H_qp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Zero(); }
  Mat<1> H_pp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Identity(); }

  // The mechanical form L = qdot^2/2 - U(q).
  double mass() const { return 1.0; }
  Vec<1> inv_mass(const Vec<1>& p) const { return p; }
  double U(const Vec<1>& q) const { return 0.25 * q[0] * q[0] * q[0] * q[0]; }
  Vec<1> U_q(const Vec<1>& q) const { return Vec<1>(q[0] * q[0] * q[0]); }
  Mat<1> U_qq(const Vec<1>& q) const { return Mat<1>::Constant(3 * q[0] * q[0]); }
  Vec<1> U_qq_times(const Vec<1>& q, const Vec<1>& v) const { return U_qq(q) * v; }
  Vec<1> force(const Vec<1>& q) const { return -U_q(q); }

  // The largest frequency of the linearised motion on the energy level H: sqrt(U''(q_max)), q_max = (4H)^(1/4).
  static double max_frequency(double H) { return std::sqrt(3.0) * std::sqrt(std::sqrt(4 * H)); }
};

}  // namespace geomint
