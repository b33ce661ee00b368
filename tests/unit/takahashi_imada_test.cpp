// The Takahashi-Imada method, its simplified version and the processing map
// chi_h (004 Sect. 1, and the note on its closed forms for the oscillator).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <type_traits>
#include <vector>

#include "../hard_case.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/transforms/rowlands_processors.hpp"

using namespace geomint;

namespace takahashi_imada_test {  // the file's scope (the tests build as one translation unit)

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

// The largest sampled relative error of H along a method from z0 over n steps of w h (w = 1).
double max_rel_energy_error(const auto& method, PhaseState<1> z0, double wh, int n) {
  const HarmonicOscillator osc{1.0, 1.0};
  double worst = 0;
  integrate(method, z0, wh, n, [&](auto, const PhaseState<1>& z) {
    worst = std::max(worst, std::abs(osc.H(z) - osc.H(z0)) / osc.H(z0));
  });
  return worst;
}

TEST(TakahashiImada, MaxRelativeEnergyErrorMatchesTheClosedForm) {
  // From q0 = 0, p0 = 1 in processed variables: max |H - H0| / H0 = x^3 / (36 (x^2 - 12 x + 48)).
  const HarmonicOscillator osc{1.0, 1.0};
  for (double wh : {0.5, 1.0, 2.0}) {
    const double x = wh * wh, closed = ti_oscillator_max_rel_energy_error(wh);
    EXPECT_NEAR(closed, x * x * x / (36 * (x * x - 12 * x + 48)), 1e-15 * closed) << wh;
    EXPECT_NEAR(max_rel_energy_error(takahashi_imada_method(osc, true), make_state(0.0, 1.0), wh, 20000), closed,
                2e-3 * closed) << wh;
  }
}

TEST(TakahashiImada, StormerVerletMaxRelativeEnergyErrorMatchesTheClosedForm) {
  // 004 Sect. 1.4: from q0 = 0, p0 = 1, max |H - H0| / H0 = x / (4 - x) along Stormer-Verlet.
  const HarmonicOscillator osc{1.0, 1.0};
  for (double wh : {0.3, 1.1, 1.9}) {
    const double closed = sv_oscillator_max_rel_energy_error(wh);
    EXPECT_NEAR(closed, wh * wh / (4 - wh * wh), 1e-15 * closed);
    EXPECT_NEAR(max_rel_energy_error(stormer_verlet_method(osc), make_state(0.0, 1.0), wh, 20000), closed,
                2e-3 * closed) << wh;
  }
}

TEST(TakahashiImada, FromRestTheEnergyErrorIsUnbounded) {
  // From q0 = 1, p0 = 0 (processed) the largest relative error of H is a - 1 = x^3 / (12 - x)^3, not the
  // closed form of the start q0 = 0, and it exceeds one near the bound 2 sqrt(3).
  const HarmonicOscillator osc{1.0, 1.0};
  for (double wh : {1.0, 2.0, 3.0, 3.4}) {
    const double x = wh * wh, closed = ti_oscillator_max_rel_energy_error_from_rest(wh);
    EXPECT_NEAR(closed, x * x * x / std::pow(12 - x, 3), 1e-14 * closed);
    EXPECT_NEAR(max_rel_energy_error(takahashi_imada_method(osc, true), make_state(1.0, 0.0), wh, 20000), closed,
                2e-3 * closed) << wh;
  }
  EXPECT_CASE("TI from rest, omega h = 3.4 (0.98 x 2 sqrt 3): largest relative error of H",
              ti_oscillator_max_rel_energy_error_from_rest(3.4), ">", 1.0);
  EXPECT_CASE("TI from q = 0, omega h = 3.4: largest relative error of H", ti_oscillator_max_rel_energy_error(3.4), "<",
              1.0);
}

TEST(TakahashiImada, Sect33RemainderOfThePrintedTermIsOrderSeven) {
  // 004 Sect. 3.3: q_{n+1} of (1.6) - q_{n+1} of (1.4) = 1/4 h^6 alpha^2 f''(f, f) + remainder. With the term
  // at q_{n+1/2} as printed the remainder is O(h^7) (not O(h^8)); at q_n it vanishes for k = 3 (U''' constant).
  const HenonHeiles hh;
  const auto z = make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.35, 0.3));
  std::vector<double> hs, at_mid;
  for (double h : {0.2, 0.1, 0.05, 0.025}) {
    const auto ti = integrate(takahashi_imada_method(hh, false), z, h, 1);
    const auto sti = integrate(simplified_ti_method(hh, false), z, h, 1);
    const Vec<2> mid = (z.q + sti.q) / 2;
    hs.push_back(h);
    at_mid.push_back((sti.q - ti.q - simplified_ti_q_correction(hh, mid, h, alpha)).norm());
    EXPECT_LT((sti.q - ti.q - simplified_ti_q_correction(hh, z.q, h, alpha)).norm(), 1e-15) << h;
  }
  EXPECT_NEAR(fit_order(hs, at_mid, 0.0).order, 7.0, 0.15);
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

