#pragma once
// The harmonic oscillator H(q, p) = p^2/(2m) + m w^2 q^2/2: with m = w = 1 the
// dimensionless form 000 eq. (74); with m = 1, w = 2 pi the oscillator of 001.
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<HarmonicOscillator>
// geomint: MethodsOn<Counting<HarmonicOscillator>>
// geomint: MethodsOn<NonlinearPendulum>
// geomint: MethodsOn<Counting<NonlinearPendulum>>
#include <cmath>

#include "geomint/core/state.hpp"

namespace geomint {

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
};

}  // namespace geomint
