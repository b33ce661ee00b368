#pragma once
// Separable Hamiltonians of unit mass, H = |p|^2/2 + U(q): the kinetic half of the
// test problems of 004 (the potential is the system's).
#include "geomint/core/state.hpp"

namespace geomint {

// H = p^2/2 + U(q) with the derivatives the Takahashi-Imada methods need.
template <int D>
struct UnitMassSeparable {
  using State = PhaseState<D>;
  static constexpr bool separable = true;
  double mass() const { return 1.0; }
  Vec<D> inv_mass(const Vec<D>& p) const { return p; }
  Vec<D> H_p(const Vec<D>&, const Vec<D>& p) const { return p; }
  Mat<D> H_qp(const Vec<D>&, const Vec<D>&) const { return Mat<D>::Zero(); }
  Mat<D> H_pp(const Vec<D>&, const Vec<D>&) const { return Mat<D>::Identity(); }
};

}  // namespace geomint