TEST(TakahashiImada, ProcessingMakesItFourthOrderOnHenonHeiles) {
  // 004 (1.5): with chi_h the global error of TI is O(h^4), without it O(h^2) (RK4 at h = 1e-3 as the reference).
  const HenonHeiles hh;
  const auto z0 = make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.45, 0.3));
  const double t = 2.0;
  const auto exact = integrate(RungeKutta4::bind(hh), z0, 1e-3, 2000);
  std::vector<double> hs, processed, kernel;
  for (double h : {0.2, 0.1, 0.05}) {
    const auto n = std::lround(t / h);
    hs.push_back(h);
    processed.push_back(phase_distance(integrate(takahashi_imada_method(hh, true), z0, h, n), exact));
    kernel.push_back(phase_distance(integrate(takahashi_imada_method(hh, false), z0, h, n), exact));
  }
  EXPECT_NEAR(fit_order(hs, processed, 1e-12).order, 4.0, 0.3);
  EXPECT_NEAR(fit_order(hs, kernel, 1e-12).order, 2.0, 0.3);
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

// max over t <= t_end of |E_n - E_0 - (the integral of (4.3) along the run, by the trapezoidal rule)| along the
// simplified method: O(h^6) when every coefficient of (4.2) is right.
template <class Sys, int D>
double modified_energy_residual(const Sys& sys, const PhaseState<D>& z0, double h, double t_end) {
  const double E0 = simplified_ti_modified_energy(sys, z0, h);
  double worst = 0, integral = 0, last_rate = simplified_ti_drift_rate(sys, z0, h);
  integrate(simplified_ti_method(sys, false), z0, h, std::lround(t_end / h), [&](auto j, const PhaseState<D>& z) {
    if (j == 0) return;
    const double rate = simplified_ti_drift_rate(sys, z, h);
    integral += h * (rate + last_rate) / 2, last_rate = rate;
    worst = std::max(worst, std::abs(simplified_ti_modified_energy(sys, z, h) - E0 - integral));
  });
  return worst;
}

TEST(ModifiedEnergy, SixthOrderAfterTheDriftOnHenonHeiles5) {
  // k = 5, where U and U^(5) do not vanish: (4.2) with its h^4 U(p^4) term and the drift (4.3) leave O(h^6).
  const HenonHeiles hh5{{}, 5};
  const auto z0 = make_state<2>(Vec<2>(0.0, 0.1), Vec<2>(0.3, 0.2));
  std::vector<double> hs, rs;
  for (double h : {0.2, 0.1, 0.05}) hs.push_back(h), rs.push_back(modified_energy_residual(hh5, z0, h, 20.0));
  EXPECT_NEAR(fit_order(hs, rs, 1e-14).order, 6.0, 0.4) << rs[0] << " " << rs[1] << " " << rs[2];
}

TEST(ModifiedEnergy, SixthOrderAfterTheDriftOnTheLennardJonesCluster) {
  // 004 Fig. 6: the 3 x 3 cluster, slightly perturbed from the grid, with small velocities.
  const LennardJones<9> lj;
  PhaseState<18> z0;
  for (int i = 0; i < 9; ++i) {
    z0.q[2 * i] = 1.12 * (i % 3) + 0.02 * std::sin(1.0 + i), z0.q[2 * i + 1] = 1.12 * (i / 3) + 0.02 * std::cos(2.0 + i);
    z0.p[2 * i] = 0.2 * std::sin(0.3 * i), z0.p[2 * i + 1] = 0.2 * std::cos(0.7 * i);
  }
  std::vector<double> hs, rs;
  for (double h : {0.02, 0.01, 0.005}) hs.push_back(h), rs.push_back(modified_energy_residual(lj, z0, h, 2.0));
  EXPECT_NEAR(fit_order(hs, rs, 1e-14).order, 6.0, 0.4);
}

