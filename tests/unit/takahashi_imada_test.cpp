// The Takahashi-Imada method, its simplified version and the processing map
// chi_h (004 Sect. 1, and the note on its closed forms for the oscillator).
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <vector>

#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/transforms/rowlands_processors.hpp"

using namespace geomint;

namespace {
const double alpha = takahashi_imada_alpha;

// Positions q_0..q_n of a plain (unprocessed) method.
std::vector<double> positions(const auto& method, PhaseState<1> z0, double h, int n) {
  std::vector<double> q;
  integrate(method, z0, h, n, [&](auto, const PhaseState<1>& z) { q.push_back(z.q[0]); });
  return q;
}
}  // namespace

TEST(TakahashiImada, OscillatorRecursion) {
  // q_{n+1} - (2 - x + alpha x^2) q_n + q_{n-1} = 0, x = (w h)^2.
  const HarmonicOscillator osc{1.0, 1.7};
  const double h = 0.3, x = std::pow(osc.w * h, 2);
  const auto q = positions(takahashi_imada_method(osc, false), make_state(0.4, 0.9), h, 200);
  for (std::size_t n = 1; n + 1 < q.size(); ++n)
    EXPECT_NEAR(q[n + 1] - (2 - x + alpha * x * x) * q[n] + q[n - 1], 0.0, 1e-14) << n;
}

TEST(TakahashiImada, SimplifiedEqualsTakahashiImadaOnTheOscillator) {
  const HarmonicOscillator osc{1.0, 1.7};
  const auto a = positions(takahashi_imada_method(osc, false), make_state(0.4, 0.9), 0.3, 200);
  const auto b = positions(simplified_ti_method(osc, false), make_state(0.4, 0.9), 0.3, 200);
  for (std::size_t n = 0; n < a.size(); ++n) EXPECT_NEAR(a[n], b[n], 1e-13) << n;
}

TEST(TakahashiImada, MaxRelativeEnergyErrorMatchesTheClosedForm) {
  // From q0 = 0, p0 = 1 in processed variables: max |H - H0| / H0 = x^3 / (36 (x^2 - 12 x + 48)).
  const HarmonicOscillator osc{1.0, 1.0};
  for (double wh : {0.5, 1.0, 2.0}) {
    const double x = wh * wh, closed = x * x * x / (36 * (x * x - 12 * x + 48));
    double worst = 0;
    const auto m = takahashi_imada_method(osc, true);
    integrate(m, make_state(0.0, 1.0), wh, 20000,
                        [&](auto, const PhaseState<1>& z) { worst = std::max(worst, std::abs(osc.H(z) - 0.5) / 0.5); });
    EXPECT_NEAR(worst, closed, 2e-3 * closed) << wh;
  }
}

TEST(TakahashiImada, OrdersOnTheOscillator) {
  // Processed TI: global error order 4, energy order 6; Stormer-Verlet: 2.
  const HarmonicOscillator osc{1.0, 1.0};
  std::vector<double> hs, e_ti, h_ti, e_sv;
  for (double h = 0.2; h > 0.01; h /= 2) {
    const int n = static_cast<int>(std::lround(10.0 / h));
    double eg = 0, eh = 0, es = 0;
    integrate(takahashi_imada_method(osc, true), make_state(0.0, 1.0), h, n, [&](auto j, const PhaseState<1>& z) {
      const auto ex = osc.exact(make_state(0.0, 1.0), static_cast<double>(j) * h);
      eg = std::max(eg, std::hypot(z.p[0] - ex.p[0], z.q[0] - ex.q[0]));
      eh = std::max(eh, std::abs(osc.H(z) - 0.5));
    });
    integrate(stormer_verlet_method(osc), make_state(0.0, 1.0), h, n, [&](auto j, const PhaseState<1>& z) {
      const auto ex = osc.exact(make_state(0.0, 1.0), static_cast<double>(j) * h);
      es = std::max(es, std::hypot(z.p[0] - ex.p[0], z.q[0] - ex.q[0]));
    });
    hs.push_back(h), e_ti.push_back(eg), h_ti.push_back(eh), e_sv.push_back(es);
  }
  EXPECT_NEAR(fit_order(hs, e_ti, 1e-13).order, 4.0, 0.3);
  EXPECT_NEAR(fit_order(hs, h_ti, 1e-13).order, 6.0, 0.4);
  EXPECT_NEAR(fit_order(hs, e_sv, 1e-13).order, 2.0, 0.15);
}

