// euler_compensation: 000 (Takacs & Fulop 2025) Figs 2, 3, 8 and 9.
//   Fig 2  explicit Euler on y' = -alpha y, in y and in ybar = Psi(y) of (15)
//   Fig 3  explicit Euler on the Gompertz equation (17), in y and in ybar of (18)
//   Fig 8  symplectic Euler (42)-(43) on the oscillator (74), with and without
//          the compensating point transformation (82)
//   Fig 9  error in H against h for both: fitted orders 1 and 2
// plus what the accuracy costs: ns per step and error against wall time.
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/integrators/integrate.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/exponential_decay.hpp"
#include "geomint/systems/gompertz.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "geomint/transforms/variable_transform.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

constexpr int kExactCurvePoints = 400;  // resolution of the exact curves in the figures

// ---- Figs 2 and 3: explicit Euler in y and in the compensating coordinate ybar ----

struct ScalarFigure {
  Csv trajectory{{"j", "t", "y_exact", "y_euler", "y_compensated", "ybar_exact", "ybar_euler", "ybar_compensated"}};
  Csv exact{{"t", "y_exact", "ybar_exact"}};
  double euler_max_rel_err = 0;        // Euler in y against the exact solution
  double compensated_max_rel_err = 0;  // Euler in ybar, mapped back by Psi^{-1}
};

template <class Sys, class Psi>
ScalarFigure scalar_figure(const Sys& sys, const Psi& psi, double y0, double h, std::int64_t steps) {
  ScalarFigure fig;
  const TransformedODE transformed{sys, psi};  // 000 eq. (3)
  double y = y0, ybar = psi(y0);
  ErrorSeries euler_err, compensated_err;
  for (std::int64_t j = 0; j <= steps; ++j) {
    const double t = static_cast<double>(j) * h;
    const double exact = sys.exact(y0, t);
    const double y_comp = psi.inverse(ybar);
    euler_err.add(relative_error(y, exact));
    compensated_err.add(relative_error(y_comp, exact));
    fig.trajectory.row(j, t, exact, y, y_comp, psi(exact), psi(y), ybar);
    y = explicit_euler(sys, y, h);
    ybar = explicit_euler(transformed, ybar, h);
  }
  fig.euler_max_rel_err = euler_err.max_abs();
  fig.compensated_max_rel_err = compensated_err.max_abs();
  const double t_end = static_cast<double>(steps) * h;
  for (int i = 0; i <= kExactCurvePoints; ++i) {
    const double t = t_end * i / kExactCurvePoints;
    const double exact = sys.exact(y0, t);
    fig.exact.row(t, exact, psi(exact));
  }
  return fig;
}

// ---- Figs 8 and 9: symplectic Euler on the oscillator, with and without (82) ----

using Oscillator = HarmonicOscillator;
using State = Oscillator::State;

// The compensated method: pre-transform by (41) once, step symplectic Euler
// (42)-(43) in (qbar, pbar), map back by (41) wherever a result is wanted.
template <class Sys>
struct Compensated {
  PointTransformed<Sys, OscillatorCompensation> sys;
  double h;
  State pre(const State& z) const { return sys.to_transformed(z); }
  State kernel(const State& zb) const { return symplectic_euler_pq(sys, zb, h); }
  State post(const State& zb, std::int64_t j) const {
    const State z = sys.to_original(zb);
    if (!std::isfinite(z.q[0]) || !std::isfinite(z.p[0])) {
      throw IntegrationError("compensating transformation (82) undefined at step " + std::to_string(j) +
                             ": |qhat| >= 1 (increase oscillator.k or decrease h)");
    }
    return z;
  }
};

template <class Sys>
Compensated<Sys> compensated(const Sys& osc, double k, double h) {
  return {PointTransformed<Sys, OscillatorCompensation>{osc, OscillatorCompensation{k, h}}, h};
}

struct EnergyRun {
  double max_err = 0, rms_err = 0;  // of H(q_j, p_j) - H(q_0, p_0), j = 0..N
  std::int64_t force_evals = 0;
};

