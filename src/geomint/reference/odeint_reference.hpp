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

#include "geomint/core/numerical_failure.hpp"
#include "geomint/core/state.hpp"

namespace geomint {

// odeint's integrate_adaptive of x from t0 to t1 (first step dt0) with an adaptive stepper, kept by
// the caller across calls; a stepper that gives up (odeint's step_adjustment_error,
// no_progress_error) or a non-finite state at t1 is a NumericalFailure.
template <class Stepper, class Rhs, class X>
void reference_integrate(Stepper& stepper, const Rhs& rhs, X& x, double t0, double t1, double dt0) {
  namespace odeint = boost::numeric::odeint;
  const auto where = [&] { return "odeint reference from t = " + std::to_string(t0) + " to " + std::to_string(t1); };
  try {
    odeint::integrate_adaptive(stepper, rhs, x, t0, t1, dt0);
  } catch (const odeint::odeint_error& e) {
    throw NumericalFailure(where() + ": " + e.what());
  }
  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }))
    throw NumericalFailure(where() + ": the state is not finite");
}

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
  constexpr int D = Sys::State::dof;
  auto x = to_odeint<D>(z0);
  boost::numeric::odeint::bulirsch_stoer<OdeintState<D>> stepper(atol, rtol);
  reference_integrate(stepper, odeint_rhs(sys), x, 0.0, t_end, std::min(1e-3, t_end));
  return from_odeint<D>(x);
}

// The same for a first-order system x' = sys.rhs(x) on std::array (the equations (3.8) of 003).
template <class Sys, std::size_t N>
std::array<double, N> reference_solution(const Sys& sys, std::array<double, N> x, double t_end, double rtol, double atol) {
  boost::numeric::odeint::bulirsch_stoer<std::array<double, N>> stepper(atol, rtol);
  reference_integrate(stepper, [&sys](const std::array<double, N>& y, std::array<double, N>& dydt, double) { dydt = sys.rhs(y); },
                      x, 0.0, t_end, std::min(1e-3, t_end));
  return x;
}

}  // namespace geomint
