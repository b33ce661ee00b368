// lobatto_table: 001 (Dubois & Rojas-Quintero 2025) Table 1, Figs 1, 2 -- the
// Lobatto variational integrator built from its definition (P3 elements,
// quadrature (2), elimination of the internal values, momenta (11)), against
// the methods the scene names (001: Simpson's variational integrator and the
// implicit midpoint rule); its stability set; its extension to nonlinear
// Lagrangians (Newton); and what the accuracy costs.
//
// Studies: table1 (Table 1), figure1 (Fig. 1), long_run (Fig. 2), stability,
// nonlinear, timing. The compared methods are registry names
// (methods/registry.hpp); CSV columns and summary keys carry their labels.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/compensated_sum.hpp"
#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/drift.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/published.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

using Z1 = PhaseState<1>;
// The largest linear frequency of the nonlinear pendulum (U'' = cos q <= 1) and of the elastic
// pendulum of the paper scene (sqrt(k/m) = 1): the h omega at which the registry's bounds apply.
constexpr double kNonlinearOmega = 1.0;
// A scan point of the stability study is stable if the spectral radius is at most 1 + this.
constexpr double kRadiusTolerance = 1e-12;
// A run at the stability bound counts as diverged when |(p, q)| exceeds this many times q(0).
constexpr double kDivergedFactor = 1e6;
// The runs around the first loss of stability: these multiples of the bound.
constexpr double kBoundFactors[] = {0.99, 1.01};
// Errors of the nonlinear study below this many times the reference's absolute tolerance are not fitted.
constexpr double kReferenceFloorFactor = 100;

// 001 eq. (15) from the computed map: H_d = (Phi_qp p^2 - Phi_pq q^2) / 2, i.e. c/(2 delta) p^2 - b/(2 delta) q^2.
double discrete_energy(const Mat<2>& Phi, const Z1& z) {
  return 0.5 * (Phi(1, 0) * z.p[0] * z.p[0] - Phi(0, 1) * z.q[0] * z.q[0]);
}

// The one-step matrix of (the kernel of) a registered method on the oscillator at step h,
// in 001's order (p, q) of eq. (13): Phi of the Lobatto scheme, with which (15) and (13) are written.
Mat<2> pq_matrix(const std::string& method, const HarmonicOscillator& osc, double h) {
  return with_kernel(method, osc, [&](const auto& m) { return in_pq_order(one_step_matrix(m, h)); });
}

Mat<2> lobatto_matrix(const HarmonicOscillator& osc, double h) { return pq_matrix("lobatto", osc, h); }

// Adds `values` to the summary section `section` (other studies may have filled it already).
void merge(Context& ctx, const char* section, const json& values) {
  for (const auto& [k, v] : values.items()) ctx.summary[section][k] = v;
}

// The labels of registered methods (CSV columns, summary keys), for summary.methods.<study>.
json labels(const std::vector<std::string>& methods) {
  json l = json::array();
  for (const auto& m : methods) l.push_back(label_of(m));
  return l;
}

// {min, max} of values.
json range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

// ---- the scene ----

Schema schema() {
  Schema s;
  s.real("oscillator.m", positive(), "mass m (001: 1)")
      .real("oscillator.omega", positive(), "angular frequency (001: 2 pi, period T = 1)")
      .real("oscillator.amplitude", positive(), "q(0); p(0) = 0 (001: pi/2)")
      .reals("meshes", at_least(1), 3, "steps per period N of Table 1 (001: 10, 20, 40)")
      .texts("table1.methods", methods_for<HarmonicOscillator>(), 0,
             "methods compared with Lobatto in Table 1 (max error of q; 001: simpson, implicit_midpoint)")
      .reals("figure1.meshes", at_least(1), 1, "steps per period of Fig. 1 (001: 3, 10)")
      .texts("figure1.methods", methods_for<HarmonicOscillator>(), 1,
             "methods drawn in Fig. 1 (001: lobatto, simpson, implicit_midpoint)")
      .real("long_run.periods", at_least(1), "periods of Fig. 2 (001: 1e5)")
      .reals("long_run.h", positive(), 1, "steps of Fig. 2 (001: 0.1, 0.05, 0.025)")
      .integer("long_run.windows", at_least(2), "windows for the maxima of the energy error")
      .real("stability.hw_min", positive(), "scan of the spectral radius over h omega")
      .real("stability.hw_max", positive(), "")
      .integer("stability.points", at_least(2), "")
      .texts("stability.methods", methods_for<HarmonicOscillator>(), 0,
             "methods whose kernel's spectral radius is scanned with Lobatto's")
      .reals("nonlinear.h", positive(), 3, "steps of the nonlinear convergence study")
      .real("nonlinear.t_end", positive(), "end time of the nonlinear runs")
      .real("nonlinear.pendulum_q0", any_finite(), "initial angle of L = qdot^2/2 + cos q (p(0) = 0)")
      .real("nonlinear.elastic.l", positive(), "elastic pendulum: relaxed length of the spring")
      .real("nonlinear.elastic.m", positive(), "elastic pendulum: mass")
      .real("nonlinear.elastic.k", positive(), "elastic pendulum: spring stiffness")
      .real("nonlinear.elastic.g", non_negative(), "elastic pendulum: gravity (y pointing down)")
      .real_rows("nonlinear.elastic_initial", 4, any_finite(), 1, "elastic pendulum [x, y, px, py]")
      .texts("nonlinear.methods", methods_for<NonlinearPendulum>(), 0,
             "methods compared with Lobatto on the nonlinear pendulum")
      .real("reference.rtol", tolerance(), "tolerances of the odeint Bulirsch-Stoer reference")
      .real("reference.atol", tolerance(), "")
      .integer("timing.repeats", at_least(1), "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .texts("timing.methods", methods_for<NonlinearPendulum>(), 1,
             "methods timed on the nonlinear pendulum at the steps nonlinear.h, against its reference")
      .reals("timing.error_targets", positive(), 1,
             "errors whose cost (wall time, force evaluations) each method's runs are asked for")
      .text("timing.equal_wall", methods_for<NonlinearPendulum>(),
            "the method of timing.methods whose most expensive run sets the wall time of the comparison at equal cost")
      .texts("long_run_cost.methods", methods_for<HarmonicOscillator>(), 1,
             "methods whose cost is measured on the oscillator of Fig. 2 over long_run.periods periods (001: lobatto, "
             "simpson, implicit_midpoint)")
      .reals("long_run_cost.h", positive(), 3, "steps of the long-run work-precision study")
      .reals("long_run_cost.error_targets", positive(), 1,
             "phase errors at the end of the long run whose cost (wall time, force evaluations) each method is asked for")
      .integer("long_run_cost.timing_steps", at_least(1),
               "steps of the timed segment; a long run's wall time is its steps times the time per step measured on it")
      .integer("checkpoint.stop_after", non_negative(),
               "long_run_cost: stop after this many rounds of its runs, leaving a checkpoint for --resume (0: run to the "
               "end)")
      .real("checkpoint.interval", non_negative(), "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work");
  return s;
}

