// The reference flow of the nonholonomic particle (nonholonomic_particle.hpp), compiled once.
#include "geomint/systems/nonholonomic_particle.hpp"

#include "geomint/reference/odeint_reference.hpp"

namespace geomint {

std::vector<std::array<double, 4>> reference_samples(const NonholonomicParticle& sys, const std::array<double, 4>& z0,
                                                     double dt, std::int64_t n, double rtol, double atol) {
  ReferenceIntegrator reference(4, array_field<4>(sys), rtol, atol);
  std::vector<std::array<double, 4>> out{z0};
  std::array<double, 4> x = z0;
  for (std::int64_t j = 1; j <= n; ++j) {
    reference.integrate(x, static_cast<double>(j - 1) * dt, static_cast<double>(j) * dt, 0.1 * dt);
    out.push_back(x);
  }
  return out;
}

}  // namespace geomint
