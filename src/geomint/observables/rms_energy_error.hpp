#pragma once
// The RMS energy error of 000 eq. (50) along symplectic Euler (42)-(43) with the generic library
// method (symplectic_euler_pq on any system of the library): the independent computation against
// which the written-out loops of the energy map (sweep/energy_map.hpp) are checked.
#include <cmath>
#include <cstdint>

#include "geomint/core/state.hpp"
#include "geomint/integrators/symplectic_euler.hpp"

namespace geomint {

// 000 eq. (50): eps = sqrt(sum_{j=1}^{J} (H_j - H_0)^2 / J) over J = `steps` steps of size h from z.
template <class Sys, int D>
double symplectic_euler_rms_energy_error(const Sys& sys, PhaseState<D> z, double h, std::int64_t steps) {
  const double H0 = sys.H(z);
  double sum = 0;
  for (std::int64_t j = 1; j <= steps; ++j) {
    z = symplectic_euler_pq(sys, z, h);
    const double d = sys.H(z) - H0;
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(steps));
}

}  // namespace geomint