// ---- checks across keys, per study ----

// The Lobatto scheme at h omega = hw (001 eq. (10)).
void check_lobatto(const Scene& s, const char* key, double hw, const std::string& what) {
  check_oscillatory_bound(s, key, key, "lobatto", hw, what + "; 001 eq. (10)", "sqrt(42 - 6 sqrt(29))");
}

// Whole numbers of steps per period N at `key`; Lobatto (the subject, if `lobatto`) and the
// methods of `methods_key` stable at h omega = 2 pi / N.
void check_meshes(const Scene& s, const char* key, const char* methods_key, bool lobatto) {
  for (double n : s.reals(key)) {
    if (n != std::floor(n)) s.reject(key, "every entry must be a whole number of steps per period");
    const double hw = 2 * std::numbers::pi / n;
    const std::string what = "h omega = 2 pi / N at N = " + format_double(n);
    if (lobatto) check_lobatto(s, key, hw, what);
    for (const auto& m : s.texts(methods_key)) check_oscillatory_bound(s, key, methods_key, m, hw, what);
  }
}

void check_table1(const Scene& s) {
  check_distinct_methods(s, "table1.methods");
  check_meshes(s, "meshes", "table1.methods", true);
}

void check_figure1(const Scene& s) {
  check_distinct_methods(s, "figure1.methods");
  check_meshes(s, "figure1.meshes", "figure1.methods", false);
}

void check_long_run(const Scene& s) {
  for (double h : s.reals("long_run.h"))
    check_lobatto(s, "long_run.h", h * s.real("oscillator.omega"), "h = " + format_double(h));
}

void check_stability(const Scene& s) {
  check_distinct_methods(s, "stability.methods");
  if (!(s.real("stability.hw_max") > s.real("stability.hw_min"))) s.reject("stability.hw_max", "must exceed stability.hw_min");
}

// `method` (of `methods_key`) stable at every step of nonlinear.h, at the pendulums' linear frequency 1.
void check_pendulum_steps(const Scene& s, const char* methods_key, const std::string& method) {
  for (double h : s.reals("nonlinear.h"))
    check_oscillatory_bound(s, "nonlinear.h", methods_key, method, h * kNonlinearOmega, "h = " + format_double(h) + ", frequency 1");
}

// Every step of nonlinear.h divides nonlinear.t_end (the runs end at t_end, where the reference is),
// checked in double before the step count is rounded to an integer.
void check_nonlinear_steps(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  for (double h : s.reals("nonlinear.h")) {
    const double n = t_end / h;
    if (!(n <= max_exact_count)) s.reject("nonlinear.h", "at most 2^53 steps to nonlinear.t_end, here h = " + format_double(h));
    if (std::round(n) < 1 || std::abs(std::round(n) * h - t_end) > 1e-9 * t_end)
      s.reject("nonlinear.h", "each h must divide nonlinear.t_end = " + format_double(t_end) + ", here h = " + format_double(h));
  }
}

void check_nonlinear(const Scene& s) {
  check_distinct_methods(s, "nonlinear.methods");
  check_nonlinear_steps(s);
  const auto e = s.real_rows("nonlinear.elastic_initial")[0];
  if (std::hypot(e[0], e[1]) == 0.0) s.reject("nonlinear.elastic_initial", "the spring force is singular at x = y = 0");
  for (double h : s.reals("nonlinear.h"))
    check_lobatto(s, "nonlinear.h", h * kNonlinearOmega, "h = " + format_double(h) + ", frequency 1");
  for (const auto& m : s.texts("nonlinear.methods")) check_pendulum_steps(s, "nonlinear.methods", m);
}

void check_long_run_cost(const Scene& s) {
  check_distinct_methods(s, "long_run_cost.methods");
  for (double h : s.reals("long_run_cost.h")) {
    const double hw = h * s.real("oscillator.omega");
    const std::string what = "h = " + format_double(h);
    for (const auto& m : s.texts("long_run_cost.methods"))
      check_oscillatory_bound(s, "long_run_cost.h", "long_run_cost.methods", m, hw, what);
  }
}

void check_timing(const Scene& s) {
  check_distinct_methods(s, "timing.methods");
  check_nonlinear_steps(s);
  for (const auto& m : s.texts("timing.methods")) check_pendulum_steps(s, "timing.methods", m);
  const auto timed = s.texts("timing.methods");
  if (std::find(timed.begin(), timed.end(), s.text("timing.equal_wall")) == timed.end())
    s.reject("timing.equal_wall", "one of timing.methods");
}

// ---- the oscillator of Table 1 and Figs 1, 2 ----

struct Oscillator {
  HarmonicOscillator osc;
  double A, T;  // amplitude q(0), period 2 pi / omega
  Z1 z0;        // (q, p) = (A, 0)
};

Oscillator oscillator(const Scene& s) {
  const HarmonicOscillator osc{s.real("oscillator.m"), s.real("oscillator.omega")};
  const double A = s.real("oscillator.amplitude");
  return {osc, A, 2 * std::numbers::pi / osc.w, make_state(A, 0.0)};
}

// The trajectory z_0..z_n of a registered method.
template <class Sys>
std::vector<Z1> trajectory(const std::string& method, const Sys& sys, const Z1& z0, double h, std::int64_t n) {
  std::vector<Z1> zs;
  with_method(method, sys, [&](const auto& m) {
    integrate(m, z0, h, n, [&](std::int64_t, const Z1& z) { zs.push_back(z); });
  });
  return zs;
}

// ---- Table 1: one period from q = A, p = 0, max over the steps of |error| (absolute) ----

// max_{j = 1..N} |q_j - q(t_j)| of the trajectory z_0..z_N.
double max_q_error(const std::vector<Z1>& zs, const Oscillator& o, double h) {
  double e = 0;
  for (std::size_t j = 1; j < zs.size(); ++j)
    e = std::max(e, std::abs(zs[j].q[0] - o.osc.exact(o.z0, static_cast<double>(j) * h).q[0]));
  return e;
}

// z_0..z_N of a linear one-step matrix Phi on (p, q), 001's order of eq. (13).
std::vector<Z1> iterate_pq(const Mat<2>& Phi, const Z1& z0, std::int64_t N) {
  std::vector<Z1> zs = {z0};
  Vec<2> x(z0.p[0], z0.q[0]);
  for (std::int64_t j = 1; j <= N; ++j) x = Phi * x, zs.push_back(make_state(x[1], x[0]));
  return zs;
}

