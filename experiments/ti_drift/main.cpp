// ti_drift: 004 (On energy conservation of the simplified Takahashi-Imada
// method) Figs 1-6 -- the methods the scene names (Stormer-Verlet,
// Takahashi-Imada (1.4), the simplified method (1.6), Forest-Ruth) on the
// harmonic oscillator at equal work (Fig. 1), the drift of the shifted energy
// on the unsymmetric pendulum (Fig. 2), the modified energy E of (3.3) and
// (4.2) on Henon-Heiles k = 3 (Fig. 3) and its random walk over an ensemble
// for k = 5 (Fig. 4), Poincare cuts of one trajectory (Fig. 5), the
// Lennard-Jones cluster (Fig. 6: a step-size scan and the ensemble
// statistics), symplecticity against volume preservation, and the cost per step.
// One study per figure (or analysis); the scene's sections say which run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/observables/modified_energy.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"
#include "geomint/systems/unsymmetric_pendulum.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

using Z1 = PhaseState<1>;
using Z2 = PhaseState<2>;

constexpr double kFitMaxOmegaH = 0.5;  // Fig. 1: the orders are fitted over omega h_eff <= 0.5

double slope(const std::vector<double>& x, const std::vector<double>& y) { return linear_fit(x, y).slope; }

// Adds the entries of `values` to summary[section] (indexing the summary afresh for each).
void put(Context& ctx, const char* section, const json& values) {
  for (const auto& [k, v] : values.items()) ctx.summary[section][k] = v;
}


