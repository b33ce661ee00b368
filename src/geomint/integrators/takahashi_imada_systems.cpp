#include "geomint/integrators/takahashi_imada_systems.hpp"

namespace geomint {

GEOMINT_TAKAHASHI_IMADA_ON(, LennardJones<9>, 18)
GEOMINT_TAKAHASHI_IMADA_ON(, HenonHeilesT<true>, 2)
GEOMINT_TAKAHASHI_IMADA_ON(, HenonHeilesT<false>, 2)

}  // namespace geomint
