// euler_compensation: 000 (Takacs & Fulop 2025) Figs 2, 3, 8 and 9.
//   Fig 2  explicit Euler on y' = -alpha y, in y and in ybar = Psi(y) of (15)
//   Fig 3  explicit Euler on the Gompertz equation (17), in y and in ybar of (18)
//   Fig 8  symplectic Euler (42)-(43) on the oscillator (74), with and without
//          the compensating point transformation (82)
//   Fig 9  error in H against h for both: fitted orders 1 and 2
// plus what the accuracy costs: ns per step and error against wall time.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
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
constexpr double kReferenceTolerance = 1e-14;  // rtol = atol of the odeint reference of Figs 2-3

// ---- Figs 2 and 3: explicit Euler in y and in the compensating coordinate ybar ----

struct ScalarFigure {
  Csv trajectory{{"j", "t", "y_exact", "y_euler", "y_compensated", "ybar_exact", "ybar_euler", "ybar_compensated"}};
  Csv exact{{"t", "y_exact", "ybar_exact"}};
  double euler_max_rel_err = 0;        // Euler in y against the exact solution
  double compensated_max_rel_err = 0;  // Euler in ybar, mapped back by Psi^{-1}
  // Against an independent solution, odeint's Bulirsch-Stoer on y' = f(y) (not the closed form,
  // which is built from the same expression as Psi^{-1}), and that reference's own error.
  double compensated_max_rel_err_odeint = 0, odeint_max_rel_err = 0;
};

// y' = sys.f(y) as the first-order system of reference_solution.
template <class Sys>
struct ScalarODE {
  const Sys& sys;
  std::array<double, 1> rhs(const std::array<double, 1>& y) const { return {sys.f(y[0])}; }
};