TEST(TakahashiImada, ProcessingMapRoundTrip) {
  const HenonHeiles hh;
  const auto z = make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.45, 0.3));
  const auto back = ti_process(hh, ti_unprocess(hh, z, 0.2, alpha), 0.2, alpha);
  EXPECT_LT((back.q - z.q).norm() + (back.p - z.p).norm(), 1e-15);
}

TEST(TakahashiImada, SymplecticButSimplifiedOnlyVolumePreserving) {
  // Central-difference Jacobians of one step on Henon-Heiles (k = 3), h = 0.2.
  const HenonHeiles hh;
  const double h = 0.2;
  const auto z0 = make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.45, 0.3));
  const Mat<4> Jt = step_jacobian_fd(takahashi_imada_method(hh, false), z0, h, 1e-5);
  const Mat<4> Js = step_jacobian_fd(simplified_ti_method(hh, false), z0, h, 1e-5);
  EXPECT_LT(symplecticity_defect(Jt), 1e-9);
  const double defect = symplecticity_defect(Js);
  EXPECT_GT(defect, 1e-7) << "the simplified method is not symplectic for two degrees of freedom";
  EXPECT_NEAR(Js.determinant(), 1.0, 1e-9);  // but it preserves volume
}

TEST(ModifiedEnergy, DerivativesAgainstFiniteDifferences) {
  // U4 and U5 against differences of U'' along a (loose tolerance), for both systems.
  const UnsymmetricPendulum up;
  const HenonHeiles hh5{{}, 5};
  const double d = 1e-3;
  {
    const Vec<1> q(0.7), a(1.3);
    const auto u3 = [&](const Vec<1>& x) {  // U'''(a^3) by a central difference of U''(a,a)
      return (a.dot(up.U_qq_times((x + d * a).eval(), a)) - a.dot(up.U_qq_times((x - d * a).eval(), a))) / (2 * d);
    };
    EXPECT_NEAR(up.U4(q, a), (u3((q + d * a).eval()) - u3((q - d * a).eval())) / (2 * d), 1e-4);
    const auto u4 = [&](const Vec<1>& x) { return up.U4(x, a); };
    EXPECT_NEAR(up.U5(q, a), (u4((q + d * a).eval()) - u4((q - d * a).eval())) / (2 * d), 1e-4);
  }
  {
    const Vec<2> q(0.1, 0.3), a(0.4, -0.7);
    const auto u4 = [&](const Vec<2>& x) { return hh5.U4(x, a); };
    EXPECT_NEAR(hh5.U5(q, a), (u4((q + d * a).eval()) - u4((q - d * a).eval())) / (2 * d), 1e-6);
    const auto u2 = [&](const Vec<2>& x) { return a.dot(hh5.U_qq_times(x, a)); };
    const double fd4 = (u2((q + d * a).eval()) - 2 * u2(q) + u2((q - d * a).eval())) / (d * d);  // d^2/ds^2 U''(a,a)
    EXPECT_NEAR(hh5.U4(q, a), fd4, 1e-4 * (1 + std::abs(fd4)));
  }
}

