#pragma once
// The energy map of 000 Fig. 6: symplectic Euler (42)-(43), p first, on the
// elastic pendulum from many initial conditions at rest, in Cartesian (73) or
// polar (72) coordinates, accumulating for each the RMS energy error of
// eq. (50), eps = sqrt(sum_{j=0}^{J} (H_j - H_0)^2 / J).
//
// Two implementations of the same computation:
//  - energy_map_scalar: one trajectory at a time, the formulas written out (the
//    straightforward loop; tested against the generic library's
//    symplectic_euler_pq on ElasticPendulumCartesian/Polar);
//  - batch kernels: kEnergyMapBatch trajectories at once in structure-of-arrays
//    form, SIMD across the batch, one translation unit per instruction set
//    (SSE2, AVX2 and AVX-512 with FMA), chosen at run time by CPU detection. They
//    differ from the scalar loop by round-off only (fused multiply-adds, and sin/cos
//    of theta carried by the angle-addition formula, within a few ulp).
// A trajectory that reaches r <= 0, a non-finite value or an energy error above
// `blowup` is marked diverged at that step; its lane is parked, never poisoning
// the others. The batch kernels test for this once per block of steps and replay
// a suspect block step by step (so the hot loop has no tests), and sum
// (H_j - H_0)^2 per block, compensated (Kahan) across blocks.
#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/sweep/arithmetic_ceiling.hpp"

namespace geomint {

enum class Coordinates { cartesian, polar };

// A coordinate system's name in scenes, CSV columns and summary keys, and in a figure, with its equation of 000.
inline const char* coordinates_name(Coordinates c) { return c == Coordinates::cartesian ? "cartesian" : "polar"; }
inline const char* coordinates_label(Coordinates c) { return c == Coordinates::cartesian ? "Cartesian (73)" : "polar (72)"; }

struct EnergyMapParams {
  double l, m, k, g;   // pendulum (000 Appendix A)
  double h;            // step
  std::int64_t steps;  // J
  double blowup;       // |H_j - H_0| above this marks divergence
};

struct EnergyMapPoint {
  double eps;           // eq. (50); NaN when diverged
  std::int64_t diverge_step;  // -1: did not diverge
  auto fields() { return std::tie(eps, diverge_step); }  // (a record of runner/distributed_map.hpp)
};

inline constexpr int kEnergyMapBatch = 64;

// Polar batch kernels carry sin and cos of theta from step to step by energy_map_turn
// while |theta_{j+1} - theta_j| <= kEnergyMapMaxTurn, and take the vector sin and cos beyond.
inline constexpr double kEnergyMapMaxTurn = 0.5;

namespace detail {
// Taylor coefficients of sin(d)/d (first = 1) or cos(d) (first = 0) in z = d^2, through z^7.
constexpr std::array<double, 8> taylor_in_d2(int first) {
  std::array<double, 8> c{};
  double f = 1.0;  // first!, then (first + 2 n)!
  for (int n = 0; n < 8; ++n) {
    c[n] = (n % 2 ? -1.0 : 1.0) / f;
    f *= (first + 2 * n + 1) * (first + 2 * n + 2);
  }
  return c;
}
inline constexpr auto kSinOverD = taylor_in_d2(1), kCosD = taylor_in_d2(0);
}  // namespace detail

// (s, c) = (sin theta, cos theta) -> (sin(theta + d), cos(theta + d)) by the angle-addition
// formula, with sin d and cos d Taylor polynomials through d^13 and d^14: for |d| <= 0.5 the
// first omitted terms are below 5e-17 relative.
inline void energy_map_turn(double d, double& s, double& c) {
  using detail::kSinOverD, detail::kCosD;
  const double z = d * d;
  const double sd = d * (kSinOverD[0] + z * (kSinOverD[1] + z * (kSinOverD[2] + z * (kSinOverD[3] +
                         z * (kSinOverD[4] + z * (kSinOverD[5] + z * kSinOverD[6]))))));
  const double cd = kCosD[0] + z * (kCosD[1] + z * (kCosD[2] + z * (kCosD[3] +
                    z * (kCosD[4] + z * (kCosD[5] + z * (kCosD[6] + z * kCosD[7]))))));
  const double sn = s * cd + c * sd;
  c = c * cd - s * sd, s = sn;
}

// A batch kernel: integrates kEnergyMapBatch trajectories from (x0[i], y0[i]), p = 0.
using EnergyMapKernel = void (*)(Coordinates, const EnergyMapParams&, const double* x0, const double* y0,
                                 EnergyMapPoint* out);

struct EnergyMapKernelInfo {
  std::string isa;   // "avx512", "avx2", "sse2"
  std::string name;  // the instruction set as the reader knows it: "AVX-512", "AVX2", "SSE2"
  EnergyMapKernel run;
  std::array<KernelArithmetic, 2> arithmetic;  // Cartesian, polar: a step's arithmetic alone (empty for SSE2)
};

// The kernels this CPU can run under GEOMINT_LANES (sweep/lanes_cap.hpp), best first.
std::vector<EnergyMapKernelInfo> energy_map_kernels();

// The straightforward scalar loop, one trajectory.
EnergyMapPoint energy_map_scalar(Coordinates c, const EnergyMapParams& p, double x0, double y0);

}  // namespace geomint
