#pragma once
// High-accuracy reference solutions from Boost.Odeint: the adaptive
// Bulirsch-Stoer extrapolation stepper on z' = J grad H(z) (000 eq. (20)),
// landing exactly on the requested time. Experiments check its accuracy in
// the run: the solution at 100x tighter tolerances must agree to well below
// the smallest error they fit. The stepper is compiled once, in
// odeint_reference.cpp, for a state of any length: this header does not parse Boost.Odeint.
#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>

#include "geomint/core/numerical_failure.hpp"
#include "geomint/core/state.hpp"

namespace geomint {

// The field of a first-order system x' = f(x): f(x, dxdt) writes dxdt (both of the integrator's length).
using ReferenceField = std::function<void(const double* x, double* dxdt)>;

// odeint's bulirsch_stoer at tolerances (rtol, atol) on a state of n doubles, kept by the caller across
// calls (its step size carries over from one call to the next).
class ReferenceIntegrator {
 public:
  ReferenceIntegrator(std::size_t n, ReferenceField f, double rtol, double atol);
  ~ReferenceIntegrator();
  ReferenceIntegrator(const ReferenceIntegrator&) = delete;
  ReferenceIntegrator& operator=(const ReferenceIntegrator&) = delete;
  // x from t0 to t1 (first step dt0) by odeint's integrate_adaptive; a stepper that gives up
  // (odeint's step_adjustment_error, no_progress_error) or a non-finite state at t1 is a NumericalFailure.
  void integrate(std::span<double> x, double t0, double t1, double dt0);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

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

// The right-hand side (20) on (q, p) stored as x = (q_1..q_D, p_1..p_D).
template <class Sys>
void hamiltonian_field(const Sys& sys, const double* x, double* dxdt) {
  constexpr int D = Sys::State::dof;
  PhaseState<D> z;
  for (int i = 0; i < D; ++i) z.q[i] = x[i], z.p[i] = x[D + i];
  const Vec<D> dq = sys.H_p(z.q, z.p), dp = -sys.H_q(z.q, z.p);
  for (int i = 0; i < D; ++i) dxdt[i] = dq[i], dxdt[D + i] = dp[i];
}

// The right-hand side (20) in odeint's system signature (for odeint's fixed-step steppers).
template <class Sys>
auto odeint_rhs(const Sys& sys) {
  constexpr int D = Sys::State::dof;
  return [&sys](const OdeintState<D>& x, OdeintState<D>& dxdt, double) { hamiltonian_field(sys, x.data(), dxdt.data()); };
}

// The solution at t_end of the system from z0, to the tolerances (rtol, atol).
template <class Sys>
typename Sys::State reference_solution(const Sys& sys, const typename Sys::State& z0, double t_end, double rtol,
                                       double atol) {
  constexpr int D = Sys::State::dof;
  auto x = to_odeint<D>(z0);
  ReferenceIntegrator(2 * D, [&sys](const double* y, double* dydt) { hamiltonian_field(sys, y, dydt); }, rtol, atol)
      .integrate(x, 0.0, t_end, std::min(1e-3, t_end));
  return from_odeint<D>(x);
}

// The field of a first-order system x' = sys.rhs(x) on std::array<double, N> (the equations (3.8) of 003).
template <std::size_t N, class Sys>
ReferenceField array_field(const Sys& sys) {
  return [&sys](const double* y, double* dydt) {
    std::array<double, N> a;
    std::copy_n(y, N, a.begin());
    const std::array<double, N> f = sys.rhs(a);
    std::copy_n(f.begin(), N, dydt);
  };
}

// The same for a first-order system x' = sys.rhs(x) on std::array.
template <class Sys, std::size_t N>
std::array<double, N> reference_solution(const Sys& sys, std::array<double, N> x, double t_end, double rtol, double atol) {
  ReferenceIntegrator(N, array_field<N>(sys), rtol, atol).integrate(x, 0.0, t_end, std::min(1e-3, t_end));
  return x;
}

}  // namespace geomint