// Henon-Heiles start with q1 = 0 and p1 > 0 from H0 (004 Sect. 5).
template <class HH>
Z2 hh_start(const HH& hh, double q2, double p2, double H0) {
  const double p1 = std::sqrt(2 * (H0 - hh.U(Vec<2>(0.0, q2))) - p2 * p2);
  return make_state<2>(Vec<2>(0.0, q2), Vec<2>(p1, p2));
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The Henon-Heiles start (q1 = 0, q2, p2) with p1 > 0 from hh.H0 exists (section: hh3 or symplecticity).
template <class HH>
void check_hh_start(const Scene& s, const std::string& section, const HH& hh) {
  const double H0 = s.real("hh.H0"), q2 = s.real(section + ".q2"), p2 = s.real(section + ".p2");
  if (!(2 * (H0 - hh.U(Vec<2>(0.0, q2))) - p2 * p2 > 0))
    s.reject(section + ".p2", "the start q1 = 0, q2 = " + short_num(q2) + ", p2 = " + short_num(p2) + " (k = " +
                                  std::to_string(hh.k) + ") needs U(0, q2) + p2^2/2 < hh.H0 = " + short_num(H0));
}

// Calls f with the Henon-Heiles system of Figs 4-5: exponent hh.k, coupling hh.coupling (compiled out if 0).
template <class F>
decltype(auto) with_ensemble_system(const Scene& s, F&& f) {
  return with_henon_heiles(static_cast<int>(s.integer("hh.k")), s.real("hh.coupling"), f);
}

// Start i of the Fig. 4 ensemble: (hh3.q2, hh3.p2) perturbed, each trajectory its own stream seeded by (seed, i).
template <class HH>
Z2 ensemble_start(const Scene& s, const HH& hhk, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("ensemble.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("ensemble.perturbation"), s.real("ensemble.perturbation"));
  const double dq = u(rng), dp = u(rng);
  return hh_start(hhk, s.real("hh3.q2") + dq, s.real("hh3.p2") + dp, s.real("hh.H0"));
}

// ---- Fig. 1: harmonic oscillator, omega = 1, start q = 0, p = 1, at equal work ----

const HarmonicOscillator kOscillator{1.0, 1.0};

// Force evaluations in one step of a method's kernel (a gradient, a force or a
// Hessian-vector product counts one: systems/counting.hpp).
std::int64_t evals_per_step(const std::string& method) {
  std::int64_t n = 0;
  const Counting<HarmonicOscillator> counted{kOscillator, &n};
  with_kernel(method, counted, [&](const auto& m) {
    const auto s = m.pre(make_state(1.0, 0.0), 0.1);
    n = 0;
    do_not_optimize(m.kernel(s, 0.1));
    return 0;
  });
  if (n < 1) throw std::logic_error(method + " evaluates no force in a step");
  return n;
}

// Equal work: per unit time a method of e evaluations per step at h = h_eff e / 2
// does as many evaluations as Takahashi-Imada (2 per step) at h = h_eff.
double step_at_equal_work(double h_eff, std::int64_t evals) { return h_eff * static_cast<double>(evals) / 2; }

void check_oscillator(const Scene& s) {
  check_methods(s, "oscillator.methods", Counting<HarmonicOscillator>{kOscillator, nullptr});
  const auto omega_h = s.reals("oscillator.omega_h");
  std::vector<int> runs(omega_h.size(), 0);
  for (const auto& m : s.texts("oscillator.methods")) {
    const std::int64_t evals = evals_per_step(m);
    const double bound = method_info(m).oscillatory_bound;
    if (bound == 0.0) s.reject("oscillator.methods", m + " is unstable on the oscillator for every h > 0");
    int fit_points = 0;
    for (std::size_t i = 0; i < omega_h.size(); ++i) {
      if (beyond_bound(kOscillator.w * step_at_equal_work(omega_h[i], evals), bound)) continue;
      ++runs[i];
      fit_points += omega_h[i] <= kFitMaxOmegaH;
    }
    if (fit_points < 3)
      s.reject("oscillator.omega_h", "at least 3 values <= " + format_double(kFitMaxOmegaH) + " within the bound of " +
                                         m + " (its orders are fitted there)");
  }
  for (std::size_t i = 0; i < omega_h.size(); ++i)
    if (runs[i] == 0)
      s.reject("oscillator.omega_h", format_double(omega_h[i]) + " is beyond the stability bound of every named method");
}

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 1: oscillator");
  const HarmonicOscillator& osc = kOscillator;
  const Z1 z0 = make_state(0.0, 1.0);
  const double T1 = s.real("oscillator.t_omega");
  struct Pt {
    double h, g, e;
  };
  struct Method {
    std::string name, label;
    std::int64_t evals;
    double bound;
    std::vector<Pt> pts;
  };
  std::vector<Method> methods;
  for (const auto& m : s.texts("oscillator.methods"))
    methods.push_back({m, label_of(m), evals_per_step(m), method_info(m).oscillatory_bound, {}});

  Csv oc({"method", "omega_h", "h_eff", "max_global_err", "max_rel_H_err"});
  for (double wh : s.reals("oscillator.omega_h")) {
    for (auto& m : methods) {
      const double h = step_at_equal_work(wh, m.evals);
      if (beyond_bound(osc.w * h, m.bound)) continue;  // (TI at h = h_eff: omega h_eff < 2 sqrt(3))
      const auto [g, e] = with_method(m.name, osc, [&](const auto& method) {  // processed where it has processing
        double gm = 0, em = 0;
        integrate(method, z0, h, std::llround(std::floor(T1 / h)), [&](std::int64_t j, const Z1& z) {
          const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
          gm = std::max(gm, std::hypot(z.p[0] - ex.p[0], z.q[0] - ex.q[0]));  // (|e_p|^2 + w^2 |e_q|^2)^(1/2)
          em = std::max(em, std::abs(osc.H(z) - osc.H(z0)) / osc.H(z0));
        });
        return std::pair{gm, em};
      });
      oc.row(m.label, wh, wh, g, e);
      m.pts.push_back({wh, g, e});
    }
  }
  ctx.write("oscillator.csv", oc);

  // The closed forms of Sect. 1.4 (start q0 = 0), over omega h_eff up to SV's bound (it runs at h = h_eff/2).
  const double sv_eff_bound = 2 * method_info("stormer_verlet").oscillatory_bound;
  const double ti_bound = method_info("takahashi_imada").oscillatory_bound;
  Csv cf({"omega_h", "sv_rel_H", "ti_rel_H"});
  for (int i = 1; i <= 400; ++i) {
    const double y = sv_eff_bound * i / 401.0;
    const double ti = y < ti_bound ? std::pow(y, 6) / (36 * (std::pow(y, 4) - 12 * y * y + 48)) : std::nan("");
    cf.row(y, y * y / (16 - y * y), ti);
  }
  ctx.write("oscillator_closed_forms.csv", cf);

  json orders, evals, eff_bound;
  for (const auto& m : methods) {
    for (const bool energy : {false, true}) {
      const std::string name = m.label + (energy ? "_energy" : "_solution");
      std::vector<double> h, e;
      for (const auto& p : m.pts)
        if (p.h <= kFitMaxOmegaH) h.push_back(p.h), e.push_back(energy ? p.e : p.g);
      orders[name] = fit_order(h, e, roundoff_floor(), name.c_str()).order;
    }
    evals[m.label] = m.evals;
    eff_bound[m.label] = m.bound * 2 / static_cast<double>(m.evals);  // in omega h_eff
  }
  put(ctx, "orders", orders);
  ctx.summary["equal_work"] = {{"evals_per_step", evals}, {"omega_h_eff_bound", eff_bound}};

  // The stability bound of TI: where the spectral radius of its one-step matrix (the kernel's) leaves 1.
  const auto radius = [&](double wh) {
    return with_kernel("takahashi_imada", osc, [&](const auto& m) { return spectral_radius(one_step_matrix(m, wh)); });
  };
  double lo = 3.0, hi = 3.9;
  for (int it = 0; it < 60; ++it) (radius(0.5 * (lo + hi)) <= 1 + 1e-12 ? lo : hi) = 0.5 * (lo + hi);
  put(ctx, "reproduced", {{"ti_stability_bound", lo}});
}

// ---- Fig. 2: unsymmetric pendulum, the shifted energy H + h^2 H_3 along the simplified method ----

void run_pendulum(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 2: unsymmetric pendulum");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const UnsymmetricPendulum up;
  const Z1 p0 = make_state(s.real("pendulum.q0"), s.real("pendulum.p0"));
  const std::int64_t n = steps_to(s.real("pendulum.t_end"), h), every = std::max<std::int64_t>(1, n / samples);
  const double E0 = shifted_energy(up, p0, h);
  Csv f2({"t", "shifted_energy_err", "H_err"});
  std::vector<double> ts, es, ts_all, es_all;
  // (4.3)'s rate averaged along the exact orbit (RK4 at step 1e-3 over 2000 time units).
  double predicted = 0;
  const std::int64_t n_ref = 2000000;
  integrate(RungeKutta4::bind(up), p0, 1e-3, n_ref,
            [&](std::int64_t j, const Z1& z) { predicted += j > 0 ? simplified_ti_drift_rate(up, z, h) : 0.0; });
  integrate(simplified_ti_method(up, false), p0, h, n, [&](std::int64_t j, const Z1& z) {
    if (j % every) return;
    const double t = static_cast<double>(j) * h, e = shifted_energy(up, z, h) - E0;
    f2.row(t, e, up.H(z) - up.H(p0));
    ts_all.push_back(t), es_all.push_back(e);
    if (t <= s.real("pendulum.fit_t")) ts.push_back(t), es.push_back(e);
  });
  ctx.write("fig2_pendulum.csv", f2);
  put(ctx, "reproduced",
      {{"unsym_pendulum_drift_rate", slope(ts, es)},                // at the start's energy
       {"unsym_pendulum_drift_rate_whole", slope(ts_all, es_all)},  // over the whole span (the rate falls with H)
       {"unsym_pendulum_drift_rate_predicted", predicted / static_cast<double>(n_ref)}});
}

// ---- Fig. 3: Henon-Heiles k = 3, E along the simplified method: bounded, no drift ----

void run_hh3(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 3: Henon-Heiles k = 3");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const HenonHeiles hh{{}, 3};
  const Z2 start = hh_start(hh, s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"));
  const std::int64_t n = steps_to(s.real("hh3.t_end"), h), every = std::max<std::int64_t>(1, n / samples);
  const double E0 = simplified_ti_modified_energy(hh, start, h);
  Csv f3({"t", "E_err", "H_err"});
  std::vector<double> ts, es;
  double worst = 0;
  integrate(simplified_ti_method(hh, false), start, h, n, [&](std::int64_t j, const Z2& z) {
    if (j % every) return;
    const double t = static_cast<double>(j) * h, e = simplified_ti_modified_energy(hh, z, h) - E0;
    f3.row(t, e, hh.H(z) - hh.H(start));
    ts.push_back(t), es.push_back(e), worst = std::max(worst, std::abs(e));
  });
  ctx.write("fig3_hh3.csv", f3);
  put(ctx, "reproduced", {{"hh3_drift_slope", slope(ts, es)}, {"hh3_max_E_err", worst}});
}

// ---- Fig. 4: Henon-Heiles k, an ensemble: mean and standard deviation of the E error;
// Fig. 5: Poincare cuts of its trajectory with the largest error ----

template <class HH>
void ensemble_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 4: ensemble");
  const double h = s.real("h");
  const std::int64_t samples = s.integer("samples");
  const auto M = static_cast<std::size_t>(s.integer("ensemble.size"));
  const std::int64_t n4 = steps_to(s.real("t_end"), h), every4 = std::max<std::int64_t>(1, n4 / samples);
  std::vector<Z2> starts(M);
  for (std::size_t i = 0; i < M; ++i) starts[i] = ensemble_start(s, hhk, i);
  const auto t0 = std::chrono::steady_clock::now();
  const auto series = parallel_map(M, [&](std::size_t i) {
    std::vector<double> e;
    const double E0 = simplified_ti_modified_energy(hhk, starts[i], h);
    integrate(simplified_ti_method(hhk, false), starts[i], h, n4, [&](std::int64_t j, const Z2& z) {
      if (j % every4 == 0) e.push_back(simplified_ti_modified_energy(hhk, z, h) - E0);
    });
    return e;
  });
  const double wall4 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::size_t ns = series[0].size();
  json reproduced;
  Csv f4s({"t", "mu", "sigma"});
  std::vector<double> tl, sl;
  for (std::size_t k = 0; k < ns; ++k) {
    double mu = 0, var = 0;
    for (const auto& e : series) mu += e[k];
    mu /= static_cast<double>(M);
    for (const auto& e : series) var += (e[k] - mu) * (e[k] - mu);
    const double sigma = std::sqrt(var / static_cast<double>(M - 1)), t = static_cast<double>(k) * static_cast<double>(every4) * h;
    f4s.row(t, mu, sigma);
    if (t >= s.real("t_end") / 10 && sigma > 0) tl.push_back(std::log(t)), sl.push_back(std::log(sigma));  // past the bounded part
    if (k + 1 == ns) reproduced["hh5_mu_final"] = mu, reproduced["hh5_sigma_final"] = sigma;
  }
  ctx.write("fig4_stats.csv", f4s);
  reproduced["hh5_sigma_exponent"] = slope(tl, sl);
  // Every trajectory's series (thinned to at most 200 times) and the outliers.
  Csv f4t({"trajectory", "outlier", "t", "E_err"});
  std::size_t worst_i = 0;
  double worst_e = 0;
  json outliers = json::array();
  for (std::size_t i = 0; i < M; ++i) {
    double mx = 0;
    for (double e : series[i]) mx = std::max(mx, std::abs(e));
    const bool out = mx > s.real("ensemble.outlier");
    if (out) outliers.push_back(i);
    if (mx > worst_e) worst_e = mx, worst_i = i;
    const std::size_t stride = std::max<std::size_t>(1, ns / 200);
    for (std::size_t k = 0; k < ns; k += stride)
      f4t.row(static_cast<std::int64_t>(i), static_cast<std::int64_t>(out), static_cast<double>(k) * static_cast<double>(every4) * h, series[i][k]);
  }
  ctx.write("fig4_trajectories.csv", f4t);
  reproduced["hh5_outliers"] = outliers;

  // Fig. 5: Poincare cuts (q1 = 0 upwards, p1 > 0) of the trajectory with the largest error,
  // on the window where its error grows fastest and on the one where it is flattest.
  ctx.progress("Fig. 5: Poincare cuts");
  const auto& e = series[worst_i];
  const std::size_t windows = 20, per = std::max<std::size_t>(2, ns / windows);
  std::size_t steep = 0, flat = 0;
  double smax = -1, smin = std::numeric_limits<double>::infinity();
  for (std::size_t w = 0; w < windows && (w + 1) * per <= ns; ++w) {
    std::vector<double> x, y;
    for (std::size_t k = w * per; k < (w + 1) * per; ++k) x.push_back(static_cast<double>(k)), y.push_back(e[k]);
    const double sl_w = std::abs(slope(x, y));
    if (sl_w > smax) smax = sl_w, steep = w;
    if (sl_w < smin) smin = sl_w, flat = w;
  }
  const double tw = static_cast<double>(per) * static_cast<double>(every4) * h;
  Csv f5({"window", "t", "q2", "p2"});
  Z2 prev = starts[worst_i];
  integrate(simplified_ti_method(hhk, false), starts[worst_i], h, n4, [&](std::int64_t j, const Z2& z) {
    const double t = static_cast<double>(j) * h;
    for (const auto& [label, w] : {std::pair{"growth", steep}, std::pair{"no_growth", flat}}) {
      if (j > 0 && t >= static_cast<double>(w) * tw && t < static_cast<double>(w + 1) * tw && prev.q[0] < 0 &&
          z.q[0] >= 0 && z.p[0] > 0) {
        const double a = -prev.q[0] / (z.q[0] - prev.q[0]);  // linear interpolation of the crossing
        f5.row(label, t - (1 - a) * h, prev.q[1] + a * (z.q[1] - prev.q[1]), prev.p[1] + a * (z.p[1] - prev.p[1]));
      }
    }
    prev = z;
  });
  ctx.write("fig5_poincare.csv", f5);
  reproduced["poincare_trajectory"] = worst_i;
  reproduced["poincare_windows"] = {{"growth", {static_cast<double>(steep) * tw, static_cast<double>(steep + 1) * tw}},
                                    {"no_growth", {static_cast<double>(flat) * tw, static_cast<double>(flat + 1) * tw}}};
  put(ctx, "reproduced", reproduced);
  put(ctx, "timing", {{"fig4_wall_s", wall4}});
}

void run_ensemble(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { ensemble_with(ctx, hhk); });
}

