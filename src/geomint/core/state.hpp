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

}  // namespace geomint
