#pragma once
// The time average of a function F(q, p) over the rotating orbit of energy E of a system with one degree
// of freedom, H = p^2/2 + U(q), U 2 pi-periodic, E > max U, p = sqrt(2 (E - U(q))) > 0: since dt = dq / p,
//   <F> = (int_0^{2 pi} F(q, p(q)) / p(q) dq) / (int_0^{2 pi} dq / p(q)),
// by the trapezoidal rule on n equidistant points (for a smooth periodic integrand its error falls faster
// than any power of 1/n). Used for the rate (4.3) of 004 at the current energy of Fig. 2's pendulum.
#include <cmath>
#include <numbers>
#include <string>

#include "geomint/core/numerical_failure.hpp"
#include "geomint/core/state.hpp"

namespace geomint {

template <class Sys, class F>
double rotation_average(const Sys& sys, double E, const F& f, int n = 4096) {
  double num = 0, den = 0;
  for (int i = 0; i < n; ++i) {
    const double q = 2 * std::numbers::pi * i / n;
    const double kinetic = 2 * (E - sys.U(Vec<1>(q)));
    if (!(kinetic > 0))
      throw NumericalFailure("rotation_average: the orbit of energy " + std::to_string(E) + " does not rotate (E <= max U)");
    const double p = std::sqrt(kinetic);
    num += f(q, p) / p, den += 1 / p;
  }
  return num / den;
}

}  // namespace geomint