// Does `reproduced` round to the printed value with its `digits` significant digits?
bool rounds_to_printed(double printed, double reproduced, int digits) {
  char a[32], b[32];
  std::snprintf(a, sizeof a, "%.*e", digits - 1, printed);
  std::snprintf(b, sizeof b, "%.*e", digits - 1, reproduced);
  return std::string(a) == b;
}

// The comparison with what 001 printed (published.toml, as the runner makes it after the run) of the
// entry whose reproduced value is at `summary_key`, for the text; nullopt if there is none or this
// scene cannot make it.
const std::vector<Published>& published_entries() {  // read once (the runner has read and checked it already)
  static const std::vector<Published> entries =
      read_published(std::filesystem::path(GEOMINT_EXPERIMENT_DIR) / "published.toml");
  return entries;
}

std::optional<json> comparison(const json& summary, const Scene& s, const std::string& summary_key) {
  for (const Published& e : published_entries()) {
    if (e.summary != summary_key) continue;
    auto c = compare_published(e, summary, s.to_json(), {e.study});
    if (c && c->contains("difference")) return c;
  }
  return std::nullopt;
}

// Table 1 against the printed values: how many of the errors of p, q and H round to the three printed
// digits, the largest relative deviation, and the range of the printed H_d errors (round-off, compared apart).
json printed_table1(const json& summary, const Scene& s) {
  int compared = 0, rounding = 0;
  double deviation = 0;
  std::vector<double> printed_Hd;
  for (double Nd : s.reals("meshes")) {
    const std::string n = std::to_string(static_cast<std::int64_t>(Nd));
    for (const char* prefix : {"p", "q", "H", "Hd"}) {
      const auto c = comparison(summary, s, std::string("reproduced.") + prefix + "_err_N" + n);
      if (!c) continue;
      const double printed = (*c)["published"], reproduced = (*c)["reproduced"];
      if (std::string(prefix) == "Hd") {
        printed_Hd.push_back(printed);
      } else {
        ++compared, rounding += rounds_to_printed(printed, reproduced, 3);
        deviation = std::max(deviation, std::abs((*c)["difference"].get<double>()));  // (relative: compare = rel)
      }
    }
  }
  json out = {{"compared", compared}, {"round_to_printed_digits", rounding}, {"max_relative_deviation", deviation}};
  if (!printed_Hd.empty()) out["Hd_err_range"] = range_of(printed_Hd);
  return out;
}

void run_table1(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Table 1");
  const Oscillator o = oscillator(s);
  const auto& [osc, A, T, z0] = o;
  const auto methods = s.texts("table1.methods");
  std::vector<std::string> columns = {"N", "h", "p_err", "q_err", "H_err", "Hd_err"};
  for (const auto& m : methods) columns.push_back(label_of(m) + "_q_err");
  Csv t1(columns);
  std::vector<double> hs, ep, eq, eH, eHd, Hd0s, e12;
  std::vector<std::vector<double>> em(methods.size());
  json reproduced = json::object();
  for (double Nd : s.reals("meshes")) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    const Mat<2> Phi = lobatto_matrix(osc, h);
    double p = 0, q = 0, H = 0, Hd = 0;
    const auto lobatto = trajectory("lobatto", osc, z0, h, N);
    const double H0 = osc.H(z0), Hd0 = discrete_energy(Phi, z0);
    for (std::int64_t j = 1; j <= N; ++j) {
      const Z1& zl = lobatto[static_cast<std::size_t>(j)];
      const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
      p = std::max(p, std::abs(zl.p[0] - ex.p[0])), q = std::max(q, std::abs(zl.q[0] - ex.q[0]));
      H = std::max(H, std::abs(osc.H(zl) - H0)), Hd = std::max(Hd, std::abs(discrete_energy(Phi, zl) - Hd0));
    }
    t1 << N << h << p << q << H << Hd;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const double e = max_q_error(trajectory(methods[k], osc, z0, h, N), o, h);
      t1 << e;
      em[k].push_back(e);
    }
    t1.end_row();
    const std::string n = std::to_string(N);
    reproduced["p_err_N" + n] = p, reproduced["q_err_N" + n] = q;
    reproduced["H_err_N" + n] = H, reproduced["Hd_err_N" + n] = Hd;
    hs.push_back(h), ep.push_back(p), eq.push_back(q), eH.push_back(H), eHd.push_back(Hd), Hd0s.push_back(Hd0);
    // 001 eq. (12) as printed, iterated as a scheme of its own (it is not (13)-(14): see the unit tests)
    e12.push_back(max_q_error(iterate_pq(lobatto_map_12(h, osc.m, osc.w, Eq12::printed), z0, N), o, h));
  }
  ctx.write("table1.csv", t1);
  const double floor = roundoff_floor();
  json orders = json::object();
  orders["lobatto_p"] = fit_order(hs, ep, floor, "lobatto_p").order;
  orders["lobatto_q"] = fit_order(hs, eq, floor, "lobatto_q").order;
  orders["lobatto_H"] = fit_order(hs, eH, floor, "lobatto_H").order;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::string l = label_of(methods[k]);
    orders[l] = fit_order(hs, em[k], floor, l.c_str()).order;
  }
  orders["lobatto_printed_eq12_q"] = fit_order(hs, e12, floor, "lobatto_printed_eq12_q").order;
  merge(ctx, "reproduced", reproduced);
  merge(ctx, "orders", orders);
  ctx.summary["norms"]["table1"] = "max over the steps j = 1..N of one period of the absolute error (p, q, H, H_d)";
  // H_d(0) (15) per mesh, the H_d errors relative to it and their range; the compared methods' errors;
  // the comparison with the printed digits.
  json relative = json::array();
  for (std::size_t i = 0; i < eHd.size(); ++i) relative.push_back(eHd[i] / Hd0s[i]);
  ctx.summary["methods"]["table1"] = labels(methods);
  json compared = json::object();  // the q errors of the compared methods per mesh, as table1.csv
  for (std::size_t k = 0; k < methods.size(); ++k) compared[label_of(methods[k])] = em[k];
  ctx.summary["table1"] = {{"Hd0", Hd0s},
                           {"Hd_err_relative", relative},
                           {"Hd_err_range", range_of(eHd)},
                           {"q_err", compared},
                           {"printed", printed_table1(ctx.summary, s)}};
}

// ---- Fig. 1: trajectories over one period ----

