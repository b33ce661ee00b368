#pragma once
// Jacobians of flows of the nonholonomic particle of 003, to test symplecticity
// (the defect max |J^T Omega J - Omega|, observables/symplecticity.hpp):
//   - the exact flow of (3.8), z' = N(y) g(z) with g = J grad H, and the flow of H with
//     N = 1, z' = g(z) (a Hamiltonian flow: symplectic), each with its variational equation
//     Phi' = Df(z) Phi, Phi(0) = I, integrated by odeint's Bulirsch-Stoer;
//   - one step of Psi_{h,E} (integrators/conformal_variational.hpp), exactly: the implicit
//     function theorem on p0 = -D_1 S_d(q0, q1), with the second derivatives of S_d by
//     forward-mode automatic differentiation.
// Compiled once in the library (nonholonomic_variational.cpp): the automatic differentiation and the
// odeint stepper are not instantiated again in each file that calls them.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "geomint/core/state.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {

// g = J grad H for H = (px^2 + (1 + y^2) py^2)/2 + U (003 (3.8) with N = 1): (x, y, px, py)' =
// (px, (1 + y^2) py, -U_x, -(y py^2 + U_y)). The field (3.8) is N(y) g (NonholonomicParticle::rhs).
template <class S>
Eigen::Matrix<S, 4, 1> canonical_field(const NonholonomicParticle& sys, const Eigen::Matrix<S, 4, 1>& z) {
  const S &x = z[0], &y = z[1], &px = z[2], &py = z[3];
  return {px, (1.0 + y * y) * py, -sys.U_x(x), -(y * py * py + sys.U_y(y))};
}

// The flow whose Jacobian is followed: that of (3.8) (conformal, N(y) g) or that of H (N = 1, g).
enum class ParticleFlow { conformal, hamiltonian };

// The field f of `flow` at z and its Jacobian Df (exact, by forward-mode AD of N(y) g or g).
std::pair<Vec<4>, Mat<4>> field_and_jacobian(const NonholonomicParticle& sys, const Vec<4>& z, ParticleFlow flow);

// A point of a flow and the Jacobian of the flow map from the start: Phi(t) = dz(t)/dz(0).
struct FlowJacobian {
  Vec<4> z;
  Mat<4> Phi;
};

// z and Phi at t_j = j dt, j = 0..n: (z, Phi)' = (f(z), Df(z) Phi), Phi(0) = I, by odeint's
// Bulirsch-Stoer at tolerances (atol, rtol) on all 20 components, landing on each t_j.
std::vector<FlowJacobian> variational_flow(const NonholonomicParticle& sys, const Vec<4>& z0, ParticleFlow flow,
                                           double dt, std::int64_t n, double rtol, double atol);

// d(q1, p1)/d(q0, p0) of one step z -> z1 of Psi_{h,E} (z1 its result): with P0 = -D_1 S_d and
// P1 = D_2 S_d (003 Sec. 4.2), p0 = P0(q0, q1) gives dq1 = P0_q1^{-1} (dp0 - P0_q0 dq0), and
// dp1 = P1_q0 dq0 + P1_q1 dq1.
Mat<4> psi_step_jacobian(Discretization d, const NonholonomicParticle& sys, const PhaseState<2>& z,
                         const PhaseState<2>& z1, double h, double E);

}  // namespace geomint
