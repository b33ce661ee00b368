#pragma once
// Jacobians of flows of the nonholonomic particle of 003, to test symplecticity
// (the defect max |J^T Omega J - Omega|, observables/symplecticity.hpp):
//   - the exact flow of (3.8), z' = N(y) g(z) with g = J grad H, and the flow of H with
//     N = 1, z' = g(z) (a Hamiltonian flow: symplectic), each with its variational equation
//     Phi' = Df(z) Phi, Phi(0) = I, integrated by odeint's Bulirsch-Stoer;
//   - one step of Psi_{h,E} (integrators/conformal_variational.hpp), exactly: the implicit
//     function theorem on p0 = -D_1 S_d(q0, q1), with the second derivatives of S_d by
//     forward-mode automatic differentiation.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <unsupported/Eigen/AutoDiff>

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
inline std::pair<Vec<4>, Mat<4>> field_and_jacobian(const NonholonomicParticle& sys, const Vec<4>& z, ParticleFlow flow) {
  using AD = Eigen::AutoDiffScalar<Vec<4>>;
  Eigen::Matrix<AD, 4, 1> za;
  for (int i = 0; i < 4; ++i) za[i] = AD(z[i], 4, i);
  Eigen::Matrix<AD, 4, 1> f = canonical_field(sys, za);
  if (flow == ParticleFlow::conformal) {
    const AD n = NonholonomicParticle::N(za[1]);
    for (int i = 0; i < 4; ++i) f[i] = n * f[i];
  }
  Vec<4> v;
  Mat<4> J;
  for (int i = 0; i < 4; ++i) v[i] = f[i].value(), J.row(i) = f[i].derivatives().transpose();
  return {v, J};
}

// A point of a flow and the Jacobian of the flow map from the start: Phi(t) = dz(t)/dz(0).
struct FlowJacobian {
  Vec<4> z;
  Mat<4> Phi;
};

// z and Phi at t_j = j dt, j = 0..n: (z, Phi)' = (f(z), Df(z) Phi), Phi(0) = I, by odeint's
// Bulirsch-Stoer at tolerances (atol, rtol) on all 20 components, landing on each t_j.
inline std::vector<FlowJacobian> variational_flow(const NonholonomicParticle& sys, const Vec<4>& z0, ParticleFlow flow,
                                                  double dt, std::int64_t n, double rtol, double atol) {
  using X = std::array<double, 20>;  // z, then Phi column-major
  const auto rhs = [&sys, flow](const double* x, double* dxdt) {
    const Vec<4> z = Eigen::Map<const Vec<4>>(x);
    const auto [f, Df] = field_and_jacobian(sys, z, flow);
    Eigen::Map<Vec<4>>{dxdt} = f;
    Eigen::Map<Mat<4>>{dxdt + 4} = Df * Eigen::Map<const Mat<4>>(x + 4);
  };
  X x{};
  Eigen::Map<Vec<4>>(x.data()) = z0;
  Eigen::Map<Mat<4>>(x.data() + 4) = Mat<4>::Identity();
  ReferenceIntegrator reference(x.size(), rhs, rtol, atol);
  const auto sample = [](const X& s) {
    return FlowJacobian{Eigen::Map<const Vec<4>>(s.data()), Eigen::Map<const Mat<4>>(s.data() + 4)};
  };
  std::vector<FlowJacobian> out{sample(x)};
  for (std::int64_t j = 1; j <= n; ++j) {
    reference.integrate(x, static_cast<double>(j - 1) * dt, static_cast<double>(j) * dt, 0.1 * dt);
    out.push_back(sample(x));
  }
  return out;
}

// d(q1, p1)/d(q0, p0) of one step z -> z1 of Psi_{h,E} (z1 its result): with P0 = -D_1 S_d and
// P1 = D_2 S_d (003 Sec. 4.2), p0 = P0(q0, q1) gives dq1 = P0_q1^{-1} (dp0 - P0_q0 dq0), and
// dp1 = P1_q0 dq0 + P1_q1 dq1.
inline Mat<4> psi_step_jacobian(Discretization d, const NonholonomicParticle& sys, const PhaseState<2>& z,
                                const PhaseState<2>& z1, double h, double E) {
  using AD = Eigen::AutoDiffScalar<Vec<4>>;
  Eigen::Matrix<AD, 2, 1> q0, q1;
  for (int i = 0; i < 2; ++i) q0[i] = AD(z.q[i], 4, i), q1[i] = AD(z1.q[i], 4, 2 + i);
  const Eigen::Matrix<AD, 2, 1> p0 = discrete_momentum(d, sys, q0, q1, h, E, -1);
  const Eigen::Matrix<AD, 2, 1> p1 = discrete_momentum(d, sys, q0, q1, h, E, +1);
  Mat<2> A, B, C, D;  // P0_q0, P0_q1, P1_q0, P1_q1
  for (int i = 0; i < 2; ++i) {
    A.row(i) = p0[i].derivatives().head<2>().transpose(), B.row(i) = p0[i].derivatives().tail<2>().transpose();
    C.row(i) = p1[i].derivatives().head<2>().transpose(), D.row(i) = p1[i].derivatives().tail<2>().transpose();
  }
  const Mat<2> Binv = B.inverse();
  Mat<4> J;
  J.block<2, 2>(0, 0) = -Binv * A;   // dq1/dq0
  J.block<2, 2>(0, 2) = Binv;        // dq1/dp0
  J.block<2, 2>(2, 0) = C + D * J.block<2, 2>(0, 0);
  J.block<2, 2>(2, 2) = D * Binv;
  return J;
}

}  // namespace geomint
