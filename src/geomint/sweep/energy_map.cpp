#include "geomint/sweep/energy_map.hpp"

#include <cmath>

#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/transforms/polar.hpp"

namespace geomint {

void energy_map_kernel_sse2(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);
void energy_map_kernel_avx2(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);
void energy_map_kernel_avx512(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);

std::vector<EnergyMapKernelInfo> energy_map_kernels() {
  __builtin_cpu_init();
  std::vector<EnergyMapKernelInfo> k;
  if (__builtin_cpu_supports("avx512f")) k.push_back({"avx512", energy_map_kernel_avx512});
  if (__builtin_cpu_supports("avx2")) k.push_back({"avx2", energy_map_kernel_avx2});
  k.push_back({"sse2", energy_map_kernel_sse2});
  return k;
}

namespace {

template <class Sys>
EnergyMapPoint scalar_run(const Sys& sys, const PhaseState<2>& z0, const EnergyMapParams& P, bool polar) {
  const double H0 = sys.H(z0);
  if (!(z0.q.allFinite() && std::isfinite(H0)) || (polar ? z0.q[0] : z0.q.norm()) <= 0.0) return {std::nan(""), 0};
  PhaseState<2> z = z0;
  double sum = 0, comp = 0;
  for (std::int64_t j = 1; j <= P.steps; ++j) {
    z = symplectic_euler_pq(sys, z, P.h);
    const double r = polar ? z.q[0] : z.q.norm(), d = sys.H(z) - H0;
    if (!(r > 0.0 && std::fabs(d) <= P.blowup)) return {std::nan(""), j};
    const double y = d * d - comp, t = sum + y;  // Kahan
    comp = (t - sum) - y;
    sum = t;
  }
  return {std::sqrt(sum / static_cast<double>(P.steps)), -1};  // (50)
}

}  // namespace

EnergyMapPoint energy_map_scalar(Coordinates c, const EnergyMapParams& P, double x0, double y0) {
  const auto z0 = make_state<2>(Vec<2>(x0, y0), Vec<2>(0.0, 0.0));
  if (c == Coordinates::cartesian) {
    const ElasticPendulumWithGravity sys{P.m, {SpringTerm{P.k, P.l}, GravityTerm{P.m, P.g}}};
    return scalar_run(sys, z0, P, false);
  }
  const ElasticPendulumPolarWithGravity sys{P.m, {SpringPolarTerm{P.k, P.l}, GravityPolarTerm{P.m, P.g}}};
  try {
    return scalar_run(sys, polar_from_cartesian(z0), P, true);
  } catch (const IntegrationError&) {  // the implicit stage failed: the run left the chart
    return {std::nan(""), -2};
  }
}

}  // namespace geomint