// Explicit Euler in y on sys and in ybar = Psi(y) on `field` (the transformed equation (3), or a
// field to be checked against it), both from y0.
template <class Sys, class Psi, class Field>
ScalarFigure scalar_figure(const Sys& sys, const Psi& psi, const Field& field, double y0, double h, std::int64_t steps) {
  ScalarFigure fig;
  double y = y0, ybar = psi(y0);
  ErrorSeries euler_err, compensated_err, compensated_odeint_err, odeint_err;
  for (std::int64_t j = 0; j <= steps; ++j) {
    const double t = static_cast<double>(j) * h;
    const double exact = sys.exact(y0, t);
    const double y_comp = psi.inverse(ybar);
    const double reference =
        j == 0 ? y0
               : reference_solution(ScalarODE<Sys>{sys}, std::array<double, 1>{y0}, t, kReferenceTolerance,
                                    kReferenceTolerance)[0];
    euler_err.add(relative_error(y, exact));
    compensated_err.add(relative_error(y_comp, exact));
    compensated_odeint_err.add(relative_error(y_comp, reference));
    odeint_err.add(relative_error(reference, exact));
    fig.trajectory.row(j, t, exact, y, y_comp, psi(exact), psi(y), ybar);
    y = explicit_euler(sys, y, h);
    ybar = explicit_euler(field, ybar, h);
  }
  fig.euler_max_rel_err = euler_err.max_abs();
  fig.compensated_max_rel_err = compensated_err.max_abs();
  fig.compensated_max_rel_err_odeint = compensated_odeint_err.max_abs();
  fig.odeint_max_rel_err = odeint_err.max_abs();
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

// The methods of Figs 8 and 9, by registry name: symplectic Euler in the
// coordinates of (82) needs the k of (82); the others come from the dispatch.
template <class Sys, class F>
auto with_oscillator_method(std::string_view name, const Sys& osc, double k, F&& f) {
  if (method_info(name).name == CompensatedSymplecticEuler::info.name)
    return f(CompensatedSymplecticEuler::bind(osc, k));
  return with_method(name, osc, f);
}

// A non-finite state is (82) left undefined (|qhat| >= 1): say where.
void check_finite(const State& z, const std::string& method, std::int64_t j, double h) {
  if (!std::isfinite(z.q[0]) || !std::isfinite(z.p[0]))
    throw IntegrationError(method + ": non-finite state at step " + std::to_string(j) + ", t = " +
                           format_double(static_cast<double>(j) * h) +
                           " (for the compensating transformation (82): |qhat| >= 1; increase oscillator.k or decrease h)");
}

struct EnergyRun {
  double max_err = 0, rms_err = 0;  // of H(q_j, p_j) - H(q_0, p_0), j = 0..N
  std::int64_t force_evals = 0;
  auto fields() { return std::tie(max_err, rms_err, force_evals); }  // (a record of runner/distributed_map.hpp)
};

// One convergence run of a method to t = N h, counting force evaluations.
EnergyRun energy_run(const std::string& method, const State& z0, double h, double k, std::int64_t n) {
  EnergyRun r;
  const Oscillator osc;
  const double H0 = osc.H(z0);
  ErrorSeries e;
  with_oscillator_method(method, Counting<Oscillator>{osc, &r.force_evals}, k, [&](const auto& m) {
    return integrate(m, z0, h, n, [&](std::int64_t j, const State& z) {
      check_finite(z, method, j, h);
      e.add(osc.H(z) - H0);
    });
  });
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

// Max over t_j in [0, N h] of the global error of explicit Euler on a scalar ODE.
template <class Sys>
double euler_max_err(const Sys& sys, double y0, double h, std::int64_t n) {
  ErrorSeries e;
  integrate(one_step_method([&](double y, double dt) { return explicit_euler(sys, y, dt); }), y0, h, n,
            [&](std::int64_t j, double y) { e.add(y - sys.exact(y0, static_cast<double>(j) * h)); });
  return e.max_abs();
}

std::vector<EnergyRun> oscillator_runs(const std::vector<std::string>& methods, const State& z0, double h, double k,
                                       std::int64_t n) {
  std::vector<EnergyRun> runs;
  for (const auto& m : methods) runs.push_back(energy_run(m, z0, h, k, n));
  return runs;
}

// The first wall time at which the work-precision curves of two methods cross (both interpolated
// linearly in log-log between their measured runs), and the error there; nullopt if they do not
// cross where both are measured. Between the merged break points the difference of the log errors
// is linear in log(wall), so a crossing is found exactly.
struct Crossing {
  double wall_s, err;
};
std::optional<Crossing> crossover(const std::vector<CostRun>& a, const std::vector<CostRun>& b) {
  const auto by_wall = [](const CostRun& x, const CostRun& y) { return x.wall_s < y.wall_s; };
  const double lo = std::max(std::min_element(a.begin(), a.end(), by_wall)->wall_s,
                             std::min_element(b.begin(), b.end(), by_wall)->wall_s);
  const double hi = std::min(std::max_element(a.begin(), a.end(), by_wall)->wall_s,
                             std::max_element(b.begin(), b.end(), by_wall)->wall_s);
  if (!(lo < hi)) return std::nullopt;
  std::vector<double> walls{lo, hi};
  for (const auto* runs : {&a, &b})
    for (const CostRun& r : *runs)
      if (lo <= r.wall_s && r.wall_s <= hi) walls.push_back(r.wall_s);
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  std::optional<std::tuple<double, double, double>> prev;  // (wall, log err_a - log err_b, log err_a)
  for (double w : walls) {
    const auto ea = error_at_wall(a, w), eb = error_at_wall(b, w);
    if (!ea || !eb) continue;
    const double la = std::log(*ea), d = la - std::log(*eb);
    if (prev) {
      const auto [w0, d0, la0] = *prev;
      if (d0 == 0) return Crossing{w0, std::exp(la0)};
      if (d0 * d < 0 || d == 0) {
        const double wc = std::exp(std::log(w0) + d0 / (d0 - d) * (std::log(w) - std::log(w0)));
        return Crossing{wc, *error_at_wall(a, wc)};
      }
    }
    prev = std::make_tuple(w, d, la);
  }
  return std::nullopt;
}

// The smallest and largest of a scene's list of steps, and their number.
json h_range(const std::vector<double>& hs) {
  return {{"min", *std::min_element(hs.begin(), hs.end())}, {"max", *std::max_element(hs.begin(), hs.end())}, {"count", hs.size()}};
}

// What Figs 8-9 and the cost study may name: the methods that step the oscillator, and (82).
std::vector<std::string> oscillator_method_choices() {
  auto names = methods_for<Counting<Oscillator>>();
  names.emplace_back(CompensatedSymplecticEuler::info.name);
  return method_choices<Counting<Oscillator>>(names);
}

Schema schema() {
  Schema s;
  s.real("decay.alpha", positive(), "rate alpha of y' = -alpha y (000 eq. (14))")
      .real("decay.y0", positive(), "initial value y(0) > 0")
      .real("decay.h", positive(), "step of explicit Euler (Fig 2); h alpha <= 2 (stability)")
      .integer("decay.steps", at_least(1), "number of steps shown in Fig 2")
      .real("decay.printed_alpha", positive(),
            "alpha at which the transformed field (16) as printed, ybar' = -alpha, is checked against (15) "
            "(they coincide at alpha = 1); h alpha <= 2")
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
      .texts("convergence.methods", oscillator_method_choices(), 1,
             "methods of Fig 9 on the oscillator (registry names or labels); compensated_symplectic_euler uses "
             "oscillator.k")
      .reals("convergence.h", positive(), 3, "steps of the convergence study (Fig 9); each divides t_end")
      .real("convergence.t_end", positive(), "errors are maxima over t in [0, t_end]")
      .texts("timing.methods", oscillator_method_choices(), 1, "methods of the cost study (registry names or labels)")
      .reals("timing.h", positive(), 3, "steps of the work-precision runs (to convergence.t_end)")
      .integer("timing.repeats", at_least(1), "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .integer("timing.steps", at_least(1), "steps of the run that measures ns per step");
  return s;
}

// ---- checks across keys, per study ----

void check_decay(const Scene& s) {
  for (const char* key : {"decay.alpha", "decay.printed_alpha"})
    if (s.real("decay.h") * s.real(key) > method_info("explicit_euler").real_bound)
      s.reject("decay.h", std::string("explicit Euler on y' = -alpha y is unstable for h > 2/alpha = ") +
                              format_double(2.0 / s.real(key)) + " (alpha = " + key + ")");
}

void check_gompertz(const Scene& s) {
  if (s.real("gompertz.h") * s.real("gompertz.b") > method_info("explicit_euler").real_bound)
    s.reject("gompertz.h", "explicit Euler is unstable at the Gompertz equilibrium for h > 2/b = " +
                               format_double(2.0 / s.real("gompertz.b")));
  if (std::log(s.real("gompertz.y0")) >= s.real("gompertz.a") / s.real("gompertz.b"))
    s.reject("gompertz.y0", "the transformation (18) needs 0 < y0 < e^{a/b}");
}

// A step h of Fig 8: symplectic Euler stable, the transformation (82) defined at q0.
void check_oscillator_step(const Scene& s, const char* key, double h) {
  check_oscillatory_bound(s, key, key, "symplectic_euler_pq", h, "omega = 1");
  if (!OscillatorCompensation{s.real("oscillator.k"), h}.defined(s.real("oscillator.q0")))
    s.reject(key, "the transformation (82) needs |q0| < 1 + k h^2 = " +
                      format_double(1 + s.real("oscillator.k") * h * h));
}

// The methods of `methods_key` at the steps of `key` (runs to convergence.t_end): each method
// once, every step below its bound (and (82) defined, if named), and each h dividing t_end.
void check_steps(const Scene& s, const char* key, const char* methods_key) {
  check_distinct_methods(s, methods_key);
  const double t_end = s.real("convergence.t_end");
  for (double h : s.reals(key)) {
    if (!(t_end / h <= max_exact_count))
      s.reject(key, "at most 2^53 steps to convergence.t_end = " + format_double(t_end) + ", here h = " + format_double(h));
    for (const auto& m : s.texts(methods_key)) {
      if (method_info(m).name == CompensatedSymplecticEuler::info.name) check_oscillator_step(s, key, h);
      else check_oscillatory_bound(s, key, methods_key, m, h, "omega = 1");
    }
    const double n = static_cast<double>(steps_to(t_end, h));
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end)
      s.reject(key, "each h must divide convergence.t_end = " + format_double(t_end));
  }
}

State initial_state(const Scene& s) { return make_state(s.real("oscillator.q0"), s.real("oscillator.p0")); }

// ---- Fig 2 and Fig 3 ----

// Writes <figure>.csv and <figure>_exact.csv, and the errors of Euler in y and in ybar under <key>_*
// (the paper calls the latter an exact solution: published.toml).
template <class Sys, class Psi>
void write_scalar_figure(Context& ctx, const std::string& figure, const std::string& key, const Sys& sys,
                         const Psi& psi, double y0, double h, std::int64_t steps) {
  const ScalarFigure fig = scalar_figure(sys, psi, TransformedODE{sys, psi}, y0, h, steps);  // 000 eq. (3)
  ctx.write(figure + ".csv", fig.trajectory);
  ctx.write(figure + "_exact.csv", fig.exact);
  ctx.summary["reproduced"][key + "_compensated_max_rel_err"] = fig.compensated_max_rel_err;
  ctx.summary["reproduced"][key + "_euler_max_rel_err"] = fig.euler_max_rel_err;
  ctx.summary["reproduced"][key + "_compensated_max_rel_err_odeint"] = fig.compensated_max_rel_err_odeint;
  ctx.summary["reproduced"][key + "_odeint_max_rel_err"] = fig.odeint_max_rel_err;
}

void run_decay(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 2: explicit Euler in y and ybar");
  const ExponentialDecay decay{s.real("decay.alpha")};
  write_scalar_figure(ctx, "fig2_decay", "decay", decay, DecayCompensation{decay.alpha}, s.real("decay.y0"),
                      s.real("decay.h"), s.integer("decay.steps"));
  // (16) as printed, ybar' = -alpha, in place of the field of (15), at decay.printed_alpha (at the
  // alpha = 1 of Fig 2 the two coincide): the error of Euler in ybar mapped back by (15).
  const ExponentialDecay check{s.real("decay.printed_alpha")};
  ctx.summary["reproduced"]["decay_printed_field_max_rel_err"] =
      scalar_figure(check, DecayCompensation{check.alpha}, DecayFieldAsPrinted16{check.alpha}, s.real("decay.y0"),
                    s.real("decay.h"), s.integer("decay.steps"))
          .compensated_max_rel_err;
}

void run_gompertz(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 3: explicit Euler in y and ybar");
  const Gompertz gompertz{s.real("gompertz.a"), s.real("gompertz.b")};
  const double y0 = s.real("gompertz.y0");
  write_scalar_figure(ctx, "fig3_gompertz", "gompertz", gompertz, GompertzCompensation{gompertz.a, gompertz.b, y0},
                      y0, s.real("gompertz.h"), s.integer("gompertz.steps"));
}

// ---- Fig 8: phase portraits over oscillator.steps steps ----

void run_oscillator(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 8: phase portraits");
  const Oscillator osc;
  const State z0 = initial_state(s);
  const double H0 = osc.H(z0);
  const double h = s.real("oscillator.h"), k = s.real("oscillator.k");
  const auto se = SymplecticEulerPQ::bind(osc);
  const auto compensated = CompensatedSymplecticEuler::bind(osc, k);
  Csv phase({"j", "t", "q_se", "p_se", "q_compensated", "p_compensated", "energy_err_se", "energy_err_compensated"});
  const std::int64_t n = s.integer("oscillator.steps");
  std::vector<State> zs;
  integrate(se, z0, h, n, [&](std::int64_t, const State& z) { zs.push_back(z); });
  ErrorSeries err_se, err_comp;
  double max_qhat = 0;
  integrate(compensated, z0, h, n, [&](std::int64_t j, const State& zc) {
    check_finite(zc, "compensated_symplectic_euler", j, h);
    const State& z = zs[static_cast<std::size_t>(j)];
    const double e_se = osc.H(z) - H0, e_comp = osc.H(zc) - H0;
    err_se.add(e_se), err_comp.add(e_comp);
    max_qhat = std::max(max_qhat, std::abs(OscillatorCompensation{k, h}.qhat(zc.q[0])));
    phase.row(j, static_cast<double>(j) * h, z.q[0], z.p[0], zc.q[0], zc.p[0], e_se, e_comp);
  });
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
  const auto methods = s.texts("convergence.methods");
  struct Row {
    std::vector<EnergyRun> osc;  // one per method
    double ee_decay, ee_gompertz;
    auto fields() { return std::tie(osc, ee_decay, ee_gompertz); }
  };
  const auto rows = distributed_map(hs.size(), [&](std::size_t i) {
    const double h = hs[i];
    const std::int64_t n = steps_to(t_end, h);
    return Row{oscillator_runs(methods, z0, h, k, n), euler_max_err(decay, s.real("decay.y0"), h, n),
               euler_max_err(gompertz, gy0, h, n)};
  });
  // Columns: h, steps, then per method (by label) the max and the eq. (50) errors and the force evaluations.
  std::vector<std::string> columns{"h", "steps"};
  for (const char* suffix : {"_max", "_rms", "_evals"})
    for (const auto& m : methods) columns.push_back(label_of(m) + suffix);
  columns.insert(columns.end(), {"ee_decay_max", "ee_gompertz_max"});
  Csv conv(columns);
  std::vector<std::vector<double>> max_err(methods.size()), rms_err(methods.size());
  std::vector<double> ee_decay, ee_gompertz;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const auto& runs = rows[i].osc;
    conv << hs[i] << steps_to(t_end, hs[i]);
    for (const auto& r : runs) conv << r.max_err;
    for (const auto& r : runs) conv << r.rms_err;
    for (const auto& r : runs) conv << r.force_evals;
    conv.row(rows[i].ee_decay, rows[i].ee_gompertz);
    for (std::size_t m = 0; m < methods.size(); ++m)
      max_err[m].push_back(runs[m].max_err), rms_err[m].push_back(runs[m].rms_err);
    ee_decay.push_back(rows[i].ee_decay), ee_gompertz.push_back(rows[i].ee_gompertz);
  }
  ctx.write("fig9_convergence.csv", conv);

  // Orders: least squares on log-log over the points above round-off.
  const double floor = roundoff_floor(std::max(H0, 1.0));
  Csv order_csv({"name", "order", "log10_c", "r2", "points", "h_min", "h_max"});
  json orders, fits;
  const auto fit = [&](const std::string& name, const std::vector<double>& err, double fit_floor) {
    const OrderFit f = fit_order(hs, err, fit_floor);
    orders[name] = f.order;
    fits[name] = to_json(f);
    order_csv.row(name, f.order, f.log10_c, f.r2, f.points, f.h_min, f.h_max);
  };
  fit("ee_decay", ee_decay, roundoff_floor(s.real("decay.y0")));
  fit("ee_gompertz", ee_gompertz, roundoff_floor(gompertz.equilibrium()));
  for (std::size_t m = 0; m < methods.size(); ++m) fit(label_of(methods[m]) + "_energy", max_err[m], floor);
  for (std::size_t m = 0; m < methods.size(); ++m) fit(label_of(methods[m]) + "_energy_rms", rms_err[m], floor);
  ctx.write("orders.csv", order_csv);
  ctx.summary["orders"] = orders;
  ctx.summary["fits"] = fits;
  ctx.summary["norms"] = {
      {"energy", "max over t_j = j h in [0, convergence.t_end] of |H(q_j, p_j) - H(q_0, p_0)|; *_rms: eq. (50)"},
      {"ee", "max over t_j in [0, convergence.t_end] of |y_j - y(t_j)|"},
      {"compensated_max_rel_err", "max over the steps of Figs 2/3 of |Psi^{-1}(ybar_j) - y(t_j)| / |y(t_j)|"},
      {"compensated_max_rel_err_odeint", "the same with y(t_j) from odeint's Bulirsch-Stoer at rtol = atol = 1e-14"},
      {"odeint_max_rel_err", "max over the steps of Figs 2/3 of |y_odeint(t_j) - y(t_j)| / |y(t_j)|"}};
  ctx.summary["h_range"]["convergence"] = h_range(hs);
}

// ---- What the accuracy costs: wall time (runner/timing.hpp) of each method to t_end over
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
  const auto methods = s.texts("timing.methods");
  SpreadTally spreads;
  const auto timed = [&](const std::string& method, double h, std::int64_t n) {
    const RunTime t = with_oscillator_method(method, osc, k, [&](const auto& m) {
      return time_runs(repeats, [&] { do_not_optimize(integrate_inlined(m, z0, h, n)); });
    });
    spreads.add(t);
    return t;
  };
  const auto timing_hs = s.reals("timing.h");
  const auto timing_runs = distributed_map(timing_hs.size(), [&](std::size_t i) {
    return oscillator_runs(methods, z0, timing_hs[i], k, steps_to(t_end, timing_hs[i]));
  });
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "energy_err_max", "wall_spread"});
  std::vector<std::vector<CostRun>> curves(methods.size());  // per method: the runs of timing.h
  for (std::size_t i = 0; i < timing_hs.size(); ++i) {
    const double h = timing_hs[i];
    const std::int64_t n = steps_to(t_end, h);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const RunTime t = timed(methods[m], h, n);
      const double wall = t.seconds();
      const EnergyRun& r = timing_runs[i][m];
      cost.row(label_of(methods[m]), h, n, wall, 1e9 * wall / static_cast<double>(n), r.force_evals, r.max_err,
               t.spread());
      curves[m].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.force_evals), r.max_err});
    }
  }
  ctx.write("timing.csv", cost);

  json& timing = ctx.summary["timing"];
  const double h8 = s.real("oscillator.h");
  const std::int64_t n_timing = s.integer("timing.steps");
  json ns_per_step, ns_spread;
  for (const auto& m : methods) {
    const RunTime t = timed(m, h8, n_timing);
    ns_per_step[label_of(m)] = 1e9 * t.seconds() / static_cast<double>(n_timing);
    ns_spread[label_of(m)] = t.spread();
  }
  timing["ns_per_step"] = ns_per_step;
  timing["ns_per_step_spread"] = ns_spread;
  json relative;  // ns per step relative to the first method of timing.methods
  for (const auto& m : methods)
    relative[label_of(m)] = ns_per_step[label_of(m)].get<double>() / ns_per_step[label_of(methods[0])].get<double>();
  timing["relative_cost"] = relative;
  if (ns_per_step.contains("se") && ns_per_step.contains("se_compensated"))
    timing["ns_per_step_ratio_compensated_over_se"] =
        ns_per_step["se_compensated"].get<double>() / ns_per_step["se"].get<double>();
  timing["method"] = timing_method_text(repeats) + "; ns_per_step at oscillator.h over timing.steps steps";
  timing["spread"] = spreads.to_json();  // of every timed measurement of the study
  // Error at equal wall time: at the geometric middle of the wall-time range
  // that all methods cover.
  double w_lo = 0, w_hi = std::numeric_limits<double>::infinity();
  for (const auto& curve : curves) {
    const auto [lo, hi] = std::minmax_element(curve.begin(), curve.end(),
                                              [](const CostRun& a, const CostRun& b) { return a.wall_s < b.wall_s; });
    w_lo = std::max(w_lo, lo->wall_s), w_hi = std::min(w_hi, hi->wall_s);
  }
  const auto or_null = [](std::optional<double> v) { return v ? json(*v) : json(nullptr); };
  if (w_lo < w_hi) {
    const double w_star = std::sqrt(w_lo * w_hi);
    json at_wall{{"wall_s", w_star}};
    for (std::size_t m = 0; m < methods.size(); ++m) at_wall[label_of(methods[m])] = or_null(error_at_wall(curves[m], w_star));
    timing["error_at_equal_wall_time"] = at_wall;
  } else {
    timing["error_at_equal_wall_time"] = nullptr;  // timing.h gives no common wall-time range
  }
  // Where the work-precision curves of the first two methods cross (null: not in the measured range).
  const auto cross = methods.size() > 1 ? crossover(curves[0], curves[1]) : std::nullopt;
  timing["crossover"] = cross ? json{{"methods", {label_of(methods[0]), label_of(methods[1])}},
                                     {"wall_s", cross->wall_s}, {"err", cross->err}}
                              : json(nullptr);
  ctx.summary["h_range"]["timing"] = h_range(timing_hs);
}

