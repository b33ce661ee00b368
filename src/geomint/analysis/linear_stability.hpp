#pragma once
// Linear stability on the harmonic oscillator q'' = -w^2 q: the one-step
// matrix of a method that is linear there, and its spectral radius (the
// method is stable where the radius is 1 and the eigenvalues are simple).
// Rows and columns are in the order (q, p); 001 eq. (13) orders them (p, q),
// the same matrix up to the swap, with the same eigenvalues (in_pq_order).
#include <cstddef>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/core/integrate.hpp"

namespace geomint {

// The matrix of the map z -> step(z) on PhaseState<1>: its columns are the images of (q, p) = (1, 0) and (0, 1).
template <class Step>
Mat<2> one_step_matrix(const Step& step) {
  const PhaseState<1> a = step(make_state(1.0, 0.0)), b = step(make_state(0.0, 1.0));
  Mat<2> M;
  M << a.q[0], b.q[0], a.p[0], b.p[0];
  return M;
}

// One step h of a bound method (pre, kernel, post). For a processed method
// pass its kernel with trivial processors (with_kernel): the kernel decides stability.
template <class Method>
Mat<2> one_step_matrix(const Method& method, double h) {
  return one_step_matrix([&](const PhaseState<1>& z) { return integrate(method, z, h, 1); });
}

// The same matrix with rows and columns in 001's order (p, q), eq. (13).
inline Mat<2> in_pq_order(const Mat<2>& M) {
  Mat<2> P;
  P << M(1, 1), M(1, 0), M(0, 1), M(0, 0);
  return P;
}

// The spectral radius of M (linear_stability.cpp).
double spectral_radius(const Mat<2>& M);

// The condition number kappa of the eigenvector matrix V of M = V D V^{-1}: where the spectral
// radius is at most 1, |M^n z| <= kappa |z| for every n (infinite at a double eigenvalue).
double eigenvector_condition(const Mat<2>& M);

// The boundary of a stable interval: `stable(lo)` holds and `stable(hi)` does not; 60 halvings of
// [lo, hi] (below the spacing of doubles for any bracket of width < 2^8 times the bound) return the
// last point found stable.
template <class Stable>
double stability_boundary(Stable&& stable, double lo, double hi) {
  for (int it = 0; it < 60; ++it) (stable(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
  return lo;
}

// The maximal runs [lo, hi] of consecutive scan points x_i (increasing) at which the spectral radius
// rho_i is at most 1 + tolerance: a scanned stable set (a run of one point has lo = hi).
struct StableInterval {
  double lo, hi;
};
std::vector<StableInterval> stable_intervals(const std::vector<double>& x, const std::vector<double>& rho,
                                             double tolerance);

}  // namespace geomint
