#pragma once
// Pre- and postprocessors of the Rowlands kernel (000 eq. (32)-(37)), and the
// trivial ones that turn a kick-drift-kick kernel into a method on (q, p).
//
// Coefficient: 000 eq. (32)-(33) print h^2/24. The kernel (31) conserves a
// modified energy whose O(h^2) part differs from H by (h^2/12) d/dt(U_q M^{-1} p);
// the processor that removes it is the time-h^2/12 flow of U_q M^{-1} p, i.e.
// (32)-(33) with h^2/12. (On the oscillator U = w^2 q^2/2 the kernel's
// invariant ellipse is p^2 + w^2 (1 - h^2 w^2/3) q^2 + O(h^4), the image of the
// exact orbits under the symplectic map qbar = (1 + h^2 w^2/12) q,
// pbar = (1 - h^2 w^2/12) p.) The cheap processors (34)-(37)
// expand to h^2/12 as well (U_q^{+1/2} + U_q^{-1/2} = 2 U_q + O(h^2)). With the
// printed h^2/24 the processed method is of order 2 only; the experiment
// rowlands_convergence measures both (see paper/).
#include "geomint/core/state.hpp"
#include "geomint/integrators/rowlands.hpp"
#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/core/integrate.hpp"

namespace geomint {

inline constexpr double rowlands_processor_coefficient = 1.0 / 12.0;          // derived (see above)
inline constexpr double rowlands_processor_coefficient_printed = 1.0 / 24.0;  // as printed in (32)-(33)

// 000 eq. (32)-(33) with coefficient c: qbar = q + c h^2 M^{-1} U_q(q), pbar = p - c h^2 U_qq(q) M^{-1} p.
template <class Sys, int D>
PhaseState<D> rowlands_pre_exact(const Sys& sys, const PhaseState<D>& z, double h, double c) {
  const double ch2 = c * h * h;
  return make_state<D>(z.q + ch2 * sys.inv_mass(sys.U_q(z.q)), z.p - ch2 * sys.U_qq_times(z.q, sys.inv_mass(z.p)));
}

// Inverse of (32)-(33) to O(h^4): q = qbar - c h^2 M^{-1} U_q(qbar), p = pbar + c h^2 U_qq(qbar) M^{-1} pbar.
template <class Sys, int D>
PhaseState<D> rowlands_post_exact(const Sys& sys, const PhaseState<D>& zb, double h, double c) {
  return rowlands_pre_exact(sys, zb, h, -c);
}

// 000 eq. (34)-(35): qbar = q + h^2/24 M^{-1}(U_q^{+} + U_q^{-}), pbar = p - h/12 (U_q^{+} - U_q^{-}),
// U_q^{+-} = U_q(q +- h/2 M^{-1} p).
template <class Sys, int D>
PhaseState<D> rowlands_pre_cheap(const Sys& sys, const PhaseState<D>& z, double h) {
  const Vec<D> v = (0.5 * h) * sys.inv_mass(z.p);
  const Vec<D> up = sys.U_q((z.q + v).eval()), um = sys.U_q((z.q - v).eval());
  return make_state<D>(z.q + (h * h / 24.0) * sys.inv_mass((up + um).eval()), z.p - (h / 12.0) * (up - um));
}

// 000 eq. (36)-(37): q^j = qbar^j + (qbar^{j+1} - 2 qbar^j + qbar^{j-1})/12,
//                    p^j = pbar^j - (pbar^{j+1} - 2 pbar^j + pbar^{j-1})/12.
template <int D>
PhaseState<D> rowlands_post_cheap(const PhaseState<D>& prev, const PhaseState<D>& cur, const PhaseState<D>& next) {
  return make_state<D>(cur.q + (next.q - 2.0 * cur.q + prev.q) / 12.0, cur.p - (next.p - 2.0 * cur.p + prev.p) / 12.0);
}

// ---- the Rowlands methods of 000 Fig. 4 as processed methods (core/integrate.hpp) ----

// The Rowlands kernel (31) without processing.
template <class Sys>
auto rowlands_kernel_method(const Sys& sys) {
  using S = KickState<Sys::State::dof>;
  return Processed{[&sys](const S& s, double h) { return rowlands_kernel(sys, s, h); },
                   [&sys](const typename Sys::State& z, double h) { return S{z, rowlands_force(sys, z.q, h)}; },
                   [](const S& s, double) { return s.z; }};
}

// The kernel (31) with the processors (32)-(33), coefficient c.
template <class Sys>
auto rowlands_method(const Sys& sys, double c = rowlands_processor_coefficient) {
  using S = KickState<Sys::State::dof>;
  return Processed{[&sys](const S& s, double h) { return rowlands_kernel(sys, s, h); },
                   [&sys, c](const typename Sys::State& z, double h) {
                     const auto zb = rowlands_pre_exact(sys, z, h, c);
                     return S{zb, rowlands_force(sys, zb.q, h)};
                   },
                   [&sys, c](const S& s, double h) { return rowlands_post_exact(sys, s.z, h, c); }};
}

// The kernel (31) with the cheap processors (34)-(37).
template <class Sys>
auto rowlands_cheap_method(const Sys& sys) {
  using S = KickState<Sys::State::dof>;
  return Processed{[&sys](const S& s, double h) { return rowlands_kernel(sys, s, h); },
                   [&sys](const typename Sys::State& z, double h) {
                     const auto zb = rowlands_pre_cheap(sys, z, h);
                     return S{zb, rowlands_force(sys, zb.q, h)};
                   },
                   [](const S& prev, const S& cur, const S& next, double) {
                     return rowlands_post_cheap(prev.z, cur.z, next.z);
                   }};
}

}  // namespace geomint
