// The registered methods on the elastic pendulum of 000 Sect. 5 (with and without gravity), counted or not.
#include "geomint/methods/by_name_impl.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint {
template struct MethodsOn<ElasticPendulumWithGravity>;
template struct MethodsOn<ElasticPendulumWithoutGravity>;
template struct MethodsOn<Counting<ElasticPendulumWithGravity>>;
template struct MethodsOn<Counting<ElasticPendulumWithoutGravity>>;
}  // namespace geomint
