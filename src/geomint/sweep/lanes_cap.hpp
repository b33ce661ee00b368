#pragma once
// The widest instruction set the lane kernels may use (the energy map's, sweep/energy_map.hpp, and the
// ensembles', sweep/ensemble_kernels.hpp): the environment variable GEOMINT_LANES, "avx512", "avx2" or "sse2",
// caps those the CPU has, so that one machine runs the kernels another would. The ensembles' lanes are the
// scalar method bit for bit on every instruction set (ctest lanes.ti_drift_same_bytes); the energy map's
// kernels agree with its scalar loop to round-off, each differently (sweep/energy_map.hpp).
#include <string>
#include <string_view>
#include <vector>

namespace geomint {

// GEOMINT_LANES: "" where unset or empty (no cap). Throws std::invalid_argument, naming the variable and the
// values it takes, for any other value.
std::string lanes_cap();

// Whether the lane kernels may use `isa` ("avx512", "avx2" or "sse2") under lanes_cap().
bool lanes_allowed(std::string_view isa);

// The kernels the CPU can run (each naming its instruction set in .isa), less those wider than lanes_cap().
template <class Kernel>
std::vector<Kernel> within_lanes_cap(std::vector<Kernel> kernels) {
  std::erase_if(kernels, [](const Kernel& k) { return !lanes_allowed(k.isa); });
  return kernels;
}

}  // namespace geomint
