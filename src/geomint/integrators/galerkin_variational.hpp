#pragma once
// Galerkin variational integrators (001, after Marsden & West): on each step
// [t_j, t_j + h], q(t) is the Lagrange interpolant of degree S through values
// Q_0 = q_j, Q_1, ..., Q_S = q_{j+1} at the nodes c_0 = 0 < ... < c_S = 1, and the
// action is approximated by the quadrature rule on the same nodes, so that
// q(c_k h) = Q_k and qdot(c_k h) = (1/h) sum_m D_km Q_m with D_km = phi_m'(c_k):
//   L_d(Q_0..Q_S) = h sum_k w_k L(Q_k, qdot_k),  L = qdot^T M qdot / 2 - V(q), M = m I.
// The internal values are eliminated by dL_d/dQ_n = 0 (n = 1..S-1), and the
// discrete Legendre transforms p_j = -dL_d/dQ_0, p_{j+1} = dL_d/dQ_S (001 eq. (11))
// make the method a one-step map (q_j, p_j) -> (q_{j+1}, p_{j+1}). Lobatto: S = 3 on
// 0, xi, 1 - xi, 1 with the quadrature (2) (order 6); Simpson: S = 2 on 0, 1/2, 1
// with Simpson's rule (order 4). The implicit stage is solved by Newton's method
// with the exact Jacobian (for a quadratic V it is linear: one iteration).
#include <array>
#include <cmath>

#include <Eigen/LU>

#include "geomint/core/state.hpp"
#include "geomint/integrators/newton.hpp"
#include "geomint/methods/registry.hpp"  // orders, bounds, citations: method_info("lobatto"), ("simpson"), ("implicit_midpoint")

namespace geomint {

template <int S>
struct GalerkinRule {
  std::array<double, S + 1> c;       // nodes on [0, 1]
  std::array<double, S + 1> w;       // quadrature weights
  Eigen::Matrix<double, S + 1, S + 1> D;  // D(k, m) = phi_m'(c_k), Lagrange basis phi_m of degree S
};

// The derivative matrix of the Lagrange basis on the nodes c.
template <int S>
GalerkinRule<S> make_galerkin_rule(const std::array<double, S + 1>& c, const std::array<double, S + 1>& w) {
  GalerkinRule<S> R{c, w, {}};
  for (int k = 0; k <= S; ++k) {
    for (int m = 0; m <= S; ++m) {
      double denom = 1.0;
      for (int n = 0; n <= S; ++n)
        if (n != m) denom *= c[m] - c[n];
      if (k == m) {
        double s = 0.0;
        for (int n = 0; n <= S; ++n)
          if (n != m) s += 1.0 / (c[m] - c[n]);
        R.D(k, m) = s;
      } else {
        double num = 1.0;
        for (int n = 0; n <= S; ++n)
          if (n != m && n != k) num *= c[k] - c[n];
        R.D(k, m) = num / denom;
      }
    }
  }
  return R;
}

// 001 eq. (2)-(3): Lobatto nodes 0, xi, 1 - xi, 1 with xi = 1/2 - sqrt(5)/10, weights 1/12, 5/12, 5/12, 1/12.
inline GalerkinRule<3> lobatto_rule() {
  const double xi = 0.5 - std::sqrt(5.0) / 10.0;
  return make_galerkin_rule<3>({0.0, xi, 1.0 - xi, 1.0}, {1.0 / 12, 5.0 / 12, 5.0 / 12, 1.0 / 12});
}
// Simpson's rule on 0, 1/2, 1 with P2 elements (001 ref. [2]).
inline GalerkinRule<2> simpson_rule() { return make_galerkin_rule<2>({0.0, 0.5, 1.0}, {1.0 / 6, 4.0 / 6, 1.0 / 6}); }

// The implicit stage of one step: unknowns X = (Q_1, ..., Q_S).
template <int S, class Sys>
struct GalerkinStage {
  static constexpr int D = Sys::State::dof;
  static constexpr int N = S * D;
  using X = Vec<N>;
  const GalerkinRule<S>& R;
  const Sys& sys;
  Vec<D> q, p;  // q_j, p_j
  double h;

