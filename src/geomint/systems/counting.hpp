#pragma once
// A system wrapper that counts force evaluations, for the work-precision
// figures: every evaluation of a gradient (H_q, U_q, force), of a
// Hessian-vector product U_qq v or of a Hessian U_qq counts one (for the elastic pendulum a
// Hessian-vector product costs about one gradient). Used in counting runs
// only, never in timed runs.
#include <cstdint>

#include "geomint/core/state.hpp"
#include "geomint/systems/frozen.hpp"

namespace geomint {

template <class Sys>
struct Counting {
  using State = typename Sys::State;
  static constexpr int D = State::dof;
  static constexpr bool separable = Sys::separable;

  Sys sys;
  std::int64_t* force_evals;  // owned by the caller; one counter per run

  double H(const State& z) const { return sys.H(z); }
  Vec<D> H_q(const Vec<D>& q, const Vec<D>& p) const { ++*force_evals; return sys.H_q(q, p); }
  Vec<D> H_p(const Vec<D>& q, const Vec<D>& p) const { return sys.H_p(q, p); }
  Mat<D> H_qp(const Vec<D>& q, const Vec<D>& p) const { return sys.H_qp(q, p); }
  Mat<D> H_pp(const Vec<D>& q, const Vec<D>& p) const { return sys.H_pp(q, p); }

  // Separable (mechanical) systems.
  double T(const Vec<D>& p) const requires requires(const Sys& s) { s.T(p); } { return sys.T(p); }
  double U(const Vec<D>& q) const requires requires(const Sys& s) { s.U(q); } { return sys.U(q); }
  Vec<D> inv_mass(const Vec<D>& p) const requires requires(const Sys& s) { s.inv_mass(p); } { return sys.inv_mass(p); }
  Vec<D> mass_times(const Vec<D>& v) const requires requires(const Sys& s) { s.mass_times(v); } {
    return sys.mass_times(v);
  }
  Vec<D> U_q(const Vec<D>& q) const requires requires(const Sys& s) { s.U_q(q); } {
    ++*force_evals;
    return sys.U_q(q);
  }
  Vec<D> force(const Vec<D>& q) const requires requires(const Sys& s) { s.force(q); } {
    ++*force_evals;
    return sys.force(q);
  }
  double mass() const requires requires(const Sys& s) { s.mass(); } { return sys.mass(); }
  Mat<D> U_qq(const Vec<D>& q) const requires requires(const Sys& s) { s.U_qq(q); } {
    ++*force_evals;
    return sys.U_qq(q);
  }
  Vec<D> U_qq_times(const Vec<D>& q, const Vec<D>& v) const requires requires(const Sys& s) { s.U_qq_times(q, v); } {
    ++*force_evals;
    return sys.U_qq_times(q, v);
  }

  struct FrozenQ {
    decltype(freeze_q(std::declval<const Sys&>(), std::declval<const Vec<D>&>())) inner;
    std::int64_t* force_evals;
    Vec<D> H_q(const Vec<D>& p) const { ++*force_evals; return inner.H_q(p); }
    Vec<D> H_p(const Vec<D>& p) const { return inner.H_p(p); }
    Mat<D> H_qp(const Vec<D>& p) const { return inner.H_qp(p); }
  };
  FrozenQ at_q(const Vec<D>& q) const { return {freeze_q(sys, q), force_evals}; }
};

}  // namespace geomint