// ---- Fig. 6: the Lennard-Jones cluster ----

void run_lj(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 6: Lennard-Jones cluster");
  const std::int64_t samples = s.integer("samples");
  using LJ = LennardJones<9>;
  using Z18 = PhaseState<18>;
  const LJ lj;
  json reproduced;
  const auto lj_start = [&](std::size_t i) {  // grid (i, j), i, j in {1, 2, 3}, perturbed; p = 0
    std::seed_seq seq{static_cast<std::uint64_t>(s.integer("lj.seed")), static_cast<std::uint64_t>(i)};
    std::mt19937_64 rng(seq);
    std::uniform_real_distribution<double> u(-s.real("lj.perturbation"), s.real("lj.perturbation"));
    Z18 z;
    for (int k = 0; k < 9; ++k) z.q[2 * k] = 1 + k % 3 + u(rng), z.q[2 * k + 1] = 1 + k / 3 + u(rng);
    return z;
  };
  // The step-size scan: max |H - H0| over t <= lj.scan_t, diverged beyond lj.blowup or when not finite.
  const auto hs = s.reals("lj.h_scan");
  const auto scan_size = static_cast<std::size_t>(s.integer("lj.scan_size"));
  const auto scan = parallel_map(hs.size() * scan_size, [&](std::size_t task) {
    const double hh = hs[task / scan_size];
    const Z18 start = lj_start(task % scan_size);
    const double Hs = lj.H(start);
    double worst = 0;
    std::int64_t diverged = -1;
    integrate(simplified_ti_method(lj, false), start, hh, steps_to(s.real("lj.scan_t"), hh),
                        [&](std::int64_t j, const Z18& z) {
                          if (diverged >= 0) return;
                          const double e = std::abs(lj.H(z) - Hs);
                          if (!(e <= s.real("lj.blowup"))) diverged = j;
                          else worst = std::max(worst, e);
                        });
    return std::pair{worst, diverged};
  });
  Csv sc({"h", "trajectory", "max_H_err", "diverged", "diverge_step"});
  json stable_h = json::array();
  for (std::size_t k = 0; k < hs.size(); ++k) {
    bool all_ok = true;
    for (std::size_t i = 0; i < scan_size; ++i) {
      const auto& [w, dv] = scan[k * scan_size + i];
      sc.row(hs[k], static_cast<std::int64_t>(i), w, static_cast<std::int64_t>(dv >= 0), dv);
      all_ok = all_ok && dv < 0;
    }
    if (all_ok) stable_h.push_back(hs[k]);
  }
  ctx.write("fig6_scan.csv", sc);
  reproduced["lj_stable_steps"] = stable_h;
  // The ensemble at lj.h: E error (3.3)+(4.2), H error, and H at the processed variables (1.5).
  const double hl = s.real("lj.h");
  const auto Ml = static_cast<std::size_t>(s.integer("lj.size"));
  const std::int64_t nl = steps_to(s.real("lj.t_end"), hl), every_l = std::max<std::int64_t>(1, nl / samples);
  const auto tl0 = std::chrono::steady_clock::now();
  struct Series {
    std::vector<double> E, H, Hhat;
  };
  const auto lj_series = parallel_map(Ml, [&](std::size_t i) {
    Series r;
    const Z18 start = lj_start(i);
    const double E0 = simplified_ti_modified_energy(lj, start, hl), Hs = lj.H(start);
    integrate(simplified_ti_method(lj, false), start, hl, nl, [&](std::int64_t j, const Z18& z) {
      if (j % every_l) return;
      r.E.push_back(simplified_ti_modified_energy(lj, z, hl) - E0);
      r.H.push_back(lj.H(z) - Hs);
      r.Hhat.push_back(lj.H(ti_process(lj, z, hl, takahashi_imada_alpha)) - Hs);
    });
    return r;
  });
  const double wall6 = std::chrono::duration<double>(std::chrono::steady_clock::now() - tl0).count();
  Csv f6({"t", "mu", "sigma", "H_err_rms", "Hhat_err_rms"});
  std::vector<double> lt, ls;
  const std::size_t nsl = lj_series[0].E.size();
  double mu_f = 0, sigma_f = 0, H_max = 0;
  for (std::size_t k = 0; k < nsl; ++k) {
    double mu = 0, var = 0, hr = 0, hhr = 0;
    for (const auto& r : lj_series) mu += r.E[k], hr += r.H[k] * r.H[k], hhr += r.Hhat[k] * r.Hhat[k];
    mu /= static_cast<double>(Ml);
    for (const auto& r : lj_series) var += (r.E[k] - mu) * (r.E[k] - mu), H_max = std::max(H_max, std::abs(r.H[k]));
    const double sigma = std::sqrt(var / static_cast<double>(Ml - 1));
    const double t = static_cast<double>(k) * static_cast<double>(every_l) * hl;
    f6.row(t, mu, sigma, std::sqrt(hr / static_cast<double>(Ml)), std::sqrt(hhr / static_cast<double>(Ml)));
    if (t >= s.real("lj.t_end") / 10 && sigma > 0) lt.push_back(std::log(t)), ls.push_back(std::log(sigma));
    mu_f = mu, sigma_f = sigma;
  }
  ctx.write("fig6_stats.csv", f6);
  Csv f6t({"trajectory", "t", "E_err"});
  const std::size_t stride = std::max<std::size_t>(1, nsl / 200);
  for (std::size_t i = 0; i < std::min<std::size_t>(Ml, 50); ++i)
    for (std::size_t k = 0; k < nsl; k += stride)
      f6t.row(static_cast<std::int64_t>(i), static_cast<double>(k) * static_cast<double>(every_l) * hl, lj_series[i].E[k]);
  ctx.write("fig6_trajectories.csv", f6t);
  reproduced["lj_h"] = hl;
  reproduced["lj_mu_final"] = mu_f, reproduced["lj_sigma_final"] = sigma_f;
  reproduced["lj_mu_final_stderr"] = sigma_f / std::sqrt(static_cast<double>(Ml));
  reproduced["lj_sigma_final_stderr"] = sigma_f / std::sqrt(2.0 * static_cast<double>(Ml - 1));
  reproduced["lj_sigma_exponent"] = lt.size() >= 2 ? slope(lt, ls) : std::nan("");
  reproduced["lj_H_err_max"] = H_max;
  put(ctx, "reproduced", reproduced);
  put(ctx, "timing", {{"fig6_wall_s", wall6}});
}

