#pragma once
// 000 eq. (74): dimensionless harmonic oscillator H(q, p) = p^2/2 + q^2/2.
#include <cmath>

#include "geomint/core/state.hpp"

namespace geomint {

struct HarmonicOscillator {
  using State = PhaseState<1>;
  static constexpr bool separable = true;  // H = T(p) + U(q)

  double H(const State& z) const { return 0.5 * (z.p[0] * z.p[0] + z.q[0] * z.q[0]); }  // (74)
  Vec<1> H_q(const Vec<1>& q, const Vec<1>& /*p*/) const { return q; }  // (75): p' = -q
  Vec<1> H_p(const Vec<1>& /*q*/, const Vec<1>& p) const { return p; }  // (76): q' = p
  Mat<1> H_qp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Zero(); }
  Mat<1> H_pp(const Vec<1>&, const Vec<1>&) const { return Mat<1>::Identity(); }
  double omega() const { return 1.0; }

  // Exact flow: rotation of the phase plane by the angle t.
  State exact(const State& z0, double t) const {
    const double c = std::cos(t), s = std::sin(t);
    State z;
    z.q[0] = c * z0.q[0] + s * z0.p[0];
    z.p[0] = -s * z0.q[0] + c * z0.p[0];
    return z;
  }
};

}  // namespace geomint