// ---- What each study would cost (--plan), from the scene before any work ----
// Steps in double; ns per step are constants measured on the paper scene (results/euler_compensation,
// summary timing.ns_per_step: symplectic Euler with (82), the most expensive, for the oscillator; study
// wall time over its steps for Figs 2, 3).

constexpr double kCellBytes = 24;        // one CSV cell held in memory
constexpr double kOscillatorNs = 272;    // compensated symplectic Euler (82), the most expensive method
constexpr double kScalarNs = 5000;       // Figs 2, 3: a step with its odeint reference from t = 0
constexpr double kEvalsPerStep = 4;      // the most of the paper scene's methods (rk4)

// Figs 2, 3: the steps of Euler in y and in ybar, and the trajectory CSV (8 columns) held in memory.
StudyPlan plan_scalar(double steps, double figures) {
  return {2 * figures * steps, 2 * figures * steps, (steps + 1) * 8 * kCellBytes, kScalarNs,
          "each step also integrates its odeint reference from t = 0 (not counted); ns per step: paper-scene "
          "study wall time over its steps"};
}

StudyPlan plan_decay(const Scene& s) { return plan_scalar(static_cast<double>(s.integer("decay.steps")), 2); }
StudyPlan plan_gompertz(const Scene& s) { return plan_scalar(static_cast<double>(s.integer("gompertz.steps")), 1); }

