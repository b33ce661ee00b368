#pragma once
// Modified energies of the Takahashi-Imada methods (004 Sect. 3-4, brackets
// written as derivative contractions as in the technical note), for unit mass
// and alpha = 1/12. Exact derivatives from the system (U_q, U_qq_times, U4, U5).
#include "geomint/core/state.hpp"

namespace geomint {

// 004 (3.3) with alpha = 1/12: H_3 = (U''(p, p) - |grad U|^2) / 12.
template <class Sys, int D>
double ti_H3(const Sys& sys, const PhaseState<D>& z) {
  const Vec<D> g = sys.U_q(z.q);
  return (z.p.dot(sys.U_qq_times(z.q, z.p)) - g.squaredNorm()) / 12.0;
}

// 004 Fig. 2: H + h^2 H_3 (TI's H_3).
template <class Sys, int D>
double shifted_energy(const Sys& sys, const PhaseState<D>& z, double h) {
  return sys.H(z) + h * h * ti_H3(sys, z);
}

// 004 (3.3) + (4.2), the quantity of Figs 3, 4, 6: E = Hhat + h^4 alpha^2 K / 2 =
// T + U + h^2/12 (U''(p,p) - |g|^2) + h^4 [-U''''(p^4)/576 + U''(g,g)/288 + |U''p|^2/96].
template <class Sys, int D>
double simplified_ti_modified_energy(const Sys& sys, const PhaseState<D>& z, double h) {
  const Vec<D> g = sys.U_q(z.q), Up = sys.U_qq_times(z.q, z.p), Ug = sys.U_qq_times(z.q, g);
  const double h2 = h * h;
  return sys.H(z) + h2 / 12.0 * (z.p.dot(Up) - g.squaredNorm()) +
         h2 * h2 * (-sys.U4(z.q, z.p) / 576.0 + g.dot(Ug) / 288.0 + Up.squaredNorm() / 96.0);
}

// 004 (4.3): d/dt E = -h^4/2880 U^(5)(p^5) + O(h^6) along the simplified method.
template <class Sys, int D>
double simplified_ti_drift_rate(const Sys& sys, const PhaseState<D>& z, double h) {
  return -h * h * h * h / 2880.0 * sys.U5(z.q, z.p);
}

}  // namespace geomint
