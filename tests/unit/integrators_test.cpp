// One step of each integrator against values computed by hand, the
// structural properties (adjointness, symplecticity) of symplectic Euler, and
// the method registry's lookups and dispatch by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "../hard_case.hpp"
#include "geomint/core/compensated_sum.hpp"
#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/methods/dispatch.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/exponential_decay.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"

using namespace geomint;

namespace integrators_test {  // the file's scope (the tests build as one translation unit)

namespace {
using Transformed = PointTransformed<HarmonicOscillator, OscillatorCompensation>;
const Transformed transformed{{}, OscillatorCompensation{2.0, 0.3}};
}  // namespace

TEST(ExplicitEuler, OneStepOnDecay) {
  // y1 = y0 + h(-alpha y0) = 1 - 0.3 * 1.5 = 0.55
  EXPECT_DOUBLE_EQ(explicit_euler(ExponentialDecay{1.5}, 1.0, 0.3), 0.55);
}

TEST(RungeKutta4, OneStepOnDecayIsTheDegree4Taylor) {
  const double h = 0.2;  // R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 at z = -h
  const double expected = 1 - h + h * h / 2 - h * h * h / 6 + h * h * h * h / 24;
  EXPECT_NEAR(runge_kutta4(ExponentialDecay{1.0}, 1.0, h), expected, 2.5e-16);
}

TEST(RungeKutta4, OneStepOnOscillatorIsTheDegree4Rotation) {
  // z1 = R(hJ) z0 with cos h ~ 1 - h^2/2 + h^4/24 and sin h ~ h - h^3/6.
  const double h = 0.1, c = 1 - h * h / 2 + h * h * h * h / 24, s = h - h * h * h / 6;
  const auto z = runge_kutta4(HamiltonianField{HarmonicOscillator{}}, make_state(1.0, 0.5), h);
  EXPECT_NEAR(z.q[0], c * 1.0 + s * 0.5, 1e-15);
  EXPECT_NEAR(z.p[0], -s * 1.0 + c * 0.5, 1e-15);
}

// Kahan summation: 2^20 increments of the double nearest 0.1 sum to within an ulp (about 1.5e-11)
// of their exact sum, where adding them one by one is off by about 1e-6.
TEST(CompensatedSum, TwoToTheTwentyIncrementsWithinAnUlpOfTheExactSum) {
  const double x = 0.1;
  const long n = 1L << 20;
  const double exact = x * static_cast<double>(n);  // (a power of two: exact)
  double s = 0, c = 0, naive = 0;
  for (long i = 0; i < n; ++i) {
    compensated_add(s, c, x);
    naive += x;
  }
  const double ulp = std::nextafter(exact, 2 * exact) - exact;
  EXPECT_LE(std::abs(s - exact), ulp);
  EXPECT_GT(std::abs(naive - exact), 1e4 * ulp);  // (the sum the compensation is there to avoid)
}

TEST(SymplecticEuler, PqOneStepOnOscillator) {
  // (42): p1 = 0.5 - 0.1 * 1 = 0.4;  (43): q1 = 1 + 0.1 * 0.4 = 1.04
  const auto z = symplectic_euler_pq(HarmonicOscillator{}, make_state(1.0, 0.5), 0.1);
  EXPECT_DOUBLE_EQ(z.p[0], 0.4);
  EXPECT_DOUBLE_EQ(z.q[0], 1.04);
}

TEST(SymplecticEuler, QpOneStepOnOscillator) {
  // q1 = 1 + 0.1 * 0.5 = 1.05;  p1 = 0.5 - 0.1 * 1.05 = 0.395
  const auto z = symplectic_euler_qp(HarmonicOscillator{}, make_state(1.0, 0.5), 0.1);
  EXPECT_DOUBLE_EQ(z.q[0], 1.05);
  EXPECT_DOUBLE_EQ(z.p[0], 0.395);
}

TEST(SymplecticEuler, ImplicitStageMatchesTheClosedFormRoot) {
  // For the transformed oscillator, (42) is the quadratic a P^2 + P - b = 0 in
  // P = pbar1, with a = h Q''(q), b = pbar - h q / Q'(q) (from (47)); its root
  // near b is 2b / (1 + sqrt(1 + 4ab)).
  const double h = 0.3;
  const auto zb = transformed.to_transformed(make_state(0.7, -0.4));
  const auto next = symplectic_euler_pq(transformed, zb, h);
  const auto& map = transformed.map;
  const double q = map.inverse(zb.q[0]);
  const double a = h * map.d2Q(q), b = zb.p[0] - h * q / map.dQ(q);
  const double P = 2 * b / (1 + std::sqrt(1 + 4 * a * b));
  EXPECT_NEAR(next.p[0], P, 4e-16 * std::abs(P));
  EXPECT_NEAR(next.q[0], zb.q[0] + h * P * map.dQ(q) * map.dQ(q), 1e-15);  // (43) with (46)
}

TEST(SymplecticEuler, QpIsTheAdjointOfPq) {
  // Phi*_h = Phi_{-h}^{-1}:  qp(pq(z, -h), h) = z, also through the Newton solves.
  const auto z0 = transformed.to_transformed(make_state(0.6, 0.5));
  const auto back = symplectic_euler_qp(transformed, symplectic_euler_pq(transformed, z0, -0.05), 0.05);
  EXPECT_NEAR(back.q[0], z0.q[0], 1e-14);
  EXPECT_NEAR(back.p[0], z0.p[0], 1e-14);
}

TEST(SymplecticEuler, TransformedStepIsSymplectic) {
  // One degree of freedom: symplectic <=> the Jacobian determinant is 1 (eq. (21)).
  const auto z0 = transformed.to_transformed(make_state(0.8, 0.3));
  const double d = 1e-6, h = 0.3;
  const auto step = [&](double dq, double dp) {
    auto z = z0;
    z.q[0] += dq, z.p[0] += dp;
    return symplectic_euler_pq(transformed, z, h);
  };
  const auto qp = step(d, 0), qm = step(-d, 0), pp = step(0, d), pm = step(0, -d);
  const double a = (qp.q[0] - qm.q[0]) / (2 * d), b = (pp.q[0] - pm.q[0]) / (2 * d);
  const double c = (qp.p[0] - qm.p[0]) / (2 * d), e = (pp.p[0] - pm.p[0]) / (2 * d);
  EXPECT_NEAR(a * e - b * c, 1.0, 1e-8);
}

TEST(Counting, ForceEvaluationsPerStep) {
  std::int64_t n = 0;
  const Counting<HarmonicOscillator> sys{{}, &n};
  integrate(SymplecticEulerPQ::bind(sys), make_state(1.0, 0.0), 0.1, 10);
  EXPECT_EQ(n, 10);  // explicit: one H_q per step
  n = 0;
  integrate(RungeKutta4::bind(sys), make_state(1.0, 0.0), 0.1, 10);
  EXPECT_EQ(n, 40);  // four stages
}

// The registry's lookups (the declared values themselves: tests/verification).
TEST(MethodRegistry, FindsByNameOrLabelAndNamesTheValidNames) {
  EXPECT_EQ(&method_info("stormer_verlet"), &method_info("sv"));
  EXPECT_EQ(method_info("ee").name, "explicit_euler");
  EXPECT_EQ(find_method("no_such_method"), nullptr);
  try {
    method_info("no_such_method");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("symplectic_euler_pq"), std::string::npos) << e.what();
  }
  EXPECT_EQ(family_name(method_info("rowlands").family), "processed");
}

