// energy_map: what its studies share (energy_map.hpp).
#include "energy_map.hpp"

#include <cmath>
#include <cstdint>

#include "geomint/core/integrate.hpp"
#include "geomint/methods/registry.hpp"

namespace geomint::energy_map {

namespace {

// Inclusive linspace; n = 1 gives the single value lo.
std::vector<double> linspace(double lo, double hi, std::int64_t n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = n == 1 ? lo : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  return v;
}

}  // namespace

MapSetup map_setup(const Scene& s) {
  MapSetup m;
  m.xs = linspace(s.real("grid.x_min"), s.real("grid.x_max"), s.integer("grid.nx"));
  m.ys = linspace(s.real("grid.y_min"), s.real("grid.y_max"), s.integer("grid.ny"));
  m.npoints = m.xs.size() * m.ys.size();
  m.nbatches = (m.npoints + kEnergyMapBatch - 1) / kEnergyMapBatch;
  m.x0.assign(m.nbatches * kEnergyMapBatch, 0.0), m.y0.assign(m.nbatches * kEnergyMapBatch, 0.0);
  for (std::size_t i = 0; i < m.npoints; ++i) m.x0[i] = m.xs[i % m.xs.size()], m.y0[i] = m.ys[i / m.xs.size()];
  const double dt = s.real("dt");
  m.P = {s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g"), dt,
         steps_to(s.real("t_max"), dt), s.real("divergence.blowup")};
  return m;
}

const char* coordinates_name(Coordinates c) { return c == Coordinates::cartesian ? "cartesian" : "polar"; }
const char* coordinates_label(Coordinates c) { return c == Coordinates::cartesian ? "Cartesian (73)" : "polar (72)"; }

double spring_frequency(const Scene& s) {
  const double omega = std::sqrt(s.real("pendulum.k") / s.real("pendulum.m"));
  if (!(std::isfinite(omega) && omega > 0))
    s.reject("pendulum.k", "the spring's frequency sqrt(k/m) = " + format_double(omega) + " with pendulum.m = " +
                               format_double(s.real("pendulum.m")) + " is not a finite positive number: k/m must be representable");
  return omega;
}

void check_map(const Scene& s) {
  if (!(s.real("grid.x_max") >= s.real("grid.x_min"))) s.reject("grid.x_max", "must be >= grid.x_min");
  if (!(s.real("grid.y_max") >= s.real("grid.y_min"))) s.reject("grid.y_max", "must be >= grid.y_min");
  const double dt = s.real("dt"), omega = spring_frequency(s);
  const double bound = method_info("symplectic_euler_pq").oscillatory_bound;
  if (!(dt * omega < bound))
    s.reject("dt", "symplectic Euler is unstable for dt sqrt(k/m) >= " + format_double(bound) +
                       " (methods/registry.hpp): dt < " + format_double(bound / omega));
  const double n = std::round(s.real("t_max") / dt);
  if (n < 1 || std::abs(n * dt - s.real("t_max")) > 1e-9 * s.real("t_max"))
    s.reject("t_max", "must be a positive multiple of dt = " + format_double(dt));
  if (!(n <= max_exact_count))  // steps are counted in int64 and t = j dt
    s.reject("t_max", "t_max / dt must be at most 2^53 steps: t_max <= " + format_double(max_exact_count * dt));
}

GridCount grid_count(const Scene& s) {
  const double points = static_cast<double>(s.integer("grid.nx")) * static_cast<double>(s.integer("grid.ny"));
  return {points, std::ceil(points / kEnergyMapBatch), std::round(s.real("t_max") / s.real("dt"))};
}

}  // namespace geomint::energy_map
