#pragma once
// 000 eq. (20): a Hamiltonian system as a first-order ODE z' = J grad H(z),
// for methods that do not see the (q, p) split (explicit Euler, RK4).
#include "geomint/core/state.hpp"

namespace geomint {

template <class Sys>
struct HamiltonianField {
  using State = typename Sys::State;
  Sys sys;

  State f(const State& z) const {  // 000 eq. (20): (q', p') = (H_p, -H_q)
    State dz;
    dz.q = sys.H_p(z.q, z.p);
    dz.p = -sys.H_q(z.q, z.p);
    return dz;
  }
};

template <class Sys>
HamiltonianField(Sys) -> HamiltonianField<Sys>;

}  // namespace geomint
