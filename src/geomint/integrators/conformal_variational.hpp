#pragma once
// The variational integrators Psi_{h,E} of 003 Sec. 5.1 for the altered system
// of the nonholonomic particle: one of the five discrete Lagrangians (5.1)
// (midpoint M or trapezoidal T quadrature of N and of L), with
// S_d = h Lambda_d (003 prints Lambda_d without the factor h), momenta
// p_j = -D_1 S_d(q_j, q_{j+1}) and p_{j+1} = D_2 S_d(q_j, q_{j+1}).
// One step solves the first equation for q_{j+1} by Newton's method with the
// exact 2x2 Jacobian from forward-mode automatic differentiation.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/newton.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {

enum class Discretization { M, MT, TM, TT, T };  // 003 eq. (5.1): quadrature of N, then of L

inline constexpr std::array<Discretization, 5> all_discretizations = {Discretization::M, Discretization::MT,
                                                                      Discretization::TM, Discretization::TT,
                                                                      Discretization::T};
inline const char* discretization_name(Discretization d) {
  constexpr const char* names[] = {"M", "MT", "TM", "TT", "T"};
  return names[static_cast<int>(d)];
}
inline std::optional<Discretization> parse_discretization(std::string_view s) {
  for (Discretization d : all_discretizations)
    if (s == discretization_name(d)) return d;
  return std::nullopt;
}

// The quadratures of the product methods: N(qbar) or (N(q0) + N(q1))/2, L(qbar, v) or
// (L(q0, v) + L(q1, v))/2 (first and second letter of the name; T is not a product).
inline bool n_midpoint(Discretization d) { return d == Discretization::M || d == Discretization::MT; }
inline bool l_midpoint(Discretization d) { return d == Discretization::M || d == Discretization::TM; }

// Lambda_d(q0, q1; E, h) of 003 eq. (5.1): an approximation of (1/h) int_0^h N (L + E) dt.
template <class S>
S discrete_lagrangian(Discretization d, const NonholonomicParticle& sys, const Eigen::Matrix<S, 2, 1>& q0,
                      const Eigen::Matrix<S, 2, 1>& q1, double h, double E) {
  using P = NonholonomicParticle;
  const Eigen::Matrix<S, 2, 1> v = (q1 - q0) / h, qm = 0.5 * (q0 + q1);
  if (d == Discretization::T)
    return 0.5 * P::N(q0[1]) * (sys.L(q0, v) + E) + 0.5 * P::N(q1[1]) * (sys.L(q1, v) + E);
  const S n = n_midpoint(d) ? P::N(qm[1]) : S(0.5 * (P::N(q0[1]) + P::N(q1[1])));
  const S l = l_midpoint(d) ? sys.L(qm, v) : S(0.5 * (sys.L(q0, v) + sys.L(q1, v)));
  return n * (l + E);
}

// The discrete momentum at one end q_s of the step: side = -1 gives p_0 = -D_1 S_d(q0, q1),
// side = +1 gives p_1 = D_2 S_d(q0, q1), differentiating (5.1) by the chain rule with
// dv/dq_s = side/h: for either quadrature dn/dy_s = n_y/2 and dl/dq_s = l_q/2 + side l_v/h.
template <class S>
Eigen::Matrix<S, 2, 1> discrete_momentum(Discretization d, const NonholonomicParticle& sys,
                                         const Eigen::Matrix<S, 2, 1>& q0, const Eigen::Matrix<S, 2, 1>& q1,
                                         double h, double E, int side) {
  using P = NonholonomicParticle;
  using V = Eigen::Matrix<S, 2, 1>;
  const V v = (q1 - q0) / h, qm = 0.5 * (q0 + q1);
  const V& qs = side < 0 ? q0 : q1;  // the end whose momentum is computed
  const double half_h = 0.5 * h * side;
  if (d == Discretization::T) {
    V p = 0.5 * (P::N(q0[1]) * P::L_v(q0, v) + P::N(q1[1]) * P::L_v(q1, v)) + half_h * P::N(qs[1]) * sys.L_q(qs, v);
    p[1] += half_h * P::N_y(qs[1]) * (sys.L(qs, v) + E);
    return p;
  }
  const bool n_mid = n_midpoint(d), l_mid = l_midpoint(d);
  const S n = n_mid ? P::N(qm[1]) : S(0.5 * (P::N(q0[1]) + P::N(q1[1])));
  const S n_y = n_mid ? P::N_y(qm[1]) : P::N_y(qs[1]);
  const S l = l_mid ? sys.L(qm, v) : S(0.5 * (sys.L(q0, v) + sys.L(q1, v)));
  const V l_v = l_mid ? P::L_v(qm, v) : V(0.5 * (P::L_v(q0, v) + P::L_v(q1, v)));
  const V l_q = l_mid ? sys.L_q(qm, v) : sys.L_q(qs, v);
  V p = n * l_v + half_h * n * l_q;
  p[1] += half_h * n_y * (l + E);
  return p;
}

struct ConformalVariationalStep {
  PhaseState<2> z;
  int newton_iterations = 0;
};

// The residual R(q1) = p0(q, q1) - p and its Jacobian dR/dq1 (exact, by forward-mode AD).
std::pair<Vec<2>, Mat<2>> momentum_residual(Discretization d, const NonholonomicParticle& sys, const PhaseState<2>& z,
                                            const Vec<2>& q1, double h, double E);

// One step of Psi_{h,E} (003 Sec. 4.2 with the discrete Lagrangian (5.1)). The Newton
// predictor is an explicit Euler step of the altered system, q + h (N px, N (1 + y^2) py).
// Both are compiled once, in conformal_variational.cpp.
ConformalVariationalStep conformal_variational_step(Discretization d, const NonholonomicParticle& sys,
                                                    const PhaseState<2>& z, double h, double E);

// Psi_{h,E} as a method on (q, p) at fixed E, for integrate(); the Newton iterations of its
// steps are added to *iterations if given.
inline auto conformal_variational_method(Discretization d, const NonholonomicParticle& sys, double E,
                                         std::int64_t* iterations = nullptr) {
  return one_step_method([d, &sys, E, iterations](const PhaseState<2>& z, double h) {
    const ConformalVariationalStep step = conformal_variational_step(d, sys, z, h, E);
    if (iterations) *iterations += step.newton_iterations;
    return step.z;
  });
}

}  // namespace geomint
