// The registered methods on the Henon-Heiles systems of 004 (with and without the cubic term), counted or not.
#include "geomint/methods/by_name_impl.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint {
template struct MethodsOn<HenonHeilesT<true>>;
template struct MethodsOn<HenonHeilesT<false>>;
template struct MethodsOn<Counting<HenonHeilesT<true>>>;
}  // namespace geomint