// A method's colour and marker name it alone: the methods a figure draws together are told apart by
// construction, whichever of them a scene names (figures/common.gp method_styles).
TEST(MethodRegistry, ColourAndMarkerNameOneMethod) {
  std::map<std::pair<std::string_view, int>, std::string_view> seen;
  for (const MethodInfo& m : method_registry()) {
    EXPECT_TRUE(m.marker >= 1 && m.marker <= 15) << m.name << ": marker " << m.marker << " is not a gnuplot point type 1-15";
    const auto [at, fresh] = seen.emplace(std::pair{m.colour, m.marker}, m.name);
    EXPECT_TRUE(fresh) << m.name << " and " << at->second << " share the colour " << m.colour << " and the marker " << m.marker;
  }
}

TEST(MethodRegistry, WithMethodBindsByNameAndRefusesWhatCannotStepTheSystem) {
  const auto z = with_method("se", HarmonicOscillator{}, [](const auto& m) { return integrate(m, make_state(1.0, 0.5), 0.1, 1); });
  EXPECT_DOUBLE_EQ(z.p[0], 0.4);  // as SymplecticEuler.PqOneStepOnOscillator
  EXPECT_REFUSAL_OF(std::invalid_argument, "an unknown method name",
                    with_method("no_such_method", HarmonicOscillator{}, [](const auto&) { return 0; }), {"no_such_method"});
  EXPECT_REFUSAL_OF(std::invalid_argument, "Lobatto on a system that is not mechanical",  // (a transformed H)
                    with_method("lobatto", transformed, [](const auto&) { return 0; }), {"lobatto"});
  const auto names = methods_for<Transformed>();  // non-separable H: symplectic Euler and the explicit methods
  EXPECT_NE(std::find(names.begin(), names.end(), "symplectic_euler_qp"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "stormer_verlet"), names.end());
}

}  // namespace integrators_test
