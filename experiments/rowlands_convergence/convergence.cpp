// 000 Fig. 4: Stormer-Verlet (26)-(28) against the Rowlands method (30)-(37) on the elastic
// pendulum (73): energy error (50) and phase-space error at t_max against h, for several initial
// conditions, of every method the scene names (`methods`), and the orders fitted to them per initial
// condition and norm. Phase errors against an odeint Bulirsch-Stoer reference at t_end, one per
// initial condition; one task per (initial condition, h), all methods in it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::rowlands_convergence {
namespace {

using State = PhaseState<2>;


struct Errors {
  double energy_rms = 0, energy_max = 0;  // of H(z_j) - H(z_0), j = 0..N: eq. (50) and the max
  double phase = 0;                       // |z_N - z(t_N)|_2 against the reference
  std::int64_t force_evals = 0;           // with postprocessing at every step
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
Errors convergence_run(const ElasticPendulumRuns& sys, const std::string& method, const State& z0, const State* z_ref,
                       double h, std::int64_t n, Observables obs) {
  Errors e;
  const double H0 = sys.H(z0);
  ErrorSeries energy;
  const auto observe = [&](std::int64_t, const State& z) { energy.add(sys.H(z) - H0); };
  // (without the energy: pre once, post once, eq. (23))
  const State zN = sys.integrate(method, z0, h, n, &e.force_evals, obs.energy ? ElasticPendulumRuns::Observer(observe) : nullptr);
  if (obs.energy) e.energy_rms = energy.rms50(), e.energy_max = energy.max_abs();
  if (obs.phase) e.phase = phase_distance(zN, *z_ref);
  return e;
}

// The ranges of the fitted orders (orders_by_initial) over all initial conditions and norms, of the
// methods whose kernel is of order 2 (Stormer-Verlet, the Rowlands kernel alone and processed), by
// their declared order: {"order_2": {min, max}, "order_4": {min, max}}.
Value order_ranges(const std::vector<std::string>& methods, const Value& by_initial) {
  int top = 0;  // the largest declared order
  for (const auto& m : methods) top = std::max(top, method_info(m).order);
  Value out = Value::record();
  for (int order = 1; order <= top; ++order) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& m : methods)
      if (method_info(m).kernel_order == 2 && method_info(m).order == order)
        for (std::size_t i = 0; i < by_initial.size(); ++i)
          for (const char* suffix : {"_energy", "_energy_max", "_phase"})
            if (const Value* o = by_initial.at(i).find(label_of(m) + suffix); o && std::isfinite(o->number()))
              lo = std::min(lo, o->number()), hi = std::max(hi, o->number());
    if (lo <= hi) out["order_" + std::to_string(order)] = {{"min", lo}, {"max", hi}};
  }
  return out;
}

// 000 (32)-(33) as printed against the kernel alone: {min, max, h} of the ratio of their errors at the
// smallest h, over all initial conditions and the recorded norms (to leading order the error is
// proportional to 1/12 - c: the analysis predicts (1/12 - 1/24) / (1/12) = 1/2); nullopt unless the
// convergence study runs both. runs[i * hs.size() + j][k]: initial condition i, step hs[j], method k.
std::optional<Value> printed_over_kernel(const std::vector<std::string>& methods,
                                         const std::vector<std::vector<Errors>>& runs, const std::vector<double>& hs,
                                         std::size_t n_initial, Observables obs) {
  std::size_t kp = methods.size(), kk = methods.size();  // (each method is named once)
  for (std::size_t k = 0; k < methods.size(); ++k) {
    if (label_of(methods[k]) == label_of("rowlands_printed")) kp = k;
    if (label_of(methods[k]) == label_of("rowlands_kernel")) kk = k;
  }
  if (kp == methods.size() || kk == methods.size()) return std::nullopt;
  const std::size_t j_min = static_cast<std::size_t>(std::min_element(hs.begin(), hs.end()) - hs.begin());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto ratio = [&](double a, double b) {
    if (b != 0 && std::isfinite(a / b)) lo = std::min(lo, a / b), hi = std::max(hi, a / b);
  };
  for (std::size_t i = 0; i < n_initial; ++i) {
    const Errors &printed = runs[i * hs.size() + j_min][kp], &kernel = runs[i * hs.size() + j_min][kk];
    if (obs.phase) ratio(printed.phase, kernel.phase);
    if (obs.energy) ratio(printed.energy_rms, kernel.energy_rms);
  }
  if (!(lo <= hi)) return std::nullopt;
  return Value{{"min", lo}, {"max", hi}, {"h", hs[j_min]}};
}

