#pragma once
// A Lennard-Jones cluster of N particles in the plane (004 Fig. 6), unit
// masses: U = sum_{i<j} V(|q_i - q_j|), V(r) = eps (r^-12 - 2 r^-6), no cutoff.
// With u = |d|^2, d = q_i - q_j, V = G(u) = eps (u^-6 - 2 u^-3), and since u is
// quadratic in d, every directional derivative is a sum over partitions into
// blocks of size one and two (the technical note on 004): with x_a = d.A,
// y = A.A for the pair differences A = a_i - a_j,
//   grad: 2 G' d;  U'' a: 4 G'' x_a d + 2 G' A;
//   U''''(a^4) = 16 G'''' x^4 + 48 G''' x^2 y + 12 G'' y^2;
//   U^(5)(a^5) = 32 G^(5) x^5 + 160 G'''' x^3 y + 120 G''' x y^2.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "geomint/core/state.hpp"

namespace geomint {

// 1 / u of the pair_index-th pair as gradient() takes it: for a double, the division; lanes of doubles
// (sweep/ensemble_kernel.inc) have their own, bit for bit the same, which may take some pairs' otherwise.
inline double reciprocal(double u, int /*pair_index*/) { return 1.0 / u; }

template <int N>
struct LennardJones {
  static constexpr int D = 2 * N;
  using State = PhaseState<D>;
  static constexpr bool separable = true;

  double eps = 0.4;

  // G^(m)(u) = eps (c12_m u^{-6-m} - 2 c6_m u^{-3-m}), m = 0..5.
  std::array<double, 6> G(double u) const {
    static constexpr std::array<double, 6> c12{1, -6, 42, -336, 3024, -30240}, c6{1, -3, 12, -60, 360, -2520};
    std::array<double, 6> out{};
    const double iu = 1.0 / u, iu3 = iu * iu * iu, iu6 = iu3 * iu3;
    double p12 = iu6, p6 = iu3;
    for (int m = 0; m < 6; ++m, p12 *= iu, p6 *= iu) out[m] = eps * (c12[m] * p12 - 2 * c6[m] * p6);
    return out;
  }
  static Vec<2> pair(const Vec<D>& v, int i, int j) { return v.template segment<2>(2 * i) - v.template segment<2>(2 * j); }

  template <class F>
  void for_pairs(const Vec<D>& q, F&& f) const {
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j) f(i, j, pair(q, i, j));
  }