  Vec<D> node(const X& x, int n) const { return n == 0 ? q : Vec<D>(x.template segment<D>((n - 1) * D)); }
  // dL_d/dQ_n = sum_k w_k D_kn M qdot_k - h w_n grad V(Q_n).
  Vec<D> dLd(const X& x, int n) const {
    Vec<D> g = Vec<D>::Zero();
    for (int k = 0; k <= S; ++k) {
      Vec<D> qdot = Vec<D>::Zero();
      for (int m = 0; m <= S; ++m) qdot += R.D(k, m) * node(x, m);
      g += R.w[k] * R.D(k, n) * sys.mass() * (qdot / h);
    }
    return g - h * R.w[n] * sys.U_q(node(x, n));
  }
  // Equations: p_j + dL_d/dQ_0 = 0 and dL_d/dQ_n = 0, n = 1..S-1.
  X residual(const X& x) const {
    X r;
    for (int n = 0; n < S; ++n) r.template segment<D>(n * D) = dLd(x, n) + (n == 0 ? p : Vec<D>::Zero());
    return r;
  }
  Mat<N> jacobian(const X& x) const {
    Mat<N> J;
    for (int r = 0; r < S; ++r) {
      for (int n = 1; n <= S; ++n) {
        double kin = 0.0;
        for (int k = 0; k <= S; ++k) kin += R.w[k] * R.D(k, r) * R.D(k, n);
        Mat<D> block = (kin * sys.mass() / h) * Mat<D>::Identity();
        if (r == n) block -= h * R.w[n] * sys.U_qq(node(x, n));
        J.template block<D, D>(r * D, (n - 1) * D) = block;
      }
    }
    return J;
  }
  X guess() const {  // Q_n = q_j + c_n h M^{-1} p_j
    X x;
    for (int n = 1; n <= S; ++n) x.template segment<D>((n - 1) * D) = q + R.c[n] * h * p / sys.mass();
    return x;
  }
};

// One step (q_j, p_j) -> (q_{j+1}, p_{j+1}); Newton's iteration count is stored in *iterations if given.
template <int S, class Sys>
typename Sys::State galerkin_step(const GalerkinRule<S>& R, const Sys& sys, const typename Sys::State& z, double h,
                                  int* iterations = nullptr) {
  constexpr int D = Sys::State::dof;
  const GalerkinStage<S, Sys> stage{R, sys, z.q, z.p, h};
  using X = typename GalerkinStage<S, Sys>::X;
  const X x = newton_solve<GalerkinStage<S, Sys>::N>(
      [&](const X& y) { return std::pair<X, Mat<GalerkinStage<S, Sys>::N>>{stage.residual(y), stage.jacobian(y)}; },
      stage.guess(), "Galerkin variational step", iterations);
  typename Sys::State next;
  next.q = stage.node(x, S);
  next.p = stage.dLd(x, S);  // (11): p_{j+1} = dL_d/dQ_S
  (void)D;
  return next;
}

// The implicit midpoint rule for L = qdot^T M qdot/2 - V(q): Z = z_j + (h/2) f(Z), z_{j+1} = 2 Z - z_j,
// f = (M^{-1} p, -grad V(q)); Newton on Z.
template <class Sys>
typename Sys::State implicit_midpoint(const Sys& sys, const typename Sys::State& z, double h, int* iterations = nullptr) {
  constexpr int D = Sys::State::dof;
  using X = Vec<2 * D>;
  X z0;
  z0 << z.q, z.p;
  const double im = 1.0 / sys.mass();
  const X Z = newton_solve<2 * D>(
      [&](const X& y) {
        const Vec<D> q = y.template head<D>(), p = y.template tail<D>();
        X r;
        r << q - z.q - 0.5 * h * im * p, p - z.p + 0.5 * h * sys.U_q(q);
        Mat<2 * D> J = Mat<2 * D>::Identity();
        J.template block<D, D>(0, D) = -0.5 * h * im * Mat<D>::Identity();
        J.template block<D, D>(D, 0) = 0.5 * h * sys.U_qq(q);
        return std::pair<X, Mat<2 * D>>{r, J};
      },
      z0, "implicit midpoint", iterations);
  typename Sys::State next;
  next.q = 2 * Z.template head<D>() - z.q;
  next.p = 2 * Z.template tail<D>() - z.p;
  return next;
}

}  // namespace geomint

namespace geomint {

// The Jacobian d(q_{j+1}, p_{j+1}) / d(q_j, p_j) of one Galerkin step, by the
// implicit function theorem on the converged stage (for the symplecticity check
// J^T Omega J = Omega, without finite differences).
template <int S, class Sys>
Mat<2 * Sys::State::dof> galerkin_step_jacobian(const GalerkinRule<S>& R, const Sys& sys,
                                                 const typename Sys::State& z, double h) {
  constexpr int D = Sys::State::dof, N = S * D;
  const GalerkinStage<S, Sys> stage{R, sys, z.q, z.p, h};
  using X = Vec<N>;
  const X x = newton_solve<N>(
      [&](const X& y) { return std::pair<X, Mat<N>>{stage.residual(y), stage.jacobian(y)}; }, stage.guess(),
      "Galerkin variational step");
  // d^2 L_d / dQ_r dQ_n for all r, n in 0..S.
  const auto d2 = [&](int r, int n) {
    double kin = 0.0;
    for (int k = 0; k <= S; ++k) kin += R.w[k] * R.D(k, r) * R.D(k, n);
    Mat<D> b = (kin * sys.mass() / h) * Mat<D>::Identity();
    if (r == n) b -= h * R.w[n] * sys.U_qq(stage.node(x, n));
    return b;
  };
  // dR/d(q_j, p_j): R_r = dL_d/dQ_r + [r == 0] p_j.
  Eigen::Matrix<double, N, 2 * D> dRdz = Eigen::Matrix<double, N, 2 * D>::Zero();
  for (int r = 0; r < S; ++r) dRdz.template block<D, D>(r * D, 0) = d2(r, 0);
  dRdz.template block<D, D>(0, D) = Mat<D>::Identity();
  const Eigen::Matrix<double, N, 2 * D> dX = -stage.jacobian(x).partialPivLu().solve(dRdz);
  Mat<2 * D> J;
  J.template block<D, 2 * D>(0, 0) = dX.template block<D, 2 * D>((S - 1) * D, 0);  // q_{j+1} = Q_S
  Eigen::Matrix<double, D, 2 * D> dp = Eigen::Matrix<double, D, 2 * D>::Zero();   // p_{j+1} = dL_d/dQ_S
  dp.template block<D, D>(0, 0) = d2(S, 0);
  for (int n = 1; n <= S; ++n) dp += d2(S, n) * dX.template block<D, 2 * D>((n - 1) * D, 0);
  J.template block<D, 2 * D>(D, 0) = dp;
  return J;
}

}  // namespace geomint
