#include "geomint/integrators/takahashi_imada_lj.hpp"

namespace geomint {

template Vec<18> simplified_ti_force(const LennardJones<9>&, const Vec<18>&, double, double);
template double simplified_ti_modified_energy(const LennardJones<9>&, const PhaseState<18>&, double);

}  // namespace geomint
