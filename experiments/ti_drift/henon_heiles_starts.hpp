#pragma once
// ti_drift: the Henon-Heiles starts of Figs 3-5, the symplecticity check and the cost studies, the
// system of Figs 4-5 as the scene names it, and the checks that the starts stay in the bounded well.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "geomint/systems/henon_heiles.hpp"
#include "ti_drift.hpp"

namespace geomint::ti_drift {

// Henon-Heiles start with q1 = 0 and p1 > 0 from H0 (004 Sect. 5).
template <class HH>
Z2 hh_start(const HH& hh, double q2, double p2, double H0) {
  const double p1 = std::sqrt(2 * (H0 - hh.U(Vec<2>(0.0, q2))) - p2 * p2);
  return make_state<2>(Vec<2>(0.0, q2), Vec<2>(p1, p2));
}

// Calls f with the Henon-Heiles system of Figs 4-5: exponent hh.k, coupling hh.coupling (compiled out if 0).
template <class F>
decltype(auto) with_ensemble_system(const Scene& s, F&& f) {
  return with_henon_heiles(static_cast<int>(s.integer("hh.k")), s.real("hh.coupling"), f);
}

// Start i of the Fig. 4 ensemble: (hh3.q2, hh3.p2) perturbed, each trajectory its own stream seeded by (seed, i).
template <class HH>
Z2 ensemble_start(const Scene& s, const HH& hhk, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("ensemble.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("ensemble.perturbation"), s.real("ensemble.perturbation"));
  const double dq = u(rng), dp = u(rng);
  return hh_start(hhk, s.real("hh3.q2") + dq, s.real("hh3.p2") + dp, s.real("hh.H0"));
}

// The Henon-Heiles starts q1 = 0, q2 in [q2 - d, q2 + d], p2 in [p2 - d, p2 + d] (d: the ensemble's
// perturbation, 0 for one start) lie in the bounded well below the escape energy (the lowest saddle of
// U): hh.H0 below it, every q2 between the saddles on the axis (q2 < 1, and q2 > -1 for even k: U(0, .)
// is monotone on either side of 0 there, so p1^2 = 2 (H0 - U(0, q2)) - p2^2 > 0 at the corners of the
// box holds on all of it), and the step h below the bound at the frequency of the linearisation at the
// start, max eig U''(0, q2) (a necessary condition).
// Compiled once, in ti_drift.cpp, for HenonHeilesT<true> and HenonHeilesT<false>.
template <class HH>
void check_hh_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h);

}  // namespace geomint::ti_drift