// References, one per initial condition, with their self-check (none unless phase errors are recorded;
// reference.csv); `self_check` becomes the largest of them.
std::vector<ElasticPendulumRuns::Reference> references(Context& ctx, const ElasticPendulumRuns& sys,
                                                       const std::vector<std::vector<double>>& initial, Observables obs,
                                                       double t_end, double rtol, double atol, double& self_check) {
  if (!obs.phase) return {};
  ctx.progress("references (odeint Bulirsch-Stoer)");
  const auto refs = sys.references(initial, t_end, rtol, atol);
  Csv ref_csv({"initial", "x", "y", "px", "py", "self_check"});
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ref_csv.row(static_cast<std::int64_t>(i), refs[i].z.q[0], refs[i].z.q[1], refs[i].z.p[0], refs[i].z.p[1],
                refs[i].self_check);
    self_check = std::max(self_check, refs[i].self_check);
  }
  ctx.write("reference.csv", ref_csv);
  return refs;
}

// Convergence: one task per (initial condition, h), all methods in it, a run's errors as 4 doubles (a record of
// runner/distributed_map.hpp: the force evaluations are exact). runs[i * hs.size() + j][k]: initial condition i,
// step hs[j], method k.
std::vector<std::vector<Errors>> convergence_runs(Context& ctx, const ElasticPendulumRuns& sys, const std::vector<double>& hs,
                                                  const std::vector<std::vector<double>>& initial,
                                                  const std::vector<std::string>& methods, Observables obs,
                                                  double t_end, const std::vector<ElasticPendulumRuns::Reference>& refs) {
  ctx.progress("Fig. 4: convergence");
  const std::size_t nh = hs.size();
  const auto flat = distributed_map(initial.size() * nh, [&](std::size_t task) {
    const std::size_t i = task / nh;
    const double h = hs[task % nh];
    std::vector<double> out;
    for (const auto& m : methods) {
      const Errors e = convergence_run(sys, m, elastic_pendulum_state(initial[i]), obs.phase ? &refs[i].z : nullptr, h,
                                       steps_to(t_end, h), obs);
      out.insert(out.end(), {e.energy_rms, e.energy_max, e.phase, static_cast<double>(e.force_evals)});
    }
    return out;
  });
  std::vector<std::vector<Errors>> runs(flat.size());
  for (std::size_t task = 0; task < flat.size(); ++task)
    for (std::size_t k = 0; k < methods.size(); ++k)
      runs[task].push_back({flat[task][4 * k], flat[task][4 * k + 1], flat[task][4 * k + 2],
                            static_cast<std::int64_t>(flat[task][4 * k + 3])});
  return runs;
}

// fig4_convergence.csv and the orders fitted per initial condition and norm (orders.csv); the
// reference's error bounds what can be fitted of the phase error.
ConvergenceStudy convergence_table(const ElasticPendulumRuns& sys, const std::vector<double>& hs, double t_end,
                                   const std::vector<std::vector<double>>& initial,
                                   const std::vector<std::string>& methods, Observables obs,
                                   const std::vector<std::vector<Errors>>& runs, double self_check) {
  std::vector<double> steps;
  for (double h : hs) steps.push_back(static_cast<double>(steps_to(t_end, h)));
  ConvergenceStudy conv({.csv = "fig4_convergence.csv", .h = hs, .steps = steps, .initials = initial.size()});
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const auto column = [&](const char* suffix, double (*field)(const Errors&)) {
      conv.column(label_of(methods[k]) + suffix, [&runs, &hs, k, field](std::size_t i, std::size_t j) {
        return field(runs[i * hs.size() + j][k]);
      });
    };
    if (obs.energy) {
      column("_energy_rms", [](const Errors& e) { return e.energy_rms; });
      column("_energy_max", [](const Errors& e) { return e.energy_max; });
    }
    if (obs.phase) column("_phase", [](const Errors& e) { return e.phase; });
    column("_evals", [](const Errors& e) { return static_cast<double>(e.force_evals); });
  }
  const auto energy_floor = [&](std::size_t i) { return roundoff_floor() * std::max(std::abs(sys.H(elastic_pendulum_state(initial[i]))), 1.0); };
  const double phase_floor = std::max(100.0 * self_check, roundoff_floor());
  for (const auto& m : methods) {  // (the CSV's columns by label)
    if (obs.energy)
      conv.fit(label_of(m) + "_energy", label_of(m) + "_energy_rms", energy_floor)
          .fit(label_of(m) + "_energy_max", label_of(m) + "_energy_max", energy_floor);
    if (obs.phase)
      conv.fit(label_of(m) + "_phase", label_of(m) + "_phase", phase_floor, "round-off or the reference's accuracy");
  }
  return conv;
}

// The fitted orders per initial condition ({name + norm suffix: order}), and the smallest phase error plotted.
struct Orders {
  Value by_initial;
  double min_phase;
};

Orders orders_of(const ConvergenceStudy& conv, std::size_t n_initial, const std::vector<std::string>& methods, Observables obs) {
  Value by_initial = Value::list();
  double min_phase = std::numeric_limits<double>::infinity();  // smallest phase error plotted
  for (std::size_t i = 0; i < n_initial; ++i) {
    by_initial.push_back(conv.orders(i));
    if (obs.phase)
      for (const auto& m : methods)
        for (double e : conv.values(label_of(m) + "_phase", i)) min_phase = std::min(min_phase, e);
  }
  return {by_initial, min_phase};
}

