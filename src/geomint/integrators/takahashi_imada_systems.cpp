#include "geomint/integrators/takahashi_imada_systems.hpp"

#include "geomint/runner/summary.hpp"

namespace geomint {

void put_simplified_ti_method(Value& summary, const std::string& study) {
  summary["methods"][study] = labels_of({"simplified_takahashi_imada"});
  summary["ti_alpha"] = takahashi_imada_alpha;
}

GEOMINT_TAKAHASHI_IMADA_ON(, LennardJones<9>, 18)
GEOMINT_TAKAHASHI_IMADA_ON(, HenonHeilesT<true>, 2)
GEOMINT_TAKAHASHI_IMADA_ON(, HenonHeilesT<false>, 2)

}  // namespace geomint
