#pragma once
// The fourth-order composition of Forest & Ruth (1990) and Yoshida (1990):
// Stormer-Verlet (000 eq. (26)-(28)) with the steps g1 h, g2 h, g1 h.
#include <cmath>

#include "geomint/integrators/stormer_verlet.hpp"

namespace geomint {

inline constexpr double forest_ruth_g1 = 1.0 / (2.0 - std::cbrt(2.0));  // g1 = 1/(2 - 2^(1/3))
inline constexpr double forest_ruth_g2 = 1.0 - 2.0 * forest_ruth_g1;    // g2 = 1 - 2 g1 (negative)

// SV(g1 h) SV(g2 h) SV(g1 h); the cached force makes it 3 force evaluations per step.
template <class Sys, int D>
KickState<D> forest_ruth(const Sys& sys, const KickState<D>& s, double h) {
  return stormer_verlet(sys, stormer_verlet(sys, stormer_verlet(sys, s, forest_ruth_g1 * h), forest_ruth_g2 * h),
                        forest_ruth_g1 * h);
}

// As a method on (q, p).
template <class Sys>
auto forest_ruth_method(const Sys& sys) {
  return force_cached_method(sys, [](const auto& sy, const auto& s, double h) { return forest_ruth(sy, s, h); });
}

}  // namespace geomint