// One convergence run of each method to t = N h, counting force evaluations.
EnergyRun run_se(const State& z0, double h, std::int64_t n) {
  EnergyRun r;
  const Counting<Oscillator> sys{{}, &r.force_evals};
  const double H0 = sys.H(z0);
  ErrorSeries e;
  integrate_n_steps([&](const State& z) { return symplectic_euler_pq(sys, z, h); }, z0, n,
                    [&](std::int64_t, const State& z) { e.add(sys.H(z) - H0); });
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

EnergyRun run_se_compensated(const State& z0, double h, double k, std::int64_t n) {
  EnergyRun r;
  const Oscillator osc;
  const auto method = compensated(Counting<Oscillator>{osc, &r.force_evals}, k, h);
  const double H0 = osc.H(z0);
  ErrorSeries e;
  integrate_n_steps([&](const State& zb) { return method.kernel(zb); }, method.pre(z0), n,
                    [&](std::int64_t j, const State& zb) { e.add(osc.H(method.post(zb, j)) - H0); });
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

EnergyRun run_rk4(const State& z0, double h, std::int64_t n) {
  EnergyRun r;
  const HamiltonianField field{Counting<Oscillator>{{}, &r.force_evals}};
  const double H0 = field.sys.H(z0);
  ErrorSeries e;
  integrate_n_steps([&](const State& z) { return runge_kutta4(field, z, h); }, z0, n,
                    [&](std::int64_t, const State& z) { e.add(field.sys.H(z) - H0); });
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

// Max over t_j in [0, N h] of the global error of explicit Euler on a scalar ODE.
template <class Sys>
double euler_max_err(const Sys& sys, double y0, double h, std::int64_t n) {
  ErrorSeries e;
  integrate_n_steps([&](double y) { return explicit_euler(sys, y, h); }, y0, n,
                    [&](std::int64_t j, double y) { e.add(y - sys.exact(y0, static_cast<double>(j) * h)); });
  return e.max_abs();
}

struct OscillatorRuns {
  EnergyRun se, comp, rk4;
};

OscillatorRuns oscillator_runs(const State& z0, double h, double k, std::int64_t n) {
  return {run_se(z0, h, n), run_se_compensated(z0, h, k, n), run_rk4(z0, h, n)};
}

// log-log interpolation of err(wall) at `wall`, on a curve sorted by wall time; NaN outside it.
double error_at_wall_time(std::vector<std::pair<double, double>> curve, double wall) {
  std::sort(curve.begin(), curve.end());
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto [w0, e0] = curve[i];
    const auto [w1, e1] = curve[i + 1];
    if (w0 <= wall && wall <= w1 && w1 > w0) {
      const double s = std::log(wall / w0) / std::log(w1 / w0);
      return std::exp(std::log(e0) + s * (std::log(e1) - std::log(e0)));
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

Schema schema() {
  Schema s;
  s.real("decay.alpha", positive(), "rate alpha of y' = -alpha y (000 eq. (14))")
      .real("decay.y0", positive(), "initial value y(0) > 0")
      .real("decay.h", positive(), "step of explicit Euler (Fig 2); h alpha <= 2 (stability)")
      .integer("decay.steps", at_least(1), "number of steps shown in Fig 2")
      .real("gompertz.a", positive(), "growth parameter a of (17)")
      .real("gompertz.b", positive(), "growth parameter b of (17)")
      .real("gompertz.y0", positive(), "initial value, 0 < y0 < e^{a/b} (domain of (18))")
      .real("gompertz.h", positive(), "step of explicit Euler (Fig 3); h b <= 2 (stability at equilibrium)")
      .integer("gompertz.steps", at_least(1), "number of steps shown in Fig 3")
      .real("oscillator.q0", any_finite(), "initial q (the compensation (82) is derived for q0 = 1, p0 = 0)")
      .real("oscillator.p0", any_finite(), "initial p")
      .real("oscillator.h", positive(), "step of symplectic Euler (Fig 8); h < 2 (stability)")
      .real("oscillator.k", positive(), "parameter k of (82), qhat = q / (1 + k h^2)")
      .integer("oscillator.steps", at_least(1), "number of steps in Fig 8")
      .reals("convergence.h", positive(), 3, "steps of the convergence study (Fig 9); each divides t_end")
      .real("convergence.t_end", positive(), "errors are maxima over t in [0, t_end]")
      .reals("timing.h", positive(), 3, "steps of the work-precision runs (to convergence.t_end)")
      .integer("timing.repeats", at_least(1), "timed repetitions per measurement (the median is reported)")
      .integer("timing.steps", at_least(1), "steps of the run that measures ns per step");
  return s;
}

// ---- checks across keys, per study ----

void check_decay(const Scene& s) {
  if (s.real("decay.h") * s.real("decay.alpha") > method_info("explicit_euler").real_bound)
    s.reject("decay.h", "explicit Euler on y' = -alpha y is unstable for h > 2/alpha = " +
                            format_double(2.0 / s.real("decay.alpha")));
}

void check_gompertz(const Scene& s) {
  if (s.real("gompertz.h") * s.real("gompertz.b") > method_info("explicit_euler").real_bound)
    s.reject("gompertz.h", "explicit Euler is unstable at the Gompertz equilibrium for h > 2/b = " +
                               format_double(2.0 / s.real("gompertz.b")));
  if (std::log(s.real("gompertz.y0")) >= s.real("gompertz.a") / s.real("gompertz.b"))
    s.reject("gompertz.y0", "the transformation (18) needs 0 < y0 < e^{a/b}");
}

// A step of symplectic Euler on the oscillator, with and without (82).
void check_oscillator_step(const Scene& s, const char* key, double h) {
  if (!(h < method_info("symplectic_euler_pq").oscillatory_bound))
    s.reject(key, "symplectic Euler on the oscillator (omega = 1) is unstable for h >= 2");
  if (!OscillatorCompensation{s.real("oscillator.k"), h}.defined(s.real("oscillator.q0")))
    s.reject(key, "the transformation (82) needs |q0| < 1 + k h^2 = " +
                      format_double(1 + s.real("oscillator.k") * h * h));
}

// Steps of the runs to convergence.t_end.
void check_steps(const Scene& s, const char* key) {
  const double t_end = s.real("convergence.t_end");
  for (double h : s.reals(key)) {
    check_oscillator_step(s, key, h);
    const double n = static_cast<double>(steps_to(t_end, h));
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end)
      s.reject(key, "each h must divide convergence.t_end = " + format_double(t_end));
  }
}

State initial_state(const Scene& s) { return make_state(s.real("oscillator.q0"), s.real("oscillator.p0")); }

// ---- Fig 2 and Fig 3 ----

void run_decay(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 2: explicit Euler in y and ybar");
  const ExponentialDecay decay{s.real("decay.alpha")};
  const auto fig2 = scalar_figure(decay, DecayCompensation{decay.alpha}, s.real("decay.y0"), s.real("decay.h"),
                                  s.integer("decay.steps"));
  ctx.write("fig2_decay.csv", fig2.trajectory);
  ctx.write("fig2_decay_exact.csv", fig2.exact);
  ctx.summary["published"]["decay_compensated_max_rel_err"] = 0.0;  // Sec. 2.3.1: "an exact solution"
  ctx.summary["reproduced"]["decay_compensated_max_rel_err"] = fig2.compensated_max_rel_err;
  ctx.summary["reproduced"]["decay_euler_max_rel_err"] = fig2.euler_max_rel_err;
}

void run_gompertz(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 3: explicit Euler in y and ybar");
  const Gompertz gompertz{s.real("gompertz.a"), s.real("gompertz.b")};
  const double gy0 = s.real("gompertz.y0");
  const auto fig3 = scalar_figure(gompertz, GompertzCompensation{gompertz.a, gompertz.b, gy0}, gy0,
                                  s.real("gompertz.h"), s.integer("gompertz.steps"));
  ctx.write("fig3_gompertz.csv", fig3.trajectory);
  ctx.write("fig3_gompertz_exact.csv", fig3.exact);
  ctx.summary["published"]["gompertz_compensated_max_rel_err"] = 0.0;  // Sec. 2.3.2: "an exact numerical solution"
  ctx.summary["reproduced"]["gompertz_compensated_max_rel_err"] = fig3.compensated_max_rel_err;
  ctx.summary["reproduced"]["gompertz_euler_max_rel_err"] = fig3.euler_max_rel_err;
}

// ---- Fig 8: phase portraits over oscillator.steps steps ----

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 8: phase portraits");
  const Oscillator osc;
  const State z0 = initial_state(s);
  const double H0 = osc.H(z0);
  const double h = s.real("oscillator.h"), k = s.real("oscillator.k");
  const auto method = compensated(osc, k, h);
  Csv phase({"j", "t", "q_se", "p_se", "q_compensated", "p_compensated", "energy_err_se", "energy_err_compensated"});
  State z = z0, zb = method.pre(z0);
  ErrorSeries err_se, err_comp;
  double max_qhat = 0;
  for (std::int64_t j = 0; j <= s.integer("oscillator.steps"); ++j) {
    const State zc = method.post(zb, j);
    const double e_se = osc.H(z) - H0, e_comp = osc.H(zc) - H0;
    err_se.add(e_se), err_comp.add(e_comp);
    max_qhat = std::max(max_qhat, std::abs(method.sys.map.qhat(zc.q[0])));
    phase.row(j, static_cast<double>(j) * h, z.q[0], z.p[0], zc.q[0], zc.p[0], e_se, e_comp);
    z = symplectic_euler_pq(osc, z, h);
    zb = method.kernel(zb);
  }
  ctx.write("fig8_phase.csv", phase);
  Csv exact({"t", "q", "p"});
  for (int i = 0; i <= kExactCurvePoints; ++i) {
    const double t = 2 * std::numbers::pi * i / kExactCurvePoints;
    const State e = osc.exact(z0, t);
    exact.row(t, e.q[0], e.p[0]);
  }
  ctx.write("fig8_exact.csv", exact);
  auto& reproduced = ctx.summary["reproduced"];
  reproduced["fig8_max_energy_err_se"] = err_se.max_abs();
  reproduced["fig8_max_energy_err_compensated"] = err_comp.max_abs();
  reproduced["fig8_max_abs_qhat"] = max_qhat;
}

// ---- Fig 9: convergence of the energy error, one task per step size ----

void run_convergence(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 9: convergence");
  const ExponentialDecay decay{s.real("decay.alpha")};
  const Gompertz gompertz{s.real("gompertz.a"), s.real("gompertz.b")};
  const double gy0 = s.real("gompertz.y0");
  const State z0 = initial_state(s);
  const double H0 = Oscillator{}.H(z0);
  const auto hs = s.reals("convergence.h");
  const double t_end = s.real("convergence.t_end"), k = s.real("oscillator.k");
  struct Row {
    OscillatorRuns osc;
    double ee_decay, ee_gompertz;
  };
  const auto rows = parallel_map(hs.size(), [&](std::size_t i) {
    const double h = hs[i];
    const std::int64_t n = steps_to(t_end, h);
    return Row{oscillator_runs(z0, h, k, n), euler_max_err(decay, s.real("decay.y0"), h, n),
               euler_max_err(gompertz, gy0, h, n)};
  });
  Csv conv({"h", "steps", "se_max", "se_compensated_max", "rk4_max", "se_rms", "se_compensated_rms", "rk4_rms",
            "se_evals", "se_compensated_evals", "rk4_evals", "ee_decay_max", "ee_gompertz_max"});
  std::vector<double> se_max, comp_max, rk4_max, se_rms, comp_rms, ee_decay, ee_gompertz;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const auto& [se, comp, rk4] = rows[i].osc;
    conv.row(hs[i], steps_to(t_end, hs[i]), se.max_err, comp.max_err, rk4.max_err, se.rms_err, comp.rms_err,
             rk4.rms_err, se.force_evals, comp.force_evals, rk4.force_evals, rows[i].ee_decay, rows[i].ee_gompertz);
    se_max.push_back(se.max_err), comp_max.push_back(comp.max_err), rk4_max.push_back(rk4.max_err);
    se_rms.push_back(se.rms_err), comp_rms.push_back(comp.rms_err);
    ee_decay.push_back(rows[i].ee_decay), ee_gompertz.push_back(rows[i].ee_gompertz);
  }
  ctx.write("fig9_convergence.csv", conv);

  // Orders: least squares on log-log over the points above round-off.
  const double floor = roundoff_floor(std::max(H0, 1.0));
  Csv order_csv({"name", "order", "log10_c", "r2", "points", "h_min", "h_max"});
  json orders, fits;
  const auto fit = [&](const char* name, const std::vector<double>& err, double fit_floor) {
    const OrderFit f = fit_order(hs, err, fit_floor);
    orders[name] = f.order;
    fits[name] = to_json(f);
    order_csv.row(name, f.order, f.log10_c, f.r2, f.points, f.h_min, f.h_max);
  };
  fit("ee_decay", ee_decay, roundoff_floor(s.real("decay.y0")));
  fit("ee_gompertz", ee_gompertz, roundoff_floor(gompertz.equilibrium()));
  fit("se_energy", se_max, floor);
  fit("se_compensated_energy", comp_max, floor);
  fit("rk4_energy", rk4_max, floor);
  fit("se_energy_rms", se_rms, floor);
  fit("se_compensated_energy_rms", comp_rms, floor);
  ctx.write("orders.csv", order_csv);
  ctx.summary["orders"] = orders;
  ctx.summary["fits"] = fits;
  json& published = ctx.summary["published"];
  published["ee_decay"] = method_info("explicit_euler").order;                  // Sec. 2.3: first order
  published["se_energy"] = method_info("symplectic_euler_pq").order;            // Fig 9 / eq. (44)
  published["se_compensated_energy"] = method_info("compensated_symplectic_euler").order;  // Fig 9, App. B
  ctx.summary["norms"] = {
      {"energy", "max over t_j = j h in [0, convergence.t_end] of |H(q_j, p_j) - H(q_0, p_0)|; *_rms: eq. (50)"},
      {"ee", "max over t_j in [0, convergence.t_end] of |y_j - y(t_j)|"},
      {"compensated_max_rel_err", "max over the steps of Figs 2/3 of |Psi^{-1}(ybar_j) - y(t_j)| / |y(t_j)|"}};
}

// ---- What the accuracy costs: median wall time of each method to t_end over
// the steps timing.h (steps only: the transformation (41) applied once before
// and once after), serial; errors and force evaluations from separate
// (parallel) counting runs. ----

void run_timing(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: timing");
  const Oscillator osc;
  const State z0 = initial_state(s);
  const double t_end = s.real("convergence.t_end"), k = s.real("oscillator.k");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto time_se = [&](double h, std::int64_t n) {
    return median_seconds(repeats, [&] {
      do_not_optimize(integrate_n_steps([&](const State& z) { return symplectic_euler_pq(osc, z, h); }, z0, n));
    });
  };
  const auto time_comp = [&](double h, std::int64_t n) {
    const auto method = compensated(osc, k, h);
    return median_seconds(repeats, [&] {
      const State zb = integrate_n_steps([&](const State& x) { return method.kernel(x); }, method.pre(z0), n);
      do_not_optimize(method.post(zb, n));
    });
  };
  const HamiltonianField field{osc};
  const auto time_rk4 = [&](double h, std::int64_t n) {
    return median_seconds(repeats, [&] {
      do_not_optimize(integrate_n_steps([&](const State& z) { return runge_kutta4(field, z, h); }, z0, n));
    });
  };
  const auto timing_hs = s.reals("timing.h");
  const auto timing_runs = parallel_map(timing_hs.size(), [&](std::size_t i) {
    return oscillator_runs(z0, timing_hs[i], k, steps_to(t_end, timing_hs[i]));
  });
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "energy_err_max"});
  std::vector<std::pair<double, double>> curve_se, curve_comp, curve_rk4;
  for (std::size_t i = 0; i < timing_hs.size(); ++i) {
    const double h = timing_hs[i];
    const std::int64_t n = steps_to(t_end, h);
    const auto record = [&](const char* name, double wall, const EnergyRun& r, auto& curve) {
      cost.row(name, h, n, wall, 1e9 * wall / static_cast<double>(n), r.force_evals, r.max_err);
      curve.emplace_back(wall, r.max_err);
    };
    record("se", time_se(h, n), timing_runs[i].se, curve_se);
    record("se_compensated", time_comp(h, n), timing_runs[i].comp, curve_comp);
    record("rk4", time_rk4(h, n), timing_runs[i].rk4, curve_rk4);
  }
  ctx.write("timing.csv", cost);

  json& timing = ctx.summary["timing"];
  const double h8 = s.real("oscillator.h");
  const std::int64_t n_timing = s.integer("timing.steps");
  const double ns_se = 1e9 * time_se(h8, n_timing) / static_cast<double>(n_timing);
  const double ns_comp = 1e9 * time_comp(h8, n_timing) / static_cast<double>(n_timing);
  const double ns_rk4 = 1e9 * time_rk4(h8, n_timing) / static_cast<double>(n_timing);
  timing["ns_per_step"] = {{"se", ns_se}, {"se_compensated", ns_comp}, {"rk4", ns_rk4}};
  timing["ns_per_step_ratio_compensated_over_se"] = ns_comp / ns_se;
  timing["method"] = "median of timing.repeats runs after one warm-up, steady_clock, single thread; "
                     "ns_per_step at oscillator.h over timing.steps steps";
  // Error at equal wall time: at the geometric middle of the wall-time range
  // that all three methods cover.
  double w_lo = 0, w_hi = std::numeric_limits<double>::infinity();
  for (const auto* curve : {&curve_se, &curve_comp, &curve_rk4}) {
    const auto [lo, hi] = std::minmax_element(curve->begin(), curve->end());
    w_lo = std::max(w_lo, lo->first), w_hi = std::min(w_hi, hi->first);
  }
  const auto or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  if (w_lo < w_hi) {
    const double w_star = std::sqrt(w_lo * w_hi);
    timing["error_at_equal_wall_time"] = {{"wall_s", w_star},
                                          {"se", or_null(error_at_wall_time(curve_se, w_star))},
                                          {"se_compensated", or_null(error_at_wall_time(curve_comp, w_star))},
                                          {"rk4", or_null(error_at_wall_time(curve_rk4, w_star))}};
  } else {
    timing["error_at_equal_wall_time"] = nullptr;  // timing.h gives no common wall-time range
  }
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"euler_compensation",
                      "000 Figs 2, 3, 8, 9: order compensation by a change of variables (explicit Euler) "
                      "and by a change of coordinates (symplectic Euler)",
                      schema(),
                      {}};
  spec.studies = {
      {"decay", "000 Fig 2", {"fig2_decay.csv", "fig2_decay_exact.csv"}, {"decay"}, check_decay, run_decay},
      {"gompertz", "000 Fig 3", {"fig3_gompertz.csv", "fig3_gompertz_exact.csv"}, {"gompertz"}, check_gompertz,
       run_gompertz},
      {"oscillator", "000 Fig 8", {"fig8_phase.csv", "fig8_exact.csv"}, {"oscillator"},
       [](const Scene& s) { check_oscillator_step(s, "oscillator.h", s.real("oscillator.h")); }, run_oscillator},
      {"convergence", "000 Fig 9", {"fig9_convergence.csv", "orders.csv"},
       {"convergence", "oscillator.q0", "oscillator.p0", "oscillator.k", "decay.alpha", "decay.y0", "gompertz.a",
        "gompertz.b", "gompertz.y0"},
       [](const Scene& s) { check_steps(s, "convergence.h"); }, run_convergence},
      {"timing", "cost: error against wall time and force evaluations", {"timing.csv"},
       {"timing", "convergence.t_end", "oscillator.q0", "oscillator.p0", "oscillator.k", "oscillator.h"},
       [](const Scene& s) { check_steps(s, "timing.h"); }, run_timing},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
