#pragma once
// The force evaluations in one step of a method (systems/counting.hpp: a gradient, a force or a Hessian-vector
// product counts one), for --plan's counts and the work of a step in the cost studies.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "geomint/methods/by_name.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {

// Force evaluations in one step of a method's kernel (its processors evaluate none), counted from z_0 on along one
// step on the harmonic oscillator: the count is the method's, not the system's.
inline std::int64_t evals_per_step(const std::string& method) {
  std::int64_t n = 0;
  MethodsOn<Counting<HarmonicOscillator>>::integrate(
      method, {HarmonicOscillator{1.0, 1.0}, &n}, make_state(1.0, 0.0), 0.1, 1,
      [&](std::int64_t j, const PhaseState<1>&) { if (j == 0) n = 0; }, Bind::kernel);
  if (n < 1) throw std::logic_error(method + " evaluates no force in a step");
  return n;
}

}  // namespace geomint
