// rowlands_convergence: 000 (Takacs & Fulop 2025) Fig. 4 -- Stormer-Verlet
// (26)-(28) against the Rowlands method (30)-(37) on the elastic pendulum
// (73): energy error (50) and phase-space error at t_max against h, for
// several initial conditions (study `convergence`); and what the accuracy
// costs, against odeint's own steppers (study `timing`). The methods are
// named by the scene (any registered method that steps the pendulum); CSV
// columns and summary keys use their registry labels.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
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
#include "geomint/systems/elastic_pendulum.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

using State = PhaseState<2>;

// The label of a method (CSV columns, summary keys) and the prefix of its orders.
std::string order_name(const std::string& method) {
  const std::string label = label_of(method);
  return label == "kernel" ? "kernel_unprocessed" : label;  // (the kernel's orders keep their published key)
}

struct Errors {
  double energy_rms = 0, energy_max = 0;  // of H(z_j) - H(z_0), j = 0..N: eq. (50) and the max
  double phase = 0;                       // |z_N - z(t_N)|_2 against the reference
  std::int64_t force_evals = 0;           // with postprocessing at every step
  auto fields() { return std::tie(energy_rms, energy_max, phase, force_evals); }  // (a record of runner/distributed_map.hpp)
};

// What the convergence study records (the scene's `observables`).
struct Observables {
  bool energy = false;  // "energy_error": H along the run (postprocessed at every step)
  bool phase = false;   // "phase_error": z_N against the reference (only then is a reference computed)
};

Observables observables_of(const Scene& s) {
  const auto named = s.texts("observables");
  const auto has = [&](const char* o) { return std::find(named.begin(), named.end(), o) != named.end(); };
  return {has("energy_error"), has("phase_error")};
}

// One run of a method; z_ref is read only for the phase error.
template <class Sys>
Errors convergence_run(const std::string& method, const Sys& sys, const State& z0, const State* z_ref, double h,
                       std::int64_t n, Observables obs) {
  Errors e;
  const Counting<Sys> counted{sys, &e.force_evals};
  const double H0 = sys.H(z0);
  ErrorSeries energy;
  const State zN = with_method(method, counted, [&](const auto& m) {
    if (!obs.energy) return integrate(m, z0, h, n);  // pre once, post once (eq. (23))
    return integrate(m, z0, h, n, [&](std::int64_t, const State& z) { energy.add(sys.H(z) - H0); });
  });
  if (obs.energy) e.energy_rms = energy.rms50(), e.energy_max = energy.max_abs();
  if (obs.phase) e.phase = phase_distance(zN, *z_ref);
  return e;
}

State state_of(const std::vector<double>& row) { return make_state<2>(Vec<2>(row[0], row[1]), Vec<2>(row[2], row[3])); }

