#pragma once
// The counted kernels' vector arithmetic per pass (arithmetic_ceiling.hpp's OpMix), read off their objects:
// tests/unit/check_kernel_arithmetic.py --loops OBJECT FUNCTION prints a loop's counts (bench/README.md). ctest
// bench.kernel_arithmetic checks that each is the step of its kernel's object as built (a kernel changed without
// a recount fails it) and that the issuing objects issue exactly these.
#include <array>

#include "geomint/sweep/arithmetic_ceiling.hpp"

namespace geomint {

// The counted kernels, g++ 12 -O3, as {fma, add, minmax, logic, estimate, div, trajectory_steps} (each instruction
// set's list is issued by its issue_mix_<isa>, arithmetic_ceiling_<isa>.cpp).
// The energy map of 000 Fig. 6 (energy_map_kernel_<isa>.cpp): one step of a batch of 64 trajectories.
inline constexpr OpMix kEnergyMapAvx512Cartesian{184, 24, 0, 0, 8, 0, 64}, kEnergyMapAvx512Polar{336, 40, 40, 24, 0, 8, 64};
inline constexpr OpMix kEnergyMapAvx2Cartesian{416, 64, 16, 16, 16, 0, 64}, kEnergyMapAvx2Polar{672, 80, 70, 80, 0, 16, 64};
// The Lennard-Jones lanes of 004 Fig. 6 (ensemble_kernel_<isa>.cpp, LennardJones<9>): one step of a register of
// lanes (AVX-512: 24 of the 72 reciprocals by vrcp14pd and the FMA units, ensemble_kernel.inc).
inline constexpr OpMix kLennardJonesAvx512{846, 648, 48, 48, 24, 48, 8}, kLennardJonesAvx2{702, 648, 0, 0, 0, 72, 4};
inline constexpr std::array kAvx512Mixes{kEnergyMapAvx512Cartesian, kEnergyMapAvx512Polar, kLennardJonesAvx512};
inline constexpr std::array kAvx2Mixes{kEnergyMapAvx2Cartesian, kEnergyMapAvx2Polar, kLennardJonesAvx2};

}  // namespace geomint
