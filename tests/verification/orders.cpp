// Verification (verification.hpp): the declared orders of a method with a generic binding.
#include "geomint/methods/dispatch.hpp"
#include "verification.hpp"

namespace geomint::verification {

namespace {

// |z_n - z(T)| of n steps of the method (or of its kernel alone) bound to sys by name.
template <class Sys, class Z>
double final_error(std::string_view name, bool kernel, const Sys& sys, const Z& z0, const Z& zT, double T, std::int64_t n) {
  const auto error = [&](const auto& m) { return phase_distance(integrate(m, z0, T / static_cast<double>(n), n), zT); };
  return kernel ? with_kernel(name, sys, error) : with_method(name, sys, error);
}

}  // namespace

// On the oscillator (closed form) and the unsymmetric pendulum (reference); a processed method
// with its effective order, and its kernel alone with the kernel order.
void check_orders(const MethodInfo& m) {
  const bool processed = m.family == Family::processed;
  // Fehlberg's eighth-order formula shows slopes 8.9-9.8 on the pendulum over all the range above
  // the reference's error (its ninth-order terms dominate there): its order is fitted on the oscillator.
  const bool nonlinear = m.name != "odeint_rkf78";
  for (const bool kernel : {false, true}) {
    if (kernel && !processed) continue;
    const int order = kernel ? m.kernel_order : m.order;
    const std::string which = kernel ? "kernel order" : processed ? "effective order" : "order";
    const PhaseState<1> exact = oscillator.exact(oscillator_z0, oscillator_T);
    expect_order(which + " on the oscillator", order, oscillator_T, 0.0, [&](std::int64_t n) {
      return final_error(m.name, kernel, oscillator, oscillator_z0, exact, oscillator_T, n);
    });
    if (!nonlinear) continue;
    const Reference& ref = pendulum_reference();
    expect_order(which + " on the unsymmetric pendulum", order, pendulum_T, ref.floor, [&](std::int64_t n) {
      return final_error(m.name, kernel, pendulum, pendulum_z0, ref.z, pendulum_T, n);
    });
  }
}

}  // namespace geomint::verification
