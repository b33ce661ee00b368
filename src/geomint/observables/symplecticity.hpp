#pragma once
// Symplecticity of a one-step map: the defect max |J^T Omega J - Omega| of its
// Jacobian J (000 eq. (21)), and J of a processed method by central differences.
#include "geomint/core/state.hpp"
#include "geomint/core/integrate.hpp"

namespace geomint {

// Omega = [[0, I], [-I, 0]] on (q, p).
template <int D2>
Mat<D2> canonical_form() {
  constexpr int D = D2 / 2;
  Mat<D2> O = Mat<D2>::Zero();
  O.template block<D, D>(0, D) = Mat<D>::Identity();
  O.template block<D, D>(D, 0) = -Mat<D>::Identity();
  return O;
}

template <int D2>
double symplecticity_defect(const Mat<D2>& J) {
  const Mat<D2> O = canonical_form<D2>();
  return (J.transpose() * O * J - O).cwiseAbs().maxCoeff();
}
// (compiled once for one and two degrees of freedom: symplecticity.cpp)
extern template double symplecticity_defect<2>(const Mat<2>&);
extern template double symplecticity_defect<4>(const Mat<4>&);

// d(q1, p1)/d(q0, p0) of one step of a processed method, by central differences of size d.
template <class Method, int D>
Mat<2 * D> step_jacobian_fd(const Method& method, const PhaseState<D>& z, double h, double d) {
  Mat<2 * D> J;
  for (int c = 0; c < 2 * D; ++c) {
    PhaseState<D> a = z, b = z;
    (c < D ? a.q[c] : a.p[c - D]) += d;
    (c < D ? b.q[c] : b.p[c - D]) -= d;
    const auto za = integrate(method, a, h, 1), zb = integrate(method, b, h, 1);
    J.col(c) << (za.q - zb.q) / (2 * d), (za.p - zb.p) / (2 * d);
  }
  return J;
}

// The same, Richardson-extrapolated: (4 J(d/2) - J(d)) / 3, truncation error O(d^4).
template <class Method, int D>
Mat<2 * D> step_jacobian_richardson(const Method& method, const PhaseState<D>& z, double h, double d) {
  return (4 * step_jacobian_fd(method, z, h, d / 2) - step_jacobian_fd(method, z, h, d)) / 3;
}

}  // namespace geomint
