// The registered methods on the quartic oscillator (the worked example, experiments/triple_jump).
#include "geomint/methods/by_name_impl.hpp"
#include "geomint/systems/quartic_oscillator.hpp"

namespace geomint {
template struct MethodsOn<QuarticOscillator>;
}  // namespace geomint
