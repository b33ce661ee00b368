#pragma once
// 000 Appendix A: the planar elastic pendulum (mass m, spring stiffness k,
// relaxed length l, gravity g). The y axis points down, as the signs of (72)
// (U = -m g r cos(theta)) and (73) (U = -m g y) imply: the pendulum hangs at
// x = 0, y = l + m g / k.
//
// The Cartesian form (73) is separable, H = |p|^2/(2m) + U(q), and is
// assembled from potential terms, so a scene without gravity compiles a step
// without a gravity term (not one multiplied by zero).
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<ElasticPendulumWithGravity>
// geomint: MethodsOn<ElasticPendulumWithoutGravity>
// geomint: MethodsOn<Counting<ElasticPendulumWithGravity>>
// geomint: MethodsOn<Counting<ElasticPendulumWithoutGravity>>
#include <cmath>
#include <tuple>

#include "geomint/core/state.hpp"

namespace geomint {

// U = (k/2)(|q| - l)^2: the spring of 000 eq. (73).
struct SpringTerm {
  double k, l;
  double U(const Vec<2>& q) const {
    const double s = q.norm() - l;
    return 0.5 * k * s * s;
  }
  Vec<2> U_q(const Vec<2>& q) const { return k * (1.0 - l / q.norm()) * q; }
  // U_qq v = k [(1 - l/r) v + (l/r^3) q (q.v)]
  Vec<2> U_qq_times(const Vec<2>& q, const Vec<2>& v) const {
    const double r = q.norm();
    return k * ((1.0 - l / r) * v + (l / (r * r * r)) * q.dot(v) * q);
  }
  Mat<2> U_qq(const Vec<2>& q) const {  // k [(1 - l/r) I + (l/r^3) q q^T]
    const double r = q.norm();
    return k * ((1.0 - l / r) * Mat<2>::Identity() + (l / (r * r * r)) * q * q.transpose());
  }
};

// U = -m g y: gravity along +y (downwards), 000 eq. (73).
struct GravityTerm {
  double m, g;
  double U(const Vec<2>& q) const { return -m * g * q[1]; }
  Vec<2> U_q(const Vec<2>&) const { return Vec<2>(0.0, -m * g); }
  Vec<2> U_qq_times(const Vec<2>&, const Vec<2>&) const { return Vec<2>::Zero(); }
  Mat<2> U_qq(const Vec<2>&) const { return Mat<2>::Zero(); }
};

// H = |p|^2/(2m) + sum of the potential terms: 000 eq. (73) with SpringTerm and GravityTerm.
template <class... Terms>
struct ElasticPendulumCartesian {
  using State = PhaseState<2>;
  static constexpr bool separable = true;

  double m;
  std::tuple<Terms...> terms;

  Vec<2> inv_mass(const Vec<2>& p) const { return p / m; }  // M^{-1} p, M = m I
  Vec<2> mass_times(const Vec<2>& v) const { return m * v; }  // M v
  double T(const Vec<2>& p) const { return 0.5 * p.squaredNorm() / m; }
  double U(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (0.0 + ... + t.U(q)); }, terms);
  }
  Vec<2> U_q(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_q(q)).eval(); }, terms);
  }
  Vec<2> U_qq_times(const Vec<2>& q, const Vec<2>& v) const {  // Hessian-vector product
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_qq_times(q, v)).eval(); }, terms);
  }
  Vec<2> force(const Vec<2>& q) const { return -U_q(q); }
  Mat<2> U_qq(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Mat<2>::Zero() + ... + t.U_qq(q)).eval(); }, terms);
  }
  double mass() const { return m; }

  double H(const State& z) const { return T(z.p) + U(z.q); }  // (73)
  Vec<2> H_q(const Vec<2>& q, const Vec<2>&) const { return U_q(q); }
  Vec<2> H_p(const Vec<2>&, const Vec<2>& p) const { return inv_mass(p); }
  Mat<2> H_qp(const Vec<2>&, const Vec<2>&) const { return Mat<2>::Zero(); }
  Mat<2> H_pp(const Vec<2>&, const Vec<2>&) const { return Mat<2>::Identity() / m; }
};

// ---- polar coordinates q = (r, theta), theta measured from +y: x = r sin(theta), y = r cos(theta) ----

// U = (k/2)(r - l)^2: the spring of 000 eq. (72).
struct SpringPolarTerm {
  double k, l;
  double U(const Vec<2>& q) const { return 0.5 * k * (q[0] - l) * (q[0] - l); }
  Vec<2> U_q(const Vec<2>& q) const { return Vec<2>(k * (q[0] - l), 0.0); }
};