TEST(ModifiedEnergy, ShiftedEnergyIsConservedToFourthOrderAlongTakahashiImada) {
  // 004 (3.3): H + h^2 H_3 is the modified Hamiltonian of TI (unprocessed) up to O(h^4), on the pendulum of Fig. 2
  // and on Henon-Heiles.
  const auto order = [](const auto& sys, const auto& z0) {
    std::vector<double> hs, es;
    for (double h : {0.2, 0.1, 0.05}) {
      double worst = 0;
      const double E0 = shifted_energy(sys, z0, h);
      integrate(takahashi_imada_method(sys, false), z0, h, std::lround(20 / h), [&](auto, const auto& z) {
        worst = std::max(worst, std::abs(shifted_energy(sys, z, h) - E0));
      });
      hs.push_back(h), es.push_back(worst);
    }
    return fit_order(hs, es, 1e-14).order;
  };
  EXPECT_NEAR(order(UnsymmetricPendulum{}, make_state(0.0, 2.0)), 4.0, 0.3);
  EXPECT_NEAR(order(HenonHeiles{}, make_state<2>(Vec<2>(0.1, 0.2), Vec<2>(0.35, 0.3))), 4.0, 0.3);
}

TEST(HenonHeiles, ThirdDerivativeAgainstFiniteDifferences) {
  // U'''(a, b, .) against the central difference of U''(q) b along a, for k = 3 and 5, with and without coupling.
  const Vec<2> q(0.15, -0.25), a(0.4, -0.7), b(-0.3, 0.5);
  const double d = 1e-5;
  const auto check = [&](const auto& hh) {
    const Vec<2> fd = (hh.U_qq_times((q + d * a).eval(), b) - hh.U_qq_times((q - d * a).eval(), b)) / (2 * d);
    EXPECT_LT((hh.U3_times(q, a, b) - fd).norm(), 1e-9) << hh.k;
    EXPECT_LT((hh.U3_times(q, a, b) - hh.U3_times(q, b, a)).norm(), 1e-15);  // symmetric in a, b
  };
  check(HenonHeiles{{}, 3});
  check(HenonHeiles{{}, 5});
  check(HenonHeilesT<true>{{}, 5, 0.7});
  check(HenonHeilesT<false>{{}, 5, 0.0});
}

TEST(UnsymmetricPendulum, LargestPotential) {
  // max U of U = -cos q + 0.2 sin 2q (004 (5.1)): the closed form against a fine grid over one period.
  const UnsymmetricPendulum up;
  double grid = -1e9;
  for (int i = 0; i < 200000; ++i) grid = std::max(grid, up.U(Vec<1>(2 * std::numbers::pi * i / 200000.0)));
  EXPECT_NEAR(UnsymmetricPendulum::U_max(), grid, 1e-9);
  EXPECT_GE(UnsymmetricPendulum::U_max(), grid);
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

TEST(LennardJones, HessianIsTheColumnsOfTheHessianVectorProductBitForBit) {
  // U_qq visits each pair once; its columns must be U_qq_times(q, e_k) to the bit, also on the exact
  // grid (aligned particles: exact zeros in d and signed zeros in the terms) and for a distant pair.
  const LennardJones<9> lj;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    Vec<18> q;
    for (int i = 0; i < 9; ++i)
      q[2 * i] = 1 + i % 3 + (trial == 0 ? 0.0 : u(rng)), q[2 * i + 1] = 1 + i / 3 + (trial == 0 ? 0.0 : u(rng));
    if (trial == 1) q.segment<2>(16) << 40.0, -25.0;
    const Mat<18> J = lj.U_qq(q);
    for (int k = 0; k < 18; ++k) {
      const Vec<18> column = lj.U_qq_times(q, Vec<18>::Unit(k));
      EXPECT_EQ(std::memcmp(J.col(k).data(), column.data(), sizeof(double) * 18), 0)  // the same bits (-0.0 too)
          << "trial " << trial << ", column " << k;
    }
  }
}

