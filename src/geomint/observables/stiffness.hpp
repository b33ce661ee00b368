#pragma once
// The stiffness of a potential at q: the largest eigenvalue omega_max^2 of its Hessian U''(q), the
// square of the highest frequency of the motion linearised about q. With the coefficients frozen
// there, a method is stable for omega_max h below its bound on the oscillator (004 Sect. 1.4).
#include "geomint/core/dense_solve.hpp"
#include "geomint/core/state.hpp"

namespace geomint {

template <class Sys, int D>
double max_hessian_eigenvalue(const Sys& sys, const Vec<D>& q) {
  return largest_symmetric_eigenvalue<D>(sys.U_qq(q));
}

}  // namespace geomint
