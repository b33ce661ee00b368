// rowlands_convergence: what its studies share (rowlands_convergence.hpp).
#include "rowlands_convergence.hpp"

#include <algorithm>
#include <cmath>

#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/counting.hpp"

namespace geomint::rowlands_convergence {

State state_of(const std::vector<double>& row) { return make_state<2>(Vec<2>(row[0], row[1]), Vec<2>(row[2], row[3])); }

ElasticPendulumParams pendulum_of(const Scene& s) {
  return {s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
}

std::vector<std::string> pendulum_method_choices() { return MethodsOn<Counting<ElasticPendulumWithGravity>>::choices(); }


void scene_summary(Context& ctx) {
  const auto hs = ctx.scene.reals("h");
  ctx.summary["h_range"] = h_range(hs);
  ctx.summary["initial_conditions"] = ctx.scene.real_rows("initial").size();
}

void check_methods(const Scene& s, const char* key) {
  const ElasticPendulumParams p = pendulum_of(s);
  with_elastic_pendulum(p, [&](const auto& sys) { MethodsOn<std::decay_t<decltype(sys)>>::check(s, key, sys); });
  const double omega = std::sqrt(p.k / p.m);
  for (const auto& m : s.texts(key))
    for (double h : s.reals("h"))
      check_oscillatory_bound(s, "h", key, m, h * omega, "h sqrt(k/m) at h = " + format_double(h) + ", named in " + key);
}

void check_common(const Scene& s) {
  const double t_end = s.real("t_end");
  for (double h : s.reals("h")) {
    if (!(t_end / h <= max_exact_count)) s.reject("h", "at most 2^53 steps to t_end = " + format_double(t_end) + ", here h = " + format_double(h));
    const double n = static_cast<double>(steps_to(t_end, h));
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end) s.reject("h", "each h must divide t_end = " + format_double(t_end));
  }
  for (const auto& row : s.real_rows("initial"))
    if (std::hypot(row[0], row[1]) == 0.0) s.reject("initial", "the spring force is singular at x = y = 0");
}


}  // namespace geomint::rowlands_convergence
