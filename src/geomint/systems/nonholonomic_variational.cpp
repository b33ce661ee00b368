#include "geomint/systems/nonholonomic_variational.hpp"

#include <unsupported/Eigen/AutoDiff>

namespace geomint {

std::pair<Vec<4>, Mat<4>> field_and_jacobian(const NonholonomicParticle& sys, const Vec<4>& z, ParticleFlow flow) {
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

std::vector<FlowJacobian> variational_flow(const NonholonomicParticle& sys, const Vec<4>& z0, ParticleFlow flow,
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

Mat<4> psi_step_jacobian(Discretization d, const NonholonomicParticle& sys, const PhaseState<2>& z,
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
