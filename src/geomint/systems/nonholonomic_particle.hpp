#pragma once
// The nonholonomic particle of 003 (García-Naranjo & Vermeeren), Example 3.1,
// as a conformally Hamiltonian system in the rescaled momenta p = e^phi m:
//   H = (px^2 + (1 + y^2) py^2) / 2 + U(x, y),   N(y) = (1 + y^2)^(-1/2),
//   q' = N H_p,  p' = -N H_q                                     (003 eq. (3.8)).
// The potential is chosen by the scene: U = (x^2 + y^2)/2 (harmonic) or U = 0
// (free); only the chosen one is ever evaluated. All functions are templated
// on the scalar so that the discrete Lagrangians can be differentiated by
// forward-mode automatic differentiation.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/core/state.hpp"

namespace geomint {

enum class Potential { harmonic, free };

inline Potential parse_potential(std::string_view s) { return s == "free" ? Potential::free : Potential::harmonic; }
inline const char* potential_name(Potential u) { return u == Potential::free ? "free" : "harmonic"; }

struct NonholonomicParticle {
  using State = PhaseState<2>;  // q = (x, y), p = (px, py)
  Potential potential = Potential::harmonic;

  template <class S>
  S U(const S& x, const S& y) const {  // 003 Sec. 5: U = (x^2 + y^2)/2 or 0
    if (potential == Potential::free) return S(0.0);
    return 0.5 * (x * x + y * y);
  }
  template <class S>
  S U_x(const S& x) const {
    return potential == Potential::free ? S(0.0) : x;
  }
  template <class S>
  S U_y(const S& y) const {
    return potential == Potential::free ? S(0.0) : y;
  }

  // Conformal factor N = e^phi, phi = -ln(1 + y^2)/2 (003 Example 3.1), and N'(y).
  template <class S>
  static S N(const S& y) {
    using std::sqrt;
    return 1.0 / sqrt(1.0 + y * y);
  }
  template <class S>
  static S N_y(const S& y) {
    using std::sqrt;
    const S w = 1.0 / (1.0 + y * y);
    return -y * w * sqrt(w);
  }

  // Reduced Lagrangian (3.7) L(q, v) = ((1 + y^2) vx^2 + vy^2)/2 - U, and its partial derivatives.
  template <class S>
  S L(const Eigen::Matrix<S, 2, 1>& q, const Eigen::Matrix<S, 2, 1>& v) const {
    return 0.5 * ((1.0 + q[1] * q[1]) * v[0] * v[0] + v[1] * v[1]) - U(q[0], q[1]);
  }
  template <class S>
  Eigen::Matrix<S, 2, 1> L_q(const Eigen::Matrix<S, 2, 1>& q, const Eigen::Matrix<S, 2, 1>& v) const {
    return {-U_x(q[0]), q[1] * v[0] * v[0] - U_y(q[1])};
  }
  template <class S>
  static Eigen::Matrix<S, 2, 1> L_v(const Eigen::Matrix<S, 2, 1>& q, const Eigen::Matrix<S, 2, 1>& v) {
    return {(1.0 + q[1] * q[1]) * v[0], v[1]};
  }

  double H(const State& z) const {  // 003 (3.8)
    const double x = z.q[0], y = z.q[1];
    return 0.5 * (z.p[0] * z.p[0] + (1.0 + y * y) * z.p[1] * z.p[1]) + U(x, y);
  }
  // Altered Hamiltonian K_E = N (H - E) (003 eq. (4.1)).
  double K(const State& z, double E) const { return N(z.q[1]) * (H(z) - E); }

  // q' = N H_p, p' = -N H_q in physical time: the reference equations (3.8).
  std::array<double, 4> rhs(const std::array<double, 4>& z) const {
    const double x = z[0], y = z[1], px = z[2], py = z[3];
    const double s = std::sqrt(1.0 + y * y);
    return {px / s, s * py, -U_x(x) / s, -(y * py * py + U_y(y)) / s};
  }
  // dq/dtau = H-gradient of K_E in p: the altered velocity (N px, N (1 + y^2) py) (003 Sec. 4).
  Vec<2> altered_velocity(const State& z) const {
    const double y = z.q[1], n = N(y);
    return {n * z.p[0], n * (1.0 + y * y) * z.p[1]};
  }
};

inline std::array<double, 4> to_array(const PhaseState<2>& z) { return {z.q[0], z.q[1], z.p[0], z.p[1]}; }
inline PhaseState<2> from_array(const std::array<double, 4>& a) { return make_state<2>(Vec<2>(a[0], a[1]), Vec<2>(a[2], a[3])); }

// The reference flow of (3.8): odeint Bulirsch-Stoer (reference/odeint_reference.hpp) at tolerances (rtol, atol)
// from z0 = (x, y, px, py), sampled at t_j = j dt, j = 0..n (nonholonomic_particle.cpp).
std::vector<std::array<double, 4>> reference_samples(const NonholonomicParticle& sys, const std::array<double, 4>& z0,
                                                     double dt, std::int64_t n, double rtol, double atol);

// The reference is checked against a second one with both tolerances multiplied by this factor.
constexpr double reference_check_factor = 1e-2;

}  // namespace geomint
