#pragma once
// The Takahashi-Imada method and its simplified version (004 Sect. 1), as
// kick-drift-kick kernels with the force cached between steps, and the
// processing map chi_h of (1.5) that gives the method effective order 4.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geomint/core/dense_solve.hpp"
#include "geomint/core/state.hpp"
#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/core/integrate.hpp"

namespace geomint {

inline constexpr double takahashi_imada_alpha = 1.0 / 12.0;  // 004 (1.4)

// 004 (1.4): F_TI(q) = (I + alpha h^2 f'(q)) f(q) = -(g - alpha h^2 U''(q) g), g = grad U(q)
// (one gradient and one Hessian-vector product).
template <class Sys, class V>
V takahashi_imada_force(const Sys& sys, const V& q, double h, double alpha) {
  const V g = sys.U_q(q);
  return (-(g - (alpha * h * h) * sys.U_qq_times(q, g))).eval();
}

// 004 (1.6): F_S(q) = f(q + alpha h^2 f(q)) = -grad U(q - alpha h^2 grad U(q)) (two gradients).
template <class Sys, class V>
V simplified_ti_force(const Sys& sys, const V& q, double h, double alpha) {
  return sys.force((q - (alpha * h * h) * sys.U_q(q)).eval());
}

// 004 (1.5), forward (numerical -> accurate variables): qhat = q - c h^2 grad U(q),
// phat = (I - c h^2 U''(q))^{-1} p (U'' at the unprocessed q).
template <class Sys, int D>
PhaseState<D> ti_process(const Sys& sys, const PhaseState<D>& z, double h, double c) {
  const double ch2 = c * h * h;
  const Mat<D> A = Mat<D>::Identity() - ch2 * sys.U_qq(z.q);
  return make_state<D>(z.q - ch2 * sys.U_q(z.q), lu_solve<D>(A, z.p));
}

// 004 (1.5), inverse: q from q - c h^2 grad U(q) = qhat by the fixed point
// q <- qhat + c h^2 grad U(q) (a contraction for c h^2 |U''| < 1, iterated to
// round-off), then p = (I - c h^2 U''(q)) phat.
template <class Sys, int D>
PhaseState<D> ti_unprocess(const Sys& sys, const PhaseState<D>& zhat, double h, double c) {
  const double ch2 = c * h * h;
  Vec<D> q = zhat.q;
  for (int it = 0; it < 200; ++it) {
    const Vec<D> next = zhat.q + ch2 * sys.U_q(q);
    const bool done = (next - q).template lpNorm<Eigen::Infinity>() <=
                      2 * std::numeric_limits<double>::epsilon() * std::max(1.0, q.template lpNorm<Eigen::Infinity>());
    q = next;
    if (done) break;
  }
  return make_state<D>(q, (Mat<D>::Identity() - ch2 * sys.U_qq(q)) * zhat.p);
}

// 004 Sect. 3.3: the printed leading term 1/4 h^6 alpha^2 f''(f, f) of q_{n+1} of (1.6) minus q_{n+1}
// of (1.4) from the same (p_n, q_n), at the point q given (printed: q_{n+1/2} = (q_n + q_{n+1})/2);
// f''(f, f) = -U'''(grad U, grad U, .) since f = -grad U.
template <class Sys, class V>
V simplified_ti_q_correction(const Sys& sys, const V& q, double h, double alpha) {
  const V g = sys.U_q(q);
  return (-0.25 * std::pow(h, 6) * alpha * alpha * sys.U3_times(q, g, g)).eval();
}

// The methods as processed methods on (q, p) (core/integrate.hpp): kick-drift-kick
// with the given force, plain (no processing, as 004 Figs 2-6 use them) or with
// chi_h, c = alpha (Fig. 1, effective order 4).
template <class Sys, class Force>
auto kick_method_with_force(const Sys& sys, Force force, bool processed, double c) {
  using S = KickState<Sys::State::dof>;
  using Z = typename Sys::State;
  return Processed{[&sys, force](const S& s, double h) {
                     return kick_drift_kick(sys, [&](const auto& q) { return force(q, h); }, s, h);
                   },
                   [&sys, force, processed, c](const Z& z, double h) {
                     const Z z0 = processed ? ti_unprocess(sys, z, h, c) : z;
                     return S{z0, force(z0.q, h)};
                   },
                   [&sys, processed, c](const S& s, double h) { return processed ? ti_process(sys, s.z, h, c) : s.z; }};
}

template <class Sys>
auto takahashi_imada_method(const Sys& sys, bool processed, double alpha = takahashi_imada_alpha) {
  return kick_method_with_force(
      sys, [&sys, alpha](const auto& q, double h) { return takahashi_imada_force(sys, q, h, alpha); }, processed, alpha);
}

template <class Sys>
auto simplified_ti_method(const Sys& sys, bool processed, double alpha = takahashi_imada_alpha) {
  return kick_method_with_force(
      sys, [&sys, alpha](const auto& q, double h) { return simplified_ti_force(sys, q, h, alpha); }, processed, alpha);
}

// ---- 004 Sect. 1.4: the harmonic oscillator, as functions of w h (x = (w h)^2) ----

// The largest relative error of H along Stormer-Verlet from a start with q_0 = 0 (attained where
// p_n = 0): x / (4 - x).
inline double sv_oscillator_max_rel_energy_error(double wh) { return wh * wh / (4 - wh * wh); }

// The same along Takahashi-Imada (1.4) (and (1.6), the same map here) in the variables of (1.5),
// from a start with q_0 = 0: (4 - beta x - 4 beta^3) / (4 - beta x) = x^3 / (36 (x^2 - 12 x + 48)),
// beta = 1 - x/12.
inline double ti_oscillator_max_rel_energy_error(double wh) {
  return std::pow(wh, 6) / (36 * (std::pow(wh, 4) - 12 * wh * wh + 48));
}

// The same from a start with p_0 = 0 instead: a - 1 = x^3 / (12 - x)^3, where a = (1 - beta x/4) beta^-3
// is the coefficient of the invariant phat^2 + a w^2 qhat^2 (unbounded as w h -> 2 sqrt(3)).
inline double ti_oscillator_max_rel_energy_error_from_rest(double wh) {
  const double x = wh * wh;
  return x * x * x / std::pow(12 - x, 3);
}

}  // namespace geomint
