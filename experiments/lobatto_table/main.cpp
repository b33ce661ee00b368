// lobatto_table: 001 (Dubois & Rojas-Quintero 2025) Table 1, Figs 1, 2 -- the
// Lobatto variational integrator built from its definition (P3 elements,
// quadrature (2), elimination of the internal values, momenta (11)), against
// Simpson's variational integrator and the implicit midpoint rule; its
// stability set; its extension to nonlinear Lagrangians (Newton); and what
// the accuracy costs.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <boost/numeric/odeint.hpp>

#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/integrators/integrate.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/observables/drift.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;
namespace odeint = boost::numeric::odeint;

namespace {

using Z1 = PhaseState<1>;
const double kLobattoBound = lobatto_info.oscillatory_bound;  // 001 eq. (10)

// The one-step map of a linear method, in the paper's ordering (p, q) (001 eq. (13)).
template <class Step>
Mat<2> one_step_matrix(const Step& step) {
  Mat<2> Phi;
  const Z1 ep = step(make_state(0.0, 1.0)), eq = step(make_state(1.0, 0.0));  // columns: p = 1, then q = 1
  Phi << ep.p[0], eq.p[0], ep.q[0], eq.q[0];
  return Phi;
}

// 001 eq. (15) from the computed map: H_d = (Phi_qp p^2 - Phi_pq q^2) / 2, i.e. c/(2 delta) p^2 - b/(2 delta) q^2.
double discrete_energy(const Mat<2>& Phi, const Z1& z) {
  return 0.5 * (Phi(1, 0) * z.p[0] * z.p[0] - Phi(0, 1) * z.q[0] * z.q[0]);
}

double spectral_radius(const Mat<2>& Phi) {
  return Eigen::EigenSolver<Mat<2>>(Phi).eigenvalues().cwiseAbs().maxCoeff();
}

Schema schema() {
  Schema s;
  s.real("oscillator.m", positive(), "mass m (001: 1)")
      .real("oscillator.omega", positive(), "angular frequency (001: 2 pi, period T = 1)")
      .real("oscillator.amplitude", positive(), "q(0); p(0) = 0 (001: pi/2)")
      .reals("meshes", at_least(1), 3, "steps per period N of Table 1 (001: 10, 20, 40)")
      .reals("figure1.meshes", at_least(1), 1, "steps per period of Fig. 1 (001: 3, 10)")
      .real("long_run.periods", at_least(1), "periods of Fig. 2 (001: 1e5)")
      .reals("long_run.h", positive(), 1, "steps of Fig. 2 (001: 0.1, 0.05, 0.025)")
      .integer("long_run.windows", at_least(2), "windows for the maxima of the energy error")
      .real("stability.hw_min", positive(), "scan of the spectral radius over h omega")
      .real("stability.hw_max", positive(), "")
      .integer("stability.points", at_least(2), "")
      .reals("nonlinear.h", positive(), 3, "steps of the nonlinear convergence study")
      .real("nonlinear.t_end", positive(), "end time of the nonlinear runs")
      .real("nonlinear.pendulum_q0", any_finite(), "initial angle of L = qdot^2/2 + cos q (p(0) = 0)")
      .real_rows("nonlinear.elastic_initial", 4, any_finite(), 1, "elastic pendulum [x, y, px, py] (l=m=k=1, g=0.2)")
      .real("reference.rtol", positive(), "tolerances of the odeint Bulirsch-Stoer reference")
      .real("reference.atol", positive(), "")
      .integer("timing.repeats", at_least(1), "timed repetitions (median)");
  return s;
}

void validate(const Scene& s) {
  const double w = s.real("oscillator.omega");
  for (const char* key : {"meshes", "figure1.meshes"})
    for (double n : s.reals(key)) {
      if (n != std::floor(n)) s.reject(key, "every entry must be a whole number of steps per period");
      if (!(2 * std::numbers::pi / n < kLobattoBound))
        s.reject(key, "the Lobatto scheme is unstable for h omega >= sqrt(42 - 6 sqrt(29)) = " + format_double(kLobattoBound) +
                          " (001 eq. (10)): N must exceed " + format_double(2 * std::numbers::pi / kLobattoBound));
    }
  for (double h : s.reals("long_run.h"))
    if (!(h * w < kLobattoBound)) s.reject("long_run.h", "h omega must be below " + format_double(kLobattoBound) + " (001 eq. (10))");
  if (!(s.real("stability.hw_max") > s.real("stability.hw_min"))) s.reject("stability.hw_max", "must exceed stability.hw_min");
}

struct Table1Row {
  double p = 0, q = 0, H = 0, Hd = 0, simpson_q = 0, midpoint_q = 0;
};

void run(Context& ctx) {
  const Scene& s = ctx.scene;
  const HarmonicOscillator osc{s.real("oscillator.m"), s.real("oscillator.omega")};
  const double A = s.real("oscillator.amplitude"), T = 2 * std::numbers::pi / osc.w;
  const auto lob = lobatto_rule();
  const auto simp = simpson_rule();
  const Z1 z0 = make_state(A, 0.0);
  json published = {{"p_err_N10", 8.95e-6},  {"p_err_N20", 1.39e-7},  {"p_err_N40", 2.17e-9},
                    {"q_err_N10", 7.64e-7},  {"q_err_N20", 1.19e-8},  {"q_err_N40", 1.88e-10},
                    {"H_err_N10", 6.62e-5},  {"H_err_N20", 1.10e-6},  {"H_err_N40", 1.70e-8},
                    {"Hd_err_N10", 2.66e-15}, {"Hd_err_N20", 1.33e-15}, {"Hd_err_N40", 2.22e-15},
                    {"stability_bound", kLobattoBound}};  // Table 1; eq. (10)
  json reproduced, orders, timing;

  // ---- Table 1: one period from q = A, p = 0, max over the steps of |error| (absolute) ----
  ctx.progress("Table 1");
  const auto meshes = s.reals("meshes");
  Csv t1({"N", "h", "p_err", "q_err", "H_err", "Hd_err", "simpson_q_err", "midpoint_q_err"});
  std::vector<double> hs, ep, eq, eH, es, em;
  for (double Nd : meshes) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    const Mat<2> Phi = one_step_matrix([&](const Z1& z) { return galerkin_step(lob, osc, z, h); });
    Table1Row r;
    Z1 zl = z0, zs = z0, zm = z0;
    const double H0 = osc.H(z0), Hd0 = discrete_energy(Phi, z0);
    for (std::int64_t j = 1; j <= N; ++j) {
      zl = galerkin_step(lob, osc, zl, h), zs = galerkin_step(simp, osc, zs, h), zm = implicit_midpoint(osc, zm, h);
      const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
      r.p = std::max(r.p, std::abs(zl.p[0] - ex.p[0])), r.q = std::max(r.q, std::abs(zl.q[0] - ex.q[0]));
      r.H = std::max(r.H, std::abs(osc.H(zl) - H0)), r.Hd = std::max(r.Hd, std::abs(discrete_energy(Phi, zl) - Hd0));
      r.simpson_q = std::max(r.simpson_q, std::abs(zs.q[0] - ex.q[0]));
      r.midpoint_q = std::max(r.midpoint_q, std::abs(zm.q[0] - ex.q[0]));
    }
    t1.row(N, h, r.p, r.q, r.H, r.Hd, r.simpson_q, r.midpoint_q);
    const std::string n = std::to_string(N);
    reproduced["p_err_N" + n] = r.p, reproduced["q_err_N" + n] = r.q;
    reproduced["H_err_N" + n] = r.H, reproduced["Hd_err_N" + n] = r.Hd;
    hs.push_back(h), ep.push_back(r.p), eq.push_back(r.q), eH.push_back(r.H), es.push_back(r.simpson_q),
        em.push_back(r.midpoint_q);
  }
  ctx.write("table1.csv", t1);
  const double floor = 1e3 * std::numeric_limits<double>::epsilon();
  orders["lobatto_p"] = fit_order(hs, ep, floor, "lobatto_p").order;
  orders["lobatto_q"] = fit_order(hs, eq, floor, "lobatto_q").order;
  orders["lobatto_H"] = fit_order(hs, eH, floor, "lobatto_H").order;
  orders["simpson"] = fit_order(hs, es, floor, "simpson").order;
  orders["midpoint"] = fit_order(hs, em, floor, "midpoint").order;

