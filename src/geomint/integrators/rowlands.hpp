#pragma once
// The Rowlands kernel (000 Section 3.3): Stormer-Verlet with the effective
// potential Uhat of 000 eq. (30), a kernel of effective order 4 (its processors
// are in transforms/rowlands_processors.hpp).
#include "geomint/core/state.hpp"
#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/methods/registry.hpp"  // its order, bounds and citation: method_info("rowlands_kernel")

namespace geomint {

// -grad Uhat for Uhat = U - h^2/24 U_q M^{-1} U_q (000 eq. (30)):
// Fhat = -U_q + (h^2/12) U_qq M^{-1} U_q  (one gradient, one Hessian-vector product).
template <class Sys, class V>
V rowlands_force(const Sys& sys, const V& q, double h) {
  const V g = sys.U_q(q);
  return (-g + (h * h / 12.0) * sys.U_qq_times(q, sys.inv_mass(g))).eval();
}

// 000 eq. (31): Exp(h/2 Uhat) Exp(h T) Exp(h/2 Uhat).
template <class Sys, int D>
KickState<D> rowlands_kernel(const Sys& sys, const KickState<D>& s, double h) {
  return kick_drift_kick(sys, [&](const Vec<D>& q) { return rowlands_force(sys, q, h); }, s, h);
}

}  // namespace geomint