ElasticPendulumParams pendulum_of(const Scene& s) {
  return {s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
}

// The registry labels of methods (their CSV columns, for the figures).
json labels_of(const std::vector<std::string>& methods) {
  json out = json::array();
  for (const auto& m : methods) out.push_back(label_of(m));
  return out;
}

// What both studies report about the scene: the step sizes and the initial conditions.
void scene_summary(Context& ctx) {
  const auto hs = ctx.scene.reals("h");
  ctx.summary["h_range"] = {{"min", *std::min_element(hs.begin(), hs.end())},
                            {"max", *std::max_element(hs.begin(), hs.end())}, {"count", hs.size()}};
  ctx.summary["initial_conditions"] = ctx.scene.real_rows("initial").size();
}

Schema schema() {
  const auto choices = method_choices<Counting<ElasticPendulumWithGravity>>();
  Schema s;
  s.real("pendulum.l", positive(), "relaxed spring length l (000 eq. (73))")
      .real("pendulum.m", positive(), "mass m")
      .real("pendulum.k", positive(), "spring stiffness k")
      .real("pendulum.g", non_negative(), "gravitational acceleration g (0: no gravity term)")
      .real_rows("initial", 4, any_finite(), 1,
                 "initial conditions [x, y, px, py]; the first is drawn in Fig. 4 and timed, orders are fitted for each")
      .real("t_end", positive(), "t_max: end of every run (000 Fig. 4: 4)")
      .reals("h", positive(), 3,
             "step sizes; each divides t_end, and h sqrt(k/m) is below the oscillatory bound of every named method")
      .texts("methods", choices, 1, "methods of the convergence study (registry names or labels)")
      .texts("observables", {"energy_error", "phase_error"}, 1,
             "what the convergence study records: energy_error (eq. (50) and the max over the run), phase_error "
             "(|z_N - z(t_end)|_2 against the odeint reference, computed only if named)")
      .real("reference.rtol", tolerance(), "relative tolerance of the odeint Bulirsch-Stoer reference")
      .real("reference.atol", tolerance(), "absolute tolerance of the odeint Bulirsch-Stoer reference")
      .texts("timing.methods", choices, 1, "methods of the cost study (registry names or labels)")
      .integer("timing.repeats", at_least(1), "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .reals("timing.error_targets", positive(), 1,
             "phase errors for which the wall time and the force evaluations to reach them are reported");
  return s;
}

// The methods named under `key`: each once, each able to step the pendulum,
// and every h sqrt(k/m) below each one's oscillatory bound (the registry's).
void check_methods(const Scene& s, const char* key) {
  const ElasticPendulumParams p = pendulum_of(s);
  with_elastic_pendulum(p, [&](const auto& sys) { check_methods(s, key, sys); });
  const double omega = std::sqrt(p.k / p.m);
  for (const auto& m : s.texts(key))
    for (double h : s.reals("h"))
      check_oscillatory_bound(s, "h", key, m, h * omega, "h sqrt(k/m) at h = " + format_double(h) + ", named in " + key);
}

void check_common(const Scene& s) {
  const double t_end = s.real("t_end");
  for (double h : s.reals("h")) {
    if (!(t_end / h <= max_exact_count)) s.reject("h", "at most 2^53 steps to t_end = " + format_double(t_end) + ", here h = " + format_double(h));
    const double n = static_cast<double>(steps_to(t_end, h));
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end) s.reject("h", "each h must divide t_end = " + format_double(t_end));
  }
  for (const auto& row : s.real_rows("initial"))
    if (std::hypot(row[0], row[1]) == 0.0) s.reject("initial", "the spring force is singular at x = y = 0");
}

// ---- Fig. 4: convergence of every named method, for every initial condition ----

// The ranges of the fitted orders (orders_by_initial) over all initial conditions and norms, of the
// methods whose kernel is of order 2 (Stormer-Verlet, the Rowlands kernel alone and processed), by
// their declared order: {"order_2": {min, max}, "order_4": {min, max}}.
json order_ranges(const std::vector<std::string>& methods, const json& by_initial) {
  std::map<int, std::pair<double, double>> ranges;
  for (const auto& m : methods) {
    if (method_info(m).kernel_order != 2) continue;
    auto& [lo, hi] = ranges.try_emplace(method_info(m).order, std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity()).first->second;
    for (const auto& o : by_initial)
      for (const char* suffix : {"_energy", "_energy_max", "_phase"})
        if (o.contains(order_name(m) + suffix)) {
          const double v = o[order_name(m) + suffix].get<double>();
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        }
  }
  json out = json::object();
  for (const auto& [order, range] : ranges)
    if (range.first <= range.second) out["order_" + std::to_string(order)] = {{"min", range.first}, {"max", range.second}};
  return out;
}