void run_figure1(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 1");
  const auto [osc, A, T, z0] = oscillator(s);
  const auto methods = s.texts("figure1.methods");
  std::vector<std::string> columns = {"j", "t"};
  for (const auto& m : methods) columns.push_back("q_" + label_of(m)), columns.push_back("p_" + label_of(m));
  json max_error = json::array();  // per mesh and method: max_j |q_j - q(t_j)| and |p_j - p(t_j)|, j = 0..N
  for (double Nd : s.reals("figure1.meshes")) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    std::vector<std::vector<Z1>> zs;
    for (const auto& m : methods) zs.push_back(trajectory(m, osc, z0, h, N));
    Csv f(columns);
    for (std::int64_t j = 0; j <= N; ++j) {
      f << j << static_cast<double>(j) * h;
      for (const auto& z : zs) f << z[static_cast<std::size_t>(j)].q[0] << z[static_cast<std::size_t>(j)].p[0];
      f.end_row();
    }
    ctx.write("fig1_N" + std::to_string(N) + ".csv", f);
    json errors = json::object();
    for (std::size_t k = 0; k < methods.size(); ++k) {
      double eq = 0, ep = 0;
      for (std::int64_t j = 0; j <= N; ++j) {
        const Z1& z = zs[k][static_cast<std::size_t>(j)];
        const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
        eq = std::max(eq, std::abs(z.q[0] - ex.q[0])), ep = std::max(ep, std::abs(z.p[0] - ex.p[0]));
      }
      errors[label_of(methods[k])] = {{"q", eq}, {"p", ep}};
    }
    max_error.push_back(errors);
  }
  Csv fe({"t", "q", "p"});
  for (int i = 0; i <= 400; ++i) {
    const Z1 e = osc.exact(z0, T * i / 400.0);
    fe.row(T * i / 400.0, e.q[0], e.p[0]);
  }
  ctx.write("fig1_exact.csv", fe);
  ctx.summary["methods"]["figure1"] = labels(methods);
  // the amplitude of the exact p = -m w A sin(w t), and the largest errors of the drawn methods
  ctx.summary["figure1"] = {{"p_amplitude", osc.m * osc.w * A}, {"max_error", max_error}};
}

// ---- Fig. 2: the discrete energy over long_run.periods periods, plain and compensated ----

void run_long_run(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 2: long runs");
  const auto [osc, A, T, z0] = oscillator(s);
  const auto long_h = s.reals("long_run.h");
  const std::int64_t windows = s.integer("long_run.windows");
  struct Long {
    std::vector<double> plain, comp, H;       // window maxima
    double slope_plain, slope_comp, slope_H;  // per period
    auto fields() { return std::tie(plain, comp, H, slope_plain, slope_comp, slope_H); }
  };
  const auto longs = distributed_map(long_h.size(), [&](std::size_t i) {
    const double h = long_h[i];
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / h);
    const Mat<2> Phi = lobatto_matrix(osc, h);
    const Mat<2> PhiI = Phi - Mat<2>::Identity();
    const double Hd0 = discrete_energy(Phi, z0), H0 = osc.H(z0);
    WindowMaxima wp(std::max<std::int64_t>(1, n / windows)), wc(std::max<std::int64_t>(1, n / windows)),
        wH(std::max<std::int64_t>(1, n / windows));
    Vec<2> x(z0.p[0], z0.q[0]), y = x, c = Vec<2>::Zero();
    for (std::int64_t j = 1; j <= n; ++j) {
      x = Phi * x;                              // (13)
      compensated_add(y, c, Vec<2>(PhiI * y));  // (13) as y + (Phi - I) y, compensated
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
  // quantity, compared in published.toml), and of |H_d - H_d(0)| with plain and with compensated
  // summation (the round-off of the discrete energy (15)).
  ctx.summary["reproduced"]["energy_growth_rate"] = growth_H;
  ctx.summary["reproduced"]["energy_growth_rate_Hd"] = growth;
  ctx.summary["reproduced"]["energy_growth_rate_Hd_compensated"] = growth_comp;
  // Per step size (by index): the rates again, with the printed one; the largest H_d errors; and the
  // growth rate of the same window maxima in exact arithmetic (the closed-form orbit of (13)-(14)),
  // with what the drift of H_d explains of the difference.
  const auto published = comparison(ctx.summary, s, "reproduced.energy_growth_rate");  // 001 Fig. 2, per h
  json rates = json::array();
  for (std::size_t i = 0; i < long_h.size(); ++i) {
    const double h = long_h[i];
    const Long& l = longs[i];
    json r = {{"h", h}, {"steps_per_period", T / h}, {"H_rate", l.slope_H}, {"Hd_rate", l.slope_plain},
              {"Hd_rate_compensated", l.slope_comp}, {"Hd_err_max", *std::max_element(l.plain.begin(), l.plain.end())},
              {"Hd_err_max_compensated", *std::max_element(l.comp.begin(), l.comp.end())}};
    if (published && published->at("published").contains(format_double(h)))
      r["published_rate"] = published->at("published")[format_double(h)];
    const auto exact = lobatto_exact_growth(h, osc.m, osc.w, A, s.real("long_run.periods"), windows);
    const auto orbit = lobatto_exact_orbit(h, osc.m, osc.w, A);
    if (exact && orbit) {
      r["exact_rate"] = exact->slope_per_period;
      r["H_rate_minus_exact"] = l.slope_H - exact->slope_per_period;
      r["bound"] = exact->bound;  // |K|
      r["periods_to_peak"] = optional_json(exact->periods_to_peak);
      // a drift of H_d seen in H: (H_0 / H_d(0)) |Hd_rate|; and the relative drift of H_d per step
      r["roundoff_in_H"] = orbit->H0 / orbit->Hd0 * std::abs(l.slope_plain);
      r["Hd_drift_per_step"] = std::abs(l.slope_plain) * h / T / orbit->Hd0;
    }
    rates.push_back(r);
  }
  ctx.summary["long_run"] = {{"window_periods", s.real("long_run.periods") / static_cast<double>(windows)}, {"rates", rates}};
}

// ---- Stability: spectral radius of Phi over h omega; the exact stable set ----

bool stable(double rho) { return rho <= 1.0 + kRadiusTolerance; }

// The intervals [lo, hi] of consecutive scan points (h omega) at which the radius is stable.
json stable_intervals(const std::vector<double>& hw, const std::vector<double>& rho) {
  json set = json::array();
  bool in_stable = false;
  double start = 0;
  for (std::size_t i = 0; i < hw.size(); ++i) {
    if (stable(rho[i]) && !in_stable) in_stable = true, start = hw[i];
    if (!stable(rho[i]) && in_stable) in_stable = false, set.push_back({start, hw[i - 1]});
  }
  if (in_stable) set.push_back({start, hw.back()});
  return set;
}

void run_stability(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("stability scan");
  const auto [osc, A, T, z0] = oscillator(s);
  const double hw0 = s.real("stability.hw_min"), hw1 = s.real("stability.hw_max");
  const auto npts = s.integer("stability.points");
  const auto methods = s.texts("stability.methods");
  const auto radius_at = [&](double hw) { return spectral_radius(lobatto_matrix(osc, hw / osc.w)); };
  std::vector<std::string> columns = {"h_omega", "spectral_radius"};
  for (const auto& m : methods) columns.push_back("spectral_radius_" + label_of(m));
  Csv st(columns);
  std::vector<double> hws, rhos;
  std::vector<std::vector<double>> rho_m(methods.size());
  for (std::int64_t i = 0; i < npts; ++i) {
    const double hw = hw0 + (hw1 - hw0) * static_cast<double>(i) / static_cast<double>(npts - 1);
    const double rho = radius_at(hw);
    st << hw << rho;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      rho_m[k].push_back(spectral_radius(pq_matrix(methods[k], osc, hw / osc.w)));
      st << rho_m[k].back();
    }
    st.end_row();
    hws.push_back(hw), rhos.push_back(rho);
  }
  ctx.write("stability.csv", st);
  // The first loss of stability, refined by bisection.
  double lo = hw0, hi = hw1;
  for (std::size_t i = 0; i < hws.size(); ++i) {
    if (!stable(rhos[i])) {
      hi = hws[i];
      break;
    }
    lo = hws[i];
  }
  for (int it = 0; it < 60; ++it) (stable(radius_at(0.5 * (lo + hi))) ? lo : hi) = 0.5 * (lo + hi);
  // Runs of long_run.periods periods at kBoundFactors times the bound: bounded below it, diverged above.
  json runs, run_list = json::array();
  for (double factor : kBoundFactors) {
    const double h = factor * lo / osc.w;
    const Mat<2> Phi = lobatto_matrix(osc, h);
    Vec<2> x(0.0, A);
    const std::int64_t n = std::llround(s.real("long_run.periods") * T / h);
    std::int64_t diverged_at = -1;
    double max_norm = 0;
    for (std::int64_t j = 1; j <= n && diverged_at < 0; ++j) {
      x = Phi * x;
      max_norm = std::max(max_norm, x.norm());
      if (!(x.norm() <= kDivergedFactor * A)) diverged_at = j;
    }
    runs[format_double(factor)] = {{"h_omega", factor * lo}, {"steps", n}, {"diverged_at_step", diverged_at},
                                   {"max_norm_over_initial", max_norm / A}};
    json r = {{"factor", factor}};
    r.update(runs[format_double(factor)]);
    run_list.push_back(r);
  }
  const json stable_set = stable_intervals(hws, rhos);
  ctx.summary["reproduced"]["stability_bound"] = lo;
  ctx.summary["reproduced"]["stable_set_h_omega"] = stable_set;
  ctx.summary["reproduced"]["bound_runs"] = runs;
  // The scan of each compared method; the exact stable set of (13)-(14); the bound as h/T and steps
  // per period; the scan point nearest h omega = pi (h = T/2, the paper's remark after (10)).
  json compared = json::object();
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const json set = stable_intervals(hws, rho_m[k]);
    compared[label_of(methods[k])] = {{"stable_set_h_omega", set}, {"intervals", set.size()}};
  }
  std::size_t near_pi = 0;
  for (std::size_t i = 1; i < hws.size(); ++i)
    if (std::abs(hws[i] - std::numbers::pi) < std::abs(hws[near_pi] - std::numbers::pi)) near_pi = i;
  const double steps_per_period = 2 * std::numbers::pi / lo;  // N = T/h = 2 pi / (h omega)
  ctx.summary["methods"]["stability"] = labels(methods);
  ctx.summary["stability"] = {
      {"grid_step", (hw1 - hw0) / static_cast<double>(npts - 1)},
      {"radius_tolerance", kRadiusTolerance},
      {"diverged_factor", kDivergedFactor},
      {"intervals", stable_set.size()},
      {"exact_set_h_omega", lobatto_stable_set()},
      {"compared", compared},
      {"bound_h_over_T", lo / (2 * std::numbers::pi)},
      {"bound_steps_per_period", steps_per_period},
      {"least_whole_steps_per_period", std::floor(steps_per_period) + 1},
      {"near_pi", {{"h_omega", hws[near_pi]}, {"spectral_radius", rhos[near_pi]}}},
      {"bound_runs", run_list}};
}

