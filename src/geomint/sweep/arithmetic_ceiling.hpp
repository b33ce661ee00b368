#pragma once
// The ceiling of a SIMD kernel on the core at hand: its vector arithmetic alone.
//
// A kernel cannot run a step faster than the core issues the step's vector arithmetic. Here that arithmetic
// is issued alone: the same instructions, in the numbers counted in the kernel's object, on independent
// chains of registers, without loads, stores or any other dependency. Its time per trajectory-step is the
// kernel's ceiling on this core, whatever the core's ports, their sharing between additions and multiplies,
// or the clock of wide vectors (bench/README.md); the kernel's time over it is the fraction of the ceiling
// the kernel reaches. Loads, stores, register moves, zeroing idioms, scalar, mask and shuffle instructions
// are not counted.
#include <cstdint>

namespace geomint {

// The vector instructions of one pass of a kernel's loop, counted with `objdump -d` in its object (the loop
// that runs a step without a test; bench/README.md), and the trajectory-steps that pass computes. The counts
// are in arithmetic_counts.hpp, which only the kernels' registries and the issuing files include: a recount
// recompiles those, not every study.
struct OpMix {
  int fma;       // multiplies and fused multiply-adds
  int add;       // additions and subtractions
  int minmax;    // minima, maxima, comparisons
  int logic;     // and, andn, xor
  int estimate;  // the 1/sqrt or 1/x estimate: vrsqrt14pd, vrcp14pd; AVX2 vcvtpd2ps, vrsqrtps, vcvtps2pd
  int div;       // divisions
  int trajectory_steps;
  constexpr int total() const { return fma + add + minmax + logic + estimate + div; }
  constexpr bool operator==(const OpMix&) const = default;
};

// Issues the instructions of `m` (one of the instruction set's list, arithmetic_counts.hpp) `repeats` times;
// returns a value that depends on all of them. Call only where the CPU has the instruction set.
double issue_mix_avx512(const OpMix& m, std::int64_t repeats);
double issue_mix_avx2(const OpMix& m, std::int64_t repeats);

// Repeats of a mix per timed call (the timing protocol lengthens a call to its floor).
inline constexpr std::int64_t kArithmeticRepeats = 4096;

// A kernel's counted arithmetic and the function that issues it; empty where not counted.
struct KernelArithmetic {
  const OpMix* mix = nullptr;
  double (*issue)(const OpMix&, std::int64_t) = nullptr;
  explicit operator bool() const { return mix != nullptr; }
  double operator()(std::int64_t repeats) const { return issue(*mix, repeats); }
  double trajectory_steps(std::int64_t repeats) const { return static_cast<double>(repeats) * mix->trajectory_steps; }
};

}  // namespace geomint
