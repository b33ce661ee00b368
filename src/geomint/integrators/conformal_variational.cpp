// The conformal variational step of integrators/conformal_variational.hpp, compiled once: its
// Newton iteration with the automatic-differentiation Jacobian is instantiated here only.
#include "geomint/integrators/conformal_variational.hpp"

namespace geomint {

std::pair<Vec<2>, Mat<2>> momentum_residual(Discretization d, const NonholonomicParticle& sys, const PhaseState<2>& z,
                                            const Vec<2>& q1, double h, double E) {
  using AD = Eigen::AutoDiffScalar<Vec<2>>;
  Eigen::Matrix<AD, 2, 1> q0a, q1a;
  for (int i = 0; i < 2; ++i) {
    q0a[i] = AD(z.q[i], Vec<2>::Zero());
    q1a[i] = AD(q1[i], 2, i);
  }
  const Eigen::Matrix<AD, 2, 1> p0 = discrete_momentum(d, sys, q0a, q1a, h, E, -1);
  Vec<2> r;
  Mat<2> J;
  for (int i = 0; i < 2; ++i) {
    r[i] = p0[i].value() - z.p[i];
    J.row(i) = p0[i].derivatives().transpose();
  }
  return {r, J};
}

ConformalVariationalStep conformal_variational_step(Discretization d, const NonholonomicParticle& sys,
                                                    const PhaseState<2>& z, double h, double E) {
  ConformalVariationalStep out;
  const Vec<2> q1 = newton_solve<2>([&](const Vec<2>& x) { return momentum_residual(d, sys, z, x, h, E); },
                                    Vec<2>(z.q + h * sys.altered_velocity(z)), "conformal variational step",
                                    &out.newton_iterations);
  out.z.q = q1;
  out.z.p = discrete_momentum<double>(d, sys, z.q, q1, h, E, +1);
  return out;
}

}  // namespace geomint
