#pragma once
// Symplectic Euler, both variants. For separable H = T(p) + U(q) both are
// explicit; otherwise the implicit stage is solved by Newton's method
// (newton.hpp) with the Jacobian I +- h H_qp, to round-off.
#include "geomint/core/compensated_sum.hpp"
#include "geomint/core/state.hpp"
#include "geomint/integrators/newton.hpp"
#include "geomint/methods/registry.hpp"  // its order, bounds and citation: method_info("symplectic_euler_pq")
#include "geomint/systems/frozen.hpp"

namespace geomint {

// 000 eq. (42)-(43): p^{j+1} = p^j - h H_q(q^j, p^{j+1});  q^{j+1} = q^j + h H_p(q^j, p^{j+1}).
template <class Sys, class State>
State symplectic_euler_pq(const Sys& sys, const State& z, double h) {
  constexpr int D = State::dof;
  const auto at = freeze_q(sys, z.q);
  State next;
  if constexpr (Sys::separable) {
    next.p = z.p - h * at.H_q(z.p);  // H_q does not depend on p
  } else {
    next.p = newton_solve<D>(
        [&](const Vec<D>& P) {
          return std::pair<Vec<D>, Mat<D>>{P - z.p + h * at.H_q(P), Mat<D>::Identity() + h * at.H_qp(P)};
        },
        z.p, "symplectic Euler (42)");
  }
  next.q = z.q + h * at.H_p(next.p);
  return next;
}

// Adjoint: q^{j+1} = q^j + h H_p(q^{j+1}, p^j);  p^{j+1} = p^j - h H_q(q^{j+1}, p^j).
template <class Sys, class State>
State symplectic_euler_qp(const Sys& sys, const State& z, double h) {
  constexpr int D = State::dof;
  State next;
  if constexpr (Sys::separable) {
    next.q = z.q + h * sys.H_p(z.q, z.p);  // H_p does not depend on q
  } else {
    next.q = newton_solve<D>(
        [&](const Vec<D>& Q) {
          return std::pair<Vec<D>, Mat<D>>{Q - z.q - h * sys.H_p(Q, z.p),
                                           Mat<D>::Identity() - h * sys.H_qp(Q, z.p).transpose()};
        },
        z.q, "adjoint symplectic Euler");
  }
  next.p = z.p - h * sys.H_q(next.q, z.p);
  return next;
}

}  // namespace geomint

namespace geomint {

template <int D>
struct CompensatedState {
  PhaseState<D> z;
  Vec<D> cq = Vec<D>::Zero(), cp = Vec<D>::Zero();  // carried rounding errors
};

// 000 eq. (42)-(43) for separable H, the increments added with compensated summation.
template <class Sys, int D>
CompensatedState<D> symplectic_euler_pq(const Sys& sys, CompensatedState<D> s, double h) {
  static_assert(Sys::separable, "compensated symplectic Euler is implemented for separable H");
  compensated_add(s.z.p, s.cp, Vec<D>(-h * sys.H_q(s.z.q, s.z.p)));
  compensated_add(s.z.q, s.cq, Vec<D>(h * sys.H_p(s.z.q, s.z.p)));
  return s;
}

}  // namespace geomint
