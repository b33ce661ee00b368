#pragma once
// A system wrapper that counts force evaluations (evaluations of H_q), for the
// work-precision figures. Used in counting runs only, never in timed runs.
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
