#pragma once
// Stormer-Verlet (kick-drift-kick) for separable H = p^T M^{-1} p / 2 + U(q).
#include "geomint/core/integrate.hpp"
#include "geomint/core/state.hpp"
#include "geomint/methods/registry.hpp"  // its order, bounds and citation: method_info("stormer_verlet")

namespace geomint {

// The state of a kick-drift-kick method: (q, p) and the force at q, which the
// last kick of a step computes and the first kick of the next step reuses
// (one force evaluation per step).
template <int D>
struct KickState {
  PhaseState<D> z;
  Vec<D> F;
};

// 000 eq. (26)-(28) with the force F(q): p^{j+1/2} = p^j + h/2 F(q^j);
// q^{j+1} = q^j + h M^{-1} p^{j+1/2};  p^{j+1} = p^{j+1/2} + h/2 F(q^{j+1}).
template <class Sys, class Force, int D>
KickState<D> kick_drift_kick(const Sys& sys, const Force& force, const KickState<D>& s, double h) {
  KickState<D> next;
  const Vec<D> p_half = s.z.p + (0.5 * h) * s.F;
  next.z.q = s.z.q + h * sys.inv_mass(p_half);
  next.F = force(next.z.q);
  next.z.p = p_half + (0.5 * h) * next.F;
  return next;
}

// Stormer-Verlet: kick-drift-kick with the force -U_q.
template <class Sys, int D>
KickState<D> stormer_verlet(const Sys& sys, const KickState<D>& s, double h) {
  return kick_drift_kick(sys, [&](const Vec<D>& q) { return sys.force(q); }, s, h);
}

// A step(sys, s, h) on kick states as a method on (q, p): the force -U_q attached before the
// first step, dropped after the last.
template <class Sys, class Step>
auto force_cached_method(const Sys& sys, Step step) {
  using S = KickState<Sys::State::dof>;
  return Processed{[&sys, step](const S& s, double h) { return step(sys, s, h); },
                   [&sys](const typename Sys::State& z, double) { return S{z, sys.force(z.q)}; },
                   [](const S& s, double) { return s.z; }};
}

// Stormer-Verlet (26)-(28) as a method on (q, p).
template <class Sys>
auto stormer_verlet_method(const Sys& sys) {
  return force_cached_method(sys, [](const auto& sy, const auto& s, double h) { return stormer_verlet(sy, s, h); });
}

}  // namespace geomint
