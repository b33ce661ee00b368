#pragma once
// State types shared by systems and integrators.
#include <Eigen/Core>

namespace geomint {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

template <int D>
using Mat = Eigen::Matrix<double, D, D>;

// A point (q, p) of the phase space of a system with D degrees of freedom.
template <int D>
struct PhaseState {
  static constexpr int dof = D;
  Vec<D> q = Vec<D>::Zero();
  Vec<D> p = Vec<D>::Zero();

  friend PhaseState operator+(const PhaseState& a, const PhaseState& b) { return {a.q + b.q, a.p + b.p}; }
  friend PhaseState operator*(double s, const PhaseState& a) { return {s * a.q, s * a.p}; }
};

template <int D>
PhaseState<D> make_state(const Vec<D>& q, const Vec<D>& p) {
  PhaseState<D> z;
  z.q = q;
  z.p = p;
  return z;
}

inline PhaseState<1> make_state(double q, double p) { return make_state<1>(Vec<1>(q), Vec<1>(p)); }

// Metadata every integrator carries: scenes pick methods by name, tests check
// the declared order by slope, experiments reject steps beyond a known bound.
struct MethodInfo {
  const char* name;      // as used in scenes, CSV columns and summary.json
  int order;             // classical order (effective order for processed methods)
  const char* equation;  // where the method is defined
  // Linear stability: the method is stable for h*|lambda| <= real_bound on
  // y' = lambda*y (lambda < 0) and for h*omega < oscillatory_bound on the
  // harmonic oscillator q'' = -omega^2 q; 0 means unstable for every h > 0.
  double real_bound;
  double oscillatory_bound;
};

}  // namespace geomint