  double U(const Vec<D>& q) const {
    double s = 0;
    for_pairs(q, [&](int, int, const Vec<2>& d) { s += G(d.squaredNorm())[0]; });
    return s;
  }
  // g = grad U(q) (the one implementation: U_q for one state, and the ensemble kernels of
  // sweep/ensemble_kernels.hpp for lanes of states, T a vector of doubles; the same operations in
  // the same order, so every lane is bit for bit U_q).
  template <class T>
  void gradient(const T* q, T* g) const {
    for (int k = 0; k < D; ++k) g[k] = T(0.0);
    int pair_index = 0;  // (the pairs in the order visited: constants once the loops are unrolled)
#pragma GCC unroll 16
    for (int i = 0; i < N; ++i) {
      T gx = g[2 * i], gy = g[2 * i + 1];  // (the sum for particle i in registers, in the same order)
#pragma GCC unroll 16
      for (int j = i + 1; j < N; ++j) {
        const T dx = q[2 * i] - q[2 * j], dy = q[2 * i + 1] - q[2 * j + 1];
        const T iu = reciprocal(dx * dx + dy * dy, pair_index++), iu2 = iu * iu, iu4 = iu2 * iu2;
        const T c = (12 * eps) * iu4 * (1.0 - iu2 * iu);  // 2 G'(u) = 12 eps u^-4 (1 - u^-3), G' = eps (6 u^-4 - 6 u^-7)
        const T wx = c * dx, wy = c * dy;
        gx += wx, gy += wy, g[2 * j] -= wx, g[2 * j + 1] -= wy;
      }
      g[2 * i] = gx, g[2 * i + 1] = gy;
    }
  }
  Vec<D> U_q(const Vec<D>& q) const {
    Vec<D> g;
    gradient(q.data(), g.data());
    return g;
  }
  // U'' a of one pair: 4 G'' (d.A) d + 2 G' A, A = a_i - a_j (+ for particle i, - for j).
  static Vec<2> hessian_pair(const std::array<double, 6>& g, const Vec<2>& d, const Vec<2>& A) {
    return 4 * g[2] * d.dot(A) * d + 2 * g[1] * A;
  }
  Vec<D> U_qq_times(const Vec<D>& q, const Vec<D>& a) const {
    Vec<D> out = Vec<D>::Zero();
    for_pairs(q, [&](int i, int j, const Vec<2>& d) {
      const Vec<2> w = hessian_pair(G(d.squaredNorm()), d, pair(a, i, j));
      out.template segment<2>(2 * i) += w, out.template segment<2>(2 * j) -= w;
    });
    return out;
  }
  // The A of column k, pair(e_k, i, j), for k = 2i, 2i + 1, 2j, 2j + 1, with its signed zeros.
  static inline const std::array<Vec<2>, 4> kUnitPairs{Vec<2>(1.0, 0.0), Vec<2>(0.0, 1.0), Vec<2>(0.0 - 1.0, 0.0 - 0.0),
                                                       Vec<2>(0.0 - 0.0, 0.0 - 1.0)};
  // Column k is U_qq_times(q, e_k) bit for bit: a pair (i, j) changes only the columns of particles i
  // and j (for the others A = 0 and w = +-0; a sum that starts at +0 is never -0, so adding +-0 leaves
  // it as it is), so each pair is visited once and each entry takes its terms in the same order.
  // (Unlike the column sums, a non-finite G of one pair reaches only that pair's columns.) The A of
  // those columns are the constants kUnitPairs, not differences of unit vectors of D entries.
  Mat<D> U_qq(const Vec<D>& q) const {
    Mat<D> J = Mat<D>::Zero();
    for_pairs(q, [&](int i, int j, const Vec<2>& d) {
      const auto g = G(d.squaredNorm());
      const std::array<int, 4> columns{2 * i, 2 * i + 1, 2 * j, 2 * j + 1};
      for (int c = 0; c < 4; ++c) {
        const Vec<2> w = hessian_pair(g, d, kUnitPairs[c]);
        J.template block<2, 1>(2 * i, columns[c]) += w, J.template block<2, 1>(2 * j, columns[c]) -= w;
      }
    });
    return J;
  }
  double U4(const Vec<D>& q, const Vec<D>& a) const {
    double s = 0;
    for_pairs(q, [&](int i, int j, const Vec<2>& d) {
      const auto g = G(d.squaredNorm());
      const Vec<2> A = pair(a, i, j);
      const double x = d.dot(A), y = A.squaredNorm();
      s += 16 * g[4] * x * x * x * x + 48 * g[3] * x * x * y + 12 * g[2] * y * y;
    });
    return s;
  }
  double U5(const Vec<D>& q, const Vec<D>& a) const {
    double s = 0;
    for_pairs(q, [&](int i, int j, const Vec<2>& d) {
      const auto g = G(d.squaredNorm());
      const Vec<2> A = pair(a, i, j);
      const double x = d.dot(A), y = A.squaredNorm();
      s += 32 * g[5] * x * x * x * x * x + 160 * g[4] * x * x * x * y + 120 * g[3] * x * y * y;
    });
    return s;
  }
  Vec<D> force(const Vec<D>& q) const { return -U_q(q); }
  double mass() const { return 1.0; }
  Vec<D> inv_mass(const Vec<D>& p) const { return p; }
  double H(const State& z) const { return 0.5 * z.p.squaredNorm() + U(z.q); }
  Vec<D> H_q(const Vec<D>& q, const Vec<D>&) const { return U_q(q); }
  Vec<D> H_p(const Vec<D>&, const Vec<D>& p) const { return p; }
};

// 004 Fig. 6: the cluster of 9 particles near the 3 x 3 grid (i, j), i, j in {1, 2, 3} (lennard_jones.cpp).
Vec<2> lennard_jones_grid(int k);  // particle k at (1 + k % 3, 1 + k / 3)
// omega_max^2 = max eig U'' of the cluster at the grid (observables/stiffness.hpp), the stiffness of Fig. 6's step bound.
double lennard_jones_grid_stiffness();
// Start i of Fig. 6: the grid with each coordinate perturbed uniformly by at most `perturbation`, p = 0, from the
// stream seeded by (seed, i).
PhaseState<18> lennard_jones_grid_start(std::uint64_t seed, double perturbation, std::size_t i);

}  // namespace geomint