// ---- Nonlinear Lagrangians: order 6 against odeint, symplecticity, Newton iterations ----

struct Pendulum {
  NonlinearPendulum pend;
  Z1 z0;  // (q, p) = (nonlinear.pendulum_q0, 0)
};

Pendulum pendulum(const Scene& s) { return {NonlinearPendulum{}, make_state(s.real("nonlinear.pendulum_q0"), 0.0)}; }

// The planar elastic pendulum of the scene (y pointing down, systems/elastic_pendulum.hpp).
ElasticPendulumWithGravity elastic_pendulum(const Scene& s) {
  const ElasticPendulumParams p{s.real("nonlinear.elastic.l"), s.real("nonlinear.elastic.m"), s.real("nonlinear.elastic.k"),
                                s.real("nonlinear.elastic.g")};
  return {p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}};
}

void run_nonlinear(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("nonlinear");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  const auto methods = s.texts("nonlinear.methods");
  const auto lob = lobatto_rule();
  const auto [pend, pz0] = pendulum(s);
  const auto elastic = elastic_pendulum(s);
  const auto er = s.real_rows("nonlinear.elastic_initial")[0];
  const PhaseState<2> ez0 = make_state<2>(Vec<2>(er[0], er[1]), Vec<2>(er[2], er[3]));
  const Z1 pref = reference_solution(pend, pz0, t_end, rtol, atol);
  const PhaseState<2> eref = reference_solution(elastic, ez0, t_end, rtol, atol);
  struct Row {
    double pendulum_err, pendulum_iterations, elastic_err, elastic_iterations;
    std::vector<double> compared;  // the pendulum error of each of nonlinear.methods
    auto fields() { return std::tie(pendulum_err, pendulum_iterations, elastic_err, elastic_iterations, compared); }
  };
  const auto rows = distributed_map(nh.size(), [&](std::size_t i) {
    const double h = nh[i];
    const std::int64_t n = steps_to(t_end, h);
    int it = 0;
    double it_p = 0, it_e = 0;
    Z1 zp = pz0;
    PhaseState<2> ze = ez0;
    for (std::int64_t j = 0; j < n; ++j) {
      zp = galerkin_step(lob, pend, zp, h, &it), it_p += it;
      ze = galerkin_step(lob, elastic, ze, h, &it), it_e += it;
    }
    Row r{phase_distance(zp, pref), it_p / static_cast<double>(n), phase_distance(ze, eref),
          it_e / static_cast<double>(n), {}};
    for (const auto& m : methods)
      r.compared.push_back(phase_distance(
          with_method(m, pend, [&](const auto& method) { return integrate(method, pz0, h, n); }), pref));
    return r;
  });
  std::vector<std::string> columns = {"h", "pendulum_err", "pendulum_newton_iterations", "elastic_err",
                                      "elastic_newton_iterations"};
  for (const auto& m : methods) columns.push_back(label_of(m) + "_pendulum_err");
  Csv nl(columns);
  std::vector<double> e_p, e_e;
  std::vector<std::vector<double>> e_m(methods.size());
  for (std::size_t i = 0; i < nh.size(); ++i) {
    const auto& r = rows[i];
    bool finite = std::isfinite(r.pendulum_err) && std::isfinite(r.elastic_err);
    for (double e : r.compared) finite = finite && std::isfinite(e);
    if (!finite)
      throw NumericalFailure("study nonlinear: a non-finite error at h = " + format_double(nh[i]) + ", t = " +
                             format_double(t_end) + " (pendulum, elastic pendulum or one of nonlinear.methods)");
    nl << nh[i] << r.pendulum_err << r.pendulum_iterations << r.elastic_err << r.elastic_iterations;
    for (std::size_t k = 0; k < methods.size(); ++k) nl << r.compared[k], e_m[k].push_back(r.compared[k]);
    nl.end_row();
    e_p.push_back(r.pendulum_err), e_e.push_back(r.elastic_err);
  }
  ctx.write("nonlinear.csv", nl);
  const double nfloor = kReferenceFloorFactor * atol;
  json orders = json::object(), fits = json::object();
  const auto fit = [&](const std::string& key, const std::vector<double>& err) {
    const OrderFit f = fit_order(nh, err, nfloor, key.c_str());
    orders[key] = f.order, fits[key] = to_json(f);
  };
  fit("lobatto_nonlinear_pendulum", e_p);
  fit("lobatto_elastic_pendulum", e_e);
  for (std::size_t k = 0; k < methods.size(); ++k) fit(label_of(methods[k]) + "_nonlinear_pendulum", e_m[k]);
  merge(ctx, "orders", orders);
  std::vector<double> it_p, it_e;
  for (const auto& r : rows) it_p.push_back(r.pendulum_iterations), it_e.push_back(r.elastic_iterations);
  ctx.summary["methods"]["nonlinear"] = labels(methods);
  ctx.summary["nonlinear"] = {{"h_range", range_of(nh)},
                              {"error_floor", nfloor},
                              {"error_floor_over_atol", kReferenceFloorFactor},
                              {"newton_iterations", {{"pendulum", range_of(it_p)}, {"elastic", range_of(it_e)}}},
                              {"fits", fits}};
  // Symplecticity of the nonlinear one-step maps: max |J^T Omega J - Omega|.
  ctx.summary["reproduced"]["symplecticity_defect_pendulum"] =
      symplecticity_defect(galerkin_step_jacobian(lob, pend, pz0, nh.front()));
  ctx.summary["reproduced"]["symplecticity_defect_elastic"] =
      symplecticity_defect(galerkin_step_jacobian(lob, elastic, ez0, nh.front()));
  ctx.summary["norms"]["nonlinear"] = "|z_N - z(t_end)|_2 against the odeint Bulirsch-Stoer reference";
}

