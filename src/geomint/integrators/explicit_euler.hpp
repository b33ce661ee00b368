#pragma once
#include "geomint/core/state.hpp"
#include "geomint/methods/registry.hpp"  // its order, bounds and citation: method_info("explicit_euler")

namespace geomint {

// 000 eq. (9): y^{j+1} = y^j + h f(y^j).
template <class Sys, class Y>
Y explicit_euler(const Sys& sys, const Y& y, double h) {
  return y + h * sys.f(y);
}

}  // namespace geomint
