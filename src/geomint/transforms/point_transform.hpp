#pragma once
// Point transformations qbar = Q(q) of one degree of freedom and the canonical
// transformation they induce on phase space (000 eq. (40)-(41)).
#include <cmath>
#include <limits>
#include <numbers>

#include "geomint/core/state.hpp"

namespace geomint {

// 000 eq. (82): Q(q) = (2/pi)(qhat sqrt(1 - qhat^2) + arcsin qhat), qhat = q/(1 + k h^2),
// the O(h^2) modification of (81), the solution of (80) that removes the
// first-order term H_p H_q of symplectic Euler's distorted Hamiltonian (44)
// along the motion of the oscillator (74) with amplitude 1.
// Defined for |qhat| < 1, i.e. |q| < 1 + k h^2.
struct OscillatorCompensation {
  double k;
  double h;

  double scale() const { return 1.0 + k * h * h; }
  double qhat(double q) const { return q / scale(); }
  bool defined(double q) const { return std::abs(qhat(q)) < 1.0; }

  double Q(double q) const {  // (82)
    const double u = qhat(q);
    return 2.0 / std::numbers::pi * (u * std::sqrt(1.0 - u * u) + std::asin(u));
  }
  double dQ(double q) const {  // Q'(q) = (4/pi) sqrt(1 - qhat^2) / (1 + k h^2)
    const double u = qhat(q);
    return 4.0 / std::numbers::pi * std::sqrt(1.0 - u * u) / scale();
  }
  double d2Q(double q) const {  // Q''(q) = -(4/pi) qhat / (sqrt(1 - qhat^2) (1 + k h^2)^2)
    const double u = qhat(q);
    return -4.0 / std::numbers::pi * u / (std::sqrt(1.0 - u * u) * scale() * scale());
  }
  // Q^{-1}: with qhat = sin(psi/2), (82) reads psi + sin psi = pi |qbar|
  // (odd in qbar); with x = pi - psi in [0, pi] this is g(x) = x - sin x - m = 0,
  // m := pi (1 - |qbar|). g is increasing and convex on [0, pi], so Newton's
  // method started right of the root decreases monotonically to it. Start:
  // x0 = cbrt(6 m) lies left of the root (x - sin x <= x^3/6); one Newton step
  // from it, capped at pi (the root is <= pi), lies right of it, and the
  // further steps dx are positive.
  // With s, c = sin, cos(x/2): sin x = 2 s c and g' = 1 - cos x = 2 s^2 (no
  // cancellation), one sin/cos pair per step. NaN for |qbar| > 1.
  double inverse(double qbar) const {
    if (!(std::abs(qbar) <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
    const double m = std::numbers::pi * (1.0 - std::abs(qbar));
    const auto newton_step = [m](double x) {
      const double s = std::sin(0.5 * x), c = std::cos(0.5 * x);
      return (x - 2.0 * s * c - m) / (2.0 * s * s);
    };
    double x = 0.0;
    if (m > 0.0) {
      x = std::cbrt(6.0 * m);
      x = std::min(std::numbers::pi, x - newton_step(x));
      // Near the simple root the relative error squares at each step, so after
      // a step of relative size <= 1e-8 the iterate is converged to round-off.
      for (int it = 0; it < 60; ++it) {
        const double dx = newton_step(x);
        if (!(dx > 0.0)) break;  // at round-off
        x -= dx;
        if (dx <= 1e-8 * x) break;
      }
    }
    return std::copysign(std::cos(0.5 * x), qbar) * scale();  // sin(psi/2) = cos(x/2)
  }
};

// The system H of one degree of freedom written in the coordinates qbar = Q(q)
// with the induced momentum pbar = p / Q'(q) (000 eq. (41)); Hbar(qbar, pbar) =
// H(Q^{-1}(qbar), pbar Q'(Q^{-1}(qbar))) (000 eq. (39)). Never separable.
template <class Sys, class PointMap>
struct PointTransformed {
  using State = PhaseState<1>;
  static constexpr bool separable = false;

  Sys sys;
  PointMap map;

  State to_transformed(const State& z) const {  // (41): pbar = p (dQ^{-1}/dqbar) = p / Q'(q)
    return make_state(map.Q(z.q[0]), z.p[0] / map.dQ(z.q[0]));
  }
  State to_original(const State& zb) const {  // (41) inverse: p = pbar Q'(q)
    const double q = map.inverse(zb.q[0]);
    return make_state(q, zb.p[0] * map.dQ(q));
  }
  double H(const State& zb) const { return sys.H(to_original(zb)); }  // (39)

  // Everything that depends on qbar only, computed once: q, Q'(q), Q''(q).
  struct AtQ {
    const Sys& sys;
    Vec<1> q;
    double dQ, d2Q;
    Vec<1> p_of(const Vec<1>& pb) const { return pb * dQ; }
    // 000 eq. (46): Hbar_pbar = H_p Q'(q).
    Vec<1> H_p(const Vec<1>& pb) const { return sys.H_p(q, p_of(pb)) * dQ; }
    // 000 eq. (47): Hbar_qbar = (H_p pbar Q''(q) + H_q) / Q'(q).
    Vec<1> H_q(const Vec<1>& pb) const {
      const Vec<1> p = p_of(pb);
      return (sys.H_p(q, p) * pb[0] * d2Q + sys.H_q(q, p)) / dQ;
    }
    // d(Hbar_qbar)/d(pbar) = H_pp pbar Q'' + H_p Q''/Q' + H_qp.
    Mat<1> H_qp(const Vec<1>& pb) const {
      const Vec<1> p = p_of(pb);
      return sys.H_pp(q, p) * (pb[0] * d2Q) + Mat<1>(sys.H_p(q, p)[0] * d2Q / dQ) + sys.H_qp(q, p);
    }
  };
  AtQ at_q(const Vec<1>& qb) const {
    const double q = map.inverse(qb[0]);
    return AtQ{sys, Vec<1>(q), map.dQ(q), map.d2Q(q)};
  }

  Vec<1> H_q(const Vec<1>& qb, const Vec<1>& pb) const { return at_q(qb).H_q(pb); }
  Vec<1> H_p(const Vec<1>& qb, const Vec<1>& pb) const { return at_q(qb).H_p(pb); }
  Mat<1> H_qp(const Vec<1>& qb, const Vec<1>& pb) const { return at_q(qb).H_qp(pb); }
};

template <class Sys, class PointMap>
PointTransformed(Sys, PointMap) -> PointTransformed<Sys, PointMap>;

}  // namespace geomint
