#pragma once
// The arithmetic ceiling of an energy-map batch kernel on the core at hand (energy_map_bench.cpp).
//
// A kernel cannot run a step faster than the core issues the step's vector arithmetic. Here that
// arithmetic is issued alone: the same instructions, in the numbers counted in the kernel's object,
// on kChains independent chains of registers, without loads, stores or any other dependency, and
// timed. Its time per trajectory-step is the kernel's ceiling on this core, whatever its ports,
// their sharing between additions and multiplies, or the clock of wide vectors (bench/README.md);
// the kernel's time over it is the fraction of the ceiling the kernel reaches. Loads, stores,
// register moves, zeroing idioms, scalar, mask and shuffle instructions are not counted.
#include <cstdint>

namespace geomint::bench {

// The vector instructions of one step of a batch (kEnergyMapBatch = 64 trajectory-steps), counted with
// `objdump -d` in the innermost loop of a kernel that runs a step without a test (bench/README.md).
struct OpMix {
  int fma;     // multiplies and fused multiply-adds
  int add;     // additions and subtractions
  int minmax;  // minima, maxima, comparisons
  int logic;   // and, andn, xor
  int rsqrt;   // the 1/sqrt estimate: vrsqrt14pd; AVX2 vcvtpd2ps, vrsqrtps, vcvtps2pd
  int div;     // divisions
  constexpr int total() const { return fma + add + minmax + logic + rsqrt + div; }
};

// g++ 12 -O3 objects of src/geomint/sweep/energy_map_kernel_{avx512,avx2}.cpp.
inline constexpr OpMix kAvx512Cartesian{.fma = 184, .add = 24, .minmax = 0, .logic = 0, .rsqrt = 8, .div = 0};
inline constexpr OpMix kAvx512Polar{.fma = 344, .add = 40, .minmax = 36, .logic = 16, .rsqrt = 0, .div = 8};
inline constexpr OpMix kAvx2Cartesian{.fma = 416, .add = 64, .minmax = 16, .logic = 16, .rsqrt = 16, .div = 0};
inline constexpr OpMix kAvx2Polar{.fma = 688, .add = 80, .minmax = 67, .logic = 64, .rsqrt = 0, .div = 16};

// Issues the mix of one step (`polar`: the polar kernel's, else the Cartesian one's) `steps` times;
// returns a sum of the chains' values (so that none of it is dead code). Defined per instruction set:
// call only where the CPU has it.
double arithmetic_of_step_avx512(bool polar, std::int64_t steps);
double arithmetic_of_step_avx2(bool polar, std::int64_t steps);

}  // namespace geomint::bench
