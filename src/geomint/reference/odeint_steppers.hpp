#pragma once
// Boost.Odeint's fixed-step steppers, the peers of our methods, as processed
// methods on (q, p) (core/integrate.hpp) whose kernel state is odeint's state. A
// Runge-Kutta stepper keeps only scratch space between steps: one lives in the
// kernel (so a bound method steps one trajectory at a time, as every driver
// here does); velocity_verlet, which caches the acceleration at the current
// point, travels with the state.
#include <array>
#include <utility>

#include <boost/numeric/odeint.hpp>

#include "geomint/reference/odeint_reference.hpp"
#include "geomint/core/integrate.hpp"

namespace geomint {

namespace detail {
template <int D>
std::array<double, D> to_std_array(const Vec<D>& v) {
  std::array<double, D> a;
  Eigen::Map<Vec<D>>(a.data()) = v;
  return a;
}
template <int D>
Vec<D> to_vec(const std::array<double, D>& a) {
  return Eigen::Map<const Vec<D>>(a.data());
}
}  // namespace detail

// One step of an explicit Runge-Kutta stepper of odeint; `stepper` is scratch space only.
template <class Stepper, class Rhs>
struct OdeintStep {
  Rhs rhs;
  mutable Stepper stepper;
  template <class X>
  X operator()(X x, double h) const {
    stepper.do_step(rhs, x, 0.0, h);
    return x;
  }
};

// An explicit Runge-Kutta stepper of odeint (runge_kutta4, runge_kutta_fehlberg78) on z' = J grad H (000 eq. (20)).
template <class Stepper, class Sys>
auto odeint_explicit_method(const Sys& sys) {
  constexpr int D = Sys::State::dof;
  return Processed{OdeintStep<Stepper, decltype(odeint_rhs(sys))>{odeint_rhs(sys), Stepper()},
                   [](const typename Sys::State& z, double) { return to_odeint<D>(z); },
                   [](const OdeintState<D>& x, double) { return from_odeint<D>(x); }};
}

template <class Sys>
auto odeint_rk4_method(const Sys& sys) {
  return odeint_explicit_method<boost::numeric::odeint::runge_kutta4<OdeintState<Sys::State::dof>>>(sys);
}

template <class Sys>
auto odeint_rkf78_method(const Sys& sys) {
  return odeint_explicit_method<boost::numeric::odeint::runge_kutta_fehlberg78<OdeintState<Sys::State::dof>>>(sys);
}

// symplectic_rkn_sb3a_mclachlan on the separable pair dq/dt = M^{-1} p, dp/dt = -U_q(q).
template <class Sys>
auto odeint_rkn_sb3a_method(const Sys& sys) {
  constexpr int D = Sys::State::dof;
  using A = std::array<double, D>;
  using S = std::pair<A, A>;
  return Processed{[&sys](S x, double h) {
                     const auto dq = [&sys](const A& p, A& dqdt) { dqdt = detail::to_std_array<D>(sys.inv_mass(detail::to_vec<D>(p))); };
                     const auto dp = [&sys](const A& q, A& dpdt) { dpdt = detail::to_std_array<D>(sys.force(detail::to_vec<D>(q))); };
                     boost::numeric::odeint::symplectic_rkn_sb3a_mclachlan<A>().do_step(std::make_pair(dq, dp), x, 0.0, h);
                     return x;
                   },
                   [](const typename Sys::State& z, double) { return S{detail::to_std_array<D>(z.q), detail::to_std_array<D>(z.p)}; },
                   [](const S& x, double) { return make_state<D>(detail::to_vec<D>(x.first), detail::to_vec<D>(x.second)); }};
}

// velocity_verlet on x'' = M^{-1} F(x), state (x, v) with v = M^{-1} p (scalar mass M = m I).
template <class Sys>
auto odeint_velocity_verlet_method(const Sys& sys) {
  constexpr int D = Sys::State::dof;
  using A = std::array<double, D>;
  using Stepper = boost::numeric::odeint::velocity_verlet<A>;
  struct S {
    std::pair<A, A> x;
    Stepper stepper;
  };
  return Processed{[&sys](S s, double h) {
                     const auto acc = [&sys](const A& q, const A&, A& a, double) {
                       a = detail::to_std_array<D>(sys.inv_mass(sys.force(detail::to_vec<D>(q))));
                     };
                     s.stepper.do_step(acc, s.x, 0.0, h);
                     return s;
                   },
                   [&sys](const typename Sys::State& z, double) {
                     return S{{detail::to_std_array<D>(z.q), detail::to_std_array<D>(sys.inv_mass(z.p))}, Stepper{}};
                   },
                   [&sys](const S& s, double) {
                     return make_state<D>(detail::to_vec<D>(s.x.first), Vec<D>(sys.mass() * detail::to_vec<D>(s.x.second)));
                   }};
}

}  // namespace geomint
