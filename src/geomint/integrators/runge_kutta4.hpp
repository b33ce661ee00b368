#pragma once
#include "geomint/core/state.hpp"
#include "geomint/methods/registry.hpp"  // its order, bounds and citation: method_info("rk4")

namespace geomint {

// The classical fourth-order Runge-Kutta method (non-symplectic baseline).
template <class Sys, class Y>
Y runge_kutta4(const Sys& sys, const Y& y, double h) {
  const Y k1 = sys.f(y);
  const Y k2 = sys.f(y + (0.5 * h) * k1);
  const Y k3 = sys.f(y + (0.5 * h) * k2);
  const Y k4 = sys.f(y + h * k3);
  return y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace geomint
