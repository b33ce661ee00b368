// The ensemble lane kernels (every instruction set this CPU runs) against the scalar method:
// simplified Takahashi-Imada (004 (1.6)) through integrate(), lane by lane, bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "geomint/sweep/ensemble_kernels.hpp"

using namespace geomint;

namespace ensemble_kernels_test {  // the file's scope (the tests build as one translation unit)

namespace {

// Bit-for-bit equality of two states (EXPECT_EQ on doubles would let -0.0 == 0.0 pass).
template <int D>
bool same_bits(const PhaseState<D>& a, const PhaseState<D>& b) {
  return std::memcmp(a.q.data(), b.q.data(), sizeof(double) * D) == 0 &&
         std::memcmp(a.p.data(), b.p.data(), sizeof(double) * D) == 0;
}

// The cluster of 004 Fig. 6: the 3 x 3 grid perturbed by up to 0.05, a different start per lane,
// at rest but for a small kick (so that p is not zero anywhere).
std::vector<PhaseState<18>> cluster_starts(int n) {
  std::vector<PhaseState<18>> z(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 9; ++k) {
      z[i].q[2 * k] = 1 + k % 3 + 0.05 * std::sin(1.3 * i + 0.7 * k);
      z[i].q[2 * k + 1] = 1 + k / 3 + 0.05 * std::cos(0.9 * i + 1.1 * k);
      z[i].p[2 * k] = 0.01 * std::sin(2.1 * i + k), z[i].p[2 * k + 1] = -0.01 * std::cos(1.7 * i + k);
    }
  return z;
}

std::vector<PhaseState<2>> henon_heiles_starts(int n) {
  std::vector<PhaseState<2>> z(n);
  for (int i = 0; i < n; ++i)  // H about 0.06: bounded motion for k = 3 and 5 (both escape energies exceed 1/10)
    z[i] = make_state<2>(Vec<2>(0.01 * i, 0.1 - 0.003 * i), Vec<2>(0.3 + 0.002 * i, 0.1));
  return z;
}

// Every kernel, n steps from each start: the lanes against integrate() of the scalar method, and the
// observed states at the multiples of `every` against the scalar run's.
template <class Sys>
void expect_lanes_are_the_scalar_method(const Sys& sys, const std::vector<typename Sys::State>& starts, double h,
                                        std::int64_t n, std::int64_t every) {
  using Z = typename Sys::State;
  const auto kernels = simplified_ti_lanes_kernels<Sys>();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(kernels.back().isa, "sse2");  // the portable fallback is always there
  std::vector<std::vector<Z>> scalar(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i)
    integrate(simplified_ti_method(sys, false), starts[i], h, n, [&](std::int64_t j, const Z& z) {
      if (j % every == 0) scalar[i].push_back(z);
    });
  for (const auto& k : kernels) {
    std::vector<std::vector<Z>> lanes(starts.size());
    const auto last = simplified_ti_lanes(sys, k.steps, std::span<const Z>(starts), h, n, every,
                                          [&](int i, std::int64_t j, const Z& z) {
                                            EXPECT_EQ(j % every, 0);
                                            lanes[i].push_back(z);
                                          });
    ASSERT_EQ(last.size(), starts.size()) << k.name;
    for (std::size_t i = 0; i < starts.size(); ++i) {
      ASSERT_EQ(lanes[i].size(), scalar[i].size()) << k.name;
      ASSERT_TRUE(scalar[i].back().q.allFinite() && scalar[i].back().p.allFinite());  // (NaNs would compare by payload)
      for (std::size_t s = 0; s < lanes[i].size(); ++s)
        ASSERT_TRUE(same_bits(lanes[i][s], scalar[i][s])) << k.name << ": trajectory " << i << ", sample " << s;
      EXPECT_TRUE(same_bits(last[i], integrate(simplified_ti_method(sys, false), starts[i], h, n))) << k.name;
    }
  }
}

}  // namespace

TEST(EnsembleKernels, LennardJonesLanesAreTheScalarMethodBitForBit) {
  // 2000 steps at the Fig. 6 step: long enough for round-off to grow by orders of magnitude in this
  // chaotic cluster, so a lane that differed in one operation would differ in many digits.
  expect_lanes_are_the_scalar_method(LennardJones<9>{}, cluster_starts(kLennardJonesLanes), 0.01, 2000, 300);
}

TEST(EnsembleKernels, HenonHeilesLanesAreTheScalarMethodBitForBit) {
  // k = 5 runs a loop of its own (the exponent a literal: ensemble_kernel.inc), every other k the loop that reads it
  for (const int k : {5, 3}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    HenonHeilesT<true> hh;
    hh.k = k;
    expect_lanes_are_the_scalar_method(hh, henon_heiles_starts(kHenonHeilesLanes), 0.2, 5000, 1000);
  }
  for (const int k : {3, 5, 6}) {  // (k = 6: int_pow's loop)
    SCOPED_TRACE("k = " + std::to_string(k) + ", no coupling");
    HenonHeilesT<false> hh;  // the coupling compiled out
    hh.k = k;
    expect_lanes_are_the_scalar_method(hh, henon_heiles_starts(kHenonHeilesLanes), 0.2, 5000, 1000);
  }
}

TEST(EnsembleKernels, AShortBatchFillsItsLanesAndReturnsOnlyItsTrajectories) {
  // 3 trajectories, and a step count that is not a multiple of `every` (the last part unobserved).
  expect_lanes_are_the_scalar_method(LennardJones<9>{}, cluster_starts(3), 0.01, 250, 100);
  // Henon-Heiles: 5 of its 32 lanes, stepped in groups of registers (kChains) that must each keep their own.
  HenonHeilesT<true> hh5;
  hh5.k = 5;
  expect_lanes_are_the_scalar_method(hh5, henon_heiles_starts(5), 0.2, 250, 100);
}

// The u whose 1/u the lanes' reciprocal (ensemble_kernel.inc) must round as the division does: every significand
// of all ones (the one case where Markstein's correction alone rounds wrongly) and of one bit set, and their
// neighbours, at every exponent of [-1000, 1000]; random significands at random exponents and in the cluster's
// range of u; and the values outside [2^-1000, 2^1000] that take the division, among ordinary ones.
std::vector<double> reciprocal_cases() {
  std::vector<double> u;
  const std::uint64_t all_ones = (std::uint64_t{1} << 52) - 1;
  for (int e = -1000; e <= 1000; ++e)
    for (std::uint64_t m : {all_ones, all_ones - 1, all_ones - 2, std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{2}})
      u.push_back(std::ldexp(std::bit_cast<double>((std::uint64_t{1023} << 52) | m), e));
  std::mt19937_64 rng(20251129);
  std::uniform_int_distribution<int> exponent(-1000, 999);
  std::uniform_real_distribution<double> cluster(0.25, 20);
  for (int i = 0; i < (1 << 20); ++i) {
    const double significand = std::bit_cast<double>((std::uint64_t{1023} << 52) | (rng() & all_ones));
    u.push_back(std::ldexp(significand, exponent(rng))), u.push_back(significand), u.push_back(cluster(rng));
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {0.0, -0.0, std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                   std::nextafter(0x1p-1000, 0.0), 0x1p-1000, 0x1p+1000, std::nextafter(0x1p+1000, inf),
                   std::numeric_limits<double>::max(), inf, -inf, -1.5, std::numeric_limits<double>::quiet_NaN()})
    u.push_back(x), u.push_back(3.0);  // (with an ordinary value beside it in the same vector)
  u.resize((u.size() + 7) / 8 * 8, 1.0);
  return u;
}

TEST(EnsembleKernels, LanesReciprocalIsTheDivisionBitForBit) {
  const std::vector<double> u = reciprocal_cases();
  for (const auto& k : simplified_ti_lanes_kernels<LennardJones<9>>()) {
    std::vector<double> out(u.size());
    k.reciprocals(u.data(), out.data(), u.size());
    std::size_t wrong = 0, first = 0;
    for (std::size_t i = 0; i < u.size(); ++i)
      if (std::bit_cast<std::uint64_t>(out[i]) != std::bit_cast<std::uint64_t>(1.0 / u[i]) && wrong++ == 0) first = i;
    EXPECT_EQ(wrong, 0u) << k.isa << ": of " << u.size() << ", the first at u = " << u[first] << " (" << out[first]
                         << " for " << 1.0 / u[first] << ")";
  }
}

}  // namespace ensemble_kernels_test
