#pragma once
// The simplified method's force (1.6) and its modified energy (3.3) + (4.2) on the 9-atom Lennard-Jones cluster of
// 004 Fig. 6, compiled once in the library (takahashi_imada_lj.cpp): a file that includes this header steps and
// measures the cluster without instantiating them again. (The SIMD lane kernels, compiled per instruction set,
// instantiate their own.)
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint {

extern template Vec<18> simplified_ti_force(const LennardJones<9>&, const Vec<18>&, double, double);
extern template double simplified_ti_modified_energy(const LennardJones<9>&, const PhaseState<18>&, double);

}  // namespace geomint