// ---- Symplecticity against volume preservation: the one-step Jacobian (central
// differences) of each named method's kernel on Henon-Heiles ----

HenonHeiles symplecticity_system(const Scene& s) { return {{}, static_cast<int>(s.integer("symplecticity.k"))}; }

void run_symplecticity(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("symplecticity");
  const HenonHeiles hh = symplecticity_system(s);
  const Z2 z = hh_start(hh, s.real("symplecticity.q2"), s.real("symplecticity.p2"), s.real("hh.H0"));
  const double h = s.real("h"), d = s.real("symplecticity.fd_step");
  json reproduced;
  for (const auto& m : s.texts("symplecticity.methods")) {
    const Mat<4> J = with_kernel(m, hh, [&](const auto& kernel) { return step_jacobian_fd(kernel, z, h, d); });
    reproduced[label_of(m) + "_symplecticity_defect"] = symplecticity_defect(J);
    reproduced[label_of(m) + "_det_minus_one"] = J.determinant() - 1.0;
  }
  put(ctx, "reproduced", reproduced);
}

// ---- Cost: ns per step of each named method's kernel (no processing, as Figs 2-6
// use them) on Henon-Heiles k, from the ensemble's first start ----

template <class HH>
void timing_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: ns per step");
  const Z2 z = ensemble_start(s, hhk, 0);
  const double h = s.real("h");
  const std::int64_t n = s.integer("timing.steps");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  json ns_per_step;
  for (const auto& m : s.texts("timing.methods"))
    ns_per_step[label_of(m)] = with_kernel(m, hhk, [&](const auto& kernel) {
      return 1e9 * median_seconds(repeats, [&] { do_not_optimize(integrate_inlined(kernel, z, h, n)); }) /
             static_cast<double>(n);
    });
  put(ctx, "timing",
      {{"ns_per_step", ns_per_step},
       {"method", "median of " + std::to_string(repeats) + " runs of " + std::to_string(n) +
                      " steps, single thread, every call inlined; fig4_wall_s, fig6_wall_s: the ensembles on --threads threads"}});
}

