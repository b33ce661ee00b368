#pragma once
// The methods of 000 Figs 8-9 and their cost study, by registry name: symplectic Euler in the
// coordinates of (82) needs the k of (82); the others come from the registry's dispatch.
#include <string_view>

#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"

namespace geomint::euler_compensation {

template <class Sys, class F>
auto with_oscillator_method(std::string_view name, const Sys& osc, double k, F&& f) {
  if (method_info(name).name == CompensatedSymplecticEuler::info.name)
    return f(CompensatedSymplecticEuler::bind(osc, k));
  return with_method(name, osc, f);
}

}  // namespace geomint::euler_compensation
