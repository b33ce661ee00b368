#pragma once
// The Henon-Heiles-type potential of 004 (simplified Takahashi-Imada), unit mass:
//   U = (q1^2 + q2^2)/2 + q1^2 q2 - q2^k/k (004 Figs 3-5, k = 3 and 5).
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<HenonHeilesT<true>>
// geomint: MethodsOn<HenonHeilesT<false>>
// geomint: MethodsOn<Counting<HenonHeilesT<true>>>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>

#include "geomint/core/state.hpp"
#include "geomint/systems/unit_mass.hpp"

namespace geomint {

class Scene;

// x^n for a small integer n >= 0 (std::pow is slow in the inner loop); T = double or a vector of lanes. The
// product ((x x) x)..., from x itself: the same roundings as from 1 (1 x is x), one dependent multiply fewer. Up to
// x^4 without a loop, whose counter and branches cost the AVX2 lanes of 004 Fig. 4 (k = 5) a tenth of their time.
template <class T>
T int_pow(const T& x, int n) {
  switch (n) {
    case 0: return T(1.0);
    case 1: return x;
    case 2: return x * x;
    case 3: return x * x * x;
    case 4: return x * x * x * x;
    default: {
      T r = x;
      for (int i = 1; i < n; ++i) r *= x;
      return r;
    }
  }
}

// 004 Figs 3-5: U = (q1^2 + q2^2)/2 + c q1^2 q2 - q2^k / k, c = 1 in 004. The coupling term
// c q1^2 q2 is compiled only if Coupling: a scene that sets c = 0 steps a system without it
// (with_henon_heiles), not one that multiplies it by zero.
template <bool Coupling = true>
struct HenonHeilesT : UnitMassSeparable<2> {
  int k = 3;
  double c = 1.0;  // coefficient of q1^2 q2 (read only if Coupling)
  double U(const Vec<2>& q) const {
    if constexpr (Coupling) return 0.5 * q.squaredNorm() + c * q[0] * q[0] * q[1] - int_pow(q[1], k) / k;
    return 0.5 * q.squaredNorm() - int_pow(q[1], k) / k;
  }
  // g = grad U(q) (the one implementation: U_q for one state, and the ensemble kernels of
  // sweep/ensemble_kernels.hpp for lanes of states, T a vector of doubles).
  template <class T>
  void gradient(const T* q, T* g) const {
    if constexpr (Coupling) {
      g[0] = q[0] + 2 * c * q[0] * q[1], g[1] = q[1] + c * q[0] * q[0] - int_pow(q[1], k - 1);
    } else {
      g[0] = q[0], g[1] = q[1] - int_pow(q[1], k - 1);
    }
  }
  Vec<2> U_q(const Vec<2>& q) const {
    Vec<2> g;
    gradient(q.data(), g.data());
    return g;
  }
  Mat<2> U_qq(const Vec<2>& q) const {
    Mat<2> J;
    if constexpr (Coupling) {
      J << 1 + 2 * c * q[1], 2 * c * q[0], 2 * c * q[0], 1 - (k - 1) * int_pow(q[1], k - 2);
    } else {
      J << 1, 0, 0, 1 - (k - 1) * int_pow(q[1], k - 2);
    }
    return J;
  }
  Vec<2> U_qq_times(const Vec<2>& q, const Vec<2>& v) const { return U_qq(q) * v; }
  Vec<2> force(const Vec<2>& q) const { return -U_q(q); }
  Vec<2> H_q(const Vec<2>& q, const Vec<2>&) const { return U_q(q); }
  double H(const State& z) const { return 0.5 * z.p.squaredNorm() + U(z.q); }
  // The vector U'''(a, b, .): U_112 = 2c (and its permutations), U_222 = -(k-1)(k-2) q2^(k-3).
  Vec<2> U3_times(const Vec<2>& q, const Vec<2>& a, const Vec<2>& b) const {
    const double U222 = -(k - 1.0) * (k - 2) * int_pow(q[1], k - 3);
    if constexpr (Coupling) return Vec<2>(2 * c * (a[0] * b[1] + a[1] * b[0]), 2 * c * a[0] * b[0] + U222 * a[1] * b[1]);
    return Vec<2>(0.0, U222 * a[1] * b[1]);
  }
  // U''''(a^4) = U_2222 a_2^4 and U^(5)(a^5) = U_22222 a_2^5 (the only nonzero components).
  double U4(const Vec<2>& q, const Vec<2>& a) const {
    return k < 4 ? 0.0 : -(k - 1.0) * (k - 2) * (k - 3) * int_pow(q[1], k - 4) * int_pow(a[1], 4);
  }
  double U5(const Vec<2>& q, const Vec<2>& a) const {
    return k < 5 ? 0.0 : -(k - 1.0) * (k - 2) * (k - 3) * (k - 4) * int_pow(q[1], k - 5) * int_pow(a[1], 5);
  }
  // The escape energy: the lowest of U's saddles, on the axis (q1 = 0, |q2| = 1: U = 1/2 - 1/k) and, for c != 0,
  // at q2 = -1/(2c), q1^2 = (q2^(k-1) - q2)/c where that is positive (1/6 for k = 3, c = 1, the triangle of 004
  // Fig. 3). Below it the motion from a start inside stays bounded.
  double escape_energy() const {
    double e = 0.5 - 1.0 / k;
    if (Coupling && c != 0.0) {
      const double q2 = -1 / (2 * c), q1sq = (int_pow(q2, k - 1) - q2) / c;
      if (q1sq > 0) e = std::min(e, U(Vec<2>(std::sqrt(q1sq), q2)));
    }
    return e;
  }
  // The start on the energy shell H = H0 with q1 = 0 and p1 > 0 (004 Sect. 5).
  State start(double q2, double p2, double H0) const {
    const double p1 = std::sqrt(2 * (H0 - U(Vec<2>(0.0, q2))) - p2 * p2);
    return make_state<2>(Vec<2>(0.0, q2), Vec<2>(p1, p2));
  }
  // Start i of an ensemble (004 Fig. 4): (q2, p2) each perturbed uniformly by at most d, from the stream seeded by
  // (seed, i), on the energy shell H = H0 (start).
  State perturbed_start(double q2, double p2, double H0, double d, std::uint64_t seed, std::size_t i) const {
    std::seed_seq seq{seed, static_cast<std::uint64_t>(i)};
    std::mt19937_64 rng(seq);
    std::uniform_real_distribution<double> u(-d, d);
    const double dq = u(rng), dp = u(rng);
    return start(q2 + dq, p2 + dp, H0);
  }
};

using HenonHeiles = HenonHeilesT<true>;

// Calls f with the Henon-Heiles system of exponent k and coupling c, compiled without the
// coupling term when c = 0.
template <class F>
decltype(auto) with_henon_heiles(int k, double c, F&& f) {
  if (c == 0.0) return f(HenonHeilesT<false>{{}, k, 0.0});
  return f(HenonHeilesT<true>{{}, k, c});
}

// The scene's Henon-Heiles starts q1 = 0, q2 in [q2 - d, q2 + d], p2 in [p2 - d, p2 + d] (<section>.q2, <section>.p2;
// d: an ensemble's perturbation, 0 for one start) lie in the bounded well below the escape energy (the lowest saddle
// of U): hh.H0 below it, every q2 between the saddles on the axis (q2 < 1, and q2 > -1 for even k: U(0, .) is
// monotone on either side of 0 there, so p1^2 = 2 (H0 - U(0, q2)) - p2^2 > 0 at the corners of the box holds on all
// of it), and, if check_h, the step h below the bound of the simplified method (004 (1.6)) at the frequency of the
// linearisation at the start, max eig U''(0, q2) (a necessary condition). Rejects the key at fault.
// Compiled once, in henon_heiles.cpp, for HenonHeilesT<true> and HenonHeilesT<false>.
template <class HH>
void check_henon_heiles_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h);

}  // namespace geomint