// 000 (32)-(33) as printed against the kernel alone: {min, max, h} of the ratio of their errors at the
// smallest h, over all initial conditions and the recorded norms (to leading order the error is
// proportional to 1/12 - c: the analysis predicts (1/12 - 1/24) / (1/12) = 1/2); nullopt unless the
// convergence study runs both. runs[i * hs.size() + j][k]: initial condition i, step hs[j], method k.
std::optional<json> printed_over_kernel(const std::vector<std::string>& methods,
                                        const std::vector<std::vector<Errors>>& runs, const std::vector<double>& hs,
                                        std::size_t n_initial, Observables obs) {
  const auto index_of = [&](const char* name) {
    const auto it = std::find_if(methods.begin(), methods.end(), [&](const auto& m) { return label_of(m) == label_of(name); });
    return it == methods.end() ? std::nullopt : std::optional(static_cast<std::size_t>(it - methods.begin()));
  };
  const auto kp = index_of("rowlands_printed"), kk = index_of("rowlands_kernel");
  if (!kp || !kk) return std::nullopt;
  const std::size_t j_min = static_cast<std::size_t>(std::min_element(hs.begin(), hs.end()) - hs.begin());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < n_initial; ++i) {
    const Errors &printed = runs[i * hs.size() + j_min][*kp], &kernel = runs[i * hs.size() + j_min][*kk];
    std::vector<std::pair<double, double>> pairs;
    if (obs.phase) pairs.emplace_back(printed.phase, kernel.phase);
    if (obs.energy) pairs.emplace_back(printed.energy_rms, kernel.energy_rms);
    for (const auto& [a, b] : pairs)
      if (b != 0 && std::isfinite(a / b)) lo = std::min(lo, a / b), hi = std::max(hi, a / b);
  }
  if (!(lo <= hi)) return std::nullopt;
  return json{{"min", lo}, {"max", hi}, {"h", hs[j_min]}};
}

