// The registered methods on the harmonic oscillator (74) and the pendulum of 001 Sect. 4, counted or not.
#include "geomint/methods/by_name_impl.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {
template struct MethodsOn<HarmonicOscillator>;
template struct MethodsOn<Counting<HarmonicOscillator>>;
}  // namespace geomint
