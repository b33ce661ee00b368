#include "geomint/sweep/energy_map.hpp"

#include <cmath>
#include <utility>

#include "geomint/sweep/arithmetic_counts.hpp"
#include "geomint/sweep/lanes_cap.hpp"

namespace geomint {

void energy_map_kernel_sse2(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);
void energy_map_kernel_avx2(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);
void energy_map_kernel_avx512(Coordinates, const EnergyMapParams&, const double*, const double*, EnergyMapPoint*);

std::vector<EnergyMapKernelInfo> energy_map_kernels() {
  __builtin_cpu_init();
  std::vector<EnergyMapKernelInfo> k;
  const bool fma = __builtin_cpu_supports("fma");  // the AVX2 and AVX-512 kernels use it
  if (fma && __builtin_cpu_supports("avx512f"))
    k.push_back({"avx512", "AVX-512", energy_map_kernel_avx512,
                 {{{&kEnergyMapAvx512Cartesian, issue_mix_avx512}, {&kEnergyMapAvx512Polar, issue_mix_avx512}}}});
  if (fma && __builtin_cpu_supports("avx2"))
    k.push_back({"avx2", "AVX2", energy_map_kernel_avx2,
                 {{{&kEnergyMapAvx2Cartesian, issue_mix_avx2}, {&kEnergyMapAvx2Polar, issue_mix_avx2}}}});
  k.push_back({"sse2", "SSE2", energy_map_kernel_sse2, {}});
  return within_lanes_cap(std::move(k));
}

// The straightforward scalar loop: one trajectory at a time, the formulas
// written out as a user would (the reference the kernels are tested against;
// itself tested against the generic symplectic_euler_pq in tests/unit).
EnergyMapPoint energy_map_scalar(Coordinates c, const EnergyMapParams& P, double x0, double y0) {
  const double m = P.m, k = P.k, l = P.l, g = P.g, h = P.h;
  const double r0 = std::hypot(x0, y0);
  if (!(r0 > 0.0)) return {std::nan(""), 0};
  double sum = 0, comp = 0;
  const auto add = [&](double d) {  // Kahan summation of d^2
    const double y = d * d - comp, t = sum + y;
    comp = (t - sum) - y;
    sum = t;
  };
  if (c == Coordinates::cartesian) {
    double x = x0, y = y0, px = 0, py = 0, r = r0;
    const double H0 = 0.5 * k * (r0 - l) * (r0 - l) - m * g * y0;  // (73)
    for (std::int64_t j = 1; j <= P.steps; ++j) {
      const double f = k * (1.0 - l / r);
      px -= h * f * x, py -= h * (f * y - m * g);  // (42)
      x += h * px / m, y += h * py / m;            // (43)
      r = std::sqrt(x * x + y * y);
      const double d = (px * px + py * py) / (2 * m) + 0.5 * k * (r - l) * (r - l) - m * g * y - H0;
      if (!(r > 0.0 && std::fabs(d) <= P.blowup)) return {std::nan(""), j};
      add(d);
    }
  } else {
    double r = r0, th = std::atan2(x0, y0), pr = 0, pt = 0;
    const double H0 = 0.5 * k * (r0 - l) * (r0 - l) - m * g * r0 * std::cos(th);  // (72)
    for (std::int64_t j = 1; j <= P.steps; ++j) {
      // (42) solved explicitly: dH/dtheta has no p, dH/dr has p_theta only; (43) with r^j.
      pt -= h * m * g * r * std::sin(th);
      pr -= h * (-pt * pt / (m * r * r * r) + k * (r - l) - m * g * std::cos(th));
      th += h * pt / (m * r * r);
      r += h * pr / m;
      const double d = (pr * pr + pt * pt / (r * r)) / (2 * m) + 0.5 * k * (r - l) * (r - l) - m * g * r * std::cos(th) - H0;
      if (!(r > 0.0 && std::fabs(d) <= P.blowup)) return {std::nan(""), j};
      add(d);
    }
  }
  return {std::sqrt(sum / static_cast<double>(P.steps)), -1};  // (50)
}

}  // namespace geomint