// U = -m g r cos(theta): gravity of 000 eq. (72).
struct GravityPolarTerm {
  double m, g;
  double U(const Vec<2>& q) const { return -m * g * q[0] * std::cos(q[1]); }
  Vec<2> U_q(const Vec<2>& q) const { return Vec<2>(-m * g * std::cos(q[1]), m * g * q[0] * std::sin(q[1])); }
};

// 000 eq. (72): H = (p_r^2 + p_theta^2 / r^2)/(2m) + sum of the potential terms. Not
// separable; theta is cyclic without gravity (p_theta is then a first integral).
template <class... Terms>
struct ElasticPendulumPolar {
  using State = PhaseState<2>;
  static constexpr bool separable = false;

  double m;
  std::tuple<Terms...> terms;

  double U(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (0.0 + ... + t.U(q)); }, terms);
  }
  Vec<2> U_q(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_q(q)).eval(); }, terms);
  }
  double H(const State& z) const {  // (72)
    const double r = z.q[0];
    return (z.p[0] * z.p[0] + z.p[1] * z.p[1] / (r * r)) / (2 * m) + U(z.q);
  }
  Vec<2> H_q(const Vec<2>& q, const Vec<2>& p) const {  // (dH/dr, dH/dtheta)
    const double r = q[0];
    return Vec<2>(-p[1] * p[1] / (m * r * r * r), 0.0) + U_q(q);
  }
  Vec<2> H_p(const Vec<2>& q, const Vec<2>& p) const { return Vec<2>(p[0] / m, p[1] / (m * q[0] * q[0])); }
  Mat<2> H_qp(const Vec<2>& q, const Vec<2>& p) const {
    Mat<2> J = Mat<2>::Zero();
    J(0, 1) = -2 * p[1] / (m * q[0] * q[0] * q[0]);  // d(dH/dr)/dp_theta
    return J;
  }
  Mat<2> H_pp(const Vec<2>& q, const Vec<2>&) const {
    Mat<2> J = Mat<2>::Zero();
    J(0, 0) = 1 / m, J(1, 1) = 1 / (m * q[0] * q[0]);
    return J;
  }
};

struct ElasticPendulumParams {
  double l, m, k, g;
};

// The angular frequency of the spring mode, omega = sqrt(k/m) (000 Appendix A).
inline double spring_frequency(const ElasticPendulumParams& p) { return std::sqrt(p.k / p.m); }

// 000 Sec. 4.1: released from rest at r(0), phi(0) (phi from the downward vertical), with the
// angular motion ignored, m r'' = -k (r - l) + m g cos(phi(0)): a radial oscillation about
// r* = l + (m g / k) cos(phi(0)), between r(0) and 2 r* - r(0).
inline double radial_rest_radius(const ElasticPendulumParams& p, double cos_phi) {
  return p.l + p.m * p.g / p.k * cos_phi;
}

// 000 Sec. 4.1: the boundary of the polar runs, r(0) = 2l + (2mg/k) cos(phi(0)); on and beyond it
// the radial oscillation reaches r = 0.
inline double polar_boundary_radius(const ElasticPendulumParams& p, double cos_phi) {
  return 2 * p.l + 2 * p.m * p.g / p.k * cos_phi;
}

// The energy at the pivot, U(r = 0) = k l^2 / 2 of (72)-(73): for a release from rest the boundary
// above is the isoline H_0 = k l^2 / 2.
inline double pivot_energy(const ElasticPendulumParams& p) { return 0.5 * p.k * (p.l * p.l); }

// The hanging equilibrium x = 0, y = l + m g / k (y pointing down, 000 eq. (73)).
inline double hanging_equilibrium_y(const ElasticPendulumParams& p) { return radial_rest_radius(p, 1.0); }

using ElasticPendulumWithGravity = ElasticPendulumCartesian<SpringTerm, GravityTerm>;
using ElasticPendulumWithoutGravity = ElasticPendulumCartesian<SpringTerm>;
using ElasticPendulumPolarWithGravity = ElasticPendulumPolar<SpringPolarTerm, GravityPolarTerm>;
using FreeParticleCartesian = ElasticPendulumCartesian<>;  // 000 eq. (61)
using FreeParticlePolar = ElasticPendulumPolar<>;          // 000 eq. (62)

// Calls f with the Cartesian pendulum made of the terms the parameters call for.
template <class F>
decltype(auto) with_elastic_pendulum(const ElasticPendulumParams& p, F&& f) {
  if (p.g == 0.0) return f(ElasticPendulumWithoutGravity{p.m, {SpringTerm{p.k, p.l}}});
  return f(ElasticPendulumWithGravity{p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}});
}

}  // namespace geomint
