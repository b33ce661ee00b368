#pragma once
#include "geomint/core/state.hpp"

namespace geomint {

inline constexpr MethodInfo explicit_euler_info{"explicit_euler", 1, "000 eq. (9)", 2.0, 0.0};

// 000 eq. (9): y^{j+1} = y^j + h f(y^j).
template <class Sys, class Y>
Y explicit_euler(const Sys& sys, const Y& y, double h) {
  return y + h * sys.f(y);
}

}  // namespace geomint