// ---- What the accuracy costs (nonlinear pendulum to t_end, against its own reference) ----

// "%g" of an error target: the key of summary.timing.cost.<method>.wall_s_to and evals_to.
std::string target_key(double target) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", target);
  return b;
}

// What each method's runs cost: per step at the smallest h, relative to the first method; its
// smallest error; its error at the wall time `equal_wall`; the wall time and the force evaluations
// at which it first reaches each target (null where its measured runs do not reach it).
json cost_summary(const std::vector<std::string>& timed, const std::map<std::string, std::vector<CostRun>>& runs,
                  const json& ns_per_step, double equal_wall, const std::vector<double>& targets) {
  json cost = json::object();
  for (const auto& label : timed) {
    const auto r = by_decreasing_h(runs.at(label));
    if (r.empty()) continue;
    double min_err = r.front().err;
    for (const CostRun& x : r) min_err = std::min(min_err, x.err);
    json c = {{"relative_cost", ns_per_step[label].get<double>() / ns_per_step[timed.front()].get<double>()},
              {"evals_per_step", r.back().evals / r.back().steps},
              {"min_err", min_err},
              {"err_at_equal_wall", optional_json(error_at_wall(r, equal_wall))}};
    for (double t : targets) {
      c["wall_s_to"][target_key(t)] = optional_json(cost_to_reach(r, t, &CostRun::wall_s));
      c["evals_to"][target_key(t)] = optional_json(cost_to_reach(r, t, &CostRun::evals));
    }
    cost[label] = c;
  }
  return cost;
}

void run_timing(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost");
  const auto nh = s.reals("nonlinear.h");
  const double t_end = s.real("nonlinear.t_end");
  const auto [pend, pz0] = pendulum(s);
  const Z1 pref = reference_solution(pend, pz0, t_end, s.real("reference.rtol"), s.real("reference.atol"));
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "error", "wall_spread"});
  json ns = json::object(), ns_spread = json::object();
  SpreadTally spreads;
  std::map<std::string, std::vector<CostRun>> runs;
  for (const auto& m : s.texts("timing.methods")) {
    const std::string label = label_of(m);
    for (double h : nh) {
      const std::int64_t n = steps_to(t_end, h);
      std::int64_t evals = 0;
      const double err = phase_distance(with_method(m, Counting<NonlinearPendulum>{pend, &evals}, [&](const auto& method) {
                                          return integrate(method, pz0, h, n);
                                        }),
                                        pref);
      const RunTime t = with_method(m, pend, [&](const auto& method) {
        return time_runs(repeats, [&] { do_not_optimize(integrate(method, pz0, h, n)); });
      });
      spreads.add(t);
      const double wall = t.seconds();
      cost << label << h << n << wall << 1e9 * wall / static_cast<double>(n) << evals << err << t.spread();
      cost.end_row();
      if (h == nh.back()) ns[label] = 1e9 * wall / static_cast<double>(n), ns_spread[label] = t.spread();
      runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(evals), err});
    }
  }
  ctx.write("timing.csv", cost);
  const json timed = labels(s.texts("timing.methods"));
  const double equal_wall = largest_wall(by_decreasing_h(runs[label_of(s.text("timing.equal_wall"))]));
  ctx.summary["methods"]["timing"] = timed;
  ctx.summary["timing"] = {
      {"ns_per_step", ns},
      {"ns_per_step_spread", ns_spread},
      {"spread", spreads.to_json()},
      {"method", "nonlinear pendulum to nonlinear.t_end; " + timing_method_text(repeats) +
                     "; ns_per_step at the smallest nonlinear.h; force evaluations count U_q and U_qq calls"},
      {"equal_wall_s", equal_wall},
      {"cost", cost_summary(timed.get<std::vector<std::string>>(), runs, ns, equal_wall,
                            s.reals("timing.error_targets"))}};
}

// ---- What the accuracy costs on the oscillator of Fig. 2 over long_run.periods periods, against the
// closed form ----

