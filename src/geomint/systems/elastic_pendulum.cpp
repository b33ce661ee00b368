// The elastic pendulum of a scene (systems/elastic_pendulum.hpp).
#include "geomint/systems/elastic_pendulum.hpp"

#include "geomint/io/csv.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/transforms/polar.hpp"

namespace geomint {

template PhaseState<2> reference_solution<ElasticPendulumWithGravity>(const ElasticPendulumWithGravity&, const PhaseState<2>&,
                                                                      double, double, double);
template PhaseState<2> reference_solution<ElasticPendulumWithoutGravity>(const ElasticPendulumWithoutGravity&,
                                                                         const PhaseState<2>&, double, double, double);

ElasticPendulumParams elastic_pendulum_params(const Scene& s, const std::string& section) {
  return {s.real(section + ".l"), s.real(section + ".m"), s.real(section + ".k"), s.real(section + ".g")};
}

double spring_frequency(const Scene& s, const std::string& section) {
  const double omega = std::sqrt(s.real(section + ".k") / s.real(section + ".m"));
  if (!(std::isfinite(omega) && omega > 0))
    s.reject(section + ".k", "the spring's frequency sqrt(k/m) = " + format_double(omega) + " with " + section +
                                 ".m = " + format_double(s.real(section + ".m")) +
                                 " is not a finite positive number: k/m must be representable");
  return omega;
}

double cartesian_energy_at_rest(const ElasticPendulumParams& p, double x, double y) {
  const ElasticPendulumWithGravity cart{p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}};
  return cart.H(make_state<2>(Vec<2>(x, y), Vec<2>(0.0, 0.0)));
}

double polar_energy_at_rest(const ElasticPendulumParams& p, double x, double y, bool as_printed_63) {
  const ElasticPendulumPolarWithGravity polar{p.m, {SpringPolarTerm{p.k, p.l}, GravityPolarTerm{p.m, p.g}}};
  const auto z = make_state<2>(Vec<2>(x, y), Vec<2>(0.0, 0.0));
  return polar.H(as_printed_63 ? make_state<2>(polar_position_as_printed_63(z.q), Vec<2>(0.0, 0.0)) : polar_from_cartesian(z));
}

void check_elastic_pendulum_states(const Scene& s, const char* key) {
  for (const auto& row : s.real_rows(key))
    if (std::hypot(row[0], row[1]) == 0.0) s.reject(key, "the spring force is singular at x = y = 0");
}

}  // namespace geomint
