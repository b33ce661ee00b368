#pragma once
// The simplified method's force (1.6), its processing (1.5), its modified energy (3.3) + (4.2) and drift (4.3), the
// stiffness of the potential, and a trajectory of the method (simplified_ti_integrate), on the systems of 004: the Henon-Heiles potentials of Figs 3-5 (with and without
// the coupling term) and the 9-atom Lennard-Jones cluster of Fig. 6, compiled once in the library
// (takahashi_imada_systems.cpp): a file that includes this header steps and measures them without instantiating
// these again. (The SIMD lane kernels, compiled per instruction set, instantiate their own.)
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>

#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"

#define GEOMINT_TAKAHASHI_IMADA_ON(prefix, Sys, D)                                                             \
  prefix template Vec<D> simplified_ti_force(const Sys&, const Vec<D>&, double, double);                      \
  prefix template PhaseState<D> ti_process(const Sys&, const PhaseState<D>&, double, double);                 \
  prefix template double simplified_ti_modified_energy(const Sys&, const PhaseState<D>&, double);             \
  prefix template double simplified_ti_drift_rate(const Sys&, const PhaseState<D>&, double);                  \
  prefix template double max_hessian_eigenvalue(const Sys&, const Vec<D>&);                                   \
  prefix template PhaseState<D> simplified_ti_integrate(const Sys&, const PhaseState<D>&, double, std::int64_t,  \
                                                        const StepObserver<D>&);

namespace geomint {

class Value;

// A figure whose trajectories the simplified method (1.6) steps, unprocessed, at the alpha of (1.4): summary
// methods.<study> (its label) and ti_alpha, which the figure's title names.
void put_simplified_ti_method(Value& summary, const std::string& study);

template <int D>  // (not deduced from a study's lambda: the system and z0 say D)
using StepObserver = std::type_identity_t<std::function<void(std::int64_t, const PhaseState<D>&)>>;

// z_n after n steps of the simplified method (1.6), unprocessed, from z0, calling observe(j, z_j) for j = 0..n:
// integrate(simplified_ti_method(sys, false), ...) (core/integrate.hpp) with the observer called through a
// std::function, so that a study's observer does not instantiate the step.
template <class Sys, int D>
PhaseState<D> simplified_ti_integrate(const Sys& sys, const PhaseState<D>& z0, double h, std::int64_t n,
                                      const StepObserver<D>& observe) {
  return integrate(simplified_ti_method(sys, false), z0, h, n, observe);
}

GEOMINT_TAKAHASHI_IMADA_ON(extern, LennardJones<9>, 18)
GEOMINT_TAKAHASHI_IMADA_ON(extern, HenonHeilesT<true>, 2)
GEOMINT_TAKAHASHI_IMADA_ON(extern, HenonHeilesT<false>, 2)

}  // namespace geomint
