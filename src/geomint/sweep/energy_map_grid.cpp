// The energy map of a scene (sweep/energy_map_grid.hpp).
#include "geomint/sweep/energy_map_grid.hpp"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

#include "geomint/core/integrate.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint {

namespace {

// Inclusive linspace; n = 1 gives the single value lo.
std::vector<double> linspace(double lo, double hi, std::int64_t n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = n == 1 ? lo : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  return v;
}

// A batch's points as a checkpoint record (runner/checkpoint.hpp): eps and diverge_step per point, eps
// of a diverged point (NaN by contract) stored as 0 and restored from its diverge_step >= 0.
struct BatchCodec {
  void encode(const std::vector<EnergyMapPoint>& batch, std::vector<double>& out) const {
    for (const EnergyMapPoint& p : batch) {
      if (p.diverge_step >= 0 && !std::isnan(p.eps)) throw std::logic_error("energy_map: a diverged point with a finite eps");
      out.push_back(p.diverge_step >= 0 ? 0.0 : p.eps), out.push_back(static_cast<double>(p.diverge_step));
    }
  }
  std::vector<EnergyMapPoint> decode(std::span<const double> v) const {
    if (v.size() != 2 * kEnergyMapBatch)
      throw std::invalid_argument("a record of " + std::to_string(v.size()) + " values, not " + std::to_string(2 * kEnergyMapBatch));
    std::vector<EnergyMapPoint> batch(kEnergyMapBatch);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const double step = v[2 * i + 1];
      if (!(step >= -1 && step == std::floor(step)))
        throw std::invalid_argument("point " + std::to_string(i) + ": diverge_step " + std::to_string(step) + " is not a step");
      batch[i].diverge_step = static_cast<std::int64_t>(step);
      batch[i].eps = step >= 0 ? std::numeric_limits<double>::quiet_NaN() : v[2 * i];
    }
    return batch;
  }
};

}  // namespace

std::vector<EnergyMapPoint> energy_map_points(Context& ctx, const std::string& name, const EnergyMapGrid& g, Coordinates c,
                                              std::size_t& computed) {
  const EnergyMapKernelInfo best = energy_map_kernels().front();
  const EnergyMapKernel kernel = best.run;
  std::atomic<std::size_t> count = 0;
  const auto batches = checkpointed_map<std::vector<EnergyMapPoint>>(
      ctx, {.name = name, .kernel = best.isa}, g.nbatches,  // (each kernel rounds in its own way)
      [&](std::size_t b) {
        std::vector<EnergyMapPoint> out(kEnergyMapBatch);
        kernel(c, g.P, &g.x0[b * kEnergyMapBatch], &g.y0[b * kEnergyMapBatch], out.data());
        ++count;
        return out;
      },
      BatchCodec{});
  computed = count;
  std::vector<EnergyMapPoint> points;
  for (const auto& batch : batches) points.insert(points.end(), batch.begin(), batch.end());
  return points;
}

EnergyMapGrid energy_map_grid(const Scene& s) {
  EnergyMapGrid m;
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

void check_energy_map(const Scene& s) {
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

EnergyMapCount energy_map_count(const Scene& s) {
  const double points = static_cast<double>(s.integer("grid.nx")) * static_cast<double>(s.integer("grid.ny"));
  return {points, std::ceil(points / kEnergyMapBatch), std::round(s.real("t_max") / s.real("dt"))};
}

const PlanRate& energy_map_kernel_rate() { return plan_rate("energy map kernel " + energy_map_kernels().front().isa); }

}  // namespace geomint