TEST(HenonHeiles, IntPowIsTheProductFromXInOrderBitForBit) {
  // int_pow's cases without a loop round as the product ((x x) x)... does (the lanes' vectors take the same code)
  for (const double x : {0.7, -1.3, 1.0 / 3.0, 2.0 / 7.0, -0.9999999}) {
    double r = 1.0;
    for (int n = 0; n <= 8; ++n) {
      EXPECT_EQ(int_pow(x, n), r) << x << "^" << n;
      r = n == 0 ? x : r * x;
    }
  }
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

TEST(EnsembleStatistics, MeanDeviationAndStandardErrors) {
  const std::vector<double> v{2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0};  // mean 5, sum of squares 32
  const auto [mean, sd] = mean_and_deviation(v);
  EXPECT_DOUBLE_EQ(mean, 5.0);
  EXPECT_DOUBLE_EQ(sd, std::sqrt(32.0 / 7.0));  // denominator M - 1
  EXPECT_DOUBLE_EQ(standard_error_of_mean(3.0, 9.0), 1.0);
  EXPECT_DOUBLE_EQ(standard_error_of_deviation(4.0, 9.0), 1.0);
  EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
}

TEST(EnsembleStatistics, PowerLawExponentSlopeAndOscillationAboutALine) {
  std::vector<double> t, s, y;
  for (int i = 1; i <= 100; ++i) {
    t.push_back(i);
    s.push_back(i < 10 ? 1e-9 : 3 * std::sqrt(i));      // sigma ~ t^(1/2) from t = 10 on
    // a line plus +-0.25 in the pattern + - - + (i = 1, 2, 3, 4, ...), orthogonal to 1 and t: peak-to-peak 0.5
    y.push_back(2 * i + (i % 4 == 1 || i % 4 == 0 ? 0.25 : -0.25));
  }
  EXPECT_NEAR(power_law_exponent(t, s, 10), 0.5, 1e-12);
  EXPECT_GT(power_law_exponent(t, s, 1), 1.0);  // the points before t = 10 would steepen it
  EXPECT_NEAR(slope_from(t, y, 50), 2.0, 1e-3);
  EXPECT_NEAR(peak_to_peak_about_line(t, y), 0.5, 1e-12);
}

TEST(EnsembleStatistics, BootstrapStandardErrorOfTheRandomWalkExponent) {
  // 200 random walks of unit Gaussian steps, sampled at t = 1..400: sigma ~ t^(1/2). The fitted exponent over
  // t >= 40 lies within a few of its bootstrap standard errors of 1/2; that standard error is of the size the
  // ensemble's finite sample leaves (neither 0 nor of order 1), and the same seed gives the same bits.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> step(0.0, 1.0);
  std::vector<std::vector<double>> walks(200);
  std::vector<double> t;
  for (int k = 1; k <= 400; ++k) t.push_back(k);
  for (auto& w : walks) {
    double x = 0;
    for (int k = 1; k <= 400; ++k) w.push_back(x += step(rng));
  }
  std::vector<double> sd;
  for (std::size_t k = 0; k < t.size(); ++k) {
    std::vector<double> column;
    for (const auto& w : walks) column.push_back(w[k]);
    sd.push_back(mean_and_deviation(column).sd);
  }
  const double gamma = power_law_exponent(t, sd, 40);
  const double se = bootstrap_exponent_stderr(walks, t, 40, kBootstrapResamples, 11);
  EXPECT_GT(se, 0.005);
  EXPECT_LT(se, 0.1);
  EXPECT_LT(std::abs(gamma - 0.5), 3 * se);
  EXPECT_EQ(se, bootstrap_exponent_stderr(walks, t, 40, kBootstrapResamples, 11));
}

TEST(EnsembleStatistics, OscillationAboutAQuadratic) {
  // A drift with curvature, 7 - 0.3 t + 2e-3 t^2 over t in [1e5, 2e5]: the least-squares quadratic recovers
  // it (no oscillation left), while about a line the curvature alone reads as 2e-3 (5e4)^2 = 5e6.
  std::vector<double> t, y;
  for (int i = 0; i <= 200; ++i) t.push_back(1e5 + 500.0 * i), y.push_back(7 - 0.3 * t.back() + 2e-3 * t.back() * t.back());
  const QuadraticFit f = quadratic_fit(t, y);
  EXPECT_NEAR(f(1.3e5), y[60], 1e-9 * std::abs(y[60]));
  EXPECT_LT(peak_to_peak_about_quadratic(t, y), 1e-9 * std::abs(y.back()));
  EXPECT_NEAR(peak_to_peak_about_line(t, y), 5e6, 5e6 * 1e-6);
  // plus a +-0.25 square wave: 0.5 about the quadratic (to the square wave's small projection on it)
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += i % 2 ? 0.25 : -0.25;
  EXPECT_NEAR(peak_to_peak_about_quadratic(t, y), 0.5, 0.01);
}

TEST(Stiffness, LargestEigenvalueOfTheHessian) {
  // omega_max^2: w^2 for the oscillator; at the origin of Henon-Heiles the Hessian is the identity,
  // at q = (0, q2) (k = 3) its eigenvalues are 1 + 2 q2 and 1 - 2 q2.
  EXPECT_DOUBLE_EQ(max_hessian_eigenvalue(HarmonicOscillator{1.0, 1.7}, Vec<1>(0.3)), 1.7 * 1.7);
  EXPECT_NEAR(max_hessian_eigenvalue(HenonHeiles{}, Vec<2>(0.0, 0.0)), 1.0, 1e-15);
  EXPECT_NEAR(max_hessian_eigenvalue(HenonHeiles{}, Vec<2>(0.0, -0.2)), 1.4, 1e-14);
}

}  // namespace takahashi_imada_test