void run_timing(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { timing_with(ctx, hhk); });
}

Schema schema() {
  Schema s;
  s.reals("oscillator.omega_h", positive(), 3,
          "effective steps omega h_eff of Fig. 1 (equal work: h = h_eff e/2 for e force evaluations per step)")
      .texts("oscillator.methods", method_choices<Counting<HarmonicOscillator>>(), 1,
             "methods of Fig. 1, processed where they have processing (registry names or labels)")
      .real("oscillator.t_omega", positive(), "errors are maxima over t <= t_omega / omega (004: 50)")
      .real("h", positive(), "step of Figs 2-5 (004: 0.2), of the symplecticity check and of the cost runs")
      .real("pendulum.q0", any_finite(), "Fig. 2 start (004: q = 0, p = 2.5)")
      .real("pendulum.p0", any_finite(), "")
      .real("pendulum.t_end", positive(), "Fig. 2 time span")
      .real("pendulum.fit_t", positive(), "the drift rate is fitted over t <= fit_t, where the energy has not yet fallen")
      .real("hh3.q2", any_finite(), "Fig. 3 start q2 (q1 = 0, p1 > 0 from hh.H0); the centre of the Fig. 4 starts")
      .real("hh3.p2", any_finite(), "Fig. 3 start p2")
      .real("hh3.t_end", positive(), "Fig. 3 time span")
      .integer("hh.k", at_least(3), "exponent k of Fig. 4 (004: 5)")
      .real("hh.H0", positive(), "energy of the Henon-Heiles starts (004: 1/8)")
      .real("hh.coupling", any_finite(),
            "coefficient c of c q1^2 q2 in the potential of Figs 4-5 (004: 1); c = 0 removes the term from the "
            "compiled step")
      .real("t_end", positive(), "Fig. 4 time span (004: 2.5e6)")
      .integer("ensemble.size", at_least(2), "Fig. 4 trajectories (004: 100)")
      .integer("ensemble.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("ensemble.perturbation", non_negative(), "q2 and p2 of each start perturbed uniformly by at most this")
      .real("ensemble.outlier", positive(), "trajectories whose max |error| exceeds this go to Fig. 4's upper panel (004: 2e-6)")
      .integer("samples", at_least(10), "output times per long run")
      .reals("lj.h_scan", positive(), 1, "Fig. 6: steps scanned for stability (004 prints h = 0.2)")
      .real("lj.scan_t", positive(), "time span of the step-size scan")
      .integer("lj.scan_size", at_least(1), "trajectories of the scan")
      .real("lj.h", positive(), "Fig. 6: the step used for the statistics")
      .real("lj.t_end", positive(), "Fig. 6 time span (004: 2e4)")
      .integer("lj.size", at_least(2), "Fig. 6 trajectories (004: 400)")
      .integer("lj.seed", non_negative(), "seed; trajectory i uses its own stream (seed, i)")
      .real("lj.perturbation", non_negative(), "each coordinate of the 3 x 3 grid perturbed uniformly by at most this (004: 0.01)")
      .real("lj.blowup", positive(), "|H - H0| above this marks a scan run diverged")
      .texts("symplecticity.methods", method_choices<HenonHeiles>(), 1,
             "methods whose one-step Jacobian (of the kernel) is checked (registry names or labels)")
      .integer("symplecticity.k", at_least(3), "exponent k of the Henon-Heiles system of the check")
      .real("symplecticity.q2", any_finite(), "start q2 of the check (q1 = 0, p1 > 0 from hh.H0)")
      .real("symplecticity.p2", any_finite(), "start p2 of the check")
      .real("symplecticity.fd_step", positive(), "step of the central differences of the Jacobian")
      .texts("timing.methods", method_choices<HenonHeiles>(), 1,
             "methods timed (their kernels, on the Fig. 4 system; registry names or labels)")
      .integer("timing.steps", at_least(1), "steps of each timed run")
      .integer("timing.repeats", at_least(1), "timed runs per method (the median is reported)");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"ti_drift", "004 Figs 1-6: energy behaviour of the (simplified) Takahashi-Imada method",
                      schema(), {}};
  spec.studies = {
      {"oscillator", "004 Fig 1", {"oscillator.csv", "oscillator_closed_forms.csv"}, {"oscillator"}, check_oscillator,
       run_oscillator},
      {"pendulum", "004 Fig 2", {"fig2_pendulum.csv"}, {"h", "samples", "pendulum"}, nullptr, run_pendulum},
      {"hh3", "004 Fig 3", {"fig3_hh3.csv"}, {"h", "samples", "hh3", "hh.H0"},
       [](const Scene& s) { check_hh_start(s, "hh3", HenonHeiles{{}, 3}); },
       run_hh3},
      {"ensemble", "004 Figs 4, 5", {"fig4_stats.csv", "fig4_trajectories.csv", "fig5_poincare.csv"},
       {"h", "t_end", "samples", "hh", "ensemble", "hh3.q2", "hh3.p2"},
       [](const Scene& s) { with_ensemble_system(s, [&](const auto& hh) { check_hh_start(s, "hh3", hh); }); },
       run_ensemble},
      {"lj", "004 Fig 6", {"fig6_*.csv"}, {"lj", "samples"}, nullptr, run_lj},
      {"symplecticity", "004 Sect. 1.3: TI symplectic, the simplified TI only volume-preserving", {},
       {"symplecticity", "h", "hh.H0"},
       [](const Scene& s) {
         check_methods(s, "symplecticity.methods", symplecticity_system(s));
         check_hh_start(s, "symplecticity", symplecticity_system(s));
       },
       run_symplecticity},
      {"timing", "cost: ns per step of each method", {},
       {"timing", "h", "hh", "hh3.q2", "hh3.p2", "ensemble.seed", "ensemble.perturbation"},
       [](const Scene& s) { with_ensemble_system(s, [&](const auto& hh) { check_methods(s, "timing.methods", hh); }); }, run_timing},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