template <class Sys>
void convergence_with(Context& ctx, const Sys& sys) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("h");
  const auto initial = s.real_rows("initial");
  const auto methods = s.texts("methods");
  const Observables obs = observables_of(s);
  const double t_end = s.real("t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  json reproduced, fits;

  // References, one per initial condition, and their self-check at 100x tighter tolerances.
  if (obs.phase) ctx.progress("references (odeint Bulirsch-Stoer)");
  struct Ref {
    State z;
    double self_check;
    auto fields() { return std::tie(z.q[0], z.q[1], z.p[0], z.p[1], self_check); }
  };
  const auto refs = distributed_map(obs.phase ? initial.size() : 0, [&](std::size_t i) {
    const State z0 = state_of(initial[i]);
    const State a = reference_solution(sys, z0, t_end, rtol, atol);
    const State b = reference_solution(sys, z0, t_end, rtol / 100, atol / 100);
    return Ref{a, phase_distance(a, b)};
  });
  Csv ref_csv({"initial", "x", "y", "px", "py", "self_check"});
  double self_check = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ref_csv.row(static_cast<std::int64_t>(i), refs[i].z.q[0], refs[i].z.q[1], refs[i].z.p[0], refs[i].z.p[1],
                refs[i].self_check);
    self_check = std::max(self_check, refs[i].self_check);
  }
  if (obs.phase) ctx.write("reference.csv", ref_csv);

  // Convergence: one task per (initial condition, h), all methods in it.
  ctx.progress("Fig. 4: convergence");
  const std::size_t nh = hs.size();
  const auto runs = distributed_map(initial.size() * nh, [&](std::size_t task) {
    const std::size_t i = task / nh;
    const double h = hs[task % nh];
    std::vector<Errors> out;
    for (const auto& m : methods)
      out.push_back(convergence_run(m, sys, state_of(initial[i]), obs.phase ? &refs[i].z : nullptr, h,
                                    steps_to(t_end, h), obs));
    return out;
  });
  std::vector<std::string> columns = {"initial", "h", "steps"};
  for (const auto& m : methods) {
    if (obs.energy) columns.insert(columns.end(), {label_of(m) + "_energy_rms", label_of(m) + "_energy_max"});
    if (obs.phase) columns.push_back(label_of(m) + "_phase");
    columns.push_back(label_of(m) + "_evals");
  }
  Csv conv(columns);
  for (std::size_t task = 0; task < runs.size(); ++task) {
    conv << static_cast<std::int64_t>(task / nh) << hs[task % nh] << steps_to(t_end, hs[task % nh]);
    for (const auto& e : runs[task]) {
      if (obs.energy) conv << e.energy_rms << e.energy_max;
      if (obs.phase) conv << e.phase;
      conv << e.force_evals;
    }
    conv.end_row();
  }
  ctx.write("fig4_convergence.csv", conv);

  // Orders, per initial condition; the reference error bounds what can be fitted.
  const double energy_floor = roundoff_floor();
  const double phase_floor = std::max(100.0 * self_check, energy_floor);
  Csv order_csv({"initial", "name", "order", "log10_c", "r2", "points", "h_min", "h_max"});
  json by_initial = json::array();
  double min_phase = std::numeric_limits<double>::infinity();  // smallest phase error plotted
  for (std::size_t i = 0; i < initial.size(); ++i) {
    json o;
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const std::string name = order_name(methods[k]);
      std::vector<double> rms, mx, ph;
      for (std::size_t j = 0; j < nh; ++j) {
        const Errors& e = runs[i * nh + j][k];
        rms.push_back(e.energy_rms), mx.push_back(e.energy_max), ph.push_back(e.phase);
      }
      const double H0 = std::abs(sys.H(state_of(initial[i])));
      std::vector<std::tuple<const char*, const std::vector<double>*, double>> fitted;
      if (obs.energy)
        fitted = {{"_energy", &rms, energy_floor * std::max(H0, 1.0)}, {"_energy_max", &mx, energy_floor * std::max(H0, 1.0)}};
      if (obs.phase) fitted.emplace_back("_phase", &ph, phase_floor);
      for (const auto& [suffix, err, floor] : fitted) {
        const OrderFit f = [&] {
          try {
            return fit_order(hs, *err, floor, (name + suffix).c_str());
          } catch (const NumericalFailure& e) {
            throw NumericalFailure(std::string(e.what()) + " (initial condition " + std::to_string(i) + ", floor " +
                                     format_double(floor) + ": the errors reach round-off or the reference's accuracy there; add larger h)");
          }
        }();
        o[name + suffix] = f.order;
        if (i == 0) fits[name + suffix] = to_json(f);
        order_csv.row(static_cast<std::int64_t>(i), name + suffix, f.order, f.log10_c, f.r2, f.points, f.h_min, f.h_max);
        if (std::string(suffix) == "_phase")
          for (double e : *err) min_phase = std::min(min_phase, e);
      }
    }
    by_initial.push_back(o);
  }
  ctx.write("orders.csv", order_csv);
  if (obs.phase) {
    reproduced["reference_self_check"] = self_check;
    reproduced["reference_margin"] = min_phase / self_check;  // must be >= 100 (checked by the tests)
  }

  if (!reproduced.empty()) ctx.summary["reproduced"] = reproduced;
  ctx.summary["orders"] = by_initial[0];
  ctx.summary["orders_by_initial"] = by_initial;
  ctx.summary["fits"] = fits;
  json norms;
  if (obs.energy) {
    norms["energy"] = "eq. (50): sqrt(sum_{j=0}^{N} (H(z_j) - H(z_0))^2 / N), z_j postprocessed at every step";
    norms["energy_max"] = "max over j of |H(z_j) - H(z_0)|";
  }
  if (obs.phase) norms["phase"] = "|z_N - z(t_end)|_2 over (x, y, px, py), against the odeint Bulirsch-Stoer reference";
  ctx.summary["norms"] = norms;

  ctx.summary["methods"]["convergence"] = labels_of(methods);
  for (const auto& m : methods) ctx.summary["declared_orders"][label_of(m)] = method_info(m).order;  // the registry's
  scene_summary(ctx);
  ctx.summary["pendulum"] = {{"y_equilibrium", hanging_equilibrium_y(pendulum_of(s))}};
  ctx.summary["order_ranges"] = order_ranges(methods, by_initial);
  if (const auto ratio = printed_over_kernel(methods, runs, hs, initial.size(), obs)) ctx.summary["printed_over_kernel"] = *ratio;
}

