// The batched energy-map kernels (every instruction set this CPU runs)
// against the scalar reference loop, and the masking of diverging lanes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geomint/sweep/energy_map.hpp"

using namespace geomint;

namespace {
const EnergyMapParams P{1.0, 1.0, 1.0, 0.02, 0.2, 2000, 1e3};  // 000 Fig. 6 parameters, 400 time units

// Regular (non-chaotic) initial positions near the hanging point (0, 1.02).
void regular_batch(std::vector<double>& x, std::vector<double>& y) {
  x.resize(kEnergyMapBatch), y.resize(kEnergyMapBatch);
  for (int i = 0; i < kEnergyMapBatch; ++i) x[i] = -0.3 + 0.02 * i, y[i] = 0.9 + 0.01 * (i % 7);
}
}  // namespace

TEST(EnergyMapKernel, EveryInstructionSetMatchesTheScalarLoop) {
  std::vector<double> x, y;
  regular_batch(x, y);
  const auto kernels = energy_map_kernels();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(kernels.back().isa, "sse2");  // the portable fallback is always there
  for (const auto& k : kernels) {
    for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
      std::vector<EnergyMapPoint> out(kEnergyMapBatch);
      k.run(c, P, x.data(), y.data(), out.data());
      for (int i : {0, 9, 17, 31}) {
        const auto ref = energy_map_scalar(c, P, x[i], y[i]);
        ASSERT_EQ(ref.diverge_step, -1);
        EXPECT_EQ(out[i].diverge_step, -1);
        EXPECT_NEAR(out[i].eps, ref.eps, 1e-10 * ref.eps) << k.isa << " lane " << i;
      }
    }
  }
}

TEST(EnergyMapKernel, DivergingLanesAreMaskedAndDoNotPoisonOthers) {
  std::vector<double> x, y;
  regular_batch(x, y);
  const auto k = energy_map_kernels().front();
  std::vector<EnergyMapPoint> clean(kEnergyMapBatch), mixed(kEnergyMapBatch);
  k.run(Coordinates::polar, P, x.data(), y.data(), clean.data());
  x[3] = 1.5, y[3] = 1.5;  // r0 = 2.12 > 2l + (2mg/k) cos(theta0): passes through r = 0
  x[4] = 0.0, y[4] = 0.0;  // the origin: no polar initial condition
  k.run(Coordinates::polar, P, x.data(), y.data(), mixed.data());
  EXPECT_GT(mixed[3].diverge_step, 0);
  EXPECT_TRUE(std::isnan(mixed[3].eps));
  EXPECT_EQ(mixed[4].diverge_step, 0);
  for (int i = 0; i < kEnergyMapBatch; ++i)
    if (i != 3 && i != 4) EXPECT_EQ(mixed[i].eps, clean[i].eps) << i;  // bit for bit
  EXPECT_GT(energy_map_scalar(Coordinates::polar, P, 1.5, 1.5).diverge_step, 0);
}