// What the study reports in summary.json: the reference's margin, the orders and their ranges, the
// norms, the methods and the scene.
void summarize(Context& ctx, const std::vector<double>& hs, std::size_t n_initial,
               const std::vector<std::string>& methods, Observables obs, const std::vector<std::vector<Errors>>& runs,
               const Orders& orders, double self_check) {
  const Scene& s = ctx.scene;
  const auto& [by_initial, min_phase] = orders;  // (in the summary already: ConvergenceStudy::write)
  Value reproduced;
  if (obs.phase) {
    reproduced["reference_self_check"] = self_check;
    reproduced["reference_margin"] = min_phase / self_check;  // must be >= 100 (checked by the tests)
  }

  if (reproduced.size() > 0) ctx.summary["reproduced"] = reproduced;
  Value norms;
  if (obs.energy) {
    norms["energy"] = "eq. (50): sqrt(sum_{j=0}^{N} (H(z_j) - H(z_0))^2 / N), z_j postprocessed at every step";
    norms["energy_max"] = "max over j of |H(z_j) - H(z_0)|";
  }
  if (obs.phase) norms["phase"] = "|z_N - z(t_end)|_2 over (x, y, px, py), against the odeint Bulirsch-Stoer reference";
  ctx.summary["norms"] = norms;

  ctx.summary["methods"]["convergence"] = labels_of(methods);
  for (const auto& m : methods) ctx.summary["declared_orders"][label_of(m)] = method_info(m).order;  // the registry's
  record_steps_and_starts(ctx.summary, s, "h", "initial");
  ctx.summary["pendulum"] = {{"y_equilibrium", hanging_equilibrium_y(elastic_pendulum_params(s))}};
  ctx.summary["order_ranges"] = order_ranges(methods, by_initial);
  if (const auto ratio = printed_over_kernel(methods, runs, hs, n_initial, obs)) ctx.summary["printed_over_kernel"] = *ratio;
}

void convergence_with(Context& ctx, const ElasticPendulumRuns& sys) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("h");
  const auto initial = s.real_rows("initial");
  const auto methods = s.texts("methods");
  const Observables obs = observables_of(s);
  const double t_end = s.real("t_end"), rtol = s.real("reference.rtol"), atol = s.real("reference.atol");
  double self_check = 0;
  const auto refs = references(ctx, sys, initial, obs, t_end, rtol, atol, self_check);
  const auto runs = convergence_runs(ctx, sys, hs, initial, methods, obs, t_end, refs);
  const ConvergenceStudy conv = convergence_table(sys, hs, t_end, initial, methods, obs, runs, self_check);
  conv.write(ctx);
  const Orders orders = orders_of(conv, initial.size(), methods, obs);
  summarize(ctx, hs, initial.size(), methods, obs, runs, orders, self_check);
}

void run_convergence(Context& ctx) {
  convergence_with(ctx, ElasticPendulumRuns(elastic_pendulum_params(ctx.scene)));
}

StudyPlan plan_convergence(const Scene& s) {
  const double runs = static_cast<double>(s.real_rows("initial").size() * s.texts("methods").size());
  const double steps = runs * steps_to_each(s.real("t_end"), s.reals("h"));
  const double rows = static_cast<double>(s.real_rows("initial").size() * s.reals("h").size());
  const PlanRate& rate = plan_rate("elastic pendulum rowlands");
  return {steps, steps * rate.evals_per_step(), rows * (3 + 4 * static_cast<double>(s.texts("methods").size())) * kCsvCellBytes,
          rate.ns_per_step, "odeint reference steps not counted; " + rate.note};
}


}  // namespace

Study convergence_study() {
  return {.name = "convergence",
          .makes = {{"000", "Fig. 4"}},
          .about = "Stormer-Verlet vs Rowlands on the elastic pendulum: orders 2 and 4",
          .files = {"fig4_convergence.csv", "orders.csv", "reference.csv"},
          .keys = Schema()
                      .texts("methods", ElasticPendulumRuns::choices(), 1, "methods of the convergence study (registry names or labels)")
                      .texts("observables", {"energy_error", "phase_error"}, 1,
                             "what the convergence study records: energy_error (eq. (50) and the max over the run), "
                             "phase_error (|z_N - z(t_end)|_2 against the odeint reference, computed only if named)"),
          .reads = {"initial", "t_end", "h", "pendulum", "reference"},
          .run = run_convergence,
          .validate =
              [](const Scene& s) {
                check_whole_steps(s, "h", "t_end");
                check_elastic_pendulum_states(s, "initial");
                ElasticPendulumRuns(elastic_pendulum_params(s)).check(s, "methods", "h");
              },
          .plan = plan_convergence};
}

}  // namespace geomint::rowlands_convergence