void run_long_run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: long runs on the oscillator");
  const auto [osc, A, T, z0] = oscillator(s);
  const auto methods = s.texts("long_run_cost.methods");
  const auto hs = s.reals("long_run_cost.h");
  const double periods = s.real("long_run.periods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto steps_of = [&](double h) { return std::llround(periods * T / h); };
  // Errors and force evaluations: one counting run per method and step (in parallel): the largest
  // |H(z_j) - H(z_0)| over the run (Fig. 2's quantity) and |z_N - z(t_N)|_2 at its end, both against
  // the closed form of the oscillator.
  struct Measured {
    std::int64_t evals = 0;
    double energy = 0, phase = 0;
    auto fields() { return std::tie(evals, energy, phase); }
  };
  const std::size_t nh = hs.size();
  const std::vector<std::string> keys = {"oscillator", "long_run.periods", "long_run_cost.methods", "long_run_cost.h"};
  const auto measured = checkpointed_map<Measured>(ctx, {"long_run_cost", keys}, methods.size() * nh, [&](std::size_t task) {
    Measured r;
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(h);
    const double H0 = osc.H(z0);
    const Counting<HarmonicOscillator> counted{osc, &r.evals};
    const Z1 zN = with_method(methods[task / nh], counted, [&](const auto& m) {
      return integrate(m, z0, h, n, [&](std::int64_t, const Z1& z) { r.energy = std::max(r.energy, std::abs(osc.H(z) - H0)); });
    });
    r.phase = phase_distance(zN, osc.exact(z0, static_cast<double>(n) * h));
    return r;
  });
  // Wall time of the same runs without observation, serial (runner/timing.hpp).
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "phase_err", "energy_err", "wall_spread"});
  SpreadTally spreads;
  json ns = json::object(), ns_spread = json::object();
  std::map<std::string, std::vector<CostRun>> phase_runs, energy_runs;
  for (std::size_t task = 0; task < measured.size(); ++task) {
    const std::string& m = methods[task / nh];
    const std::string label = label_of(m);
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(h);
    // The time per step on the oscillator does not depend on where the step is taken: it is measured
    // on a segment of long_run_cost.timing_steps steps (at most the run), and the run's wall time is
    // its n steps at that rate.
    const std::int64_t n_timed = std::min<std::int64_t>(n, s.integer("long_run_cost.timing_steps"));
    const RunTime t = with_method(m, osc, [&](const auto& method) {
      return time_runs(repeats, [&] { do_not_optimize(integrate(method, z0, h, n_timed)); });
    });
    spreads.add(t);
    const Measured& r = measured[task];
    const double per_step = t.seconds() / static_cast<double>(n_timed), wall = per_step * static_cast<double>(n);
    cost << label << h << n << wall << 1e9 * per_step << r.evals << r.phase << r.energy << t.spread();
    cost.end_row();
    if (h == *std::min_element(hs.begin(), hs.end()))  // time per step at the smallest step
      ns[label] = 1e9 * per_step, ns_spread[label] = t.spread();
    phase_runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.evals), r.phase});
    energy_runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.evals), r.energy});
  }
  ctx.write("timing_long_run.csv", cost);
  // The closed form's own error at t_N = periods T: the round-off of cos and sin of omega t_N, about
  // u omega t_N in the phase, i.e. u omega t_N |(A, m omega A)| in z (A and m omega A: the amplitudes
  // of q and p).
  const double t_N = periods * T;
  const double reference_error = std::numeric_limits<double>::epsilon() * osc.w * t_N * std::hypot(A, osc.m * osc.w * A);
  json errors = json::object();
  for (const auto& m : methods) {
    const std::string label = label_of(m);
    double phase_min = std::numeric_limits<double>::infinity(), energy_max = 0, energy_min = phase_min;
    for (const CostRun& r : phase_runs[label]) phase_min = std::min(phase_min, r.err);
    for (const CostRun& r : energy_runs[label]) energy_min = std::min(energy_min, r.err), energy_max = std::max(energy_max, r.err);
    errors[label] = {{"phase_min", phase_min}, {"energy_min", energy_min}, {"energy_max", energy_max}};
  }
  ctx.summary["methods"]["long_run_cost"] = labels(methods);
  ctx.summary["long_run_cost"] = {{"t_end", t_N}, {"h_range", range_of(hs)}, {"reference_error", reference_error},
                                  {"errors", errors},
                                  {"norms", "phase: |z_N - z(t_N)|_2 against the closed form; energy: max over the "
                                            "steps of |H(z_j) - H(z_0)|"}};
  // The common budget: the smallest over the methods of their most expensive run (inside every
  // method's measured range when the ranges overlap).
  double equal_wall = std::numeric_limits<double>::infinity();
  for (const auto& m : methods) equal_wall = std::min(equal_wall, largest_wall(by_decreasing_h(phase_runs[label_of(m)])));
  json c = json::object();
  for (const auto& m : methods) {
    const std::string label = label_of(m);
    const auto phase = by_decreasing_h(phase_runs[label]), energy = by_decreasing_h(energy_runs[label]);
    json cm = {{"ns_per_step", ns[label]}, {"ns_per_step_spread", ns_spread[label]},
               {"relative_cost", ns[label].get<double>() / ns[label_of(methods.front())].get<double>()},
               {"evals_per_step", phase.empty() ? json(nullptr) : json(phase.back().evals / phase.back().steps)},
               {"phase_err_at_equal_wall", optional_json(error_at_wall(phase, equal_wall))},
               {"energy_err_at_equal_wall", optional_json(error_at_wall(energy, equal_wall))}};
    cm["wall_s_to"] = json::array(), cm["evals_to"] = json::array();  // per target of long_run_cost.error_targets
    for (double target : s.reals("long_run_cost.error_targets")) {
      cm["wall_s_to"].push_back(optional_json(cost_to_reach(phase, target, &CostRun::wall_s)));
      cm["evals_to"].push_back(optional_json(cost_to_reach(phase, target, &CostRun::evals)));
    }
    c[label] = cm;
  }
  ctx.summary["timing"]["long_run_cost"] = {
      {"cost", c},
      {"equal_wall_s", equal_wall},
      {"spread", spreads.to_json()},
      {"method", "the oscillator of Fig. 2 over long_run.periods periods, every call of a step through integrate; " +
                     timing_method_text(repeats) + "; ns_per_step at the smallest long_run_cost.h; force evaluations "
                     "count U_q and U_qq calls"}};
}

// ---- What each study would cost (--plan), from the scene before any work ----
//
// Steps are counted in double (t_end = 1e300 gives a huge count, refused by the runner, not an overflowed
// integer). The ns per step are constants measured on the paper scene (results/lobatto_table, 2 threads):
// summary timing.ns_per_step and timing.long_run_cost.cost.*.ns_per_step, and study wall time over steps for
// the linear iterations; force evaluations per step are the largest of summary timing.cost.*.evals_per_step.

