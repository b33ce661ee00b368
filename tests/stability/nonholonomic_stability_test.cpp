// Hard case of the nonholonomic particle (003 Sec. 5.3): without a potential
// y grows linearly and the conformal factor N = (1 + y^2)^(-1/2) tends to 0
// (N ~ 0.01 at t = 100), so the altered Lagrangian degenerates. Phi^(4) must
// stay finite, keep Newton at a few iterations and keep H near H0.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "../hard_case.hpp"

using namespace geomint;

namespace nonholonomic_stability_test {  // the file's scope (the tests build as one translation unit)

TEST(NonholonomicStability, FreeParticlePhi4ToT100) {
  const NonholonomicParticle sys{Potential::free};
  const double h = 0.25;
  const auto z0 = make_state<2>(Vec<2>(0, 0), Vec<2>(1, 1));
  for (Discretization d : all_discretizations) {
    const double E = ModifiedSeries(d, sys, h).E(4, z0), H0 = sys.H(z0);
    auto z = z0;
    int max_iterations = 0;
    double max_H_err = 0;
    for (int j = 0; j < 400; ++j) {
      const auto step = conformal_variational_step(d, sys, z, h, E);
      z = step.z;
      max_iterations = std::max(max_iterations, step.newton_iterations);
      max_H_err = std::max(max_H_err, std::abs(sys.H(z) - H0));
      ASSERT_TRUE(z.q.allFinite() && z.p.allFinite()) << discretization_name(d) << " step " << j;
    }
    const std::string name = discretization_name(d);
    EXPECT_CASE(name + ": N at t = 100 (the degenerate regime was reached)", NonholonomicParticle::N(z.q[1]), "<", 0.02);
    EXPECT_CASE(name + ": most Newton iterations of a step", max_iterations, "<=", 6);
    EXPECT_CASE(name + ": max |H - H0| to t = 100", max_H_err, "<", 0.05);
  }
}

}  // namespace nonholonomic_stability_test
