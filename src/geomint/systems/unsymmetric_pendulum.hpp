#pragma once
// The unsymmetric pendulum of 004 Fig. 2, unit mass: U = -cos q + 0.2 sin 2q.
#include <cmath>

#include "geomint/core/state.hpp"
#include "geomint/systems/unit_mass.hpp"

namespace geomint {

// 004 Fig. 2: U = -cos q + 0.2 sin 2q.
struct UnsymmetricPendulum : UnitMassSeparable<1> {
  double U(const Vec<1>& q) const { return -std::cos(q[0]) + 0.2 * std::sin(2 * q[0]); }
  Vec<1> U_q(const Vec<1>& q) const { return Vec<1>(std::sin(q[0]) + 0.4 * std::cos(2 * q[0])); }
  Mat<1> U_qq(const Vec<1>& q) const { return Mat<1>::Constant(std::cos(q[0]) - 0.8 * std::sin(2 * q[0])); }
  Vec<1> U_qq_times(const Vec<1>& q, const Vec<1>& v) const { return U_qq(q) * v; }
  Vec<1> force(const Vec<1>& q) const { return -U_q(q); }
  Vec<1> H_q(const Vec<1>& q, const Vec<1>&) const { return U_q(q); }
  double H(const State& z) const { return 0.5 * z.p.squaredNorm() + U(z.q); }
  // Higher directional derivatives (one degree of freedom: U^(k)(a^k) = U^(k)(q) a^k).
  double U4(const Vec<1>& q, const Vec<1>& a) const { return (-std::cos(q[0]) + 3.2 * std::sin(2 * q[0])) * std::pow(a[0], 4); }
  double U5(const Vec<1>& q, const Vec<1>& a) const { return (std::sin(q[0]) + 6.4 * std::cos(2 * q[0])) * std::pow(a[0], 5); }
  // The largest value of U: U' = sin q + 0.4 (1 - 2 sin^2 q) = 0 at sin q = s = (1 - sqrt(2.28)) / 1.6 (the root
  // in [-1, 1]), where U = cos q (0.4 s - 1) is largest with cos q = -sqrt(1 - s^2).
  static double U_max() {
    const double s = (1 - std::sqrt(2.28)) / 1.6;
    return std::sqrt(1 - s * s) * (1 - 0.4 * s);
  }
};

}  // namespace geomint