constexpr double kCellBytes = 24;            // one CSV cell held in memory (text and separator)
constexpr double kStateBytes = sizeof(Z1);   // one stored (q, p)
constexpr double kOscillatorEvals = 11;      // force evaluations per step on the oscillator (Lobatto, the most)
constexpr double kPendulumEvals = 16;        // per step on the nonlinear pendulum (Lobatto's Newton, the most)
constexpr double kMatrixNs = 25;             // one step of a 2x2 one-step matrix (Fig. 2, stability runs)
constexpr double kOscillatorNs = 280;        // one Lobatto step through integrate on the oscillator
constexpr double kPendulumNs = 520;          // one Lobatto step (Newton) on the nonlinear pendulum

double period_of(const Scene& s) { return 2 * std::numbers::pi / s.real("oscillator.omega"); }

StudyPlan plan_table1(const Scene& s) {
  double steps = 0, largest = 0;
  const double runs = 2.0 + static_cast<double>(s.texts("table1.methods").size());  // Lobatto, (12), compared
  for (double n : s.reals("meshes")) steps += runs * n, largest = std::max(largest, n);
  return {steps, steps * kOscillatorEvals, 2 * (largest + 1) * kStateBytes, kOscillatorNs,
          "ns per step: Lobatto on the oscillator (paper-scene summary timing.long_run_cost)"};
}

StudyPlan plan_figure1(const Scene& s) {
  const double methods = static_cast<double>(s.texts("figure1.methods").size());
  double steps = 0, largest = 0;
  for (double n : s.reals("figure1.meshes")) steps += methods * n, largest = std::max(largest, n);
  return {steps, steps * kOscillatorEvals, (largest + 1) * (methods * kStateBytes + (2 + 2 * methods) * kCellBytes),
          kOscillatorNs, "ns per step: Lobatto on the oscillator (paper-scene summary timing.long_run_cost)"};
}

StudyPlan plan_long_run(const Scene& s) {
  const double periods = s.real("long_run.periods"), T = period_of(s);
  const double windows = static_cast<double>(s.integer("long_run.windows"));
  double steps = 0;
  for (double h : s.reals("long_run.h")) steps += periods * T / h;
  const double runs = static_cast<double>(s.reals("long_run.h").size());
  return {steps, 0, runs * windows * (3 * sizeof(double) + 5 * kCellBytes), kMatrixNs,
          "iterates the one-step matrix (13), no force evaluations; ns per step: paper-scene study wall time over its steps"};
}

StudyPlan plan_stability(const Scene& s) {
  const double points = static_cast<double>(s.integer("stability.points"));
  const double methods = static_cast<double>(s.texts("stability.methods").size());
  const double periods = s.real("long_run.periods");
  double steps = points * (1 + methods);  // one one-step matrix per point and method
  for (double factor : kBoundFactors) steps += periods * 2 * std::numbers::pi / (factor * method_info("lobatto").oscillatory_bound);
  return {steps, 0, points * (2 + methods) * (sizeof(double) + kCellBytes), kMatrixNs,
          "runs at the bound iterate the one-step matrix (13); ns per step: paper-scene study wall time over its steps"};
}

StudyPlan plan_nonlinear(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const double runs = 2.0 + static_cast<double>(s.texts("nonlinear.methods").size());  // both pendulums, compared
  double steps = 0;
  for (double h : s.reals("nonlinear.h")) steps += runs * t_end / h;
  return {steps, steps * kPendulumEvals, static_cast<double>(s.reals("nonlinear.h").size()) * runs * 4 * sizeof(double),
          kPendulumNs, "odeint reference steps not counted; ns per step: Lobatto on the pendulum (paper-scene summary timing)"};
}

StudyPlan plan_timing(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  double steps = 0;
  for (double h : s.reals("nonlinear.h")) steps += methods * (1 + repeats) * t_end / h;  // a counting run, the timed runs
  return {steps, steps / (1 + repeats) * kPendulumEvals, methods * static_cast<double>(s.reals("nonlinear.h").size()) * 8 * kCellBytes,
          kPendulumNs, "timed runs of < 10 ms are repeated to 10 ms (not counted); ns per step: Lobatto on the pendulum (paper-scene summary timing)"};
}

StudyPlan plan_long_run_cost(const Scene& s) {
  const double periods = s.real("long_run.periods"), T = period_of(s);
  const double methods = static_cast<double>(s.texts("long_run_cost.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double timed = static_cast<double>(s.integer("long_run_cost.timing_steps"));
  double counted = 0, steps = 0;
  for (double h : s.reals("long_run_cost.h")) {
    const double n = periods * T / h;
    counted += methods * n, steps += methods * (n + repeats * std::min(n, timed));
  }
  return {steps, counted * kOscillatorEvals,
          methods * static_cast<double>(s.reals("long_run_cost.h").size()) * 9 * kCellBytes, kOscillatorNs,
          "ns per step: Lobatto on the oscillator (paper-scene summary timing.long_run_cost)"};
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"lobatto_table",
                      "001 Table 1, Figs 1, 2: the Lobatto variational integrator from its definition, "
                      "its stability set, nonlinear Lagrangians, and what the accuracy costs",
                      schema(),
                      {}};
  spec.studies = {
      {"table1", "001 Table 1", {"table1.csv"}, {"meshes", "oscillator", "table1"}, check_table1, run_table1, plan_table1},
      {"figure1", "001 Fig 1", {"fig1_N*.csv", "fig1_exact.csv"}, {"figure1", "oscillator"}, check_figure1, run_figure1, plan_figure1},
      {"long_run", "001 Fig 2", {"fig2_energy.csv"}, {"long_run", "oscillator"}, check_long_run, run_long_run, plan_long_run},
      {"stability", "stability set beyond 001 eq. (10); runs at 0.99 and 1.01 of the bound", {"stability.csv"},
       {"stability", "oscillator", "long_run.periods"}, check_stability, run_stability, plan_stability},
      {"nonlinear", "nonlinear Lagrangians (Newton): order 6, symplecticity", {"nonlinear.csv"},
       {"nonlinear", "reference"},
       check_nonlinear, run_nonlinear, plan_nonlinear},
      {"timing", "cost: error against wall time and force evaluations", {"timing.csv"},
       {"timing", "nonlinear.h", "nonlinear.t_end", "nonlinear.pendulum_q0", "reference"},
       check_timing, run_timing, plan_timing},
      {"long_run_cost", "cost over the long run of Fig 2: error against wall time and force evaluations",
       {"timing_long_run.csv"}, {"long_run_cost", "long_run.periods", "oscillator", "timing.repeats", "checkpoint"},
       check_long_run_cost, run_long_run_cost, plan_long_run_cost},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
