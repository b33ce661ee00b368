#pragma once
// The ceiling of an energy-map batch kernel (energy_map.hpp) on the core at hand: its vector arithmetic alone.
//
// A kernel cannot run a step faster than the core issues the step's vector arithmetic. Here that arithmetic
// is issued alone: the same instructions, in the numbers counted in the kernel's object, on independent
// chains of registers, without loads, stores or any other dependency. Its time per trajectory-step is the
// kernel's ceiling on this core, whatever the core's ports, their sharing between additions and multiplies,
// or the clock of wide vectors (bench/README.md); the kernel's time over it is the fraction of the ceiling
// the kernel reaches. Loads, stores, register moves, zeroing idioms, scalar, mask and shuffle instructions
// are not counted.
#include <cstdint>

#include "geomint/sweep/energy_map.hpp"

namespace geomint {

// The vector instructions of one step of a batch (kEnergyMapBatch = 64 trajectory-steps), counted with
// `objdump -d` in the innermost loop of the kernel that runs a step without a test (bench/README.md).
struct OpMix {
  int fma;     // multiplies and fused multiply-adds
  int add;     // additions and subtractions
  int minmax;  // minima, maxima, comparisons
  int logic;   // and, andn, xor
  int rsqrt;   // the 1/sqrt estimate: vrsqrt14pd; AVX2 vcvtpd2ps, vrsqrtps, vcvtps2pd
  int div;     // divisions
  constexpr int total() const { return fma + add + minmax + logic + rsqrt + div; }
};

// g++ 12 -O3 objects of energy_map_kernel_avx512.cpp and energy_map_kernel_avx2.cpp.
inline constexpr OpMix kAvx512Cartesian{.fma = 184, .add = 24, .minmax = 0, .logic = 0, .rsqrt = 8, .div = 0};
inline constexpr OpMix kAvx512Polar{.fma = 344, .add = 40, .minmax = 36, .logic = 16, .rsqrt = 0, .div = 8};
inline constexpr OpMix kAvx2Cartesian{.fma = 416, .add = 64, .minmax = 16, .logic = 16, .rsqrt = 16, .div = 0};
inline constexpr OpMix kAvx2Polar{.fma = 688, .add = 80, .minmax = 67, .logic = 64, .rsqrt = 0, .div = 16};

// The kernel's arithmetic (EnergyMapArithmetic of energy_map.hpp), per instruction set: call only where the
// CPU has it (energy_map_kernels()).
double energy_map_arithmetic_avx512(Coordinates c, std::int64_t steps);
double energy_map_arithmetic_avx2(Coordinates c, std::int64_t steps);

}  // namespace geomint
