// The symplecticity defect of observables/symplecticity.hpp for one and two degrees of freedom, compiled once.
#include "geomint/observables/symplecticity.hpp"

namespace geomint {

template double symplecticity_defect<2>(const Mat<2>&);
template double symplecticity_defect<4>(const Mat<4>&);

}  // namespace geomint
