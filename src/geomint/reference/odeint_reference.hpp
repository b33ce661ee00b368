#pragma once
// High-accuracy reference solutions from Boost.Odeint: the adaptive
// Bulirsch-Stoer extrapolation stepper on z' = J grad H(z) (000 eq. (20)),
// landing exactly on the requested time. Experiments check its accuracy in
// the run: the solution at 100x tighter tolerances must agree to well below
// the smallest error they fit.
#include <algorithm>
#include <array>
#include <cmath>

#include <boost/numeric/odeint.hpp>

#include "geomint/core/state.hpp"

namespace geomint {

template <int D>
using OdeintState = std::array<double, 2 * D>;  // (q_1..q_D, p_1..p_D)

template <int D>
OdeintState<D> to_odeint(const PhaseState<D>& z) {
  OdeintState<D> x;
  for (int i = 0; i < D; ++i) x[i] = z.q[i], x[D + i] = z.p[i];
  return x;
}

template <int D>
PhaseState<D> from_odeint(const OdeintState<D>& x) {
  PhaseState<D> z;
  for (int i = 0; i < D; ++i) z.q[i] = x[i], z.p[i] = x[D + i];
  return z;
}

// The right-hand side (20) in odeint's system signature.
template <class Sys>
auto odeint_rhs(const Sys& sys) {
  constexpr int D = Sys::State::dof;
  return [&sys](const OdeintState<D>& x, OdeintState<D>& dxdt, double) {
    const PhaseState<D> z = from_odeint<D>(x);
    const Vec<D> dq = sys.H_p(z.q, z.p), dp = -sys.H_q(z.q, z.p);
    for (int i = 0; i < D; ++i) dxdt[i] = dq[i], dxdt[D + i] = dp[i];
  };
}

// The solution at t_end of the system from z0, to the tolerances (rtol, atol).
template <class Sys>
typename Sys::State reference_solution(const Sys& sys, const typename Sys::State& z0, double t_end, double rtol,
                                       double atol) {
  namespace odeint = boost::numeric::odeint;
  constexpr int D = Sys::State::dof;
  auto x = to_odeint<D>(z0);
  odeint::bulirsch_stoer<OdeintState<D>> stepper(atol, rtol);
  odeint::integrate_adaptive(stepper, odeint_rhs(sys), x, 0.0, t_end, std::min(1e-3, t_end));
  return from_odeint<D>(x);
}

// The same for a first-order system x' = sys.rhs(x) on std::array (the equations (3.8) of 003).
template <class Sys, std::size_t N>
std::array<double, N> reference_solution(const Sys& sys, std::array<double, N> x, double t_end, double rtol, double atol) {
  namespace odeint = boost::numeric::odeint;
  odeint::bulirsch_stoer<std::array<double, N>> stepper(atol, rtol);
  odeint::integrate_adaptive(stepper, [&sys](const std::array<double, N>& y, std::array<double, N>& dydt, double) { dydt = sys.rhs(y); },
                             x, 0.0, t_end, std::min(1e-3, t_end));
  return x;
}

}  // namespace geomint
