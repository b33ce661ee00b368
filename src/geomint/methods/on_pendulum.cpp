// The registered methods on the nonlinear pendulum of 001 Sect. 4, counted or not.
#include "geomint/methods/by_name_impl.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {
template struct MethodsOn<NonlinearPendulum>;
template struct MethodsOn<Counting<NonlinearPendulum>>;
}  // namespace geomint