// What each method's accuracy costs (summary.json timing.cost.<label>): at the smallest h, the force
// evaluations per step; its smallest error; its error at the wall time of the most expensive run of
// the first method (`budget`, at which the methods are compared); and for every target error the wall time
// and the force evaluations at which its error first reaches it, or null (reaches: false) where the
// measured step sizes do not reach it (log-log interpolation, never extrapolated).
json cost_summary(const std::vector<std::string>& methods, const std::vector<std::vector<CostRun>>& all,
                  const std::vector<double>& targets, double budget) {
  const auto or_null = [](std::optional<double> v) { return v ? json(*v) : json(nullptr); };
  json out;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::vector<CostRun> runs = by_decreasing_h(all[k]);
    if (runs.empty()) continue;
    json c{{"evals_per_step", runs.back().evals / runs.back().steps},
           {"min_err", std::min_element(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.err < b.err; })->err},
           {"err_at_equal_wall", or_null(error_at_wall(runs, budget))},
           {"wall_to", json::array()}, {"evals_to", json::array()}, {"reaches", json::array()}};
    for (double t : targets) {
      c["wall_to"].push_back(or_null(cost_to_reach(runs, t, &CostRun::wall_s)));
      c["evals_to"].push_back(or_null(cost_to_reach(runs, t, &CostRun::evals)));
      c["reaches"].push_back(cost_to_reach(runs, t, &CostRun::evals).has_value());
    }
    out[label_of(methods[k])] = c;
  }
  return out;
}

// ---- What the accuracy costs: wall time (runner/timing.hpp) of each method from
// initial[0] to t_end (pre once, post once, eq. (23)); force evaluations and
// phase errors (against the reference at initial[0]) from separate counting runs. ----

template <class Sys>
void timing_with(Context& ctx, const Sys& sys) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("h");
  const std::size_t nh = hs.size();
  const double t_end = s.real("t_end");
  const auto methods = s.texts("timing.methods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const State z0 = state_of(s.real_rows("initial")[0]);
  ctx.progress("cost: reference (odeint Bulirsch-Stoer)");
  const State z_ref = reference_solution(sys, z0, t_end, s.real("reference.rtol"), s.real("reference.atol"));

  ctx.progress("cost: timing");
  struct Count {
    std::int64_t evals = 0;
    double phase = 0;
    auto fields() { return std::tie(evals, phase); }
  };
  const auto counts = distributed_map(methods.size() * nh, [&](std::size_t task) {
    Count c;
    const Counting<Sys> counted{sys, &c.evals};
    const double h = hs[task % nh];
    const std::int64_t n = steps_to(t_end, h);
    const State zN = with_method(methods[task / nh], counted, [&](const auto& m) { return integrate(m, z0, h, n); });
    c.phase = phase_distance(zN, z_ref);
    return c;
  });
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "phase_err", "wall_spread"});
  json ns_per_step, ns_spread, timing;
  SpreadTally spreads;
  std::vector<std::vector<CostRun>> runs(methods.size());  // per method, its runs of `h`
  const double h_ns = *std::min_element(hs.begin(), hs.end());
  for (std::size_t task = 0; task < counts.size(); ++task) {
    const std::string label = label_of(methods[task / nh]);
    const double h = hs[task % nh];
    const std::int64_t n = steps_to(t_end, h);
    const RunTime t = with_method(methods[task / nh], sys, [&](const auto& m) {  // (the dispatch outside the clock)
      return time_runs(repeats, [&] { do_not_optimize(integrate_inlined(m, z0, h, n)); });
    });
    spreads.add(t);
    const double wall = t.seconds();
    cost.row(label, h, n, wall, 1e9 * wall / static_cast<double>(n), counts[task].evals, counts[task].phase, t.spread());
    runs[task / nh].push_back({h, static_cast<double>(n), wall, static_cast<double>(counts[task].evals), counts[task].phase});
    if (h == h_ns) ns_per_step[label] = 1e9 * wall / static_cast<double>(n), ns_spread[label] = t.spread();
  }
  ctx.write("timing.csv", cost);
  timing["ns_per_step"] = ns_per_step;
  timing["ns_per_step_spread"] = ns_spread;
  timing["spread"] = spreads.to_json();  // of every timed run of the study
  if (ns_per_step.contains("sv") && ns_per_step.contains("rowlands"))
    timing["ns_per_step_ratio_rowlands_over_sv"] = ns_per_step["rowlands"].get<double>() / ns_per_step["sv"].get<double>();
  timing["method"] = timing_method_text(repeats) + "; from initial[0] to t_end (pre- and postprocessing once, every "
                     "call inlined); ns_per_step at the smallest h";
  const double budget = largest_wall(by_decreasing_h(runs[0]));  // the most expensive run of the first method
  timing["cost"] = cost_summary(methods, runs, s.reals("timing.error_targets"), budget);
  timing["equal_wall_s"] = budget;
  for (const auto& m : methods)
    timing["relative_cost"][label_of(m)] = ns_per_step[label_of(m)].get<double>() / ns_per_step[label_of(methods[0])].get<double>();
  ctx.summary["timing"] = timing;
  ctx.summary["methods"]["timing"] = labels_of(methods);
  scene_summary(ctx);
}

