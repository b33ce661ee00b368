#pragma once
#include "geomint/core/state.hpp"

namespace geomint {

// Stability: real-axis interval [-2.785, 0]; imaginary-axis interval |h w| <= 2 sqrt(2).
inline constexpr MethodInfo runge_kutta4_info{"rk4", 4, "classical RK4 (Hairer, Norsett, Wanner I, Table 1.2)",
                                              2.785293563405282, 2.8284271247461903};

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
