#pragma once
// Evaluation of H's derivatives with the position frozen at q, as needed by
// symplectic Euler, whose implicit stage (000 eq. (42)) solves for p^{j+1}
// at fixed q^j. A system may provide `at_q(q)` to precompute what depends on
// q only (a transformed system inverts its coordinate map there once per
// step); otherwise this default binds q and forwards.
#include <utility>

#include "geomint/core/state.hpp"

namespace geomint {

template <class Sys>
struct BoundQ {
  static constexpr int D = Sys::State::dof;
  const Sys& sys;
  Vec<D> q;
  Vec<D> H_q(const Vec<D>& p) const { return sys.H_q(q, p); }
  Vec<D> H_p(const Vec<D>& p) const { return sys.H_p(q, p); }
  Mat<D> H_qp(const Vec<D>& p) const { return sys.H_qp(q, p); }
};

template <class Sys, class V>
auto freeze_q(const Sys& sys, const V& q) {
  if constexpr (requires { sys.at_q(q); }) {
    return sys.at_q(q);
  } else {
    return BoundQ<Sys>{sys, q};
  }
}

}  // namespace geomint