void run_convergence(Context& ctx) {
  with_elastic_pendulum(pendulum_of(ctx.scene), [&](const auto& sys) { convergence_with(ctx, sys); });
}

void run_timing(Context& ctx) {
  with_elastic_pendulum(pendulum_of(ctx.scene), [&](const auto& sys) { timing_with(ctx, sys); });
}

// ---- What each study would cost (--plan), from the scene before any work ----
// Steps in double (t_end / h summed over the runs); the ns per step and force evaluations per step are
// constants measured on the paper scene (results/rowlands_convergence, summary timing.ns_per_step and
// timing.cost.*.evals_per_step: the processed Rowlands method and the most evaluations per step, odeint_rkn_sb3a).

constexpr double kNsPerStep = 40;   // the processed Rowlands method on the elastic pendulum
constexpr double kEvalsPerStep = 6; // the most of the paper scene's methods (odeint_rkn_sb3a)
constexpr double kCellBytes = 24;   // one CSV cell held in memory

double steps_per_run(const Scene& s) {
  double steps = 0;
  for (double h : s.reals("h")) steps += s.real("t_end") / h;
  return steps;
}

StudyPlan plan_convergence(const Scene& s) {
  const double runs = static_cast<double>(s.real_rows("initial").size() * s.texts("methods").size());
  const double steps = runs * steps_per_run(s);
  const double rows = static_cast<double>(s.real_rows("initial").size() * s.reals("h").size());
  return {steps, steps * kEvalsPerStep, rows * (3 + 4 * static_cast<double>(s.texts("methods").size())) * kCellBytes,
          kNsPerStep, "odeint reference steps not counted; ns per step: the processed Rowlands method (paper-scene summary timing)"};
}

StudyPlan plan_timing(const Scene& s) {
  const double methods = static_cast<double>(s.texts("timing.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double counted = methods * steps_per_run(s);
  return {counted * (1 + repeats), counted * kEvalsPerStep, methods * static_cast<double>(s.reals("h").size()) * 8 * kCellBytes,
          kNsPerStep, "timed runs of < 10 ms are repeated to 10 ms (not counted); ns per step: the processed Rowlands method "
          "(paper-scene summary timing)"};
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"rowlands_convergence",
                      "000 Fig. 4: Stormer-Verlet against the Rowlands method on the elastic pendulum, "
                      "with what the accuracy costs",
                      schema(),
                      {}};
  spec.studies = {
      {"convergence", "000 Fig 4", {"fig4_convergence.csv", "orders.csv", "reference.csv"},
       {"initial", "t_end", "h", "methods", "observables", "pendulum", "reference"},
       [](const Scene& s) {
         check_common(s);
         check_methods(s, "methods");
       },
       run_convergence, plan_convergence},
      {"timing", "cost: error against wall time and force evaluations, against odeint's steppers", {"timing.csv"},
       {"timing", "initial", "t_end", "h", "pendulum", "reference"},
       [](const Scene& s) {
         check_common(s);
         check_methods(s, "timing.methods");
       },
       run_timing, plan_timing},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}