TEST(ModifiedEnergy, ConservedToSixthOrderAlongTheSimplifiedMethodOnHenonHeiles3) {
  // The note's check: max |E_n - E_0| over t <= 100 drops by 2^6 when h halves (k = 3: U'''' = U^(5) = 0).
  const HenonHeiles hh;
  const auto z0 = make_state<2>(Vec<2>(0.0, 0.2), Vec<2>(0.354024481262713, 0.3));
  std::vector<double> hs, es;
  for (double h : {0.2, 0.1, 0.05}) {
    double worst = 0;
    const double E0 = simplified_ti_modified_energy(hh, z0, h);
    integrate(simplified_ti_method(hh, false), z0, h, std::lround(100 / h), [&](auto, const PhaseState<2>& z) {
      worst = std::max(worst, std::abs(simplified_ti_modified_energy(hh, z, h) - E0));
    });
    hs.push_back(h), es.push_back(worst);
  }
  EXPECT_NEAR(fit_order(hs, es, 1e-14).order, 6.0, 0.3);
}

TEST(LennardJones, DerivativesAgainstFiniteDifferences) {
  // 3 x 3 grid, slightly perturbed (004 Fig. 6), and a direction a.
  const LennardJones<9> lj;
  Vec<18> q, a;
  for (int i = 0; i < 9; ++i) {
    q[2 * i] = 1 + i % 3 + 0.01 * std::sin(1.0 + i), q[2 * i + 1] = 1 + i / 3 + 0.01 * std::cos(2.0 + i);
    a[2 * i] = std::sin(0.3 * i), a[2 * i + 1] = std::cos(0.7 * i);
  }
  const double d = 1e-5;
  const auto along = [&](const auto& f, double s) { return f((q + s * a).eval()); };
  const auto U = [&](const Vec<18>& x) { return lj.U(x); };
  EXPECT_NEAR(lj.U_q(q).dot(a), (along(U, d) - along(U, -d)) / (2 * d), 1e-6);
  const Vec<18> hv = (lj.U_q((q + d * a).eval()) - lj.U_q((q - d * a).eval())) / (2 * d);
  EXPECT_LT((lj.U_qq_times(q, a) - hv).norm(), 1e-5 * (1 + hv.norm()));
  const auto U2 = [&](const Vec<18>& x) { return a.dot(lj.U_qq_times(x, a)); };
  const double e = 1e-3;
  const double fd4 = (along(U2, e) - 2 * along(U2, 0.0) + along(U2, -e)) / (e * e);
  EXPECT_NEAR(lj.U4(q, a), fd4, 1e-4 * (1 + std::abs(fd4)));
  const auto U4 = [&](const Vec<18>& x) { return lj.U4(x, a); };
  const double fd5 = (along(U4, e / 10) - along(U4, -e / 10)) / (e / 5);
  EXPECT_NEAR(lj.U5(q, a), fd5, 1e-4 * (1 + std::abs(fd5)));
}

TEST(HenonHeiles, ZeroCouplingIsCompiledOutAndOneIsThePaperPotential) {
  // with_henon_heiles(k, 0) steps a system without the term c q1^2 q2 (not one that multiplies it by 0),
  // and with c = 1 the same bits as the paper's potential.
  const Vec<2> q(0.3, -0.2), p(0.1, 0.4);
  with_henon_heiles(5, 0.0, [&](const auto& hh) {
    EXPECT_TRUE((std::is_same_v<std::decay_t<decltype(hh)>, HenonHeilesT<false>>));
    const HenonHeilesT<true> times_zero{{}, 5, 0.0};
    EXPECT_EQ(hh.U_q(q), times_zero.U_q(q));
    EXPECT_EQ(hh.U(q), times_zero.U(q));
  });
  with_henon_heiles(5, 1.0, [&](const auto& hh) {
    const HenonHeiles paper{{}, 5};
    const auto a = simplified_ti_method(hh, false), b = simplified_ti_method(paper, false);
    EXPECT_EQ(phase_distance(integrate(a, make_state<2>(q, p), 0.1, 100), integrate(b, make_state<2>(q, p), 0.1, 100)),
              0.0);
  });
}
