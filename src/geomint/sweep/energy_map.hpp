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
#include <cstdint>
#include <string>
#include <vector>

namespace geomint {

enum class Coordinates { cartesian, polar };

struct EnergyMapParams {
  double l, m, k, g;   // pendulum (000 Appendix A)
  double h;            // step
  std::int64_t steps;  // J
  double blowup;       // |H_j - H_0| above this marks divergence
};

struct EnergyMapPoint {
  double eps;           // eq. (50); NaN when diverged
  std::int64_t diverge_step;  // -1: did not diverge
};

inline constexpr int kEnergyMapBatch = 64;

// Polar batch kernels carry sin and cos of theta from step to step by the angle-addition
// formula, with Taylor sin and cos of the turn theta_{j+1} - theta_j = h p_theta / (m r^2)
// while |turn| <= kEnergyMapMaxTurn, and take the vector sin and cos beyond.
inline constexpr double kEnergyMapMaxTurn = 0.5;

// A batch kernel: integrates kEnergyMapBatch trajectories from (x0[i], y0[i]), p = 0.
using EnergyMapKernel = void (*)(Coordinates, const EnergyMapParams&, const double* x0, const double* y0,
                                 EnergyMapPoint* out);

struct EnergyMapKernelInfo {
  std::string isa;  // "avx512", "avx2", "sse2"
  EnergyMapKernel run;
};

// The kernels this CPU can run, best first.
std::vector<EnergyMapKernelInfo> energy_map_kernels();

// The straightforward scalar loop, one trajectory.
EnergyMapPoint energy_map_scalar(Coordinates c, const EnergyMapParams& p, double x0, double y0);

}  // namespace geomint