  // ---- Fig. 1: trajectories over one period ----
  for (double Nd : s.reals("figure1.meshes")) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    Csv f({"j", "t", "q_lobatto", "p_lobatto", "q_simpson", "p_simpson", "q_midpoint", "p_midpoint"});
    Z1 zl = z0, zs = z0, zm = z0;
    for (std::int64_t j = 0; j <= N; ++j) {
      if (j > 0) zl = galerkin_step(lob, osc, zl, h), zs = galerkin_step(simp, osc, zs, h), zm = implicit_midpoint(osc, zm, h);
      f.row(j, static_cast<double>(j) * h, zl.q[0], zl.p[0], zs.q[0], zs.p[0], zm.q[0], zm.p[0]);
    }
    ctx.write("fig1_N" + std::to_string(N) + ".csv", f);
  }
  Csv fe({"t", "q", "p"});
  for (int i = 0; i <= 400; ++i) {
    const Z1 e = osc.exact(z0, T * i / 400.0);
    fe.row(T * i / 400.0, e.q[0], e.p[0]);
  }
  ctx.write("fig1_exact.csv", fe);

  // ---- Fig. 2: the discrete energy over long_run.periods periods, plain and compensated ----
  ctx.progress("Fig. 2: long runs");
  const auto long_h = s.reals("long_run.h");
  const std::int64_t windows = s.integer("long_run.windows");
  struct Long {
    std::vector<double> plain, comp, H;    // window maxima
    double slope_plain, slope_comp, slope_H;  // per period
  };
  const auto longs = parallel_map(long_h.size(), [&](std::size_t i) {
    const double h = long_h[i];
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / h);
    const Mat<2> Phi = one_step_matrix([&](const Z1& z) { return galerkin_step(lob, osc, z, h); });
    const Mat<2> PhiI = Phi - Mat<2>::Identity();
    const double Hd0 = discrete_energy(Phi, z0), H0 = osc.H(z0);
    WindowMaxima wp(std::max<std::int64_t>(1, n / windows)), wc(std::max<std::int64_t>(1, n / windows)),
        wH(std::max<std::int64_t>(1, n / windows));
    Vec<2> x(z0.p[0], z0.q[0]), y = x, c = Vec<2>::Zero();
    for (std::int64_t j = 1; j <= n; ++j) {
      x = Phi * x;                                        // (13)
      compensated_add(y, c, Vec<2>(PhiI * y));            // (13) as y + (Phi - I) y, compensated
      wp.add(discrete_energy(Phi, make_state(x[1], x[0])) - Hd0);
      wc.add(discrete_energy(Phi, make_state(y[1], y[0])) - Hd0);
      wH.add(osc.H(make_state(x[1], x[0])) - H0);
    }
    const double per_window = static_cast<double>(std::max<std::int64_t>(1, n / windows)) * h / T;
    return Long{wp.maxima(), wc.maxima(), wH.maxima(), wp.slope_per_window() / per_window,
                wc.slope_per_window() / per_window, wH.slope_per_window() / per_window};
  });
  Csv f2({"h", "period", "Hd_err_plain", "Hd_err_compensated", "H_err"});
  json growth, growth_comp, growth_H;
  for (std::size_t i = 0; i < long_h.size(); ++i) {
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / long_h[i]);
    const double per_window = static_cast<double>(std::max<std::int64_t>(1, n / windows)) * long_h[i] / T;
    for (std::size_t k = 0; k < longs[i].plain.size(); ++k)
      f2.row(long_h[i], static_cast<double>(k + 1) * per_window, longs[i].plain[k], longs[i].comp[k], longs[i].H[k]);
    growth[format_double(long_h[i])] = longs[i].slope_plain;
    growth_comp[format_double(long_h[i])] = longs[i].slope_comp;
    growth_H[format_double(long_h[i])] = longs[i].slope_H;
  }
  ctx.write("fig2_energy.csv", f2);
  // Growth rates: least-squares slope, per period, of the window maxima of |H - H(0)| (Fig. 2's
  // quantity: it reproduces the published 2.50e-11 at h = 0.1), and of |H_d - H_d(0)| with plain
  // and with compensated summation (the round-off of the discrete energy (15)).
  reproduced["energy_growth_rate"] = growth_H;
  reproduced["energy_growth_rate_Hd"] = growth;
  reproduced["energy_growth_rate_Hd_compensated"] = growth_comp;
  published["energy_growth_rate"] = {{"0.10000000000000001", 2.50e-11}, {"0.050000000000000003", 5.45e-14},
                                     {"0.025000000000000001", 1.35e-13}};  // Fig. 2 caption

  // ---- Stability: spectral radius of Phi over h omega; the exact stable set ----
  ctx.progress("stability scan");
  const double hw0 = s.real("stability.hw_min"), hw1 = s.real("stability.hw_max");
  const auto npts = s.integer("stability.points");
  const auto radius_at = [&](const GalerkinRule<3>& R, double hw) {
    const double h = hw / osc.w;
    return spectral_radius(one_step_matrix([&](const Z1& z) { return galerkin_step(R, osc, z, h); }));
  };
  Csv st({"h_omega", "spectral_radius", "spectral_radius_simpson"});
  json stable_set = json::array();
  bool in_stable = false;
  double start = 0, prev = hw0;
  const auto stable = [](double rho) { return rho <= 1.0 + 1e-12; };
  for (std::int64_t i = 0; i < npts; ++i) {
    const double hw = hw0 + (hw1 - hw0) * static_cast<double>(i) / static_cast<double>(npts - 1);
    const double rho = radius_at(lob, hw);
    const double rho_s = spectral_radius(one_step_matrix([&](const Z1& z) { return galerkin_step(simp, osc, z, hw / osc.w); }));
    st.row(hw, rho, rho_s);
    if (stable(rho) && !in_stable) in_stable = true, start = hw;
    if (!stable(rho) && in_stable) in_stable = false, stable_set.push_back({start, prev});
    prev = hw;
  }
  if (in_stable) stable_set.push_back({start, prev});
  ctx.write("stability.csv", st);
  // The first loss of stability, refined by bisection.
  double lo = hw0, hi = hw1;
  for (std::int64_t i = 0; i < npts; ++i) {
    const double hw = hw0 + (hw1 - hw0) * static_cast<double>(i) / static_cast<double>(npts - 1);
    if (!stable(radius_at(lob, hw))) { hi = hw; break; }
    lo = hw;
  }
  for (int it = 0; it < 60; ++it) (stable(radius_at(lob, 0.5 * (lo + hi))) ? lo : hi) = 0.5 * (lo + hi);
  reproduced["stability_bound"] = lo;
  reproduced["stable_set_h_omega"] = stable_set;
  // 10^5-period runs at 0.99 and 1.01 times the bound: bounded, and reported as diverged.
  json runs;
  for (double factor : {0.99, 1.01}) {
    const double h = factor * lo / osc.w;
    const Mat<2> Phi = one_step_matrix([&](const Z1& z) { return galerkin_step(lob, osc, z, h); });
    Vec<2> x(0.0, A);
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / h);
    std::int64_t diverged_at = -1;
    double max_norm = 0;
    for (std::int64_t j = 1; j <= n && diverged_at < 0; ++j) {
      x = Phi * x;
      max_norm = std::max(max_norm, x.norm());
      if (!(x.norm() <= 1e6 * A)) diverged_at = j;
    }
    runs[format_double(factor)] = {{"h_omega", factor * lo}, {"steps", n}, {"diverged_at_step", diverged_at},
                                   {"max_norm_over_initial", max_norm / A}};
  }
  reproduced["bound_runs"] = runs;

  // ---- Nonlinear Lagrangians: order 6 against odeint, symplecticity, Newton iterations ----
  ctx.progress("nonlinear");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  const NonlinearPendulum pend;
  const ElasticPendulumWithGravity elastic{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.2}}};
  const Z1 pz0 = make_state(s.real("nonlinear.pendulum_q0"), 0.0);
  const auto er = s.real_rows("nonlinear.elastic_initial")[0];
  const PhaseState<2> ez0 = make_state<2>(Vec<2>(er[0], er[1]), Vec<2>(er[2], er[3]));
  const Z1 pref = reference_solution(pend, pz0, t_end, rtol, atol);
  const PhaseState<2> eref = reference_solution(elastic, ez0, t_end, rtol, atol);
  Csv nl({"h", "pendulum_err", "pendulum_newton_iterations", "elastic_err", "elastic_newton_iterations",
          "simpson_pendulum_err", "midpoint_pendulum_err"});
  std::vector<double> e_p, e_e, e_sp, e_mp;
  const auto rows = parallel_map(nh.size(), [&](std::size_t i) {
    const double h = nh[i];
    const std::int64_t n = steps_to(t_end, h);
    int it = 0;
    double it_p = 0, it_e = 0;
    Z1 zp = pz0, zs = pz0, zm = pz0;
    PhaseState<2> ze = ez0;
    for (std::int64_t j = 0; j < n; ++j) {
      zp = galerkin_step(lob, pend, zp, h, &it), it_p += it;
      ze = galerkin_step(lob, elastic, ze, h, &it), it_e += it;
      zs = galerkin_step(simp, pend, zs, h), zm = implicit_midpoint(pend, zm, h);
    }
    return std::array<double, 6>{phase_distance(zp, pref), it_p / static_cast<double>(n), phase_distance(ze, eref),
                                 it_e / static_cast<double>(n), phase_distance(zs, pref), phase_distance(zm, pref)};
  });
  for (std::size_t i = 0; i < nh.size(); ++i) {
    const auto& r = rows[i];
    nl.row(nh[i], r[0], r[1], r[2], r[3], r[4], r[5]);
    e_p.push_back(r[0]), e_e.push_back(r[2]), e_sp.push_back(r[4]), e_mp.push_back(r[5]);
  }
  ctx.write("nonlinear.csv", nl);
  const double nfloor = 100 * atol;  // errors within 100x the reference tolerance are not fitted
  orders["lobatto_nonlinear_pendulum"] = fit_order(nh, e_p, nfloor, "lobatto_nonlinear_pendulum").order;
  orders["lobatto_elastic_pendulum"] = fit_order(nh, e_e, nfloor, "lobatto_elastic_pendulum").order;
  orders["simpson_nonlinear_pendulum"] = fit_order(nh, e_sp, nfloor, "simpson_nonlinear_pendulum").order;
  orders["midpoint_nonlinear_pendulum"] = fit_order(nh, e_mp, nfloor, "midpoint_nonlinear_pendulum").order;
  // Symplecticity of the nonlinear one-step maps: max |J^T Omega J - Omega|.
  reproduced["symplecticity_defect_pendulum"] = symplecticity_defect(galerkin_step_jacobian(lob, pend, pz0, nh.front()));
  reproduced["symplecticity_defect_elastic"] = symplecticity_defect(galerkin_step_jacobian(lob, elastic, ez0, nh.front()));

  // ---- What the accuracy costs (nonlinear pendulum to t_end) ----
  ctx.progress("cost");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const std::vector<std::string> methods = {"lobatto", "simpson", "midpoint", "odeint_rk4", "odeint_rkf78"};
  const auto run_method = [&](const std::string& m, const auto& sys, double h) -> Z1 {
    const std::int64_t n = steps_to(t_end, h);
    if (m == "lobatto") return integrate_n_steps([&](const Z1& z) { return galerkin_step(lob, sys, z, h); }, pz0, n);
    if (m == "simpson") return integrate_n_steps([&](const Z1& z) { return galerkin_step(simp, sys, z, h); }, pz0, n);
    if (m == "midpoint") return integrate_n_steps([&](const Z1& z) { return implicit_midpoint(sys, z, h); }, pz0, n);
    auto x = to_odeint<1>(pz0);
    const auto rhs = odeint_rhs(sys);
    if (m == "odeint_rk4") {
      odeint::runge_kutta4<OdeintState<1>> st4;
      for (std::int64_t j = 0; j < n; ++j) st4.do_step(rhs, x, static_cast<double>(j) * h, h);
    } else {
      odeint::runge_kutta_fehlberg78<OdeintState<1>> st78;
      for (std::int64_t j = 0; j < n; ++j) st78.do_step(rhs, x, static_cast<double>(j) * h, h);
    }
    return from_odeint<1>(x);
  };
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "error"});
  json ns;
  for (const auto& m : methods) {
    for (double h : nh) {
      std::int64_t evals = 0;
      const double err = phase_distance(run_method(m, Counting<NonlinearPendulum>{pend, &evals}, h), pref);
      const double wall = median_seconds(repeats, [&] { do_not_optimize(run_method(m, pend, h)); });
      const std::int64_t n = steps_to(t_end, h);
      cost.row(m, h, n, wall, 1e9 * wall / static_cast<double>(n), evals, err);
      if (h == nh.back()) ns[m] = 1e9 * wall / static_cast<double>(n);
    }
  }
  ctx.write("timing.csv", cost);
  timing["ns_per_step"] = ns;
  timing["method"] = "nonlinear pendulum to nonlinear.t_end; median of timing.repeats runs after one warm-up, single "
                     "thread; ns_per_step at the smallest nonlinear.h; force evaluations count U_q and U_qq calls";

  ctx.summary["published"] = published;
  ctx.summary["reproduced"] = reproduced;
  ctx.summary["orders"] = orders;
  ctx.summary["norms"] = {{"table1", "max over the steps j = 1..N of one period of the absolute error (p, q, H, H_d)"},
                          {"nonlinear", "|z_N - z(t_end)|_2 against the odeint Bulirsch-Stoer reference"}};
  ctx.summary["timing"] = timing;
}

}  // namespace

int main(int argc, char** argv) {
  const ExperimentSpec spec{"lobatto_table",
                            "001 Table 1, Figs 1, 2: the Lobatto variational integrator from its definition, "
                            "its stability set, nonlinear Lagrangians, and what the accuracy costs",
                            schema(), validate, run};
  return run_experiment(argc, argv, spec, GEOMINT_EXPERIMENT_DIR);
}
