// The method Phi^(ell) of 003 (4.5) on single points and on clouds, and the check of the modified series against
// independent values (nonholonomic_modified_series.hpp), compiled once.
#include <algorithm>
#include <cmath>

#include "geomint/core/integrate.hpp"
#include "geomint/systems/nonholonomic_golden.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"

namespace geomint {

PointTrajectory run_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                        const std::array<double, 4>& z0, std::int64_t n) {
  const double E = ModifiedSeries(d, sys, h).E(ell, from_array(z0));
  PointTrajectory t;
  t.z.reserve(static_cast<std::size_t>(n) + 1);
  integrate(conformal_variational_method(d, sys, E, &t.iterations), from_array(z0), h, n,
            [&](std::int64_t, const PhaseState<2>& z) { t.z.push_back(to_array(z)); });
  return t;
}

CloudRun transpose(const std::vector<PointTrajectory>& per_point) {
  CloudRun c;
  const std::size_t n = per_point.front().z.size();
  c.snapshots.assign(n, std::vector<std::array<double, 4>>(per_point.size()));
  for (std::size_t i = 0; i < per_point.size(); ++i) {
    for (std::size_t j = 0; j < n; ++j) c.snapshots[j][i] = per_point[i].z[j];
    c.iterations += per_point[i].iterations, c.steps += static_cast<std::int64_t>(n - 1);
  }
  return c;
}

CloudRun cloud_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                   const std::vector<std::array<double, 4>>& cloud, std::int64_t n) {
  std::vector<PointTrajectory> per_point;
  for (const auto& z0 : cloud) per_point.push_back(run_phi(d, sys, h, ell, z0, n));
  return transpose(per_point);
}

double modified_series_golden_error(const NonholonomicParticle& sys) {
  const std::string pot = potential_name(sys.potential);
  double worst = 0;
  for (const auto& g : nonholonomic::golden_cases) {
    if (g.potential != pot) continue;
    const ModifiedSeries ms(*parse_discretization(g.discretization), sys, nonholonomic::golden_h);
    for (const auto* p : {&g.a, &g.b}) {
      const PhaseState<2> z = from_array(p->z);
      const double got[] = {ms.E(2, z), ms.E(4, z), ms.N(2, z), ms.N(4, z), ms.K4(z, 1.0)};
      const double want[] = {p->E2, p->E4, p->N2, p->N4, p->K4_at_E1};
      for (int k = 0; k < 5; ++k) worst = std::max(worst, std::abs(got[k] - want[k]) / std::abs(want[k]));
    }
  }
  return worst;
}

}  // namespace geomint