StudyPlan plan_oscillator(const Scene& s) {
  const double n = static_cast<double>(s.integer("oscillator.steps"));
  return {2 * n, 2 * n, (n + 1) * (sizeof(State) + 8 * kCellBytes), kOscillatorNs,
          "ns per step: symplectic Euler with (82) (paper-scene summary timing.ns_per_step)"};
}

double steps_to_t_end(const Scene& s, const char* key) {
  double steps = 0;
  for (double h : s.reals(key)) steps += s.real("convergence.t_end") / h;
  return steps;
}

StudyPlan plan_convergence(const Scene& s) {
  const double methods = static_cast<double>(s.texts("convergence.methods").size());
  const double steps = (methods + 2) * steps_to_t_end(s, "convergence.h");  // and Euler on (14), (17)
  return {steps, steps * kEvalsPerStep, static_cast<double>(s.reals("convergence.h").size()) * (4 + 3 * methods) * kCellBytes,
          kOscillatorNs, "ns per step: symplectic Euler with (82) (paper-scene summary timing.ns_per_step)"};
}

StudyPlan plan_timing(const Scene& s) {
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double counted = methods * steps_to_t_end(s, "timing.h");
  const double steps = counted * (1 + repeats) + methods * repeats * static_cast<double>(s.integer("timing.steps"));
  return {steps, counted * kEvalsPerStep, methods * static_cast<double>(s.reals("timing.h").size()) * 8 * kCellBytes,
          kOscillatorNs, "timed runs of < 10 ms are repeated to 10 ms (not counted); ns per step: symplectic Euler "
          "with (82) (paper-scene summary timing.ns_per_step)"};
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"euler_compensation",
                      "000 Figs 2, 3, 8, 9: order compensation by a change of variables (explicit Euler) "
                      "and by a change of coordinates (symplectic Euler)",
                      schema(),
                      {}};
  spec.studies = {
      {"decay", "000 Fig 2", {"fig2_decay.csv", "fig2_decay_exact.csv"}, {"decay"}, check_decay, run_decay, plan_decay},
      {"gompertz", "000 Fig 3", {"fig3_gompertz.csv", "fig3_gompertz_exact.csv"}, {"gompertz"}, check_gompertz,
       run_gompertz, plan_gompertz},
      {"oscillator", "000 Fig 8", {"fig8_phase.csv", "fig8_exact.csv"}, {"oscillator"},
       [](const Scene& s) { check_oscillator_step(s, "oscillator.h", s.real("oscillator.h")); }, run_oscillator, plan_oscillator},
      {"convergence", "000 Fig 9", {"fig9_convergence.csv", "orders.csv"},
       {"convergence", "oscillator.q0", "oscillator.p0", "oscillator.k", "decay.alpha", "decay.y0", "gompertz.a",
        "gompertz.b", "gompertz.y0"},
       [](const Scene& s) { check_steps(s, "convergence.h", "convergence.methods"); }, run_convergence, plan_convergence},
      {"timing", "cost: error against wall time and force evaluations", {"timing.csv"},
       {"timing", "convergence.t_end", "oscillator.q0", "oscillator.p0", "oscillator.k", "oscillator.h"},
       [](const Scene& s) { check_steps(s, "timing.h", "timing.methods"); }, run_timing, plan_timing},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
